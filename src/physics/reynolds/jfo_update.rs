//! Low-rank updates of the mass-conserving film's factorisation between active-set steps (`jfo.rs`).
//!
//! ## Equation
//! A step of the active set moves a few nodes between the pressurised and the cavitated set; in the mixed
//! matrix only their columns change (a pressure column `A e_j` becomes a film-fraction column
//! `T̃ e_j / scale`, or back). With the factorised matrix `M₀`, the `k` changed columns `J` and
//! `U = (M − M₀) E_J` (`E_J` the unit columns of `J`):
//!
//! ```text
//! M = M₀ + U E_Jᵀ,   M⁻¹ b = y − W (I + E_Jᵀ W)⁻¹ E_Jᵀ y,   y = M₀⁻¹ b,   W = M₀⁻¹ U   (Sherman–Morrison–Woodbury)
//! ```
//!
//! `W` costs `k` back-substitutions with the existing factorisation and the `k × k` capacitance matrix a
//! dense LU, against a full sparse LU per step otherwise. Contract: the caller fills the new values into `m`
//! and asks [`JfoState::update_or_factor`]; it refactors (and makes `m` the new base) on the first step of a
//! solve, when more than [`MAX_UPDATE_COLUMNS`] columns differ from the base, or when the capacitance matrix
//! is near singular. [`JfoState::solve_mixed`] then solves with `M` either way, and so does the
//! linearisation's back-substitution after convergence.
//!
//! Measured and rejected: keeping the factorisation across solves (a new thickness) as the approximate
//! inverse of an iterative refinement to round-off (componentwise backward error 4ε). It cut the compressor
//! bearing's factorisations from 117 to 83 at standard with identical results (15 digits), but each film
//! solve and each linearisation column then needed 5–10 back-substitutions, which cost more than the LU
//! they saved: process CPU 0.14 s against 0.10 s at standard, 1.15 s against 1.0 s at reference (where the
//! refinement mostly failed to contract and refactorised: 145 factorisations).

use nalgebra::{DMatrix, DVector};

use crate::fem::LuSolver;
use crate::physics::reynolds::jfo::{JfoState, ThetaRule, Update};
use crate::physics::reynolds::FilmError;

/// Most changed columns handled by an update before a refactorisation (each costs one back-substitution).
pub(super) const MAX_UPDATE_COLUMNS: usize = 12;

/// Largest accepted residual of a solve after a factorisation without row exchanges, relative to the
/// size of the products it sums (a stable factorisation reaches ~1e-15).
const RESIDUAL_TOL: f64 = 1e-10;

/// Smallest pivot of the capacitance matrix, relative to its largest entry, accepted for an update.
const MIN_PIVOT: f64 = 1e-8;

impl JfoState {
    /// Makes the solver represent the mixed matrix in `m` for the cavitated set `cav`: by a low-rank update
    /// of the base factorisation when allowed (`refactor` false) and few columns changed, else by a new
    /// factorisation. Returns whether it factorised.
    pub(super) fn update_or_factor(&mut self, cav: &[bool], refactor: bool) -> Result<bool, FilmError> {
        if !refactor {
            let changed: Vec<usize> = (0..self.pattern.n)
                .filter(|&j| self.rule[j] == ThetaRule::Free && cav[j] != self.base_cav[j])
                .collect();
            if changed.is_empty() {
                self.update = None;
                return Ok(false);
            }
            if changed.len() <= MAX_UPDATE_COLUMNS {
                if let Some(u) = self.low_rank(changed)? {
                    self.update = Some(u);
                    return Ok(false);
                }
            }
        }
        self.factor_base(cav, false)?;
        Ok(true)
    }

    /// Factorises `m` as the new base: without row exchanges (`fem::ldu`) unless `pivoted` or the static
    /// factorisation refuses a pivot, then with the pivoting LU (counted in `fallbacks`).
    fn factor_base(&mut self, cav: &[bool], pivoted: bool) -> Result<(), FilmError> {
        self.update = None;
        self.base_pivoted = pivoted || self.pivot_always || self.ldu.factor(&self.m).is_err();
        if self.base_pivoted {
            self.fallbacks += 1;
            if self.lu.is_none() {
                self.lu = Some(LuSolver::new_supernodal(&self.pattern)?);
            }
            let Some(lu) = self.lu.as_mut() else { unreachable!("built above") };
            lu.factor(&self.pattern, &self.m)?;
        }
        self.m_base.copy_from_slice(&self.m);
        self.base_cav.copy_from_slice(cav);
        Ok(())
    }

