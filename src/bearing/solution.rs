//! Results of a bearing solve, in SI, self-describing (the resolved inputs travel with them).

use serde::Serialize;

use crate::model::{Case, LoadSpec};
use crate::physics::reynolds::PadFlows;

use super::coefficients::{FullCoefficients, ReducedCoefficients};
use super::equilibrium::SolveReport;

/// Quantities derived from the inputs that a reader of a result file needs.
#[derive(Debug, Clone, PartialEq, Serialize)]
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
#[derive(Debug, Clone, PartialEq, Serialize, Default)]
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
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PadResult {
    pub index: usize,
    /// Pad tilt about the pivot [rad] (counter-clockwise; > 0 closes the trailing edge); `None` for fixed sectors.
    pub tilt_rad: Option<f64>,
    /// Radial pivot displacement [m] (finite pivot stiffness).
    pub pivot_displacement_m: Option<f64>,
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
    /// The pad carries almost no load.
    pub unloaded: bool,
    #[serde(skip)]
    pub field: PadField,
}

/// Whole-bearing flows [m³/s].
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Default)]
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
#[derive(Debug, Clone, PartialEq, Serialize)]
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
    pub friction_power_w: f64,
    pub friction_torque_nm: f64,
    pub flows_m3_per_s: BearingFlows,
    pub full: FullCoefficients,
    pub reduced: ReducedCoefficients,
    /// Global coordinates at equilibrium ([e_x, e_y, pad coordinates…]), for warm starts.
    pub coordinates: Vec<f64>,
    pub report: SolveReport,
    pub derived: Derived,
    pub inputs: Case,
}

impl Solution {
    /// Angle of the load direction used for the attitude angle [rad].
    #[must_use]
    pub fn load_angle_rad(&self) -> f64 {
        match self.inputs.operating.load {
            LoadSpec::Force { angle_rad, magnitude_n } if magnitude_n > 0.0 => angle_rad,
            _ => self.load_n[1].atan2(self.load_n[0]),
        }
    }
}
