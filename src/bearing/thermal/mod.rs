//! Thermohydrodynamic (THD) equilibrium: the static equilibrium and the thermal fields, iterated until the
//! viscosity field converges (model.md §6). This file holds the thermal model and its data (per-pad systems,
//! parameters, report); the outer loop is [`run`] ([`ThdRun`]).
//!
//! ## Loop
//! ```text
//! µ⁰ = µ(T_film of the case)                              (the isothermal equilibrium is iteration 0)
//! repeat k = 1, 2, …
//!   equilibrium with the nodal viscosity µᵏ⁻¹, warm-started from the previous journal/pad position
//!   per pad: film energy (+ pad conduction for BC2/BC3), one factorisation, three right-hand sides
//!            → film (and pad) temperatures affine in (T_in, T_j)           (thermal_pad.rs)
//!   all pads at once: groove mixing balance for every T_in and the journal condition for T_j
//!            (a dense (n_pads + 1) system: the pads' coupling through the grooves is solved exactly)
//!   T ← T_old + ω (T_new − T_old), Anderson-accelerated;  µᵏ = µ(T) at the film nodes
//! until max_nodes |µ(T_new) − µᵏ⁻¹| / µᵏ⁻¹ < tol
//! then (BC1) solve the pad conduction with the film temperature on its face; assemble the solution, whose
//! dynamic coefficients are the film's perturbation at the converged state (temperatures frozen).
//! ```
//!
//! ## Lightly loaded pads
//! The loop freezes the viscosity field at the film nodes while the equilibrium moves the pads. A lightly
//! loaded pad (offset pivot, thick diverging film) can have a moment curve whose maximum barely reaches zero;
//! the axial and circumferential viscosity variation can then remove its root altogether, and the pad force
//! jumps between a loaded and an unloaded branch, so no equilibrium exists for the frozen field. When that
//! happens, pads carrying less than [`LIGHT_PAD_SHARE`] of the load are given their mean film viscosity
//! (a uniform viscosity scales the pad's pressure and leaves its tilt root where the isothermal one is); the
//! report says which. Otherwise the temperature step is halved back towards the last field that worked.
//!
//! Inlet mixing and the journal temperature: [`crate::bearing::thermal::mixing`]; the acceleration: [`crate::bearing::thermal::anderson`].

use serde::{Deserialize, Serialize};
use web_time::Instant;

use crate::fem::supg::Stabilisation;
use crate::fem::SolverError;
use crate::mesh::pad3d::PadMesh;
use crate::model::{Case, CavitatedFilm, PadFilmBc};
use crate::physics::energy::{BalanceInputs, Exchange, FilmHeat, Injection, Oil};
use crate::physics::pad_conduction::{PadConduction, PadDirichletSolver, PadMaterial};

use crate::bearing::equilibrium::{Cancel, Equilibrium, EquilibriumParams, NoSuspend, Progress};
use crate::bearing::film::model::{BearingModel, OperatingPoint};
use crate::bearing::report::error::{Budget, Iteration, SolveError};
use crate::bearing::thermal::anderson::{flatten, unflatten, Anderson};
use crate::bearing::thermal::growth::{Growth, GrowthField, TehdModel, GROWTH_TOL};
use crate::bearing::thermal::mixing::inlet_and_journal;
use crate::bearing::thermal::pad_system::{PadTemperatures, PadThermal, ThermalSetup};

