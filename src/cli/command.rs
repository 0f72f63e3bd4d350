//! The command line's grammar: every command, its arguments and their parsers (clap). What each command
//! does is in the file of its name; [`super::run`] dispatches.

use std::path::PathBuf;

use clap::{Parser, Subcommand};

use crate::study::estimate::DEFAULT_MAX_HOURS;

use super::{coefficients, inputs};

#[derive(Debug, Parser)]
#[command(
    name = "tiltpad",
    version,
    about = "Tilting-pad journal bearing workbench: `tiltpad` without arguments opens the interactive workbench; the commands below run batch solves",
    after_help = "Without a command, tiltpad opens the workbench window (editor, views, results) on the case edited last, or on the compressor bearing."
)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Option<Command>,
}

#[derive(Debug, Subcommand)]
pub enum Command {
    /// Solve one case and print a summary.
    Solve {
        /// Case file (TOML).
        case: PathBuf,
        /// Override a case value, e.g. `--set operating.speed_rpm=3000` (repeatable).
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
        /// Write the full result as JSON (`-`: standard output; the summary then goes to standard error).
        #[arg(long, value_name = "OUT")]
        json: Option<PathBuf>,
        /// Write the film fields on the 3-D pad surfaces as a VTK grid (`OUT.vtu`; pad temperatures of a
        /// thermal solve to `OUT-pads.vtu`), for ParaView.
        #[arg(long, value_name = "OUT.vtu")]
        vtu: Option<PathBuf>,
    },
    /// Time and error of each fidelity level (preview, standard, reference) on this case, against a finer
    /// solve (twice the reference level's element counts): what each level costs and how accurate it is.
    Fidelity {
        /// Case file (TOML); it must not fix the element counts (they override mesh.fidelity).
        case: PathBuf,
        /// Override a case value, e.g. `--set thermal.model=thd` (repeatable).
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
        /// Solves per level; each level's time is their median (1 to 50).
        #[arg(long, default_value_t = 3, value_parser = clap::value_parser!(u16).range(1..=50))]
        repeats: u16,
        /// JSON of the levels: film nodes, median time [ms], errors as fractions (`-`: standard output).
        #[arg(long, value_name = "OUT")]
        json: Option<PathBuf>,
        /// CSV, one row per level and the truth's (`-`: standard output).
        #[arg(long, value_name = "OUT")]
        csv: Option<PathBuf>,
        /// Most estimated hours of work (the finer solve and each level's solves; refused before the first
        /// solve beyond it).
        #[arg(long, value_name = "H", default_value_t = DEFAULT_MAX_HOURS, value_parser = inputs::parse_hours)]
        max_hours: f64,
    },
    /// Solve a case over a grid of any case keys; one row per point, written as it completes.
    Sweep {
        /// Case file (TOML) the sweep starts from.
        case: PathBuf,
        /// A swept key: `KEY=FROM:TO:STEPS`, `KEY=v1,v2,…` or `KEY=[a,b];[c,d]` (repeat for a grid; the
        /// first varies slowest).
        #[arg(long = "vary", value_name = "KEY=VALUES")]
        vary: Vec<String>,
        /// One swept key (with --from, --to, --steps), same as `--vary KEY=FROM:TO:STEPS`.
        #[arg(long, value_name = "KEY")]
        param: Option<String>,
        /// First value of the --param key (in the key's unit, e.g. rpm for `operating.speed_rpm`).
        #[arg(long, requires = "param", allow_negative_numbers = true)]
        from: Option<f64>,
        /// Last value of the --param key.
        #[arg(long, requires = "param", allow_negative_numbers = true)]
        to: Option<f64>,
        /// Number of evenly spaced values of the --param key, both ends included.
        #[arg(long, default_value_t = 11)]
        steps: usize,
        /// Override a case value for every point, e.g. `--set thermal.model=thd` (repeatable).
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
        /// CSV of the rows (`-`: standard output, the default when no output is given).
        #[arg(long, value_name = "OUT")]
        csv: Option<PathBuf>,
        /// JSON lines of the rows (one object per point).
        #[arg(long, value_name = "OUT")]
        jsonl: Option<PathBuf>,
        /// A ParaView collection `OUT.pvd` with one `.vtu` per solved point beside it.
        #[arg(long, value_name = "OUT.pvd")]
        vtu: Option<PathBuf>,
        /// Most points the sweep may have (refused before the first solve beyond it).
        #[arg(long, value_name = "N", default_value_t = inputs::DEFAULT_MAX_POINTS)]
        max_points: usize,
        /// Most estimated hours of work (points × the work model's time per point; refused before the first
        /// solve beyond it).
        #[arg(long, value_name = "H", default_value_t = DEFAULT_MAX_HOURS, value_parser = inputs::parse_hours)]
        max_hours: f64,
    },
    /// The Sommerfeld chart of a case: a load sweep (or an eccentricity sweep, for a case that prescribes
    /// the journal position) as ε, attitude, h_min/Cb and the reduced coefficients against S, with the
    /// short-bearing reference of a plain 360° bearing. CSV on standard output unless --csv/--json.
    Sommerfeld {
        /// Case file (TOML); the sweep runs from 0.2 to 3 times its load.
        case: PathBuf,
        /// Override a case value for every point, e.g. `--set mesh.fidelity=preview` (repeatable).
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
        /// Number of swept points (2 to 101).
        #[arg(long, default_value_t = 12)]
        points: usize,
        /// CSV, one row per drawn point: plot, curve, sommerfeld, value (`-`: standard output).
        #[arg(long, value_name = "OUT")]
        csv: Option<PathBuf>,
        /// JSON: the plots, the failed points and the deviation from the reference.
        #[arg(long, value_name = "OUT")]
        json: Option<PathBuf>,
    },
    /// Solve every design of a table (one design per row, any case keys as columns) on a base case.
    Batch {
        /// Designs table (CSV with a header of case keys).
        designs: PathBuf,
        /// Base case file (TOML) the designs change.
        #[arg(long)]
        case: PathBuf,
        /// Override a case value for every design, e.g. `--set mesh.fidelity="preview"` (repeatable).
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
        /// Run only block I of N (1 ≤ I ≤ N) of the designs, e.g. `--shard $SLURM_ARRAY_TASK_ID/8`.
        #[arg(long, value_name = "I/N")]
        shard: Option<String>,
        /// CSV of the rows (`-`: standard output, the default when no output is given).
        #[arg(long, value_name = "OUT")]
        csv: Option<PathBuf>,
        /// JSON lines of the rows.
        #[arg(long, value_name = "OUT")]
        jsonl: Option<PathBuf>,
        /// Most designs this run may solve (refused before the first solve beyond it).
        #[arg(long, value_name = "N", default_value_t = inputs::DEFAULT_MAX_POINTS)]
        max_points: usize,
        /// Most estimated hours of work (designs × the work model's time per design; refused before the
        /// first solve beyond it).
        #[arg(long, value_name = "H", default_value_t = DEFAULT_MAX_HOURS, value_parser = inputs::parse_hours)]
        max_hours: f64,
    },
    /// Reduced stiffness and damping over running speed or excitation frequency, for ROSS and as CSV.
    Coefficients(coefficients::CoefficientArgs),
    /// Pad bending modes on the pivot (frequency, modal mass and stiffness), optionally the mesh-convergence
    /// table of the first pad's modes (thesis Table 3.1 style).
    Modes {
        /// Case file (TOML).
        case: PathBuf,
        /// Override a case value, e.g. `--set operating.speed_rpm=3000` (repeatable).
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
        /// Bending modes per pad (1–6).
        #[arg(long, default_value_t = 3, value_parser = clap::value_parser!(u16).range(1..=6))]
        count: u16,
        /// Also the convergence table over film/solid meshes.
        #[arg(long)]
        table: bool,
        /// JSON of the modes (and table) (`-`: standard output).
        #[arg(long, value_name = "OUT")]
        json: Option<PathBuf>,
        /// CSV of the modes, or of the table with --table (`-`: standard output).
        #[arg(long, value_name = "OUT")]
        csv: Option<PathBuf>,
    },
    /// Rotor–bearing analysis over a speed range: damped modes, onset, critical speeds, unbalance response.
    Rotor {
        /// Rotor file (TOML; bearing cases relative to it).
        rotor: PathBuf,
        #[command(flatten)]
        range: SpeedRange,
        /// Override the rotor's bearing coefficients: `full` or `reduced`.
        #[arg(long, value_parser = ["full", "reduced"])]
        coefficients: Option<String>,
        /// Override the rotor's shaft reduction: fixed-interface modes per bending plane (0: full shaft; at
        /// most 400, as in the rotor file).
        #[arg(long, value_name = "N", value_parser = clap::value_parser!(u16).range(0..=400))]
        shaft_modes: Option<u16>,
        /// Instead of the analysis: the undamped critical-speed map (critical speeds against a support
        /// stiffness at the bearings), the bearings' stiffness over `--speeds` and their crossings.
        #[arg(long)]
        critical_map: bool,
        /// Whole result as JSON (`-`: standard output).
        #[arg(long, value_name = "OUT")]
        json: Option<PathBuf>,
        /// One row per speed as CSV (`-`: standard output).
        #[arg(long, value_name = "OUT")]
        csv: Option<PathBuf>,
    },
    /// Active control: the closed loop of a rotor file's `[control]` over a speed range (poles open and
    /// closed, onset against the loop gain, Nyquist margins at each valve's input, unbalance response with
    /// and without control, valve signal and nozzle pressure amplitudes).
    Control {
        /// Rotor file (TOML) with a `[control]` section.
        rotor: PathBuf,
        #[command(flatten)]
        range: SpeedRange,
        /// Override `control.gain` (0 opens the loop, −1 flips its sign).
        #[arg(long, allow_hyphen_values = true)]
        gain: Option<f64>,
        /// Onset speed at each of these loop gains: `G1,G2,…` or `FROM:TO:N`.
        #[arg(long, value_name = "GAINS", allow_hyphen_values = true)]
        gain_sweep: Option<String>,
        /// Root locus at this speed [rpm] over the --gain-sweep gains (without it: 0 to twice the gain).
        #[arg(long, value_name = "RPM")]
        root_locus: Option<f64>,
        /// Whole result as compact JSON (`-`: standard output).
        #[arg(long, value_name = "OUT")]
        json: Option<PathBuf>,
        /// Keep the Nyquist curves in the JSON (left out by default: they are most of its size).
        #[arg(long)]
        nyquist_curves: bool,
        /// One row per speed as CSV (`-`: standard output).
        #[arg(long, value_name = "OUT")]
        csv: Option<PathBuf>,
        /// One row per gain of --gain-sweep (onset speed against the gain) as CSV.
        #[arg(long, value_name = "OUT")]
        gain_csv: Option<PathBuf>,
        /// The root locus' poles as CSV (one row per gain and pole).
        #[arg(long, value_name = "OUT")]
        locus_csv: Option<PathBuf>,
    },
    /// Frequency responses of the controllable bearing (valve G1, line G2, film G3, G = G1·G2·G3 per port
    /// and force component; with `[hydraulics.rig]` the calibrated-shaker chain C, Ĥ, H).
    Frf {
        /// Case file (TOML).
        case: PathBuf,
        /// Override a case value, e.g. `--set operating.speed_rpm=3000` (repeatable).
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
        /// Lowest frequency [Hz] (0 allowed: the band is then linear, else logarithmic).
        #[arg(long, default_value_t = 1.0, allow_negative_numbers = true)]
        from: f64,
        /// Highest frequency [Hz].
        #[arg(long, default_value_t = 1000.0, allow_negative_numbers = true)]
        to: f64,
        /// Frequencies in the band (2 to 100000).
        #[arg(long, default_value_t = 400)]
        points: usize,
        /// Control-signal amplitude [V] to check against the valve model's small-signal range (a positive
        /// number).
        #[arg(long, value_name = "V", value_parser = parse_amplitude)]
        amplitude_v: Option<f64>,
        /// CSV of magnitude and phase per curve (`-`: standard output; the default without --json).
        #[arg(long, value_name = "OUT")]
        csv: Option<PathBuf>,
        /// A controller file (`[control]`: the journal's vertical motion fed back to the valve) closing the
        /// loop on the rig: X/F with control against without.
        #[arg(long, value_name = "CONTROL.toml")]
        control: Option<PathBuf>,
        /// The rig's closed loop (X/F open and closed, valve signal per force) as CSV.
        #[arg(long, value_name = "OUT")]
        loop_csv: Option<PathBuf>,
        /// JSON of the curves, notes and timings.
        #[arg(long, value_name = "OUT")]
        json: Option<PathBuf>,
    },
    /// Print every case key with its unit, allowed values, default and meaning.
    Schema {
        /// The rotor-file keys instead of the case keys.
        #[arg(long)]
        rotor: bool,
        /// Write the table as JSON instead (`-`: standard output).
        #[arg(long, value_name = "OUT")]
        json: Option<PathBuf>,
    },
    /// Convergence map of the equilibrium: every shipped case and a generated family of 144 bearings, load
    /// direction every `--step-deg` × Sommerfeld number 10 … 0.01; counts converged / physical error /
    /// failure (run in --release; the 30° grid, 7392 points, took 4.4 min on this two-core machine, the 5°
    /// grid takes about six times that).
    ConvergenceMap {
        /// Directions every 30° and the 4-pad family only (a quick check).
        #[arg(long)]
        quick: bool,
        /// Step of the load direction [deg].
        #[arg(long, default_value_t = 5.0, value_parser = parse_step_deg)]
        step_deg: f64,
        /// Write every point as CSV.
        #[arg(long, value_name = "OUT")]
        csv: Option<PathBuf>,
        /// Write the table into docs/VALIDATION.md (between its markers).
        #[arg(long)]
        update_doc: bool,
        /// Only the bearings whose name contains this text (a case file name such as `fillon-a`, or a family
        /// group such as `3 pads,`); with --update-doc (shipped cases only) their rows of the table are
        /// replaced and the **all** row's counts moved by the difference.
        #[arg(long, value_name = "TEXT")]
        only: Option<String>,
        /// Only these points of the grid, `DIRECTION_DEG@S,…` (e.g. `65@0.1,200@0.1`); not with --update-doc.
        #[arg(long, value_name = "POINTS")]
        only_points: Option<String>,
        /// Project root (where `cases/` and `docs/` are).
        #[arg(long, default_value = ".")]
        root: PathBuf,
    },
}

