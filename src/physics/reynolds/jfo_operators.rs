//! Operators of the mass-conserving film (docs/MODEL.md §2.3), assembled per thickness into the full
//! (non-symmetric) storage of `jfo.rs`:
//!
//! ```text
//!   T_ij = −∫ 6 U w N_j ∂N_i/∂s        Couette flow of the oil (w the thickness h, or a shape φ_k for a derivative)
//!   T̃    = T + D,  D_ij = −max(0, T_ij, T_ji) (i ≠ j), D_ii = −Σ_{j≠i} D_ij      (discrete upwinding)
//!   S_ij = ∫ 12 w N_i N_j               squeeze of the oil (w a velocity-like field)
//! ```
//!
//! and the inlet film fraction of a starved pad, `θ_in = min(1, Q / Q_cap)` with `Q_cap = Σ_{inlet rows} (T̃ 1)/12`
//! the Couette inflow of a full inlet. The caller provides the sampled fields at the quadrature points; the
//! operators are added into the caller's storage (not cleared).

use crate::physics::reynolds::jfo::{JfoState, ThetaRule};
use crate::physics::reynolds::{FilmGeometry, Inlet};

/// Sampled thickness-like field for the Couette operator: the film thickness or a shape `φ_k`.
pub(super) type QpField<'a> = &'a [[f64; 4]];

impl JfoState {
    /// Adds the Couette operator `−∫ 6 U w N_j ∂N_i/∂s` of the field `w` (the thickness, or a shape for a
    /// derivative) into `out` (full storage, not cleared).
    pub(super) fn add_couette(&self, geom: &FilmGeometry, u: f64, w: QpField<'_>, out: &mut [f64]) {
        for (e, _) in geom.elements.iter().enumerate() {
            let pos = self.pattern.group_positions(e);
            for (k, q) in geom.qp[e].iter().enumerate() {
                let c = q.w * 6.0 * u * w[e][k];
                for a in 0..4 {
                    for b in 0..4 {
                        out[pos[4 * a + b]] -= c * q.n[b] * q.dn_ds[a];
                    }
                }
            }
        }
    }

    /// Applies the discrete upwinding to a Couette operator in `t` (module documentation): with `record`
    /// the branch of every pair is chosen from `t` and stored; otherwise the stored branches are applied
    /// (the derivative of the limited operator, for a perturbation of the thickness).
    pub(super) fn limit(&mut self, t: &mut [f64], record: bool) {
        let p = &self.pattern;
        for c in 0..p.n {
            for k in p.col_ptr[c]..p.col_ptr[c + 1] {
                let r = p.row_idx[k];
                if r <= c {
                    continue;
                }
                let kt = self.transpose[k];
                let (own, tr) = (t[k], t[kt]);
                if record {
                    self.branch[k] = if own >= tr && own > 0.0 {
                        1
                    } else if tr > own && tr > 0.0 {
                        2
                    } else {
                        0
                    };
                }
                let d = match self.branch[k] {
                    1 => own,
                    2 => tr,
                    _ => 0.0,
                };
                if d != 0.0 {
                    t[k] -= d;
                    t[kt] -= d;
                    t[p.diag[r]] += d;
                    t[p.diag[c]] += d;
                }
            }
        }
    }

    /// Adds the squeeze operator `∫ 12 w N_i N_j` of a velocity-like field `w` into `out`.
    pub(super) fn add_squeeze(&self, geom: &FilmGeometry, w: QpField<'_>, out: &mut [f64]) {
        for (e, _) in geom.elements.iter().enumerate() {
            let pos = self.pattern.group_positions(e);
            for (k, q) in geom.qp[e].iter().enumerate() {
                let c = 12.0 * q.w * w[e][k];
                for a in 0..4 {
                    for b in 0..4 {
                        out[pos[4 * a + b]] += c * q.n[a] * q.n[b];
                    }
                }
            }
        }
    }

    /// Sets the inlet film fraction from the inlet condition and the current operator (`capacity12`: the
    /// full inlet's Couette inflow, times 12, modelled domain).
    pub(super) fn set_inlet(&mut self, inlet: Inlet, sym: f64) {
        let n = self.pattern.n;
        let mut cap = 0.0;
        for j in (0..n).filter(|&j| self.rule[j] == ThetaRule::Inlet) {
            cap += self.pattern.row_positions(j).iter().map(|&k| self.t[k]).sum::<f64>();
        }
        self.capacity12 = cap;
        (self.theta_in, self.supply) = match inlet {
            Inlet::Flooded => (1.0, None),
            Inlet::Supply { flow_m3_s } => {
                let q_cap = sym * cap / 12.0;
                (if q_cap > 0.0 { (flow_m3_s / q_cap).min(1.0) } else { 1.0 }, Some(flow_m3_s))
            }
        };
    }

    /// Couette inflow of a full inlet at the last solve, whole pad [m³/s] (`sym` the symmetry factor).
    pub(super) fn inlet_capacity(&self, sym: f64) -> f64 {
        sym * self.capacity12 / 12.0
    }
}
