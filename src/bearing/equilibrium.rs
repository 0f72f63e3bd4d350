//! Static equilibrium of journal and pads.
//!
//! ## Problem
//! Find the global coordinates `u = [e_x, e_y, pad coordinates…]` such that
//!
//! ```text
//! journal:  Σ_k Q_journal,k(u) + W = 0             (film forces balance the static load W)
//! pad k:    Q_pad,k(u) − K_s,k q_k = 0             (zero moment about a frictionless pivot; pivot spring)
//! ```
//!
//! ## Method (Lund's pad assembly, nested Newton)
//! - Inner: for a given journal position each pad is solved on its own. A tilt-only pad uses Newton
//!   safeguarded by a bracket: the tilt moment decreases with δ and the admissible tilts (h > 0 everywhere)
//!   form an interval, so bisection takes over whenever Newton would leave the bracket. Pads with a pivot
//!   spring use damped Newton with a step that keeps h > 0.
//! - Outer: Newton on (e_x, e_y) with the pad-condensed Jacobian `K_jj − K_jp K_pp⁻¹ K_pj` (exact, by the
//!   implicit function theorem) and backtracking on the force residual; steps that close a film are halved.
//! - Fallback: load continuation (the load raised in steps from a centred journal).
//!
//! Jacobians come from the films' analytic perturbations ([`crate::physics::reynolds::PadFilm::linearize`]).
//! The outcome is an [`Equilibrium`] with a [`SolveReport`], or a [`SolveError`] (touchdown,
//! non-convergence); never NaN.

use nalgebra::{DMatrix, Matrix2, Vector2};
use serde::Serialize;
use web_time::Instant;

use crate::model::LoadSpec;
use crate::physics::reynolds::{FilmError, FilmLinearization, FilmSolveInfo};

use super::error::SolveError;
use super::geometry::PadDof;
use super::model::{BearingModel, OperatingPoint, PadModel};

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
    /// Resuming a suspended cold start ([`SolveError::Suspended`]): the pads before this index are already
    /// placed in `start` (0: an ordinary solve).
    pub placed_pads: usize,
}

impl Default for EquilibriumParams {
    fn default() -> Self {
        Self { force_tol: 1e-9, pad_tol: 1e-10, max_iterations: 60, max_inner_iterations: 80, max_step: 0.4, max_film_solves_per_pad: 1500, placed_pads: 0 }
    }
}

/// What a solve did: iterations, residuals, time, warnings.
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct SolveReport {
    /// Outer (journal) Newton iterations, summed over continuation steps.
    pub iterations: usize,
    /// Pad (inner) iterations.
    pub inner_iterations: usize,
    pub film_solves: usize,
    pub factorizations: usize,
    /// Final journal force residual |ΣF + W| relative to the force scale.
    pub residual: f64,
    /// Largest final pad residual relative to the pad's scale.
    pub pad_residual: f64,
    /// Residual after each outer iteration.
    pub residual_history: Vec<f64>,
    pub method: String,
    pub seconds: f64,
    pub warnings: Vec<String>,
}

impl SolveReport {
    fn warn(&mut self, w: String) {
        if !self.warnings.contains(&w) {
            self.warnings.push(w);
        }
    }

    /// Adds the work of an earlier part of the same solve (a suspended part, [`SolveError::Suspended`]):
    /// counts and time add up, its residual history comes first, warnings are merged. The final residuals
    /// and the method stay this part's.
    pub fn add_earlier(&mut self, earlier: SolveReport) {
        self.iterations += earlier.iterations;
        self.inner_iterations += earlier.inner_iterations;
        self.film_solves += earlier.film_solves;
        self.factorizations += earlier.factorizations;
        self.seconds += earlier.seconds;
        let mut history = earlier.residual_history;
        history.append(&mut self.residual_history);
        self.residual_history = history;
        for w in earlier.warnings {
            self.warn(w);
        }
    }
}

/// Converged state of one pad.
#[derive(Debug, Clone, PartialEq)]
pub struct PadState {
    /// Pad coordinates (tilt, pivot displacement, …).
    pub q: Vec<f64>,
    /// Generalised film forces `[F_x, F_y, Q_pad…]` (film on journal; moment about the pivot).
    pub forces: Vec<f64>,
    /// Film stiffness and damping in local coordinates.
    pub lin: FilmLinearization,
    /// The pad carries (almost) no load: its coordinates are not determined by the film.
    pub unloaded: bool,
    pub residual: f64,
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

/// Something that can stop a solve (a superseded job) or ask it to hand its work back for now.
pub trait Cancel {
    /// Stop: the result is no longer wanted.
    fn cancelled(&self) -> bool;
    /// Pause at the next safe point (the web build, which has no threads, when a frame's time budget is
    /// spent): the coupled Newton returns [`SolveError::Suspended`] with its current iterate after at least
    /// one iteration, and the caller resumes by warm-starting from it.
    fn suspend(&self) -> bool {
        false
    }
}

/// Forwards cancellation but never suspends (solves whose caller cannot resume them: the fallbacks, the
/// equilibria inside a THD outer iteration, THD sweep points).
pub struct NoSuspend<'a>(pub &'a dyn Cancel);
impl Cancel for NoSuspend<'_> {
    fn cancelled(&self) -> bool {
        self.0.cancelled()
    }
}

/// Never cancels.
pub struct NoCancel;
impl Cancel for NoCancel {
    fn cancelled(&self) -> bool {
        false
    }
}

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

struct Ctx<'a> {
    op: &'a OperatingPoint,
    params: EquilibriumParams,
    force_scale: f64,
    report: SolveReport,
    /// Film solves allowed in total.
    budget: usize,
}

impl Ctx<'_> {
    fn exhausted(&self) -> bool {
        self.report.film_solves > self.budget
    }

    /// A film failure on pad k as a solve error; running out of the work budget is non-convergence.
    fn film_error(&self, k: usize, e: FilmError) -> SolveError {
        if self.exhausted() {
            SolveError::NotConverged {
                iterations: self.report.iterations,
                residual: self.report.residual_history.last().copied().unwrap_or(1.0),
                reason: format!("work budget of {} film solves exhausted", self.budget),
            }
        } else {
            SolveError::Film { pad: k, source: e }
        }
    }
}

