//! Damped eigen-solution of the rotor–bearing system at one speed.
//!
//! `M ü + C u̇ + K u = 0` with `u = φ e^{λt}` is solved in first-order form
//! ```text
//! A = [[0, I], [−M⁻¹K, −M⁻¹C]],   A [φ; λφ] = λ [φ; λφ]
//! ```
//! (scaled, see [`state_matrix`]) by faer's dense non-symmetric eigen-decomposition (real Schur, then eigenvectors). Complex pairs give the
//! damped modes: damped natural frequency `ω_d = Im λ`, logarithmic decrement `δ = −2π Re λ / Im λ` (δ < 0:
//! unstable), damping ratio `ζ = −Re λ / |λ|`. Whirl: at each node the orbit `x + iy` of the mode
//! `(X, Y) e^{iω_d t}` splits into a forward circle of radius |X + iY|/2 (turning with the spin, +z) and a
//! backward one |X − iY|/2; the mode is forward when Σ|X + iY|² > Σ|X − iY|² over the shaft nodes.
//! Real eigenvalues (over-damped motions) are not modes; one with Re λ > 0 is an instability and is reported.

use nalgebra::{Complex, DMatrix};
use serde::{Deserialize, Serialize};

use super::assembly::{NodeDof, ShaftModel, Weights};
use super::coupling::System;
use super::error::RotorError;

/// Whirl direction of a mode.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Whirl {
    Forward,
    Backward,
}

/// One damped mode.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Mode {
    /// Eigenvalue λ [1/s].
    pub real_per_s: f64,
    pub imag_rad_s: f64,
    /// Logarithmic decrement (negative: unstable).
    pub log_dec: f64,
    pub damping_ratio: f64,
    pub whirl: Whirl,
    /// Σ|X + iY|² / Σ(|X + iY|² + |X − iY|²) over the shaft nodes (1 pure forward, 0 pure backward).
    pub forward_fraction: f64,
    /// Complex (x, y) amplitude per shaft node, scaled so the largest is 1.
    #[serde(skip)]
    pub shape: Vec<[Complex<f64>; 2]>,
}

impl Mode {
    /// Damped natural frequency [Hz].
    #[must_use]
    pub fn frequency_hz(&self) -> f64 {
        self.imag_rad_s / std::f64::consts::TAU
    }
}

/// All damped modes at one speed.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Modes {
    /// Oscillatory modes, ascending in frequency.
    pub modes: Vec<Mode>,
    /// Largest real eigenvalue over the non-oscillatory roots [1/s] (> 0: a divergent, non-oscillating motion).
    pub max_real_overdamped: Option<f64>,
}

/// First-order state matrix in mass-normalised, scaled coordinates: with `M = LLᵀ`, `u = L⁻ᵀ p`,
/// `K̃ = L⁻¹ K L⁻ᵀ`, `C̃ = L⁻¹ C L⁻ᵀ` and the state `[p; ṗ/s]`, `s = √max|K̃|`,
/// `A = [[0, sI], [−K̃/s, −C̃]]`. Both blocks then have entries of the size of the eigenvalues and, for a
/// lightly damped system, nearly orthogonal eigenvectors (a plain `M⁻¹K` with nearly massless rotations
/// loses the low modes to round-off). Returns A and `L⁻ᵀ` (to map eigenvectors back).
pub fn state_matrix(sys: &System) -> Result<(DMatrix<f64>, DMatrix<f64>), RotorError> {
    let n = sys.n_dofs();
    let sym = (&sys.mass + sys.mass.transpose()) * 0.5;
    let l = sym.cholesky().ok_or(RotorError::SingularMass { size: n })?.l();
    let linv = l.solve_lower_triangular(&DMatrix::identity(n, n)).ok_or(RotorError::SingularMass { size: n })?;
    let kt = &linv * &sys.stiffness * linv.transpose();
    let ct = &linv * &sys.damping * linv.transpose();
    let s = kt.amax().sqrt().max(f64::MIN_POSITIVE);
    let mut a = DMatrix::zeros(2 * n, 2 * n);
    for i in 0..n {
        a[(i, n + i)] = s;
        for j in 0..n {
            a[(n + i, j)] = -kt[(i, j)] / s;
            a[(n + i, n + j)] = -ct[(i, j)];
        }
    }
    Ok((a, linv.transpose()))
}

