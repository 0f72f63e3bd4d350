//! Shaft beam element: two nodes, bending in two planes, rotary inertia, shear and gyroscopic coupling
//! (the Timoshenko element of Nelson & McVaugh 1976, in the interdependent-interpolation form).
//!
//! ## Coordinates
//! The shaft axis is z (out of the bearing's x–y plane, so that the journal's counter-clockwise spin Ω is
//! positive about +z). Each node carries `[x, y, a, b]`: the displacements and the rotations of the cross
//! section, `a ≈ ∂x/∂z`, `b ≈ ∂y/∂z` (equal for Euler–Bernoulli, differing by the shear strain for
//! Timoshenko). The section normal is `n ≈ (a, b, 1)`.
//!
//! ## Equations (per plane, w the displacement and θ the section rotation)
//! ```text
//! strain energy   U = ½ ∫ EI (θ')² + κGA (w' − θ)² dz
//! kinetic energy  T = ½ ∫ ρA ẇ² + ρI θ̇² dz
//! gyroscopic      the section's angular momentum ρJ Ω n + ρI (n × ṅ) per unit length gives the generalised
//!                 forces Q_a = ρI ä + Ω ρJ ḃ,  Q_b = ρI b̈ − Ω ρJ ȧ   (J = 2I, the polar second moment)
//! ```
//! so `M q̈ + Ω G q̇ + K q = f` with `G = [[0, R], [−R, 0]]` over the (a-plane, b-plane) rotation shapes,
//! `R = ∫ ρJ N_θᵀ N_θ dz`. A positive (forward, counter-clockwise) whirl is stiffened by `G`.
//!
//! ## Interpolation (ξ = z/L, Φ = 12 EI / (κGA L²) the shear parameter)
//! ```text
//! N_w = [1 − 3ξ² + 2ξ³ + Φ(1 − ξ),  L(ξ − 2ξ² + ξ³ + Φ(ξ − ξ²)/2),  3ξ² − 2ξ³ + Φξ,  L(−ξ² + ξ³ − Φ(ξ − ξ²)/2)] / (1 + Φ)
//! N_θ = [6(ξ² − ξ)/L,  1 − 4ξ + 3ξ² + Φ(1 − ξ),  6(ξ − ξ²)/L,  −2ξ + 3ξ² + Φξ] / (1 + Φ)
//! ```
//! These solve the static Timoshenko equations exactly (constant shear strain `w' − θ`); with Φ = 0 they are
//! the Hermite cubics and `N_θ = N_w'`. The matrices are the integrals above, evaluated with 4-point Gauss
//! quadrature (exact: the integrands are polynomials of degree ≤ 6).
//!
//! Euler–Bernoulli: Φ = 0, no shear energy and no transverse rotary inertia (`ρI θ̇²` dropped); the
//! gyroscopic term is kept (it is the polar inertia of the spinning sections).

use nalgebra::{SMatrix, SVector};

/// Degrees of freedom per node: x, y, a, b.
pub const NODE_DOFS: usize = 4;

/// 8×8 element matrix over `[x₁, y₁, a₁, b₁, x₂, y₂, a₂, b₂]`.
pub type Mat8 = SMatrix<f64, 8, 8>;
type Mat4 = SMatrix<f64, 4, 4>;
type Vec4 = SVector<f64, 4>;

// The section's data (and its area, second moment and mass) belong to the rotor file's SI form (`model`);
// this module is the element built on it.
pub use crate::model::shaft::{BeamSection, BeamTheory};

impl BeamSection {
    /// Shear coefficient κ of a (hollow) circular section (Hutchinson's form as given by Cowper):
    /// `κ = 6(1 + ν)(1 + m²)² / ((7 + 6ν)(1 + m²)² + (20 + 12ν) m²)`, m = inner/outer diameter.
    #[must_use]
    pub fn shear_coefficient(&self) -> f64 {
        let nu = self.poisson_ratio;
        let m2 = (self.inner_diameter_m / self.outer_diameter_m).powi(2);
        6.0 * (1.0 + nu) * (1.0 + m2).powi(2) / ((7.0 + 6.0 * nu) * (1.0 + m2).powi(2) + (20.0 + 12.0 * nu) * m2)
    }

