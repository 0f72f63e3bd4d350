//! One pad's equilibrium for a fixed journal position (Lund's pad assembly, inner problem).
//!
//! ```text
//! R_d(q) = Q_d(e, q) − (K_s q)_d = 0        for every pad coordinate d
//! ```
//!
//! - **Tilt** (frictionless pivot): the moment decreases with δ, and the admissible tilts (h > 0 at every
//!   node) form an interval; Newton runs inside a bracket that bisection shrinks whenever Newton would leave
//!   it. A pad without film pressure has a zero moment only because nothing acts on it: the root is sought
//!   towards larger δ (trailing edge closing), and a pad that carries a vanishing share of the load is
//!   placed at the onset of pressure (a deterministic, continuous choice: an outer thermal loop relies on it).
//! - **Other coordinates** (pivot translations, elastic modes: all carry a structural stiffness): Newton with
//!   the tilt condensed (`k_eff = K_dd + K_s,dd − K_dt K_tt⁻¹ K_td`) around the tilt solve. One such
//!   coordinate is safeguarded by a bracket on its monotone residual; several take the coupled Newton step
//!   when it lowers the residual and otherwise one bracketed sweep per coordinate (Gauss–Seidel).

use nalgebra::{DMatrix, DVector};

use crate::physics::reynolds::FilmError;

use crate::bearing::equilibrium::eval::{eval_pad, pad_scales, relative, structural_force, Ctx};
use crate::bearing::equilibrium::state::{
    PadState, NO_PRESSURE_SHARE, ONSET_FIRST_STEP, ONSET_WIDTH, SUFFICIENT_DECREASE, UNLOADED_SHARE,
};
use crate::bearing::film::coordinates::{PadDof, JOURNAL_DOFS};
use crate::bearing::film::model::{BearingModel, PadModel};

/// Solves one pad's coordinates for a fixed journal position (warm-started from `q`).
pub(super) fn solve_pad(
    pm: &mut PadModel,
    k: usize,
    journal: [f64; 2],
    q: &[f64],
    ctx: &mut Ctx<'_>,
) -> Result<PadState, FilmError> {
    let local: Vec<f64> = journal.iter().chain(q).copied().collect();
    if pm.dofs().is_empty() || ctx.held(k) {
        let (forces, lin) = eval_pad(pm, k, &local, ctx)?;
        let share = forces[0].hypot(forces[1]) / ctx.force_scale;
        // A held pad stays held only while it carries no load; one that picks up load is solved.
        if pm.dofs().is_empty() || share < UNLOADED_SHARE {
            let unloaded = !pm.dofs().is_empty();
            return Ok(PadState { q: q.to_vec(), forces, lin, unloaded, residual: 0.0 });
        }
    }
    let others: Vec<usize> = (0..q.len()).filter(|&d| pm.dofs()[d] != PadDof::Tilt).collect();
    match others.as_slice() {
        [] => solve_tilt(pm, k, &local, ctx),
        [d] => solve_one(pm, k, local, *d, ctx),
        _ => solve_several(pm, k, local, &others, ctx),
    }
}

/// Pad coordinates that keep the film as it was after the journal moves by `de`: the least-squares
/// solution of `Φ_p Δq = −Φ_j Δe` over the film nodes (a tilt follows a transverse journal motion exactly).
/// All pads at a journal position, warm-started from `u`; returns pad states and the total film force.
pub(super) fn solve_all_pads(
    model: &mut BearingModel,
    journal: [f64; 2],
    u: &[f64],
    ctx: &mut Ctx<'_>,
) -> Result<(Vec<PadState>, [f64; 2]), (usize, FilmError)> {
    let mut states = Vec::with_capacity(model.pads.len());
    let mut f = [0.0, 0.0];
    for k in 0..model.pads.len() {
        let q = u[model.dofs.pad_slice(k)].to_vec();
        let st = solve_pad(&mut model.pads[k], k, journal, &q, ctx).map_err(|e| (k, e))?;
        f[0] += st.forces[0];
        f[1] += st.forces[1];
        states.push(st);
    }
    Ok((states, f))
}

