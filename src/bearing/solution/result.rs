//! The result of a bearing solve ([`Solution`]), in SI, self-describing (the resolved inputs travel with it):
//! per-pad results and fields, the bearing's flows, the dynamic coefficients, the thermal results of a THD
//! solve, and the solve's report.

use serde::{Deserialize, Serialize};

use crate::model::{Case, LoadSpec, PadFilmBc};
use crate::physics::energy::FilmHeat;
use crate::physics::reynolds::PadFlows;

use crate::bearing::report::SolveReport;
use crate::bearing::solution::coefficients::{FullCoefficients, ReducedCoefficients};
use crate::bearing::thermal::ThermalReport;

/// Quantities derived from the inputs that a reader of a result file needs.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Derived {
    pub assembled_clearance_m: f64,
    pub pad_clearances_m: Vec<f64>,
    pub preloads: Vec<f64>,
    pub speed_rad_s: f64,
    pub speed_rpm: f64,
    /// Viscosity used by the isothermal film [Pa·s] (and for the Sommerfeld number).
    pub film_viscosity_pa_s: f64,
    pub film_nodes: usize,
}

/// Nodal fields of one pad on its grid (z fastest).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, Default)]
pub struct PadField {
    /// Circumferential node positions: arc length from the leading edge [m].
    pub s_m: Vec<f64>,
    /// Node angles [rad] (same length as `s_m`).
    pub theta_rad: Vec<f64>,
    /// Axial node positions [m].
    pub z_m: Vec<f64>,
    /// True if `z_m` covers only half the pad (symmetry plane at z = 0).
    pub half: bool,
    pub periodic: bool,
    /// Pressure [Pa], `pressure[i * z.len() + j]` for column i, row j (a periodic pad repeats column 0).
    pub pressure_pa: Vec<f64>,
    pub film_thickness_m: Vec<f64>,
    pub cavitated: Vec<bool>,
    /// Viscosity at the nodes [Pa·s].
    pub viscosity_pa_s: Vec<f64>,
    /// Local film Reynolds number ρ U h / µ at the nodes (docs/MODEL.md §2.7): laminar below
    /// `physics.transition_reynolds_start`, turbulent above its end.
    #[serde(default)]
    pub reynolds: Vec<f64>,
    /// Film temperature (mean across the film) at the nodes [°C] (thermal model only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub film_temperature_c: Option<Vec<f64>>,
    /// Temperature of the pad's film-side surface at the nodes [°C] (thermal model with a pad solid).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pad_surface_temperature_c: Option<Vec<f64>>,
}

impl PadField {
    #[must_use]
    pub fn rows(&self) -> usize {
        self.z_m.len()
    }
    /// Value index of column i, row j.
    #[must_use]
    pub fn index(&self, i: usize, j: usize) -> usize {
        let cols = if self.periodic { self.s_m.len() - 1 } else { self.s_m.len() };
        (i % cols) * self.z_m.len() + j
    }
}

/// Per-pad results.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PadResult {
    pub index: usize,
    /// Pad tilt about the pivot [rad] (counter-clockwise; > 0 closes the trailing edge); `None` for fixed sectors.
    pub tilt_rad: Option<f64>,
    /// Radial pivot displacement [m] (finite pivot stiffness).
    pub pivot_displacement_m: Option<f64>,
    /// Transverse pivot displacement [m] (finite transverse pivot stiffness).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pivot_transverse_displacement_m: Option<f64>,
    pub h_min_m: f64,
    /// Where h is smallest [deg].
    pub h_min_angle_deg: f64,
    pub p_max_pa: f64,
    /// Film force of this pad on the journal [N].
    pub force_n: [f64; 2],
    /// Film moment about the pivot [N·m] (zero at equilibrium for a tilting pad).
    pub moment_nm: f64,
    pub flows_m3_per_s: PadFlows,
    /// Flow into the film through each orifice [m³/s].
    pub orifice_flows_m3_per_s: Vec<f64>,
    pub friction_power_w: f64,
    /// Fraction of film nodes cavitated.
    pub cavitated_fraction: f64,
    /// The pad carries almost no load (a floating pad: see [`crate::bearing::equilibrium::FLOATING_SHARE`]).
    pub unloaded: bool,
    /// Amplitude of each retained bending mode (flexible pads) [m]: the largest film-face radial
    /// displacement of the mode, positive opening the film where the mode's shape peaks.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub mode_amplitudes_m: Vec<f64>,
    /// Elastic radial displacement of the film face at each film node, Σ q_i φ_i [m] (empty for rigid pads).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub elastic_displacement_m: Vec<f64>,
    /// The pad solid's thermal growth in the converged TEHD state (`None` without pad growth).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub thermal_growth: Option<PadThermalGrowth>,
    /// The flexible pad's modes and solid layers, for drawing (`None` for rigid pads).
    #[serde(skip)]
    pub flex: Option<PadFlex>,
    #[serde(skip)]
    pub field: PadField,
    /// Thermal results (thermal model only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub thermal: Option<PadThermalResult>,
    /// The Hertz pivot at its load: load, approach, tangent stiffness (pivot contact only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pivot_contact: Option<crate::physics::hertz::ContactState>,
}

