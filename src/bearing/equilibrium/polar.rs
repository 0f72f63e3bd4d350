//! Polar bracketing search for the journal position: robust where Newton cycles.
//!
//! With every pad solved inside (pad assembly), the residual `R(e) = F(e) + W` is continuous but need not be
//! smooth: a zero-preload pad whose film is uniform carries a load ∝ √(approach) on one side and floats on
//! the other, so the bearing's force law has an infinite slope (Newton overshoots to the mirror point and
//! cycles). In polar journal coordinates `e = s (cos ψ, sin ψ)`:
//!
//! ```text
//! g(s; ψ) = R(s u_ψ)·u_ψ        along the ray: > 0 at the centre for |ψ − ψ_W| < 90°, < 0 far out (restoring)
//! s*(ψ)   = the first root of g on the ray              (Illinois regula falsi in a bracket)
//! h(ψ)    = R(s*(ψ) u_ψ)·u_ψ⊥   across the ray: > 0 below the equilibrium angle, < 0 above
//! ψ*      = the root of h                               (Illinois regula falsi in a bracket)
//! ```
//!
//! Both roots are bracketed, so the search converges for any continuous restoring force law (intermediate
//! value theorem), superlinearly where the law is smooth. Each evaluation is a pad assembly.
//!
//! ## Pads near a fold
//! A floating pad may also have a loaded state beyond a fold of its tilt equilibrium; the search takes the
//! loaded one, so that the force law is one function of the journal position. Looking for it costs a scan
//! of the pad's loaded tilt range (about a dozen film solves per floating pad), which at every probe was
//! two thirds of the search's work on a starved bearing. So the probes place floating pads at their onset
//! of pressure only (the cheap law), and each ray's outcome is confirmed: at a ray's root every floating
//! pad is searched for a loaded state once. Where none has one, the root is a root of the loaded-preferring
//! law too (both laws agree there); where one has — or the ray found no root, ending the search — the ray is
//! solved again with the search on every probe, and so is every later ray.

use crate::bearing::equilibrium::eval::{external_load, min_film, Ctx};
use crate::bearing::equilibrium::pad::{assemble_u, solve_all_pads_open, solve_pad};
use crate::bearing::equilibrium::state::{Found, PadState, Stall, TOUCHDOWN_FRACTION, UNLOADED_SHARE};
use crate::bearing::film::model::BearingModel;
use crate::bearing::report::error::SolveError;
use crate::bearing::report::error::StallReason;
use crate::bearing::report::progress::Cancel;
use crate::bearing::report::warning::Method;
use crate::physics::reynolds::FilmError;

/// First angular step from the load direction [rad] (doubled until the bracket is found), and the largest
/// angle from the load that is searched.
const FIRST_ANGLE_STEP: f64 = 0.035;
const MAX_ANGLE: f64 = 1.55;
/// First radial step (fraction of Cb) when looking for a bracket along a ray; doubled up to `MAX_RADIAL_STEP`.
const FIRST_RADIAL_STEP: f64 = 0.02;
const MAX_RADIAL_STEP: f64 = 0.2;
/// Largest eccentricity searched, in units of Cb (zero-preload pads allow up to ~1/cos(β/2)).
const MAX_RADIUS: f64 = 10.0;
/// Bracket iterations at most per root.
const MAX_BRACKET_ITERATIONS: usize = 80;
/// A ray whose bracket collapses onto a step of its force law larger than this fraction of the load ends at
/// a jump, not a root.
const JUMP: f64 = 1e-3;
/// A ray's root is solved to this fraction of the smaller transverse residual at the ends of the angular
/// bracket (enough to know the sign of the transverse residual), never tighter than a tenth of the
/// tolerance; the first rays use the load as that scale.
const RAY_TOL_FRACTION: f64 = 1e-3;
/// An angular bracket narrower than this [rad] whose ends still differ by more than [`JUMP`] of the load
/// across their rays has collapsed onto a jump of the transverse force, not onto a root.
const ANGLE_JUMP_WIDTH: f64 = 1e-7;

