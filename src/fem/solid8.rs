//! 8-node hexahedra for linear isotropic elasticity, with incompatible bending modes.
//!
//! ## Equation (per element, small strain)
//! ```text
//! K_ab = ∫ B_aᵀ D B_b dV          stiffness (D: isotropic, Lamé λ = Eν/((1+ν)(1−2ν)), µ = E/(2(1+ν)))
//! M_ab = ∫ ρ N_a N_b dV · I₃      consistent mass
//! ε = (ε_xx, ε_yy, ε_zz, γ_xy, γ_yz, γ_zx) = B u       (engineering shear strains)
//! ```
//! The geometry is isoparametric (trilinear map of the reference cube (ξ, η, ζ) ∈ [−1, 1]³ onto the element's
//! eight Cartesian nodes, node order of [`super::hex8::NODES`]), integrated with 2×2×2 Gauss points.
//!
//! ## Why incompatible modes
//! A plain trilinear hexahedron cannot bend: under a pure moment its edges stay straight, so it adds a
//! spurious shear strain, and a thin pad (a few elements through the thickness) comes out several times too
//! stiff (shear locking; the bending test in `physics::pad_elastic` measures it). Following Wilson and the
//! Taylor correction, each element adds three internal displacement fields `(1 − ξ²), (1 − η²), (1 − ζ²)`
//! per component (9 internal unknowns) that let the element curve; their derivatives are evaluated with the
//! Jacobian at the element centre, scaled by `det J₀ / det J`, so the element passes the constant-strain patch
//! test on distorted shapes. The internal unknowns are condensed out element by element:
//! `K = K_cc − K_ci K_ii⁻¹ K_ic`. The mass uses the compatible shape functions only.
//!
//! Thermal strain `ε_th = α ΔT (1, 1, 1, 0, 0, 0)` enters as the load `∫ Bᵀ D ε_th dV` (condensed like the
//! stiffness), for the pads' thermal growth.
//!
//! Units: SI (m, Pa, kg/m³); the element matrices act on `u = (u_x, u_y, u_z)` per node, node-major.

use nalgebra::{Matrix3, SMatrix, SVector, Vector3};

use super::hex8::NODES;

const G: f64 = 0.577_350_269_189_625_8;

/// Element formulation.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Formulation {
    /// Plain trilinear displacements (locks in bending; kept to show it).
    Trilinear,
    /// Trilinear plus Wilson–Taylor incompatible modes (the default).
    Incompatible,
}

/// Isotropic linear elastic material.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Elastic {
    /// Young's modulus E [Pa].
    pub youngs_modulus: f64,
    /// Poisson's ratio ν.
    pub poisson_ratio: f64,
    /// Density ρ [kg/m³].
    pub density: f64,
}

impl Elastic {
    /// The 6×6 isotropic constitutive matrix (engineering shear strains).
    #[must_use]
    pub fn d_matrix(&self) -> SMatrix<f64, 6, 6> {
        let (e, nu) = (self.youngs_modulus, self.poisson_ratio);
        let lambda = e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
        let mu = e / (2.0 * (1.0 + nu));
        let mut d = SMatrix::<f64, 6, 6>::zeros();
        for i in 0..3 {
            for j in 0..3 {
                d[(i, j)] = lambda;
            }
            d[(i, i)] += 2.0 * mu;
            d[(i + 3, i + 3)] = mu;
        }
        d
    }
}

/// Element stiffness and mass, 24 × 24 (node-major, x y z per node).
pub type Matrix24 = SMatrix<f64, 24, 24>;

fn shape(p: [f64; 3]) -> [f64; 8] {
    NODES.map(|(a, b, c)| 0.125 * (1.0 + p[0] * a) * (1.0 + p[1] * b) * (1.0 + p[2] * c))
}

/// ∂N_a/∂(ξ, η, ζ).
fn dshape(p: [f64; 3]) -> [Vector3<f64>; 8] {
    NODES.map(|(a, b, c)| {
        Vector3::new(
            0.125 * a * (1.0 + p[1] * b) * (1.0 + p[2] * c),
            0.125 * b * (1.0 + p[0] * a) * (1.0 + p[2] * c),
            0.125 * c * (1.0 + p[0] * a) * (1.0 + p[1] * b),
        )
    })
}

/// Jacobian `J_ij = ∂x_j/∂ξ_i` at a reference point.
fn jacobian(x: &[[f64; 3]; 8], d: &[Vector3<f64>; 8]) -> Matrix3<f64> {
    let mut j = Matrix3::zeros();
    for (xa, da) in x.iter().zip(d) {
        for r in 0..3 {
            for c in 0..3 {
                j[(r, c)] += da[r] * xa[c];
            }
        }
    }
    j
}

/// Strain–displacement columns of a field with global gradient `g` (one column per displacement component).
fn b_columns(g: &Vector3<f64>) -> SMatrix<f64, 6, 3> {
    SMatrix::<f64, 6, 3>::from_row_slice(&[
        g[0], 0.0, 0.0, //
        0.0, g[1], 0.0, //
        0.0, 0.0, g[2], //
        g[1], g[0], 0.0, //
        0.0, g[2], g[1], //
        g[2], 0.0, g[0],
    ])
}

