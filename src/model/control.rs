//! A controller description — sensors, actuators and the control law that closes the loop through the
//! controllable bearing — as the user writes it (the `[control]` section of a rotor file) and validated into
//! SI ([`Control`]). The keys and their ranges are the rows of [`super::control_schema`].
//!
//! ```toml
//! [control]                 # gain (multiplies the whole controller)
//! [[control.sensor]]        # node or bearing, direction = "x" | "y", quantity = "displacement" | "velocity"
//! [[control.actuator]]      # kind = "valve" (bearing) | "force" (node, direction, gain_n_per_v[, natural_frequency_hz,
//!                           #   damping_ratio]); max_voltage_v
//! [[control.loop]]          # one per actuator: actuator, sensor, law = "pd" (kp_v_per_um, kd_v_per_mm_s, rolloff_hz)
//!                           #   | "transfer_function" (numerator, denominator)
//! [control.mimo]            # or: gain matrices kp_v_per_um, kd_v_per_mm_s (a row per actuator), rolloff_hz
//! [control.lqr]             # or: an LQR designed by tiltpad: design_speed_rpm, output_weight (per sensor),
//!                           #   input_weight (per actuator), max_frequency_hz, sensor_noise
//! ```
//!
//! Convention: every law is negative feedback, `u = −gain · K(s) y`, with `u` the actuators' control signals
//! [V] and `y` the sensors' readings (SI inside: m or m/s; the gains are written per µm and per mm/s). A
//! velocity pickup reads `s y`, so a PD loop on it has no proportional term and its roll-off is a low-pass.
//!
//! Validation needs the plant ([`PlantInfo`]: the rotor's nodes and bearing positions, or the rig) and refuses
//! what cannot be a controller: a sensor on a node that does not exist, a valve on a bearing without
//! `[hydraulics]` or a port whose pads have no orifice, NaN gains, an improper transfer function, a controller
//! that is unstable on its own (Routh–Hurwitz on its denominator). A controller that destabilises the rotor is
//! valid: that is a result.

use serde::{Deserialize, Serialize};

use super::error::CaseError;
use super::Case;

// ------------------------------------------------------------------------------------------- file form

/// A direction of the bearing's frame.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Axis {
    X,
    Y,
}

/// What a sensor reads.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Quantity {
    #[default]
    Displacement,
    Velocity,
}

impl Quantity {
    /// The SI value of one unit of a reading as gains and weights take it: µm, or mm/s for a velocity pickup.
    #[must_use]
    pub fn reading_unit(self) -> f64 {
        match self {
            Quantity::Displacement => crate::units::UM.si,
            Quantity::Velocity => crate::units::MM.si,
        }
    }
}

/// `control.actuator[].kind`
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ActuatorWord {
    #[default]
    Valve,
    Force,
}

/// `control.loop[].law`
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum LawWord {
    #[default]
    Pd,
    TransferFunction,
}

/// `[control]` as written.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ControlTable {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub gain: Option<f64>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub sensor: Vec<SensorTable>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub actuator: Vec<ActuatorTable>,
    #[serde(default, rename = "loop", skip_serializing_if = "Vec::is_empty")]
    pub loops: Vec<LoopTable>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mimo: Option<MimoTable>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub lqr: Option<LqrTable>,
}

/// `[[control.sensor]]`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SensorTable {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub node: Option<usize>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub bearing: Option<usize>,
    pub direction: Axis,
    #[serde(default)]
    pub quantity: Quantity,
}

/// `[[control.actuator]]`
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ActuatorTable {
    #[serde(default)]
    pub kind: ActuatorWord,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub bearing: Option<usize>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub node: Option<usize>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub direction: Option<Axis>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub gain_n_per_v: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub natural_frequency_hz: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub damping_ratio: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_voltage_v: Option<f64>,
}

/// `[[control.loop]]`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LoopTable {
    pub actuator: usize,
    pub sensor: usize,
    #[serde(default)]
    pub law: LawWord,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub kp_v_per_um: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub kd_v_per_mm_s: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rolloff_hz: Option<f64>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub numerator: Vec<f64>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub denominator: Vec<f64>,
}

