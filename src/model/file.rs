//! The case file as the user writes it: TOML, engineering units in the key names.
//!
//! This is the persisted, editable form of a case (the workbench edits it, `--set` overrides it). It is
//! converted to SI exactly once, by [`CaseFile::resolve`](super::resolve), which also validates every value.
//! Optional keys are `Option`s so that a file round-trips without inventing values the user never wrote.
//! Each key's unit, allowed values, default and meaning are its row in [`super::schema`]; the comments here
//! only say what a field is.
//!
//! Layout (see `cases/*.toml` for complete examples):
//!
//! ```toml
//! title = "…"
//! [bearing]            # journal_radius_mm, length_mm, assembled_clearance_um
//! [bearing.pads]       # common pad data: count, arc_deg, pivot_deg, offset, preload | clearance_um | bore_radius_mm, …
//! [[bearing.pads.orifice]]   # orifices on every pad: position_frac, axial_frac, diameter_mm, length_mm
//! [[bearing.pad]]      # optional per-pad overrides of any [bearing.pads] value, one table per pad
//! [lubricant]          # two-point viscosity law, density, c_p, conductivity
//! [operating]          # speed_rpm, load_n + load_angle_deg (or eccentricity_ratio + eccentricity_angle_deg), …
//! [mesh]               # fidelity or explicit element counts, node budget (max_nodes)
//! [physics]            # cavitation model, …
//! [thermal]            # isothermal | thd, film–pad exchange (bc1/bc2/bc3), pad conduction, inlet mixing
//! [hydraulics]         # servovalve, ports and injection lines, test rig (see super::hydraulics)
//! [limits]             # design limits: h_min, pad temperature, specific load, p_max, Reynolds (see super::limits)
//! ```

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};

/// The keys of one section that its struct has no field for (tuning keys, or unknown ones), as written; read
/// by [`super::tuning`].
pub type TuningFile = BTreeMap<String, toml::Value>;

/// A whole case file.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CaseFile {
    /// Free text shown in the workbench and in result files.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub title: Option<String>,
    pub bearing: BearingFile,
    pub lubricant: LubricantFile,
    pub operating: OperatingFile,
    #[serde(default)]
    pub mesh: MeshFile,
    #[serde(default)]
    pub physics: PhysicsFile,
    #[serde(default)]
    pub thermal: ThermalFile,
    /// How oil reaches the pads (flooded, leading-edge groove, spray bar).
    #[serde(default, skip_serializing_if = "FeedingFile::is_empty")]
    pub feeding: FeedingFile,
    /// The controllable bearing's valve, lines and rig ([`super::hydraulics`]); absent for a passive bearing.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub hydraulics: Option<super::hydraulics::HydraulicsFile>,
    /// Design limits the results are checked against ([`super::limits`]); absent keys take the conventions.
    #[serde(default, skip_serializing_if = "super::limits::LimitsFile::is_empty")]
    pub limits: super::limits::LimitsFile,
}

/// `[bearing]`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BearingFile {
    /// Journal radius R.
    pub journal_radius_mm: f64,
    /// Axial length L of the pads.
    pub length_mm: f64,
    /// Assembled (bearing) radial clearance Cb.
    pub assembled_clearance_um: f64,
    /// Data shared by all pads.
    pub pads: PadFile,
    /// Optional per-pad overrides; when present their number is the pad count.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub pad: Vec<PadFile>,
}

/// Pad kind: a tilting pad, or a fixed (non-tilting) sector such as a lobe or a plain 360° bore.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "lowercase")]
pub enum PadKindFile {
    #[default]
    Tilting,
    Fixed,
}

/// Pivot contact geometry (`pivot_contact`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum ContactKindFile {
    Rocker,
    Ball,
}

/// One number or one number per pad.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum OneOrMany {
    One(f64),
    Many(Vec<f64>),
}

