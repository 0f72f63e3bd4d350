//! Thermohydrodynamic (THD) equilibrium: the static equilibrium and the thermal fields, iterated until the
//! viscosity field converges (model.md §6).
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
//! Inlet mixing and the journal temperature: [`super::mixing`]; the acceleration: [`super::anderson`].

use serde::Serialize;
use web_time::Instant;

use crate::fem::supg::Stabilisation;
use crate::mesh::pad3d::PadMesh;
use crate::model::{Case, CavitatedFilm, PadFilmBc};
use crate::physics::energy::{BalanceInputs, Exchange, FilmHeat, Injection, Oil};
use crate::fem::SolverError;
use crate::physics::pad_thermal::{PadConduction, PadDirichletSolver, PadMaterial};

use super::equilibrium::{solve_equilibrium, Cancel, Equilibrium, EquilibriumParams};
use super::error::{Budget, Iteration, SolveError};
use super::model::{BearingModel, OperatingPoint};
use super::anderson::{flatten, unflatten, Anderson};
use super::mixing::inlet_and_journal;
use super::tehd::{self, Growth, GrowthField, TehdModel, GROWTH_TOL};
use super::thermal_pad::{PadTemperatures, PadThermal, ThermalSetup};

/// History depth of the Anderson acceleration of the thermal loop.
pub const ANDERSON_DEPTH: usize = 4;
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
    /// Iteration budget: outer iterations at most (default 40).
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
        Self { viscosity_tol: 1e-4, max_iterations: 40, max_seconds: DEFAULT_MAX_SECONDS, relaxation: 0.8, stabilisation: Stabilisation::Supg }
    }
}

