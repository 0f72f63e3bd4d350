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
//! dense LU, against a full sparse LU per step otherwise.
//!
//! ## Reuse across solves: iterative refinement
//! The next solve of the pad (the next equilibrium iterate, a perturbed pad) changes the film thickness,
//! so every column changes a little. Its first step keeps the old factorisation as `M₀` (with the low-rank
//! correction for the nodes that changed set) and solves `M x = b` by iterative refinement:
//!
//! ```text
//! x₀ = M̃⁻¹ b,   x_{k+1} = x_k + M̃⁻¹ (b − M x_k)      (M̃ = M₀ + U E_Jᵀ, the corrected old factorisation)
//! ```
//!
//! which contracts by `‖I − M̃⁻¹ M‖ ≈ 3 ‖Δh‖/h` per step: a few back-substitutions near an equilibrium,
//! against a sparse LU. It stops at round-off, measured row by row (the rows of the film and of the
//! boundary differ by ten orders of magnitude): the componentwise backward error
//! `ω = maxᵢ |b − M x|ᵢ / (|M| |x| + |b|)ᵢ ≤ 4 ε` (that of the direct solve), or an `ω` that stops falling
//! below [`ROUND_OFF`]. A step that contracts slower
//! than [`MIN_CONTRACTION`], or [`MAX_REFINEMENT_STEPS`] steps, refactorise `M` and solve directly. So
//! every solve with `M` — the film solve and the linearisation's back-substitutions — is the solution of
//! the current matrix to round-off, whichever factorisation it used.
//!
//! Contract: the caller fills the new values into `m` and asks [`JfoState::update_or_factor`]; it refactors
//! (and makes `m` the new base) when no factorisation exists, when more than [`MAX_UPDATE_COLUMNS`] columns
//! differ from the base, or when the capacitance matrix is near singular. [`JfoState::solve_mixed`] then
//! solves with `M` either way, and so does the linearisation's back-substitution after convergence.

use nalgebra::{DMatrix, DVector};

use crate::physics::reynolds::jfo::{JfoState, ThetaRule};
use crate::physics::reynolds::FilmError;

/// Most changed columns handled by an update before a refactorisation (each costs one back-substitution).
pub(super) const MAX_UPDATE_COLUMNS: usize = 12;

/// Smallest pivot of the capacitance matrix, relative to its largest entry, accepted for an update.
const MIN_PIVOT: f64 = 1e-8;

/// Most refinement steps with an old factorisation before a refactorisation.
const MAX_REFINEMENT_STEPS: usize = 10;

/// Largest residual ratio of two refinement steps accepted (slower: refactorise, a direct solve is cheaper).
const MIN_CONTRACTION: f64 = 0.2;

/// Componentwise backward error below which a refinement that stops falling has reached round-off.
const ROUND_OFF: f64 = 1e-14;

/// Work of the mixed solver: back-substitutions with the factorisation (each right-hand side counts
/// one) and factorisations forced by a refinement that did not contract.
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct Work {
    pub back_substitutions: usize,
    pub refactorizations: usize,
}

/// The correction of the base factorisation: changed columns, `W = M₀⁻¹ U` (column-major, n × k) and the
/// LU of the capacitance matrix `I + E_Jᵀ W`.
#[derive(Debug, Clone)]
pub(super) struct Update {
    nodes: Vec<usize>,
    w: Vec<f64>,
    capacitance: nalgebra::LU<f64, nalgebra::Dyn, nalgebra::Dyn>,
}

