//! Coupled Newton on all coordinates at once: one film solve per pad per iteration, the films' analytic
//! Jacobian `∂R/∂u = −(K_film + K_s)` assembled through the [`DofMap`](crate::bearing::film::coordinates::DofMap).
//!
//! Safeguards: on a cold start, and whenever a pad's own stiffness is not positive (far from its
//! equilibrium the tilt moment is not monotone), that pad is placed with the safeguarded pad solve; pads
//! that carry no load are held and placed the same way. The Newton system is solved in a basis of the
//! journal directions that have stiffness plus the loaded pads' coordinates, so a zero-stiffness journal
//! direction (a two-pad bearing sideways) is held, as in the pad-assembly method. A backtracking line search
//! on the scaled residual keeps every film open.
//!
//! Before accepting a converged state, every unloaded pad is searched once for a loaded state
//! ([`recheck_unloaded`]); Newton goes on from one it finds. A lightly loaded pad near the fold of its tilt
//! equilibrium (its moment rises through zero past the onset of pressure and falls again) can lose that
//! state within Newton's first step: its film drops to the onset of pressure again and the pads are back
//! in the states the solve had converged in. Newton then returns to that converged state rather than
//! iterating to it a second time.

use crate::bearing::report::error::StallReason;
use crate::bearing::report::warning::Method;
use nalgebra::{DMatrix, DVector, Vector2};

use crate::bearing::equilibrium::eval::{coupled_residual, eval_all, external_load, total_force, Ctx};
use crate::bearing::equilibrium::journal::{bearing_stiffness, journal_step, pads_ahead, unsupported_direction};
use crate::bearing::equilibrium::pad::{follow_journal, solve_pad};
use crate::bearing::equilibrium::state::{Found, PadState, Resume, Stall, SUFFICIENT_DECREASE, UNLOADED_SHARE};
use crate::bearing::film::coordinates::JOURNAL_DOFS;
use crate::bearing::film::model::BearingModel;
use crate::bearing::report::error::SolveError;
use crate::bearing::report::progress::{Cancel, Progress};

/// Backtracking halvings of a Newton step before the line search gives up.
const LINE_SEARCH_HALVINGS: usize = 12;
/// Fraction of the local film thickness a step may close at most.
const FILM_CLOSING_FRACTION: f64 = 0.5;
/// Relative force residual below which a Newton step that the line search rejects is taken anyway (at most
/// [`KINK_STEPS`] times per solve): there the film force is continuous but only piecewise smooth (a node of
/// the cavitation boundary changes state between the point and the step), the Jacobian of one side need not
/// decrease the residual on the other, and the next Newton step, with the Jacobian of the side it lands on,
/// converges. Measured on a 4-pad zero-preload bearing at S = 0.01 (h_min 4.7 µm): Newton reached 2.1e-5,
/// 3.4e-8, then no step decreased the residual (until the work budget ran out in the fallbacks); the step
/// taken anyway lands at 1.4e-4 and Newton converges from there in four steps to 1e-12.
const KINK_RESIDUAL: f64 = 1e-6;
/// Newton steps taken without decrease near a kink, at most, per solve.
const KINK_STEPS: usize = 4;
/// Fraction of the force tolerance above which an unloaded pad's film force is placed away
/// ([`settle_stray_pressure`]).
const STRAY_SHARE: f64 = 0.1;

type Outcome = Progress<Result<Found, Stall>, Resume>;
/// An accepted trial point: coordinates and pad states.
type Accepted = (Vec<f64>, Vec<PadState>);

