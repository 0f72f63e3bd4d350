//! One table of a solution's outputs ([`OUTPUTS`]): every scalar quantity a bearing engineer reads off a
//! solve, declared once, as one row.
//!
//! A row ([`Output`]) says what the quantity is called (`label`, as the results panel, the compare table and
//! the command line's summary write it), what it means, the unit a person reads it in, where the JSON
//! `tiltpad solve --json` writes it (in SI), its CSV column of `sweep`/`batch` (in the row's unit; `None`:
//! not a column), its Python attributes, how a live value compares with a pinned one (relative for
//! magnitudes, a difference for angles and Celsius temperatures), the panel section it is shown in and the
//! group whose values share one unit prefix. Its `value` reads the SI value from a [`Solution`]; that and the
//! physics that computes it are all an added output needs. Every reader goes through this table:
//! [`crate::bearing::solution::json`] (the JSON), [`crate::study::columns`] (CSV columns and pins),
//! `scene::summary` (the results panel and the command line's summary), `scene::compare` (the compare table)
//! and the Python package's `Solution` attributes.
//!
//! **Where it lives.** The table reads [`Solution`], so it sits in `bearing/` — the lowest layer that can see
//! a solution (`model/` lies below `bearing/` and cannot) and below every reader (`study`, `scene`, `cli`,
//! the app and Python).
//!
//! **What stays structural.** The JSON writer writes every row whose path is one key at the top
//! (`/h_min_m`) from this table; a row whose path runs deeper (`/reduced/k_n_per_m/0/1`,
//! `/thermal/journal_temperature_c`, `/inputs/speed_rad_s`) names where the serialised structures already
//! hold it, and a test checks that both agree. Structural, and not rows: the vectors and the full matrices
//! (the load and journal position as `[x, y]`, the reduced `K` and `C` as 2×2 arrays beside their eight
//! scalar rows, the full coefficient matrices, the per-pad results and fields, the flows of each pad), the
//! nested reports (the solve and thermal reports with their warnings and histories, the flow-regime checks,
//! the design limits and their checks) and the resolved inputs — each has a shape of its own that a table of
//! numbers does not describe, and each is written by serialising its Rust type.
//!
//! Units: `value` is the number the JSON holds — SI, or the unit the solution's field names (temperatures in
//! °C, the attitude angle in degrees); the row's `unit` converts it for the CSV column, the panel and the
//! `Py::Shown` attributes.

use serde_json::Value;

use crate::bearing::solution::result::{Solution, ThermalResult};
use crate::units::{
    Unit, CELSIUS, COUNT, L_PER_MIN, MPA, MPA_S, MS, NODES, NS_PER_M, N_M, N_PER_M, ONE, RAD_PER_S, RPM, UM, W,
};

/// How the panel and the summary write a value.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Digits {
    /// A fixed number of decimals in the row's unit (h_min 53.93 µm).
    Decimals(usize),
    /// Four significant digits in the row's unit (the Sommerfeld number).
    Significant,
    /// Four significant digits in the row's SI unit with an engineering prefix, the one prefix of its group
    /// chosen by the group's largest magnitude (Kxx and Kyy both in MN/m).
    Prefixed,
    /// A relative residual or balance: round-off (below 1e-12) reads "< 1e-12".
    RoundOff,
    /// A whole number.
    Count,
}

/// How a live value compares with a pinned one.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Compare {
    /// (live − pinned) / |pinned|, in per cent: a magnitude (a load, a thickness, a stiffness).
    Relative,
    /// live − pinned, in the row's unit: an angle, or a temperature on the Celsius scale, whose zero is a
    /// convention, so a ratio means nothing (an attitude angle from 2° to −8.9° changed by −10.9°, not −545 %).
    Difference,
    /// Not compared (solver bookkeeping, not a result).
    Not,
}

/// The part of the results panel a row is shown in, in panel order.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Section {
    Operating,
    Flows,
    Thermal,
    Coefficients,
    Solver,
}

impl Section {
    pub const ALL: [Section; 5] =
        [Section::Operating, Section::Flows, Section::Thermal, Section::Coefficients, Section::Solver];

