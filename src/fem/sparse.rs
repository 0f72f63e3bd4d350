//! Sparse symmetric assembly and Cholesky factorisation (faer), with lifetimes split as the solver needs:
//!
//! - [`Pattern`] (once per mesh): the lower-triangular CSC pattern of a 4-node-element mesh and, for every
//!   element, where each of its 16 entries lands in the value array.
//! - [`SpdSolver`] (once per mesh): the symbolic Cholesky factorisation (fill-reducing ordering, elimination
//!   tree) plus the numeric buffers; each Newton or active-set step only refactors numerically.
//!
//! Rows and columns can be "fixed" (Dirichlet or cavitated nodes): they are replaced by identity rows in the
//! factorised copy, so the pattern and the symbolic factorisation never change.

use faer::dyn_stack::{MemBuffer, MemStack};
use faer::perm::PermRef;
use faer::sparse::linalg::cholesky::{factorize_symbolic_cholesky, LltRef, SymbolicCholesky, SymmetricOrdering};
use faer::sparse::{SparseColMatRef, SymbolicSparseColMatRef};
use faer::{Conj, MatMut, Par, Side};
use serde::{Deserialize, Serialize};
use thiserror::Error;

/// Failure of the linear algebra.
#[derive(Debug, Clone, PartialEq, Eq, Error, Serialize, Deserialize)]
pub enum SolverError {
    #[error("matrix is not positive definite (film thickness or viscosity not positive?)")]
    NotPositiveDefinite,
    #[error("symbolic factorisation failed: {0}")]
    Symbolic(String),
    /// The LU factorisation found no usable pivot (singular or non-finite matrix).
    #[error("matrix is singular: {0}")]
    Singular(String),
}

/// Lower-triangular CSC pattern with an element scatter map.
#[derive(Debug, Clone)]
pub struct Pattern {
    pub n: usize,
    pub col_ptr: Vec<usize>,
    pub row_idx: Vec<usize>,
    /// Position in the value array of entry (a, b) of element e, `usize::MAX` for the upper triangle
    /// (which is not stored): `scatter[e][4 a + b]`.
    pub scatter: Vec<[usize; 16]>,
    /// Position of each diagonal entry.
    pub diag: Vec<usize>,
    /// Elimination order of the unknowns for the Cholesky factorisation (`order[k]`: the unknown eliminated
    /// k-th), when the caller knows a better one than faer's approximate minimum degree (`None`).
    pub ordering: Option<Vec<usize>>,
}

impl Pattern {
    /// Builds the pattern of `n` nodes connected by 4-node elements.
    #[must_use]
    pub fn from_elements(n: usize, elements: &[[usize; 4]]) -> Self {
        let (mut pattern, flat) = Self::from_groups(n, elements.iter().map(|e| &e[..]));
        pattern.scatter = flat.chunks_exact(16).map(|c| std::array::from_fn(|k| c[k])).collect();
        pattern
    }

