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

use nalgebra::DMatrix;
use web_time::Instant;

use crate::model::LoadSpec;
use crate::physics::reynolds::{FilmError, FilmLinearization};

use crate::bearing::film::model::{BearingModel, OperatingPoint};
use crate::bearing::report::error::SolveError;
pub use crate::bearing::report::progress::{Cancel, NoCancel, NoSuspend, Progress};
pub use crate::bearing::report::SolveReport;

pub use eval::force_scale;

/// Pad load share (pad load over the force scale) below which a pad has no film pressure at all (round-off):
/// its moment vanishes only because nothing acts on it.
pub const NO_PRESSURE_SHARE: f64 = 1e-15;
/// A pad at the onset of pressure is placed within this fraction of its admissible tilt range of the onset
/// (on its pressure-free side).
pub const ONSET_WIDTH: f64 = 1e-6;
/// First step of the search for the onset of pressure from a warm start, as a fraction of the admissible
/// tilt range (grows eightfold per step).
pub const ONSET_FIRST_STEP: f64 = 1e-2;
/// Pad load share below which the film does not determine a pad's coordinates: Newton does not move them,
/// the pad solve places them at the onset of pressure (a deterministic, continuous choice).
pub const UNLOADED_SHARE: f64 = 1e-6;
/// Pad load share below which a pad *floats*: reported, and its film — at cavitation pressure everywhere,
/// unable to carry tension — contributes no stiffness or damping.
pub const FLOATING_SHARE: f64 = 1e-4;

/// Sufficient decrease of a line search: a step of length α must lower the residual norm by the fraction
/// `SUFFICIENT_DECREASE · α` (Armijo). Larger than the textbook 1e-4 on purpose: a force law with an infinite
/// slope (a zero-preload pad at its float point) makes full Newton steps jump to the mirror point with the
/// same residual; rejecting them halves the step onto the root.
pub const SUFFICIENT_DECREASE: f64 = 0.1;

/// Solver settings with documented defaults.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EquilibriumParams {
    /// Journal force residual tolerance, relative to the force scale (load or hydrodynamic scale).
    pub force_tol: f64,
    /// Pad residual tolerance, relative to the pad's own load (× lever for moments).
    pub pad_tol: f64,
    pub max_iterations: usize,
    pub max_inner_iterations: usize,
    /// Largest journal step, as a fraction of the assembled clearance.
    pub max_step: f64,
    /// Work budget: film solves per pad over all methods and fallbacks (bounds the time to fail).
    pub max_film_solves_per_pad: usize,
    /// Time budget of one solve over all methods [s].
    pub max_seconds: f64,
    /// Resuming a suspended cold start: the pads before this index are already placed in `start`
    /// (0: an ordinary solve).
    pub placed_pads: usize,
}

impl Default for EquilibriumParams {
    fn default() -> Self {
        Self {
            force_tol: 1e-9,
            pad_tol: 1e-10,
            max_iterations: 60,
            max_inner_iterations: 80,
            max_step: 0.4,
            max_film_solves_per_pad: 3000,
            max_seconds: 60.0,
            placed_pads: 0,
        }
    }
}

/// Converged state of one pad.
#[derive(Debug, Clone, PartialEq)]
pub struct PadState {
    /// Pad coordinates, in the pad's order ([`crate::bearing::film::model::PadModel::dofs`]).
    pub q: Vec<f64>,
    /// Generalised film forces `[F_x, F_y, Q_pad…]` (film on journal; moment about the pivot; …).
    pub forces: Vec<f64>,
    /// Film stiffness and damping in local coordinates `[e_x, e_y, pad coordinates…]`.
    pub lin: FilmLinearization,
    /// The pad carries (almost) no load: its coordinates are not determined by the film.
    pub unloaded: bool,
    pub residual: f64,
}

impl PadState {
    /// The pad's film force on the journal [N].
    #[must_use]
    pub fn journal_force(&self) -> [f64; 2] {
        [self.forces[0], self.forces[1]]
    }

    /// Generalised film force on pad coordinate `d`.
    #[must_use]
    pub fn pad_force(&self, d: usize) -> f64 {
        self.forces[crate::bearing::film::coordinates::JOURNAL_DOFS + d]
    }

    /// Film stiffness block over the pad's own coordinates.
    #[must_use]
    pub fn pad_stiffness(&self) -> DMatrix<f64> {
        let j = crate::bearing::film::coordinates::JOURNAL_DOFS;
        let n = self.q.len();
        self.lin.stiffness.view((j, j), (n, n)).into_owned()
    }
}

/// A converged equilibrium.
#[derive(Debug, Clone, PartialEq)]
pub struct Equilibrium {
    /// Global coordinates.
    pub u: Vec<f64>,
    pub pads: Vec<PadState>,
    /// Total film force on the journal [N].
    pub film_force: [f64; 2],
    pub report: SolveReport,
}

/// Where a suspended solve resumes: its last iterate, the pads its cold start had placed, and the work
/// done so far (to be added to the final report).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Resume {
    pub coordinates: Vec<f64>,
    pub placed_pads: usize,
    pub report: SolveReport,
}

