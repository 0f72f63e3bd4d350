//! Errors of a bearing solve. Each says what failed and where; none is ever replaced by NaN.

use crate::fem::SolverError;
use crate::model::CaseError;
use crate::physics::hertz::HertzError;
use crate::physics::pad_elastic::ElasticError;
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

/// The budget that stopped an iteration. Budgets count work, never time, so the same case stops at the same
/// point on an idle and on a busy machine; each names the case key that raises it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum Budget {
    /// At most this many outer iterations (`thermal.max_iterations`).
    Iterations(usize),
    /// At most `per_pad` film solves per pad, `per_pad × pads` in all (`physics.max_film_solves_per_pad`).
    FilmSolves { per_pad: usize, pads: usize },
}

impl Budget {
    /// The case key that raises this budget.
    #[must_use]
    pub fn key(self) -> &'static str {
        match self {
            Self::Iterations(_) => "thermal.max_iterations",
            Self::FilmSolves { .. } => "physics.max_film_solves_per_pad",
        }
    }
}

impl std::fmt::Display for Budget {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match *self {
            Self::Iterations(n) => write!(f, "iteration budget ({n} outer iterations, {} = {n})", self.key()),
            Self::FilmSolves { per_pad, pads } => write!(
                f,
                "work budget ({} film solves: {} = {per_pad} per pad × {pads} pads)",
                per_pad.saturating_mul(pads),
                self.key()
            ),
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
    /// A trial position of the search closed the film of a pad (h ≤ 0 somewhere, or a tilt at the end of its
    /// admissible range, where h reaches 0) and no method found a state
    /// with an open film that carries the load. Not touchdown: the closed film belongs to a trial, not to a
    /// state of the bearing (a pad so flexible or so grown that it is pressed onto the journal, a film
    /// pressure that pushes the pads into it).
    #[error(
        "no equilibrium: the film of pad {pad} closed at a trial position of the search (h {h_min_um:.3} µm at \
         θ = {theta_deg:.1}°, journal last at ε = {eccentricity_ratio:.3}) and no method found an open film that \
         carries the load; check the pads' stiffness, thermal growth and the injection pressure"
    )]
    FilmClosed { pad: usize, h_min_um: f64, theta_deg: f64, eccentricity_ratio: f64 },
    /// A prescribed journal position (`operating.eccentricity_ratio`) at which a pad's film closes (h ≤ 0):
    /// the journal would cut into the pad. Not touchdown, which is a load the film cannot carry; the position
    /// is not one the bearing can take.
    #[error(
        "the prescribed position ε = {eccentricity_ratio:.3} closes the film of pad {pad} (h {h_min_um:.3} µm at \
         θ = {theta_deg:.1}°): the journal would cut into the pad; give a smaller operating.eccentricity_ratio"
    )]
    PositionClosesFilm { pad: usize, h_min_um: f64, theta_deg: f64, eccentricity_ratio: f64 },
    /// A load on a journal that does not turn, with no injection: the steady film has no pressure source
    /// (no wedge without sliding, no orifice pressure), so no position carries the load. Found before the
    /// first film solve.
    #[error(
        "no rotation: at 0 rpm with no injection pressure the film has no pressure source and cannot carry the \
         load of {load_n:.3e} N at any position; give operating.speed_rpm > 0, or inject \
         (operating.injection_pressure_bar)"
    )]
    NoRotation { load_n: f64 },
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
    NotConverged { iterations: usize, residual: f64, reason: StallReason },
    /// An iteration used up its work budget before converging (never reported as anything else: a budget
    /// says nothing about the physics).
    #[error(
        "{what} not converged: stopped by its {budget} after {iterations} iterations, {} {residual:.2e}; this is a \
         work limit, not a result: raise {} (or coarsen the mesh) to let it go on",
        what.residual_name(),
        budget.key()
    )]
    BudgetExceeded { what: Iteration, budget: Budget, iterations: usize, residual: f64 },
    /// Stopped from outside (a superseded interactive job, an interrupted command): no result, and no
    /// statement about the case.
    #[error("solve cancelled (stopped from outside before it finished; not a property of the case)")]
    Cancelled,
    /// A pad's thermal system (film energy, pad conduction) could not be factorised or solved.
    #[error("pad {pad} {system}: {error}")]
    PadThermal { pad: usize, system: ThermalSystem, error: SolverError },
    /// A pad's elastic solid (its bending modes, its thermal growth) could not be built or solved.
    #[error("pad {pad} {what}: {error}")]
    PadElastic { pad: usize, what: ElasticWork, error: ElasticError },
    /// A Hertz pivot contact outside the theory's range at the load its pad carries.
    #[error("pad {pad} pivot contact: {error}")]
    PivotContact { pad: usize, error: HertzError },
    /// A coupled system of the bearing is singular.
    #[error("{0}")]
    Singular(SingularSystem),
    /// The thermal loop computed a non-finite film temperature.
    #[error("non-finite film temperature in the thermal loop")]
    NonFiniteTemperature,
    /// The case asks for something this model of it cannot do (validation lets it through because it depends
    /// on what is computed).
    #[error("{0}")]
    Unsupported(Unsupported),
    /// FRFs of a case without a `[hydraulics]` section.
    #[error("the case has no [hydraulics] section (valve, ports, lines): nothing to compute FRFs of")]
    NoHydraulics,
    /// A broken invariant of the solver (a bug): what was expected.
    #[error("internal error: {0}")]
    Internal(InternalError),
}

