//! `tiltpad rotor`: the rotor–bearing analysis over a speed range — damped natural frequencies, logarithmic
//! decrements and whirl directions per speed, the instability onset, the 1× critical speeds and the
//! unbalance response (with the API 617 limit) — as a summary, JSON (`--json`) and CSV (`--csv`, one row
//! per speed).

use crate::units::RPM;
use std::path::Path;
use std::path::PathBuf;

use anyhow::{bail, Context, Result};

use crate::io::read::read_rotor;
use crate::io::rotor_text::{csv_text, summary};
use crate::model::rotor::CoefficientModel;
use crate::rotor::analysis::{Analysis, AnalysisParams, Step, ONSET_PROBES};
use crate::study::estimate::Estimate;

use super::rows::announce;
use super::{is_stdout, write_atomic};

/// The highest speed of a `--speeds` range [rpm]: the top of `operating.speed_rpm`'s allowed range.
const MAX_SPEED_RPM: f64 = match crate::key!("operating.speed_rpm").allowed {
    crate::model::schema::Allowed::Number(range) => range.hi,
    _ => panic!("operating.speed_rpm: a number"),
};

/// Parses `FROM:TO:N` (rpm) into N speeds [rad/s].
///
/// # Errors
/// A malformed range.
pub fn parse_speeds(spec: &str, max_points: usize) -> Result<Vec<f64>> {
    let parts: Vec<&str> = spec.split(':').collect();
    let [a, b, n] = parts.as_slice() else { bail!("--speeds `{spec}`: expected FROM:TO:N in rpm") };
    let (a, b): (f64, f64) = (a.trim().parse().context("--speeds FROM")?, b.trim().parse().context("--speeds TO")?);
    let n: usize = n.trim().parse().context("--speeds N")?;
    if !(a.is_finite() && b.is_finite() && a >= 0.0 && b > a && n >= 2) {
        bail!("--speeds `{spec}`: needs 0 ≤ FROM < TO ≤ {MAX_SPEED_RPM} rpm and N ≥ 2");
    }
    if b > MAX_SPEED_RPM {
        bail!(
            "--speeds `{spec}`: TO = {b} rpm is above {MAX_SPEED_RPM} rpm, the highest speed a bearing case allows \
             (operating.speed_rpm)"
        );
    }
    super::inputs::check_points("--speeds", n, max_points)?;
    #[allow(clippy::cast_precision_loss)]
    Ok((0..n).map(|i| RPM.to_si(a + (b - a) * i as f64 / (n - 1) as f64)).collect())
}

/// Arguments of `tiltpad rotor`.
pub struct RotorArgs<'a> {
    pub rotor: &'a Path,
    pub speeds: &'a str,
    /// Most speeds.
    pub max_points: usize,
    /// Most estimated hours of work.
    pub max_hours: f64,
    pub coefficients: Option<CoefficientModel>,
    /// Shaft modes per plane (0: full shaft), overriding the file's `shaft_modes`.
    pub shaft_modes: Option<usize>,
    pub json: Option<PathBuf>,
    pub csv: Option<PathBuf>,
}

/// Runs the analysis and writes the outputs.
///
/// # Errors
/// Input, solve and I/O errors.
pub fn run(args: &RotorArgs<'_>) -> Result<()> {
    let mut rotor = read_rotor(args.rotor)?;
    if let Some(c) = args.coefficients {
        rotor.coefficients = c;
    }
    if let Some(m) = args.shaft_modes {
        rotor.shaft_modes = m;
    }
    let speeds = parse_speeds(args.speeds, args.max_points)?;
    let estimate = Estimate::rotor("rotor", &rotor, speeds.len(), ONSET_PROBES);
    super::inputs::check_work(&estimate, args.max_hours)?;
    let context = || format!("analysing {}", args.rotor.display());
    // One bearing solve and one eigen-solution per speed: a bar on standard error shows them go by, and the
    // heartbeat names the speed being solved when one takes long (a large full shaft).
    let mut pb = super::sweep::progress(speeds.len(), "speeds");
    let step = StepText::new(&estimate, &speeds);
    pb.set_message("shaft model");
    super::interrupt::doing(step.shaft());
    let mut analysis = Analysis::new(&rotor, AnalysisParams::new(speeds)).with_context(context)?;
    let of = analysis.speeds_to_do();
    let mut next = 0;
    loop {
        let text = step.speed(next);
        pb.set_message(text.clone());
        super::interrupt::doing(text);
        let Step::More { done, .. } = analysis.step().with_context(context)? else { break };
        next = done;
        pb.set_position(done as u64);
        if super::interrupt::requested() {
            analysis.stop();
            break;
        }
    }
    pb.set_message("onset and critical speeds");
    super::interrupt::doing(step.onset());
    let result = analysis.finish().with_context(context)?;
    super::interrupt::doing("");
    pb.finish_and_clear();
    let done = result.speeds.len();
    if done == 0 {
        return Err(super::interrupt::Interrupted::new(0, of, "speeds", &[]).into());
    }
    emit(args, &summary(&rotor, &result), &result, || Ok(csv_text(&result)?))?;
    stopped(done, of, args)
}

