//! What a fidelity level costs and how accurate it is, as measured by the developers' bench
//! (`cargo xtask bench`, [`crate::study::fidelity`]) on the compressor bearing (`assets/fidelity.json`,
//! written with `docs/PERFORMANCE.md`). The editor shows it next to the fidelity selector; `tiltpad fidelity`
//! measures the same for a user's own case.

use serde::{Deserialize, Serialize};

use crate::study::fidelity::LevelCost;

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
                let q = r.err_flows.map_or_else(String::new, |e| format!(", flows ±{:.1} %", 100.0 * e));
                format!(
                    "{run}: {:.0} ms, ε ±{:.1} %, K ±{:.1} %, C ±{:.1} %{t}{q}",
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
        let err = |level: &str| {
            t.rows.iter().find(|r| r.level == level && !r.case.contains("THD")).map(|r| (r.err_k, r.median_ms))
        };
        let (p, s, r) = (err("preview").unwrap(), err("standard").unwrap(), err("reference").unwrap());
        assert!(p.0 > s.0 && s.0 > r.0, "errors fall with fidelity: {p:?} {s:?} {r:?}");
        assert!(p.1 < s.1 && s.1 < r.1, "time rises with fidelity");
        assert_eq!(t.describe("standard").len(), t.rows.iter().filter(|r| r.level == "standard").count());
    }

    /// A row's flow error shows in its line.
    #[test]
    fn a_rows_flow_error_is_described() {
        let mut row = shipped().unwrap().rows[0].clone();
        row.err_flows = Some(0.3);
        let table = FidelityTable {
            generated: String::new(),
            machine: String::new(),
            case: String::new(),
            rows: vec![row.clone()],
        };
        assert!(table.describe(&row.level)[0].ends_with(", flows ±30.0 %"), "{:?}", table.describe(&row.level));
    }
}
