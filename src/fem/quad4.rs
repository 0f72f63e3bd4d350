//! Bilinear (4-node) rectangle elements aligned with the (s, z) axes.
//!
//! On the reference square (ξ, η) ∈ [−1, 1]², node a at (ξ_a, η_a) ∈ {(−1,−1), (1,−1), (1,1), (−1,1)}
//! (counter-clockwise, matching [`crate::mesh::PadGrid::element_nodes`]) has
//! `N_a = (1 + ξ ξ_a)(1 + η η_a) / 4`. A rectangle of size `ds × dz` maps affinely, so
//! `∂N/∂s = (2/ds) ∂N/∂ξ`, `∂N/∂z = (2/dz) ∂N/∂η` and `dA = (ds dz / 4) dξ dη`.

/// Reference coordinates of the four nodes.
pub const NODES: [(f64, f64); 4] = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)];

/// 2×2 Gauss points on the reference square (weights are all 1).
pub const GAUSS_2X2: [(f64, f64); 4] = {
    const G: f64 = 0.577_350_269_189_625_8; // 1/√3
    [(-G, -G), (G, -G), (G, G), (-G, G)]
};

/// Shape function values at (ξ, η).
#[must_use]
pub fn shape(xi: f64, eta: f64) -> [f64; 4] {
    let mut n = [0.0; 4];
    for (a, &(xa, ya)) in NODES.iter().enumerate() {
        n[a] = 0.25 * (1.0 + xi * xa) * (1.0 + eta * ya);
    }
    n
}

/// Reference derivatives (∂N/∂ξ, ∂N/∂η) at (ξ, η).
#[must_use]
pub fn shape_derivatives(xi: f64, eta: f64) -> [(f64, f64); 4] {
    let mut d = [(0.0, 0.0); 4];
    for (a, &(xa, ya)) in NODES.iter().enumerate() {
        d[a] = (0.25 * xa * (1.0 + eta * ya), 0.25 * ya * (1.0 + xi * xa));
    }
    d
}

/// A rectangle `[s0, s0+ds] × [z0, z0+dz]`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RectElement {
    pub s0: f64,
    pub z0: f64,
    pub ds: f64,
    pub dz: f64,
}

/// Everything needed at one quadrature point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct QuadPoint {
    pub s: f64,
    pub z: f64,
    /// Weight times Jacobian: ∫ f dA ≈ Σ f(q) w.
    pub w: f64,
    pub n: [f64; 4],
    pub dn_ds: [f64; 4],
    pub dn_dz: [f64; 4],
}

impl RectElement {
    /// Physical point of reference coordinates (ξ, η).
    #[must_use]
    pub fn point(&self, xi: f64, eta: f64) -> (f64, f64) {
        (self.s0 + 0.5 * (xi + 1.0) * self.ds, self.z0 + 0.5 * (eta + 1.0) * self.dz)
    }

    /// Quadrature point data at (ξ, η) with reference weight `wref`.
    #[must_use]
    pub fn quad_point(&self, xi: f64, eta: f64, wref: f64) -> QuadPoint {
        let (s, z) = self.point(xi, eta);
        let d = shape_derivatives(xi, eta);
        let mut dn_ds = [0.0; 4];
        let mut dn_dz = [0.0; 4];
        for a in 0..4 {
            dn_ds[a] = 2.0 * d[a].0 / self.ds;
            dn_dz[a] = 2.0 * d[a].1 / self.dz;
        }
        QuadPoint { s, z, w: wref * 0.25 * self.ds * self.dz, n: shape(xi, eta), dn_ds, dn_dz }
    }

    /// The 2×2 Gauss points.
    #[must_use]
    pub fn gauss_2x2(&self) -> [QuadPoint; 4] {
        GAUSS_2X2.map(|(xi, eta)| self.quad_point(xi, eta, 1.0))
    }

    /// Sub-cell Gauss rule (m × m sub-rectangles, 3×3 Gauss in each) for integrands with a kink inside the
    /// element, e.g. the orifice paraboloid cut at the hole's edge.
    #[must_use]
    pub fn subcell_points(&self, m: usize) -> Vec<QuadPoint> {
        const G3: [(f64, f64); 3] =
            [(-0.774_596_669_241_483_4, 5.0 / 9.0), (0.0, 8.0 / 9.0), (0.774_596_669_241_483_4, 5.0 / 9.0)];
        #[allow(clippy::cast_precision_loss)]
        let mf = m as f64;
        let mut out = Vec::with_capacity(m * m * 9);
        for a in 0..m {
            for b in 0..m {
                for &(gx, wx) in &G3 {
                    for &(gy, wy) in &G3 {
                        #[allow(clippy::cast_precision_loss)]
                        let xi = -1.0 + (2.0 * a as f64 + 1.0 + gx) / mf;
                        #[allow(clippy::cast_precision_loss)]
                        let eta = -1.0 + (2.0 * b as f64 + 1.0 + gy) / mf;
                        out.push(self.quad_point(xi, eta, wx * wy / (mf * mf)));
                    }
                }
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn partition_of_unity_and_gradients() {
        let e = RectElement { s0: 1.0, z0: -2.0, ds: 0.5, dz: 0.25 };
        for q in e.gauss_2x2() {
            assert!((q.n.iter().sum::<f64>() - 1.0).abs() < 1e-14);
            assert!(q.dn_ds.iter().sum::<f64>().abs() < 1e-12);
            assert!(q.dn_dz.iter().sum::<f64>().abs() < 1e-12);
        }
        let area: f64 = e.gauss_2x2().iter().map(|q| q.w).sum();
        assert!((area - 0.125).abs() < 1e-14);
        let area_sub: f64 = e.subcell_points(3).iter().map(|q| q.w).sum();
        assert!((area_sub - 0.125).abs() < 1e-14);
    }

    #[test]
    fn interpolates_linear_fields_exactly() {
        let e = RectElement { s0: 0.0, z0: 0.0, ds: 2.0, dz: 1.0 };
        let f = |s: f64, z: f64| 3.0 * s - 2.0 * z + 1.0;
        let nodal = [f(0.0, 0.0), f(2.0, 0.0), f(2.0, 1.0), f(0.0, 1.0)];
        for q in e.subcell_points(2) {
            let v: f64 = (0..4).map(|a| q.n[a] * nodal[a]).sum();
            let ds: f64 = (0..4).map(|a| q.dn_ds[a] * nodal[a]).sum();
            let dz: f64 = (0..4).map(|a| q.dn_dz[a] * nodal[a]).sum();
            assert!((v - f(q.s, q.z)).abs() < 1e-12);
            assert!((ds - 3.0).abs() < 1e-12 && (dz + 2.0).abs() < 1e-12);
        }
    }
}
