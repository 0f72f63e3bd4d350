//! Bench section: mass-conserving (JFO) cavitation and starvation. The compressor bearing (isothermal) with
//! the Reynolds and the JFO option at every fidelity level — time, the JFO/Reynolds time ratio, and each
//! option's errors against its own reference-fine solution (the flow column: the worst flow, as the main
//! table) — then the starved compressor bearing (`cases/compressor-bearing-starved.toml`) the same way, and
//! a supply-flow sweep at standard fidelity (friction power, eccentricity, minimum film, inflow).

use std::fmt::Write as _;
use std::path::Path;

use anyhow::Result;

use crate::bearing::solve_case;
use crate::model::load_case;
use crate::units::L_PER_MIN;

use super::bench::{levels, pct};

/// The section's heading in docs/PERFORMANCE.md.
pub const HEADING: &str = "## Mass-conserving cavitation and starvation (`physics.cavitation = \"jfo\"`)";

/// The section's markdown.
///
/// # Errors
/// A case cannot be read or a level fails to solve.
pub fn section(root: &Path, repeats: usize) -> Result<String> {
    let read = |f: &str| std::fs::read_to_string(root.join("cases").join(f));
    let compressor = read("compressor-bearing.toml")?;
    let starved = read("compressor-bearing-starved.toml")?;
    let iso = "thermal.model=\"isothermal\"".to_string();
    eprintln!("bench: cavitation (Reynolds)");
    let reynolds = levels("compressor-bearing, reynolds", &compressor, std::slice::from_ref(&iso), repeats)?;
    eprintln!("bench: cavitation (JFO)");
    let jfo_set = [iso.clone(), "physics.cavitation=\"jfo\"".to_string()];
    let jfo = levels("compressor-bearing, jfo", &compressor, &jfo_set, repeats)?;
    eprintln!("bench: cavitation (starved)");
    // The starved case's equilibrium can fail at a level (a touchdown on the way); the section says so.
    let (starved_rows, starved_failure) = match levels("compressor-bearing-starved", &starved, &[iso], repeats) {
        Ok(rows) => (rows, None),
        Err(e) => (Vec::new(), Some(e.to_string())),
    };
    let mut md = String::new();
    let _ = writeln!(
        md,
        "\n{HEADING}\n\nCompressor bearing, isothermal: each option against its own reference-fine solution (twice the \
         reference level's element counts); the JFO/Reynolds column is the time ratio on the same mesh. Then the starved \
         case (25 l/min, JFO).\n"
    );
    let _ = writeln!(
        md,
        "| case | level | film nodes | time | JFO / Reynolds | ε error | K error | C error | p_max error | flow error |\n|---|---|---|---|---|---|---|---|---|---|"
    );
    let rows = reynolds
        .iter()
        .map(|r| (r, None))
        .chain(jfo.iter().zip(&reynolds).map(|(j, r)| (j, Some(j.median_ms / r.median_ms))));
    for (r, ratio) in rows.chain(starved_rows.iter().map(|r| (r, None))) {
        let _ = writeln!(
            md,
            "| {} | {} | {} | {:.1} ms | {} | {} | {} | {} | {} | {} |",
            r.case,
            r.level,
            r.film_nodes,
            r.median_ms,
            ratio.map_or_else(|| "—".to_string(), |x| format!("{x:.2}×")),
            pct(r.err_eccentricity),
            pct(r.err_k),
            pct(r.err_c),
            pct(r.err_p_max),
            r.err_flows.map_or_else(|| "—".to_string(), pct)
        );
    }
    if let Some(e) = starved_failure {
        let _ = writeln!(md, "\ncompressor-bearing-starved: a level or its reference-fine solution failed: {e}");
    }
    let _ = writeln!(
        md,
        "\nStarvation sweep (compressor bearing, JFO, standard fidelity): the supply shared equally by the five pads.\n\n\
         | supply | friction power | ε | h_min | leading-edge inflow | pads with p_max above 1 % of the bearing's |\n|---|---|---|---|---|---|"
    );
    for supply in [None, Some(35.0), Some(30.0), Some(25.0), Some(20.0), Some(15.0)] {
        let mut set = vec!["physics.cavitation=\"jfo\"".to_string()];
        if let Some(q) = supply {
            set.push(format!("operating.supply_flow_l_per_min={q}"));
        }
        let label = supply.map_or_else(|| "flooded".to_string(), |q| format!("{q} l/min"));
        let case = load_case(&compressor, &set)?.1;
        match solve_case(&case) {
            Ok(s) => {
                let loaded = s.pads.iter().filter(|p| p.p_max_pa > 0.01 * s.p_max_pa).count();
                let _ = writeln!(
                    md,
                    "| {label} | {:.0} W | {:.4} | {:.2} µm | {:.2} l/min | {loaded} of {} |",
                    s.friction_power_w,
                    s.eccentricity_ratio,
                    crate::units::UM.from_si(s.h_min_m),
                    L_PER_MIN.from_si(s.flows_m3_per_s.leading_edges_in),
                    s.pads.len()
                );
            }
            Err(e) => {
                let _ = writeln!(md, "| {label} | no equilibrium: {e} | | | | |");
            }
        }
    }
    Ok(md)
}