/// Why a method of the equilibrium stopped short of the tolerance.
#[derive(Debug, Clone, PartialEq, Error, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum StallReason {
    #[error("film closes at the start")]
    FilmClosesAtStart,
    #[error("{0} iterations")]
    IterationLimit(usize),
    #[error("line search found no decrease")]
    NoDecrease,
    #[error("singular Jacobian")]
    SingularJacobian,
    /// A load component of `component_n` [N] acts along `axis_deg`, where the bearing has no stiffness.
    #[error(
        "a load component of {component_n:.3e} N acts along the {axis_deg:.0}° axis, where the bearing has no stiffness"
    )]
    NoStiffnessAlong { axis_deg: f64, component_n: f64 },
    #[error("the bearing has no stiffness at this position")]
    NoStiffness,
    #[error("non-finite bearing stiffness or failed singular value decomposition")]
    NonFiniteStiffness,
    #[error("the force along a ray inside the angular bracket jumps over zero")]
    RayForceJumps,
    #[error("a ray without a restoring root inside the angular bracket")]
    RayWithoutRoot,
    #[error("no load to search along")]
    NoLoad,
    #[error("the force along the load jumps across the load")]
    ForceJumpsAcrossLoad,
    #[error("no restoring root along the load")]
    NoRootAlongLoad,
    #[error("no sign change of the transverse residual within 90° of the load")]
    NoTransverseSignChange,
    #[error("the force across the balancing rays jumps across zero")]
    BalancingRaysJump,
    #[error("angular bracket exhausted")]
    BracketExhausted,
    /// The search stopped on a direction without stiffness although the pads surround the load.
    #[error("{reason} (pads surround the load, yet the search stopped with no stiffness along {axis_deg:.0}°)")]
    StoppedWithoutStiffness { reason: Box<StallReason>, axis_deg: f64 },
    /// No method was tried (an empty stall).
    #[error("no method tried")]
    None,
}

/// A pad's thermal system.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ThermalSystem {
    /// Film energy (with pad conduction for BC2/BC3), assembled and factorised.
    Assembly,
    /// Its solve in an outer iteration.
    Solve,
    /// The pad's conduction with the film temperature on its face (BC1).
    Conduction,
}

impl std::fmt::Display for ThermalSystem {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Self::Assembly => "thermal system",
            Self::Solve => "thermal solve",
            Self::Conduction => "conduction",
        })
    }
}

/// What a pad's elastic solid was computing.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ElasticWork {
    Modes,
    ThermalGrowth,
}

impl std::fmt::Display for ElasticWork {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Self::Modes => "elastic modes",
            Self::ThermalGrowth => "thermal growth",
        })
    }
}

/// A coupled system of the bearing that is singular.
#[derive(Debug, Clone, PartialEq, Error, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SingularSystem {
    #[error("the inlet mixing / journal balance is singular (no oil flows through the bearing?)")]
    InletMixing,
    #[error("the coupled valve–line–bearing system is singular at {frequency_hz} Hz")]
    ValveLineBearing { frequency_hz: f64 },
}

/// What the model of a case cannot do.
#[derive(Debug, Clone, PartialEq, Eq, Error, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Unsupported {
    #[error("pad {pad}: the thermal model needs sectors with a leading edge (a 360° bore has no oil inlet)")]
    ThermalWithoutInlet { pad: usize },
    #[error("pad {pad} has no pad solid (a fixed sector without thickness): use thermal.pad_film_bc = \"bc1\"")]
    NoPadSolid { pad: usize },
    #[error("port {port} feeds pad {pad}, but the bearing has {pads} pads")]
    PortPadMissing { port: usize, pad: usize, pads: usize },
    #[error("pad {pad} is fed by ports {first} and {second}")]
    PadFedTwice { pad: usize, first: usize, second: usize },
}

/// A broken invariant of the solver.
#[derive(Debug, Clone, PartialEq, Eq, Error, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum InternalError {
    /// A stage read another stage's output it may not read (a bug in the registration order).
    #[error("stage '{reader}' cannot read stage '{stage}': {why}")]
    StageRead { reader: String, stage: String, why: String },
    /// A wanted stage published nothing.
    #[error("stage '{stage}' published no output")]
    Unpublished { stage: String },
    /// A computation that never pauses paused.
    #[error("{what} paused unexpectedly after {parts} parts")]
    Paused { what: String, parts: usize },
    /// A number of pad structures that is not the model's number of pads.
    #[error("{structures} pad structures for a model of {pads} pads")]
    StructureCount { structures: usize, pads: usize },
    /// A pad structure over other coordinates than the model's pad.
    #[error("pad {pad}: the structure's coordinates differ from the model's")]
    StructureCoordinates { pad: usize },
    /// A pivot contact's pad has no radial pivot coordinate in the model.
    #[error("pad {pad}: a pivot contact without the radial pivot coordinate in the model")]
    ContactWithoutCoordinate { pad: usize },
}
