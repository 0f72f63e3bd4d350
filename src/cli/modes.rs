//! `tiltpad modes`: each pad's bending modes on its pivot (frequency, modal mass and stiffness, how the
//! eigen-solution went), and with `--table` the mesh-convergence table of the first pad's modes in the style
//! of the thesis's Table 3.1 (film meshes of 72 … 882 elements, two solid elements per film element through
//! the thickness as there, plus our finer reference). JSON (`--json`) and CSV (`--csv`), SI with units in
//! the names.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use anyhow::{Context, Result};
use serde::Serialize;

use crate::bearing::film::flex::{mode_table, pad_solid_modes, ModeCache, ModeTableRow};
use crate::bearing::film::model::pad_grid;

use super::rows::announce;
use super::{read_case, write_atomic};

/// Meshes of the convergence table: (circumferential, axial over the modelled part, layers). The first six
/// follow the thesis's progression (n × n/2 film elements, 2 layers); the last is the reference.
pub const TABLE_MESHES: [(usize, usize, usize); 7] =
    [(12, 6, 2), (18, 9, 2), (24, 12, 2), (30, 15, 2), (36, 18, 2), (42, 21, 2), (84, 42, 8)];

/// One mode of one pad.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ModeRow {
    pub pad: usize,
    pub mode: usize,
    pub frequency_hz: f64,
    pub modal_mass_kg: f64,
    pub modal_stiffness_n_per_m: f64,
    /// Reduced unknowns of the pad solid, subspace iterations and the pair's relative residual.
    pub unknowns: usize,
    pub iterations: usize,
    pub residual: f64,
    pub seconds: f64,
}

#[derive(Debug, Serialize)]
struct Output {
    modes: Vec<ModeRow>,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    table: Vec<ModeTableRow>,
}

/// Arguments of `tiltpad modes`.
pub struct ModeArgs<'a> {
    pub case: &'a Path,
    pub set: &'a [String],
    pub count: usize,
    pub table: bool,
    pub json: Option<PathBuf>,
    pub csv: Option<PathBuf>,
}

/// The modes of every tilting pad with thickness, on the case's own mesh.
///
/// # Errors
/// Elastic-model failures, naming the pad.
pub fn pad_mode_rows(case: &crate::model::Case, count: usize) -> Result<Vec<ModeRow>> {
    let mut cache = ModeCache::new();
    let mut rows = Vec::new();
    for (k, pad) in case.bearing.pads.iter().enumerate() {
        if pad.kind != crate::model::PadKind::Tilting || pad.thickness_m <= 0.0 {
            continue;
        }
        let grid = pad_grid(case, k);
        let flex = pad_solid_modes(case, k, &grid, case.mesh.pad_radial_elements, count, &mut cache)?;
        let r = &flex.modes.report;
        for (i, m) in flex.modes.modes.iter().enumerate() {
            rows.push(ModeRow {
                pad: k,
                mode: i,
                frequency_hz: m.frequency_hz,
                modal_mass_kg: m.mass,
                modal_stiffness_n_per_m: m.stiffness,
                unknowns: r.unknowns,
                iterations: r.iterations,
                residual: r.residuals.get(i + 1).copied().unwrap_or(f64::NAN),
                seconds: r.seconds,
            });
        }
    }
    Ok(rows)
}

fn text(rows: &[ModeRow], table: &[ModeTableRow]) -> String {
    let mut s = String::from("pad  mode  frequency [Hz]  modal mass [kg]  modal stiffness [N/m]  unknowns  residual\n");
    for r in rows {
        let _ = writeln!(
            s,
            "{:>3}  {:>4}  {:>14.1}  {:>15.4e}  {:>21.4e}  {:>8}  {:>8.1e}",
            r.pad, r.mode, r.frequency_hz, r.modal_mass_kg, r.modal_stiffness_n_per_m, r.unknowns, r.residual
        );
    }
    if !table.is_empty() {
        s.push_str("\nmesh  film elements  solid elements  frequencies [Hz] (relative error vs the last mesh)\n");
        for (i, r) in table.iter().enumerate() {
            let cols: Vec<String> = r
                .frequencies_hz
                .iter()
                .zip(&r.relative_error)
                .map(|(f, e)| format!("{f:.1} ({:.2} %)", 100.0 * e))
                .collect();
            let _ = writeln!(s, "{:>4}  {:>13}  {:>14}  {}", i + 1, r.film_elements, r.solid_elements, cols.join("  "));
        }
    }
    s
}

fn csv(rows: &[ModeRow], table: &[ModeTableRow]) -> String {
    let mut s = String::new();
    if table.is_empty() {
        s.push_str("pad,mode,frequency_hz,modal_mass_kg,modal_stiffness_n_per_m,unknowns,iterations,residual\n");
        for r in rows {
            let _ = writeln!(
                s,
                "{},{},{},{},{},{},{},{}",
                r.pad,
                r.mode,
                r.frequency_hz,
                r.modal_mass_kg,
                r.modal_stiffness_n_per_m,
                r.unknowns,
                r.iterations,
                r.residual
            );
        }
    } else {
        s.push_str("mesh,film_elements,solid_elements,layers,mode,frequency_hz,relative_error,unknowns,seconds\n");
        for (i, r) in table.iter().enumerate() {
            for (m, (f, e)) in r.frequencies_hz.iter().zip(&r.relative_error).enumerate() {
                let _ = writeln!(
                    s,
                    "{},{},{},{},{m},{f},{e},{},{}",
                    i + 1,
                    r.film_elements,
                    r.solid_elements,
                    r.layers,
                    r.unknowns,
                    r.seconds
                );
            }
        }
    }
    s
}

/// Computes and writes the modes.
///
/// # Errors
/// Invalid case, elastic-model failure, or an output that cannot be written.
pub fn run(args: &ModeArgs<'_>) -> Result<()> {
    let (_, case) = read_case(args.case, args.set)?;
    let count = args.count;
    let table_unknowns: Vec<usize> = if args.table {
        TABLE_MESHES.iter().map(|&(nc, nz, layers)| 3 * (nc + 1) * (nz + 1) * (layers + 1)).collect()
    } else {
        Vec::new()
    };
    let estimate = crate::study::estimate::Estimate::pad_modes(&case, count, &table_unknowns);
    super::inputs::check_work(&estimate, f64::INFINITY)?;
    let rows = pad_mode_rows(&case, count).with_context(|| format!("pad modes of {}", args.case.display()))?;
    let first = case.bearing.pads.iter().position(|p| p.kind == crate::model::PadKind::Tilting && p.thickness_m > 0.0);
    let table = match (args.table, first) {
        (true, Some(k)) => mode_table(&case, k, &TABLE_MESHES, count)?,
        _ => Vec::new(),
    };
    let to_stdout = [&args.json, &args.csv].iter().any(|p| p.as_ref().is_some_and(|p| p.as_os_str() == "-"));
    if to_stdout {
        eprint!("{}", text(&rows, &table));
    } else {
        print!("{}", text(&rows, &table));
    }
    if let Some(out) = &args.json {
        let mut t = serde_json::to_string_pretty(&Output { modes: rows.clone(), table: table.clone() })?;
        t.push('\n');
        write_atomic(out, t.as_bytes())?;
        announce(out);
    }
    if let Some(out) = &args.csv {
        write_atomic(out, csv(&rows, &table).as_bytes())?;
        announce(out);
    }
    Ok(())
}
