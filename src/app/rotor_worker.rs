//! Runs a rotor analysis ([`crate::rotor::analysis::Analysis`]) off the UI thread.
//!
//! - Native: one named thread per job loops [`Analysis::step`] (one speed: its bearing solves and the
//!   eigen-solution), reports progress over a channel and wakes the UI with `request_repaint`; a newer job
//!   (or dropping the runner) raises the old job's cancel flag, checked between speeds.
//! - Web: a web worker runs the analysis ([`super::web_solver::RotorLink`]); where no worker can run,
//!   [`RotorRunner::poll`] does one step per frame — one speed, or the finishing onset bisection — and asks
//!   for the next frame (a bearing solve is not split between frames then).

use std::sync::Arc;

use crate::model::rotor::Rotor;
use crate::rotor::analysis::{Analysis, AnalysisParams, AnalysisResult, Step};

/// What a job reports.
#[derive(Debug, Clone)]
pub enum RotorEvent {
    Progress { done: usize, of: usize },
    Done(Result<Arc<AnalysisResult>, String>),
}

/// Steps an analysis once: its progress, or the result when it finished (the analysis is then taken).
pub(super) fn advance(analysis: &mut Option<Analysis>) -> RotorEvent {
    let Some(a) = analysis.as_mut() else { return RotorEvent::Done(Err("no analysis".into())) };
    match a.step() {
        Ok(Step::More { done, of }) => RotorEvent::Progress { done, of },
        Ok(Step::Finished) => match analysis.take() {
            Some(a) => RotorEvent::Done(a.finish().map(Arc::new).map_err(|e| e.to_string())),
            None => RotorEvent::Done(Err("no analysis".into())),
        },
        Err(e) => {
            *analysis = None;
            RotorEvent::Done(Err(e.to_string()))
        }
    }
}

/// The background rotor analysis.
pub struct RotorRunner {
    repaint: egui::Context,
    #[cfg(not(target_arch = "wasm32"))]
    job: Option<native::Job>,
    #[cfg(target_arch = "wasm32")]
    link: Option<super::web_solver::RotorLink>,
    /// A job that could not start, reported at the next poll.
    failed: Option<String>,
    busy: bool,
}

impl RotorRunner {
    #[must_use]
    pub fn new(repaint: egui::Context) -> Self {
        Self {
            repaint,
            #[cfg(not(target_arch = "wasm32"))]
            job: None,
            #[cfg(target_arch = "wasm32")]
            link: None,
            failed: None,
            busy: false,
        }
    }

    /// Starts analysing `rotor` at `params`, cancelling a running job.
    pub fn start(&mut self, rotor: &Rotor, params: AnalysisParams) {
        self.busy = true;
        #[cfg(not(target_arch = "wasm32"))]
        {
            self.job = None;
        }
        #[cfg(target_arch = "wasm32")]
        {
            self.link = Some(super::web_solver::RotorLink::start(rotor, params, &self.repaint));
            self.repaint.request_repaint();
        }
        #[cfg(not(target_arch = "wasm32"))]
        self.start_native(rotor, params);
    }

    #[cfg(not(target_arch = "wasm32"))]
    fn start_native(&mut self, rotor: &Rotor, params: AnalysisParams) {
        let analysis = match Analysis::new(rotor, params) {
            Ok(a) => a,
            Err(e) => {
                self.failed = Some(e.to_string());
                self.repaint.request_repaint();
                return;
            }
        };
        self.job = Some(native::Job::spawn(analysis, self.repaint.clone()));
        self.repaint.request_repaint();
    }

    /// Events since the last call (on the web, one step of the work happens here).
    pub fn poll(&mut self) -> Vec<RotorEvent> {
        if let Some(e) = self.failed.take() {
            self.busy = false;
            return vec![RotorEvent::Done(Err(e))];
        }
        #[cfg(not(target_arch = "wasm32"))]
        let events: Vec<RotorEvent> = self.job.as_ref().map(native::Job::drain).unwrap_or_default();
        #[cfg(target_arch = "wasm32")]
        let events: Vec<RotorEvent> = self.link.as_mut().map(super::web_solver::RotorLink::poll).unwrap_or_default();
        if events.iter().any(|e| matches!(e, RotorEvent::Done(_))) {
            self.busy = false;
        }
        events
    }

    /// A job is running or its result has not been polled yet.
    #[must_use]
    pub fn busy(&self) -> bool {
        self.busy
    }
}

#[cfg(not(target_arch = "wasm32"))]
mod native {
    use std::sync::atomic::{AtomicBool, Ordering};
    use std::sync::mpsc::{channel, Receiver};
    use std::sync::Arc;

    use super::{advance, RotorEvent};
    use crate::rotor::analysis::Analysis;

    /// One analysis on its own thread.
    pub struct Job {
        events: Receiver<RotorEvent>,
        cancel: Arc<AtomicBool>,
    }

    impl Job {
        pub fn spawn(analysis: Analysis, repaint: egui::Context) -> Self {
            let (tx, events) = channel();
            let cancel = Arc::new(AtomicBool::new(false));
            let flag = cancel.clone();
            let mut analysis = Some(analysis);
            let spawned = std::thread::Builder::new().name("tiltpad-rotor".into()).spawn(move || {
                while !flag.load(Ordering::Relaxed) {
                    let event = advance(&mut analysis);
                    let done = matches!(event, RotorEvent::Done(_));
                    if tx.send(event).is_err() {
                        return;
                    }
                    repaint.request_repaint();
                    if done {
                        return;
                    }
                }
            });
            if let Err(e) = spawned {
                let (tx, events) = channel();
                let _ = tx.send(RotorEvent::Done(Err(format!("cannot start the rotor thread: {e}"))));
                return Self { events, cancel };
            }
            Self { events, cancel }
        }

        pub fn drain(&self) -> Vec<RotorEvent> {
            self.events.try_iter().collect()
        }
    }

    impl Drop for Job {
        fn drop(&mut self) {
            self.cancel.store(true, Ordering::Relaxed);
        }
    }
}
