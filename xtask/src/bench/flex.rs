//! Bench section: flexible pads. Time of a complete solve of `cases/compressor-bearing-flexible.toml`
//! (standard fidelity, isothermal) per number of retained bending modes and per pad-solid layer count, with
//! the error each level makes on ε, h_min, K_yy and C_yy (synchronously reduced) against the richest level
//! (3 modes, 8 layers). Mode computation is part of the time (each solve builds its model from scratch).
//!
//! TEHD: the same case with the THD model (BC1) and steel pads and journal growing from a 20 °C assembly
//! ([`TEHD`]), at the preview and standard fidelity, with the error on ε, K, C (Frobenius, synchronously
//! reduced), the film temperature rise and h_min against the reference film mesh (4 pad layers); and where the
//! time goes (equilibria, film energy + pad conduction + growth, outer iterations). Then the pad layers' own
//! share at the standard film mesh: 2, 4 (growth solid merged and not) and 8 layers.

use std::fmt::Write as _;
use std::path::Path;

use anyhow::{Context, Result};
use web_time::Instant;

use tiltpad::bearing::{solve_case, Solution};
use tiltpad::model::load_case;

use tiltpad::study::fidelity::{matrix_relative, relative, temperature_rise};

/// The TEHD variant of the flexible compressor bearing: THD (BC1, as the case's thermal data) with steel
/// pads (12 × 10⁻⁶/K) and journal (11 × 10⁻⁶/K) assembled at 20 °C (the values of `cases/fillon-a-tehd.toml`).
pub const TEHD: [&str; 4] = [
    "thermal.model=\"thd\"",
    "thermal.pad_expansion_ppm_per_k=12",
    "thermal.journal_expansion_ppm_per_k=11",
    "thermal.reference_temperature_c=20",
];

fn solve_level(text: &str, modes: usize, layers: usize, repeats: usize) -> Result<(f64, Solution)> {
    let set = vec![format!("physics.pad_modes={modes}"), format!("mesh.pad_radial_elements={layers}")];
    solve_set(text, &set, repeats)
}

/// Median time [ms] of `repeats` complete solves of the case with `set`, and the last solution.
fn solve_set(text: &str, set: &[String], repeats: usize) -> Result<(f64, Solution)> {
    let case = load_case(text, set)?.1;
    let (modes, layers) = (case.physics.pad_modes, case.mesh.pad_radial_elements);
    let mut times = Vec::with_capacity(repeats);
    let mut last = None;
    for _ in 0..repeats {
        let t0 = Instant::now();
        let s = solve_case(&case).with_context(|| format!("{modes} modes, {layers} layers"))?;
        times.push(t0.elapsed().as_secs_f64() * 1e3);
        last = Some(s);
    }
    times.sort_by(f64::total_cmp);
    Ok((times[times.len() / 2], last.context("no repeats")?))
}

fn errors(s: &Solution, truth: &Solution) -> [f64; 4] {
    [
        relative(s.eccentricity_ratio, truth.eccentricity_ratio),
        relative(s.h_min_m, truth.h_min_m),
        relative(s.reduced.k_n_per_m[1][1], truth.reduced.k_n_per_m[1][1]),
        relative(s.reduced.c_ns_per_m[1][1], truth.reduced.c_ns_per_m[1][1]),
    ]
}

/// The markdown section.
///
/// # Errors
/// A missing case file or a failed solve.
pub fn section(root: &Path, repeats: usize) -> Result<String> {
    let text = std::fs::read_to_string(root.join("cases").join("compressor-bearing-flexible.toml"))?;
    super::say("bench: flexible pads");
    let (_, truth) = solve_level(&text, 3, 8, 1)?;
    let mut md = String::from(
        "\n## Flexible pads (`physics.pad_modes`)\n\n`cases/compressor-bearing-flexible.toml` at standard fidelity (isothermal); each solve builds \
         its pad solids and modes from scratch (identical pads share one eigen-solution). Errors against 3 modes on 8 pad layers.\n\n\
         | modes | pad layers | time | ε error | h_min error | K_yy error | C_yy error |\n|---|---|---|---|---|---|---|\n",
    );
    for (modes, layers) in [(0, 4), (1, 2), (1, 4), (1, 8), (2, 4), (3, 4)] {
        let (ms, s) = solve_level(&text, modes, layers, repeats)?;
        let e = errors(&s, &truth);
        let _ = writeln!(
            md,
            "| {modes} | {layers} | {ms:.1} ms | {:.2} % | {:.2} % | {:.2} % | {:.2} % |",
            100.0 * e[0],
            100.0 * e[1],
            100.0 * e[2],
            100.0 * e[3]
        );
    }
    md.push_str(&tehd_table(&text, repeats)?);
    Ok(md)
}

