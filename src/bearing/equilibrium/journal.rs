//! The journal's part of a Newton step: the pad-condensed journal stiffness and a step that does not move
//! along directions without stiffness.
//!
//! ```text
//! K_red = K_jj − K_jp K_pp⁻¹ K_pj        (exact, by the implicit function theorem, for pads in equilibrium)
//! K_red Δe = r  solved by singular values; σ_i < 1e-7 σ_max: no step along v_i (the direction is held)
//! ```

use nalgebra::{DMatrix, Matrix2, Vector2};

use super::super::coordinates::JOURNAL_DOFS;
use super::super::model::PadModel;
use super::PadState;

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

/// Newton step `K Δ = r` by singular values: directions without stiffness are not moved along; a load
/// component there above `tol` cannot be carried. Returns the step and the held direction, if any.
pub(super) fn journal_step(k: &Matrix2<f64>, r: &Vector2<f64>, tol: f64) -> Result<(Vector2<f64>, Option<Vector2<f64>>), String> {
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
        if svd.singular_values[i] > STIFFNESS_RANK_TOL * smax {
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
