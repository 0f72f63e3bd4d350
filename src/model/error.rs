//! Errors raised while reading, overriding or validating a case (and a rotor file).
//!
//! Every variant names the key (dotted path as written in the case file, e.g. `bearing.pads.preload`),
//! and where it makes sense the offending value and the allowed range, so a message can be shown next to
//! the field it concerns. Values that are each fine but do not fit together are an [`Inconsistency`], one
//! variant per condition with the numbers it is about, so a caller can match the condition (an editor that
//! offers to move an orifice back onto its pad, a batch that counts overlapping pads) rather than its text.

use serde::{Deserialize, Serialize};
use thiserror::Error;

/// A problem with a case file or with one of its values.
#[derive(Debug, Clone, PartialEq, Error, Serialize, Deserialize)]
pub enum CaseError {
    /// The text is not valid TOML.
    #[error("case file is not valid TOML: {message}")]
    Syntax { message: String },
    /// A key the schema does not know (often a typo or a missing unit suffix).
    #[error("unknown key `{key}`{}", hint_suffix(.hint))]
    UnknownKey { key: String, hint: String },
    /// A required key is absent.
    #[error("missing required key `{key}` ({meaning})")]
    MissingKey { key: String, meaning: String },
    /// A key holds a value of the wrong type (string where a number is expected, …).
    #[error("`{key}`: {message}")]
    WrongType { key: String, message: String },
    /// A number outside its physical or numerical range, NaN or infinite.
    #[error("`{key}` = {value} is out of range: allowed {allowed}")]
    OutOfRange { key: String, value: f64, allowed: String },
    /// Values that are each fine but contradict one another (overlapping pads, orifice outside its pad, …).
    #[error("`{key}`: {reason}")]
    Inconsistent { key: String, reason: Inconsistency },
    /// The meshes would need more nodes than the budget `mesh.max_nodes` allows (refused before anything is
    /// allocated; see [`crate::model::budget`]).
    #[error(
        "`mesh.max_nodes`: the meshes would need {needed} nodes ({film} film nodes over all pads, pad {largest_pad} \
         alone {largest_pad_film}; {pad_solid} pad-solid nodes; {orifices} orifices), more than the budget of {budget}; \
         coarsen mesh.circumferential_elements, mesh.axial_elements or mesh.orifice_elements (each orifice is refined \
         with mesh.orifice_elements across its diameter), mesh.pad_radial_elements for the thermal model, use fewer \
         orifices, or raise mesh.max_nodes"
    )]
    NodeBudget {
        needed: usize,
        budget: usize,
        film: usize,
        pad_solid: usize,
        largest_pad: usize,
        largest_pad_film: usize,
        orifices: usize,
    },
    /// A `--set key=value` override (or an editor's edit) that cannot be applied.
    #[error("override `{text}`: {problem}")]
    BadOverride { text: String, problem: OverrideProblem },
}

