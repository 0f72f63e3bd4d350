//! The journal's part of a Newton step: the pad-condensed journal stiffness and a step that does not move
//! along directions without stiffness.
//!
//! ```text
//! K_red = K_jj − K_jp K_pp⁻¹ K_pj        (exact, by the implicit function theorem, for pads in equilibrium)
//! K_red Δe = r  solved by singular values; σ_i < 1e-7 σ_max: no step along v_i (the direction is held)
//! ```

use nalgebra::{DMatrix, Matrix2, Vector2};

use crate::bearing::equilibrium::state::PadState;
use crate::bearing::film::coordinates::JOURNAL_DOFS;
use crate::bearing::film::model::PadModel;
use crate::bearing::report::error::StallReason;

/// Singular values below this fraction of the largest are treated as zero stiffness.
pub(super) const STIFFNESS_RANK_TOL: f64 = 1e-7;

/// Pad-condensed journal stiffness `K_jj − K_jp K_pp⁻¹ K_pj` (structural stiffness included). An unloaded
/// tilting pad contributes nothing: its film's stiffness at a held tilt is not what the journal meets (the
/// pad tilts away), and it carries a vanishing share of the load.
pub(super) fn condensed_journal_stiffness(pm: &PadModel, st: &PadState) -> Matrix2<f64> {
    let k = &st.lin.stiffness;
    let j = JOURNAL_DOFS;
    let kjj = Matrix2::new(k[(0, 0)], k[(0, 1)], k[(1, 0)], k[(1, 1)]);
    let n = pm.dofs().len();
    if n == 0 {
        return kjj;
    }
    if st.unloaded {
        return Matrix2::zeros();
    }
    let kpp = DMatrix::from_fn(n, n, |a, b| k[(j + a, j + b)] + pm.structure.stiffness[(a, b)]);
    let kpj = DMatrix::from_fn(n, 2, |a, b| k[(j + a, b)]);
    let kjp = DMatrix::from_fn(2, n, |a, b| k[(a, j + b)]);
    match kpp.lu().solve(&kpj) {
        Some(x) => {
            let c = kjp * x;
            kjj - Matrix2::new(c[(0, 0)], c[(0, 1)], c[(1, 0)], c[(1, 1)])
        }
        None => kjj,
    }
}

/// The bearing's condensed journal stiffness: the sum over pads.
pub(super) fn bearing_stiffness(pads: &[PadModel], states: &[PadState]) -> Matrix2<f64> {
    pads.iter().zip(states).map(|(pm, st)| condensed_journal_stiffness(pm, st)).sum()
}

/// The singular directions of a journal stiffness: left `u`, right `vt` rows, values, and which of them
/// count as zero stiffness (below [`STIFFNESS_RANK_TOL`] of the largest, or all when the largest is zero).
struct Directions {
    u: Matrix2<f64>,
    vt: Matrix2<f64>,
    sigma: Vector2<f64>,
    soft: [bool; 2],
}

impl Directions {
    /// `None` when `k` is not finite or its decomposition fails.
    fn of(k: &Matrix2<f64>) -> Option<Self> {
        if !k.iter().all(|v| v.is_finite()) {
            return None;
        }
        let svd = k.svd(true, true);
        let (u, vt) = (svd.u?, svd.v_t?);
        let sigma = svd.singular_values;
        let smax = sigma.max();
        let soft = [0, 1].map(|i| smax <= 0.0 || sigma[i] <= STIFFNESS_RANK_TOL * smax);
        Some(Self { u, vt, sigma, soft })
    }

    /// The load component of `r` along left direction `i`, and that direction.
    fn component(&self, i: usize, r: &Vector2<f64>) -> (f64, Vector2<f64>) {
        let ui = self.u.column(i).into_owned();
        (ui.dot(r), ui)
    }
}

fn axis_deg(d: &Vector2<f64>) -> f64 {
    d[1].atan2(d[0]).to_degrees().rem_euclid(180.0)
}

