//! Anderson acceleration of a fixed-point iteration `x = G(x)` (Walker & Ni, SIAM J. Numer. Anal. 49, 2011,
//! "type II"): keeps the last `depth` iterates and residuals `f = G(x) − x` and extrapolates
//! `x⁺ = x + β f − (ΔX + β ΔF) γ` with `γ = argmin |f − ΔF γ|` (least squares by SVD). The thermal loop
//! uses it on the film temperatures; `reset` restarts the history after a rejected step. Safeguarded form
//! ([`Anderson::step_safeguarded`]): when the caller's residual grows, the history is dropped and β halved
//! (down to a floor), i.e. the iteration falls back to damped fixed-point steps where extrapolation fails.

use nalgebra::{DMatrix, DVector};

/// Growth of the residual over the last step's at which [`Anderson::step_safeguarded`] restarts with a
/// smaller β: any growth. (Twice the smallest residual since the last restart was measured and left: 27
/// failures of Fillon A's 5° map instead of 24, and Fillon A with thermal growth at S = 10 ended in
/// touchdown, pads grown into the journal, at all 72 points that converge with this rule; not analysed.)
pub const SAFEGUARD_GROWTH: f64 = 1.0;

/// Safeguarded steps in a row whose residual fell after which [`Anderson::step_safeguarded`] doubles β
/// again (up to the damping it started with). Without it a loop that once needed β at its floor kept it
/// there: Fillon A at S = 0.1, 55°, contracted at 0.97 per step at β = 0.1 after a blow-up of its
/// extrapolation and ran out of its 300 iterations at a change of 8e-4; with it, it converges in 94.
pub const RECOVER_AFTER: usize = 5;

/// Anderson mixing state.
pub struct Anderson {
    depth: usize,
    beta: f64,
    /// Smallest damping the safeguard ([`Anderson::step_safeguarded`]) lowers β to.
    beta_min: f64,
    /// Damping the safeguard restores β towards ([`Anderson::step_safeguarded`]).
    beta_max: f64,
    /// Residual measure of the last safeguarded step, and the safeguarded steps in a row whose residual fell.
    last_residual: Option<f64>,
    falls: usize,
    x: Vec<Vec<f64>>,
    f: Vec<Vec<f64>>,
}

impl Anderson {
    pub fn new(depth: usize, beta: f64) -> Self {
        Self {
            depth,
            beta,
            beta_min: beta,
            beta_max: beta,
            last_residual: None,
            falls: 0,
            x: Vec::new(),
            f: Vec::new(),
        }
    }
    /// With the safeguard of [`Anderson::step_safeguarded`]: β is halved down to `beta_min`.
    pub fn safeguarded(depth: usize, beta: f64, beta_min: f64) -> Self {
        Self { beta_min: beta_min.min(beta), ..Self::new(depth, beta) }
    }
    pub fn reset(&mut self) {
        self.x.clear();
        self.f.clear();
    }
    /// The damping β now.
    pub fn beta(&self) -> f64 {
        self.beta
    }
    /// [`Anderson::step`] with a safeguard: when the caller's residual measure of `x` (e.g. the largest
    /// relative change `|G(x) − x|`) exceeds [`SAFEGUARD_GROWTH`] times the last step's, the extrapolation did not contract: the history is dropped (it describes a map the iterate
    /// has left) and β is halved, down to `beta_min`, so the next steps are damped fixed-point steps that
    /// rebuild the history from where the iterate is; after [`RECOVER_AFTER`] falls of the residual in a
    /// row β is doubled again, up to the damping the iteration started with.
    pub fn step_safeguarded(&mut self, x: &[f64], g: &[f64], residual: f64) -> Vec<f64> {
        if self.last_residual.is_some_and(|last| residual > SAFEGUARD_GROWTH * last) {
            self.reset();
            self.beta = (0.5 * self.beta).max(self.beta_min);
            self.falls = 0;
        } else if self.last_residual.is_some() {
            self.falls += 1;
            if self.falls >= RECOVER_AFTER && self.beta < self.beta_max {
                self.beta = (2.0 * self.beta).min(self.beta_max);
                self.falls = 0;
            }
        }
        self.last_residual = Some(residual);
        self.step(x, g)
    }
    /// Next iterate from the current one `x` and its image `g`.
    pub fn step(&mut self, x: &[f64], g: &[f64]) -> Vec<f64> {
        let f: Vec<f64> = g.iter().zip(x).map(|(a, b)| a - b).collect();
        self.x.push(x.to_vec());
        self.f.push(f.clone());
        if self.x.len() > self.depth + 1 {
            self.x.remove(0);
            self.f.remove(0);
        }
        let m = self.x.len() - 1;
        let mut next: Vec<f64> = x.iter().zip(&f).map(|(a, b)| a + self.beta * b).collect();
        if m == 0 {
            return next;
        }
        let n = x.len();
        let df = DMatrix::from_fn(n, m, |i, j| self.f[j + 1][i] - self.f[j][i]);
        let rhs = DVector::from_column_slice(&f);
        let Ok(gamma) = df.clone().svd(true, true).solve(&rhs, 1e-10) else { return next };
        if gamma.iter().any(|v| !v.is_finite()) {
            return next;
        }
        for j in 0..m {
            for i in 0..n {
                let dx = self.x[j + 1][i] - self.x[j][i];
                next[i] -= gamma[j] * (dx + self.beta * df[(i, j)]);
            }
        }
        next
    }
}