    /// Builds the pattern of `n` nodes connected by groups of any size (every pair within a group couples),
    /// and the value position of entry (a, b) of each group, row-major, `usize::MAX` above the diagonal;
    /// the groups' blocks follow one another (group g starts after the `len²` entries of the ones before).
    /// The returned pattern's `scatter` is empty.
    #[must_use]
    pub fn from_groups<'a>(n: usize, groups: impl IntoIterator<Item = &'a [usize]> + Clone) -> (Self, Vec<usize>) {
        let c = CscGroups::build(n, groups, |row, col| row >= col);
        (
            Self { n, col_ptr: c.col_ptr, row_idx: c.row_idx, scatter: Vec::new(), diag: c.diag, ordering: None },
            c.scatter,
        )
    }

    #[must_use]
    pub fn nnz(&self) -> usize {
        self.row_idx.len()
    }

    fn symbolic(&self) -> SymbolicSparseColMatRef<'_, usize> {
        SymbolicSparseColMatRef::new_checked(self.n, self.n, &self.col_ptr, None, &self.row_idx)
    }

    /// y = A x for the symmetric matrix whose lower triangle is `values`.
    pub fn sym_matvec(&self, values: &[f64], x: &[f64], y: &mut [f64]) {
        y.fill(0.0);
        for c in 0..self.n {
            for k in self.col_ptr[c]..self.col_ptr[c + 1] {
                let r = self.row_idx[k];
                let v = values[k];
                y[r] += v * x[c];
                if r != c {
                    y[c] += v * x[r];
                }
            }
        }
    }

    /// Y = A X for a block of `p` vectors stored interleaved (row-major: entry (i, j) at `i p + j`), in one
    /// pass over the pattern — the eigen-solver's block products, several times faster than `p` single
    /// products because each matrix entry is read once.
    pub fn sym_matmat_interleaved(&self, values: &[f64], p: usize, x: &[f64], y: &mut [f64]) {
        y.fill(0.0);
        for c in 0..self.n {
            let xc = c * p;
            for k in self.col_ptr[c]..self.col_ptr[c + 1] {
                let r = self.row_idx[k];
                let v = values[k];
                let xr = r * p;
                for (yv, xv) in y[xr..xr + p].iter_mut().zip(&x[xc..xc + p]) {
                    *yv += v * xv;
                }
                if r != c {
                    for (yv, xv) in y[xc..xc + p].iter_mut().zip(&x[xr..xr + p]) {
                        *yv += v * xv;
                    }
                }
            }
        }
    }

    /// Copies `values` into `out`, replacing fixed rows/columns by identity rows.
    pub fn fix_rows(&self, values: &[f64], fixed: &[bool], out: &mut [f64]) {
        for c in 0..self.n {
            for k in self.col_ptr[c]..self.col_ptr[c + 1] {
                let r = self.row_idx[k];
                out[k] = if fixed[r] || fixed[c] {
                    if r == c {
                        1.0
                    } else {
                        0.0
                    }
                } else {
                    values[k]
                };
            }
        }
    }
}

/// A CSC structure built from node groups: the entries (row, col) of every pair within a group for which
/// `keep(row, col)` holds, plus the whole diagonal; with each group's value positions (row-major,
/// `usize::MAX` where `keep` is false) and the diagonal positions. Shared by the symmetric (lower triangle)
/// and the general (full) patterns.
pub(crate) struct CscGroups {
    pub col_ptr: Vec<usize>,
    pub row_idx: Vec<usize>,
    pub scatter: Vec<usize>,
    pub diag: Vec<usize>,
}

impl CscGroups {
    pub(crate) fn build<'a>(
        n: usize,
        groups: impl IntoIterator<Item = &'a [usize]> + Clone,
        keep: impl Fn(usize, usize) -> bool,
    ) -> Self {
        // The groups flattened, and the groups of each unknown (incidence), so that each column gathers its rows
        // once, with a marker against repeats, instead of collecting every pair and sorting the repeats away.
        let mut g_ptr = vec![0];
        let mut g_items: Vec<usize> = Vec::new();
        for g in groups {
            g_items.extend_from_slice(g);
            g_ptr.push(g_items.len());
        }
        let n_groups = g_ptr.len() - 1;
        let mut inc_ptr = vec![0usize; n + 1];
        for &a in &g_items {
            inc_ptr[a + 1] += 1;
        }
        for i in 0..n {
            inc_ptr[i + 1] += inc_ptr[i];
        }
        let mut next = inc_ptr.clone();
        let mut inc = vec![0usize; g_items.len()];
        for g in 0..n_groups {
            for &a in &g_items[g_ptr[g]..g_ptr[g + 1]] {
                inc[next[a]] = g;
                next[a] += 1;
            }
        }
        let mut mark = vec![usize::MAX; n];
        let mut col_ptr = Vec::with_capacity(n + 1);
        let mut row_idx = Vec::new();
        col_ptr.push(0);
        for b in 0..n {
            let first = row_idx.len();
            mark[b] = b;
            row_idx.push(b);
            for &g in &inc[inc_ptr[b]..inc_ptr[b + 1]] {
                for &a in &g_items[g_ptr[g]..g_ptr[g + 1]] {
                    if mark[a] != b && keep(a, b) {
                        mark[a] = b;
                        row_idx.push(a);
                    }
                }
            }
            row_idx[first..].sort_unstable();
            col_ptr.push(row_idx.len());
        }
        // Each group's block, row-major: the position of each row of column b from a dense map of that column.
        let mut pos = vec![usize::MAX; n];
        let mut scatter = Vec::with_capacity(g_ptr.iter().zip(&g_ptr[1..]).map(|(a, b)| (b - a) * (b - a)).sum());
        for g in 0..n_groups {
            let items = &g_items[g_ptr[g]..g_ptr[g + 1]];
            let (len, offset) = (items.len(), scatter.len());
            scatter.resize(offset + len * len, usize::MAX);
            for (ib, &b) in items.iter().enumerate() {
                for k in col_ptr[b]..col_ptr[b + 1] {
                    pos[row_idx[k]] = k;
                }
                for (ia, &a) in items.iter().enumerate() {
                    if keep(a, b) {
                        scatter[offset + ia * len + ib] = pos[a];
                    }
                }
            }
        }
        let diag = (0..n)
            .map(|i| {
                col_ptr[i]
                    + row_idx[col_ptr[i]..col_ptr[i + 1]]
                        .binary_search(&i)
                        .unwrap_or_else(|_| unreachable!("diagonal in pattern"))
            })
            .collect();
        Self { col_ptr, row_idx, scatter, diag }
    }
}

