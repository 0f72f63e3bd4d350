//! Sparse LDU factorisation without row exchanges, for non-symmetric matrices whose pattern is symmetric
//! (the mass-conserving film's mixed pressure/film-fraction system: `physics::reynolds::jfo`).
//!
//! ## Equation
//! With the fill-reducing symmetric permutation `P` of the symmetric pattern (approximate minimum degree,
//! the ordering a Cholesky factorisation of the same pattern would use):
//!
//! ```text
//! P M Pᵀ = L D U,   L unit lower, U unit upper, D diagonal,   struct(L) = struct(Uᵀ) = struct(Cholesky factor)
//! ```
//!
//! Without row exchanges the fill of `L` and `U` is that of a Cholesky factorisation of the pattern, so
//! the symbolic structure is built once per pattern and every numeric factorisation fills it (up-looking:
//! row `k` of `L` and column `k` of `U` are two sparse triangular solves over the entries of row `k` of the
//! factor, `d_k = m_kk − Σ_i L_ki d_i U_ik`). A general sparse LU (row pivoting) instead bounds its fill by
//! the structure of `MᵀM`, which for a film grid is several times denser.
//!
//! ## Contract
//! Stability without pivoting is not guaranteed for every matrix, so [`StaticLdu::factor`] refuses a pivot
//! smaller than [`MIN_PIVOT`] times the largest entry of its row and column of `M` ([`SolverError::Singular`],
//! naming the unknown), and the caller checks the residual of its solves and factorises with the pivoting
//! [`super::LuSolver`] when either fails. Symmetric positive definite blocks, column diagonally dominant
//! blocks and mixtures of the two (the film's pressure and film-fraction columns) factorise stably.

use faer::sparse::linalg::cholesky::{
    factorize_symbolic_cholesky, CholeskySymbolicParams, SymbolicCholeskyRaw, SymmetricOrdering,
};
use faer::sparse::linalg::SupernodalThreshold;
use faer::sparse::SymbolicSparseColMatRef;
use faer::Side;

use super::lu::GeneralPattern;
use super::sparse::SolverError;

/// Smallest pivot accepted, relative to the largest entry of its row and column of the matrix.
pub const MIN_PIVOT: f64 = 1e-10;

/// Symbolic structure (once per pattern) and numeric values of the factorisation.
#[derive(Debug, Clone)]
pub struct StaticLdu {
    n: usize,
    /// `perm[k]`: the unknown eliminated k-th; `inv[perm[k]] = k`.
    perm: Vec<usize>,
    /// Columns of the factor (permuted numbering), sorted rows, the diagonal first.
    l_ptr: Vec<usize>,
    l_row: Vec<usize>,
    /// Row k of the factor below the diagonal: (column i, position in column i), columns increasing.
    row_ptr: Vec<usize>,
    row_at: Vec<(usize, usize)>,
    /// Entries of the permuted matrix's column k above the diagonal and of its row k left of the diagonal:
    /// (permuted index, position in the value array of the general pattern).
    above_ptr: Vec<usize>,
    above: Vec<(usize, usize)>,
    left_ptr: Vec<usize>,
    left: Vec<(usize, usize)>,
    /// Position of the diagonal entry of the k-th eliminated unknown.
    diag_pos: Vec<usize>,
    /// `L_ri` and `U_ir` at the position of (r, i) in the factor's column i.
    lv: Vec<f64>,
    uv: Vec<f64>,
    d: Vec<f64>,
    x: Vec<f64>,
    z: Vec<f64>,
    factored: bool,
}

