//! The sweeps' results as plain data: reduced coefficients per excitation ratio ([`FrequencySweep`]) and the
//! scalar results per speed ([`SpeedPoint`]).

use serde::{Deserialize, Serialize};

use crate::bearing::report::error::SolveError;
use crate::bearing::solution::coefficients::ReducedCoefficients;
use crate::bearing::solution::Solution;

/// Reduced coefficients at each excitation ratio ω/Ω of a frequency sweep.
pub type FrequencySweep = Vec<(f64, ReducedCoefficients)>;

/// One point of a speed sweep.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SpeedPoint {
    pub speed_rad_s: f64,
    /// The point's results, or why it has none (touchdown, …).
    pub result: Result<SweepValues, SolveError>,
}

/// The scalar results a sweep keeps per point.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct SweepValues {
    pub eccentricity_ratio: f64,
    pub attitude_angle_deg: f64,
    pub h_min_m: f64,
    pub p_max_pa: f64,
    pub friction_power_w: f64,
    pub reduced: ReducedCoefficients,
}

impl SweepValues {
    #[must_use]
    pub fn of(s: &Solution) -> Self {
        Self {
            eccentricity_ratio: s.eccentricity_ratio,
            attitude_angle_deg: s.attitude_angle_deg,
            h_min_m: s.h_min_m,
            p_max_pa: s.p_max_pa,
            friction_power_w: s.friction_power_w,
            reduced: s.reduced,
        }
    }
}
