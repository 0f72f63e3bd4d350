//! The rotor job: a rotor analysis ([`Analysis`]) over its speeds, one speed a step (its bearing solves and
//! the eigen-solution), then the finish (onset bisection, critical speeds). A newer job supersedes it
//! between speeds.

use std::sync::Arc;

use serde::{Deserialize, Deserializer, Serialize, Serializer};

use super::job::{Job, JobError, Progress, Step};
use crate::bearing::Cancel;
use crate::model::rotor::Rotor;
use crate::rotor::analysis::{Analysis, AnalysisParams, AnalysisResult, Step as RotorStep};
use crate::rotor::wire::AnalysisData;

/// A rotor analysis.
#[derive(Serialize, Deserialize)]
pub struct RotorJob {
    pub rotor: Rotor,
    pub params: AnalysisParams,
    #[serde(skip)]
    analysis: Option<Analysis>,
}

impl RotorJob {
    #[must_use]
    pub fn new(rotor: Rotor, params: AnalysisParams) -> Self {
        Self { rotor, params, analysis: None }
    }
}

/// A finished analysis (shared: the views keep it while drawing); it crosses to the page with its mode
/// shapes ([`AnalysisData`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Analysed(pub Arc<AnalysisResult>);

impl Serialize for Analysed {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        AnalysisData::from(self.0.as_ref()).serialize(s)
    }
}

impl<'de> Deserialize<'de> for Analysed {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        Ok(Self(Arc::new(AnalysisData::deserialize(d)?.into())))
    }
}

impl Job for RotorJob {
    const NAME: &'static str = "rotor";
    type Output = Analysed;
    type Keep = ();

    fn step(&mut self, (): &mut (), cancel: &dyn Cancel) -> Result<Step<Analysed>, JobError> {
        if cancel.cancelled() {
            return Err(JobError::Cancelled);
        }
        if self.analysis.is_none() {
            self.analysis = Some(Analysis::new(&self.rotor, self.params.clone()).map_err(JobError::failed)?);
        }
        let step = self.analysis.as_mut().map(Analysis::step).transpose().map_err(JobError::failed)?;
        match step {
            Some(RotorStep::More { done, of }) => {
                #[allow(clippy::cast_precision_loss)]
                let progress = Progress::new(done as f64, of as f64, format!("speed {done} of {of}"));
                Ok(Step::More { progress, output: None })
            }
            _ => {
                let a = self.analysis.take().ok_or_else(|| JobError::Failed("no analysis".into()))?;
                Ok(Step::Done(Analysed(Arc::new(a.finish().map_err(JobError::failed)?))))
            }
        }
    }
}