/// Pad data (`[bearing.pads]` for all pads, `[[bearing.pad]]` for one pad). Every value optional here;
/// resolution takes the per-pad value, else the common one, else the key's default.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct PadFile {
    /// Number of pads (only in `[bearing.pads]`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub count: Option<usize>,
    /// `tilting` or `fixed`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub kind: Option<PadKindFile>,
    /// Pad arc β.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub arc_deg: Option<f64>,
    /// Pivot angle(s) from +x, counter-clockwise: one list entry per pad, or one angle for the first pad
    /// with the others evenly spaced.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pivot_deg: Option<OneOrMany>,
    /// Pivot offset α (fraction of the arc from the leading edge; 0.5 = centred).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub offset: Option<f64>,
    /// Preload m = 1 − Cb/Cp (give exactly one of preload, clearance_um, bore_radius_mm).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub preload: Option<f64>,
    /// Machined pad clearance Cp.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub clearance_um: Option<f64>,
    /// Pad bore radius Rp = R + Cp.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub bore_radius_mm: Option<f64>,
    /// Pad thickness t (pivot at Rp + t from the pad's centre of curvature).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub thickness_mm: Option<f64>,
    /// Radial pivot stiffness; absent = rigid pivot.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pivot_stiffness_n_per_m: Option<f64>,
    /// Transverse pivot stiffness (across the pivot line, e.g. a rocker's tangential contact); absent = rigid.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pivot_transverse_stiffness_n_per_m: Option<f64>,
    /// Pad material density.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub density_kg_per_m3: Option<f64>,
    /// Pads without inertia (zero mass and moment of inertia), as databook coefficients assume; no
    /// density may be given with it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub massless: Option<bool>,
    /// Pad material Young's modulus (used by pad flexibility).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub youngs_modulus_gpa: Option<f64>,
    /// Pad material Poisson ratio.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub poisson_ratio: Option<f64>,
    /// Pivot from a Hertz contact instead of a given stiffness: `rocker` (cylinder in a cylindrical seat) or
    /// `ball` (sphere in a spherical socket); the stiffness then follows the pad's load.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pivot_contact: Option<ContactKindFile>,
    /// Radius of the pivot's convex surface (rocker back or ball), of the pad's material.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pivot_radius_mm: Option<f64>,
    /// Radius of the housing's concave seat (larger than the pivot radius).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pivot_seat_radius_mm: Option<f64>,
    /// Rocker contact length.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pivot_length_mm: Option<f64>,
    /// Seat (housing) material Young's modulus and Poisson ratio.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pivot_seat_youngs_modulus_gpa: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pivot_seat_poisson_ratio: Option<f64>,
    /// Injection orifices (replace, not add to, the common list when given per pad).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub orifice: Option<Vec<OrificeFile>>,
}

/// `[[bearing.pads.orifice]]`: an injection orifice through the pad.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct OrificeFile {
    /// Circumferential position of the centre as a fraction of the pad arc from the leading edge.
    pub position_frac: f64,
    /// Axial position of the centre as a fraction of the length (0.5 = mid-plane).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub axial_frac: Option<f64>,
    /// Orifice diameter d0.
    pub diameter_mm: f64,
    /// Orifice (capillary) length l0.
    pub length_mm: f64,
}

/// `[lubricant]`: viscosity µ(T) = µ1 exp(−η (T − T1)), with η from a second point or given.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LubricantFile {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub name: Option<String>,
    /// Dynamic viscosity µ1 at `viscosity_temperature_c`.
    pub viscosity_pa_s: f64,
    /// Temperature T1 of the first viscosity point.
    pub viscosity_temperature_c: f64,
    /// Second viscosity point µ2 …
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub viscosity2_pa_s: Option<f64>,
    /// … at T2.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub viscosity2_temperature_c: Option<f64>,
    /// Or the temperature coefficient η directly.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub viscosity_coefficient_per_k: Option<f64>,
    pub density_kg_per_m3: f64,
    pub specific_heat_j_per_kg_k: f64,
    pub conductivity_w_per_m_k: f64,
}

