//! The web build's solvers, off the page's thread: a module web worker (`web/worker.js`) loads a second
//! instance of the program and runs the [`Stages`] there; the page and the worker exchange [`Order`]s and
//! [`Report`]s as bytes in the wire format ([`crate::bearing::stages::to_bytes`]). The page's frames then
//! carry only the UI, however long a stage's step takes. Each page-side solver has a worker of its own:
//! the edited case's and the pins' [`Link`]s (jobs and [`Event`]s), the sweep view's [`SweepLink`] (points
//! and their rows), the rotor view's [`RotorLink`] (an analysis, its progress and result).
//!
//! - Page side: an order is posted to the worker, and the reports its message handler receives are collected
//!   (with a repaint). If the worker cannot be created, fails to load, or a report does not decode, the
//!   solver falls back to stepping inside the page's frames within a time budget ([`Stepper`],
//!   [`SteppedPoints`]), as before the worker existed, and carries on with the work that was left; the
//!   console says so.
//! - Worker side, [`receive`]: a job replaces the one under way (the worker's own "latest job" makes the old
//!   one cancel at its next check); the work steps for [`TICK_S`] at a time, each tick posts its reports (the
//!   last progress, any result, the rows finished), and the next tick is queued behind the messages that
//!   arrived meanwhile, so a newer job cancels an older one within about one tick.

use std::cell::RefCell;
use std::rc::Rc;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Arc;

use wasm_bindgen::closure::Closure;
use wasm_bindgen::{JsCast as _, JsValue};
use web_time::Instant;

use super::rotor_worker::{advance, RotorEvent};
use super::sweep_steps::SteppedPoints;
use super::worker::{event_job, Event, Running, Superseded};
use crate::bearing::stages::{from_bytes, to_bytes, Stages};
use crate::bearing::FrameBudget;
use crate::model::rotor::Rotor;
use crate::rotor::analysis::{Analysis, AnalysisParams};
use crate::rotor::wire::AnalysisData;
use crate::study::{Row, Runner};

/// What the page asks of a worker.
#[derive(serde::Serialize, serde::Deserialize)]
pub(super) enum Order {
    /// Solve a job (supersedes the one under way).
    Solve(Box<Running>),
    /// Solve a sweep's points.
    Sweep(SweepOrder),
    /// Analyse a rotor (supersedes the analysis under way).
    Rotor(Box<(Rotor, AnalysisParams)>),
}

/// A sweep's points: each point's case is `text` with `overrides` and `key` = the point's value.
#[derive(Clone, serde::Serialize, serde::Deserialize)]
pub(super) struct SweepOrder {
    pub text: String,
    pub overrides: Vec<String>,
    pub key: String,
    pub values: Vec<f64>,
}

impl SweepOrder {
    /// The points from `first` on, stepped in this thread.
    fn stepped(&self, first: usize) -> SteppedPoints {
        let runner = Runner::new(self.text.clone(), self.overrides.clone(), true);
        SteppedPoints::new(runner, &self.key, self.values[first.min(self.values.len())..].to_vec()).numbered_from(first)
    }
}

/// What a worker sends back.
#[derive(serde::Serialize, serde::Deserialize)]
pub(super) enum Report {
    Event(Event),
    /// Sweep points finished, as `(value, row)`.
    Rows(Vec<(f64, Row)>),
    /// A rotor analysis's progress, or its result.
    RotorProgress {
        done: usize,
        of: usize,
    },
    RotorDone(Result<Box<AnalysisData>, String>),
}

impl Report {
    fn of_rotor(e: &RotorEvent) -> Self {
        match e {
            RotorEvent::Progress { done, of } => Self::RotorProgress { done: *done, of: *of },
            RotorEvent::Done(r) => {
                Self::RotorDone(r.as_ref().map(|a| Box::new(AnalysisData::from(a.as_ref()))).map_err(Clone::clone))
            }
        }
    }

    fn into_rotor(self) -> Option<RotorEvent> {
        match self {
            Self::RotorProgress { done, of } => Some(RotorEvent::Progress { done, of }),
            Self::RotorDone(r) => Some(RotorEvent::Done(r.map(|d| Arc::new((*d).into())))),
            _ => None,
        }
    }
}
/// Worker-side work between two looks at the message queue [s].
pub const TICK_S: f64 = 0.1;

/// The script that starts the worker (relative to the page).
const WORKER_SCRIPT: &str = "./worker.js";

/// The stages stepped in the caller's thread until a time budget is spent.
pub(super) struct Stepper {
    stages: Stages,
    running: Option<Running>,
}

impl Stepper {
    pub fn new() -> Self {
        Self { stages: Stages::new(), running: None }
    }

    pub fn start(&mut self, running: Running) {
        self.running = Some(running);
    }

