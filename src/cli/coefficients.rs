//! `tiltpad coefficients`: reduced coefficients over running speed (a warm-started speed sweep, each point
//! condensed at the case's excitation ratio) or over excitation frequency at the case's speed (one solve,
//! the full matrices condensed at each ω), written for ROSS (`--ross`, one bearing element per `--node`) and
//! as CSV (`--csv`).
//!
//! For ROSS the speed band is refined where its spline would miss the coefficients (a pad starting to float)
//! and checked ([`crate::study::band`]): warnings on standard error say where the coefficients jump between
//! samples and when the band does not cover `--analysis-rpm`, the speed range of the rotor analysis. The
//! Python package's `tiltpad.ross.bearing_element` samples through the same code, so both give the same
//! elements.

use std::path::PathBuf;

use anyhow::{bail, Context, Result};

use crate::bearing::SolveError;
use crate::io::coefficients::CoefficientTable;
use crate::io::write_file;
use crate::study::band::{self, Band, BandParams, BandWarning, Sample};
use crate::study::estimate::{point_cost, Estimate};
use crate::study::{Axis, PointError, Runner};

use super::interrupt::{self, Interrupt, Interrupted};
use super::rows::announce;
use super::sweep::progress;

/// `tiltpad coefficients` arguments.
#[derive(Debug, clap::Args)]
pub struct CoefficientArgs {
    /// Case file (TOML).
    pub case: PathBuf,
    /// Override a case value, e.g. `--set operating.speed_rpm=3000` (repeatable).
    #[arg(long = "set", value_name = "KEY=VALUE")]
    pub set: Vec<String>,
    /// Running speeds, rpm: `FROM:TO:STEPS` or a list (each condensed at the case's excitation ratio).
    #[arg(long, value_name = "RPM")]
    pub speed_rpm: Option<String>,
    /// Excitation ratios ω/Ω at the case's speed: `FROM:TO:STEPS` or a list (frequency-dependent
    /// coefficients).
    #[arg(long, value_name = "RATIOS")]
    pub excitation_ratio: Option<String>,
    /// ROSS bearing-element file (TOML, `ross.BearingElement.load` reads it; one element per `--node`).
    #[arg(long, value_name = "OUT.toml")]
    pub ross: Option<PathBuf>,
    /// CSV with units in the header (`-`: standard output; the default without --ross).
    #[arg(long, value_name = "OUT")]
    pub csv: Option<PathBuf>,
    /// Rotor node of the bearing in the ROSS model; several (`--node 3 --node 12` or `--node 3,12`) write one
    /// bearing element per node with the same coefficients.
    #[arg(long, value_delimiter = ',', default_value = "0")]
    pub node: Vec<usize>,
    /// Tag of the ROSS element: one, or one per node (a single tag for several nodes becomes `TAG_<node>`).
    #[arg(long, value_delimiter = ',', default_value = "tiltpad")]
    pub tag: Vec<String>,
    /// Speed range of the rotor analysis the elements serve, rpm (`FROM:TO`): a warning when the sampled
    /// band does not cover it (ROSS extrapolates its spline outside the band).
    #[arg(long, value_name = "FROM:TO")]
    pub analysis_rpm: Option<String>,
    /// Write exactly the requested speeds for ROSS: no refinement where the spline misses the
    /// coefficients (the jump warnings still apply).
    #[arg(long)]
    pub no_refine: bool,
    /// Most speeds or ratios (refused before the first solve beyond it).
    #[arg(long, value_name = "N", default_value_t = super::inputs::DEFAULT_MAX_POINTS)]
    pub max_points: usize,
    /// Most estimated hours of work (solves × the work model's time per solve; refused before the first
    /// solve beyond it).
    #[arg(
        long,
        value_name = "H",
        default_value_t = crate::study::estimate::DEFAULT_MAX_HOURS,
        value_parser = super::inputs::parse_hours
    )]
    pub max_hours: f64,
}

