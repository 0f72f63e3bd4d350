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
    #[error("bearing `{bearing}` at {speed_rpm:.0} rpm: {source}")]
    Bearing { bearing: String, speed_rpm: f64, source: SolveError },
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
    /// The shaft cannot be reduced (component mode synthesis).
    #[error("shaft reduction: {message}")]
    Reduction { message: String },
    /// A speed list that cannot be swept.
    #[error("speeds: {0}")]
    Speeds(String),
}
