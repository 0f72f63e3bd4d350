//! A slot's jobs stepped in the caller's thread, a time budget at a time: how the web build runs a job where
//! no web worker starts (inside the page's frames), how the web worker itself runs it between looks at its
//! message queue, and what the tests use to check a job's steps without threads.
//!
//! [`Stepped::run_for`] steps the current job until `budget_s` is spent (at least one step); the job's solver
//! is asked to pause when the budget is spent ([`FrameBudget`]), so one long stage spreads over calls. Only
//! the latest job's events come back: [`Stepped::start`] supersedes the one under way.

use web_time::Instant;

use super::job::{Event, Job, JobError, Step};
use crate::bearing::{Cancel, FrameBudget, NoCancel};

/// The current job of a slot, with what the slot keeps between jobs.
pub struct Stepped<J: Job> {
    keep: J::Keep,
    job: Option<J>,
}

impl<J: Job> Default for Stepped<J> {
    fn default() -> Self {
        Self { keep: J::Keep::default(), job: None }
    }
}

impl<J: Job> Stepped<J> {
    /// Starts `job`, dropping the one under way.
    pub fn start(&mut self, job: J) {
        self.job = Some(job);
    }

    /// Drops the job under way.
    pub fn stop(&mut self) {
        self.job = None;
    }

    /// A job is under way.
    #[must_use]
    pub fn busy(&self) -> bool {
        self.job.is_some()
    }

    /// Steps the job until `budget_s` is spent (at least one step); its events, the last progress only.
    pub fn run_for(&mut self, budget_s: f64) -> Vec<Event<J::Output>> {
        self.run_with(&FrameBudget::new(&NoCancel, Instant::now(), budget_s))
    }

    /// Steps the job until `cancel` asks to suspend (at least one step).
    pub fn run_with(&mut self, cancel: &dyn Cancel) -> Vec<Event<J::Output>> {
        let mut events = Vec::new();
        let mut progress = None;
        while let Some(job) = self.job.as_mut() {
            match job.step(&mut self.keep, cancel) {
                Ok(Step::More { progress: p, output }) => {
                    progress = Some(p);
                    events.extend(output.map(Event::Partial));
                }
                Ok(Step::Done(o)) => {
                    events.push(Event::Done(o));
                    self.job = None;
                }
                Err(JobError::Cancelled) => self.job = None,
                Err(JobError::Failed(e)) => {
                    events.push(Event::Failed(e));
                    self.job = None;
                }
            }
            if cancel.suspend() || cancel.cancelled() {
                break;
            }
        }
        // The progress first: the outputs after it are newer.
        if let (Some(p), true) = (progress, self.job.is_some()) {
            events.insert(0, Event::Progress(p));
        }
        events
    }
}
