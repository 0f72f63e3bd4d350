//! What a caller asks the stages for ([`Request`]): the case, the stages whose results it wants, the grids
//! of the sweeps, and where solves start ([`Start`]).

use serde::{Deserialize, Serialize};

use crate::bearing::stages::id::StageId;
use crate::model::Case;

/// Where a solve starts.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
pub enum Start {
    /// From the last converged state on the same films (and from scratch if that fails): the workbench, speed
    /// sweeps, the rotor's speeds — neighbouring points converge in a few iterations.
    #[default]
    Warm,
    /// From a centred journal every time, so a result does not depend on what was solved before it: batches
    /// and the convergence map. (An output already cached for the same inputs is still reused.)
    Cold,
}

/// What the caller wants computed.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Request {
    pub case: Case,
    /// The stages whose results are wanted (the stages they read run too).
    pub wanted: Vec<StageId>,
    /// Excitation ratios ω/Ω of the frequency sweep.
    pub frequency_ratios: Vec<f64>,
    /// Speeds of the speed sweep [rad/s] (everything else as in the case).
    pub speeds_rad_s: Vec<f64>,
    pub start: Start,
}

impl Request {
    /// The stages `wanted` for `case`, with no sweep grids, warm-started.
    #[must_use]
    pub fn of(case: Case, wanted: &[StageId]) -> Self {
        Self {
            case,
            wanted: wanted.to_vec(),
            frequency_ratios: Vec::new(),
            speeds_rad_s: Vec::new(),
            start: Start::default(),
        }
    }

    /// The solution of a case ([`super::Outcome::solution`]).
    #[must_use]
    pub fn solution(case: Case) -> Self {
        Self::of(case, &[StageId::Reduction])
    }

    /// The full coefficients of a case (its solution with the pads' inertia, not yet reduced:
    /// [`super::Outcome::coefficients`]).
    #[must_use]
    pub fn coefficients(case: Case) -> Self {
        Self::of(case, &[StageId::Coefficients])
    }

    /// The bearing linearised for its injection ports ([`super::Outcome::frf`]).
    #[must_use]
    pub fn frf(case: Case) -> Self {
        Self::of(case, &[StageId::Frf])
    }

    /// The same request, starting its solves as `start` says.
    #[must_use]
    pub fn starting(self, start: Start) -> Self {
        Self { start, ..self }
    }

    /// The same request restricted to `stages` (those of them it wants).
    #[must_use]
    pub fn only(&self, stages: &[StageId]) -> Self {
        Self { wanted: self.wanted.iter().copied().filter(|s| stages.contains(s)).collect(), ..self.clone() }
    }
}
