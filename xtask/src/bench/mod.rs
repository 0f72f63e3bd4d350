//! `cargo xtask bench`: the measurements of docs/PERFORMANCE.md, a developer tool outside the product (the
//! `tiltpad` binary and the Python wheel do not contain it). Run in release (the `xtask` alias builds it so).
//!
//! Without `--only` every section is measured and the whole file rewritten ([`table`] first, then the
//! sections of [`sections`]); `--only SECTION` re-measures one section and replaces it in place, closed by a
//! line with the machine's speed then ([`calibration_note`]): a shared machine's speed drifts between runs.
//! The sections measured by other means (the Python package's, the web build's) are carried over as they are.

mod batch;
mod cavitation;
mod control;
mod estimates;
mod feeding;
mod flex;
mod flows;
mod frf;
mod rotor;
mod sommerfeld;
mod table;
mod turb;

use std::fmt::Write as _;
use std::path::Path;

use anyhow::{Context, Result};
use tiltpad::bearing::{solve_case, Solution};
use tiltpad::model::{load_case, Case};
use tiltpad::study::fidelity::{FidelityTrade, LevelCost as LevelRow};
use web_time::Instant;

/// What the bench is doing, on standard error.
fn say(line: impl AsRef<str>) {
    eprintln!("{}", line.as_ref());
}

/// Writes a file safely ([`tiltpad::io::write_file`]).
fn write(path: &Path, bytes: &[u8]) -> Result<()> {
    Ok(tiltpad::io::write_file(path, bytes)?)
}

/// Median wall time of `repeats` complete solves [ms], and the last solution.
fn timed(case: &Case, repeats: usize) -> Result<(f64, Solution)> {
    let mut times = Vec::with_capacity(repeats);
    let mut last = None;
    for _ in 0..repeats {
        let t0 = Instant::now();
        let s = solve_case(case)?;
        times.push(t0.elapsed().as_secs_f64() * 1e3);
        last = Some(s);
    }
    times.sort_by(f64::total_cmp);
    let sol = last.context("no run")?;
    Ok((times[times.len() / 2], sol))
}

/// The case `text` with the overrides `set`.
fn with_mesh(text: &str, set: &[String]) -> Result<Case> {
    Ok(load_case(text, set)?.1)
}

/// The levels of one case (with extra overrides) against its reference-fine solution, then the truth's row
/// ([`FidelityTrade`]).
fn levels(name: &str, text: &str, extra: &[String], repeats: usize) -> Result<Vec<LevelRow>> {
    Ok(FidelityTrade::new(name, text, extra, repeats)?.run()?)
}

/// The names of the shipped cases (every `.toml` in `root/cases/`), sorted.
fn shipped_names(root: &Path) -> Result<Vec<String>> {
    let dir = root.join("cases");
    let mut names: Vec<String> = std::fs::read_dir(&dir)
        .with_context(|| format!("cannot read {}", dir.display()))?
        .filter_map(|e| e.ok().map(|e| e.file_name().to_string_lossy().into_owned()))
        .filter(|n| n.ends_with(".toml"))
        .collect();
    names.sort();
    Ok(names)
}

/// `FROM:TO:N` [rpm] as N speeds [rad/s] (a section's own constant).
fn speeds(spec: &str) -> Result<Vec<f64>> {
    let parts: Vec<f64> = spec.split(':').map(str::parse).collect::<Result<_, _>>()?;
    let [from, to, n] = parts[..] else { anyhow::bail!("speeds `{spec}`: FROM:TO:N") };
    #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
    let n = n as usize;
    #[allow(clippy::cast_precision_loss)]
    Ok((0..n).map(|i| tiltpad::units::RPM.to_si(from + (to - from) * i as f64 / (n - 1) as f64)).collect())
}

/// The machine: CPU model, cores and memory.
fn machine() -> String {
    let cpu = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|t| {
            t.lines()
                .find(|l| l.starts_with("model name"))
                .map(|l| l.split(':').nth(1).unwrap_or("").trim().to_string())
        })
        .unwrap_or_else(|| "unknown CPU".into());
    let cores = std::thread::available_parallelism().map_or(1, std::num::NonZero::get);
    let mem = std::fs::read_to_string("/proc/meminfo")
        .ok()
        .and_then(|t| t.lines().next().and_then(|l| l.split_whitespace().nth(1)).and_then(|k| k.parse::<f64>().ok()))
        .map_or_else(String::new, |kb| format!(", {:.0} GiB", kb / 1024.0 / 1024.0));
    format!("{cpu}, {cores} cores{mem}")
}

/// Now, as `date` prints it.
fn today() -> String {
    std::process::Command::new("date")
        .arg("+%Y-%m-%d %H:%M %Z")
        .output()
        .ok()
        .map_or_else(|| "unknown date".into(), |o| String::from_utf8_lossy(&o.stdout).trim().to_string())
}