/// Solves the static equilibrium (or, for a prescribed position, the pads and the load) to the end.
///
/// `start`: a previous solution's global coordinates to warm-start from (sweeps).
///
/// # Errors
/// Touchdown, non-convergence, budgets, film failures or cancellation.
pub fn solve_equilibrium(
    model: &mut BearingModel,
    op: &OperatingPoint,
    params: EquilibriumParams,
    start: Option<&[f64]>,
    cancel: &dyn Cancel,
) -> Result<Equilibrium, SolveError> {
    match step_equilibrium(model, op, params, start, &NoSuspend(cancel))? {
        Progress::Done(eq) => Ok(eq),
        // NoSuspend never asks for a pause.
        Progress::Suspended(r) => Err(SolveError::Invalid(format!(
            "equilibrium paused unexpectedly after {} iterations",
            r.report.iterations
        ))),
    }
}

/// As [`solve_equilibrium`], but pauses when `cancel` asks for it ([`Cancel::suspend`]): the coupled Newton
/// pauses between its cold-start pad placements and between iterations; resume by calling again with
/// `start = resume.coordinates` and `params.placed_pads = resume.placed_pads`.
///
/// # Errors
/// As [`solve_equilibrium`].
pub fn step_equilibrium(
    model: &mut BearingModel,
    op: &OperatingPoint,
    params: EquilibriumParams,
    start: Option<&[f64]>,
    cancel: &dyn Cancel,
) -> Result<Progress<Equilibrium, Resume>, SolveError> {
    let t0 = Instant::now();
    let mut ctx = eval::Ctx::new(model, op, params, t0);
    let result = solve_inner(model, &mut ctx, start, cancel);
    match result {
        Ok(Progress::Done(found)) => finish::finish(model, found, ctx).map(Progress::Done),
        Ok(Progress::Suspended(mut r)) => {
            r.report = std::mem::take(&mut ctx.report);
            r.report.seconds = t0.elapsed().as_secs_f64();
            Ok(Progress::Suspended(r))
        }
        Err(e) => Err(finish::classify_failure(model, &ctx, e)),
    }
}

/// A state the methods found: coordinates, pad states, film force, and the method's name.
pub(crate) struct Found {
    pub u: Vec<f64>,
    pub pads: Vec<PadState>,
    pub force: [f64; 2],
    pub method: String,
}

/// Why a method stopped short of the tolerance, and where.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Stall {
    pub journal: [f64; 2],
    /// Journal force residual relative to the force scale.
    pub residual: f64,
    pub reason: String,
}

impl Stall {
    fn new(u: &[f64], residual: f64, reason: &str) -> Self {
        Self { journal: [u[0], u[1]], residual, reason: reason.to_string() }
    }
}

/// Tries the methods in turn.
fn solve_inner(
    model: &mut BearingModel,
    ctx: &mut eval::Ctx<'_>,
    start: Option<&[f64]>,
    cancel: &dyn Cancel,
) -> Result<Progress<Found, Resume>, SolveError> {
    let cb = model.assembled_clearance;
    let n = model.n_dofs();
    if let LoadSpec::Position { eccentricity_ratio, angle_rad } = ctx.op.load {
        let journal = [eccentricity_ratio * cb * angle_rad.cos(), eccentricity_ratio * cb * angle_rad.sin()];
        let mut u = start.filter(|s| s.len() == n).map_or_else(|| vec![0.0; n], <[f64]>::to_vec);
        u[..2].copy_from_slice(&journal);
        let (pads, force) = eval::solve_all_pads(model, journal, &u, ctx).map_err(|(k, e)| match e {
            FilmError::Contact { h_min_m, .. } => {
                SolveError::Touchdown { pad: k, h_min_um: h_min_m * 1e6, eccentricity_ratio }
            }
            e => ctx.film_error(k, e),
        })?;
        let u = eval::assemble_u(model, journal, &pads);
        return Ok(Progress::Done(Found {
            u,
            pads,
            force,
            method: "prescribed journal position (pads solved)".into(),
        }));
    }

    // Initial guess: previous solution, else a small displacement along the load.
    let warm = start.filter(|s| s.len() == n && s.iter().all(|v| v.is_finite()));
    let u0 = warm.map_or_else(
        || {
            let mut u = vec![0.0; n];
            let dir = eval::load_direction(ctx.op);
            u[0] = 0.2 * cb * dir[0];
            u[1] = 0.2 * cb * dir[1];
            u
        },
        <[f64]>::to_vec,
    );
    let cold = ctx.params.placed_pads > 0 || warm.is_none();
    match coupled::coupled_newton(model, &u0, cold, ctx, cancel)? {
        Progress::Suspended(r) => return Ok(Progress::Suspended(r)),
        Progress::Done(Ok(found)) => return Ok(Progress::Done(found)),
        Progress::Done(Err(fail)) => {
            ctx.report.warn(format!("coupled Newton failed ({}); trying the fallbacks", fail.reason))
        }
    }
    // The fallbacks run to the end once started (their state is not a single iterate to resume from).
    fallback::run(model, &u0, ctx, &NoSuspend(cancel)).map(Progress::Done)
}
