//! The reduction stage: the solution the views show — the full coefficients reduced to the journal's
//! `K`, `C` at the case's excitation frequency ω = (ω/Ω)·Ω. The title and the case are stamped when the
//! solution is published (they are read by no stage).

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

/// The inputs of the reduced solution.
#[derive(Debug, Clone, PartialEq)]
pub struct ReductionInputs {
    pub coefficients: CoefficientsInputs,
    pub excitation_ratio: f64,
}

#[derive(Default)]
pub struct ReductionStage {
    /// The last published solution, to hand out again while nothing changes.
    /// (the case it was stamped with, the output it was made from, the stamped solution).
    published: Option<(crate::model::Case, Arc<Solution>, Arc<Solution>)>,
}

impl Stage for ReductionStage {
    const LABEL: &'static str = "reduced coefficients";
    const NEEDS: &'static [StageId] = &[StageId::Coefficients];
    type Inputs = ReductionInputs;
    type Output = Arc<Solution>;

    fn inputs(req: &Request) -> Option<ReductionInputs> {
        Some(ReductionInputs {
            coefficients: CoefficientsInputs::of(&req.case),
            excitation_ratio: req.case.operating.excitation_ratio,
        })
    }

    fn poll(
        &mut self,
        inputs: &ReductionInputs,
        ctx: &mut Ctx<'_>,
        _cancel: &dyn Cancel,
    ) -> Result<Poll<Arc<Solution>>, SolveError> {
        let mut s = Solution::clone(ctx.output::<CoefficientsStage>()?);
        s.reduced = reduce(&s.full, inputs.excitation_ratio * s.derived.speed_rad_s);
        Ok(Progress::Done(Arc::new(s)))
    }

    fn publish(&mut self, output: &Arc<Solution>, req: &Request) -> Option<Published> {
        let fresh =
            self.published.as_ref().is_none_or(|(case, from, _)| *case != req.case || !Arc::ptr_eq(from, output));
        if fresh {
            let mut s = Solution::clone(output);
            s.title.clone_from(&req.case.title);
            s.inputs = req.case.clone();
            self.published = Some((req.case.clone(), output.clone(), Arc::new(s)));
        }
        let out: Arc<Solution> = self.published.as_ref()?.2.clone();
        Some(out)
    }
}