/// History depth of the Anderson acceleration of the thermal loop.
pub const ANDERSON_DEPTH: usize = 4;
/// Smallest damping of the temperature update the safeguard of the Anderson acceleration lowers ω to (each
/// outer iteration whose viscosity change grows halves it). Measured on Fillon A at five times its load
/// (S = 0.1, h_min 3.6 µm): damped fixed-point steps contract there at ω ≤ 0.3 (rate about 0.93 per step),
/// the undamped extrapolation does not.
pub const MIN_RELAXATION: f64 = 0.1;
/// Outer iterations of the plain Anderson loop (the former iteration budget) before the safeguard applies:
/// a loop that converged before converges as before (from the start, the safeguard made the compressor
/// bearing's 40 bar leading-edge injection, which the plain loop converges in 27 iterations through rises
/// of its change, spend 100 iterations).
pub const SAFEGUARD_AFTER: usize = 40;
/// Outer iterations of the safeguarded phase without the viscosity change falling below [`STALL_GAIN`]
/// times its best after which the loop gives up the Anderson extrapolation for plain damped steps
/// ([`PLAIN_RELAXATION`], still halved on growth and restored on falls). Where the extrapolation keeps
/// proposing fields whose images move away (Fillon A at S = 0.1, 40°: a change of 0.1–0.2 for 260
/// iterations), the damped steps contract (converged in 74 outer iterations).
pub const STALL_WINDOW: usize = 20;
/// See [`STALL_WINDOW`].
pub const STALL_GAIN: f64 = 0.5;
/// Damping of the plain steps a stalled loop falls back to ([`STALL_WINDOW`]).
pub const PLAIN_RELAXATION: f64 = 0.4;
/// Default iteration budget of the thermal loop. The safeguarded steps contract at about 0.93 per step where
/// they are needed ([`MIN_RELAXATION`]), so from a change of order 1e-1 at [`SAFEGUARD_AFTER`] the 1e-4
/// tolerance takes about 100 more: a budget of 100 stopped such loops short by construction (Fillon A at
/// S = 0.1: 20 of the convergence map's points converge in 102–224 iterations). A loop that converges
/// within 100 is unchanged.
pub const DEFAULT_MAX_ITERATIONS: usize = 300;
/// Halvings of a temperature update whose viscosity field has no equilibrium.
pub const MAX_BACKTRACKS: usize = 6;
/// Default time budget of the thermal loop [s]: about a hundred times what a THD solve of a shipped case
/// takes at the standard fidelity in a release build (docs/PERFORMANCE.md).
pub const DEFAULT_MAX_SECONDS: f64 = 120.0;
/// Load share below which a pad whose non-uniform viscosity leaves it without an equilibrium tilt is given
/// its mean film viscosity instead.
pub const LIGHT_PAD_SHARE: f64 = 0.1;

/// Settings of the thermal loop, with documented defaults.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ThermalParams {
    /// Largest nodal relative viscosity change at convergence (default 1e-4).
    pub viscosity_tol: f64,
    /// Iteration budget: outer iterations at most (default [`DEFAULT_MAX_ITERATIONS`]: [`SAFEGUARD_AFTER`] plain
    /// ones, then the safeguarded damped steps; an outer iteration of a preview-mesh THD solve takes
    /// milliseconds, and the time budget bounds the rest).
    pub max_iterations: usize,
    /// Time budget: computing time of the whole loop at most [s] (default [`DEFAULT_MAX_SECONDS`]; counted
    /// inside [`ThdRun::step`] only, so a caller that spreads the loop over frames is not charged for the
    /// time in between). An equilibrium running when it is spent is stopped at its next iteration.
    pub max_seconds: f64,
    /// Damping ω of the film temperature update (default 0.8).
    pub relaxation: f64,
    /// Stabilisation of the film energy equation (default plain SUPG: linear, so the loop's fixed point is
    /// smooth; [`Stabilisation::SupgCrosswind`] lags its capturing term by one outer iteration and can stall
    /// the loop in a ~1e-3 limit cycle).
    pub stabilisation: Stabilisation,
}

impl Default for ThermalParams {
    fn default() -> Self {
        Self {
            viscosity_tol: 1e-4,
            max_iterations: DEFAULT_MAX_ITERATIONS,
            max_seconds: DEFAULT_MAX_SECONDS,
            relaxation: 0.8,
            stabilisation: Stabilisation::Supg,
        }
    }
}

/// What the thermal loop did.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct ThermalReport {
    /// Outer (equilibrium + thermal) iterations.
    pub outer_iterations: usize,
    /// Largest nodal relative viscosity change after each outer iteration.
    pub viscosity_change: Vec<f64>,
    pub converged: bool,
    pub stop_reason: String,
    /// Energy balance closure of the converged state (P − H − C)/P, whole bearing.
    pub energy_balance_closure: f64,
    /// Worst closure over the pads.
    pub energy_balance_worst_pad: f64,
    pub equilibrium_iterations: usize,
    /// Pad (inner) iterations of those equilibria.
    pub inner_iterations: usize,
    pub film_solves: usize,
    /// Reynolds factorisations of those equilibria.
    pub equilibrium_factorizations: usize,
    pub thermal_factorizations: usize,
    pub seconds: f64,
    pub equilibrium_seconds: f64,
    /// Film energy, pad conduction and mixing (all iterations).
    pub thermal_seconds: f64,
    /// Of which the final BC1 pad conduction solves.
    pub pad_conduction_seconds: f64,
    /// TEHD: largest change of the films' thermal growth after each outer iteration [m] (empty without
    /// thermal growth; the loop also needs it below `GROWTH_TOL` × the assembled clearance).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub growth_change_m: Vec<f64>,
    /// TEHD: journal growth α_j R (T_j − T_ref) and the range of the pads' film-face growth in the converged
    /// films [m].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub journal_growth_m: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pad_growth_range_m: Option<[f64; 2]>,
    /// TEHD: outward displacement of each pad's pivot (of a fixed sector's bore) by the housing's growth
    /// α_h R_p (T_h − T_ref) [m] (empty without housing growth).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub housing_growth_m: Vec<f64>,
    /// TEHD, of `thermal_seconds`: building the growth model (pad solids assembled and factorised, thermal-load
    /// operators) and the growth steps of every outer iteration (pad conduction for BC1, thermal loads,
    /// solves) [s].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub growth_setup_seconds: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub growth_seconds: Option<f64>,
    pub warnings: Vec<String>,
}

