//! What the stages hand back: the published outputs of the wanted stages ([`Outcome`]), or that more work
//! is to be done ([`Step::Pending`]).

use std::any::Any;
use std::sync::Arc;

use crate::bearing::frf::model::FrfModel;
use crate::bearing::solution::Solution;
use crate::bearing::stages::id::StageId;

/// An output handed to the caller (downcast with [`Outcome::get`]).
pub type Published = Arc<dyn Any + Send + Sync>;

/// The published results of the wanted stages.
#[derive(Debug, Clone, Default)]
pub struct Outcome {
    pub(super) outputs: Vec<(StageId, Published)>,
}

impl Outcome {
    /// A stage's published output, if it was wanted and has one of type `T`.
    #[must_use]
    pub fn get<T: Any + Send + Sync>(&self, stage: StageId) -> Option<Arc<T>> {
        self.outputs.iter().find(|(s, _)| *s == stage).and_then(|(_, o)| o.clone().downcast::<T>().ok())
    }

    /// The solution at the case's operating point and excitation ratio.
    #[must_use]
    pub fn solution(&self) -> Option<Arc<Solution>> {
        self.get(StageId::Reduction)
    }

    /// The solution with its full coefficients (inertia included), before reduction.
    #[must_use]
    pub fn coefficients(&self) -> Option<Arc<Solution>> {
        self.get(StageId::Coefficients)
    }

    #[must_use]
    pub fn frequency_sweep(&self) -> Option<Arc<crate::bearing::stages::sweeps::FrequencySweep>> {
        self.get(StageId::FrequencySweep)
    }

    #[must_use]
    pub fn speed_sweep(&self) -> Option<Arc<Vec<crate::bearing::stages::sweeps::SpeedPoint>>> {
        self.get(StageId::SpeedSweep)
    }

    /// The bearing linearised for its injection ports (`None` for a case without `[hydraulics]`).
    #[must_use]
    pub fn frf(&self) -> Option<Arc<FrfModel>> {
        self.get(StageId::Frf)
    }
}

/// Result of one step.
#[derive(Debug, Clone)]
pub enum Step {
    /// More work to do: the stage worked on, and its completed fraction (1 when it just finished).
    Pending {
        stage: StageId,
        fraction: f64,
    },
    Done(Outcome),
}
