//! The results panel as rows of text in display units, with what each quantity means.
//!
//! The rows are the table of outputs ([`crate::bearing::solution::outputs::OUTPUTS`]), section by section in
//! the table's order, each in its unit: a row's label, digits, unit and meaning are the table's. Values of
//! one group share one engineering prefix, chosen by the group's largest magnitude, so a matrix reads in one
//! unit (Kxx and Kyy both in MN/m) and the power losses in one (kW). The rows of a group with several values
//! to a line share a line (`Kxx, Kxy`). A few rows are structural — text or vectors the table does not hold:
//! the journal position, the solver's method, the thermal model's film–pad condition, inlet temperatures and
//! loop. Quantities the solution does not have (the maximum temperature of an isothermal solve) say why
//! instead of showing a number; a section with none of its quantities (the thermal one of an isothermal
//! solve) is left out.

use crate::bearing::solution::outputs::{Digits, Output, Section, OUTPUTS};
use crate::bearing::solution::Solution;
use crate::units::{L_PER_MIN, MPA, MRAD, MS, UM};

/// One labelled value.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    pub label: String,
    pub value: String,
    /// The unit as shown: an SI unit with its engineering prefix (`kN`) or a unit chosen for reading (µm).
    pub unit: String,
    /// Physical meaning, for a tooltip.
    pub meaning: String,
}

/// A titled group of rows.
#[derive(Debug, Clone, PartialEq)]
pub struct Group {
    pub title: &'static str,
    pub rows: Vec<Row>,
}

/// Per-pad results in display units.
#[derive(Debug, Clone, PartialEq)]
pub struct PadRow {
    pub index: usize,
    pub tilt_mrad: Option<f64>,
    pub h_min_um: f64,
    pub p_max_mpa: f64,
    pub load_n: f64,
    /// Net orifice flow into the film [l/min]; negative = oil leaves through the hole.
    pub orifice_flow_l_min: Option<f64>,
    pub cavitated_percent: f64,
    pub unloaded: bool,
}

/// Everything the results panel shows.
#[derive(Debug, Clone, PartialEq)]
pub struct Summary {
    pub groups: Vec<Group>,
    pub pads: Vec<PadRow>,
    pub warnings: Vec<String>,
}

fn row(label: &str, value: String, unit: &str, meaning: &str) -> Row {
    Row { label: label.to_string(), value, unit: unit.to_string(), meaning: meaning.to_string() }
}

/// A relative residual or balance: round-off (below 1e-12) is shown as such, not as its noise digits.
#[must_use]
pub fn small(x: f64) -> String {
    if x.abs() < 1e-12 {
        "< 1e-12".into()
    } else {
        format!("{x:.1e}")
    }
}

/// Four significant figures ([`crate::number::sig`]).
#[must_use]
pub fn sig4(x: f64) -> String {
    crate::number::sig(x, 4)
}

/// The scale and prefixed unit of values read together: the engineering prefix of the largest magnitude
/// (`[4.6e7, 1.95e9]` N/m → 1e9, "GN/m").
#[must_use]
pub fn shared_prefix(values: impl IntoIterator<Item = f64>, unit: &str) -> (f64, String) {
    let largest = values.into_iter().filter(|v| v.is_finite()).fold(0.0_f64, |m, v| m.max(v.abs()));
    let (scale, prefix) = crate::number::eng_prefix(largest);
    (scale, format!("{prefix}{unit}"))
}

/// The scale and unit a row is shown in: its group's prefix for [`Digits::Prefixed`] (chosen over every row
/// of the group that has a value), its own unit otherwise.
#[must_use]
pub fn row_unit(o: &Output, s: &Solution) -> (f64, String) {
    if o.digits != Digits::Prefixed {
        return (1.0, o.unit.symbol.to_string());
    }
    let peers = OUTPUTS.iter().filter(|p| p.label == o.label || (o.group.is_some() && p.group == o.group));
    shared_prefix(peers.filter_map(|p| p.shown(s)), o.unit.symbol)
}