    /// Shear parameter Φ = 12 EI / (κ G A L²) (0 for Euler–Bernoulli).
    #[must_use]
    pub fn shear_parameter(&self, theory: BeamTheory) -> f64 {
        match theory {
            BeamTheory::EulerBernoulli => 0.0,
            BeamTheory::Timoshenko => {
                let g = self.youngs_modulus_pa / (2.0 * (1.0 + self.poisson_ratio));
                12.0 * self.youngs_modulus_pa * self.second_moment()
                    / (self.shear_coefficient() * g * self.area() * self.length_m.powi(2))
            }
        }
    }
}

/// Mass, stiffness and gyroscopic (per unit Ω) matrices of one element.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ElementMatrices {
    pub mass: Mat8,
    pub stiffness: Mat8,
    pub gyroscopic: Mat8,
}

/// Shape functions of one plane at ξ: (N_w, N_θ, N_θ' = dN_θ/dz, shear strain shape N_w' − N_θ).
fn shapes(xi: f64, l: f64, phi: f64) -> [Vec4; 4] {
    let d = 1.0 + phi;
    let (x2, x3) = (xi * xi, xi * xi * xi);
    let nw = Vec4::new(
        1.0 - 3.0 * x2 + 2.0 * x3 + phi * (1.0 - xi),
        l * (xi - 2.0 * x2 + x3 + phi * (xi - x2) / 2.0),
        3.0 * x2 - 2.0 * x3 + phi * xi,
        l * (-x2 + x3 - phi * (xi - x2) / 2.0),
    ) / d;
    let nt = Vec4::new(
        6.0 * (x2 - xi) / l,
        1.0 - 4.0 * xi + 3.0 * x2 + phi * (1.0 - xi),
        6.0 * (xi - x2) / l,
        -2.0 * xi + 3.0 * x2 + phi * xi,
    ) / d;
    let dnt =
        Vec4::new(6.0 * (2.0 * xi - 1.0) / l, -4.0 + 6.0 * xi - phi, 6.0 * (1.0 - 2.0 * xi) / l, -2.0 + 6.0 * xi + phi)
            / (d * l);
    let dnw = Vec4::new(
        (-6.0 * xi + 6.0 * x2 - phi) / l,
        1.0 - 4.0 * xi + 3.0 * x2 + phi * (1.0 - 2.0 * xi) / 2.0,
        (6.0 * xi - 6.0 * x2 + phi) / l,
        -2.0 * xi + 3.0 * x2 - phi * (1.0 - 2.0 * xi) / 2.0,
    ) / d;
    [nw, nt, dnt, dnw - nt]
}

/// Gauss–Legendre points and weights on [0, 1] (4 points).
const GAUSS4: [(f64, f64); 4] = [
    (0.069_431_844_202_973_71, 0.173_927_422_568_726_93),
    (0.330_009_478_207_571_87, 0.326_072_577_431_273_07),
    (0.669_990_521_792_428_1, 0.326_072_577_431_273_07),
    (0.930_568_155_797_026_3, 0.173_927_422_568_726_93),
];

/// Per-plane 4×4 matrices over `[w₁, θ₁, w₂, θ₂]`: (mass, stiffness, polar `R`).
fn plane_matrices(s: &BeamSection, theory: BeamTheory) -> (Mat4, Mat4, Mat4) {
    let l = s.length_m;
    let phi = s.shear_parameter(theory);
    let (ei, rho_a, rho_i) = (
        s.youngs_modulus_pa * s.second_moment(),
        s.density_kg_per_m3 * s.area(),
        s.density_kg_per_m3 * s.second_moment(),
    );
    let kga = if phi > 0.0 { 12.0 * ei / (phi * l * l) } else { 0.0 };
    let rotary = if theory == BeamTheory::Timoshenko { rho_i } else { 0.0 };
    let (mut m, mut k, mut r) = (Mat4::zeros(), Mat4::zeros(), Mat4::zeros());
    for (xi, w) in GAUSS4 {
        let [nw, nt, dnt, gamma] = shapes(xi, l, phi);
        let wl = w * l;
        m += (rho_a * nw * nw.transpose() + rotary * nt * nt.transpose()) * wl;
        k += (ei * dnt * dnt.transpose() + kga * gamma * gamma.transpose()) * wl;
        r += 2.0 * rho_i * nt * nt.transpose() * wl;
    }
    let sym = |a: Mat4| (a + a.transpose()) * 0.5;
    (sym(m), sym(k), sym(r))
}