    #[must_use]
    pub fn title(self) -> &'static str {
        match self {
            Section::Operating => "Operating point",
            Section::Flows => "Flows",
            Section::Thermal => "Thermal (THD)",
            Section::Coefficients => "Reduced coefficients",
            Section::Solver => "Solver report",
        }
    }
}

/// Rows read together: their values share one unit prefix (chosen by the largest magnitude among them), and
/// the panel shows `per_line` of them on a line (a 2×2 matrix as two lines of two).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Group {
    pub name: &'static str,
    pub per_line: usize,
}

/// The reduced stiffness matrix.
pub const STIFFNESS: Group = Group { name: "K", per_line: 2 };
/// The reduced damping matrix.
pub const DAMPING: Group = Group { name: "C", per_line: 2 };
/// The power losses.
pub const POWER: Group = Group { name: "power", per_line: 1 };
/// The film's heat balance.
pub const HEAT: Group = Group { name: "heat", per_line: 1 };

/// A Python attribute of `tiltpad.Solution`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Py {
    /// The SI value (`h_min_m`).
    Si(&'static str),
    /// The value in the row's unit (`h_min_um`, `speed_rpm`).
    Shown(&'static str),
    /// A whole number (`iterations`).
    Count(&'static str),
}

impl Py {
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Py::Si(n) | Py::Shown(n) | Py::Count(n) => n,
        }
    }
}

/// One output quantity.
#[derive(Clone, Copy)]
pub struct Output {
    /// Its name where people read it: the results panel, the summary, the compare table.
    pub label: &'static str,
    /// What it means (the panel's hover text).
    pub meaning: &'static str,
    /// The unit it is read in (CSV column, panel, summary); for [`Digits::Prefixed`] the SI unit that takes
    /// the prefix.
    pub unit: Unit,
    pub digits: Digits,
    /// JSON pointer of its SI value in the solution's JSON (a top-level key is written from this table).
    pub json: &'static str,
    /// Its CSV column in `sweep`/`batch` (and the key of a pinned cell), in [`Self::unit`]; `None`: no column.
    pub csv: Option<&'static str>,
    /// Its attributes on Python's `tiltpad.Solution`.
    pub python: &'static [Py],
    pub compare: Compare,
    pub section: Section,
    pub group: Option<Group>,
    /// The value as the JSON holds it (SI, or the unit its key names); `None` where the solution has none
    /// (temperatures of an isothermal solve).
    pub value: fn(&Solution) -> Option<f64>,
    /// Why the panel shows no number (`"isothermal"`), where it shows none.
    pub note: fn(&Solution) -> Option<&'static str>,
}

impl std::fmt::Debug for Output {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.label)
    }
}

impl Output {
    /// The value as the JSON holds it (SI, or the unit its key names).
    #[must_use]
    pub fn si(&self, s: &Solution) -> Option<f64> {
        (self.value)(s)
    }

    /// The value in the row's unit (the CSV cell).
    #[must_use]
    pub fn shown(&self, s: &Solution) -> Option<f64> {
        self.si(s).map(|v| self.unit.from_si(v))
    }

    /// The JSON key this table writes (a path of one key), or `None` for a path inside the structures.
    #[must_use]
    pub fn json_key(&self) -> Option<&'static str> {
        self.json.strip_prefix('/').filter(|k| !k.contains('/'))
    }
}

/// The row of a CSV column.
#[must_use]
pub fn by_column(name: &str) -> Option<&'static Output> {
    OUTPUTS.iter().find(|o| o.csv == Some(name))
}

/// The row and attribute of a Python name.
#[must_use]
pub fn by_python(name: &str) -> Option<(&'static Output, Py)> {
    OUTPUTS.iter().find_map(|o| o.python.iter().find(|p| p.name() == name).map(|p| (o, *p)))
}

/// Writes the rows of top-level keys into a solution's JSON object (null where the solution has no value).
pub fn write_json(json: &mut Value, s: &Solution) {
    if let Value::Object(map) = json {
        for o in OUTPUTS {
            if let Some(key) = o.json_key() {
                map.insert(key.to_string(), o.si(s).map_or(Value::Null, Value::from));
            }
        }
    }
}

/// Degrees as the solution keeps its attitude angle (the field names its unit): a factor of one.
const DEGREES: Unit = Unit { symbol: "°", si: 1.0 };