/// As [`solve_all_pads`], for the searches over journal positions: a state whose thinnest film is below the
/// touchdown film (`physics.touchdown_film_um`) counts as a closed film there. The surfaces touch in such a
/// state, and the film force it shows means nothing: a pad pressed onto the journal at one node (h → 0 at a
/// pad edge) keeps an open film in arithmetic down to h ≈ 1e-16 m, where each pad solve takes hundreds of
/// film solves and the force law runs from 0.1 to 3 times the load within 1e-3 Cb.
pub(super) fn solve_all_pads_open(
    model: &mut BearingModel,
    journal: [f64; 2],
    u: &[f64],
    ctx: &mut Ctx<'_>,
) -> Result<(Vec<PadState>, [f64; 2]), (usize, FilmError)> {
    let solved = solve_all_pads(model, journal, u, ctx)?;
    for (k, pm) in model.pads.iter().enumerate() {
        let (h_min_m, node) = pm.film.h_min();
        if h_min_m < ctx.op.touchdown_film {
            let g = &pm.film.geom;
            return Err((
                k,
                FilmError::Contact { h_min_m, theta_deg: g.node_theta[node].to_degrees(), z_m: g.node_z[node] },
            ));
        }
    }
    Ok(solved)
}

/// The global vector of a journal position and pad states.
pub(super) fn assemble_u(model: &BearingModel, journal: [f64; 2], states: &[PadState]) -> Vec<f64> {
    let qs: Vec<&[f64]> = states.iter().map(|s| s.q.as_slice()).collect();
    model.dofs.assemble(journal, &qs)
}

/// A warm start for a pad whose coordinates the film does not determine.
pub(super) fn follow_journal(pm: &PadModel, q: &[f64], de: [f64; 2]) -> Vec<f64> {
    let shapes = &pm.film.geom.shapes;
    let n = q.len();
    let nodes = pm.film.geom.n_nodes();
    let phi_p = DMatrix::from_fn(nodes, n, |i, d| shapes[JOURNAL_DOFS + d].node[i]);
    let target = DVector::from_fn(nodes, |i, _| -(shapes[0].node[i] * de[0] + shapes[1].node[i] * de[1]));
    let normal = phi_p.transpose() * &phi_p;
    match normal.lu().solve(&(phi_p.transpose() * target)) {
        Some(dq) if dq.iter().all(|v| v.is_finite()) => q.iter().zip(dq.iter()).map(|(a, b)| a + b).collect(),
        _ => q.to_vec(),
    }
}

/// The pad's state with its tilt solved and every other coordinate as in `local`.
fn solve_tilt(pm: &mut PadModel, k: usize, local: &[f64], ctx: &mut Ctx<'_>) -> Result<PadState, FilmError> {
    match pm.dofs().iter().position(|d| *d == PadDof::Tilt) {
        Some(t) => tilt_search(pm, k, local, JOURNAL_DOFS + t, ctx),
        None => {
            let (forces, lin) = eval_pad(pm, k, local, ctx)?;
            let residual = residual_of(pm, local, &forces, ctx);
            Ok(PadState { q: local[JOURNAL_DOFS..].to_vec(), forces, lin, unloaded: false, residual })
        }
    }
}

/// Largest scaled residual over the pad's coordinates.
fn residual_of(pm: &PadModel, local: &[f64], forces: &[f64], ctx: &Ctx<'_>) -> f64 {
    let q = &local[JOURNAL_DOFS..];
    let sc = pad_scales(pm, forces, ctx.force_scale);
    (0..q.len()).map(|d| relative(forces[JOURNAL_DOFS + d] - structural_force(pm, q, d), sc[d])).fold(0.0, f64::max)
}

/// Admissible interval of local coordinate `slot` (h > 0 at every node) with the others as in `local`.
fn admissible_interval(pm: &PadModel, local: &[f64], slot: usize) -> Result<(f64, f64), FilmError> {
    let film = &pm.film;
    let mut base = local.to_vec();
    base[slot] = 0.0;
    let hc = film.nodal_thickness(&base);
    let phi = &film.geom.shapes[slot].node;
    let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
    for (&h, &f) in hc.iter().zip(phi) {
        if f < 0.0 {
            hi = hi.min(h / -f);
        } else if f > 0.0 {
            lo = lo.max(-h / f);
        } else if h <= 0.0 {
            return Err(thinnest(pm, &hc));
        }
    }
    if lo >= hi {
        return Err(thinnest(pm, &hc));
    }
    Ok((lo, hi))
}

