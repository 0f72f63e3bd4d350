//! Anderson acceleration of a fixed-point iteration `x = G(x)` (Walker & Ni, SIAM J. Numer. Anal. 49, 2011,
//! "type II"): keeps the last `depth` iterates and residuals `f = G(x) − x` and extrapolates
//! `x⁺ = x + β f − (ΔX + β ΔF) γ` with `γ = argmin |f − ΔF γ|` (least squares by SVD). The thermal loop
//! uses it on the film temperatures; `reset` restarts the history after a rejected step.

use nalgebra::{DMatrix, DVector};

/// Anderson mixing state.
pub struct Anderson {
    depth: usize,
    beta: f64,
    x: Vec<Vec<f64>>,
    f: Vec<Vec<f64>>,
}

impl Anderson {
    pub fn new(depth: usize, beta: f64) -> Self {
        Self { depth, beta, x: Vec::new(), f: Vec::new() }
    }
    pub fn reset(&mut self) {
        self.x.clear();
        self.f.clear();
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
    fn flatten_round_trips() {
        let t = vec![vec![1.0, 2.0], vec![3.0], vec![]];
        assert_eq!(unflatten(&flatten(&t), &t), t);
    }
}