/// Runs the coupled Newton from `u0` (`cold`: place every pad first).
pub(super) fn coupled_newton(
    model: &mut BearingModel,
    u0: &[f64],
    cold: bool,
    ctx: &mut Ctx<'_>,
    cancel: &dyn Cancel,
) -> Result<Outcome, SolveError> {
    let w = external_load(ctx.op, 1.0);
    let tol = ctx.params.force_tol * ctx.force_scale;
    let mut u = u0.to_vec();
    let mut states = if cold {
        match cold_start(model, &mut u, ctx, cancel)? {
            Progress::Done(Some(st)) => st,
            Progress::Done(None) => {
                return Ok(Progress::Done(Err(Stall::new(&u, f64::INFINITY, StallReason::FilmClosesAtStart))))
            }
            Progress::Suspended(r) => return Ok(Progress::Suspended(r)),
        }
    } else {
        match eval_all(model, &u, ctx) {
            Ok(st) => st,
            Err(_) => return Ok(Progress::Done(Err(Stall::new(&u, f64::INFINITY, StallReason::FilmClosesAtStart)))),
        }
    };
    // Unloaded pads already re-examined in this solve.
    let mut rechecked = vec![false; model.pads.len()];
    let none_moved = vec![false; model.pads.len()];
    // Walks along an unsupported load taken so far (each loads one more pad).
    let mut walks = 0;
    // Step limit of the line search [m]: `max_step` Cb, doubled after each capped step taken whole.
    let base_radius = ctx.params.max_step * model.assembled_clearance;
    let mut radius = base_radius;
    let mut kink_steps = 0;
    // The converged state before the search before acceptance loaded a pad again ([`recheck_unloaded`]).
    let mut before_recheck: Option<Accepted> = None;
    place_hard_pads(model, &mut u, &mut states, &none_moved, ctx)?;
    for it in 0..ctx.params.max_iterations {
        if cancel.cancelled() {
            return Err(SolveError::Cancelled);
        }
        if it > 0 && cancel.suspend() {
            return Ok(Progress::Suspended(Resume { coordinates: u, placed_pads: 0, report: Default::default() }));
        }
        if before_recheck.as_ref().is_some_and(|(_, s1)| same_unloaded(s1, &states)) {
            // Newton dropped every pad the search loaded again (it passed the fold of the pad's loaded branch:
            // no equilibrium with it loaded is reachable from here) and is back among the pad states it had
            // converged in, whose unloaded pads have all been searched: that converged state is the answer,
            // which Newton would otherwise reach again (in seven iterations on the preview compressor, JFO).
            if let Some((u1, s1)) = before_recheck.take() {
                (u, states) = (u1, s1);
            }
        }
        ctx.report.iterations += 1;
        let (r, merit) = coupled_residual(model, &u, &states, w, ctx.force_scale);
        ctx.report.residual_history.push(r[0].hypot(r[1]) / ctx.force_scale);
        let pads_ok = states.iter().all(|s| s.unloaded || s.residual <= ctx.params.pad_tol);
        if r[0].hypot(r[1]) <= tol && pads_ok {
            // Before accepting, give every unloaded (not held) pad the safeguarded search: a pad without film
            // pressure is in equilibrium only trivially, and from a warm start (a sweep, an edit) it may sit in
            // its pressure-free range although a loaded equilibrium exists at this operating point.
            let converged = (u.clone(), states.clone());
            let loaded_again = recheck_unloaded(model, &mut u, &mut states, &mut rechecked, ctx)?;
            if loaded_again && before_recheck.is_none() {
                before_recheck = Some(converged);
            }
            let (r2, _) = coupled_residual(model, &u, &states, w, ctx.force_scale);
            if !loaded_again && r2[0].hypot(r2[1]) <= tol {
                let force = total_force(&states);
                return Ok(Progress::Done(Ok(Found { u, pads: states, force, method: Method::CoupledNewton })));
            }
            continue;
        }
        let step = newton_step(model, &states, &r);
        let accepted = match &step {
            Ok(s) => match line_search(model, (&u, &states), s, merit, w, radius, false, ctx)? {
                None if kink_steps < KINK_STEPS && r[0].hypot(r[1]) <= KINK_RESIDUAL * ctx.force_scale => {
                    kink_steps += 1;
                    line_search(model, (&u, &states), s, merit, w, radius, true, ctx)?
                }
                a => a,
            },
            Err(_) => None,
        };
        if let Some(((u2, s2), full_capped)) = accepted {
            u = u2;
            states = s2;
            // A capped step taken whole: the films are far from their load (soft pivots under a heavy load),
            // so let the steps grow; otherwise back to the base limit.
            radius = if full_capped { 2.0 * radius } else { base_radius };
            continue;
        }
        // No Newton progress. A floating pad may have a loaded state here too (a fold: negative preload, pivot
        // past mid-pad), which the cheap placement did not look for: search every unloaded pad thoroughly once.
        // (Placing them moves their film force: Newton then has a new residual to work on.)
        let before = total_force(&states);
        let loaded_again = recheck_unloaded(model, &mut u, &mut states, &mut rechecked, ctx)?;
        let settled = settle_stray_pressure(model, &mut u, &mut states, ctx)?;
        let after = total_force(&states);
        if loaded_again || settled || (after[0] - before[0]).hypot(after[1] - before[1]) > STRAY_SHARE * tol {
            continue;
        }
        // If part of the load acts where no pad holds the journal (every pad floats, or
        // the loaded pads leave a direction without stiffness), walk along it until another pad picks up load.
        let kred = bearing_stiffness(&model.pads, &states);
        if walks < model.pads.len() {
            if let Some(d) =
                unsupported_direction(&kred, &Vector2::new(r[0], r[1]), tol).filter(|d| pads_ahead(&model.pads, *d))
            {
                walks += 1;
                // Following the journal rigidly first (cheap); then, if no pad picked up load before a film
                // closed, searching the approached floating pads for a loaded state on the way.
                let walked = match advance_until_loaded(model, &u, &states, d, false, ctx)? {
                    None => advance_until_loaded(model, &u, &states, d, true, ctx)?,
                    found => found,
                };
                if let Some((u2, s2)) = walked {
                    u = u2;
                    states = s2;
                    continue;
                }
            }
        }
        // Leave the films at the last accepted point.
        let _ = eval_all(model, &u, ctx);
        let reason = step.err().unwrap_or(StallReason::NoDecrease);
        return Ok(Progress::Done(Err(stall(&u, &states, w, reason, ctx))));
    }
    Ok(Progress::Done(Err(stall(&u, &states, w, StallReason::IterationLimit(ctx.params.max_iterations), ctx))))
}

