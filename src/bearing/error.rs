//! Errors of a bearing solve. Each says what failed and where; none is ever replaced by NaN.

use crate::model::CaseError;
use crate::physics::reynolds::FilmError;
use thiserror::Error;

#[derive(Debug, Clone, PartialEq, Error)]
pub enum SolveError {
    #[error(transparent)]
    Case(#[from] CaseError),
    #[error("pad {pad}: {source}")]
    Film { pad: usize, source: FilmError },
    /// The load cannot be carried without the film closing.
    #[error(
        "touchdown: the film closes on pad {pad} (h_min {h_min_um:.3} µm at ε = {eccentricity_ratio:.3}) before \
         the load is carried; reduce the load, raise the speed or viscosity, or inject"
    )]
    Touchdown { pad: usize, h_min_um: f64, eccentricity_ratio: f64 },
    /// Newton (and its fallbacks) stopped without meeting the tolerance.
    #[error("equilibrium not converged after {iterations} iterations: relative force residual {residual:.2e} ({reason})")]
    NotConverged { iterations: usize, residual: f64, reason: String },
    /// The thermal loop stopped before the viscosity field converged.
    #[error("thermal (THD) loop not converged after {iterations} outer iterations: largest relative viscosity change {viscosity_change:.2e}")]
    ThermalNotConverged { iterations: usize, viscosity_change: f64 },
    #[error("solve cancelled")]
    Cancelled,
    #[error("{0}")]
    Invalid(String),
}
