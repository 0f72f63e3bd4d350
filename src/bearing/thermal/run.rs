//! The THD outer loop ([`ThdRun`]): one outer iteration per step — equilibrium at the current viscosity
//! field, film and pad temperatures, viscosity update (Anderson-accelerated, backtracked), thermal growth of
//! pads and journal when the case asks for it (TEHD), a load step of the Hertz pivots when the pads have
//! them ([`HertzPivots`]) — with its budgets, deadline and report.

use crate::bearing::report::error::ThermalSystem;
use crate::bearing::report::warning::Warning;
use web_time::Instant;

use crate::bearing::equilibrium::pivots::{self, HertzPivots};
use crate::bearing::equilibrium::Equilibrium;
use crate::bearing::film::model::{BearingModel, OperatingPoint};
use crate::bearing::report::error::{Budget, Iteration, SolveError};
use crate::bearing::report::progress::{Cancel, Progress};
use crate::bearing::thermal::anderson::{flatten, Anderson};
use crate::bearing::thermal::growth;
use crate::bearing::thermal::growth::{Growth, GrowthField, TehdModel, GROWTH_TOL};
use crate::bearing::thermal::iteration::{
    equilibrium_params, film_temperatures, load_shares, nodal_viscosity, setup, viscosity_change, warm_equilibrium,
};
use crate::bearing::thermal::mixing;
use crate::bearing::thermal::model::{
    PadThermalState, ThdState, ThermalConvergence, ThermalModel, ThermalParams, ThermalReport, ANDERSON_DEPTH,
    LIGHT_PAD_SHARE, MIN_RELAXATION,
};
use crate::bearing::thermal::pad_system::PadTemperatures;
use crate::bearing::thermal::resumable::{equilibrium_part, PendingEquilibrium};
use crate::model::Case;
use crate::physics::energy::{BalanceInputs, Exchange, FilmHeat};

/// A starved bearing's loop has converged when the flow offered to every leading edge (supply share plus
/// carried hot oil) changes by less than this fraction between outer iterations.
const OFFERED_FLOW_RTOL: f64 = 1e-3;

mod update;
/// The THD loop as a resumable computation: one [`ThdRun::step`] is one outer iteration (an equilibrium at
/// the current viscosity field, then the film and pad temperatures), so a caller without threads (the web
/// build) can spread a THD solve over frames; when the caller's [`Cancel::suspend`] asks, the outer
/// iteration's equilibrium itself pauses ([`crate::bearing::thermal::resumable`]) and the next step resumes it.
///
/// Robustness: the temperature update is Anderson-accelerated (depth [`ANDERSON_DEPTH`], damping ω); after
/// [`SAFEGUARD_AFTER`] outer iterations without convergence it is safeguarded: an outer iteration whose
/// viscosity change is larger than the previous one drops the history and halves ω (down to
/// [`MIN_RELAXATION`]), so the loop falls back to damped fixed-point steps where the extrapolation does not
/// contract (near touchdown, where the film's heating is steep in the viscosity); if the
/// equilibrium cannot be found with a proposed viscosity field (e.g. a lightly loaded pad whose moment
/// curve loses its root), the proposal — its temperatures and, with thermal growth, its growth — is halved
/// back towards the last field that worked, up to [`MAX_BACKTRACKS`] times, and the history is restarted. Every proposal is clamped to the range of the
/// image it was made from; ω is doubled again after falls of the change ([`crate::bearing::thermal::anderson::RECOVER_AFTER`]);
/// a safeguarded loop whose change has not halved in [`STALL_WINDOW`] outer iterations drops the
/// extrapolation for plain damped steps; and a touchdown the loop walked into (or an equilibrium that spent
/// its work budget at a proposed field) restarts it once, safeguarded from the start (`update.rs`).
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
    /// Computing time spent inside [`ThdRun::step`] so far [s] (reported only).
    work_seconds: f64,
    /// TEHD ([`crate::bearing::thermal::tehd`]): the growth model (built on first use), the growth in the films of the current
    /// outer iteration, and the one the last temperatures give (installed at the next iteration).
    tehd: Option<TehdModel>,
    growth: Option<GrowthField>,
    growth_next: Option<GrowthField>,
    /// The current outer iteration's equilibrium, suspended.
    pending: Option<PendingEquilibrium>,
    /// Hertz pivots: their load iteration, one load step per outer iteration (built on first use), and the
    /// last step's relative change of the secant springs.
    pivots: Option<HertzPivots>,
    pivot_change: f64,
    /// Smallest viscosity change of the safeguarded phase and the outer iteration it was reached at; and
    /// whether the loop has fallen back to plain damped steps ([`STALL_WINDOW`]).
    best_change: (f64, usize),
    plain: bool,
    /// The touchdown that made the loop restart, safeguarded from its first step
    /// ([`ThdRun::restart_cautiously`]; `None`: not restarted), and what it restarts from.
    restarted_from: Option<SolveError>,
    growth_at_start: Option<GrowthField>,
    /// TEHD: the growth in the films of the last equilibrium that was found (a backtracked step halves the
    /// growth towards it, as it halves the temperatures towards theirs).
    growth_ok: Option<GrowthField>,
    u_start: Option<Vec<f64>>,
}

