//! The test rig with its loop closed: the journal free vertically on the rig's support (docs/MODEL.md §9,
//! configuration 2), its vertical displacement `y` fed back through a controller `K(s)` to the bearing's
//! valve, and the rig's calibrated shaker pushing on the journal with a force `F`.
//!
//! With the FRF stage's two transfers on the rig ([`crate::bearing::frf::dynamics::BearingDynamics::shaker`]:
//! `P(s) = y/u` through valve, lines, nozzles and film, the *pseudo* FRF; `H(s) = y/F`, the *direct* one) and
//! the loop `u = −g K(s) y` (negative feedback, [`crate::model::control`]):
//!
//! ```text
//! y = P u + H F = −g K P y + H F     ⇒     X/F (closed) = H / (1 + g K P),     u/F = −g K · X/F (closed)
//! ```
//!
//! exact in the FRF stage's distributed lines. The same loop in state space (the valve chain in lumped
//! segments, [`super::plant`]) gives the closed loop's poles — whether the loop is stable — and a second path
//! to the same X/F (a test holds the two together).

use nalgebra::DMatrix;
use serde::{Deserialize, Serialize};

use super::closed_loop::{closed, forced, Poles};
use super::error::ControlError;
use super::law::design;
use super::plant::{ActuatorPlant, Plant, ValvePlant};
use super::state_space::{eigenvalues, StateSpace, C64};
use crate::bearing::frf::dynamics::{BearingDynamics, Hydraulics, Rig};
use crate::bearing::frf::model::FrfModel;
use crate::model::control::{ActuatorKind, Axis, Control, Quantity, Sensor};
use crate::model::Case;
use crate::physics::hydraulics::servovalve::SMALL_SIGNAL_FRACTION;
use crate::rotor::coupling::System;

/// The closed loop's X/F at one frequency.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct RigPoint {
    pub frequency_hz: f64,
    /// X/F with the loop open [m/N], magnitude and phase [deg].
    pub open_m_per_n: f64,
    pub open_phase_deg: f64,
    /// X/F with the loop closed [m/N], magnitude and phase [deg].
    pub closed_m_per_n: f64,
    pub closed_phase_deg: f64,
    /// The valve signal the closed loop sends per newton of shaker force [V/N].
    pub signal_v_per_n: f64,
}

/// The rig, its bearing linearised, and the controller.
pub struct RigLoop {
    dynamics: BearingDynamics,
    hydraulics: Hydraulics,
    rig: Rig,
    controller: StateSpace,
    gain: f64,
    /// The sensor reads a velocity (`K` then acts on `s y`).
    velocity: bool,
    /// The loop in state space (journal y and the pad coordinates, x held).
    plant: Plant,
    /// The valve's small-signal range [V] (the actuator's `max_voltage_v`, else the valve's).
    limit_v: f64,
}

/// The rig's loop over a band: what `tiltpad frf --control` writes and the Control view draws.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RigSweep {
    pub gain: f64,
    /// Stable by the closed loop's eigenvalues (lines in lumped segments).
    pub stable: bool,
    pub min_log_dec: f64,
    /// The valve's small-signal range [V].
    pub limit_v: f64,
    pub points: Vec<RigPoint>,
}

impl RigSweep {
    /// The largest X/F over the band [m/N] and its frequency [Hz], loop open or closed.
    #[must_use]
    pub fn peak(&self, closed: bool) -> (f64, f64) {
        self.points
            .iter()
            .map(|p| (if closed { p.closed_m_per_n } else { p.open_m_per_n }, p.frequency_hz))
            .fold((0.0, 0.0), |a, b| if b.0 > a.0 { b } else { a })
    }

    /// The largest valve signal per shaker force over the band [V/N].
    #[must_use]
    pub fn signal_v_per_n(&self) -> f64 {
        self.points.iter().map(|p| p.signal_v_per_n).fold(0.0, f64::max)
    }
}

impl RigLoop {
    /// The rig of `case` (its `[hydraulics.rig]`) linearised by the FRF stage (`frf`), closed through
    /// `control`: one sensor on the journal's vertical motion, one valve actuator.
    ///
    /// # Errors
    /// [`ControlError::NotARigLoop`] for another controller layout; [`ControlError::NoController`] without
    /// `[hydraulics]` or `[hydraulics.rig]`.
    pub fn new(case: &Case, frf: &FrfModel, control: &Control) -> Result<Self, ControlError> {
        let h =
            case.hydraulics.as_ref().ok_or(ControlError::NotARigLoop { what: "[hydraulics] with [hydraulics.rig]" })?;
        let r = h.rig.ok_or(ControlError::NotARigLoop { what: "[hydraulics.rig] (the rig's mass and support)" })?;
        let [sensor] = control.sensors.as_slice() else {
            return Err(ControlError::NotARigLoop { what: "exactly one control.sensor" });
        };
        if sensor.direction != Axis::Y {
            return Err(ControlError::NotARigLoop { what: "control.sensor[0].direction = \"y\" (the rig's free DOF)" });
        }
        let [actuator] = control.actuators.as_slice() else {
            return Err(ControlError::NotARigLoop { what: "exactly one control.actuator" });
        };
        if !matches!(actuator.kind, ActuatorKind::Valve { bearing: 0 }) {
            return Err(ControlError::NotARigLoop { what: "control.actuator[0].kind = \"valve\" on bearing 0" });
        }
        let rig = Rig { mass: r.mass_kg, stiffness: r.support_stiffness_n_per_m, damping: r.support_damping_ns_per_m };
        let hydraulics = frf.hydraulics(h);
        let plant = rig_plant(&frf.dynamics, &hydraulics, rig, sensor)?;
        let limit_v = actuator.max_voltage_v.unwrap_or(h.valve.full_scale_v * SMALL_SIGNAL_FRACTION);
        // an LQR on the rig is designed at the case's own speed
        let (controller, _) = design(control, |_| Ok((plant.clone(), case.operating.speed_rad_s)))?;
        Ok(Self {
            dynamics: frf.dynamics.clone(),
            hydraulics,
            rig,
            controller,
            gain: control.gain,
            velocity: sensor.quantity == Quantity::Velocity,
            plant,
            limit_v,
        })
    }

