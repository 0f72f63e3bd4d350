//! Bench section: flexible pads. Time of a complete solve of `cases/compressor-bearing-flexible.toml`
//! (standard fidelity, isothermal) per number of retained bending modes and per pad-solid layer count, with
//! the error each level makes on ε, h_min, K_yy and C_yy (synchronously reduced) against the richest level
//! (3 modes, 8 layers). Mode computation is part of the time (each solve builds its model from scratch).

use std::fmt::Write as _;
use std::path::Path;

use anyhow::{Context, Result};
use web_time::Instant;

use crate::bearing::{solve_case, Solution};
use crate::model::load_case;

fn solve_level(text: &str, modes: usize, layers: usize, repeats: usize) -> Result<(f64, Solution)> {
    let set = vec![format!("physics.pad_modes={modes}"), format!("mesh.pad_radial_elements={layers}")];
    let case = load_case(text, &set)?.1;
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
    let rel = |a: f64, b: f64| ((a - b) / b).abs();
    [
        rel(s.eccentricity_ratio, truth.eccentricity_ratio),
        rel(s.h_min_m, truth.h_min_m),
        rel(s.reduced.k_n_per_m[1][1], truth.reduced.k_n_per_m[1][1]),
        rel(s.reduced.c_ns_per_m[1][1], truth.reduced.c_ns_per_m[1][1]),
    ]
}

/// The markdown section.
///
/// # Errors
/// A missing case file or a failed solve.
pub fn section(root: &Path, repeats: usize) -> Result<String> {
    let text = std::fs::read_to_string(root.join("cases").join("compressor-bearing-flexible.toml"))?;
    eprintln!("bench: flexible pads");
    let (_, truth) = solve_level(&text, 3, 8, 1)?;
    let mut md = String::from(
        "\n## Flexible pads (`physics.pad_modes`)\n\n`cases/compressor-bearing-flexible.toml` at standard fidelity (isothermal); each solve builds \
         its pad solids and modes from scratch (identical pads share one eigen-solution). Errors against 3 modes on 8 pad layers.\n\n\
         | modes | pad layers | time | ε error | h_min error | K_yy error | C_yy error |\n|---|---|---|---|---|---|---|\n",
    );
    for (modes, layers) in [(0, 4), (1, 2), (1, 4), (1, 8), (2, 4), (3, 4)] {
        let (ms, s) = solve_level(&text, modes, layers, repeats)?;
        let e = errors(&s, &truth);
        let _ = writeln!(md, "| {modes} | {layers} | {ms:.1} ms | {:.2} % | {:.2} % | {:.2} % | {:.2} % |", 100.0 * e[0], 100.0 * e[1], 100.0 * e[2], 100.0 * e[3]);
    }
    Ok(md)
}
