//! Errors of a bearing solve. Each says what failed and where; none is ever replaced by NaN.

use crate::model::CaseError;
use crate::physics::reynolds::FilmError;
use serde::{Deserialize, Serialize};
use thiserror::Error;

/// An iteration that runs under a budget ([`SolveError::BudgetExceeded`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum Iteration {
    /// The thermal (THD) outer loop: equilibrium, film and pad temperatures, viscosity update.
    Thermal,
    /// The static equilibrium (all its methods together).
    Equilibrium,
}

impl Iteration {
    /// What the residual of [`SolveError::BudgetExceeded`] measures.
    #[must_use]
    pub fn residual_name(self) -> &'static str {
        match self {
            Self::Thermal => "largest relative viscosity change",
            Self::Equilibrium => "relative force residual",
        }
    }
}

impl std::fmt::Display for Iteration {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Self::Thermal => "thermal (THD) loop",
            Self::Equilibrium => "equilibrium",
        })
    }
}

/// The budget that stopped an iteration.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub enum Budget {
    /// At most this many iterations.
    Iterations(usize),
    /// At most this much computing time [s].
    Seconds(f64),
    /// At most this many film solves.
    FilmSolves(usize),
}

impl std::fmt::Display for Budget {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Iterations(n) => write!(f, "iteration budget ({n} iterations)"),
            Self::Seconds(s) => write!(f, "time budget ({s} s)"),
            Self::FilmSolves(n) => write!(f, "work budget ({n} film solves)"),
        }
    }
}

#[derive(Debug, Clone, PartialEq, Error, Serialize, Deserialize)]
pub enum SolveError {
    #[error(transparent)]
    Case(#[from] CaseError),
    /// A film solve failed (its message is part of this one, not a separate cause).
    #[error("pad {pad}: {error}")]
    Film { pad: usize, error: FilmError },
    /// The load cannot be carried without the film closing.
    #[error(
        "touchdown: the film closes on pad {pad} (h_min {h_min_um:.3} µm at ε = {eccentricity_ratio:.3}) before \
         the load is carried; reduce the load, raise the speed or viscosity, or inject"
    )]
    Touchdown { pad: usize, h_min_um: f64, eccentricity_ratio: f64 },
    /// The bearing has no static stiffness along a direction in which the load has a component (e.g. two
    /// tilting pads whose pivot line is perpendicular to the load: their forces pass through the pivots).
    #[error(
        "no stiffness along the {axis_deg:.0}° axis: a load component of {load_component_n:.3e} N acts where the \
         bearing cannot carry it (tilting-pad forces pass through the pivots); turn the load or the pads"
    )]
    NoStiffness { axis_deg: f64, load_component_n: f64 },
    /// Along the load the bearing's static force law jumps across the load: a pad switches from floating to
    /// a loaded state beyond a fold of its tilt equilibrium, where it already carries more than the load
    /// (negative preload, pivot past mid-pad, light load). No static position balances the load on that line.
    #[error(
        "no static equilibrium along the load: the bearing force along it jumps from {below_n:.3e} N to \
         {above_n:.3e} N where pad {pad} engages (it has no loaded state carrying less: a fold of its tilt \
         equilibrium), so the load of {load_n:.3e} N falls in the gap and the pads float around it; raise the load \
         or the preload, or move the pivot towards mid-pad"
    )]
    ForceGap { pad: usize, below_n: f64, above_n: f64, load_n: f64 },
    /// The two-dimensional form of [`Self::ForceGap`]: the journal positions that balance the load along their
    /// own direction from the centre break off at a direction where the residual force (along that direction,
    /// or across it) jumps over zero because a pad engages beyond a fold of its tilt equilibrium, and neither
    /// the scan along the load nor load continuation finds a position beyond it. What was searched, not a proof
    /// over the whole plane.
    #[error(
        "no static equilibrium found: the journal positions that balance the load along their direction break \
         off near {angle_deg:.2}° from the bearing centre, where the residual force (film force plus load) jumps \
         from {before_n:.3e} N to {after_n:.3e} N, across zero, as pad {pad} engages beyond a fold of its tilt \
         equilibrium (it has no loaded state carrying less); a scan along the load and load continuation found no \
         position either, so the load of {load_n:.3e} N falls in a two-dimensional force gap; raise the load or \
         the preload, or move the pivot towards mid-pad"
    )]
    ForceGap2d { pad: usize, angle_deg: f64, before_n: f64, after_n: f64, load_n: f64 },
    /// Newton (and its fallbacks) stopped without meeting the tolerance.
    #[error(
        "equilibrium not converged after {iterations} iterations: relative force residual {residual:.2e} ({reason})"
    )]
    NotConverged { iterations: usize, residual: f64, reason: String },
    /// An iteration used up its iteration or time budget before converging.
    #[error(
        "{what} not converged: stopped by its {budget} after {iterations} iterations ({seconds:.1} s); {} {residual:.2e}",
        what.residual_name()
    )]
    BudgetExceeded { what: Iteration, budget: Budget, iterations: usize, seconds: f64, residual: f64 },
    #[error("solve cancelled")]
    Cancelled,
    #[error("{0}")]
    Invalid(String),
}