/// Why values that are each valid do not fit together: one variant per condition, with its numbers.
#[derive(Debug, Clone, PartialEq, Error, Serialize, Deserialize)]
pub enum Inconsistency {
    // ------------------------------------------------------------------------------------------ pads
    #[error("the pad count belongs in [bearing.pads], not in a per-pad entry")]
    PadCountInPadEntry,
    #[error("{entries} per-pad entries for {pads} pads (bearing.pads.count)")]
    PadEntries { entries: usize, pads: usize },
    /// A per-pad list (pivot angles, injection pressures) whose length is not the pad count.
    #[error("{given} values for {pads} pads (give one value, or one per pad)")]
    PerPadValues { given: usize, pads: usize },
    #[error(
        "pads {first} and {second} overlap: pad {first} spans {first_from_deg:.2}°–{first_to_deg:.2}°, pad {second} \
         starts at {second_from_deg:.2}°"
    )]
    PadsOverlap { first: usize, second: usize, first_from_deg: f64, first_to_deg: f64, second_from_deg: f64 },
    #[error("a fixed sector has no pivot")]
    FixedSectorPivot,
    #[error("massless pads have no density: remove it, or set massless = false")]
    MasslessWithDensity,
    /// More than one of preload, clearance_um and bore_radius_mm in one table (`given`: the keys given).
    #[error("give one of preload, clearance_um, bore_radius_mm, not {}", .given.join(" and "))]
    PadGeometryTwice { given: Vec<String> },
    #[error("gives preload {preload:.4} (1 − Cb/Cp); allowed [-1, 1)")]
    PreloadOutOfRange { preload: f64 },
    #[error(
        "orifice outside its pad: an orifice of {diameter_mm:.3} mm at {position_frac} of a {arc_deg}° arc (arc \
         length {arc_length_mm:.3} mm) crosses the pad edge; allowed position_frac in ({lowest:.4}, {highest:.4})"
    )]
    OrificeOffArc { diameter_mm: f64, position_frac: f64, arc_deg: f64, arc_length_mm: f64, lowest: f64, highest: f64 },
    #[error(
        "orifice outside its pad: a {diameter_mm:.3} mm orifice at axial_frac {axial_frac} crosses the pad's axial end"
    )]
    OrificeOffLength { diameter_mm: f64, axial_frac: f64 },
    #[error("orifice overlaps orifice {other} of the same pad")]
    OrificesOverlap { other: usize },
    #[error("describes a pivot contact: give bearing.pads.pivot_contact (\"rocker\" or \"ball\") too, or remove it")]
    ContactWithoutKind,
    #[error("give either a pivot contact or pivot_stiffness_n_per_m, not both")]
    ContactAndStiffness,
    #[error("the seat ({seat_mm:.4} mm) must be larger than the pivot radius ({pivot_mm:.4} mm)")]
    SeatNotLarger { seat_mm: f64, pivot_mm: f64 },
    // ------------------------------------------------------------------------------------- lubricant
    #[error("give either a second viscosity point or the coefficient, not both")]
    ViscosityPointAndCoefficient,
    #[error("the two viscosity points need different temperatures")]
    ViscosityPointsAtOneTemperature,
    #[error("the two points give η = {eta_per_k:.4} /K; viscosity must fall with temperature (η in [0, 1] /K)")]
    ViscosityRises { eta_per_k: f64 },
    // ------------------------------------------------------------------------------------- operating
    #[error("give either load_n (find the position) or eccentricity_ratio (find the load), not both")]
    LoadAndEccentricity,
    #[error("with a prescribed eccentricity use eccentricity_angle_deg")]
    LoadAngleWithEccentricity,
    #[error("only meaningful with eccentricity_ratio")]
    EccentricityAngleWithoutRatio,
    /// A starved inlet needs the film fraction, which only the mass-conserving cavitation model computes.
    #[error("a supply flow (starved pads) needs physics.cavitation = \"jfo\" (mass-conserving cavitation)")]
    SupplyFlowWithoutJfo,
    #[error("give either the bearing's operating.supply_flow_l_per_min or the per-pad operating.pad_supply_flow_l_per_min, not both")]
    SupplyFlowTwice,
    // ------------------------------------------------------------------------------ mesh and thermal
    #[error("the half model needs every orifice on the mid-plane (axial_frac = 0.5)")]
    HalfModelOffMidPlane,
    #[error("only used with pad_film_bc = \"bc2\"")]
    OnlyWithBc2,
    /// A carry-over coefficient the case's feeding does not use (`used`: the key it uses).
    #[error(
        "not used with feeding.kind = \"{kind}\" (its hot-oil carry-over is {used}): remove it, or change feeding.kind"
    )]
    CarryOverOfOtherFeeding { kind: String, used: String },
    /// A leading-edge groove that does not fit in the gap ahead of a pad (`pad`: the first such pad).
    #[error(
        "{width_deg}° is a groove wider than the gap between pads: allowed (0, {gap_deg}]° (the gap ahead of pad {pad}, from the pads' leading edges and arcs)"
    )]
    GrooveWiderThanGap { width_deg: f64, gap_deg: f64, pad: usize },
    /// A leading-edge groove width given for another feeding kind.
    #[error("only used with feeding.kind = \"leading_edge_groove\"")]
    OnlyWithGroove,
    /// The churning loss of a flooded housing scaled for a directed feeding, whose housing drains.
    #[error(
        "only used with feeding.kind = \"flooded\" (with feeding.kind = \"{kind}\" the housing drains: no churning loss)"
    )]
    OnlyWithFlooded { kind: String },
    /// A leading-edge pressure with the mass-conserving inlet, whose condition is a film fraction.
    #[error(
        "a leading-edge (ram) pressure needs a full inlet: physics.cavitation = \"reynolds\" or \"gumbel\" (the mass-conserving inlet is a film fraction)"
    )]
    RamPressureWithJfo,
    /// The mass-conserving film on a 360° sleeve with no oil fed into it: the sleeve has no leading edge.
    #[error(
        "\"jfo\" on a 360° sleeve (pad {pad}) without an injecting orifice: a sleeve has no leading edge, so the \
         mass-conserving film has no oil coming in and carries nothing; allowed: \"reynolds\" or \"gumbel\", or an \
         orifice on the pad (bearing.pads.orifice) with operating.injection_pressure_bar > 0"
    )]
    JfoSleeveWithoutFeed { pad: usize },
    // ------------------------------------------------------------------------------------ hydraulics
    #[error("must be below the supply pressure")]
    ReturnNotBelowSupply,
    #[error("{ports} ports: a four-way valve has one or two (A, B)")]
    PortCount { ports: usize },
    /// A valve port (`A` or `B`) named by two lines.
    #[error("port {port} used twice")]
    PortTwice { port: char },
    #[error("feeds no pad")]
    PortFeedsNoPad,
    #[error("pad {pad} does not exist (pads 0 to {last})")]
    NoSuchPad { pad: usize, last: usize },
    #[error("pad {pad} is fed by two ports")]
    PadFedTwice { pad: usize },
    /// A line feeds a pad that has no orifice: no flow reaches its film, so the valve has nothing to act on.
    #[error("pad {pad} has no orifice (bearing.pads.orifice): the line's flow cannot reach its film")]
    PortPadWithoutOrifice { pad: usize },
    /// The valve cannot hold a fed pad's static injection pressure from its supply.
    #[error(
        "{supply_bar} bar is below pad {pad}'s injection pressure of {injection_bar} bar \
         (operating.injection_pressure_bar): the valve cannot hold it; allowed: at least {injection_bar} bar"
    )]
    SupplyBelowInjection { supply_bar: f64, pad: usize, injection_bar: f64 },
    // ----------------------------------------------------------------------------------------- rotor
    #[error("{modes:?}: two increasing flexible-mode numbers in [1, 20]")]
    DampingModes { modes: [usize; 2] },
    /// More shaft elements than a rotor analysis is allowed to assemble (dense matrices, one eigen-solution
    /// per speed).
    #[error(
        "{total} shaft elements in all (Σ rotor.section[].elements); at most {max}: the shaft's dense matrices and \
         its eigen-solutions grow with the cube of the count (a few dozen elements resolve a compressor rotor)"
    )]
    ShaftElements { total: usize, max: usize },
    #[error("give both rotor.min_speed_rpm and rotor.max_speed_rpm, or neither")]
    SpeedRangeHalf,
    /// The rotor file names a bearing case the caller could not read (`reason`: the caller's words).
    #[error("cannot read `{name}`: {reason}")]
    CaseUnreadable { name: String, reason: String },
    /// The rotor file names a bearing case that is itself invalid.
    #[error("`{name}`: {error}")]
    CaseInvalid { name: String, error: Box<CaseError> },
    #[error("{rows} rows; needs {expected} (one per entry of speeds_rpm, or one row without speeds_rpm)")]
    CoefficientRows { rows: usize, expected: usize },
    #[error("give either `case` or `k_n_per_m` and `c_ns_per_m`")]
    CaseOrNumbers,
    // --------------------------------------------------------------------------------------- control
    #[error("give either `node` or `bearing` (the journal of rotor.bearing[i]), not both or neither")]
    SensorPlace,
    #[error("rotor.bearing[{bearing}] holds coefficients given by numbers, not a bearing case: it has no valve")]
    BearingWithoutCase { bearing: usize },
    #[error("the case of rotor.bearing[{bearing}] (`{name}`) has no [hydraulics]: no valve to drive")]
    NoValve { bearing: usize, name: String },
    /// A valve port whose pads have no injection orifice: the valve cannot act through it.
    #[error("port {port} feeds pads {pads:?}, none with an injection orifice: the port feeds no pad")]
    PortWithoutOrifice { port: char, pads: Vec<usize> },
    #[error("the valve of rotor.bearing[{bearing}] is already actuator {first}")]
    ValveTwice { bearing: usize, first: usize },
    #[error("{loops} loops drive actuator {actuator}: each actuator needs exactly one")]
    LoopsPerActuator { actuator: usize, loops: usize },
    /// No control law, or several (`given`: the tables given).
    #[error("give one control law: [[control.loop]] (one per actuator) or [control.mimo]; given: {}", if .given.is_empty() { "none".to_string() } else { .given.join(", ") })]
    ControlLaw { given: Vec<String> },
    #[error(
        "a numerator of degree {numerator} over a denominator of degree {denominator} is an improper transfer \
         function; allowed: numerator degree ≤ denominator degree"
    )]
    ImproperTransferFunction { numerator: usize, denominator: usize },
    #[error("every coefficient of the denominator is zero")]
    ZeroDenominator,
    #[error(
        "{poles} pole(s) with Re ≥ 0 (Routh–Hurwitz): the controller is unstable on its own; allowed: every root of \
         the denominator with Re < 0"
    )]
    UnstableController { poles: usize },
    #[error("a derivative gain on a displacement sensor needs rolloff_hz (the controller is improper without it)")]
    DerivativeWithoutRolloff,
    #[error("a proportional gain needs a displacement sensor; sensor {sensor} measures velocity (allowed: 0)")]
    ProportionalOnVelocity { sensor: usize },
    #[error("{rows}×{columns} entries; needs {actuators}×{sensors} (a row per actuator, a column per sensor)")]
    GainMatrixShape { rows: usize, columns: usize, actuators: usize, sensors: usize },
    #[error("{given} weights; needs {needs} (one per sensor for output_weight, one per actuator for input_weight)")]
    WeightCount { given: usize, needs: usize },
    #[error("needs at least one sensor and one actuator")]
    NothingToControl,
    // ------------------------------------------------------------------------------------ any layer
    /// A valid case the solver's model cannot be built for (`reason`: the solver's error, as text: the model
    /// layer cannot hold the solver's types).
    #[error("the solver cannot build the case: {reason}")]
    NotBuildable { reason: String },
}

