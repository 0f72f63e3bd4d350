//! Evaluation for the equilibrium methods: film solves of one pad or all pads (in parallel on native
//! targets when the films are large), the global residual and its merit, scales, budgets and the solve
//! context shared by every method.

use crate::bearing::report::warning::Warning;
use web_time::Instant;

use crate::model::LoadSpec;
use crate::physics::reynolds::{FilmError, FilmLinearization, FilmSolveInfo};

use crate::bearing::equilibrium::state::{EquilibriumParams, PadState, FLOATING_SHARE, UNLOADED_SHARE};
use crate::bearing::film::coordinates::JOURNAL_DOFS;
use crate::bearing::film::model::{BearingModel, OperatingPoint, PadModel};
use crate::bearing::report::error::{Budget, Iteration, SolveError};
use crate::bearing::report::SolveReport;

/// A force scale for residuals: the larger of the load, the hydrodynamic load at S = 1, and a hydrostatic
/// scale from the injection pressure.
#[must_use]
pub fn force_scale(model: &BearingModel, op: &OperatingPoint) -> f64 {
    let (r, l, c) = (model.journal_radius, model.length, model.assembled_clearance);
    let w_hydro = op.viscosity * (op.speed_rad_s / std::f64::consts::TAU) * l * 2.0 * r * (r / c).powi(2);
    let p_inj = op.injection_pressure.iter().fold(0.0_f64, |m, &p| m.max(p));
    let w_static = match op.load {
        LoadSpec::Force { magnitude_n, .. } => magnitude_n,
        LoadSpec::Position { .. } => 0.0,
    };
    w_static.max(w_hydro).max(0.01 * p_inj * l * 2.0 * r).max(1e-6)
}

/// The static load on the journal at `fraction` of its magnitude [N].
pub(super) fn external_load(op: &OperatingPoint, fraction: f64) -> [f64; 2] {
    match op.load {
        LoadSpec::Force { magnitude_n, angle_rad } => {
            [fraction * magnitude_n * angle_rad.cos(), fraction * magnitude_n * angle_rad.sin()]
        }
        LoadSpec::Position { .. } => [0.0, 0.0],
    }
}

/// Unit vector along the load (or zero without one).
pub(super) fn load_direction(op: &OperatingPoint) -> [f64; 2] {
    let w = external_load(op, 1.0);
    let n = w[0].hypot(w[1]);
    if n > 0.0 {
        [w[0] / n, w[1] / n]
    } else {
        [0.0, 0.0]
    }
}

/// What every method shares: the operating point, settings, scales, budgets and the report.
pub(crate) struct Ctx<'a> {
    pub op: &'a OperatingPoint,
    pub params: EquilibriumParams,
    pub force_scale: f64,
    pub report: SolveReport,
    /// Along the load, the film closed before the force balanced: (pad, thinnest film [m], ε) there.
    pub closes_before_balance: Option<(usize, f64, f64)>,
    /// A load component was met along a direction without stiffness: (axis [deg], component [N]).
    pub no_stiffness: Option<(f64, f64)>,
    /// Pads found at the onset of pressure are searched for a loaded root further on (the final
    /// placements; see `pad::loaded_root_beyond`).
    pub thorough_onset: bool,
    /// Pads the thorough search found a loaded state of where they floated (a pad near a fold has two).
    pub loaded_state_found: Vec<usize>,
    /// Along the load the bearing force jumps across the load: (pad that switches, force along the load
    /// before and after the jump [N]).
    pub force_gap: Option<(usize, f64, f64)>,
    /// The polar search met a jump over zero of the residual force inside its angular bracket, along a ray or
    /// across neighbouring rays: (pad that switched, direction [rad], residual component on either side [N]).
    pub gap_2d: Option<(usize, f64, f64, f64)>,
    /// Film solves allowed in total.
    budget: Budget,
    /// When the solve started (for the report's timing only: no outcome depends on it).
    started: Instant,
}

impl<'a> Ctx<'a> {
    /// Runs `f` with the thorough onset search (`thorough_onset`) set to `on`, and restores the setting it
    /// found afterwards, whatever `f` returns.
    pub fn with_thorough_onset<T>(&mut self, on: bool, f: impl FnOnce(&mut Self) -> T) -> T {
        let before = std::mem::replace(&mut self.thorough_onset, on);
        let out = f(self);
        self.thorough_onset = before;
        out
    }

    pub fn new(model: &BearingModel, op: &'a OperatingPoint, params: EquilibriumParams, started: Instant) -> Self {
        let budget = Budget::FilmSolves { per_pad: params.max_film_solves_per_pad, pads: model.pads.len().max(1) };
        Self {
            op,
            params,
            force_scale: force_scale(model, op),
            report: SolveReport::default(),
            closes_before_balance: None,
            no_stiffness: None,
            thorough_onset: false,
            loaded_state_found: Vec::new(),
            force_gap: None,
            gap_2d: None,
            budget,
            started,
        }
    }

