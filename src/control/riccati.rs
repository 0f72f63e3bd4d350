//! The continuous algebraic Riccati equation of the linear–quadratic regulator (docs/MODEL.md §14, "LQR on the reduced model"):
//!
//! ```text
//! Aᵀ X + X A − X B R⁻¹ Bᵀ X + Q = 0,     K = R⁻¹ Bᵀ X,     A − B K stable
//! ```
//!
//! with `Q = Qᵀ ≥ 0` [state²], `R = Rᵀ > 0` [input²]. Solved through the Hamiltonian
//! `H = [[A, −G], [−Q, −Aᵀ]]` (`G = B R⁻¹ Bᵀ`), whose stable invariant subspace is spanned by `[I; X]`:
//! the matrix sign function `W = sign(H)` (Newton's iteration `Z ← (Z/c + c Z⁻¹)/2` with determinant scaling
//! `c = |det Z|^{1/2n}`, Byers 1987) maps that subspace to −1, so `(W + I) [I; X] = 0`, i.e.
//! `[W₁₂; W₂₂ + I] X = −[W₁₁ + I; W₂₁]`, solved in least squares. The answer is symmetrised and checked: the
//! closed loop `A − B K` must be stable, else the pair `(A, B)` is not stabilisable (or `(A, Q)` has a mode
//! on the imaginary axis that `Q` does not see) and [`RiccatiError`] says so.
//!
//! The caller scales the states so that `A`, `B`, `Q` have comparable entries ([`super::lqr`] works in µm
//! and volts on modal coordinates); the iteration itself needs no other care on the reduced models here
//! (tens of states).

use nalgebra::DMatrix;
use thiserror::Error;

use super::state_space::eigenvalues;

/// Newton steps of the sign iteration before giving up (it converges quadratically: ~10–20 steps).
const MAX_STEPS: usize = 100;
/// Relative change between two iterates that ends the iteration.
const TOLERANCE: f64 = 1e-13;

/// Why the Riccati equation has no stabilising solution.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum RiccatiError {
    /// The Hamiltonian has eigenvalues on (or too near) the imaginary axis: the sign iteration stalls.
    #[error("the Hamiltonian has eigenvalues on the imaginary axis (the sign iteration stalled after {steps} steps)")]
    NoSign { steps: usize },
    /// A solution was found but `A − B K` is not stable (largest real part given) [1/s].
    #[error("the feedback does not stabilise: a closed-loop pole at Re = {max_real_per_s:.3e} 1/s")]
    NotStabilising { max_real_per_s: f64 },
    /// `R` is not positive definite or a matrix is singular or non-finite.
    #[error("singular or non-finite matrices")]
    Singular,
}

/// The stabilising solution `X` of the CARE and the gain `K = R⁻¹ Bᵀ X`.
#[derive(Debug, Clone, PartialEq)]
pub struct Lqr {
    pub x: DMatrix<f64>,
    pub k: DMatrix<f64>,
}

/// Solves `Aᵀ X + X A − X B R⁻¹ Bᵀ X + Q = 0` for its stabilising solution.
///
/// # Errors
/// [`RiccatiError`].
pub fn care(a: &DMatrix<f64>, b: &DMatrix<f64>, q: &DMatrix<f64>, r: &DMatrix<f64>) -> Result<Lqr, RiccatiError> {
    let n = a.nrows();
    if n == 0 {
        return Ok(Lqr { x: DMatrix::zeros(0, 0), k: DMatrix::zeros(b.ncols(), 0) });
    }
    let r_inv = r.clone().cholesky().ok_or(RiccatiError::Singular)?.inverse();
    let g = b * &r_inv * b.transpose();
    let mut h = DMatrix::zeros(2 * n, 2 * n);
    h.view_mut((0, 0), (n, n)).copy_from(a);
    h.view_mut((0, n), (n, n)).copy_from(&(-&g));
    h.view_mut((n, 0), (n, n)).copy_from(&(-q));
    h.view_mut((n, n), (n, n)).copy_from(&(-a.transpose()));
    let w = sign(h)?;
    let mut lhs = DMatrix::zeros(2 * n, n);
    lhs.view_mut((0, 0), (n, n)).copy_from(&w.view((0, n), (n, n)));
    lhs.view_mut((n, 0), (n, n)).copy_from(&(w.view((n, n), (n, n)) + DMatrix::identity(n, n)));
    let mut rhs = DMatrix::zeros(2 * n, n);
    rhs.view_mut((0, 0), (n, n)).copy_from(&(-(w.view((0, 0), (n, n)) + DMatrix::identity(n, n))));
    rhs.view_mut((n, 0), (n, n)).copy_from(&(-w.view((n, 0), (n, n))));
    let x = lhs.svd(true, true).solve(&rhs, 1e-14).map_err(|_| RiccatiError::Singular)?;
    let x = (&x + x.transpose()) / 2.0;
    if x.iter().any(|v| !v.is_finite()) {
        return Err(RiccatiError::Singular);
    }
    let k = &r_inv * b.transpose() * &x;
    let closed = a - b * &k;
    let values = eigenvalues(&closed).map_err(|_| RiccatiError::Singular)?;
    let max_real = values.iter().map(|l| l.re).fold(f64::NEG_INFINITY, f64::max);
    if max_real >= 0.0 {
        return Err(RiccatiError::NotStabilising { max_real_per_s: max_real });
    }
    Ok(Lqr { x, k })
}

