//! The case keys, one table: dotted key, unit, allowed values, typical range, default and physical meaning.
//!
//! `tiltpad schema` prints this table and the workbench's editor takes each row's unit, tooltip and drag
//! range from it by key, so the two never disagree. The allowed ranges are the ones validation
//! ([`super::resolve`]) enforces; a test sets every key just outside its range and checks that validation
//! rejects it with the same interval. Keys inside arrays are written with `[]`
//! (`bearing.pads.orifice[].diameter_mm`); a per-pad override `bearing.pad.<i>.<name>` takes the row of
//! `bearing.pads.<name>` ([`spec`] maps both).

use std::fmt::Write as _;

use super::error::Range;

/// What values a key accepts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Allowed {
    /// A finite number in an interval.
    Number(Range),
    /// A number in an interval, or a list of them with one entry per pad.
    NumberPerPad(Range),
    /// A whole number in `[lo, hi]`.
    Integer {
        lo: usize,
        hi: usize,
    },
    /// One of these words (TOML strings).
    Choice(&'static [&'static str]),
    Bool,
    Text,
    /// Depends on other values; the text says how.
    Rule(&'static str),
}

impl Allowed {
    /// The allowed values as one line of text.
    #[must_use]
    pub fn describe(&self) -> String {
        match self {
            Self::Number(r) => r.describe(),
            Self::NumberPerPad(r) => format!("{} (one value, or a list with one per pad)", r.describe()),
            Self::Integer { lo, hi } => format!("integer in [{lo}, {hi}]"),
            Self::Choice(words) => words.iter().map(|w| format!("\"{w}\"")).collect::<Vec<_>>().join(" | "),
            Self::Bool => "true | false".into(),
            Self::Text => "text".into(),
            Self::Rule(text) => (*text).to_string(),
        }
    }
}

/// One case key.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KeySpec {
    /// Dotted key as written in the case file and in `--set`.
    pub key: &'static str,
    /// Unit of the value as written (engineering units; `–` dimensionless, empty for counts and words).
    pub unit: &'static str,
    pub allowed: Allowed,
    /// Range of values engineers usually use (sets the editor's drag speed; a sensible sweep range).
    pub typical: Option<(f64, f64)>,
    /// What applies when the key is absent; empty for a required key.
    pub default: &'static str,
    /// What the value does physically.
    pub meaning: &'static str,
}

const TEMP: Range = Range::closed(-60.0, 400.0);
const ANGLE: Range = Range::closed(-3600.0, 3600.0);

const fn num(
    key: &'static str,
    unit: &'static str,
    range: Range,
    typical: (f64, f64),
    default: &'static str,
    meaning: &'static str,
) -> KeySpec {
    KeySpec { key, unit, allowed: Allowed::Number(range), typical: Some(typical), default, meaning }
}

const fn rule(
    key: &'static str,
    unit: &'static str,
    text: &'static str,
    typical: (f64, f64),
    default: &'static str,
    meaning: &'static str,
) -> KeySpec {
    KeySpec { key, unit, allowed: Allowed::Rule(text), typical: Some(typical), default, meaning }
}

const fn other(
    key: &'static str,
    unit: &'static str,
    allowed: Allowed,
    default: &'static str,
    meaning: &'static str,
) -> KeySpec {
    KeySpec { key, unit, allowed, typical: None, default, meaning }
}

const fn count(key: &'static str, lo: usize, hi: usize, default: &'static str, meaning: &'static str) -> KeySpec {
    KeySpec { key, unit: "", allowed: Allowed::Integer { lo, hi }, typical: Some((2.0, 200.0)), default, meaning }
}