/// The converged point on one ray.
struct RayRoot {
    s: f64,
    thinnest: (usize, f64),
    /// Residual along and across the ray [N].
    g: f64,
    h: f64,
    u: Vec<f64>,
    states: Vec<PadState>,
    force: [f64; 2],
}

/// One evaluation on a ray: `None` when a film closes there.
struct Probe {
    g: f64,
    /// Thinnest film there: (pad, h_min [m]).
    thinnest: (usize, f64),
    u: Vec<f64>,
    states: Vec<PadState>,
    force: [f64; 2],
}

/// Illinois (modified regula falsi) step inside a bracket `(a, fa) > 0 > (b, fb)`.
fn illinois(a: f64, fa: f64, b: f64, fb: f64) -> f64 {
    if fa.is_finite() && fb.is_finite() && fa != fb {
        let x = b - fb * (b - a) / (fb - fa);
        if x > a.min(b) && x < a.max(b) {
            return x;
        }
    }
    0.5 * (a + b)
}

/// The Illinois weights after an update of one end of the bracket (`side`: true for the positive end): the
/// updated end's weight `1`, and the retained end's weight `other` halved only when the same end was
/// updated the time before too (regula falsi stalling on one side). Successive updates alternating between
/// the ends are plain secant steps, superlinear on a smooth function; halving the retained end on every
/// update would bias every step and make the convergence linear.
fn illinois_scales(last_side: &mut Option<bool>, side: bool, other: f64) -> (f64, f64) {
    let other = if *last_side == Some(side) { 0.5 * other } else { 1.0 };
    *last_side = Some(side);
    (1.0, other)
}

struct Search<'m, 'c, 'o> {
    model: &'m mut BearingModel,
    ctx: &'c mut Ctx<'o>,
    w: [f64; 2],
    warm: Vec<f64>,
    tol: f64,
    /// Tolerance of the current ray's root [N] (see [`RAY_TOL_FRACTION`]).
    ray_tol: f64,
    /// The last ray ended at a jump of its force law rather than at a root: (pad that switched, g on the
    /// carrying-less side, g on the other) [N].
    jump: Option<(usize, f64, f64)>,
    /// Every probe searches its floating pads for a loaded state beyond a fold (set once a ray's outcome
    /// was not confirmed under the cheap law; see the module notes).
    thorough: bool,
}

