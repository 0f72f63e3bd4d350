//! The scalar attributes of `tiltpad.Solution`: one read-only property for each Python name of the
//! library's table of outputs (`tiltpad::bearing::solution::outputs::OUTPUTS`), put on the class when the
//! module loads. An output given a Python name in that table is an attribute here with nothing written in
//! this crate; the type stubs (`tiltpad/_tiltpad.pyi`) list it, and `mypy.stubtest` checks that they agree.
//!
//! A name reads the value as `to_dict()` holds it (SI, or the unit the name ends with), in the row's unit
//! (`h_min_um`, `speed_rpm`), or as a whole number (`iterations`); `None` where the solution has none.
//! `_outputs()` lists every name with its place in `to_dict()` and the factor between the two, for the tests.

use pyo3::prelude::*;
use pyo3::types::{PyCFunction, PyDict, PyTuple};

use tiltpad::bearing::solution::outputs::{Output, Py as Attr, OUTPUTS};
use tiltpad::bearing::Solution as Solved;

use crate::solution::Solution;

/// The attribute's value.
fn value(py: Python<'_>, o: &Output, attr: Attr, s: &Solved) -> PyResult<Py<PyAny>> {
    Ok(match attr {
        Attr::Si(_) => o.si(s).into_pyobject(py)?.into_any().unbind(),
        Attr::Shown(_) => o.shown(s).into_pyobject(py)?.into_any().unbind(),
        #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
        Attr::Count(_) => o.si(s).map(|v| v as u64).into_pyobject(py)?.into_any().unbind(),
    })
}

/// What the value is divided by to read it from `to_dict()`.
fn factor(o: &Output, attr: Attr) -> f64 {
    match attr {
        Attr::Shown(_) => o.unit.si,
        Attr::Si(_) | Attr::Count(_) => 1.0,
    }
}

/// Puts a property for every Python name of the table on `tiltpad.Solution`.
pub fn install(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    let class = py.get_type::<Solution>();
    let property = py.import("builtins")?.getattr("property")?;
    for o in OUTPUTS {
        for &attr in o.python {
            let get = PyCFunction::new_closure(
                py,
                None,
                None,
                move |args: &Bound<'_, PyTuple>, _: Option<&Bound<'_, PyDict>>| -> PyResult<Py<PyAny>> {
                    let slf = args.get_item(0)?;
                    let slf = slf.cast::<Solution>()?;
                    value(args.py(), o, attr, &slf.get().sol)
                },
            )?;
            let unit = match attr {
                Attr::Shown(_) => format!(" [{}]", o.unit.symbol),
                Attr::Si(_) | Attr::Count(_) => String::new(),
            };
            let doc = format!("{}{unit} (`{}` of `to_dict()`)", o.meaning, o.json);
            class.setattr(attr.name(), property.call1((get, py.None(), py.None(), doc))?)?;
        }
    }
    Ok(())
}

/// Every scalar attribute of `Solution`: its name, its JSON pointer in `to_dict()` and the factor that
/// divides that value to give the attribute's.
#[pyfunction]
pub fn _outputs() -> Vec<(&'static str, &'static str, f64)> {
    OUTPUTS.iter().flat_map(|o| o.python.iter().map(move |&a| (a.name(), o.json, factor(o, a)))).collect()
}
