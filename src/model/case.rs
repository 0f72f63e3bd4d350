//! The resolved case, in SI units, validated. This is what the solver reads.
//!
//! Angles are radians measured from +x counter-clockwise (x horizontal, y vertical up); the journal surface
//! moves towards +θ. Temperatures are °C (they only enter through differences and the viscosity law).

use serde::{Deserialize, Serialize};

pub use super::file::{CavitatedFilmFile as CavitatedFilm, Cavitation, Fidelity, ThermalModelKind, Turbulence};

/// A complete, validated case in SI units.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Case {
    pub title: String,
    pub bearing: Bearing,
    pub lubricant: Lubricant,
    pub operating: Operating,
    pub mesh: MeshSpec,
    pub physics: Physics,
    pub thermal: Thermal,
    pub hydraulics: Option<super::hydraulics::Hydraulics>,
    /// Design limits (read by no solver stage: checked on the solution).
    pub limits: super::limits::Limits,
    /// The tuning keys' values ([`super::tuning`]: read by the equilibrium, the thermal loop and what follows).
    pub tuning: super::tuning::Tuning,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Bearing {
    /// Journal radius R [m].
    pub journal_radius_m: f64,
    /// Axial length L [m].
    pub length_m: f64,
    /// Assembled radial clearance Cb [m].
    pub assembled_clearance_m: f64,
    pub pads: Vec<Pad>,
}

impl Bearing {
    /// The longest pad arc [rad] (sets the circumferential element count of a fidelity level).
    #[must_use]
    pub fn longest_arc_rad(&self) -> f64 {
        self.pads.iter().map(|p| p.arc_rad).fold(0.0, f64::max)
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum PadKind {
    Tilting,
    Fixed,
}

/// One pad (or fixed sector).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Pad {
    pub kind: PadKind,
    /// Leading-edge angle θ_le [rad].
    pub leading_edge_rad: f64,
    /// Arc β [rad]; a fixed sector of 2π is a periodic full bore.
    pub arc_rad: f64,
    /// Pivot angle θ_p = θ_le + α β [rad] (for fixed sectors: the lobe centre, where h = Cb).
    pub pivot_rad: f64,
    /// Pivot offset α.
    pub offset: f64,
    /// Machined pad clearance Cp [m].
    pub clearance_m: f64,
    /// Preload m = 1 − Cb/Cp.
    pub preload: f64,
    /// Pad thickness t [m].
    pub thickness_m: f64,
    /// Radial pivot stiffness [N/m]; `None` = rigid.
    pub pivot_stiffness_n_per_m: Option<f64>,
    /// Transverse pivot stiffness (across the pivot line) [N/m]; `None` = rigid.
    pub pivot_transverse_stiffness_n_per_m: Option<f64>,
    pub density_kg_per_m3: f64,
    /// No inertia: the pad's mass and moment of inertia are zero (the density is then not used for them).
    pub massless: bool,
    pub youngs_modulus_pa: f64,
    pub poisson_ratio: f64,
    /// Hertz contact of the pivot (its radial stiffness follows the pad's load); then
    /// `pivot_stiffness_n_per_m` is `None`.
    pub pivot_contact: Option<PivotContact>,
    pub orifices: Vec<Orifice>,
}

impl Pad {
    /// Pad bore radius Rp = R + Cp.
    #[must_use]
    pub fn bore_radius_m(&self, journal_radius_m: f64) -> f64 {
        journal_radius_m + self.clearance_m
    }
    /// A 360° fixed sector is periodic in θ (no leading or trailing edge).
    #[must_use]
    pub fn is_full_circle(&self) -> bool {
        (self.arc_rad - std::f64::consts::TAU).abs() < 1e-9
    }
    /// Trailing-edge angle [rad].
    #[must_use]
    pub fn trailing_edge_rad(&self) -> f64 {
        self.leading_edge_rad + self.arc_rad
    }
}

/// The pivot's contact geometry.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ContactKind {
    /// Cylinder in a cylindrical seat (line contact along the pad's length).
    Rocker,
    /// Sphere in a spherical socket (point contact).
    Ball,
}

/// A pivot's Hertz contact: geometry and materials [SI]. Its law (approach and stiffness under a load) is
/// in `physics::hertz`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct PivotContact {
    pub kind: ContactKind,
    /// Radius of the convex body (rocker back, ball) R₁ [m].
    pub pivot_radius_m: f64,
    /// Radius of the concave seat R₂ > R₁ [m].
    pub seat_radius_m: f64,
    /// Contact length of a rocker [m] (unused for a ball).
    pub length_m: f64,
    /// Convex body's E₁ [Pa] and ν₁ (the pad's material).
    pub pivot_youngs_modulus_pa: f64,
    pub pivot_poisson_ratio: f64,
    /// Seat's E₂ [Pa] and ν₂ (the housing's material).
    pub seat_youngs_modulus_pa: f64,
    pub seat_poisson_ratio: f64,
}