impl Search<'_, '_, '_> {
    fn probe(&mut self, psi: f64, s: f64) -> Result<Option<Probe>, SolveError> {
        let dir = [psi.cos(), psi.sin()];
        let journal = [s * dir[0], s * dir[1]];
        let warm = self.warm.clone();
        let model = &mut *self.model;
        let placed = self.ctx.with_thorough_onset(self.thorough, |ctx| solve_all_pads_open(model, journal, &warm, ctx));
        match placed {
            Ok((states, force)) => {
                let u = assemble_u(self.model, journal, &states);
                self.warm.clone_from(&u);
                let g = (force[0] + self.w[0]) * dir[0] + (force[1] + self.w[1]) * dir[1];
                Ok(Some(Probe { g, thinnest: min_film(self.model), u, states, force }))
            }
            Err((_, FilmError::Contact { .. })) => Ok(None),
            Err((k, e)) => Err(self.ctx.film_error(k, e)),
        }
    }

    /// The search stops at a ray ψ without a restoring root; one that ended at a jump of its force law over
    /// zero is recorded as a gap in two dimensions.
    fn ray_without_root(&mut self, psi: f64) -> Result<Result<Found, Stall>, SolveError> {
        if let Some((pad, g_before, g_after)) = self.jump {
            self.ctx.gap_2d = Some((pad, psi, g_before, g_after));
            return Ok(Err(Stall { journal: [0.0; 2], residual: f64::INFINITY, reason: StallReason::RayForceJumps }));
        }
        Ok(Err(Stall { journal: [0.0; 2], residual: f64::INFINITY, reason: StallReason::RayWithoutRoot }))
    }

    /// The ray's root as [`Self::ray_tol_to`] finds it, confirmed under the loaded-preferring law: solved again
    /// with the fold search on every probe (from now on) when a floating pad has a loaded state at the root,
    /// or when the ray has no root.
    fn ray_to(
        &mut self,
        psi: f64,
        guess: f64,
        transverse_scale: f64,
        cancel: &dyn Cancel,
    ) -> Result<Option<RayRoot>, SolveError> {
        let r = self.ray_tol_to(psi, guess, transverse_scale, cancel)?;
        if self.thorough {
            return Ok(r);
        }
        if let Some(root) = r.as_ref() {
            if !self.loaded_beyond_fold(psi, root)? {
                return Ok(r);
            }
        }
        self.thorough = true;
        self.ray_tol_to(psi, guess, transverse_scale, cancel)
    }

    /// Whether a pad that floats at the ray's root has a loaded state there too (the fold search, once per
    /// floating pad).
    fn loaded_beyond_fold(&mut self, psi: f64, root: &RayRoot) -> Result<bool, SolveError> {
        let journal = [root.s * psi.cos(), root.s * psi.sin()];
        for (k, st) in root.states.iter().enumerate() {
            let pm = &mut self.model.pads[k];
            if !st.unloaded || pm.dofs().is_empty() || self.ctx.held(k) {
                continue;
            }
            let placed = self.ctx.with_thorough_onset(true, |ctx| solve_pad(pm, k, journal, &st.q, ctx));
            match placed {
                Ok(p) if self.ctx.share(&p) >= UNLOADED_SHARE => return Ok(true),
                Ok(_) => {}
                // The pad's film closes in the search (it did not at the root): not a state of the cheap law.
                Err(FilmError::Contact { .. }) => return Ok(true),
                Err(e) => return Err(self.ctx.film_error(k, e)),
            }
        }
        Ok(false)
    }

    /// The ray's root to a tolerance of [`RAY_TOL_FRACTION`] of `transverse_scale` [N]; solved again to a tenth
    /// of the tolerance when its transverse residual is already within the tolerance (a candidate answer).
    fn ray_tol_to(
        &mut self,
        psi: f64,
        guess: f64,
        transverse_scale: f64,
        cancel: &dyn Cancel,
    ) -> Result<Option<RayRoot>, SolveError> {
        let tight = 0.1 * self.tol;
        self.ray_tol = (RAY_TOL_FRACTION * transverse_scale).max(tight);
        let r = self.ray(psi, guess, cancel)?;
        match r {
            Some(r) if self.ray_tol > tight && r.h.abs() <= self.tol && r.g.abs() > tight => {
                self.ray_tol = tight;
                self.ray(psi, r.s, cancel)
            }
            r => Ok(r),
        }
    }

    /// The first root of g on the ray ψ, searched from `guess` [m]; `None` if the ray has no restoring root.
    fn ray(&mut self, psi: f64, guess: f64, cancel: &dyn Cancel) -> Result<Option<RayRoot>, SolveError> {
        let cb = self.model.assembled_clearance;
        self.jump = None;
        // Last point with g > 0, and first with g ≤ 0 or a closed film (`None` probe).
        let mut lo: Option<(f64, Probe)> = None;
        let mut hi: Option<(f64, Option<Probe>)> = None;
        // Bracket: walk out while g > 0, in while g ≤ 0 (or the film is closed).
        let mut s = guess.max(0.0);
        let mut step = FIRST_RADIAL_STEP * cb;
        loop {
            if cancel.cancelled() {
                return Err(SolveError::Cancelled);
            }
            let p = self.probe(psi, s)?;
            let positive = p.as_ref().is_some_and(|p| p.g > 0.0);
            if positive {
                lo = p.map(|p| (s, p));
                if hi.is_some() {
                    break;
                }
                s += step;
                if s > MAX_RADIUS * cb {
                    return Ok(None);
                }
            } else {
                hi = Some((s, p));
                if lo.is_some() {
                    break;
                }
                if s == 0.0 {
                    return Ok(None);
                }
                s = (s - step).max(0.0);
            }
            step = (2.0 * step).min(MAX_RADIAL_STEP * cb);
        }
        let (Some((mut a, mut pa)), Some((mut b, mut pb))) = (lo, hi) else { return Ok(None) };
        let (mut fa_scale, mut fb_scale) = (1.0, 1.0);
        let mut last_side = None;
        for _ in 0..MAX_BRACKET_ITERATIONS {
            let gb = pb.as_ref().map_or(f64::NEG_INFINITY, |p| p.g);
            let converged_b = gb.abs() <= self.ray_tol;
            if converged_b || pa.g.abs() <= self.ray_tol || (b - a).abs() <= 1e-13 * cb {
                if let Some(p) = pb.as_ref().filter(|p| {
                    !converged_b && pa.g.abs() > self.ray_tol && pa.g - p.g > JUMP * self.w[0].hypot(self.w[1])
                }) {
                    // No root but a jump: a pad switched between floating and a loaded state across it (any
                    // other jump — near a closing film, say — is only the end of this ray's search).
                    if let Some(pad) =
                        switching_pad(self.ctx, (&pa.states, pa.thinnest.1), (&p.states, p.thinnest.1), cb)
                    {
                        self.jump = Some((pad, pa.g, p.g));
                    }
                    return Ok(None);
                }
                // A bracket that collapsed onto a closed film (`pb` none) with the load still not carried at its
                // open end has no root: the film closes first.
                let (s, p) = if converged_b || (pb.is_some() && pa.g.abs() > gb.abs()) {
                    (b, pb)
                } else if pb.is_some() || pa.g.abs() <= self.ray_tol {
                    (a, Some(pa))
                } else {
                    (b, None)
                };
                let Some(p) = p else {
                    // The film closes before the force balances along this ray: remember the thinnest film
                    // seen on its carrying side (touchdown, if no other method finds an equilibrium).
                    if self.probe(psi, a)?.is_some() {
                        let (pad, h) = min_film(self.model);
                        self.ctx.closes_before_balance = Some((pad, h, a / cb));
                    }
                    return Ok(None);
                };
                let perp = [-psi.sin(), psi.cos()];
                let h = (p.force[0] + self.w[0]) * perp[0] + (p.force[1] + self.w[1]) * perp[1];
                return Ok(Some(RayRoot {
                    s,
                    thinnest: p.thinnest,
                    g: p.g,
                    h,
                    u: p.u,
                    states: p.states,
                    force: p.force,
                }));
            }
            let x = illinois(a, fa_scale * pa.g, b, fb_scale * gb);
            match self.probe(psi, x)? {
                Some(p) if p.g > 0.0 => {
                    a = x;
                    pa = p;
                    (fa_scale, fb_scale) = illinois_scales(&mut last_side, true, fb_scale);
                }
                p => {
                    b = x;
                    pb = p;
                    (fb_scale, fa_scale) = illinois_scales(&mut last_side, false, fa_scale);
                }
            }
        }
        Ok(None)
    }
}

