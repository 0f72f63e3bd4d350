//! Outputs of the last film solve: consistent flows from the nodal residual (flow leaving node i is
//! `−r_i/12` with `r = A p − b`, so the discrete mass balance closes exactly), orifice and edge flows,
//! friction, peak pressure and minimum thickness.

use crate::mesh::grid::NodeSite;
use crate::physics::reynolds::{FilmInputs, PadFilm, PadFlows};

impl PadFilm {
    /// Consistent flows of the last solve (whole pad).
    #[must_use]
    pub fn flows(&self, inp: &FilmInputs<'_>) -> PadFlows {
        let g = &self.geom;
        let mut f = PadFlows::default();
        for (i, r) in self.r.iter().enumerate() {
            let out = -g.sym * r / 12.0;
            match g.sites[i] {
                NodeSite::Leading => f.leading_edge_in -= out,
                NodeSite::Trailing => f.trailing_edge_out += out,
                NodeSite::Side => f.sides_out += out,
                NodeSite::Interior | NodeSite::Symmetry => f.to_cavitation += out,
            }
        }
        f.orifice_in = (0..g.orifices.len()).map(|k| self.orifice_flow(k, inp)).sum();
        f
    }

    /// Oil the cavitation condition puts into the film at its interior nodes [m³/s, whole pad]: the sum of
    /// the nodal flows from those nodes into the film (their negative outflows). The Reynolds and Gümbel
    /// conditions hold `p = 0` in a cavitated zone and count its gap as full of oil, so the Couette flow of a
    /// diverging film and a reformation edge draw oil there that is gas in the bearing (and an orifice in
    /// the zone drains it). With the mass-conserving option it is round-off.
    #[must_use]
    pub fn created_at_cavity(&self) -> f64 {
        let g = &self.geom;
        self.r
            .iter()
            .zip(&g.sites)
            .filter(|(_, site)| matches!(site, NodeSite::Interior | NodeSite::Symmetry))
            .map(|(r, _)| (g.sym * r / 12.0).max(0.0))
            .sum()
    }

    /// Flow work of the oil entering through a pressurised leading edge [W, whole pad]: `Σ p_i q_i` over the
    /// leading-edge nodes with their consistent nodal inflows (0 with an ambient leading edge).
    /// The film dissipates it with the journal's shear power.
    #[must_use]
    pub fn leading_edge_pressure_work(&self) -> f64 {
        if self.leading_edge_pressure == 0.0 {
            return 0.0;
        }
        self.leading.iter().map(|&(i, _)| self.p[i] * self.geom.sym * self.r[i] / 12.0).sum()
    }

    /// Flow into the film through orifice `k` [m³/s] (negative when the hole drains the film).
    #[must_use]
    pub fn orifice_flow(&self, k: usize, inp: &FilmInputs<'_>) -> f64 {
        let g = &self.geom;
        let o = &g.orifices[k];
        let gp: f64 = o.vector.iter().map(|&(i, v)| v * self.p[i]).sum();
        g.sym * (inp.injection_pressure * o.total - gp) / (12.0 * inp.injection_viscosity)
    }