/// Thermal model of the bearing: per-pad systems built once per geometry and mesh.
#[derive(Debug, Clone)]
pub struct ThermalModel {
    pub pads: Vec<PadThermal>,
    /// `upstream[k]`: the pad whose trailing edge feeds the groove ahead of pad k.
    pub upstream: Vec<usize>,
    /// BC1 pad conduction solvers, one per distinct pad mesh (built on first use), and which one each pad
    /// uses.
    pad_solvers: Vec<PadDirichletSolver>,
    pad_solver_of: Vec<Option<usize>>,
}

impl ThermalModel {
    /// Builds the pad meshes and the thermal systems of a bearing model.
    ///
    /// # Errors
    /// A 360° sector (no inlet), or a failed symbolic factorisation.
    pub fn new(case: &Case, model: &BearingModel) -> Result<Self, SolveError> {
        let b = &case.bearing;
        let mut pads = Vec::with_capacity(model.pads.len());
        for (k, (pm, pad)) in model.pads.iter().zip(&b.pads).enumerate() {
            let film = &pm.film;
            if film.geom.grid.periodic {
                return Err(SolveError::Invalid(format!(
                    "pad {k}: the thermal model needs sectors with a leading edge (a 360° bore has no oil inlet)"
                )));
            }
            let conduction = (pad.thickness_m > 0.0).then(|| {
                let mesh = pm.solid.clone().unwrap_or_else(|| {
                    std::sync::Arc::new(PadMesh::extrude(
                        &film.geom.grid,
                        b.journal_radius_m,
                        pad.leading_edge_rad,
                        pad.bore_radius_m(b.journal_radius_m),
                        pad.thickness_m,
                        case.mesh.pad_radial_elements,
                    ))
                });
                PadConduction::new(mesh)
            });
            if conduction.is_none() && !matches!(case.thermal.pad_film_bc, PadFilmBc::Bc1) {
                return Err(SolveError::Invalid(format!(
                    "pad {k} has no pad solid (a fixed sector without thickness): use thermal.pad_film_bc = \"bc1\""
                )));
            }
            pads.push(
                PadThermal::new(film, conduction)
                    .map_err(|e| SolveError::Invalid(format!("pad {k} thermal system: {e}")))?,
            );
        }
        // Upstream pad: the one whose leading edge comes last before pad k's, going against the rotation.
        let n = b.pads.len();
        let le: Vec<f64> = b.pads.iter().map(|p| p.leading_edge_rad.rem_euclid(std::f64::consts::TAU)).collect();
        let upstream = (0..n)
            .map(|k| {
                (0..n)
                    .filter(|&j| j != k || n == 1)
                    .min_by(|&a, &c| {
                        let da = (le[k] - le[a]).rem_euclid(std::f64::consts::TAU);
                        let dc = (le[k] - le[c]).rem_euclid(std::f64::consts::TAU);
                        let da = if da == 0.0 { std::f64::consts::TAU } else { da };
                        let dc = if dc == 0.0 { std::f64::consts::TAU } else { dc };
                        da.total_cmp(&dc)
                    })
                    .unwrap_or(k)
            })
            .collect();
        let n_pads = pads.len();
        Ok(Self { pads, upstream, pad_solvers: Vec::new(), pad_solver_of: vec![None; n_pads] })
    }

