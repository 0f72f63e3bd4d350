//! Bench section: mass-conserving (JFO) cavitation and starvation. The compressor bearing (isothermal) with
//! the Reynolds and the JFO option at every fidelity level — time, the JFO/Reynolds time ratio, and each
//! option's errors against its own reference-fine solution (the flow column: the worst flow, as the main
//! table) — then the starved compressor bearing (`cases/compressor-bearing-starved.toml`) the same way, and
//! a supply-flow sweep at standard fidelity (friction power, eccentricity, minimum film, inflow).
//!
//! On a shared machine the wall time mostly measures the wait for a core, so the section also gives the
//! process CPU time of each option (the least of the repeats) and the work it counts (sparse
//! factorisations, film solves): the JFO/Reynolds ratio is given for both times.

use std::fmt::Write as _;
use std::path::Path;

use anyhow::Result;

use tiltpad::bearing::solve_case;
use tiltpad::model::{load_case, Case, Fidelity};
use tiltpad::units::L_PER_MIN;

use super::{levels, pct, with_mesh};

/// Process CPU time and work of one option at one level: the least CPU time of `repeats` solves [ms], the
/// sparse factorisations, those of them the pivoting LU did (a pivot the factorisation without row
/// exchanges refused) and the film solves of the last.
struct CpuCost {
    cpu_ms: f64,
    factorizations: usize,
    pivoted: usize,
    film_solves: usize,
}

fn cpu_cost(case: &Case, repeats: usize) -> Result<CpuCost> {
    let mut best = f64::INFINITY;
    let mut work = (0, 0, 0);
    for _ in 0..repeats.max(1) {
        let t0 = cpu_time::ProcessTime::try_now()?;
        let s = solve_case(case)?;
        best = best.min(t0.try_elapsed()?.as_secs_f64() * 1e3);
        work = (s.report.factorizations, s.report.pivoted_factorizations, s.report.film_solves);
    }
    Ok(CpuCost { cpu_ms: best, factorizations: work.0, pivoted: work.1, film_solves: work.2 })
}

/// [`cpu_cost`] of the case at the preview, standard and reference levels.
fn cpu_levels(text: &str, extra: &[String], repeats: usize) -> Result<Vec<CpuCost>> {
    [Fidelity::Preview, Fidelity::Standard, Fidelity::Reference]
        .iter()
        .map(|level| {
            let mut set = extra.to_vec();
            set.push(format!("mesh.fidelity=\"{}\"", format!("{level:?}").to_lowercase()));
            cpu_cost(&with_mesh(text, &set)?, repeats)
        })
        .collect()
}

/// Where the JFO time goes, per level: the CPU time per factorisation and the work of each option, and
/// what the mass-conserving solve does differently (measured numbers; the prose explains them).
fn where_the_time_goes(reynolds: &[CpuCost], jfo: &[CpuCost]) -> String {
    let cells: Vec<String> = ["preview", "standard", "reference"]
        .iter()
        .zip(reynolds.iter().zip(jfo))
        .map(|(level, (r, j))| {
            let per = |c: &CpuCost| c.cpu_ms / c.factorizations.max(1) as f64;
            format!(
                "{level} {:.2}× the CPU time per factorisation ({:.2} against {:.2} ms), {:.2}× the factorisations, \
                 {:.2}× the film solves",
                per(j) / per(r),
                per(j),
                per(r),
                j.factorizations as f64 / r.factorizations.max(1) as f64,
                j.film_solves as f64 / r.film_solves.max(1) as f64
            )
        })
        .collect();
    format!(
        "Where the JFO time goes (CPU, JFO against Reynolds): {}. A factorisation of the mass-conserving film is an \
         LDU factorisation of the non-symmetric mixed pressure/film-fraction matrix without row exchanges, on the \
         fill of the Reynolds matrix's Cholesky factor (about twice a Cholesky factorisation's arithmetic, done \
         simplicially; a pivoting sparse LU takes over a refused pivot), against a Cholesky factorisation of the \
         symmetric Reynolds matrix (supernodal from 2500 nodes per pad); the counts include the Reynolds \
         active-set solve that starts each pad's first mass-conserving solve. The CPU time per factorisation \
         divides the whole solve's time by the factorisations: at the preview level a factorisation without row \
         exchanges costs about what the simplicial Cholesky costs (with its per-factorisation symbolic pass), and \
         most of the difference lies around it: the search for the end of an unloaded pad's pressure-free range \
         (column sweeps of the film-fraction transport), the Couette right-hand sides of the linearisation and the \
         back-substitutions of the low-rank active-set updates and of the linearisation.",
        cells.join("; ")
    )
}

/// The section's heading in docs/PERFORMANCE.md.
pub const HEADING: &str = "## Mass-conserving cavitation and starvation (`physics.cavitation = \"jfo\"`)";

/// The section's markdown.
///
/// # Errors
/// A case cannot be read or a level fails to solve.
pub fn section(root: &Path, repeats: usize) -> Result<String> {
    Ok(measured(root, repeats)?.0)
}

/// The line under the first table of docs/PERFORMANCE.md: the compressor bearing's flow error per level
/// with the mass-conserving option.
fn flow_note(jfo: &[tiltpad::study::fidelity::LevelCost]) -> String {
    let cells: Vec<String> = jfo
        .iter()
        .filter(|r| r.err_flows.is_some_and(|e| e > 0.0))
        .map(|r| format!("{} {}", r.level, r.err_flows.map_or_else(|| "—".to_string(), pct)))
        .collect();
    format!(
        "\nFlow error of compressor-bearing with `physics.cavitation = \"jfo\"` (isothermal): {}. Its orifices are open \
         to ambient and drain the film; no cavitated zone touches them, so the default Reynolds condition gives the \
         same flows (its flow column above).\n",
        cells.join(", ")
    )
}

