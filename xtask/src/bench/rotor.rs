//! Bench section: the rotor–bearing analysis (`tiltpad rotor`) of the representative compressor rotor
//! (55 Timoshenko elements, two 5-pad bearings sharing one case, full coefficients with the pad
//! coordinates), 50 speeds over 1000–13 000 rpm, per shaft reduction (fixed-interface modes per plane, 0 = the
//! full finite-element shaft) and bearing fidelity level: the bearing solves (one per speed: the two bearings
//! are identical), the damped eigen-solutions (sweep and onset bisection) and the total, each the median of
//! repeated runs; the errors of each reduction against the full shaft on the same bearings (damped
//! frequencies and log decrements of the first modes over all speeds, onset speed, peak unbalance response),
//! and the onset's change with the bearing fidelity.

use std::fmt::Write as _;
use std::path::Path;

use anyhow::Result;

use tiltpad::io::read::read_rotor;
use tiltpad::model::load_case;
use tiltpad::model::rotor::{BearingSupport, Rotor, DEFAULT_SHAFT_MODES};
use tiltpad::rotor::analysis::{run, AnalysisParams, AnalysisResult};

/// The target: 50 speeds, bearings included, at preview fidelity.
const TARGET_S: f64 = 2.0;
const SPEEDS: &str = "1000:13000:50";
/// Modes compared per speed.
const MODES: usize = 4;
/// Shaft reductions measured at preview fidelity (0: full shaft, the reference).
const REDUCTIONS: [usize; 6] = [0, 2, 4, 8, 16, 32];

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// Errors of a result against the full shaft's: largest relative frequency error and largest log-dec error
/// of the first [`MODES`] modes over all speeds, relative onset error, relative peak response error.
#[derive(Default)]
struct Errors {
    frequency: f64,
    log_dec: f64,
    onset: Option<f64>,
    peak: f64,
}

fn peak_response(r: &AnalysisResult) -> f64 {
    r.speeds.iter().flat_map(|s| s.orbits.iter().map(|o| o.major_pp_m)).fold(0.0, f64::max)
}

fn errors(r: &AnalysisResult, truth: &AnalysisResult) -> Errors {
    let mut e = Errors::default();
    for (a, b) in r.speeds.iter().zip(&truth.speeds) {
        for (m, t) in a.point.modes.modes.iter().zip(&b.point.modes.modes).take(MODES) {
            e.frequency = e.frequency.max((m.imag_rad_s - t.imag_rad_s).abs() / t.imag_rad_s);
            e.log_dec = e.log_dec.max((m.log_dec - t.log_dec).abs());
        }
    }
    e.onset = match (r.onset, truth.onset) {
        (Some(a), Some(b)) => Some((a.speed_rad_s - b.speed_rad_s).abs() / b.speed_rad_s),
        _ => None,
    };
    let (p, q) = (peak_response(r), peak_response(truth));
    e.peak = if q > 0.0 { (p - q).abs() / q } else { 0.0 };
    e
}

struct Row {
    level: &'static str,
    shaft_modes: usize,
    result: AnalysisResult,
    bearing_s: f64,
    eigen_s: f64,
    total_s: f64,
}

fn measure(rotor: &Rotor, level: &'static str, shaft_modes: usize, speeds: &[f64], repeats: usize) -> Result<Row> {
    let mut rotor = rotor.clone();
    rotor.shaft_modes = shaft_modes;
    let (mut bearing, mut eigen, mut total) = (Vec::new(), Vec::new(), Vec::new());
    let mut last = None;
    for _ in 0..repeats.max(1) {
        let r = run(&rotor, AnalysisParams::new(speeds.to_vec()))?;
        bearing.push(r.report.bearing_seconds);
        eigen.push(r.report.eigen_seconds);
        total.push(r.report.seconds);
        last = Some(r);
    }
    let result = last.ok_or_else(|| anyhow::anyhow!("no run"))?;
    Ok(Row { level, shaft_modes, result, bearing_s: median(bearing), eigen_s: median(eigen), total_s: median(total) })
}

fn at_level(base: &Rotor, bearing_text: &str, level: &str) -> Result<Rotor> {
    let mut rotor = base.clone();
    for b in &mut rotor.bearings {
        if let BearingSupport::Case { case, .. } = &mut b.support {
            **case = load_case(bearing_text, &[format!("mesh.fidelity=\"{level}\"")])?.1;
        }
    }
    Ok(rotor)
}

