//! Static equilibrium of journal and pads.
//!
//! ## Problem
//! Find the global coordinates `u = [e_x, e_y, pad coordinates…]` (layout: [`crate::bearing::film::coordinates::DofMap`])
//! such that
//!
//! ```text
//! journal:  Σ_k Q_journal,k(u) + W = 0             (film forces balance the static load W)
//! pad k:    Q_pad,k(u) − K_s,k q_k = 0             (zero moment about a frictionless pivot; pivot springs,
//!                                                   modal stiffness)
//! ```
//!
//! ## Method
//! - [`coupled`]: Newton on all coordinates at once with the films' analytic Jacobian (one film solve per
//!   pad per iteration). Pads that carry no load, or whose own stiffness is not positive, are placed by the
//!   safeguarded pad solve first; directions without stiffness are held.
//! - [`pad`]: one pad's coordinates for a fixed journal (tilt by Newton safeguarded by bisection on the
//!   admissible interval; the other coordinates by Newton with the tilt condensed, each safeguarded by a
//!   bracket).
//! - [`fallback`]: Lund's pad assembly (Newton on the journal with pad-condensed stiffness, pads solved
//!   inside), a scan along the load, load continuation, and — for the non-smooth force laws of floating
//!   zero-preload pads, where Newton cycles — a bracketing search in polar journal coordinates that
//!   converges for any continuous restoring force.
//! - [`finish`]: the converged state's full linearisation, floating pads, touchdown, the report.
//!
//! Jacobians come from the films' analytic perturbations ([`crate::physics::reynolds::PadFilm::linearize`]).
//! The outcome is an [`Equilibrium`] with a [`SolveReport`], a [`Progress::Suspended`] state to resume from
//! (only when the caller's [`Cancel::suspend`] asks for it), or a [`SolveError`] (touchdown,
//! non-convergence, budgets); never NaN.

mod coupled;
mod eval;
mod fallback;
mod finish;
mod journal;
mod pad;
pub mod pivots;
mod polar;
mod solve;
pub mod state;
#[cfg(test)]
mod tests;

pub use eval::force_scale;
pub use solve::{solve_equilibrium, step_equilibrium};
pub use state::{
    Equilibrium, EquilibriumParams, PadState, Resume, FLOATING_SHARE, NO_PRESSURE_SHARE, ONSET_FIRST_STEP, ONSET_WIDTH,
    SUFFICIENT_DECREASE, UNLOADED_SHARE,
};