/// A value in the row's unit (divided by `scale` for a prefixed row) written with the row's digits.
#[must_use]
pub fn value_text(o: &Output, shown: f64, scale: f64) -> String {
    match o.digits {
        Digits::Decimals(n) => format!("{shown:.n$}"),
        Digits::Significant => sig4(shown),
        Digits::Prefixed => sig4(shown / scale),
        Digits::RoundOff => small(shown),
        Digits::Count => format!("{shown:.0}"),
    }
}

/// The row's value as the panel shows it: the number, or why there is none (`— (isothermal)`).
fn cell(o: &Output, s: &Solution, scale: f64) -> String {
    match ((o.note)(s), o.shown(s)) {
        (Some(why), _) => format!("— ({why})"),
        (None, Some(v)) => value_text(o, v, scale),
        (None, None) => "—".into(),
    }
}

/// The table's rows of one section as panel lines: a group of several values to a line shares it.
fn table_rows(section: Section, s: &Solution) -> Vec<Row> {
    let rows: Vec<&Output> = OUTPUTS.iter().filter(|o| o.section == section).collect();
    let mut out = Vec::new();
    let mut k = 0;
    while k < rows.len() {
        let o = rows[k];
        let per_line = o.group.map_or(1, |g| g.per_line.max(1));
        let line: Vec<&Output> = rows[k..].iter().take(per_line).take_while(|p| p.group == o.group).copied().collect();
        k += line.len();
        let (scale, unit) = row_unit(o, s);
        let mut meanings: Vec<&str> = Vec::new();
        for p in &line {
            if !meanings.contains(&p.meaning) {
                meanings.push(p.meaning);
            }
        }
        let cells: Vec<String> = line.iter().map(|p| cell(p, s, scale)).collect();
        // A line with no number ("— (isothermal)") has no unit to show.
        let unit = if cells.iter().all(|c| c.starts_with('—')) { String::new() } else { unit };
        out.push(Row {
            label: line.iter().map(|p| p.label).collect::<Vec<_>>().join(", "),
            value: cells.join(", "),
            unit,
            meaning: meanings.join(" "),
        });
    }
    out
}

/// The structural rows of a section (text and vectors), and where they go: first or last.
fn structural_rows(section: Section, s: &Solution) -> (Vec<Row>, Vec<Row>) {
    match section {
        Section::Operating => {
            let [x, y] = s.journal_position_m.map(|v| UM.from_si(v));
            let meaning = "Journal centre displacement in the bearing frame (y up).";
            (Vec::new(), vec![row("Journal x, y", format!("{x:.2}, {y:.2}"), UM.symbol, meaning)])
        }
        Section::Thermal => {
            let Some(t) = &s.thermal else { return (Vec::new(), Vec::new()) };
            let rep = &t.report;
            let inlets: Vec<String> = t.inlet_temperatures_c.iter().map(|v| format!("{v:.1}")).collect();
            let first = vec![row(
                "Film-pad condition",
                format!("{:?}", t.pad_film_bc),
                "",
                "How heat passes between film and pad: BC1 adiabatic film, BC2 exchange coefficient, BC3 Knight & \
                 Barrett parabola.",
            )];
            let viscosity = rep.viscosity_change.last().map_or_else(|| "—".into(), |v| format!("{v:.1e}"));
            let last = vec![
                row(
                    "Inlet T per pad",
                    inlets.join(", "),
                    "°C",
                    "Leading-edge oil temperature of each pad from the groove mixing of hot carried-over oil with \
                     fresh supply.",
                ),
                row(
                    "Thermal loop",
                    rep.outer_iterations.to_string(),
                    "iterations",
                    "Outer iterations of equilibrium + temperatures until the viscosity field converged.",
                ),
                row(
                    "Thermal loop time",
                    format!("{:.0}", MS.from_si(rep.seconds)),
                    MS.symbol,
                    "Wall time of the thermal loop (equilibria, film energy, pad conduction, mixing).",
                ),
                row(
                    "Viscosity change",
                    viscosity,
                    "–",
                    "Largest nodal relative viscosity change of the last outer iteration (converged below 1e-4).",
                ),
            ];
            (first, last)
        }
        Section::Solver => (
            vec![row(
                "Method",
                s.report.method_text(),
                "",
                "How equilibrium was found: coupled Newton on journal and pad coordinates; pad assembly (nested \
                 Newton), a scan along the load and load continuation as fallbacks.",
            )],
            Vec::new(),
        ),
        Section::Flows | Section::Coefficients => (Vec::new(), Vec::new()),
    }
}