    /// X/F open and closed at each of `freqs` [Hz] (a frequency where a transfer is singular is left out),
    /// with the loop's stability.
    ///
    /// # Errors
    /// [`ControlError::Eigen`].
    pub fn sweep(&self, freqs: &[f64]) -> Result<RigSweep, ControlError> {
        let poles = self.poles()?;
        Ok(RigSweep {
            gain: self.gain,
            stable: poles.stable(),
            min_log_dec: poles.min_log_dec(),
            limit_v: self.limit_v,
            points: freqs.iter().filter_map(|&f| self.at(f)).collect(),
        })
    }

    /// X/F open and closed at `frequency_hz` (`None` where a transfer is singular).
    #[must_use]
    pub fn at(&self, frequency_hz: f64) -> Option<RigPoint> {
        let p = self.dynamics.shaker(&self.hydraulics, self.rig, frequency_hz)?;
        let s = C64::new(0.0, std::f64::consts::TAU * frequency_hz);
        let reading = if self.velocity { s } else { C64::from(1.0) };
        let k = self.controller.response(s)?[(0, 0)] * reading * self.gain;
        let closed = p.direct / (C64::from(1.0) + k * p.pseudo);
        let deg = |z: C64| z.arg().to_degrees();
        Some(RigPoint {
            frequency_hz,
            open_m_per_n: p.direct.norm(),
            open_phase_deg: deg(p.direct),
            closed_m_per_n: closed.norm(),
            closed_phase_deg: deg(closed),
            signal_v_per_n: (k * closed).norm(),
        })
    }

    /// The closed loop's poles (state space, lines in lumped segments).
    ///
    /// # Errors
    /// [`ControlError::Eigen`].
    pub fn poles(&self) -> Result<Poles, ControlError> {
        Ok(Poles::of(&eigenvalues(&closed(&self.plant, &self.controller, self.gain))?))
    }

    /// X/F of the closed loop in state space at `frequency_hz` [m/N] (the second path).
    ///
    /// # Errors
    /// [`ControlError::Singular`].
    pub fn state_space_at(&self, frequency_hz: f64) -> Result<C64, ControlError> {
        let n = self.plant.coordinates.nrows();
        let mut f = nalgebra::DVector::zeros(n);
        f[0] = C64::from(1.0);
        let omega = std::f64::consts::TAU * frequency_hz;
        Ok(forced(&self.plant, &self.controller, self.gain, omega, &f)?.coordinates[0])
    }
}

/// The rig in state space: coordinates journal y (with the rig's mass, support stiffness and damping) and
/// every pad coordinate (journal x held), the valve chain acting through the nozzle–film coupling, `sensor`
/// on the journal's y.
///
/// # Errors
/// A singular mass matrix.
pub fn rig_plant(
    d: &BearingDynamics,
    hydraulics: &Hydraulics,
    rig: Rig,
    sensor: &Sensor,
) -> Result<Plant, ControlError> {
    let n = d.k.nrows();
    let sub = |m: &DMatrix<f64>| DMatrix::from_fn(n - 1, n - 1, |i, j| m[(i + 1, j + 1)]);
    let mut sys =
        System { n_shaft: n - 1, appended: Vec::new(), mass: sub(&d.m), damping: sub(&d.c), stiffness: sub(&d.k) };
    sys.mass[(0, 0)] += rig.mass;
    sys.damping[(0, 0)] += rig.damping;
    sys.stiffness[(0, 0)] += rig.stiffness;
    let coordinates = (0..n).map(|c| if c == 0 { None } else { Some(vec![(c - 1, 1.0)]) }).collect();
    let act = vec![ActuatorPlant::Valve(Box::new(ValvePlant {
        hydraulics: hydraulics.clone(),
        coupling: d.coupling.clone(),
        coordinates,
    }))];
    Plant::new(&sys, &|_, _| vec![(0, 1.0)], std::slice::from_ref(sensor), &act)
}