/// A level's cells from its name on: `| level | film nodes | time | errors… |`.
fn level_cells(r: &LevelRow) -> String {
    format!(
        "| {} | {} | {:.1} ms | {} | {} | {} | {} | {} | {} |",
        r.level,
        r.film_nodes,
        r.median_ms,
        pct(r.err_eccentricity),
        pct(r.err_k),
        pct(r.err_c),
        pct(r.err_p_max),
        r.err_t_max.map_or_else(|| "—".to_string(), pct),
        r.err_flows.map_or_else(|| "—".to_string(), pct)
    )
}

fn pct(x: f64) -> String {
    if x == 0.0 {
        "—".into()
    } else {
        format!("{:.2} %", 100.0 * x)
    }
}

/// Every section after the first part, the notes and the carried-over sections.
fn sections(root: &Path, repeats: usize, cavitation: &str) -> Result<String> {
    let mut md = String::new();
    md.push_str(&batch::section(root, repeats.min(3))?);
    md.push_str(&frf::section(root, repeats)?);
    md.push_str(&flex::section(root, repeats.min(3))?);
    md.push_str(cavitation);
    md.push_str(&rotor::section(root, repeats.min(3))?);
    md.push_str(&turb::section(root, repeats.min(3))?);
    md.push_str(&control::section(root, repeats.min(3))?);
    md.push_str(&sommerfeld::section(root, repeats.min(3))?);
    md.push_str(&feeding::section(root, repeats.min(3))?);
    md.push_str(&flows::section(root)?);
    md.push_str(&estimates::section(root)?);
    let _ = writeln!(
        md,
        "\n## Notes\n\n\
         - Equilibrium: a coupled Newton over journal and pad coordinates (one film solve per pad per iteration, analytic \
           Jacobian), about 6 iterations; the nested pad-assembly method, a scan along the load and load continuation are \
           fallbacks. Symbolic factorisations and sparsity patterns are built once per mesh.\n\
         - Measured choices (profiled with `perf` on the isothermal compressor bearing at standard fidelity): the sparse \
           Cholesky factorisation takes ~47 % of a solve and its triangular solves ~9 %, the analytic film linearisation ~11 %. \
           faer's simplicial variant is faster up to ~1000 nodes per pad, the supernodal one from ~4600 (reference: 259 vs \
           307 ms), so the variant follows the pad size. Orifice integrals use sub-cells only on the hole's rim: they took \
           15 % of a solve when every cell was sub-divided and now take 0.3 %.\n\
         - Pads are solved on scoped threads when the film has at least 2500 nodes (native only, none on wasm); on this \
           2-core machine that saves 2 % at standard and 7 % at reference fidelity (the rest of a solve is serial).\n\
         - THD: about 80 % of a BC1 solve is its equilibria; BC3 couples film and pad in one LU system (see docs/THERMAL.md)."
    );
    // Measured by python/benchmarks/overhead.py (against this command line) and by hand in a browser (not by
    // this command): carried over as they are.
    md.push_str(&kept_section(root, PYTHON_SECTION));
    md.push_str(&kept_section(root, WEB_SECTION));
    Ok(md)
}

/// Heading of the Python package's cost against the command line (`python python/benchmarks/overhead.py
/// --write-doc`).
const PYTHON_SECTION: &str = "## Python package (`tiltpad.solve`)";

/// Heading of the web build's frame times in docs/PERFORMANCE.md (measured in Chromium with `?probe`).
const WEB_SECTION: &str = "## Web build: frame times";

/// The section of the current docs/PERFORMANCE.md that starts with `heading` (up to the next `## `), with a
/// leading blank line; empty when absent.
fn kept_section(root: &Path, heading: &str) -> String {
    let doc = std::fs::read_to_string(root.join("docs").join("PERFORMANCE.md")).unwrap_or_default();
    let Some(start) = doc.find(heading) else { return String::new() };
    let end = doc[start + heading.len()..].find("\n## ").map_or(doc.len(), |e| start + heading.len() + e + 1);
    format!("\n{}\n", doc[start..end].trim_end())
}

/// Replaces the section of docs/PERFORMANCE.md that starts with `heading` (up to the next `## `) by
/// `section`, or appends it before the notes when absent.
///
/// # Errors
/// The document cannot be read or written.
pub fn replace_section(root: &Path, heading: &str, section: &str) -> Result<()> {
    let path = root.join("docs").join("PERFORMANCE.md");
    let doc = std::fs::read_to_string(&path)?;
    let section = section.trim_start_matches('\n');
    let out = match doc.find(heading) {
        Some(start) => {
            let end = doc[start + heading.len()..].find("\n## ").map_or(doc.len(), |e| start + heading.len() + e + 1);
            format!("{}{section}\n{}", &doc[..start], &doc[end..])
        }
        None => match doc.find("\n## Notes") {
            Some(i) => format!("{}\n{section}{}", &doc[..i], &doc[i..]),
            None => format!("{doc}\n{section}"),
        },
    };
    write(&path, out.as_bytes())?;
    println!("updated {}", path.display());
    Ok(())
}

/// The calibration solve's case: the compressor bearing, isothermal, at standard fidelity (a row of the
/// first table).
const CALIBRATION: [&str; 2] = ["thermal.model=\"isothermal\"", "mesh.fidelity=\"standard\""];