impl JfoState {
    /// Makes the solver represent the mixed matrix in `m` for the cavitated set `cav`. `new_values`: `m`
    /// was refilled for a new thickness (the first step of a solve), so the base factorisation, if any, is
    /// kept as the refinement's approximate inverse. Otherwise (a later active-set step) only the columns of
    /// the nodes that changed set differ from the last step. A low-rank update of the base factorisation
    /// when few columns changed set, else a new factorisation. Returns whether it factorised.
    pub(super) fn update_or_factor(&mut self, cav: &[bool], new_values: bool) -> Result<bool, FilmError> {
        if new_values && self.factorised {
            self.stale = true;
        }
        if self.factorised {
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
        self.factor_current(cav)?;
        Ok(true)
    }

    /// A new factorisation of `m` (the new base, exact for the current thickness).
    fn factor_current(&mut self, cav: &[bool]) -> Result<(), FilmError> {
        self.factorised = false;
        self.lu.factor(&self.pattern, &self.m)?;
        self.m_base.copy_from_slice(&self.m);
        self.base_cav.copy_from_slice(cav);
        self.update = None;
        self.stale = false;
        self.factorised = true;
        Ok(())
    }

    /// The componentwise backward error of `x` for `M x = b`: `maxᵢ |r|ᵢ / (|M| |x| + |b|)ᵢ`, with the
    /// residual `r = b − M x` left in `r`.
    fn backward_error(&self, x: &[f64], b: &[f64], r: &mut [f64], scale: &mut [f64]) -> f64 {
        let p = &self.pattern;
        r.copy_from_slice(b);
        for (s, bi) in scale.iter_mut().zip(b) {
            *s = bi.abs();
        }
        for c in 0..p.n {
            for k in p.col_ptr[c]..p.col_ptr[c + 1] {
                let row = p.row_idx[k];
                r[row] -= self.m[k] * x[c];
                scale[row] += (self.m[k] * x[c]).abs();
            }
        }
        r.iter().zip(scale.iter()).fold(0.0, |w, (ri, si)| if *ri == 0.0 { w } else { w.max(ri.abs() / si) })
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
        self.lu.solve_in_place(&mut w, n)?;
        self.work.back_substitutions += k;
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

    /// Solves `M x = b` in place for every column of `rhs` (length n each): with the base factorisation
    /// and the current update, refined against the current `m` when the base belongs to another thickness
    /// (module documentation); a refinement that does not contract refactorises and solves directly.
    pub(super) fn solve_mixed(&mut self, rhs: &mut [f64]) -> Result<(), FilmError> {
        if !self.stale {
            return self.apply_inverse(rhs);
        }
        let n = self.pattern.n;
        let b = rhs.to_vec();
        self.apply_inverse(rhs)?;
        let (mut r, mut scale) = (vec![0.0; n], vec![0.0; n]);
        for (x, bc) in rhs.chunks_mut(n).zip(b.chunks(n)) {
            if !self.refine(x, bc, &mut r, &mut scale)? {
                // The old factorisation is too far from the current matrix: factorise it and solve directly.
                let cav = self.m_cav.clone();
                self.factor_current(&cav)?;
                self.work.refactorizations += 1;
                rhs.copy_from_slice(&b);
                return self.apply_inverse(rhs);
            }
        }
        Ok(())
    }

    /// Iterative refinement of one column `x` of `M x = b` (module documentation); `false` when it does not
    /// contract fast enough.
    fn refine(&mut self, x: &mut [f64], b: &[f64], r: &mut [f64], scale: &mut [f64]) -> Result<bool, FilmError> {
        let mut last = f64::INFINITY;
        for step in 0..=MAX_REFINEMENT_STEPS {
            let res = self.backward_error(x, b, r, scale);
            if !res.is_finite() {
                return Ok(false);
            }
            if res <= 4.0 * f64::EPSILON || (res > 0.5 * last && res <= ROUND_OFF) {
                return Ok(true);
            }
            if step == MAX_REFINEMENT_STEPS || res > MIN_CONTRACTION * last {
                return Ok(false);
            }
            last = res;
            self.apply_inverse(r)?;
            for (xi, di) in x.iter_mut().zip(r.iter()) {
                *xi += di;
            }
        }
        Ok(false)
    }

    /// `M̃⁻¹ rhs` for every column: the base factorisation's solve and the low-rank correction.
    fn apply_inverse(&mut self, rhs: &mut [f64]) -> Result<(), FilmError> {
        let n = self.pattern.n;
        self.lu.solve_in_place(rhs, n)?;
        self.work.back_substitutions += rhs.len() / n.max(1);
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