/// One film solve of pad k at local coordinates: forces, stiffness and what the solve did. Touches only
/// the pad, so pads can be evaluated in parallel.
fn film_eval(pm: &mut PadModel, k: usize, local: &[f64], warm: bool, op: &OperatingPoint) -> Result<(Vec<f64>, FilmLinearization, FilmSolveInfo), FilmError> {
    pm.film.set_coordinates(local)?;
    let inp = op.film_inputs(k);
    let info = pm.film.solve(&inp, warm)?;
    let forces = pm.film.generalized_forces();
    let lin = pm.film.linearize_stiffness(&inp);
    Ok((forces, lin, info))
}

/// Accounts for one film solve in the report.
fn account(ctx: &mut Ctx<'_>, k: usize, info: FilmSolveInfo) {
    ctx.report.film_solves += 1;
    ctx.report.factorizations += info.factorizations;
    for w in info.warnings {
        ctx.report.warn(format!("pad {k}: {w}"));
    }
}

/// Evaluates pad k at local coordinates: forces and linearisation.
fn eval_pad(pm: &mut PadModel, k: usize, local: &[f64], warm: bool, ctx: &mut Ctx<'_>) -> Result<(Vec<f64>, FilmLinearization), FilmError> {
    if ctx.exhausted() {
        return Err(FilmError::Input(format!("work budget of {} film solves exhausted", ctx.budget)));
    }
    let (forces, lin, info) = film_eval(pm, k, local, warm, ctx.op)?;
    account(ctx, k, info);
    Ok((forces, lin))
}

/// Scale of each pad residual: the pad's load (times the lever for the tilt moment).
fn pad_scales(pm: &PadModel, forces: &[f64], floor: f64) -> Vec<f64> {
    let f = forces[0].hypot(forces[1]).max(floor);
    let lever = pm.film.geom.radius;
    pm.dofs.iter().map(|d| if *d == PadDof::Tilt { f * lever } else { f }).collect()
}

/// Admissible tilt interval (h > 0 at every node) with the other local coordinates fixed at `base`
/// (`base[2]`, the tilt slot, is ignored).
fn tilt_interval(pm: &PadModel, base: &[f64]) -> Result<(f64, f64), FilmError> {
    let film = &pm.film;
    let mut local = base.to_vec();
    local[2] = 0.0;
    let hc = film.nodal_thickness(&local);
    let phi = &film.geom.shapes[2].node;
    let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
    let contact = |i: usize, h: f64| FilmError::Contact { h_min_m: h, theta_deg: film.geom.node_theta[i].to_degrees(), z_m: film.geom.node_z[i] };
    for (i, (&h, &f)) in hc.iter().zip(phi).enumerate() {
        if f < 0.0 {
            hi = hi.min(h / -f);
        } else if f > 0.0 {
            lo = lo.max(-h / f);
        } else if h <= 0.0 {
            return Err(contact(i, h));
        }
    }
    if lo >= hi {
        let (h, i) = hc.iter().enumerate().fold((f64::INFINITY, 0), |m, (i, &v)| if v < m.0 { (v, i) } else { m });
        return Err(contact(i, h));
    }
    Ok((lo, hi))
}

fn relative(r: f64, scale: f64) -> f64 {
    (r / scale).abs()
}

/// Solves one pad's coordinates for a fixed journal position (warm-started from `q`).
///
/// Tilt: Newton safeguarded by bisection. Pivot translation (finite pivot stiffness): an outer safeguarded
/// Newton on ξ around the tilt solve, with the tilt-condensed stiffness; `Q_ξ − k ξ` decreases with ξ.
fn solve_pad(pm: &mut PadModel, k: usize, journal: [f64; 2], q: &[f64], ctx: &mut Ctx<'_>) -> Result<PadState, FilmError> {
    let floor = 1e-9 * ctx.force_scale;
    if ctx.op.held_pads.get(k).copied().unwrap_or(false) && !pm.dofs.is_empty() {
        let local: Vec<f64> = journal.iter().chain(q.iter()).copied().collect();
        let (forces, lin) = eval_pad(pm, k, &local, true, ctx)?;
        return Ok(PadState { q: q.to_vec(), forces, lin, unloaded: true, residual: 0.0 });
    }
    match pm.dofs.as_slice() {
        [] => {
            let (forces, lin) = eval_pad(pm, k, &journal, true, ctx)?;
            Ok(PadState { q: vec![], forces, lin, unloaded: false, residual: 0.0 })
        }
        [PadDof::Tilt] => solve_tilt(pm, k, &[journal[0], journal[1], 0.0], q[0], ctx, floor),
        [PadDof::Tilt, PadDof::PivotRadial] => solve_pivot(pm, k, journal, q, ctx, floor),
        other => Err(FilmError::Input(format!("unsupported pad coordinates {other:?}"))),
    }
}