/// The pad that switches between floating and a loaded state across a jump between the states `a` and `b`
/// (each with its thinnest film [m]): the one whose load share changes most, if it floats on one side and
/// carries load on the other, and neither side's film is closing (that is touchdown's territory).
fn switching_pad(ctx: &Ctx<'_>, a: (&[PadState], f64), b: (&[PadState], f64), cb: f64) -> Option<usize> {
    if a.1.min(b.1) < TOUCHDOWN_FRACTION * cb {
        return None;
    }
    let pad = (0..a.0.len()).max_by(|&i, &j| {
        let d = |k: usize| (ctx.share(&a.0[k]) - ctx.share(&b.0[k])).abs();
        d(i).total_cmp(&d(j))
    })?;
    let (sa, sb) = (ctx.share(&a.0[pad]), ctx.share(&b.0[pad]));
    (sa.min(sb) < UNLOADED_SHARE && sa.max(sb) >= UNLOADED_SHARE).then_some(pad)
}

/// Runs the polar bracketing search (force-prescribed loads only).
///
/// Where a pad has two states (floating, and loaded beyond a fold), the loaded one is taken: the force law is
/// then one function of the journal position, and a jump in it is a property of the bearing. A load ray that
/// ends at such a jump (the force along it steps across the load) is recorded in `ctx.force_gap`.
pub(super) fn polar_search(
    model: &mut BearingModel,
    centred: &[f64],
    ctx: &mut Ctx<'_>,
    cancel: &dyn Cancel,
) -> Result<Result<Found, Stall>, SolveError> {
    ctx.with_thorough_onset(false, |ctx| search(model, centred, ctx, cancel))
}

