//! `[hydraulics]`: the controllable bearing's servovalve, its ports and injection lines, and the test rig
//! (model.md §8, §9) — the file form, its validation and the SI form the frequency responses read.
//!
//! ```toml
//! [hydraulics]            # supply_pressure_bar, return_pressure_bar
//! [hydraulics.valve]      # natural_frequency_hz, damping_ratio, rated_flow_l_per_min, rated_drop_bar,
//!                         # full_scale_v, flow_pressure_coefficient_l_per_min_bar, leakage_l_per_min
//! [[hydraulics.port]]     # valve_port = "A" | "B", pads = [i, …] (0-based), line_length_mm,
//!                         # line_diameter_mm, bulk_modulus_gpa, air_fraction, wall_compliance_per_gpa, modes
//! [hydraulics.rig]        # mass_kg, support_stiffness_n_per_m, support_damping_ns_per_m
//! ```
//!
//! The nozzles are the pads' orifices (`[[bearing.pads.orifice]]`); the static pressure each port holds is
//! the pads' `operating.injection_pressure_bar` (the equilibrium is solved at it; the entrained air's bulk
//! modulus is taken at it).

use serde::{Deserialize, Serialize};

use super::error::{CaseError, Range};

const BAR: f64 = 1e5;
/// 1 L/min in m³/s.
const L_PER_MIN: f64 = 1e-3 / 60.0;

/// Largest number of acoustic modes per line.
pub const MAX_MODES: usize = 50;

/// `[hydraulics]` as written.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HydraulicsFile {
    /// Supply pressure at the valve's P port.
    pub supply_pressure_bar: f64,
    /// Return (tank) pressure, default 0.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub return_pressure_bar: Option<f64>,
    pub valve: ValveFile,
    pub port: Vec<PortFile>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rig: Option<RigFile>,
}

/// `[hydraulics.valve]`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ValveFile {
    pub natural_frequency_hz: f64,
    pub damping_ratio: f64,
    /// Rated flow at full-scale signal and rated drop (datasheet).
    pub rated_flow_l_per_min: f64,
    pub rated_drop_bar: f64,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub full_scale_v: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub flow_pressure_coefficient_l_per_min_bar: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub leakage_l_per_min: Option<f64>,
}

/// Which valve port feeds a line.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum ValvePort {
    A,
    B,
}

/// `[[hydraulics.port]]`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PortFile {
    pub valve_port: ValvePort,
    /// The pads this port's line feeds (0-based).
    pub pads: Vec<usize>,
    pub line_length_mm: f64,
    pub line_diameter_mm: f64,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub bulk_modulus_gpa: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub air_fraction: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub wall_compliance_per_gpa: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub modes: Option<usize>,
}

/// `[hydraulics.rig]`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RigFile {
    pub mass_kg: f64,
    pub support_stiffness_n_per_m: f64,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub support_damping_ns_per_m: Option<f64>,
}