/// Unknowns above which the supernodal Cholesky is used. Measured on the pad meshes (release, 2 cores):
/// simplicial is faster up to ~1000 nodes per pad (preview, standard: 9 vs 12 ms, 38 vs 44 ms for the
/// compressor bearing), supernodal from ~4600 (reference: 259 vs 307 ms); faer's own flop-ratio rule picks
/// simplicial for all of them.
const SUPERNODAL_FROM: usize = 2500;

fn supernodal_threshold(n: usize) -> faer::sparse::linalg::SupernodalThreshold {
    if n >= SUPERNODAL_FROM {
        faer::sparse::linalg::SupernodalThreshold::FORCE_SUPERNODAL
    } else {
        faer::sparse::linalg::SupernodalThreshold::FORCE_SIMPLICIAL
    }
}

/// Cholesky solver: symbolic factorisation once, numeric refactorisation into reused buffers.
pub struct SpdSolver {
    symbolic: std::sync::Arc<SymbolicCholesky<usize>>,
    l_values: Vec<f64>,
    work: MemBuffer,
    factored: bool,
}

impl std::fmt::Debug for SpdSolver {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("SpdSolver").field("n", &self.symbolic.nrows()).field("factored", &self.factored).finish()
    }
}

impl Clone for SpdSolver {
    fn clone(&self) -> Self {
        let work = MemBuffer::new(Self::scratch(&self.symbolic));
        Self { symbolic: self.symbolic.clone(), l_values: self.l_values.clone(), work, factored: self.factored }
    }
}

impl SpdSolver {
    fn scratch(symbolic: &SymbolicCholesky<usize>) -> faer::dyn_stack::StackReq {
        symbolic
            .factorize_numeric_llt_scratch::<f64>(Par::Seq, Default::default())
            .or(symbolic.solve_in_place_scratch::<f64>(8, Par::Seq))
    }

    /// Symbolic analysis of the pattern (fill-reducing ordering, elimination tree).
    ///
    /// # Errors
    /// If faer's symbolic factorisation fails (out of memory).
    pub fn new(pattern: &Pattern) -> Result<Self, SolverError> {
        let params = faer::sparse::linalg::cholesky::CholeskySymbolicParams {
            supernodal_flop_ratio_threshold: supernodal_threshold(pattern.n),
            ..Default::default()
        };
        // A given ordering that is not a permutation of the unknowns falls back to AMD.
        let inverse: Option<Vec<usize>> =
            pattern.ordering.as_ref().filter(|o| o.len() == pattern.n).and_then(|order| {
                let mut inv = vec![usize::MAX; order.len()];
                for (k, &i) in order.iter().enumerate() {
                    if *inv.get(i)? != usize::MAX {
                        return None;
                    }
                    inv[i] = k;
                }
                Some(inv)
            });
        let ordering = match (&pattern.ordering, &inverse) {
            (Some(order), Some(inv)) => SymmetricOrdering::Custom(PermRef::new_checked(order, inv, pattern.n)),
            _ => SymmetricOrdering::Amd,
        };
        let symbolic = factorize_symbolic_cholesky(pattern.symbolic(), Side::Lower, ordering, params)
            .map_err(|e| SolverError::Symbolic(format!("{e:?}")))?;
        let l_values = vec![0.0; symbolic.len_val()];
        let work = MemBuffer::new(Self::scratch(&symbolic));
        Ok(Self { symbolic: std::sync::Arc::new(symbolic), l_values, work, factored: false })
    }