fn solve_pivot(pm: &mut PadModel, k: usize, journal: [f64; 2], q: &[f64], ctx: &mut Ctx<'_>, floor: f64) -> Result<PadState, FilmError> {
    let stiff = pm.structural_stiffness[1];
    let clearance = pm.film.geom.base.node.iter().fold(0.0_f64, |m, &h| m.max(h));
    let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
    let mut xi = q[1];
    let mut tilt = q[0];
    let mut last = None;
    for _ in 0..ctx.params.max_inner_iterations {
        ctx.report.inner_iterations += 1;
        let st = match solve_tilt(pm, k, &[journal[0], journal[1], 0.0, xi], tilt, ctx, floor) {
            Ok(s) => s,
            Err(FilmError::Contact { .. }) => {
                // The pad cannot sit this close: move it out.
                lo = xi;
                xi = if hi.is_finite() { 0.5 * (lo + hi) } else { xi + 0.1 * clearance };
                continue;
            }
            Err(e) => return Err(e),
        };
        tilt = st.q[0];
        let r = st.forces[3] - stiff * xi;
        let scale = st.forces[0].hypot(st.forces[1]).max(floor);
        let l = &st.lin.stiffness;
        let k_eff = l[(3, 3)] + stiff - if l[(2, 2)] > 0.0 { l[(3, 2)] * l[(2, 3)] / l[(2, 2)] } else { 0.0 };
        let state = PadState { q: vec![tilt, xi], residual: relative(r, scale).max(st.residual), ..st };
        if relative(r, scale) <= ctx.params.pad_tol {
            return Ok(state);
        }
        if r > 0.0 {
            lo = xi;
        } else {
            hi = xi;
        }
        let newton = if k_eff > 0.0 { xi + r / k_eff } else { f64::NAN };
        xi = if newton > lo && newton < hi {
            newton
        } else if lo.is_finite() && hi.is_finite() {
            0.5 * (lo + hi)
        } else {
            xi + r.signum() * 0.1 * clearance
        };
        last = Some(state);
        if lo.is_finite() && hi.is_finite() && hi - lo <= 1e-14 * clearance {
            break;
        }
    }
    last.ok_or_else(|| FilmError::Input("pivot displacement not found".into()))
}

/// Tilt-only solve: Newton safeguarded by bisection on the admissible interval, with the other local
/// coordinates fixed at `base` (`base[2]` is the tilt slot).
fn solve_tilt(pm: &mut PadModel, k: usize, base: &[f64], warm: f64, ctx: &mut Ctx<'_>, floor: f64) -> Result<PadState, FilmError> {
    let (lo, hi) = tilt_interval(pm, base)?;
    let margin = 1e-7 * (hi - lo);
    let (mut blo, mut bhi) = (lo + margin, hi - margin);
    let mut d = warm.clamp(blo + margin, bhi - margin);
    let mut local = base.to_vec();
    let mut last: Option<PadState> = None;
    for _ in 0..ctx.params.max_inner_iterations {
        ctx.report.inner_iterations += 1;
        local[2] = d;
        let (forces, lin) = eval_pad(pm, k, &local, true, ctx)?;
        let r = forces[2];
        let kt = lin.stiffness[(2, 2)];
        let scale = pad_scales(pm, &forces, floor)[0];
        let rel = relative(r, scale);
        // A pad without any film pressure (fully diverging film) is not an equilibrium: the moment is zero
        // only because nothing acts on it. The true root lies towards larger δ (trailing edge closing).
        let share = forces[0].hypot(forces[1]) / ctx.force_scale;
        let loaded = share > 1e-9;
        let state = PadState { q: local[2..].to_vec(), forces, lin, unloaded: !loaded || kt <= 0.0, residual: rel };
        if rel <= ctx.params.pad_tol && loaded {
            return Ok(state);
        }
        // Pressure has appeared but the pad carries a vanishing share of the load: its tilt is not determined
        // by the film. Bisection goes on to the onset of pressure, so that the tilt of an unloaded pad is a
        // deterministic, continuous function of the inputs (an outer thermal loop relies on that).
        if loaded && share < 1e-6 && r <= 0.0 && (bhi - blo) <= 1e-8 * (hi - lo) {
            return Ok(PadState { unloaded: true, residual: 0.0, ..state });
        }
        if r > 0.0 || !loaded {
            blo = d;
        } else {
            bhi = d;
        }
        let newton = if kt > 0.0 && loaded { d + r / kt } else { f64::NAN };
        let next = if newton > blo && newton < bhi { newton } else { 0.5 * (blo + bhi) };
        last = Some(state);
        if (bhi - blo) <= 1e-13 * (hi - lo) {
            break;
        }
        d = next;
    }
    last.ok_or_else(|| FilmError::Input("no tilt iteration".into()))
}

/// Pad-condensed journal stiffness `K_jj − K_jp K_pp⁻¹ K_pj` (structural stiffness included).
fn condensed_journal_stiffness(pm: &PadModel, st: &PadState) -> Matrix2<f64> {
    let k = &st.lin.stiffness;
    let kjj = Matrix2::new(k[(0, 0)], k[(0, 1)], k[(1, 0)], k[(1, 1)]);
    let n = pm.dofs.len();
    if n == 0 || st.unloaded {
        return kjj;
    }
    let kpp = DMatrix::from_fn(n, n, |i, j| k[(2 + i, 2 + j)] + if i == j { pm.structural_stiffness[i] } else { 0.0 });
    let kpj = DMatrix::from_fn(n, 2, |i, j| k[(2 + i, j)]);
    let kjp = DMatrix::from_fn(2, n, |i, j| k[(i, 2 + j)]);
    match kpp.lu().solve(&kpj) {
        Some(x) => {
            let c = kjp * x;
            kjj - Matrix2::new(c[(0, 0)], c[(0, 1)], c[(1, 0)], c[(1, 1)])
        }
        None => kjj,
    }
}

/// Warns that the journal is held along a direction without static stiffness (reported as an axis, so ±d
/// give one warning).
fn warn_held(report: &mut SolveReport, dir: Vector2<f64>) {
    let axis = dir[1].atan2(dir[0]).to_degrees().rem_euclid(180.0).round() % 180.0 + 0.0;
    report.warn(format!(
        "the bearing has no static stiffness along the {axis:.0}° axis: the journal is held at its start \
         position in that direction (as for a guided rotor)"
    ));
}