/// Whether two sets of pad states have the same pads unloaded.
fn same_unloaded(a: &[PadState], b: &[PadState]) -> bool {
    a.iter().zip(b).all(|(x, y)| x.unloaded == y.unloaded)
}

fn stall(u: &[f64], states: &[PadState], w: [f64; 2], reason: StallReason, ctx: &Ctx<'_>) -> Stall {
    let f = total_force(states);
    Stall::new(u, (f[0] + w[0]).hypot(f[1] + w[1]) / ctx.force_scale, reason)
}

/// Places every pad at the starting journal position (those placed before a suspension again: from their
/// placed coordinates that costs one film solve each). `None` if a film closes.
fn cold_start(
    model: &mut BearingModel,
    u: &mut [f64],
    ctx: &mut Ctx<'_>,
    cancel: &dyn Cancel,
) -> Result<Progress<Option<Vec<PadState>>, Resume>, SolveError> {
    let mut st = Vec::with_capacity(model.pads.len());
    for k in 0..model.pads.len() {
        if k > ctx.params.placed_pads && cancel.suspend() {
            return Ok(Progress::Suspended(Resume {
                coordinates: u.to_vec(),
                placed_pads: k,
                report: Default::default(),
            }));
        }
        let slice = model.dofs.pad_slice(k);
        let q = u[slice.clone()].to_vec();
        match solve_pad(&mut model.pads[k], k, [u[0], u[1]], &q, ctx) {
            Ok(p) => {
                u[slice].copy_from_slice(&p.q);
                st.push(p);
            }
            Err(_) => return Ok(Progress::Done(None)),
        }
    }
    Ok(Progress::Done(Some(st)))
}