/// The film closed at its thinnest node (nodal thicknesses `h`), as a contact.
fn thinnest(pm: &PadModel, h: &[f64]) -> FilmError {
    let g = &pm.film.geom;
    let (i, h_min_m) = h.iter().enumerate().fold((0, f64::INFINITY), |m, (i, &v)| if v < m.1 { (i, v) } else { m });
    FilmError::Contact { h_min_m, theta_deg: g.node_theta[i].to_degrees(), z_m: g.node_z[i] }
}

/// Tilt solve: Newton safeguarded by bisection on the admissible interval (`slot`: the tilt's local index).
///
/// Where the moment is negative on the whole loaded side (a zero-preload pad whose film is uniform, a
/// diverging film), the root is the onset of pressure: the pad's load grows from zero there while its
/// moment has no slope, so Newton cannot find it. The onset is bracketed by steps growing from
/// [`ONSET_WIDTH`] of the admissible interval away from the warm start (a pad placed before and moved with
/// the journal is found in two film solves), then bisected to that width; the pressure-free end is
/// returned, so a floating pad adds no force at all.
fn tilt_search(
    pm: &mut PadModel,
    k: usize,
    local: &[f64],
    slot: usize,
    ctx: &mut Ctx<'_>,
) -> Result<PadState, FilmError> {
    let (lo, hi) = admissible_interval(pm, local, slot)?;
    let range = hi - lo;
    let margin = 1e-7 * range;
    let (mut blo, mut bhi) = (lo + margin, hi - margin);
    let mut local = local.to_vec();
    let mut d = local[slot].clamp(blo + margin, bhi - margin);
    let t = slot - JOURNAL_DOFS;
    // The last pressure-free state (left end of an onset bracket), the last two onset points (right of it)
    // and the growing step of the search for the onset.
    let mut free: Option<PadState> = None;
    let mut onset_pts: [Option<(f64, f64)>; 2] = [None, None];
    let mut reach = ONSET_FIRST_STEP * range;
    let width = ONSET_WIDTH * range;
    // The exact onset from the film's right-hand side (Reynolds condition), once it has been tried.
    let mut exact_onset: Option<Option<f64>> = None;
    let mut last: Option<PadState> = None;
    for _ in 0..ctx.params.max_inner_iterations {
        ctx.report.inner_iterations += 1;
        local[slot] = d;
        let (forces, lin) = eval_pad(pm, k, &local, ctx)?;
        let r = forces[slot] - structural_force(pm, &local[JOURNAL_DOFS..], t);
        let kt = lin.stiffness[(slot, slot)] + pm.structure.stiffness[(t, t)];
        let scale = pad_scales(pm, &forces, ctx.force_scale)[t];
        let rel = relative(r, scale);
        let share = forces[0].hypot(forces[1]) / ctx.force_scale;
        let loaded = share > NO_PRESSURE_SHARE;
        let state = PadState {
            q: local[JOURNAL_DOFS..].to_vec(),
            forces,
            lin,
            unloaded: share < UNLOADED_SHARE || kt <= 0.0,
            residual: rel,
        };
        // Onset of pressure: loaded, the moment still pushing the trailing edge out, a vanishing share (there
        // the moment is second order in the tilt, so a small moment says nothing about the distance to the root).
        let onset = loaded && share < UNLOADED_SHARE && r <= 0.0;
        if rel <= ctx.params.pad_tol && loaded && !onset {
            return Ok(state);
        }
        if r > 0.0 || !loaded {
            blo = d;
            if !loaded {
                free = Some(state.clone());
            }
        } else {
            bhi = d;
            onset_pts = if onset { [Some((d, share)), onset_pts[0]] } else { [None, None] };
        }
        if let Some(f) = free.as_ref().filter(|_| onset_pts[0].is_some() && bhi - blo <= width) {
            if ctx.thorough_onset {
                if let Some(st) = loaded_root_beyond(pm, k, &local, slot, bhi, hi - margin, ctx)? {
                    return Ok(st);
                }
            }
            return Ok(PadState { unloaded: true, residual: 0.0, ..f.clone() });
        }
        let inside = |x: f64| x > blo && x < bhi;
        let newton = if kt > 0.0 && loaded { d + r / kt } else { f64::NAN };
        if exact_onset.is_none() && (!loaded || r <= 0.0) {
            let inp = ctx.op.film_inputs(k);
            exact_onset = Some(
                pm.film.pressure_free_interval(&local, slot, &inp).map(|(_, end)| end).filter(|&x| x >= lo && x < hi),
            );
        }
        let onset_at = exact_onset.flatten();
        let probe = onset_at.map(|x| x + 0.5 * width);
        // Towards the onset: no pressure here, or the moment pushes the pad back and Newton heads for the onset
        // (it would cross into the pressure-free range, or halve the distance to it: the moment has a double
        // root at the onset, where Newton converges only linearly).
        let towards_onset =
            !loaded || onset || (r <= 0.0 && onset_at.is_some_and(|x| newton.is_nan() || newton - x <= 0.6 * (d - x)));
        let next = if let Some(p) = probe.filter(|&p| inside(p) && onset_pts[0].is_none() && towards_onset) {
            // Just past the exact onset of pressure: is the moment there pushing the pad back (then the root is
            // the onset)?
            p
        } else if let Some(x) = onset_at.filter(|&x| Some(d) == probe && onset && free.is_none() && x > blo) {
            // It is: the pressure-free state at the onset itself.
            x
        } else if onset_pts[0].is_some() && free.is_some() {
            // Onset bracketed: extrapolate the load share to zero from the two last onset points (exact for a
            // share linear in the tilt), never closer to the pressure-free end than half the final width.
            let est = match onset_pts {
                [Some((d1, s1)), Some((d2, s2))] if s1 != s2 => d1 - s1 * (d1 - d2) / (s1 - s2),
                // One onset point: the moment's own Newton step (the moment grows with the load from zero at
                // the onset, in proportion to it, so Newton points at the onset), just past it on the
                // pressure-free side.
                _ if inside(newton - 0.5 * width) => newton - 0.5 * width,
                _ => 0.5 * (blo + bhi),
            };
            let x = est.max(blo + 0.5 * width);
            if inside(x) {
                x
            } else {
                0.5 * (blo + bhi)
            }
        } else if inside(newton) && !onset {
            newton
        } else if !loaded && bhi == hi - margin && inside(d + reach) {
            // Pressure-free with nothing loaded found to the right yet: step out towards the onset.
            reach *= 8.0;
            d + reach / 8.0
        } else if onset && free.is_none() && inside(newton - 0.5 * width) {
            // At the onset side with no pressure-free point found yet: the moment's Newton step points at the
            // onset (see above); just past it.
            newton - 0.5 * width
        } else if onset && free.is_none() && inside(d - reach) {
            // At the onset side with no pressure-free point found to the left yet: step back.
            reach *= 8.0;
            d - reach / 8.0
        } else {
            0.5 * (blo + bhi)
        };
        if (bhi - blo) <= 1e-13 * range {
            if loaded && !state.unloaded && rel > ctx.params.pad_tol && (blo == lo + margin || bhi == hi - margin) {
                // The film's own moment presses an edge of the pad onto the journal over the whole admissible
                // range (an unloaded negative-preload pad leaning on its edge): the film closes there.
                return Err(thinnest(pm, &pm.film.nodal_thickness(&local)));
            }
            last = Some(state);
            break;
        }
        last = Some(state);
        d = next;
    }
    last.map(|s| if s.unloaded { PadState { residual: 0.0, ..s } } else { s })
        .ok_or_else(|| FilmError::Input("no tilt iteration".into()))
}