fn search(
    model: &mut BearingModel,
    centred: &[f64],
    ctx: &mut Ctx<'_>,
    cancel: &dyn Cancel,
) -> Result<Result<Found, Stall>, SolveError> {
    let w = external_load(ctx.op, 1.0);
    let stall = |reason: StallReason| Ok(Err(Stall { journal: [0.0; 2], residual: f64::INFINITY, reason }));
    if w[0].hypot(w[1]) <= 0.0 {
        return stall(StallReason::NoLoad);
    }
    let psi_w = w[1].atan2(w[0]);
    let tol = ctx.params.force_tol * ctx.force_scale;
    let cb = model.assembled_clearance;
    let warm = centred.to_vec();
    let load = w[0].hypot(w[1]);
    let mut search = Search { model, ctx, w, warm, tol, ray_tol: 0.1 * tol, jump: None, thorough: false };
    let mut guess = 0.3 * cb;
    let Some(mid) = search.ray_to(psi_w, guess, load, cancel)? else {
        if let Some((pad, g_before, g_after)) = search.jump {
            search.ctx.force_gap = Some((pad, load - g_before, load - g_after));
            return stall(StallReason::ForceJumpsAcrossLoad);
        }
        return stall(StallReason::NoRootAlongLoad);
    };
    guess = mid.s;
    search.ctx.report.iterations += 1;
    // Bracket ψ: h > 0 below the equilibrium angle, < 0 above.
    let (mut a, mut ra, mut b, mut rb) = (psi_w, None, psi_w, None);
    let mut step = FIRST_ANGLE_STEP;
    let up = mid.h > 0.0;
    if up {
        (a, ra) = (psi_w, Some(mid))
    } else {
        (b, rb) = (psi_w, Some(mid))
    }
    loop {
        let done_a = ra.as_ref().is_some_and(|r: &RayRoot| r.g.hypot(r.h) <= tol);
        let done_b = rb.as_ref().is_some_and(|r: &RayRoot| r.g.hypot(r.h) <= tol);
        if done_a || done_b || (ra.is_some() && rb.is_some()) {
            break;
        }
        if step > MAX_ANGLE {
            return stall(StallReason::NoTransverseSignChange);
        }
        let psi = if up { psi_w + step } else { psi_w - step };
        search.ctx.report.iterations += 1;
        let Some(r) = search.ray_to(psi, guess, load, cancel)? else { return search.ray_without_root(psi) };
        guess = r.s;
        match (up, r.h > 0.0) {
            (true, true) => (a, ra) = (psi, Some(r)),
            (true, false) => (b, rb) = (psi, Some(r)),
            (false, false) => (b, rb) = (psi, Some(r)),
            (false, true) => (a, ra) = (psi, Some(r)),
        }
        step *= 2.0;
    }
    let (mut fa_scale, mut fb_scale) = (1.0, 1.0);
    let mut last_side = None;
    for _ in 0..MAX_BRACKET_ITERATIONS {
        for r in [ra.as_ref(), rb.as_ref()].into_iter().flatten() {
            if r.g.hypot(r.h) <= tol {
                let residual = r.g.hypot(r.h) / search.ctx.force_scale;
                search.ctx.report.residual_history.push(residual);
                let pads = r.states.clone();
                return Ok(Ok(Found { u: r.u.clone(), pads, force: r.force, method: Method::None }));
            }
        }
        let (Some(pa), Some(pb)) = (ra.as_ref(), rb.as_ref()) else { break };
        let across = pa.h.abs().min(pb.h.abs());
        if (b - a).abs() <= ANGLE_JUMP_WIDTH && across > JUMP * load {
            // The rays' transverse force steps across zero between two rays a hair apart: if a pad engages
            // there beyond its fold, no ray in between balances the load.
            if let Some(pad) = switching_pad(search.ctx, (&pa.states, pa.thinnest.1), (&pb.states, pb.thinnest.1), cb) {
                search.ctx.gap_2d = Some((pad, 0.5 * (a + b), pa.h, pb.h));
                return stall(StallReason::BalancingRaysJump);
            }
        }
        if (b - a).abs() <= 1e-14 {
            break;
        }
        search.ctx.report.residual_history.push(pa.h.abs().min(pb.h.abs()) / search.ctx.force_scale);
        let psi = illinois(a, fa_scale * pa.h, b, fb_scale * pb.h);
        search.ctx.report.iterations += 1;
        let Some(r) = search.ray_to(psi, guess, across, cancel)? else { return search.ray_without_root(psi) };
        guess = r.s;
        if r.h > 0.0 {
            (a, ra) = (psi, Some(r));
            (fa_scale, fb_scale) = illinois_scales(&mut last_side, true, fb_scale);
        } else {
            (b, rb) = (psi, Some(r));
            (fb_scale, fa_scale) = illinois_scales(&mut last_side, false, fa_scale);
        }
    }
    let best = [ra, rb].into_iter().flatten().fold(None, |m: Option<RayRoot>, r| match m {
        Some(b) if b.g.hypot(b.h) <= r.g.hypot(r.h) => Some(b),
        _ => Some(r),
    });
    // The best point balances the load only with a nearly closed film: touchdown, if nothing else succeeds.
    if let Some(r) = best.as_ref().filter(|r| r.thinnest.1 < TOUCHDOWN_FRACTION * cb) {
        search.ctx.closes_before_balance = Some((r.thinnest.0, r.thinnest.1, r.s / cb));
    }
    let best = best.map_or(f64::INFINITY, |r| r.g.hypot(r.h));
    Ok(Err(Stall { journal: [0.0; 2], residual: best / search.ctx.force_scale, reason: StallReason::BracketExhausted }))
}

