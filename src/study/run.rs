//! Solving the points of a study, one [`Row`] per point.
//!
//! A [`Runner`] holds the base case text and its `--set` overrides. Each point's overrides are applied on
//! top, the case is validated and asked of the runner's [`Stages`], which rebuild only what the point's
//! values change (the films while the geometry and mesh stay, the pads' thermal systems while the pad mesh
//! stays). With warm starts (sweeps) a point starts from the previous point's equilibrium and, if that
//! fails, once more from scratch; without them (batches) every point is solved from scratch
//! ([`Start::Cold`]), so its row does not depend on which points came before it.

use web_time::Instant;

use crate::bearing::solution::limits::LimitKind;
use crate::bearing::{Cancel, NoCancel, Request, Solution, SolveError, Stages, Start};
use crate::model::{load_case, replaced_keys, Case, CaseError, Replaced};

use super::columns::{outputs, COLUMNS};

/// Why one point has no results.
#[derive(Debug, Clone, PartialEq, thiserror::Error, serde::Serialize, serde::Deserialize)]
pub enum PointError {
    #[error(transparent)]
    Case(#[from] CaseError),
    #[error(transparent)]
    Solve(#[from] SolveError),
}

/// One row of a study: the point's index and overrides, and its output cells or its error.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Row {
    pub index: usize,
    /// The point's `(key, value)` overrides, as given.
    pub inputs: Vec<(String, String)>,
    /// Output cells in [`COLUMNS`] order, or the error.
    pub result: Result<Vec<Option<f64>>, PointError>,
    /// Names of the design limits the point's solution exceeds ([`crate::bearing::solution::limits`]); empty for a
    /// point within them and for a failed point.
    #[serde(deserialize_with = "limit_names")]
    pub limits_exceeded: Vec<&'static str>,
    /// Wall time of the point [s] (the only column that differs from run to run).
    pub seconds: f64,
}

/// Limit names read back as the names [`LimitKind::name`] gives (the web build's sweep rows cross a wire).
fn limit_names<'de, D: serde::Deserializer<'de>>(d: D) -> Result<Vec<&'static str>, D::Error> {
    let names: Vec<String> = serde::Deserialize::deserialize(d)?;
    names
        .iter()
        .map(|n| {
            LimitKind::ALL
                .iter()
                .map(|k| k.name())
                .find(|k| k == n)
                .ok_or_else(|| serde::de::Error::custom(format!("no design limit named {n:?}")))
        })
        .collect()
}

/// The CSV column (and JSON key) listing the exceeded design limits, `;`-separated.
pub const LIMITS_COLUMN: &str = "limits_exceeded";

fn cell(v: Option<f64>) -> String {
    v.map_or_else(String::new, |x| format!("{x:?}"))
}

/// A `--set` value as JSON: numbers, lists and words as TOML reads them.
fn json_value(raw: &str) -> serde_json::Value {
    let parsed = format!("v = {raw}").parse::<toml::Table>().ok().and_then(|mut t| t.remove("v"));
    parsed.and_then(|v| serde_json::to_value(v).ok()).unwrap_or_else(|| serde_json::Value::String(raw.to_string()))
}

impl Row {
    /// CSV header: the index column, the input keys, the output columns, `limits_exceeded`, `seconds`, `error`.
    #[must_use]
    pub fn header(index_name: &str, input_keys: &[String]) -> Vec<String> {
        let mut h = vec![index_name.to_string()];
        h.extend(input_keys.iter().cloned());
        h.extend(COLUMNS.iter().map(|c| c.name.to_string()));
        h.push(LIMITS_COLUMN.into());
        h.push("seconds".into());
        h.push("error".into());
        h
    }

    /// The row's CSV cells (empty output cells for a failed point, the error in the last cell).
    #[must_use]
    pub fn record(&self) -> Vec<String> {
        let mut r = vec![self.index.to_string()];
        r.extend(self.inputs.iter().map(|(_, v)| v.clone()));
        match &self.result {
            Ok(cells) => r.extend(cells.iter().map(|&c| cell(c))),
            Err(_) => r.extend(std::iter::repeat_n(String::new(), COLUMNS.len())),
        }
        r.push(self.limits_exceeded.join(";"));
        r.push(format!("{:?}", self.seconds));
        r.push(self.error_text());
        r
    }

    /// The error message on one line (empty for a solved point).
    #[must_use]
    pub fn error_text(&self) -> String {
        self.result.as_ref().err().map_or_else(String::new, |e| e.to_string().replace(['\n', '\r'], " "))
    }

