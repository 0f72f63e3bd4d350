//! Bench section: the rotor–bearing analysis (`tiltpad rotor`) of the representative compressor rotor
//! (55 Timoshenko elements, two 5-pad bearings sharing one case, full coefficients with the pad
//! coordinates), 50 speeds over 1000–13 000 rpm, per bearing fidelity level: the bearing solves (one per
//! speed: the two bearings are identical), the damped eigen-solutions (sweep and onset bisection) and the
//! total, each the median of repeated runs; the onset speed's error against the finest level run.

use std::fmt::Write as _;
use std::path::Path;

use anyhow::Result;

use crate::cli::rotor::{parse_speeds, read_rotor};
use crate::model::rotor::BearingSupport;
use crate::model::load_case;
use crate::rotor::analysis::{run, AnalysisParams, AnalysisReport};

/// The target of issue 11: 50 speeds, bearings included, at preview fidelity.
const TARGET_S: f64 = 2.0;
const SPEEDS: &str = "1000:13000:50";

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// The markdown section.
///
/// # Errors
/// Missing files, an invalid rotor or case, a failed analysis.
pub fn section(root: &Path, repeats: usize) -> Result<String> {
    eprintln!("bench: rotor");
    let base = read_rotor(&root.join("cases").join("rotors").join("compressor-rotor.toml"))?;
    let bearing_text = std::fs::read_to_string(root.join("cases").join("compressor-bearing.toml"))?;
    let speeds = parse_speeds(SPEEDS)?;
    let mut rows: Vec<(&str, AnalysisReport, f64, Option<f64>)> = Vec::new();
    for level in ["preview", "standard"] {
        let mut rotor = base.clone();
        for b in &mut rotor.bearings {
            if let BearingSupport::Case { case, .. } = &mut b.support {
                **case = load_case(&bearing_text, &[format!("mesh.fidelity=\"{level}\"")])?.1;
            }
        }
        let (mut bearing, mut eigen, mut total) = (Vec::new(), Vec::new(), Vec::new());
        let mut last = None;
        for _ in 0..repeats {
            let r = run(&rotor, AnalysisParams::new(speeds.clone()))?;
            bearing.push(r.report.bearing_seconds);
            eigen.push(r.report.eigen_seconds);
            total.push(r.report.seconds);
            last = Some(r);
        }
        let Some(r) = last else { continue };
        let mut report = r.report.clone();
        (report.bearing_seconds, report.eigen_seconds) = (median(bearing), median(eigen));
        rows.push((level, report, median(total), r.onset.map(|o| o.speed_rad_s * 30.0 / std::f64::consts::PI)));
    }
    let truth = rows.last().and_then(|r| r.3);
    let mut md = String::new();
    let _ = writeln!(
        md,
        "\n## Rotor–bearing analysis (`tiltpad rotor`)\n\n`cases/rotors/compressor-rotor.toml` (representative shaft, 55 Timoshenko elements, two \
         5-pad compressor bearings from one case, full coefficients with the pad coordinates appended), speeds `{SPEEDS}` rpm. \
         Times are medians of {repeats} runs: the bearing solves (isothermal; one per speed, warm-started from the nearest speed \
         solved), the damped eigen-solutions (the sweep and the onset bisection to 0.1 %) and the whole analysis. The error is \
         the onset speed's against the standard level.\n\n\
         | level | bearing solves | eigen-solutions | DOFs | bearings | eigen | total | onset | onset error |\n|---|---|---|---|---|---|---|---|---|"
    );
    for (level, rep, total, onset) in &rows {
        let onset_s = onset.map_or("—".to_string(), |o| format!("{o:.0} rpm"));
        let err = match (onset, truth) {
            (Some(o), Some(t)) if *level != "standard" => format!("{:.2} %", 100.0 * (o - t).abs() / t),
            _ => "—".to_string(),
        };
        let _ = writeln!(
            md,
            "| {level} | {} | {} | {} | {:.2} s | {:.2} s | {total:.2} s | {onset_s} | {err} |",
            rep.bearing_solves, rep.eigen_solutions, rep.system_dofs, rep.bearing_seconds, rep.eigen_seconds
        );
    }
    if let Some((_, _, t, _)) = rows.iter().find(|r| r.0 == "preview") {
        let status = if *t <= TARGET_S { "met".to_string() } else { format!("missed by {:.2} s", t - TARGET_S) };
        let _ = writeln!(md, "\nTarget: 50 speeds with the bearing solves ≤ {TARGET_S} s at preview fidelity: {t:.2} s, {status}.");
    }
    Ok(md)
}
