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