/// Why a `key=value` override cannot be applied.
#[derive(Debug, Clone, PartialEq, Error, Serialize, Deserialize)]
pub enum OverrideProblem {
    #[error("expected key=value")]
    NoEquals,
    #[error("empty key")]
    EmptyKey,
    #[error("`{array}` has {len} entries; index {index} is out of range")]
    IndexOutOfRange { array: String, len: usize, index: usize },
    #[error("`{path}` is not a table")]
    EntryNotATable { path: String },
    #[error("an override must end at a value, not a whole table")]
    WholeTable,
    #[error("`{path}` is a value, not a table")]
    ValueNotATable { path: String },
}

fn hint_suffix(hint: &str) -> String {
    if hint.is_empty() {
        String::new()
    } else {
        format!(" ({hint})")
    }
}

impl CaseError {
    /// The dotted key the error concerns, if any (used by the editor to flag the field in place).
    #[must_use]
    pub fn key(&self) -> Option<&str> {
        match self {
            Self::Syntax { .. } | Self::BadOverride { .. } => None,
            Self::UnknownKey { key, .. }
            | Self::MissingKey { key, .. }
            | Self::WrongType { key, .. }
            | Self::OutOfRange { key, .. }
            | Self::Inconsistent { key, .. } => Some(key),
            Self::NodeBudget { .. } => Some("mesh.max_nodes"),
        }
    }