fn gauss_points() -> impl Iterator<Item = [f64; 3]> {
    [-G, G].into_iter().flat_map(|a| [-G, G].into_iter().flat_map(move |b| [-G, G].into_iter().map(move |c| [a, b, c])))
}

/// Element integrals before condensation: compatible and internal (incompatible) blocks.
struct Parts {
    kcc: Matrix24,
    kci: SMatrix<f64, 24, 9>,
    kii: SMatrix<f64, 9, 9>,
    m: Matrix24,
    /// Thermal load per unit α and unit nodal temperature rise, `∫ Bᵀ D m N_a dV` (column a, m = [1 1 1 0 0 0]ᵀ)
    /// on the compatible and the internal unknowns: the load of `α ΔT` is `α G ΔT_nodal` (linear in both).
    gc: SMatrix<f64, 24, 8>,
    gi: SMatrix<f64, 9, 8>,
}

/// Integrates the element.
fn integrate(x: &[[f64; 3]; 8], mat: &Elastic, form: Formulation) -> Option<Parts> {
    let d_mat = mat.d_matrix();
    let j0 = jacobian(x, &dshape([0.0; 3]));
    let det0 = j0.determinant();
    let j0_inv = j0.try_inverse()?;
    let mut p = Parts {
        kcc: Matrix24::zeros(),
        kci: SMatrix::zeros(),
        kii: SMatrix::zeros(),
        m: Matrix24::zeros(),
        gc: SMatrix::zeros(),
        gi: SMatrix::zeros(),
    };
    // Stress of a unit thermal strain (1, 1, 1, 0, 0, 0).
    let sigma_unit = d_mat * SVector::<f64, 6>::from_row_slice(&[1.0, 1.0, 1.0, 0.0, 0.0, 0.0]);
    for gp in gauss_points() {
        let d = dshape(gp);
        let j = jacobian(x, &d);
        let det = j.determinant();
        if det <= 0.0 {
            return None;
        }
        let j_inv = j.try_inverse()?;
        let mut b = SMatrix::<f64, 6, 24>::zeros();
        for (a, da) in d.iter().enumerate() {
            b.fixed_view_mut::<6, 3>(0, 3 * a).copy_from(&b_columns(&(j_inv * da)));
        }
        let db = d_mat * b;
        p.kcc += b.transpose() * db * det;
        let n = shape(gp);
        // Thermal strain ΔT(gp) (1, 1, 1, 0, 0, 0) with ΔT(gp) = Σ_a N_a ΔT_a: column a gets Bᵀ D m N_a.
        let n_row = SMatrix::<f64, 1, 8>::from_row_slice(&n);
        p.gc += (b.transpose() * sigma_unit * det) * n_row;
        if form == Formulation::Incompatible {
            // Internal fields (1 − ξ_i²): reference gradient −2 ξ_i e_i, mapped with the centre Jacobian.
            let mut bi = SMatrix::<f64, 6, 9>::zeros();
            for i in 0..3 {
                let mut dp = Vector3::zeros();
                dp[i] = -2.0 * gp[i];
                let g = (j0_inv * dp) * (det0 / det);
                bi.fixed_view_mut::<6, 3>(0, 3 * i).copy_from(&b_columns(&g));
            }
            p.kci += db.transpose() * bi * det;
            p.kii += bi.transpose() * d_mat * bi * det;
            p.gi += (bi.transpose() * sigma_unit * det) * n_row;
        }
        for a in 0..8 {
            for bb in 0..8 {
                let v = mat.density * n[a] * n[bb] * det;
                for c in 0..3 {
                    p.m[(3 * a + c, 3 * bb + c)] += v;
                }
            }
        }
    }
    Some(p)
}

/// Stiffness and mass of one element with Cartesian nodes `x`. `None` if the element is inverted
/// (`det J ≤ 0` at a Gauss point).
#[must_use]
pub fn element_matrices(x: &[[f64; 3]; 8], mat: &Elastic, form: Formulation) -> Option<(Matrix24, Matrix24)> {
    element_matrices_and_thermal(x, mat, form).map(|(k, m, _)| (k, m))
}

/// Stiffness, mass and the condensed thermal-load operator of one element from one integration (a thermally
/// loaded solid needs all three). The operator is the load per unit α and unit nodal temperature rise,
/// `G = G_c − K_ci K_ii⁻¹ G_i` (column a: the load of ΔT = N_a, `∫ Bᵀ D m N_a dV` condensed consistently with
/// the stiffness), so the load of `α ΔT` is `α G ΔT_nodal`: one 24 × 8 product per new temperature field.
#[must_use]
pub fn element_matrices_and_thermal(
    x: &[[f64; 3]; 8],
    mat: &Elastic,
    form: Formulation,
) -> Option<(Matrix24, Matrix24, SMatrix<f64, 24, 8>)> {
    let p = integrate(x, mat, form)?;
    if form == Formulation::Incompatible {
        let chol = p.kii.cholesky()?;
        Some((p.kcc - p.kci * chol.solve(&p.kci.transpose()), p.m, p.gc - p.kci * chol.solve(&p.gi)))
    } else {
        Some((p.kcc, p.m, p.gc))
    }
}

