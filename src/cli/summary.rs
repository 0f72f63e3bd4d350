//! Human-readable summary and the JSON result document.

use std::fmt::Write as _;

use serde_json::{json, Value};

use crate::bearing::Solution;

/// The JSON result: SI, units in the key names, resolved inputs included.
#[must_use]
pub fn solution_json(s: &Solution) -> Value {
    let pads: Vec<Value> = s
        .pads
        .iter()
        .map(|p| {
            json!({
                "index": p.index,
                "tilt_rad": p.tilt_rad,
                "pivot_displacement_m": p.pivot_displacement_m,
                "h_min_m": p.h_min_m,
                "h_min_angle_deg": p.h_min_angle_deg,
                "p_max_pa": p.p_max_pa,
                "force_n": p.force_n,
                "moment_nm": p.moment_nm,
                "flows_m3_per_s": p.flows_m3_per_s,
                "orifice_flows_m3_per_s": p.orifice_flows_m3_per_s,
                "friction_power_w": p.friction_power_w,
                "cavitated_fraction": p.cavitated_fraction,
                "unloaded": p.unloaded,
                "thermal": p.thermal,
            })
        })
        .collect();
    json!({
        "title": s.title,
        "eccentricity_ratio": s.eccentricity_ratio,
        "attitude_angle_deg": s.attitude_angle_deg,
        "journal_position_m": s.journal_position_m,
        "load_n": s.load_n,
        "load_magnitude_n": s.load_magnitude_n,
        "sommerfeld": s.sommerfeld,
        "h_min_m": s.h_min_m,
        "p_max_pa": s.p_max_pa,
        "friction_power_w": s.friction_power_w,
        "friction_torque_nm": s.friction_torque_nm,
        "flows_m3_per_s": s.flows_m3_per_s,
        "reduced": s.reduced,
        "full": s.full,
        "pads": pads,
        "coordinates": s.coordinates,
        "report": s.report,
        "t_max_film_c": s.thermal.as_ref().map(|t| t.t_max_film_c),
        "t_max_pad_c": s.thermal.as_ref().and_then(|t| t.t_max_pad_c),
        "thermal": s.thermal,
        "design_limits": {
            "limits": s.inputs.limits,
            "checks": crate::bearing::solution::limits::check(&s.inputs.limits, s),
        },
        "inputs": {
            "case": s.inputs,
            "assembled_clearance_m": s.derived.assembled_clearance_m,
            "pad_clearances_m": s.derived.pad_clearances_m,
            "preloads": s.derived.preloads,
            "speed_rad_s": s.derived.speed_rad_s,
            "speed_rpm": s.derived.speed_rpm,
            "film_viscosity_pa_s": s.derived.film_viscosity_pa_s,
            "film_nodes": s.derived.film_nodes,
        },
    })
}

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
        d.assembled_clearance_m * 1e6,
        d.film_nodes
    );
    let _ = writeln!(
        o,
        "  eccentricity {:.4}  attitude {:+.2}°  journal ({:+.2}, {:+.2}) µm  Sommerfeld {}",
        s.eccentricity_ratio,
        s.attitude_angle_deg,
        s.journal_position_m[0] * 1e6,
        s.journal_position_m[1] * 1e6,
        s.sommerfeld.map_or_else(|| "—".to_string(), |v| format!("{v:.4}"))
    );
    let _ = writeln!(
        o,
        "  h_min {:.2} µm  p_max {:.3} MPa  friction {:.1} W  flows: LE in {:.3} l/min, orifices {:+.3} l/min, sides {:.3} l/min",
        s.h_min_m * 1e6,
        s.p_max_pa * 1e-6,
        s.friction_power_w,
        s.flows_m3_per_s.leading_edges_in * 6e4,
        s.flows_m3_per_s.orifices_in * 6e4,
        s.flows_m3_per_s.sides_out * 6e4
    );
    let _ = writeln!(o, "  pad   tilt [mrad]  h_min [µm]  p_max [MPa]  Fx [N]      Fy [N]");
    for p in &s.pads {
        let _ = writeln!(
            o,
            "  {:>3}   {:>10}  {:>10.2}  {:>11.3}  {:>9.1}  {:>9.1}{}",
            p.index,
            p.tilt_rad.map_or_else(|| "fixed".into(), |t| format!("{:.4}", t * 1e3)),
            p.h_min_m * 1e6,
            p.p_max_pa * 1e-6,
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
        r.k_n_per_m[0][0] * 1e-6,
        r.k_n_per_m[0][1] * 1e-6,
        r.c_ns_per_m[0][0] * 1e-3,
        r.c_ns_per_m[0][1] * 1e-3
    );
    let _ = writeln!(
        o,
        "               [{:>10.3} {:>10.3}]              [{:>10.3} {:>10.3}]",
        r.k_n_per_m[1][0] * 1e-6,
        r.k_n_per_m[1][1] * 1e-6,
        r.c_ns_per_m[1][0] * 1e-3,
        r.c_ns_per_m[1][1] * 1e-3
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
            "    heat: power in {:.1} W = carried by oil {:.1} W + conducted {:.1} W (closure {:+.2e}); pads to surroundings {:.1} W",
            t.heat.power_in(),
            t.heat_carried_by_oil_w,
            t.heat_conducted_w,
            t.energy_balance_closure,
            t.heat_pads_to_surroundings_w
        );
        let r = &t.report;
        let _ = writeln!(
            o,
            "    thermal loop: {} outer iterations ({}), {} equilibrium iterations, {} film solves, {:.1} ms ({:.1} ms equilibrium, {:.1} ms thermal)",
            r.outer_iterations,
            r.stop_reason,
            r.equilibrium_iterations,
            r.film_solves,
            r.seconds * 1e3,
            r.equilibrium_seconds * 1e3,
            r.thermal_seconds * 1e3
        );
        if let Some(j) = r.journal_growth_m {
            let pads = r.pad_growth_range_m.map_or_else(String::new, |[lo, hi]| {
                format!(", pads' film faces {:.2} … {:.2} µm", lo * 1e6, hi * 1e6)
            });
            let housing = r.housing_growth_m.iter().copied().reduce(f64::max);
            let housing = housing.map_or_else(String::new, |h| format!(", housing at the pivots {:.2} µm", h * 1e6));
            let _ = writeln!(o, "    thermal growth: journal {:.2} µm{pads}{housing}", j * 1e6);
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
        rep.method,
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
