//! Rows of what the bearing runs with and at: `[lubricant]` and `[operating]`.

use super::Group::{Lubricant, Operating};
use super::Widget::{Custom, Number, Optional, Text};
use super::{Fallback, KeySpec, ANGLE, TEMPERATURE};
use crate::model::error::Range;
use crate::model::file::CaseFile;
use crate::model::file::Cavitation;
use crate::units::{BAR, CELSIUS, DEG, J_PER_KG_K, KG_PER_M3, L_PER_MIN, N, ONE, PA_S, PER_K, RPM, W_PER_M_K};

type Key = KeySpec;

fn by_points(f: &CaseFile) -> bool {
    f.lubricant.viscosity_coefficient_per_k.is_none()
}
fn by_coefficient(f: &CaseFile) -> bool {
    f.lubricant.viscosity_coefficient_per_k.is_some()
}
fn by_load(f: &CaseFile) -> bool {
    f.operating.eccentricity_ratio.is_none()
}
fn by_position(f: &CaseFile) -> bool {
    f.operating.eccentricity_ratio.is_some()
}
/// The supply temperature, the default of the temperatures that follow it [°C].
pub(super) fn supply(f: &CaseFile) -> f64 {
    f.operating.supply_temperature_c
}
pub(super) const SUPPLY: Fallback = Fallback::Follows { text: "the supply temperature", value: supply };

fn mass_conserving(f: &CaseFile) -> bool {
    f.physics.cavitation == Some(Cavitation::Jfo)
}

const VISCOSITY_LAW: Fallback = Fallback::Rule("give a second point or viscosity_coefficient_per_k");
const LOAD_OR_POSITION: Fallback = Fallback::Rule("give load_n or eccentricity_ratio");