    /// The row as one JSON object (a JSON-lines record): index, inputs, outputs, seconds, error.
    #[must_use]
    pub fn json(&self, index_name: &str) -> serde_json::Value {
        let inputs: serde_json::Map<String, serde_json::Value> =
            self.inputs.iter().map(|(k, v)| (k.clone(), json_value(v))).collect();
        let outputs: serde_json::Map<String, serde_json::Value> = match &self.result {
            Ok(cells) => COLUMNS
                .iter()
                .zip(cells)
                .map(|(c, v)| (c.name.to_string(), v.map_or(serde_json::Value::Null, serde_json::Value::from)))
                .collect(),
            Err(_) => serde_json::Map::new(),
        };
        let error = self.result.as_ref().err().map(ToString::to_string);
        let mut obj = serde_json::Map::new();
        obj.insert(index_name.to_string(), self.index.into());
        obj.insert("inputs".into(), inputs.into());
        obj.insert("outputs".into(), outputs.into());
        obj.insert(LIMITS_COLUMN.into(), self.limits_exceeded.clone().into());
        obj.insert("seconds".into(), self.seconds.into());
        obj.insert("error".into(), error.into());
        serde_json::Value::Object(obj)
    }
}

/// Solves points of one base case.
pub struct Runner {
    text: String,
    base: Vec<String>,
    start: Start,
    stages: Stages,
}

impl Runner {
    /// A runner for the case `text` with `base` overrides (`key=value`); `warm`: start each point from the
    /// previous equilibrium.
    #[must_use]
    pub fn new(text: impl Into<String>, base: Vec<String>, warm: bool) -> Self {
        Self { text: text.into(), base, start: if warm { Start::Warm } else { Start::Cold }, stages: Stages::new() }
    }

    /// The validated case of a point.
    ///
    /// # Errors
    /// Syntax, unknown keys and every validation failure of the point's values.
    pub fn case(&self, overrides: &[(String, String)]) -> Result<Case, CaseError> {
        let mut set = self.base.clone();
        set.extend(overrides.iter().map(|(k, v)| format!("{k}={v}")));
        Ok(load_case(&self.text, &set)?.1)
    }

    /// What the points' overrides replace in the base case (an alternative pad-geometry key set where the
    /// case gives another: `bearing.pads.preload` over `bearing.pads.bore_radius_mm`), each once, as notes
    /// for the user. Points whose overrides do not apply are left out (their rows carry the error).
    #[must_use]
    pub fn replaced(&self, points: &[Vec<(String, String)>]) -> Vec<Replaced> {
        let mut notes: Vec<Replaced> = Vec::new();
        for point in points {
            let mut set = self.base.clone();
            set.extend(point.iter().map(|(k, v)| format!("{k}={v}")));
            for r in replaced_keys(&self.text, &set).unwrap_or_default() {
                if !notes.iter().any(|n| n.set == r.set && n.removed == r.removed) {
                    notes.push(r);
                }
            }
        }
        notes
    }

    /// The first key a point sets that another key of the same point replaces (an alternative pad-geometry
    /// key, a key the point's feeding kind does not use): that key's values would never be solved, so its
    /// column would show values that were not. `None` when every key a point sets is used.
    #[must_use]
    pub fn shadowed(&self, points: &[Vec<(String, String)>]) -> Option<Replaced> {
        let normal = |k: &str| k.replace('[', ".").replace([']', ' '], "");
        points.iter().find_map(|point| {
            let mut set = self.base.clone();
            set.extend(point.iter().map(|(k, v)| format!("{k}={v}")));
            replaced_keys(&self.text, &set)
                .unwrap_or_default()
                .into_iter()
                .find(|r| point.iter().any(|(k, _)| normal(k) == normal(&r.removed)))
        })
    }

    /// Checks, before anything is solved, that every key a study varies is a key of the case (with the base
    /// overrides): a misspelt key in a `--vary` or a batch header would otherwise fail every point, after
    /// solving none. `keys` are `(key, one of its values)`; a value that is only wrong for some points is
    /// left to those points' rows.
    ///
    /// # Errors
    /// The first unknown or malformed key ([`CaseError::UnknownKey`] with the schema's hint,
    /// [`CaseError::BadOverride`]).
    pub fn check_keys(&self, keys: &[(String, String)]) -> Result<(), CaseError> {
        for (key, value) in keys {
            let mut set = self.base.clone();
            set.push(format!("{key}={value}"));
            if let Err(e @ (CaseError::UnknownKey { .. } | CaseError::BadOverride { .. })) =
                crate::model::parse_case_file(&self.text, &set)
            {
                return Err(e);
            }
        }
        Ok(())
    }

    /// Solves one point.
    ///
    /// # Errors
    /// The point's case error or solve error.
    pub fn solve(&mut self, overrides: &[(String, String)]) -> Result<Solution, PointError> {
        self.solve_with(overrides, &NoCancel)
    }

    /// Solves one point, stopping when `cancel` says so ([`SolveError::Cancelled`]).
    ///
    /// # Errors
    /// The point's case error or solve error.
    pub fn solve_with(&mut self, overrides: &[(String, String)], cancel: &dyn Cancel) -> Result<Solution, PointError> {
        let case = self.case(overrides)?;
        let solution = self.stages.solution(&Request::solution(case).starting(self.start), cancel)?;
        Ok(std::sync::Arc::unwrap_or_clone(solution))
    }

