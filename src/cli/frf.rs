//! `tiltpad frf`: the controllable bearing's frequency responses over a band (docs/MODEL.md §8, §9) — G1, G2,
//! G3, G per port and force component, and with a rig the calibrated-shaker chain — as CSV and JSON.

use std::path::{Path, PathBuf};

use anyhow::{bail, Context, Result};
use serde_json::json;

use crate::bearing::frf::model::band;
use crate::bearing::Stages;
use crate::io::write_file;
use crate::scene::frf::{port_names, FrfCurves};

use super::read_case;
use super::rows::announce;

/// The band and where the curves go.
pub struct FrfArgs<'a> {
    pub case: &'a Path,
    pub set: &'a [String],
    pub from_hz: f64,
    pub to_hz: f64,
    pub points: usize,
    /// Control amplitude to check against the valve's small-signal range [V].
    pub amplitude_v: Option<f64>,
    pub csv: Option<PathBuf>,
    pub json: Option<PathBuf>,
    /// A controller file closing the loop on the rig.
    pub control: Option<&'a Path>,
    /// The rig's closed loop as CSV.
    pub loop_csv: Option<PathBuf>,
}

/// Computes and writes the curves.
///
/// # Errors
/// Bad band, an invalid case or one without `[hydraulics]`, a failed equilibrium, or an unwritable output.
pub fn run(args: &FrfArgs<'_>) -> Result<()> {
    if !(args.from_hz >= 0.0 && args.to_hz > args.from_hz && args.to_hz.is_finite()) {
        bail!("--from {} --to {}: need 0 ≤ from < to", args.from_hz, args.to_hz);
    }
    if !(2..=100_000).contains(&args.points) {
        bail!("--points {}: allowed 2 to 100000", args.points);
    }
    let (_, case) = read_case(args.case, args.set)?;
    let cost = crate::study::estimate::point_cost(&case);
    super::inputs::check_work(&crate::study::estimate::Estimate::points("frf", 1, cost), f64::INFINITY)?;
    let model = match Stages::new().frf(&case, &super::interrupt::Interrupt) {
        Ok(m) => m,
        Err(crate::bearing::SolveError::Cancelled) if super::interrupt::requested() => {
            return Err(super::interrupt::Interrupted::new(0, 1, "solves", &[]).into())
        }
        Err(e) => return Err(anyhow::Error::new(e).context(format!("solving {}", args.case.display()))),
    };
    let freqs = band(args.from_hz, args.to_hz, args.points);
    let sweep = model.sweep(&case, &freqs)?;
    let h = case.hydraulics.as_ref().context("no [hydraulics]")?;
    let title = format!(
        "{} — {:.0} rpm, ε = {:.3}, supply {:.0} bar",
        case.title,
        crate::units::RPM.from_si(case.operating.speed_rad_s),
        model.eccentricity_ratio,
        crate::units::BAR.from_si(h.supply_pressure_pa)
    );
    let rig_loop = match args.control {
        Some(path) => Some(super::control::rig_loop(path, &case, &model, &freqs)?),
        None => None,
    };
    if rig_loop.is_none() && args.loop_csv.is_some() {
        bail!("--loop-csv needs --control CONTROL.toml (the controller that closes the rig's loop)");
    }
    let mut curves = FrfCurves::new(&sweep, &port_names(&case), title);
    if let Some(a) = args.amplitude_v {
        curves.check_signal(a, 0.1 * h.valve.full_scale_v);
    }
    eprintln!(
        "{}: equilibrium {:.3} s, linearisation {:.4} s, {} frequencies {:.4} s",
        curves.title, model.report.seconds, model.linearise_seconds, args.points, sweep.seconds
    );
    for n in &curves.notes {
        eprintln!("note: {n}");
    }
    if args.csv.is_none() && args.json.is_none() {
        print!("{}", curves.csv());
    }
    if let Some(p) = &args.csv {
        write_file(p, curves.csv().as_bytes())?;
        announce(p);
    }
    if let (Some(p), Some(l)) = (&args.loop_csv, &rig_loop) {
        write_file(p, super::control::rig_loop_csv(l)?.as_bytes())?;
        announce(p);
    }
    if let Some(p) = &args.json {
        let doc = json!({
            "curves": curves,
            "rig_loop": rig_loop,
            "seconds": { "equilibrium": model.report.seconds, "linearisation": model.linearise_seconds, "frf": sweep.seconds },
        });
        let mut text = serde_json::to_string_pretty(&doc)?;
        text.push('\n');
        write_file(p, text.as_bytes())?;
        announce(p);
    }
    Ok(())
}