    /// Seconds since the solve started (reported, never compared with a limit).
    pub fn elapsed(&self) -> f64 {
        self.started.elapsed().as_secs_f64()
    }

    /// Which budget is spent, if any: the film solves counted so far against the work budget (a count, so the
    /// same case stops at the same film solve whatever the machine's load).
    pub fn exhausted(&self) -> Option<Budget> {
        let Budget::FilmSolves { per_pad, pads } = self.budget else { return None };
        (self.report.film_solves >= per_pad.saturating_mul(pads)).then_some(self.budget)
    }

    /// The error of a spent budget.
    pub fn budget_error(&self, budget: Budget) -> SolveError {
        SolveError::BudgetExceeded {
            what: Iteration::Equilibrium,
            budget,
            iterations: self.report.iterations,
            residual: self.report.residual_history.last().copied().unwrap_or(1.0),
        }
    }

    /// A film failure on pad k as a solve error; running out of a budget is that budget's error.
    pub fn film_error(&self, k: usize, e: FilmError) -> SolveError {
        match self.exhausted() {
            Some(b) => self.budget_error(b),
            None => SolveError::Film { pad: k, error: e },
        }
    }

    /// A pad's load as a share of the force scale.
    pub fn share(&self, st: &PadState) -> f64 {
        let f = st.journal_force();
        f[0].hypot(f[1]) / self.force_scale
    }

    /// The pad's coordinates are held at their start values while it carries no load (an outer thermal loop
    /// holds unloaded pads, so that they cannot flip between equivalent pressure-free states).
    pub fn held(&self, k: usize) -> bool {
        self.op.held_pads.get(k).copied().unwrap_or(false)
    }
}

/// One film solve of pad k at local coordinates: forces, stiffness and what the solve did. Touches only
/// the pad, so pads can be evaluated in parallel.
pub(super) fn film_eval(
    pm: &mut PadModel,
    k: usize,
    local: &[f64],
    op: &OperatingPoint,
) -> Result<(Vec<f64>, FilmLinearization, FilmSolveInfo), FilmError> {
    pm.film.set_coordinates(local)?;
    let inp = op.film_inputs(k);
    let info = pm.film.solve(&inp, true)?;
    let forces = pm.film.generalized_forces();
    let lin = pm.film.linearize_stiffness(&inp);
    Ok((forces, lin, info))
}

/// Accounts for one film solve in the report.
pub(super) fn account(ctx: &mut Ctx<'_>, k: usize, info: FilmSolveInfo) {
    ctx.report.film_solves += 1;
    ctx.report.factorizations += info.factorizations;
    ctx.report.pivoted_factorizations += info.pivoted_factorizations;
    for warning in info.warnings {
        ctx.report.warn(Warning::Film { pad: k, warning });
    }
}

/// Evaluates pad k at local coordinates: forces and linearisation.
pub(super) fn eval_pad(
    pm: &mut PadModel,
    k: usize,
    local: &[f64],
    ctx: &mut Ctx<'_>,
) -> Result<(Vec<f64>, FilmLinearization), FilmError> {
    if let Some(b) = ctx.exhausted() {
        return Err(FilmError::Input(b.to_string()));
    }
    let (forces, lin, info) = film_eval(pm, k, local, ctx.op)?;
    account(ctx, k, info);
    Ok((forces, lin))
}

/// Scale of each pad residual: the pad's load (times the lever for moments), at least the load a floating
/// pad may carry ([`FLOATING_SHARE`] of the force scale): a pad's residual matters through the force it
/// leaves unbalanced, and below that share the pad's film counts for nothing.
pub(super) fn pad_scales(pm: &PadModel, forces: &[f64], force_scale: f64) -> Vec<f64> {
    let f = forces[0].hypot(forces[1]).max(FLOATING_SHARE * force_scale);
    let lever = pm.film.geom.radius;
    pm.dofs().iter().map(|d| if d.is_rotation() { f * lever } else { f }).collect()
}

/// `|r / scale|`.
pub(super) fn relative(r: f64, scale: f64) -> f64 {
    (r / scale).abs()
}

/// The structural force `K_s q` on pad coordinate `d`.
pub(super) fn structural_force(pm: &PadModel, q: &[f64], d: usize) -> f64 {
    (0..q.len()).map(|e| pm.structure.stiffness[(d, e)] * q[e]).sum()
}

/// Total film force on the journal.
pub(super) fn total_force(states: &[PadState]) -> [f64; 2] {
    states.iter().fold([0.0; 2], |a, p| [a[0] + p.forces[0], a[1] + p.forces[1]])
}

