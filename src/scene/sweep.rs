//! "Any input against any output": the workbench's sweep as plain data.
//!
//! A [`SweepSpec`] names one numeric case key (any number row of [`crate::model::schema`]), a range and a
//! count; its points are `x_i = from + (to − from) i / (count − 1)`. Each point is solved by the study
//! runner ([`crate::study::Runner`]) and kept as a [`crate::study::Row`]: every output column of
//! [`crate::study::COLUMNS`] (ε, attitude, load, Sommerfeld number, h_min, p_max, temperatures, power loss,
//! flows, K and C terms), or the point's error. [`SweepTable`] turns the rows into plot series (each with
//! its unit, against the key or against the Sommerfeld number) and into CSV with every output column. No
//! GUI types, no threads: the app decides where the points are solved.

use serde::{Deserialize, Serialize};

use crate::model::schema::{Allowed, KeySpec, KEYS};
use crate::study::{Row, COLUMNS};

/// Most points a workbench sweep may have.
pub const MAX_POINTS: usize = 101;

/// What to sweep (persisted with the view settings).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct SweepSpec {
    /// Dotted case key (a schema number row).
    pub key: String,
    pub from: f64,
    pub to: f64,
    pub count: usize,
    /// Output column names (from [`COLUMNS`]) to plot.
    pub outputs: Vec<String>,
    /// Plot against the Sommerfeld number instead of the key (the designers' chart).
    pub against_sommerfeld: bool,
    /// Solve the points at preview fidelity (fast, coarser).
    pub preview: bool,
    /// Draw the Sommerfeld chart ([`crate::scene::sommerfeld`], which also makes its sweep:
    /// `SweepSpec::sommerfeld_chart`) rather than the outputs one by one.
    pub chart: bool,
}

impl Default for SweepSpec {
    fn default() -> Self {
        Self {
            key: "operating.load_n".into(),
            from: 1000.0,
            to: 10000.0,
            count: 10,
            outputs: vec!["eccentricity_ratio".into(), "h_min_um".into(), "p_max_mpa".into()],
            against_sommerfeld: false,
            preview: false,
            chart: false,
        }
    }
}

/// Why a sweep cannot start.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SweepSpecError {
    #[error("`{0}` is not a numeric case key")]
    NotNumeric(String),
    #[error("point count {0} is outside [2, {MAX_POINTS}]")]
    Count(usize),
    #[error("range {from} – {to} is empty or not finite")]
    Range { from: f64, to: f64 },
}

impl SweepSpec {
    /// The swept values.
    ///
    /// # Errors
    /// A key that is not a number row, a count outside [2, [`MAX_POINTS`]], an empty or infinite range.
    pub fn values(&self) -> Result<Vec<f64>, SweepSpecError> {
        if !sweepable_keys().iter().any(|k| k.key == self.key) {
            return Err(SweepSpecError::NotNumeric(self.key.clone()));
        }
        if !(2..=MAX_POINTS).contains(&self.count) {
            return Err(SweepSpecError::Count(self.count));
        }
        if !(self.from.is_finite() && self.to.is_finite()) || self.from == self.to {
            return Err(SweepSpecError::Range { from: self.from, to: self.to });
        }
        #[allow(clippy::cast_precision_loss)]
        let n = (self.count - 1) as f64;
        #[allow(clippy::cast_precision_loss)]
        Ok((0..self.count).map(|i| self.from + (self.to - self.from) * i as f64 / n).collect())
    }

    /// The unit of the swept key.
    #[must_use]
    pub fn unit(&self) -> &'static str {
        crate::model::schema::spec(&self.key).map_or("", |s| s.unit)
    }
}

/// The case keys a sweep may vary: every number row of the schema outside arrays (a per-pad row sets
/// every pad at once).
#[must_use]
pub fn sweepable_keys() -> Vec<&'static KeySpec> {
    KEYS.iter()
        .filter(|k| matches!(k.allowed, Allowed::Number(_) | Allowed::NumberPerPad(_)) && !k.key.contains("[]"))
        .collect()
}

