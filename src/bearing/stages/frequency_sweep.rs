//! The frequency sweep: the full coefficients reduced at each excitation ratio ω/Ω of the request.

use std::sync::Arc;

use crate::bearing::solution::coefficients::{reduce, ReducedCoefficients};
use crate::bearing::report::error::SolveError;
use crate::bearing::report::progress::Cancel;

use crate::bearing::stages::coefficients::{CoefficientsInputs, CoefficientsStage};
use crate::bearing::stages::{Ctx, Poll, Progress, Published, Request, Stage, StageId};

/// Reduced coefficients at each excitation ratio ω/Ω of a frequency sweep.
pub type FrequencySweep = Vec<(f64, ReducedCoefficients)>;

/// The inputs of the frequency sweep.
#[derive(Debug, Clone, PartialEq)]
pub struct FrequencySweepInputs {
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
        Some(FrequencySweepInputs { coefficients: CoefficientsInputs::of(&req.case), ratios: req.frequency_ratios.clone() })
    }

    fn poll(&mut self, inputs: &FrequencySweepInputs, ctx: &mut Ctx<'_>, _cancel: &dyn Cancel) -> Result<Poll<Arc<FrequencySweep>>, SolveError> {
        let s = ctx.output::<CoefficientsStage>()?;
        let w = s.derived.speed_rad_s;
        Ok(Progress::Done(Arc::new(inputs.ratios.iter().map(|&r| (r, reduce(&s.full, r * w))).collect())))
    }

    fn publish(&mut self, output: &Arc<FrequencySweep>, _req: &Request) -> Option<Published> {
        Some(output.clone())
    }
}
