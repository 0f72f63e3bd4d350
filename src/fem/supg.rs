//! Steady advection–diffusion–reaction on 4-node elements, stabilised with streamline-upwind
//! Petrov–Galerkin (SUPG, Brooks & Hughes 1982).
//!
//! ## Equation
//! ```text
//! −∇·(D ∇u) + a·∇u + c u = f        D ≥ 0 diffusivity, a advection velocity, c ≥ 0 reaction, f source
//! ```
//!
//! ## Weak form, term by term
//! Test functions are `W_i = N_i + τ a·∇N_i` (Galerkin plus the streamline perturbation). For every node i:
//!
//! ```text
//!   ∫ D ∇u·∇N_i dA              diffusion (Galerkin only: for bilinear elements the element-interior
//!                               second derivatives in the SUPG residual are dropped, the usual choice)
//! + ∫ (a·∇u) W_i dA             advection, with the upwind perturbation along the streamline
//! + ∫ c u W_i dA                reaction (weighted by W_i too, so the method stays consistent)
//! = ∫ f W_i dA                  source (weighted by W_i)
//! ```
//!
//! ## The stabilisation parameter τ
//! Per element, from element-averaged coefficients:
//! - streamline element length `h_e = 2|a| / Σ_b |a·∇N_b|` (evaluated with the element-centre gradients; it
//!   equals the element's extent along `a` for rectangles and stays meaningful on distorted quads);
//! - element Péclet number `Pe = |a| h_e / (2D)`;
//! - `τ = h_e / (2|a|) · ξ(Pe)`, `ξ(Pe) = coth Pe − 1/Pe` (0 for pure diffusion, → 1 for pure advection);
//!   with linear elements in 1-D this makes the scheme nodally exact (docs/REFERENCES.md §4);
//! - reaction-dominated limit: `τ ≤ 1/c` (where the reaction time is shorter than the advection time across
//!   the element, the streamline perturbation must not exceed it).
//!
//! ## Two additions that plain SUPG needs on the skew-advection benchmark
//! SUPG is not monotone: on the Hughes–Mallet–Mizukami test (docs/REFERENCES.md §4) it overshoots by ~40 % in the
//! Dirichlet *outflow* boundary layers and undershoots by ~5 % across the internal layer. Hence:
//! - **Outflow boundary parameter** (after Knobloch, ETNA 32, 2008): on an element with an edge on a Dirichlet
//!   outflow boundary (outward normal n, a·n > 0), τ is at least the value that makes the scheme nodally exact
//!   across that boundary, `τ_n = h_n/(2 a·n) ξ(a·n h_n/(2D))`, `h_n` the element height normal to the edge.
//!   The film energy equation has no Dirichlet outflow boundaries (its outflow edges are natural), so there
//!   this never applies.
//! - **Crosswind discontinuity capturing** (Codina, CMAME 110, 1993), [`add_crosswind_point`]: a consistent,
//!   residual-based diffusion across the streamlines, with Codina's constant `C = 0.7` for linear elements.
//!   It makes the scheme nonlinear: [`solve_picard`] iterates on it (damped fixed point).
//!
//! [`Stabilisation::Galerkin`] sets τ = 0 (plain Galerkin, which oscillates at high Péclet numbers; kept to
//! show exactly that in the benchmarks).

use super::lu::GeneralPattern;
use super::quad4::QuadPoint;

/// Coefficients of the equation at one point.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Adr {
    /// Diffusivity D.
    pub d: f64,
    /// Advection velocity a (components along the element's two coordinates).
    pub a: [f64; 2],
    /// Reaction coefficient c ≥ 0.
    pub c: f64,
    /// Source f.
    pub f: f64,
}

/// Stabilisation of the advective term.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Stabilisation {
    /// Plain Bubnov–Galerkin (τ = 0).
    Galerkin,
    /// Streamline-upwind Petrov–Galerkin with the τ described in the module documentation (linear).
    Supg,
    /// SUPG plus crosswind discontinuity capturing (nonlinear).
    SupgCrosswind,
}

