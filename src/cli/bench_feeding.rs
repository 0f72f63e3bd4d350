//! Bench section: oil feeding (`[feeding]`, docs/MODEL.md §3.4). The compressor bearing with the thermal model
//! (BC1) fed by leading-edge grooves, per fidelity level, with its errors against the reference-fine mesh;
//! then the three feedings and a starved groove-fed bearing at the standard level: time, ratio to the
//! flooded housing, friction power, churning and total loss, film peak and mean inlet temperature, film inflow and energy closure;
//! and the ram pressure (docs/MODEL.md §2.2) per fidelity level and at the standard level.

use std::fmt::Write as _;
use std::path::Path;

use anyhow::Result;

use super::bench::{level_cells, levels, timed, with_mesh};
use crate::units::L_PER_MIN;

pub const HEADING: &str = "## Oil feeding";

/// The markdown section.
///
/// # Errors
/// A missing case file or a failed solve.
pub fn section(root: &Path, repeats: usize) -> Result<String> {
    let read = |name: &str| std::fs::read_to_string(root.join("cases").join(format!("{name}.toml")));
    let compressor = read("compressor-bearing")?;
    super::interrupt::say("bench: feeding");
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
        "\nThe same with the leading-edge ram pressure, `feeding.ram_pressure_coefficient` 0.5 (4.9 bar at 9000 rpm):\n\n\
         | level | film nodes | time | ε error | K error | C error | p_max error | T_max error | flow error |\n\
         |---|---|---|---|---|---|---|---|---|\n",
    );
    for r in &ram_rows {
        let _ = writeln!(md, "{}", level_cells(r));
    }
    md.push_str(
        "\nThe feedings at the standard level (median time; ratio to the flooded housing; the films' friction power, the \
         flooded housing's churning between the pads (docs/MODEL.md §3.8; none with directed feeding) and their sum, film peak \
         temperature, mean inlet temperature, film inflow at the leading edges, energy-balance closure). The starved rows \
         use `cases/compressor-bearing-starved.toml` (25 l/min, mass-conserving cavitation):\n\n\
         | case | feeding | time | ratio | film friction | churning | total loss | film T_max | mean T_in | inflow | closure |\n\
         |---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    let starved = read("compressor-bearing-starved")?;
    let spray = ["feeding.kind=\"spray_bar\"".to_string()];
    let runs: [(&str, &str, &String, Vec<String>); 6] = [
        ("compressor-bearing THD", "flooded", &compressor, thd.to_vec()),
        ("compressor-bearing THD", "leading_edge_groove", &compressor, [&thd[..], &groove[..]].concat()),
        ("compressor-bearing THD", "spray_bar", &compressor, [&thd[..], &spray[..]].concat()),
        (
            "compressor-bearing THD",
            "leading_edge_groove, ram 0.5",
            &compressor,
            [&thd[..], &groove[..], &ram[..]].concat(),
        ),
        ("starved 25 l/min THD", "flooded", &starved, thd.to_vec()),
        ("starved 25 l/min THD", "leading_edge_groove", &starved, [&thd[..], &groove[..]].concat()),
    ];
    let mut flooded_ms = None;
    for (label, feeding, text, extra) in runs {
        let mut set = extra;
        set.push("mesh.fidelity=\"standard\"".to_string());
        let (ms, s) = timed(&with_mesh(text, &set)?, repeats)?;
        let base = *flooded_ms.get_or_insert(ms);
        let t = s.thermal.as_ref().ok_or_else(|| anyhow::anyhow!("{label}: no thermal result"))?;
        #[allow(clippy::cast_precision_loss)]
        let t_in = t.inlet_temperatures_c.iter().sum::<f64>() / t.inlet_temperatures_c.len().max(1) as f64;
        let _ = writeln!(
            md,
            "| {label} | {feeding} | {ms:.1} ms | {:.2} | {:.2} kW | {:.2} kW | {:.2} kW | {:.2} °C | {t_in:.2} °C | {:.1} l/min | {:.1e} |",
            ms / base,
            s.friction_power_w / 1e3,
            s.churning_power_w() / 1e3,
            s.total_power_loss_w() / 1e3,
            t.t_max_film_c,
            L_PER_MIN.from_si(s.flows_m3_per_s.leading_edges_in),
            t.energy_balance_closure,
        );
    }
    Ok(md)
}
