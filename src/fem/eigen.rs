//! Lowest eigenpairs of a sparse symmetric pencil `K v = λ M v` by shift-inverted subspace iteration.
//!
//! ## Method (Bathe's subspace iteration with a shift σ < λ₁)
//! ```text
//! A = K − σ M   (positive definite: K ⪰ 0, M ≻ 0, σ < 0), factorised once by sparse Cholesky
//! repeat:  Z = A⁻¹ M X                               (p block vectors, p = max(2m, 8))
//!          K̂ = Zᵀ K Z,  M̂ = Zᵀ M Z                  (projection; K Z = M X + σ M Z needs no product with K)
//!          K̂ Q = M̂ Q Λ,  Qᵀ M̂ Q = I                  (dense p × p problem)
//!          X = Z Q
//! until the m wanted Ritz pairs have residuals ‖K v − λ M v‖∞ < tol · max_j ‖K v_j‖∞, or the Ritz values
//! stand still (change < 10⁻¹¹ of the largest wanted value) while the residuals stop falling (the round-off floor, about
//! 10⁻⁹ for pad meshes whose stiffness spans six decades)
//! ```
//! Each vector's error shrinks per iteration by about `(λ_i − σ)/(λ_{p+1} − σ)`. Zero eigenvalues (free rigid
//! motions, such as a pad's tilt about a frictionless pivot) are allowed: σ is negative.
//! Matrices share one lower-triangular [`Pattern`]; eigenvectors come back M-orthonormal, eigenvalues
//! ascending, with the residual `‖K v − λ M v‖∞` of each pair relative to the largest `‖K v‖∞` of the block.

use nalgebra::DMatrix;

use super::{Pattern, SolverError, SpdSolver};

/// Smallest block: the Cholesky work space solves eight columns in one pass over the factor, so up to four
/// wanted pairs cost one pass per iteration (a pad's tilt and first bending mode: 9 iterations with 8
/// vectors or with 10, which took two passes and 30 % longer).
const BLOCK: usize = 8;

/// Settings of the iteration.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EigenParams {
    /// Relative residual of the wanted Ritz pairs that ends the iteration.
    pub tol: f64,
    pub max_iterations: usize,
}

impl Default for EigenParams {
    fn default() -> Self {
        Self { tol: 1e-10, max_iterations: 300 }
    }
}

/// The lowest eigenpairs and how they were found.
#[derive(Debug, Clone, PartialEq)]
pub struct EigenPairs {
    /// λ ascending.
    pub values: Vec<f64>,
    /// n × m, M-orthonormal columns.
    pub vectors: DMatrix<f64>,
    pub iterations: usize,
    /// Relative residual of each pair.
    pub residuals: Vec<f64>,
    /// Whether the residuals met `tol` (else `max_iterations` ended the iteration).
    pub converged: bool,
}

/// Failure of the eigen-solution.
#[derive(Debug, Clone, PartialEq, thiserror::Error, serde::Serialize, serde::Deserialize)]
pub enum EigenError {
    #[error("shifted matrix K − σM (σ = {shift:e}) is not positive definite: {source}")]
    Factor { shift: f64, source: SolverError },
    #[error("the subspace lost M-orthogonality at iteration {iteration} (projected mass not positive definite)")]
    Projection { iteration: usize },
    #[error("asked for {wanted} eigenpairs of a {n}-unknown problem")]
    TooMany { wanted: usize, n: usize },
}

/// `Y = A X` for every column of `x`, in one pass over the pattern ([`Pattern::sym_matmat_interleaved`]).
fn matvec_block(pattern: &Pattern, values: &[f64], x: &DMatrix<f64>) -> DMatrix<f64> {
    let (n, p) = (x.nrows(), x.ncols());
    let xt: Vec<f64> = x.transpose().as_slice().to_vec();
    let mut yt = vec![0.0; n * p];
    pattern.sym_matmat_interleaved(values, p, &xt, &mut yt);
    DMatrix::from_row_slice(n, p, &yt)
}

