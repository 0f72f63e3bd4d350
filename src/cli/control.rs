//! `tiltpad control`: the closed-loop analysis of a rotor file with a `[control]` section over a speed range
//! — the poles with the loop open and closed, the onset speed (and against the loop gain with
//! `--gain-sweep`), the Nyquist check and margins at each actuator's input, the unbalance response with and
//! without control and the valve signal and nozzle pressure amplitudes it needs (a warning where they leave
//! the valve's small-signal range) — as a summary, JSON (`--json`) and CSV (`--csv`, one row per speed).

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use anyhow::{bail, Context, Result};

use crate::control::analysis::{ControlAnalysis, ControlParams, ControlResult, GainOnset};
use crate::control::rig::{RigLoop, RigSweep};
use crate::io::read::read_controlled;
use crate::model::control::{parse_control_file, PlantInfo};
use crate::units::{BAR, KN, RPM, UM};

use super::rotor::parse_speeds;
use super::rows::announce;
use super::{is_stdout, write_atomic};

/// Closed-loop poles written per speed in the CSV and the summary.
const POLES: usize = 4;

/// Arguments of `tiltpad control`.
pub struct ControlArgs<'a> {
    pub rotor: &'a Path,
    pub speeds: &'a str,
    /// Most speeds (`--max-points`).
    pub max_points: usize,
    /// Most estimated hours of work (`--max-hours`).
    pub max_hours: f64,
    pub gain: Option<f64>,
    pub gain_sweep: Option<&'a str>,
    /// Speed of the root locus [rpm].
    pub root_locus_rpm: Option<f64>,
    pub json: Option<PathBuf>,
    /// Keep the Nyquist curves in the JSON.
    pub nyquist_curves: bool,
    pub csv: Option<PathBuf>,
    /// Onset against the gain, one row per gain.
    pub gain_csv: Option<PathBuf>,
    /// The root locus, one row per gain and pole.
    pub locus_csv: Option<PathBuf>,
}

/// Parses `G1,G2,…` or `FROM:TO:N` into gains.
///
/// # Errors
/// A malformed list.
pub fn parse_gains(spec: &str) -> Result<Vec<f64>> {
    let parts: Vec<&str> = spec.split(':').collect();
    let gains: Vec<f64> = if let [a, b, n] = parts.as_slice() {
        let (a, b): (f64, f64) = (a.trim().parse()?, b.trim().parse()?);
        let n: usize = n.trim().parse()?;
        if !(2..=1000).contains(&n) {
            bail!("--gain-sweep `{spec}`: needs 2 ≤ N ≤ 1000");
        }
        #[allow(clippy::cast_precision_loss)]
        (0..n).map(|i| a + (b - a) * i as f64 / (n - 1) as f64).collect()
    } else {
        spec.split(',').map(|g| g.trim().parse::<f64>()).collect::<Result<_, _>>()?
    };
    if gains.is_empty() || gains.iter().any(|g| !g.is_finite()) {
        bail!("--gain-sweep `{spec}`: expected finite gains G1,G2,… or FROM:TO:N");
    }
    Ok(gains)
}

