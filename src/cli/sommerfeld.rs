//! `tiltpad sommerfeld`: the Sommerfeld chart of a case ([`crate::scene::sommerfeld`]) — the sweep the
//! Sweep view's "Sommerfeld chart" runs (12 loads from 0.2 to 3 times the case's, or ε from 0.1 to 0.85 for a
//! case that prescribes the journal position), written as CSV (one row per drawn point: plot, curve, S,
//! value, the reference line included) or JSON (the plots, the failed points, the deviation from the
//! reference).

use std::path::{Path, PathBuf};

use anyhow::{bail, Context, Result};

use crate::scene::sommerfeld::{chart, chart_csv, chart_json, reference_deviation, ChartGeometry, ChartPlot};
use crate::scene::sweep::{point_override, SweepSpec, SweepTable, MAX_POINTS};
use crate::study::Runner;

use super::rows::announce;
use crate::io::write_file;

/// What to chart and where it goes.
pub struct SommerfeldArgs<'a> {
    pub case: &'a Path,
    pub set: &'a [String],
    /// Swept points.
    pub points: usize,
    pub csv: Option<PathBuf>,
    pub json: Option<PathBuf>,
}

/// The chart's sweep solved: the table of rows and the geometry the chart reads. On Ctrl-C the table holds
/// the points finished before it, in sweep order, and the count asked for is returned beside it.
///
/// # Errors
/// An unreadable or invalid case, a point count outside [2, [`MAX_POINTS`]].
pub fn sweep(case_path: &Path, set: &[String], points: usize) -> Result<(SweepTable, ChartGeometry, usize)> {
    let (_, case) = super::read_case(case_path, set)?;
    let text = crate::io::read::read_text(case_path, "case file")?;
    let mut spec = SweepSpec::sommerfeld_chart(&case);
    spec.count = points;
    let values = spec.values().with_context(|| format!("--points {points}: allowed 2 to {MAX_POINTS}"))?;
    // at most 101 points: the memory of one point's meshes is what can be too much
    let cost = crate::study::estimate::point_cost(&case);
    let estimate = crate::study::estimate::Estimate::points("sommerfeld", values.len(), cost);
    super::inputs::check_work(&estimate, f64::INFINITY)?;
    let mut runner = Runner::new(text, set.to_vec(), true);
    let mut table = SweepTable::new(&spec.key);
    let asked = values.len();
    let mut pb = super::sweep::progress(asked, "points");
    for (i, x) in values.into_iter().enumerate() {
        if super::interrupt::requested() {
            break;
        }
        pb.set_message(format!("{} = {x:.4}", spec.key));
        let (row, _) = runner.row(i, &point_override(&spec.key, x));
        if row.result.is_err() {
            pb.println(format!("point {i}: {}", row.error_text()));
        }
        table.points.push((x, row));
        pb.inc(1);
    }
    pb.finish_and_clear();
    Ok((table, ChartGeometry::of(&case), asked))
}

/// Runs the sweep and writes the chart (on Ctrl-C, the chart of the points finished, then
/// [`super::interrupt::Interrupted`]).
///
/// # Errors
/// See [`sweep`]; every point failed; an output that cannot be written; Ctrl-C.
pub fn run(args: &SommerfeldArgs<'_>) -> Result<()> {
    let (table, g, asked) = sweep(args.case, args.set, args.points)?;
    let done = table.points.len();
    if done < asked && table.points.iter().all(|(_, row)| row.result.is_err()) {
        return Err(super::interrupt::Interrupted::new(done, asked, "points", &[]).into());
    }
    let failed = table.failures();
    if failed.len() == table.points.len() {
        bail!("every point of the chart's sweep failed ({} of {}): {}", failed.len(), failed.len(), failed[0].1);
    }
    let plots: Vec<ChartPlot> = chart(&table, &g);
    match (g.plain_360_l_over_d, reference_deviation(&plots, &g)) {
        (Some(ld), Some(d)) => eprintln!(
            "plain 360° bearing, L/D = {ld:.3}: S within {:.2} % of the short-bearing reference at the same ε",
            100.0 * d
        ),
        _ => eprintln!("no closed-form reference for this geometry (only a plain 360° bearing has one)"),
    }
    for (x, why) in &failed {
        eprintln!("no solution at {} = {x}: {why}", table.key);
    }
    if args.csv.is_none() && args.json.is_none() {
        print!("{}", chart_csv(&plots));
    }
    if let Some(p) = &args.csv {
        write_file(p, chart_csv(&plots).as_bytes())?;
        announce(p);
    }
    if let Some(p) = &args.json {
        let mut text = serde_json::to_string_pretty(&chart_json(&plots, &g, &table))?;
        text.push('\n');
        write_file(p, text.as_bytes())?;
        announce(p);
    }
    if done < asked {
        let stdout = Path::new("-");
        let outputs: Vec<&Path> = match (&args.csv, &args.json) {
            (None, None) => vec![stdout],
            (csv, json) => [csv.as_deref(), json.as_deref()].into_iter().flatten().collect(),
        };
        return Err(super::interrupt::Interrupted::new(done, asked, "points", &outputs).into());
    }
    Ok(())
}
