//! Linear time-invariant systems in state-space form and the two numerical tools the loop needs.
//!
//! ```text
//! ẋ = A x + B u,   y = C x + D u,   G(s) = C (sI − A)⁻¹ B + D
//! ```
//!
//! - [`StateSpace::response`]: `G(s)` at one complex `s` (one complex LU of `sI − A`);
//! - [`eigenvalues`]: the eigenvalues of a real matrix, after a diagonal balancing (Parlett–Reinsch: powers
//!   of two, so the similarity is exact in floating point). The closed loop mixes rotor coordinates in
//!   metres, nozzle pressures in pascals and line flows in m³/s: without balancing the eigen-solver would
//!   see entries twelve orders of magnitude apart and lose the rotor's lightly damped modes to round-off.

use nalgebra::{Complex, DMatrix};

use super::error::ControlError;

pub type C64 = Complex<f64>;

/// `ẋ = A x + B u`, `y = C x + D u`.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct StateSpace {
    pub a: DMatrix<f64>,
    pub b: DMatrix<f64>,
    pub c: DMatrix<f64>,
    pub d: DMatrix<f64>,
}

impl StateSpace {
    /// A static gain `y = D u` (no states).
    #[must_use]
    pub fn gain(d: DMatrix<f64>) -> Self {
        let (o, i) = d.shape();
        Self { a: DMatrix::zeros(0, 0), b: DMatrix::zeros(0, i), c: DMatrix::zeros(o, 0), d }
    }

    #[must_use]
    pub fn states(&self) -> usize {
        self.a.nrows()
    }

    /// `G(s) = C (sI − A)⁻¹ B + D`; `None` where `sI − A` is singular (`s` an eigenvalue).
    #[must_use]
    pub fn response(&self, s: C64) -> Option<DMatrix<C64>> {
        let n = self.states();
        let mut g = self.d.map(C64::from);
        if n == 0 {
            return Some(g);
        }
        let m = DMatrix::from_fn(n, n, |i, j| if i == j { s - self.a[(i, j)] } else { C64::from(-self.a[(i, j)]) });
        let x = m.lu().solve(&self.b.map(C64::from))?;
        g += self.c.map(C64::from) * x;
        Some(g)
    }
}

/// Diagonal balancing `D⁻¹ A D` (powers of two; Parlett and Reinsch's iteration): returns the balanced
/// matrix and `D`'s diagonal.
#[must_use]
pub fn balance(a: &DMatrix<f64>) -> (DMatrix<f64>, Vec<f64>) {
    let n = a.nrows();
    let mut a = a.clone();
    let mut d = vec![1.0; n];
    for _ in 0..100 {
        let mut converged = true;
        for i in 0..n {
            let (mut c, mut r) = (0.0, 0.0);
            for j in 0..n {
                if j != i {
                    c += a[(j, i)].abs();
                    r += a[(i, j)].abs();
                }
            }
            if c == 0.0 || r == 0.0 {
                continue;
            }
            let s = c + r;
            let mut f = 1.0;
            let (mut c2, mut r2) = (c, r);
            while c2 < r2 / 2.0 {
                c2 *= 2.0;
                r2 /= 2.0;
                f *= 2.0;
            }
            while c2 >= r2 * 2.0 {
                c2 /= 2.0;
                r2 *= 2.0;
                f /= 2.0;
            }
            if c2 + r2 < 0.95 * s {
                converged = false;
                d[i] *= f;
                for j in 0..n {
                    a[(i, j)] /= f;
                    a[(j, i)] *= f;
                }
            }
        }
        if converged {
            break;
        }
    }
    (a, d)
}

/// Eigenvalues of the real matrix `a` (balanced first).
///
/// # Errors
/// [`ControlError::Eigen`] when the eigen-solver fails or returns a non-finite value.
pub fn eigenvalues(a: &DMatrix<f64>) -> Result<Vec<C64>, ControlError> {
    let n = a.nrows();
    if n == 0 {
        return Ok(Vec::new());
    }
    let (b, _) = balance(a);
    let fa = faer::Mat::<f64>::from_fn(n, n, |i, j| b[(i, j)]);
    let values = fa.eigenvalues().map_err(|_| ControlError::Eigen { size: n })?;
    let out: Vec<C64> = values.iter().map(|l| C64::new(l.re, l.im)).collect();
    if out.iter().any(|l| !l.re.is_finite() || !l.im.is_finite()) {
        return Err(ControlError::Eigen { size: n });
    }
    Ok(out)
}

/// Eigenvalues and right eigenvectors (columns) of the real matrix `a`, balanced for the solve and mapped
/// back.
///
/// # Errors
/// [`ControlError::Eigen`].
pub fn eigen(a: &DMatrix<f64>) -> Result<(Vec<C64>, DMatrix<C64>), ControlError> {
    let n = a.nrows();
    let (b, d) = balance(a);
    let fa = faer::Mat::<f64>::from_fn(n, n, |i, j| b[(i, j)]);
    let evd = fa.eigen().map_err(|_| ControlError::Eigen { size: n })?;
    let (s, u) = (evd.S(), evd.U());
    let values: Vec<C64> = (0..n).map(|k| C64::new(s.column_vector()[k].re, s.column_vector()[k].im)).collect();
    // A = D B D⁻¹: eigenvectors of A are D times those of B
    let vectors = DMatrix::from_fn(n, n, |i, k| C64::new(u[(i, k)].re, u[(i, k)].im) * d[i]);
    if values.iter().any(|l| !l.re.is_finite() || !l.im.is_finite()) {
        return Err(ControlError::Eigen { size: n });
    }
    Ok((values, vectors))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Balancing is a similarity: a badly scaled companion matrix of (s+1)(s+2)(s+3) with its states in
    /// units 1e6 apart keeps its eigenvalues −1, −2, −3 to 1e-12.
    #[test]
    fn balanced_eigenvalues_of_a_badly_scaled_matrix() {
        let t = DMatrix::from_diagonal(&nalgebra::DVector::from_vec(vec![1.0, 1e6, 1e-6]));
        let a0 = DMatrix::from_row_slice(3, 3, &[0.0, 1.0, 0.0, 0.0, 0.0, 1.0, -6.0, -11.0, -6.0]);
        let a = &t * a0 * t.try_inverse().unwrap();
        let mut l: Vec<f64> = eigenvalues(&a).unwrap().iter().map(|z| z.re).collect();
        l.sort_by(f64::total_cmp);
        for (got, want) in l.iter().zip([-3.0, -2.0, -1.0]) {
            assert!((got - want).abs() < 1e-12, "{got} vs {want}");
        }
    }
}
