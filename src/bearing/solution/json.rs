//! The JSON form of a solution: SI, units in the key names, the resolved inputs included — what `tiltpad
//! solve --json` writes and the workbench exports. The scalar outputs at the top level come from the table of
//! outputs ([`crate::bearing::solution::outputs`]); vectors, matrices, pads and reports are serialised as
//! their types are. Warnings carry their `kind` and data and, as `message`, the
//! sentence a reader sees; the report's `method` is named as `method_text` too.

use serde_json::{json, Value};

use crate::bearing::report::SolveReport;
use crate::bearing::solution::limits::check;
use crate::bearing::solution::outputs::write_json;
use crate::bearing::solution::result::{Solution, ThermalResult};

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
    // The scalar outputs of the table's top-level keys are written from the table; the rest is structure.
    let mut v = json!({
        "title": s.title,
        "journal_position_m": s.journal_position_m,
        "load_n": s.load_n,
        "churning_gaps": s.churning,
        "flows_m3_per_s": s.flows_m3_per_s,
        "reduced": s.reduced,
        "full": s.full,
        "pads": pads,
        "coordinates": s.coordinates,
        "report": report_json(&s.report),
        "regime": s.regime,
        "thermal": s.thermal.as_ref().map(thermal_json),
        "design_limits": {
            "limits": s.inputs.limits,
            "checks": check(&s.inputs.limits, s),
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
    });
    write_json(&mut v, s);
    v
}

/// A warning list with each warning's sentence added as `message`.
fn warnings_json<W: serde::Serialize + std::fmt::Display>(warnings: &[W]) -> Value {
    warnings
        .iter()
        .map(|w| {
            let mut v = serde_json::to_value(w).unwrap_or(Value::Null);
            if let Value::Object(o) = &mut v {
                o.insert("message".into(), w.to_string().into());
            }
            v
        })
        .collect()
}

/// The solve report, its warnings with their sentences and its method in words.
fn report_json(r: &SolveReport) -> Value {
    let mut v = serde_json::to_value(r).unwrap_or(Value::Null);
    if let Value::Object(o) = &mut v {
        o.insert("warnings".into(), warnings_json(&r.warnings));
        o.insert("method_text".into(), r.method_text().into());
    }
    v
}

/// The thermal results, the loop's warnings with their sentences and its stop reason in words.
fn thermal_json(t: &ThermalResult) -> Value {
    let mut v = serde_json::to_value(t).unwrap_or(Value::Null);
    if let Some(Value::Object(o)) = v.get_mut("report") {
        o.insert("warnings".into(), warnings_json(&t.report.warnings));
        o.insert("stop_reason_text".into(), t.report.stop_reason.map(|c| c.to_string()).into());
    }
    v
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bearing::report::warning::Warning;

    #[test]
    fn warnings_carry_kind_data_and_message() {
        let w = [Warning::PadFloats { pad: 2, share: 1e-5, tilting: false }];
        let v = warnings_json(&w);
        assert_eq!(v[0]["kind"], "pad_floats");
        assert_eq!(v[0]["pad"], 2);
        assert_eq!(v[0]["message"], w[0].to_string());
    }
}