/// A flexible pad's retained modes (shared with the model) and the radii of its solid's node layers.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PadFlex {
    pub modes: std::sync::Arc<crate::physics::pad_modes::PadModes>,
    /// Layer radii of the pad solid, film face first [m] (pad node = layer · film nodes + film node).
    pub radii_m: Vec<f64>,
}

/// Thermal growth of a pad solid (TEHD, [`crate::bearing::thermal::growth`]): displacement from the reference temperature, the
/// pad supported on its pivot line (the journal's growth is not in it).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PadThermalGrowth {
    /// Radial displacement of the film face at each film node [m] (positive away from the journal).
    pub film_radial_m: Vec<f64>,
    /// (u_r, u_θ, u_z) at every pad node (layer-major, film face first, as the pad temperature) [m].
    #[serde(skip)]
    pub nodal_polar_m: Vec<f64>,
    /// Layer radii of the pad solid, film face first [m].
    #[serde(skip)]
    pub radii_m: Vec<f64>,
}

/// The 3-D pad temperature field, stored compactly on the extruded film grid.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, Default)]
pub struct PadSolidField {
    /// Layer radii from the film-side face (Rp) to the back (Rp + t) [m].
    pub radii_m: Vec<f64>,
    /// Temperatures [°C], `temperature_c[layer · n_film + film node]` (film nodes as in [`PadField`]).
    pub temperature_c: Vec<f64>,
}

/// Thermal results of one pad.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PadThermalResult {
    /// Leading-edge oil temperature (given or from the groove mixing).
    pub inlet_temperature_c: f64,
    /// Flow-weighted trailing-edge oil temperature.
    pub outlet_temperature_c: f64,
    pub film_t_max_c: f64,
    /// Oil-filled area mean of the film temperature.
    pub film_t_mean_c: f64,
    /// Highest pad temperature anywhere in the pad, and on its film-side surface.
    pub pad_t_max_c: Option<f64>,
    pub pad_surface_t_max_c: Option<f64>,
    pub heat: FilmHeat,
    /// Heat the pad gives to its surroundings through its free faces [W].
    pub pad_to_surroundings_w: f64,
    #[serde(skip)]
    pub solid: Option<PadSolidField>,
}

/// Thermal results of the bearing.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ThermalResult {
    pub pad_film_bc: PadFilmBc,
    pub journal_temperature_c: f64,
    pub t_max_film_c: f64,
    pub t_mean_film_c: f64,
    /// Highest pad temperature (`None` without pad solids).
    pub t_max_pad_c: Option<f64>,
    pub inlet_temperatures_c: Vec<f64>,
    /// The film energy balance of the whole bearing.
    pub heat: FilmHeat,
    /// Heat carried away by the oil [W] (edges, orifices, ruptured zones).
    pub heat_carried_by_oil_w: f64,
    /// Heat conducted out of the film [W] (into pads and journal, net of inflows by conduction).
    pub heat_conducted_w: f64,
    /// Heat the pads give to their surroundings [W]. With BC1 this heat is not part of the film's balance
    /// (the adiabatic film and the pad's Dirichlet face are BC1's known inconsistency).
    pub heat_pads_to_surroundings_w: f64,
    /// (P − H − C)/P of the film energy balance.
    pub energy_balance_closure: f64,
    pub report: ThermalReport,
}

