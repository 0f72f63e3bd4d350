//! What the workbench exports besides the case file: nodal fields as CSV and results as JSON.
//!
//! The CSV has one line per film node of every pad, SI units in the column names; a half model is written
//! as solved (z from the symmetry plane), so the file is the solver's data, not a picture of it. The JSON is
//! the same self-describing document as `tiltpad solve --json`, with the pinned results beside it: under
//! `"pins"`, each pin's name, case text, output cells (`"values"`, by column name) and the live result's
//! difference from it (`"difference"`, live − pinned). The results CSV is one row per result, the live one
//! first, then each pin, every output column ([`crate::scene::compare::pins_csv`]).

use std::fmt::Write as _;

use serde_json::{json, Map, Value};

use crate::bearing::solution::Solution;
use crate::scene::compare::{compare, pins_csv, Pin};

/// Nodal fields of every pad: `pad,s_m,theta_deg,z_m,pressure_pa,film_thickness_m,cavitated,viscosity_pa_s`.
#[must_use]
pub fn fields_csv(solution: &Solution) -> String {
    let mut out = String::from("pad,s_m,theta_deg,z_m,pressure_pa,film_thickness_m,cavitated,viscosity_pa_s\n");
    for p in &solution.pads {
        let f = &p.field;
        let cols = if f.periodic { f.s_m.len().saturating_sub(1) } else { f.s_m.len() };
        for i in 0..cols {
            for j in 0..f.z_m.len() {
                let k = f.index(i, j);
                let _ = writeln!(
                    out,
                    "{},{:.9e},{:.6},{:.9e},{:.9e},{:.9e},{},{:.6e}",
                    p.index,
                    f.s_m[i],
                    f.theta_rad[i].to_degrees(),
                    f.z_m[j],
                    f.pressure_pa[k],
                    f.film_thickness_m[k],
                    u8::from(f.cavitated[k]),
                    f.viscosity_pa_s[k]
                );
            }
        }
    }
    out
}

/// The result document (as `tiltpad solve --json`) with the pins beside it, pretty-printed.
#[must_use]
pub fn results_json(solution: &Solution, pins: &[Pin]) -> String {
    let mut doc = crate::bearing::solution::json::solution_json(solution);
    let pins: Vec<Value> = pins
        .iter()
        .map(|p| {
            let values: Map<String, Value> =
                p.columns.iter().zip(&p.cells).map(|(c, v)| (c.clone(), json!(v))).collect();
            let difference: Map<String, Value> =
                compare(solution, p).into_iter().map(|r| (r.column.to_string(), json!(r.difference))).collect();
            json!({ "name": p.name, "case_toml": p.case_toml, "values": values, "difference": difference })
        })
        .collect();
    if let Some(map) = doc.as_object_mut() {
        map.insert("pins".into(), Value::Array(pins));
    }
    serde_json::to_string_pretty(&doc).unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"))
}

/// The results as CSV: `name` then every output column; the live result (`live`) first, then the pins.
#[must_use]
pub fn results_csv(solution: &Solution, pins: &[Pin]) -> String {
    let table = pins_csv(pins, Some(solution));
    let mut lines: Vec<&str> = table.lines().collect();
    // pins_csv writes the live row last: move it under the header.
    if let Some(live) = lines.pop() {
        lines.insert(1.min(lines.len()), live);
    }
    lines.iter().map(|l| format!("{l}\n")).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Pin the 9000 rpm result, export the 6000 rpm one: the JSON carries the live document and, under
    /// `pins`, the pin's name, case, values and differences exactly as compared; the CSV has the live row
    /// first, then the pin, and reads back to the same numbers.
    #[test]
    fn pins_export_beside_the_live_result_and_read_back() {
        let fast = crate::bearing::stages::registry::compressor_preview(&[]);
        let slow = crate::bearing::stages::registry::compressor_preview(&["operating.speed_rpm=6000"]);
        let pin = Pin::new("9000 rpm", "title = \"pinned\"", &fast);
        let doc: Value = serde_json::from_str(&results_json(&slow, std::slice::from_ref(&pin))).unwrap();
        assert_eq!(doc["eccentricity_ratio"].as_f64(), Some(slow.eccentricity_ratio));
        let pins = doc["pins"].as_array().unwrap();
        assert_eq!(pins.len(), 1);
        assert_eq!(
            (pins[0]["name"].as_str(), pins[0]["case_toml"].as_str()),
            (Some("9000 rpm"), Some("title = \"pinned\""))
        );
        let eps = pins[0]["values"]["eccentricity_ratio"].as_f64().unwrap();
        assert!((eps - fast.eccentricity_ratio).abs() <= 1e-15 * eps, "{eps}");
        let d = pins[0]["difference"]["eccentricity_ratio"].as_f64().unwrap();
        assert!((d - (slow.eccentricity_ratio - fast.eccentricity_ratio)).abs() <= 1e-15, "{d}");
        assert!(pins[0]["values"]["t_max_film_c"].is_null(), "isothermal: no temperature");
        assert!(doc["pins"].as_array().is_some_and(|a| a.len() == 1));
        assert_eq!(
            serde_json::from_str::<Value>(&results_json(&slow, &[])).unwrap()["pins"].as_array().map(Vec::len),
            Some(0)
        );

        let csv = results_csv(&slow, &[pin]);
        let mut r = csv::Reader::from_reader(csv.as_bytes());
        let headers = r.headers().unwrap().clone();
        let col = headers.iter().position(|h| h == "eccentricity_ratio").unwrap();
        let rows: Vec<csv::StringRecord> = r.records().map(Result::unwrap).collect();
        assert_eq!(rows.iter().map(|r| r[0].to_string()).collect::<Vec<_>>(), ["live", "9000 rpm"]);
        assert_eq!(rows[0][col].parse::<f64>().unwrap(), slow.eccentricity_ratio);
        assert_eq!(rows[1][col].parse::<f64>().unwrap(), fast.eccentricity_ratio);
    }
}