/// Runs the analysis and writes the outputs.
///
/// # Errors
/// Input, solve and I/O errors.
pub fn run(args: &ControlArgs<'_>) -> Result<()> {
    let (rotor, mut control) = read_controlled(args.rotor)?;
    if let Some(g) = args.gain {
        if !g.is_finite() {
            bail!("--gain {g}: expected a finite number");
        }
        control.gain = g;
    }
    let mut params = ControlParams::new(parse_speeds(args.speeds, args.max_points)?);
    if let Some(spec) = args.gain_sweep {
        params.gains = parse_gains(spec)?;
    }
    if let Some(rpm) = args.root_locus_rpm {
        if !(rpm.is_finite() && rpm >= 0.0) {
            bail!("--root-locus {rpm}: expected a speed ≥ 0 rpm");
        }
        params.root_locus_rad_s = Some(RPM.to_si(rpm));
    }
    if args.gain_csv.is_some() && params.gains.is_empty() {
        bail!("--gain-csv needs --gain-sweep (the gains whose onsets it lists)");
    }
    if args.locus_csv.is_some() && params.root_locus_rad_s.is_none() {
        bail!("--locus-csv needs --root-locus RPM (the speed of the locus)");
    }
    let estimate = params.estimate(&rotor, &control);
    super::inputs::check_work(&estimate, args.max_hours)?;
    let context = || format!("analysing {}", args.rotor.display());
    // One bearing solve per bearing and speed: a bar on standard error shows them go by; Ctrl-C stops after
    // the speed being solved and writes the speeds done.
    let of = params.speeds_rad_s.len();
    let mut pb = super::sweep::progress(of, "speeds");
    let step = super::rotor::StepText::new(&estimate, &params.speeds_rad_s);
    pb.set_message("shaft and controller");
    super::interrupt::doing(step.shaft());
    let mut analysis = ControlAnalysis::new(&rotor, &control, params).with_context(context)?;
    pb.set_message("speeds");
    let mut done = 0;
    while !super::interrupt::requested() {
        super::interrupt::doing(step.speed(done));
        let finished = analysis.step().with_context(context)?;
        done = (done + 1).min(of);
        pb.set_position(done as u64);
        if finished {
            break;
        }
    }
    pb.set_message("onsets");
    if done == of {
        pb.println("onsets: bisecting the stability onsets (Ctrl-C stops them and keeps the speeds)");
    }
    // Ctrl-C during the onset bisections stops them (each onset left is the middle of its bracket, with a
    // warning); the speeds solved are written as after an interruption of the sweep.
    super::interrupt::doing(step.onset());
    let mut result = analysis.finish_until(&super::interrupt::Interrupt).with_context(context)?;
    super::interrupt::doing("");
    pb.finish_and_clear();
    let done = result.speeds.len();
    if done == 0 {
        return Err(super::interrupt::Interrupted::new(0, of, "speeds", &[]).into());
    }
    if !args.nyquist_curves {
        for s in &mut result.speeds {
            for l in &mut s.loops {
                l.curve.clear();
            }
        }
    }
    let text = summary(&result);
    if is_stdout(args.json.as_ref()) || is_stdout(args.csv.as_ref()) {
        eprint!("{text}");
    } else {
        print!("{text}");
    }
    if let Some(out) = &args.json {
        let mut s = serde_json::to_string(&result)?;
        s.push('\n');
        write_atomic(out, s.as_bytes())?;
        announce(out);
    }
    if let Some(out) = &args.csv {
        write_atomic(out, csv_text(&result)?.as_bytes())?;
        announce(out);
    }
    if let Some(out) = &args.gain_csv {
        write_atomic(out, gain_csv_text(&result)?.as_bytes())?;
        announce(out);
    }
    if let Some(out) = &args.locus_csv {
        write_atomic(out, locus_csv_text(&result)?.as_bytes())?;
        announce(out);
    }
    if done < of || super::interrupt::requested() {
        let outputs: Vec<&Path> = [args.json.as_deref(), args.csv.as_deref()].into_iter().flatten().collect();
        let outputs = if outputs.is_empty() { vec![Path::new("-")] } else { outputs };
        let what = if done < of { "speeds" } else { "speeds (onsets not refined)" };
        return Err(super::interrupt::Interrupted::new(done, of, what, &outputs).into());
    }
    Ok(())
}

/// Onset against the loop gain: one row per gain of the sweep (`onset_rpm` empty: none in the speed range;
/// `stable_at_first_speed` false: the onset lies below it).
///
/// # Errors
/// CSV writer errors.
pub fn gain_csv_text(r: &ControlResult) -> Result<String> {
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record(["gain", "onset_rpm", "stable_at_first_speed"])?;
    for g in &r.gain_sweep {
        w.write_record([
            format!("{}", g.gain),
            g.onset_rad_s.map_or(String::new(), |x| format!("{}", RPM.from_si(x))),
            g.stable_at_first.to_string(),
        ])?;
    }
    Ok(String::from_utf8(w.into_inner()?)?)
}

