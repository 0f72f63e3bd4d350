//! `tiltpad rotor ROTOR.toml --critical-map`: the undamped critical-speed map (critical speeds against a
//! support stiffness at the bearings, [`crate::rotor::critical_map`]), the bearings' direct stiffnesses over
//! the `--speeds` and where they cross the mode lines — as a summary, JSON (`--json`) and CSV (`--csv`, long
//! form: one row per point of a series `modeN`, `bearingB_kxx`, `bearingB_kyy` or `crossing`, with its
//! stiffness [N/m] and speed [rpm]).

use crate::units::RPM;
use std::fmt::Write as _;
use std::path::Path;

use anyhow::{Context, Result};

use crate::io::read::read_rotor;
use crate::rotor::critical_map::{CriticalMapRun, CriticalSpeedMap, MapStep, MAP_POINTS};

use super::rotor::{emit, parse_speeds, RotorArgs};

/// Modes drawn.
const MODES: usize = 4;

/// Runs the map and writes the outputs. The bearings' speeds, then the map's eigen-solutions, go by on the
/// progress display (and the heartbeat, with how many are done); Ctrl-C stops at the next step, and what is
/// done is written (the curves of the speeds solved, the map up to the stiffness reached) before the
/// command says where and exits with status 130.
///
/// # Errors
/// Input, solve and I/O errors; [`super::interrupt::Interrupted`] after Ctrl-C.
pub fn run(args: &RotorArgs<'_>) -> Result<()> {
    let rotor = read_rotor(args.rotor)?;
    let speeds = parse_speeds(args.speeds, args.max_points)?;
    let estimate = crate::study::estimate::Estimate::critical_map(&rotor, speeds.len(), MAP_POINTS);
    super::inputs::check_work(&estimate, args.max_hours)?;
    let each = estimate
        .eigen
        .map_or(String::new(), |e| format!(", {} each", crate::study::estimate::duration_text(e.seconds_each)));
    let of_speeds = speeds.len();
    let context = || format!("critical-speed map of {}", args.rotor.display());
    let mut run = CriticalMapRun::new(&rotor, speeds, MAP_POINTS, MODES);
    let mut pb = super::sweep::progress(of_speeds, "speeds");
    super::interrupt::doing(format!(
        "critical-speed map: bearing stiffness at {of_speeds} speeds, then {MAP_POINTS} undamped eigen-solutions of the \
         shaft{each} (about {} in all by the estimate)",
        crate::study::estimate::duration_text(estimate.seconds)
    ));
    while !super::interrupt::requested() {
        match run.step().with_context(context)? {
            MapStep::Speed { done, .. } => pb.set_position(done as u64),
            MapStep::Stiffness { done: 0, of } => {
                pb.finish_and_clear();
                pb = super::sweep::progress(of, "eigen-solutions");
                pb.set_message("undamped eigen-solutions");
                super::interrupt::doing(format!(
                    "critical-speed map: {of} undamped eigen-solutions of the shaft{each}"
                ));
            }
            MapStep::Stiffness { done, .. } => pb.set_position(done as u64),
            MapStep::Done => break,
        }
    }
    pb.finish_and_clear();
    super::interrupt::doing("");
    let (speeds_done, stiffnesses) = (run.speeds_done(), run.stiffnesses_done());
    let map = run.finish();
    if speeds_done == 0 {
        return Err(super::interrupt::Interrupted::new(0, of_speeds, "speeds", &[]).into());
    }
    emit(args, &summary(&map), &map, || csv_text(&map))?;
    if super::interrupt::requested() && stiffnesses < MAP_POINTS {
        let outputs: Vec<&Path> = [args.json.as_deref(), args.csv.as_deref()].into_iter().flatten().collect();
        let outputs = if outputs.is_empty() { vec![Path::new("-")] } else { outputs };
        let stop = if speeds_done < of_speeds {
            super::interrupt::Interrupted::new(speeds_done, of_speeds, "speeds", &outputs)
        } else {
            super::interrupt::Interrupted::new(stiffnesses, MAP_POINTS, "eigen-solutions", &outputs)
        };
        return Err(stop.into());
    }
    Ok(())
}

fn direction(d: usize) -> &'static str {
    if d == 0 {
        "kxx"
    } else {
        "kyy"
    }
}

/// The human-readable summary: the map's range and the crossings.
#[must_use]
pub fn summary(m: &CriticalSpeedMap) -> String {
    let mut s = String::new();
    let ks = &m.map.stiffness_n_per_m;
    match (ks.first(), ks.last()) {
        (Some(lo), Some(hi)) if ks.len() >= 2 => {
            let _ = writeln!(
                s,
                "undamped critical-speed map: {} stiffnesses {lo:.2e}–{hi:.2e} N/m at the bearings, {MODES} modes",
                ks.len(),
            );
        }
        // stopped (Ctrl-C) before the map had a line to draw: the bearings' curves only
        _ => {
            let speeds = m.bearing_curves.iter().map(Vec::len).max().unwrap_or(0);
            let _ =
                writeln!(s, "undamped critical-speed map: not computed; the bearings' stiffness at {speeds} speeds");
        }
    }
    if m.crossings.is_empty() {
        let _ = writeln!(s, "no bearing curve crosses a mode line over the speeds");
    }
    for c in &m.crossings {
        let _ = writeln!(
            s,
            "mode {} × bearing {} {}: {:.0} rpm at {:.3e} N/m",
            c.mode + 1,
            c.bearing,
            direction(c.direction),
            RPM.from_si(c.speed_rad_s),
            c.stiffness_n_per_m
        );
    }
    s
}

/// Long-form CSV: `series,stiffness_n_per_m,speed_rpm`.
///
/// # Errors
/// CSV writer errors.
pub fn csv_text(m: &CriticalSpeedMap) -> Result<String> {
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record(["series", "stiffness_n_per_m", "speed_rpm"])?;
    for mode in 0..MODES {
        for (k, f) in m.map.stiffness_n_per_m.iter().zip(&m.map.frequencies_rad_s) {
            if let Some(w_rad_s) = f.get(mode) {
                w.write_record([format!("mode{}", mode + 1), format!("{k}"), format!("{}", RPM.from_si(*w_rad_s))])?;
            }
        }
    }
    for (b, curve) in m.bearing_curves.iter().enumerate() {
        for d in 0..2 {
            for p in curve {
                w.write_record([
                    format!("bearing{b}_{}", direction(d)),
                    format!("{}", if d == 0 { p.1 } else { p.2 }),
                    format!("{}", RPM.from_si(p.0)),
                ])?;
            }
        }
    }
    for c in &m.crossings {
        w.write_record([
            "crossing".to_string(),
            format!("{}", c.stiffness_n_per_m),
            format!("{}", RPM.from_si(c.speed_rad_s)),
        ])?;
    }
    Ok(String::from_utf8(w.into_inner()?)?)
}