/// Tilt samples across the loaded side when looking for a loaded root beyond the onset of pressure.
const LOADED_ROOT_SAMPLES: usize = 12;

/// One evaluation of the tilt moment residual `r` and its slope `dr/dδ` at tilt `d`.
fn moment_at(
    pm: &mut PadModel,
    k: usize,
    local: &mut [f64],
    slot: usize,
    d: f64,
    ctx: &mut Ctx<'_>,
) -> Result<(f64, f64, PadState), FilmError> {
    let t = slot - JOURNAL_DOFS;
    local[slot] = d;
    let (forces, lin) = eval_pad(pm, k, local, ctx)?;
    let r = forces[slot] - structural_force(pm, &local[JOURNAL_DOFS..], t);
    let slope = -(lin.stiffness[(slot, slot)] + pm.structure.stiffness[(t, t)]);
    let rel = relative(r, pad_scales(pm, &forces, ctx.force_scale)[t]);
    let share = forces[0].hypot(forces[1]) / ctx.force_scale;
    Ok((
        r,
        slope,
        PadState { q: local[JOURNAL_DOFS..].to_vec(), forces, lin, unloaded: share < UNLOADED_SHARE, residual: rel },
    ))
}

/// A pad whose moment pushes it back just past the onset of pressure may still have a loaded root further
/// on, where the moment rises through zero and falls again (a lightly loaded preloaded pad near a fold:
/// two stable states, floating and loaded). The floating state is only neutrally stable (no moment on its
/// pressure-free side), so the loaded root is preferred when it exists — a deterministic choice whatever the
/// starting point. The loaded side `(from, to)` is sampled for a positive moment or a local maximum of the
/// moment (slope changing sign), and the falling root after it is bracketed and solved.
fn loaded_root_beyond(
    pm: &mut PadModel,
    k: usize,
    local: &[f64],
    slot: usize,
    from: f64,
    to: f64,
    ctx: &mut Ctx<'_>,
) -> Result<Option<PadState>, FilmError> {
    let mut local = local.to_vec();
    let step = (to - from) / (LOADED_ROOT_SAMPLES + 1) as f64;
    let mut prev: Option<(f64, f64, f64)> = None;
    let mut positive: Option<f64> = None;
    for i in 1..=LOADED_ROOT_SAMPLES {
        let d = from + step * i as f64;
        let (r, slope, _) = moment_at(pm, k, &mut local, slot, d, ctx)?;
        if r > 0.0 {
            positive = Some(d);
            break;
        }
        if let Some((dp, rp, sp)) = prev {
            if sp > 0.0 && slope <= 0.0 {
                // A local maximum of the moment between dp and d: refine it by secant on the slope.
                let (mut a, mut sa, mut b, mut sb) = (dp, sp, d, slope);
                let mut best = rp.max(r);
                for _ in 0..6 {
                    let x = if sa != sb { a - sa * (b - a) / (sb - sa) } else { 0.5 * (a + b) };
                    let x = if x > a && x < b { x } else { 0.5 * (a + b) };
                    let (rx, sx, _) = moment_at(pm, k, &mut local, slot, x, ctx)?;
                    best = best.max(rx);
                    if rx > 0.0 {
                        positive = Some(x);
                        break;
                    }
                    if sx > 0.0 {
                        (a, sa) = (x, sx)
                    } else {
                        (b, sb) = (x, sx)
                    }
                }
                if positive.is_some() || best < 0.0 {
                    break;
                }
            }
        }
        prev = Some((d, r, slope));
    }
    let Some(mut a) = positive else { return Ok(None) };
    // The falling root after the positive point: Newton inside a bracket [a (r > 0), b (r < 0)].
    let mut b = to;
    let mut x = a + 0.5 * step;
    for _ in 0..ctx.params.max_inner_iterations {
        ctx.report.inner_iterations += 1;
        let (r, slope, st) = moment_at(pm, k, &mut local, slot, x, ctx)?;
        if st.residual <= ctx.params.pad_tol && !st.unloaded {
            return Ok(Some(st));
        }
        if r > 0.0 {
            a = x
        } else {
            b = x
        }
        let newton = if slope < 0.0 { x - r / slope } else { f64::NAN };
        x = if newton > a && newton < b { newton } else { 0.5 * (a + b) };
        if b - a <= 1e-13 * (to - from) {
            return Ok((!st.unloaded).then_some(st));
        }
    }
    Ok(None)
}

