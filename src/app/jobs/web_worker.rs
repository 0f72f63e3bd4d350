//! The web worker's entry points (`web/worker.js` calls [`receive`] for each message from the page): the
//! worker's side of [`super::remote`] with the JavaScript around it. Work is done a tick ([`TICK_S`]) at a
//! time; each tick posts its reports, and the next tick is queued behind the messages that arrived meanwhile,
//! so a newer job supersedes an older one within about one tick.

use std::cell::RefCell;

use wasm_bindgen::closure::Closure;
use wasm_bindgen::JsCast as _;

use super::worker_side::WorkerSide;

/// Work between two looks at the message queue [s].
pub const TICK_S: f64 = 0.1;

thread_local! {
    static WORKER: RefCell<(WorkerSide, bool)> = RefCell::new((WorkerSide::default(), false));
}

/// Starts logging to the worker's console (called once, before the first job).
pub fn init_worker() {
    eframe::WebLogger::init(log::LevelFilter::Info).ok();
}

/// An order from the page.
pub fn receive(bytes: &[u8]) {
    let (reports, queue) = WORKER.with_borrow_mut(|(w, queued)| {
        let reports = w.receive(bytes);
        let queue = w.busy() && !std::mem::replace(queued, true);
        (reports, queue)
    });
    post(&reports);
    if queue {
        queue_tick();
    }
}

/// Runs [`tick`] once the messages already queued have been handled.
fn queue_tick() {
    let scope: web_sys::WorkerGlobalScope = js_sys::global().unchecked_into();
    let callback = Closure::once_into_js(tick);
    if let Err(e) = scope.set_timeout_with_callback_and_timeout_and_arguments_0(callback.unchecked_ref(), 0) {
        log::error!("solver worker: cannot queue its next step: {e:?}");
        WORKER.with_borrow_mut(|(_, queued)| *queued = false);
    }
}

fn tick() {
    let (reports, more) = WORKER.with_borrow_mut(|(w, queued)| {
        let reports = w.tick(TICK_S);
        *queued = w.busy();
        (reports, *queued)
    });
    post(&reports);
    if more {
        queue_tick();
    }
}

fn post(reports: &[Vec<u8>]) {
    let scope: web_sys::DedicatedWorkerGlobalScope = js_sys::global().unchecked_into();
    for bytes in reports {
        if let Err(e) = scope.post_message(&js_sys::Uint8Array::from(bytes.as_slice())) {
            log::error!("solver worker: cannot send a report: {e:?}");
        }
    }
}
