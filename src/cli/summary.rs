//! Human-readable summary of a solution (its JSON form is [`crate::bearing::solution::json`]).

use crate::units::{KNS_PER_M, L_PER_MIN, MN_PER_M, MPA, UM};
use std::fmt::Write as _;

use crate::bearing::Solution;

/// A readable summary in engineering units.
#[must_use]
pub fn summary_text(s: &Solution) -> String {
    let mut o = String::new();
    let d = &s.derived;
    let _ = writeln!(o, "{}", if s.title.is_empty() { "tiltpad solution" } else { &s.title });
    let _ = writeln!(
        o,
        "  speed {:.0} rpm, load {:.1} N, film viscosity {:.4} Pa·s, Cb {:.1} µm, {} film nodes",
        d.speed_rpm,
        s.load_magnitude_n,
        d.film_viscosity_pa_s,
        UM.from_si(d.assembled_clearance_m),
        d.film_nodes
    );
    let _ = writeln!(
        o,
        "  eccentricity {:.4}  attitude {:+.2}°  journal ({:+.2}, {:+.2}) µm  Sommerfeld {}",
        s.eccentricity_ratio,
        s.attitude_angle_deg,
        UM.from_si(s.journal_position_m[0]),
        UM.from_si(s.journal_position_m[1]),
        s.sommerfeld.map_or_else(|| "—".to_string(), |v| format!("{v:.4}"))
    );
    let _ = writeln!(
        o,
        "  h_min {:.2} µm  p_max {:.3} MPa  power loss {:.1} W (film friction {:.1} W, housing churning {:.1} W)  flows: LE in {:.3} l/min, orifices {:+.3} l/min, sides {:.3} l/min",
        UM.from_si(s.h_min_m),
        MPA.from_si(s.p_max_pa),
        s.total_power_loss_w(),
        s.friction_power_w,
        s.churning_power_w(),
        L_PER_MIN.from_si(s.flows_m3_per_s.leading_edges_in),
        L_PER_MIN.from_si(s.flows_m3_per_s.orifices_in),
        L_PER_MIN.from_si(s.flows_m3_per_s.sides_out)
    );
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
    let r = &s.reduced;
    let _ = writeln!(o, "  reduced coefficients at ω = {:.1} rad/s (x, y):", r.omega_rad_s);
    let _ = writeln!(
        o,
        "    K [MN/m]   [{:>10.3} {:>10.3}]   C [kN·s/m] [{:>10.3} {:>10.3}]",
        MN_PER_M.from_si(r.k_n_per_m[0][0]),
        MN_PER_M.from_si(r.k_n_per_m[0][1]),
        KNS_PER_M.from_si(r.c_ns_per_m[0][0]),
        KNS_PER_M.from_si(r.c_ns_per_m[0][1])
    );
    let _ = writeln!(
        o,
        "               [{:>10.3} {:>10.3}]              [{:>10.3} {:>10.3}]",
        MN_PER_M.from_si(r.k_n_per_m[1][0]),
        MN_PER_M.from_si(r.k_n_per_m[1][1]),
        KNS_PER_M.from_si(r.c_ns_per_m[1][0]),
        KNS_PER_M.from_si(r.c_ns_per_m[1][1])
    );
    if let Some(t) = &s.thermal {
        let _ = writeln!(
            o,
            "  thermal ({:?}): film max {:.1} °C, mean {:.1} °C; pad max {}; journal {:.1} °C; inlets {} °C",
            t.pad_film_bc,
            t.t_max_film_c,
            t.t_mean_film_c,
            t.t_max_pad_c.map_or_else(|| "—".to_string(), |v| format!("{v:.1} °C")),
            t.journal_temperature_c,
            t.inlet_temperatures_c.iter().map(|v| format!("{v:.1}")).collect::<Vec<_>>().join(", ")
        );
        let _ = writeln!(
            o,
            "    heat: generated {:.1} W = carried by oil {:.1} W + conducted {:.1} W (closure {:+.2e}; journal power {:.1} W, identity {:+.2e}); pads to surroundings {:.1} W",
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
        for w in &r.warnings {
            let _ = writeln!(o, "  warning: {w}");
        }
    }
    let _ = writeln!(o, "{}", limits_line(s));
    let rep = &s.report;
    let _ = writeln!(
        o,
        "  solver: {} — {} iterations ({} pad), {} film solves, residual {:.1e}, {:.1} ms",
        rep.method_text(),
        rep.iterations,
        rep.inner_iterations,
        rep.film_solves,
        rep.residual,
        rep.seconds * 1e3
    );
    for w in &rep.warnings {
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