/// Momentum of a displacement (velocity) field over the element, `∫ ρ u dV` [kg · unit of u].
#[must_use]
pub fn element_momentum(x: &[[f64; 3]; 8], density: f64, u: &[[f64; 3]; 8]) -> [f64; 3] {
    let mut out = [0.0; 3];
    for p in gauss_points() {
        let det = jacobian(x, &dshape(p)).determinant();
        let n = shape(p);
        for (na, ua) in n.iter().zip(u) {
            for c in 0..3 {
                out[c] += density * det * na * ua[c];
            }
        }
    }
    out
}

/// Element displacement vector of a field given at the nodes.
#[must_use]
pub fn nodal_vector(x: &[[f64; 3]; 8], f: impl Fn([f64; 3]) -> [f64; 3]) -> SVector<f64, 24> {
    SVector::<f64, 24>::from_fn(|i, _| f(x[i / 3])[i % 3])
}

#[cfg(test)]
mod tests {
    use super::*;

    fn distorted() -> [[f64; 3]; 8] {
        let mut x = NODES.map(|(a, b, c)| [0.5 * (a + 1.0) * 0.02, 0.5 * (b + 1.0) * 0.01, 0.5 * (c + 1.0) * 0.015]);
        x[2] = [0.023, 0.012, 0.017];
        x[5] = [0.018, -0.002, 0.001];
        x[7] = [0.021, 0.001, 0.014];
        x
    }

    const STEEL: Elastic = Elastic { youngs_modulus: 200e9, poisson_ratio: 0.3, density: 7800.0 };

    #[test]
    fn rigid_motions_cost_nothing_and_mass_is_the_volume_times_density() {
        let x = distorted();
        let (k, m) = element_matrices(&x, &STEEL, Formulation::Incompatible).unwrap();
        let scale = k.abs().max();
        for rigid in [
            nodal_vector(&x, |_| [1.0, 0.0, 0.0]),
            nodal_vector(&x, |_| [0.0, 0.0, 1.0]),
            nodal_vector(&x, |p| [-p[1], p[0], 0.0]),
            nodal_vector(&x, |p| [0.0, -p[2], p[1]]),
        ] {
            assert!((k * rigid).abs().max() < 1e-9 * scale, "{}", (k * rigid).abs().max() / scale);
        }
        // Σ_ab M_ab for one component = ρ V; volume of the distorted element by the divergence theorem is
        // not closed-form, so compare with the 2×2×2 integral of det J (exact for a trilinear map).
        let ones = nodal_vector(&x, |_| [1.0, 0.0, 0.0]);
        let mass = (ones.transpose() * m * ones)[0];
        let volume: f64 = gauss_points().map(|p| jacobian(&x, &dshape(p)).determinant()).sum();
        assert!((mass - 7800.0 * volume).abs() < 1e-12 * mass);
    }

    /// Constant-strain patch test: a linear displacement field stores exactly ½ εᵀDε V, also on a distorted
    /// element (this is what the Taylor correction buys; Wilson's original element fails it).
    #[test]
    fn constant_strain_energy_is_exact_on_a_distorted_element() {
        let x = distorted();
        let volume: f64 = gauss_points().map(|p| jacobian(&x, &dshape(p)).determinant()).sum();
        let grad = [[1e-3, 2e-4, -3e-4], [5e-4, -1e-3, 1e-4], [0.0, 3e-4, 2e-3]];
        let u = nodal_vector(&x, |p| std::array::from_fn(|i| (0..3).map(|j| grad[i][j] * p[j]).sum()));
        let eps = SVector::<f64, 6>::from_row_slice(&[
            grad[0][0],
            grad[1][1],
            grad[2][2],
            grad[0][1] + grad[1][0],
            grad[1][2] + grad[2][1],
            grad[2][0] + grad[0][2],
        ]);
        let exact = (eps.transpose() * STEEL.d_matrix() * eps)[0] * volume;
        for form in [Formulation::Trilinear, Formulation::Incompatible] {
            let (k, _) = element_matrices(&x, &STEEL, form).unwrap();
            let energy = (u.transpose() * k * u)[0];
            assert!((energy - exact).abs() < 1e-10 * exact, "{form:?}: {energy} vs {exact}");
        }
    }

    #[test]
    fn an_inverted_element_is_refused() {
        let mut x = distorted();
        x.swap(0, 4);
        x.swap(1, 5);
        x.swap(2, 6);
        x.swap(3, 7);
        assert!(element_matrices(&x, &STEEL, Formulation::Incompatible).is_none());
    }
}
