//! What the workbench exports besides the case file: nodal fields as CSV and results as JSON.
//!
//! The CSV has one line per film node of every pad, SI units in the column names; a half model is written
//! as solved (z from the symmetry plane), so the file is the solver's data, not a picture of it. The JSON is
//! the same self-describing document as `tiltpad solve --json`.

use std::fmt::Write as _;

use crate::bearing::solution::Solution;

/// Nodal fields of every pad: `pad,s_m,theta_deg,z_m,pressure_pa,film_thickness_m,cavitated,viscosity_pa_s`.
#[must_use]
pub fn fields_csv(solution: &Solution) -> String {
    let mut out = String::from("pad,s_m,theta_deg,z_m,pressure_pa,film_thickness_m,cavitated,viscosity_pa_s\n");
    for p in &solution.pads {
        let f = &p.field;
        let cols = if f.periodic { f.s_m.len().saturating_sub(1) } else { f.s_m.len() };
        for i in 0..cols {
            for j in 0..f.z_m.len() {
                let k = f.index(i, j);
                let _ = writeln!(
                    out,
                    "{},{:.9e},{:.6},{:.9e},{:.9e},{:.9e},{},{:.6e}",
                    p.index,
                    f.s_m[i],
                    f.theta_rad[i].to_degrees(),
                    f.z_m[j],
                    f.pressure_pa[k],
                    f.film_thickness_m[k],
                    u8::from(f.cavitated[k]),
                    f.viscosity_pa_s[k]
                );
            }
        }
    }
    out
}

/// The result document (as `tiltpad solve --json`), pretty-printed.
#[must_use]
pub fn results_json(solution: &Solution) -> String {
    serde_json::to_string_pretty(&crate::cli::solution_json(solution)).unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"))
}
