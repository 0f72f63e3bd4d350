//! Python values as case-file values (the text a `--set key=value` override carries) and NumPy arrays of the
//! library's vectors (one copy each, read-only: results are shared).

use numpy::ndarray::{Array, Array2, Array3, Dimension};
use numpy::{PyArray, PyArray1, PyArrayMethods};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyList, PyString, PyTuple};

/// A TOML string literal.
fn quoted(s: &str) -> String {
    toml::Value::String(s.to_string()).to_string()
}

/// A Python value as the text of a case-file value: bools, whole and real numbers (NumPy's too), strings
/// (quoted), lists, tuples and 1-D arrays (TOML arrays). `None` is the empty text, which removes the key.
///
/// # Errors
/// A value of another type, or a non-finite number (`TypeError`/`ValueError` naming the key).
pub fn toml_text(key: &str, v: &Bound<'_, PyAny>) -> PyResult<String> {
    if v.is_none() {
        return Ok(String::new());
    }
    if v.is_instance_of::<PyBool>() {
        return Ok(if v.is_truthy()? { "true".into() } else { "false".into() });
    }
    if let Ok(s) = v.cast::<PyString>() {
        return Ok(quoted(&s.to_cow()?));
    }
    if let Ok(i) = v.extract::<i64>() {
        return Ok(i.to_string());
    }
    if let Ok(x) = v.extract::<f64>() {
        // `{:?}` keeps a decimal point and every digit (the value round-trips).
        return Ok(format!("{x:?}"));
    }
    let items: Option<Vec<Bound<'_, PyAny>>> = if let Ok(l) = v.cast::<PyList>() {
        Some(l.iter().collect())
    } else if let Ok(t) = v.cast::<PyTuple>() {
        Some(t.iter().collect())
    } else if v.hasattr("tolist")? {
        let list = v.call_method0("tolist")?;
        list.cast::<PyList>().ok().map(|l| l.iter().collect())
    } else {
        None
    };
    match items {
        Some(items) => {
            let parts = items.iter().map(|x| toml_text(key, x)).collect::<PyResult<Vec<_>>>()?;
            Ok(format!("[{}]", parts.join(", ")))
        }
        None => Err(PyTypeError::new_err(format!(
            "`{key}`: a case value is a number, a bool, a string, a list of them or None (to remove the key), not {}",
            v.get_type().name()?
        ))),
    }
}

/// A read-only NumPy array owning `data` (no copy beyond the one that made `data`).
pub fn array<'py, D: Dimension>(py: Python<'py>, data: Array<f64, D>) -> Bound<'py, PyArray<f64, D>> {
    let a = PyArray::from_owned_array(py, data);
    readonly(a)
}

fn readonly<'py, T: numpy::Element, D: Dimension>(a: Bound<'py, PyArray<T, D>>) -> Bound<'py, PyArray<T, D>> {
    // Clearing NumPy's WRITEABLE flag goes through a read-write borrow, which cannot fail on a fresh array.
    if let Ok(rw) = a.try_readwrite() {
        let _ = rw.make_nonwriteable();
    }
    a
}

/// A read-only 1-D array copied from `v`.
pub fn vector<'py>(py: Python<'py>, v: &[f64]) -> Bound<'py, PyArray1<f64>> {
    readonly(PyArray1::from_slice(py, v))
}

/// A read-only 1-D bool array copied from `v`.
pub fn bools<'py>(py: Python<'py>, v: &[bool]) -> Bound<'py, PyArray1<bool>> {
    readonly(PyArray1::from_slice(py, v))
}

/// A read-only 2-D array from rows (all of one length).
pub fn matrix<'py>(py: Python<'py>, rows: &[Vec<f64>]) -> PyResult<Bound<'py, PyArray<f64, numpy::Ix2>>> {
    let n = rows.first().map_or(0, Vec::len);
    let flat: Vec<f64> = rows.iter().flat_map(|r| r.iter().copied()).collect();
    let a = Array2::from_shape_vec((rows.len(), n), flat)
        .map_err(|e| pyo3::exceptions::PyValueError::new_err(e.to_string()))?;
    Ok(array(py, a))
}

/// A read-only 2×2 array.
pub fn two_by_two<'py>(py: Python<'py>, m: &[[f64; 2]; 2]) -> Bound<'py, PyArray<f64, numpy::Ix2>> {
    array(py, Array2::from_shape_fn((2, 2), |(i, j)| m[i][j]))
}

/// A read-only (n, 2, 2) array of 2×2 matrices.
pub fn stack<'py>(py: Python<'py>, ms: &[[[f64; 2]; 2]]) -> Bound<'py, PyArray<f64, numpy::Ix3>> {
    array(py, Array3::from_shape_fn((ms.len(), 2, 2), |(k, i, j)| ms[k][i][j]))
}