/// Codina's crosswind constant for linear elements.
pub const CROSSWIND_CONSTANT: f64 = 0.7;

/// An element edge on a Dirichlet boundary (for the outflow parameter).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BoundaryEdge {
    pub element: usize,
    /// Outward unit normal.
    pub normal: [f64; 2],
    pub length: f64,
}

/// What the assembly needs of a Q4 mesh.
#[derive(Debug, Clone, Copy)]
pub struct AdrMesh<'a> {
    pub elements: &'a [[usize; 4]],
    /// 2×2 Gauss points of each element.
    pub qp: &'a [[QuadPoint; 4]],
    /// Element diameters (longest diagonal), for the crosswind term.
    pub diameters: &'a [f64],
    /// Element edges on Dirichlet boundaries.
    pub dirichlet_edges: &'a [BoundaryEdge],
}

/// `ξ(Pe) = coth Pe − 1/Pe`, evaluated without cancellation for small Pe.
#[must_use]
pub fn upwind_function(pe: f64) -> f64 {
    if pe < 1e-3 {
        pe / 3.0
    } else if pe > 20.0 {
        1.0 - 1.0 / pe
    } else {
        1.0 / pe.tanh() - 1.0 / pe
    }
}

/// SUPG parameter τ for an element with averaged coefficients `coef` and element-centre shape-function
/// gradients `grad` (`grad[b] = ∇N_b`).
#[must_use]
pub fn supg_tau(coef: &Adr, grad: &[[f64; 2]; 4]) -> f64 {
    let speed = coef.a[0].hypot(coef.a[1]);
    if speed <= 0.0 || !speed.is_finite() {
        return 0.0;
    }
    let proj: f64 = grad.iter().map(|g| (coef.a[0] * g[0] + coef.a[1] * g[1]).abs()).sum();
    if proj <= 0.0 {
        return 0.0;
    }
    let h_e = 2.0 * speed / proj;
    let xi = if coef.d > 0.0 { upwind_function(speed * h_e / (2.0 * coef.d)) } else { 1.0 };
    let tau = h_e / (2.0 * speed) * xi;
    if coef.c > 0.0 {
        tau.min(1.0 / coef.c)
    } else {
        tau
    }
}

/// Test-function values `W_i = N_i + τ a·∇N_i` at a point.
#[must_use]
pub fn test_weights(q: &QuadPoint, a: [f64; 2], tau: f64) -> [f64; 4] {
    let mut w = q.n;
    for (i, wi) in w.iter_mut().enumerate() {
        *wi += tau * (a[0] * q.dn_ds[i] + a[1] * q.dn_dz[i]);
    }
    w
}

/// Adds the contribution of one point to the element matrix `ke[i][j]` (row i = test, column j = trial)
/// and vector `fe`.
pub fn add_point(q: &QuadPoint, coef: &Adr, tau: f64, ke: &mut [[f64; 4]; 4], fe: &mut [f64; 4]) {
    let w = test_weights(q, coef.a, tau);
    for i in 0..4 {
        fe[i] += q.w * coef.f * w[i];
        for j in 0..4 {
            let adv = coef.a[0] * q.dn_ds[j] + coef.a[1] * q.dn_dz[j];
            let diff = coef.d * (q.dn_ds[i] * q.dn_ds[j] + q.dn_dz[i] * q.dn_dz[j]);
            ke[i][j] += q.w * (diff + (adv + coef.c * q.n[j]) * w[i]);
        }
    }
}

