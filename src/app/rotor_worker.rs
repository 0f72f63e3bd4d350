//! Runs a rotor analysis ([`crate::rotor::analysis::Analysis`]) off the UI thread.
//!
//! - Native: the shared runner ([`super::job_runner`]) loops [`Analysis::step`] (one speed: its bearing solves
//!   and the eigen-solution) on a named thread, reports progress over a channel and wakes the UI; a newer job
//!   (or dropping the runner) cancels the old one between speeds.
//! - Web: a web worker runs the analysis ([`super::web_solver::RotorLink`]); where no worker can run,
//!   [`RotorRunner::poll`] does one step per frame — one speed, or the finishing onset bisection — and asks
//!   for the next frame (a bearing solve is not split between frames then).

use std::sync::Arc;

use super::job_runner::Event;
use crate::model::rotor::Rotor;
use crate::rotor::analysis::{Analysis, AnalysisParams, AnalysisResult, Step};

/// What a rotor analysis reports.
pub type RotorEvent = Event<Arc<AnalysisResult>>;

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

/// A rotor analysis as the shared runner's work (an analysis that could not start fails at its first step).
#[cfg(not(target_arch = "wasm32"))]
struct RotorWork {
    analysis: Result<Option<Analysis>, String>,
    progress: (usize, usize),
}

#[cfg(not(target_arch = "wasm32"))]
impl super::job_runner::Work for RotorWork {
    type Output = Arc<AnalysisResult>;
    const THREAD: &'static str = "tiltpad-rotor";

    fn step(&mut self) -> Result<Option<Arc<AnalysisResult>>, String> {
        let analysis = self.analysis.as_mut().map_err(|e| e.clone())?;
        match advance(analysis) {
            Event::Progress { done, of } => {
                self.progress = (done, of);
                Ok(None)
            }
            Event::Done(r) => r.map(Some),
        }
    }

    fn progress(&self) -> (usize, usize) {
        self.progress
    }
}

/// The background rotor analysis.
pub struct RotorRunner {
    #[cfg(not(target_arch = "wasm32"))]
    runner: super::job_runner::Runner<RotorWork>,
    #[cfg(target_arch = "wasm32")]
    repaint: egui::Context,
    #[cfg(target_arch = "wasm32")]
    link: Option<super::web_solver::RotorLink>,
    #[cfg(target_arch = "wasm32")]
    busy: bool,
}

impl RotorRunner {
    #[must_use]
    pub fn new(repaint: egui::Context) -> Self {
        Self {
            #[cfg(not(target_arch = "wasm32"))]
            runner: super::job_runner::Runner::new(repaint),
            #[cfg(target_arch = "wasm32")]
            repaint,
            #[cfg(target_arch = "wasm32")]
            link: None,
            #[cfg(target_arch = "wasm32")]
            busy: false,
        }
    }

    /// Starts analysing `rotor` at `params`, cancelling a running job.
    pub fn start(&mut self, rotor: &Rotor, params: AnalysisParams) {
        #[cfg(not(target_arch = "wasm32"))]
        {
            let analysis = Analysis::new(rotor, params).map(Some).map_err(|e| e.to_string());
            self.runner.start(RotorWork { analysis, progress: (0, 1) });
        }
        #[cfg(target_arch = "wasm32")]
        {
            self.busy = true;
            self.link = Some(super::web_solver::RotorLink::start(rotor, params, &self.repaint));
            self.repaint.request_repaint();
        }
    }

    /// Events since the last call (on the web without a worker, one step of the work happens here).
    pub fn poll(&mut self) -> Vec<RotorEvent> {
        #[cfg(not(target_arch = "wasm32"))]
        return self.runner.poll();
        #[cfg(target_arch = "wasm32")]
        {
            let events: Vec<RotorEvent> =
                self.link.as_mut().map(super::web_solver::RotorLink::poll).unwrap_or_default();
            if events.iter().any(|e| matches!(e, RotorEvent::Done(_))) {
                self.busy = false;
            }
            events
        }
    }

    /// A job is running or its result has not been polled yet.
    #[must_use]
    pub fn busy(&self) -> bool {
        #[cfg(not(target_arch = "wasm32"))]
        return self.runner.busy();
        #[cfg(target_arch = "wasm32")]
        self.busy
    }
}