/// The flow note for the first table alone (`cargo xtask bench --only table`): the compressor bearing's levels with
/// the mass-conserving option.
///
/// # Errors
/// The case cannot be read or a level fails to solve.
pub fn flow_note_measured(root: &Path, repeats: usize) -> Result<String> {
    let compressor = std::fs::read_to_string(root.join("cases").join("compressor-bearing.toml"))?;
    let jfo_set = ["thermal.model=\"isothermal\"".to_string(), "physics.cavitation=\"jfo\"".to_string()];
    Ok(flow_note(&levels("compressor-bearing, jfo", &compressor, &jfo_set, repeats)?))
}

/// The section's markdown and the flow note for the first table ([`flow_note`]).
///
/// # Errors
/// A case cannot be read or a level fails to solve.
pub fn measured(root: &Path, repeats: usize) -> Result<(String, String)> {
    let read = |f: &str| std::fs::read_to_string(root.join("cases").join(f));
    let compressor = read("compressor-bearing.toml")?;
    let starved = read("compressor-bearing-starved.toml")?;
    let iso = "thermal.model=\"isothermal\"".to_string();
    super::say("bench: cavitation (Reynolds)");
    let reynolds = levels("compressor-bearing, reynolds", &compressor, std::slice::from_ref(&iso), repeats)?;
    super::say("bench: cavitation (JFO)");
    let jfo_set = [iso.clone(), "physics.cavitation=\"jfo\"".to_string()];
    let jfo = levels("compressor-bearing, jfo", &compressor, &jfo_set, repeats)?;
    super::say("bench: cavitation (CPU time and work per option)");
    let cpu_repeats = repeats.max(3);
    let reynolds_cpu = cpu_levels(&compressor, std::slice::from_ref(&iso), cpu_repeats)?;
    let jfo_cpu = cpu_levels(&compressor, &jfo_set, cpu_repeats)?;
    super::say("bench: cavitation (starved)");
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
         case (25 l/min, JFO). Wall: the median wall time; CPU: the process CPU time, least of {cpu_repeats} solves \
         (on a loaded machine the wall time mostly measures the wait for a core); work: sparse factorisations / film \
         solves of one complete solve (in brackets: the factorisations a pivoting LU did again, where the \
         factorisation without row exchanges refused a pivot).\n"
    );
    let _ = writeln!(
        md,
        "| case | level | film nodes | wall | CPU | JFO / Reynolds (wall, CPU) | work | ε error | K error | C error | p_max error | flow error |\n|---|---|---|---|---|---|---|---|---|---|---|---|"
    );
    let none = || "—".to_string();
    let rows = reynolds
        .iter()
        .zip(reynolds_cpu.iter().map(Some).chain(std::iter::repeat(None)))
        .map(|(r, c)| (r, c, None))
        .chain(jfo.iter().zip(&reynolds).enumerate().map(|(i, (j, r))| {
            let cost = jfo_cpu.get(i);
            let cpu_ratio = cost.zip(reynolds_cpu.get(i)).map(|(a, b)| a.cpu_ms / b.cpu_ms);
            (j, cost, Some((j.median_ms / r.median_ms, cpu_ratio)))
        }));
    for (r, cost, ratio) in rows.chain(starved_rows.iter().map(|r| (r, None, None))) {
        let _ = writeln!(
            md,
            "| {} | {} | {} | {:.1} ms | {} | {} | {} | {} | {} | {} | {} | {} |",
            r.case,
            r.level,
            r.film_nodes,
            r.median_ms,
            cost.map_or_else(none, |c| format!("{:.1} ms", c.cpu_ms)),
            ratio.map_or_else(none, |(w, c)| format!("{w:.2}×, {}", c.map_or_else(none, |c| format!("{c:.2}×")))),
            cost.map_or_else(none, |c| format!("{} / {} ({} pivoted)", c.factorizations, c.film_solves, c.pivoted)),
            pct(r.err_eccentricity),
            pct(r.err_k),
            pct(r.err_c),
            pct(r.err_p_max),
            r.err_flows.map_or_else(|| "—".to_string(), pct)
        );
    }
    let _ = writeln!(md, "\n{}", where_the_time_goes(&reynolds_cpu, &jfo_cpu));
    if let Some(e) = starved_failure {
        let _ = writeln!(md, "\ncompressor-bearing-starved: a level or its reference-fine solution failed: {e}");
    }
    let _ = writeln!(
        md,
        "\nStarvation sweep (compressor bearing, JFO, standard fidelity): the supply shared equally by the five pads.\n\n\
         | supply | friction power | ε | h_min | leading-edge inflow | pads with p_max above 1 % of the bearing's | film solves |\n|---|---|---|---|---|---|---|"
    );
    for supply in [None, Some(35.0), Some(30.0), Some(25.0), Some(20.0), Some(15.0), Some(12.0), Some(10.0)] {
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
                    "| {label} | {:.0} W | {:.4} | {:.2} µm | {:.2} l/min | {loaded} of {} | {} |",
                    s.friction_power_w,
                    s.eccentricity_ratio,
                    tiltpad::units::UM.from_si(s.h_min_m),
                    L_PER_MIN.from_si(s.flows_m3_per_s.leading_edges_in),
                    s.pads.len(),
                    s.report.film_solves
                );
            }
            Err(e) => {
                let _ = writeln!(md, "| {label} | no equilibrium: {e} | | | | | |");
            }
        }
    }
    Ok((md, flow_note(&jfo)))
}