    /// BC1 pad conduction of pad k with the film temperature `film_t` on its face (`None` without a pad
    /// solid). Identical pads share one solver and its factorisation.
    ///
    /// # Errors
    /// A failed factorisation.
    pub fn pad_bc1(
        &mut self,
        k: usize,
        film_t: &[f64],
        material: &PadMaterial,
    ) -> Result<Option<Vec<f64>>, SolverError> {
        let Some(mesh) = self.pads[k].conduction.as_ref().map(|c| &c.mesh) else { return Ok(None) };
        if self.pad_solver_of[k].is_none() {
            let shared = (0..self.pads.len()).find(|&j| {
                self.pad_solver_of[j].is_some()
                    && self.pads[j].conduction.as_ref().is_some_and(|c| c.mesh.same_shape(mesh))
            });
            self.pad_solver_of[k] = Some(match shared {
                Some(j) => self.pad_solver_of[j].unwrap_or_default(),
                None => {
                    self.pad_solvers.push(PadDirichletSolver::new(mesh)?);
                    self.pad_solvers.len() - 1
                }
            });
        }
        let i = self.pad_solver_of[k].unwrap_or_default();
        self.pads[k].solve_pad_bc1(&mut self.pad_solvers[i], film_t, material)
    }

    /// Numeric factorisations of the BC1 pad solvers so far.
    #[must_use]
    pub fn pad_factorizations(&self) -> usize {
        self.pad_solvers.iter().map(|s| s.factorizations).sum()
    }
}

/// Thermal state of one pad at convergence.
#[derive(Debug, Clone, PartialEq)]
pub struct PadThermalState {
    pub inlet_temperature_c: f64,
    /// Flow-weighted trailing-edge temperature.
    pub outlet_temperature_c: f64,
    /// Film temperature at the film nodes.
    pub film_c: Vec<f64>,
    /// Pad temperature at every pad node (layer-major, layer 0 = film face); `None` without a pad solid.
    pub pad_c: Option<Vec<f64>>,
    /// Layer radii of the pad mesh [m].
    pub pad_radii_m: Vec<f64>,
    pub heat: FilmHeat,
    /// Heat the pad gives to its surroundings [W] (whole pad).
    pub pad_to_surroundings_w: f64,
    /// Oil in through the leading edge / out through the trailing edge [m³/s].
    pub inflow_m3_per_s: f64,
    pub outflow_m3_per_s: f64,
    /// Film fraction θ at the film nodes.
    pub film_fraction: Vec<f64>,
    /// Oil-filled (θ-weighted) area mean of the film temperature.
    pub film_mean_c: f64,
    /// ∫ θ dA [m²] (whole pad), the weight of `film_mean_c`.
    pub oil_area_m2: f64,
}

/// Converged THD state.
#[derive(Debug, Clone, PartialEq)]
pub struct ThdState {
    pub equilibrium: Equilibrium,
    /// The operating point with the converged nodal viscosities.
    pub op: OperatingPoint,
    pub pads: Vec<PadThermalState>,
    pub journal_temperature_c: f64,
    pub heat: FilmHeat,
    pub report: ThermalReport,
    /// The thermal growth in the films of the converged state (TEHD), installed to assemble the solution.
    pub growth: Option<GrowthField>,
    /// The Hertz pivots' load iteration at the converged state (their tangent stiffnesses linearise it).
    pub pivots: Option<crate::bearing::equilibrium::pivots::HertzPivots>,
}

fn setup(case: &Case, op: &OperatingPoint, k: usize, stabilisation: Stabilisation) -> ThermalSetup {
    let l = &case.lubricant;
    let t = &case.thermal;
    ThermalSetup {
        oil: Oil {
            density: l.density_kg_per_m3,
            specific_heat: l.specific_heat_j_per_kg_k,
            conductivity: l.conductivity_w_per_m_k,
        },
        injection: Injection {
            pressure: op.injection_pressure[k],
            viscosity: op.injection_viscosity,
            temperature_c: case.operating.injection_temperature_c,
        },
        exchange: match t.pad_film_bc {
            PadFilmBc::Bc1 => Exchange::Adiabatic,
            PadFilmBc::Bc2 { h_w_per_m2_k } => Exchange::Convective { h: h_w_per_m2_k },
            PadFilmBc::Bc3 => Exchange::Parabolic,
        },
        material: PadMaterial {
            conductivity: t.pad_conductivity_w_per_m_k,
            convection: t.convection_w_per_m2_k,
            ambient_c: t.ambient_temperature_c,
        },
        stabilisation,
        striated: t.cavitated_film == CavitatedFilm::Striated,
    }
}

/// Viscosity at the film nodes for temperatures `t`; `uniform`: the viscosity at their mean instead.
fn nodal_viscosity(law: &crate::model::ViscosityLaw, t: &[f64], uniform: bool) -> Vec<f64> {
    if uniform {
        #[allow(clippy::cast_precision_loss)]
        let mean = t.iter().sum::<f64>() / t.len().max(1) as f64;
        vec![law.at(mean); t.len()]
    } else {
        t.iter().map(|&x| law.at(x)).collect()
    }
}

