//! `tiltpad fidelity`: the speed–accuracy trade measured on the user's own case
//! ([`crate::study::fidelity`]) — each fidelity level (preview, standard, reference) solved `--repeats` times
//! with its median wall time, film nodes and relative errors (ε, reduced K and C, p_max, T_max rise of a THD
//! case, the flows) against a finer solve, the truth: twice the reference level's element counts. The
//! editor's note beside the fidelity selector gives the same numbers measured on the compressor bearing;
//! this is them for the case at hand.
//!
//! A table on standard output (on standard error when an output goes to standard output), JSON (`--json`:
//! the rows with their errors as fractions, and the levels that failed) and CSV (`--csv`: one row per level
//! and the truth's, an `error` column for a level that failed). The truth is solved first; Ctrl-C keeps the
//! levels finished and writes them.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use anyhow::{Context, Result};
use serde_json::json;

use crate::number::csv;
use crate::study::estimate::point_cost;
use crate::study::fidelity::{level_name, FidelityError, FidelityTrade, LevelCost, LevelFailure, TradeStep};

use super::rows::announce;
use super::{interrupt, is_stdout, read_case, write_atomic};

/// What to measure and where it goes.
pub struct FidelityArgs<'a> {
    pub case: &'a Path,
    pub set: &'a [String],
    /// Solves per level (the median time is given).
    pub repeats: usize,
    pub json: Option<PathBuf>,
    pub csv: Option<PathBuf>,
    /// Most estimated hours of work.
    pub max_hours: f64,
}

/// Measures the trade and writes it (on Ctrl-C, the levels finished, then [`interrupt::Interrupted`]).
///
/// # Errors
/// An invalid case, an explicit element count in it, a truth that does not solve, an output that cannot be
/// written; Ctrl-C.
pub fn run(args: &FidelityArgs<'_>) -> Result<()> {
    let (_, case) = read_case(args.case, args.set)?;
    let text = crate::io::read::read_text(args.case, "case file")?;
    let label = args.case.file_name().map_or_else(|| args.case.display().to_string(), |n| n.to_string_lossy().into());
    let mut trade = FidelityTrade::new(&label, &text, args.set, args.repeats)
        .with_context(|| format!("invalid case {}", args.case.display()))?;
    super::inputs::check_work(&trade.estimate(), args.max_hours)?;
    let mut pb = super::sweep::progress(trade.solves(), "solves");
    let mut stopped = false;
    while let Some((what, level_case)) = trade.next() {
        let doing = format!("{what}: {} film nodes", point_cost(level_case).film_nodes);
        pb.set_message(doing.clone());
        interrupt::doing(doing);
        match trade.step(&interrupt::Interrupt) {
            Ok(TradeStep::More { done, .. }) => pb.set_position(done as u64),
            Ok(TradeStep::Done) => break,
            Err(FidelityError::Cancelled) => {
                stopped = true;
                break;
            }
            Err(e) => return Err(anyhow::Error::new(e).context(format!("measuring {}", args.case.display()))),
        }
        if interrupt::requested() {
            stopped = true;
            break;
        }
    }
    interrupt::doing("");
    pb.finish_and_clear();
    let (rows, failed) = trade.finish();
    let levels_done = rows.len().saturating_sub(1) + failed.len();
    if rows.is_empty() {
        return Err(interrupt::Interrupted::new(0, crate::study::fidelity::LEVELS.len(), "levels", &[]).into());
    }
    let title = format!("{} ({label})", case.title);
    let text = table(&title, args.repeats.max(1), &rows, &failed);
    if is_stdout(args.json.as_ref()) || is_stdout(args.csv.as_ref()) {
        eprint!("{text}");
    } else {
        print!("{text}");
    }
    if let Some(out) = &args.json {
        let mut s =
            serde_json::to_string_pretty(&json_of(args.case, &case.title, args.repeats.max(1), &rows, &failed))?;
        s.push('\n');
        write_atomic(out, s.as_bytes())?;
        announce(out);
    }
    if let Some(out) = &args.csv {
        write_atomic(out, csv_of(&rows, &failed).as_bytes())?;
        announce(out);
    }
    if stopped {
        let outputs: Vec<&Path> = [args.json.as_deref(), args.csv.as_deref()].into_iter().flatten().collect();
        let outputs = if outputs.is_empty() { vec![Path::new("-")] } else { outputs };
        let of = crate::study::fidelity::LEVELS.len();
        return Err(interrupt::Interrupted::new(levels_done, of, "levels", &outputs).into());
    }
    Ok(())
}

