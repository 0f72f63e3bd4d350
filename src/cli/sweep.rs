//! `tiltpad sweep`: one parameter over a range, warm-started point to point, with a progress bar.

use std::fmt::Write as _;
use std::path::Path;

use anyhow::{bail, Result};
use indicatif::{ProgressBar, ProgressStyle};

use crate::bearing::{solve_point, BearingModel, NoCancel, ThermalModel};
use crate::model::load_case;

use super::write_atomic;

/// Runs the sweep and writes the CSV.
///
/// # Errors
/// Case errors at any point of the range, solve failures are recorded per row, I/O errors.
pub fn run(case: &Path, param: &str, from: f64, to: f64, steps: usize, set: &[String], csv: &Path) -> Result<()> {
    if steps < 1 {
        bail!("--steps must be at least 1");
    }
    let text = std::fs::read_to_string(case)?;
    let pb = ProgressBar::new(steps as u64);
    pb.set_style(ProgressStyle::with_template("{bar:40} {pos}/{len} {msg}").unwrap_or_else(|_| ProgressStyle::default_bar()));
    let mut out = String::from(
        "value,eccentricity_ratio,attitude_angle_deg,h_min_um,p_max_mpa,friction_power_w,kxx_n_per_m,kxy_n_per_m,kyx_n_per_m,kyy_n_per_m,cxx_ns_per_m,cxy_ns_per_m,cyx_ns_per_m,cyy_ns_per_m,iterations,seconds,error\n",
    );
    let mut model: Option<(BearingModel, String)> = None;
    let mut thermal: Option<ThermalModel> = None;
    let mut start: Option<Vec<f64>> = None;
    for i in 0..steps {
        #[allow(clippy::cast_precision_loss)]
        let v = if steps == 1 { from } else { from + (to - from) * i as f64 / (steps - 1) as f64 };
        let mut sets = set.to_vec();
        sets.push(format!("{param}={v}"));
        let (_, c) = load_case(&text, &sets)?;
        // Reuse the model while the geometry and mesh are unchanged.
        let key = format!("{:?}{:?}", c.bearing, c.mesh);
        if model.as_ref().map(|m| &m.1) != Some(&key) {
            model = Some((BearingModel::new(&c)?, key));
            thermal = None;
            start = None;
        }
        let Some((m, _)) = model.as_mut() else { unreachable!() };
        pb.set_message(format!("{param} = {v:.4}"));
        match solve_point(m, &mut thermal, &c, start.as_deref(), &NoCancel) {
            Ok(s) => {
                let (k, cc) = (s.reduced.k_n_per_m, s.reduced.c_ns_per_m);
                let _ = writeln!(
                    out,
                    "{v},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},",
                    s.eccentricity_ratio,
                    s.attitude_angle_deg,
                    s.h_min_m * 1e6,
                    s.p_max_pa * 1e-6,
                    s.friction_power_w,
                    k[0][0],
                    k[0][1],
                    k[1][0],
                    k[1][1],
                    cc[0][0],
                    cc[0][1],
                    cc[1][0],
                    cc[1][1],
                    s.report.iterations,
                    s.report.seconds
                );
                start = Some(s.coordinates.clone());
            }
            Err(e) => {
                let _ = writeln!(out, "{v},,,,,,,,,,,,,,,,\"{}\"", e.to_string().replace('"', "'"));
                start = None;
            }
        }
        pb.inc(1);
    }
    pb.finish_with_message("done");
    write_atomic(csv, out.as_bytes())?;
    println!("wrote {}", csv.display());
    Ok(())
}