/// The root locus: one row per gain and pole (oscillatory poles once, with their frequency; real poles with
/// frequency 0).
///
/// # Errors
/// CSV writer errors.
pub fn locus_csv_text(r: &ControlResult) -> Result<String> {
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record(["speed_rpm", "gain", "real_per_s", "frequency_hz", "log_dec"])?;
    if let Some(l) = &r.root_locus {
        let rpm = format!("{}", RPM.from_si(l.speed_rad_s));
        for (g, poles) in l.gains.iter().zip(&l.poles) {
            for p in poles {
                let im = p[1] * std::f64::consts::TAU;
                let log_dec = if im > 0.0 { format!("{}", -std::f64::consts::TAU * p[0] / im) } else { String::new() };
                w.write_record([rpm.clone(), format!("{g}"), format!("{}", p[0]), format!("{}", p[1]), log_dec])?;
            }
        }
    }
    Ok(String::from_utf8(w.into_inner()?)?)
}

fn onset_text(o: &GainOnset) -> String {
    match o.onset_rad_s {
        Some(w) => format!("{:.0} rpm", RPM.from_si(w)),
        None if o.stable_at_first => "none in the sweep (stable throughout)".into(),
        None => "below the sweep (unstable from its first speed)".into(),
    }
}

/// Largest major axis over the response nodes [m], open and closed, and the speed of each [rad/s].
#[must_use]
pub fn peaks(r: &ControlResult) -> ((f64, f64), (f64, f64)) {
    let mut open = (0.0, 0.0);
    let mut closed = (0.0, 0.0);
    for s in &r.speeds {
        if let Some(resp) = &s.response {
            for o in &resp.open {
                if o.major_pp_m > open.0 {
                    open = (o.major_pp_m, s.speed_rad_s);
                }
            }
            for o in &resp.closed {
                if o.major_pp_m > closed.0 {
                    closed = (o.major_pp_m, s.speed_rad_s);
                }
            }
        }
    }
    (open, closed)
}

/// The human-readable summary.
#[must_use]
pub fn summary(r: &ControlResult) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "{}", r.title);
    let _ = writeln!(
        s,
        "loop gain {}; closed loop {} states; {} bearing solves, {} eigen-solutions, {:.2} s",
        r.gain, r.states, r.bearing_solves, r.eigen_solutions, r.seconds
    );
    if let Some(d) = &r.lqr {
        let _ = writeln!(
            s,
            "LQR designed at {:.0} rpm on a reduced model of {} states (of {}; modes at {} Hz)",
            RPM.from_si(d.design_speed_rad_s),
            d.reduced_states,
            d.full_states,
            d.kept_hz.iter().map(|f| format!("{f:.1}")).collect::<Vec<_>>().join(", ")
        );
        let poles = |p: &[(f64, f64)]| {
            p.iter()
                .filter(|z| z.1 > 0.0)
                .map(|z| format!("{:.1} Hz ζ {:.3}", z.1 / std::f64::consts::TAU, -z.0 / z.0.hypot(z.1)))
                .collect::<Vec<_>>()
                .join(", ")
        };
        let _ = writeln!(s, "  regulator poles (reduced model): {}", poles(&d.regulator_poles));
        let _ = writeln!(s, "  observer poles (reduced model): {}", poles(&d.observer_poles));
    }
    let _ = writeln!(s, "instability onset, loop open: {}", onset_text(&r.onset_open));
    let _ = writeln!(s, "instability onset, loop closed: {}", onset_text(&r.onset_closed));
    for g in &r.gain_sweep {
        let _ = writeln!(s, "  gain {:>8.3}: onset {}", g.gain, onset_text(g));
    }
    if let Some(l) = &r.root_locus {
        let _ = writeln!(
            s,
            "root locus at {:.0} rpm: {} gains from {} to {}, poles up to {} Hz",
            RPM.from_si(l.speed_rad_s),
            l.gains.len(),
            l.gains.first().copied().unwrap_or(0.0),
            l.gains.last().copied().unwrap_or(0.0),
            l.max_hz
        );
    }
    let ((po, wo), (pc, wc)) = peaks(r);
    if po > 0.0 {
        let _ = writeln!(
            s,
            "unbalance response peak: open {:.2} µm pp at {:.0} rpm, closed {:.2} µm pp at {:.0} rpm",
            UM.from_si(po),
            RPM.from_si(wo),
            UM.from_si(pc),
            RPM.from_si(wc)
        );
    }
    for (a, limit) in r.limit_v.iter().enumerate() {
        let most = r.speeds.iter().filter_map(|p| p.response.as_ref().map(|x| x.signal_v[a])).fold(0.0, f64::max);
        let _ = writeln!(s, "actuator {a}: largest signal {most:.4} V (linear range {limit:.3} V)");
    }
    for w in &r.warnings {
        let _ = writeln!(s, "warning: {w}");
    }
    let _ = writeln!(
        s,
        "{:>9}  min log dec open / closed | Nyquist (per actuator: stable, GM, PM) | closed-loop poles [Hz]/log dec",
        "rpm"
    );
    for p in &r.speeds {
        let _ = write!(
            s,
            "{:>9.0}  {:>7.3} / {:>7.3} |",
            RPM.from_si(p.speed_rad_s),
            p.open.min_log_dec(),
            p.closed.min_log_dec()
        );
        for n in &p.loops {
            let gm = n.gain_margin.map_or("—".to_string(), |g| format!("{:.1} dB", 20.0 * g.log10()));
            let pm = n.phase_margin_deg.map_or("—".to_string(), |p| format!("{p:.0}°"));
            let _ = write!(s, " {} {gm} {pm} |", if n.stable() { "S" } else { "U" });
        }
        for m in p.closed.modes.iter().take(POLES) {
            let _ = write!(s, " {:>7.2}/{:>6.3}", m.frequency_hz(), m.log_dec);
        }
        let _ = writeln!(s);
    }
    s
}