/// `[operating]`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct OperatingFile {
    /// Journal speed; the journal surface moves towards +θ (counter-clockwise).
    pub speed_rpm: f64,
    /// Static load magnitude on the journal (give this, or `eccentricity_ratio`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub load_n: Option<f64>,
    /// Load direction from +x, counter-clockwise (270 = downward).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub load_angle_deg: Option<f64>,
    /// Prescribed journal eccentricity ratio e/Cb ("given eccentricity, find load").
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub eccentricity_ratio: Option<f64>,
    /// Direction of the prescribed journal displacement.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub eccentricity_angle_deg: Option<f64>,
    /// Oil supply temperature.
    pub supply_temperature_c: f64,
    /// Film temperature used by the isothermal model.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub film_temperature_c: Option<f64>,
    /// Injection (orifice entry) pressure: one value for all pads or one per pad. Default 0 (orifices open to
    /// ambient: they act as sinks).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub injection_pressure_bar: Option<OneOrMany>,
    /// Temperature of the injected oil.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub injection_temperature_c: Option<f64>,
    /// Oil supply flow of the whole bearing, shared equally by the pads' leading edges (starved lubrication;
    /// mass-conserving cavitation only). Absent: every pad is flooded.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub supply_flow_l_per_min: Option<f64>,
    /// Oil supply flow of each pad (one value per pad, or one for every pad), instead of the bearing's.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pad_supply_flow_l_per_min: Option<OneOrMany>,
    /// Excitation-to-running frequency ratio ω/Ω for the reduced coefficients (1: synchronous).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub excitation_ratio: Option<f64>,
}

/// Named mesh densities; explicit element counts override them.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "lowercase")]
pub enum Fidelity {
    Preview,
    #[default]
    Standard,
    Reference,
}

/// `[mesh]`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct MeshFile {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub fidelity: Option<Fidelity>,
    /// Elements along each pad's arc (before orifice refinement).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub circumferential_elements: Option<usize>,
    /// Elements across the full axial length (half of them when the half model is used).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub axial_elements: Option<usize>,
    /// Elements across each orifice diameter (local refinement).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub orifice_elements: Option<usize>,
    /// Model half the length with a symmetry plane: default when every orifice is on the mid-plane.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub half_model: Option<bool>,
    /// Element layers through the pad thickness for pad heat conduction (thermal model).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pad_radial_elements: Option<usize>,
    /// Node budget: the most mesh nodes a solve may allocate, film nodes over all pads plus (thermal model)
    /// pad-solid nodes; a case whose meshes would need more is refused before anything is built. Default
    /// [`crate::model::budget::DEFAULT_MAX_NODES`].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_nodes: Option<usize>,
}

/// Cavitation condition of the film.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "lowercase")]
pub enum Cavitation {
    /// Reynolds / Swift–Stieber: p ≥ 0 with the Reynolds residual ≥ 0 and their product zero (a
    /// complementarity problem solved exactly).
    #[default]
    Reynolds,
    /// Gümbel (half-Sommerfeld): solve, then set negative pressures to zero.
    Gumbel,
    /// Mass-conserving (Jakobsson–Floberg–Olsson, Elrod–Adams): pressure and film fraction complementary,
    /// with rupture and reformation; the only option that can model a starved inlet.
    Jfo,
}

/// Film flow regime: laminar coefficients everywhere, turbulent above the transition band, or turbulent
/// everywhere (docs/MODEL.md §2.7).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "lowercase")]
pub enum Turbulence {
    /// Laminar: the laminar Reynolds and energy equations at every Reynolds number.
    #[default]
    Off,
    /// Laminar below the transition band, Ng–Pan turbulent above it, blended inside it.
    Auto,
    /// Ng–Pan turbulent coefficients at every point of the film.
    On,
}

/// `[physics]`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, Default)]
pub struct PhysicsFile {
    /// The section's tuning keys (and any unknown key, refused when the file is read): [`super::tuning`].
    #[serde(flatten)]
    pub tuning: TuningFile,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub cavitation: Option<Cavitation>,
    /// Smallest film thickness accepted at equilibrium; below it the solve reports touchdown (surfaces in
    /// contact through their roughness). Default: 1 % of the assembled clearance.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub touchdown_film_um: Option<f64>,
    /// Bending modes per tilting pad beyond the rigid tilt (pad flexibility); 0 = rigid pads.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pad_modes: Option<usize>,
    /// `off` (laminar), `auto` (turbulent above the transition band) or `on` (turbulent everywhere).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub turbulence: Option<Turbulence>,
    /// Local film Reynolds number where the transition band starts (laminar below).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub transition_reynolds_start: Option<f64>,
    /// Local film Reynolds number where the transition band ends (fully turbulent above).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub transition_reynolds_end: Option<f64>,
    /// Film solves per pad the equilibrium may spend (its work budget).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_film_solves_per_pad: Option<usize>,
}