/// An injection orifice (capillary) through a pad.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Orifice {
    /// Angle of the centre θ0 [rad].
    pub angle_rad: f64,
    /// Axial position of the centre from the mid-plane z0 [m].
    pub axial_m: f64,
    pub diameter_m: f64,
    pub length_m: f64,
}

/// µ(T) = µ_ref exp(−η (T − T_ref)).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct ViscosityLaw {
    pub mu_ref_pa_s: f64,
    pub t_ref_c: f64,
    pub eta_per_k: f64,
}

impl ViscosityLaw {
    /// Viscosity at temperature `t_c` [Pa·s].
    #[must_use]
    pub fn at(&self, t_c: f64) -> f64 {
        self.mu_ref_pa_s * (-self.eta_per_k * (t_c - self.t_ref_c)).exp()
    }
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Lubricant {
    pub name: String,
    pub viscosity: ViscosityLaw,
    pub density_kg_per_m3: f64,
    pub specific_heat_j_per_kg_k: f64,
    pub conductivity_w_per_m_k: f64,
}

/// What fixes the journal position.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(tag = "mode", rename_all = "snake_case")]
pub enum LoadSpec {
    /// A static load on the journal: find the position.
    Force { magnitude_n: f64, angle_rad: f64 },
    /// A prescribed journal position: find the load.
    Position { eccentricity_ratio: f64, angle_rad: f64 },
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Operating {
    /// Journal angular speed Ω [rad/s].
    pub speed_rad_s: f64,
    pub load: LoadSpec,
    pub supply_temperature_c: f64,
    /// Temperature of the isothermal film.
    pub film_temperature_c: f64,
    /// Injection pressure at each pad's orifice entry [Pa] (one per pad).
    pub injection_pressure_pa: Vec<f64>,
    pub injection_temperature_c: f64,
    /// Oil supply flow of each pad's leading edge [m³/s] (the bearing's supply shared equally, or given per
    /// pad); `None`: flooded pads.
    pub supply_flow_m3_s: Option<Vec<f64>>,
    /// ω/Ω for the reduced coefficients.
    pub excitation_ratio: f64,
}

impl Operating {
    /// Journal speed [rev/s].
    #[must_use]
    pub fn speed_rev_s(&self) -> f64 {
        crate::units::HZ_ANGULAR.from_si(self.speed_rad_s)
    }
}

/// Resolved mesh density.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub struct MeshSpec {
    pub fidelity: Fidelity,
    pub circumferential_elements: usize,
    pub axial_elements: usize,
    pub orifice_elements: usize,
    pub half_model: bool,
    /// Element layers through the pad thickness (pad conduction).
    pub pad_radial_elements: usize,
    /// Most mesh nodes (film over all pads + pad solids) a solve may allocate ([`super::budget`]).
    pub max_nodes: usize,
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Physics {
    pub cavitation: Cavitation,
    /// Film thickness below which an equilibrium counts as touchdown [m].
    pub touchdown_film_m: f64,
    /// Bending modes per tilting pad beyond the rigid tilt (pseudo-modal pad flexibility, docs/MODEL.md §5);
    /// 0 = rigid pads.
    pub pad_modes: usize,
    /// Laminar or turbulent film coefficients (docs/MODEL.md §2.7).
    pub turbulence: Turbulence,
    /// Laminar–turbulent transition band of the local film Reynolds number ρ U h / µ: [start, end].
    pub transition_reynolds: [f64; 2],
    /// The equilibrium's work budget: film solves per pad over all its methods.
    pub max_film_solves_per_pad: usize,
    /// Share of the dynamic pressure `ρ U²/2` the oil entering each film raises at the leading edge
    /// (`feeding.ram_pressure_coefficient`; 0: ambient leading edges; docs/MODEL.md §2.2).
    pub ram_pressure_coefficient: f64,
}

/// Film–pad heat exchange (docs/MODEL.md §3).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "lowercase")]
pub enum PadFilmBc {
    /// Adiabatic film; pad surface = film temperature (Dirichlet). Film and pad decouple.
    Bc1,
    /// `S_loss = H (T − T_pad)` with a constant coefficient H [W/(m² K)].
    Bc2 { h_w_per_m2_k: f64 },
    /// Knight & Barrett parabola across the film; film and pad coupled.
    Bc3,
}

/// Thermal model settings, SI (temperatures °C).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Thermal {
    pub model: ThermalModelKind,
    pub pad_film_bc: PadFilmBc,
    /// H∞ on the pads' free faces [W/(m² K)].
    pub convection_w_per_m2_k: f64,
    /// T∞ [°C].
    pub ambient_temperature_c: f64,
    /// Pad conductivity [W/(m K)].
    pub pad_conductivity_w_per_m_k: f64,
    /// Given leading-edge temperature [°C], else the mixing balance.
    pub inlet_temperature_c: Option<f64>,
    /// Given journal temperature [°C], else zero net heat flux.
    pub journal_temperature_c: Option<f64>,
    pub cavitated_film: CavitatedFilm,
    /// Thermal expansion of the pads α_p and of the journal α_j [1/K] (0: no growth; TEHD when either is set).
    pub pad_expansion_per_k: f64,
    pub journal_expansion_per_k: f64,
    /// Temperature at which the clearances are given [°C], else the supply temperature.
    pub reference_temperature_c: Option<f64>,
    /// Thermal expansion of the housing and pivots α_h [1/K] (0: none) at the housing temperature [°C]
    /// (else the supply temperature).
    pub housing_expansion_per_k: f64,
    pub housing_temperature_c: Option<f64>,
    /// How oil reaches the pads (`[feeding]`): the groove mixing rule and its carry-over.
    pub feeding: Feeding,
}

/// How supply oil reaches the pads' leading edges, with the hot-oil carry-over each kind uses
/// (docs/MODEL.md §3.4).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Feeding {
    /// Oil bath: the carried hot oil (`carry_over` of the upstream outflow) enters first; the journal churns
    /// the oil between the pads (`churning_factor` scales that loss, §3.8).
    Flooded { carry_over: f64, churning_factor: f64 },
    /// Supply at each leading edge: only `carry_over` (small) of the hot oil passes the groove, and enters first.
    LeadingEdgeGroove { carry_over: f64 },
    /// Supply sprayed between pads: the carried hot oil and the sprayed oil mix fully before the film takes its
    /// share.
    SprayBar { carry_over: f64 },
}