/// `[control.mimo]`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MimoTable {
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub kp_v_per_um: Vec<Vec<f64>>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub kd_v_per_mm_s: Vec<Vec<f64>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rolloff_hz: Option<f64>,
}

/// `[control.lqr]`
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LqrTable {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub design_speed_rpm: Option<f64>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub output_weight: Vec<f64>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub input_weight: Vec<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_frequency_hz: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sensor_noise: Option<f64>,
}

// ---------------------------------------------------------------------------------------------- SI form

/// Where a sensor reads.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum SensorAt {
    /// A rotor node.
    Node(usize),
    /// The journal of a bearing position.
    Journal(usize),
}

/// A sensor: place, direction, what it reads; `node` is the shaft node it reads (a journal's node).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub struct Sensor {
    pub at: SensorAt,
    pub node: usize,
    pub direction: Axis,
    pub quantity: Quantity,
}

/// Second-order dynamics `ω² / (s² + 2ζωs + ω²)`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct SecondOrder {
    pub natural_frequency_rad_s: f64,
    pub damping_ratio: f64,
}

/// What an actuator is.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub enum ActuatorKind {
    /// The valve of the bearing case at position `bearing`.
    Valve { bearing: usize },
    /// A force `gain · G(s) u` [N] on `node` in `direction` (`dynamics` `None`: flat).
    Force { node: usize, direction: Axis, gain_n_per_v: f64, dynamics: Option<SecondOrder> },
}

/// An actuator and its saturation amplitude.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Actuator {
    pub kind: ActuatorKind,
    /// Given amplitude limit [V]; `None`: the valve's small-signal range, or 10 V for a force actuator.
    pub max_voltage_v: Option<f64>,
}

/// A SISO loop's law from its sensor's SI reading (m or m/s) to volts.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub enum Rule {
    /// `K(s) = kp + kd s/(1 + s/ω_f)` on a displacement, `kd/(1 + s/ω_f)` on a velocity [V/m, V·s/m, rad/s];
    /// `rolloff_rad_s` `None`: no roll-off (velocity pickups only).
    Pd { kp: f64, kd: f64, rolloff_rad_s: Option<f64> },
    /// `K(s) = Σ n_i s^i / Σ d_i s^i`, highest power first, denominator's leading coefficient 1.
    TransferFunction { numerator: Vec<f64>, denominator: Vec<f64> },
}

/// One loop: an actuator driven from a sensor.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Loop {
    pub actuator: usize,
    pub sensor: usize,
    pub rule: Rule,
}

/// An LQR to design on the plant's reduced model ([`crate::control::lqr`]): the cost
/// `∫ Σ_s q_s y_s² + Σ_a r_a u_a² dt` with the readings in µm (mm/s) and the signals in volts.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct LqrSpec {
    /// Speed of the plant it is designed on [rad/s]; `None` on the test rig (the case's speed).
    pub design_speed_rad_s: Option<f64>,
    /// `q_s`, one per sensor [per µm² or per (mm/s)²].
    pub output_weight: Vec<f64>,
    /// `r_a`, one per actuator [per V²].
    pub input_weight: Vec<f64>,
    /// The reduced model keeps the modes with `|λ|` below this [rad/s].
    pub max_frequency_rad_s: f64,
    /// The observer's sensor-noise intensity per unit input disturbance [reading unit² per V²].
    pub sensor_noise: f64,
}

/// The control law.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub enum Law {
    /// One loop per actuator, in actuator order.
    Loops(Vec<Loop>),
    /// PD gain matrices (actuators × sensors) [V/m, V·s/m] with one roll-off.
    Mimo { kp: Vec<Vec<f64>>, kd: Vec<Vec<f64>>, rolloff_rad_s: Option<f64> },
    /// A regulator designed by tiltpad with an observer (sensors in, actuators out).
    Lqr(LqrSpec),
}

/// A validated controller [SI].
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Control {
    pub gain: f64,
    pub sensors: Vec<Sensor>,
    pub actuators: Vec<Actuator>,
    pub law: Law,
}