    /// An [`CaseError::Inconsistent`] at `key`.
    pub(crate) fn inconsistent(key: impl Into<String>, reason: Inconsistency) -> Self {
        Self::Inconsistent { key: key.into(), reason }
    }

    /// A [`CaseError::MissingKey`] at `key`.
    pub(crate) fn missing(key: impl Into<String>, meaning: impl Into<String>) -> Self {
        Self::MissingKey { key: key.into(), meaning: meaning.into() }
    }
}

/// Checks that `value` is finite and inside `[lo, hi]` (bounds inclusive unless stated by `open_lo`/`open_hi`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Range {
    pub lo: f64,
    pub hi: f64,
    pub open_lo: bool,
    pub open_hi: bool,
}

impl Range {
    pub const fn closed(lo: f64, hi: f64) -> Self {
        Self { lo, hi, open_lo: false, open_hi: false }
    }
    pub const fn positive(hi: f64) -> Self {
        Self { lo: 0.0, hi, open_lo: true, open_hi: false }
    }
    pub const fn open_lo(lo: f64, hi: f64) -> Self {
        Self { lo, hi, open_lo: true, open_hi: false }
    }
    pub const fn open(lo: f64, hi: f64) -> Self {
        Self { lo, hi, open_lo: true, open_hi: true }
    }
    /// `[lo, hi)`.
    pub const fn open_hi(lo: f64, hi: f64) -> Self {
        Self { lo, hi, open_lo: false, open_hi: true }
    }

    /// The interval as validation messages and `tiltpad schema` write it, e.g. `(0, 10000]`.
    #[must_use]
    pub fn describe(&self) -> String {
        let l = if self.open_lo { "(" } else { "[" };
        let r = if self.open_hi { ")" } else { "]" };
        format!("{l}{}, {}{r}", fmt_bound(self.lo), fmt_bound(self.hi))
    }

    /// Whether `value` is finite and inside.
    #[must_use]
    pub fn contains(&self, value: f64) -> bool {
        let below = if self.open_lo { value <= self.lo } else { value < self.lo };
        let above = if self.open_hi { value >= self.hi } else { value > self.hi };
        value.is_finite() && !below && !above
    }

    /// `value` if it is inside, else [`CaseError::OutOfRange`] naming `key`, the value and the interval.
    ///
    /// # Errors
    /// The value is outside the interval, NaN or infinite.
    pub fn check(&self, key: &str, value: f64) -> Result<f64, CaseError> {
        if !self.contains(value) {
            return Err(CaseError::OutOfRange {
                key: key.to_string(),
                value,
                allowed: format!("a finite number in {}", self.describe()),
            });
        }
        Ok(value)
    }
}

fn fmt_bound(x: f64) -> String {
    if x.is_infinite() {
        if x > 0.0 {
            "inf".into()
        } else {
            "-inf".into()
        }
    } else {
        crate::number::csv(x)
    }
}
