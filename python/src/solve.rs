//! `tiltpad.solve`: one request to the stages (`bearing::Stages`, the one entrance to the solver), stepped
//! with the GIL released, exactly as `tiltpad solve` runs it (`solve_case`: fresh stages, the solution's
//! request, no suspension), so the numbers are the command line's to the last digit.

use std::sync::Arc;

use pyo3::prelude::*;

use tiltpad::bearing::{Request, SolveError, StageId, Stages, Step};

use crate::case::Case;
use crate::control::{CancelToken, Control};
use crate::solution::Solution;

/// Steps `req` on fresh stages until done, telling `control` after each stage: the fraction `share` ×
/// (stages done, counted up to `last`) / (`last` + 1), and the stage's name. Stops with `Cancelled` as soon
/// as the caller asks (between stages, and inside a stage wherever the solver polls its [`tiltpad::bearing::Cancel`]).
///
/// Without the GIL: call it inside `py.detach`.
pub fn run_stages(
    req: &Request,
    last: StageId,
    share: f64,
    control: &Control,
) -> Result<tiltpad::bearing::Outcome, SolveError> {
    let mut stages = Stages::new();
    #[allow(clippy::cast_precision_loss)]
    let of = (last.index() + 1) as f64;
    loop {
        match stages.step(req, control)? {
            Step::Done(o) => return Ok(o),
            Step::Pending { stage, .. } => {
                #[allow(clippy::cast_precision_loss)]
                control.report(share * (stage.index() + 1) as f64 / of, stage.label());
                if control.stopped() {
                    return Err(SolveError::Cancelled);
                }
            }
        }
    }
}

/// Runs the solution's request on fresh stages, reporting each finished stage; without the GIL.
pub fn solve_detached(
    py: Python<'_>,
    case: tiltpad::model::Case,
    control: &Control,
) -> Result<Arc<tiltpad::bearing::Solution>, SolveError> {
    py.detach(|| {
        let outcome = run_stages(&Request::solution(case), StageId::Reduction, 1.0, control)?;
        outcome.solution().ok_or(SolveError::Cancelled)
    })
}

/// Solves a case: the static equilibrium of journal and pads (and the thermal loop for THD cases), the
/// full and reduced dynamic coefficients, the design-limit checks — what `tiltpad solve` computes, with the
/// same numbers.
///
/// - `fidelity`: `"preview"`, `"standard"` or `"reference"` overrides the case's `mesh.fidelity`.
/// - `progress(fraction, message)`: called after each solver stage (fraction of the solve done, the stage's
///   name); returning `False` cancels.
/// - `cancel`: a `CancelToken`; `cancel.cancel()` from another thread stops the solve.
///
/// The solve releases the GIL: threads (`concurrent.futures.ThreadPoolExecutor`, Dask's threaded scheduler)
/// run solves in parallel. Raises `SolveError` (touchdown, no equilibrium, a spent budget: see `kind`),
/// `CaseError`, or `Cancelled`.
#[pyfunction]
#[pyo3(signature = (case, *, fidelity = None, progress = None, cancel = None))]
pub fn solve(
    py: Python<'_>,
    case: &Bound<'_, Case>,
    fidelity: Option<&str>,
    progress: Option<Bound<'_, PyAny>>,
    cancel: Option<&Bound<'_, CancelToken>>,
) -> PyResult<Solution> {
    let resolved = case.borrow().with(py, &Case::fidelity_override(fidelity))?;
    let control = Control::new(progress, cancel);
    match solve_detached(py, resolved, &control) {
        Ok(sol) => Ok(Solution::new(sol)),
        Err(e) => Err(control.error(py, &e)),
    }
}
