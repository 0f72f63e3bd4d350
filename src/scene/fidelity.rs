//! What a fidelity level costs and how accurate it is, as measured by `tiltpad bench` on the compressor
//! bearing (`assets/fidelity.json`, written with `docs/PERFORMANCE.md`). The editor shows it next to the
//! fidelity selector.

use serde::{Deserialize, Serialize};

use crate::bearing::solution::BearingFlows;

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
    /// Worst relative error of the bearing's flows ([`flow_error`]; absent in tables measured before it).
    #[serde(default)]
    pub err_flows: Option<f64>,
}

/// Worst relative error over the bearing's flows (leading edges in, trailing edges out, sides out,
/// orifices in, into cavitation), each against its own truth value, over the flows that carry at least
/// 1 % of the throughput (smaller ones are round-off of a balance); `None` when no flow does.
#[must_use]
pub fn flow_error(flows: &BearingFlows, truth: &BearingFlows) -> Option<f64> {
    worst_flow(flows, truth).map(|(e, _)| e)
}

/// [`flow_error`] and the name of the flow it is (`"orifices"`, `"into cavitation"`, …).
#[must_use]
pub fn worst_flow(flows: &BearingFlows, truth: &BearingFlows) -> Option<(f64, &'static str)> {
    let parts = |f: &BearingFlows| {
        [
            ("leading edges", f.leading_edges_in),
            ("trailing edges", f.trailing_edges_out),
            ("sides", f.sides_out),
            ("orifices", f.orifices_in),
            ("into cavitation", f.to_cavitation),
        ]
    };
    let (a, t) = (parts(flows), parts(truth));
    let throughput: f64 = t.iter().map(|(_, v)| v.abs()).sum();
    a.iter()
        .zip(&t)
        .filter(|(_, (_, t))| throughput > 0.0 && t.abs() >= 0.01 * throughput)
        .map(|((name, a), (_, t))| (((a - t) / t).abs(), *name))
        .reduce(|w, x| if x.0 > w.0 { x } else { w })
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

    #[test]
    fn flow_error_is_the_worst_flow_that_matters() {
        let truth = BearingFlows {
            leading_edges_in: 10.0,
            trailing_edges_out: 6.0,
            sides_out: 3.0,
            orifices_in: 1.0,
            to_cavitation: 0.1,
            mass_balance_error: 0.0,
        };
        // The orifice flow 30 % off dominates; the flow into cavitation (0.5 % of the throughput) is left out.
        let coarse = BearingFlows { leading_edges_in: 10.1, orifices_in: 1.3, to_cavitation: 0.2, ..truth };
        let e = flow_error(&coarse, &truth).unwrap();
        assert!((e - 0.3).abs() < 1e-12, "{e}");
        assert_eq!(worst_flow(&coarse, &truth).map(|(_, name)| name), Some("orifices"));
        assert_eq!(flow_error(&truth, &truth), Some(0.0));
        assert_eq!(flow_error(&truth, &BearingFlows::default()), None);
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
