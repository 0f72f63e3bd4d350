//! Helpers shared by the integration tests.
#![allow(dead_code)]

use std::path::PathBuf;

use tiltpad::bearing::{solve_case, Solution};
use tiltpad::model::{load_case, Case};

/// Path of a shipped case file.
pub fn case_path(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("cases").join(name)
}

/// Loads a shipped case with overrides.
pub fn case(name: &str, set: &[&str]) -> Case {
    let text = std::fs::read_to_string(case_path(name)).expect("case file");
    let set: Vec<String> = set.iter().map(|s| (*s).to_string()).collect();
    load_case(&text, &set).expect("valid case").1
}

/// Solves a shipped case with overrides.
pub fn solve(name: &str, set: &[&str]) -> Solution {
    solve_case(&case(name, set)).expect("solve")
}

/// Relative error.
pub fn rel(a: f64, b: f64) -> f64 {
    (a - b) / b
}

/// Someya's frame: x along the load (downward here), y 90° ahead in the direction of rotation (our +x).
/// Returns the 2×2 matrix in that frame.
pub fn to_load_frame(m: [[f64; 2]; 2]) -> [[f64; 2]; 2] {
    // Unit vectors of the load frame in our (x, y) frame: ex' = (0, −1), ey' = (1, 0).
    let t = [[0.0, -1.0], [1.0, 0.0]];
    let mut out = [[0.0; 2]; 2];
    for a in 0..2 {
        for b in 0..2 {
            for i in 0..2 {
                for j in 0..2 {
                    out[a][b] += t[a][i] * m[i][j] * t[b][j];
                }
            }
        }
    }
    out
}

/// A plain 360° bearing (R = 50 mm, C = 100 µm, µ = 0.02 Pa·s, 3000 rpm) with a prescribed eccentricity.
pub const PLAIN_360: &str = r#"
[bearing]
journal_radius_mm = 50.0
length_mm = 10.0
assembled_clearance_um = 100.0
[bearing.pads]
count = 1
kind = "fixed"
arc_deg = 360.0
pivot_deg = 0.0
preload = 0.0
[lubricant]
viscosity_pa_s = 0.02
viscosity_temperature_c = 40.0
viscosity_coefficient_per_k = 0.0
density_kg_per_m3 = 860.0
specific_heat_j_per_kg_k = 2000.0
conductivity_w_per_m_k = 0.13
[operating]
speed_rpm = 3000.0
eccentricity_ratio = 0.5
supply_temperature_c = 40.0
[mesh]
circumferential_elements = 360
axial_elements = 32
"#;

#[cfg(feature = "gui")]
pub mod painted_text;