/// Re-places pad k with the safeguarded pad solve; a pad carrying a vanishing share counts as unloaded.
fn replace_pad(model: &mut BearingModel, k: usize, u: &mut [f64], ctx: &mut Ctx<'_>) -> Result<PadState, SolveError> {
    let slice = model.dofs.pad_slice(k);
    let q = u[slice.clone()].to_vec();
    let st = solve_pad(&mut model.pads[k], k, [u[0], u[1]], &q, ctx).map_err(|e| ctx.film_error(k, e))?;
    u[slice].copy_from_slice(&st.q);
    let floating = ctx.share(&st) < UNLOADED_SHARE;
    Ok(PadState { unloaded: st.unloaded || floating, residual: if floating { 0.0 } else { st.residual }, ..st })
}

/// Places the pads Newton cannot handle: no positive stiffness of their own, or no load. An unloaded pad
/// that `moved_unloaded` says was carried along with a moving journal ([`follow_journal`]) is searched again
/// only if it picked up load (a journal moving towards a floating pad loads it); one that stays unloaded
/// carries a negligible force until the search before acceptance ([`recheck_unloaded`]) places it exactly.
fn place_hard_pads(
    model: &mut BearingModel,
    u: &mut [f64],
    states: &mut [PadState],
    moved_unloaded: &[bool],
    ctx: &mut Ctx<'_>,
) -> Result<(), SolveError> {
    for k in 0..model.pads.len() {
        let pm = &model.pads[k];
        let nd = pm.dofs().len();
        if nd == 0 || (ctx.held(k) && states[k].unloaded) {
            continue;
        }
        let own_ok = (0..nd).all(|d| {
            states[k].lin.stiffness[(JOURNAL_DOFS + d, JOURNAL_DOFS + d)] + pm.structure.stiffness[(d, d)] > 0.0
        });
        let picked_up = moved_unloaded[k] && ctx.share(&states[k]) >= UNLOADED_SHARE;
        if picked_up || ((!own_ok || states[k].unloaded) && states[k].residual > ctx.params.pad_tol) {
            states[k] = replace_pad(model, k, u, ctx)?;
        }
    }
    Ok(())
}

/// Gives every unloaded, not held pad one safeguarded search; true if one of them picked up load.
fn recheck_unloaded(
    model: &mut BearingModel,
    u: &mut [f64],
    states: &mut [PadState],
    rechecked: &mut [bool],
    ctx: &mut Ctx<'_>,
) -> Result<bool, SolveError> {
    let mut loaded_again = false;
    for k in 0..model.pads.len() {
        if !states[k].unloaded || ctx.held(k) || model.pads[k].dofs().is_empty() || rechecked[k] {
            continue;
        }
        rechecked[k] = true;
        let placed = ctx.with_thorough_onset(true, |ctx| replace_pad(model, k, u, ctx));
        states[k] = placed?;
        if ctx.share(&states[k]) >= UNLOADED_SHARE {
            loaded_again = true;
            ctx.loaded_state_found.push(k);
        }
    }
    Ok(loaded_again)
}

/// Places again at its onset of pressure every unloaded (not held) pad that carries more than
/// [`STRAY_SHARE`] of the force tolerance; true if one of them then carries less. Newton does not move an
/// unloaded pad, and one carried along with the journal can pick up a film force below [`UNLOADED_SHARE`]
/// but above the tolerance, which no journal motion removes where the bearing has no stiffness across it
/// (the test rig's floating top pad, 2.3e-7 of a 118 kN load, sideways), after its one thorough search
/// ([`recheck_unloaded`]) has been spent.
fn settle_stray_pressure(
    model: &mut BearingModel,
    u: &mut [f64],
    states: &mut [PadState],
    ctx: &mut Ctx<'_>,
) -> Result<bool, SolveError> {
    let stray = STRAY_SHARE * ctx.params.force_tol;
    let mut settled = false;
    for k in 0..model.pads.len() {
        let share = ctx.share(&states[k]);
        if !states[k].unloaded || ctx.held(k) || model.pads[k].dofs().is_empty() || share <= stray {
            continue;
        }
        let placed = replace_pad(model, k, u, ctx)?;
        settled |= ctx.share(&placed) < share;
        states[k] = placed;
    }
    Ok(settled)
}

