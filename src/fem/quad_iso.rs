//! Bilinear isoparametric quadrilaterals: the general (non-rectangular) 4-node element.
//!
//! The reference square (ξ, η) ∈ [−1, 1]² maps to the element by the same shape functions that interpolate
//! the field, `x(ξ, η) = Σ N_a(ξ, η) x_a` (nodes counter-clockwise, as [`super::quad4::NODES`]). With the
//! Jacobian `J = ∂(x, y)/∂(ξ, η)`, physical gradients are `∇N = J⁻ᵀ ∇_ξ N` and `dA = det J dξ dη`.
//! The result is the same [`QuadPoint`] the rectangles produce (its `s`, `z` fields hold x, y), so every
//! assembly routine written for the film grid also runs on an irregular mesh.

use super::quad4::{shape, shape_derivatives, QuadPoint, GAUSS_2X2};

/// A degenerate or inverted element (det J ≤ 0 at a quadrature point).
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
#[error("quadrilateral with non-positive Jacobian {det:.3e} (nodes not counter-clockwise, or degenerate)")]
pub struct InvertedElement {
    pub det: f64,
}

/// Quadrature data at (ξ, η) with reference weight `wref` for the element with corners `xy`
/// (counter-clockwise).
///
/// # Errors
/// [`InvertedElement`] if the Jacobian determinant is not positive there.
pub fn iso_point(xy: &[[f64; 2]; 4], xi: f64, eta: f64, wref: f64) -> Result<QuadPoint, InvertedElement> {
    let n = shape(xi, eta);
    let d = shape_derivatives(xi, eta);
    let (mut x, mut y) = (0.0, 0.0);
    let (mut x_xi, mut x_eta, mut y_xi, mut y_eta) = (0.0, 0.0, 0.0, 0.0);
    for a in 0..4 {
        x += n[a] * xy[a][0];
        y += n[a] * xy[a][1];
        x_xi += d[a].0 * xy[a][0];
        x_eta += d[a].1 * xy[a][0];
        y_xi += d[a].0 * xy[a][1];
        y_eta += d[a].1 * xy[a][1];
    }
    let det = x_xi * y_eta - x_eta * y_xi;
    // Written so that a NaN determinant is rejected too.
    #[allow(clippy::neg_cmp_op_on_partial_ord)]
    if !(det > 0.0) {
        return Err(InvertedElement { det });
    }
    let mut dn_ds = [0.0; 4];
    let mut dn_dz = [0.0; 4];
    for a in 0..4 {
        // J⁻ᵀ = (1/det) [[y_eta, −y_xi], [−x_eta, x_xi]]
        dn_ds[a] = (y_eta * d[a].0 - y_xi * d[a].1) / det;
        dn_dz[a] = (-x_eta * d[a].0 + x_xi * d[a].1) / det;
    }
    Ok(QuadPoint { s: x, z: y, w: wref * det, n, dn_ds, dn_dz })
}

/// The 2×2 Gauss points of the element with corners `xy`.
///
/// # Errors
/// [`InvertedElement`] if the element is inverted or degenerate.
pub fn iso_gauss_2x2(xy: &[[f64; 2]; 4]) -> Result<[QuadPoint; 4], InvertedElement> {
    let mut out = [QuadPoint { s: 0.0, z: 0.0, w: 0.0, n: [0.0; 4], dn_ds: [0.0; 4], dn_dz: [0.0; 4] }; 4];
    for (o, &(xi, eta)) in out.iter_mut().zip(GAUSS_2X2.iter()) {
        *o = iso_point(xy, xi, eta, 1.0)?;
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fem::RectElement;

    #[test]
    fn matches_the_rectangle_on_a_rectangle() {
        let r = RectElement { s0: 0.5, z0: -1.0, ds: 2.0, dz: 0.5 };
        let xy = [[0.5, -1.0], [2.5, -1.0], [2.5, -0.5], [0.5, -0.5]];
        for (a, b) in r.gauss_2x2().iter().zip(iso_gauss_2x2(&xy).unwrap().iter()) {
            assert!((a.w - b.w).abs() < 1e-14 && (a.s - b.s).abs() < 1e-14 && (a.z - b.z).abs() < 1e-14);
            for k in 0..4 {
                assert!((a.dn_ds[k] - b.dn_ds[k]).abs() < 1e-12 && (a.dn_dz[k] - b.dn_dz[k]).abs() < 1e-12);
            }
        }
    }

    #[test]
    fn reproduces_linear_fields_on_a_distorted_quad() {
        let xy = [[0.0, 0.0], [1.2, 0.1], [1.0, 0.9], [-0.1, 1.3]];
        let f = |x: f64, y: f64| 2.0 * x - 3.0 * y + 0.5;
        let nodal: Vec<f64> = xy.iter().map(|p| f(p[0], p[1])).collect();
        let pts = iso_gauss_2x2(&xy).unwrap();
        let area: f64 = pts.iter().map(|q| q.w).sum();
        // Shoelace area.
        let shoelace = 0.5 * (0..4).map(|a| xy[a][0] * xy[(a + 1) % 4][1] - xy[(a + 1) % 4][0] * xy[a][1]).sum::<f64>();
        assert!((area - shoelace).abs() < 1e-12);
        for q in pts {
            let gx: f64 = (0..4).map(|a| q.dn_ds[a] * nodal[a]).sum();
            let gy: f64 = (0..4).map(|a| q.dn_dz[a] * nodal[a]).sum();
            assert!((gx - 2.0).abs() < 1e-12 && (gy + 3.0).abs() < 1e-12);
        }
        // Clockwise ordering is rejected.
        let cw = [xy[0], xy[3], xy[2], xy[1]];
        assert!(iso_gauss_2x2(&cw).is_err());
    }
}