/// The override of one point: the key and its value as TOML reads it.
#[must_use]
pub fn point_override(key: &str, value: f64) -> Vec<(String, String)> {
    vec![(key.to_string(), format!("{value:?}"))]
}

/// A column's display name and unit, from the unit suffix of its name (`h_min_um` → `h_min`, `µm`).
#[must_use]
pub fn column_label(name: &str) -> (String, &'static str) {
    const SUFFIXES: [(&str, &str); 11] = [
        ("_l_per_min", "l/min"),
        ("_ns_per_m", "N·s/m"),
        ("_n_per_m", "N/m"),
        ("_um", "µm"),
        ("_mpa", "MPa"),
        ("_deg", "°"),
        ("_c", "°C"),
        ("_w", "W"),
        ("_n", "N"),
        ("_ratio", "–"),
        ("iterations", ""),
    ];
    for (suffix, unit) in SUFFIXES {
        if let Some(stem) = name.strip_suffix(suffix) {
            let stem = if stem.is_empty() { name } else { stem };
            let stem = if suffix == "_ratio" { name } else { stem };
            return (stem.replace('_', " "), unit);
        }
    }
    (name.replace('_', " "), "–")
}

/// The points of a sweep solved so far, in order.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct SweepTable {
    pub key: String,
    /// `(x, row)` per point.
    pub points: Vec<(f64, Row)>,
}

fn column_index(name: &str) -> Option<usize> {
    COLUMNS.iter().position(|c| c.name == name)
}

impl SweepTable {
    #[must_use]
    pub fn new(key: &str) -> Self {
        Self { key: key.to_string(), points: Vec::new() }
    }

    /// The cell of `column` at every solved point, against the key's value or, with `against_sommerfeld`,
    /// the point's Sommerfeld number; failed points and empty cells are left out.
    #[must_use]
    pub fn series(&self, column: &str, against_sommerfeld: bool) -> Vec<[f64; 2]> {
        self.series_where(column, against_sommerfeld, |_| true)
    }

    /// The same points as [`Self::series`], only those beyond a design limit.
    #[must_use]
    pub fn series_over_limits(&self, column: &str, against_sommerfeld: bool) -> Vec<[f64; 2]> {
        self.series_where(column, against_sommerfeld, |r| !r.limits_exceeded.is_empty())
    }

    fn series_where(&self, column: &str, against_sommerfeld: bool, keep: impl Fn(&Row) -> bool) -> Vec<[f64; 2]> {
        let (Some(k), s) = (column_index(column), column_index("sommerfeld")) else { return Vec::new() };
        self.points
            .iter()
            .filter(|(_, row)| keep(row))
            .filter_map(|(x, row)| {
                let cells = row.result.as_ref().ok()?;
                let x = if against_sommerfeld { cells[s?]? } else { *x };
                Some([x, cells[k]?])
            })
            .collect()
    }

    /// The points that failed, with their errors.
    #[must_use]
    pub fn failures(&self) -> Vec<(f64, String)> {
        self.points.iter().filter(|(_, r)| r.result.is_err()).map(|(x, r)| (*x, r.error_text())).collect()
    }

    /// The points where a design limit is exceeded, with the limits' names.
    #[must_use]
    pub fn limit_marks(&self) -> Vec<(f64, String)> {
        self.points
            .iter()
            .filter(|(_, r)| !r.limits_exceeded.is_empty())
            .map(|(x, r)| (*x, r.limits_exceeded.join(", ")))
            .collect()
    }

