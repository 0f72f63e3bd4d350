//! Command-line interface: `tiltpad solve`, `sweep`, `sommerfeld`, `batch`, `coefficients`, `modes`, `frf`, `rotor`, `control`, `fidelity`, `schema`, `convergence-map`.
//!
//! Engineering units at this edge only; JSON and CSV outputs are SI or carry their unit in each name.
//! Every output path may be `-` (standard output); human-readable text then goes to standard error, which
//! also receives every error, with a non-zero exit status. Files are written safely ([`crate::io`]).
//! Native only (the web workbench exports a solution's JSON form through
//! [`crate::bearing::solution::json`]).

mod batch;
mod coefficients;
mod command;
pub mod control;
mod convergence_map;
mod fidelity;
pub mod frf;
mod inputs;
pub mod interrupt;
pub mod modes;
mod progress;
pub mod rotor;
mod rotor_map;
mod rows;
mod solve;
mod sommerfeld;
mod sweep;
mod vtu;

use std::path::{Path, PathBuf};

use anyhow::{Context, Result};

use crate::model::{load_case, Case, CaseFile};

pub use crate::bearing::solution::json::solution_json;
pub use crate::scene::summary_text::summary_text;
pub use command::{Cli, Command};

/// Reads and validates a case file with overrides.
///
/// # Errors
/// I/O and every case error, with the file name.
pub fn read_case(path: &Path, set: &[String]) -> Result<(CaseFile, Case)> {
    let text = crate::io::read::read_text(path, "case file")?;
    for note in crate::model::replaced_keys(&text, set).unwrap_or_default() {
        eprintln!("note: {note}");
    }
    load_case(&text, set).with_context(|| format!("invalid case {}", path.display()))
}

/// Writes a file safely (see [`crate::io::safe_write`]).
///
/// # Errors
/// I/O errors, naming the path.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<()> {
    Ok(crate::io::write_file(path, bytes)?)
}

fn is_stdout(p: Option<&PathBuf>) -> bool {
    p.is_some_and(|p| p.as_os_str() == "-")
}