/// Whole-bearing flows [m³/s].
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, Default)]
pub struct BearingFlows {
    pub leading_edges_in: f64,
    pub trailing_edges_out: f64,
    pub sides_out: f64,
    pub orifices_in: f64,
    pub to_cavitation: f64,
    /// (in − out) / (sum of the magnitudes of all flows), for the consistent flows: the discrete mass balance.
    pub mass_balance_error: f64,
}

/// Everything a solve produces.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Solution {
    pub title: String,
    pub eccentricity_ratio: f64,
    /// Angle from the load direction to the journal displacement, positive in the direction of rotation.
    pub attitude_angle_deg: f64,
    pub journal_position_m: [f64; 2],
    /// Load carried by the film (equal and opposite to its force on the journal) [N].
    pub load_n: [f64; 2],
    pub load_magnitude_n: f64,
    /// Sommerfeld number S = µ N L D / W (R/Cb)² with the film viscosity and the assembled clearance;
    /// `None` for an unloaded journal.
    pub sommerfeld: Option<f64>,
    pub pads: Vec<PadResult>,
    pub h_min_m: f64,
    pub p_max_pa: f64,
    /// Friction power of the films (every pad's shear) [W]; the housing's churning is apart ([`Self::churning`]).
    pub friction_power_w: f64,
    pub friction_torque_nm: f64,
    /// Churning loss of a flooded housing: the gap ahead of each pad (empty: none; docs/MODEL.md §3.8).
    pub churning: Vec<crate::physics::churning::GapLoss>,
    pub flows_m3_per_s: BearingFlows,
    pub full: FullCoefficients,
    pub reduced: ReducedCoefficients,
    /// Global coordinates at equilibrium ([e_x, e_y, pad coordinates…]), for warm starts.
    pub coordinates: Vec<f64>,
    pub report: SolveReport,
    /// Flow regime: the local film Reynolds number's largest value, the share of the film in and past the
    /// transition band, and the other validity checks (their warnings are in the report).
    pub regime: Regime,
    pub derived: Derived,
    pub inputs: Case,
    /// Thermal results (`None` for the isothermal model).
    pub thermal: Option<ThermalResult>,
}

impl Solution {
    /// The housing's churning loss, every gap [W] (0 without churning).
    #[must_use]
    pub fn churning_power_w(&self) -> f64 {
        // An empty f64 sum is −0.0; no churning reads as 0.
        if self.churning.is_empty() {
            return 0.0;
        }
        self.churning.iter().map(|g| g.power_w).sum()
    }

    /// The bearing's power loss: the films' friction and the housing's churning [W].
    #[must_use]
    pub fn total_power_loss_w(&self) -> f64 {
        self.friction_power_w + self.churning_power_w()
    }

    /// Angle of the load direction used for the attitude angle [rad].
    #[must_use]
    pub fn load_angle_rad(&self) -> f64 {
        match self.inputs.operating.load {
            LoadSpec::Force { angle_rad, magnitude_n } if magnitude_n > 0.0 => angle_rad,
            _ => self.load_n[1].atan2(self.load_n[0]),
        }
    }
}

/// The flow-regime checks' numbers (computed and checked by `bearing::solution::regime`).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Regime {
    /// Largest local film Reynolds number ρ U h / µ, and its pad.
    pub reynolds_max: f64,
    pub reynolds_pad: usize,
    /// The film model's turbulence setting (`physics.turbulence`) and the transition band [start, end].
    pub turbulence: crate::model::Turbulence,
    pub transition_reynolds: [f64; 2],
    /// Share of the film nodes whose local Reynolds number lies above the transition band's start (where the
    /// film is turbulent or in transition; with `turbulence = "off"` the laminar model is used there all the
    /// same, and the report warns).
    pub transitional_fraction: f64,
    /// Share of the film nodes above the band's end (fully turbulent).
    pub turbulent_fraction: f64,
    /// Largest local Taylor number Re √(h/R).
    pub taylor_max: f64,
    /// Smallest film thickness [m].
    pub h_min_m: f64,
    /// Assembled clearance ratio Cb/R.
    pub clearance_ratio: f64,
    /// Largest radial pivot deflection |ξ| over the pads, as a multiple of the assembled clearance, and
    /// its pad (0 without pivot springs).
    pub pivot_deflection_cb: f64,
    pub pivot_pad: usize,
}