/// Newton step `K Δ = r` by singular values: directions without stiffness (σ < 1e-7 σ_max) are not moved
/// along; a load component there cannot be carried. Returns the step and the held direction, if any.
fn journal_step(k: &Matrix2<f64>, r: &Vector2<f64>, tol: f64) -> Result<(Vector2<f64>, Option<Vector2<f64>>), String> {
    if !k.iter().all(|v| v.is_finite()) {
        return Err("non-finite bearing stiffness".into());
    }
    let svd = k.svd(true, true);
    let (Some(u), Some(vt)) = (svd.u, svd.v_t) else { return Err("singular value decomposition failed".into()) };
    let smax = svd.singular_values.max();
    if smax <= 0.0 {
        return Err("the bearing has no stiffness at this position".into());
    }
    let mut step = Vector2::zeros();
    let mut held = None;
    for i in 0..2 {
        let (ui, vi) = (u.column(i), vt.row(i).transpose());
        let ri = ui.dot(r);
        if svd.singular_values[i] > 1e-7 * smax {
            step += vi * (ri / svd.singular_values[i]);
        } else {
            if ri.abs() > 10.0 * tol {
                return Err(format!(
                    "a load component of {ri:.3e} N acts along ({:.2}, {:.2}), where the bearing has no stiffness",
                    ui[0], ui[1]
                ));
            }
            held = Some(vi);
        }
    }
    Ok((step, held))
}

/// All pads at a journal position, warm-started from `u`; returns pad states and the total film force.
fn solve_all_pads(model: &mut BearingModel, journal: [f64; 2], u: &[f64], ctx: &mut Ctx<'_>) -> Result<(Vec<PadState>, [f64; 2]), (usize, FilmError)> {
    let mut states = Vec::with_capacity(model.pads.len());
    let mut f = [0.0, 0.0];
    for k in 0..model.pads.len() {
        let (off, n) = (model.pads[k].offset, model.pads[k].dofs.len());
        let st = solve_pad(&mut model.pads[k], k, journal, &u[off..off + n], ctx).map_err(|e| (k, e))?;
        f[0] += st.forces[0];
        f[1] += st.forces[1];
        states.push(st);
    }
    Ok((states, f))
}

fn external_load(op: &OperatingPoint, fraction: f64) -> [f64; 2] {
    match op.load {
        LoadSpec::Force { magnitude_n, angle_rad } => [fraction * magnitude_n * angle_rad.cos(), fraction * magnitude_n * angle_rad.sin()],
        LoadSpec::Position { .. } => [0.0, 0.0],
    }
}

fn assemble_u(model: &BearingModel, journal: [f64; 2], states: &[PadState]) -> Vec<f64> {
    let mut u = vec![0.0; model.n_dofs];
    u[0] = journal[0];
    u[1] = journal[1];
    for (pm, st) in model.pads.iter().zip(states) {
        u[pm.offset..pm.offset + st.q.len()].copy_from_slice(&st.q);
    }
    u
}

fn min_film(model: &BearingModel) -> (usize, f64) {
    model.pads.iter().enumerate().map(|(k, p)| (k, p.film.h_min().0)).fold((0, f64::INFINITY), |m, x| if x.1 < m.1 { x } else { m })
}

enum Outer {
    Converged(Vec<f64>, Vec<PadState>, [f64; 2]),
    Failed { journal: [f64; 2], residual: f64, reason: String },
}

/// Newton on the journal position for load fraction `fraction`, from `u0`.
fn newton_journal(model: &mut BearingModel, u0: &[f64], fraction: f64, ctx: &mut Ctx<'_>, cancel: &dyn Cancel) -> Result<Outer, SolveError> {
    let w = external_load(ctx.op, fraction);
    let cb = model.assembled_clearance;
    let mut journal = [u0[0], u0[1]];
    let mut u = u0.to_vec();
    let (mut states, mut f) = match solve_all_pads(model, journal, &u, ctx) {
        Ok(x) => x,
        Err((_, FilmError::Contact { .. })) => {
            // Start from the centre if the guess closes a film.
            journal = [0.0, 0.0];
            u.iter_mut().for_each(|v| *v = 0.0);
            solve_all_pads(model, journal, &u, ctx).map_err(|(k, e)| ctx.film_error(k, e))?
        }
        Err((k, e)) => return Err(ctx.film_error(k, e)),
    };
    let tol = ctx.params.force_tol * ctx.force_scale;
    for _ in 0..ctx.params.max_iterations {
        if cancel.cancelled() {
            return Err(SolveError::Cancelled);
        }
        ctx.report.iterations += 1;
        let r = Vector2::new(f[0] + w[0], f[1] + w[1]);
        ctx.report.residual_history.push(r.norm() / ctx.force_scale);
        u = assemble_u(model, journal, &states);
        if r.norm() <= tol {
            return Ok(Outer::Converged(u, states, f));
        }
        let kred: Matrix2<f64> = model.pads.iter().zip(&states).map(|(pm, st)| condensed_journal_stiffness(pm, st)).sum();
        let mut step = match journal_step(&kred, &r, tol) {
            Ok((step, held)) => {
                if let Some(dir) = held {
                    warn_held(&mut ctx.report, dir);
                }
                step
            }
            Err(reason) => return Ok(Outer::Failed { journal, residual: r.norm() / ctx.force_scale, reason }),
        };
        let max = ctx.params.max_step * cb;
        if step.norm() > max {
            step *= max / step.norm();
        }
        let mut alpha = 1.0;
        let mut accepted = None;
        for _ in 0..14 {
            let trial = [journal[0] + alpha * step[0], journal[1] + alpha * step[1]];
            match solve_all_pads(model, trial, &u, ctx) {
                Ok((st2, f2)) => {
                    let r2 = Vector2::new(f2[0] + w[0], f2[1] + w[1]);
                    if r2.norm() < (1.0 - 1e-4 * alpha) * r.norm() || r2.norm() <= tol {
                        accepted = Some((trial, st2, f2));
                        break;
                    }
                }
                Err((_, FilmError::Contact { .. })) => {}
                Err((k, e)) => return Err(ctx.film_error(k, e)),
            }
            alpha *= 0.5;
        }
        match accepted {
            Some((j, s, ff)) => {
                journal = j;
                states = s;
                f = ff;
            }
            None => {
                // Leave the films at the last accepted point.
                let _ = solve_all_pads(model, journal, &u, ctx);
                return Ok(Outer::Failed { journal, residual: r.norm() / ctx.force_scale, reason: "line search found no decrease".into() });
            }
        }
    }
    let r = Vector2::new(f[0] + w[0], f[1] + w[1]);
    Ok(Outer::Failed { journal, residual: r.norm() / ctx.force_scale, reason: format!("{} iterations", ctx.params.max_iterations) })
}