/// The Newton step over the journal directions with stiffness and the loaded pads' coordinates.
fn newton_step(model: &BearingModel, states: &[PadState], r: &[f64]) -> Result<Vec<f64>, StallReason> {
    let n = model.n_dofs();
    let kred = bearing_stiffness(&model.pads, states);
    // Pads are not in equilibrium yet, so a residual along a zero-stiffness direction is allowed here.
    let (_, held) = journal_step(&kred, &Vector2::new(r[0], r[1]), f64::INFINITY)?;
    let unit = |i: usize| {
        let mut b = vec![0.0; n];
        b[i] = 1.0;
        b
    };
    let mut basis: Vec<Vec<f64>> = match held {
        Some(v) => {
            let mut b = vec![0.0; n];
            b[0] = -v[1];
            b[1] = v[0];
            vec![b]
        }
        None => (0..JOURNAL_DOFS).map(unit).collect(),
    };
    let mut k = DMatrix::<f64>::zeros(n, n);
    for (p, (pm, st)) in model.pads.iter().zip(states).enumerate() {
        // An unloaded tilting pad is held and contributes nothing (see `condensed_journal_stiffness`).
        if st.unloaded && !pm.dofs().is_empty() {
            continue;
        }
        model.dofs.scatter_add(p, &st.lin.stiffness, &mut k);
        model.dofs.scatter_add_pad_block(p, &pm.structure.stiffness, &mut k);
        basis.extend(model.dofs.pad_slice(p).map(unit));
    }
    let bm = DMatrix::from_fn(n, basis.len(), |i, c| basis[c][i]);
    let kr = bm.transpose() * &k * &bm;
    let rr = bm.transpose() * DVector::from_column_slice(r);
    let y = kr.lu().solve(&rr).filter(|s| s.iter().all(|v| v.is_finite())).ok_or(StallReason::SingularJacobian)?;
    Ok((&bm * y).iter().copied().collect())
}

/// Steps of the walk along an unbalanced force while every pad floats, as a fraction of Cb, and their number.
const WALK_STEP: f64 = 0.05;
const WALK_STEPS: usize = 60;

/// Moves the journal along the unit direction `d` in steps of [`WALK_STEP`] Cb, every pad with coordinates
/// following it rigidly ([`follow_journal`]), until a pad that floats now picks up load; `None` if a film
/// closes first or none does within [`WALK_STEPS`]. `search_approached`: a floating pad whose film thins
/// is also searched for a loaded state beyond its fold at each step (a negative-preload pad followed
/// rigidly keeps a diverging film, without pressure, until it closes).
fn advance_until_loaded(
    model: &mut BearingModel,
    u: &[f64],
    states: &[PadState],
    d: Vector2<f64>,
    search_approached: bool,
    ctx: &mut Ctx<'_>,
) -> Result<Option<Accepted>, SolveError> {
    let cb = model.assembled_clearance;
    let follows: Vec<bool> = model
        .pads
        .iter()
        .enumerate()
        .map(|(k, pm)| !(pm.dofs().is_empty() || ctx.held(k) && states[k].unloaded))
        .collect();
    let floating: Vec<bool> = follows.iter().zip(states).map(|(f, s)| *f && s.unloaded).collect();
    // Thinnest film of each floating pad at the previous step (the first step only sets it: the pads were
    // searched at the start).
    let mut last_h_min = vec![0.0; model.pads.len()];
    for i in 1..=WALK_STEPS {
        #[allow(clippy::cast_precision_loss)]
        let de = [WALK_STEP * cb * i as f64 * d[0], WALK_STEP * cb * i as f64 * d[1]];
        let mut trial = u.to_vec();
        trial[0] += de[0];
        trial[1] += de[1];
        for k in (0..model.pads.len()).filter(|k| follows[*k]) {
            let slice = model.dofs.pad_slice(k);
            let q = follow_journal(&model.pads[k], &u[slice.clone()], de);
            trial[slice].copy_from_slice(&q);
        }
        let Ok(mut st2) = eval_all(model, &trial, ctx) else { return Ok(None) };
        for (a, b) in st2.iter_mut().zip(states) {
            a.unloaded |= b.unloaded && ctx.share(a) < UNLOADED_SHARE;
        }
        place_hard_pads(model, &mut trial, &mut st2, &floating, ctx)?;
        // A floating pad the journal approaches may have a loaded state beyond its fold (negative preload)
        // that following the journal rigidly never reaches: search it thoroughly while its film thins.
        for k in 0..model.pads.len() {
            if !(search_approached && floating[k] && st2[k].unloaded) {
                continue;
            }
            let h = model.pads[k].film.h_min().0;
            if h < last_h_min[k] {
                let placed = ctx.with_thorough_onset(true, |ctx| replace_pad(model, k, &mut trial, ctx));
                st2[k] = placed?;
            }
            last_h_min[k] = h;
        }
        if st2.iter().zip(&floating).any(|(s, f)| *f && !s.unloaded) {
            return Ok(Some((trial, st2)));
        }
    }
    Ok(None)
}

