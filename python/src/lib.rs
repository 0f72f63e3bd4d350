//! The Python package `tiltpad` (its compiled half, `tiltpad._tiltpad`): cases, solves, studies, coefficients,
//! frequency responses and rotor analyses of the solver library, with the GIL released while the solver
//! works. The Python half (`tiltpad/__init__.py`, `tiltpad/ross.py`) adds DataFrames and the ROSS hand-off;
//! `tiltpad/_tiltpad.pyi` types this module.
//!
//! Every call reaches the solver as the command line does (the same case loading and validation, the same
//! requests to the stages), so the numbers are the command line's.

use pyo3::prelude::*;

mod case;
mod control;
mod convert;
mod dynamics;
mod errors;
mod outputs;
mod rotor;
mod solution;
mod solve;
mod study;

#[pymodule]
fn _tiltpad(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<case::Case>()?;
    m.add_class::<control::CancelToken>()?;
    m.add_class::<solution::Solution>()?;
    outputs::install(m)?;
    m.add_class::<solution::Pad>()?;
    m.add_class::<dynamics::Coefficients>()?;
    m.add_class::<rotor::RotorResult>()?;
    m.add_function(wrap_pyfunction!(case::load_case, m)?)?;
    m.add_function(wrap_pyfunction!(case::schema, m)?)?;
    m.add_function(wrap_pyfunction!(solve::solve, m)?)?;
    m.add_function(wrap_pyfunction!(study::_sweep, m)?)?;
    m.add_function(wrap_pyfunction!(study::_batch, m)?)?;
    m.add_function(wrap_pyfunction!(dynamics::coefficients, m)?)?;
    m.add_function(wrap_pyfunction!(dynamics::frf, m)?)?;
    m.add_function(wrap_pyfunction!(rotor::rotor, m)?)?;
    m.add_function(wrap_pyfunction!(outputs::_outputs, m)?)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
