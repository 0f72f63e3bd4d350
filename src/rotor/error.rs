//! Errors of the rotor analyses.

use thiserror::Error;

use crate::bearing::report::error::SolveError;
use crate::model::CaseError;

/// Why a rotor analysis failed.
#[derive(Debug, Error)]
pub enum RotorError {
    #[error(transparent)]
    Input(#[from] CaseError),
    /// A bearing case could not be solved at a speed.
    /// The bearing's solve failed at that speed (its message is part of this one, not a separate cause, so
    /// it is printed once).
    #[error("bearing `{bearing}` at {speed_rpm:.0} rpm: {error}")]
    Bearing { bearing: String, speed_rpm: f64, error: SolveError },
    /// The mass matrix cannot be inverted (a coordinate without inertia).
    #[error("the mass matrix is singular ({size} coordinates): every coordinate needs inertia")]
    SingularMass { size: usize },
    /// The dynamic stiffness at a speed is singular (a free rigid-body motion at the forcing frequency).
    #[error("the dynamic stiffness is singular at {speed_rpm:.1} rpm (a free rigid-body motion?)")]
    SingularResponse { speed_rpm: f64 },
    /// The dense eigen-solver did not converge.
    #[error("eigen-solution failed ({size}×{size} state matrix)")]
    Eigen { size: usize },
    /// Proportional damping asks for a free–free mode the shaft model does not have.
    #[error("`rotor.damping.modes`: flexible mode {mode} requested, the shaft model has {available}")]
    DampingMode { mode: usize, available: usize },
    /// The shaft cannot be reduced (component mode synthesis): free with only the `attached` nodes held.
    #[error(
        "shaft reduction: the shaft is free with only nodes {attached:?} held (interior stiffness singular); use \
         shaft_modes = 0 (the full model)"
    )]
    Reduction { attached: Vec<usize> },
    /// A speed list that cannot be swept.
    #[error("speeds must be finite, ≥ 0 and strictly ascending")]
    Speeds,
    /// A critical-speed map over a stiffness range that is not one.
    #[error("critical-speed map: needs 0 < k_min < k_max and n ≥ 2 (got {k_min:e}, {k_max:e}, {n})")]
    StiffnessRange { k_min: f64, k_max: f64, n: usize },
}

/// What a rotor analysis warns about.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum RotorWarning {
    /// The rotor is unstable already at the first speed of the sweep.
    UnstableFromFirstSpeed,
    /// The shaft could not be reduced: the full shaft model is used.
    FullShaftModel { attached: Vec<usize> },
    /// The sweep was stopped (Ctrl-C) after `done` of `of` speeds: results cover those speeds only, and the
    /// onset was not bisected.
    Stopped { done: usize, of: usize },
}

impl std::fmt::Display for RotorWarning {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::UnstableFromFirstSpeed => {
                f.write_str("unstable from the first speed of the sweep: the onset lies below it")
            }
            Self::FullShaftModel { attached } => {
                write!(f, "{}: the full shaft model is used", RotorError::Reduction { attached: attached.clone() })
            }
            Self::Stopped { done, of } => write!(
                f,
                "stopped after {done} of {of} speeds: the results cover those speeds only and the onset was not \
                 bisected"
            ),
        }
    }
}
