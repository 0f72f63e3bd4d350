//! `tiltpad.sweep` and `tiltpad.batch` (their Rust halves): the command line's studies (`study::Runner`,
//! `study::grid`, `study::Designs`), rows in the command line's columns (`study::columns`), returned as one
//! dict of columns in the CSV's order; `tiltpad/__init__.py` makes it a pandas DataFrame when pandas is there.
//!
//! Empty CSV cells (temperatures of an isothermal solve, the outputs of a failed point) are NaN in the float
//! columns; a failed point keeps its row with its error in `error`, as in the CSV.

use std::ops::Range;

use numpy::ndarray::Array1;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyString, PyTuple};

use tiltpad::bearing::SolveError;
use tiltpad::study::run::LIMITS_COLUMN;
use tiltpad::study::{grid, Axis, Designs, PointError, Row, Runner, Shard, COLUMNS};

use crate::case::Case;
use crate::control::{CancelToken, Control};
use crate::convert::{array, toml_text};
use crate::errors::{case_error, json_to_py, study_error};

/// A cell as the JSON-lines writer reads it: a number, a word or a list.
fn cell_value<'py>(py: Python<'py>, raw: &str) -> PyResult<Bound<'py, PyAny>> {
    if raw.is_empty() {
        return Ok(py.None().into_bound(py));
    }
    let parsed = format!("v = {raw}").parse::<toml::Table>().ok().and_then(|mut t| t.remove("v"));
    match parsed.and_then(|v| serde_json::to_value(v).ok()) {
        Some(v) => json_to_py(py, &v),
        None => Ok(PyString::new(py, raw).into_any()),
    }
}

/// The columns of `rows` (in order), keyed by the CSV's header.
fn columns<'py>(py: Python<'py>, index_name: &str, keys: &[String], rows: &[Row]) -> PyResult<Bound<'py, PyDict>> {
    let out = PyDict::new(py);
    #[allow(clippy::cast_possible_wrap)]
    let index: Vec<i64> = rows.iter().map(|r| r.index as i64).collect();
    out.set_item(index_name, numpy::PyArray1::from_vec(py, index))?;
    for (k, key) in keys.iter().enumerate() {
        let values = PyList::empty(py);
        for r in rows {
            values.append(cell_value(py, r.inputs.get(k).map_or("", |(_, v)| v.as_str()))?)?;
        }
        out.set_item(key, values)?;
    }
    for (c, col) in COLUMNS.iter().enumerate() {
        let values = Array1::from_iter(
            rows.iter().map(|r| r.result.as_ref().ok().and_then(|cells| cells[c]).unwrap_or(f64::NAN)),
        );
        out.set_item(col.name, array(py, values))?;
    }
    let limits: Vec<String> = rows.iter().map(|r| r.limits_exceeded.join(";")).collect();
    out.set_item(LIMITS_COLUMN, limits)?;
    out.set_item("seconds", array(py, Array1::from_iter(rows.iter().map(|r| r.seconds))))?;
    out.set_item("error", rows.iter().map(Row::error_text).collect::<Vec<_>>())?;
    Ok(out)
}

/// Whether a row was cancelled (then the study stops).
fn cancelled(row: &Row) -> bool {
    matches!(row.result, Err(PointError::Solve(SolveError::Cancelled)))
}

/// Runs `points` on one runner in order, reporting each; stops at a cancelled point.
fn run_points(
    runner: &mut Runner,
    points: &[(usize, Vec<(String, String)>)],
    control: &Control,
    done: &std::sync::atomic::AtomicUsize,
    total: usize,
) -> Vec<Row> {
    let mut rows = Vec::with_capacity(points.len());
    for (i, overrides) in points {
        if control.stopped() {
            break;
        }
        let (row, _) = runner.row_with(*i, overrides, control);
        if cancelled(&row) {
            break;
        }
        let n = done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
        let what = overrides.iter().map(|(k, v)| format!("{k} = {v}")).collect::<Vec<_>>().join(", ");
        #[allow(clippy::cast_precision_loss)]
        control.report(n as f64 / total as f64, &format!("point {} of {total}: {what}", n));
        rows.push(row);
    }
    rows
}

