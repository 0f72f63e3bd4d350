//! Engineering units, defined once.
//!
//! The solver works in SI (m, s, Pa, N, rad, W; temperatures in °C). A value crosses into the units people
//! read and type — rpm, bar, µm, L/min — only at the edges: the case file, the command line, the workbench's
//! labels and the exports, and there the unit is in the name (`speed_rpm`, `supply_pressure_bar`). Every such
//! crossing goes through a [`Unit`] of this module, so a factor is written in exactly one place:
//!
//! ```text
//! SI value = value in the unit × Unit::si        (RPM.si = 2π/60 rad/s, BAR.si = 1e5 Pa, …)
//! ```
//!
//! Temperatures stay in °C inside as well (no offset units here).

use std::f64::consts::TAU;

/// A unit as a multiple of its SI unit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Unit {
    /// How it is written after a number (`rpm`, `bar`, `µm`).
    pub symbol: &'static str,
    /// The SI value of one of this unit.
    pub si: f64,
}

impl Unit {
    /// A value in this unit, in SI.
    #[must_use]
    pub fn to_si(self, value: f64) -> f64 {
        value * self.si
    }

    /// An SI value, in this unit.
    #[must_use]
    pub fn from_si(self, value_si: f64) -> f64 {
        value_si / self.si
    }
}

const fn unit(symbol: &'static str, si: f64) -> Unit {
    Unit { symbol, si }
}

// Rotational speed and angles.
/// Revolutions per minute, in rad/s.
pub const RPM: Unit = unit("rpm", TAU / 60.0);
/// Hertz as an angular frequency, in rad/s.
pub const HZ_ANGULAR: Unit = unit("Hz", TAU);
/// Degrees, in rad.
pub const DEG: Unit = unit("°", TAU / 360.0);
/// Milliradians (pad tilt), in rad.
pub const MRAD: Unit = unit("mrad", 1e-3);

// Time.
/// Milliseconds (solve and frame times), in s.
pub const MS: Unit = unit("ms", 1e-3);

// Lengths.
pub const MM: Unit = unit("mm", 1e-3);
pub const UM: Unit = unit("µm", 1e-6);

// Pressure and stress.
pub const BAR: Unit = unit("bar", 1e5);
pub const KPA: Unit = unit("kPa", 1e3);
pub const MPA: Unit = unit("MPa", 1e6);
pub const GPA: Unit = unit("GPa", 1e9);

// Flow, force, stiffness, damping, power.
/// Litres per minute, in m³/s.
pub const L_PER_MIN: Unit = unit("L/min", 1e-3 / 60.0);
pub const KN: Unit = unit("kN", 1e3);
/// Meganewtons per metre (stiffness), in N/m.
pub const MN_PER_M: Unit = unit("MN/m", 1e6);
/// Kilonewton-seconds per metre (damping), in N·s/m.
pub const KNS_PER_M: Unit = unit("kN·s/m", 1e3);
pub const KW: Unit = unit("kW", 1e3);

// Material and thermal properties.
/// Parts per million per kelvin (thermal expansion), in 1/K.
pub const PPM_PER_K: Unit = unit("ppm/K", 1e-6);
/// Millipascal-seconds (viscosity), in Pa·s.
pub const MPA_S: Unit = unit("mPa·s", 1e-3);

// Mass and unbalance.
pub const G: Unit = unit("g", 1e-3);
/// Gram-millimetres (unbalance), in kg·m.
pub const G_MM: Unit = unit("g·mm", 1e-6);

// Hydraulics.
/// Litres per minute and bar (a valve's flow–pressure coefficient), in m³/(s·Pa).
pub const L_PER_MIN_BAR: Unit = unit("L/(min·bar)", 1e-3 / 60.0 / 1e5);
/// Per gigapascal (a compliance), in 1/Pa.
pub const PER_GPA: Unit = unit("1/GPa", 1e-9);

// Values written in their SI unit (a factor of one): the case keys name their unit all the same, so every key
// has a `Unit` and its row says how it is written.
/// A pure number (ratios, fractions, coefficients).
pub const ONE: Unit = unit("–", 1.0);
/// A count (pads, elements, modes): no unit.
pub const COUNT: Unit = unit("", 1.0);
/// Mesh nodes (a budget).
pub const NODES: Unit = unit("nodes", 1.0);
/// Temperature: °C inside as well.
pub const CELSIUS: Unit = unit("°C", 1.0);
pub const N: Unit = unit("N", 1.0);
pub const N_PER_M: Unit = unit("N/m", 1.0);
/// Newton-metres (a torque).
pub const N_M: Unit = unit("N·m", 1.0);
/// Watts (a power, a heat flow).
pub const W: Unit = unit("W", 1.0);
/// Radians per second (an angular speed or frequency).
pub const RAD_PER_S: Unit = unit("rad/s", 1.0);
pub const NS_PER_M: Unit = unit("N·s/m", 1.0);
pub const KG: Unit = unit("kg", 1.0);
pub const KG_M2: Unit = unit("kg·m²", 1.0);
pub const KG_PER_M3: Unit = unit("kg/m³", 1.0);
pub const PA_S: Unit = unit("Pa·s", 1.0);
pub const PER_K: Unit = unit("1/K", 1.0);
pub const J_PER_KG_K: Unit = unit("J/(kg·K)", 1.0);
pub const W_PER_M_K: Unit = unit("W/(m·K)", 1.0);
pub const W_PER_M2_K: Unit = unit("W/(m²·K)", 1.0);
pub const VOLT: Unit = unit("V", 1.0);

// Active control (the rotor file's `[control]`).
/// Volts per micrometre (a gain on a displacement signal), in V/m.
pub const V_PER_UM: Unit = unit("V/µm", 1e6);
/// Volts per millimetre per second (a gain on a velocity signal), in V·s/m.
pub const V_PER_MM_S: Unit = unit("V/(mm/s)", 1e3);
/// Newtons per volt (an ideal force actuator's gain).
pub const N_PER_V: Unit = unit("N/V", 1.0);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn conversions_round_trip_and_match_their_definitions() {
        // 3000 rpm is 50 rev/s.
        assert!((RPM.to_si(3000.0) - 100.0 * std::f64::consts::PI).abs() < 1e-12);
        assert!((RPM.from_si(RPM.to_si(6000.0)) - 6000.0).abs() < 1e-9);
        // 60 L/min is one litre per second.
        assert!((L_PER_MIN.to_si(60.0) - 1e-3).abs() < 1e-18);
        assert_eq!(BAR.to_si(2.0), 2e5);
        assert!((DEG.to_si(180.0) - std::f64::consts::PI).abs() < 1e-15);
        assert!((UM.from_si(1e-4) - 100.0).abs() < 1e-9);
        // 1 L/(min·bar) is a litre per minute per 1e5 Pa.
        assert!((L_PER_MIN_BAR.to_si(6e6) - 1e-3).abs() < 1e-15);
        assert_eq!(PER_GPA.to_si(2.0), 2e-9);
    }
}
