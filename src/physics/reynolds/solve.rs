//! Assembly and solution of the film equation (see the module header of `reynolds`): the matrix and
//! right-hand side for the current thickness, then either the Gümbel clip or the Reynolds (Swift–Stieber)
//! complementarity problem `p ≥ 0, A p − b ≥ 0, p·(A p − b) = 0` by a warm-started primal–dual active set.

use crate::model::Cavitation;
use crate::physics::reynolds::jfo::{JfoResult, JfoSolve, JfoState};
use crate::physics::reynolds::{FilmError, FilmInputs, FilmSolveInfo, PadFilm, MAX_ACTIVE_SET_ITERATIONS};

impl PadFilm {
    /// Assembles the matrix (lower triangle) and the right-hand side for the current thickness.
    fn assemble(&mut self, inp: &FilmInputs<'_>) {
        let g = &self.geom;
        let u = inp.surface_speed;
        self.a_raw.fill(0.0);
        self.b.fill(0.0);
        for (e, nodes) in g.elements.iter().enumerate() {
            let map = &g.pattern.scatter[e];
            for (k, q) in g.qp[e].iter().enumerate() {
                let h = self.h.qp[e][k];
                // Diffusion coefficient h³/µ times the quadrature weight; turbulent: G_s h³/µ along s and
                // G_z h³/µ along z (physics::turbulence).
                let kd = q.w * h * h * h / self.mu_qp[e][k];
                // The laminar film keeps its own arithmetic (bit for bit the laminar solver's).
                let turb = self.turb_qp.get(e).map(|t| (kd * t[k].gs, kd * t[k].gz));
                for a in 0..4 {
                    // Couette wedge, integrated by parts: ∫ 6 U h ∂N_a/∂s.
                    self.b[nodes[a]] += q.w * 6.0 * u * h * q.dn_ds[a];
                    for bb in 0..4 {
                        let pos = map[4 * a + bb];
                        if pos != usize::MAX {
                            self.a_raw[pos] += match turb {
                                Some((ks, kz)) => ks * q.dn_ds[a] * q.dn_ds[bb] + kz * q.dn_dz[a] * q.dn_dz[bb],
                                None => kd * (q.dn_ds[a] * q.dn_ds[bb] + q.dn_dz[a] * q.dn_dz[bb]),
                            };
                        }
                    }
                }
            }
        }
        // Squeeze: −∫ 12 ∂h/∂t N_a.
        if let Some(sq) = &self.squeeze {
            for (e, nodes) in g.elements.iter().enumerate() {
                for (k, q) in g.qp[e].iter().enumerate() {
                    for a in 0..4 {
                        self.b[nodes[a]] -= 12.0 * q.w * sq.qp[e][k] * q.n[a];
                    }
                }
            }
        }
        // Orifices: 3 g (p − p_inj) / (µ_inj l0).
        let mu_inj = inp.injection_viscosity;
        for o in &g.orifices {
            for &(pos, v) in o.entries(inp.injection_pressure) {
                self.a_raw[pos] += v / mu_inj;
            }
            if inp.injection_pressure != 0.0 {
                for &(i, v) in &o.vector {
                    self.b[i] += inp.injection_pressure * v / mu_inj;
                }
            }
        }
    }