/// Median time of the calibration solve [ms] (7 solves): how fast the machine is now.
fn calibration_ms(root: &Path) -> Result<f64> {
    let text = std::fs::read_to_string(root.join("cases").join("compressor-bearing.toml"))?;
    let set: Vec<String> = CALIBRATION.iter().map(|s| (*s).to_string()).collect();
    Ok(timed(&with_mesh(&text, &set)?, 7)?.0)
}

/// The calibration solve's time in the first table of `doc` [ms] (the compressor bearing's standard row).
fn calibration_in_doc(doc: &str) -> Option<f64> {
    let row = doc.lines().find(|l| l.starts_with("| compressor-bearing | standard |"))?;
    row.split('|').nth(4)?.trim().strip_suffix(" ms")?.parse().ok()
}

/// The closing line of a section measured alone: when, and how fast the machine was then against the run
/// that measured the rest of the file (a shared machine's speed drifts between runs; times in sections
/// measured at different times compare through this ratio).
fn calibration_note(only: &str, before_ms: f64, after_ms: f64, in_doc_ms: Option<f64>) -> String {
    let against = in_doc_ms.map_or_else(String::new, |d| {
        format!(
            " against {d:.1} ms in the first table: times here run about {:.1}× those of the sections measured with it",
            0.5 * (before_ms + after_ms) / d
        )
    });
    format!(
        "\n*Measured alone (`cargo xtask bench --only {only}`) on {}; the machine's speed then: the calibration solve (compressor \
         bearing, isothermal, standard fidelity, median of 7) took {before_ms:.1} ms before the section and {after_ms:.1} ms \
         after it{against}.*\n",
        today()
    )
}

/// The sections `--only` measures alone: `table` is the first part of the file (the fidelity table with its
/// targets, the thermal loop's cost, the cost growth and `assets/fidelity.json`).
pub const SECTIONS: [&str; 11] = [
    "table",
    "frf",
    "flex",
    "rotor",
    "turbulence",
    "cavitation",
    "control",
    "sommerfeld",
    "feeding",
    "flows",
    "estimates",
];

/// `cargo xtask bench --only SECTION` (or every section when `only` is `None`): replaces that section of
/// docs/PERFORMANCE.md, closed by a line with the machine's speed at the time ([`calibration_note`]).
///
/// # Errors
/// An unknown section, a failed measurement, I/O.
pub fn run(root: &Path, only: Option<&str>, repeats: usize) -> Result<()> {
    let Some(only) = only else { return table::run_parts(root, repeats.max(1), false) };
    if only == "table" {
        return table::run_parts(root, repeats.max(1), true);
    }
    if !SECTIONS.contains(&only) {
        anyhow::bail!("--only {only}: known sections: {}", SECTIONS.join(", "));
    }
    let few = repeats.clamp(1, 3);
    let before = calibration_ms(root)?;
    let (heading, section) = match only {
        "frf" => ("## Controllable lubrication", frf::section(root, repeats.max(1))?),
        "cavitation" => (cavitation::HEADING, cavitation::section(root, few)?),
        "flex" => ("## Flexible pads", flex::section(root, few)?),
        "rotor" => ("## Rotor–bearing analysis", rotor::section(root, repeats.max(1))?),
        "turbulence" => ("## Turbulence", turb::section(root, few)?),
        "control" => ("## Active control", control::section(root, few)?),
        "sommerfeld" => (sommerfeld::HEADING, sommerfeld::section(root, few)?),
        "feeding" => (feeding::HEADING, feeding::section(root, few)?),
        "flows" => (flows::HEADING, flows::section(root)?),
        _ => (estimates::HEADING, estimates::section(root)?),
    };
    let after = calibration_ms(root)?;
    let doc = std::fs::read_to_string(root.join("docs").join("PERFORMANCE.md")).unwrap_or_default();
    let note = calibration_note(only, before, after, calibration_in_doc(&doc));
    replace_section(root, heading, &format!("{}\n{note}", section.trim_end()))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A section measured alone closes with the calibration solve's times, against the same solve in the
    /// first table (45.8 ms there, 120 and 130 ms now: 2.7×); without a first table, no ratio.
    #[test]
    fn a_section_measured_alone_says_the_machines_speed_against_the_first_table() {
        let doc = "| compressor-bearing | preview | 1620 | 10.5 ms | 3.23 % |\n\
                   | compressor-bearing | standard | 4940 | 45.8 ms | 1.19 % |\n\
                   | compressor-bearing THD BC1 | standard | 4940 | 179.8 ms | 1.59 % |\n";
        assert_eq!(calibration_in_doc(doc), Some(45.8));
        assert_eq!(calibration_in_doc("# Performance\n"), None);
        let note = calibration_note("feeding", 120.0, 130.0, calibration_in_doc(doc));
        assert!(note.contains("`cargo xtask bench --only feeding`"), "{note}");
        assert!(note.contains("120.0 ms before the section and 130.0 ms after it against 45.8 ms"), "{note}");
        assert!(note.contains("about 2.7×"), "{note}");
        assert!(!calibration_note("feeding", 120.0, 130.0, None).contains("first table"));
    }
}