/// Every case key, in file order.
pub const KEYS: &[KeySpec] = &[
    other("title", "", Allowed::Text, "empty", "Free text shown in the workbench and in result files."),
    // [bearing]
    num("bearing.journal_radius_mm", "mm", Range::positive(1e4), (10.0, 500.0), "", "Radius of the shaft journal running in the bearing."),
    num("bearing.length_mm", "mm", Range::positive(1e4), (10.0, 400.0), "", "Axial length of the pads. With L/D below about 0.5 side leakage dominates and the load capacity falls quickly."),
    rule(
        "bearing.assembled_clearance_um",
        "µm",
        "(0, 5 % of the journal radius]",
        (20.0, 400.0),
        "",
        "Radial clearance of the assembled bearing: the gap between the journal and the pads at their pivots with the journal centred. Typically 1–2 ‰ of the radius.",
    ),
    // [bearing.pads]
    other("bearing.pads.count", "", Allowed::Integer { lo: 1, hi: super::resolve::MAX_PADS }, "the number of [[bearing.pad]] entries or pivot angles", "How many pads share the circumference."),
    other(
        "bearing.pads.kind",
        "",
        Allowed::Choice(&["tilting", "fixed"]),
        "tilting",
        "Tilting pads rotate freely about their pivots (no cross-coupled stiffness from a symmetric bearing); fixed sectors do not tilt (lobed or plain bearings).",
    ),
    rule("bearing.pads.arc_deg", "°", "(0, 360/count] (360 for one fixed sector)", (20.0, 120.0), "", "Angular extent of each pad."),
    KeySpec {
        key: "bearing.pads.pivot_deg",
        unit: "°",
        allowed: Allowed::NumberPerPad(ANGLE),
        typical: Some((0.0, 360.0)),
        default: "",
        meaning: "Angle of each pad's pivot from +x (horizontal), counter-clockwise; the load usually acts at 270° (down). A pivot at 270° is load on pad, pivots at 225° and 315° load between pads. One angle: the first pad, the others evenly spaced.",
    },
    rule(
        "bearing.pads.offset",
        "–",
        "(0, 1) for tilting pads, [0, 1] for fixed sectors",
        (0.4, 0.7),
        "0.5 for fixed sectors",
        "Pivot position as a fraction of the arc from the leading edge: 0.5 is centred (either rotation direction), 0.6 is the common offset that raises the film thickness and lowers the temperature.",
    ),
    num(
        "bearing.pads.preload",
        "–",
        Range { lo: -1.0, hi: 1.0, open_lo: false, open_hi: true },
        (0.0, 0.7),
        "give one of preload, clearance_um, bore_radius_mm",
        "m = 1 − Cb/Cp: how much the pads' own curvature converges on the journal. Preload keeps unloaded pads working (a converging wedge) and raises stiffness.",
    ),
    num("bearing.pads.clearance_um", "µm", Range::positive(1e6), (20.0, 600.0), "give one of preload, clearance_um, bore_radius_mm", "Machined radial clearance of the pads: pad bore radius minus journal radius."),
    rule("bearing.pads.bore_radius_mm", "mm", "(journal radius, 10000]", (10.0, 500.0), "give one of preload, clearance_um, bore_radius_mm", "Radius to which the pads are machined, Rp = R + Cp."),
    num("bearing.pads.thickness_mm", "mm", Range::positive(1e4), (3.0, 150.0), "0 for fixed sectors", "Radial thickness of the pad; the pivot sits on its back, so t sets the lever of the tilt."),
    num(
        "bearing.pads.pivot_stiffness_n_per_m",
        "N/m",
        Range::closed(1e5, 1e14),
        (1e6, 1e10),
        "rigid pivot",
        "Radial stiffness of the pivot contact (a rocker-back Hertz contact, a spring). Absent: rigid pivot. A soft pivot lowers the bearing's effective stiffness.",
    ),
    num(
        "bearing.pads.pivot_transverse_stiffness_n_per_m",
        "N/m",
        Range::closed(1e5, 1e14),
        (1e6, 1e10),
        "rigid pivot",
        "Stiffness of the pivot across the pivot line (a rocker's tangential contact). Absent: the pivot does not move sideways. A finite value adds the sideways pivot motion as a pad coordinate.",
    ),
    num("bearing.pads.density_kg_per_m3", "kg/m³", Range::positive(3e4), (1000.0, 9000.0), "7800", "Pad material density: sets the pad inertia that enters the frequency-dependent reduced coefficients."),
    other(
        "bearing.pads.massless",
        "",
        Allowed::Bool,
        "false",
        "Pads without inertia (zero mass and moment of inertia), as databook coefficients assume; the reduced coefficients then do not depend on the pad material. Give no density with it.",
    ),
    num("bearing.pads.youngs_modulus_gpa", "GPa", Range::positive(2000.0), (70.0, 220.0), "200", "Pad material stiffness, for the pad flexibility model (steel 200 GPa, brass about 100 GPa). Not used by rigid pads."),
    num("bearing.pads.poisson_ratio", "–", Range::open(-1.0, 0.5), (0.25, 0.35), "0.3", "Pad material Poisson ratio, for the pad flexibility model."),
    other(
        "bearing.pads.pivot_contact",
        "",
        Allowed::Choice(&["rocker", "ball"]),
        "none (pivot_stiffness_n_per_m, else rigid)",
        "Pivot stiffness from a Hertz contact, nonlinear in the pad's load: a rocker (cylinder in a cylindrical seat, line contact) or a ball in a socket. The radial stiffness follows each pad's load in the equilibrium (isothermal model). Instead of pivot_stiffness_n_per_m.",
    ),
    num("bearing.pads.pivot_radius_mm", "mm", Range::positive(1e4), (5.0, 200.0), "required with pivot_contact", "Radius of the pivot's convex surface (rocker back or ball), of the pad's material. Smaller radii make softer, more load-dependent pivots."),
    num("bearing.pads.pivot_seat_radius_mm", "mm", Range::positive(1e4), (5.0, 250.0), "required with pivot_contact", "Radius of the housing's concave seat, larger than the pivot radius; the closer the two, the more conformal and stiffer the contact."),
    num("bearing.pads.pivot_length_mm", "mm", Range::positive(1e4), (10.0, 300.0), "the bearing length", "Length of a rocker's line contact (not used by a ball)."),
    num("bearing.pads.pivot_seat_youngs_modulus_gpa", "GPa", Range::positive(2000.0), (70.0, 220.0), "200", "Young's modulus of the pivot seat (housing) material."),
    num("bearing.pads.pivot_seat_poisson_ratio", "–", Range::open(-1.0, 0.5), (0.25, 0.35), "0.3", "Poisson ratio of the pivot seat (housing) material."),
    // [[bearing.pads.orifice]]
    rule(
        "bearing.pads.orifice[].position_frac",
        "–",
        "(0, 1), the hole inside the pad's arc",
        (0.1, 0.9),
        "",
        "Circumferential position of the orifice centre as a fraction of the arc from the leading edge. Injection near the leading edge lifts the pad's leading edge and cools the film.",
    ),
    rule(
        "bearing.pads.orifice[].axial_frac",
        "–",
        "(0, 1), the hole inside the pad's length",
        (0.2, 0.8),
        "0.5",
        "Axial position as a fraction of the length; 0.5 is the mid-plane (the half model needs every orifice there).",
    ),
    num("bearing.pads.orifice[].diameter_mm", "mm", Range::positive(1e3), (1.0, 10.0), "", "Orifice diameter: the injected flow scales with d0⁴ (Hagen–Poiseuille)."),
    num(
        "bearing.pads.orifice[].length_mm",
        "mm",
        Range::positive(1e4),
        (1.0, 20.0),
        "",
        "Length of the capillary through the pad: its hydraulic resistance, proportional to l0/d0⁴, throttles the injection.",
    ),
    // [lubricant]
    other("lubricant.name", "", Allowed::Text, "empty", "Oil name, for the record (e.g. ISO VG32)."),
    num(
        "lubricant.viscosity_pa_s",
        "Pa·s",
        Range::positive(100.0),
        (0.002, 0.1),
        "",
        "Dynamic viscosity at the first catalogue temperature (ISO VG32 ≈ 0.028 Pa·s at 40 °C). Pressure and load capacity scale with µ.",
    ),
    num("lubricant.viscosity_temperature_c", "°C", TEMP, (20.0, 100.0), "", "Temperature of the first viscosity point."),
    num(
        "lubricant.viscosity2_pa_s",
        "Pa·s",
        Range::positive(100.0),
        (0.001, 0.05),
        "give a second point or viscosity_coefficient_per_k",
        "Second catalogue viscosity point: with the first it fixes the exponential viscosity–temperature law.",
    ),
    num("lubricant.viscosity2_temperature_c", "°C", TEMP, (40.0, 120.0), "give a second point or viscosity_coefficient_per_k", "Temperature of the second viscosity point (e.g. 100 °C)."),
    num(
        "lubricant.viscosity_coefficient_per_k",
        "1/K",
        Range::closed(0.0, 1.0),
        (0.0, 0.06),
        "from the two viscosity points",
        "µ(T) = µ1 exp(−η (T − T1)): how fast the oil thins with temperature (mineral oils ≈ 0.03 /K).",
    ),
    num("lubricant.density_kg_per_m3", "kg/m³", Range::positive(2e4), (800.0, 950.0), "", "Oil density (thermal model: heat carried by the flow)."),
    num("lubricant.specific_heat_j_per_kg_k", "J/(kg·K)", Range::positive(1e5), (1700.0, 2200.0), "", "Heat capacity of the oil (thermal model)."),
    num("lubricant.conductivity_w_per_m_k", "W/(m·K)", Range::positive(1e3), (0.1, 0.16), "", "Thermal conductivity of the oil (thermal model)."),
    // [operating]
    num(
        "operating.speed_rpm",
        "rpm",
        Range::closed(0.0, 1e6),
        (500.0, 15000.0),
        "",
        "Journal speed. Faster running drags more oil into the wedge: the journal rises towards the centre (smaller ε), power loss grows about with the square of speed.",
    ),
    num(
        "operating.load_n",
        "N",
        Range::closed(0.0, 1e10),
        (0.0, 50000.0),
        "give load_n or eccentricity_ratio",
        "Static load on the journal (for example the rotor weight share). Specific loads of 0.5–3 MPa on the projected area L·D are usual.",
    ),
    num("operating.load_angle_deg", "°", ANGLE, (0.0, 360.0), "270", "Direction of the load from +x, counter-clockwise: 270° is straight down."),
    num("operating.eccentricity_ratio", "–", Range::closed(0.0, 10.0), (0.0, 0.9), "give load_n or eccentricity_ratio", "Prescribed journal displacement divided by the assembled clearance."),
    num("operating.eccentricity_angle_deg", "°", ANGLE, (0.0, 360.0), "270", "Direction of the prescribed displacement from +x, counter-clockwise."),
    num("operating.supply_temperature_c", "°C", TEMP, (20.0, 70.0), "", "Temperature of the oil fed to the bearing."),
    num(
        "operating.film_temperature_c",
        "°C",
        TEMP,
        (20.0, 120.0),
        "the supply temperature",
        "The one temperature of the isothermal film (sets its viscosity). Unset: the supply temperature. A few tens of kelvin above supply is more realistic.",
    ),
    KeySpec {
        key: "operating.injection_pressure_bar",
        unit: "bar",
        allowed: Allowed::NumberPerPad(Range::closed(0.0, 5000.0)),
        typical: Some((0.0, 100.0)),
        default: "0",
        meaning: "Pressure at the orifice entry (controllable lubrication). 0: the orifice is open to ambient and acts as a sink where the film pressure is higher. High pressure lifts the pad and reverses the film flow upstream of the orifice.",
    },
    num(
        "operating.injection_temperature_c",
        "°C",
        TEMP,
        (20.0, 80.0),
        "the supply temperature",
        "Temperature of the injected oil: sets its viscosity in the orifice (and cools the film in the thermal model). Unset: the supply temperature.",
    ),
    num(
        "operating.excitation_ratio",
        "–",
        Range::closed(0.0, 1e3),
        (0.0, 3.0),
        "1",
        "Frequency at which the pad coordinates are condensed out of the coefficients, relative to the running speed. 1 = synchronous (unbalance response); sub-synchronous values matter for stability.",
    ),
    // [mesh]
    other(
        "mesh.fidelity",
        "",
        Allowed::Choice(&["preview", "standard", "reference"]),
        "standard",
        "Element counts per pad: preview 16×8 (fast, a few % error), standard 36×16, reference 96×48 (for convergence checks); pads longer than 80° get proportionally more along the arc (a 360° bore: 4.5×). Each orifice is refined further.",
    ),
    count("mesh.circumferential_elements", 4, 2000, "from the fidelity", "Explicit element count along each pad's arc (before orifice refinement), overriding the fidelity level."),
    count("mesh.axial_elements", 2, 1000, "from the fidelity", "Explicit element count across the full axial length (even with the half model), overriding the fidelity level."),
    count("mesh.orifice_elements", 2, 64, "from the fidelity", "Explicit element count across each orifice diameter (local refinement), overriding the fidelity level."),
    count("mesh.pad_radial_elements", 1, 200, "from the fidelity", "Explicit element layers through the pad thickness (pad conduction), overriding the fidelity level."),
    KeySpec {
        key: "mesh.max_nodes",
        unit: "nodes",
        allowed: Allowed::Integer { lo: crate::model::budget::MAX_NODES_RANGE.0, hi: crate::model::budget::MAX_NODES_RANGE.1 },
        typical: Some((1e4, 1e7)),
        default: "500000",
        meaning: "Node budget: the most mesh nodes a solve may allocate (film nodes over all pads plus, with the thermal model, the pad solids' nodes). A case whose meshes would need more is refused before anything is built; memory grows about 2 kB per node and time faster than the node count.",
    },
    other(
        "mesh.half_model",
        "",
        Allowed::Bool,
        "true when every orifice is on the mid-plane",
        "Model half the pad length with a symmetry plane (half the cost). Automatic: used when every orifice is on the mid-plane, the only case where the film is symmetric.",
    ),
    // [physics]
    other(
        "physics.cavitation",
        "",
        Allowed::Choice(&["reynolds", "gumbel"]),
        "reynolds",
        "Where the film diverges the pressure would fall below ambient; oil cannot sustain that and the film ruptures. Reynolds (Swift–Stieber): p ≥ 0 with zero flux gradient at the rupture boundary, solved exactly. Gümbel: solve, then clip negative pressures (simpler, violates mass conservation).",
    ),
    rule(
        "physics.touchdown_film_um",
        "µm",
        "(0, half the assembled clearance]",
        (0.1, 10.0),
        "1 % of the assembled clearance",
        "Smallest film thickness accepted at equilibrium; below it the solve reports touchdown (contact through the surface roughness).",
    ),
    KeySpec {
        key: "physics.pad_modes",
        unit: "",
        allowed: Allowed::Integer { lo: 0, hi: 3 },
        typical: Some((0.0, 3.0)),
        default: "0 (rigid pads)",
        meaning: "Bending modes per tilting pad beyond the rigid tilt (pad flexibility by pseudo-modal reduction of the pad's finite-element model, with E, ν and density of the pads). Each mode adds a coordinate to the equilibrium and a row/column to the full coefficient matrices. The first bending mode carries almost all of the effect.",
    },
    // [thermal]
    other(
        "thermal.model",
        "",
        Allowed::Choice(&["isothermal", "thd"]),
        "isothermal",
        "Isothermal: one viscosity, at the film temperature. THD: the film energy equation (shear heating, convection, conduction, injection), 3-D pad conduction and the groove mixing between pads, iterated with the equilibrium until the viscosity field converges. THD lowers stiffness and damping.",
    ),
    other(
        "thermal.pad_film_bc",
        "",
        Allowed::Choice(&["bc1", "bc2", "bc3"]),
        "bc1",
        "BC1: adiabatic film, the pad surface takes the film temperature (decoupled, fast; laminar bearings). BC2: convective exchange with a constant coefficient. BC3 (Knight & Barrett): parabolic temperature across the film, coupled with the pad and the journal (near the laminar limit).",
    ),
    num(
        "thermal.h_oil_pad_w_per_m2_k",
        "W/(m²·K)",
        Range::positive(1e8),
        (100.0, 20_000.0),
        "required with bc2, not allowed otherwise",
        "BC2 only: heat flux from the film into the pad surface per kelvin of difference. A single coefficient cannot describe the laminar film well (the thesis shows BC2 is poor); offered for comparison.",
    ),
    num("thermal.convection_w_per_m2_k", "W/(m²·K)", Range::closed(0.0, 1e6), (10.0, 1000.0), "100", "Heat-transfer coefficient from the pads' free faces (back, sides, edges) to the surrounding oil at T∞."),
    num("thermal.ambient_temperature_c", "°C", TEMP, (0.0, 150.0), "the supply temperature", "Temperature of the oil around the pads (default: the supply temperature)."),
    num("thermal.pad_conductivity_w_per_m_k", "W/(m·K)", Range::positive(1e4), (1.0, 400.0), "45", "Thermal conductivity of the pad material (steel ≈ 45, brass ≈ 109, bronze ≈ 60)."),
    num(
        "thermal.carry_over",
        "–",
        Range::closed(0.0, 1.0),
        (0.0, 1.0),
        "0.8",
        "Fraction of the hot oil leaving a pad's trailing edge that enters the next pad (typically 0.7–0.9); fresh supply oil makes up the rest of the leading-edge inflow.",
    ),
    num("thermal.inlet_temperature_c", "°C", TEMP, (0.0, 150.0), "from the groove mixing", "Leading-edge oil temperature of every pad, when measured. Unset: from the groove mixing balance."),
    num("thermal.journal_temperature_c", "°C", TEMP, (0.0, 150.0), "from zero net heat flux", "Journal surface temperature, when known. Unset: from zero net heat flux into the journal."),
    num(
        "thermal.pad_expansion_ppm_per_k",
        "10⁻⁶/K",
        Range::closed(0.0, 100.0),
        (10.0, 20.0),
        "0",
        "TEHD: thermal expansion of the pads (steel ≈ 12, bronze ≈ 18). The pad's 3-D temperature strains its solid (clamped on the pivot patch); the film-face radial displacement changes the film thickness inside the thermal loop. 0: no pad growth.",
    ),
    num(
        "thermal.journal_expansion_ppm_per_k",
        "10⁻⁶/K",
        Range::closed(0.0, 100.0),
        (10.0, 20.0),
        "0",
        "TEHD: thermal expansion of the journal (steel ≈ 11–12): it grows by α R (T_journal − T_ref), closing every film by as much. 0: no journal growth.",
    ),
    num("thermal.reference_temperature_c", "°C", TEMP, (0.0, 60.0), "the supply temperature", "TEHD: temperature at which the clearances are given (the assembly temperature); growth is counted from it."),
    num(
        "thermal.housing_expansion_ppm_per_k",
        "10⁻⁶/K",
        Range::closed(0.0, 100.0),
        (10.0, 24.0),
        "0",
        "TEHD: thermal expansion of the housing and pivots (steel ≈ 12, aluminium ≈ 23) at the housing temperature: each pivot moves out by α R_p (T_housing − T_ref) (R_p: the pivot radius, journal radius + assembled clearance + pad thickness), opening its film by that times cos(θ − θ_pivot); a fixed sector's bore grows by α times its radius. 0: no housing growth.",
    ),
    num("thermal.housing_temperature_c", "°C", TEMP, (20.0, 80.0), "the supply temperature", "TEHD: temperature of the housing and pivots, for their growth (thermal.housing_expansion_ppm_per_k)."),
    other(
        "thermal.cavitated_film",
        "",
        Allowed::Choice(&["striated", "full_film"]),
        "striated",
        "Striated: in a ruptured zone oil fills only the fraction of the gap that carries the flow entering it (mass conservation of the Couette flow); shear and heat capacity scale with it. Full film: as the thesis assumes.",
    ),
    // [hydraulics]
    num("hydraulics.supply_pressure_bar", "bar", Range::positive(1000.0), (10.0, 200.0), "", "Supply pressure at the servovalve's P port. Sets the valve's flow gain (Bernoulli: ∝ √(supply − return)); the thesis' rig used 20, 40 and 80 bar."),
    num("hydraulics.return_pressure_bar", "bar", Range::closed(0.0, 1000.0), (0.0, 5.0), "0", "Tank pressure at the valve's T port; must stay below the supply."),
    num("hydraulics.valve.natural_frequency_hz", "Hz", Range::positive(1e5), (20.0, 500.0), "", "Natural frequency ω_V/2π of the spool's second-order response (G1 = x_V/u_V); its bandwidth limits the active force at high frequency."),
    num("hydraulics.valve.damping_ratio", "–", Range::positive(10.0), (0.3, 1.2), "", "Damping ratio ξ_V of the spool's second-order response."),
    num("hydraulics.valve.rated_flow_l_per_min", "L/min", Range::positive(1e4), (1.0, 100.0), "", "Datasheet rated flow at full-scale signal and rated pressure drop."),
    num("hydraulics.valve.rated_drop_bar", "bar", Range::positive(1000.0), (35.0, 140.0), "", "Datasheet pressure drop at which the rated flow is given (over both metering edges)."),
    num("hydraulics.valve.full_scale_v", "V", Range::positive(1000.0), (1.0, 10.0), "10", "Full-scale control signal. The linear valve model holds up to about 10 % of it (small signals)."),
    num(
        "hydraulics.valve.flow_pressure_coefficient_l_per_min_bar",
        "L/(min·bar)",
        Range::closed(0.0, 1000.0),
        (0.0, 0.1),
        "0",
        "Flow–pressure coefficient K_c = −K_pq: port flow lost per unit load pressure. Terminates the lines at the valve end (damps their acoustic modes) and limits the static pressure gain.",
    ),
    num("hydraulics.valve.leakage_l_per_min", "L/min", Range::closed(0.0, 1e4), (0.0, 2.0), "0", "Null leakage into each port (underlapped spool). Static only: it sets the nozzle pressure with the spool centred, not the small-signal responses."),
    other("hydraulics.port[].valve_port", "", Allowed::Choice(&["A", "B"]), "", "Which valve port feeds this line: A (driven with the signal) or B (against it)."),
    other("hydraulics.port[].pads", "", Allowed::Rule("list of pad indices, 0-based, each pad on at most one port"), "", "The pads whose orifices this line feeds; they share its nozzle-end pressure."),
    num("hydraulics.port[].line_length_mm", "mm", Range::positive(1e5), (100.0, 3000.0), "", "Length of the injection line from the valve port to the nozzles. Its quarter-wave modes f_i = (2i−1) c0/(4 l) shape G2; 700 mm on the thesis' rig."),
    num("hydraulics.port[].line_diameter_mm", "mm", Range::positive(1000.0), (2.0, 12.0), "", "Inner diameter of the injection line (area, laminar friction 32 µ/(ρ D²))."),
    num("hydraulics.port[].bulk_modulus_gpa", "GPa", Range::positive(100.0), (1.0, 2.0), "1.5", "Bulk modulus of the air-free oil (mineral oils 1.4–1.7 GPa)."),
    num("hydraulics.port[].air_fraction", "–", Range::closed(0.0, 0.5), (0.0, 0.02), "0", "Volume fraction of entrained air at the line's static pressure. A little air lowers the line's modes dramatically (1 % at a few bar: 470 Hz → about 100 Hz)."),
    num("hydraulics.port[].wall_compliance_per_gpa", "1/GPa", Range::closed(0.0, 1000.0), (0.0, 1.0), "0", "Compliance of the line's wall, added to the oil's 1/β (a hose is much softer than a steel tube)."),
    other("hydraulics.port[].modes", "", Allowed::Integer { lo: 1, hi: super::hydraulics::MAX_MODES }, "4", "Acoustic modes kept in the line's modal model (the quasi-static rest is added back)."),
    num("hydraulics.rig.mass_kg", "kg", Range::positive(1e6), (5.0, 500.0), "", "Effective mass of the rig's rotor and tilting frame on its one vertical degree of freedom."),
    num("hydraulics.rig.support_stiffness_n_per_m", "N/m", Range::closed(0.0, 1e12), (1e5, 1e8), "", "Stiffness of the rig's support (parallel to the bearing film)."),
    num("hydraulics.rig.support_damping_ns_per_m", "N·s/m", Range::closed(0.0, 1e9), (0.0, 1e4), "0", "Damping of the rig's support."),
    // [limits] (conventions, see super::limits)
    num("limits.min_film_thickness_um", "µm", super::limits::MIN_FILM_RANGE, (5.0, 30.0), "10 (convention)", "Smallest acceptable film thickness on any pad. ISO 7902-3 permits about 3–20 µm depending on journal diameter and speed; 10 µm is a convention for 100–250 mm journals."),
    num("limits.max_pad_temperature_c", "°C", super::limits::PAD_TEMPERATURE_RANGE, (90.0, 130.0), "120 (convention)", "Hottest acceptable pad (babbitt) temperature; checked on THD solves (the film maximum when the pads have no solid). Tin babbitt softens above about 120–130 °C."),
    num("limits.max_specific_load_mpa", "MPa", super::limits::SPECIFIC_LOAD_RANGE, (1.0, 5.0), "3.5 (convention)", "Highest acceptable unit load W/(L·D). Tilting-pad journal bearings commonly run at 1–3.5 MPa."),
    num("limits.max_peak_pressure_mpa", "MPa", super::limits::PEAK_PRESSURE_RANGE, (10.0, 40.0), "20 (convention)", "Highest acceptable film pressure (babbitt fatigue). Published allowables range from about 15 to 35 MPa with babbitt thickness and temperature."),
    num("limits.max_reynolds", "–", super::limits::REYNOLDS_RANGE, (500.0, 2000.0), "1000 (convention)", "Highest acceptable local film Reynolds number ρ Ω R h / µ: above the laminar–turbulent transition (1000–1500) the laminar model underestimates loss and temperature."),
];