/// Newton step `K Δ = r` by singular values: directions without stiffness are not moved along; a load
/// component there above `10 tol` cannot be carried. Returns the step and the held direction, if any.
pub(super) fn journal_step(
    k: &Matrix2<f64>,
    r: &Vector2<f64>,
    tol: f64,
) -> Result<(Vector2<f64>, Option<Vector2<f64>>), StallReason> {
    let Some(dirs) = Directions::of(k) else {
        return Err(StallReason::NonFiniteStiffness);
    };
    if dirs.soft == [true, true] {
        if r.norm() > 10.0 * tol {
            return Err(StallReason::NoStiffnessAlong { axis_deg: axis_deg(r), component_n: r.norm() });
        }
        return Err(StallReason::NoStiffness);
    }
    let mut step = Vector2::zeros();
    let mut held = None;
    for i in 0..2 {
        let (ri, ui) = dirs.component(i, r);
        let vi = dirs.vt.row(i).transpose();
        if !dirs.soft[i] {
            step += vi * (ri / dirs.sigma[i]);
        } else if ri.abs() > 10.0 * tol {
            return Err(StallReason::NoStiffnessAlong { axis_deg: axis_deg(&ui), component_n: ri.abs() });
        } else {
            held = Some(vi);
        }
    }
    Ok((step, held))
}

/// The unit direction along which part of the unbalanced force `r` (above `tol`) acts where `k` has no
/// stiffness: `r` itself when nothing holds the journal. `None` when every load component is supported.
pub(super) fn unsupported_direction(k: &Matrix2<f64>, r: &Vector2<f64>, tol: f64) -> Option<Vector2<f64>> {
    let dirs = Directions::of(k)?;
    if dirs.soft == [true, true] {
        return (r.norm() > tol).then(|| r / r.norm());
    }
    (0..2).find_map(|i| {
        let (ri, ui) = dirs.component(i, r);
        (dirs.soft[i] && ri.abs() > tol).then(|| ui * ri.signum())
    })
}

/// Whether the pads surround the load direction `w`: it lies inside the cone of the pads' outward normals
/// (each pad's mean film normal, from its journal shapes `∂h/∂e = −(cos θ, sin θ)`), so that pressure on
/// them can balance it. Only outside that cone is "no stiffness" an answer rather than a failure.
pub(super) fn pads_surround(pads: &[PadModel], w: [f64; 2]) -> bool {
    use std::f64::consts::{PI, TAU};
    let mut angles: Vec<f64> = pad_normals(pads).iter().map(|n| n[1].atan2(n[0]).rem_euclid(TAU)).collect();
    if angles.is_empty() || w[0].hypot(w[1]) == 0.0 {
        return false;
    }
    angles.sort_by(f64::total_cmp);
    let phi = w[1].atan2(w[0]).rem_euclid(TAU);
    // The load on a pad, or in a gap between consecutive pad normals of under a half turn.
    let on_pad = angles.iter().any(|a| ((phi - a + PI).rem_euclid(TAU) - PI).abs() < 1e-6);
    on_pad
        || (0..angles.len()).any(|i| {
            let a = angles[i];
            let b = if i + 1 < angles.len() { angles[i + 1] } else { angles[0] + TAU };
            let gap = b - a;
            let inside = (phi - a).rem_euclid(TAU) <= gap;
            inside && gap < PI - 1e-9
        })
}

/// Each pad's mean outward film normal (towards the pad from the bearing centre), from its journal shapes.
fn pad_normals(pads: &[PadModel]) -> Vec<[f64; 2]> {
    pads.iter()
        .map(|pm| {
            let s = &pm.film.geom.shapes;
            let (cx, cy) = (-s[0].node.iter().sum::<f64>(), -s[1].node.iter().sum::<f64>());
            let n = cx.hypot(cy);
            if n > 0.0 {
                [cx / n, cy / n]
            } else {
                [0.0, 0.0]
            }
        })
        .collect()
}

/// The pad normal nearest the direction of `w` (`None` without pads).
pub(super) fn nearest_normal(pads: &[PadModel], w: [f64; 2]) -> Option<[f64; 2]> {
    pad_normals(pads).into_iter().max_by(|a, b| (a[0] * w[0] + a[1] * w[1]).total_cmp(&(b[0] * w[0] + b[1] * w[1])))
}

/// Whether moving the journal along `d` approaches some pad (a walk along `d` can load one).
pub(super) fn pads_ahead(pads: &[PadModel], d: Vector2<f64>) -> bool {
    pad_normals(pads).iter().any(|n| n[0] * d[0] + n[1] * d[1] > 1e-6)
}
