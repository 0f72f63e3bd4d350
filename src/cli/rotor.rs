//! `tiltpad rotor`: the rotor–bearing analysis over a speed range — damped natural frequencies, logarithmic
//! decrements and whirl directions per speed, the instability onset, the 1× critical speeds and the
//! unbalance response (with the API 617 limit) — as a summary, JSON (`--json`) and CSV (`--csv`, one row
//! per speed).

use crate::units::RPM;
use std::fmt::Write as _;
use std::path::Path;
use std::path::PathBuf;

use anyhow::{bail, Context, Result};

use crate::model::rotor::{parse_rotor_file, CoefficientModel, Rotor};
use crate::rotor::analysis::{Analysis, AnalysisParams, AnalysisResult, Step};
use crate::rotor::eigen::Whirl;
use crate::study::estimate::Estimate;

use super::rows::announce;
use super::{is_stdout, write_atomic};

/// The highest speed of a `--speeds` range [rpm]: the top of `operating.speed_rpm`'s allowed range.
const MAX_SPEED_RPM: f64 = match crate::key!("operating.speed_rpm").allowed {
    crate::model::schema::Allowed::Number(range) => range.hi,
    _ => panic!("operating.speed_rpm: a number"),
};

/// Speeds the onset bisection adds, at most, in the estimate (a relative bracket of 10⁻³ takes ten halvings).
pub(super) const ONSET_PROBES: usize = 12;

/// Modes written per speed in the CSV and the summary.
const MODES: usize = 6;

/// Reads a rotor file and the bearing cases it names (relative to it).
///
/// # Errors
/// I/O and validation errors, naming the file and the key.
pub fn read_rotor(path: &Path) -> Result<Rotor> {
    let text = super::inputs::read_text(path, "rotor file")?;
    let file = parse_rotor_file(&text).with_context(|| format!("invalid rotor file {}", path.display()))?;
    let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
    let read = |name: &str| super::inputs::read_text(&dir.join(name), "bearing case").map_err(|e| format!("{e:#}"));
    file.resolve(&read).with_context(|| format!("invalid rotor file {}", path.display()))
}

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

/// A rotor file: a uniform shaft of `elements` elements (four equal sections, `elements` a multiple of 4 up
/// to the file's 400) with one impeller and its unbalance at mid-span, on two bearings given by the case
/// `bearing` (an absolute path), analysed on the full shaft (`shaft_modes = 0`): the eigen-solutions are
/// most of its work (the bench of the estimates and the tests of its progress use it).
pub fn uniform_rotor(elements: usize, bearing: &Path) -> String {
    let section = elements / 4;
    let mut t = format!(
        "title = \"Uniform shaft, {elements} elements, full shaft (generated)\"\n\n[rotor]\nshaft_modes = 0\n\
         coefficients = \"full\"\n"
    );
    for _ in 0..4 {
        t.push_str(&format!(
            "\n[[rotor.section]]\nlength_mm = 300.0\nouter_diameter_mm = 101.6\nelements = {section}\n"
        ));
    }
    let (a, mid, b) = (elements / 20, elements / 2, elements - elements / 20);
    t.push_str(&format!(
        "\n[[rotor.disk]]\nnode = {mid}\nmass_kg = 46.0\npolar_inertia_kg_m2 = 0.92\ntransverse_inertia_kg_m2 = 0.47\n\
         \n[[rotor.unbalance]]\nnode = {mid}\namount_g_mm = 720.0\n"
    ));
    for node in [a, b] {
        t.push_str(&format!("\n[[rotor.bearing]]\nnode = {node}\ncase = {:?}\n", bearing.display().to_string()));
    }
    t
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
    emit(args, &summary(&rotor, &result), &result, || csv_text(&result))?;
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

fn whirl(w: Whirl) -> &'static str {
    match w {
        Whirl::Forward => "F",
        Whirl::Backward => "B",
    }
}