pub fn flatten(t: &[Vec<f64>]) -> Vec<f64> {
    t.iter().flatten().copied().collect()
}

pub fn unflatten(flat: &[f64], like: &[Vec<f64>]) -> Vec<Vec<f64>> {
    let mut out = Vec::with_capacity(like.len());
    let mut at = 0;
    for v in like {
        out.push(flat[at..at + v.len()].to_vec());
        at += v.len();
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn accelerates_a_slow_linear_fixed_point() {
        // x = G(x) = A x + b with spectral radius 0.95: plain damped iteration needs hundreds of steps.
        let g = |x: &[f64]| vec![0.95 * x[0] + 0.01 * x[1] + 1.0, 0.02 * x[0] + 0.9 * x[1] - 2.0];
        let exact = {
            // (I − A) x = b
            let (a, b, c, d): (f64, f64, f64, f64) = (0.05, -0.01, -0.02, 0.1);
            let det = a * d - b * c;
            [(d * 1.0 - b * -2.0) / det, (a * -2.0 - c * 1.0) / det]
        };
        let mut aa = Anderson::new(4, 0.8);
        let mut x = vec![0.0, 0.0];
        let mut steps = 0;
        while ((x[0] - exact[0]).abs() + (x[1] - exact[1]).abs()) > 1e-10 && steps < 50 {
            let gx = g(&x);
            x = aa.step(&x, &gx);
            steps += 1;
        }
        assert!(steps < 10, "{steps} steps");
    }

    #[test]
    fn a_growing_residual_drops_the_history_and_halves_the_damping() {
        let mut aa = Anderson::safeguarded(4, 0.8, 0.1);
        let _ = aa.step_safeguarded(&[0.0], &[1.0], 1.0);
        let _ = aa.step_safeguarded(&[0.8], &[1.5], 0.5);
        assert_eq!((aa.x.len(), aa.beta()), (2, 0.8));
        // The residual grows: no extrapolation from the old pair, a plain step damped by 0.4.
        let next = aa.step_safeguarded(&[2.0], &[3.0], 1.1);
        assert!((aa.beta() - 0.4).abs() < 1e-15 && aa.x.len() == 1, "β {} history {}", aa.beta(), aa.x.len());
        assert!((next[0] - 2.4).abs() < 1e-15, "{next:?}");
        // Halving stops at the floor.
        for r in [3.0, 4.0, 5.0, 6.0] {
            let _ = aa.step_safeguarded(&[2.0], &[3.0], r);
        }
        assert!((aa.beta() - 0.1).abs() < 1e-15, "β {}", aa.beta());
        // Falls in a row restore it, doubling after each RECOVER_AFTER of them, up to the starting 0.8.
        let mut r = 6.0;
        let mut betas = Vec::new();
        for _ in 0..4 * RECOVER_AFTER {
            r *= 0.9;
            let _ = aa.step_safeguarded(&[2.0], &[3.0], r);
            betas.push(aa.beta());
        }
        let at = |falls: usize| betas[falls - 1];
        assert!((at(RECOVER_AFTER - 1) - 0.1).abs() < 1e-15 && (at(RECOVER_AFTER) - 0.2).abs() < 1e-15, "{betas:?}");
        assert!(
            (at(3 * RECOVER_AFTER) - 0.8).abs() < 1e-15 && (at(4 * RECOVER_AFTER) - 0.8).abs() < 1e-15,
            "{betas:?}"
        );
    }

    #[test]
    fn flatten_round_trips() {
        let t = vec![vec![1.0, 2.0], vec![3.0], vec![]];
        assert_eq!(unflatten(&flatten(&t), &t), t);
    }
}