/// Deterministic start block: one column per unknown-pattern (smooth plus a few hashed entries), so runs
/// are reproducible.
fn start_block(n: usize, p: usize) -> DMatrix<f64> {
    let mut state: u64 = 0x9E37_79B9_7F4A_7C15;
    DMatrix::from_fn(n, p, |_, _| {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        // Top 53 bits to a float in [−0.5, 0.5).
        #[allow(clippy::cast_precision_loss)]
        let u = (state >> 11) as f64 / (1u64 << 53) as f64;
        u - 0.5
    })
}

/// Generalised symmetric eigenproblem of the projected p × p pencil: Λ ascending and Q with Qᵀ M̂ Q = I.
fn projected(k: &DMatrix<f64>, m: &DMatrix<f64>) -> Option<(Vec<f64>, DMatrix<f64>)> {
    let sym = |a: &DMatrix<f64>| (a + a.transpose()) * 0.5;
    let chol = sym(m).cholesky()?;
    let l = chol.l();
    let l_inv = l.clone().try_inverse()?;
    let c = sym(&(&l_inv * sym(k) * l_inv.transpose()));
    let eig = c.symmetric_eigen();
    let mut order: Vec<usize> = (0..eig.eigenvalues.len()).collect();
    order.sort_by(|&a, &b| eig.eigenvalues[a].total_cmp(&eig.eigenvalues[b]));
    let values = order.iter().map(|&i| eig.eigenvalues[i]).collect();
    let v = DMatrix::from_fn(k.nrows(), order.len(), |r, j| eig.eigenvectors[(r, order[j])]);
    Some((values, l_inv.transpose() * v))
}

