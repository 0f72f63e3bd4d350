//! The equilibrium's data: settings ([`EquilibriumParams`]), the converged state of each pad ([`PadState`])
//! and of the bearing ([`Equilibrium`]), where a suspended solve resumes ([`Resume`]), what a method found or
//! why it stalled, and the load-share thresholds every method uses.

use nalgebra::DMatrix;

use crate::bearing::report::error::StallReason;
use crate::bearing::report::warning::Method;
use crate::bearing::report::SolveReport;
use crate::physics::reynolds::FilmLinearization;

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

/// A film thinner than this fraction of Cb when every method has failed means the load cannot be carried.
pub const TOUCHDOWN_FRACTION: f64 = 0.05;

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
    /// Work budget: film solves per pad over all methods and fallbacks (bounds the work to fail; the case key
    /// `physics.max_film_solves_per_pad`). Work, not time: the outcome does not depend on the machine's load.
    pub max_film_solves_per_pad: usize,
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
            max_film_solves_per_pad: DEFAULT_MAX_FILM_SOLVES_PER_PAD,
            placed_pads: 0,
        }
    }
}

/// The default of `physics.max_film_solves_per_pad` (its schema row's).
pub const DEFAULT_MAX_FILM_SOLVES_PER_PAD: usize = match crate::key!("physics.max_film_solves_per_pad").default {
    crate::model::schema::Fallback::Count(n) => n,
    _ => panic!("physics.max_film_solves_per_pad: a count"),
};

impl EquilibriumParams {
    /// The defaults, with the case's work budget (`physics.max_film_solves_per_pad`).
    #[must_use]
    pub fn of(case: &crate::model::Case) -> Self {
        Self { max_film_solves_per_pad: case.physics.max_film_solves_per_pad, ..Self::default() }
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

/// A state the methods found: coordinates, pad states, film force, and the method's name.
pub(super) struct Found {
    pub u: Vec<f64>,
    pub pads: Vec<PadState>,
    pub force: [f64; 2],
    pub method: Method,
}

/// Why a method stopped short of the tolerance, and where.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Stall {
    pub journal: [f64; 2],
    /// Journal force residual relative to the force scale.
    pub residual: f64,
    pub reason: StallReason,
}

impl Stall {
    pub(super) fn new(u: &[f64], residual: f64, reason: StallReason) -> Self {
        Self { journal: [u[0], u[1]], residual, reason }
    }
}
