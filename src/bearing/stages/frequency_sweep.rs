//! The frequency sweep: the full coefficients reduced at each excitation ratio ω/Ω of the request.

use std::sync::Arc;

use crate::bearing::report::error::SolveError;
use crate::bearing::report::progress::{Cancel, Progress};
use crate::bearing::solution::coefficients::reduce;
use crate::bearing::stages::coefficients::{CoefficientsInputs, CoefficientsStage};
use crate::bearing::stages::id::StageId;
use crate::bearing::stages::outcome::Published;
use crate::bearing::stages::request::Request;
use crate::bearing::stages::stage::{Ctx, Poll, Stage};
use crate::bearing::stages::sweeps::FrequencySweep;

/// The inputs of the frequency sweep.
#[derive(Debug, Clone, PartialEq)]
pub struct FrequencySweepInputs {
    /// The coefficients it reduces.
    pub coefficients: CoefficientsInputs,
    /// The request's ratios ω/Ω.
    pub ratios: Vec<f64>,
}

#[derive(Default)]
pub struct FrequencySweepStage;

impl Stage for FrequencySweepStage {
    const LABEL: &'static str = "frequency sweep";
    const NEEDS: &'static [StageId] = &[StageId::Coefficients];
    type Inputs = FrequencySweepInputs;
    type Output = Arc<FrequencySweep>;

    fn inputs(req: &Request) -> Option<FrequencySweepInputs> {
        Some(FrequencySweepInputs {
            coefficients: CoefficientsInputs::of(&req.case),
            ratios: req.frequency_ratios.clone(),
        })
    }

    fn poll(
        &mut self,
        inputs: &FrequencySweepInputs,
        ctx: &mut Ctx<'_>,
        _cancel: &dyn Cancel,
    ) -> Result<Poll<Arc<FrequencySweep>>, SolveError> {
        let s = ctx.output::<CoefficientsStage>(&inputs.coefficients)?;
        let w = s.derived.speed_rad_s;
        Ok(Progress::Done(Arc::new(inputs.ratios.iter().map(|&r| (r, reduce(&s.full, r * w))).collect())))
    }

    fn publish(&mut self, output: &Arc<FrequencySweep>) -> Option<Published> {
        Some(output.clone())
    }
}