    /// Solves the film for the thickness set by [`Self::set_coordinates`].
    ///
    /// `warm`: start the active-set iteration from the previous cavitated set.
    ///
    /// # Errors
    /// Invalid inputs or a failed factorisation (never returns NaN pressures).
    pub fn solve(&mut self, inp: &FilmInputs<'_>, warm: bool) -> Result<FilmSolveInfo, FilmError> {
        if !(inp.surface_speed.is_finite() && inp.injection_pressure.is_finite()) {
            return Err(FilmError::Input("non-finite speed or injection pressure".into()));
        }
        if !(inp.injection_viscosity > 0.0 && inp.injection_viscosity.is_finite()) {
            return Err(FilmError::Input(format!("injection viscosity {}", inp.injection_viscosity)));
        }
        if !(inp.leading_edge_pressure >= 0.0 && inp.leading_edge_pressure.is_finite()) {
            return Err(FilmError::Input(format!("leading-edge pressure {} Pa", inp.leading_edge_pressure)));
        }
        if inp.leading_edge_pressure != 0.0 && inp.cavitation == Cavitation::Jfo {
            // The mass-conserving inlet is a film fraction, not a pressure (refused when the case is read).
            return Err(FilmError::Input("a leading-edge pressure with mass-conserving cavitation".into()));
        }
        self.leading_edge_pressure = inp.leading_edge_pressure;
        self.set_viscosity(inp.viscosity)?;
        self.set_turbulence(inp)?;
        self.assemble(inp);
        let info = match inp.cavitation {
            Cavitation::Gumbel => self.solve_gumbel()?,
            Cavitation::Reynolds => self.solve_reynolds(warm && self.solved_with == Some(Cavitation::Reynolds))?,
            Cavitation::Jfo => self.solve_jfo(inp, warm && self.solved_with == Some(Cavitation::Jfo))?,
        };
        if inp.cavitation != Cavitation::Jfo {
            self.theta.fill(1.0);
        }
        self.solved_with = Some(inp.cavitation);
        if self.p.iter().any(|v| !v.is_finite()) {
            return Err(FilmError::Input("pressure is not finite (ill-conditioned film)".into()));
        }
        Ok(info)
    }

    fn factor_and_solve(&mut self) -> Result<(), FilmError> {
        let g = &self.geom;
        g.pattern.fix_rows(&self.a_raw, &self.fixed, &mut self.a_work);
        self.solver.factor(&g.pattern, &self.a_work)?;
        let p_le = self.leading_edge_pressure;
        if p_le == 0.0 {
            for i in 0..self.p.len() {
                self.p[i] = if self.fixed[i] { 0.0 } else { self.b[i] };
            }
        } else {
            // Lifting: the leading-edge values p_d are known; A_ff p_f = b_f − A_fd p_d, and the fixed rows
            // (identity after fix_rows) return p_d itself.
            self.p.fill(0.0);
            for &(i, share) in &self.leading {
                self.p[i] = p_le * share;
            }
            g.pattern.sym_matvec(&self.a_raw, &self.p, &mut self.r);
            for i in 0..self.p.len() {
                self.p[i] = if self.fixed[i] { self.p[i] } else { self.b[i] - self.r[i] };
            }
        }
        self.solver.solve_in_place(&mut self.p);
        // Residual of the unmodified equations: reactions at fixed nodes, ~0 elsewhere.
        g.pattern.sym_matvec(&self.a_raw, &self.p, &mut self.r);
        for (r, b) in self.r.iter_mut().zip(&self.b) {
            *r -= b;
        }
        Ok(())
    }

    fn solve_gumbel(&mut self) -> Result<FilmSolveInfo, FilmError> {
        self.fixed.copy_from_slice(&self.geom.dirichlet);
        self.factor_and_solve()?;
        self.p_full.copy_from_slice(&self.p);
        let mut n_cav = 0;
        for i in 0..self.p.len() {
            self.cavitated[i] = self.p[i] < 0.0;
            if self.cavitated[i] {
                self.p[i] = 0.0;
                n_cav += 1;
            }
        }
        // Residual of the clipped field (flows).
        let g = &self.geom;
        g.pattern.sym_matvec(&self.a_raw, &self.p, &mut self.r);
        for (r, b) in self.r.iter_mut().zip(&self.b) {
            *r -= b;
        }
        Ok(FilmSolveInfo { factorizations: 1, active_set_iterations: 1, cavitated_nodes: n_cav, ..Default::default() })
    }