/// Element-averaged coefficients and centre gradients (mean over the element's quadrature points).
#[must_use]
pub fn element_average(qp: &[QuadPoint; 4], coefs: &[Adr; 4]) -> (Adr, [[f64; 2]; 4]) {
    let mut avg = Adr::default();
    let mut grad = [[0.0; 2]; 4];
    for (q, c) in qp.iter().zip(coefs) {
        avg.d += 0.25 * c.d;
        avg.a[0] += 0.25 * c.a[0];
        avg.a[1] += 0.25 * c.a[1];
        avg.c += 0.25 * c.c;
        avg.f += 0.25 * c.f;
        for b in 0..4 {
            grad[b][0] += 0.25 * q.dn_ds[b];
            grad[b][1] += 0.25 * q.dn_dz[b];
        }
    }
    (avg, grad)
}

/// τ on an element with an edge on a Dirichlet outflow boundary (module documentation).
#[must_use]
pub fn outflow_tau(coef: &Adr, edge: &BoundaryEdge, area: f64) -> f64 {
    let an = coef.a[0] * edge.normal[0] + coef.a[1] * edge.normal[1];
    if an <= 0.0 || edge.length <= 0.0 {
        return 0.0;
    }
    let h_n = area / edge.length;
    let xi = if coef.d > 0.0 { upwind_function(an * h_n / (2.0 * coef.d)) } else { 1.0 };
    h_n / (2.0 * an) * xi
}

/// Assembles a whole Q4 mesh (2×2 Gauss per element) into `values` (the pattern's groups must be the
/// elements, in order) and `rhs`, both zeroed first. `coef(e, k)` gives the coefficients at point k of
/// element e; `u_prev` is the iterate the crosswind term is computed from (ignored unless
/// [`Stabilisation::SupgCrosswind`]).
#[allow(clippy::too_many_arguments)]
pub fn assemble(
    pattern: &GeneralPattern,
    mesh: &AdrMesh<'_>,
    coef: &dyn Fn(usize, usize) -> Adr,
    stab: Stabilisation,
    u_prev: Option<&[f64]>,
    values: &mut [f64],
    rhs: &mut [f64],
) {
    values.fill(0.0);
    rhs.fill(0.0);
    let mut tau_out = vec![0.0; mesh.elements.len()];
    if stab != Stabilisation::Galerkin {
        for edge in mesh.dirichlet_edges {
            let e = edge.element;
            let c: [Adr; 4] = [0, 1, 2, 3].map(|k| coef(e, k));
            let (avg, _) = element_average(&mesh.qp[e], &c);
            let area: f64 = mesh.qp[e].iter().map(|q| q.w).sum();
            tau_out[e] = f64::max(tau_out[e], outflow_tau(&avg, edge, area));
        }
    }
    for (e, nodes) in mesh.elements.iter().enumerate() {
        let c: [Adr; 4] = [0, 1, 2, 3].map(|k| coef(e, k));
        let (avg, grad) = element_average(&mesh.qp[e], &c);
        let tau = match stab {
            Stabilisation::Galerkin => 0.0,
            Stabilisation::Supg | Stabilisation::SupgCrosswind => supg_tau(&avg, &grad).max(tau_out[e]),
        };
        let mut ke = [[0.0; 4]; 4];
        let mut fe = [0.0; 4];
        let prev = match (stab, u_prev) {
            (Stabilisation::SupgCrosswind, Some(u)) => Some(nodes.map(|k| u[k])),
            _ => None,
        };
        for (q, ck) in mesh.qp[e].iter().zip(&c) {
            add_point(q, ck, tau, &mut ke, &mut fe);
            if let Some(up) = &prev {
                add_crosswind_point(q, ck, up, mesh.diameters[e], CROSSWIND_CONSTANT, &mut ke);
            }
        }
        let pos = pattern.group_positions(e);
        for i in 0..4 {
            rhs[nodes[i]] += fe[i];
            for j in 0..4 {
                values[pos[4 * i + j]] += ke[i][j];
            }
        }
    }
}