/// The TEHD rows: each fidelity level (1 mode) against the reference mesh with 3 modes.
fn tehd_table(text: &str, repeats: usize) -> Result<String> {
    super::say("bench: flexible pads, TEHD");
    let with = |extra: &[&str]| -> Vec<String> { TEHD.iter().chain(extra).map(|s| (*s).to_string()).collect() };
    // The reference film mesh with 4 pad layers: 8 layers (the reference default) with 3 modes spent the thermal
    // loop's 120 s budget in its first outer iteration on this machine.
    let (truth_ms, truth) = solve_set(text, &with(&["mesh.fidelity=\"reference\"", "mesh.pad_radial_elements=4"]), 1)?;
    let mut md = format!(
        "\n### TEHD: flexible pads with thermal growth\n\nThe same case with the THD model (BC1) and thermal growth of steel pads \
         and journal from a 20 °C assembly (`{}`), one bending mode, per mesh fidelity (default pad layers: 2 preview, 4 \
         standard). Errors against the reference film mesh with 4 pad layers ({} film nodes, {truth_ms:.0} ms; the effect of \
         more layers and modes is in the isothermal table above); K and C synchronously reduced, Frobenius norm; T: the largest film temperature rise above \
         the supply. Time split (all outer iterations): equilibria; film energy, pad conduction and growth; of that the growth \
         (model set-up + steps). The rest of a solve is building the model (meshes, the pads' modes).\n\n\
         | fidelity | film nodes | time | outer it. | equilibria | thermal | growth | ε error | K error | C error | T_max error | h_min error |\n\
         |---|---|---|---|---|---|---|---|---|---|---|---|\n",
        TEHD.join(" "),
        truth.derived.film_nodes
    );
    for level in ["preview", "standard"] {
        let (ms, s) = solve_set(text, &with(&[&format!("mesh.fidelity=\"{level}\"")]), repeats)?;
        let r = s.thermal.as_ref().map(|t| t.report.clone()).context("a THD solution")?;
        let (setup, steps) = growth_ms(&r);
        let e = tehd_errors_pct(&s, &truth);
        let _ = writeln!(
            md,
            "| {level} | {} | {ms:.1} ms | {} | {:.0} ms | {:.0} ms | {setup:.0} + {steps:.0} ms | {:.2} % | {:.2} % | {:.2} % | {:.2} % | {:.2} % |",
            s.derived.film_nodes,
            r.outer_iterations,
            1e3 * r.equilibrium_seconds,
            1e3 * r.thermal_seconds,
            e[0],
            e[1],
            e[2],
            e[3],
            e[4],
        );
    }
    md.push_str(&layers_table(text, repeats)?);
    Ok(md)
}

/// The pad layers' share of the TEHD error: the standard film mesh with 2, 4 (the growth solid on every second
/// layer, the standard default, and on all) and 8 pad layers (the truth). The explicit film mesh with the
/// reference fidelity keeps every layer in the growth solid ([`tiltpad::bearing::thermal::growth::growth_layer_step`]).
fn layers_table(text: &str, repeats: usize) -> Result<String> {
    let with = |extra: &[String]| -> Vec<String> {
        TEHD.iter().map(|s| (*s).to_string()).chain(extra.iter().cloned()).collect()
    };
    let standard = with(&["mesh.fidelity=\"standard\"".to_string()]);
    let m = load_case(text, &standard)?.1.mesh;
    let film = |fidelity: &str, layers: usize| -> Vec<String> {
        with(&[
            format!("mesh.fidelity=\"{fidelity}\""),
            format!("mesh.circumferential_elements={}", m.circumferential_elements),
            format!("mesh.axial_elements={}", m.axial_elements),
            format!("mesh.orifice_elements={}", m.orifice_elements),
            format!("mesh.pad_radial_elements={layers}"),
        ])
    };
    let (truth_ms, truth) = solve_set(text, &film("reference", 8), 1)?;
    let mut md = format!(
        "\nPad layers at the standard film mesh ({} film nodes), against 8 layers with every layer in the growth solid \
         ({truth_ms:.0} ms): standard fidelity merges every two element layers into one of the growth solid (pad \
         conduction keeps all; `bearing/thermal/growth.rs`).\n\n\
         | pad layers | growth solid layers | time | growth | ε error | K error | C error | T_max error | h_min error |\n\
         |---|---|---|---|---|---|---|---|---|\n",
        truth.derived.film_nodes
    );
    for (layers, growth, set) in
        [(2, 2, film("standard", 2)), (4, 2, film("standard", 4)), (4, 4, film("reference", 4))]
    {
        let (ms, s) = solve_set(text, &set, repeats)?;
        let r = s.thermal.as_ref().map(|t| t.report.clone()).context("a THD solution")?;
        let (setup, steps) = growth_ms(&r);
        let e = tehd_errors_pct(&s, &truth);
        let _ = writeln!(
            md,
            "| {layers} | {growth} | {ms:.1} ms | {setup:.0} + {steps:.0} ms | {:.3} % | {:.3} % | {:.3} % | {:.3} % | {:.3} % |",
            e[0], e[1], e[2], e[3], e[4],
        );
    }
    Ok(md)
}

/// The growth's model set-up and steps of a TEHD solve [ms].
fn growth_ms(r: &tiltpad::bearing::thermal::ThermalReport) -> (f64, f64) {
    let setup = r.growth_setup_seconds.unwrap_or(0.0);
    (1e3 * setup, 1e3 * (r.growth_seconds.unwrap_or(0.0) - setup))
}

/// Errors of a TEHD solution against the truth [%]: ε, K and C (Frobenius, synchronously reduced), the film
/// temperature rise and h_min.
fn tehd_errors_pct(s: &Solution, truth: &Solution) -> [f64; 5] {
    let t_err = temperature_rise(s).zip(temperature_rise(truth)).map_or(f64::NAN, |(a, b)| relative(a, b));
    [
        relative(s.eccentricity_ratio, truth.eccentricity_ratio),
        matrix_relative(s.reduced.k_n_per_m, truth.reduced.k_n_per_m),
        matrix_relative(s.reduced.c_ns_per_m, truth.reduced.c_ns_per_m),
        t_err,
        relative(s.h_min_m, truth.h_min_m),
    ]
    .map(|e| 100.0 * e)
}