/// Builds the summary of a solution.
#[must_use]
pub fn summary(s: &Solution) -> Summary {
    let r = &s.report;
    let mut groups = Vec::new();
    for section in Section::ALL {
        // A section none of whose quantities the solution has is left out (the thermal one of an isothermal solve).
        if !OUTPUTS.iter().any(|o| o.section == section && o.si(s).is_some()) {
            continue;
        }
        let (first, last) = structural_rows(section, s);
        let rows = first.into_iter().chain(table_rows(section, s)).chain(last).collect();
        groups.push(Group { title: section.title(), rows });
    }
    let pads = s
        .pads
        .iter()
        .map(|p| PadRow {
            index: p.index,
            tilt_mrad: p.tilt_rad.map(|t| MRAD.from_si(t)),
            h_min_um: UM.from_si(p.h_min_m),
            p_max_mpa: MPA.from_si(p.p_max_pa),
            load_n: p.force_n[0].hypot(p.force_n[1]),
            orifice_flow_l_min: (!p.orifice_flows_m3_per_s.is_empty())
                .then(|| L_PER_MIN.from_si(p.orifice_flows_m3_per_s.iter().sum::<f64>())),
            cavitated_percent: 100.0 * p.cavitated_fraction,
            unloaded: p.unloaded,
        })
        .collect();
    let mut warnings: Vec<String> = r.warnings.iter().map(ToString::to_string).collect();
    if let Some(t) = &s.thermal {
        warnings.extend(t.report.warnings.iter().map(ToString::to_string));
    }
    Summary { groups, pads, warnings }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_off_is_shown_as_such() {
        assert_eq!(small(-7.9e-17), "< 1e-12");
        assert_eq!(small(4.4e-6), "4.4e-6");
    }

    #[test]
    fn four_significant_figures() {
        assert_eq!(sig4(1918.0), "1918");
        assert_eq!(sig4(9000.0), "9000");
        assert_eq!(sig4(0.012345), "0.01235");
        assert_eq!(sig4(123.456), "123.5");
        assert_eq!(sig4(2.5e7), "2.5e7");
        assert_eq!(sig4(0.0), "0");
    }

    /// A stiffness matrix whose Kxx is 46 MN/m and whose Kyy is 1.95 GN/m reads in one unit, GN/m (it read
    /// "46.36, …" MN/m on one line and "…, 1.95" GN/m on the next); the damping matrix keeps its own prefix,
    /// and the power losses share theirs (5.452 kW and a churning loss of 0.1473 kW, not 147.3 W).
    #[test]
    fn a_matrix_reads_in_one_prefix() {
        let mut s = crate::bearing::stages::registry::compressor_preview(&[]);
        s.reduced.k_n_per_m = [[4.636e7, -1.839e6], [2.2e5, 1.95e9]];
        s.reduced.c_ns_per_m = [[6.597e4, 12.0], [-30.0, 7.1e4]];
        let sum = summary(&s);
        let rows: Vec<&Row> = sum.groups.iter().flat_map(|g| &g.rows).collect();
        let find = |label: &str| *rows.iter().find(|r| r.label == label).unwrap_or_else(|| panic!("{label}"));
        let (kx, ky) = (find("Kxx, Kxy"), find("Kyx, Kyy"));
        assert_eq!((kx.value.as_str(), kx.unit.as_str()), ("0.04636, -0.001839", "GN/m"));
        assert_eq!((ky.value.as_str(), ky.unit.as_str()), ("0.00022, 1.95", "GN/m"));
        let cy = find("Cyx, Cyy");
        assert_eq!((cy.value.as_str(), cy.unit.as_str()), ("-0.03, 71", "kN·s/m"));
        let power = ["Film friction", "Churning", "Total power loss"].map(|l| find(l).unit.clone());
        assert_eq!(power, ["kW", "kW", "kW"].map(String::from));
        assert_eq!(find("Churning").value, sig4(s.churning_power_w() / 1e3));
    }
}