fn thermal(s: &Solution) -> Option<&ThermalResult> {
    s.thermal.as_ref()
}

fn isothermal(s: &Solution) -> Option<&'static str> {
    s.thermal.is_none().then_some("isothermal")
}

#[allow(clippy::cast_precision_loss)]
fn count(n: usize) -> Option<f64> {
    Some(n as f64)
}

/// The defaults a row starts from.
const ROW: Output = Output {
    label: "",
    meaning: "",
    unit: ONE,
    digits: Digits::Significant,
    json: "",
    csv: None,
    python: &[],
    compare: Compare::Relative,
    section: Section::Operating,
    group: None,
    value: |_| None,
    note: |_| None,
};

const K_MEANING: &str = "Reduced stiffness: force along the first axis per displacement along the second.";
const C_MEANING: &str = "Reduced damping: force along the first axis per velocity along the second.";

/// Every output, in the order of the CSV columns and of the panel within each section. A new row goes at the
/// end: its section puts it in its place in the panel, and the CSV's columns keep their positions.
pub const OUTPUTS: &[Output] = &[
    // Operating point.
    Output {
        label: "Speed",
        meaning: "Journal speed Ω.",
        unit: RPM,
        json: "/inputs/speed_rad_s",
        python: &[Py::Si("speed_rad_s"), Py::Shown("speed_rpm")],
        value: |s| Some(s.derived.speed_rad_s),
        ..ROW
    },
    Output {
        label: "Eccentricity ε",
        meaning: "Journal displacement from the bearing centre divided by the assembled clearance Cb.",
        digits: Digits::Decimals(4),
        json: "/eccentricity_ratio",
        csv: Some("eccentricity_ratio"),
        python: &[Py::Si("eccentricity"), Py::Si("eccentricity_ratio")],
        value: |s| Some(s.eccentricity_ratio),
        ..ROW
    },
    Output {
        label: "Attitude angle",
        meaning: "Angle from the load direction to the journal displacement, positive in the direction of rotation. \
                  Zero for a symmetric load-on-pad tilting-pad bearing.",
        unit: DEGREES,
        digits: Digits::Decimals(2),
        json: "/attitude_angle_deg",
        csv: Some("attitude_angle_deg"),
        python: &[Py::Si("attitude_angle_deg")],
        compare: Compare::Difference,
        value: |s| Some(s.attitude_angle_deg),
        ..ROW
    },
    Output {
        label: "Load",
        meaning: "Static load carried by the film, equal and opposite to the film force.",
        unit: crate::units::N,
        digits: Digits::Prefixed,
        json: "/load_magnitude_n",
        csv: Some("load_n"),
        python: &[Py::Si("load_magnitude_n")],
        value: |s| Some(s.load_magnitude_n),
        ..ROW
    },
    Output {
        label: "Sommerfeld S",
        meaning: "S = µ N L D / W (R/Cb)², with the film viscosity and the assembled clearance: the bearing's duty \
                  in one number (large S = lightly loaded).",
        json: "/sommerfeld",
        csv: Some("sommerfeld"),
        python: &[Py::Si("sommerfeld")],
        value: |s| s.sommerfeld,
        note: |s| s.sommerfeld.is_none().then_some("no load"),
        ..ROW
    },
    Output {
        label: "h_min",
        meaning: "Smallest film thickness on any pad: the margin against metal contact.",
        unit: UM,
        digits: Digits::Decimals(2),
        json: "/h_min_m",
        csv: Some("h_min_um"),
        python: &[Py::Si("h_min_m"), Py::Shown("h_min_um")],
        value: |s| Some(s.h_min_m),
        ..ROW
    },
    Output {
        label: "p_max",
        meaning: "Largest film pressure on any pad (babbitt fatigue limit is typically a few MPa).",
        unit: MPA,
        digits: Digits::Decimals(3),
        json: "/p_max_pa",
        csv: Some("p_max_mpa"),
        python: &[Py::Si("p_max_pa"), Py::Shown("p_max_mpa")],
        value: |s| Some(s.p_max_pa),
        ..ROW
    },
    Output {
        label: "T_max film",
        meaning: "Largest film temperature from the thermal model. The isothermal model uses one film temperature; \
                  switch the physics to THD to compute temperatures.",
        unit: CELSIUS,
        digits: Digits::Decimals(1),
        json: "/t_max_film_c",
        csv: Some("t_max_film_c"),
        python: &[Py::Si("t_max_film_c")],
        compare: Compare::Difference,
        value: |s| thermal(s).map(|t| t.t_max_film_c),
        note: isothermal,
        ..ROW
    },
    Output {
        label: "T_max pad",
        meaning: "Hottest point of the pads, surface or body (the babbitt limit is ~120–130 °C).",
        unit: CELSIUS,
        digits: Digits::Decimals(1),
        json: "/t_max_pad_c",
        csv: Some("t_max_pad_c"),
        python: &[Py::Si("t_max_pad_c")],
        compare: Compare::Difference,
        section: Section::Thermal,
        value: |s| thermal(s).and_then(|t| t.t_max_pad_c),
        note: |s| match thermal(s) {
            None => Some("isothermal"),
            Some(t) => t.t_max_pad_c.is_none().then_some("no pad solid"),
        },
        ..ROW
    },
    Output {
        label: "Journal T",
        meaning: "Journal surface temperature: given, or from zero net heat flux into the journal.",
        unit: CELSIUS,
        digits: Digits::Decimals(1),
        json: "/thermal/journal_temperature_c",
        csv: Some("t_journal_c"),
        python: &[Py::Si("t_journal_c")],
        compare: Compare::Difference,
        section: Section::Thermal,
        value: |s| thermal(s).map(|t| t.journal_temperature_c),
        note: isothermal,
        ..ROW
    },
    Output {
        label: "Film friction",
        meaning: "Viscous shear power dissipated in the films (friction loss).",
        unit: W,
        digits: Digits::Prefixed,
        json: "/friction_power_w",
        csv: Some("friction_power_w"),
        python: &[Py::Si("friction_power_w")],
        group: Some(POWER),
        value: |s| Some(s.friction_power_w),
        ..ROW
    },
    Output {
        label: "Churning",
        meaning: "Power the journal loses stirring the oil of a flooded housing in the gaps between the pads \
                  (feeding.churning_factor; 0 with directed feeding).",
        unit: W,
        digits: Digits::Prefixed,
        json: "/churning_power_w",
        csv: Some("churning_power_w"),
        python: &[Py::Si("churning_power_w")],
        group: Some(POWER),
        value: |s| Some(s.churning_power_w()),
        ..ROW
    },
    Output {
        label: "Total power loss",
        meaning: "Film friction and churning: the power the bearing takes from the shaft.",
        unit: W,
        digits: Digits::Prefixed,
        json: "/total_power_loss_w",
        csv: Some("total_power_loss_w"),
        python: &[Py::Si("total_power_loss_w")],
        group: Some(POWER),
        value: |s| Some(s.total_power_loss_w()),
        ..ROW
    },
    Output {
        label: "Friction torque",
        meaning: "Drag torque of the films on the journal.",
        unit: N_M,
        digits: Digits::Prefixed,
        json: "/friction_torque_nm",
        python: &[Py::Si("friction_torque_nm")],
        value: |s| Some(s.friction_torque_nm),
        ..ROW
    },
    Output {
        label: "Film viscosity",
        meaning: "Viscosity of the isothermal film (and of the Sommerfeld number), from the lubricant's law at the \
                  film temperature.",
        unit: MPA_S,
        json: "/inputs/film_viscosity_pa_s",
        python: &[Py::Si("film_viscosity_pa_s")],
        value: |s| Some(s.derived.film_viscosity_pa_s),
        ..ROW
    },
    Output {
        label: "Clearance Cb",
        meaning: "Radial clearance between the journal and the pads' pivot circle.",
        unit: UM,
        digits: Digits::Decimals(1),
        json: "/inputs/assembled_clearance_m",
        python: &[Py::Si("assembled_clearance_m")],
        value: |s| Some(s.derived.assembled_clearance_m),
        ..ROW
    },
    // Flows.
    Output {
        label: "Leading edges in",
        meaning: "Oil drawn into the films at the pads' leading edges.",
        unit: L_PER_MIN,
        digits: Digits::Decimals(3),
        json: "/flows_m3_per_s/leading_edges_in",
        csv: Some("flow_leading_edges_in_l_per_min"),
        section: Section::Flows,
        value: |s| Some(s.flows_m3_per_s.leading_edges_in),
        ..ROW
    },
    Output {
        label: "Trailing edges out",
        meaning: "Oil carried out at the trailing edges (partly carried over to the next pad).",
        unit: L_PER_MIN,
        digits: Digits::Decimals(3),
        json: "/flows_m3_per_s/trailing_edges_out",
        csv: Some("flow_trailing_edges_out_l_per_min"),
        section: Section::Flows,
        value: |s| Some(s.flows_m3_per_s.trailing_edges_out),
        ..ROW
    },
    Output {
        label: "Sides out",
        meaning: "Side leakage at the axial ends: this is the flow the supply must replace.",
        unit: L_PER_MIN,
        digits: Digits::Decimals(3),
        json: "/flows_m3_per_s/sides_out",
        csv: Some("flow_sides_out_l_per_min"),
        section: Section::Flows,
        value: |s| Some(s.flows_m3_per_s.sides_out),
        ..ROW
    },
    Output {
        label: "Orifices in",
        meaning: "Net flow injected through the orifices (negative: oil leaves through the holes).",
        unit: L_PER_MIN,
        digits: Digits::Decimals(3),
        json: "/flows_m3_per_s/orifices_in",
        csv: Some("flow_orifices_in_l_per_min"),
        section: Section::Flows,
        value: |s| Some(s.flows_m3_per_s.orifices_in),
        // A bearing without orifices has no orifice flow to show (not a measured 0.000).
        note: |s| s.pads.iter().all(|p| p.orifice_flows_m3_per_s.is_empty()).then_some("no orifices"),
        ..ROW
    },
    Output {
        label: "Into cavitation",
        meaning: "Net flow from the full film into cavitated (ruptured) regions; negative where more oil re-enters \
                  the full film at reformation than leaves it at rupture.",
        unit: L_PER_MIN,
        digits: Digits::Decimals(3),
        json: "/flows_m3_per_s/to_cavitation",
        section: Section::Flows,
        value: |s| Some(s.flows_m3_per_s.to_cavitation),
        ..ROW
    },
    Output {
        label: "Mass balance",
        meaning: "(in − out) / throughput of the discrete solution: should be round-off small.",
        digits: Digits::RoundOff,
        json: "/flows_m3_per_s/mass_balance_error",
        section: Section::Flows,
        value: |s| Some(s.flows_m3_per_s.mass_balance_error),
        ..ROW
    },
    // Thermal (the film's extremes and the journal are above, with the CSV columns' order).
    Output {
        label: "T mean film",
        meaning: "Mean film temperature (averaged across the film thickness, over the oil-filled area).",
        unit: CELSIUS,
        digits: Digits::Decimals(1),
        json: "/thermal/t_mean_film_c",
        compare: Compare::Difference,
        section: Section::Thermal,
        value: |s| thermal(s).map(|t| t.t_mean_film_c),
        note: isothermal,
        ..ROW
    },
    Output {
        label: "Heat to oil",
        meaning: "Friction power that leaves as enthalpy of the oil (edges, orifices, ruptured zones).",
        unit: W,
        digits: Digits::Prefixed,
        json: "/thermal/heat_carried_by_oil_w",
        section: Section::Thermal,
        group: Some(HEAT),
        value: |s| thermal(s).map(|t| t.heat_carried_by_oil_w),
        note: isothermal,
        ..ROW
    },
    Output {
        label: "Heat conducted",
        meaning: "Friction power conducted out of the film into pads and journal.",
        unit: W,
        digits: Digits::Prefixed,
        json: "/thermal/heat_conducted_w",
        section: Section::Thermal,
        group: Some(HEAT),
        value: |s| thermal(s).map(|t| t.heat_conducted_w),
        note: isothermal,
        ..ROW
    },
    Output {
        label: "Energy balance",
        meaning: "(heat generated − heat to oil − heat conducted) / heat generated: the discrete energy balance, \
                  should be at round-off.",
        digits: Digits::RoundOff,
        json: "/thermal/energy_balance_closure",
        section: Section::Thermal,
        value: |s| thermal(s).map(|t| t.energy_balance_closure),
        note: isothermal,
        ..ROW
    },
    // Reduced coefficients.
    Output {
        label: "ω/Ω",
        meaning: "Excitation frequency ratio used for the reduction of the pad coordinates.",
        json: "/inputs/case/operating/excitation_ratio",
        section: Section::Coefficients,
        value: |s| Some(s.inputs.operating.excitation_ratio),
        ..ROW
    },
    Output {
        label: "Excitation ω",
        meaning: "Excitation frequency of the reduced coefficients: ω/Ω times the speed.",
        unit: RAD_PER_S,
        digits: Digits::Decimals(1),
        json: "/reduced/omega_rad_s",
        python: &[Py::Si("excitation_rad_s")],
        section: Section::Coefficients,
        value: |s| Some(s.reduced.omega_rad_s),
        ..ROW
    },
    Output {
        label: "Kxx",
        meaning: K_MEANING,
        unit: N_PER_M,
        digits: Digits::Prefixed,
        json: "/reduced/k_n_per_m/0/0",
        csv: Some("kxx_n_per_m"),
        section: Section::Coefficients,
        group: Some(STIFFNESS),
        value: |s| Some(s.reduced.k_n_per_m[0][0]),
        ..ROW
    },
    Output {
        label: "Kxy",
        meaning: K_MEANING,
        unit: N_PER_M,
        digits: Digits::Prefixed,
        json: "/reduced/k_n_per_m/0/1",
        csv: Some("kxy_n_per_m"),
        section: Section::Coefficients,
        group: Some(STIFFNESS),
        value: |s| Some(s.reduced.k_n_per_m[0][1]),
        ..ROW
    },
    Output {
        label: "Kyx",
        meaning: K_MEANING,
        unit: N_PER_M,
        digits: Digits::Prefixed,
        json: "/reduced/k_n_per_m/1/0",
        csv: Some("kyx_n_per_m"),
        section: Section::Coefficients,
        group: Some(STIFFNESS),
        value: |s| Some(s.reduced.k_n_per_m[1][0]),
        ..ROW
    },
    Output {
        label: "Kyy",
        meaning: K_MEANING,
        unit: N_PER_M,
        digits: Digits::Prefixed,
        json: "/reduced/k_n_per_m/1/1",
        csv: Some("kyy_n_per_m"),
        section: Section::Coefficients,
        group: Some(STIFFNESS),
        value: |s| Some(s.reduced.k_n_per_m[1][1]),
        ..ROW
    },
    Output {
        label: "Cxx",
        meaning: C_MEANING,
        unit: NS_PER_M,
        digits: Digits::Prefixed,
        json: "/reduced/c_ns_per_m/0/0",
        csv: Some("cxx_ns_per_m"),
        section: Section::Coefficients,
        group: Some(DAMPING),
        value: |s| Some(s.reduced.c_ns_per_m[0][0]),
        ..ROW
    },
    Output {
        label: "Cxy",
        meaning: C_MEANING,
        unit: NS_PER_M,
        digits: Digits::Prefixed,
        json: "/reduced/c_ns_per_m/0/1",
        csv: Some("cxy_ns_per_m"),
        section: Section::Coefficients,
        group: Some(DAMPING),
        value: |s| Some(s.reduced.c_ns_per_m[0][1]),
        ..ROW
    },
    Output {
        label: "Cyx",
        meaning: C_MEANING,
        unit: NS_PER_M,
        digits: Digits::Prefixed,
        json: "/reduced/c_ns_per_m/1/0",
        csv: Some("cyx_ns_per_m"),
        section: Section::Coefficients,
        group: Some(DAMPING),
        value: |s| Some(s.reduced.c_ns_per_m[1][0]),
        ..ROW
    },
    Output {
        label: "Cyy",
        meaning: C_MEANING,
        unit: NS_PER_M,
        digits: Digits::Prefixed,
        json: "/reduced/c_ns_per_m/1/1",
        csv: Some("cyy_ns_per_m"),
        section: Section::Coefficients,
        group: Some(DAMPING),
        value: |s| Some(s.reduced.c_ns_per_m[1][1]),
        ..ROW
    },
    // Solver report.
    Output {
        label: "Iterations",
        meaning: "Journal Newton iterations over the whole solve (THD: every equilibrium of the thermal loop and \
                  its isothermal start).",
        unit: COUNT,
        digits: Digits::Count,
        json: "/report/iterations",
        csv: Some("iterations"),
        python: &[Py::Count("iterations")],
        compare: Compare::Not,
        section: Section::Solver,
        value: |s| count(s.report.iterations),
        ..ROW
    },
    Output {
        label: "Pad iterations",
        meaning: "Pad (inner) iterations over the whole solve.",
        unit: COUNT,
        digits: Digits::Count,
        json: "/report/inner_iterations",
        compare: Compare::Not,
        section: Section::Solver,
        value: |s| count(s.report.inner_iterations),
        ..ROW
    },
    Output {
        label: "Film solves",
        meaning: "Reynolds solves of the whole solve.",
        unit: COUNT,
        digits: Digits::Count,
        json: "/report/film_solves",
        compare: Compare::Not,
        section: Section::Solver,
        value: |s| count(s.report.film_solves),
        ..ROW
    },
    Output {
        label: "Factorisations",
        meaning: "Sparse numeric factorisations (THD: with the film-energy and pad-conduction factorisations).",
        unit: COUNT,
        digits: Digits::Count,
        json: "/report/factorizations",
        compare: Compare::Not,
        section: Section::Solver,
        value: |s| count(s.report.factorizations),
        ..ROW
    },
    Output {
        label: "Residual",
        meaning: "Final force residual relative to the force scale.",
        digits: Digits::RoundOff,
        json: "/report/residual",
        compare: Compare::Not,
        section: Section::Solver,
        value: |s| Some(s.report.residual),
        ..ROW
    },
    Output {
        label: "Pad residual",
        meaning: "Largest pad residual (moment and force balance of the pads).",
        digits: Digits::RoundOff,
        json: "/report/pad_residual",
        compare: Compare::Not,
        section: Section::Solver,
        value: |s| Some(s.report.pad_residual),
        ..ROW
    },
    Output {
        label: "Solve time",
        meaning: "Wall time of the whole solve (THD: the isothermal start and the thermal loop).",
        unit: MS,
        digits: Digits::Decimals(0),
        json: "/report/seconds",
        python: &[Py::Si("seconds")],
        compare: Compare::Not,
        section: Section::Solver,
        value: |s| Some(s.report.seconds),
        ..ROW
    },
    Output {
        label: "Film nodes",
        meaning: "Finite-element nodes over all pads (mesh fidelity).",
        unit: NODES,
        digits: Digits::Count,
        json: "/inputs/film_nodes",
        compare: Compare::Not,
        section: Section::Solver,
        value: |s| count(s.derived.film_nodes),
        ..ROW
    },
    Output {
        label: "h_min at",
        meaning: "Where the film is thinnest: the angle of the smallest film thickness on any pad, from +x \
                  counter-clockwise (the frame of the pivot angles).",
        unit: DEGREES,
        digits: Digits::Decimals(1),
        json: "/h_min_angle_deg",
        csv: Some("h_min_angle_deg"),
        python: &[Py::Si("h_min_angle_deg")],
        compare: Compare::Difference,
        value: |s| s.pads.iter().min_by(|a, b| a.h_min_m.total_cmp(&b.h_min_m)).map(|p| p.h_min_angle_deg),
        ..ROW
    },
];

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bearing::solution::json::solution_json;
    use crate::bearing::stages::registry::{compressor_preview, solve_case};

    /// Fillon's bearing A, THD at preview fidelity: every thermal row has a value.
    fn thd() -> Solution {
        let text = include_str!("../../../cases/fillon-a.toml");
        let (_, case) = crate::model::load_case(text, &["mesh.fidelity=\"preview\"".to_string()]).unwrap();
        solve_case(&case).unwrap()
    }

    /// Each row, on an isothermal solve (the compressor bearing) and a THD one (Fillon's bearing A): its JSON
    /// path holds its value; the CSV cell `tiltpad sweep` writes is that value in the row's unit; the results
    /// panel and the command line's summary write that value with the row's digits; its Python names are
    /// its own.
    #[test]
    fn every_row_reads_the_same_number_in_json_csv_and_summary() {
        for s in [compressor_preview(&[]), thd()] {
            let json = solution_json(&s);
            let row = crate::study::Row {
                index: 0,
                inputs: Vec::new(),
                result: Ok(crate::study::columns::outputs(&s)),
                limits_exceeded: Vec::new(),
                seconds: 0.0,
            };
            let header = crate::study::Row::header("point", &[]);
            let record = row.record();
            let summary = crate::scene::summary::summary(&s);
            let text = crate::scene::summary_text::summary_text(&s);
            for o in OUTPUTS {
                let value = o.si(&s);
                // A path inside a structure the solution lacks (`/thermal/…` of an isothermal solve) ends at a null.
                let null = serde_json::Value::Null;
                let absent = || {
                    let parts: Vec<&str> = o.json.split('/').collect();
                    (2..parts.len()).any(|n| json.pointer(&parts[..n].join("/")).is_some_and(Value::is_null))
                };
                let at = match json.pointer(o.json) {
                    Some(at) => at,
                    None if value.is_none() && absent() => &null,
                    None => panic!("{}: no {} in the JSON", o.label, o.json),
                };
                assert_eq!(at.as_f64(), value, "{}: JSON {} against the table", o.label, o.json);
                if let Some(column) = o.csv {
                    let k = header.iter().position(|h| h == column).unwrap();
                    let cell: Option<f64> = (!record[k].is_empty()).then(|| record[k].parse().unwrap());
                    assert_eq!(cell, at.as_f64().map(|v| o.unit.from_si(v)), "{}: CSV {column}", o.label);
                }
                // The panel's line of the row (a matrix's line holds two rows) and the summary's; a section none
                // of whose rows has a value (the thermal one of an isothermal solve) is left out.
                let Some(line) =
                    summary.groups.iter().flat_map(|g| &g.rows).find(|r| r.label.split(", ").any(|l| l == o.label))
                else {
                    let section: Vec<&Output> = OUTPUTS.iter().filter(|p| p.section == o.section).collect();
                    assert!(section.iter().all(|p| p.si(&s).is_none()), "{}: not in the results panel", o.label);
                    continue;
                };
                let (scale, unit) = crate::scene::summary::row_unit(o, &s);
                let shown = match ((o.note)(&s), at.as_f64()) {
                    (Some(why), _) => format!("— ({why})"),
                    (None, Some(v)) => crate::scene::summary::value_text(o, o.unit.from_si(v), scale),
                    (None, None) => "—".into(),
                };
                assert!(line.value.split(", ").any(|v| v == shown), "{}: {shown} not in {line:?}", o.label);
                // A line of missing values ("— (isothermal)") has no unit.
                let unit = if line.value.starts_with('—') { String::new() } else { unit };
                assert_eq!(line.unit, unit, "{}", o.label);
                assert!(text.contains(&line.value), "{}: {} not in the summary text", o.label, line.value);
            }
        }
        // Labels name the rows (the panel finds a row's group by it), CSV columns and Python names are unique.
        let unique = |names: Vec<&str>| names.iter().all(|n| names.iter().filter(|m| *m == n).count() == 1);
        assert!(unique(OUTPUTS.iter().map(|o| o.label).collect()));
        assert!(unique(OUTPUTS.iter().filter_map(|o| o.csv).collect()));
        assert!(unique(OUTPUTS.iter().flat_map(|o| o.python.iter().map(|p| p.name())).collect()));
    }

    /// The JSON's scalar keys as `tiltpad solve --json` has always written them come from the table (an added
    /// row may add a key; none may go).
    #[test]
    fn the_table_writes_the_top_level_scalars() {
        let keys: Vec<&str> = OUTPUTS.iter().filter_map(Output::json_key).collect();
        for key in [
            "eccentricity_ratio",
            "attitude_angle_deg",
            "load_magnitude_n",
            "sommerfeld",
            "h_min_m",
            "p_max_pa",
            "t_max_film_c",
            "t_max_pad_c",
            "friction_power_w",
            "churning_power_w",
            "total_power_loss_w",
            "friction_torque_nm",
        ] {
            assert!(keys.contains(&key), "{key}");
        }
    }
}