    /// CSV: point index, the key, every output column, the exceeded limits, seconds, error.
    #[must_use]
    pub fn csv(&self) -> String {
        let mut w = csv::WriterBuilder::new().from_writer(Vec::new());
        let mut out = w.write_record(Row::header("point", std::slice::from_ref(&self.key))).is_ok();
        for (_, row) in &self.points {
            out &= w.write_record(row.record()).is_ok();
        }
        let bytes = w.into_inner().unwrap_or_default();
        if out {
            String::from_utf8_lossy(&bytes).into_owned()
        } else {
            String::new()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spec_values_and_its_errors() {
        let s =
            SweepSpec { key: "operating.load_n".into(), from: 1000.0, to: 4000.0, count: 4, ..SweepSpec::default() };
        assert_eq!(s.values().unwrap(), [1000.0, 2000.0, 3000.0, 4000.0]);
        assert_eq!(s.unit(), "N");
        let bad = SweepSpec { key: "thermal.model".into(), ..s.clone() };
        assert_eq!(bad.values(), Err(SweepSpecError::NotNumeric("thermal.model".into())));
        assert_eq!(SweepSpec { count: 1, ..s.clone() }.values(), Err(SweepSpecError::Count(1)));
        assert!(SweepSpec { to: 1000.0, ..s }.values().is_err());
        let keys: Vec<&str> = sweepable_keys().iter().map(|k| k.key).collect();
        for k in [
            "operating.speed_rpm",
            "bearing.pads.preload",
            "operating.injection_pressure_bar",
            "operating.supply_temperature_c",
            "limits.min_film_thickness_um",
        ] {
            assert!(keys.contains(&k), "{k}");
        }
        assert!(!keys.iter().any(|k| k.contains("[]")));
    }

    #[test]
    fn every_column_has_a_label_and_a_unit() {
        assert_eq!(column_label("h_min_um"), ("h min".into(), "µm"));
        assert_eq!(column_label("eccentricity_ratio"), ("eccentricity ratio".into(), "–"));
        assert_eq!(column_label("kxy_n_per_m"), ("kxy".into(), "N/m"));
        assert_eq!(column_label("flow_sides_out_l_per_min"), ("flow sides out".into(), "l/min"));
        assert_eq!(column_label("t_max_pad_c"), ("t max pad".into(), "°C"));
        assert_eq!(column_label("sommerfeld"), ("sommerfeld".into(), "–"));
    }

    /// A load sweep of the compressor bearing: ε rises and h_min falls with load, the Sommerfeld number
    /// falls as 1/W, and the CSV carries every output column.
    #[test]
    fn a_load_sweep_gives_series_and_csv() {
        let text = include_str!("../../cases/compressor-bearing.toml");
        let mut runner = crate::study::Runner::new(text, vec!["mesh.fidelity=\"preview\"".into()], true);
        let spec =
            SweepSpec { key: "operating.load_n".into(), from: 1000.0, to: 4000.0, count: 3, ..SweepSpec::default() };
        let mut table = SweepTable::new(&spec.key);
        for (i, x) in spec.values().unwrap().into_iter().enumerate() {
            let (row, _) = runner.row(i, &point_override(&spec.key, x));
            table.points.push((x, row));
        }
        let eps = table.series("eccentricity_ratio", false);
        let h = table.series("h_min_um", false);
        assert_eq!(eps.len(), 3);
        assert!(eps.windows(2).all(|w| w[1][1] > w[0][1]) && h.windows(2).all(|w| w[1][1] < w[0][1]), "{eps:?} {h:?}");
        let s = table.series("sommerfeld", false);
        // S = µ N L D / W (R/C)² with the film's load W: S·W is the same at every point.
        let w = table.series("load_n", false);
        assert!((s[0][1] * w[0][1] / (s[2][1] * w[2][1]) - 1.0).abs() < 1e-12, "{s:?} {w:?}");
        let against_s = table.series("eccentricity_ratio", true);
        assert_eq!(against_s[0], [s[0][1], eps[0][1]]);
        let csv = table.csv();
        let header = csv.lines().next().unwrap();
        for c in COLUMNS {
            assert!(header.split(',').any(|h| h == c.name), "{} missing from {header}", c.name);
        }
        assert!(header.starts_with("point,operating.load_n,") && header.contains("limits_exceeded"));
        assert_eq!(csv.lines().count(), 4);
        assert!(table.failures().is_empty());
    }
}