/// Tilt-condensed stiffness of the pad coordinates `others` (film + structure), `K_oo − K_ot K_tt⁻¹ K_to`.
fn condensed(pm: &PadModel, st: &PadState, others: &[usize]) -> DMatrix<f64> {
    let j = JOURNAL_DOFS;
    let l = &st.lin.stiffness;
    let ks = &pm.structure.stiffness;
    let kk = |a: usize, b: usize| l[(j + a, j + b)] + ks[(a, b)];
    let mut m = DMatrix::from_fn(others.len(), others.len(), |a, b| kk(others[a], others[b]));
    if let Some(t) = pm.dofs().iter().position(|d| *d == PadDof::Tilt) {
        let ktt = kk(t, t);
        if ktt > 0.0 {
            for (a, &oa) in others.iter().enumerate() {
                for (b, &ob) in others.iter().enumerate() {
                    m[(a, b)] -= kk(oa, t) * kk(t, ob) / ktt;
                }
            }
        }
    }
    m
}

/// Residual of coordinate `d` (film force minus structural force) and its scale.
fn coordinate_residual(pm: &PadModel, st: &PadState, d: usize, ctx: &Ctx<'_>) -> (f64, f64) {
    let r = st.pad_force(d) - structural_force(pm, &st.q, d);
    let scale = pad_scales(pm, &st.forces, ctx.force_scale)[d];
    (r, scale)
}

