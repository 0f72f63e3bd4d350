//! `tiltpad batch DESIGNS.csv --case BASE.toml`: one solve per design (any case keys as columns), each
//! from scratch so that a row does not depend on the rows before it; `--shard I/N` runs the I-th of N
//! blocks, for GNU parallel or a Slurm job array (see the README). Rows carry the design's number, its
//! inputs and its results (or its error), in CSV and/or JSON lines, written as they complete.

use std::path::{Path, PathBuf};

use anyhow::{bail, Context, Result};

use crate::study::estimate::Estimate;
use crate::study::{Designs, Runner, Shard};

use super::rows::RowSink;
use super::sweep::progress;

/// What to run and where the rows go.
pub struct BatchArgs<'a> {
    pub designs: &'a Path,
    pub case: &'a Path,
    pub set: &'a [String],
    pub shard: Shard,
    pub csv: Option<PathBuf>,
    pub jsonl: Option<PathBuf>,
    /// Most designs this run may solve.
    pub max_points: usize,
    /// Most estimated hours of work.
    pub max_hours: f64,
}

/// Runs the shard.
///
/// # Errors
/// Unreadable inputs, a bad designs table, an output that cannot be written, or every design failed.
pub fn run(args: &BatchArgs<'_>) -> Result<()> {
    let table = crate::io::read::read_text(args.designs, "designs table")?;
    let designs = Designs::parse(&table).with_context(|| format!("in {}", args.designs.display()))?;
    if designs.rows.is_empty() {
        bail!("{} has a header but no design rows: nothing to solve", args.designs.display());
    }
    let text = crate::io::read::read_text(args.case, "case file")?;
    let range = args.shard.range(designs.rows.len());
    super::inputs::check_points("batch", range.len(), args.max_points)?;
    let runner = Runner::new(text, args.set.to_vec(), false);
    // Every column's key, with its first given value, is checked before the first design is solved.
    let firsts: Vec<(String, String)> =
        designs.keys.iter().filter_map(|k| designs.rows.iter().flatten().find(|(g, _)| g == k).cloned()).collect();
    runner.check_keys(&firsts).with_context(|| format!("in the header of {}", args.designs.display()))?;
    if let Some(r) = runner.shadowed(&designs.rows[range.clone()]) {
        bail!(
            "in the header of {}: column {} replaces column {} in a design that sets both ({r}): its values of {} \
             would not be solved; give one of them",
            args.designs.display(),
            r.set,
            r.removed,
            r.removed
        );
    }
    let mine = &designs.rows[range.clone()];
    let ends: Vec<&[(String, String)]> =
        [Some(&[][..]), mine.first().map(Vec::as_slice), mine.last().map(Vec::as_slice)]
            .into_iter()
            .flatten()
            .collect();
    if let Some(cost) = super::inputs::costliest(&runner, &ends) {
        super::inputs::check_work(&Estimate::points("batch", range.len(), cost), args.max_hours)?;
    }
    let csv = args.csv.clone().or_else(|| args.jsonl.is_none().then(|| PathBuf::from("-")));
    let mut sink = RowSink::open(csv.as_deref(), args.jsonl.as_deref(), "design", &designs.keys)?;
    let mut runner = runner;
    for note in runner.replaced(&designs.rows[range.clone()]) {
        eprintln!("note: {note}");
    }
    let mut pb = progress(range.len(), "designs");
    let mut failed = 0;
    let mut done = 0;
    for i in range.clone() {
        if super::interrupt::requested() {
            break;
        }
        // Every key of the table is a column, in header order, empty where the design keeps the base value.
        let given = &designs.rows[i];
        let (mut row, _) = runner.row(i, given);
        row.inputs = designs
            .keys
            .iter()
            .map(|k| (k.clone(), given.iter().find(|(g, _)| g == k).map(|(_, v)| v.clone()).unwrap_or_default()))
            .collect();
        if row.result.is_err() {
            failed += 1;
            pb.println(format!("design {i}: {}", row.error_text()));
        }
        sink.write(&row)?;
        done += 1;
        pb.inc(1);
    }
    pb.finish_and_clear();
    sink.finish()?;
    if done < range.len() {
        let outputs: Vec<&Path> = [csv.as_deref(), args.jsonl.as_deref()].into_iter().flatten().collect();
        return Err(super::interrupt::Interrupted::new(done, range.len(), "designs", &outputs).into());
    }
    if !range.is_empty() && failed == range.len() {
        bail!("every design of this shard failed ({failed} of {failed}); the rows say why");
    }
    if failed > 0 {
        eprintln!("{failed} of {} designs failed; their rows hold the error", range.len());
    }
    Ok(())
}
