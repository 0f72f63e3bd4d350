//! Closing the loop: the plant ([`super::plant::Plant`]) with the controller ([`super::law`]) under the loop
//! gain `g`, `u = −g (C_c x_c + D_c y)`:
//!
//! ```text
//! d/dt [x_p; x_c] = [[A_p − g B_p D_c C_p, −g B_p C_c], [B_c C_p, A_c]] [x_p; x_c]
//! ```
//!
//! The same system with the loop broken at one actuator's input ([`broken`]): that actuator driven by an
//! outside signal `w`, the others still closed, the output `z = g (C_c x_c + D_c y)` the signal the
//! controller would send it. Closing `w = −z` gives the closed loop back (`A − B C`), and `L(s) = z/w` is the
//! loop transfer at that valve's input whose Nyquist plot [`super::nyquist`] reads.
//!
//! [`Poles`]: every eigenvalue of the closed loop; the oscillatory ones (Im > 0) are its damped modes —
//! rotor, actuator and controller alike — with their logarithmic decrements.

use nalgebra::{DMatrix, DVector};
use serde::{Deserialize, Serialize};

use super::error::ControlError;
use super::plant::Plant;
use super::state_space::{eigenvalues, StateSpace, C64};

/// One oscillatory closed-loop pole.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Pole {
    pub real_per_s: f64,
    pub imag_rad_s: f64,
    /// Logarithmic decrement `−2π Re/Im` (negative: unstable).
    pub log_dec: f64,
    pub damping_ratio: f64,
}

impl Pole {
    #[must_use]
    pub fn frequency_hz(&self) -> f64 {
        self.imag_rad_s / std::f64::consts::TAU
    }
}

/// The closed loop's poles at one speed and gain.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Poles {
    /// Oscillatory poles (Im > 0), ascending in frequency.
    pub modes: Vec<Pole>,
    /// Largest real part over the real poles [1/s].
    pub max_real_overdamped: Option<f64>,
}

impl Poles {
    /// From eigenvalues.
    #[must_use]
    pub fn of(values: &[C64]) -> Self {
        let mut modes = Vec::new();
        let mut max_real: Option<f64> = None;
        for l in values {
            let mag = l.norm();
            if l.im.abs() <= 1e-9 * mag.max(1e-12) {
                max_real = Some(max_real.map_or(l.re, |m: f64| m.max(l.re)));
            } else if l.im > 0.0 {
                modes.push(Pole {
                    real_per_s: l.re,
                    imag_rad_s: l.im,
                    log_dec: -std::f64::consts::TAU * l.re / l.im,
                    damping_ratio: -l.re / mag,
                });
            }
        }
        modes.sort_by(|a, b| a.imag_rad_s.total_cmp(&b.imag_rad_s));
        Self { modes, max_real_overdamped: max_real }
    }

    /// Smallest logarithmic decrement (−∞ when a real pole is positive).
    #[must_use]
    pub fn min_log_dec(&self) -> f64 {
        if self.max_real_overdamped.is_some_and(|r| r > 0.0) {
            return f64::NEG_INFINITY;
        }
        self.modes.iter().map(|m| m.log_dec).fold(f64::INFINITY, f64::min)
    }

    /// Stable: every pole in the open left half-plane.
    #[must_use]
    pub fn stable(&self) -> bool {
        self.min_log_dec() > 0.0
    }

    /// Poles with Re ≥ 0, counting each complex pair twice.
    #[must_use]
    pub fn unstable_count(values: &[C64]) -> usize {
        values.iter().filter(|l| l.re >= 0.0).count()
    }
}