    /// Mass-conserving cavitation (`jfo.rs`): from the previous solve's sets (`warm`) or the Reynolds
    /// (Swift–Stieber) active set.
    fn solve_jfo(&mut self, inp: &FilmInputs<'_>, warm: bool) -> Result<FilmSolveInfo, FilmError> {
        if let crate::physics::reynolds::Inlet::Supply { flow_m3_s } = inp.inlet {
            if !(flow_m3_s > 0.0 && flow_m3_s.is_finite()) {
                return Err(FilmError::Input(format!("supply flow {flow_m3_s} m³/s")));
            }
        }
        let mut start = FilmSolveInfo::default();
        if !warm {
            start = self.solve_reynolds(false)?;
        }
        if self.jfo.is_none() {
            self.jfo = Some(Box::new(JfoState::new(&self.geom)?));
        }
        let g = &self.geom;
        let mut f = vec![0.0; g.n_nodes()];
        if inp.injection_pressure != 0.0 {
            for o in &g.orifices {
                for &(i, v) in &o.vector {
                    f[i] += inp.injection_pressure * v / inp.injection_viscosity;
                }
            }
        }
        let problem = JfoSolve {
            geom: g,
            a_raw: &self.a_raw,
            f: &f,
            h_qp: &self.h.qp,
            squeeze: self.squeeze.as_ref(),
            surface_speed: inp.surface_speed,
            inlet: inp.inlet,
        };
        let mut out =
            JfoResult { p: &mut self.p, theta: &mut self.theta, cavitated: &mut self.cavitated, r: &mut self.r };
        let Some(state) = self.jfo.as_deref_mut() else { unreachable!("built above") };
        let mut info = state.solve(&problem, &mut out)?;
        info.factorizations += start.factorizations;
        info.active_set_iterations += start.active_set_iterations;
        Ok(info)
    }

    /// The cavitation model of the last solve (`None` before the first).
    #[must_use]
    pub fn solved_with(&self) -> Option<Cavitation> {
        self.solved_with
    }

    /// The inlet film fraction and the Couette inflow of a full inlet [m³/s, whole pad] of the last
    /// mass-conserving solve (`None` after a Reynolds or Gümbel solve).
    #[must_use]
    pub fn inlet_state(&self) -> Option<(f64, f64)> {
        let j = self.jfo.as_deref().filter(|_| self.solved_with == Some(Cavitation::Jfo))?;
        Some((j.theta_in, j.inlet_capacity(self.geom.sym)))
    }

    /// Primal–dual active set for p ≥ 0, λ = A p − b ≥ 0, p λ = 0.
    fn solve_reynolds(&mut self, warm: bool) -> Result<FilmSolveInfo, FilmError> {
        let n = self.p.len();
        if !warm {
            self.cavitated.fill(false);
        }
        let mut info = FilmSolveInfo::default();
        let mut next = self.cavitated.clone();
        loop {
            info.active_set_iterations += 1;
            for i in 0..n {
                self.fixed[i] = self.geom.dirichlet[i] || self.cavitated[i];
            }
            self.factor_and_solve()?;
            info.factorizations += 1;
            let p_scale = self.p.iter().fold(0.0_f64, |m, v| m.max(v.abs())).max(f64::MIN_POSITIVE);
            let r_scale = self.b.iter().fold(0.0_f64, |m, v| m.max(v.abs())).max(f64::MIN_POSITIVE);
            let mut changed = 0;
            for i in 0..n {
                if self.geom.dirichlet[i] {
                    next[i] = false;
                    continue;
                }
                // Stay cavitated while the multiplier is non-negative; enter when the pressure goes negative.
                next[i] = if self.cavitated[i] { self.r[i] > -1e-11 * r_scale } else { self.p[i] < -1e-11 * p_scale };
                if next[i] != self.cavitated[i] {
                    changed += 1;
                }
            }
            if changed == 0 {
                break;
            }
            if info.active_set_iterations >= MAX_ACTIVE_SET_ITERATIONS {
                // Keep the set that matches the last factorisation; report how far from complementarity.
                let viol_p = self.p.iter().fold(0.0_f64, |m, &v| m.max(-v)) / p_scale;
                let viol_r = (0..n).filter(|&i| self.cavitated[i]).fold(0.0_f64, |m, i| m.max(-self.r[i])) / r_scale;
                info.complementarity = viol_p.max(viol_r);
                info.warnings.push(super::FilmWarning::ActiveSetChanging {
                    iterations: info.active_set_iterations,
                    changed_nodes: changed,
                    complementarity: info.complementarity,
                });
                for v in &mut self.p {
                    *v = v.max(0.0);
                }
                break;
            }
            std::mem::swap(&mut self.cavitated, &mut next);
        }
        info.cavitated_nodes = self.cavitated.iter().filter(|&&c| c).count();
        Ok(info)
    }
}

#[cfg(test)]
#[path = "ram_tests.rs"]
mod ram_tests;
