//! `tiltpad.load_case` and `tiltpad.Case`: a case file and the edits made to it, validated exactly as the
//! command line validates `tiltpad solve CASE --set key=value …` (the same `model::load_case`, the same key
//! table, the same messages).
//!
//! A `Case` keeps the file's text and the edits as `key=value` overrides in the order they were made; every
//! edit is validated at once (an invalid one raises `CaseError` and is not kept), and `to_toml()` writes the
//! edits into the original text, keeping its comments (`model::edit`).

use std::path::PathBuf;

use pyo3::exceptions::{PyFileNotFoundError, PyKeyError};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use tiltpad::model::{self, load::value_at, CaseFile};

use crate::convert::toml_text;
use crate::errors::{case_error, json_to_py, os_error};

/// A bearing case: the file (or text) it came from and the edits made to it, validated.
#[pyclass(module = "tiltpad")]
#[derive(Clone)]
pub struct Case {
    /// The TOML text as read.
    pub text: String,
    /// Where it was read from (`None` for text).
    pub path: Option<PathBuf>,
    /// The edits, `key=value`, in order.
    pub overrides: Vec<String>,
    pub file: CaseFile,
    pub case: model::Case,
}

impl Case {
    /// Validates `text` with `overrides`.
    pub fn new(py: Python<'_>, text: String, path: Option<PathBuf>, overrides: Vec<String>) -> PyResult<Self> {
        let (file, case) = model::load_case(&text, &overrides).map_err(|e| case_error(py, &e, None))?;
        Ok(Self { text, path, overrides, file, case })
    }

    /// The validated case with `extra` overrides on top (a fidelity, a point of a sweep).
    pub fn with(&self, py: Python<'_>, extra: &[String]) -> PyResult<model::Case> {
        let mut all = self.overrides.clone();
        all.extend_from_slice(extra);
        model::load_case(&self.text, &all).map(|(_, c)| c).map_err(|e| case_error(py, &e, None))
    }

    /// The override that sets the mesh fidelity, if one is asked for.
    pub fn fidelity_override(fidelity: Option<&str>) -> Vec<String> {
        fidelity.map(|f| vec![format!("mesh.fidelity={}", toml::Value::String(f.to_string()))]).unwrap_or_default()
    }

    /// Applies `pairs` as overrides and validates the case once with all of them; an invalid result keeps
    /// none (its `CaseError` names the value given for the key it concerns).
    fn apply(&mut self, py: Python<'_>, pairs: &[(String, Bound<'_, PyAny>)]) -> PyResult<()> {
        let mut overrides = self.overrides.clone();
        for (key, value) in pairs {
            overrides.push(format!("{key}={}", toml_text(key, value)?));
        }
        let (file, case) = model::load_case(&self.text, &overrides).map_err(|e| {
            let given = e.key().and_then(|k| pairs.iter().rev().find(|(key, _)| key == k));
            let given = given.or(if pairs.len() == 1 { pairs.first() } else { None });
            case_error(py, &e, given.map(|(k, v)| (k.as_str(), v)))
        })?;
        self.overrides = overrides;
        self.file = file;
        self.case = case;
        Ok(())
    }

    /// A name for messages: the file's path or `<text>`.
    pub fn source(&self) -> String {
        self.path.as_ref().map_or_else(|| "<text>".to_string(), |p| p.display().to_string())
    }
}

/// Reads `path_or_text`: a path (`str` or `os.PathLike`) to a case file, or the TOML text itself.
fn read(py: Python<'_>, path_or_text: &Bound<'_, PyAny>) -> PyResult<(String, Option<PathBuf>)> {
    let fspath = py.import("os")?.getattr("fspath")?;
    let is_str = path_or_text.is_instance_of::<pyo3::types::PyString>();
    let as_path: Option<PathBuf> = if is_str {
        let s: String = path_or_text.extract()?;
        let looks_like_text = s.contains('\n') || (s.contains('=') && !s.ends_with(".toml"));
        (!looks_like_text).then(|| PathBuf::from(s))
    } else {
        Some(fspath.call1((path_or_text,))?.extract::<PathBuf>()?)
    };
    match as_path {
        Some(p) => match std::fs::read_to_string(&p) {
            Ok(text) => Ok((text, Some(p))),
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
                Err(PyFileNotFoundError::new_err(format!("cannot read case file {}: {e}", p.display())))
            }
            Err(e) => Err(os_error(format!("cannot read case file {}: {e}", p.display()))),
        },
        None => Ok((path_or_text.extract()?, None)),
    }
}

