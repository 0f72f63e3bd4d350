//! The speed sweep: one solution per speed of the request (everything else as in the case), one point per
//! poll (or the part of it that fits when the caller asks to pause), asked of a nested computation of the
//! stages themselves ([`Ctx::nested`]): its films are built once, each point starts from the previous one's
//! converged state, an isothermal point may itself be suspended between frames and resumed, and a THD point
//! runs its thermal loop one outer iteration per step. The points' requests are built from the sweep's
//! inputs — the reduced solution's view of the case with the speed left out — so the nested stages see
//! nothing the sweep's key does not hold.

use std::sync::Arc;

use crate::bearing::report::error::SolveError;
use crate::bearing::report::progress::{Cancel, Progress};
use crate::bearing::stages::cache::Cached;
use crate::bearing::stages::id::StageId;
use crate::bearing::stages::outcome::{Published, Step};
use crate::bearing::stages::reduction::ReductionInputs;
use crate::bearing::stages::request::{Request, Start};
use crate::bearing::stages::stage::{Ctx, Poll, Solver, Stage};
use crate::bearing::stages::sweeps::{SpeedPoint, SweepValues};
use crate::bearing::stages::view;
use crate::model::{Case, Operating};

/// Steps the nested stages towards one point until it is done or the caller asks to pause (`None`: paused).
fn step_point(stages: &mut dyn Solver, req: &Request, cancel: &dyn Cancel) -> Result<Option<Step>, SolveError> {
    loop {
        match stages.step(req, cancel)? {
            Step::Pending { .. } if cancel.suspend() => return Ok(None),
            Step::Pending { .. } => {}
            done @ Step::Done(_) => return Ok(Some(done)),
        }
    }
}

/// The inputs of the speed sweep: the case as its points see it ([`super::view`]) and the request's speeds.
#[derive(Debug, Clone, PartialEq)]
pub struct SpeedSweepInputs {
    /// What the reduced solution reads, with the case's speed left out (each point has its own).
    pub case: Case,
    pub speeds_rad_s: Vec<f64>,
}

impl SpeedSweepInputs {
    fn of(req: &Request) -> Self {
        let reduction = ReductionInputs::of(&req.case).case;
        let operating = Operating { speed_rad_s: view::BLANK, ..reduction.operating };
        Self { case: Case { operating, ..reduction }, speeds_rad_s: req.speeds_rad_s.clone() }
    }

    /// The request of the point at `speed_rad_s`.
    fn point(&self, speed_rad_s: f64, start: Start) -> Request {
        let operating = Operating { speed_rad_s, ..self.case.operating.clone() };
        Request::solution(Case { operating, ..self.case.clone() }).starting(start)
    }
}

/// A sweep under way: the points solved so far and the nested stages that solve them.
struct SweepRun {
    points: Vec<SpeedPoint>,
    stages: Box<dyn Solver>,
}

#[derive(Default)]
pub struct SpeedSweepStage {
    run: Cached<SpeedSweepInputs, SweepRun>,
}

impl Stage for SpeedSweepStage {
    const LABEL: &'static str = "speed sweep";
    const NEEDS: &'static [StageId] = &[];
    type Inputs = SpeedSweepInputs;
    type Output = Arc<Vec<SpeedPoint>>;

    fn inputs(req: &Request) -> Option<SpeedSweepInputs> {
        Some(SpeedSweepInputs::of(req))
    }

    fn poll(
        &mut self,
        inputs: &SpeedSweepInputs,
        ctx: &mut Ctx<'_>,
        cancel: &dyn Cancel,
    ) -> Result<Poll<Arc<Vec<SpeedPoint>>>, SolveError> {
        let mut st = match self.run.take(inputs) {
            Some(st) => st,
            None => SweepRun { points: Vec::new(), stages: ctx.nested() },
        };
        let n = inputs.speeds_rad_s.len();
        if let Some(&speed_rad_s) = inputs.speeds_rad_s.get(st.points.len()) {
            let req = inputs.point(speed_rad_s, ctx.start());
            let result = match step_point(st.stages.as_mut(), &req, cancel) {
                Ok(None | Some(Step::Pending { .. })) => None,
                Ok(Some(Step::Done(outcome))) => Some(outcome.solution().map(|s| SweepValues::of(&s)).ok_or(
                    SolveError::Internal(crate::bearing::report::error::InternalError::Unpublished {
                        stage: "reduced coefficients".into(),
                    }),
                )),
                Err(SolveError::Cancelled) => return Err(SolveError::Cancelled),
                Err(e) => Some(Err(e)),
            };
            if let Some(result) = result {
                st.points.push(SpeedPoint { speed_rad_s, result });
            }
        }
        if st.points.len() == n {
            return Ok(Progress::Done(Arc::new(st.points)));
        }
        #[allow(clippy::cast_precision_loss)]
        let fraction = st.points.len() as f64 / n as f64;
        self.run.put(inputs.clone(), st);
        Ok(Progress::Suspended(fraction))
    }

    fn publish(&mut self, output: &Arc<Vec<SpeedPoint>>) -> Option<Published> {
        Some(output.clone())
    }
}
