//! Linearisation of the mass-conserving film about a converged solve, for fixed sets (docs/MODEL.md §2.3).
//!
//! For fixed pressurised and cavitated sets the mixed system `M x = rhs(q)` is linear in the unknowns
//! (`p` on the pressurised nodes, `θ` on the cavitated ones):
//!
//! ```text
//! ∂x/∂q_k = M⁻¹ (−∂r/∂q_k),   ∂r/∂q_k = (∂A/∂q_k) p + (∂T̃/∂q_k) θ (+ T̃ ∂θ_in/∂q_k at a starved inlet)
//! squeeze right-hand side of a velocity q̇_k:  −S[φ_k] θ      (the oil content follows the motion)
//! ```
//!
//! The caller (`linearize.rs`) adds `−(∂A/∂q_k) p`, back-substitutes with the converged factorisation and
//! takes the pressure part (zero on cavitated nodes): exact for a fixed cavitation boundary, like the
//! Reynolds option's perturbations (Lund's method).

use crate::physics::reynolds::jfo::{JfoState, ThetaRule};
use crate::physics::reynolds::jfo_operators::QpField;
use crate::physics::reynolds::{FilmError, FilmGeometry};

impl JfoState {
    /// Solves `M x = rhs` for every column of `rhs` (length n each) with the last factorisation and returns
    /// the pressure part (the cavitated and boundary nodes' entries set to zero).
    pub(super) fn back_substitute(&mut self, rhs: &mut [f64], cav: &[bool]) -> Result<(), FilmError> {
        let n = self.pattern.n;
        for col in rhs.chunks_mut(n) {
            for i in 0..n {
                if self.rule[i] != ThetaRule::Free {
                    col[i] = 0.0;
                }
            }
        }
        self.solve_mixed(rhs)?;
        for col in rhs.chunks_mut(n) {
            for i in 0..n {
                if self.rule[i] != ThetaRule::Free || cav[i] {
                    col[i] = 0.0;
                }
            }
        }
        Ok(())
    }

    /// `−∂r/∂q` for a thickness shape `phi` (sampled at the quadrature points) about the state `(p, θ)`,
    /// without the Poiseuille part (the caller adds `−(∂A/∂q) p`): `−(∂T̃/∂q) θ − T̃ ∂θ_in/∂q`.
    pub(super) fn couette_derivative(
        &mut self,
        geom: &FilmGeometry,
        u: f64,
        phi: QpField<'_>,
        theta: &[f64],
    ) -> Vec<f64> {
        let n = self.pattern.n;
        let mut dt = vec![0.0; self.pattern.nnz()];
        self.add_couette(geom, u, phi, &mut dt);
        self.limit(&mut dt, false);
        let mut out = vec![0.0; n];
        self.pattern.matvec(&dt, theta, &mut out);
        // A starved inlet: θ_in = Q / Q_cap(h) moves with the thickness.
        if self.supply.is_some() && self.theta_in < 1.0 && self.capacity12 > 0.0 {
            let mut dcap = 0.0;
            for j in (0..n).filter(|&j| self.rule[j] == ThetaRule::Inlet) {
                dcap += self.pattern.row_positions(j).iter().map(|&k| dt[k]).sum::<f64>();
            }
            let dtheta_in = -self.theta_in * dcap / self.capacity12;
            let mut unit = vec![0.0; n];
            for j in 0..n {
                unit[j] = if self.rule[j] == ThetaRule::Inlet { dtheta_in } else { 0.0 };
            }
            let mut add = vec![0.0; n];
            self.pattern.matvec(&self.t, &unit, &mut add);
            for (o, a) in out.iter_mut().zip(&add) {
                *o += a;
            }
        }
        for v in &mut out {
            *v = -*v;
        }
        out
    }

    /// `−S[φ] θ`: the squeeze right-hand side of a unit velocity of a coordinate with shape `phi`.
    pub(super) fn squeeze_rhs(&self, geom: &FilmGeometry, phi: QpField<'_>, theta: &[f64]) -> Vec<f64> {
        let mut s = vec![0.0; self.pattern.nnz()];
        self.add_squeeze(geom, phi, &mut s);
        let mut out = vec![0.0; self.pattern.n];
        self.pattern.matvec(&s, theta, &mut out);
        for v in &mut out {
            *v = -*v;
        }
        out
    }
}

