//! Bench section: flows against the mesh on every shipped case. Each case as shipped (its own cavitation
//! condition and thermal model) and with the mass-conserving film (`physics.cavitation = "jfo"`), at the
//! standard level against twice the reference level's element counts: the worst relative flow error (as in
//! the first table, [`tiltpad::study::fidelity::worst_flow`]), which flow it is, and the oil the Reynolds
//! condition creates in cavitated zones (the report's warning) as a share of the leading-edge inflow.
//! A thermal case whose film and pads are solved as one coupled system (BC3) is measured against the
//! reference level itself: twice its mesh took more than 35 min and 9 GB here (88 s at reference).

use std::fmt::Write as _;
use std::path::Path;

use anyhow::Result;

use tiltpad::bearing::report::warning::Warning;
use tiltpad::bearing::{solve_case, Solution};
use tiltpad::model::case::{Case, PadFilmBc, ThermalModelKind};
use tiltpad::study::fidelity::{finer_overrides, worst_flow};

use super::{pct, with_mesh};

pub const HEADING: &str = "## Flows against the mesh, every shipped case";

/// The share of the leading-edge inflow the cavitation condition creates ([`Warning::CavitationCreatesOil`]).
fn created_share(s: &Solution) -> Option<f64> {
    s.report.warnings.iter().find_map(|w| match w {
        Warning::CavitationCreatesOil { share_of_inflow, .. } => Some(*share_of_inflow),
        _ => None,
    })
}

/// The worst flow at standard against the reference-fine mesh: its relative error and name (`None`: no
/// flow above 1 % of the throughput), and the share of oil the cavitation condition creates; or why not:
/// `refused` (the case's validation refuses the variant, e.g. a ram pressure with the mass-conserving inlet)
/// or `failed` (a solve failed), with the error's first words.
type FlowCells = Result<(Option<(f64, &'static str)>, Option<f64>), (&'static str, String)>;

fn flow_cells(text: &str, extra: &[String], truth: Truth) -> FlowCells {
    let case = |set: &[String]| with_mesh(text, set).map_err(|e| ("refused", first_words(&e.to_string())));
    let solve = |set: &[String]| solve_case(&case(set)?).map_err(|e| ("failed", first_words(&e.to_string())));
    let mut standard = extra.to_vec();
    standard.push("mesh.fidelity=\"standard\"".into());
    let fine = match truth {
        Truth::ReferenceFine => finer_overrides(&case(extra)?, extra),
        Truth::Reference => {
            let mut set = extra.to_vec();
            set.push("mesh.fidelity=\"reference\"".into());
            set
        }
    };
    match (solve(&standard), solve(&fine)) {
        (Ok(s), Ok(t)) => Ok((worst_flow(&s.flows_m3_per_s, &t.flows_m3_per_s), created_share(&s))),
        (Err(e), _) | (_, Err(e)) => Err(e),
    }
}

/// The mesh the flows are measured against.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Truth {
    /// Twice the reference level's element counts.
    ReferenceFine,
    /// The reference level: a coupled film–pad (BC3) thermal case, whose reference-fine solve is too large here.
    Reference,
}

impl Truth {
    fn of(case: &Case) -> Self {
        if case.thermal.model == ThermalModelKind::Thd && case.thermal.pad_film_bc == PadFilmBc::Bc3 {
            Self::Reference
        } else {
            Self::ReferenceFine
        }
    }

    fn cell(self) -> &'static str {
        match self {
            Self::ReferenceFine => "reference ×2",
            Self::Reference => "reference",
        }
    }
}

/// The error and flow columns of [`FlowCells`].
fn error_cells(cells: &FlowCells) -> (String, String) {
    match cells {
        Ok((Some((e, name)), _)) => (pct(*e), (*name).to_string()),
        Ok((None, _)) => ("—".into(), "no flow above 1 %".into()),
        Err((what, why)) => ((*what).to_string(), why.clone()),
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
         (the report's warning; a share of the leading-edge inflow, — when below 1 %). A thermal case whose film and \
         pads are solved as one coupled system (BC3) is measured against the reference level itself (\"against\"): \
         twice its mesh took more than 35 min and 9 GB here. With the second-order convergence of the flows, an error \
         against the reference level is about 86 % of the error against the converged value (the reference element \
         is 2.7 times smaller than the standard one).\n\n\
         | case | against | cavitation as shipped | worst flow error | worst flow | oil created | JFO: worst flow error | JFO: worst flow |\n\
         |---|---|---|---|---|---|---|---|\n"
    );
    let jfo = ["physics.cavitation=\"jfo\"".to_string()];
    let mut worst_jfo: Option<(f64, String)> = None;
    let mut refused_jfo = Vec::new();
    for name in &names {
        super::say(format!("bench: flows: {name}"));
        let text = std::fs::read_to_string(root.join("cases").join(name))?;
        let (shipped, truth) = match tiltpad::model::load_case(&text, &[]) {
            Ok((_, c)) => (format!("{:?}", c.physics.cavitation).to_lowercase(), Truth::of(&c)),
            Err(e) => {
                let _ = writeln!(md, "| `{name}` | | {} | | | | | |", first_words(&e.to_string()));
                continue;
            }
        };
        let as_shipped = flow_cells(&text, &[], truth);
        let jfo_cells = if shipped == "jfo" { None } else { Some(flow_cells(&text, &jfo, truth)) };
        let jfo_error = match jfo_cells.as_ref().unwrap_or(&as_shipped) {
            Ok((Some((e, _)), _)) => Some(*e),
            _ => None,
        };
        if let Some(Err(("refused", _))) = &jfo_cells {
            refused_jfo.push(format!("`{name}`"));
        }
        if let Some(e) = jfo_error {
            if worst_jfo.as_ref().is_none_or(|(w, _)| e > *w) {
                worst_jfo = Some((e, name.clone()));
            }
        }
        let (err, flow) = error_cells(&as_shipped);
        let (jerr, jflow) = jfo_cells.as_ref().map_or(("(as shipped)".into(), String::new()), error_cells);
        let created = match &as_shipped {
            Ok((_, Some(c))) => pct(*c),
            _ => "—".into(),
        };
        let row =
            format!("| `{name}` | {} | {shipped} | {err} | {flow} | {created} | {jerr} | {jflow} |", truth.cell());
        // each row on standard error as it is measured: the section takes about an hour, and a run stopped
        // before its end still leaves the rows it finished
        eprintln!("{row}");
        let _ = writeln!(md, "{row}");
    }
    if let Some((w, name)) = worst_jfo {
        let refused = if refused_jfo.is_empty() {
            String::new()
        } else {
            format!(" The variant is refused for {} (the reason in each row).", refused_jfo.join(", "))
        };
        let _ = writeln!(
            md,
            "\nWith the mass-conserving film the worst flow error at standard is {} (`{name}`).{refused}",
            pct(w)
        );
    }
    Ok(md)
}
