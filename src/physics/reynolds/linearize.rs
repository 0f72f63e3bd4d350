//! Film forces and their linearisation about the last solve (Lund's perturbation method):
//! `Q_k = ∫ p φ_k dA`, `K_kl = −∂Q_k/∂q_l`, `C_kl = −∂Q_k/∂q̇_l`, the perturbation pressures coming from
//! back-substitutions with the factorisation of the converged solve (exact for a fixed cavitation boundary).
//! After a mass-conserving solve the factorisation is that of the mixed pressure/film-fraction system and
//! the Couette and squeeze right-hand sides carry the film fraction (`jfo.rs`).

use crate::model::Cavitation;
use crate::physics::reynolds::{FilmInputs, FilmLinearization, PadFilm};
use nalgebra::DMatrix;

impl PadFilm {
    /// Generalised film forces `Q_k = ∫ p φ_k dA` (whole pad).
    #[must_use]
    pub fn generalized_forces(&self) -> Vec<f64> {
        let g = &self.geom;
        g.loads.iter().map(|f| g.sym * f.iter().zip(&self.p).map(|(a, b)| a * b).sum::<f64>()).collect()
    }

    /// Film stiffness and damping in the pad's generalised coordinates (analytic perturbation about the
    /// last solve; requires a preceding [`Self::solve`] with the same inputs).
    #[must_use]
    pub fn linearize(&mut self, inp: &FilmInputs<'_>) -> FilmLinearization {
        self.linearize_impl(inp, true)
    }

    /// As [`Self::linearize`] but the stiffness only (the damping is returned as zeros): half the
    /// back-substitutions, for Newton iterations.
    #[must_use]
    pub fn linearize_stiffness(&mut self, inp: &FilmInputs<'_>) -> FilmLinearization {
        self.linearize_impl(inp, false)
    }

    fn linearize_impl(&mut self, inp: &FilmInputs<'_>, with_damping: bool) -> FilmLinearization {
        let fields = self.perturbation_fields(inp, with_damping);
        let g = &self.geom;
        let n = g.n_nodes();
        let m = g.n_dofs();
        let mut stiffness = DMatrix::zeros(m, m);
        let mut damping = DMatrix::zeros(m, m);
        for j in 0..m {
            for k in 0..m {
                let dk = &fields[k * n..(k + 1) * n];
                stiffness[(j, k)] = -g.sym * g.loads[j].iter().zip(dk).map(|(a, b)| a * b).sum::<f64>();
                if with_damping {
                    let dc = &fields[(m + k) * n..(m + k + 1) * n];
                    damping[(j, k)] = -g.sym * g.loads[j].iter().zip(dc).map(|(a, b)| a * b).sum::<f64>();
                }
            }
        }
        FilmLinearization { stiffness, damping }
    }

    /// The pressure perturbation fields `∂p/∂q_k` (columns `0..m`) and, with `with_damping`, `∂p/∂q̇_k`
    /// (columns `m..2m`), each of length n, by back-substitution with the factorisation of the last solve.
    pub(super) fn perturbation_fields(&mut self, inp: &FilmInputs<'_>, with_damping: bool) -> Vec<f64> {
        let g = &self.geom;
        let n = g.n_nodes();
        let m = g.n_dofs();
        let u = inp.surface_speed;
        let gumbel = self.solved_with == Some(Cavitation::Gumbel);
        let jfo = self.solved_with == Some(Cavitation::Jfo);
        let pg = if gumbel { &self.p_full } else { &self.p };
        let cols = if with_damping { 2 * m } else { m };
        let mut rhs = vec![0.0; n * cols];
        // Mass-conserving cavitation: the oil's Couette and squeeze terms carry the film fraction (jfo.rs).
        if jfo {
            if let Some(state) = self.jfo.as_deref_mut() {
                state.perturbation_rhs(g, u, &self.theta, with_damping, &mut rhs);
            }
        }
        for (e, nodes) in g.elements.iter().enumerate() {
            for (k, q) in g.qp[e].iter().enumerate() {
                let h = self.h.qp[e][k];
                let mu = self.mu_qp[e][k];
                let (mut dps, mut dpz) = (0.0, 0.0);
                for a in 0..4 {
                    dps += q.dn_ds[a] * pg[nodes[a]];
                    dpz += q.dn_dz[a] * pg[nodes[a]];
                }
                // ∂(h³ G/µ)/∂h = (h²/µ) G e per direction (laminar: G = 1, e = 3).
                let turb = self.turb_qp.get(e).map(|t| (t[k].gs * t[k].es, t[k].gz * t[k].ez));
                let couette = if jfo { 0.0 } else { 6.0 * u };
                for a in 0..4 {
                    // ∂b/∂q_k − (∂A/∂q_k) p, per unit φ_k:
                    //   6 U ∂N_a/∂s − 3 h²/µ ∇p·∇N_a   (laminar; turbulent: the per-direction coefficients; the
                    //   Couette part above for the mass-conserving option)
                    let poiseuille = match turb {
                        Some((cs, cz)) => h * h / mu * (cs * dps * q.dn_ds[a] + cz * dpz * q.dn_dz[a]),
                        None => 3.0 * h * h / mu * (dps * q.dn_ds[a] + dpz * q.dn_dz[a]),
                    };
                    let c = q.w * (couette * q.dn_ds[a] - poiseuille);
                    // Squeeze: −12 N_a per unit φ_k q̇_k.
                    let d = -12.0 * q.w * q.n[a];
                    for (s, shape) in g.shapes.iter().enumerate() {
                        let phi = shape.qp[e][k];
                        rhs[s * n + nodes[a]] += phi * c;
                        if with_damping && !jfo {
                            rhs[(m + s) * n + nodes[a]] += phi * d;
                        }
                    }
                }
            }
        }
        self.back_substitute(&mut rhs);
        rhs
    }

    /// Solves `A x = r` for every column of `rhs` (length n each) with the factorisation of the last solve:
    /// fixed rows zeroed first; under Gümbel cavitation the clipped nodes are zeroed after.
    pub(super) fn back_substitute(&mut self, rhs: &mut [f64]) {
        let n = self.geom.n_nodes();
        if self.solved_with == Some(Cavitation::Jfo) {
            if let Some(state) = self.jfo.as_deref_mut() {
                if state.back_substitute(rhs, &self.cavitated).is_err() {
                    // The factorisation of the converged solve succeeded, so its solves are finite; a failure
                    // here can only come from a non-finite right-hand side: no response.
                    rhs.fill(0.0);
                }
                return;
            }
        }
        for col in rhs.chunks_mut(n) {
            for i in 0..n {
                if self.fixed[i] {
                    col[i] = 0.0;
                }
            }
        }
        self.solver.solve_many_in_place(rhs, n);
        if self.solved_with == Some(Cavitation::Gumbel) {
            for col in rhs.chunks_mut(n) {
                for i in 0..n {
                    if self.cavitated[i] {
                        col[i] = 0.0;
                    }
                }
            }
        }
    }
}
