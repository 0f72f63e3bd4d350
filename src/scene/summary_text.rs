//! The summary `tiltpad solve` prints and Python's `str(solution)` returns: the results panel's sections
//! ([`crate::scene::summary`], so the rows of the table of outputs with their labels, digits and units) as
//! aligned text, then what only a reader of text gets: the flow regime, the pad table, the thermal loop's
//! heat balance and growth, the design limits and the warnings. Its JSON form is
//! [`crate::bearing::solution::json`].

use std::fmt::Write as _;

use crate::bearing::Solution;
use crate::scene::summary::summary;
use crate::units::{MPA, UM};

/// Width of the label column [characters].
const LABEL: usize = 24;

/// A readable summary in engineering units.
#[must_use]
pub fn summary_text(s: &Solution) -> String {
    let mut o = String::new();
    let sum = summary(s);
    let _ = writeln!(o, "{}", if s.title.is_empty() { "tiltpad solution" } else { &s.title });
    for g in &sum.groups {
        // Headings in the command line's lower case ("reduced coefficients").
        let mut title = g.title.chars();
        let title: String = title.next().map(|c| c.to_lowercase().chain(title).collect()).unwrap_or_default();
        let _ = writeln!(o, "  {title}");
        for r in &g.rows {
            let line = format!("    {:<LABEL$} {} {}", r.label, r.value, r.unit);
            let _ = writeln!(o, "{}", line.trim_end());
        }
    }
    let g = &s.regime;
    let _ = writeln!(
        o,
        "  film Reynolds number ρUh/µ up to {:.0} (pad {}); turbulence {}: {:.0} % of the film past the transition band's start {:.0}, {:.0} % past its end {:.0}",
        g.reynolds_max,
        g.reynolds_pad,
        match g.turbulence {
            crate::model::Turbulence::Off => "off (laminar)",
            crate::model::Turbulence::Auto => "auto",
            crate::model::Turbulence::On => "on",
        },
        100.0 * g.transitional_fraction,
        g.transition_reynolds[0],
        100.0 * g.turbulent_fraction,
        g.transition_reynolds[1]
    );
    let _ = writeln!(o, "  pad   tilt [mrad]  h_min [µm]  p_max [MPa]  Fx [N]      Fy [N]");
    for p in &s.pads {
        let _ = writeln!(
            o,
            "  {:>3}   {:>10}  {:>10.2}  {:>11.3}  {:>9.1}  {:>9.1}{}",
            p.index,
            p.tilt_rad.map_or_else(|| "fixed".into(), |t| format!("{:.4}", t * 1e3)),
            UM.from_si(p.h_min_m),
            MPA.from_si(p.p_max_pa),
            p.force_n[0],
            p.force_n[1],
            if p.unloaded { "  (unloaded)" } else { "" }
        );
    }
    if let Some(t) = &s.thermal {
        let _ = writeln!(
            o,
            "  thermal ({:?}) heat: generated {:.1} W = carried by oil {:.1} W + conducted {:.1} W (closure {:+.2e}; journal power {:.1} W, identity {:+.2e}); pads to surroundings {:.1} W",
            t.pad_film_bc,
            t.heat.heat_generated(),
            t.heat_carried_by_oil_w,
            t.heat_conducted_w,
            t.energy_balance_closure,
            t.heat.power_in(),
            t.report.power_identity,
            t.heat_pads_to_surroundings_w
        );
        let r = &t.report;
        let _ = writeln!(
            o,
            "    thermal loop: {} outer iterations ({}), {} equilibrium iterations, {} film solves, {:.1} ms ({:.1} ms equilibrium, {:.1} ms thermal)",
            r.outer_iterations,
            r.stop_reason.map_or_else(|| "not converged".to_string(), |c| c.to_string()),
            r.equilibrium_iterations,
            r.film_solves,
            r.seconds * 1e3,
            r.equilibrium_seconds * 1e3,
            r.thermal_seconds * 1e3
        );
        if let Some(j) = r.journal_growth_m {
            let pads = r.pad_growth_range_m.map_or_else(String::new, |[lo, hi]| {
                format!(", pads' film faces {:.2} … {:.2} µm", UM.from_si(lo), UM.from_si(hi))
            });
            let housing = r.housing_growth_m.iter().copied().reduce(f64::max);
            let housing =
                housing.map_or_else(String::new, |h| format!(", housing at the pivots {:.2} µm", UM.from_si(h)));
            let _ = writeln!(o, "    thermal growth: journal {:.2} µm{pads}{housing}", UM.from_si(j));
        }
    }
    let _ = writeln!(o, "{}", limits_line(s));
    for w in &sum.warnings {
        let _ = writeln!(o, "  warning: {w}");
    }
    o
}

/// One line: the design limits the solution exceeds, or that it meets them all.
#[must_use]
pub fn limits_line(s: &Solution) -> String {
    let checks = crate::bearing::solution::limits::check(&s.inputs.limits, s);
    let bad: Vec<String> = checks.iter().filter(|c| c.exceeded).map(crate::scene::limits::text).collect();
    if bad.is_empty() {
        let all: Vec<String> = checks.iter().map(crate::scene::limits::text).collect();
        format!("  design limits met: {}", all.join(", "))
    } else {
        format!("  DESIGN LIMITS EXCEEDED: {}", bad.join("; "))
    }
}
