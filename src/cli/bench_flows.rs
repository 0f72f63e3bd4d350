//! Bench section: flows against the mesh on every shipped case. Each case as shipped (its own cavitation
//! condition and thermal model) and with the mass-conserving film (`physics.cavitation = "jfo"`), at the
//! standard level against twice the reference level's element counts: the worst relative flow error (as in
//! the first table: leading edges, trailing edges, sides, orifices, into cavitation, each against itself,
//! over those carrying at least 1 % of the throughput), which flow it is, and the oil the Reynolds
//! condition creates in cavitated zones (the report's warning) as a share of the leading-edge inflow.

use std::fmt::Write as _;
use std::path::Path;

use anyhow::Result;

use crate::bearing::report::warning::Warning;
use crate::bearing::solution::BearingFlows;
use crate::bearing::{solve_case, Solution};
use crate::model::Fidelity;

use super::bench::{pct, with_mesh};

pub const HEADING: &str = "## Flows against the mesh, every shipped case";

/// The overrides of twice the reference level's element counts (the first table's truth).
fn reference_fine() -> Vec<String> {
    let (nx, nz, no) = Fidelity::Reference.elements();
    vec![
        "mesh.fidelity=\"reference\"".into(),
        format!("mesh.circumferential_elements={}", 2 * nx),
        format!("mesh.axial_elements={}", 2 * nz),
        format!("mesh.orifice_elements={}", 2 * no),
        "mesh.max_nodes=2000000".into(),
    ]
}

/// The worst flow's relative error and its name, over the flows above 1 % of the throughput.
fn worst_flow(flows: &BearingFlows, truth: &BearingFlows) -> Option<(f64, &'static str)> {
    let parts = |f: &BearingFlows| {
        [
            ("leading edges", f.leading_edges_in),
            ("trailing edges", f.trailing_edges_out),
            ("sides", f.sides_out),
            ("orifices", f.orifices_in),
            ("into cavitation", f.to_cavitation),
        ]
    };
    let throughput: f64 = parts(truth).iter().map(|(_, v)| v.abs()).sum();
    parts(flows)
        .iter()
        .zip(parts(truth))
        .filter(|(_, (_, t))| throughput > 0.0 && t.abs() >= 0.01 * throughput)
        .map(|((name, a), (_, t))| (((a - t) / t).abs(), *name))
        .max_by(|a, b| a.0.total_cmp(&b.0))
}

/// The share of the leading-edge inflow the cavitation condition creates ([`Warning::CavitationCreatesOil`]).
fn created_share(s: &Solution) -> Option<f64> {
    s.report.warnings.iter().find_map(|w| match w {
        Warning::CavitationCreatesOil { share_of_inflow, .. } => Some(*share_of_inflow),
        _ => None,
    })
}

/// One cell pair of the table: the worst flow error at standard and its flow, or why there is none.
fn cells(text: &str, extra: &[String]) -> (String, String, Option<f64>) {
    let solve = |set: &[String]| with_mesh(text, set).and_then(|c| Ok(solve_case(&c)?));
    let mut standard = extra.to_vec();
    standard.push("mesh.fidelity=\"standard\"".into());
    let fine: Vec<String> = extra.iter().cloned().chain(reference_fine()).collect();
    match (solve(&standard), solve(&fine)) {
        (Ok(s), Ok(t)) => {
            let created = created_share(&s);
            match worst_flow(&s.flows_m3_per_s, &t.flows_m3_per_s) {
                Some((e, name)) => (pct(e), name.to_string(), created),
                None => ("—".into(), "no flow above 1 %".into(), created),
            }
        }
        (Err(e), _) | (_, Err(e)) => ("failed".into(), first_words(&e.to_string()), None),
    }
}

/// An error's first sentence, short enough for a table cell.
fn first_words(text: &str) -> String {
    let t = text.split(": ").take(2).collect::<Vec<_>>().join(": ");
    t.chars().take(90).collect()
}

/// The markdown section.
///
/// # Errors
/// The cases folder cannot be read.
pub fn section(root: &Path) -> Result<String> {
    let mut names: Vec<String> = std::fs::read_dir(root.join("cases"))?
        .filter_map(Result::ok)
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| Path::new(n).extension().is_some_and(|x| x == "toml"))
        .collect();
    names.sort();
    let mut md = format!(
        "\n{HEADING}\n\nEvery case of `cases/` as shipped (its cavitation condition and thermal model) and with the \
         mass-conserving film (`physics.cavitation = \"jfo\"`), at the standard level against twice the reference \
         level's element counts: the worst relative flow error over the flows carrying at least 1 % of the throughput \
         (as in the first table), which flow that is, and the oil the shipped condition creates in cavitated zones \
         (the report's warning; a share of the leading-edge inflow, — when below 1 %).\n\n\
         | case | cavitation as shipped | worst flow error | worst flow | oil created | JFO: worst flow error | JFO: worst flow |\n\
         |---|---|---|---|---|---|---|\n"
    );
    let jfo = ["physics.cavitation=\"jfo\"".to_string()];
    let mut worst_jfo: Option<(f64, String)> = None;
    for name in &names {
        super::interrupt::say(format!("bench: flows: {name}"));
        let text = std::fs::read_to_string(root.join("cases").join(name))?;
        let shipped = crate::model::load_case(&text, &[]).map(|(_, c)| c.physics.cavitation);
        let shipped = match shipped {
            Ok(c) => format!("{c:?}").to_lowercase(),
            Err(e) => {
                let _ = writeln!(md, "| `{name}` | {} | | | | | |", first_words(&e.to_string()));
                continue;
            }
        };
        let (err, flow, created) = cells(&text, &[]);
        let (jerr, jflow) = if shipped == "jfo" {
            ("(as shipped)".to_string(), String::new())
        } else {
            let (e, f, _) = cells(&text, &jfo);
            (e, f)
        };
        let je = if shipped == "jfo" { &err } else { &jerr };
        if let Ok(v) = je.trim_end_matches(" %").parse::<f64>() {
            if worst_jfo.as_ref().is_none_or(|(w, _)| v > *w) {
                worst_jfo = Some((v, name.clone()));
            }
        }
        let created = created.map_or("—".into(), pct);
        let _ = writeln!(md, "| `{name}` | {shipped} | {err} | {flow} | {created} | {jerr} | {jflow} |");
    }
    if let Some((w, name)) = worst_jfo {
        let _ =
            writeln!(md, "\nWith the mass-conserving film the worst flow error at standard is {w:.2} % (`{name}`).");
    }
    Ok(md)
}

#[cfg(test)]
mod tests {
    use super::worst_flow;
    use crate::bearing::solution::BearingFlows;

    /// The worst flow is named, and a flow below 1 % of the throughput is left out however far off it is.
    #[test]
    fn the_worst_flow_is_named_and_flows_below_one_percent_of_the_throughput_are_left_out() {
        let truth = BearingFlows {
            leading_edges_in: 10.0,
            trailing_edges_out: 4.0,
            sides_out: 5.95,
            orifices_in: 0.0,
            to_cavitation: 0.05,
            ..BearingFlows::default()
        };
        let flows = BearingFlows {
            leading_edges_in: 10.2,
            trailing_edges_out: 4.2,
            sides_out: 5.9,
            to_cavitation: 0.5,
            ..truth
        };
        let (e, name) = worst_flow(&flows, &truth).unwrap();
        assert_eq!(name, "trailing edges");
        assert!((e - 0.05).abs() < 1e-12, "{e}");
        assert_eq!(worst_flow(&truth, &BearingFlows::default()), None);
    }
}