    /// Edge flows by direct integration of `q_s = −h³/(12µ) ∂p/∂s + U h/2` and `q_z = −h³/(12µ) ∂p/∂z`
    /// across the pad boundary, with element gradients (an independent check of [`Self::flows`]):
    /// (leading edge in, trailing edge out, sides out).
    #[must_use]
    pub fn direct_edge_flows(&self, inp: &FilmInputs<'_>) -> (f64, f64, f64) {
        let g = &self.geom;
        let grid = &g.grid;
        let ncs = grid.s.len() - 1;
        let ncz = grid.z.len() - 1;
        let u = inp.surface_speed;
        let gauss = [-0.577_350_269_189_625_8, 0.577_350_269_189_625_8];
        let mut le = 0.0;
        let mut te = 0.0;
        let mut side = 0.0;
        // (h, ∂p/∂s, ∂p/∂z, µ/G_s, µ/G_z): the turbulence multipliers enter as an effective viscosity per
        // direction (element means, like µ).
        let eval = |e: usize, xi: f64, eta: f64| -> (f64, f64, f64, f64, f64) {
            let r = &g.rects[e];
            let q = r.quad_point(xi, eta, 1.0);
            let nodes = g.elements[e];
            let (mut h, mut ps, mut pz, mut mu) = (0.0, 0.0, 0.0, 0.0);
            for a in 0..4 {
                h += q.n[a] * self.h.node[nodes[a]];
                ps += q.dn_ds[a] * self.p[nodes[a]];
                pz += q.dn_dz[a] * self.p[nodes[a]];
            }
            let (mut gs, mut gz) = (1.0, 1.0);
            if let Some(t) = self.turb_qp.get(e) {
                gs = t.iter().map(|f| 0.25 * f.gs).sum();
                gz = t.iter().map(|f| 0.25 * f.gz).sum();
            }
            for k in 0..4 {
                mu += 0.25 * self.mu_qp[e][k];
            }
            (h, ps, pz, mu / gs, mu / gz)
        };
        if !grid.periodic {
            for j in 0..ncz {
                for &eta in &gauss {
                    let e0 = j; // column 0
                    let (h, ps, _, mu, _) = eval(e0, -1.0, eta);
                    le += 0.5 * g.rects[e0].dz * (-h * h * h / (12.0 * mu) * ps + 0.5 * u * h);
                    let e1 = (ncs - 1) * ncz + j;
                    let (h, ps, _, mu, _) = eval(e1, 1.0, eta);
                    te += 0.5 * g.rects[e1].dz * (-h * h * h / (12.0 * mu) * ps + 0.5 * u * h);
                }
            }
        }
        for i in 0..ncs {
            for &xi in &gauss {
                let top = i * ncz + (ncz - 1);
                let (h, _, pz, _, mu) = eval(top, xi, 1.0);
                side += 0.5 * g.rects[top].ds * (-h * h * h / (12.0 * mu) * pz);
                if !grid.half {
                    let bot = i * ncz;
                    let (h, _, pz, _, mu) = eval(bot, xi, -1.0);
                    side += 0.5 * g.rects[bot].ds * (h * h * h / (12.0 * mu) * pz);
                }
            }
        }
        (g.sym * le, g.sym * te, g.sym * side)
    }

    /// Viscous drag on the journal and the power it dissipates, `P = U ∫ (θ C_f µ U/h + (h/2) ∂p/∂s) dA`
    /// → (force N, power W). C_f = 1 laminar. θ is the mass-conserving solve's film fraction; after a Reynolds
    /// or Gümbel solve θ ≡ 1 (a full film assumed in cavitated regions, a conservative choice).
    #[must_use]
    pub fn friction(&self, inp: &FilmInputs<'_>) -> (f64, f64) {
        let g = &self.geom;
        let u = inp.surface_speed;
        let mut force = 0.0;
        for (e, nodes) in g.elements.iter().enumerate() {
            for (k, q) in g.qp[e].iter().enumerate() {
                let h = self.h.qp[e][k];
                let dps: f64 = (0..4).map(|a| q.dn_ds[a] * self.p[nodes[a]]).sum();
                let cf = self.turb_qp.get(e).map_or(1.0, |t| t[k].cf);
                let theta: f64 = (0..4).map(|a| q.n[a] * self.theta[nodes[a]]).sum();
                force += q.w * (theta * cf * self.mu_qp[e][k] * u / h + 0.5 * h * dps);
            }
        }
        (g.sym * force, g.sym * force * u)
    }

    /// Largest nodal pressure [Pa].
    #[must_use]
    pub fn p_max(&self) -> f64 {
        self.p.iter().fold(0.0_f64, |m, &v| m.max(v))
    }

    /// Smallest nodal film thickness [m] and its node.
    #[must_use]
    pub fn h_min(&self) -> (f64, usize) {
        self.h.node.iter().enumerate().fold((f64::INFINITY, 0), |m, (i, &v)| if v < m.0 { (v, i) } else { m })
    }

    /// Viscosity at the quadrature points of the last solve.
    #[must_use]
    pub fn viscosity_qp(&self) -> &[[f64; 4]] {
        &self.mu_qp
    }

    /// Nodal residual `A p − b` of the last solve.
    #[must_use]
    pub fn residual(&self) -> &[f64] {
        &self.r
    }
}