/// The row of a key as written in a file, a `--set` override or a validation message:
/// `bearing.pads.orifice[2].diameter_mm` and `bearing.pads.orifice.2.diameter_mm` find
/// `bearing.pads.orifice[].diameter_mm`; `bearing.pad.3.offset` and `bearing.pads.pivot_deg[1]` find
/// their `bearing.pads` rows.
#[must_use]
pub fn spec(key: &str) -> Option<&'static KeySpec> {
    let normal = normalise(key);
    KEYS.iter().find(|s| s.key == normal)
}

fn normalise(key: &str) -> String {
    // `a[3].b` → `a.3.b`, then every numeric segment becomes `[]` on the segment before it.
    let dotted = key.replace('[', ".").replace(']', "");
    let mut out: Vec<String> = Vec::new();
    for part in dotted.split('.').filter(|p| !p.is_empty()) {
        if part.parse::<usize>().is_ok() {
            if let Some(last) = out.last_mut() {
                last.push_str("[]");
            }
        } else {
            out.push(part.to_string());
        }
    }
    let mut k = out.join(".");
    // Per-pad overrides share the rows of the common pad table.
    if let Some(rest) = k.strip_prefix("bearing.pad[].") {
        k = format!("bearing.pads.{rest}");
    }
    // A list element (`pivot_deg[1]`) is the list's key.
    k.strip_suffix("[]").map_or(k.clone(), str::to_string)
}