impl JfoState {
    /// The Couette and squeeze right-hand sides of every shape at once, without assembling a matrix per
    /// shape: `rhs` holds `n` values per column, `−(∂T̃/∂q_k) θ` in column `k` and, with `with_damping`,
    /// `−S[φ_k] θ` in column `m + k` (added to what is there). The same values as [`Self::couette_derivative`]
    /// and [`Self::squeeze_rhs`] to round-off:
    ///
    /// ```text
    /// (T[φ] θ)_a = −Σ_qp w 6 U φ θ_qp ∂N_a/∂s,   (S[φ] θ)_a = Σ_qp w 12 φ θ_qp N_a,   θ_qp = Σ_b N_b θ_b
    /// (D[φ] θ)_r = Σ_c d_rc (θ_r − θ_c)   over the upwinded pairs, d_rc the limited entry of T[φ]
    /// ```
    ///
    /// The upwinding term vanishes where `θ_r = θ_c`, so it is summed only over the pairs whose film fractions
    /// differ (on the elements whose film fraction is not uniform: the ruptured zone and its edge), and of each
    /// such pair only the limited entry the recorded branch picks is assembled. A starved inlet, whose film
    /// fraction moves with the thickness, takes the assembled path.
    pub(super) fn perturbation_rhs(
        &mut self,
        geom: &FilmGeometry,
        u: f64,
        theta: &[f64],
        with_damping: bool,
        rhs: &mut [f64],
    ) {
        let n = self.pattern.n;
        let m = geom.shapes.len();
        if self.supply.is_some() && self.theta_in < 1.0 {
            for (s, shape) in geom.shapes.iter().enumerate() {
                let dc = self.couette_derivative(geom, u, &shape.qp, theta);
                rhs[s * n..(s + 1) * n].copy_from_slice(&dc);
                if with_damping {
                    let ds = self.squeeze_rhs(geom, &shape.qp, theta);
                    rhs[(m + s) * n..(m + s + 1) * n].copy_from_slice(&ds);
                }
            }
            return;
        }
        // The unlimited Couette and the squeeze terms, element by element.
        let mut mixed = Vec::new();
        for (e, nodes) in geom.elements.iter().enumerate() {
            let th = nodes.map(|i| theta[i]);
            if th.iter().any(|&t| t != th[0]) {
                mixed.push(e);
            }
            for (k, q) in geom.qp[e].iter().enumerate() {
                let tq: f64 = (0..4).map(|b| q.n[b] * th[b]).sum();
                let c = q.w * 6.0 * u * tq;
                let d = -12.0 * q.w * tq;
                for (s, shape) in geom.shapes.iter().enumerate() {
                    let phi = shape.qp[e][k];
                    for a in 0..4 {
                        rhs[s * n + nodes[a]] += c * phi * q.dn_ds[a];
                        if with_damping {
                            rhs[(m + s) * n + nodes[a]] += d * phi * q.n[a];
                        }
                    }
                }
            }
        }
        if mixed.is_empty() {
            return;
        }
        // The upwinding of the Couette derivative on the elements with a non-uniform film fraction: only the
        // limited entry of each upwinded pair whose film fractions differ is needed (`d = dt_k` or its
        // transpose's, by the recorded branch), summed over the elements that hold the pair.
        let (pairs, entries) = self.upwinded_pairs(geom, &mixed, theta);
        if pairs.is_empty() {
            return;
        }
        let mut dt = std::mem::take(&mut self.scratch);
        dt.resize(self.pattern.nnz(), 0.0);
        for (s, shape) in geom.shapes.iter().enumerate() {
            for &(e, a, b, pos) in &entries {
                for (k, q) in geom.qp[e].iter().enumerate() {
                    let c = q.w * 6.0 * u * shape.qp[e][k];
                    dt[pos] -= c * q.n[b] * q.dn_ds[a];
                }
            }
            let col = &mut rhs[s * n..(s + 1) * n];
            for &(r, c, pos) in &pairs {
                let jump = dt[pos] * (theta[r] - theta[c]);
                col[r] -= jump;
                col[c] += jump;
            }
            for &(_, _, _, pos) in &entries {
                dt[pos] = 0.0;
            }
        }
        self.scratch = dt;
    }

    /// The upwinded pairs `(r, c, position of the limited entry)` (r > c) of the elements `mixed` whose film
    /// fractions differ, in the order the elements meet them, and the element entries `(element, a, b,
    /// position)` that sum into those limited entries, element by element (so each limited entry is summed in
    /// the order of a full assembly of the operator).
    #[allow(clippy::type_complexity)]
    fn upwinded_pairs(
        &self,
        geom: &FilmGeometry,
        mixed: &[usize],
        theta: &[f64],
    ) -> (Vec<(usize, usize, usize)>, Vec<(usize, usize, usize, usize)>) {
        let (mut pairs, mut entries) = (Vec::new(), Vec::new());
        let mut listed = vec![false; self.pattern.nnz()];
        for &e in mixed {
            let nodes = geom.elements[e];
            let pos = self.pattern.group_positions(e);
            for a in 0..4 {
                for b in 0..4 {
                    let (r, c, k) = (nodes[a], nodes[b], pos[4 * a + b]);
                    if r <= c || theta[r] == theta[c] {
                        continue;
                    }
                    // The limited entry: (r, c) itself or its transpose, element entry (b, a).
                    let (limited, ea, eb) = match self.branch[k] {
                        1 => (k, a, b),
                        2 => (self.transpose[k], b, a),
                        _ => continue,
                    };
                    if !listed[limited] {
                        listed[limited] = true;
                        pairs.push((r, c, limited));
                    }
                    entries.push((e, ea, eb, limited));
                }
            }
        }
        (pairs, entries)
    }
}