/// The `m` lowest eigenpairs of `K v = λ M v` (K, M: lower triangles of `pattern`), with shift `shift` < λ₁.
///
/// # Errors
/// [`EigenError::Factor`] if `K − σM` is not positive definite (shift above λ₁, or M singular),
/// [`EigenError::Projection`] on a degenerate subspace, [`EigenError::TooMany`] if `m` exceeds the size.
pub fn lowest(
    pattern: &Pattern,
    k: &[f64],
    m: &[f64],
    wanted: usize,
    shift: f64,
    params: EigenParams,
) -> Result<EigenPairs, EigenError> {
    let n = pattern.n;
    if wanted == 0 || wanted > n {
        return Err(EigenError::TooMany { wanted, n });
    }
    let p = (2 * wanted).max(BLOCK).min(n);
    let a: Vec<f64> = k.iter().zip(m).map(|(kv, mv)| kv - shift * mv).collect();
    let mut solver = SpdSolver::new(pattern).map_err(|source| EigenError::Factor { shift, source })?;
    solver.factor(pattern, &a).map_err(|source| EigenError::Factor { shift, source })?;
    let mut x = start_block(n, p);
    let mut values = Vec::new();
    let mut residuals = vec![f64::INFINITY; wanted];
    let mut converged = false;
    let mut iterations = 0;
    let mut previous = vec![f64::INFINITY; wanted];
    let mut history: Vec<f64> = Vec::new();
    // M X: one block product for the start; afterwards X = Z Q gives M X = (M Z) Q from the products at hand.
    let mut mx_block = matvec_block(pattern, m, &x);
    while iterations < params.max_iterations {
        iterations += 1;
        let mut z = mx_block.clone();
        solver.solve_many_in_place(z.as_mut_slice(), n);
        let mz = matvec_block(pattern, m, &z);
        // K Z = (K − σM) Z + σ M Z = M X + σ M Z: no product with K (Bathe's projection). It omits the solve's
        // round-off, which the true residuals after the loop include.
        let kz = mx_block + &mz * shift;
        let (lambda, q) = projected(&(z.transpose() * &kz), &(z.transpose() * &mz))
            .ok_or(EigenError::Projection { iteration: iterations })?;
        x = &z * &q;
        mx_block = &mz * &q;
        values = lambda;
        // Residuals of the Ritz pairs from the products already at hand: K X = (K Z) Q, M X = (M Z) Q.
        let qw = q.columns(0, wanted);
        let (kx, mx) = (&kz * qw, &mz * qw);
        // Scaled by the largest |K v| of the block, so that a zero eigenvalue (K v ≈ 0) is measured fairly.
        let scale = kx.amax().max(f64::MIN_POSITIVE);
        for (i, r) in residuals.iter_mut().enumerate() {
            *r = (kx.column(i) - mx.column(i) * values[i]).amax() / scale;
        }
        // Relative to the largest wanted value, so that zero eigenvalues (noise of order ε‖K‖) do not count.
        let top = values[wanted - 1].abs() + shift.abs();
        let change = (0..wanted).map(|i| (values[i] - previous[i]).abs() / top).fold(0.0, f64::max);
        previous.copy_from_slice(&values[..wanted]);
        let worst = residuals.iter().copied().fold(0.0, f64::max);
        history.push(worst);
        // Round-off floor: the Ritz values no longer move and the residuals stopped falling.
        let stalled = change < 1e-11 && history.len() > 4 && worst > 0.5 * history[history.len() - 5];
        if worst < params.tol || stalled {
            converged = true;
            break;
        }
    }
    let vectors = x.columns(0, wanted).into_owned();
    values.truncate(wanted);
    // The reported residuals are the true ones, from products with K and M.
    let (kx, mx) = (matvec_block(pattern, k, &vectors), matvec_block(pattern, m, &vectors));
    let scale = kx.amax().max(f64::MIN_POSITIVE);
    for (i, r) in residuals.iter_mut().enumerate() {
        *r = (kx.column(i) - mx.column(i) * values[i]).amax() / scale;
    }
    Ok(EigenPairs { values, vectors, iterations, residuals, converged })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Fixed–fixed spring–mass chain: λ_j = (2k/m)(1 − cos(jπ/(n+1))), exactly.
    #[test]
    fn spring_chain_eigenvalues_are_exact() {
        let n = 60;
        let springs: Vec<[usize; 2]> = (0..n - 1).map(|i| [i, i + 1]).collect();
        let (pattern, scatter) = Pattern::from_groups(n, springs.iter().map(|s| &s[..]));
        let (ks, ms) = (3.0e6, 0.2);
        let mut k = vec![0.0; pattern.nnz()];
        let mut m = vec![0.0; pattern.nnz()];
        for (s, pos) in scatter.chunks_exact(4).enumerate() {
            let _ = s;
            for (ab, &p) in pos.iter().enumerate() {
                if p != usize::MAX {
                    k[p] += if ab == 0 || ab == 3 { ks } else { -ks };
                }
            }
        }
        // Ends tied to ground: one extra spring at each end.
        k[pattern.diag[0]] += ks;
        k[pattern.diag[n - 1]] += ks;
        for i in 0..n {
            m[pattern.diag[i]] = ms;
        }
        let pairs = lowest(&pattern, &k, &m, 4, -1.0, EigenParams::default()).unwrap();
        assert!(pairs.converged);
        for (j, &lam) in pairs.values.iter().enumerate() {
            #[allow(clippy::cast_precision_loss)]
            let exact = 2.0 * ks / ms * (1.0 - ((j + 1) as f64 * std::f64::consts::PI / (n + 1) as f64).cos());
            assert!((lam - exact).abs() < 1e-10 * exact, "{j}: {lam} vs {exact}");
        }
        assert!(pairs.residuals.iter().all(|&r| r < 1e-8), "{:?}", pairs.residuals);
        // M-orthonormal.
        let mv = matvec_block(&pattern, &m, &pairs.vectors);
        let g = pairs.vectors.transpose() * mv;
        assert!((g - DMatrix::identity(4, 4)).amax() < 1e-10);
    }
}