/// The exception of a study that stopped before its end.
fn stop_error(py: Python<'_>, control: &Control) -> PyErr {
    control.take_error().unwrap_or_else(|| control.cancelled(py))
}

/// The sweep's Rust half: `axes` as `[(key, [values…]), …]`; returns the columns.
#[pyfunction]
#[pyo3(signature = (case, axes, *, fidelity = None, progress = None, cancel = None))]
pub fn _sweep<'py>(
    py: Python<'py>,
    case: &Bound<'py, Case>,
    axes: &Bound<'py, PyList>,
    fidelity: Option<&str>,
    progress: Option<Bound<'py, PyAny>>,
    cancel: Option<&Bound<'py, CancelToken>>,
) -> PyResult<Bound<'py, PyDict>> {
    let mut parsed = Vec::new();
    for axis in axes.iter() {
        let pair = axis.cast::<PyTuple>()?;
        let key: String = pair.get_item(0)?.extract()?;
        let values: Vec<String> =
            pair.get_item(1)?.try_iter()?.map(|v| toml_text(&key, &v?)).collect::<PyResult<_>>()?;
        if values.is_empty() {
            let e = tiltpad::study::StudyError::BadAxis { spec: key.clone(), message: "no values".into() };
            return Err(study_error(py, &e));
        }
        parsed.push(Axis { key, values });
    }
    let points = grid::points(&parsed).map_err(|e| study_error(py, &e))?;
    let keys: Vec<String> = parsed.iter().map(|a| a.key.clone()).collect();
    let (text, mut base) = {
        let c = case.borrow();
        (c.text.clone(), c.overrides.clone())
    };
    base.extend(Case::fidelity_override(fidelity));
    // The base case must be valid on its own (a bad fidelity is the caller's error, not every point's).
    tiltpad::model::load_case(&text, &base).map_err(|e| case_error(py, &e, None))?;
    let control = Control::new(progress, cancel);
    let total = points.len();
    let indexed: Vec<(usize, Vec<(String, String)>)> = points.into_iter().enumerate().collect();
    let rows = py.detach(|| {
        let mut runner = Runner::new(text, base, true);
        run_points(&mut runner, &indexed, &control, &std::sync::atomic::AtomicUsize::new(0), total)
    });
    if rows.len() < total {
        return Err(stop_error(py, &control));
    }
    columns(py, "point", &keys, &rows)
}

/// The designs of a CSV text, a dict of columns or a list of dicts.
fn designs(py: Python<'_>, source: &Bound<'_, PyAny>) -> PyResult<Designs> {
    if let Ok(text) = source.extract::<String>() {
        return Designs::parse(&text).map_err(|e| study_error(py, &e));
    }
    let records: Vec<Bound<'_, PyDict>> = if let Ok(d) = source.cast::<PyDict>() {
        // Columns: {key: [values…]}.
        let keys: Vec<String> = d.keys().iter().map(|k| k.extract()).collect::<PyResult<_>>()?;
        let cols: Vec<Vec<Bound<'_, PyAny>>> =
            d.values().iter().map(|v| v.try_iter()?.collect::<PyResult<Vec<_>>>()).collect::<PyResult<_>>()?;
        let n = cols.first().map_or(0, Vec::len);
        if cols.iter().any(|c| c.len() != n) {
            let e = tiltpad::study::StudyError::BadDesigns { line: 1, message: "columns of different lengths".into() };
            return Err(study_error(py, &e));
        }
        (0..n)
            .map(|i| {
                let r = PyDict::new(py);
                for (k, c) in keys.iter().zip(&cols) {
                    r.set_item(k, &c[i])?;
                }
                Ok(r)
            })
            .collect::<PyResult<_>>()?
    } else {
        source.try_iter()?.map(|r| Ok(r?.cast_into::<PyDict>()?)).collect::<PyResult<_>>()?
    };
    let mut keys: Vec<String> = Vec::new();
    for r in &records {
        for k in r.keys() {
            let k: String = k.extract()?;
            if !keys.contains(&k) {
                keys.push(k);
            }
        }
    }
    let mut rows = Vec::with_capacity(records.len());
    for r in &records {
        let mut row = Vec::new();
        for k in &keys {
            if let Some(v) = r.get_item(k)? {
                // None and NaN (pandas' empty cell) keep the base case's value.
                let nan = v.extract::<f64>().is_ok_and(f64::is_nan);
                if !v.is_none() && !nan {
                    row.push((k.clone(), toml_text(k, &v)?));
                }
            }
        }
        rows.push(row);
    }
    Ok(Designs { keys, rows })
}