impl ThdRun {
    #[must_use]
    pub fn new(
        model: &BearingModel,
        thermal: &mut ThermalModel,
        case: &Case,
        params: ThermalParams,
        start: Option<&[f64]>,
    ) -> Self {
        let n = model.pads.len();
        let factorizations0: usize = thermal.pads.iter().map(|p| p.factorizations).sum();
        for pt in &mut thermal.pads {
            pt.t_prev = None;
        }
        let housing = growth::housing_only(case, model);
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
            anderson: Anderson::safeguarded(ANDERSON_DEPTH, params.relaxation, MIN_RELAXATION),
            backtracks: 0,
            last_change: f64::INFINITY,
            uniform: vec![false; n],
            shares: vec![1.0; n],
            work_seconds: 0.0,
            tehd: None,
            growth: None,
            // The housing's growth is given: in the films from the first equilibrium, which decides the
            // lightly loaded pads.
            growth_next: housing.clone(),
            growth_ok: housing.clone(),
            growth_at_start: housing,
            u_start: start.map(<[f64]>::to_vec),
            pending: None,
            pivots: None,
            pivot_change: 0.0,
            best_change: (f64::INFINITY, 0),
            plain: false,
            restarted_from: None,
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
    /// Equilibrium failures, a singular thermal system, or a loop that spends its iteration budget
    /// ([`SolveError::BudgetExceeded`]).
    pub fn step(
        &mut self,
        model: &mut BearingModel,
        thermal: &mut ThermalModel,
        case: &Case,
        cancel: &dyn Cancel,
    ) -> Result<Option<ThdState>, SolveError> {
        if cancel.cancelled() {
            return Err(SolveError::Cancelled);
        }
        let started = Instant::now();
        let result = self.outer_iteration(model, thermal, case, cancel);
        if self.growth.is_some() || self.growth_next.is_some() {
            // The films are shared with other stages: they hold the growth only while the loop works.
            growth::clear(model);
        }
        self.work_seconds += started.elapsed().as_secs_f64();
        result
    }

    /// The loop ran out of its budget. Also after a cautious restart ([`ThdRun`]'s robustness notes): the
    /// touchdown that started it belonged to an intermediate viscosity field, not to the converged state, so the
    /// answer is the spent budget, not that touchdown.
    fn budget_exceeded(&self, budget: Budget) -> SolveError {
        SolveError::BudgetExceeded {
            what: Iteration::Thermal,
            budget,
            iterations: self.report.outer_iterations,
            residual: self.last_change,
        }
    }

    fn outer_iteration(
        &mut self,
        model: &mut BearingModel,
        thermal: &mut ThermalModel,
        case: &Case,
        cancel: &dyn Cancel,
    ) -> Result<Option<ThdState>, SolveError> {
        let law = case.lubricant.viscosity;
        let n = model.pads.len();
        let params = self.params;
        let pending = match self.pending.take() {
            Some(p) => p,
            None => {
                self.report.outer_iterations += 1;
                self.growth.clone_from(&self.growth_next);
                for k in 0..n {
                    self.op.nodal_viscosity[k] =
                        self.t_try.as_ref().map(|t| nodal_viscosity(&law, &t[k], self.uniform[k]));
                }
                PendingEquilibrium::new(equilibrium_params(self.last_change, &params), self.u.clone())
            }
        };
        // Installed at every step: a step ends with the films cleared (see `step`), and a stage may rebuild
        // the pad structures between steps.
        if let Some(g) = &self.growth {
            growth::install(model, g);
        }
        if self.pivots.is_none() && pivots::has_contacts(case) {
            self.pivots = HertzPivots::new(model, case)?;
        }
        if let Some(p) = &self.pivots {
            p.install(model);
        }
        let te = Instant::now();
        let exact = pending.params == self.params.equilibrium;
        let attempt = equilibrium_part(model, &self.op, pending, cancel);
        self.report.equilibrium_seconds += te.elapsed().as_secs_f64();
        let eq = match attempt {
            Ok(Progress::Done(eq)) => eq,
            Ok(Progress::Suspended(p)) => {
                self.pending = Some(p);
                return Ok(None);
            }
            Err(SolveError::Cancelled) => return Err(SolveError::Cancelled),
            Err(e) => return self.failed_equilibrium(thermal, e),
        };
        self.backtracks = 0;
        self.growth_ok.clone_from(&self.growth);
        self.shares = load_shares(&eq);
        // An unloaded pad's tilt is not determined by its film: from the first equilibrium in which it is
        // unloaded it is held for the rest of the loop, so that it cannot flip between equivalent states (each
        // flip changes its cavitated extent, hence the oil it hands to the next pad's inlet).
        for (k, p) in eq.pads.iter().enumerate() {
            if p.unloaded && !self.op.held_pads[k] && !model.pads[k].dofs().is_empty() {
                self.op.held_pads[k] = true;
                self.report.warnings.push(Warning::TiltHeld { pad: k, outer_iteration: self.report.outer_iterations });
            }
        }
        if self.t_ok.is_none() && self.t_try.is_none() {
            // First (isothermal) equilibrium: decide once which pads are lightly loaded.
            for k in 0..n {
                if self.shares[k] < LIGHT_PAD_SHARE && !model.pads[k].dofs().is_empty() {
                    self.uniform[k] = true;
                    self.report.warnings.push(Warning::MeanViscosity { pad: k, load_percent: 100.0 * self.shares[k] });
                }
            }
        }
        self.report.equilibrium_iterations += eq.report.iterations;
        self.report.inner_iterations += eq.report.inner_iterations;
        self.report.film_solves += eq.report.film_solves;
        self.report.equilibrium_factorizations += eq.report.factorizations;
        self.u = Some(eq.u.clone());
        self.t_ok = self.t_try.take();
        if let Some(p) = self.pivots.as_mut() {
            self.pivot_change = p.update(case, &eq)?;
        }
        let tt = Instant::now();
        let (sols, t_in, t_j, t_new) = film_temperatures(model, thermal, case, &self.op, &params)?;
        let growth_change = self.update_growth(model, thermal, case, (&sols, &t_in, t_j, &t_new))?;
        let current = self.t_ok.as_ref().unwrap_or(&self.t_iso);
        let change = viscosity_change(&law, &t_new, current);
        self.report.viscosity_change.push(change);
        self.last_change = change;
        self.report.thermal_seconds += tt.elapsed().as_secs_f64();
        // A starved bearing's films are offered their supply share plus the carried hot oil (mixing.rs).
        let offered = mixing::offered_inlets(case, &sols, &thermal.upstream);
        let inlet_change = offered.as_ref().map_or(0.0, |o| mixing::inlet_change(&self.op.inlet, o));
        if change < params.viscosity_tol
            && growth_change <= GROWTH_TOL * case.bearing.assembled_clearance_m
            && self.pivot_change < pivots::RTOL
            && inlet_change < OFFERED_FLOW_RTOL
        {
            self.report.converged = true;
            self.report.stop_reason = Some(ThermalConvergence {
                viscosity_change: change,
                viscosity_tol: params.viscosity_tol,
                pivot_change: self.pivots.is_some().then_some([self.pivot_change, pivots::RTOL]),
            });
            self.report.thermal_factorizations = self.factorizations0;
            let report = std::mem::take(&mut self.report);
            if exact {
                return finish(model, thermal, case, params, self.op.clone(), eq, &sols, &t_in, t_j, report, self.t0)
                    .map(|s| Some(self.with_structure(s)));
            }
            // The last equilibrium was solved loosely (early iterations are inexact on purpose): polish it with
            // the full tolerances on the same viscosity field, and take the temperatures of that state.
            let mut report = report;
            let te = Instant::now();
            let eq = warm_equilibrium(model, &self.op, self.params.equilibrium, Some(&eq.u), cancel)?;
            if let Some(p) = self.pivots.as_mut() {
                // The contact states at the polished loads (the springs moved by less than the tolerance).
                p.update(case, &eq)?;
            }
            report.equilibrium_seconds += te.elapsed().as_secs_f64();
            report.equilibrium_iterations += eq.report.iterations;
            report.inner_iterations += eq.report.inner_iterations;
            report.film_solves += eq.report.film_solves;
            report.equilibrium_factorizations += eq.report.factorizations;
            let (sols, t_in, t_j, t_polished) = film_temperatures(model, thermal, case, &self.op, &params)?;
            report.viscosity_change.push(viscosity_change(&law, &t_polished, current));
            return finish(model, thermal, case, params, self.op.clone(), eq, &sols, &t_in, t_j, report, self.t0)
                .map(|s| Some(self.with_structure(s)));
        }
        if self.report.outer_iterations >= params.max_iterations {
            return Err(self.budget_exceeded(Budget::Iterations(params.max_iterations)));
        }
        if let Some(o) = offered {
            self.op.inlet = o;
        }
        let current = flatten(current);
        self.t_try = Some(self.propose(case, &current, &t_new, change));
        for (pt, t) in thermal.pads.iter_mut().zip(t_new) {
            pt.t_prev = Some(t);
        }
        Ok(None)
    }
}

/// TEHD steps of the loop ([`crate::bearing::thermal::tehd`]), kept apart from the THD iteration itself.
impl ThdRun {
    /// Thermal growth for the temperatures just computed (`temps`: per-pad solutions, T_in per pad, T_j, film
    /// temperatures); stored for the next outer iteration. Returns its change against the growth in the
    /// films now (0 without thermal growth).
    fn update_growth(
        &mut self,
        model: &BearingModel,
        thermal: &mut ThermalModel,
        case: &Case,
        temps: (&[PadTemperatures], &[f64], f64, &[Vec<f64>]),
    ) -> Result<f64, SolveError> {
        let (sols, t_in, t_j, t_new) = temps;
        if Growth::of(case).is_off() {
            return Ok(0.0);
        }
        let started = Instant::now();
        if self.tehd.is_none() {
            let meshes: Vec<_> = thermal.pads.iter().map(|p| p.conduction.as_ref().map(|c| c.mesh.clone())).collect();
            self.tehd = TehdModel::new(case, model, &meshes)?;
            self.report.growth_setup_seconds = Some(started.elapsed().as_secs_f64());
        }
        let Some(tehd) = self.tehd.as_mut() else { return Ok(0.0) };
        let mut pad_c = Vec::with_capacity(sols.len());
        for (k, sol) in sols.iter().enumerate() {
            let s = setup(case, &self.op, k, self.params.stabilisation);
            pad_c.push(if s.exchange == Exchange::Adiabatic {
                thermal.pad_bc1(k, &t_new[k], &s.material).map_err(|error| SolveError::PadThermal {
                    pad: k,
                    system: ThermalSystem::Conduction,
                    error,
                })?
            } else {
                sol.pad(t_in[k], t_j)
            });
        }
        let nodes: Vec<usize> = model.pads.iter().map(|p| p.film.geom.n_nodes()).collect();
        let g = tehd.evaluate(&pad_c, t_j, &nodes);
        let change = self.growth.as_ref().map_or_else(|| g.magnitude(), |old| g.change(old));
        self.report.growth_change_m.push(change);
        self.growth_next = Some(g);
        *self.report.growth_seconds.get_or_insert(0.0) += started.elapsed().as_secs_f64();
        Ok(change)
    }

