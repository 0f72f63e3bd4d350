//! The solve job: a solver request ([`Request`]) worked on by the cached, steppable stages
//! ([`Stages::step`]), which the slot keeps between jobs — so an edit re-runs only the stages whose inputs
//! it changed. The edited case's solve and the pins' re-solves are each a slot of this job.
//!
//! Two phases: first everything but the speed sweep (the solution and the frequency sweep: what most views
//! need, so they update as soon as possible, handed back as a partial output), then the speed sweep if the
//! request wants it.

use serde::{Deserialize, Serialize};

use super::job::{Job, JobError, Progress, Step};
use crate::bearing::stages::{Outcome, Request, StageId, Stages, Step as StageStep};
use crate::bearing::{Cancel, SolveError};

/// A solver request, in two phases.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SolveJob {
    pub request: Request,
    /// False while working on the first phase (no speed sweep).
    second_phase: bool,
}

impl SolveJob {
    #[must_use]
    pub fn new(request: Request) -> Self {
        Self { request, second_phase: false }
    }

    fn phase_request(&self) -> Request {
        if self.second_phase {
            self.request.clone()
        } else {
            let first: Vec<StageId> = StageId::ALL.iter().copied().filter(|s| *s != StageId::SpeedSweep).collect();
            self.request.only(&first)
        }
    }
}

/// The stage a solve's progress names (its label), if any.
#[must_use]
pub fn stage_of(progress: &Progress) -> Option<StageId> {
    StageId::ALL.iter().copied().find(|s| s.label() == progress.label)
}

impl Job for SolveJob {
    const NAME: &'static str = "solve";
    type Output = Outcome;
    type Keep = Stages;

    fn step(&mut self, stages: &mut Stages, cancel: &dyn Cancel) -> Result<Step<Outcome>, JobError> {
        match stages.step(&self.phase_request(), cancel) {
            Ok(StageStep::Pending { stage, fraction }) => {
                Ok(Step::More { progress: Progress::new(fraction, 1.0, stage.label()), output: None })
            }
            Ok(StageStep::Done(outcome)) => {
                let more = !self.second_phase && self.request.wanted.contains(&StageId::SpeedSweep);
                if more {
                    self.second_phase = true;
                    let progress = Progress::new(0.0, 1.0, StageId::SpeedSweep.label());
                    Ok(Step::More { progress, output: Some(outcome) })
                } else {
                    Ok(Step::Done(outcome))
                }
            }
            Err(SolveError::Cancelled) => Err(JobError::Cancelled),
            Err(e) => Err(JobError::failed(e)),
        }
    }
}
