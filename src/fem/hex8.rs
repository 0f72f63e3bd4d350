//! Trilinear 8-node hexahedra that are boxes in cylindrical coordinates, for steady heat conduction in a pad.
//!
//! An element is `[r0, r0 + dr] × [θ0, θ0 + dθ] × [z0, z0 + dz]`; its shape functions are trilinear in
//! (r, θ, z) on the reference cube (ξ, η, ζ) ∈ [−1, 1]³, `N_a = (1 + ξ ξ_a)(1 + η η_a)(1 + ζ ζ_a) / 8`.
//! Element faces are coordinate surfaces, so neighbouring elements share faces exactly and the mesh follows
//! the curved pad without geometric error. In these coordinates
//!
//! ```text
//! ∇N = (∂N/∂r, (1/r) ∂N/∂θ, ∂N/∂z),   dV = r dr dθ dz
//! ```
//!
//! Node order: first the four nodes on `r = r0` counter-clockwise in (θ, z) — (θ0, z0), (θ1, z0), (θ1, z1),
//! (θ0, z1), the order of the film grid's Q4 elements — then the same four on `r = r0 + dr`.
//! Integrals use 2×2×2 Gauss points (the 1/r of the conduction integrand is not polynomial; the error is of
//! the order of (dr/r)², negligible for pad layers).

use super::quad4::GAUSS_2X2;

const G: f64 = 0.577_350_269_189_625_8;

/// Reference coordinates (ξ ↔ r, η ↔ θ, ζ ↔ z) of the eight nodes.
pub const NODES: [(f64, f64, f64); 8] = [
    (-1.0, -1.0, -1.0),
    (-1.0, 1.0, -1.0),
    (-1.0, 1.0, 1.0),
    (-1.0, -1.0, 1.0),
    (1.0, -1.0, -1.0),
    (1.0, 1.0, -1.0),
    (1.0, 1.0, 1.0),
    (1.0, -1.0, 1.0),
];

/// A face of the box.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Face {
    /// r = r0 (the film side of the innermost layer).
    Inner,
    /// r = r0 + dr.
    Outer,
    /// θ = θ0.
    ThetaMin,
    /// θ = θ0 + dθ.
    ThetaMax,
    /// z = z0.
    ZMin,
    /// z = z0 + dz.
    ZMax,
}

/// A box element in (r, θ, z).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CylBox {
    pub r0: f64,
    pub dr: f64,
    pub theta0: f64,
    pub dtheta: f64,
    pub z0: f64,
    pub dz: f64,
}

fn shape(xi: f64, eta: f64, zeta: f64) -> [f64; 8] {
    NODES.map(|(a, b, c)| 0.125 * (1.0 + xi * a) * (1.0 + eta * b) * (1.0 + zeta * c))
}

fn dshape(xi: f64, eta: f64, zeta: f64) -> [[f64; 3]; 8] {
    NODES.map(|(a, b, c)| {
        [
            0.125 * a * (1.0 + eta * b) * (1.0 + zeta * c),
            0.125 * b * (1.0 + xi * a) * (1.0 + zeta * c),
            0.125 * c * (1.0 + xi * a) * (1.0 + eta * b),
        ]
    })
}

impl CylBox {
    fn radius(&self, xi: f64) -> f64 {
        self.r0 + 0.5 * (xi + 1.0) * self.dr
    }

    /// Conduction matrix `K_ab = ∫ k ∇N_a·∇N_b dV`.
    #[must_use]
    pub fn conduction(&self, k: f64) -> [[f64; 8]; 8] {
        let mut m = [[0.0; 8]; 8];
        for xi in [-G, G] {
            for eta in [-G, G] {
                for zeta in [-G, G] {
                    let r = self.radius(xi);
                    let d = dshape(xi, eta, zeta);
                    let w = k * r * 0.125 * self.dr * self.dtheta * self.dz;
                    let grad: [[f64; 3]; 8] =
                        d.map(|g| [2.0 * g[0] / self.dr, 2.0 * g[1] / (r * self.dtheta), 2.0 * g[2] / self.dz]);
                    for a in 0..8 {
                        for b in 0..8 {
                            m[a][b] +=
                                w * (grad[a][0] * grad[b][0] + grad[a][1] * grad[b][1] + grad[a][2] * grad[b][2]);
                        }
                    }
                }
            }
        }
        m
    }

    /// Face mass matrix `M_ab = ∫_face N_a N_b dA` (zero outside the face's four nodes).
    #[must_use]
    pub fn face_mass(&self, face: Face) -> [[f64; 8]; 8] {
        let mut m = [[0.0; 8]; 8];
        for &(u, v) in &GAUSS_2X2 {
            // (ξ, η, ζ) of the point and the area weight dA/(du dv).
            let (xi, eta, zeta, wa) = match face {
                Face::Inner => (-1.0, u, v, self.r0 * 0.25 * self.dtheta * self.dz),
                Face::Outer => (1.0, u, v, (self.r0 + self.dr) * 0.25 * self.dtheta * self.dz),
                Face::ThetaMin => (u, -1.0, v, 0.25 * self.dr * self.dz),
                Face::ThetaMax => (u, 1.0, v, 0.25 * self.dr * self.dz),
                Face::ZMin => (u, v, -1.0, self.radius(u) * 0.25 * self.dr * self.dtheta),
                Face::ZMax => (u, v, 1.0, self.radius(u) * 0.25 * self.dr * self.dtheta),
            };
            let n = shape(xi, eta, zeta);
            for a in 0..8 {
                for b in 0..8 {
                    m[a][b] += wa * n[a] * n[b];
                }
            }
        }
        m
    }

    /// Volume `∫ dV`.
    #[must_use]
    pub fn volume(&self) -> f64 {
        (self.r0 + 0.5 * self.dr) * self.dr * self.dtheta * self.dz
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn el() -> CylBox {
        CylBox { r0: 0.05, dr: 0.004, theta0: 0.3, dtheta: 0.02, z0: -0.01, dz: 0.005 }
    }

    #[test]
    fn constants_have_no_flux_and_faces_have_their_area() {
        let e = el();
        let k = e.conduction(45.0);
        for row in &k {
            assert!(row.iter().sum::<f64>().abs() < 1e-12 * row[0].abs());
        }
        let area = |f: Face| e.face_mass(f).iter().flatten().sum::<f64>();
        assert!((area(Face::Outer) - 0.054 * 0.02 * 0.005).abs() < 1e-15);
        assert!((area(Face::Inner) - 0.05 * 0.02 * 0.005).abs() < 1e-15);
        assert!((area(Face::ThetaMin) - 0.004 * 0.005).abs() < 1e-15);
        let annulus = 0.5 * (0.054_f64.powi(2) - 0.05_f64.powi(2)) * 0.02;
        assert!((area(Face::ZMax) - annulus).abs() < 1e-15);
    }

    #[test]
    fn radial_conduction_through_a_thin_shell() {
        // T = r: (K T) summed over the outer nodes is ∫ k ∂(Σ_outer N_a)/∂r ∂T/∂r dV = k/dr ∫ r dr dθ dz
        // = k r_mean dθ dz, exact with the 2-point rule (the integrand is linear in r).
        let e = el();
        let k = e.conduction(2.0);
        let t: Vec<f64> = NODES.iter().map(|n| e.radius(n.0)).collect();
        let outer: f64 = (4..8).map(|a| (0..8).map(|b| k[a][b] * t[b]).sum::<f64>()).sum();
        let mean_r = e.r0 + 0.5 * e.dr;
        assert!((outer - 2.0 * mean_r * e.dtheta * e.dz).abs() < 1e-12, "{outer}");
    }
}