    pub fn busy(&self) -> bool {
        self.running.is_some()
    }

    /// Steps the current job until `budget_s` is spent (at least one step per call).
    pub fn run_for(&mut self, budget_s: f64, latest: &Arc<AtomicU64>) -> Vec<Event> {
        let start = Instant::now();
        let mut events = Vec::new();
        while let Some(running) = self.running.as_mut() {
            let superseded = Superseded { latest: latest.clone(), job: running.job };
            let cancel = FrameBudget::new(&superseded, start, budget_s);
            let (event, finished) = running.step(&mut self.stages, &cancel);
            events.extend(event);
            if finished {
                self.running = None;
            }
            if start.elapsed().as_secs_f64() >= budget_s {
                break;
            }
        }
        events
    }
}

/// The page's end of the solver.
pub(super) struct Link {
    repaint: egui::Context,
    remote: Option<Remote>,
    /// The fallback (and the solver when no worker could start).
    local: Stepper,
    /// The job last submitted, until it finishes (re-submitted locally if the worker fails).
    current: Option<Running>,
}

/// Reports at least this large have their decoding time logged under `?probe` (a solution with its fields).
const PROBED_REPORT_BYTES: usize = 64 * 1024;

/// A started web worker and what its handlers collect.
struct Remote {
    worker: web_sys::Worker,
    inbox: Rc<RefCell<Vec<Report>>>,
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
        // `?probe`: the decoding time of each large report is logged (what the wire format costs the page).
        let probing = web_sys::window()
            .and_then(|w| w.location().search().ok())
            .is_some_and(|q| super::frame_probe::FrameProbe::from_query(&q).is_some());
        let on_message = {
            let (inbox, failed, repaint) = (inbox.clone(), failed.clone(), repaint.clone());
            Closure::<dyn FnMut(web_sys::MessageEvent)>::new(move |e: web_sys::MessageEvent| {
                let bytes = js_sys::Uint8Array::new(&e.data()).to_vec();
                let decoding = Instant::now();
                let decoded = from_bytes::<Report>(&bytes);
                if probing && bytes.len() >= PROBED_REPORT_BYTES {
                    let ms = decoding.elapsed().as_secs_f64() * 1e3;
                    log::info!("probe: a report of {:.0} kB decoded in {ms:.1} ms", bytes.len() as f64 / 1e3);
                }
                match decoded {
                    Ok(report) => inbox.borrow_mut().push(report),
                    Err(err) => {
                        *failed.borrow_mut() = Some(format!("a report from the solver worker does not decode: {err}"))
                    }
                }
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

    fn post(&self, order: &Order) -> Result<(), String> {
        let bytes = to_bytes(order).map_err(|e| e.to_string())?;
        self.worker.post_message(&js_sys::Uint8Array::from(bytes.as_slice())).map_err(|e| format!("{e:?}"))
    }

    /// The reports so far, or why the worker is no longer usable.
    fn take(&self) -> Result<Vec<Report>, String> {
        match self.failed.borrow_mut().take() {
            Some(e) => Err(e),
            None => Ok(std::mem::take(&mut *self.inbox.borrow_mut())),
        }
    }

    /// Starts a worker, logging why when none can start.
    fn try_start(repaint: &egui::Context) -> Option<Self> {
        Self::start(repaint).map_err(|e| log::warn!("no solver worker ({e}); solving inside the page's frames")).ok()
    }

    /// Starts a worker and posts `order` to it; `None` (logged) when either fails.
    fn start_with(repaint: &egui::Context, order: &Order) -> Option<Self> {
        Self::try_start(repaint).and_then(|r| r.post(order).map_err(|e| log_fallback(&e)).ok().map(|()| r))
    }
}

/// The worker stopped being usable (it has been dropped; the caller falls back to stepping in the page).
struct WorkerFailed;

/// The reports of `remote` since the last call (none without a worker); when the worker has failed it is
/// dropped, with the reason logged.
fn take_reports(remote: &mut Option<Remote>) -> Result<Vec<Report>, WorkerFailed> {
    let Some(r) = remote.as_ref() else { return Ok(Vec::new()) };
    r.take().map_err(|e| {
        log_fallback(&e);
        *remote = None;
        WorkerFailed
    })
}

impl Drop for Remote {
    fn drop(&mut self) {
        self.worker.terminate();
    }
}

fn log_fallback(why: &str) {
    log::warn!("{why}; solving inside the page's frames from now on");
}

impl Link {
    pub fn new(repaint: egui::Context) -> Self {
        Self { remote: Remote::try_start(&repaint), repaint, local: Stepper::new(), current: None }
    }

    pub fn start(&mut self, running: Running) {
        if let Some(remote) = &self.remote {
            match remote.post(&Order::Solve(Box::new(running.clone()))) {
                Ok(()) => {
                    self.current = Some(running);
                    return;
                }
                Err(e) => {
                    log_fallback(&e);
                    self.remote = None;
                }
            }
        }
        self.local.start(running);
        self.repaint.request_repaint();
    }

    /// Events since the last call; without a worker the stages step here within `budget_s`.
    pub fn poll(&mut self, budget_s: f64, latest: &Arc<AtomicU64>) -> Vec<Event> {
        let mut events = Vec::new();
        match take_reports(&mut self.remote) {
            Ok(reports) => {
                events.extend(reports.into_iter().filter_map(|r| if let Report::Event(e) = r { Some(e) } else { None }))
            }
            Err(WorkerFailed) => {
                if let Some(running) = self.current.take() {
                    self.local.start(running);
                }
            }
        }
        let job = latest.load(Ordering::Relaxed);
        if events.iter().any(|e| finishes(e, job)) {
            self.current = None;
        }
        if self.local.busy() {
            events.extend(self.local.run_for(budget_s, latest));
            if self.local.busy() {
                self.repaint.request_repaint();
            }
        }
        events
    }
}

/// The event ends job `job` (its last result or its failure).
fn finishes(e: &Event, job: u64) -> bool {
    matches!(e, Event::Solved { job: j, complete: true, .. } | Event::Failed { job: j, .. } if *j == job)
}

/// The page's end of a sweep's solver.
pub(super) struct SweepLink {
    repaint: egui::Context,
    order: SweepOrder,
    remote: Option<Remote>,
    /// Stepping in the page's frames (no worker, or it failed).
    local: Option<SteppedPoints>,
    /// Rows received so far.
    received: usize,
}

impl SweepLink {
    pub fn start(order: SweepOrder, repaint: &egui::Context) -> Self {
        let remote = Remote::start_with(repaint, &Order::Sweep(order.clone()));
        let local = remote.is_none().then(|| order.stepped(0));
        Self { repaint: repaint.clone(), order, remote, local, received: 0 }
    }

    /// Rows finished since the last call; without a worker the points step here within `budget_s`.
    pub fn poll(&mut self, budget_s: f64) -> Vec<(f64, Row)> {
        let mut rows = Vec::new();
        match take_reports(&mut self.remote) {
            Ok(reports) => {
                rows.extend(
                    reports.into_iter().flat_map(|r| if let Report::Rows(rows) = r { rows } else { Vec::new() }),
                )
            }
            Err(WorkerFailed) => self.local = Some(self.order.stepped(self.received)),
        }
        if let Some(local) = self.local.as_mut() {
            rows.extend(local.poll(budget_s));
            if self.received + rows.len() < self.order.values.len() {
                self.repaint.request_repaint();
            }
        }
        self.received += rows.len();
        rows
    }
}

/// The page's end of a rotor analysis.
pub(super) struct RotorLink {
    repaint: egui::Context,
    order: Option<Box<(Rotor, AnalysisParams)>>,
    remote: Option<Remote>,
    /// Stepping in the page's frames (no worker, or it failed).
    local: Option<Analysis>,
    /// The analysis could not start here (reported at the next poll).
    failed: Option<String>,
}

impl RotorLink {
    pub fn start(rotor: &Rotor, params: AnalysisParams, repaint: &egui::Context) -> Self {
        let order = Box::new((rotor.clone(), params));
        let remote = Remote::start_with(repaint, &Order::Rotor(order.clone()));
        let mut link = Self { repaint: repaint.clone(), order: Some(order), remote, local: None, failed: None };
        if link.remote.is_none() {
            link.start_local();
        }
        link
    }

    /// Falls back to stepping here; a rotor that does not start is reported at the next poll.
    fn start_local(&mut self) {
        if let Some(order) = self.order.take() {
            let (rotor, params) = *order;
            match Analysis::new(&rotor, params) {
                Ok(a) => self.local = Some(a),
                Err(e) => self.failed = Some(e.to_string()),
            }
        }
    }

    /// Events since the last call; without a worker one step of the analysis happens here.
    pub fn poll(&mut self) -> Vec<RotorEvent> {
        let mut events = Vec::new();
        match take_reports(&mut self.remote) {
            Ok(reports) => events.extend(reports.into_iter().filter_map(Report::into_rotor)),
            Err(WorkerFailed) => self.start_local(),
        }
        if let Some(e) = self.failed.take() {
            events.push(RotorEvent::Done(Err(e)));
        } else if self.remote.is_none() && self.local.is_some() {
            events.push(advance(&mut self.local));
            self.repaint.request_repaint();
        }
        events
    }
}

/// The worker's state (one per worker instance).
struct WorkerSide {
    stepper: Stepper,
    latest: Arc<AtomicU64>,
    sweep: Option<SteppedPoints>,
    rotor: Option<Analysis>,
    tick_queued: bool,
}

impl WorkerSide {
    fn busy(&self) -> bool {
        self.stepper.busy() || self.sweep.as_ref().is_some_and(|s| !s.finished()) || self.rotor.is_some()
    }

    /// Steps the rotor analysis for up to `budget_s` (at least once); its events.
    fn step_rotor(&mut self, budget_s: f64) -> Vec<RotorEvent> {
        let start = Instant::now();
        let mut events = Vec::new();
        while self.rotor.is_some() && (events.is_empty() || start.elapsed().as_secs_f64() < budget_s) {
            events.push(advance(&mut self.rotor));
        }
        events
    }
}

thread_local! {
    static WORKER: RefCell<WorkerSide> = RefCell::new(WorkerSide { stepper: Stepper::new(), latest: Arc::new(AtomicU64::new(0)), sweep: None, rotor: None, tick_queued: false });
}

/// Worker side: starts logging to the worker's console (called once, before the first job).
pub fn init_worker() {
    eframe::WebLogger::init(log::LevelFilter::Info).ok();
}

/// Worker side: an order from the page (called by `web/worker.js` for each message).
pub fn receive(bytes: &[u8]) {
    let order: Order = match from_bytes(bytes) {
        Ok(o) => o,
        Err(e) => {
            log::error!("solver worker: an order does not decode: {e}");
            return;
        }
    };
    let queue = WORKER.with_borrow_mut(|w| {
        match order {
            Order::Solve(running) => {
                w.latest.store(running.job, Ordering::Relaxed);
                w.stepper.start(*running);
            }
            Order::Sweep(sweep) => w.sweep = Some(sweep.stepped(0)),
            Order::Rotor(order) => {
                let (rotor, params) = *order;
                match Analysis::new(&rotor, params) {
                    Ok(a) => w.rotor = Some(a),
                    Err(e) => {
                        w.rotor = None;
                        post(&Report::RotorDone(Err(e.to_string())), || {
                            Report::RotorDone(Err("the rotor analysis cannot start".into()))
                        });
                    }
                }
            }
        }
        !std::mem::replace(&mut w.tick_queued, true)
    });
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
        WORKER.with_borrow_mut(|w| w.tick_queued = false);
    }
}

/// One tick of work; posts its reports (the last progress, every result or failure, the rows finished).
fn tick() {
    let (events, rows, rotor, more) = WORKER.with_borrow_mut(|w| {
        let latest = w.latest.clone();
        let (mut events, mut rows, mut rotor) = (Vec::new(), Vec::new(), Vec::new());
        if w.stepper.busy() {
            events = w.stepper.run_for(TICK_S, &latest);
        } else if w.rotor.is_some() {
            rotor = w.step_rotor(TICK_S);
        } else {
            rows = w.sweep.as_mut().map(|s| s.poll(TICK_S)).unwrap_or_default();
        }
        w.tick_queued = w.busy();
        (events, rows, rotor, w.tick_queued)
    });
    // The rotor's last progress and its result.
    let last_rotor = rotor.len().checked_sub(1);
    for (i, e) in rotor.iter().enumerate() {
        if matches!(e, RotorEvent::Done(_)) || Some(i) == last_rotor {
            post(&Report::of_rotor(e), || {
                Report::RotorDone(Err("the solver worker cannot send the rotor result".into()))
            });
        }
    }
    let last_progress = events.iter().rposition(|e| matches!(e, Event::Progress { .. }));
    for (i, event) in events.into_iter().enumerate() {
        if matches!(event, Event::Progress { .. }) && Some(i) != last_progress {
            continue;
        }
        let job = event_job(&event);
        // An event that cannot be encoded reaches the page as its job's failure (never a silent hang).
        post(&Report::Event(event), || {
            Report::Event(Event::Failed { job, error: "the solver worker cannot send its result".into() })
        });
    }
    if !rows.is_empty() {
        post(&Report::Rows(rows), || Report::Rows(Vec::new()));
    }
    if more {
        queue_tick();
    }
}

/// Posts a report to the page; if it cannot be encoded, posts `instead()` and logs why.
fn post(report: &Report, instead: impl FnOnce() -> Report) {
    let scope: web_sys::DedicatedWorkerGlobalScope = js_sys::global().unchecked_into();
    let bytes = to_bytes(report).or_else(|e| {
        log::error!("solver worker: cannot encode a report: {e}");
        to_bytes(&instead())
    });
    let posted = bytes
        .map_err(|e| JsValue::from_str(&e.to_string()))
        .and_then(|bytes| scope.post_message(&js_sys::Uint8Array::from(bytes.as_slice())));
    if let Err(e) = posted {
        log::error!("solver worker: cannot send a report: {e:?}");
    }
}