    /// Solves with the base factorisation (either kind).
    fn base_solve(&mut self, rhs: &mut [f64], n: usize) -> Result<(), FilmError> {
        match (&mut self.lu, self.base_pivoted) {
            (Some(lu), true) => lu.solve_in_place(rhs, n)?,
            _ => self.ldu.solve_in_place(rhs, n)?,
        }
        Ok(())
    }

    /// Solves `M x = b` in place (`rhs` holds b, one column) and checks the residual: when
    /// `max |M x − b| > RESIDUAL_TOL · max (|M| |x| + |b|)` after a factorisation without row exchanges, the
    /// matrix is factorised again with the pivoting LU (counted) and solved again. Returns whether it
    /// factorised.
    pub(super) fn solve_checked(&mut self, rhs: &mut [f64], cav: &[bool]) -> Result<bool, FilmError> {
        let b = rhs.to_vec();
        self.solve_mixed(rhs)?;
        if self.base_pivoted || self.residual(&b, rhs) <= RESIDUAL_TOL {
            return Ok(false);
        }
        self.factor_base(cav, true)?;
        rhs.copy_from_slice(&b);
        self.solve_mixed(rhs)?;
        Ok(true)
    }

    /// `max |M x − b| / max (|M| |x| + |b|)` for the matrix in `m`.
    fn residual(&self, b: &[f64], x: &[f64]) -> f64 {
        let p = &self.pattern;
        let mut r: Vec<f64> = b.iter().map(|v| -v).collect();
        let mut size: Vec<f64> = b.iter().map(|v| v.abs()).collect();
        for c in 0..p.n {
            for k in p.col_ptr[c]..p.col_ptr[c + 1] {
                let v = self.m[k] * x[c];
                r[p.row_idx[k]] += v;
                size[p.row_idx[k]] += v.abs();
            }
        }
        let worst = r.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        let scale = size.iter().fold(0.0_f64, |m, &v| m.max(v));
        if worst.is_finite() && scale > 0.0 {
            worst / scale
        } else if worst == 0.0 {
            0.0
        } else {
            f64::INFINITY
        }
    }

    /// `W` and the capacitance LU for the changed columns, or `None` when the capacitance matrix is near
    /// singular (the caller refactors).
    fn low_rank(&mut self, nodes: Vec<usize>) -> Result<Option<Update>, FilmError> {
        let n = self.pattern.n;
        let k = nodes.len();
        let mut w = vec![0.0; n * k];
        for (c, &j) in nodes.iter().enumerate() {
            for p in self.pattern.col_ptr[j]..self.pattern.col_ptr[j + 1] {
                w[c * n + self.pattern.row_idx[p]] = self.m[p] - self.m_base[p];
            }
        }
        self.base_solve(&mut w, n)?;
        let cap = DMatrix::from_fn(k, k, |r, c| f64::from(u8::from(r == c)) + w[c * n + nodes[r]]);
        let big = cap.amax();
        let capacitance = cap.lu();
        let u = capacitance.u();
        let small = (0..k).map(|i| u[(i, i)].abs()).fold(f64::INFINITY, f64::min);
        // A NaN pivot fails the test too.
        if small.is_nan() || small <= MIN_PIVOT * big {
            return Ok(None);
        }
        Ok(Some(Update { nodes, w, capacitance }))
    }

    /// Solves `M x = b` in place for every column of `rhs` (length n each) with the base factorisation and
    /// the current update.
    pub(super) fn solve_mixed(&mut self, rhs: &mut [f64]) -> Result<(), FilmError> {
        let n = self.pattern.n;
        self.base_solve(rhs, n)?;
        if let Some(u) = &self.update {
            for col in rhs.chunks_mut(n) {
                let b = DVector::from_iterator(u.nodes.len(), u.nodes.iter().map(|&j| col[j]));
                let z = u.capacitance.solve(&b).ok_or_else(|| FilmError::Input("singular active-set update".into()))?;
                for (c, zc) in z.iter().enumerate() {
                    for (x, wv) in col.iter_mut().zip(&u.w[c * n..(c + 1) * n]) {
                        *x -= wv * zc;
                    }
                }
            }
        }
        Ok(())
    }
}

#[cfg(test)]
impl crate::physics::reynolds::PadFilm {
    /// Makes every mass-conserving factorisation of this film use the pivoting LU (tests compare the two, and
    /// count the pivoted factorisations up to the bearing's report).
    pub(crate) fn always_pivot(&mut self) {
        let state = self.jfo.get_or_insert_with(|| Box::new(JfoState::new(&self.geom).expect("film state")));
        state.pivot_always = true;
    }
}