/// What the thermal loop did.
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
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
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub growth_change_m: Vec<f64>,
    /// TEHD: journal growth α_j R (T_j − T_ref) and the range of the pads' film-face growth in the converged
    /// films [m].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub journal_growth_m: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pad_growth_range_m: Option<[f64; 2]>,
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
            pads.push(PadThermal::new(film, conduction).map_err(|e| SolveError::Invalid(format!("pad {k} thermal system: {e}")))?);
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
    pub fn pad_bc1(&mut self, k: usize, film_t: &[f64], material: &PadMaterial) -> Result<Option<Vec<f64>>, SolverError> {
        let Some(mesh) = self.pads[k].conduction.as_ref().map(|c| &c.mesh) else { return Ok(None) };
        if self.pad_solver_of[k].is_none() {
            let shared = (0..self.pads.len()).find(|&j| {
                self.pad_solver_of[j].is_some() && self.pads[j].conduction.as_ref().is_some_and(|c| c.mesh.same_shape(mesh))
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
}

fn setup(case: &Case, op: &OperatingPoint, k: usize, stabilisation: Stabilisation) -> ThermalSetup {
    let l = &case.lubricant;
    let t = &case.thermal;
    ThermalSetup {
        oil: Oil { density: l.density_kg_per_m3, specific_heat: l.specific_heat_j_per_kg_k, conductivity: l.conductivity_w_per_m_k },
        injection: Injection { pressure: op.injection_pressure[k], viscosity: op.injection_viscosity, temperature_c: case.operating.injection_temperature_c },
        exchange: match t.pad_film_bc {
            PadFilmBc::Bc1 => Exchange::Adiabatic,
            PadFilmBc::Bc2 { h_w_per_m2_k } => Exchange::Convective { h: h_w_per_m2_k },
            PadFilmBc::Bc3 => Exchange::Parabolic,
        },
        material: PadMaterial { conductivity: t.pad_conductivity_w_per_m_k, convection: t.convection_w_per_m2_k, ambient_c: t.ambient_temperature_c },
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
        EquilibriumParams { force_tol: (1e-3 * last_change).clamp(full.force_tol, 1e-4), pad_tol: (1e-4 * last_change).clamp(full.pad_tol, 1e-5), ..full }
    } else {
        full
    }
}

/// The equilibrium warm-started from `u`, retried from scratch if that fails.
fn warm_equilibrium(model: &mut BearingModel, op: &OperatingPoint, params: EquilibriumParams, u: Option<&[f64]>, cancel: &dyn Cancel) -> Result<Equilibrium, SolveError> {
    match solve_equilibrium(model, op, params, u, cancel) {
        Err(SolveError::Cancelled) => Err(SolveError::Cancelled),
        Err(_) if u.is_some() => solve_equilibrium(model, op, params, None, cancel),
        r => r,
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

fn film_temperatures(model: &BearingModel, thermal: &mut ThermalModel, case: &Case, op: &OperatingPoint, params: &ThermalParams) -> Result<FilmTemperatures, SolveError> {
    let n = model.pads.len();
    let mut sols = Vec::with_capacity(n);
    for k in 0..n {
        let s = setup(case, op, k, params.stabilisation);
        let inp = op.film_inputs(k);
        let sol = thermal.pads[k].solve(&model.pads[k].film, &inp, &s).map_err(|e| SolveError::Invalid(format!("pad {k} thermal solve: {e}")))?;
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

/// The THD loop as a resumable computation: one [`ThdRun::step`] is one outer iteration (an equilibrium at
/// the current viscosity field, then the film and pad temperatures), so a caller without threads (the web
/// build) can spread a THD solve over frames.
///
/// Robustness: the temperature update is Anderson-accelerated (depth [`ANDERSON_DEPTH`], damping ω); if the
/// equilibrium cannot be found with a proposed viscosity field (e.g. a lightly loaded pad whose moment
/// curve loses its root), the proposal is halved back towards the last field that worked, up to
/// [`MAX_BACKTRACKS`] times, and the history is restarted.
pub struct ThdRun {
    t0: Instant,
    params: ThermalParams,
    op: OperatingPoint,
    report: ThermalReport,
    /// Coordinates of the last equilibrium (warm start of the next).
    u: Option<Vec<f64>>,
    factorizations0: usize,
    /// The isothermal temperature field (the start).
    t_iso: Vec<Vec<f64>>,
    /// Temperatures whose viscosity gave the last successful equilibrium (None: the isothermal start), and
    /// the proposal for the next one.
    t_ok: Option<Vec<Vec<f64>>>,
    t_try: Option<Vec<Vec<f64>>>,
    anderson: Anderson,
    backtracks: usize,
    last_change: f64,
    /// Pads whose film sees its mean viscosity only (see the module documentation), and the load shares of
    /// the last equilibrium.
    uniform: Vec<bool>,
    shares: Vec<f64>,
    /// Computing time spent inside [`ThdRun::step`] so far [s] (the time budget's count).
    work_seconds: f64,
    /// TEHD ([`super::tehd`]): the growth model (built on first use), the growth in the films of the current
    /// outer iteration, and the one the last temperatures give (installed at the next iteration).
    tehd: Option<TehdModel>,
    growth: Option<GrowthField>,
    growth_next: Option<GrowthField>,
}

/// Forwards the caller's cancellation and suspension, and cancels once a time budget is spent.
struct Deadline<'a> {
    inner: &'a dyn Cancel,
    /// `None`: no limit (an infinite or unrepresentable budget).
    until: Option<Instant>,
}

impl<'a> Deadline<'a> {
    fn after(inner: &'a dyn Cancel, seconds: f64) -> Self {
        let until = std::time::Duration::try_from_secs_f64(seconds.max(0.0)).ok().and_then(|d| Instant::now().checked_add(d));
        Self { inner, until }
    }
    fn expired(&self) -> bool {
        self.until.is_some_and(|t| Instant::now() >= t)
    }
}

impl Cancel for Deadline<'_> {
    fn cancelled(&self) -> bool {
        self.inner.cancelled() || self.expired()
    }
    fn suspend(&self) -> bool {
        self.inner.suspend()
    }
}

impl ThdRun {
    #[must_use]
    pub fn new(model: &BearingModel, thermal: &mut ThermalModel, case: &Case, params: ThermalParams, start: Option<&[f64]>) -> Self {
        let n = model.pads.len();
        let factorizations0: usize = thermal.pads.iter().map(|p| p.factorizations).sum();
        for pt in &mut thermal.pads {
            pt.t_prev = None;
        }
        Self {
            t0: Instant::now(),
            params,
            op: OperatingPoint::isothermal(case),
            report: ThermalReport::default(),
            u: start.map(<[f64]>::to_vec),
            factorizations0,
            t_iso: model.pads.iter().map(|p| vec![case.operating.film_temperature_c; p.film.geom.n_nodes()]).collect(),
            t_ok: None,
            t_try: None,
            anderson: Anderson::new(ANDERSON_DEPTH, params.relaxation),
            backtracks: 0,
            last_change: f64::INFINITY,
            uniform: vec![false; n],
            shares: vec![1.0; n],
            work_seconds: 0.0,
            tehd: None,
            growth: None,
            growth_next: None,
        }
    }

    /// Outer iterations done so far.
    #[must_use]
    pub fn outer_iterations(&self) -> usize {
        self.report.outer_iterations
    }

    /// One outer iteration; `Some` with the converged state when the loop has finished. Use the same model,
    /// thermal model and case as [`ThdRun::new`].
    ///
    /// # Errors
    /// Equilibrium failures, a singular thermal system, or a loop that spends its iteration or time budget
    /// ([`SolveError::BudgetExceeded`], saying which).
    pub fn step(&mut self, model: &mut BearingModel, thermal: &mut ThermalModel, case: &Case, cancel: &dyn Cancel) -> Result<Option<ThdState>, SolveError> {
        if cancel.cancelled() {
            return Err(SolveError::Cancelled);
        }
        let time_budget = Budget::Seconds(self.params.max_seconds);
        if self.work_seconds >= self.params.max_seconds {
            return Err(self.budget_exceeded(time_budget));
        }
        let started = Instant::now();
        let deadline = Deadline::after(cancel, self.params.max_seconds - self.work_seconds);
        let result = self.outer_iteration(model, thermal, case, &deadline);
        if self.growth.is_some() || self.growth_next.is_some() {
            // The films are shared with other stages: they hold the growth only while the loop works.
            tehd::clear(model);
        }
        self.work_seconds += started.elapsed().as_secs_f64();
        match result {
            Err(SolveError::Cancelled) if !cancel.cancelled() && deadline.expired() => Err(self.budget_exceeded(time_budget)),
            r => r,
        }
    }

    fn budget_exceeded(&self, budget: Budget) -> SolveError {
        SolveError::BudgetExceeded {
            what: Iteration::Thermal,
            budget,
            iterations: self.report.outer_iterations,
            seconds: self.work_seconds,
            residual: self.last_change,
        }
    }

    fn outer_iteration(&mut self, model: &mut BearingModel, thermal: &mut ThermalModel, case: &Case, cancel: &dyn Cancel) -> Result<Option<ThdState>, SolveError> {
        let law = case.lubricant.viscosity;
        let n = model.pads.len();
        let params = self.params;
        self.report.outer_iterations += 1;
        self.growth.clone_from(&self.growth_next);
        if let Some(g) = &self.growth {
            tehd::install(model, g);
        }
        for k in 0..n {
            self.op.nodal_viscosity[k] = self.t_try.as_ref().map(|t| nodal_viscosity(&law, &t[k], self.uniform[k]));
        }
        let te = Instant::now();
        let eq_params = equilibrium_params(self.last_change, &params);
        let exact = eq_params == EquilibriumParams::default();
        let attempt = warm_equilibrium(model, &self.op, eq_params, self.u.as_deref(), cancel);
        self.report.equilibrium_seconds += te.elapsed().as_secs_f64();
        let eq = match attempt {
            Ok(eq) => eq,
            Err(SolveError::Cancelled) => return Err(SolveError::Cancelled),
            Err(e) => {
                let Some(tt) = &self.t_try else { return Err(e) };
                let light: Vec<usize> = (0..n).filter(|&k| !self.uniform[k] && self.shares[k] < LIGHT_PAD_SHARE).collect();
                if !light.is_empty() {
                    for &k in &light {
                        self.uniform[k] = true;
                        self.report.warnings.push(format!(
                            "pad {k} carries {:.1} % of the load and had no equilibrium tilt with its non-uniform viscosity \
                             ({e}): it is given its mean film viscosity",
                            100.0 * self.shares[k]
                        ));
                    }
                    return Ok(None);
                }
                if self.report.outer_iterations >= params.max_iterations {
                    return Err(self.budget_exceeded(Budget::Iterations(params.max_iterations)));
                }
                if self.backtracks >= MAX_BACKTRACKS {
                    return Err(e);
                }
                self.backtracks += 1;
                let base = self.t_ok.as_ref().unwrap_or(&self.t_iso);
                self.t_try = Some(tt.iter().zip(base).map(|(a, b)| a.iter().zip(b).map(|(x, y)| y + 0.5 * (x - y)).collect()).collect());
                self.anderson.reset();
                self.report.warnings.push(format!("equilibrium failed with the updated viscosity field ({e}); step halved"));
                return Ok(None);
            }
        };
        self.backtracks = 0;
        self.shares = load_shares(&eq);
        // An unloaded pad's tilt is not determined by its film: from the first equilibrium in which it is
        // unloaded it is held for the rest of the loop, so that it cannot flip between equivalent states (each
        // flip changes its cavitated extent, hence the oil it hands to the next pad's inlet).
        for (k, p) in eq.pads.iter().enumerate() {
            if p.unloaded && !self.op.held_pads[k] && !model.pads[k].dofs().is_empty() {
                self.op.held_pads[k] = true;
                self.report.warnings.push(format!("pad {k} is unloaded: its tilt is held from outer iteration {}", self.report.outer_iterations));
            }
        }
        if self.t_ok.is_none() && self.t_try.is_none() {
            // First (isothermal) equilibrium: decide once which pads are lightly loaded.
            for k in 0..n {
                if self.shares[k] < LIGHT_PAD_SHARE && !model.pads[k].dofs().is_empty() {
                    self.uniform[k] = true;
                    self.report.warnings.push(format!(
                        "pad {k} carries {:.1} % of the load: its Reynolds equation uses its mean film viscosity (the \
                         film and pad temperatures are computed in full)",
                        100.0 * self.shares[k]
                    ));
                }
            }
        }
        self.report.equilibrium_iterations += eq.report.iterations;
        self.report.inner_iterations += eq.report.inner_iterations;
        self.report.film_solves += eq.report.film_solves;
        self.report.equilibrium_factorizations += eq.report.factorizations;
        self.u = Some(eq.u.clone());
        self.t_ok = self.t_try.take();
        let tt = Instant::now();
        let (sols, t_in, t_j, t_new) = film_temperatures(model, thermal, case, &self.op, &params)?;
        let growth_change = self.update_growth(model, thermal, case, (&sols, &t_in, t_j, &t_new))?;
        let current = self.t_ok.as_ref().unwrap_or(&self.t_iso);
        let change = viscosity_change(&law, &t_new, current);
        self.report.viscosity_change.push(change);
        self.last_change = change;
        self.report.thermal_seconds += tt.elapsed().as_secs_f64();
        if change < params.viscosity_tol && growth_change <= GROWTH_TOL * case.bearing.assembled_clearance_m {
            self.report.converged = true;
            self.report.stop_reason = format!("viscosity change {change:.1e} below {:.0e}", params.viscosity_tol);
            self.report.thermal_factorizations = self.factorizations0;
            let report = std::mem::take(&mut self.report);
            if exact {
                return finish(model, thermal, case, params, self.op.clone(), eq, &sols, &t_in, t_j, report, self.t0).map(|s| Some(self.with_growth(s)));
            }
            // The last equilibrium was solved loosely (early iterations are inexact on purpose): polish it with
            // the full tolerances on the same viscosity field, and take the temperatures of that state.
            let mut report = report;
            let te = Instant::now();
            let eq = warm_equilibrium(model, &self.op, EquilibriumParams::default(), Some(&eq.u), cancel)?;
            report.equilibrium_seconds += te.elapsed().as_secs_f64();
            report.equilibrium_iterations += eq.report.iterations;
            report.inner_iterations += eq.report.inner_iterations;
            report.film_solves += eq.report.film_solves;
            report.equilibrium_factorizations += eq.report.factorizations;
            let (sols, t_in, t_j, t_polished) = film_temperatures(model, thermal, case, &self.op, &params)?;
            report.viscosity_change.push(viscosity_change(&law, &t_polished, current));
            return finish(model, thermal, case, params, self.op.clone(), eq, &sols, &t_in, t_j, report, self.t0).map(|s| Some(self.with_growth(s)));
        }
        if self.report.outer_iterations >= params.max_iterations {
            return Err(self.budget_exceeded(Budget::Iterations(params.max_iterations)));
        }
        let next = self.anderson.step(&flatten(current), &flatten(&t_new));
        self.t_try = Some(unflatten(&next, &t_new));
        for (pt, t) in thermal.pads.iter_mut().zip(t_new) {
            pt.t_prev = Some(t);
        }
        Ok(None)
    }
}

/// TEHD steps of the loop ([`super::tehd`]), kept apart from the THD iteration itself.
impl ThdRun {
    /// Thermal growth for the temperatures just computed (`temps`: per-pad solutions, T_in per pad, T_j, film
    /// temperatures); stored for the next outer iteration. Returns its change against the growth in the
    /// films now (0 without thermal growth).
    fn update_growth(&mut self, model: &BearingModel, thermal: &mut ThermalModel, case: &Case, temps: (&[PadTemperatures], &[f64], f64, &[Vec<f64>])) -> Result<f64, SolveError> {
        let (sols, t_in, t_j, t_new) = temps;
        if Growth::of(case).is_off() {
            return Ok(0.0);
        }
        if self.tehd.is_none() {
            let meshes: Vec<_> = thermal.pads.iter().map(|p| p.conduction.as_ref().map(|c| c.mesh.clone())).collect();
            self.tehd = TehdModel::new(case, model, &meshes)?;
        }
        let Some(tehd) = self.tehd.as_mut() else { return Ok(0.0) };
        let mut pad_c = Vec::with_capacity(sols.len());
        for (k, sol) in sols.iter().enumerate() {
            let s = setup(case, &self.op, k, self.params.stabilisation);
            pad_c.push(if s.exchange == Exchange::Adiabatic {
                thermal.pad_bc1(k, &t_new[k], &s.material).map_err(|e| SolveError::Invalid(format!("pad {k} conduction: {e}")))?
            } else {
                sol.pad(t_in[k], t_j)
            });
        }
        let nodes: Vec<usize> = model.pads.iter().map(|p| p.film.geom.n_nodes()).collect();
        let g = tehd.evaluate(&pad_c, t_j, &nodes)?;
        let change = self.growth.as_ref().map_or_else(|| g.magnitude(), |old| g.change(old));
        self.report.growth_change_m.push(change);
        self.growth_next = Some(g);
        Ok(change)
    }

    /// The converged state with the growth its films hold, reported.
    fn with_growth(&self, mut state: ThdState) -> ThdState {
        if let Some(g) = &self.growth {
            state.report.journal_growth_m = Some(g.journal_m);
            state.report.pad_growth_range_m = Some(g.pad_film_m.iter().flatten().fold([f64::INFINITY, f64::NEG_INFINITY], |[lo, hi], &v| [lo.min(v), hi.max(v)]));
        }
        state.growth.clone_from(&self.growth);
        state
    }
}

/// Final pad conduction (BC1), energy balance and the converged state.
#[allow(clippy::too_many_arguments)]
fn finish(
    model: &mut BearingModel,
    thermal: &mut ThermalModel,
    case: &Case,
    params: ThermalParams,
    op: OperatingPoint,
    eq: Equilibrium,
    sols: &[PadTemperatures],
    t_in: &[f64],
    t_j: f64,
    mut report: ThermalReport,
    t0: Instant,
) -> Result<ThdState, SolveError> {
    let tt = Instant::now();
    let mut pads = Vec::with_capacity(sols.len());
    let mut heat = FilmHeat::default();
    let mut worst = 0.0_f64;
    for (k, sol) in sols.iter().enumerate() {
        let s = setup(case, &op, k, params.stabilisation);
        for w in &sol.warnings {
            report.warnings.push(format!("pad {k}: {w}"));
        }
        let film_c = sol.film(t_in[k], t_j);
        let pad_c = if s.exchange == Exchange::Adiabatic {
            let tp = Instant::now();
            let r = thermal.pad_bc1(k, &film_c, &s.material).map_err(|e| SolveError::Invalid(format!("pad {k} conduction: {e}")))?;
            report.pad_conduction_seconds += tp.elapsed().as_secs_f64();
            r
        } else {
            sol.pad(t_in[k], t_j)
        };
        let film = &model.pads[k].film;
        let face = pad_c.as_ref().map(|p| &p[..film.geom.n_nodes()]);
        let bal = BalanceInputs {
            oil: &s.oil,
            exchange: s.exchange,
            t: &film_c,
            t_pad: face,
            t_journal: t_j,
            t_ref: case.operating.supply_temperature_c,
            dirichlet_reaction: sol.dirichlet_reaction(t_in[k], t_j),
        };
        let pt = &thermal.pads[k];
        let h = pt.energy.heat_balance(film, &sol.flow, &bal);
        worst = worst.max(h.closure().abs());
        heat = heat.add(&h);
        let (radii, to_surroundings) = match (&pt.conduction, &pad_c) {
            (Some(c), Some(p)) => (c.mesh.radii.clone(), film.geom.sym * c.heat_to_surroundings(&s.material, p)),
            _ => (Vec::new(), 0.0),
        };
        pads.push(PadThermalState {
            inlet_temperature_c: t_in[k],
            outlet_temperature_c: sol.t_te.at(t_in[k], t_j),
            film_c,
            pad_c,
            pad_radii_m: radii,
            heat: h,
            pad_to_surroundings_w: to_surroundings,
            inflow_m3_per_s: sol.q_in,
            outflow_m3_per_s: sol.q_te,
            film_fraction: sol.flow.theta.clone(),
            film_mean_c: sol.mean_film.at(t_in[k], t_j),
            oil_area_m2: sol.area,
        });
    }
    report.thermal_seconds += tt.elapsed().as_secs_f64();
    report.energy_balance_closure = heat.closure();
    report.energy_balance_worst_pad = worst;
    report.thermal_factorizations = thermal.pads.iter().map(|p| p.factorizations).sum::<usize>() - report.thermal_factorizations;
    if report.energy_balance_closure.abs() > 0.01 {
        report.warnings.push(format!("energy balance closes to {:.2} % only", 100.0 * report.energy_balance_closure));
    }
    report.seconds = t0.elapsed().as_secs_f64();
    Ok(ThdState { equilibrium: eq, op, pads, journal_temperature_c: t_j, heat, report, growth: None })
}