fn rpm(r: &AnalysisResult) -> String {
    r.onset.map_or("—".to_string(), |o| format!("{:.0} rpm", tiltpad::units::RPM.from_si(o.speed_rad_s)))
}

/// The markdown section.
///
/// # Errors
/// Missing files, an invalid rotor or case, a failed analysis.
pub fn section(root: &Path, repeats: usize) -> Result<String> {
    super::say("bench: rotor");
    let base = read_rotor(&root.join("cases").join("rotors").join("compressor-rotor.toml"))?;
    let bearing_text = std::fs::read_to_string(root.join("cases").join("compressor-bearing.toml"))?;
    let speeds = super::speeds(SPEEDS)?;
    let preview = at_level(&base, &bearing_text, "preview")?;
    let mut rows = Vec::new();
    for m in REDUCTIONS {
        rows.push(measure(&preview, "preview", m, &speeds, repeats)?);
    }
    let standard =
        measure(&at_level(&base, &bearing_text, "standard")?, "standard", DEFAULT_SHAFT_MODES, &speeds, repeats)?;
    let mut md = String::new();
    let _ = writeln!(
        md,
        "\n## Rotor–bearing analysis (`tiltpad rotor`)\n\n`cases/rotors/compressor-rotor.toml` (representative shaft, 55 Timoshenko elements, two \
         5-pad compressor bearings from one case, full coefficients with the pad coordinates appended), speeds `{SPEEDS}` rpm. \
         The shaft is reduced (Craig–Bampton: the x, y of the bearing and unbalance nodes kept, `shaft modes` fixed-interface \
         modes per bending plane; 0 = the full finite-element shaft; rotor key `shaft_modes`, CLI `--shaft-modes`, default \
         {DEFAULT_SHAFT_MODES}). Times are medians of {repeats} runs: the bearing solves (isothermal; one per speed, warm-started \
         from the nearest speed solved), the damped eigen-solutions (the sweep and the onset bisection to 0.1 %) and the whole \
         analysis. Errors against the full shaft on the same bearings: the largest relative error of the first {MODES} damped \
         frequencies and the largest absolute error of their log decrements over all speeds, the onset speed's relative error \
         (0: bisected to the same speed as the full shaft's) and the peak unbalance response's (largest major axis over speeds and response nodes).\n\n\
         | bearings | shaft modes | DOFs | bearing solves | eigen-solutions | bearings | eigen | total | onset | frequency error | log dec error | onset error | peak response error |\n\
         |---|---|---|---|---|---|---|---|---|---|---|---|---|"
    );
    let truth = &rows[0].result;
    for row in rows.iter().chain(std::iter::once(&standard)) {
        let r = &row.result;
        let errs = if row.level == "preview" && row.shaft_modes != 0 {
            let e = errors(r, truth);
            let onset = e.onset.map_or("—".to_string(), |o| format!("{o:.1e}"));
            format!("{:.1e} | {:.1e} | {onset} | {:.1e}", e.frequency, e.log_dec, e.peak)
        } else {
            "— | — | — | —".to_string()
        };
        let modes = if row.shaft_modes == 0 { "full".to_string() } else { row.shaft_modes.to_string() };
        let _ = writeln!(
            md,
            "| {} | {modes} | {} | {} | {} | {:.2} s | {:.3} s | {:.2} s | {} | {errs} |",
            row.level,
            r.report.system_dofs,
            r.report.bearing_solves,
            r.report.eigen_solutions,
            row.bearing_s,
            row.eigen_s,
            row.total_s,
            rpm(r)
        );
    }
    if let (Some(a), Some(b)) =
        (rows.iter().find(|r| r.shaft_modes == DEFAULT_SHAFT_MODES).and_then(|r| r.result.onset), standard.result.onset)
    {
        let _ = writeln!(md, "\nBearing fidelity: the onset at preview differs from standard's by {:.2} % (shaft modes {DEFAULT_SHAFT_MODES}).", 100.0 * (a.speed_rad_s - b.speed_rad_s).abs() / b.speed_rad_s);
    }
    if let Some(row) = rows.iter().find(|r| r.shaft_modes == DEFAULT_SHAFT_MODES) {
        let t = row.total_s;
        let status = if t <= TARGET_S { "met".to_string() } else { format!("missed by {:.2} s", t - TARGET_S) };
        let _ = writeln!(md, "\nTarget: 50 speeds with the bearing solves ≤ {TARGET_S} s at preview fidelity (default shaft reduction): {t:.2} s, {status}.");
    }
    Ok(md)
}