impl StaticLdu {
    /// Symbolic analysis of a structurally symmetric pattern.
    ///
    /// # Errors
    /// [`SolverError::Symbolic`] if the pattern is not symmetric or faer's analysis fails.
    pub fn new(pattern: &GeneralPattern) -> Result<Self, SolverError> {
        let n = pattern.n;
        // The lower triangle for the symbolic Cholesky analysis (simplicial: its column structure is read).
        let mut col_ptr = vec![0usize];
        let mut row_idx = Vec::new();
        for c in 0..n {
            for k in pattern.col_ptr[c]..pattern.col_ptr[c + 1] {
                let r = pattern.row_idx[k];
                if r >= c {
                    if pattern.position(c, r).is_none() {
                        return Err(SolverError::Symbolic(format!("pattern not symmetric at ({r}, {c})")));
                    }
                    row_idx.push(r);
                }
            }
            col_ptr.push(row_idx.len());
        }
        let lower = SymbolicSparseColMatRef::new_checked(n, n, &col_ptr, None, &row_idx);
        let params = CholeskySymbolicParams {
            supernodal_flop_ratio_threshold: SupernodalThreshold::FORCE_SIMPLICIAL,
            ..Default::default()
        };
        let symbolic = factorize_symbolic_cholesky(lower, Side::Lower, SymmetricOrdering::Amd, params)
            .map_err(|e| SolverError::Symbolic(format!("{e:?}")))?;
        let perm: Vec<usize> = match symbolic.perm() {
            Some(p) => p.arrays().0.to_vec(),
            None => (0..n).collect(),
        };
        let SymbolicCholeskyRaw::Simplicial(s) = symbolic.raw() else {
            return Err(SolverError::Symbolic("simplicial structure expected".into()));
        };
        let l_ptr = s.col_ptr().to_vec();
        let mut l_row = s.row_idx().to_vec();
        for c in 0..n {
            l_row[l_ptr[c]..l_ptr[c + 1]].sort_unstable();
            if l_row.get(l_ptr[c]) != Some(&c) {
                return Err(SolverError::Symbolic(format!("factor column {c} without its diagonal")));
            }
        }
        let mut inv = vec![0; n];
        for (k, &i) in perm.iter().enumerate() {
            inv[i] = k;
        }
        // Rows of the factor below the diagonal, by a counting pass over its columns.
        let mut row_ptr = vec![0usize; n + 1];
        for c in 0..n {
            for &r in &l_row[l_ptr[c] + 1..l_ptr[c + 1]] {
                row_ptr[r + 1] += 1;
            }
        }
        for r in 0..n {
            row_ptr[r + 1] += row_ptr[r];
        }
        let mut fill = row_ptr.clone();
        let mut row_at = vec![(0, 0); l_row.len() - n];
        for c in 0..n {
            for p in l_ptr[c] + 1..l_ptr[c + 1] {
                let r = l_row[p];
                row_at[fill[r]] = (c, p);
                fill[r] += 1;
            }
        }
        // The matrix entries of each permuted column above, and row left of, the diagonal.
        let (mut above_ptr, mut above, mut left_ptr, mut left) = (vec![0], Vec::new(), vec![0], Vec::new());
        let mut diag_pos = Vec::with_capacity(n);
        for k in 0..n {
            let c = perm[k];
            for q in pattern.col_ptr[c]..pattern.col_ptr[c + 1] {
                let j = inv[pattern.row_idx[q]];
                if j < k {
                    above.push((j, q));
                }
            }
            for &q in pattern.row_positions(c) {
                let col = pattern.col_ptr.partition_point(|&p| p <= q) - 1;
                let j = inv[col];
                if j < k {
                    left.push((j, q));
                }
            }
            above_ptr.push(above.len());
            left_ptr.push(left.len());
            diag_pos.push(pattern.diag[c]);
        }
        let nnz = l_row.len();
        Ok(Self {
            n,
            perm,
            l_ptr,
            l_row,
            row_ptr,
            row_at,
            above_ptr,
            above,
            left_ptr,
            left,
            diag_pos,
            lv: vec![0.0; nnz],
            uv: vec![0.0; nnz],
            d: vec![0.0; n],
            x: vec![0.0; n],
            z: vec![0.0; n],
            factored: false,
        })
    }

    /// Entries of the factors (`L` and `U` together, diagonal once).
    #[must_use]
    pub fn factor_entries(&self) -> usize {
        2 * self.l_row.len() - self.n
    }

