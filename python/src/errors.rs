//! The library's typed errors as Python exceptions (defined in `tiltpad/_errors.py`, so they can inherit from
//! both `TiltpadError` and the matching built-in: `CaseError` is a `ValueError`, `SolveError` a
//! `RuntimeError`). Each carries `kind` (the variant, snake_case) and `details` (its fields, as the JSON form
//! serialises them); case errors also `key`, `value` and `allowed`. The message is the library's `Display`,
//! the same text the command line prints.

use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use serde::Serialize;

use tiltpad::bearing::SolveError;
use tiltpad::model::CaseError;
use tiltpad::rotor::RotorError;
use tiltpad::study::{PointError, StudyError};

/// `OutOfRange` → `out_of_range`.
fn snake(name: &str) -> String {
    let mut s = String::new();
    for (i, c) in name.chars().enumerate() {
        if c.is_ascii_uppercase() {
            if i > 0 {
                s.push('_');
            }
            s.push(c.to_ascii_lowercase());
        } else {
            s.push(c);
        }
    }
    s
}

/// The variant name and fields of a serde-tagged error (`{"Variant": {fields}}`, `"Variant"` or
/// `{"Variant": value}`).
fn kind_and_details(e: &impl Serialize) -> (String, serde_json::Value) {
    match serde_json::to_value(e) {
        Ok(serde_json::Value::String(name)) => (snake(&name), serde_json::Value::Object(serde_json::Map::new())),
        Ok(serde_json::Value::Object(map)) if map.len() == 1 => {
            let (name, inner) = map.into_iter().next().unwrap_or_default();
            let details = match inner {
                serde_json::Value::Object(o) => serde_json::Value::Object(o),
                other => serde_json::json!({ "value": other }),
            };
            (snake(&name), details)
        }
        _ => (String::new(), serde_json::Value::Object(serde_json::Map::new())),
    }
}

/// A JSON value as a Python object (through `json.loads`, so the types are exactly what the CLI's JSON gives).
pub fn json_to_py<'py>(py: Python<'py>, v: &serde_json::Value) -> PyResult<Bound<'py, PyAny>> {
    let text = serde_json::to_string(v).map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
    py.import("json")?.call_method1("loads", (text,))
}

fn class<'py>(py: Python<'py>, name: &str) -> PyResult<Bound<'py, PyAny>> {
    py.import("tiltpad._errors")?.getattr(name)
}

/// An exception of class `name` with `message`, `kind`, `details` and extra keyword attributes.
fn raise(py: Python<'_>, name: &str, message: String, err: &impl Serialize, extra: &Bound<'_, PyDict>) -> PyErr {
    let build = || -> PyResult<PyErr> {
        let (kind, details) = kind_and_details(err);
        let details = json_to_py(py, &details)?;
        extra.set_item("kind", kind)?;
        extra.set_item("details", details)?;
        let instance = class(py, name)?.call((message,), Some(extra))?;
        Ok(PyErr::from_value(instance))
    };
    build().unwrap_or_else(|e| e)
}

/// A case error; `given` is the value the caller set at `given_key`, reported when the error concerns that key
/// and carries no value of its own.
pub fn case_error(py: Python<'_>, e: &CaseError, given: Option<(&str, &Bound<'_, PyAny>)>) -> PyErr {
    let extra = PyDict::new(py);
    let fill = || -> PyResult<()> {
        extra.set_item("key", e.key())?;
        match e {
            CaseError::OutOfRange { value, allowed, .. } => {
                extra.set_item("value", *value)?;
                extra.set_item("allowed", allowed)?;
            }
            _ => {
                if let Some((key, value)) = given {
                    if e.key().is_none_or(|k| k == key) {
                        extra.set_item("value", value)?;
                    }
                }
                if let Some(spec) = e.key().and_then(tiltpad::model::schema::spec) {
                    extra.set_item("allowed", spec.allowed.describe())?;
                }
            }
        }
        Ok(())
    };
    if let Err(err) = fill() {
        return err;
    }
    raise(py, "CaseError", e.to_string(), e, &extra)
}

/// A solve error (`Cancelled` as `tiltpad.Cancelled`; a case error inside as `CaseError`).
pub fn solve_error(py: Python<'_>, e: &SolveError) -> PyErr {
    match e {
        SolveError::Case(c) => case_error(py, c, None),
        SolveError::Cancelled => raise(py, "Cancelled", e.to_string(), e, &PyDict::new(py)),
        _ => raise(py, "SolveError", e.to_string(), e, &PyDict::new(py)),
    }
}

/// `tiltpad.Cancelled`, its message saying who stopped the call (`by`: "the progress callback returned
/// False", "its CancelToken was cancelled"); `kind` "cancelled", `details` `{"by": by}`.
pub fn cancelled(py: Python<'_>, by: &str) -> PyErr {
    let e = SolveError::Cancelled;
    let extra = PyDict::new(py);
    let message = format!("{e}: {by}");
    let mut map = serde_json::Map::new();
    map.insert("Cancelled".into(), serde_json::json!({ "by": by }));
    raise(py, "Cancelled", message, &serde_json::Value::Object(map), &extra)
}

/// A point of a study that failed.
pub fn point_error(py: Python<'_>, e: &PointError) -> PyErr {
    match e {
        PointError::Case(c) => case_error(py, c, None),
        PointError::Solve(s) => solve_error(py, s),
    }
}

/// A study that cannot start.
pub fn study_error(py: Python<'_>, e: &StudyError) -> PyErr {
    let (kind, details) = match e {
        StudyError::BadAxis { spec, message } => ("bad_axis", serde_json::json!({ "spec": spec, "message": message })),
        StudyError::BadDesigns { line, message } => {
            ("bad_designs", serde_json::json!({ "line": line, "message": message }))
        }
        StudyError::BadShard { spec, message } => {
            ("bad_shard", serde_json::json!({ "spec": spec, "message": message }))
        }
    };
    let mut map = serde_json::Map::new();
    map.insert(kind.to_string(), details);
    raise(py, "StudyError", e.to_string(), &serde_json::Value::Object(map), &PyDict::new(py))
}

/// A rotor analysis that failed (a bearing's solve error keeps its kind in `details`).
pub fn rotor_error(py: Python<'_>, e: &RotorError) -> PyErr {
    match e {
        RotorError::Bearing { error: SolveError::Cancelled, .. } => solve_error(py, &SolveError::Cancelled),
        _ => raise(py, "RotorError", e.to_string(), &RotorErrorKind(e), &PyDict::new(py)),
    }
}

/// The variant name of a rotor error (it is not serialisable as a whole).
struct RotorErrorKind<'a>(&'a RotorError);
impl Serialize for RotorErrorKind<'_> {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let debug = format!("{:?}", self.0);
        let name: String = debug.chars().take_while(char::is_ascii_alphanumeric).collect();
        s.serialize_str(&name)
    }
}

/// Every point of a band failed (`SolveError` of kind `no_point_solved`; the message lists each failure).
pub fn no_point_solved(py: Python<'_>, message: String) -> PyErr {
    raise(py, "SolveError", message, &"NoPointSolved", &PyDict::new(py))
}

/// Any other failure, with its message (I/O: `OSError`).
pub fn os_error(message: String) -> PyErr {
    pyo3::exceptions::PyOSError::new_err(message)
}