    /// Solves one point and makes its row; the solution too when there is one (for field exports).
    pub fn row(&mut self, index: usize, overrides: &[(String, String)]) -> (Row, Option<Solution>) {
        self.row_with(index, overrides, &NoCancel)
    }

    /// [`Self::row`], stopping when `cancel` says so (the row then holds [`SolveError::Cancelled`]).
    pub fn row_with(
        &mut self,
        index: usize,
        overrides: &[(String, String)],
        cancel: &dyn Cancel,
    ) -> (Row, Option<Solution>) {
        let t0 = Instant::now();
        let result = self.solve_with(overrides, cancel);
        let seconds = t0.elapsed().as_secs_f64();
        match result {
            Ok(s) => (Row::of(index, overrides, Ok(&s), seconds), Some(s)),
            Err(e) => (Row::of(index, overrides, Err(e), seconds), None),
        }
    }
}

impl Row {
    /// The row of point `index` (`overrides`), solved or failed in `seconds`.
    #[must_use]
    pub fn of(
        index: usize,
        overrides: &[(String, String)],
        result: Result<&Solution, PointError>,
        seconds: f64,
    ) -> Self {
        let limits_exceeded = result.as_ref().map_or_else(
            |_| Vec::new(),
            |s| crate::bearing::solution::limits::exceeded(&s.inputs.limits, s).iter().map(|c| c.kind.name()).collect(),
        );
        Self { index, inputs: overrides.to_vec(), result: result.map(outputs), limits_exceeded, seconds }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::study::columns::column;

    fn runner(warm: bool) -> Runner {
        Runner::new(include_str!("../../cases/compressor-bearing.toml"), vec!["mesh.fidelity=\"preview\"".into()], warm)
    }

    fn value(row: &Row, name: &str) -> Option<f64> {
        let k = COLUMNS.iter().position(|c| c.name == name).unwrap();
        row.result.as_ref().unwrap()[k]
    }

    #[test]
    fn a_bad_point_is_a_row_with_its_error_and_the_next_point_still_solves() {
        let mut r = runner(true);
        let p = |v: &str| vec![("operating.speed_rpm".to_string(), v.to_string())];
        let (a, _) = r.row(0, &p("6000.0"));
        let (bad, none) = r.row(1, &p("-5.0"));
        let (c, sol) = r.row(2, &p("8000.0"));
        assert!(none.is_none() && sol.is_some());
        let msg = bad.error_text();
        assert!(msg.contains("operating.speed_rpm") && msg.contains("-5"), "{msg}");
        assert!(bad.record().last().unwrap().contains("operating.speed_rpm"));
        // Faster journal, thicker film.
        assert!(value(&a, "eccentricity_ratio").unwrap() > value(&c, "eccentricity_ratio").unwrap());
        // Isothermal: no temperatures, empty cells.
        assert_eq!(value(&a, "t_max_film_c"), None);
        let rec = a.record();
        let k = 2 + COLUMNS.iter().position(|c| c.name == "t_max_film_c").unwrap();
        assert_eq!(rec[k], "");
        assert!(column("h_min_um").is_some());
    }

    #[test]
    fn cold_rows_do_not_depend_on_the_rows_before_them() {
        let p = |v: &str| {
            vec![
                ("bearing.pads.preload".to_string(), v.to_string()),
                ("bearing.pads.bore_radius_mm".to_string(), String::new()),
            ]
        };
        let mut alone = runner(false);
        let (x, _) = alone.row(0, &p("0.3"));
        let mut after = runner(false);
        let _ = after.row(0, &p("0.1"));
        let (y, _) = after.row(0, &p("0.3"));
        assert_eq!(x.result, y.result);
    }

    /// Rows cross the web build's wire: limits, cells and errors come back equal; an unknown limit name
    /// is refused.
    #[test]
    fn rows_round_trip_through_the_wire_format() {
        use crate::bearing::stages::{from_bytes, to_bytes};
        let mut r = runner(true);
        let p = |k: &str, v: &str| vec![(k.to_string(), v.to_string())];
        let (hot, _) = r.row(0, &p("operating.load_n", "60000.0"));
        let (bad, _) = r.row(1, &p("operating.speed_rpm", "-5.0"));
        assert!(!hot.limits_exceeded.is_empty() && bad.result.is_err(), "{:?} {:?}", hot.limits_exceeded, bad.result);
        for row in [hot, bad] {
            assert_eq!(from_bytes::<Row>(&to_bytes(&row).unwrap()).unwrap(), row);
        }
        let unknown = Row {
            index: 0,
            inputs: Vec::new(),
            result: Ok(Vec::new()),
            limits_exceeded: vec!["no_such_limit"],
            seconds: 0.0,
        };
        assert!(from_bytes::<Row>(&to_bytes(&unknown).unwrap()).is_err_and(|e| e.to_string().contains("no_such_limit")));
    }
}