/// The numbers of `--flag spec` (a range or a list), each finite and at least `min` (`what`: their meaning),
/// at most `max_points` of them.
fn numbers(flag: &str, spec: &str, min: f64, what: &str, max_points: usize) -> Result<Vec<f64>> {
    let axis = Axis::parse(&format!("{flag}={spec}"))?;
    super::inputs::check_points(flag, axis.values.len(), max_points)?;
    let values: Vec<f64> = axis
        .values
        .iter()
        .map(|v| v.parse::<f64>().with_context(|| format!("{flag} {spec}: `{v}` is not a number")))
        .collect::<Result<_>>()?;
    if let Some(v) = values.iter().find(|v| !(v.is_finite() && **v >= min)) {
        bail!("{flag} {spec}: {v} is not allowed; {what} must be finite and at least {min}");
    }
    Ok(values)
}

/// `FROM:TO` in rpm.
fn range_rpm(spec: &str) -> Result<[f64; 2]> {
    let (a, b) = spec.split_once(':').with_context(|| format!("--analysis-rpm `{spec}`: expected FROM:TO"))?;
    let (a, b): (f64, f64) = (
        a.trim().parse().with_context(|| format!("--analysis-rpm `{spec}`: FROM"))?,
        b.trim().parse().with_context(|| format!("--analysis-rpm `{spec}`: TO"))?,
    );
    if !(a.is_finite() && b.is_finite() && 0.0 <= a && a <= b) {
        bail!("--analysis-rpm `{spec}`: needs 0 ≤ FROM ≤ TO");
    }
    Ok([a, b])
}

/// The `(node, tag)` of every element: one tag per node, or one tag for all (then suffixed with the node).
fn elements(nodes: &[usize], tags: &[String]) -> Result<Vec<(usize, String)>> {
    match (nodes.len(), tags.len()) {
        (_, 1) if nodes.len() == 1 => Ok(vec![(nodes[0], tags[0].clone())]),
        (_, 1) => Ok(nodes.iter().map(|n| (*n, format!("{}_{n}", tags[0]))).collect()),
        (n, t) if n == t => Ok(nodes.iter().copied().zip(tags.iter().cloned()).collect()),
        (n, t) => bail!("{t} tags for {n} nodes: give one tag, or one per node"),
    }
}

/// The band over `speeds` [rpm], refined for ROSS unless `refine` is off, with its warnings. On Ctrl-C: the
/// samples solved so far, in speed order, and the interruption (the caller writes them, then reports it).
fn speed_table(
    runner: &mut Runner,
    speeds: &[f64],
    refine: bool,
    analysis_rpm: Option<[f64; 2]>,
) -> Result<(CoefficientTable, Vec<BandWarning>, Option<Interrupted>)> {
    let ratio = runner.case(&[])?.operating.excitation_ratio;
    let params = BandParams { refine, analysis_rpm, ..BandParams::default() };
    let mut pb = progress(speeds.len(), "speeds");
    let mut solves = 0;
    let mut solved: Vec<Sample> = Vec::new();
    let most = params.max_samples.max(speeds.len());
    let result = band::sample(speeds, &params, &mut |rpm| {
        if interrupt::requested() {
            return Err(PointError::Solve(SolveError::Cancelled));
        }
        solves += 1;
        // Refinement adds speeds until the cubic fits: count against its bound (not against the speeds done,
        // which read "29/29" as if the band were finishing).
        if solves == speeds.len() + 1 {
            pb.inc_length((most - speeds.len()) as u64);
        }
        if solves > speeds.len() {
            pb.set_message(format!(
                "{rpm:.0} rpm (refining the band for ROSS's spline: at most {most} speeds, usually far fewer)"
            ));
        } else {
            pb.set_message(format!("{rpm:.0} rpm"));
        }
        let s = band::solve_point(runner, rpm, &Interrupt);
        if let Ok(sample) = &s {
            solved.push(sample.clone());
        }
        pb.inc(1);
        s
    });
    pb.finish_and_clear();
    match result {
        Ok(band) => Ok((CoefficientTable::of_band(&band, ratio), band.warnings, None)),
        Err(PointError::Solve(SolveError::Cancelled)) => {
            solved.sort_by(|a, b| a.speed_rpm.total_cmp(&b.speed_rpm));
            let done = solved.len();
            let band = Band { samples: solved, warnings: Vec::new(), solves };
            let stop = Interrupted::new(done, speeds.len().max(done), "speeds", &[]);
            Ok((CoefficientTable::of_band(&band, ratio), Vec::new(), Some(stop)))
        }
        Err(e) => Err(e.into()),
    }
}

