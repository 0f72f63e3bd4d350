//! The onset of pressure of a mass-conserving film along one coordinate (docs/MODEL.md §2.3): where a pad
//! that carries no pressure starts to carry some as the coordinate grows.
//!
//! ## Condition
//! With no pressure anywhere every free node is cavitated and the film fraction solves the transport alone,
//! `(T̃ + S) θ = f` (`jfo.rs`); `p ≡ 0` is the solution of the complementarity problem exactly when that
//! `θ` stays at or below 1 at every free node. Moving the coordinate `x` changes the thickness and so `θ(x)`;
//! the onset is the smallest `x` above the start where `max_i θ_i(x) = 1`.
//!
//! ## Method
//! Along a striation the oil content `θ h` is nearly constant and `h` is affine in the coordinate, so
//! `1/θ_i(x)` is nearly affine: Newton on `1/θ_i = 1` for every node,
//!
//! ```text
//! x_{k+1} = x_k + min_{i: θ'_i > 0} θ_i (1 − θ_i) / θ'_i,   θ' = ∂θ/∂x  (one back-substitution, jfo_linearize.rs)
//! ```
//!
//! where `θ` is the all-cavitated transport's solution at `x_k` (one factorisation of the mixed matrix with
//! every free node cavitated, one solve): from a pressure-free point the step goes to the nearest node
//! filling up, from a point with pressure (some `θ_i > 1`) back to where the last of them drops to 1. Points
//! with `max θ ≤ 1` and `> 1` bracket the onset; a Newton point outside the bracket is replaced by its
//! midpoint. The result is the last pressure-free point, within [`ONSET_TOL`] of the thickness scale of the
//! onset, so the film there carries no pressure at all.
//!
//! The Reynolds option's interval (`mod.rs`) is affine and needs no solve; the mass-conserving one is not
//! (the oil reaching a node depends on the thickness upstream), hence these few transport solves. They run on
//! a copy of the film, so the caller's film keeps its last solve.

use crate::model::Cavitation;
use crate::physics::reynolds::{FilmError, FilmInputs, PadFilm};

/// Newton and bisection steps of the onset search, at most.
const MAX_ONSET_STEPS: usize = 30;

/// Stopping distance of the onset search: the coordinate change that moves the film by this fraction of its
/// thinnest value (at any node).
const ONSET_TOL: f64 = 1e-10;

impl PadFilm {
    /// The onset of pressure along coordinate `slot` (the others as in `q`) under mass-conserving cavitation
    /// (module documentation): the largest value up to which the film carries no pressure, searched from
    /// `q[slot]` (with or without pressure there). `None` before a first mass-conserving solve, with a squeeze
    /// velocity, when no node fills up as the coordinate grows or when the search finds no pressure-free
    /// point. The search runs on a copy of the film; its factorisations are added to the next solve's count.
    pub(super) fn jfo_onset(&mut self, q: &[f64], slot: usize, inp: &FilmInputs<'_>) -> Option<f64> {
        if inp.cavitation != Cavitation::Jfo || self.solved_with != Some(Cavitation::Jfo) || self.squeeze.is_some() {
            return None;
        }
        let phi = &self.geom.shapes[slot].node;
        let phi_max = phi.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        if phi_max == 0.0 {
            return None;
        }
        let mut film = self.clone();
        let mut factorizations = 0;
        let onset = film.search_onset(q, slot, inp, phi_max, &mut factorizations);
        self.onset_factorizations += factorizations;
        onset
    }

    /// The safeguarded Newton iteration of [`Self::jfo_onset`] on a copy of the film, counting its
    /// factorisations.
    fn search_onset(
        &mut self,
        q: &[f64],
        slot: usize,
        inp: &FilmInputs<'_>,
        phi_max: f64,
        factorizations: &mut usize,
    ) -> Option<f64> {
        let mut qn = q.to_vec();
        let (mut free, mut loaded): (Option<f64>, Option<f64>) = (None, None);
        let mut x = q[slot];
        let mut tol = f64::INFINITY;
        for _ in 0..MAX_ONSET_STEPS {
            qn[slot] = x;
            let (filled, step) = match self.transport(&qn, slot, inp, factorizations) {
                Ok(t) => {
                    tol = tol.min(ONSET_TOL * self.h_min().0 / phi_max);
                    t
                }
                // The film closes there: past the onset.
                Err(_) => (true, None),
            };
            if filled {
                loaded = Some(loaded.map_or(x, |l: f64| l.min(x)));
            } else {
                free = Some(free.map_or(x, |f: f64| f.max(x)));
            }
            let mut next = match step {
                Some(s) => x + s,
                None if !filled => return free,
                None => f64::NAN,
            };
            match (free, loaded) {
                (Some(f), Some(l)) => {
                    if l - f <= tol {
                        break;
                    }
                    // Outside the bracket, or not a number (no step from a point with pressure).
                    if next.is_nan() || next <= f || next >= l {
                        next = 0.5 * (f + l);
                    }
                }
                (Some(f), None) if next.is_nan() || next - f <= tol => break,
                (None, Some(l)) if next.is_nan() || next >= l => return None,
                _ => {}
            }
            x = next;
        }
        free
    }

    /// The all-cavitated transport at `q`: whether some node's film fraction exceeds 1 (the film carries
    /// pressure there) and the Newton step of the module documentation (`None` when no film fraction grows
    /// with the coordinate).
    fn transport(
        &mut self,
        q: &[f64],
        slot: usize,
        inp: &FilmInputs<'_>,
        factorizations: &mut usize,
    ) -> Result<(bool, Option<f64>), FilmError> {
        self.set_coordinates(q)?;
        self.cavitated.fill(true);
        let Some(state) = self.jfo.as_deref_mut() else { return Err(FilmError::Input("no film state".into())) };
        state.transport_only = true;
        let solved = self.solve(inp, true);
        if let Some(state) = self.jfo.as_deref_mut() {
            state.transport_only = false;
        }
        *factorizations += solved?.factorizations;
        let g = &self.geom;
        let Some(state) = self.jfo.as_deref_mut() else { return Err(FilmError::Input("no film state".into())) };
        let dtheta = state.theta_response(g, inp.surface_speed, &g.shapes[slot].qp, &self.theta, &self.cavitated)?;
        let free = |i: usize| self.cavitated[i];
        let filled = (0..g.n_nodes()).any(|i| free(i) && self.theta[i] > 1.0);
        let step = (0..g.n_nodes())
            .filter(|&i| free(i) && dtheta[i] > 0.0)
            .map(|i| self.theta[i] * (1.0 - self.theta[i]) / dtheta[i])
            .fold(f64::INFINITY, f64::min);
        Ok((filled, step.is_finite().then_some(step)))
    }
}
