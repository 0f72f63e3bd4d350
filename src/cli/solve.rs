//! `tiltpad solve`: one case, its summary, and the full result as JSON or VTK when asked.

use std::path::{Path, PathBuf};

use anyhow::Result;

use crate::bearing::{Request, SolveError, Stages};
use crate::study::estimate::{point_cost, Estimate};

use super::{inputs, interrupt, is_stdout, read_case, rows, solution_json, summary_text, vtu, write_atomic};

/// Solves `case` with the overrides `set` and writes what is asked.
///
/// # Errors
/// Input, solve and I/O errors; [`interrupt::Interrupted`] after Ctrl-C.
pub fn solve(case: &Path, set: &[String], json: Option<&PathBuf>, vtu: Option<&PathBuf>) -> Result<()> {
    inputs::check_outputs(
        &[("case file", case)],
        &[("--json", json.map(PathBuf::as_path)), ("--vtu", vtu.map(PathBuf::as_path))],
    )?;
    let (_, c) = read_case(case, set)?;
    inputs::check_work(&Estimate::points("solve", 1, point_cost(&c)), f64::INFINITY)?;
    let sol = match Stages::new().solution(&Request::solution(c), &interrupt::Interrupt) {
        Ok(s) => std::sync::Arc::unwrap_or_clone(s),
        Err(SolveError::Cancelled) if interrupt::requested() => {
            return Err(interrupt::Interrupted::new(0, 1, "solves", &[]).into())
        }
        Err(e) => return Err(anyhow::Error::new(e).context(format!("solving {}", case.display()))),
    };
    // Standard output belongs to the JSON when it goes there.
    if is_stdout(json) {
        eprint!("{}", summary_text(&sol));
    } else {
        print!("{}", summary_text(&sol));
    }
    if let Some(out) = json {
        let mut text = serde_json::to_string_pretty(&solution_json(&sol))?;
        text.push('\n');
        write_atomic(out, text.as_bytes())?;
        rows::announce(out);
    }
    if let Some(out) = vtu {
        for p in vtu::write_solution(out, &sol)? {
            rows::announce(&p);
        }
    }
    Ok(())
}