/// Element matrices over `[x₁, y₁, a₁, b₁, x₂, y₂, a₂, b₂]`.
#[must_use]
pub fn element_matrices(s: &BeamSection, theory: BeamTheory) -> ElementMatrices {
    let (pm, pk, pr) = plane_matrices(s, theory);
    // Plane slot i ∈ {w₁, θ₁, w₂, θ₂} → element dof, for the x–a plane and the y–b plane.
    let xa = [0, 2, 4, 6];
    let yb = [1, 3, 5, 7];
    let (mut mass, mut stiffness, mut gyroscopic) = (Mat8::zeros(), Mat8::zeros(), Mat8::zeros());
    for i in 0..4 {
        for j in 0..4 {
            for map in [xa, yb] {
                mass[(map[i], map[j])] = pm[(i, j)];
                stiffness[(map[i], map[j])] = pk[(i, j)];
            }
            // G[a-plane, b-plane] = R, G[b-plane, a-plane] = −R (R couples all four slots: N_θ has w terms).
            gyroscopic[(xa[i], yb[j])] = pr[(i, j)];
            gyroscopic[(yb[i], xa[j])] = -pr[(i, j)];
        }
    }
    ElementMatrices { mass, stiffness, gyroscopic }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn steel(l: f64, d: f64) -> BeamSection {
        BeamSection {
            length_m: l,
            outer_diameter_m: d,
            inner_diameter_m: 0.0,
            density_kg_per_m3: 7800.0,
            youngs_modulus_pa: 2.0e11,
            poisson_ratio: 0.3,
        }
    }

    /// The quadrature reproduces the closed-form Timoshenko stiffness
    /// `EI/((1+Φ)L³) [[12, 6L, −12, 6L], [6L, (4+Φ)L², −6L, (2−Φ)L²], …]`.
    #[test]
    fn stiffness_matches_closed_form() {
        let s = steel(0.1, 0.08);
        let (_, k, _) = plane_matrices(&s, BeamTheory::Timoshenko);
        let (l, phi, ei) =
            (s.length_m, s.shear_parameter(BeamTheory::Timoshenko), s.youngs_modulus_pa * s.second_moment());
        assert!(phi > 0.5, "a thick element should have a large Φ, got {phi}");
        let c = ei / ((1.0 + phi) * l.powi(3));
        let exact = Mat4::new(
            12.0,
            6.0 * l,
            -12.0,
            6.0 * l,
            6.0 * l,
            (4.0 + phi) * l * l,
            -6.0 * l,
            (2.0 - phi) * l * l,
            -12.0,
            -6.0 * l,
            12.0,
            -6.0 * l,
            6.0 * l,
            (2.0 - phi) * l * l,
            -6.0 * l,
            (4.0 + phi) * l * l,
        ) * c;
        assert!((k - exact).norm() <= 1e-12 * exact.norm(), "{k} vs {exact}");
    }

    /// Mass is conserved: a rigid translation carries the element's mass; the polar matrix integrates ρJ
    /// over a rigid rotation of unit rate (ρ J L).
    #[test]
    fn rigid_motions_carry_mass_and_polar_inertia() {
        let s = steel(0.3, 0.05);
        let e = element_matrices(&s, BeamTheory::Timoshenko);
        let mut tx = SVector::<f64, 8>::zeros();
        tx[0] = 1.0;
        tx[4] = 1.0;
        assert!(((tx.transpose() * e.mass * tx)[0] - s.mass()).abs() <= 1e-12 * s.mass());
        let mut ra = SVector::<f64, 8>::zeros();
        let mut rb = SVector::<f64, 8>::zeros();
        ra[2] = 1.0;
        ra[6] = 1.0;
        ra[4] = s.length_m;
        rb[3] = 1.0;
        rb[7] = 1.0;
        rb[5] = s.length_m;
        let polar = s.density_kg_per_m3 * 2.0 * s.second_moment() * s.length_m;
        assert!(((ra.transpose() * e.gyroscopic * rb)[0] - polar).abs() <= 1e-12 * polar);
        assert!(((rb.transpose() * e.gyroscopic * ra)[0] + polar).abs() <= 1e-12 * polar);
        assert!((e.gyroscopic + e.gyroscopic.transpose()).norm() == 0.0);
        // a rigid rotation about the first node strains nothing
        let l = s.length_m;
        let mut rot = SVector::<f64, 8>::zeros();
        rot[2] = 1.0;
        rot[6] = 1.0;
        rot[4] = l;
        assert!((e.stiffness * rot).norm() <= 1e-12 * e.stiffness.norm() * l);
    }
}