pub(super) const KEYS: &[Key] = &[
    // [lubricant]
    Key::text("lubricant.name").edit(Lubricant, "Name", Text).meaning("Oil name, for the record (e.g. ISO VG32)."),
    Key::number("lubricant.viscosity_pa_s", PA_S, Range::positive(100.0))
        .typical(0.002, 0.1)
        .edit(Lubricant, "Viscosity µ1", Number(5))
        .meaning("Dynamic viscosity at the first catalogue temperature (ISO VG32 ≈ 0.028 Pa·s at 40 °C). Pressure and load capacity scale with µ."),
    Key::number("lubricant.viscosity_temperature_c", CELSIUS, TEMPERATURE)
        .typical(20.0, 100.0)
        .edit(Lubricant, "at temperature T1", Number(1))
        .meaning("Temperature of the first viscosity point."),
    Key::number("lubricant.viscosity2_pa_s", PA_S, Range::positive(100.0))
        .typical(0.001, 0.05)
        .default(VISCOSITY_LAW)
        .edit(Lubricant, "Viscosity µ2", Number(5))
        .when(by_points)
        .meaning("Second catalogue viscosity point: with the first it fixes the exponential viscosity–temperature law."),
    Key::number("lubricant.viscosity2_temperature_c", CELSIUS, TEMPERATURE)
        .typical(40.0, 120.0)
        .default(VISCOSITY_LAW)
        .edit(Lubricant, "at temperature T2", Number(1))
        .when(by_points)
        .meaning("Temperature of the second viscosity point (e.g. 100 °C)."),
    Key::number("lubricant.viscosity_coefficient_per_k", PER_K, Range::closed(0.0, 1.0))
        .typical(0.0, 0.06)
        .default(Fallback::Rule("from the two viscosity points"))
        .edit(Lubricant, "Temperature coefficient η", Number(4))
        .when(by_coefficient)
        .meaning("µ(T) = µ1 exp(−η (T − T1)): how fast the oil thins with temperature (mineral oils ≈ 0.03 /K)."),
    Key::number("lubricant.density_kg_per_m3", KG_PER_M3, Range::positive(2e4))
        .typical(800.0, 950.0)
        .edit(Lubricant, "Density ρ", Number(1))
        .meaning("Oil density (thermal model: heat carried by the flow)."),
    Key::number("lubricant.specific_heat_j_per_kg_k", J_PER_KG_K, Range::positive(1e5))
        .typical(1700.0, 2200.0)
        .edit(Lubricant, "Specific heat c_p", Number(0))
        .meaning("Heat capacity of the oil (thermal model)."),
    Key::number("lubricant.conductivity_w_per_m_k", W_PER_M_K, Range::positive(1e3))
        .typical(0.1, 0.16)
        .edit(Lubricant, "Conductivity κ", Number(3))
        .meaning("Thermal conductivity of the oil (thermal model)."),
    // [operating]
    Key::number("operating.speed_rpm", RPM, Range::closed(0.0, 1e6))
        .typical(500.0, 15000.0)
        .edit(Operating, "Speed", Number(0))
        .meaning("Journal speed. Faster running drags more oil into the wedge: the journal rises towards the centre (smaller ε), power loss grows about with the square of speed."),
    Key::number("operating.load_n", N, Range::closed(0.0, 1e10))
        .typical(0.0, 50000.0)
        .default(LOAD_OR_POSITION)
        .edit(Operating, "Load W", Number(1))
        .when(by_load)
        .meaning("Static load on the journal (for example the rotor weight share). Specific loads of 0.5–3 MPa on the projected area L·D are usual."),
    Key::number("operating.load_angle_deg", DEG, ANGLE)
        .typical(0.0, 360.0)
        .or(270.0)
        .edit(Operating, "Load direction", Optional(1))
        .when(by_load)
        .meaning("Direction of the load from +x, counter-clockwise: 270° is straight down."),
    Key::number("operating.eccentricity_ratio", ONE, Range::closed(0.0, 10.0))
        .typical(0.0, 0.9)
        .default(LOAD_OR_POSITION)
        .edit(Operating, "Eccentricity ε", Number(3))
        .when(by_position)
        .meaning("Prescribed journal displacement divided by the assembled clearance."),
    Key::number("operating.eccentricity_angle_deg", DEG, ANGLE)
        .typical(0.0, 360.0)
        .or(270.0)
        .edit(Operating, "Displacement direction", Optional(1))
        .when(by_position)
        .meaning("Direction of the prescribed displacement from +x, counter-clockwise."),
    Key::number("operating.supply_temperature_c", CELSIUS, TEMPERATURE)
        .typical(20.0, 70.0)
        .edit(Operating, "Supply temperature", Number(1))
        .meaning("Temperature of the oil fed to the bearing."),
    Key::number("operating.film_temperature_c", CELSIUS, TEMPERATURE)
        .typical(20.0, 120.0)
        .default(SUPPLY)
        .edit(Operating, "Film temperature", Optional(1))
        .meaning("The one temperature of the isothermal film (sets its viscosity). Unset: the supply temperature. A few tens of kelvin above supply is more realistic."),
    Key::number("operating.injection_temperature_c", CELSIUS, TEMPERATURE)
        .typical(20.0, 80.0)
        .default(SUPPLY)
        .edit(Operating, "Injection temperature", Optional(1))
        .meaning("Temperature of the injected oil: sets its viscosity in the orifice (and cools the film in the thermal model). Unset: the supply temperature."),
    Key::per_pad("operating.injection_pressure_bar", BAR, Range::closed(0.0, 5000.0))
        .typical(0.0, 100.0)
        .or(0.0)
        .edit(Operating, "Injection pressure", Custom)
        .meaning("Pressure at the orifice entry (controllable lubrication). 0: the orifice is open to ambient and acts as a sink where the film pressure is higher. High pressure lifts the pad and reverses the film flow upstream of the orifice."),
    Key::number("operating.supply_flow_l_per_min", L_PER_MIN, Range::open_lo(0.0, 1e5))
        .typical(1.0, 500.0)
        .default(Fallback::Rule("absent: flooded pads (as much oil as the films take)"))
        .edit(Operating, "Supply flow", Optional(2))
        .when(mass_conserving)
        .meaning("Oil fed to the bearing, shared equally by the pads' leading edges (starved lubrication, to cut power loss). A pad offered less than its film drags in at the leading edge runs starved: its film starts partly filled (inlet film fraction = offered / full-inlet flow) and builds pressure later; offered more, it is flooded and the excess drains. With the thermal model each pad is also offered the hot oil the journal carries from the pad upstream (feeding.kind). Needs physics.cavitation = \"jfo\". Absent: flooded pads (or operating.pad_supply_flow_l_per_min per pad)."),
    Key::per_pad("operating.pad_supply_flow_l_per_min", L_PER_MIN, Range::open_lo(0.0, 1e5))
        .typical(0.2, 100.0)
        .default(Fallback::Rule("absent: the bearing's supply flow shared equally, or flooded pads"))
        .edit(Operating, "Supply flow per pad", Custom)
        .when(mass_conserving)
        .meaning("Oil fed to each pad's leading edge, one value per pad (or one value for every pad), instead of the bearing's operating.supply_flow_l_per_min shared equally: for feeds that differ around the bearing (a spray bar or groove per pad with its own orifice). Each pad is starved or flooded as with the bearing's supply. Needs physics.cavitation = \"jfo\"; give this or operating.supply_flow_l_per_min, not both."),
    Key::number("operating.excitation_ratio", ONE, Range::closed(0.0, 1e3))
        .typical(0.0, 3.0)
        .or(1.0)
        .edit(Operating, "Excitation ratio ω/Ω", Optional(3))
        .meaning("Frequency at which the pad coordinates are condensed out of the coefficients, relative to the running speed. 1 = synchronous (unbalance response); sub-synchronous values matter for stability."),
];
