//! `tiltpad bench`: the speed–accuracy table.
//!
//! For each shipped benchmark case and each fidelity level it measures the wall time of a complete solve
//! (mesh build, equilibrium, full and synchronously reduced coefficients; median of repeated runs) and the
//! relative error against a reference-fine solution (twice the reference level's element counts):
//! eccentricity, reduced K and C (Frobenius norm of the 2×2 difference over the norm), p_max. It also
//! measures the cost growth with the number of film nodes (fitted exponent) and writes
//! `docs/PERFORMANCE.md`, `docs/performance-error-vs-time.svg` and `assets/fidelity.json` (what the
//! workbench shows next to the fidelity selector). Run it in release: `cargo run --release -- bench`.

use std::fmt::Write as _;
use std::path::Path;

use anyhow::{Context, Result};
use web_time::Instant;

use crate::bearing::{solve_case, Solution};
use crate::model::{load_case, Case, Fidelity};
use crate::scene::fidelity::{flow_error, FidelityTable, LevelCost as LevelRow};

use super::write_atomic;

pub(super) fn frob_rel(a: [[f64; 2]; 2], b: [[f64; 2]; 2]) -> f64 {
    let mut d = 0.0;
    let mut n = 0.0;
    for i in 0..2 {
        for j in 0..2 {
            d += (a[i][j] - b[i][j]).powi(2);
            n += b[i][j].powi(2);
        }
    }
    (d / n).sqrt()
}

pub(super) fn rel(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs()
}

