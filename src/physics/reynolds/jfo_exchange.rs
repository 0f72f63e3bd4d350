//! The oil the discrete upwinding of the mass-conserving film moves between neighbouring nodes
//! (docs/MODEL.md §2.3 and §3.1), for the energy equation.
//!
//! ## Why
//! The mass-conserving residual is `r_i = (A p)_i + (T θ)_i + (D θ)_i − f_i = 0` at every free node
//! (`jfo.rs`). Its Galerkin part `A p + T θ − f` is, divided by −12, the nodal flow `o_i = ∫ q·∇N_i + ∫ v N_i`
//! of the flux field `q = −h³/(12µ) ∇p + U θ h/2` that the energy equation carries heat with; so that flux
//! field alone is not conservative at the nodes where θ varies (`o_i = (D θ)_i / 12 ≠ 0`). The rest of the
//! oil's path is the upwinding `D`: symmetric, zero row sums, so `(D θ)_i = Σ_j D_ij (θ_j − θ_i)` is a sum of
//! exchanges between neighbours. Pair (i, j) carries
//!
//! ```text
//!   m_ij = −D_ij (θ_j − θ_i) / 12 = d_ij (θ_j − θ_i) / 12     from node j to node i   [m³/s]
//! ```
//!
//! (`d_ij = −D_ij ≥ 0`, the limited Couette entry). Adding these exchanges to the Galerkin nodal flows
//! gives zero at every free node to round-off: the oil that leaves the film is the oil that the film's
//! own mass balance lets out, at its edges and orifices.
//!
//! Contract: after a mass-conserving solve of the current thickness; the pairs are in the modelled domain
//! (no symmetry factor); pairs whose θ agree are left out.

use crate::physics::reynolds::PadFilm;

/// One exchange of oil between neighbouring nodes: `m` [m³/s] flows from node `from` to node `to`
/// (`m ≥ 0`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NodeExchange {
    pub from: usize,
    pub to: usize,
    pub m: f64,
}

impl PadFilm {
    /// The upwinding's exchanges of oil between neighbouring nodes at the last mass-conserving solve
    /// (module documentation); empty after a Reynolds or Gümbel solve.
    #[must_use]
    pub fn upwinding_exchanges(&self, surface_speed: f64) -> Vec<NodeExchange> {
        let Some(state) = self.jfo.as_deref().filter(|_| self.solved_with() == Some(crate::model::Cavitation::Jfo))
        else {
            return Vec::new();
        };
        let p = &state.pattern;
        let mut t = vec![0.0; state.t.len()];
        state.add_couette(&self.geom, surface_speed, &self.h.qp, &mut t);
        let th = &self.theta;
        let mut out = Vec::new();
        for c in 0..p.n {
            for k in p.col_ptr[c]..p.col_ptr[c + 1] {
                let r = p.row_idx[k];
                if r <= c {
                    continue;
                }
                let d = match state.branch[k] {
                    1 => t[k],
                    2 => t[state.transpose[k]],
                    _ => continue,
                };
                // m from c to r.
                let m = d * (th[c] - th[r]) / 12.0;
                if m > 0.0 {
                    out.push(NodeExchange { from: c, to: r, m });
                } else if m < 0.0 {
                    out.push(NodeExchange { from: r, to: c, m: -m });
                }
            }
        }
        out
    }
}
