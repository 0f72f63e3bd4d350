//! Validation of a controller description ([`super::control::ControlTable::resolve`]): every key checked
//! against its row in [`super::control_schema`], the sensors, actuators and law checked against the plant
//! ([`PlantInfo`]), converted to SI ([`Control`]). Errors name the key, the value and the allowed range.

use super::control::routh_unstable_roots;
use super::control::{
    Actuator, ActuatorKind, ActuatorWord, Control, ControlTable, Law, LawWord, Loop, LoopTable, LqrSpec, LqrTable,
    MimoTable, PlantInfo, Quantity, Rule, SecondOrder, Sensor, SensorAt,
};
use super::control_schema::control_row as row;
use super::error::{CaseError, Inconsistency, Range};
use super::hydraulics::ValvePort;
use super::Case;

/// The row of a controller key, found while compiling.
macro_rules! control_key {
    ($key:literal) => {
        const { row($key) }
    };
}

fn index(key: &str, value: usize, count: usize) -> Result<usize, CaseError> {
    if value < count {
        Ok(value)
    } else {
        #[allow(clippy::cast_precision_loss)]
        Err(CaseError::OutOfRange {
            key: key.into(),
            value: value as f64,
            allowed: if count == 0 {
                "none (the list is empty)".into()
            } else {
                format!("integer in [0, {}]", count - 1)
            },
        })
    }
}

/// A polynomial as written (`key`: its key for errors), finite, leading zeros removed.
fn polynomial(key: &str, coefficients: &[f64]) -> Result<Vec<f64>, CaseError> {
    for (i, &c) in coefficients.iter().enumerate() {
        Range::closed(-1e300, 1e300).check(&format!("{key}[{i}]"), c)?;
    }
    let first = coefficients.iter().position(|c| *c != 0.0).unwrap_or(coefficients.len());
    Ok(coefficients[first..].to_vec())
}

impl ControlTable {
    /// Validates and converts to SI for the rotor described by `info`.
    ///
    /// # Errors
    /// The first invalid value, named by its key, with the value and the allowed range.
    #[allow(clippy::too_many_lines)]
    pub fn resolve(&self, info: &PlantInfo<'_>) -> Result<Control, CaseError> {
        let gain = control_key!("control.gain").value(self.gain)?;
        if self.sensor.is_empty() || self.actuator.is_empty() {
            let key = if self.sensor.is_empty() { "control.sensor" } else { "control.actuator" };
            return Err(CaseError::inconsistent(key, Inconsistency::NothingToControl));
        }
        let n_bearings = info.bearings.len();
        let mut sensors = Vec::new();
        for (i, s) in self.sensor.iter().enumerate() {
            let key = |k: &str| format!("control.sensor[{i}].{k}");
            let (at, node) = match (s.node, s.bearing) {
                (Some(n), None) => (SensorAt::Node(index(&key("node"), n, info.n_nodes)?), n),
                (None, Some(b)) => {
                    let b = index(&key("bearing"), b, n_bearings)?;
                    (SensorAt::Journal(b), info.bearings[b].0)
                }
                _ => return Err(CaseError::inconsistent(key("node"), Inconsistency::SensorPlace)),
            };
            sensors.push(Sensor { at, node, direction: s.direction, quantity: s.quantity });
        }
        let mut actuators = Vec::new();
        for (i, a) in self.actuator.iter().enumerate() {
            let key = |k: &str| format!("control.actuator[{i}].{k}");
            let max_voltage_v = control_key!("control.actuator[].max_voltage_v")
                .optional(a.max_voltage_v)
                .map_err(|e| at_index(e, &key("max_voltage_v")))?;
            let kind = match a.kind {
                ActuatorWord::Valve => {
                    let b = a.bearing.ok_or_else(|| {
                        CaseError::missing(key("bearing"), "the bearing whose valve this actuator drives")
                    })?;
                    let b = index(&key("bearing"), b, n_bearings)?;
                    valve_bearing(&key("bearing"), b, info.bearings[b].1)?;
                    if let Some(first) =
                        actuators.iter().position(|x: &Actuator| x.kind == ActuatorKind::Valve { bearing: b })
                    {
                        return Err(CaseError::inconsistent(
                            key("bearing"),
                            Inconsistency::ValveTwice { bearing: b, first },
                        ));
                    }
                    ActuatorKind::Valve { bearing: b }
                }
                ActuatorWord::Force => {
                    let node =
                        a.node.ok_or_else(|| CaseError::missing(key("node"), "the node a force actuator pushes"))?;
                    let direction =
                        a.direction.ok_or_else(|| CaseError::missing(key("direction"), "the direction it pushes"))?;
                    let g = a.gain_n_per_v.ok_or_else(|| CaseError::missing(key("gain_n_per_v"), "force per volt"))?;
                    let dynamics = match a.natural_frequency_hz {
                        None => None,
                        Some(f) => Some(SecondOrder {
                            natural_frequency_rad_s: control_key!("control.actuator[].natural_frequency_hz")
                                .value_at(&key("natural_frequency_hz"), Some(f))?,
                            damping_ratio: control_key!("control.actuator[].damping_ratio")
                                .value_at(&key("damping_ratio"), a.damping_ratio)?,
                        }),
                    };
                    ActuatorKind::Force {
                        node: index(&key("node"), node, info.n_nodes)?,
                        direction,
                        gain_n_per_v: control_key!("control.actuator[].gain_n_per_v")
                            .value_at(&key("gain_n_per_v"), Some(g))?,
                        dynamics,
                    }
                }
            };
            actuators.push(Actuator { kind, max_voltage_v });
        }
        let given: Vec<String> = [
            (!self.loops.is_empty()).then(|| "[[control.loop]]".to_string()),
            self.mimo.is_some().then(|| "[control.mimo]".to_string()),
            self.lqr.is_some().then(|| "[control.lqr]".to_string()),
        ]
        .into_iter()
        .flatten()
        .collect();
        if given.len() != 1 {
            return Err(CaseError::inconsistent("control", Inconsistency::ControlLaw { given }));
        }
        let law = if let Some(m) = &self.mimo {
            resolve_mimo(m, &sensors, actuators.len())?
        } else if let Some(l) = &self.lqr {
            Law::Lqr(resolve_lqr(l, sensors.len(), actuators.len())?)
        } else {
            Law::Loops(resolve_loops(&self.loops, &sensors, actuators.len())?)
        };
        Ok(Control { gain, sensors, actuators, law })
    }
}