/// Which film model: isothermal (one viscosity at `operating.film_temperature_c`) or thermohydrodynamic.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "lowercase")]
pub enum ThermalModelKind {
    #[default]
    Isothermal,
    /// Film energy equation, pad conduction and inlet mixing, iterated with the equilibrium.
    Thd,
}

/// `[feeding]`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct FeedingFile {
    /// `flooded` (default), `leading_edge_groove` or `spray_bar`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub kind: Option<FeedingKind>,
    /// Hot-oil carry-over past a leading-edge groove λg.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub groove_carry_over: Option<f64>,
    /// Angular width of a leading-edge groove [°] (checked against the gap between pads).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub groove_width_deg: Option<f64>,
    /// Share of the dynamic pressure ρU²/2 raised at each leading edge (ram pressure).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ram_pressure_coefficient: Option<f64>,
    /// Scale on the flooded housing's churning loss between the pads (0: none).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub churning_factor: Option<f64>,
}

impl FeedingFile {
    /// Nothing given (the section is left out when written).
    #[must_use]
    pub fn is_empty(&self) -> bool {
        *self == Self::default()
    }
}

/// How supply oil reaches the pads' leading edges (docs/MODEL.md §3.4).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum FeedingKind {
    /// The pads run in an oil bath.
    #[default]
    Flooded,
    /// Supply oil fed at each pad's leading edge.
    LeadingEdgeGroove,
    /// Supply oil sprayed into the gap between pads.
    SprayBar,
}

/// Heat exchange between the film and the pad's film-side surface (docs/MODEL.md §3).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "lowercase")]
pub enum PadFilmBcFile {
    /// Adiabatic film; the pad surface takes the film temperature (decoupled). Laminar bearings.
    #[default]
    Bc1,
    /// Convective exchange with a constant coefficient (`h_oil_pad_w_per_m2_k`).
    Bc2,
    /// Knight & Barrett parabolic profile across the film (coupled). Near the laminar limit.
    Bc3,
}

/// How the thermal model treats cavitated zones.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum CavitatedFilmFile {
    /// Oil striations filling the fraction of the gap that carries the flow entering the zone (default).
    #[default]
    Striated,
    /// Full film everywhere, as the thesis assumes.
    FullFilm,
}

/// `[thermal]`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, Default)]
pub struct ThermalFile {
    /// The section's tuning keys (and any unknown key, refused when the file is read): [`super::tuning`].
    #[serde(flatten)]
    pub tuning: TuningFile,
    /// `isothermal` or `thd`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub model: Option<ThermalModelKind>,
    /// Film–pad exchange: `bc1`, `bc2`, `bc3`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pad_film_bc: Option<PadFilmBcFile>,
    /// Exchange coefficient H_oil-pad for `bc2` (required there).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub h_oil_pad_w_per_m2_k: Option<f64>,
    /// Free-convection coefficient H∞ on the pads' free faces.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub convection_w_per_m2_k: Option<f64>,
    /// Temperature T∞ around the pads.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ambient_temperature_c: Option<f64>,
    /// Pad material thermal conductivity.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pad_conductivity_w_per_m_k: Option<f64>,
    /// Hot-oil carry-over λ in the groove mixing balance.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub carry_over: Option<f64>,
    /// Given leading-edge oil temperature (else from the groove mixing balance).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub inlet_temperature_c: Option<f64>,
    /// Given journal temperature (else from zero net heat flux to the journal).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub journal_temperature_c: Option<f64>,
    /// Cavitated zones: `striated` or `full_film`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub cavitated_film: Option<CavitatedFilmFile>,
    /// Pad thermal expansion coefficient (0: no thermal growth of the pads).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pad_expansion_ppm_per_k: Option<f64>,
    /// Journal thermal expansion coefficient (0: no journal growth).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub journal_expansion_ppm_per_k: Option<f64>,
    /// Temperature at which the clearances are given.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub reference_temperature_c: Option<f64>,
    /// Housing (and pivot) thermal expansion coefficient (0: no housing growth).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub housing_expansion_ppm_per_k: Option<f64>,
    /// Housing temperature.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub housing_temperature_c: Option<f64>,
}
