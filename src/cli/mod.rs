//! Command-line interface for batch runs: `tiltpad solve`, `tiltpad sweep`.
//!
//! Engineering units at this edge only; the JSON written by `solve --json` is SI with units in the key names.
//! The result documents ([`solution_json`], [`summary_text`]) build on every target (the web workbench
//! exports them too); the commands themselves are native only.

#[cfg(not(target_arch = "wasm32"))]
mod bench;
mod summary;
#[cfg(not(target_arch = "wasm32"))]
mod sweep;

#[cfg(not(target_arch = "wasm32"))]
use std::path::{Path, PathBuf};

#[cfg(not(target_arch = "wasm32"))]
use anyhow::{Context, Result};
#[cfg(not(target_arch = "wasm32"))]
use clap::{Parser, Subcommand};

#[cfg(not(target_arch = "wasm32"))]
use crate::bearing::solve_case;
#[cfg(not(target_arch = "wasm32"))]
use crate::model::{load_case, Case, CaseFile};

pub use summary::{solution_json, summary_text};

#[cfg(not(target_arch = "wasm32"))]
#[derive(Debug, Parser)]
#[command(name = "tiltpad", version, about = "Tilting-pad journal bearing workbench (solver CLI)")]
pub struct Cli {
    #[command(subcommand)]
    pub command: Option<Command>,
}

#[cfg(not(target_arch = "wasm32"))]
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Solve one case and print a summary.
    Solve {
        /// Case file (TOML).
        case: PathBuf,
        /// Override a case value, e.g. `--set operating.speed_rpm=3000` (repeatable).
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
        /// Write the full result as JSON.
        #[arg(long, value_name = "OUT")]
        json: Option<PathBuf>,
    },
    /// Solve a case over a range of one parameter and write a CSV table.
    Sweep {
        case: PathBuf,
        /// Dotted case key to vary, e.g. `operating.speed_rpm`.
        #[arg(long)]
        param: String,
        #[arg(long)]
        from: f64,
        #[arg(long)]
        to: f64,
        #[arg(long, default_value_t = 11)]
        steps: usize,
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
        #[arg(long, value_name = "OUT")]
        csv: PathBuf,
    },
    /// Measure time and error per fidelity level; writes docs/PERFORMANCE.md (run in --release).
    Bench {
        /// Repeated solves per measurement (the median is reported).
        #[arg(long, default_value_t = 7)]
        repeats: usize,
        /// Project root (where `cases/` and `docs/` are).
        #[arg(long, default_value = ".")]
        root: PathBuf,
    },
}

#[cfg(not(target_arch = "wasm32"))]
/// Reads and validates a case file with overrides.
///
/// # Errors
/// I/O and every case error, with the file name.
pub fn read_case(path: &Path, set: &[String]) -> Result<(CaseFile, Case)> {
    let text = std::fs::read_to_string(path).with_context(|| format!("cannot read case file {}", path.display()))?;
    load_case(&text, set).with_context(|| format!("invalid case {}", path.display()))
}

#[cfg(not(target_arch = "wasm32"))]
/// Writes a file atomically (temporary file in the same folder, then rename).
///
/// # Errors
/// I/O errors.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<()> {
    let dir = path.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or_else(|| Path::new("."));
    let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
    let tmp = dir.join(format!(".{name}.tmp{}", std::process::id()));
    std::fs::write(&tmp, bytes).with_context(|| format!("cannot write {}", tmp.display()))?;
    std::fs::rename(&tmp, path).with_context(|| format!("cannot move {} to {}", tmp.display(), path.display()))?;
    Ok(())
}

#[cfg(not(target_arch = "wasm32"))]
/// Runs a CLI command.
///
/// # Errors
/// Case, solve and I/O errors (printed by `main`).
pub fn run(command: Command) -> Result<()> {
    match command {
        Command::Solve { case, set, json } => {
            let (_, c) = read_case(&case, &set)?;
            let sol = solve_case(&c).with_context(|| format!("solving {}", case.display()))?;
            print!("{}", summary_text(&sol));
            if let Some(out) = json {
                let text = serde_json::to_string_pretty(&solution_json(&sol))?;
                write_atomic(&out, text.as_bytes())?;
                println!("wrote {}", out.display());
            }
            Ok(())
        }
        Command::Sweep { case, param, from, to, steps, set, csv } => sweep::run(&case, &param, from, to, steps, &set, &csv),
        Command::Bench { repeats, root } => bench::run(&root, repeats.max(1)),
    }
}