/// The matrix sign function by the scaled Newton iteration.
fn sign(mut z: DMatrix<f64>) -> Result<DMatrix<f64>, RiccatiError> {
    let size = z.nrows();
    #[allow(clippy::cast_precision_loss)]
    let nf = size as f64;
    for step in 0..MAX_STEPS {
        let lu = z.clone().lu();
        // |det Z|^{1/N} through the logarithms of U's diagonal (no overflow)
        let u = lu.u();
        let log_det: f64 = (0..size).map(|i| u[(i, i)].abs().ln()).sum();
        if !log_det.is_finite() {
            return Err(RiccatiError::NoSign { steps: step });
        }
        let inv = lu.try_inverse().ok_or(RiccatiError::NoSign { steps: step })?;
        let c = (log_det / nf).exp();
        let next = (&z / c + inv * c) / 2.0;
        let change = (&next - &z).norm() / next.norm();
        z = next;
        if !change.is_finite() {
            return Err(RiccatiError::NoSign { steps: step });
        }
        if change < TOLERANCE {
            return Ok(z);
        }
    }
    Err(RiccatiError::NoSign { steps: MAX_STEPS })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn m(rows: usize, cols: usize, v: &[f64]) -> DMatrix<f64> {
        DMatrix::from_row_slice(rows, cols, v)
    }

    /// Scalar plant ẋ = a x + b u, cost ∫ q x² + r u²: X = r (a + √(a² + b² q/r)) / b² = q / (√(a² + b² q/r) − a)
    /// (the second form free of cancellation), stable and unstable a.
    #[test]
    fn scalar_lqr_is_the_closed_form() {
        for (a, b, q, r) in [
            (-1.0, 1.0, 1.0, 1.0),
            (2.0, 0.5, 3.0, 0.1),
            (0.0, 2.0, 5.0, 7.0),
            (-40.0, 3.0, 1e-3, 2.0),
            (1e3, 1e-2, 1e6, 1e-4),
        ] {
            let got = care(&m(1, 1, &[a]), &m(1, 1, &[b]), &m(1, 1, &[q]), &m(1, 1, &[r])).unwrap();
            let x = q / ((a * a + b * b * q / r).sqrt() - a);
            assert!((got.x[(0, 0)] - x).abs() < 1e-13 * x.abs(), "a {a}: {} vs {x}", got.x[(0, 0)]);
            assert!((got.k[(0, 0)] - b * x / r).abs() < 1e-13 * (b * x / r).abs());
        }
    }

    /// Double integrator ẍ = u with Q = diag(q, 0), R = r: K = [√(q/r), √(2√(q/r))] (the closed loop has
    /// damping ratio 1/√2 at ω = (q/r)^{1/4}).
    #[test]
    fn double_integrator_lqr_is_the_closed_form() {
        for (q, r) in [(1.0, 1.0), (100.0, 0.01), (1e-4, 3.0)] {
            let got = care(
                &m(2, 2, &[0.0, 1.0, 0.0, 0.0]),
                &m(2, 1, &[0.0, 1.0]),
                &m(2, 2, &[q, 0.0, 0.0, 0.0]),
                &m(1, 1, &[r]),
            )
            .unwrap();
            let w = (q / r).sqrt();
            let want = [w, (2.0 * w).sqrt()];
            for (j, k) in want.iter().enumerate() {
                assert!((got.k[(0, j)] - k).abs() < 1e-12 * k, "q {q} r {r}: K {} vs {k}", got.k[(0, j)]);
            }
            // the residual of the equation itself
            let (a, b) = (m(2, 2, &[0.0, 1.0, 0.0, 0.0]), m(2, 1, &[0.0, 1.0]));
            let res = a.transpose() * &got.x + &got.x * &a - &got.x * &b * b.transpose() * &got.x / r
                + m(2, 2, &[q, 0.0, 0.0, 0.0]);
            assert!(res.norm() < 1e-12 * got.x.norm().max(q), "residual {}", res.norm());
        }
    }

    /// An unstable mode the input cannot reach (ẋ₁ = x₁, ẋ₂ = −x₂ + u): no stabilising solution.
    #[test]
    fn unstabilisable_pair_is_an_error() {
        let e =
            care(&m(2, 2, &[1.0, 0.0, 0.0, -1.0]), &m(2, 1, &[0.0, 1.0]), &DMatrix::identity(2, 2), &m(1, 1, &[1.0]))
                .unwrap_err();
        assert!(matches!(e, RiccatiError::NoSign { .. } | RiccatiError::NotStabilising { .. }), "{e:?}");
    }
}