    /// The converged state with the growth its films hold and its pivots' load iteration, reported.
    fn with_structure(&self, mut state: ThdState) -> ThdState {
        if let Some(g) = &self.growth {
            state.report.journal_growth_m = Some(g.journal_m);
            state.report.housing_growth_m.clone_from(&g.housing_m);
            state.report.pad_growth_range_m = Some(
                g.pad_film_m
                    .iter()
                    .flatten()
                    .fold([f64::INFINITY, f64::NEG_INFINITY], |[lo, hi], &v| [lo.min(v), hi.max(v)]),
            );
        }
        state.growth.clone_from(&self.growth);
        state.pivots.clone_from(&self.pivots);
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
        if sol.no_inflow {
            report.warnings.push(Warning::NoLeadingEdgeInflow { pad: k });
        }
        let film_c = sol.film(t_in[k], t_j);
        let pad_c = if s.exchange == Exchange::Adiabatic {
            let tp = Instant::now();
            let r = thermal.pad_bc1(k, &film_c, &s.material).map_err(|error| SolveError::PadThermal {
                pad: k,
                system: ThermalSystem::Conduction,
                error,
            })?;
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
    report.power_identity = heat.power_identity();
    report.energy_balance_worst_pad = worst;
    report.thermal_factorizations =
        thermal.pads.iter().map(|p| p.factorizations).sum::<usize>() - report.thermal_factorizations;
    if report.energy_balance_closure.abs() > 0.01 {
        report.warnings.push(Warning::EnergyBalance { closure: report.energy_balance_closure });
    }
    report.seconds = t0.elapsed().as_secs_f64();
    Ok(ThdState { equilibrium: eq, op, pads, journal_temperature_c: t_j, heat, report, growth: None, pivots: None })
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