/// Film nodes above which pads are solved in parallel (below, thread start-up costs more than it saves).
#[cfg(not(target_arch = "wasm32"))]
const PARALLEL_MIN_NODES: usize = 2500;

/// Film solves of all pads at `u`, in parallel on native targets when the meshes are large enough.
#[allow(clippy::type_complexity)]
fn eval_films(model: &mut BearingModel, u: &[f64], op: &OperatingPoint) -> Vec<Result<(Vec<f64>, FilmLinearization, FilmSolveInfo), FilmError>> {
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
                                .map(|(i, pm)| {
                                    let k = c * chunk + i;
                                    film_eval(pm, k, &locals[k], true, op)
                                })
                                .collect::<Vec<_>>()
                        })
                    })
                    .collect();
                handles
                    .into_iter()
                    .flat_map(|h| h.join().unwrap_or_else(|_| vec![Err(FilmError::Input("pad solve thread panicked".into()))]))
                    .collect()
            });
        }
    }
    model.pads.iter_mut().enumerate().map(|(k, pm)| film_eval(pm, k, &locals[k], true, op)).collect()
}

/// Evaluates every pad at the global coordinates `u` (one film solve each, no pad iteration).
fn eval_all(model: &mut BearingModel, u: &[f64], ctx: &mut Ctx<'_>) -> Result<Vec<PadState>, (usize, FilmError)> {
    if ctx.exhausted() {
        return Err((0, FilmError::Input(format!("work budget of {} film solves exhausted", ctx.budget))));
    }
    let floor = 1e-9 * ctx.force_scale;
    let results = eval_films(model, u, ctx.op);
    let mut states = Vec::with_capacity(model.pads.len());
    for (k, res) in results.into_iter().enumerate() {
        let (forces, lin, info) = res.map_err(|e| (k, e))?;
        account(ctx, k, info);
        let pm = &model.pads[k];
        let q = u[pm.offset..pm.offset + pm.dofs.len()].to_vec();
        let sc = pad_scales(pm, &forces, floor);
        let residual = q.iter().enumerate().map(|(d, qd)| relative(forces[2 + d] - pm.structural_stiffness[d] * qd, sc[d])).fold(0.0, f64::max);
        let share = forces[0].hypot(forces[1]) / ctx.force_scale;
        // An unloaded pad's relative residual is meaningless (its scale is its vanishing load); a held pad is
        // treated as unloaded (its coordinates are not solved for).
        let unloaded = share < 1e-6 || ctx.op.held_pads.get(k).copied().unwrap_or(false);
        states.push(PadState { q, forces, lin, unloaded, residual: if unloaded { 0.0 } else { residual } });
    }
    Ok(states)
}

/// Global residual `R(u)` (journal force balance, pad balances) and its merit (scaled sum of squares).
fn coupled_residual(model: &BearingModel, u: &[f64], states: &[PadState], w: [f64; 2], force_scale: f64) -> (Vec<f64>, f64) {
    let mut r = vec![0.0; model.n_dofs];
    let mut merit = 0.0;
    for st in states {
        r[0] += st.forces[0];
        r[1] += st.forces[1];
    }
    r[0] += w[0];
    r[1] += w[1];
    merit += (r[0] / force_scale).powi(2) + (r[1] / force_scale).powi(2);
    for (pm, st) in model.pads.iter().zip(states) {
        for (d, dof) in pm.dofs.iter().enumerate() {
            let i = pm.offset + d;
            r[i] = st.forces[2 + d] - pm.structural_stiffness[d] * u[i];
            let scale = if *dof == PadDof::Tilt { force_scale * model.journal_radius } else { force_scale };
            if !st.unloaded {
                merit += (r[i] / scale).powi(2);
            }
        }
    }
    (r, merit)
}