/// Settings of the fixed-point iteration on the crosswind term.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PicardParams {
    /// Stop when the largest nodal change is below this, relative to the solution's range.
    pub tol: f64,
    pub max_iterations: usize,
    /// Under-relaxation of the update (1 = none).
    pub relaxation: f64,
}

impl Default for PicardParams {
    fn default() -> Self {
        Self { tol: 1e-6, max_iterations: 200, relaxation: 0.5 }
    }
}

/// Result of [`solve_picard`].
#[derive(Debug, Clone, PartialEq)]
pub struct PicardSolution {
    pub u: Vec<f64>,
    pub iterations: usize,
    /// Last relative change (below `tol` when converged).
    pub change: f64,
    pub converged: bool,
}

/// Solves the problem on a Q4 mesh with Dirichlet values where `dirichlet[k]` is `Some`. Linear for
/// [`Stabilisation::Galerkin`] and [`Stabilisation::Supg`]; for [`Stabilisation::SupgCrosswind`] a damped
/// fixed-point iteration started from the SUPG solution.
///
/// # Errors
/// A singular system.
pub fn solve_picard(
    pattern: &GeneralPattern,
    lu: &mut super::lu::LuSolver,
    mesh: &AdrMesh<'_>,
    coef: &dyn Fn(usize, usize) -> Adr,
    dirichlet: &[Option<f64>],
    stab: Stabilisation,
    params: PicardParams,
) -> Result<PicardSolution, super::sparse::SolverError> {
    let n = pattern.n;
    let mut values = vec![0.0; pattern.nnz()];
    let mut rhs = vec![0.0; n];
    let mut u: Vec<f64> = Vec::new();
    let mut change = 0.0;
    let max_it = if stab == Stabilisation::SupgCrosswind { params.max_iterations.max(1) } else { 1 };
    for it in 0..max_it {
        let step = if it == 0 && stab == Stabilisation::SupgCrosswind { Stabilisation::Supg } else { stab };
        assemble(pattern, mesh, coef, step, (it > 0).then_some(u.as_slice()), &mut values, &mut rhs);
        for (k, d) in dirichlet.iter().enumerate() {
            if let Some(v) = d {
                pattern.set_identity_row(&mut values, k);
                rhs[k] = *v;
            }
        }
        lu.factor(pattern, &values)?;
        lu.solve_in_place(&mut rhs, n)?;
        if it == 0 {
            u.clone_from(&rhs);
            continue;
        }
        let range = u.iter().fold(f64::MIN, |m, &v| m.max(v)) - u.iter().fold(f64::MAX, |m, &v| m.min(v));
        change = rhs.iter().zip(&u).fold(0.0_f64, |m, (a, b)| m.max((a - b).abs())) / range.max(f64::MIN_POSITIVE);
        for (uk, nk) in u.iter_mut().zip(&rhs) {
            *uk += params.relaxation * (nk - *uk);
        }
        if change < params.tol {
            return Ok(PicardSolution { u, iterations: it + 1, change, converged: true });
        }
    }
    let converged = stab != Stabilisation::SupgCrosswind;
    Ok(PicardSolution { u, iterations: max_it, change, converged })
}

