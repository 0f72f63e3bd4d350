//! `[hydraulics]`: the controllable bearing's servovalve, its ports and injection lines, and the test rig
//! (docs/MODEL.md §8, §9) — the file form and the SI form the frequency responses read (the validation that
//! converts one into the other: `model/resolve/hydraulics.rs`).
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

/// `[hydraulics]` as written.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HydraulicsFile {
    /// Supply pressure at the valve's P port.
    pub supply_pressure_bar: f64,
    /// Return (tank) pressure.
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