/// A fraction as per cent (— for the truth's zero).
fn pct(x: f64) -> String {
    if x == 0.0 {
        "—".into()
    } else {
        format!("{:.2} %", 100.0 * x)
    }
}

/// The table people read.
fn table(title: &str, repeats: usize, rows: &[LevelCost], failed: &[LevelFailure]) -> String {
    let mut s = format!(
        "{title}: time and error per fidelity level against a finer solve (twice the reference level's element \
         counts), median of {repeats} solve{}\n",
        if repeats == 1 { "" } else { "s" }
    );
    let _ = writeln!(
        s,
        "{:<24} {:>10} {:>11} {:>8} {:>8} {:>8} {:>8} {:>8} {:>8}",
        "level", "film nodes", "time", "ε", "K", "C", "p_max", "T_max", "flows"
    );
    let opt = |x: Option<f64>| x.map_or_else(|| "—".to_string(), pct);
    for r in rows {
        let _ = writeln!(
            s,
            "{:<24} {:>10} {:>8.1} ms {:>8} {:>8} {:>8} {:>8} {:>8} {:>8}",
            r.level,
            r.film_nodes,
            r.median_ms,
            pct(r.err_eccentricity),
            pct(r.err_k),
            pct(r.err_c),
            pct(r.err_p_max),
            opt(r.err_t_max),
            opt(r.err_flows)
        );
    }
    for f in failed {
        let _ = writeln!(s, "{:<24} failed: {}", level_name(f.level), f.error);
    }
    s.push_str(
        "Errors are relative: K and C the Frobenius norm of the reduced 2×2 difference over the truth's; T_max the \
         hottest film temperature's rise above supply (THD); flows the worst flow that carries at least 1 % of the \
         throughput. Times are this machine's wall times.\n",
    );
    s
}

/// The JSON form: the rows (errors as fractions, time in ms) and the levels that failed.
fn json_of(path: &Path, title: &str, repeats: usize, rows: &[LevelCost], failed: &[LevelFailure]) -> serde_json::Value {
    let failed: Vec<_> =
        failed.iter().map(|f| json!({ "level": level_name(f.level), "error": f.error.to_string() })).collect();
    json!({
        "case": path.display().to_string(),
        "title": title,
        "repeats": repeats,
        "truth": "twice the reference level's element counts",
        "levels": rows,
        "failed": failed,
    })
}

/// The CSV form: one row per level and the truth's; empty cells where a quantity does not apply.
fn csv_of(rows: &[LevelCost], failed: &[LevelFailure]) -> String {
    let mut s =
        String::from("level,film_nodes,median_ms,err_eccentricity,err_k,err_c,err_p_max,err_t_max,err_flows,error\n");
    let opt = |x: Option<f64>| x.map_or_else(String::new, csv);
    for r in rows {
        let _ = writeln!(
            s,
            "{},{},{},{},{},{},{},{},{},",
            r.level,
            r.film_nodes,
            csv(r.median_ms),
            csv(r.err_eccentricity),
            csv(r.err_k),
            csv(r.err_c),
            csv(r.err_p_max),
            opt(r.err_t_max),
            opt(r.err_flows)
        );
    }
    for f in failed {
        let error = f.error.to_string().replace('"', "\"\"");
        let _ = writeln!(s, "{},,,,,,,,,\"{error}\"", level_name(f.level));
    }
    s
}