fn excitation_table(runner: &mut Runner, ratios: &[f64]) -> Result<CoefficientTable> {
    match runner.solve_with(&[], &Interrupt) {
        Ok(s) => Ok(CoefficientTable::of_excitation(&s, ratios)),
        Err(PointError::Solve(SolveError::Cancelled)) => Err(Interrupted::new(0, 1, "solves", &[]).into()),
        Err(e) => Err(e.into()),
    }
}

/// Computes and writes the tables.
///
/// # Errors
/// Bad arguments, an invalid case, every point failed, or an output that cannot be written.
pub fn run(args: &CoefficientArgs) -> Result<()> {
    let elements = elements(&args.node, &args.tag)?;
    let analysis = args.analysis_rpm.as_deref().map(range_rpm).transpose()?;
    let mut runner = band::cold_runner(crate::io::read::read_text(&args.case, "case file")?, args.set.clone());
    // Refinement serves ROSS's spline; a CSV alone keeps exactly the requested speeds.
    let refine = args.ross.is_some() && !args.no_refine;
    let (table, warnings, stop) = match (&args.speed_rpm, &args.excitation_ratio) {
        (Some(spec), None) => {
            let speeds = numbers("--speed-rpm", spec, 0.0, "speeds [rpm]", args.max_points)?;
            // Refinement adds samples up to the band's budget.
            let solves = if refine { speeds.len().max(BandParams::default().max_samples) } else { speeds.len() };
            let cost = point_cost(&runner.case(&[])?);
            super::inputs::check_work(&Estimate::points("coefficients", solves, cost), args.max_hours)?;
            speed_table(&mut runner, &speeds, refine, analysis)?
        }
        (None, Some(spec)) => {
            if analysis.is_some() {
                bail!("--analysis-rpm checks a speed band: give it with --speed-rpm");
            }
            // one bearing solve at the case's speed (the frequencies reuse its coefficients)
            let cost = point_cost(&runner.case(&[])?);
            super::inputs::check_work(&Estimate::points("coefficients", 1, cost), args.max_hours)?;
            (
                excitation_table(
                    &mut runner,
                    &numbers("--excitation-ratio", spec, 0.0, "excitation ratios ω/Ω", args.max_points)?,
                )?,
                Vec::new(),
                None,
            )
        }
        (Some(_), Some(_)) => bail!("give --speed-rpm (a speed sweep) or --excitation-ratio (one speed), not both"),
        (None, None) => {
            let case = runner.case(&[])?;
            super::inputs::check_work(&Estimate::points("coefficients", 1, point_cost(&case)), args.max_hours)?;
            let rpm = crate::units::RPM.from_si(case.operating.speed_rad_s);
            speed_table(&mut runner, &[rpm], false, analysis)?
        }
    };
    for w in &warnings {
        eprintln!("warning: {w}");
    }
    if let (Some(stop), true) = (&stop, table.frequency_rad_s.is_empty()) {
        bail!("{stop}");
    }
    if table.frequency_rad_s.is_empty() {
        bail!("no point solved (each point's reason is printed above); nothing to write");
    }
    if args.ross.is_none() && args.csv.is_none() {
        print!("{}", table.csv());
    }
    if let Some(p) = &args.ross {
        write_file(p, table.ross_toml_elements(&elements, &args.case.display().to_string()).as_bytes())?;
        announce(p);
    }
    if let Some(p) = &args.csv {
        write_file(p, table.csv().as_bytes())?;
        announce(p);
    }
    if let Some(stop) = stop {
        let stdout = std::path::Path::new("-");
        let outputs: Vec<&std::path::Path> =
            [args.ross.as_deref(), args.csv.as_deref()].into_iter().flatten().collect();
        let outputs = if outputs.is_empty() { vec![stdout] } else { outputs };
        return Err(Interrupted::new(stop.done, stop.of, stop.what, &outputs).into());
    }
    Ok(())
}