/// Coupled Newton on all coordinates at once (one film solve per pad per iteration).
///
/// Safeguards: on a cold start and whenever a pad's own stiffness is not positive (far from its
/// equilibrium the tilt moment is not monotone) that pad is placed with the safeguarded pad solve; pads that
/// carry no load are held and placed the same way; the Newton system is solved in a basis of the journal
/// directions that have stiffness plus the free pad coordinates, so a zero-stiffness journal direction (a
/// two-pad bearing sideways) is held, as in the pad-assembly method.
fn coupled_newton(model: &mut BearingModel, u0: &[f64], cold: bool, ctx: &mut Ctx<'_>, cancel: &dyn Cancel) -> Result<Outer, SolveError> {
    let n = model.n_dofs;
    let w = external_load(ctx.op, 1.0);
    let cb = model.assembled_clearance;
    let tol = ctx.params.force_tol * ctx.force_scale;
    let failed = |u: &[f64], states: &[PadState], reason: &str, fs: f64| {
        let f = states.iter().fold([0.0; 2], |a, p| [a[0] + p.forces[0], a[1] + p.forces[1]]);
        Outer::Failed { journal: [u[0], u[1]], residual: (f[0] + w[0]).hypot(f[1] + w[1]) / fs, reason: reason.to_string() }
    };
    let mut u = u0.to_vec();
    // Unloaded pads already re-examined in this solve.
    let mut rechecked = vec![false; model.pads.len()];
    let mut states = if cold {
        // Place every pad at the starting journal position (those placed before a suspension again: from
        // their placed coordinates that costs one film solve each).
        let mut st = Vec::with_capacity(model.pads.len());
        for k in 0..model.pads.len() {
            if k > ctx.params.placed_pads && cancel.suspend() {
                return Err(SolveError::Suspended { coordinates: u, placed_pads: k, report: Box::new(std::mem::take(&mut ctx.report)) });
            }
            let (off, nd) = (model.pads[k].offset, model.pads[k].dofs.len());
            let q: Vec<f64> = u[off..off + nd].to_vec();
            match solve_pad(&mut model.pads[k], k, [u[0], u[1]], &q, ctx) {
                Ok(p) => {
                    u[off..off + nd].copy_from_slice(&p.q);
                    st.push(p);
                }
                Err(_) => return Ok(Outer::Failed { journal: [u[0], u[1]], residual: f64::INFINITY, reason: "film closes at the start".into() }),
            }
        }
        st
    } else {
        match eval_all(model, &u, ctx) {
            Ok(st) => st,
            Err(_) => return Ok(Outer::Failed { journal: [u[0], u[1]], residual: f64::INFINITY, reason: "film closes at the start".into() }),
        }
    };
    for it in 0..ctx.params.max_iterations {
        if cancel.cancelled() {
            return Err(SolveError::Cancelled);
        }
        if it > 0 && cancel.suspend() {
            return Err(SolveError::Suspended { coordinates: u, placed_pads: 0, report: Box::new(std::mem::take(&mut ctx.report)) });
        }
        // Place pads that Newton cannot handle: no positive stiffness of their own, or no load.
        for k in 0..model.pads.len() {
            let pm = &model.pads[k];
            let nd = pm.dofs.len();
            let own_ok = (0..nd).all(|d| states[k].lin.stiffness[(2 + d, 2 + d)] + pm.structural_stiffness[d] > 0.0);
            if nd > 0 && (!own_ok || states[k].unloaded) && states[k].residual > ctx.params.pad_tol {
                let off = pm.offset;
                let q: Vec<f64> = u[off..off + nd].to_vec();
                let st = match solve_pad(&mut model.pads[k], k, [u[0], u[1]], &q, ctx) {
                    Ok(st) => st,
                    Err(e) => return Err(ctx.film_error(k, e)),
                };
                u[off..off + nd].copy_from_slice(&st.q);
                let share = st.forces[0].hypot(st.forces[1]) / ctx.force_scale;
                states[k] = PadState { unloaded: st.unloaded || share < 1e-6, residual: if share < 1e-6 { 0.0 } else { st.residual }, ..st };
            }
        }
        ctx.report.iterations += 1;
        let (r, merit) = coupled_residual(model, &u, &states, w, ctx.force_scale);
        ctx.report.residual_history.push(r[0].hypot(r[1]) / ctx.force_scale);
        let pads_ok = states.iter().all(|s| s.unloaded || s.residual <= ctx.params.pad_tol);
        if r[0].hypot(r[1]) <= tol && pads_ok {
            // Before accepting, give every unloaded (not held) pad the safeguarded search: a pad without
            // film pressure is in equilibrium only trivially, and from a warm start (a sweep, an edit) it may
            // sit in its pressure-free range although a loaded equilibrium exists at this operating point.
            let mut loaded_again = false;
            for k in 0..model.pads.len() {
                let held = ctx.op.held_pads.get(k).copied().unwrap_or(false);
                if !states[k].unloaded || held || model.pads[k].dofs.is_empty() || rechecked[k] {
                    continue;
                }
                rechecked[k] = true;
                let (off, nd) = (model.pads[k].offset, model.pads[k].dofs.len());
                let q: Vec<f64> = u[off..off + nd].to_vec();
                let st = match solve_pad(&mut model.pads[k], k, [u[0], u[1]], &q, ctx) {
                    Ok(st) => st,
                    Err(e) => return Err(ctx.film_error(k, e)),
                };
                let share = st.forces[0].hypot(st.forces[1]) / ctx.force_scale;
                u[off..off + nd].copy_from_slice(&st.q);
                loaded_again |= share >= 1e-6;
                states[k] = PadState { unloaded: st.unloaded || share < 1e-6, residual: if share < 1e-6 { 0.0 } else { st.residual }, ..st };
            }
            let (r2, _) = coupled_residual(model, &u, &states, w, ctx.force_scale);
            if !loaded_again && r2[0].hypot(r2[1]) <= tol {
                let f = states.iter().fold([0.0; 2], |a, p| [a[0] + p.forces[0], a[1] + p.forces[1]]);
                return Ok(Outer::Converged(u, states, f));
            }
            continue;
        }
        // Basis: journal directions with stiffness, then the free pad coordinates.
        let kred: Matrix2<f64> = model.pads.iter().zip(&states).map(|(pm, st)| condensed_journal_stiffness(pm, st)).sum();
        // Pads are not in equilibrium yet, so a residual along a zero-stiffness direction is allowed here.
        let (_, held) = match journal_step(&kred, &Vector2::new(r[0], r[1]), f64::INFINITY) {
            Ok(x) => x,
            Err(reason) => return Ok(failed(&u, &states, &reason, ctx.force_scale)),
        };
        if let Some(v) = held {
            warn_held(&mut ctx.report, v);
        }
        let mut basis: Vec<Vec<f64>> = Vec::new();
        match held {
            Some(v) => {
                let mut b = vec![0.0; n];
                b[0] = -v[1];
                b[1] = v[0];
                basis.push(b);
            }
            None => {
                for i in 0..2 {
                    let mut b = vec![0.0; n];
                    b[i] = 1.0;
                    basis.push(b);
                }
            }
        }
        let mut k = DMatrix::<f64>::zeros(n, n);
        for (pm, st) in model.pads.iter().zip(&states) {
            let idx: Vec<usize> = [0, 1].into_iter().chain((0..pm.dofs.len()).map(|d| pm.offset + d)).collect();
            for (a, &ga) in idx.iter().enumerate() {
                for (b, &gb) in idx.iter().enumerate() {
                    k[(ga, gb)] += st.lin.stiffness[(a, b)];
                }
            }
            for d in 0..pm.dofs.len() {
                k[(pm.offset + d, pm.offset + d)] += pm.structural_stiffness[d];
                if !st.unloaded {
                    let mut b = vec![0.0; n];
                    b[pm.offset + d] = 1.0;
                    basis.push(b);
                }
            }
        }
        let m = basis.len();
        let bm = DMatrix::from_fn(n, m, |i, c| basis[c][i]);
        let kr = bm.transpose() * &k * &bm;
        let rr = bm.transpose() * nalgebra::DVector::from_column_slice(&r);
        let Some(y) = kr.lu().solve(&rr).filter(|s| s.iter().all(|v| v.is_finite())) else {
            return Ok(failed(&u, &states, "singular Jacobian", ctx.force_scale));
        };
        let step: Vec<f64> = (&bm * y).iter().copied().collect();
        // Limit the journal step, and keep every film open with margin.
        let js = step[0].hypot(step[1]);
        let mut alpha = if js > ctx.params.max_step * cb { ctx.params.max_step * cb / js } else { 1.0 };
        for (kk, pm) in model.pads.iter().enumerate() {
            let dh = pm.film.nodal_thickness_delta(&model.local(kk, &step));
            for (h, d) in pm.film.h.node.iter().zip(&dh) {
                if *d < 0.0 {
                    alpha = alpha.min(0.5 * h / -d);
                }
            }
        }
        let mut accepted = false;
        for _ in 0..12 {
            let trial: Vec<f64> = u.iter().zip(&step).map(|(a, d)| a + alpha * d).collect();
            if let Ok(mut st2) = eval_all(model, &trial, ctx) {
                for (a, b) in st2.iter_mut().zip(&states) {
                    a.unloaded |= b.unloaded && a.forces[0].hypot(a.forces[1]) < 1e-6 * ctx.force_scale;
                }
                let (r2, m2) = coupled_residual(model, &trial, &st2, w, ctx.force_scale);
                if m2 < (1.0 - 1e-4 * alpha) * merit || (r2[0].hypot(r2[1]) <= tol && m2 <= merit) {
                    u = trial;
                    states = st2;
                    accepted = true;
                    break;
                }
            }
            alpha *= 0.5;
        }
        if !accepted {
            // Leave the films at the last accepted point.
            let _ = eval_all(model, &u, ctx);
            return Ok(failed(&u, &states, "line search found no decrease", ctx.force_scale));
        }
    }
    Ok(failed(&u, &states, "iteration limit", ctx.force_scale))
}