/// What validation needs of the plant: nodes, and per bearing position its node and case (if a case). Of a
/// rotor: `PlantInfo::rotor` (with the rotor, which holds its controller's table).
pub struct PlantInfo<'a> {
    pub n_nodes: usize,
    pub bearings: Vec<(usize, Option<&'a Case>)>,
}

/// A controller in a file of its own (`[control]` and nothing else): the test rig's, closed around the case's
/// one bearing (bearing 0, its journal the only node).
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ControlFile {
    pub control: ControlTable,
}

/// Reads a controller file.
///
/// # Errors
/// TOML syntax, unknown keys and wrong types, naming the key.
pub fn parse_control_file(text: &str) -> Result<ControlFile, CaseError> {
    let table: toml::Table = text.parse().map_err(|e: toml::de::Error| CaseError::Syntax { message: e.to_string() })?;
    serde_path_to_error::deserialize::<_, ControlFile>(toml::Value::Table(table)).map_err(|e| {
        let path = e.path().to_string();
        super::load::schema_error(&path, &e.into_inner().to_string())
    })
}

impl<'a> PlantInfo<'a> {
    /// A bearing case on the test rig: one bearing (position 0) at node 0.
    #[must_use]
    pub fn rig(case: &'a Case) -> Self {
        Self { n_nodes: 1, bearings: vec![(0, Some(case))] }
    }
}

/// Number of roots of `p` (highest power first, `p[0] ≠ 0`) with Re ≥ 0, by the Routh–Hurwitz array: the
/// sign changes in its first column; a zero in the first column (a root on the imaginary axis, or a
/// symmetric pair) counts as at least one.
#[must_use]
pub fn routh_unstable_roots(p: &[f64]) -> usize {
    let n = p.len();
    if n < 2 {
        return 0;
    }
    let mut rows: Vec<Vec<f64>> =
        vec![p.iter().step_by(2).copied().collect(), p.iter().skip(1).step_by(2).copied().collect()];
    let width = rows[0].len();
    rows[1].resize(width, 0.0);
    for _ in 2..n {
        let (a, b) = (&rows[rows.len() - 2], &rows[rows.len() - 1]);
        if b[0] == 0.0 {
            return 1.max(count_changes(&rows));
        }
        let next: Vec<f64> = (0..width)
            .map(|j| {
                let a1 = a.get(j + 1).copied().unwrap_or(0.0);
                let b1 = b.get(j + 1).copied().unwrap_or(0.0);
                (b[0] * a1 - a[0] * b1) / b[0]
            })
            .collect();
        rows.push(next);
    }
    if rows.last().is_some_and(|r| r[0] == 0.0) {
        return 1.max(count_changes(&rows));
    }
    count_changes(&rows)
}

fn count_changes(rows: &[Vec<f64>]) -> usize {
    let col: Vec<f64> = rows.iter().map(|r| r[0]).filter(|v| *v != 0.0).collect();
    col.windows(2).filter(|w| w[0].signum() != w[1].signum()).count()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn routh_counts_the_right_half_plane_roots() {
        // (s + 1)(s + 2)(s + 3) = s³ + 6s² + 11s + 6: stable
        assert_eq!(routh_unstable_roots(&[1.0, 6.0, 11.0, 6.0]), 0);
        // (s − 1)(s + 2) = s² + s − 2: one
        assert_eq!(routh_unstable_roots(&[1.0, 1.0, -2.0]), 1);
        // s² − 2s + 5 (1 ± 2i): two
        assert_eq!(routh_unstable_roots(&[1.0, -2.0, 5.0]), 2);
        // s² + 4 (±2i, on the axis): counted
        assert!(routh_unstable_roots(&[1.0, 0.0, 4.0]) >= 1);
        // s (a pole at 0): counted
        assert!(routh_unstable_roots(&[1.0, 0.0]) >= 1);
        // first order
        assert_eq!(routh_unstable_roots(&[1.0, 5.0]), 0);
        assert_eq!(routh_unstable_roots(&[2.0]), 0);
        // (s + 1)⁴ and (s − 0.5)(s + 1)³
        assert_eq!(routh_unstable_roots(&[1.0, 4.0, 6.0, 4.0, 1.0]), 0);
        assert_eq!(routh_unstable_roots(&[1.0, 2.5, 1.5, -0.5, -0.5]), 1);
    }
}
