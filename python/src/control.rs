//! Cancellation and progress of a call that runs the solver with the GIL released.
//!
//! A [`Control`] is the solver's [`Cancel`]: it stops the solve when the caller's [`CancelToken`] is set
//! (from any thread), when the progress callback returns `False` or raises, or on Ctrl-C (Python's signal
//! handlers run at most every 0.1 s of computing, on the main thread). The solver asks it without the GIL;
//! only the callback and the signal check attach to the interpreter, briefly.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};

use pyo3::prelude::*;
use web_time::Instant;

use tiltpad::bearing::{Cancel, SolveError};

/// Seconds of computing between two checks for Ctrl-C.
const SIGNAL_INTERVAL_S: f64 = 0.1;

/// A flag that stops the solves it is passed to, set from any thread.
///
/// ```python
/// token = tiltpad.CancelToken()
/// future = pool.submit(tiltpad.solve, case, cancel=token)
/// token.cancel()          # the solve raises tiltpad.Cancelled
/// ```
#[pyclass(module = "tiltpad", frozen)]
#[derive(Default)]
pub struct CancelToken {
    flag: Arc<AtomicBool>,
}

#[pymethods]
impl CancelToken {
    #[new]
    fn new() -> Self {
        Self::default()
    }

    /// Stops every solve this token was passed to (they raise `tiltpad.Cancelled`).
    fn cancel(&self) {
        self.flag.store(true, Ordering::Relaxed);
    }

    /// Whether `cancel()` was called.
    #[getter]
    fn cancelled(&self) -> bool {
        self.flag.load(Ordering::Relaxed)
    }

    fn __repr__(&self) -> String {
        format!("CancelToken(cancelled={})", if self.cancelled() { "True" } else { "False" })
    }
}

/// The caller's progress callback and cancel token for one call.
pub struct Control {
    progress: Option<Py<PyAny>>,
    token: Option<Arc<AtomicBool>>,
    stop: AtomicBool,
    error: Mutex<Option<PyErr>>,
    last_check: Mutex<Instant>,
    /// The largest fraction told so far: threads of a batch finish out of order, the callback sees a
    /// fraction that never decreases.
    told: Mutex<f64>,
}

impl Control {
    pub fn new(progress: Option<Bound<'_, PyAny>>, cancel: Option<&Bound<'_, CancelToken>>) -> Self {
        Self {
            progress: progress.filter(|p| !p.is_none()).map(Bound::unbind),
            token: cancel.map(|t| Arc::clone(&t.get().flag)),
            stop: AtomicBool::new(false),
            error: Mutex::new(None),
            last_check: Mutex::new(Instant::now()),
            told: Mutex::new(0.0),
        }
    }

    fn fail(&self, e: PyErr) {
        self.stop.store(true, Ordering::Relaxed);
        if let Ok(mut slot) = self.error.lock() {
            slot.get_or_insert(e);
        }
    }

    /// Tells the callback how far the call is (`fraction` of it done, `message`: what just finished); may be
    /// called without the GIL.
    pub fn report(&self, fraction: f64, message: &str) {
        let Some(callback) = &self.progress else { return };
        Python::attach(|py| {
            // Taken under the GIL, just before the call: calls start in increasing order.
            let fraction = self.told.lock().map_or(fraction, |mut told| {
                *told = told.max(fraction);
                *told
            });
            self.call(py, callback, fraction, message);
        });
    }

    fn call(&self, py: Python<'_>, callback: &Py<PyAny>, fraction: f64, message: &str) {
        match callback.call1(py, (fraction, message)) {
            Ok(v) => {
                if v.bind(py).is(pyo3::types::PyBool::new(py, false)) {
                    self.stop.store(true, Ordering::Relaxed);
                }
            }
            Err(e) => self.fail(e),
        }
    }

    /// Whether the call should stop.
    pub fn stopped(&self) -> bool {
        self.stop.load(Ordering::Relaxed) || self.token.as_ref().is_some_and(|t| t.load(Ordering::Relaxed))
    }

    /// The exception to raise for a call that ended with `e`: the callback's own exception or Ctrl-C's
    /// `KeyboardInterrupt` first, then `Cancelled` (saying who cancelled) or the solver's error.
    pub fn error(&self, py: Python<'_>, e: &SolveError) -> PyErr {
        match (self.take_error(), e) {
            (Some(err), _) => err,
            (None, SolveError::Cancelled) => self.cancelled(py),
            (None, _) => crate::errors::solve_error(py, e),
        }
    }

    /// `tiltpad.Cancelled` naming who stopped the call.
    pub fn cancelled(&self, py: Python<'_>) -> PyErr {
        let by = if self.stop.load(Ordering::Relaxed) {
            "the progress callback returned False"
        } else if self.token.as_ref().is_some_and(|t| t.load(Ordering::Relaxed)) {
            "its CancelToken was cancelled"
        } else {
            "stopped from outside"
        };
        crate::errors::cancelled(py, by)
    }

    /// The callback's exception or Ctrl-C, if the call stopped for one.
    pub fn take_error(&self) -> Option<PyErr> {
        self.error.lock().ok().and_then(|mut slot| slot.take())
    }
}

impl Cancel for Control {
    fn cancelled(&self) -> bool {
        if self.stopped() {
            return true;
        }
        let due = self.last_check.lock().is_ok_and(|mut t| {
            let due = t.elapsed().as_secs_f64() >= SIGNAL_INTERVAL_S;
            if due {
                *t = Instant::now();
            }
            due
        });
        if due {
            if let Err(e) = Python::attach(|py| py.check_signals()) {
                self.fail(e);
            }
        }
        self.stopped()
    }
}