/// One row per speed.
///
/// # Errors
/// CSV writer errors.
pub fn csv_text(r: &ControlResult) -> Result<String> {
    let mut w = csv::Writer::from_writer(Vec::new());
    let mut head = vec!["speed_rpm".to_string(), "open_min_log_dec".into(), "closed_min_log_dec".into()];
    for i in 1..=POLES {
        head.extend([format!("pole{i}_hz"), format!("pole{i}_log_dec")]);
    }
    let actuators = r.limit_v.len();
    for a in 0..actuators {
        head.extend([
            format!("loop{a}_nyquist_stable"),
            format!("loop{a}_gain_margin_db"),
            format!("loop{a}_phase_margin_deg"),
            format!("actuator{a}_signal_v"),
            format!("actuator{a}_nozzle_pressure_bar"),
        ]);
    }
    for n in &r.response_nodes {
        head.extend([format!("node{n}_open_pp_um"), format!("node{n}_closed_pp_um")]);
    }
    head.push("api617_limit_um".into());
    w.write_record(&head)?;
    let num = |v: Option<f64>| v.map_or(String::new(), |x| format!("{x}"));
    for p in &r.speeds {
        let mut row = vec![
            format!("{}", RPM.from_si(p.speed_rad_s)),
            format!("{}", p.open.min_log_dec()),
            format!("{}", p.closed.min_log_dec()),
        ];
        for i in 0..POLES {
            let m = p.closed.modes.get(i);
            row.extend([num(m.map(super::super::control::closed_loop::Pole::frequency_hz)), num(m.map(|m| m.log_dec))]);
        }
        for a in 0..actuators {
            let n = p.loops.get(a);
            row.push(n.map_or(String::new(), |n| n.stable().to_string()));
            row.push(num(n.and_then(|n| n.gain_margin).map(|g| 20.0 * g.log10())));
            row.push(num(n.and_then(|n| n.phase_margin_deg)));
            let resp = p.response.as_ref();
            row.push(num(resp.map(|x| x.signal_v[a])));
            row.push(num(resp
                .and_then(|x| x.nozzle_pressure_pa[a].iter().copied().reduce(f64::max))
                .map(|v| BAR.from_si(v))));
        }
        for n in &r.response_nodes {
            let find = |v: &[crate::rotor::unbalance::Orbit]| {
                v.iter().find(|o| o.node == *n).map(|o| UM.from_si(o.major_pp_m))
            };
            row.push(num(p.response.as_ref().and_then(|x| find(&x.open))));
            row.push(num(p.response.as_ref().and_then(|x| find(&x.closed))));
        }
        row.push(if p.api617_limit_um.is_finite() { format!("{}", p.api617_limit_um) } else { String::new() });
        w.write_record(&row)?;
    }
    Ok(String::from_utf8(w.into_inner()?)?)
}