/// The thinnest film over all pads and where it is.
pub(super) fn min_film(model: &BearingModel) -> (usize, f64) {
    model.pads.iter().enumerate().map(|(k, p)| (k, p.film.h_min().0)).fold((0, f64::INFINITY), |m, x| {
        if x.1 < m.1 {
            x
        } else {
            m
        }
    })
}

/// Film nodes above which pads are solved in parallel (below, thread start-up costs more than it saves).
#[cfg(not(target_arch = "wasm32"))]
const PARALLEL_MIN_NODES: usize = 2500;

type FilmResult = Result<(Vec<f64>, FilmLinearization, FilmSolveInfo), FilmError>;

/// Film solves of all pads at `u`, in parallel on native targets when the meshes are large enough.
fn eval_films(model: &mut BearingModel, u: &[f64], op: &OperatingPoint) -> Vec<FilmResult> {
    let locals: Vec<Vec<f64>> = (0..model.pads.len()).map(|k| model.local(k, u)).collect();
    #[cfg(not(target_arch = "wasm32"))]
    {
        let threads = std::thread::available_parallelism().map_or(1, std::num::NonZero::get).min(model.pads.len());
        if threads > 1 && model.film_nodes() >= PARALLEL_MIN_NODES {
            let chunk = model.pads.len().div_ceil(threads);
            return std::thread::scope(|scope| {
                let handles: Vec<_> = model
                    .pads
                    .chunks_mut(chunk)
                    .enumerate()
                    .map(|(c, pads)| {
                        let locals = &locals;
                        scope.spawn(move || {
                            pads.iter_mut()
                                .enumerate()
                                .map(|(i, pm)| film_eval(pm, c * chunk + i, &locals[c * chunk + i], op))
                                .collect::<Vec<_>>()
                        })
                    })
                    .collect();
                handles
                    .into_iter()
                    .flat_map(|h| {
                        h.join().unwrap_or_else(|_| vec![Err(FilmError::Input("pad solve thread panicked".into()))])
                    })
                    .collect()
            });
        }
    }
    model.pads.iter_mut().enumerate().map(|(k, pm)| film_eval(pm, k, &locals[k], op)).collect()
}

/// Evaluates every pad at the global coordinates `u` (one film solve each, no pad iteration).
pub(super) fn eval_all(
    model: &mut BearingModel,
    u: &[f64],
    ctx: &mut Ctx<'_>,
) -> Result<Vec<PadState>, (usize, FilmError)> {
    if let Some(b) = ctx.exhausted() {
        return Err((0, FilmError::Input(b.to_string())));
    }
    let results = eval_films(model, u, ctx.op);
    let mut states = Vec::with_capacity(model.pads.len());
    for (k, res) in results.into_iter().enumerate() {
        let (forces, lin, info) = res.map_err(|e| (k, e))?;
        account(ctx, k, info);
        let pm = &model.pads[k];
        let q = u[model.dofs.pad_slice(k)].to_vec();
        let sc = pad_scales(pm, &forces, ctx.force_scale);
        let residual = (0..q.len())
            .map(|d| relative(forces[JOURNAL_DOFS + d] - structural_force(pm, &q, d), sc[d]))
            .fold(0.0, f64::max);
        let mut st = PadState { q, forces, lin, unloaded: false, residual };
        // An unloaded pad's relative residual is meaningless (its scale is its vanishing load); a held pad
        // that picks up load is solved like any other.
        st.unloaded = ctx.share(&st) < UNLOADED_SHARE;
        if st.unloaded {
            st.residual = 0.0;
        }
        states.push(st);
    }
    Ok(states)
}

/// Global residual `R(u)` (journal force balance, pad balances) and its merit (scaled sum of squares;
/// unloaded pads do not count).
pub(super) fn coupled_residual(
    model: &BearingModel,
    u: &[f64],
    states: &[PadState],
    w: [f64; 2],
    force_scale: f64,
) -> (Vec<f64>, f64) {
    let mut r = vec![0.0; model.n_dofs()];
    let f = total_force(states);
    r[0] = f[0] + w[0];
    r[1] = f[1] + w[1];
    let mut merit = (r[0] / force_scale).powi(2) + (r[1] / force_scale).powi(2);
    for (k, (pm, st)) in model.pads.iter().zip(states).enumerate() {
        let slice = model.dofs.pad_slice(k);
        let q = &u[slice.clone()];
        for (d, i) in slice.enumerate() {
            r[i] = st.pad_force(d) - structural_force(pm, q, d);
            let scale = if pm.dofs()[d].is_rotation() { force_scale * model.journal_radius } else { force_scale };
            if !st.unloaded {
                merit += (r[i] / scale).powi(2);
            }
        }
    }
    (r, merit)
}