/// One non-tilt coordinate `d` (pivot translation, elastic mode), the tilt solved inside: Newton on the
/// decreasing residual, safeguarded by a bracket; a position where the film closes moves the pad out.
fn solve_one(
    pm: &mut PadModel,
    k: usize,
    mut local: Vec<f64>,
    d: usize,
    ctx: &mut Ctx<'_>,
) -> Result<PadState, FilmError> {
    let slot = JOURNAL_DOFS + d;
    let clearance = pm.film.geom.base.node.iter().fold(0.0_f64, |m, &h| m.max(h));
    // Unit of the coordinate's film shape: a translation or mode of 0.1 Cp moves the film by about 0.1 Cp.
    let shape = pm.film.geom.shapes[slot].node.iter().fold(0.0_f64, |m, &v| m.max(v.abs())).max(f64::MIN_POSITIVE);
    let probe = 0.1 * clearance / shape;
    let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
    let mut x = local[slot];
    let mut last = None;
    let mut closed = None;
    for _ in 0..ctx.params.max_inner_iterations {
        ctx.report.inner_iterations += 1;
        local[slot] = x;
        let st = match solve_tilt(pm, k, &local, ctx) {
            Ok(s) => s,
            Err(contact @ FilmError::Contact { .. }) => {
                // The pad cannot sit here: move it the way its shape opens the film where it closed
                // (h = h0 + Σ q φ: raising x opens a node where φ > 0). A shape that does not move that
                // node cannot open it: the film closes whatever this coordinate does.
                match opening_side(pm, slot, &contact) {
                    Some(true) => {
                        lo = x;
                        x = if hi.is_finite() { 0.5 * (lo + hi) } else { x + probe };
                    }
                    Some(false) => {
                        hi = x;
                        x = if lo.is_finite() { 0.5 * (lo + hi) } else { x - probe };
                    }
                    None => return Err(contact),
                }
                closed = Some(contact);
                continue;
            }
            Err(e) => return Err(e),
        };
        local[JOURNAL_DOFS..].copy_from_slice(&st.q);
        let (r, scale) = coordinate_residual(pm, &st, d, ctx);
        let k_eff = condensed(pm, &st, &[d])[(0, 0)];
        let rel = relative(r, scale);
        let state = PadState { residual: rel.max(st.residual), ..st };
        if rel <= ctx.params.pad_tol {
            return Ok(state);
        }
        if r > 0.0 {
            lo = x;
        } else {
            hi = x;
        }
        let newton = if k_eff > 0.0 { x + r / k_eff } else { f64::NAN };
        x = if newton > lo && newton < hi {
            newton
        } else if lo.is_finite() && hi.is_finite() {
            0.5 * (lo + hi)
        } else {
            x + r.signum() * probe
        };
        last = Some(state);
        if lo.is_finite() && hi.is_finite() && hi - lo <= 1e-14 * probe {
            break;
        }
    }
    // Every trial closed the film: the pad is pressed onto the journal (touchdown, once classified).
    match (last, closed) {
        (Some(state), _) => Ok(state),
        (None, Some(contact)) => Err(contact),
        (None, None) => Err(FilmError::Input(format!("pad coordinate {:?} not found", pm.dofs()[d]))),
    }
}