/// What a rotor run is doing, for its bar and its heartbeat: the speed and its work by the estimate.
pub(super) struct StepText {
    speeds_rpm: Vec<f64>,
    eigen: Option<crate::study::estimate::EigenWork>,
}

impl StepText {
    pub(super) fn new(estimate: &Estimate, speeds_rad_s: &[f64]) -> Self {
        Self { speeds_rpm: speeds_rad_s.iter().map(|&w| RPM.from_si(w)).collect(), eigen: estimate.eigen }
    }

    fn eigen_text(&self) -> String {
        self.eigen.map_or(String::new(), |e| {
            format!(
                " and an eigen-solution of {} states (about {} at the reference rate)",
                e.states,
                crate::study::estimate::duration_text(e.seconds_each)
            )
        })
    }

    /// Building the shaft model.
    pub(super) fn shaft(&self) -> String {
        let t = self.eigen.map_or(String::new(), |e| {
            format!(" (about {} at the reference rate)", crate::study::estimate::duration_text(e.shaft_seconds))
        });
        format!("shaft model{t}")
    }

    /// Speed `i` (from 0).
    pub(super) fn speed(&self, i: usize) -> String {
        let rpm = self.speeds_rpm.get(i).copied().unwrap_or(f64::NAN);
        format!("speed {} of {} ({rpm:.0} rpm): bearing solves{}", i + 1, self.speeds_rpm.len(), self.eigen_text())
    }

    /// The onset bisection and the critical speeds.
    pub(super) fn onset(&self) -> String {
        format!("onset bisection: up to {ONSET_PROBES} more speeds, each with bearing solves{}", self.eigen_text())
    }
}

/// The interruption, after the outputs of the speeds done were written (`Ok` when every speed was done).
///
/// # Errors
/// [`super::interrupt::Interrupted`] when fewer than `of` speeds were done.
fn stopped(done: usize, of: usize, args: &RotorArgs<'_>) -> Result<()> {
    if done < of {
        let outputs: Vec<&Path> = [args.json.as_deref(), args.csv.as_deref()].into_iter().flatten().collect();
        let outputs = if outputs.is_empty() { vec![Path::new("-")] } else { outputs };
        return Err(super::interrupt::Interrupted::new(done, of, "speeds", &outputs).into());
    }
    Ok(())
}

/// Prints the summary (to standard error when an output goes to standard output) and writes the JSON and
/// CSV outputs the arguments name.
///
/// # Errors
/// Serialisation and I/O errors.
pub(super) fn emit<T: serde::Serialize>(
    args: &RotorArgs<'_>,
    text: &str,
    json: &T,
    csv: impl FnOnce() -> Result<String>,
) -> Result<()> {
    if is_stdout(args.json.as_ref()) || is_stdout(args.csv.as_ref()) {
        eprint!("{text}");
    } else {
        print!("{text}");
    }
    if let Some(out) = &args.json {
        let mut s = serde_json::to_string_pretty(json)?;
        s.push('\n');
        write_atomic(out, s.as_bytes())?;
        announce(out);
    }
    if let Some(out) = &args.csv {
        write_atomic(out, csv()?.as_bytes())?;
        announce(out);
    }
    Ok(())
}