/// Inexact early equilibria: while the viscosity field is still far from converged, solving the
/// equilibrium to 1e-9 is wasted; the tolerance follows the last viscosity change (full precision once the
/// change is within ten times the thermal tolerance, so the converged state is exact).
fn equilibrium_params(last_change: f64, params: &ThermalParams) -> EquilibriumParams {
    let full = EquilibriumParams::default();
    if last_change.is_finite() && last_change > 10.0 * params.viscosity_tol {
        EquilibriumParams {
            force_tol: (1e-3 * last_change).clamp(full.force_tol, 1e-4),
            pad_tol: (1e-4 * last_change).clamp(full.pad_tol, 1e-5),
            ..full
        }
    } else {
        full
    }
}

/// The equilibrium warm-started from `u`, retried from scratch if that fails, to its end: the resumable
/// form's rule ([`resumable::equilibrium_part`]) without pauses.
fn warm_equilibrium(
    model: &mut BearingModel,
    op: &OperatingPoint,
    params: EquilibriumParams,
    u: Option<&[f64]>,
    cancel: &dyn Cancel,
) -> Result<Equilibrium, SolveError> {
    let pending = resumable::PendingEquilibrium::new(params, u.map(<[f64]>::to_vec));
    match resumable::equilibrium_part(model, op, pending, &NoSuspend(cancel))? {
        Progress::Done(eq) => Ok(eq),
        // NoSuspend never asks for a pause.
        Progress::Suspended(p) => {
            Err(SolveError::Invalid(format!("equilibrium paused unexpectedly after {} parts", p.parts())))
        }
    }
}

/// Each pad's share of the total pad load.
fn load_shares(eq: &Equilibrium) -> Vec<f64> {
    let total: f64 = eq.pads.iter().map(|p| p.forces[0].hypot(p.forces[1])).sum::<f64>().max(f64::MIN_POSITIVE);
    eq.pads.iter().map(|p| p.forces[0].hypot(p.forces[1]) / total).collect()
}

/// Thermal solves of every pad at the films' last state, then the inlet and journal temperatures:
/// (per-pad solutions, T_in per pad, T_j, film temperatures).
type FilmTemperatures = (Vec<PadTemperatures>, Vec<f64>, f64, Vec<Vec<f64>>);

fn film_temperatures(
    model: &BearingModel,
    thermal: &mut ThermalModel,
    case: &Case,
    op: &OperatingPoint,
    params: &ThermalParams,
) -> Result<FilmTemperatures, SolveError> {
    let n = model.pads.len();
    let mut sols = Vec::with_capacity(n);
    for k in 0..n {
        let s = setup(case, op, k, params.stabilisation);
        let inp = op.film_inputs(k);
        let sol = thermal.pads[k]
            .solve(&model.pads[k].film, &inp, &s)
            .map_err(|e| SolveError::Invalid(format!("pad {k} thermal solve: {e}")))?;
        sols.push(sol);
    }
    let (t_in, t_j) = inlet_and_journal(case, &sols, &thermal.upstream)?;
    let t_new: Vec<Vec<f64>> = (0..n).map(|k| sols[k].film(t_in[k], t_j)).collect();
    if t_new.iter().flatten().any(|v| !v.is_finite()) {
        return Err(SolveError::Invalid("non-finite film temperature in the thermal loop".into()));
    }
    Ok((sols, t_in, t_j, t_new))
}

/// Largest relative viscosity change between two temperature fields.
fn viscosity_change(law: &crate::model::ViscosityLaw, a: &[Vec<f64>], b: &[Vec<f64>]) -> f64 {
    a.iter().flatten().zip(b.iter().flatten()).fold(0.0_f64, |m, (&x, &y)| m.max((law.at(x) / law.at(y) - 1.0).abs()))
}

/// Solves the THD equilibrium of a case on an existing model (all outer iterations of a [`ThdRun`]).
///
/// # Errors
/// As [`ThdRun::step`].
pub fn solve_thd(
    model: &mut BearingModel,
    thermal: &mut ThermalModel,
    case: &Case,
    params: ThermalParams,
    start: Option<&[f64]>,
    cancel: &dyn Cancel,
) -> Result<ThdState, SolveError> {
    let mut run = ThdRun::new(model, thermal, case, params, start);
    loop {
        if let Some(state) = run.step(model, thermal, case, cancel)? {
            return Ok(state);
        }
    }
}

pub mod anderson;
pub mod growth;
pub mod growth_solid;
pub mod mixing;
pub mod pad_system;
pub mod resumable;
mod run;
pub use run::ThdRun;