/// Whether raising coordinate `slot` opens the film at the node where `contact` found it closed
/// (`Some(true)`), closes it further (`Some(false)`), or hardly moves it (`None`: |φ| there below 1 % of
/// the shape's largest value).
fn opening_side(pm: &PadModel, slot: usize, contact: &FilmError) -> Option<bool> {
    let FilmError::Contact { theta_deg, z_m, .. } = *contact else { return None };
    let g = &pm.film.geom;
    let node = (0..g.n_nodes()).min_by(|&a, &b| {
        let d = |i: usize| (g.node_theta[i].to_degrees() - theta_deg).abs() + (g.node_z[i] - z_m).abs();
        d(a).total_cmp(&d(b))
    })?;
    let shape = &g.shapes[slot].node;
    let largest = shape.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    let phi = shape[node];
    (phi.abs() > 0.01 * largest).then_some(phi > 0.0)
}

/// Several non-tilt coordinates: the coupled Newton step when it lowers the residual, else one bracketed
/// sweep over the coordinates.
fn solve_several(
    pm: &mut PadModel,
    k: usize,
    mut local: Vec<f64>,
    others: &[usize],
    ctx: &mut Ctx<'_>,
) -> Result<PadState, FilmError> {
    let merit = |pm: &PadModel, st: &PadState, ctx: &Ctx<'_>| {
        others.iter().map(|&d| coordinate_residual(pm, st, d, ctx)).map(|(r, s)| (r / s).powi(2)).sum::<f64>()
    };
    let mut st = solve_tilt(pm, k, &local, ctx)?;
    for _ in 0..ctx.params.max_inner_iterations {
        ctx.report.inner_iterations += 1;
        local[JOURNAL_DOFS..].copy_from_slice(&st.q);
        let m0 = merit(pm, &st, ctx);
        let worst = others
            .iter()
            .map(|&d| coordinate_residual(pm, &st, d, ctx))
            .map(|(r, s)| relative(r, s))
            .fold(0.0, f64::max);
        if worst <= ctx.params.pad_tol {
            return Ok(PadState { residual: worst.max(st.residual), ..st });
        }
        let r = DVector::from_iterator(others.len(), others.iter().map(|&d| coordinate_residual(pm, &st, d, ctx).0));
        let step = condensed(pm, &st, others).lu().solve(&r).filter(|s| s.iter().all(|v| v.is_finite()));
        let mut improved = None;
        if let Some(step) = step {
            let mut alpha = 1.0;
            for _ in 0..8 {
                let mut trial = local.clone();
                for (a, &d) in others.iter().enumerate() {
                    trial[JOURNAL_DOFS + d] += alpha * step[a];
                }
                if let Ok(s2) = solve_tilt(pm, k, &trial, ctx) {
                    if merit(pm, &s2, ctx).sqrt() < (1.0 - SUFFICIENT_DECREASE * alpha) * m0.sqrt() {
                        improved = Some(s2);
                        break;
                    }
                }
                alpha *= 0.5;
            }
        }
        st = match improved {
            Some(s) => s,
            None => {
                // Gauss–Seidel: each coordinate on its own bracket, the others fixed.
                let mut s = st;
                for &d in others {
                    local[JOURNAL_DOFS..].copy_from_slice(&s.q);
                    s = solve_one(pm, k, local.clone(), d, ctx)?;
                }
                s
            }
        };
    }
    Ok(st)
}