/// The loop broken at actuator `at`'s input (`w` in, `z` out; SISO).
#[must_use]
pub fn broken(plant: &Plant, controller: &StateSpace, gain: f64, at: usize) -> StateSpace {
    let p = &plant.ss;
    let (np, nc) = (p.states(), controller.states());
    let n = np + nc;
    // the other actuators' columns close through −g
    let mut bp_closed = p.b.clone();
    bp_closed.column_mut(at).fill(0.0);
    let mut a = DMatrix::zeros(n, n);
    let dc_cp = &controller.d * &p.c;
    a.view_mut((0, 0), (np, np)).copy_from(&(&p.a - &bp_closed * &dc_cp * gain));
    a.view_mut((0, np), (np, nc)).copy_from(&(-(&bp_closed * &controller.c) * gain));
    a.view_mut((np, 0), (nc, np)).copy_from(&(&controller.b * &p.c));
    a.view_mut((np, np), (nc, nc)).copy_from(&controller.a);
    let mut b = DMatrix::zeros(n, 1);
    b.view_mut((0, 0), (np, 1)).copy_from(&p.b.column(at));
    let mut c = DMatrix::zeros(1, n);
    c.view_mut((0, 0), (1, np)).copy_from(&(dc_cp.row(at) * gain));
    c.view_mut((0, np), (1, nc)).copy_from(&(controller.c.row(at) * gain));
    StateSpace { a, b, c, d: DMatrix::zeros(1, 1) }
}

/// The closed loop's state matrix.
#[must_use]
pub fn closed(plant: &Plant, controller: &StateSpace, gain: f64) -> DMatrix<f64> {
    if plant.ss.b.ncols() == 0 {
        return plant.ss.a.clone();
    }
    let l = broken(plant, controller, gain, 0);
    &l.a - &l.b * &l.c
}

/// The closed loop's poles.
///
/// # Errors
/// [`ControlError::Eigen`].
pub fn poles(plant: &Plant, controller: &StateSpace, gain: f64) -> Result<Poles, ControlError> {
    Ok(Poles::of(&eigenvalues(&closed(plant, controller, gain))?))
}

/// A steady harmonic response of the closed loop.
#[derive(Debug, Clone, PartialEq)]
pub struct Forced {
    /// System coordinates `u` (complex amplitudes).
    pub coordinates: DVector<C64>,
    /// Each actuator's signal [V].
    pub signals: Vec<C64>,
    /// Per actuator, per port, the nozzle-end pressure [Pa].
    pub pressures: Vec<Vec<C64>>,
}

/// The closed loop's response at `s = iω` to the generalised forces `f` (complex amplitudes on the system's
/// coordinates).
///
/// # Errors
/// [`ControlError::Singular`].
pub fn forced(
    plant: &Plant,
    controller: &StateSpace,
    gain: f64,
    omega: f64,
    f: &DVector<C64>,
) -> Result<Forced, ControlError> {
    let a = closed(plant, controller, gain);
    let (np, n) = (plant.ss.states(), a.nrows());
    let s = C64::new(0.0, omega);
    let m = DMatrix::from_fn(n, n, |i, j| if i == j { s - a[(i, j)] } else { C64::from(-a[(i, j)]) });
    let mut rhs = DVector::zeros(n);
    let force = plant.force.map(C64::from);
    rhs.rows_mut(0, np).copy_from(&(force * f));
    let singular = || ControlError::Singular { speed_rpm: crate::units::RPM.from_si(omega) };
    let x = m.lu().solve(&rhs).ok_or_else(singular)?;
    if x.iter().any(|v| !v.re.is_finite() || !v.im.is_finite()) {
        return Err(singular());
    }
    let xp = x.rows(0, np).into_owned();
    let xc = x.rows(np, n - np).into_owned();
    let y = plant.ss.c.map(C64::from) * &xp;
    let v = controller.c.map(C64::from) * xc + controller.d.map(C64::from) * y;
    let signals = v.iter().map(|z| -z * gain).collect();
    let pressures = plant.nozzle_pressure.iter().map(|ports| ports.iter().map(|&i| xp[i]).collect()).collect();
    Ok(Forced { coordinates: plant.coordinates.map(C64::from) * xp, signals, pressures })
}
