//! Developer tools of tiltpad, run from the repository as `cargo xtask COMMAND` (the alias in
//! `.cargo/config.toml` builds this crate in release and runs it). Not part of the product: the `tiltpad`
//! binary and the Python wheel do not link it; it uses the library as any program would.
//!
//! - `cargo xtask bench [--only SECTION] [--repeats N]`: measures time and error per fidelity level and every
//!   section of docs/PERFORMANCE.md, and rewrites it (with `docs/performance-error-vs-time.svg` and
//!   `assets/fidelity.json`). A user measures the same trade on their own case with `tiltpad fidelity`.

mod bench;

use std::path::PathBuf;

use clap::{Parser, Subcommand};

#[derive(Debug, Parser)]
#[command(
    name = "cargo xtask",
    bin_name = "cargo xtask",
    about = "Developer tools of tiltpad (not part of the product)"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Measure time and error per fidelity level and every section of docs/PERFORMANCE.md, and write it.
    Bench {
        /// Repeated solves per measurement (the median is reported).
        #[arg(long, default_value_t = 7)]
        repeats: usize,
        /// Project root (where `cases/` and `docs/` are).
        #[arg(long, default_value = ".")]
        root: PathBuf,
        /// Re-measure one section only and replace it in docs/PERFORMANCE.md, keeping the rest (`table`: the
        /// first table with its targets, thermal-loop cost, cost growth and `assets/fidelity.json`); the section
        /// closes with the time of a calibration solve before and after it, against the same solve in the
        /// first table (the machine's speed drifts between runs). The `estimates` section runs the `tiltpad`
        /// binary: `$TILTPAD_BIN`, else the one cargo builds beside this program.
        #[arg(long, value_name = "SECTION", value_parser = clap::builder::PossibleValuesParser::new(bench::SECTIONS))]
        only: Option<String>,
    },
}

fn main() {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Bench { repeats, root, only } => bench::run(&root, only.as_deref(), repeats),
    };
    if let Err(e) = result {
        eprintln!("error: {e:#}");
        std::process::exit(1);
    }
}