/// Walks the journal along the load direction from the centre in steps of 0.1 Cb until the residual along
/// the load changes sign with a restoring slope; returns the coordinates there (or `None`).
fn scan_along_load(model: &mut BearingModel, ctx: &mut Ctx<'_>, cancel: &dyn Cancel) -> Result<Option<Vec<f64>>, SolveError> {
    let w = external_load(ctx.op, 1.0);
    let wn = w[0].hypot(w[1]);
    if wn <= 0.0 {
        return Ok(None);
    }
    let dir = [w[0] / wn, w[1] / wn];
    let cb = model.assembled_clearance;
    let mut u = vec![0.0; model.n_dofs];
    let mut prev: Option<(f64, Vec<f64>)> = None;
    for i in 0..=100 {
        if cancel.cancelled() {
            return Err(SolveError::Cancelled);
        }
        #[allow(clippy::cast_precision_loss)]
        let e = 0.1 * cb * i as f64;
        let journal = [e * dir[0], e * dir[1]];
        let Ok((states, f)) = solve_all_pads(model, journal, &u, ctx) else { return Ok(None) };
        let g = (f[0] + w[0]) * dir[0] + (f[1] + w[1]) * dir[1];
        u = assemble_u(model, journal, &states);
        if let Some((gp, up)) = &prev {
            if *gp > 0.0 && g <= 0.0 {
                // Linear interpolation between the bracketing points.
                let t = gp / (gp - g);
                return Ok(Some(up.iter().zip(&u).map(|(a, b)| a + t * (b - a)).collect()));
            }
        }
        prev = Some((g, u.clone()));
    }
    Ok(None)
}

/// Solves the static equilibrium (or, for a prescribed position, the pads and the load).
///
/// `start`: a previous solution's global coordinates to warm-start from (sweeps).
///
/// # Errors
/// Touchdown, non-convergence, film failures or cancellation.
pub fn solve_equilibrium(
    model: &mut BearingModel,
    op: &OperatingPoint,
    params: EquilibriumParams,
    start: Option<&[f64]>,
    cancel: &dyn Cancel,
) -> Result<Equilibrium, SolveError> {
    solve_equilibrium_inner(model, op, params, start, cancel).map_err(|e| match e {
        // Every method failed with the films last seen close to contact: the load cannot be carried.
        SolveError::NotConverged { .. } => {
            let (pad, hmin) = min_film(model);
            let cb = model.assembled_clearance;
            if hmin < 0.05 * cb {
                let e = model.pads.first().map_or(&[0.0, 0.0][..], |p| p.film.coordinates());
                SolveError::Touchdown { pad, h_min_um: hmin * 1e6, eccentricity_ratio: e[0].hypot(e[1]) / cb }
            } else {
                e
            }
        }
        e => e,
    })
}