/// `--step-deg`: a divisor of 360 between 1 and 90.
fn parse_step_deg(s: &str) -> std::result::Result<f64, String> {
    let v: f64 = s.parse().map_err(|e| format!("{e}"))?;
    let n = 360.0 / v;
    if !(1.0..=90.0).contains(&v) || (n - n.round()).abs() > 1e-9 {
        return Err(format!("--step-deg {v}: must divide 360 and lie in 1 … 90"));
    }
    Ok(v)
}

/// `--amplitude-v`: a finite positive voltage.
fn parse_amplitude(s: &str) -> std::result::Result<f64, String> {
    let v: f64 = s.trim().parse().map_err(|e| format!("`{s}` is not a number: {e}"))?;
    if !(v.is_finite() && v > 0.0) {
        return Err(format!("{v} V: the control amplitude must be a finite positive voltage"));
    }
    Ok(v)
}

/// The speeds of a rotor or control run and the bounds on them (refused before the first solve beyond
/// either).
#[derive(clap::Args, Debug)]
pub struct SpeedRange {
    /// Spin speeds, rpm: `FROM:TO:N` (N at most --max-points).
    #[arg(long, value_name = "FROM:TO:N")]
    pub speeds: String,
    /// Most speeds (refused before the first solve beyond it).
    #[arg(long, value_name = "N", default_value_t = inputs::DEFAULT_MAX_POINTS)]
    pub max_points: usize,
    /// Most estimated hours of work (speeds × bearing solves and eigen-solutions by the work model; refused
    /// before the first solve beyond it).
    #[arg(long, value_name = "H", default_value_t = DEFAULT_MAX_HOURS, value_parser = inputs::parse_hours)]
    pub max_hours: f64,
}