/// Crosswind discontinuity capturing (Codina 1993): an extra diffusion across the streamlines, active only
/// where the discrete residual is large (layers), computed from a previous iterate `u_prev`:
///
/// ```text
/// + ∫ ε̃ ∇u·(I − â âᵀ)·∇N_i dA,   â = a/|a|,
/// ε̃ = ½ max(0, C − 2D / (|∇u_prev| h_e)) · h_e |R(u_prev)| / |∇u_prev|,   R = a·∇u + c u − f
/// ```
///
/// with `h_e` the element diameter and `C` the method constant. The term is consistent (it vanishes with the
/// residual) and adds no streamline smearing; it makes the scheme nonlinear (Picard iteration on `u_prev`).
pub fn add_crosswind_point(
    q: &QuadPoint,
    coef: &Adr,
    u_prev: &[f64; 4],
    h_e: f64,
    constant: f64,
    ke: &mut [[f64; 4]; 4],
) {
    let speed = coef.a[0].hypot(coef.a[1]);
    let (mut gx, mut gz, mut u) = (0.0, 0.0, 0.0);
    for a in 0..4 {
        gx += q.dn_ds[a] * u_prev[a];
        gz += q.dn_dz[a] * u_prev[a];
        u += q.n[a] * u_prev[a];
    }
    let grad = gx.hypot(gz);
    if speed <= 0.0 || grad <= 1e-14 * (u.abs() + 1.0) / h_e {
        return;
    }
    let r = coef.a[0] * gx + coef.a[1] * gz + coef.c * u - coef.f;
    let eps = 0.5 * (constant - 2.0 * coef.d / (grad * h_e)).max(0.0) * h_e * r.abs() / grad;
    if eps <= 0.0 {
        return;
    }
    let (ax, az) = (coef.a[0] / speed, coef.a[1] / speed);
    // Crosswind projector P = I − â âᵀ.
    let p = [[1.0 - ax * ax, -ax * az], [-ax * az, 1.0 - az * az]];
    for i in 0..4 {
        let gi = [q.dn_ds[i], q.dn_dz[i]];
        for j in 0..4 {
            let gj = [q.dn_ds[j], q.dn_dz[j]];
            let v = gi[0] * (p[0][0] * gj[0] + p[0][1] * gj[1]) + gi[1] * (p[1][0] * gj[0] + p[1][1] * gj[1]);
            ke[i][j] += q.w * eps * v;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fem::RectElement;

    #[test]
    fn upwind_function_limits() {
        assert!((upwind_function(1e-6) - 1e-6 / 3.0).abs() < 1e-15);
        assert!((upwind_function(1.0) - (1.0 / 1.0_f64.tanh() - 1.0)).abs() < 1e-15);
        assert!((upwind_function(1e4) - 1.0).abs() < 2e-4);
        // Continuity at the switch points.
        assert!((upwind_function(20.0 - 1e-9) - upwind_function(20.0 + 1e-9)).abs() < 1e-8);
    }

    #[test]
    fn tau_is_half_the_element_length_over_speed_for_pure_advection() {
        let r = RectElement { s0: 0.0, z0: 0.0, ds: 0.2, dz: 0.05 };
        let qp = r.gauss_2x2();
        let coef = [Adr { d: 0.0, a: [3.0, 0.0], c: 0.0, f: 0.0 }; 4];
        let (avg, grad) = element_average(&qp, &coef);
        assert!((supg_tau(&avg, &grad) - 0.2 / 6.0).abs() < 1e-14);
        // Along z the streamline length is dz.
        let coef = [Adr { d: 0.0, a: [0.0, -2.0], c: 0.0, f: 0.0 }; 4];
        let (avg, grad) = element_average(&qp, &coef);
        assert!((supg_tau(&avg, &grad) - 0.05 / 4.0).abs() < 1e-14);
        // A strong reaction caps τ.
        let coef = [Adr { d: 0.0, a: [3.0, 0.0], c: 100.0, f: 0.0 }; 4];
        let (avg, grad) = element_average(&qp, &coef);
        assert!((supg_tau(&avg, &grad) - 0.01).abs() < 1e-14);
    }

    #[test]
    fn supg_weights_sum_to_one() {
        // Σ_i W_i = 1 because Σ_i ∇N_i = 0: summed over all nodes the SUPG terms vanish, which keeps the
        // global balance of the equation.
        let r = RectElement { s0: 0.0, z0: 0.0, ds: 0.3, dz: 0.1 };
        for q in r.gauss_2x2() {
            let w = test_weights(&q, [2.0, -1.0], 0.7);
            assert!((w.iter().sum::<f64>() - 1.0).abs() < 1e-14);
        }
    }
}