fn solve_equilibrium_inner(
    model: &mut BearingModel,
    op: &OperatingPoint,
    params: EquilibriumParams,
    start: Option<&[f64]>,
    cancel: &dyn Cancel,
) -> Result<Equilibrium, SolveError> {
    let t0 = Instant::now();
    let budget = params.max_film_solves_per_pad * model.pads.len().max(1);
    let mut ctx = Ctx { op, params, force_scale: force_scale(model, op), report: SolveReport::default(), budget };
    let cb = model.assembled_clearance;
    let finish = |model: &mut BearingModel, u: Vec<f64>, pads: Vec<PadState>, f: [f64; 2], mut ctx: Ctx<'_>, method: &str| {
        let w = external_load(op, 1.0);
        ctx.report.residual = if matches!(op.load, LoadSpec::Force { .. }) { (f[0] + w[0]).hypot(f[1] + w[1]) / ctx.force_scale } else { 0.0 };
        ctx.report.pad_residual = pads.iter().filter(|p| !p.unloaded).fold(0.0_f64, |m, p| m.max(p.residual));
        ctx.report.method = method.to_string();
        let mut pads = pads;
        // Full linearisation (stiffness and damping) at the converged state: the films hold it.
        for (k, p) in pads.iter_mut().enumerate() {
            p.lin = model.pads[k].film.linearize(&op.film_inputs(k));
        }
        for (k, p) in pads.iter_mut().enumerate() {
            // A pad whose load is a negligible share of the bearing's is "unloaded": its tilt sits where film
            // pressure just vanishes and is weakly determined.
            let share = p.forces[0].hypot(p.forces[1]) / ctx.force_scale;
            p.unloaded |= share < 1e-4;
            if p.unloaded && !model.pads[k].dofs.is_empty() {
                ctx.report.warn(format!(
                    "pad {k} carries almost no load ({:.1e} of the load scale): its tilt is weakly determined",
                    share
                ));
            } else if p.residual > 1e3 * ctx.params.pad_tol {
                ctx.report.warn(format!("pad {k} equilibrium residual {:.1e} (relative) above tolerance", p.residual));
            }
        }
        let (kmin, hmin) = min_film(model);
        if hmin < op.touchdown_film {
            return Err(SolveError::Touchdown { pad: kmin, h_min_um: hmin * 1e6, eccentricity_ratio: u[0].hypot(u[1]) / cb });
        }
        if hmin < 2.0 * op.touchdown_film {
            ctx.report.warn(format!("minimum film thickness {:.2} µm on pad {kmin} is close to touchdown ({:.2} µm)", hmin * 1e6, op.touchdown_film * 1e6));
        }
        ctx.report.seconds = t0.elapsed().as_secs_f64();
        Ok(Equilibrium { u, pads, film_force: f, report: ctx.report })
    };

    if let LoadSpec::Position { eccentricity_ratio, angle_rad } = op.load {
        let journal = [eccentricity_ratio * cb * angle_rad.cos(), eccentricity_ratio * cb * angle_rad.sin()];
        let mut u = start.map_or_else(|| vec![0.0; model.n_dofs], <[f64]>::to_vec);
        u[0] = journal[0];
        u[1] = journal[1];
        let (states, f) = solve_all_pads(model, journal, &u, &mut ctx).map_err(|(k, e)| match e {
            FilmError::Contact { h_min_m, .. } => SolveError::Touchdown { pad: k, h_min_um: h_min_m * 1e6, eccentricity_ratio },
            e => ctx.film_error(k, e),
        })?;
        let u = assemble_u(model, journal, &states);
        return finish(model, u, states, f, ctx, "prescribed journal position (pads solved)");
    }

    // Initial guess: previous solution, else a small displacement along the load.
    let u0 = match start {
        Some(s) if s.len() == model.n_dofs && s.iter().all(|v| v.is_finite()) => s.to_vec(),
        _ => {
            let mut u = vec![0.0; model.n_dofs];
            let w = external_load(op, 1.0);
            let wn = w[0].hypot(w[1]);
            if wn > 0.0 {
                u[0] = 0.2 * cb * w[0] / wn;
                u[1] = 0.2 * cb * w[1] / wn;
            }
            u
        }
    };
    let cold = params.placed_pads > 0 || !matches!(start, Some(s) if s.len() == model.n_dofs);
    let newton = match coupled_newton(model, &u0, cold, &mut ctx, cancel) {
        Err(SolveError::Suspended { coordinates, placed_pads, mut report }) => {
            report.seconds = t0.elapsed().as_secs_f64();
            return Err(SolveError::Suspended { coordinates, placed_pads, report });
        }
        r => r?,
    };
    match newton {
        Outer::Converged(u, s, f) => return finish(model, u, s, f, ctx, "coupled Newton"),
        Outer::Failed { reason, .. } => ctx.report.warn(format!("coupled Newton failed ({reason}); using pad assembly")),
    }
    // The fallbacks run to the end once started (their state is not a single iterate to resume from).
    let cancel = &NoSuspend(cancel);
    match newton_journal(model, &u0, 1.0, &mut ctx, cancel)? {
        Outer::Converged(u, s, f) => return finish(model, u, s, f, ctx, "Newton (pad assembly)"),
        Outer::Failed { reason, .. } => ctx.report.warn(format!("Newton from the initial guess failed ({reason}); trying a scan along the load")),
    }

    // Scan along the load direction for the first stable crossing (handles negative-stiffness regions and
    // folds, e.g. hydrostatic pads on soft pivots), then polish with Newton.
    if let Some(u_scan) = scan_along_load(model, &mut ctx, cancel)? {
        match newton_journal(model, &u_scan, 1.0, &mut ctx, cancel)? {
            Outer::Converged(u, s, f) => return finish(model, u, s, f, ctx, "scan along the load + Newton"),
            Outer::Failed { reason, .. } => ctx.report.warn(format!("Newton after the load-direction scan failed ({reason}); using load continuation")),
        }
    }

    // Load continuation from a centred journal.
    let steps = 12;
    let mut u = vec![0.0; model.n_dofs];
    let mut last_fail = (0.0, String::new());
    for s in 1..=steps {
        #[allow(clippy::cast_precision_loss)]
        let frac = s as f64 / steps as f64;
        match newton_journal(model, &u, frac, &mut ctx, cancel)? {
            Outer::Converged(u2, st, f) => {
                u = u2;
                if s == steps {
                    return finish(model, u, st, f, ctx, "load continuation");
                }
            }
            Outer::Failed { journal, residual, reason } => {
                last_fail = (residual, reason);
                let (pad, hmin) = min_film(model);
                let ecc = journal[0].hypot(journal[1]) / cb;
                if hmin < 0.05 * cb {
                    return Err(SolveError::Touchdown { pad, h_min_um: hmin * 1e6, eccentricity_ratio: ecc });
                }
                break;
            }
        }
    }
    Err(SolveError::NotConverged { iterations: ctx.report.iterations, residual: last_fail.0, reason: last_fail.1 })
}