    /// Numeric factorisation of the matrix with the given values (in the general pattern's storage).
    ///
    /// # Errors
    /// [`SolverError::Singular`] for a non-finite entry or a pivot below [`MIN_PIVOT`] (relative).
    pub fn factor(&mut self, values: &[f64]) -> Result<(), SolverError> {
        self.factored = false;
        for k in 0..self.n {
            let mut big = values[self.diag_pos[k]].abs();
            for &(j, q) in &self.above[self.above_ptr[k]..self.above_ptr[k + 1]] {
                self.x[j] = values[q];
                big = big.max(values[q].abs());
            }
            for &(j, q) in &self.left[self.left_ptr[k]..self.left_ptr[k + 1]] {
                self.z[j] = values[q];
                big = big.max(values[q].abs());
            }
            let mut dk = values[self.diag_pos[k]];
            // Row k of L and column k of U: forward substitution with L (for D U_:k) and with Uᵀ (for
            // D L_k:ᵀ), column by column in elimination order.
            for &(i, pik) in &self.row_at[self.row_ptr[k]..self.row_ptr[k + 1]] {
                let (yi, zi) = (self.x[i], self.z[i]);
                self.x[i] = 0.0;
                self.z[i] = 0.0;
                let lki = zi / self.d[i];
                self.lv[pik] = lki;
                self.uv[pik] = yi / self.d[i];
                dk -= lki * yi;
                // A zero entry of both triangular solves changes nothing below it (the mixed matrix's
                // upwinded film-fraction columns hold many).
                if yi == 0.0 && zi == 0.0 {
                    continue;
                }
                let below = self.l_ptr[i] + 1..pik;
                let (x, z) = (&mut self.x, &mut self.z);
                for ((&r, &l), &u) in self.l_row[below.clone()].iter().zip(&self.lv[below.clone()]).zip(&self.uv[below])
                {
                    x[r] -= l * yi;
                    z[r] -= u * zi;
                }
            }
            if !dk.is_finite() || dk.abs() <= MIN_PIVOT * big {
                for v in self.x.iter_mut().chain(self.z.iter_mut()) {
                    *v = 0.0;
                }
                return Err(SolverError::Singular(format!(
                    "pivot {dk:.3e} of unknown {} against entries up to {big:.3e} (no row exchanges)",
                    self.perm[k]
                )));
            }
            self.d[k] = dk;
        }
        self.factored = true;
        Ok(())
    }

    /// Solves `M X = B` in place for the right-hand sides stored column-major in `rhs` (n × k).
    ///
    /// # Errors
    /// [`SolverError::Singular`] before a successful factorisation or when the solution is not finite.
    pub fn solve_in_place(&mut self, rhs: &mut [f64], n: usize) -> Result<(), SolverError> {
        if !self.factored || n != self.n {
            return Err(SolverError::Singular("solve before a successful factorisation".into()));
        }
        let grouped = rhs.len() / (LANES * n) * (LANES * n);
        let (head, tail) = rhs.split_at_mut(grouped);
        for block in head.chunks_mut(LANES * n) {
            self.solve_block(block);
        }
        for col in tail.chunks_mut(n) {
            self.solve_one(col);
        }
        if let Some(i) = rhs.iter().position(|v| !v.is_finite()) {
            return Err(SolverError::Singular(format!("non-finite solution at unknown {}", i % n)));
        }
        Ok(())
    }
}

/// Right-hand sides solved together (interleaved, each factor entry read once per group).
const LANES: usize = 4;

impl StaticLdu {
    /// One right-hand side.
    fn solve_one(&mut self, col: &mut [f64]) {
        let n = self.n;
        let y = &mut self.x;
        for (k, &i) in self.perm.iter().enumerate() {
            y[k] = col[i];
        }
        // L y = P b.
        for c in 0..n {
            let yc = y[c];
            if yc != 0.0 {
                let below = self.l_ptr[c] + 1..self.l_ptr[c + 1];
                for (&r, &l) in self.l_row[below.clone()].iter().zip(&self.lv[below]) {
                    y[r] -= l * yc;
                }
            }
        }
        // D, then U x = y from the last unknown up (row c of U is column c of the factor).
        for c in (0..n).rev() {
            let mut s = y[c] / self.d[c];
            let below = self.l_ptr[c] + 1..self.l_ptr[c + 1];
            for (&r, &u) in self.l_row[below.clone()].iter().zip(&self.uv[below]) {
                s -= u * y[r];
            }
            y[c] = s;
        }
        for (k, &i) in self.perm.iter().enumerate() {
            col[i] = y[k];
            y[k] = 0.0;
        }
    }

