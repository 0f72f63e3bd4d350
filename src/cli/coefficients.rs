//! `tiltpad coefficients`: reduced coefficients over running speed (a warm-started speed sweep, each point
//! condensed at the case's excitation ratio) or over excitation frequency at the case's speed (one solve,
//! the full matrices condensed at each ω), written for ROSS (`--ross`) and as CSV (`--csv`).

use std::path::{Path, PathBuf};

use anyhow::{bail, Context, Result};

use crate::bearing::solution::coefficients::reduce;
use crate::io::coefficients::{CoefficientTable, FrequencyMeaning};
use crate::io::write_file;
use crate::study::{Axis, Runner};

use super::rows::announce;
use super::sweep::progress;

/// Which frequencies and where the tables go.
pub struct CoefficientArgs<'a> {
    pub case: &'a Path,
    pub set: &'a [String],
    /// `FROM:TO:STEPS` or a list, rpm.
    pub speed_rpm: Option<&'a str>,
    /// `FROM:TO:STEPS` or a list of ω/Ω at the case's speed.
    pub excitation_ratio: Option<&'a str>,
    pub ross: Option<PathBuf>,
    pub csv: Option<PathBuf>,
    pub node: usize,
    pub tag: &'a str,
    /// Most speeds or ratios.
    pub max_points: usize,
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

fn empty_table(meaning: FrequencyMeaning) -> CoefficientTable {
    CoefficientTable {
        meaning,
        frequency_rad_s: vec![],
        speed_rpm: vec![],
        excitation_rad_s: vec![],
        k_n_per_m: vec![],
        c_ns_per_m: vec![],
    }
}

fn speed_table(runner: &mut Runner, speeds: &[f64]) -> Result<CoefficientTable> {
    let ratio = runner.case(&[])?.operating.excitation_ratio;
    let mut t = empty_table(FrequencyMeaning::RunningSpeed { excitation_ratio: ratio });
    let pb = progress(speeds.len());
    for &rpm in speeds {
        match runner.solve(&[("operating.speed_rpm".into(), format!("{rpm:?}"))]) {
            Ok(s) => {
                t.frequency_rad_s.push(s.derived.speed_rad_s);
                t.speed_rpm.push(rpm);
                t.excitation_rad_s.push(s.reduced.omega_rad_s);
                t.k_n_per_m.push(s.reduced.k_n_per_m);
                t.c_ns_per_m.push(s.reduced.c_ns_per_m);
            }
            Err(e) => pb.println(format!("{rpm} rpm left out: {e}")),
        }
        pb.inc(1);
    }
    pb.finish_and_clear();
    Ok(t)
}

fn excitation_table(runner: &mut Runner, ratios: &[f64]) -> Result<CoefficientTable> {
    let s = runner.solve(&[])?;
    let mut t = empty_table(FrequencyMeaning::Excitation);
    for &r in ratios {
        let omega = r * s.derived.speed_rad_s;
        let red = reduce(&s.full, omega);
        t.frequency_rad_s.push(omega);
        t.speed_rpm.push(s.derived.speed_rpm);
        t.excitation_rad_s.push(omega);
        t.k_n_per_m.push(red.k_n_per_m);
        t.c_ns_per_m.push(red.c_ns_per_m);
    }
    Ok(t)
}

/// Computes and writes the tables.
///
/// # Errors
/// Bad arguments, an invalid case, every point failed, or an output that cannot be written.
pub fn run(args: &CoefficientArgs<'_>) -> Result<()> {
    let text = super::inputs::read_text(args.case, "case file")?;
    let mut runner = Runner::new(text, args.set.to_vec(), true);
    let table = match (args.speed_rpm, args.excitation_ratio) {
        (Some(spec), None) => {
            speed_table(&mut runner, &numbers("--speed-rpm", spec, 0.0, "speeds [rpm]", args.max_points)?)?
        }
        (None, Some(spec)) => excitation_table(
            &mut runner,
            &numbers("--excitation-ratio", spec, 0.0, "excitation ratios ω/Ω", args.max_points)?,
        )?,
        (Some(_), Some(_)) => bail!("give --speed-rpm (a speed sweep) or --excitation-ratio (one speed), not both"),
        (None, None) => {
            let rpm = crate::units::RPM.from_si(runner.case(&[])?.operating.speed_rad_s);
            speed_table(&mut runner, &[rpm])?
        }
    };
    if table.frequency_rad_s.is_empty() {
        bail!("no point solved (each point's reason is printed above); nothing to write");
    }
    if args.ross.is_none() && args.csv.is_none() {
        print!("{}", table.csv());
    }
    if let Some(p) = &args.ross {
        write_file(p, table.ross_toml(args.node, args.tag, &args.case.display().to_string()).as_bytes())?;
        announce(p);
    }
    if let Some(p) = &args.csv {
        write_file(p, table.csv().as_bytes())?;
        announce(p);
    }
    Ok(())
}
