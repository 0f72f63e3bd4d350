//! What a fidelity level costs and how accurate it is, as measured by `tiltpad bench` on the compressor
//! bearing (`assets/fidelity.json`, written with `docs/PERFORMANCE.md`). The editor shows it next to the
//! fidelity selector.

use serde::{Deserialize, Serialize};

/// One measured level of one run (isothermal or THD): written by the bench, read by the editor.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct LevelCost {
    pub case: String,
    pub level: String,
    pub film_nodes: usize,
    pub median_ms: f64,
    pub err_eccentricity: f64,
    pub err_k: f64,
    pub err_c: f64,
    pub err_p_max: f64,
    /// Relative error of the maximum film temperature rise above supply (THD rows only).
    #[serde(default)]
    pub err_t_max: Option<f64>,
}

/// The measured table.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct FidelityTable {
    pub generated: String,
    pub machine: String,
    /// The case the rows were measured on.
    #[serde(default)]
    pub case: String,
    pub rows: Vec<LevelCost>,
}

/// The table shipped with this build.
#[must_use]
pub fn shipped() -> Option<FidelityTable> {
    serde_json::from_str(include_str!("../../assets/fidelity.json")).ok()
}

impl FidelityTable {
    /// One line per run for `level` (e.g. "isothermal: 76 ms, ε ±1.2 %, K ±1.6 %, C ±0.8 %").
    #[must_use]
    pub fn describe(&self, level: &str) -> Vec<String> {
        self.rows
            .iter()
            .filter(|r| r.level == level)
            .map(|r| {
                let run = if r.case.contains("THD") { "THD" } else { "isothermal" };
                let t = r.err_t_max.map_or_else(String::new, |e| format!(", T rise ±{:.1} %", 100.0 * e));
                format!(
                    "{run}: {:.0} ms, ε ±{:.1} %, K ±{:.1} %, C ±{:.1} %{t}",
                    r.median_ms,
                    100.0 * r.err_eccentricity,
                    100.0 * r.err_k,
                    100.0 * r.err_c
                )
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shipped_table_covers_every_level_and_errors_fall_with_fidelity() {
        let t = shipped().expect("assets/fidelity.json parses");
        let err = |level: &str| t.rows.iter().find(|r| r.level == level && !r.case.contains("THD")).map(|r| (r.err_k, r.median_ms));
        let (p, s, r) = (err("preview").unwrap(), err("standard").unwrap(), err("reference").unwrap());
        assert!(p.0 > s.0 && s.0 > r.0, "errors fall with fidelity: {p:?} {s:?} {r:?}");
        assert!(p.1 < s.1 && s.1 < r.1, "time rises with fidelity");
        assert_eq!(t.describe("standard").len(), t.rows.iter().filter(|r| r.level == "standard").count());
    }
}
