//! Rows of `[hydraulics]`: the servovalve, one injection line per `[[hydraulics.port]]`, and the test rig.

use super::Group::Hydraulics;
use super::Widget::{Number, Optional};
use super::{Fallback, KeySpec};
use crate::model::error::Range;
use crate::model::file::CaseFile;
use crate::units::{
    BAR, COUNT, GPA, HZ_ANGULAR, KG, L_PER_MIN, L_PER_MIN_BAR, MM, NS_PER_M, N_PER_M, ONE, PER_GPA, VOLT,
};

type Key = KeySpec;

fn has_hydraulics(f: &CaseFile) -> bool {
    f.hydraulics.is_some()
}
fn has_rig(f: &CaseFile) -> bool {
    f.hydraulics.as_ref().is_some_and(|h| h.rig.is_some())
}

pub(super) const KEYS: &[Key] = &[
    Key::number("hydraulics.supply_pressure_bar", BAR, Range::positive(1000.0))
        .typical(10.0, 200.0)
        .edit(Hydraulics, "Supply pressure", Number(1))
        .when(has_hydraulics)
        .meaning("Supply pressure at the servovalve's P port. Sets the valve's flow gain (Bernoulli: ∝ √(supply − return)); the thesis' rig used 20, 40 and 80 bar."),
    Key::number("hydraulics.valve.natural_frequency_hz", HZ_ANGULAR, Range::positive(1e5))
        .typical(20.0, 500.0)
        .edit(Hydraulics, "Valve ω_V/2π", Number(1))
        .when(has_hydraulics)
        .meaning("Natural frequency ω_V/2π of the spool's second-order response (G1 = x_V/u_V); its bandwidth limits the active force at high frequency."),
    Key::number("hydraulics.valve.damping_ratio", ONE, Range::positive(10.0))
        .typical(0.3, 1.2)
        .edit(Hydraulics, "Valve damping ξ_V", Number(2))
        .when(has_hydraulics)
        .meaning("Damping ratio ξ_V of the spool's second-order response."),
    Key::number("hydraulics.valve.rated_flow_l_per_min", L_PER_MIN, Range::positive(1e4))
        .typical(1.0, 100.0)
        .edit(Hydraulics, "Valve rated flow", Number(2))
        .when(has_hydraulics)
        .meaning("Datasheet rated flow at full-scale signal and rated pressure drop."),
    Key::number("hydraulics.valve.rated_drop_bar", BAR, Range::positive(1000.0))
        .typical(35.0, 140.0)
        .edit(Hydraulics, "Valve rated drop", Number(1))
        .when(has_hydraulics)
        .meaning("Datasheet pressure drop at which the rated flow is given (over both metering edges)."),
    Key::number("hydraulics.return_pressure_bar", BAR, Range::closed(0.0, 1000.0))
        .typical(0.0, 5.0)
        .or(0.0)
        .edit(Hydraulics, "Return pressure", Optional(1))
        .when(has_hydraulics)
        .meaning("Tank pressure at the valve's T port; must stay below the supply."),
    Key::number("hydraulics.valve.full_scale_v", VOLT, Range::positive(1000.0))
        .typical(1.0, 10.0)
        .or(10.0)
        .edit(Hydraulics, "Valve full-scale signal", Optional(1))
        .when(has_hydraulics)
        .meaning("Full-scale control signal. The linear valve model holds up to about 10 % of it (small signals)."),
    Key::number("hydraulics.valve.flow_pressure_coefficient_l_per_min_bar", L_PER_MIN_BAR, Range::closed(0.0, 1000.0))
        .typical(0.0, 0.1)
        .or(0.0)
        .edit(Hydraulics, "Valve flow–pressure K_c", Optional(4))
        .when(has_hydraulics)
        .meaning("Flow–pressure coefficient K_c = −K_pq: port flow lost per unit load pressure. Terminates the lines at the valve end (damps their acoustic modes) and limits the static pressure gain."),
    Key::number("hydraulics.valve.leakage_l_per_min", L_PER_MIN, Range::closed(0.0, 1e4))
        .typical(0.0, 2.0)
        .or(0.0)
        .edit(Hydraulics, "Valve leakage", Optional(3))
        .when(has_hydraulics)
        .meaning("Null leakage into each port (underlapped spool). Static only: it sets the nozzle pressure with the spool centred, not the small-signal responses."),
    // [[hydraulics.port]]: the editor shows each line's port and pads above its rows (edited in the file).
    Key::choice("hydraulics.port[].valve_port", &["A", "B"])
        .meaning("Which valve port feeds this line: A (driven with the signal) or B (against it)."),
    Key::rule("hydraulics.port[].pads", COUNT, "list of pad indices, 0-based, each pad on at most one port")
        .meaning("The pads whose orifices this line feeds; they share its nozzle-end pressure."),
    Key::number("hydraulics.port[].line_length_mm", MM, Range::positive(1e5))
        .typical(100.0, 3000.0)
        .edit(Hydraulics, "length", Number(0))
        .meaning("Length of the injection line from the valve port to the nozzles. Its quarter-wave modes f_i = (2i−1) c0/(4 l) shape G2; 700 mm on the thesis' rig."),
    Key::number("hydraulics.port[].line_diameter_mm", MM, Range::positive(1000.0))
        .typical(2.0, 12.0)
        .edit(Hydraulics, "inner diameter", Number(2))
        .meaning("Inner diameter of the injection line (area, laminar friction 32 µ/(ρ D²))."),
    Key::number("hydraulics.port[].air_fraction", ONE, Range::closed(0.0, 0.5))
        .typical(0.0, 0.02)
        .or(0.0)
        .edit(Hydraulics, "air fraction", Optional(4))
        .meaning("Volume fraction of entrained air at the line's static pressure. A little air lowers the line's modes dramatically (1 % at a few bar: 470 Hz → about 100 Hz)."),
    Key::number("hydraulics.port[].bulk_modulus_gpa", GPA, Range::positive(100.0))
        .typical(1.0, 2.0)
        .or(1.5)
        .edit(Hydraulics, "oil bulk modulus", Optional(2))
        .meaning("Bulk modulus of the air-free oil (mineral oils 1.4–1.7 GPa)."),
    Key::number("hydraulics.port[].wall_compliance_per_gpa", PER_GPA, Range::closed(0.0, 1000.0))
        .typical(0.0, 1.0)
        .or(0.0)
        .edit(Hydraulics, "wall compliance", Optional(3))
        .meaning("Compliance of the line's wall, added to the oil's 1/β (a hose is much softer than a steel tube)."),
    Key::integer("hydraulics.port[].modes", COUNT, 1, 50)
        .default(Fallback::Count(4))
        .meaning("Acoustic modes kept in the line's modal model (the quasi-static rest is added back)."),
    // [hydraulics.rig]
    Key::number("hydraulics.rig.mass_kg", KG, Range::positive(1e6))
        .typical(5.0, 500.0)
        .edit(Hydraulics, "Rig mass", Number(1))
        .when(has_rig)
        .meaning("Effective mass of the rig's rotor and tilting frame on its one vertical degree of freedom."),
    Key::number("hydraulics.rig.support_stiffness_n_per_m", N_PER_M, Range::closed(0.0, 1e12))
        .typical(1e5, 1e8)
        .edit(Hydraulics, "Rig support stiffness", Number(0))
        .when(has_rig)
        .meaning("Stiffness of the rig's support (parallel to the bearing film)."),
    Key::number("hydraulics.rig.support_damping_ns_per_m", NS_PER_M, Range::closed(0.0, 1e9))
        .typical(0.0, 1e4)
        .or(0.0)
        .edit(Hydraulics, "Rig support damping", Optional(0))
        .when(has_rig)
        .meaning("Damping of the rig's support."),
];