/// Backtracking on the merit, the step limited to `max_step` Cb (journal motion or film change) and every
/// film kept open. A trial
/// point is judged with its unloaded pads placed again (what the next iteration starts from).
/// `any`: the first trial point whose films are open is taken, decrease or not (see [`KINK_RESIDUAL`]).
#[allow(clippy::too_many_arguments)]
fn line_search(
    model: &mut BearingModel,
    (u, states): (&[f64], &[PadState]),
    step: &[f64],
    merit: f64,
    w: [f64; 2],
    radius: f64,
    any: bool,
    ctx: &mut Ctx<'_>,
) -> Result<Option<(Accepted, bool)>, SolveError> {
    let tol = ctx.params.force_tol * ctx.force_scale;
    let js = step[0].hypot(step[1]);
    // The step is limited where it changes the films: by `radius` of journal motion, or, when the pads move
    // with the journal, of film thickness change.
    let mut dh_max = 0.0_f64;
    let mut closing = 1.0_f64;
    for (kk, pm) in model.pads.iter().enumerate() {
        let dh = pm.film.nodal_thickness_delta(&model.local(kk, step));
        for (h, d) in pm.film.h.node.iter().zip(&dh) {
            dh_max = dh_max.max(d.abs());
            if *d < 0.0 {
                closing = closing.min(FILM_CLOSING_FRACTION * h / -d);
            }
        }
    }
    let mut alpha = if js > radius && dh_max > radius { radius / js.min(dh_max) } else { 1.0 };
    let capped = alpha < 1.0 && alpha < closing;
    alpha = alpha.min(closing);
    // Unloaded pads are held by the Newton step; on a trial point they follow the journal.
    let moved: Vec<bool> = model
        .pads
        .iter()
        .zip(states)
        .enumerate()
        .map(|(k, (pm, st))| st.unloaded && !pm.dofs().is_empty() && !ctx.held(k))
        .collect();
    for halving in 0..LINE_SEARCH_HALVINGS {
        let mut trial: Vec<f64> = u.iter().zip(step).map(|(a, d)| a + alpha * d).collect();
        let de = [alpha * step[0], alpha * step[1]];
        for (k, _) in moved.iter().enumerate().filter(|m| *m.1) {
            let slice = model.dofs.pad_slice(k);
            let q = follow_journal(&model.pads[k], &u[slice.clone()], de);
            trial[slice].copy_from_slice(&q);
        }
        if let Ok(mut st2) = eval_all(model, &trial, ctx) {
            for (a, b) in st2.iter_mut().zip(states) {
                a.unloaded |= b.unloaded && ctx.share(a) < UNLOADED_SHARE;
            }
            place_hard_pads(model, &mut trial, &mut st2, &moved, ctx)?;
            let (r2, m2) = coupled_residual(model, &trial, &st2, w, ctx.force_scale);
            if any
                || m2.sqrt() < (1.0 - SUFFICIENT_DECREASE * alpha) * merit.sqrt()
                || (r2[0].hypot(r2[1]) <= tol && m2 <= merit)
            {
                return Ok(Some(((trial, st2), capped && halving == 0)));
            }
        }
        alpha *= 0.5;
    }
    Ok(None)
}