    /// [`LANES`] right-hand sides (column-major, n each), interleaved in a work array.
    fn solve_block(&mut self, block: &mut [f64]) {
        let n = self.n;
        let mut w = vec![[0.0_f64; LANES]; n];
        for (k, &i) in self.perm.iter().enumerate() {
            for (j, v) in w[k].iter_mut().enumerate() {
                *v = block[j * n + i];
            }
        }
        for c in 0..n {
            let yc = w[c];
            let below = self.l_ptr[c] + 1..self.l_ptr[c + 1];
            for (&row, &l) in self.l_row[below.clone()].iter().zip(&self.lv[below]) {
                let r = &mut w[row];
                for j in 0..LANES {
                    r[j] -= l * yc[j];
                }
            }
        }
        for c in (0..n).rev() {
            let d = self.d[c];
            let mut s = w[c].map(|v| v / d);
            let below = self.l_ptr[c] + 1..self.l_ptr[c + 1];
            for (&row, &u) in self.l_row[below.clone()].iter().zip(&self.uv[below]) {
                let r = &w[row];
                for j in 0..LANES {
                    s[j] -= u * r[j];
                }
            }
            w[c] = s;
        }
        for (k, &i) in self.perm.iter().enumerate() {
            for (j, v) in w[k].iter().enumerate() {
                block[j * n + i] = *v;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fem::LuSolver;

    /// A grid of `nx × ny` nodes and bilinear "elements", with values: a Laplacian-like block on the
    /// `pressure` nodes' columns and a one-sided transport on the others (the film's mixed system).
    fn grid(nx: usize, ny: usize) -> (GeneralPattern, Vec<[usize; 4]>) {
        let node = |i: usize, j: usize| i * ny + j;
        let elems: Vec<[usize; 4]> = (0..nx - 1)
            .flat_map(|i| (0..ny - 1).map(move |j| [node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)]))
            .collect();
        (GeneralPattern::from_groups(nx * ny, elems.iter().map(|e| &e[..])), elems)
    }

    #[allow(clippy::cast_precision_loss)]
    fn mixed_values(p: &GeneralPattern, ny: usize) -> Vec<f64> {
        let mut v = vec![0.0; p.nnz()];
        for c in 0..p.n {
            // Columns 3..6 of the grid "cavitated": transport from upstream (lower grid column index).
            let transport = (3..6).contains(&(c / ny));
            for k in p.col_ptr[c]..p.col_ptr[c + 1] {
                let r = p.row_idx[k];
                v[k] = if transport {
                    if r == c {
                        2.0 + 0.1 * (c % 5) as f64
                    } else if r / ny == c / ny + 1 {
                        -0.6
                    } else {
                        0.0
                    }
                } else if r == c {
                    8.0 + (c % 3) as f64
                } else {
                    -1.0 + 0.05 * ((r + 2 * c) % 7) as f64
                };
            }
        }
        v
    }

    /// The static-pivot LDU solves the mixed system as faer's pivoting LU does, to round-off, and its
    /// factors hold fewer entries than the pivoting LU's structure allows.
    #[test]
    fn solves_a_mixed_system_as_the_pivoting_lu() {
        let (nx, ny) = (12, 7);
        let (p, _) = grid(nx, ny);
        let v = mixed_values(&p, ny);
        let mut ldu = StaticLdu::new(&p).unwrap();
        ldu.factor(&v).unwrap();
        #[allow(clippy::cast_precision_loss)]
        let x: Vec<f64> = (0..p.n).map(|i| (i as f64 * 0.37).sin() + 0.5).collect();
        let mut b = vec![0.0; p.n];
        p.matvec(&v, &x, &mut b);
        // Five right-hand sides: a group of four solved together and one alone.
        let mut two = [b.clone(), b.clone(), b.clone(), b.clone(), b.clone()].concat();
        ldu.solve_in_place(&mut two, p.n).unwrap();
        for c in 1..5 {
            assert_eq!(two[..p.n], two[c * p.n..(c + 1) * p.n], "column {c}");
        }
        let mut lu = LuSolver::new(&p).unwrap();
        lu.factor(&p, &v).unwrap();
        let mut y = b.clone();
        lu.solve_in_place(&mut y, p.n).unwrap();
        for i in 0..p.n {
            assert!((two[i] - x[i]).abs() < 1e-13, "node {i}: {} vs {}", two[i], x[i]);
            assert!((two[p.n + i] - y[i]).abs() < 1e-13, "node {i}: {} vs LU {}", two[p.n + i], y[i]);
        }
    }

    /// A zero pivot (a node decoupled with a zero diagonal) is refused, naming the unknown.
    #[test]
    fn refuses_a_zero_pivot() {
        let (p, _) = grid(4, 3);
        let mut v = mixed_values(&p, 3);
        for &k in p.row_positions(5) {
            v[k] = 0.0;
        }
        for k in p.col_ptr[5]..p.col_ptr[6] {
            v[k] = 0.0;
        }
        let mut ldu = StaticLdu::new(&p).unwrap();
        let r = ldu.factor(&v);
        assert!(matches!(&r, Err(SolverError::Singular(m)) if m.contains("unknown 5")), "{r:?}");
        let mut rhs = vec![1.0; p.n];
        assert!(ldu.solve_in_place(&mut rhs, p.n).is_err());
    }
}
