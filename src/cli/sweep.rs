//! `tiltpad sweep`: a grid over any case keys, warm-started point to point, each row written as it
//! completes; a failed point is a row with its error, and the command fails only when every point did.

use std::path::{Path, PathBuf};

use anyhow::{bail, Context, Result};

use crate::study::estimate::Estimate;
use crate::study::{grid, Axis, Runner};

use super::rows::RowSink;
use super::vtu::VtuSeries;

/// What to sweep and where the rows go.
pub struct SweepArgs<'a> {
    pub case: &'a Path,
    pub axes: Vec<Axis>,
    pub set: &'a [String],
    pub csv: Option<PathBuf>,
    pub jsonl: Option<PathBuf>,
    pub vtu: Option<PathBuf>,
    /// Most points the grid may have.
    pub max_points: usize,
    /// Most estimated hours of work.
    pub max_hours: f64,
}

/// The progress display of a command over `len` points, each one `unit` (`points`, `speeds`, …).
#[must_use]
pub fn progress(len: usize, unit: &'static str) -> super::progress::Progress {
    super::progress::Progress::new(len, unit)
}

/// Two spellings of one case key (`bearing.pad.2.offset`, `bearing.pad[2].offset`).
fn same_key(a: &str, b: &str) -> bool {
    let normal = |k: &str| k.replace('[', ".").replace([']', ' '], "");
    normal(a) == normal(b)
}

/// Runs the sweep.
///
/// # Errors
/// An unreadable case, bad axes, an output that cannot be written, or every point failed.
pub fn run(args: SweepArgs<'_>) -> Result<()> {
    if args.axes.is_empty() {
        bail!("nothing to sweep: give --vary KEY=FROM:TO:STEPS (or --param KEY --from A --to B --steps N)");
    }
    let text = crate::io::read::read_text(args.case, "case file")?;
    for (i, a) in args.axes.iter().enumerate() {
        if let Some(b) = args.axes[..i].iter().find(|b| same_key(&a.key, &b.key)) {
            bail!(
                "--vary {} and --vary {}: the same key twice (its rows would show values that were not solved); \
                 give all its values in one --vary",
                a.key,
                b.key
            );
        }
    }
    let total = args.axes.iter().try_fold(1usize, |n, a| n.checked_mul(a.values.len())).unwrap_or(usize::MAX);
    super::inputs::check_points("sweep", total, args.max_points)?;
    let points = grid::points(&args.axes)?;
    let keys: Vec<String> = args.axes.iter().map(|a| a.key.clone()).collect();
    let mut runner = Runner::new(text, args.set.to_vec(), true);
    let firsts: Vec<(String, String)> = args.axes.iter().map(|a| (a.key.clone(), a.values[0].clone())).collect();
    runner.check_keys(&firsts).context("a swept key (--vary or --param)")?;
    if let Some(r) = runner.shadowed(&points) {
        bail!(
            "--vary {} replaces --vary {} at a point that sets both ({r}): its rows would show values of {} that \
             were not solved; vary one of them",
            r.set,
            r.removed,
            r.removed
        );
    }
    let ends: Vec<&[(String, String)]> =
        [Some(&[][..]), points.first().map(Vec::as_slice), points.last().map(Vec::as_slice)]
            .into_iter()
            .flatten()
            .collect();
    if let Some(cost) = super::inputs::costliest(&runner, &ends) {
        super::inputs::check_work(&Estimate::points("sweep", points.len(), cost), args.max_hours)?;
    }
    let csv = args.csv.clone().or_else(|| args.jsonl.is_none().then(|| PathBuf::from("-")));
    let mut sink = RowSink::open(csv.as_deref(), args.jsonl.as_deref(), "point", &keys)?;
    let mut vtu = args.vtu.as_deref().map(VtuSeries::new);
    // One numeric axis: ParaView steps through its values; otherwise through the point numbers.
    let single = (args.axes.len() == 1).then(|| &args.axes[0]);
    for note in runner.replaced(&points) {
        eprintln!("note: {note}");
    }
    let mut pb = progress(points.len(), "points");
    let mut failed = 0;
    let mut done = 0;
    for (i, point) in points.iter().enumerate() {
        if super::interrupt::requested() {
            break;
        }
        pb.set_message(point.iter().map(|(k, v)| format!("{k} = {v}")).collect::<Vec<_>>().join(", "));
        let (row, solution) = runner.row(i, point);
        if row.result.is_err() {
            failed += 1;
            pb.println(format!("point {i}: {}", row.error_text()));
        }
        sink.write(&row)?;
        if let (Some(series), Some(s)) = (&mut vtu, &solution) {
            #[allow(clippy::cast_precision_loss)]
            let step = single.and_then(|a| a.values[i].parse::<f64>().ok()).unwrap_or(i as f64);
            series.add(i, step, s)?;
        }
        done += 1;
        pb.inc(1);
    }
    pb.finish_and_clear();
    sink.finish()?;
    if let Some(series) = vtu {
        series.finish()?;
    }
    if done < points.len() {
        let outputs: Vec<&Path> =
            [csv.as_deref(), args.jsonl.as_deref(), args.vtu.as_deref()].into_iter().flatten().collect();
        return Err(super::interrupt::Interrupted::new(done, points.len(), "points", &outputs).into());
    }
    if failed == points.len() {
        bail!("every point of the sweep failed ({failed} of {failed}); the rows say why");
    }
    if failed > 0 {
        eprintln!("{failed} of {} points failed; their rows hold the error", points.len());
    }
    Ok(())
}
