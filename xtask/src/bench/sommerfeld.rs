//! Bench section: the Sommerfeld chart (`tiltpad sommerfeld`, the Sweep view's "Sommerfeld chart"). The
//! chart's sweep (12 loads from 0.2 to 3 times the case's) of the shipped plain 360° bearing
//! (`cases/plain-360-sommerfeld.toml`, L/D = 0.1) per fidelity level, with the largest relative difference in
//! S from the short-bearing reference at the same ε (the finite length and the mesh both contribute; the
//! reference is the L/D → 0 limit, not the exact answer); then the compressor bearing's chart (tilting pads:
//! no closed form) per level, timed.

use std::fmt::Write as _;
use std::path::Path;

use anyhow::Result;

use tiltpad::model::load_case;
use tiltpad::scene::sommerfeld::{chart, reference_deviation, ChartGeometry};
use tiltpad::scene::sweep::{point_override, SweepSpec, SweepTable};
use tiltpad::study::Runner;

/// Heading of the section in docs/PERFORMANCE.md.
pub const HEADING: &str = "## Sommerfeld chart";

/// The chart's sweep of the case `text` with `set` over `points` loads, as `tiltpad sommerfeld` solves it
/// (each point warm-started from the one before).
fn chart_sweep(text: &str, set: &[String], points: usize) -> Result<(SweepTable, ChartGeometry)> {
    let case = load_case(text, set)?.1;
    let mut spec = SweepSpec::sommerfeld_chart(&case);
    spec.count = points;
    let mut runner = Runner::new(text, set.to_vec(), true);
    let mut table = SweepTable::new(&spec.key);
    for (i, x) in spec.values()?.into_iter().enumerate() {
        let (row, _) = runner.row(i, &point_override(&spec.key, x));
        table.points.push((x, row));
    }
    Ok((table, ChartGeometry::of(&case)))
}

/// The markdown section.
///
/// # Errors
/// A missing case file or a sweep whose every point failed.
pub fn section(root: &Path, repeats: usize) -> Result<String> {
    super::say("bench: sommerfeld");
    let mut md = format!(
        "\n{HEADING} (`tiltpad sommerfeld`)\n\nThe chart's sweep: 12 loads from 0.2 to 3 times the case's, each point \
         warm-started from the one before (median of {repeats} runs). S deviation: the largest relative difference \
         between a solved point's S and the short-bearing (Ocvirk) S at the same ε; the reference is the L/D → 0 \
         limit, so part of it is the finite length, not the mesh.\n\n| case | level | chart time | per point | failed | S deviation |\n|---|---|---|---|---|---|\n"
    );
    for (case, label) in
        [("plain-360-sommerfeld", "plain 360°, L/D 0.1"), ("compressor-bearing", "compressor (tilting)")]
    {
        let text = std::fs::read_to_string(root.join("cases").join(format!("{case}.toml")))?;
        for level in ["preview", "standard", "reference"] {
            let set = vec![format!("mesh.fidelity=\"{level}\"")];
            let mut times = Vec::new();
            let mut last = None;
            for _ in 0..repeats.max(1) {
                let t = web_time::Instant::now();
                let out = chart_sweep(&text, &set, 12)?;
                times.push(t.elapsed().as_secs_f64());
                last = Some(out);
            }
            times.sort_by(f64::total_cmp);
            let ms = 1e3 * times[times.len() / 2];
            let Some((table, g)) = last else { continue };
            let failed = table.failures().len();
            let deviation =
                reference_deviation(&chart(&table, &g), &g).map_or("—".into(), |d| format!("{:.2} %", 100.0 * d));
            #[allow(clippy::cast_precision_loss)]
            let per = ms / table.points.len() as f64;
            let _ = writeln!(md, "| {label} | {level} | {ms:.0} ms | {per:.1} ms | {failed} | {deviation} |");
        }
    }
    Ok(md)
}