impl Feeding {
    /// The fraction of the hot oil leaving the pad upstream that reaches the next leading edge.
    #[must_use]
    pub fn carry_over(self) -> f64 {
        match self {
            Self::Flooded { carry_over, .. }
            | Self::LeadingEdgeGroove { carry_over }
            | Self::SprayBar { carry_over } => carry_over,
        }
    }

    /// The scale on the churning loss of the oil between the pads: `feeding.churning_factor` for a flooded
    /// housing; 0 for directed feeding, whose housing drains (docs/MODEL.md §3.8).
    #[must_use]
    pub fn churning_factor(self) -> f64 {
        match self {
            Self::Flooded { churning_factor, .. } => churning_factor,
            Self::LeadingEdgeGroove { .. } | Self::SprayBar { .. } => 0.0,
        }
    }
}

/// The pad arc the levels' circumferential counts are set for (the 60–80° pads of the shipped
/// tilting-pad bearings) [rad].
pub const LEVEL_ARC_RAD: f64 = 80.0 * crate::units::DEG.si;

impl Fidelity {
    /// Default element counts (circumferential per pad of up to [`LEVEL_ARC_RAD`], axial over the full
    /// length, across an orifice).
    #[must_use]
    pub fn elements(self) -> (usize, usize, usize) {
        match self {
            Self::Preview => (16, 8, 6),
            Self::Standard => (36, 16, 12),
            Self::Reference => (96, 48, 24),
        }
    }

    /// Circumferential elements per pad for pads of up to `arc_rad`: the level's count, scaled up with the
    /// arc beyond [`LEVEL_ARC_RAD`] so the element length (and the accuracy a level stands for) stays the
    /// same on a 160° sector or a 360° bore; shorter pads keep the level's count.
    #[must_use]
    #[allow(clippy::cast_precision_loss, clippy::cast_possible_truncation, clippy::cast_sign_loss)]
    pub fn circumferential_elements(self, arc_rad: f64) -> usize {
        let n = self.elements().0;
        let scaled = (n as f64 * arc_rad / LEVEL_ARC_RAD - 1e-9).ceil();
        if scaled.is_finite() && scaled > n as f64 {
            scaled.min(1e6) as usize
        } else {
            n
        }
    }

    /// Default element layers through the pad thickness (pad conduction). Graded layers converge at about
    /// second order; on Fillon bearing A (BC3) 4 layers put the pad's maximum temperature within 0.005 K of
    /// the 24-layer value (docs/THERMAL.md).
    #[must_use]
    pub fn pad_radial_elements(self) -> usize {
        match self {
            Self::Preview => 2,
            Self::Standard => 4,
            Self::Reference => 8,
        }
    }
}
