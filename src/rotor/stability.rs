//! Stability against speed: damped modes at each speed of a sweep (the bearing coefficients recomputed at
//! each speed by the caller's provider) and the instability onset speed.
//!
//! The system is stable at Ω when every oscillatory mode has a positive logarithmic decrement and no real
//! eigenvalue is positive. The onset speed is the first speed of the sweep where the smallest decrement
//! changes sign, located by bisection on the speed (each probe a new eigen-solution with the provider's
//! coefficients at that speed) until the bracket is narrower than `tol` relative.

use serde::{Deserialize, Serialize};

use super::assembly::ShaftModel;
use super::coupling::{assemble, BearingCoefficients};
use super::eigen::{damped_modes, Modes};
use super::error::RotorError;

/// Bearing coefficients at a spin speed [rad/s], one per bearing position.
pub type Provider<'a> = dyn FnMut(f64) -> Result<Vec<BearingCoefficients>, RotorError> + 'a;

/// Modes at one speed.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SpeedPoint {
    pub speed_rad_s: f64,
    pub modes: Modes,
}

impl SpeedPoint {
    /// Smallest logarithmic decrement (−∞ when a real eigenvalue is positive; +∞ without modes).
    #[must_use]
    pub fn min_log_dec(&self) -> f64 {
        if self.modes.max_real_overdamped.is_some_and(|r| r > 0.0) {
            return f64::NEG_INFINITY;
        }
        self.modes.modes.iter().map(|m| m.log_dec).fold(f64::INFINITY, f64::min)
    }
}

/// Damped modes at one speed.
///
/// # Errors
/// The provider's errors and the eigen-solution's.
pub fn modes_at(
    shaft: &ShaftModel,
    nodes: &[usize],
    provider: &mut Provider<'_>,
    omega: f64,
) -> Result<SpeedPoint, RotorError> {
    let coeffs = provider(omega)?;
    let sys = assemble(shaft, nodes, &coeffs, omega);
    Ok(SpeedPoint { speed_rad_s: omega, modes: damped_modes(&sys, shaft)? })
}

/// Onset search result.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Onset {
    /// Onset speed [rad/s].
    pub speed_rad_s: f64,
    /// Final bracket width [rad/s].
    pub bracket_rad_s: f64,
    pub probes: usize,
}

/// First stable → unstable crossing in a sweep (sorted by speed), refined by bisection to `tol` relative.
/// `None` when the sweep has no such crossing (stable throughout, or unstable from its first speed).
///
/// # Errors
/// The provider's errors and the eigen-solution's.
pub fn onset(
    shaft: &ShaftModel,
    nodes: &[usize],
    provider: &mut Provider<'_>,
    sweep: &[SpeedPoint],
    tol: f64,
) -> Result<Option<Onset>, RotorError> {
    let Some(i) = sweep.windows(2).position(|w| w[0].min_log_dec() > 0.0 && w[1].min_log_dec() <= 0.0) else {
        return Ok(None);
    };
    let (mut lo, mut hi) = (sweep[i].speed_rad_s, sweep[i + 1].speed_rad_s);
    let mut probes = 0;
    while hi - lo > tol * hi && probes < 60 {
        let mid = 0.5 * (lo + hi);
        if modes_at(shaft, nodes, provider, mid)?.min_log_dec() > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
        probes += 1;
    }
    Ok(Some(Onset { speed_rad_s: 0.5 * (lo + hi), bracket_rad_s: hi - lo, probes }))
}
