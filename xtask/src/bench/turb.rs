//! Bench section: turbulent films (`physics.turbulence`, docs/MODEL.md §2.7). The large five-pad bearing in
//! transition (`cases/large-5pad-transition.toml`, isothermal, `turbulence = "auto"`) per fidelity level,
//! with its errors against the reference-fine mesh; then the cost of the option: the same case and the
//! compressor bearing (isothermal, whose film is laminar: `auto` must cost nothing there) solved with
//! `off`, `auto` and `on` at the standard level, and the time ratio to `off`.

use std::fmt::Write as _;
use std::path::Path;

use anyhow::Result;

use super::{level_cells, levels, timed, with_mesh};

const CASE: &str = "large-5pad-transition";

/// The markdown section.
///
/// # Errors
/// A missing case file or a failed solve.
pub fn section(root: &Path, repeats: usize) -> Result<String> {
    let text = std::fs::read_to_string(root.join("cases").join(format!("{CASE}.toml")))?;
    super::say("bench: turbulence");
    // Per level isothermal: the THD solve on twice the reference mesh (the truth) exceeds the thermal loop's
    // time budget on this machine; the option's cost under THD is in the second table.
    let rows =
        levels("large-5pad-transition isothermal auto", &text, &["thermal.model=\"isothermal\"".to_string()], repeats)?;
    let mut md = String::from(
        "\n## Turbulence (`physics.turbulence`)\n\n`cases/large-5pad-transition.toml` (400 mm, five pads, 3600 rpm, \
         `turbulence = \"auto\"`: about half the film past the transition band's start), isothermal. Errors as in the first table, against \
         twice the reference mesh.\n\n| level | film nodes | time | ε error | K error | C error | p_max error | T_max error | flow error |\n\
         |---|---|---|---|---|---|---|---|---|\n",
    );
    for r in &rows {
        let _ = writeln!(md, "{}", level_cells(r));
    }
    md.push_str(
        "\nCost of the option at the standard level (median time; ratio to `off`; friction power and largest local \
         Reynolds number of the solution):\n\n| case | turbulence | time | ratio | friction | Re max |\n|---|---|---|---|---|---|\n",
    );
    let compressor = std::fs::read_to_string(root.join("cases").join("compressor-bearing.toml"))?;
    for (label, text, extra) in [
        ("large-5pad-transition THD", &text, vec![]),
        ("compressor-bearing isothermal", &compressor, vec!["thermal.model=\"isothermal\"".to_string()]),
    ] {
        let mut off_ms = None;
        for mode in ["off", "auto", "on"] {
            let mut set = extra.clone();
            set.extend(["mesh.fidelity=\"standard\"".to_string(), format!("physics.turbulence=\"{mode}\"")]);
            let (ms, s) = timed(&with_mesh(text, &set)?, repeats)?;
            let base = *off_ms.get_or_insert(ms);
            let _ = writeln!(
                md,
                "| {label} | {mode} | {ms:.1} ms | {:.2} | {:.1} kW | {:.0} |",
                ms / base,
                s.friction_power_w / 1e3,
                s.regime.reynolds_max
            );
        }
    }
    Ok(md)
}