/// Runs a CLI command.
///
/// # Errors
/// Case, solve and I/O errors (printed by `main` on standard error).
pub fn run(command: Command) -> Result<()> {
    interrupt::install(&std::env::args().nth(1).unwrap_or_default());
    match command {
        Command::Solve { case, set, json, vtu } => solve::solve(&case, &set, json.as_ref(), vtu.as_ref()),
        Command::Fidelity { case, set, repeats, json, csv, max_hours } => {
            inputs::check_outputs(&[("case file", &case)], &[("--json", json.as_deref()), ("--csv", csv.as_deref())])?;
            fidelity::run(&fidelity::FidelityArgs {
                case: &case,
                set: &set,
                repeats: usize::from(repeats),
                json,
                csv,
                max_hours,
            })
        }
        Command::Sweep { case, vary, param, from, to, steps, set, csv, jsonl, vtu, max_points, max_hours } => {
            let mut axes = Vec::new();
            if let Some(key) = param {
                let (Some(from), Some(to)) = (from, to) else { anyhow::bail!("--param needs --from and --to") };
                if !(from.is_finite() && to.is_finite()) {
                    anyhow::bail!("--from {from} --to {to}: both must be finite numbers");
                }
                if steps < 1 {
                    anyhow::bail!("--steps must be at least 1");
                }
                axes.push(crate::study::Axis::linspace(&key, from, to, steps));
            }
            for spec in &vary {
                axes.push(crate::study::Axis::parse(spec)?);
            }
            let outputs = [("--csv", csv.as_deref()), ("--jsonl", jsonl.as_deref()), ("--vtu", vtu.as_deref())];
            inputs::check_outputs(&[("case file", &case)], &outputs)?;
            sweep::run(sweep::SweepArgs { case: &case, axes, set: &set, csv, jsonl, vtu, max_points, max_hours })
        }
        Command::Sommerfeld { case, set, points, csv, json } => {
            inputs::check_outputs(&[("case file", &case)], &[("--csv", csv.as_deref()), ("--json", json.as_deref())])?;
            sommerfeld::run(&sommerfeld::SommerfeldArgs { case: &case, set: &set, points, csv, json })
        }
        Command::Batch { designs, case, set, shard, csv, jsonl, max_points, max_hours } => {
            let shard = shard.as_deref().map_or(Ok(crate::study::Shard::ALL), crate::study::Shard::parse)?;
            inputs::check_outputs(
                &[("designs table", &designs), ("case file", &case)],
                &[("--csv", csv.as_deref()), ("--jsonl", jsonl.as_deref())],
            )?;
            batch::run(&batch::BatchArgs {
                designs: &designs,
                case: &case,
                set: &set,
                shard,
                csv,
                jsonl,
                max_points,
                max_hours,
            })
        }
        Command::Coefficients(args) => {
            inputs::check_outputs(
                &[("case file", &args.case)],
                &[("--ross", args.ross.as_deref()), ("--csv", args.csv.as_deref())],
            )?;
            coefficients::run(&args)
        }
        Command::Modes { case, set, count, table, json, csv } => {
            inputs::check_outputs(&[("case file", &case)], &[("--json", json.as_deref()), ("--csv", csv.as_deref())])?;
            modes::run(&modes::ModeArgs { case: &case, set: &set, count: usize::from(count), table, json, csv })
        }
        Command::Frf { case, set, from, to, points, amplitude_v, csv, control, loop_csv, json } => {
            inputs::check_outputs(&[("case file", &case)], &[("--csv", csv.as_deref()), ("--json", json.as_deref())])?;
            frf::run(&frf::FrfArgs {
                case: &case,
                set: &set,
                from_hz: from,
                to_hz: to,
                points,
                amplitude_v,
                csv,
                json,
                control: control.as_deref(),
                loop_csv,
            })
        }
        Command::Schema { rotor, json } => {
            use crate::model::{control_schema::CONTROL_KEYS, rotor_schema::ROTOR_KEYS, schema};
            match json {
                Some(out) => {
                    let table = if rotor {
                        let mut t = schema::json_table_of(ROTOR_KEYS);
                        if let (Some(a), serde_json::Value::Array(b)) =
                            (t.as_array_mut(), schema::json_table_of(CONTROL_KEYS))
                        {
                            a.extend(b);
                        }
                        t
                    } else {
                        schema::json_table()
                    };
                    let mut text = serde_json::to_string_pretty(&table)?;
                    text.push('\n');
                    write_atomic(&out, text.as_bytes())?;
                    rows::announce(&out);
                }
                None if rotor => {
                    print!("{}{}", schema::text_table_of(ROTOR_KEYS), schema::text_table_of(CONTROL_KEYS));
                }
                None => print!("{}", schema::text_table()),
            }
            Ok(())
        }
        Command::Rotor { rotor, range, coefficients, shaft_modes, critical_map, json, csv } => {
            inputs::check_outputs(
                &[("rotor file", &rotor)],
                &[("--json", json.as_deref()), ("--csv", csv.as_deref())],
            )?;
            let args = rotor::RotorArgs {
                rotor: &rotor,
                speeds: &range.speeds,
                max_points: range.max_points,
                max_hours: range.max_hours,
                coefficients: coefficients.map(|c| {
                    if c == "full" {
                        crate::model::rotor::CoefficientModel::Full
                    } else {
                        crate::model::rotor::CoefficientModel::Reduced
                    }
                }),
                shaft_modes: shaft_modes.map(usize::from),
                json,
                csv,
            };
            if critical_map {
                rotor_map::run(&args)
            } else {
                rotor::run(&args)
            }
        }
        Command::Control {
            rotor,
            range,
            gain,
            gain_sweep,
            root_locus,
            json,
            nyquist_curves,
            csv,
            gain_csv,
            locus_csv,
        } => {
            inputs::check_outputs(
                &[("rotor file", &rotor)],
                &[
                    ("--json", json.as_deref()),
                    ("--csv", csv.as_deref()),
                    ("--gain-csv", gain_csv.as_deref()),
                    ("--locus-csv", locus_csv.as_deref()),
                ],
            )?;
            control::run(&control::ControlArgs {
                rotor: &rotor,
                speeds: &range.speeds,
                max_points: range.max_points,
                max_hours: range.max_hours,
                gain,
                gain_sweep: gain_sweep.as_deref(),
                root_locus_rpm: root_locus,
                json,
                nyquist_curves,
                csv,
                gain_csv,
                locus_csv,
            })
        }
        Command::ConvergenceMap { quick, step_deg, csv, update_doc, only, only_points, root } => {
            let spec = crate::study::convergence::MapSpec {
                direction_step_deg: if quick { 30.0 } else { step_deg },
                ..crate::study::convergence::MapSpec::full()
            };
            let points = only_points.as_deref().map_or(Ok(Vec::new()), |p| convergence_map::parse_points(p, &spec))?;
            convergence_map::run(
                &root,
                &convergence_map::Selection { quick, step_deg, only, points },
                csv.as_deref(),
                update_doc,
            )
        }
    }
}
