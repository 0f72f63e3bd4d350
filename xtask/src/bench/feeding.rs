//! Bench section: oil feeding (`[feeding]`, docs/MODEL.md §3.4). The compressor bearing with the thermal model
//! (BC1) fed by leading-edge grooves, per fidelity level, with its errors against the reference-fine mesh;
//! then the three feedings, a starved groove-fed bearing, and the large 400 mm bearing groove-fed against flooded
//! and starved by its grooves, at the standard level: time, ratio to the
//! flooded housing, friction power, churning and total loss, film peak and mean inlet temperature, film inflow and energy closure;
//! and the ram pressure (docs/MODEL.md §2.2) per fidelity level and at the standard level.

use std::fmt::Write as _;
use std::path::Path;

use anyhow::Result;

use super::{level_cells, levels, timed, with_mesh};
use tiltpad::units::L_PER_MIN;

pub const HEADING: &str = "## Oil feeding";

/// Rows of the feedings table that share a base case: its label, its case text and each row's feeding and overrides.
type Group<'a> = (&'a str, &'a String, Vec<(&'a str, Vec<String>)>);

/// The markdown section.
///
/// # Errors
/// A missing case file or a failed solve.
pub fn section(root: &Path, repeats: usize) -> Result<String> {
    let read = |name: &str| std::fs::read_to_string(root.join("cases").join(format!("{name}.toml")));
    let compressor = read("compressor-bearing")?;
    super::say("bench: feeding");
    let thd = ["thermal.model=\"thd\"".to_string(), "thermal.pad_film_bc=\"bc1\"".to_string()];
    let groove = [
        "feeding.kind=\"leading_edge_groove\"".to_string(),
        // The compressor case writes the flooded housing's carry-over, which a groove does not use.
        "thermal.carry_over=".to_string(),
    ];
    let rows = levels("compressor-bearing THD BC1, groove", &compressor, &[&thd[..], &groove[..]].concat(), repeats)?;
    let mut md = format!(
        "\n{HEADING} (`[feeding]`)\n\n`cases/compressor-bearing.toml` with the thermal model (BC1) fed by leading-edge \
         grooves (`feeding.groove_carry_over` 0.2). Errors as in the first table, against twice the reference mesh.\n\n\
         | level | film nodes | time | ε error | K error | C error | p_max error | T_max error | flow error |\n\
         |---|---|---|---|---|---|---|---|---|\n"
    );
    for r in &rows {
        let _ = writeln!(md, "{}", level_cells(r));
    }
    let ram = ["feeding.ram_pressure_coefficient=0.5".to_string()];
    let ram_rows = levels(
        "compressor-bearing THD BC1, groove, ram 0.5",
        &compressor,
        &[&thd[..], &groove[..], &ram[..]].concat(),
        repeats,
    )?;
    md.push_str(
        "\nThe same with the leading-edge ram pressure, `feeding.ram_pressure_coefficient` 0.5 (4.9 bar on the mid-plane at 9000 rpm):\n\n\
         | level | film nodes | time | ε error | K error | C error | p_max error | T_max error | flow error |\n\
         |---|---|---|---|---|---|---|---|---|\n",
    );
    for r in &ram_rows {
        let _ = writeln!(md, "{}", level_cells(r));
    }
    md.push_str(
        "\nThe feedings at the standard level (median time; ratio to the flooded housing; the films' friction power, the \
         flooded housing's churning between the pads (docs/MODEL.md §3.8; none with directed feeding) and their sum, film peak \
         temperature, hottest pad temperature, mean inlet temperature, film \
         inflow at the leading edges, energy-balance closure). The starved rows use `cases/compressor-bearing-starved.toml` \
         (25 l/min, mass-conserving cavitation). Then the large bearing, `cases/large-5pad-leg.toml` (400 mm, 75 m/s), \
         against a flooded housing, and starved by its grooves (`cases/large-5pad-leg-starved.toml`), each group's \
         ratio to its first row:\n\n\
         | case | feeding | time | ratio | film friction | churning | total loss | film T_max | pad T_max | mean T_in | inflow | closure |\n\
         |---|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    let starved = read("compressor-bearing-starved")?;
    let large = read("large-5pad-leg")?;
    let large_starved = read("large-5pad-leg-starved")?;
    let spray = ["feeding.kind=\"spray_bar\"".to_string()];
    let large_flooded =
        ["feeding.kind=\"flooded\"", "feeding.groove_carry_over=", "thermal.carry_over=0.5"].map(String::from).to_vec();
    let supply = |q: &str| vec![format!("operating.supply_flow_l_per_min={q}")];
    // Each group's ratio is to its first row (its flooded housing, or its fully fed films).
    let groups: [Group; 4] = [
        (
            "compressor-bearing THD",
            &compressor,
            vec![
                ("flooded", thd.to_vec()),
                ("leading_edge_groove", [&thd[..], &groove[..]].concat()),
                ("spray_bar", [&thd[..], &spray[..]].concat()),
                ("leading_edge_groove, ram 0.5", [&thd[..], &groove[..], &ram[..]].concat()),
            ],
        ),
        (
            "starved 25 l/min THD",
            &starved,
            vec![("flooded", thd.to_vec()), ("leading_edge_groove", [&thd[..], &groove[..]].concat())],
        ),
        ("large-5pad-leg THD", &large, vec![("flooded, λ 0.5", large_flooded), ("leading_edge_groove", vec![])]),
        (
            "large-5pad-leg-starved THD",
            &large_starved,
            vec![
                ("leading_edge_groove, 2000 l/min", supply("2000")),
                ("leading_edge_groove, 900 l/min", supply("900")),
                ("leading_edge_groove, 700 l/min", supply("700")),
                ("leading_edge_groove, 500 l/min", supply("500")),
            ],
        ),
    ];
    for (label, text, runs) in groups {
        let mut base_ms = None;
        for (feeding, mut set) in runs {
            set.push("mesh.fidelity=\"standard\"".to_string());
            let (ms, s) = timed(&with_mesh(text, &set)?, repeats)?;
            let base = *base_ms.get_or_insert(ms);
            let t = s.thermal.as_ref().ok_or_else(|| anyhow::anyhow!("{label}: no thermal result"))?;
            #[allow(clippy::cast_precision_loss)]
            let t_in = t.inlet_temperatures_c.iter().sum::<f64>() / t.inlet_temperatures_c.len().max(1) as f64;
            let pad = t.t_max_pad_c.map_or_else(|| "—".to_string(), |v| format!("{v:.2} °C"));
            let _ = writeln!(
                md,
                "| {label} | {feeding} | {ms:.1} ms | {:.2} | {:.2} kW | {:.2} kW | {:.2} kW | {:.2} °C | {pad} | {t_in:.2} °C | {:.1} l/min | {:.1e} |",
                ms / base,
                s.friction_power_w / 1e3,
                s.churning_power_w() / 1e3,
                s.total_power_loss_w() / 1e3,
                t.t_max_film_c,
                L_PER_MIN.from_si(s.flows_m3_per_s.leading_edges_in),
                t.energy_balance_closure,
            );
        }
    }
    Ok(md)
}