/// The human-readable summary.
#[must_use]
pub fn summary(rotor: &Rotor, r: &AnalysisResult) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "{}{}",
        r.title,
        if r.representative { "  [REPRESENTATIVE rotor: not all data published]" } else { "" }
    );
    let _ = writeln!(
        s,
        "{} elements, {:.1} kg, {} bearing(s), coefficients {:?}; shaft {}; system {} coordinates",
        rotor.elements.len(),
        rotor.mass(),
        rotor.bearings.len(),
        rotor.coefficients,
        if r.report.shaft_modes == 0 {
            "full".to_string()
        } else {
            format!("reduced to {} modes per plane", r.report.shaft_modes)
        },
        r.report.system_dofs
    );
    let _ = writeln!(
        s,
        "{} bearing solves, {} eigen-solutions, {:.2} s",
        r.report.bearing_solves, r.report.eigen_solutions, r.report.seconds
    );
    match r.onset {
        Some(o) => {
            let _ = writeln!(
                s,
                "instability onset: {:.0} rpm (± {:.0})",
                RPM.from_si(o.speed_rad_s),
                RPM.from_si(o.bracket_rad_s) / 2.0
            );
        }
        None => {
            let _ = writeln!(s, "instability onset: none in the sweep");
        }
    }
    for c in &r.critical_speeds {
        let _ = writeln!(
            s,
            "critical speed (1×, forward mode {}): {:.0} rpm, log dec {:.3}",
            c.rank + 1,
            RPM.from_si(c.speed_rad_s),
            c.log_dec
        );
    }
    for w in &r.report.warnings {
        let _ = writeln!(s, "warning: {w}");
    }
    let _ = writeln!(s, "{:>9}  modes: frequency [Hz] / log dec / whirl", "rpm");
    for p in &r.speeds {
        let _ = write!(s, "{:>9.0} ", RPM.from_si(p.point.speed_rad_s));
        for m in p.point.modes.modes.iter().take(MODES) {
            let _ = write!(s, " {:>8.2}/{:>7.3}/{}", m.frequency_hz(), m.log_dec, whirl(m.whirl));
        }
        let _ = writeln!(s);
    }
    s
}

/// One row per speed: modes, then the response at each response node and the API 617 limit.
///
/// # Errors
/// CSV writer errors.
pub fn csv_text(r: &AnalysisResult) -> Result<String> {
    let mut w = csv::Writer::from_writer(Vec::new());
    let mut head = vec!["speed_rpm".to_string(), "min_log_dec".to_string()];
    for i in 1..=MODES {
        head.extend([format!("mode{i}_hz"), format!("mode{i}_log_dec"), format!("mode{i}_whirl")]);
    }
    for n in &r.response_nodes {
        head.extend([format!("node{n}_pp_um"), format!("node{n}_x_phase_deg")]);
    }
    head.push("api617_limit_um".into());
    w.write_record(&head)?;
    for p in &r.speeds {
        let mut row = vec![format!("{}", RPM.from_si(p.point.speed_rad_s)), format!("{}", p.point.min_log_dec())];
        for i in 0..MODES {
            match p.point.modes.modes.get(i) {
                Some(m) => {
                    row.extend([format!("{}", m.frequency_hz()), format!("{}", m.log_dec), whirl(m.whirl).to_string()])
                }
                None => row.extend([String::new(), String::new(), String::new()]),
            }
        }
        for n in &r.response_nodes {
            match p.orbits.iter().find(|o| o.node == *n) {
                Some(o) => row.extend([format!("{}", o.major_pp_m * 1e6), format!("{}", o.x_phase_rad.to_degrees())]),
                None => row.extend([String::new(), String::new()]),
            }
        }
        row.push(if p.api617_limit_um.is_finite() { format!("{}", p.api617_limit_um) } else { String::new() });
        w.write_record(&row)?;
    }
    Ok(String::from_utf8(w.into_inner()?)?)
}
