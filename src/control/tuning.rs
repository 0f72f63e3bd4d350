//! The loop closed again on plants already built: what a designer's gain change costs once the bearings are
//! solved. A [`PlantSweep`] keeps the plant of every speed of a sweep ([`super::plant::Plant`]: the rotor with
//! its bearings and valve chains linearised there) and the unbalance forces; closing it through another
//! controller or loop gain is then linear algebra only — one eigen-solution and one complex solve per speed,
//! no bearing solve:
//!
//! - [`PlantSweep::at`]: the closed loop's poles and unbalance response at one speed of the sweep;
//! - [`onset_on_grid`]: the first stable → unstable crossing of the smallest logarithmic decrement, linearly
//!   interpolated between the two speeds of the sweep that bracket it (the CLI refines the same bracket by
//!   bisection with new bearing solves; on a grid of 25 speeds the two agree to a fraction of the grid step);
//! - [`root_locus`]: the closed-loop poles at one speed over a list of loop gains.
//!
//! The Control view calls these as its sliders move; `tiltpad control --root-locus` writes the locus.

use nalgebra::{Complex, DVector};
use serde::{Deserialize, Serialize};

use super::closed_loop::{closed, forced, Poles};
use super::error::ControlError;
use super::plant::Plant;
use super::state_space::{eigenvalues, StateSpace, C64};
use crate::rotor::assembly::Weights;
use crate::rotor::unbalance::Orbit;

/// The plants of a speed sweep and what the unbalance response reads from them.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct PlantSweep {
    /// Spin speeds [rad/s], ascending.
    pub speeds_rad_s: Vec<f64>,
    pub plants: Vec<Plant>,
    /// Per speed, the unbalance forces on the system's coordinates (`None`: no unbalance, or speed 0).
    pub(super) forces: Vec<Option<DVector<C64>>>,
    /// The response nodes with the weights of their x and y displacements over the system's coordinates.
    pub(super) nodes: Vec<(usize, Weights, Weights)>,
    /// Each actuator's linear range [V].
    pub limits_v: Vec<f64>,
}

/// The closed loop at one speed of a sweep, at one controller and gain.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct TunedSpeed {
    pub speed_rad_s: f64,
    pub poles: Poles,
    /// Unbalance response orbits at the response nodes (empty without unbalance).
    pub orbits: Vec<Orbit>,
    /// Each actuator's signal amplitude in that response [V].
    pub signal_v: Vec<f64>,
}

impl PlantSweep {
    /// Speeds in the sweep.
    #[must_use]
    pub fn len(&self) -> usize {
        self.plants.len()
    }

    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.plants.is_empty()
    }

    /// The response nodes, ascending.
    #[must_use]
    pub fn response_nodes(&self) -> Vec<usize> {
        self.nodes.iter().map(|n| n.0).collect()
    }

    /// The loop closed through `controller` at `gain`, at speed `i` of the sweep.
    ///
    /// # Errors
    /// [`ControlError::Eigen`], [`ControlError::Singular`].
    pub fn at(&self, i: usize, controller: &StateSpace, gain: f64) -> Result<TunedSpeed, ControlError> {
        let plant = &self.plants[i];
        let omega = self.speeds_rad_s[i];
        let poles = Poles::of(&eigenvalues(&closed(plant, controller, gain))?);
        let (orbits, signal_v) = match &self.forces[i] {
            Some(f) => {
                let r = forced(plant, controller, gain, omega, f)?;
                let at = |w: &Weights| w.iter().fold(Complex::new(0.0, 0.0), |acc, &(j, c)| acc + r.coordinates[j] * c);
                let orbits =
                    self.nodes.iter().map(|(node, x, y)| Orbit::from_amplitudes(*node, at(x), at(y))).collect();
                (orbits, r.signals.iter().map(|z| z.norm()).collect())
            }
            None => (Vec::new(), Vec::new()),
        };
        Ok(TunedSpeed { speed_rad_s: omega, poles, orbits, signal_v })
    }
}

/// The first stable → unstable crossing of `min_log_dec` over `speeds` [rad/s], linearly interpolated in
/// the bracketing interval (the midpoint when a decrement there is −∞: a real pole crossed).
#[must_use]
pub fn onset_on_grid(speeds: &[f64], min_log_dec: &[f64]) -> Option<f64> {
    let i = min_log_dec.windows(2).position(|w| w[0] > 0.0 && w[1] <= 0.0)?;
    let (d0, d1) = (min_log_dec[i], min_log_dec[i + 1]);
    let (w0, w1) = (speeds[i], speeds[i + 1]);
    if d0.is_finite() && d1.is_finite() && d0 > d1 {
        Some(w0 + (w1 - w0) * d0 / (d0 - d1))
    } else {
        Some(0.5 * (w0 + w1))
    }
}

/// The closed-loop poles at one speed over a range of loop gains.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RootLocus {
    pub speed_rad_s: f64,
    pub gains: Vec<f64>,
    /// Per gain, the poles kept: `[Re [1/s], Im [Hz]]`, oscillatory ones with `0 < Im ≤ max_hz` and real ones
    /// with `|Re| ≤ 2π max_hz` (the valve's and the lines' fast poles left out).
    pub poles: Vec<Vec<[f64; 2]>>,
    /// The band kept [Hz].
    pub max_hz: f64,
}

/// The root locus of `plant` through `controller` over `gains`, poles up to `max_hz`.
///
/// # Errors
/// [`ControlError::Eigen`].
pub fn root_locus(
    plant: &Plant,
    controller: &StateSpace,
    speed_rad_s: f64,
    gains: &[f64],
    max_hz: f64,
) -> Result<RootLocus, ControlError> {
    let top = std::f64::consts::TAU * max_hz;
    let mut poles = Vec::with_capacity(gains.len());
    for &g in gains {
        let values = eigenvalues(&closed(plant, controller, g))?;
        let mut kept: Vec<[f64; 2]> = values
            .iter()
            .filter(|l| {
                let real = l.im.abs() <= 1e-9 * l.norm().max(1e-12);
                (real && l.re.abs() <= top) || (!real && l.im > 0.0 && l.im <= top)
            })
            .map(|l| [l.re, if l.im > 0.0 { l.im / std::f64::consts::TAU } else { 0.0 }])
            .collect();
        kept.sort_by(|a, b| a[1].total_cmp(&b[1]).then(a[0].total_cmp(&b[0])));
        poles.push(kept);
    }
    Ok(RootLocus { speed_rad_s, gains: gains.to_vec(), poles, max_hz })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The onset lies where the straight line through the bracketing decrements crosses zero: δ = 0.2 at
    /// 100 rad/s and −0.2 at 200 rad/s cross at 150; δ = 0.1 and −0.3 at 125; none when stable throughout;
    /// the first crossing when there are two.
    #[test]
    fn onset_on_the_grid_is_the_interpolated_crossing() {
        let w = [0.0, 100.0, 200.0, 300.0];
        assert_eq!(onset_on_grid(&w, &[1.0, 0.2, -0.2, -1.0]), Some(150.0));
        assert_eq!(onset_on_grid(&w, &[1.0, 0.1, -0.3, -1.0]), Some(125.0));
        assert_eq!(onset_on_grid(&w, &[1.0, 0.5, 0.3, 0.1]), None);
        assert_eq!(onset_on_grid(&w, &[0.4, -0.4, 0.2, -0.2]), Some(50.0));
        assert_eq!(onset_on_grid(&w, &[0.4, f64::NEG_INFINITY, 0.2, 0.1]), Some(50.0));
    }
}