/// The table as plain text: one block per key.
#[must_use]
pub fn text_table() -> String {
    text_table_of(KEYS)
}

/// A table of keys (the case's, or the rotor file's: [`super::rotor_schema::ROTOR_KEYS`]) as plain text.
#[must_use]
pub fn text_table_of(keys: &[KeySpec]) -> String {
    let mut s = String::new();
    for k in keys {
        let unit = if k.unit.is_empty() { "–" } else { k.unit };
        let default = if k.default.is_empty() { "required" } else { k.default };
        let _ = writeln!(s, "{}  [{unit}]\n  allowed: {}\n  default: {default}", k.key, k.allowed.describe());
        if let Some((lo, hi)) = k.typical {
            let _ = writeln!(s, "  typical: {lo} – {hi}");
        }
        let _ = writeln!(s, "  {}\n", k.meaning);
    }
    s
}

/// The table as JSON (one object per key).
#[must_use]
pub fn json_table() -> serde_json::Value {
    json_table_of(KEYS)
}

/// A table of keys as JSON (one object per key).
#[must_use]
pub fn json_table_of(keys: &[KeySpec]) -> serde_json::Value {
    serde_json::Value::Array(
        keys.iter()
            .map(|k| {
                serde_json::json!({
                    "key": k.key,
                    "unit": k.unit,
                    "allowed": k.allowed.describe(),
                    "typical": k.typical.map(|(a, b)| [a, b]),
                    "required": k.default.is_empty(),
                    "default": k.default,
                    "meaning": k.meaning,
                })
            })
            .collect(),
    )
}

#[cfg(test)]
mod tests;