/// The rig's loop closed by a controller file: X/F open and closed over the band, the loop's stability.
#[derive(Debug, Clone, serde::Serialize)]
pub struct RigLoopRows {
    pub controller: String,
    #[serde(flatten)]
    pub sweep: RigSweep,
}

/// Closes the rig's loop of `case` (its FRF `model`) with the controller file at `path`; prints a summary
/// (stability, X/F peaks open and closed, the valve signal per force against the small-signal range).
///
/// # Errors
/// An unreadable or invalid controller file (naming the key), a controller that is not the rig's loop.
pub fn rig_loop(
    path: &Path,
    case: &crate::model::Case,
    model: &crate::bearing::frf::model::FrfModel,
    freqs: &[f64],
) -> Result<RigLoopRows> {
    let text =
        std::fs::read_to_string(path).with_context(|| format!("cannot read controller file {}", path.display()))?;
    let file = parse_control_file(&text).with_context(|| format!("invalid controller file {}", path.display()))?;
    let control = file
        .control
        .resolve(&PlantInfo::rig(case))
        .with_context(|| format!("invalid controller file {}", path.display()))?;
    let rig = RigLoop::new(case, model, &control).with_context(|| format!("closing the loop of {}", path.display()))?;
    let sweep = rig.sweep(freqs)?;
    let ((open, fo), (closed, fc)) = (sweep.peak(false), sweep.peak(true));
    let signal = sweep.signal_v_per_n();
    let limit_v = sweep.limit_v;
    let per_kn = |x: f64| UM.from_si(x * KN.to_si(1.0));
    eprintln!(
        "rig loop ({}, gain {}): {}, smallest log dec {:.3}; X/F peak open {:.3} µm/kN at {fo:.1} Hz, closed {:.3} µm/kN at \
         {fc:.1} Hz; valve signal up to {:.4} V/kN: the small-signal range ({limit_v:.2} V) holds to {:.0} N of shaker force",
        path.display(),
        control.gain,
        if sweep.stable { "stable" } else { "UNSTABLE" },
        sweep.min_log_dec,
        per_kn(open),
        per_kn(closed),
        signal * KN.to_si(1.0),
        if signal > 0.0 { limit_v / signal } else { f64::INFINITY }
    );
    Ok(RigLoopRows { controller: path.display().to_string(), sweep })
}

/// One row per frequency: X/F open and closed [µm/kN, deg], the valve signal per force [V/kN].
///
/// # Errors
/// CSV writer errors.
pub fn rig_loop_csv(l: &RigLoopRows) -> Result<String> {
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record([
        "frequency_hz",
        "open_um_per_kn",
        "open_phase_deg",
        "closed_um_per_kn",
        "closed_phase_deg",
        "signal_v_per_kn",
    ])?;
    let per_kn = |x: f64| UM.from_si(x * KN.to_si(1.0));
    for p in &l.sweep.points {
        w.write_record([
            format!("{}", p.frequency_hz),
            format!("{}", per_kn(p.open_m_per_n)),
            format!("{}", p.open_phase_deg),
            format!("{}", per_kn(p.closed_m_per_n)),
            format!("{}", p.closed_phase_deg),
            format!("{}", p.signal_v_per_n * KN.to_si(1.0)),
        ])?;
    }
    Ok(String::from_utf8(w.into_inner()?)?)
}
