//! `tiltpad rotor ROTOR.toml --critical-map`: the undamped critical-speed map (critical speeds against a
//! support stiffness at the bearings, [`crate::rotor::critical_map`]), the bearings' direct stiffnesses over
//! the `--speeds` and where they cross the mode lines — as a summary, JSON (`--json`) and CSV (`--csv`, long
//! form: one row per point of a series `modeN`, `bearingB_kxx`, `bearingB_kyy` or `crossing`, with its
//! stiffness [N/m] and speed [rpm]).

use crate::units::RPM;
use std::fmt::Write as _;

use anyhow::{Context, Result};

use crate::rotor::critical_map::{critical_speed_map, CriticalSpeedMap};

use super::rotor::{emit, parse_speeds, read_rotor, RotorArgs};

/// Stiffnesses of the map (logarithmic) and modes drawn.
pub(super) const POINTS: usize = 81;
const MODES: usize = 4;

/// Runs the map and writes the outputs.
///
/// # Errors
/// Input, solve and I/O errors.
pub fn run(args: &RotorArgs<'_>) -> Result<()> {
    let rotor = read_rotor(args.rotor)?;
    let speeds = parse_speeds(args.speeds, args.max_points)?;
    let estimate = crate::study::estimate::Estimate::critical_map(&rotor, speeds.len(), POINTS);
    super::inputs::check_work(&estimate, args.max_hours)?;
    // no bar: the heartbeat names the work under way when it takes long (a large shaft's eigen-solutions)
    let each = estimate
        .eigen
        .map_or(String::new(), |e| format!(", {} each", crate::study::estimate::duration_text(e.seconds_each)));
    super::interrupt::doing(format!(
        "critical-speed map: bearing stiffness at {} speeds, then {POINTS} undamped eigen-solutions of the shaft{each} \
         (about {} in all by the estimate)",
        speeds.len(),
        crate::study::estimate::duration_text(estimate.seconds)
    ));
    let map = critical_speed_map(&rotor, &speeds, POINTS, MODES)
        .with_context(|| format!("critical-speed map of {}", args.rotor.display()));
    super::interrupt::doing("");
    let map = map?;
    emit(args, &summary(&map), &map, || csv_text(&map))
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
    let _ = writeln!(
        s,
        "undamped critical-speed map: {} stiffnesses {:.2e}–{:.2e} N/m at the bearings, {} modes",
        ks.len(),
        ks[0],
        ks[ks.len() - 1],
        MODES
    );
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