/// Damped modes of a system built on `shaft` (mode shapes over its nodes).
///
/// # Errors
/// [`RotorError::SingularMass`], [`RotorError::Eigen`].
pub fn damped_modes(sys: &System, shaft: &ShaftModel) -> Result<Modes, RotorError> {
    let (a, back) = state_matrix(sys)?;
    let n2 = a.nrows();
    let n = sys.n_dofs();
    let ns = sys.n_shaft;
    let nodal: Vec<[Weights; 2]> =
        (0..shaft.n_nodes).map(|node| [shaft.weights(node, NodeDof::X), shaft.weights(node, NodeDof::Y)]).collect();
    let fa = faer::Mat::<f64>::from_fn(n2, n2, |i, j| a[(i, j)]);
    let evd = fa.eigen().map_err(|_| RotorError::Eigen { size: n2 })?;
    let (s, u) = (evd.S(), evd.U());
    let mut modes = Vec::new();
    let mut max_real: Option<f64> = None;
    for k in 0..n2 {
        let l = s.column_vector()[k];
        let (re, im) = (l.re, l.im);
        if !re.is_finite() || !im.is_finite() {
            return Err(RotorError::Eigen { size: n2 });
        }
        let mag = re.hypot(im);
        if im.abs() <= 1e-9 * mag.max(1e-12) {
            max_real = Some(max_real.map_or(re, |m: f64| m.max(re)));
            continue;
        }
        if im < 0.0 {
            continue;
        }
        let p: Vec<Complex<f64>> = (0..n).map(|i| Complex::new(u[(i, k)].re, u[(i, k)].im)).collect();
        // shaft coordinates u = L⁻ᵀ p (upper triangular), then the nodal x, y through the shaft's weights
        let q: Vec<Complex<f64>> =
            (0..ns).map(|row| (row..n).fold(Complex::new(0.0, 0.0), |acc, j| acc + p[j] * back[(row, j)])).collect();
        let at = |w: &Weights| w.iter().fold(Complex::new(0.0, 0.0), |acc, &(j, c)| acc + q[j] * c);
        let mut shape: Vec<[Complex<f64>; 2]> = nodal.iter().map(|[x, y]| [at(x), at(y)]).collect();
        let (mut fwd, mut bwd) = (0.0, 0.0);
        for [x, y] in &shape {
            let iy = Complex::new(-y.im, y.re);
            fwd += (x + iy).norm_sqr();
            bwd += (x - iy).norm_sqr();
        }
        let biggest =
            shape
                .iter()
                .flat_map(|p| p.iter())
                .fold(Complex::new(0.0, 0.0), |m: Complex<f64>, z| if z.norm() > m.norm() { *z } else { m });
        if biggest.norm() > 0.0 {
            let scale = Complex::new(1.0, 0.0) / biggest;
            for p in &mut shape {
                p[0] *= scale;
                p[1] *= scale;
            }
        }
        let forward_fraction = if fwd + bwd > 0.0 { fwd / (fwd + bwd) } else { 0.5 };
        modes.push(Mode {
            real_per_s: re,
            imag_rad_s: im,
            log_dec: -std::f64::consts::TAU * re / im,
            damping_ratio: -re / mag,
            whirl: if fwd >= bwd { Whirl::Forward } else { Whirl::Backward },
            forward_fraction,
            shape,
        });
    }
    modes.sort_by(|a, b| a.imag_rad_s.total_cmp(&b.imag_rad_s));
    Ok(Modes { modes, max_real_overdamped: max_real })
}
