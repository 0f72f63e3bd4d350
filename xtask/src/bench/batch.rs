//! Bench section: cost per design of a design-space batch (`tiltpad batch`), per fidelity level, with
//! the projection to designs per core-hour and the error of each level against the reference level over
//! the same designs. Uses `cases/designs-compressor.csv` on `cases/compressor-bearing.toml`; every design
//! is solved from scratch, as the batch does.

use std::fmt::Write as _;
use std::path::Path;

use anyhow::{Context, Result};
use web_time::Instant;

use tiltpad::study::{Designs, Row, Runner};

/// Solves every design at a fidelity level: (mean wall time per design [ms], rows).
fn run_level(text: &str, designs: &Designs, level: &str) -> (f64, Vec<Row>) {
    let mut runner = Runner::new(text, vec![format!("mesh.fidelity=\"{level}\"")], false);
    let t0 = Instant::now();
    let rows: Vec<Row> = designs.rows.iter().enumerate().map(|(i, d)| runner.row(i, d).0).collect();
    #[allow(clippy::cast_precision_loss)]
    let ms = t0.elapsed().as_secs_f64() * 1e3 / designs.rows.len().max(1) as f64;
    (ms, rows)
}

fn cell(row: &Row, name: &str) -> Option<f64> {
    let k = tiltpad::study::COLUMNS.iter().position(|c| c.name == name)?;
    row.result.as_ref().ok()?.get(k).copied().flatten()
}

/// Largest relative difference of column `name` between two runs over the designs solved in both.
fn worst(a: &[Row], b: &[Row], name: &str) -> f64 {
    a.iter()
        .zip(b)
        .filter_map(|(x, y)| Some(((cell(x, name)? - cell(y, name)?) / cell(y, name)?).abs()))
        .fold(0.0, f64::max)
}

/// The section's heading.
pub const HEADING: &str = "## Design-space batches (`tiltpad batch`)";

/// The markdown section.
///
/// # Errors
/// Missing files or a bad designs table.
pub fn section(root: &Path, repeats: usize) -> Result<String> {
    let designs_path = root.join("cases").join("designs-compressor.csv");
    let table =
        std::fs::read_to_string(&designs_path).with_context(|| format!("cannot read {}", designs_path.display()))?;
    let designs = Designs::parse(&table)?;
    let text = std::fs::read_to_string(root.join("cases").join("compressor-bearing.toml"))?;
    super::say("bench: batch cost per design");
    let (_, truth) = run_level(&text, &designs, "reference");
    let mut md = String::new();
    let _ = writeln!(
        md,
        "\n{HEADING}\n\n`cases/designs-compressor.csv`: {} designs of the compressor bearing (isothermal), each solved from \
         scratch on one core as `tiltpad batch` does; time per design is the median over {repeats} runs of the whole batch. \
         Errors are the largest over the designs, against the reference level.\n\n\
         | level | time per design | designs per core-hour | ε error | h_min error | K_yy error | failed |\n|---|---|---|---|---|---|---|",
        designs.rows.len()
    );
    for level in ["preview", "standard", "reference"] {
        let mut times = Vec::new();
        let mut rows = Vec::new();
        for _ in 0..repeats {
            let (ms, r) = run_level(&text, &designs, level);
            times.push(ms);
            rows = r;
        }
        times.sort_by(f64::total_cmp);
        let ms = times[times.len() / 2];
        let failed = rows.iter().filter(|r| r.result.is_err()).count();
        let pct = |x: f64| if level == "reference" { "—".to_string() } else { format!("{:.2} %", 100.0 * x) };
        let _ = writeln!(
            md,
            "| {level} | {ms:.1} ms | {:.0} | {} | {} | {} | {failed} |",
            3.6e6 / ms,
            pct(worst(&rows, &truth, "eccentricity_ratio")),
            pct(worst(&rows, &truth, "h_min_um")),
            pct(worst(&rows, &truth, "kyy_n_per_m")),
        );
    }
    let _ = writeln!(
        md,
        "\nShards scale with cores: `--shard I/N` jobs share nothing, so N cores (GNU parallel, a Slurm array) give N times the \
         designs per hour, less the start-up of each job (reading the case, building the first mesh: one design's time)."
    );
    Ok(md)
}
