//! Bench section: the closed-loop analysis (`tiltpad control`) of the shipped active compressor rotor
//! (`cases/rotors/compressor-rotor-active.toml`: two controllable bearings, displacement feedback to each valve),
//! 50 speeds over 2000–12 000 rpm at preview and standard bearing fidelity: the whole analysis (bearing solves,
//! FRF linearisations, closed-loop poles open and closed, the Nyquist check at both valves, the unbalance
//! response with and without control, the onset bisections), the median of repeated runs; and the onset
//! speeds open and closed with the preview's change against standard.

use std::fmt::Write as _;
use std::path::Path;

use anyhow::Result;

use crate::cli::control::read_controlled;
use crate::cli::rotor::parse_speeds;
use crate::control::analysis::{ControlAnalysis, ControlParams, ControlResult};
use crate::model::load_case;
use crate::model::rotor::BearingSupport;
use crate::units::RPM;

/// The target: 50 speeds at preview fidelity.
const TARGET_S: f64 = 2.0;
const SPEEDS: &str = "2000:12000:50";

/// CPU time of this process so far [s] (user + system, from `/proc/self/stat` at 100 ticks per second;
/// `None` where there is no such file): on the shared machine the wall time is mostly waiting for a core.
fn cpu_seconds() -> Option<f64> {
    let stat = std::fs::read_to_string("/proc/self/stat").ok()?;
    // fields after the command name's closing parenthesis: state is field 3, utime 14, stime 15
    let rest = stat.rsplit_once(')')?.1;
    let fields: Vec<&str> = rest.split_whitespace().collect();
    let ticks: f64 = fields.get(11)?.parse::<f64>().ok()? + fields.get(12)?.parse::<f64>().ok()?;
    Some(ticks / 100.0)
}

/// One whole analysis, and the time to close the loop again at another gain on its plants (what a slider of
/// the Control view costs) [s].
fn analyse(
    rotor: &crate::model::rotor::Rotor,
    control: &crate::model::control::Control,
    speeds: &[f64],
) -> Result<(ControlResult, Option<f64>, f64)> {
    let cpu = cpu_seconds();
    let mut a = ControlAnalysis::new(rotor, control, ControlParams::new(speeds.to_vec()))?;
    while !a.step()? {}
    let sweep = a.sweep();
    let k = a.controller().clone();
    let r = a.finish()?;
    let cpu = cpu.zip(cpu_seconds()).map(|(a, b)| b - a);
    let start = web_time::Instant::now();
    for i in 0..sweep.len() {
        sweep.at(i, &k, 2.0 * control.gain)?;
    }
    Ok((r, cpu, start.elapsed().as_secs_f64()))
}

fn onset(r: &ControlResult, closed: bool) -> Option<f64> {
    (if closed { r.onset_closed } else { r.onset_open }).onset_rad_s
}

/// The markdown section.
///
/// # Errors
/// Missing files, an invalid rotor or case, a failed analysis.
pub fn section(root: &Path, repeats: usize) -> Result<String> {
    eprintln!("bench: control");
    let (base, control) = read_controlled(&root.join("cases").join("rotors").join("compressor-rotor-active.toml"))?;
    let bearing_text = std::fs::read_to_string(root.join("cases").join("compressor-bearing-active.toml"))?;
    let speeds = parse_speeds(SPEEDS, usize::MAX)?;
    let mut md = String::new();
    let _ = writeln!(
        md,
        "\n## Active control (`tiltpad control`)\n\n`cases/rotors/compressor-rotor-active.toml` (the representative compressor rotor on two \
         controllable bearings, each journal's displacement fed back to its valve), speeds `{SPEEDS}` rpm: the whole closed-loop \
         analysis — bearing solves and FRF linearisations, poles with the loop open and closed, the Nyquist check at both valves, \
         the unbalance response with and without control, the onset bisections (open and closed, to 0.1 %) — median of {repeats} runs.\n\n\
         Total is wall time (CPU time of the process beside it: on a loaded machine the difference is waiting for a core); \
         *another gain* is closing the loop again at twice the gain on the sweep's 50 plants (poles and unbalance response, \
         no bearing solve: what a slider of the Control view costs).\n\n\
         | bearings | states | bearing solves | eigen-solutions | total (CPU) | another gain | onset open | onset closed | onset change vs standard |\n\
         |---|---|---|---|---|---|---|---|---|"
    );
    let mut rows = Vec::new();
    for level in ["preview", "standard"] {
        let mut rotor = base.clone();
        for b in &mut rotor.bearings {
            if let BearingSupport::Case { case, .. } = &mut b.support {
                **case = load_case(&bearing_text, &[format!("mesh.fidelity=\"{level}\"")])?.1;
            }
        }
        let mut times = Vec::new();
        let mut last = None;
        for _ in 0..repeats.max(1) {
            let (r, cpu, again) = analyse(&rotor, &control, &speeds)?;
            times.push((r.seconds, cpu, again));
            last = Some(r);
        }
        times.sort_by(|a, b| a.0.total_cmp(&b.0));
        rows.push((level, times[times.len() / 2], last.ok_or_else(|| anyhow::anyhow!("no run"))?));
    }
    let standard = rows[1].2.clone();
    let rpm = |w: Option<f64>| w.map_or("—".to_string(), |w| format!("{:.0} rpm", RPM.from_si(w)));
    for (level, (t, cpu, again), r) in &rows {
        let change = match (onset(r, true), onset(&standard, true)) {
            (Some(a), Some(b)) if *level == "preview" => format!("{:.2} %", 100.0 * (a - b) / b),
            _ => "—".to_string(),
        };
        let _ = writeln!(
            md,
            "| {level} | {} | {} | {} | {t:.2} s ({}) | {again:.3} s | {} | {} | {change} |",
            r.states,
            r.bearing_solves,
            r.eigen_solutions,
            cpu.map_or("—".to_string(), |c| format!("{c:.2} s")),
            rpm(onset(r, false)),
            rpm(onset(r, true))
        );
    }
    let (t, cpu, _) = rows[0].1;
    let status = if t <= TARGET_S { "met".to_string() } else { format!("missed by {:.2} s", t - TARGET_S) };
    let _ = writeln!(
        md,
        "\nTarget: a closed-loop sweep of 50 speeds at preview fidelity ≤ {TARGET_S} s: {t:.2} s wall ({} CPU), {status}.",
        cpu.map_or("—".to_string(), |c| format!("{c:.2} s"))
    );
    Ok(md)
}
