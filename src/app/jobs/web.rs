//! The web runner of one slot, on the page: a module web worker (`web/worker.js`) loads a second instance of
//! the program and runs the slot's jobs there ([`super::remote`]: orders and reports as bytes), so the
//! page's frames carry only the UI however long a step takes. The worker is started at the slot's first job
//! and kept for the next ones (a newer job supersedes the one under way on the worker).
//!
//! Where no worker can start, fails to load, or sends a report that does not decode, the slot falls back to
//! stepping its jobs inside the page's frames within a time budget ([`super::stepped`]) and carries on with
//! the job that was left; the console says so.

use std::cell::RefCell;
use std::rc::Rc;

use wasm_bindgen::closure::Closure;
use wasm_bindgen::JsCast as _;

use super::job::{Event, Job};
use super::remote::{order_bytes, read_report};
use super::stepped::Stepped;
use crate::bearing::stages::from_bytes;

/// The script that starts the worker (relative to the page).
const WORKER_SCRIPT: &str = "./worker.js";

/// A started web worker and what its handlers collect (reports as bytes).
struct Remote {
    worker: web_sys::Worker,
    inbox: Rc<RefCell<Vec<Vec<u8>>>>,
    failed: Rc<RefCell<Option<String>>>,
    _on_message: Closure<dyn FnMut(web_sys::MessageEvent)>,
    _on_error: Closure<dyn FnMut(web_sys::Event)>,
}

impl Remote {
    fn start(repaint: &egui::Context) -> Result<Self, String> {
        let options = web_sys::WorkerOptions::new();
        options.set_type(web_sys::WorkerType::Module);
        let worker = web_sys::Worker::new_with_options(WORKER_SCRIPT, &options).map_err(|e| format!("{e:?}"))?;
        let inbox = Rc::new(RefCell::new(Vec::new()));
        let failed = Rc::new(RefCell::new(None));
        let on_message = {
            let (inbox, repaint) = (inbox.clone(), repaint.clone());
            Closure::<dyn FnMut(web_sys::MessageEvent)>::new(move |e: web_sys::MessageEvent| {
                inbox.borrow_mut().push(js_sys::Uint8Array::new(&e.data()).to_vec());
                repaint.request_repaint();
            })
        };
        let on_error = {
            let (failed, repaint) = (failed.clone(), repaint.clone());
            Closure::<dyn FnMut(web_sys::Event)>::new(move |e: web_sys::Event| {
                let what = e
                    .dyn_ref::<web_sys::ErrorEvent>()
                    .map_or_else(|| "failed to load".to_string(), web_sys::ErrorEvent::message);
                *failed.borrow_mut() = Some(format!("the solver worker stopped: {what}"));
                repaint.request_repaint();
            })
        };
        worker.set_onmessage(Some(on_message.as_ref().unchecked_ref()));
        worker.set_onerror(Some(on_error.as_ref().unchecked_ref()));
        Ok(Self { worker, inbox, failed, _on_message: on_message, _on_error: on_error })
    }

    fn post(&self, bytes: &[u8]) -> Result<(), String> {
        self.worker.post_message(&js_sys::Uint8Array::from(bytes)).map_err(|e| format!("{e:?}"))
    }

    /// The reports so far, or why the worker is no longer usable.
    fn take(&self) -> Result<Vec<Vec<u8>>, String> {
        match self.failed.borrow_mut().take() {
            Some(e) => Err(e),
            None => Ok(std::mem::take(&mut *self.inbox.borrow_mut())),
        }
    }
}

impl Drop for Remote {
    fn drop(&mut self) {
        self.worker.terminate();
    }
}

fn log_fallback(why: &str) {
    log::warn!("{why}; solving inside the page's frames from now on");
}

/// The page's end of a slot.
pub(super) struct Link<J: Job> {
    repaint: egui::Context,
    /// `None` before the first job, `Some(None)` once no worker could start (or it failed).
    remote: Option<Option<Remote>>,
    /// The fallback.
    local: Stepped<J>,
    /// The order of the job on the worker, until it ends (restarted here if the worker fails).
    current: Option<(u64, Vec<u8>)>,
    /// The latest job's id (the local job's).
    id: u64,
}

impl<J: Job> Link<J> {
    pub fn new(repaint: egui::Context) -> Self {
        Self { repaint, remote: None, local: Stepped::default(), current: None, id: 0 }
    }

    fn remote(&mut self) -> Option<&Remote> {
        let repaint = &self.repaint;
        self.remote
            .get_or_insert_with(|| {
                Remote::start(repaint)
                    .map_err(|e| log_fallback(&format!("no solver worker for {} ({e})", J::NAME)))
                    .ok()
            })
            .as_ref()
    }

    /// Starts job `id` (`None`: stops the job under way).
    pub fn submit(&mut self, id: u64, job: Option<J>) {
        self.id = id;
        let posted = match order_bytes(id, job.as_ref()) {
            Ok(bytes) => match self.remote().map(|r| r.post(&bytes)) {
                Some(Ok(())) => {
                    self.current = job.is_some().then_some((id, bytes));
                    true
                }
                Some(Err(e)) => {
                    log_fallback(&e);
                    self.remote = Some(None);
                    false
                }
                None => false,
            },
            Err(e) => {
                log::error!("{e}");
                false
            }
        };
        if posted {
            self.local.stop();
        } else {
            match job {
                Some(job) => self.local.start(job),
                None => self.local.stop(),
            }
        }
        self.repaint.request_repaint();
    }

    /// Events since the last call, by job id; without a worker the job steps here within `budget_s`.
    pub fn poll(&mut self, budget_s: f64) -> Vec<(u64, Event<J::Output>)> {
        let mut events = Vec::new();
        let taken = match self.remote.as_ref().and_then(Option::as_ref) {
            Some(r) => r.take(),
            None => Ok(Vec::new()),
        };
        match taken {
            Ok(reports) => {
                for bytes in reports {
                    match read_report::<J::Output>(&bytes) {
                        Ok((id, e)) => {
                            if e.ends() && self.current.as_ref().is_some_and(|(c, _)| *c == id) {
                                self.current = None;
                            }
                            events.push((id, e));
                        }
                        Err(e) => {
                            self.fall_back(&e);
                            break;
                        }
                    }
                }
            }
            Err(e) => self.fall_back(&e),
        }
        if self.local.busy() {
            let id = self.id;
            events.extend(self.local.run_for(budget_s).into_iter().map(|e| (id, e)));
            if self.local.busy() {
                self.repaint.request_repaint();
            }
        }
        events
    }

    /// Drops the worker and carries on here with the job it had.
    fn fall_back(&mut self, why: &str) {
        log_fallback(why);
        self.remote = Some(None);
        if let Some((_, bytes)) = self.current.take() {
            match from_bytes::<super::remote::Order<J>>(&bytes) {
                Ok(order) => {
                    if let Some(job) = order.job {
                        self.local.start(job);
                    }
                }
                Err(e) => log::error!("the {} job cannot be restarted here: {e}", J::NAME),
            }
        }
    }
}