#[cfg(test)]
mod tests {
    use super::{illinois, illinois_scales};

    /// Iterations of the weighted regula falsi on `f` inside `[a, b]` (f(a) > 0 > f(b)) to |f| ≤ 1e-12.
    fn iterations(f: impl Fn(f64) -> f64, mut a: f64, mut b: f64) -> usize {
        let (mut fa, mut fb) = (f(a), f(b));
        let (mut wa, mut wb) = (1.0, 1.0);
        let mut last_side = None;
        for it in 1..=200 {
            let x = illinois(a, wa * fa, b, wb * fb);
            let fx = f(x);
            if fx.abs() <= 1e-12 {
                return it;
            }
            if fx > 0.0 {
                (a, fa) = (x, fx);
                (wa, wb) = illinois_scales(&mut last_side, true, wb);
            } else {
                (b, fb) = (x, fx);
                (wb, wa) = illinois_scales(&mut last_side, false, wa);
            }
        }
        usize::MAX
    }

    /// On smooth functions the Illinois method converges superlinearly (order ≈ 1.44): measured 12 and 7
    /// iterations to |f| ≤ 1e-12 from these brackets. Halving the retained end after every update, also when
    /// the updates alternate, makes the convergence linear (43 and 39 iterations) — the polar search's
    /// transverse force on the bearing starved to 12 l/min fell by only about 2 per ray that way.
    #[test]
    fn illinois_converges_superlinearly_on_smooth_functions() {
        let cubic = iterations(|x| 2.0 - x * x * x, 0.0, 3.0);
        let cosine = iterations(|x: f64| x.cos() - x, 0.0, 1.5);
        assert!(cubic <= 15 && cosine <= 15, "cubic {cubic}, cosine {cosine} iterations");
    }
}
