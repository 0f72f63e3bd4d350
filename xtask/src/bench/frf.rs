//! Bench section: the controllable bearing's FRFs (`tiltpad frf`) on the Publication 5 rig, per fidelity
//! level — the equilibrium, the linearisation (full coefficients and the injection influence fields: one
//! back-substitution per port) and 400 frequencies of every FRF (G1, G2, G3, G per port and axis, the
//! rig's shaker chain), each the median of repeated runs; the active force's error against the reference
//! level at a low and a high frequency.

use std::fmt::Write as _;
use std::path::Path;

use anyhow::Result;
use web_time::Instant;

use tiltpad::bearing::frf::model::band;
use tiltpad::bearing::{NoCancel, Stages};
use tiltpad::model::load_case;

/// The target: 400 frequencies of all FRFs after the equilibrium.
const TARGET_MS: f64 = 20.0;

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// The markdown section.
///
/// # Errors
/// Missing case file, an invalid case or a failed solve.
pub fn section(root: &Path, repeats: usize) -> Result<String> {
    let text = std::fs::read_to_string(root.join("cases").join("test-rig-pub5.toml"))?;
    super::say("bench: FRFs");
    let freqs = band(1.0, 1000.0, 400);
    let probe = [20.0, 200.0];
    let mut rows = Vec::new();
    for level in ["preview", "standard", "reference"] {
        let (_, case) = load_case(&text, &[format!("mesh.fidelity=\"{level}\"")])?;
        let (mut eq, mut lin, mut sweep) = (Vec::new(), Vec::new(), Vec::new());
        let mut model = None;
        for _ in 0..repeats {
            let t0 = Instant::now();
            let m = Stages::new().frf(&case, &NoCancel)?;
            let total = t0.elapsed().as_secs_f64();
            eq.push((total - m.linearise_seconds) * 1e3);
            lin.push(m.linearise_seconds * 1e3);
            let t1 = Instant::now();
            let s = m.sweep(&case, &freqs)?;
            sweep.push(t1.elapsed().as_secs_f64() * 1e3);
            drop(s);
            model = Some(m);
        }
        let Some(m) = model else { continue };
        let g: Vec<_> = m.sweep(&case, &probe)?.points.iter().map(|p| p.g[1]).collect();
        let nodes = tiltpad::bearing::BearingModel::new(&case)?.film_nodes();
        rows.push((level, nodes, median(eq), median(lin), median(sweep), g));
    }
    let Some(truth) = rows.last().map(|r| r.5.clone()) else { return Ok(String::new()) };
    let mut md = String::new();
    let _ = writeln!(
        md,
        "\n## Controllable lubrication: FRFs (`tiltpad frf`)\n\n`cases/test-rig-pub5.toml` (two pads, one port each, 700 mm lines, rig in configuration 2). \
         Times are medians of {repeats} runs: the isothermal equilibrium (with the mesh build), the linearisation at it (full \
         coefficients and the injection influence fields) and 400 log-spaced frequencies from 1 Hz to 1 kHz of every FRF \
         (one complex LU of the coupled valve–line–pad–journal system per frequency and mounting). The error is that of the \
         vertical active force per volt, |ΔG_y|/|G_y|, against the reference level.\n\n\
         | level | film nodes | equilibrium | linearisation | 400 frequencies | G_y error at 20 Hz | at 200 Hz |\n|---|---|---|---|---|---|---|"
    );
    for (level, nodes, e, l, s, g) in &rows {
        let err = |i: usize| {
            if *level == "reference" {
                "—".to_string()
            } else {
                format!("{:.2} %", 100.0 * (g[i] - truth[i]).norm() / truth[i].norm())
            }
        };
        let _ = writeln!(md, "| {level} | {nodes} | {e:.1} ms | {l:.2} ms | {s:.2} ms | {} | {} |", err(0), err(1));
    }
    if let Some((_, _, _, _, s, _)) = rows.iter().find(|r| r.0 == "standard") {
        let status = if *s <= TARGET_MS { "met".to_string() } else { format!("missed by {:.1} ms", s - TARGET_MS) };
        let _ = writeln!(md, "\nTarget: 400 frequencies of all FRFs ≤ {TARGET_MS} ms after the equilibrium (standard): {s:.2} ms, {status}.");
    }
    Ok(md)
}