    /// Numeric factorisation of the matrix with the given lower-triangle values.
    ///
    /// # Errors
    /// [`SolverError::NotPositiveDefinite`] when a pivot is not positive.
    pub fn factor(&mut self, pattern: &Pattern, values: &[f64]) -> Result<(), SolverError> {
        let mat = SparseColMatRef::new(pattern.symbolic(), values);
        self.factored = false;
        self.symbolic
            .factorize_numeric_llt(
                &mut self.l_values,
                mat,
                Side::Lower,
                Default::default(),
                Par::Seq,
                MemStack::new(&mut self.work),
                Default::default(),
            )
            .map_err(|_| SolverError::NotPositiveDefinite)?;
        self.factored = true;
        Ok(())
    }

    /// Solves A x = b in place for one right-hand side.
    pub fn solve_in_place(&mut self, rhs: &mut [f64]) {
        debug_assert!(self.factored, "solve before factor");
        let n = rhs.len();
        let llt = LltRef::new(&self.symbolic, &self.l_values);
        llt.solve_in_place_with_conj(
            Conj::No,
            MatMut::from_column_major_slice_mut(rhs, n, 1),
            Par::Seq,
            MemStack::new(&mut self.work),
        );
    }

    /// Solves for the right-hand sides stored column-major in `rhs` (n × k), eight at a time (the work
    /// space holds eight).
    pub fn solve_many_in_place(&mut self, rhs: &mut [f64], n: usize) {
        debug_assert!(self.factored, "solve before factor");
        for chunk in rhs.chunks_mut(8 * n) {
            let kk = chunk.len() / n;
            let llt = LltRef::new(&self.symbolic, &self.l_values);
            llt.solve_in_place_with_conj(
                Conj::No,
                MatMut::from_column_major_slice_mut(chunk, n, kk),
                Par::Seq,
                MemStack::new(&mut self.work),
            );
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The pattern and scatter map from every pair of every group, sorted and deduplicated, each entry found
    /// by search: the straightforward construction [`CscGroups::build`] must reproduce.
    fn build_by_pairs(
        n: usize,
        groups: &[Vec<usize>],
        keep: impl Fn(usize, usize) -> bool,
    ) -> (Vec<usize>, Vec<usize>, Vec<usize>, Vec<usize>) {
        let mut cols: Vec<Vec<usize>> = (0..n).map(|i| vec![i]).collect();
        for g in groups {
            for &a in g {
                for &b in g {
                    if keep(a, b) {
                        cols[b].push(a);
                    }
                }
            }
        }
        let (mut col_ptr, mut row_idx) = (vec![0], Vec::new());
        for c in &mut cols {
            c.sort_unstable();
            c.dedup();
            row_idx.extend_from_slice(c);
            col_ptr.push(row_idx.len());
        }
        let find = |r: usize, c: usize| col_ptr[c] + row_idx[col_ptr[c]..col_ptr[c + 1]].binary_search(&r).unwrap();
        let scatter = groups
            .iter()
            .flat_map(|g| g.iter().flat_map(|&a| g.iter().map(move |&b| (a, b))))
            .map(|(a, b)| if keep(a, b) { find(a, b) } else { usize::MAX })
            .collect();
        let diag = (0..n).map(|i| find(i, i)).collect();
        (col_ptr, row_idx, scatter, diag)
    }

    /// Irregular groups (sizes 1 to 7, shared and repeated unknowns, an unknown in no group) give the same
    /// pattern, scatter map and diagonal as the pair-by-pair construction, lower triangle and full.
    #[test]
    fn group_pattern_matches_the_pair_by_pair_construction() {
        let n = 40;
        let mut seed = 12345_u64;
        let mut next = || {
            seed = seed.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
            usize::try_from(seed >> 33).unwrap()
        };
        let mut groups: Vec<Vec<usize>> =
            (0..60).map(|_| (0..1 + next() % 7).map(|_| next() % (n - 1)).collect()).collect();
        groups.push(vec![3, 3, 5]);
        for lower in [true, false] {
            let keep = move |r: usize, c: usize| !lower || r >= c;
            let c = CscGroups::build(n, groups.iter().map(Vec::as_slice), keep);
            let (col_ptr, row_idx, scatter, diag) = build_by_pairs(n, &groups, keep);
            assert_eq!(c.col_ptr, col_ptr, "lower {lower}");
            assert_eq!(c.row_idx, row_idx, "lower {lower}");
            assert_eq!(c.scatter, scatter, "lower {lower}");
            assert_eq!(c.diag, diag, "lower {lower}");
        }
    }

    /// 1-D chain of "elements" (degenerate quads) gives the classic tridiagonal Laplacian.
    #[test]
    fn solves_laplacian_and_fixes_rows() {
        // Grid of 3×3 nodes, 2×2 elements.
        let node = |i: usize, j: usize| i * 3 + j;
        let elems: Vec<[usize; 4]> = (0..2)
            .flat_map(|i| (0..2).map(move |j| [node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)]))
            .collect();
        let p = Pattern::from_elements(9, &elems);
        // Diagonally dominant SPD matrix: 4 on the diagonal, −0.5 off-diagonal.
        let mut vals = vec![0.0; p.nnz()];
        for c in 0..9 {
            for k in p.col_ptr[c]..p.col_ptr[c + 1] {
                vals[k] = if p.row_idx[k] == c { 4.0 } else { -0.5 };
            }
        }
        let x_true: Vec<f64> = (0..9).map(|i| (i as f64).sin()).collect();
        let mut b = vec![0.0; 9];
        p.sym_matvec(&vals, &x_true, &mut b);
        let mut s = SpdSolver::new(&p).unwrap();
        s.factor(&p, &vals).unwrap();
        s.solve_in_place(&mut b);
        for i in 0..9 {
            assert!((b[i] - x_true[i]).abs() < 1e-12);
        }
        // Fixing node 4 decouples it.
        let mut fixed = vec![false; 9];
        fixed[4] = true;
        let mut work = vec![0.0; p.nnz()];
        p.fix_rows(&vals, &fixed, &mut work);
        s.factor(&p, &work).unwrap();
        let mut rhs = vec![1.0; 9];
        rhs[4] = 7.0;
        s.solve_in_place(&mut rhs);
        assert!((rhs[4] - 7.0).abs() < 1e-14);
    }

    /// The interleaved block product is the column-by-column product, entry by entry.
    #[test]
    fn block_product_equals_single_products() {
        let node = |i: usize, j: usize| i * 4 + j;
        let elems: Vec<[usize; 4]> = (0..3)
            .flat_map(|i| (0..3).map(move |j| [node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)]))
            .collect();
        let p = Pattern::from_elements(16, &elems);
        #[allow(clippy::cast_precision_loss)]
        let vals: Vec<f64> = (0..p.nnz()).map(|k| 1.0 + (k % 7) as f64 - 0.3 * (k % 3) as f64).collect();
        let cols = 3;
        #[allow(clippy::cast_precision_loss)]
        let x: Vec<f64> = (0..16 * cols).map(|k| ((k * 37) % 11) as f64 - 5.0).collect();
        let mut y = vec![0.0; 16 * cols];
        p.sym_matmat_interleaved(&vals, cols, &x, &mut y);
        for c in 0..cols {
            let xc: Vec<f64> = (0..16).map(|i| x[i * cols + c]).collect();
            let mut yc = vec![0.0; 16];
            p.sym_matvec(&vals, &xc, &mut yc);
            for i in 0..16 {
                assert_eq!(y[i * cols + c], yc[i], "row {i}, column {c}");
            }
        }
    }

    #[test]
    fn reports_indefinite_matrix() {
        let p = Pattern::from_elements(4, &[[0, 1, 2, 3]]);
        let vals = vec![-1.0; p.nnz()];
        let mut s = SpdSolver::new(&p).unwrap();
        assert_eq!(s.factor(&p, &vals), Err(SolverError::NotPositiveDefinite));
    }
}
