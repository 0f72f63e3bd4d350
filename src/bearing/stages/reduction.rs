//! The reduction stage: the solution the views show — the full coefficients reduced to the journal's
//! `K`, `C` at the case's excitation frequency ω = (ω/Ω)·Ω. The title and the case are read by no stage:
//! the registry stamps them on the published solution ([`super::stamp`]).

use std::sync::Arc;

use crate::bearing::report::error::SolveError;
use crate::bearing::report::progress::{Cancel, Progress};
use crate::bearing::solution::coefficients::reduce;
use crate::bearing::solution::Solution;
use crate::bearing::stages::coefficients::{CoefficientsInputs, CoefficientsStage};
use crate::bearing::stages::id::StageId;
use crate::bearing::stages::outcome::Published;
use crate::bearing::stages::request::Request;
use crate::bearing::stages::stage::{Ctx, Poll, Stage};
use crate::model::{Case, Operating};

/// The inputs of the reduced solution: the case as it sees it ([`super::view`]).
#[derive(Debug, Clone, PartialEq)]
pub struct ReductionInputs {
    /// The coefficients' view with the excitation ratio ω/Ω.
    pub case: Case,
}

impl ReductionInputs {
    /// Exhaustive over the operating point (no `..`).
    #[must_use]
    pub fn of(case: &Case) -> Self {
        let Operating {
            speed_rad_s: _,
            load: _,
            supply_temperature_c: _,
            film_temperature_c: _,
            injection_pressure_pa: _,
            injection_temperature_c: _,
            supply_flow_m3_s: _, // the coefficients' view
            excitation_ratio,
        } = &case.operating;
        let coefficients = CoefficientsInputs::of(case).case;
        let operating = Operating { excitation_ratio: *excitation_ratio, ..coefficients.operating };
        Self { case: Case { operating, ..coefficients } }
    }

    /// The coefficients it reduces.
    #[must_use]
    pub fn coefficients(&self) -> CoefficientsInputs {
        CoefficientsInputs::of(&self.case)
    }
}

#[derive(Default)]
pub struct ReductionStage;

impl Stage for ReductionStage {
    const LABEL: &'static str = "reduced coefficients";
    const NEEDS: &'static [StageId] = &[StageId::Coefficients];
    type Inputs = ReductionInputs;
    type Output = Arc<Solution>;

    fn inputs(req: &Request) -> Option<ReductionInputs> {
        Some(ReductionInputs::of(&req.case))
    }

    fn poll(
        &mut self,
        inputs: &ReductionInputs,
        ctx: &mut Ctx<'_>,
        _cancel: &dyn Cancel,
    ) -> Result<Poll<Arc<Solution>>, SolveError> {
        let mut s = Solution::clone(ctx.output::<CoefficientsStage>(&inputs.coefficients())?);
        s.reduced = reduce(&s.full, inputs.case.operating.excitation_ratio * s.derived.speed_rad_s);
        Ok(Progress::Done(Arc::new(s)))
    }

    fn publish(&mut self, output: &Arc<Solution>) -> Option<Published> {
        let out: Arc<Solution> = output.clone();
        Some(out)
    }
}