/// `e` (an error at a row's key) at the indexed key `key`.
fn at_index(e: CaseError, key: &str) -> CaseError {
    match e {
        CaseError::OutOfRange { value, allowed, .. } => CaseError::OutOfRange { key: key.into(), value, allowed },
        other => other,
    }
}

/// Checks that bearing position `b` holds a case whose valve feeds, through each port, a pad with an orifice.
fn valve_bearing(key: &str, b: usize, case: Option<&Case>) -> Result<(), CaseError> {
    let case = case.ok_or_else(|| CaseError::inconsistent(key, Inconsistency::BearingWithoutCase { bearing: b }))?;
    let h = case
        .hydraulics
        .as_ref()
        .ok_or_else(|| CaseError::inconsistent(key, Inconsistency::NoValve { bearing: b, name: case.title.clone() }))?;
    for port in &h.ports {
        if port.pads.iter().all(|&p| case.bearing.pads.get(p).is_none_or(|pad| pad.orifices.is_empty())) {
            let name = if port.sign > 0.0 { ValvePort::A } else { ValvePort::B };
            return Err(CaseError::inconsistent(
                key,
                Inconsistency::PortWithoutOrifice {
                    port: if name == ValvePort::A { 'A' } else { 'B' },
                    pads: port.pads.clone(),
                },
            ));
        }
    }
    Ok(())
}

/// A PD term's gains for `sensor` (SI), checked: no proportional gain on a velocity pickup, a roll-off with a
/// derivative of a displacement.
fn pd_gains(
    keys: [&str; 3],
    given: [Option<f64>; 3],
    sensor: (usize, Quantity),
) -> Result<(f64, f64, Option<f64>), CaseError> {
    let kp = control_key!("control.loop[].kp_v_per_um").value_at(keys[0], given[0].or(Some(0.0)))?;
    let kd = control_key!("control.loop[].kd_v_per_mm_s").value_at(keys[1], given[1].or(Some(0.0)))?;
    let rolloff = control_key!("control.loop[].rolloff_hz").optional(given[2]).map_err(|e| at_index(e, keys[2]))?;
    if sensor.1 == Quantity::Velocity && kp != 0.0 {
        return Err(CaseError::inconsistent(keys[0], Inconsistency::ProportionalOnVelocity { sensor: sensor.0 }));
    }
    if sensor.1 == Quantity::Displacement && kd != 0.0 && rolloff.is_none() {
        return Err(CaseError::inconsistent(keys[2], Inconsistency::DerivativeWithoutRolloff));
    }
    Ok((kp, kd, rolloff))
}