/// The hydraulic system in SI.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Hydraulics {
    pub supply_pressure_pa: f64,
    pub return_pressure_pa: f64,
    pub valve: Valve,
    pub ports: Vec<Port>,
    pub rig: Option<Rig>,
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Valve {
    pub natural_frequency_rad_s: f64,
    pub damping_ratio: f64,
    pub rated_flow_m3_s: f64,
    pub rated_drop_pa: f64,
    pub full_scale_v: f64,
    /// K_c ≥ 0 [m³/(s·Pa)].
    pub flow_pressure_coefficient: f64,
    pub leakage_m3_s: f64,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Port {
    /// +1 for A, −1 for B.
    pub sign: f64,
    pub pads: Vec<usize>,
    pub line_length_m: f64,
    pub line_diameter_m: f64,
    pub oil_bulk_modulus_pa: f64,
    pub air_fraction: f64,
    /// [1/Pa]
    pub wall_compliance_per_pa: f64,
    pub modes: usize,
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Rig {
    pub mass_kg: f64,
    pub support_stiffness_n_per_m: f64,
    pub support_damping_ns_per_m: f64,
}

fn inconsistent(key: &str, message: impl Into<String>) -> CaseError {
    CaseError::Inconsistent { key: key.to_string(), message: message.into() }
}

/// Validates `[hydraulics]` against a bearing of `n_pads` pads and converts it to SI.
///
/// # Errors
/// The first value out of range or inconsistent (a pad fed twice or missing, ports named twice), by key.
pub fn resolve_hydraulics(h: &HydraulicsFile, n_pads: usize) -> Result<Hydraulics, CaseError> {
    let supply = Range::positive(1000.0).check("hydraulics.supply_pressure_bar", h.supply_pressure_bar)? * BAR;
    let ret =
        Range::closed(0.0, 1000.0).check("hydraulics.return_pressure_bar", h.return_pressure_bar.unwrap_or(0.0))? * BAR;
    if ret >= supply {
        return Err(inconsistent("hydraulics.return_pressure_bar", "must be below the supply pressure"));
    }
    let v = &h.valve;
    let valve = Valve {
        natural_frequency_rad_s: Range::positive(1e5)
            .check("hydraulics.valve.natural_frequency_hz", v.natural_frequency_hz)?
            * std::f64::consts::TAU,
        damping_ratio: Range::positive(10.0).check("hydraulics.valve.damping_ratio", v.damping_ratio)?,
        rated_flow_m3_s: Range::positive(1e4).check("hydraulics.valve.rated_flow_l_per_min", v.rated_flow_l_per_min)?
            * L_PER_MIN,
        rated_drop_pa: Range::positive(1000.0).check("hydraulics.valve.rated_drop_bar", v.rated_drop_bar)? * BAR,
        full_scale_v: Range::positive(1000.0).check("hydraulics.valve.full_scale_v", v.full_scale_v.unwrap_or(10.0))?,
        flow_pressure_coefficient: Range::closed(0.0, 1000.0).check(
            "hydraulics.valve.flow_pressure_coefficient_l_per_min_bar",
            v.flow_pressure_coefficient_l_per_min_bar.unwrap_or(0.0),
        )? * L_PER_MIN
            / BAR,
        leakage_m3_s: Range::closed(0.0, 1e4)
            .check("hydraulics.valve.leakage_l_per_min", v.leakage_l_per_min.unwrap_or(0.0))?
            * L_PER_MIN,
    };
    if h.port.is_empty() || h.port.len() > 2 {
        return Err(inconsistent(
            "hydraulics.port",
            format!("{} ports: a four-way valve has one or two (A, B)", h.port.len()),
        ));
    }
    let mut fed = vec![false; n_pads];
    let mut ports = Vec::with_capacity(h.port.len());
    for (i, p) in h.port.iter().enumerate() {
        let key = |name: &str| format!("hydraulics.port[{i}].{name}");
        if h.port[..i].iter().any(|q| q.valve_port == p.valve_port) {
            return Err(inconsistent(&key("valve_port"), format!("port {:?} used twice", p.valve_port)));
        }
        if p.pads.is_empty() {
            return Err(inconsistent(&key("pads"), "feeds no pad"));
        }
        for &k in &p.pads {
            match fed.get_mut(k) {
                None => {
                    return Err(inconsistent(
                        &key("pads"),
                        format!("pad {k} does not exist (pads 0 to {})", n_pads.saturating_sub(1)),
                    ))
                }
                Some(true) => return Err(inconsistent(&key("pads"), format!("pad {k} is fed by two ports"))),
                Some(f) => *f = true,
            }
        }
        let modes = p.modes.unwrap_or(4);
        if !(1..=MAX_MODES).contains(&modes) {
            return Err(CaseError::OutOfRange {
                key: key("modes"),
                value: modes as f64,
                allowed: format!("an integer in [1, {MAX_MODES}]"),
            });
        }
        ports.push(Port {
            sign: if p.valve_port == ValvePort::A { 1.0 } else { -1.0 },
            pads: p.pads.clone(),
            line_length_m: Range::positive(1e5).check(&key("line_length_mm"), p.line_length_mm)? * 1e-3,
            line_diameter_m: Range::positive(1000.0).check(&key("line_diameter_mm"), p.line_diameter_mm)? * 1e-3,
            oil_bulk_modulus_pa: Range::positive(100.0)
                .check(&key("bulk_modulus_gpa"), p.bulk_modulus_gpa.unwrap_or(1.5))?
                * 1e9,
            air_fraction: Range::closed(0.0, 0.5).check(&key("air_fraction"), p.air_fraction.unwrap_or(0.0))?,
            wall_compliance_per_pa: Range::closed(0.0, 1000.0)
                .check(&key("wall_compliance_per_gpa"), p.wall_compliance_per_gpa.unwrap_or(0.0))?
                * 1e-9,
            modes,
        });
    }
    let rig = match &h.rig {
        None => None,
        Some(r) => Some(Rig {
            mass_kg: Range::positive(1e6).check("hydraulics.rig.mass_kg", r.mass_kg)?,
            support_stiffness_n_per_m: Range::closed(0.0, 1e12)
                .check("hydraulics.rig.support_stiffness_n_per_m", r.support_stiffness_n_per_m)?,
            support_damping_ns_per_m: Range::closed(0.0, 1e9)
                .check("hydraulics.rig.support_damping_ns_per_m", r.support_damping_ns_per_m.unwrap_or(0.0))?,
        }),
    };
    Ok(Hydraulics { supply_pressure_pa: supply, return_pressure_pa: ret, valve, ports, rig })
}

#[cfg(test)]
mod tests {
    use crate::model::{load_case, CaseError};

    const RIG: &str = include_str!("../../cases/test-rig-pub5.toml");

    #[test]
    fn the_rig_case_resolves_to_si() {
        let (_, case) = load_case(RIG, &[]).unwrap();
        let h = case.hydraulics.unwrap();
        assert_eq!(h.ports.len(), 2);
        assert_eq!((h.ports[0].sign, h.ports[1].sign), (1.0, -1.0));
        assert!((h.ports[0].line_length_m - 0.7).abs() < 1e-15);
        assert!((h.supply_pressure_pa - 40e5).abs() < 1e-9);
    }

    #[test]
    fn inconsistent_ports_are_refused_by_key() {
        let cases = [
            ("hydraulics.port.1.pads=[0]", "hydraulics.port[1].pads"),
            ("hydraulics.port.1.pads=[7]", "hydraulics.port[1].pads"),
            ("hydraulics.port.1.valve_port=\"A\"", "hydraulics.port[1].valve_port"),
            ("hydraulics.port.0.modes=0", "hydraulics.port[0].modes"),
            ("hydraulics.return_pressure_bar=50", "hydraulics.return_pressure_bar"),
        ];
        for (set, key) in cases {
            let e = load_case(RIG, &[set.to_string()]).unwrap_err();
            assert_eq!(e.key(), Some(key), "{set}: {e}");
            assert!(matches!(e, CaseError::Inconsistent { .. } | CaseError::OutOfRange { .. }), "{e}");
        }
    }
}