/// Reads and validates a case: a path to a TOML case file (`"cases/compressor-bearing.toml"`), or the TOML
/// text itself. `set` applies edits at once (`{"operating.speed_rpm": 9000}`), validated together as `Case.update`
/// does.
///
/// Raises `CaseError` (with `key`, `value`, `allowed`) for every problem `tiltpad solve` reports, with the
/// same message; `FileNotFoundError` for a missing file.
#[pyfunction]
#[pyo3(signature = (path_or_text, *, set = None))]
pub fn load_case(py: Python<'_>, path_or_text: &Bound<'_, PyAny>, set: Option<&Bound<'_, PyDict>>) -> PyResult<Case> {
    let (text, path) = read(py, path_or_text)?;
    let mut case = Case::new(py, text, path, Vec::new())?;
    if let Some(set) = set {
        case.update(py, set)?;
    }
    Ok(case)
}

#[pymethods]
impl Case {
    /// Sets a case key, as `tiltpad solve --set key=value` does: the dotted key of the file
    /// (`"bearing.pads.preload"`, `"bearing.pad.2.offset"`, `"operating.injection_pressure_bar"`) in the key's
    /// own unit (the unit is in its name: `speed_rpm`, `load_n`); a list sets per-pad values; `None` removes
    /// the key (`case.set("operating.load_n", None)` before setting `operating.eccentricity_ratio`).
    ///
    /// The whole case is validated at once: an invalid value raises `CaseError` (its `key`, `value` and
    /// `allowed` range) and is not kept.
    fn set(&mut self, py: Python<'_>, key: &str, value: &Bound<'_, PyAny>) -> PyResult<()> {
        self.apply(py, &[(key.to_string(), value.clone())])
    }

    /// Sets several keys at once, validating the case once with all of them: for edits that are only valid
    /// together (`{"bearing.pads.bore_radius_mm": None, "bearing.pads.preload": 0.3}` replaces one way of
    /// giving the pad bore by another). An invalid result raises `CaseError` and keeps none of them.
    fn update(&mut self, py: Python<'_>, values: &Bound<'_, PyDict>) -> PyResult<()> {
        let pairs = values.iter().map(|(k, v)| Ok((k.extract::<String>()?, v))).collect::<PyResult<Vec<_>>>()?;
        self.apply(py, &pairs)
    }

    /// A copy with the keys of `values` set at once, as `update` does (this case unchanged).
    fn with_values(&self, py: Python<'_>, values: &Bound<'_, PyDict>) -> PyResult<Self> {
        let mut c = self.clone();
        c.update(py, values)?;
        Ok(c)
    }

    /// The value of a key as the case has it (in the key's unit), or `None` when the file leaves it to its
    /// default.
    fn get<'py>(&self, py: Python<'py>, key: &str) -> PyResult<Bound<'py, PyAny>> {
        let table = self.file.to_table().map_err(|e| case_error(py, &e, None))?;
        match value_at(&table, key) {
            Some(v) => {
                let json = serde_json::to_value(v).map_err(|e| os_error(e.to_string()))?;
                json_to_py(py, &json)
            }
            None if model::schema::spec(key).is_some() => Ok(py.None().into_bound(py)),
            None => Err(PyKeyError::new_err(format!("unknown key `{key}` (tiltpad.schema() lists every key)"))),
        }
    }

    fn __getitem__<'py>(&self, py: Python<'py>, key: &str) -> PyResult<Bound<'py, PyAny>> {
        self.get(py, key)
    }

    fn __setitem__(&mut self, py: Python<'_>, key: &str, value: &Bound<'_, PyAny>) -> PyResult<()> {
        self.set(py, key, value)
    }

    /// An independent copy.
    fn copy(&self) -> Self {
        self.clone()
    }

    /// The edits made so far, as `--set` takes them (`["bearing.pads.preload=0.3"]`).
    #[getter]
    fn overrides(&self) -> Vec<String> {
        self.overrides.clone()
    }

    /// The case file this was read from, or `None` for text.
    #[getter]
    fn path(&self) -> Option<PathBuf> {
        self.path.clone()
    }

    #[getter]
    fn title(&self) -> String {
        self.case.title.clone()
    }

    /// The case as TOML: the original text with the edits written in, its comments kept.
    fn to_toml(&self, py: Python<'_>) -> PyResult<String> {
        self.file.to_toml_preserving(&self.text).map_err(|e| case_error(py, &e, None))
    }

    /// Writes `to_toml()` to `path` safely (a temporary file renamed over it).
    fn save(&self, py: Python<'_>, path: PathBuf) -> PyResult<()> {
        let text = self.to_toml(py)?;
        tiltpad::io::write_file(&path, text.as_bytes()).map_err(|e| os_error(e.to_string()))
    }

    fn __repr__(&self) -> String {
        format!("Case({:?}, source={:?}, overrides={:?})", self.case.title, self.source(), self.overrides)
    }
}

/// Every case key: unit, allowed values, default and meaning (what `tiltpad schema --json` writes).
#[pyfunction]
pub fn schema(py: Python<'_>) -> PyResult<Bound<'_, PyAny>> {
    json_to_py(py, &model::schema::json_table())
}