fn resolve_loops(loops: &[LoopTable], sensors: &[Sensor], n_actuators: usize) -> Result<Vec<Loop>, CaseError> {
    let mut out: Vec<Option<Loop>> = vec![None; n_actuators];
    for (i, l) in loops.iter().enumerate() {
        let key = |k: &str| format!("control.loop[{i}].{k}");
        let a = index(&key("actuator"), l.actuator, n_actuators)?;
        let s = index(&key("sensor"), l.sensor, sensors.len())?;
        if out[a].is_some() {
            let count = loops.iter().filter(|x| x.actuator == a).count();
            return Err(CaseError::inconsistent(
                key("actuator"),
                Inconsistency::LoopsPerActuator { actuator: a, loops: count },
            ));
        }
        let q = sensors[s].quantity;
        let rule = match l.law {
            LawWord::Pd => {
                let (kp, kd, rolloff_rad_s) = pd_gains(
                    [&key("kp_v_per_um"), &key("kd_v_per_mm_s"), &key("rolloff_hz")],
                    [l.kp_v_per_um, l.kd_v_per_mm_s, l.rolloff_hz],
                    (s, q),
                )?;
                Rule::Pd { kp, kd, rolloff_rad_s }
            }
            LawWord::TransferFunction => {
                let num = polynomial(&key("numerator"), &l.numerator)?;
                let den = polynomial(&key("denominator"), &l.denominator)?;
                if l.numerator.is_empty() {
                    return Err(CaseError::missing(key("numerator"), "the transfer function's numerator"));
                }
                let Some(&lead) = den.first() else {
                    return Err(CaseError::inconsistent(key("denominator"), Inconsistency::ZeroDenominator));
                };
                if num.len() > den.len() {
                    return Err(CaseError::inconsistent(
                        key("numerator"),
                        Inconsistency::ImproperTransferFunction {
                            numerator: num.len() - 1,
                            denominator: den.len() - 1,
                        },
                    ));
                }
                let unstable = routh_unstable_roots(&den);
                if unstable > 0 {
                    return Err(CaseError::inconsistent(
                        key("denominator"),
                        Inconsistency::UnstableController { poles: unstable },
                    ));
                }
                // per SI reading, monic denominator
                let scale = 1.0 / (q.reading_unit() * lead);
                Rule::TransferFunction {
                    numerator: num.iter().map(|c| c * scale).collect(),
                    denominator: den.iter().map(|c| c / lead).collect(),
                }
            }
        };
        out[a] = Some(Loop { actuator: a, sensor: s, rule });
    }
    out.into_iter()
        .enumerate()
        .map(|(a, l)| {
            l.ok_or_else(|| {
                CaseError::inconsistent("control.loop", Inconsistency::LoopsPerActuator { actuator: a, loops: 0 })
            })
        })
        .collect()
}

fn resolve_mimo(m: &MimoTable, sensors: &[Sensor], n_actuators: usize) -> Result<Law, CaseError> {
    let shape = |key: &str, rows: &[Vec<f64>]| -> Result<Vec<Vec<f64>>, CaseError> {
        if rows.is_empty() {
            return Ok(vec![vec![0.0; sensors.len()]; n_actuators]);
        }
        let columns = rows.iter().map(Vec::len).max().unwrap_or(0);
        if rows.len() != n_actuators || rows.iter().any(|r| r.len() != sensors.len()) {
            return Err(CaseError::inconsistent(
                key,
                Inconsistency::GainMatrixShape {
                    rows: rows.len(),
                    columns,
                    actuators: n_actuators,
                    sensors: sensors.len(),
                },
            ));
        }
        Ok(rows.to_vec())
    };
    let kp_rows = shape("control.mimo.kp_v_per_um", &m.kp_v_per_um)?;
    let kd_rows = shape("control.mimo.kd_v_per_mm_s", &m.kd_v_per_mm_s)?;
    let mut kp = vec![vec![0.0; sensors.len()]; n_actuators];
    let mut kd = kp.clone();
    let mut rolloff = None;
    for a in 0..n_actuators {
        for (s, sensor) in sensors.iter().enumerate() {
            let (p, d, r) = pd_gains(
                [
                    &format!("control.mimo.kp_v_per_um[{a}][{s}]"),
                    &format!("control.mimo.kd_v_per_mm_s[{a}][{s}]"),
                    "control.mimo.rolloff_hz",
                ],
                [Some(kp_rows[a][s]), Some(kd_rows[a][s]), m.rolloff_hz],
                (s, sensor.quantity),
            )?;
            (kp[a][s], kd[a][s], rolloff) = (p, d, r);
        }
    }
    Ok(Law::Mimo { kp, kd, rolloff_rad_s: rolloff })
}

/// `[control.lqr]` checked: weights per sensor and per actuator (1 each when absent), every one in range.
fn resolve_lqr(l: &LqrTable, n_sensors: usize, n_actuators: usize) -> Result<LqrSpec, CaseError> {
    let weights = |key: &str, given: &[f64], count: usize, row: &KeyRow| -> Result<Vec<f64>, CaseError> {
        if given.is_empty() {
            return (0..count).map(|_| row.value_at(key, None)).collect();
        }
        if given.len() != count {
            return Err(CaseError::inconsistent(key, Inconsistency::WeightCount { given: given.len(), needs: count }));
        }
        given.iter().enumerate().map(|(i, &w)| row.value_at(&format!("{key}[{i}]"), Some(w))).collect()
    };
    Ok(LqrSpec {
        design_speed_rad_s: control_key!("control.lqr.design_speed_rpm").optional(l.design_speed_rpm)?,
        output_weight: weights(
            "control.lqr.output_weight",
            &l.output_weight,
            n_sensors,
            control_key!("control.lqr.output_weight"),
        )?,
        input_weight: weights(
            "control.lqr.input_weight",
            &l.input_weight,
            n_actuators,
            control_key!("control.lqr.input_weight"),
        )?,
        max_frequency_rad_s: control_key!("control.lqr.max_frequency_hz").value(l.max_frequency_hz)?,
        sensor_noise: control_key!("control.lqr.sensor_noise").value(l.sensor_noise)?,
    })
}

type KeyRow = super::schema::KeySpec<super::rotor::RotorFile>;