/// The batch's Rust half: `designs` as CSV text, `{key: [values…]}` or `[{key: value}, …]`.
#[pyfunction]
#[pyo3(signature = (case, designs, *, shard = None, workers = 1, fidelity = None, progress = None, cancel = None))]
#[allow(clippy::too_many_arguments)]
pub fn _batch<'py>(
    py: Python<'py>,
    case: &Bound<'py, Case>,
    designs: &Bound<'py, PyAny>,
    shard: Option<(usize, usize)>,
    workers: usize,
    fidelity: Option<&str>,
    progress: Option<Bound<'py, PyAny>>,
    cancel: Option<&Bound<'py, CancelToken>>,
) -> PyResult<Bound<'py, PyDict>> {
    let table = self::designs(py, designs)?;
    let shard = match shard {
        None => Shard::ALL,
        Some((i, n)) => Shard::parse(&format!("{i}/{n}")).map_err(|e| study_error(py, &e))?,
    };
    let (text, mut base) = {
        let c = case.borrow();
        (c.text.clone(), c.overrides.clone())
    };
    base.extend(Case::fidelity_override(fidelity));
    tiltpad::model::load_case(&text, &base).map_err(|e| case_error(py, &e, None))?;
    let range = shard.range(table.rows.len());
    let points: Vec<(usize, Vec<(String, String)>)> = range.clone().map(|i| (i, table.rows[i].clone())).collect();
    let control = Control::new(progress, cancel);
    let total = points.len();
    let blocks = blocks(total, workers.max(1));
    let rows: Vec<Row> = py.detach(|| {
        let done = std::sync::atomic::AtomicUsize::new(0);
        std::thread::scope(|s| {
            let handles: Vec<_> = blocks
                .iter()
                .map(|r| {
                    let (text, base, points, control, done) = (&text, &base, &points[r.clone()], &control, &done);
                    s.spawn(move || {
                        let mut runner = Runner::new(text.clone(), base.clone(), false);
                        run_points(&mut runner, points, control, done, total)
                    })
                })
                .collect();
            handles.into_iter().flat_map(|h| h.join().unwrap_or_default()).collect()
        })
    });
    if rows.len() < total {
        return Err(stop_error(py, &control));
    }
    // Every key of the table is a column, empty where the design keeps the base value (as the CLI writes it).
    let rows: Vec<Row> = rows
        .into_iter()
        .map(|mut row| {
            let given = &table.rows[row.index];
            row.inputs = table
                .keys
                .iter()
                .map(|k| (k.clone(), given.iter().find(|(g, _)| g == k).map(|(_, v)| v.clone()).unwrap_or_default()))
                .collect();
            row
        })
        .collect();
    columns(py, "design", &table.keys, &rows)
}

/// `n` items in `workers` contiguous, nearly equal blocks (as shards split a batch).
fn blocks(n: usize, workers: usize) -> Vec<Range<usize>> {
    (1..=workers.min(n.max(1))).map(|i| Shard { index: i, count: workers.min(n.max(1)) }.range(n)).collect()
}
