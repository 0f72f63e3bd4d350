//! The rotor analysis as text: the summary `tiltpad rotor` prints (and the Python `RotorResult.summary`)
//! and its CSV, one row per speed (the first [`MODES`] damped modes: frequency [Hz], logarithmic decrement,
//! whirl `F`/`B`; then the unbalance response at each response node [µm peak-to-peak, degrees] and the
//! API 617 limit [µm]). Speeds in rpm, the unit in every CSV column name.

use std::fmt::Write as _;

use crate::model::rotor::Rotor;
use crate::rotor::analysis::AnalysisResult;
use crate::rotor::eigen::Whirl;
use crate::units::RPM;

/// Modes written per speed in the CSV and the summary.
pub const MODES: usize = 6;

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
pub fn csv_text(r: &AnalysisResult) -> Result<String, csv::Error> {
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
    let bytes = w.into_inner().map_err(|e| csv::Error::from(e.into_error()))?;
    Ok(String::from_utf8_lossy(&bytes).into_owned())
}