/// Median wall time of `repeats` complete solves [ms], and the last solution.
pub(super) fn timed(case: &Case, repeats: usize) -> Result<(f64, Solution)> {
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

pub(super) fn with_mesh(text: &str, set: &[String]) -> Result<Case> {
    Ok(load_case(text, set)?.1)
}

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

fn today() -> String {
    std::process::Command::new("date")
        .arg("+%Y-%m-%d %H:%M %Z")
        .output()
        .ok()
        .map_or_else(|| "unknown date".into(), |o| String::from_utf8_lossy(&o.stdout).trim().to_string())
}

/// Temperature rise of the hottest film point above supply [K] (THD solutions).
pub(super) fn t_rise(s: &Solution) -> Option<f64> {
    s.thermal.as_ref().map(|t| t.t_max_film_c - s.inputs.operating.supply_temperature_c)
}

/// `extra` and the overrides of the reference-fine mesh, the truth of every error column: twice the
/// reference level's element counts.
pub(super) fn reference_fine(extra: &[String]) -> Vec<String> {
    let (nx, nz, no) = Fidelity::Reference.elements();
    let mut set = extra.to_vec();
    set.extend([
        "mesh.fidelity=\"reference\"".into(),
        format!("mesh.circumferential_elements={}", 2 * nx),
        format!("mesh.axial_elements={}", 2 * nz),
        format!("mesh.orifice_elements={}", 2 * no),
        // Twice the reference mesh exceeds the default node budget with the pad solids of the thermal model.
        "mesh.max_nodes=2000000".into(),
    ]);
    set
}

/// Levels of one case (with extra overrides) against its reference-fine solution.
pub(super) fn levels(name: &str, text: &str, extra: &[String], repeats: usize) -> Result<Vec<LevelRow>> {
    let fine = with_mesh(text, &reference_fine(extra))?;
    let truth = solve_case(&fine)?;
    let mut rows = Vec::new();
    for level in [Fidelity::Preview, Fidelity::Standard, Fidelity::Reference] {
        let name_l = format!("{level:?}").to_lowercase();
        let mut set = extra.to_vec();
        set.push(format!("mesh.fidelity=\"{name_l}\""));
        let case = with_mesh(text, &set)?;
        let (ms, s) = timed(&case, repeats)?;
        rows.push(LevelRow {
            case: name.to_string(),
            level: name_l,
            film_nodes: s.derived.film_nodes,
            median_ms: ms,
            err_eccentricity: rel(s.eccentricity_ratio, truth.eccentricity_ratio),
            err_k: frob_rel(s.reduced.k_n_per_m, truth.reduced.k_n_per_m),
            err_c: frob_rel(s.reduced.c_ns_per_m, truth.reduced.c_ns_per_m),
            err_p_max: rel(s.p_max_pa, truth.p_max_pa),
            err_t_max: t_rise(&s).zip(t_rise(&truth)).map(|(a, b)| rel(a, b)),
            err_flows: flow_error(&s.flows_m3_per_s, &truth.flows_m3_per_s),
        });
    }
    rows.push(LevelRow {
        case: name.to_string(),
        level: "reference-fine (truth)".into(),
        film_nodes: truth.derived.film_nodes,
        median_ms: timed(&fine, 1)?.0,
        err_eccentricity: 0.0,
        err_k: 0.0,
        err_c: 0.0,
        err_p_max: 0.0,
        err_t_max: t_rise(&truth).map(|_| 0.0),
        err_flows: Some(0.0),
    });
    Ok(rows)
}

/// Time vs film nodes for uniformly refined meshes, and the least-squares exponent of t ∝ nodes^a.
fn growth(text: &str, repeats: usize) -> Result<(Vec<(usize, f64)>, f64)> {
    let mut pts = Vec::new();
    for (nx, nz, no) in [(12, 4, 3), (24, 8, 4), (48, 16, 6), (96, 32, 12), (192, 64, 24)] {
        let case = with_mesh(
            text,
            &[
                format!("mesh.circumferential_elements={nx}"),
                format!("mesh.axial_elements={nz}"),
                format!("mesh.orifice_elements={no}"),
            ],
        )?;
        let (ms, s) = timed(&case, repeats)?;
        pts.push((s.derived.film_nodes, ms));
    }
    #[allow(clippy::cast_precision_loss)]
    let (xs, ys): (Vec<f64>, Vec<f64>) = pts.iter().map(|&(n, t)| ((n as f64).ln(), t.ln())).unzip();
    #[allow(clippy::cast_precision_loss)]
    let m = xs.len() as f64;
    let (mx, my) = (xs.iter().sum::<f64>() / m, ys.iter().sum::<f64>() / m);
    let sxy: f64 = xs.iter().zip(&ys).map(|(x, y)| (x - mx) * (y - my)).sum();
    let sxx: f64 = xs.iter().map(|x| (x - mx).powi(2)).sum();
    Ok((pts, sxy / sxx))
}

/// Wall time of the isothermal solve and of the THD loop with BC1 and BC3 at standard fidelity:
/// `(case, [isothermal, BC1, BC3] ms, film nodes)`.
fn thermal_cost(texts: &[(&str, String)], repeats: usize) -> Result<Vec<(String, [f64; 3], usize)>> {
    let mut out = Vec::new();
    for file in ["compressor-bearing", "fillon-a"] {
        let Some((_, text)) = texts.iter().find(|(f, _)| *f == file) else { continue };
        let mut ms = [0.0; 3];
        let mut nodes = 0;
        for (i, model) in [("isothermal", "bc1"), ("thd", "bc1"), ("thd", "bc3")].iter().enumerate() {
            let case = with_mesh(
                text,
                &[
                    "mesh.fidelity=\"standard\"".into(),
                    format!("thermal.model=\"{}\"", model.0),
                    format!("thermal.pad_film_bc=\"{}\"", model.1),
                ],
            )?;
            let (t, s) = timed(&case, repeats)?;
            ms[i] = t;
            nodes = s.derived.film_nodes;
        }
        out.push((file.to_string(), ms, nodes));
    }
    Ok(out)
}

/// Error vs time on log–log axes, one marker per level, one line per case.
fn svg_plot(rows: &[LevelRow]) -> String {
    let (w, h, pad) = (640.0, 400.0, 60.0);
    let pts: Vec<&LevelRow> = rows.iter().filter(|r| r.err_k > 0.0).collect();
    let err = |r: &LevelRow| {
        r.err_eccentricity
            .max(r.err_k)
            .max(r.err_c)
            .max(r.err_p_max)
            .max(r.err_t_max.unwrap_or(0.0))
            .max(r.err_flows.unwrap_or(0.0))
            .max(1e-6)
    };
    let (tmin, tmax) = pts.iter().fold((f64::INFINITY, 0.0_f64), |(a, b), r| (a.min(r.median_ms), b.max(r.median_ms)));
    let (emin, emax) = pts.iter().fold((f64::INFINITY, 0.0_f64), |(a, b), r| (a.min(err(r)), b.max(err(r))));
    let (lt0, lt1) = ((tmin * 0.5).log10().floor(), (tmax * 2.0).log10().ceil());
    let (le0, le1) = ((emin * 0.5).log10().floor(), (emax * 2.0).log10().ceil());
    let x = |t: f64| pad + (t.log10() - lt0) / (lt1 - lt0) * (w - 1.5 * pad);
    let y = |e: f64| h - pad - (e.log10() - le0) / (le1 - le0) * (h - 1.5 * pad);
    let mut s = format!("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n");
    let _ = writeln!(
        s,
        "<line x1=\"{pad}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"black\"/>",
        h - pad,
        w - 0.5 * pad,
        h - pad
    );
    let _ = writeln!(s, "<line x1=\"{pad}\" y1=\"{}\" x2=\"{pad}\" y2=\"{}\" stroke=\"black\"/>", h - pad, 0.5 * pad);
    #[allow(clippy::cast_possible_truncation)]
    for d in lt0 as i32..=lt1 as i32 {
        let t = 10f64.powi(d);
        let _ = writeln!(s, "<text x=\"{:.1}\" y=\"{}\" text-anchor=\"middle\">{t} ms</text>", x(t), h - pad + 18.0);
    }
    #[allow(clippy::cast_possible_truncation)]
    for d in le0 as i32..=le1 as i32 {
        let e = 10f64.powi(d);
        let _ = writeln!(s, "<text x=\"{}\" y=\"{:.1}\" text-anchor=\"end\">1e{d}</text>", pad - 6.0, y(e) + 4.0);
    }
    let _ = writeln!(
        s,
        "<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">wall time per solve (release)</text>",
        w / 2.0,
        h - 12.0
    );
    let _ = writeln!(s, "<text x=\"14\" y=\"{}\" transform=\"rotate(-90 14 {})\" text-anchor=\"middle\">largest relative error (ε, K, C, p_max, T_max, flows)</text>", h / 2.0, h / 2.0);
    let colours = ["#440154", "#21918c", "#d07000", "#3b528b"];
    let mut cases: Vec<&str> = pts.iter().map(|r| r.case.as_str()).collect();
    cases.dedup();
    for (ci, c) in cases.iter().enumerate() {
        let col = colours[ci % colours.len()];
        let line: Vec<String> =
            pts.iter().filter(|r| r.case == *c).map(|r| format!("{:.1},{:.1}", x(r.median_ms), y(err(r)))).collect();
        let _ =
            writeln!(s, "<polyline points=\"{}\" fill=\"none\" stroke=\"{col}\" stroke-width=\"2\"/>", line.join(" "));
        for r in pts.iter().filter(|r| r.case == *c) {
            let _ = writeln!(
                s,
                "<circle cx=\"{:.1}\" cy=\"{:.1}\" r=\"4\" fill=\"{col}\"/><text x=\"{:.1}\" y=\"{:.1}\">{}</text>",
                x(r.median_ms),
                y(err(r)),
                x(r.median_ms) + 6.0,
                y(err(r)) - 6.0,
                r.level
            );
        }
        let _ = writeln!(
            s,
            "<text x=\"{}\" y=\"{}\" fill=\"{col}\">{c}</text>",
            w - 200.0,
            30.0 + 16.0 * f64::from(u32::try_from(ci).unwrap_or(0))
        );
    }
    s.push_str("</svg>\n");
    s
}

/// A level's cells from its name on: `| level | film nodes | time | errors… |`.
pub(super) fn level_cells(r: &LevelRow) -> String {
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

pub(super) fn pct(x: f64) -> String {
    if x == 0.0 {
        "—".into()
    } else {
        format!("{:.2} %", 100.0 * x)
    }
}

/// Runs the benchmark and writes the documents under `root`.
///
/// # Errors
/// Case, solve and I/O errors.
pub fn run(root: &Path, repeats: usize) -> Result<()> {
    run_parts(root, repeats, false)
}

/// The whole file, or (`table_only`) its first part: the fidelity table with its flow note and plot, the
/// targets, the thermal loop's cost and the cost growth, and `assets/fidelity.json`, the sections after it
/// kept as they are.
fn run_parts(root: &Path, repeats: usize, table_only: bool) -> Result<()> {
    let mut rows = Vec::new();
    let mut texts = Vec::new();
    let thd = vec!["thermal.model=\"thd\"".to_string(), "thermal.pad_film_bc=\"bc1\"".to_string()];
    let runs: [(&str, &str, Vec<String>); 4] = [
        ("compressor-bearing", "compressor-bearing", vec!["thermal.model=\"isothermal\"".to_string()]),
        ("compressor-bearing THD BC1", "compressor-bearing", thd),
        ("fillon-a THD BC1", "fillon-a", vec![]),
        ("test-rig", "test-rig", vec!["thermal.model=\"isothermal\"".to_string()]),
    ];
    for (label, file, extra) in &runs {
        let text = std::fs::read_to_string(root.join("cases").join(format!("{file}.toml")))?;
        super::interrupt::say(format!("bench: {label}"));
        rows.extend(levels(label, &text, extra, repeats)?);
        texts.push((*file, text));
    }
    super::interrupt::say("bench: cost growth");
    let (pts, exponent) = growth(&texts[0].1, repeats.min(3))?;
    super::interrupt::say("bench: thermal loop cost");
    let thermal = thermal_cost(&texts, repeats)?;
    let (cavitation, flow_note) = if table_only {
        super::interrupt::say("bench: flow note (JFO)");
        (String::new(), super::bench_cavitation::flow_note_measured(root, repeats.min(3))?)
    } else {
        super::bench_cavitation::measured(root, repeats.min(3))?
    };
    let machine = machine();
    let date = today();
    let mut md = String::new();
    let _ =
        writeln!(md, "# Performance\n\nGenerated by `cargo run --release -- bench` on {date}.\nMachine: {machine}.\n");
    let _ = writeln!(
        md,
        "Each time is the median of {repeats} complete solves in one process (mesh build, equilibrium — with the thermal loop for \
         THD rows —, full and synchronously reduced coefficients). Errors are relative to a reference-fine solution with twice \
         the reference level's element counts (K, C: Frobenius norm of the reduced 2×2 difference over the norm; T_max: the \
         hottest film temperature's rise above supply; flows: the worst of leading-edge, trailing-edge, side, orifice and \
         cavitation flows, each relative to itself, over those above 1 % of the throughput).\n"
    );
    let _ = writeln!(md, "| case | level | film nodes | time | ε error | K error | C error | p_max error | T_max error | flow error |\n|---|---|---|---|---|---|---|---|---|---|");
    for r in &rows {
        let _ = writeln!(md, "| {} {}", r.case, level_cells(r));
    }
    md.push_str(&flow_note);
    let _ = writeln!(md, "\n![error vs time](performance-error-vs-time.svg)\n");
    let _ = writeln!(md, "## Targets (compressor bearing, 5 pads)\n\n| target | measured | status |\n|---|---|---|");
    for (level, limit) in [("preview", 15.0), ("standard", 100.0)] {
        if let Some(r) = rows.iter().find(|r| r.case == "compressor-bearing" && r.level == level) {
            let status = if r.median_ms <= limit {
                "met".to_string()
            } else {
                format!("missed by {:.1} ms", r.median_ms - limit)
            };
            let _ = writeln!(md, "| isothermal {level} ≤ {limit} ms | {:.1} ms | {status} |", r.median_ms);
        }
    }
    if let Some(r) = rows.iter().find(|r| r.case == "compressor-bearing THD BC1" && r.level == "standard") {
        let status =
            if r.median_ms <= 300.0 { "met".to_string() } else { format!("missed by {:.1} ms", r.median_ms - 300.0) };
        let _ = writeln!(md, "| THD (BC1) standard ≤ 300 ms | {:.1} ms | {status} |", r.median_ms);
    }
    let _ = writeln!(
        md,
        "\n## Cost of the thermal loop (standard fidelity)\n\n| case | film nodes | isothermal | THD BC1 | THD BC3 | BC1 / isothermal | BC1 saves vs BC3 |\n|---|---|---|---|---|---|---|"
    );
    for (case, ms, nodes) in &thermal {
        let _ = writeln!(
            md,
            "| {case} | {nodes} | {:.1} ms | {:.1} ms | {:.1} ms | {:.1}× | {:.0} % |",
            ms[0],
            ms[1],
            ms[2],
            ms[1] / ms[0],
            100.0 * (1.0 - ms[1] / ms[2])
        );
    }
    let _ = writeln!(
        md,
        "\n## Cost growth\n\nCompressor bearing, uniformly refined meshes:\n\n| film nodes | time |\n|---|---|"
    );
    for (n, t) in &pts {
        let _ = writeln!(md, "| {n} | {t:.1} ms |");
    }
    #[allow(clippy::cast_precision_loss)]
    let range = pts.last().map_or(0.0, |p| p.0 as f64) / pts.first().map_or(1.0, |p| p.0 as f64);
    let _ = writeln!(md, "\nFitted t ∝ nodes^a over a {range:.0}× range: **a = {exponent:.2}** (sparse Cholesky of a 2-D grid with nested-dissection-like ordering grows as n^1.5 at worst; the coupled Newton needs a nearly constant number of film solves).");
    if table_only {
        let doc = std::fs::read_to_string(root.join("docs").join("PERFORMANCE.md"))?;
        let rest = doc.find(&format!("\n{}", super::bench_batch::HEADING)).map_or("", |i| &doc[i..]);
        md.push_str(rest);
    } else {
        md.push_str(&sections(root, repeats, &cavitation)?);
    }
    write_atomic(&root.join("docs").join("PERFORMANCE.md"), md.as_bytes())?;
    write_atomic(&root.join("docs").join("performance-error-vs-time.svg"), svg_plot(&rows).as_bytes())?;
    let table = FidelityTable {
        generated: date,
        machine,
        case: "compressor-bearing".into(),
        rows: rows.iter().filter(|r| r.case.starts_with("compressor-bearing")).cloned().collect(),
    };
    std::fs::create_dir_all(root.join("assets"))?;
    write_atomic(&root.join("assets").join("fidelity.json"), serde_json::to_string_pretty(&table)?.as_bytes())?;
    println!("wrote docs/PERFORMANCE.md, docs/performance-error-vs-time.svg, assets/fidelity.json");
    Ok(())
}

/// Every section after the first part, the notes and the carried-over sections.
fn sections(root: &Path, repeats: usize, cavitation: &str) -> Result<String> {
    let mut md = String::new();
    md.push_str(&super::bench_batch::section(root, repeats.min(3))?);
    md.push_str(&super::bench_frf::section(root, repeats)?);
    md.push_str(&super::bench_flex::section(root, repeats.min(3))?);
    md.push_str(cavitation);
    md.push_str(&super::bench_rotor::section(root, repeats.min(3))?);
    md.push_str(&super::bench_turb::section(root, repeats.min(3))?);
    md.push_str(&super::bench_control::section(root, repeats.min(3))?);
    md.push_str(&super::bench_sommerfeld::section(root, repeats.min(3))?);
    md.push_str(&super::bench_feeding::section(root, repeats.min(3))?);
    md.push_str(&super::bench_flows::section(root)?);
    md.push_str(&super::bench_estimates::section(root)?);
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
    write_atomic(&path, out.as_bytes())?;
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
        "\n*Measured alone (`bench --only {only}`) on {}; the machine's speed then: the calibration solve (compressor \
         bearing, isothermal, standard fidelity, median of 7) took {before_ms:.1} ms before the section and {after_ms:.1} ms \
         after it{against}.*\n",
        today()
    )
}

/// `bench --only SECTION` (or every section when `only` is `None`): replaces that section of
/// docs/PERFORMANCE.md, closed by a line with the machine's speed at the time ([`calibration_note`]).
///
/// # Errors
/// An unknown section, a failed measurement, I/O.
pub fn run_only(root: &Path, only: Option<&str>, repeats: usize) -> Result<()> {
    const SECTIONS: [&str; 11] = [
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
    let Some(only) = only else { return run(root, repeats.max(1)) };
    if only == "table" {
        return run_parts(root, repeats.max(1), true);
    }
    if !SECTIONS.contains(&only) {
        anyhow::bail!("--only {only}: known sections: {}", SECTIONS.join(", "));
    }
    let few = repeats.clamp(1, 3);
    let before = calibration_ms(root)?;
    let (heading, section) = match only {
        "frf" => ("## Controllable lubrication", super::bench_frf::section(root, repeats.max(1))?),
        "cavitation" => (super::bench_cavitation::HEADING, super::bench_cavitation::section(root, few)?),
        "flex" => ("## Flexible pads", super::bench_flex::section(root, few)?),
        "rotor" => ("## Rotor–bearing analysis", super::bench_rotor::section(root, repeats.max(1))?),
        "turbulence" => ("## Turbulence", super::bench_turb::section(root, few)?),
        "control" => ("## Active control", super::bench_control::section(root, few)?),
        "sommerfeld" => (super::bench_sommerfeld::HEADING, super::bench_sommerfeld::section(root, few)?),
        "feeding" => (super::bench_feeding::HEADING, super::bench_feeding::section(root, few)?),
        "flows" => (super::bench_flows::HEADING, super::bench_flows::section(root)?),
        _ => (super::bench_estimates::HEADING, super::bench_estimates::section(root)?),
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
        assert!(note.contains("`bench --only feeding`"), "{note}");
        assert!(note.contains("120.0 ms before the section and 130.0 ms after it against 45.8 ms"), "{note}");
        assert!(note.contains("about 2.7×"), "{note}");
        assert!(!calibration_note("feeding", 120.0, 130.0, None).contains("first table"));
    }
}
