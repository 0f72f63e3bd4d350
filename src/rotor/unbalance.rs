//! Unbalance response: the steady synchronous orbit under the rotor's unbalances.
//!
//! An unbalance `m e` at angle φ at node n gives the rotating force `m e Ω² (cos(Ωt + φ), sin(Ωt + φ))`, i.e.
//! the complex amplitudes `F_x = m e Ω² e^{iφ}`, `F_y = −i m e Ω² e^{iφ}` (`f = Re(F e^{iΩt})`). The response
//! solves `(K − Ω² M + iΩ C) U = F` with the system at Ω — with full bearing coefficients this is the same as
//! the synchronously reduced bearing (the condensation is exact at the forcing frequency). At a node the orbit
//! `(X, Y)` has forward and backward radii `r_f = |X + iY|/2`, `r_b = |X − iY|/2`: major semi-axis `r_f + r_b`;
//! the reported amplitude is the major axis peak-to-peak, `2(r_f + r_b)`, the quantity the API 617 limit
//! `A = 25.4 √(12000/N)` µm (N in rpm) bounds.

use nalgebra::{Complex, DMatrix, DVector};
use serde::{Deserialize, Serialize};

use super::assembly::{NodeDof, ShaftModel};
use super::coupling::System;
use super::error::RotorError;
use crate::model::rotor::Unbalance;

/// API 617 unbalance-response limit (peak-to-peak) [µm] at `speed_rpm`.
#[must_use]
pub fn api617_limit_um(speed_rpm: f64) -> f64 {
    25.4 * (12000.0 / speed_rpm).sqrt()
}

/// Orbit at one node.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Orbit {
    pub node: usize,
    /// Amplitudes [m] and phases [rad] of x and y (`x = |X| cos(Ωt + ∠X)`).
    pub x_amplitude_m: f64,
    pub x_phase_rad: f64,
    pub y_amplitude_m: f64,
    pub y_phase_rad: f64,
    /// Major axis, peak-to-peak [m].
    pub major_pp_m: f64,
    /// Forward radius minus backward radius over their sum (1 circular forward, −1 circular backward).
    pub forward_ratio: f64,
}

impl Orbit {
    #[must_use]
    pub fn from_amplitudes(node: usize, x: Complex<f64>, y: Complex<f64>) -> Self {
        let iy = Complex::new(-y.im, y.re);
        let (rf, rb) = ((x + iy).norm() / 2.0, (x - iy).norm() / 2.0);
        Self {
            node,
            x_amplitude_m: x.norm(),
            x_phase_rad: x.arg(),
            y_amplitude_m: y.norm(),
            y_phase_rad: y.arg(),
            major_pp_m: 2.0 * (rf + rb),
            forward_ratio: if rf + rb > 0.0 { (rf - rb) / (rf + rb) } else { 0.0 },
        }
    }
}

/// The unbalances' complex force amplitudes at spin speed `omega` [rad/s] on a system of `n` coordinates (the
/// nodal forces through the shaft's weights: a reduced shaft's `Tᵀ f`).
#[must_use]
pub fn forces(n: usize, shaft: &ShaftModel, unbalances: &[Unbalance], omega: f64) -> DVector<Complex<f64>> {
    let mut f = DVector::from_element(n, Complex::new(0.0, 0.0));
    for u in unbalances {
        let a = Complex::from_polar(u.amount * omega * omega, u.phase);
        for (j, w) in shaft.weights(u.node, NodeDof::X) {
            f[j] += a * w;
        }
        for (j, w) in shaft.weights(u.node, NodeDof::Y) {
            f[j] += Complex::new(a.im, -a.re) * w;
        }
    }
    f
}

/// Response of `sys` at spin speed `omega` [rad/s] at the given nodes.
///
/// # Errors
/// [`RotorError::SingularResponse`] when the dynamic stiffness is singular.
pub fn response(
    sys: &System,
    shaft: &ShaftModel,
    unbalances: &[Unbalance],
    omega: f64,
    nodes: &[usize],
) -> Result<Vec<Orbit>, RotorError> {
    let n = sys.n_dofs();
    let w2 = omega * omega;
    let z = DMatrix::from_fn(n, n, |i, j| {
        Complex::new(sys.stiffness[(i, j)] - w2 * sys.mass[(i, j)], omega * sys.damping[(i, j)])
    });
    let f = forces(n, shaft, unbalances, omega);
    let x = z.lu().solve(&f).ok_or(RotorError::SingularResponse { speed_rpm: crate::units::RPM.from_si(omega) })?;
    if x.iter().any(|v| !v.re.is_finite() || !v.im.is_finite()) {
        return Err(RotorError::SingularResponse { speed_rpm: crate::units::RPM.from_si(omega) });
    }
    let at = |node, dof| shaft.weights(node, dof).iter().fold(Complex::new(0.0, 0.0), |acc, &(j, w)| acc + x[j] * w);
    Ok(nodes.iter().map(|&node| Orbit::from_amplitudes(node, at(node, NodeDof::X), at(node, NodeDof::Y))).collect())
}
