//! The contract of a background job ([`Job`]): what every piece of work the workbench runs off the UI thread
//! implements — the edited case's solve, a pin's re-solve, a sweep's points, a rotor analysis, the Control
//! view's plants and its loop closed again — so that one runner per platform ([`super::Runner`]) runs them
//! all, supersedes them the same way and reports them the same way.
//!
//! - A job is a value (`Serialize`: on the web it crosses to a worker as bytes) that does its work in steps:
//!   [`Job::step`] does one unit (one solver stage or the part of it that fits, one sweep point, one speed)
//!   and returns [`Step::More`] with its progress — and, when it has something to show already, an output
//!   (a sweep's new rows, a solve's first phase) — or [`Step::Done`] with the last output.
//! - `cancel` is the runner's: [`Cancel::cancelled`] once a newer job of the same slot was submitted (the job
//!   then returns [`JobError::Cancelled`] at its next safe point), [`Cancel::suspend`] when a web frame's
//!   budget is spent (the job returns `More` and resumes at the next call). Errors are failures; progress and
//!   suspension are return values.
//! - [`Job::Keep`] is what the runner keeps between the jobs of one slot (the solver stages with their
//!   cache, so a re-solve after an edit reuses the films): created once per slot, handed to every step.
//!
//! Adding a job: one file implementing [`Job`], and its line in [`super::registry`] (which the web worker
//! reads to rebuild a job from its bytes).

use serde::de::DeserializeOwned;
use serde::{Deserialize, Serialize};

use crate::bearing::Cancel;

/// Work done in steps, off the UI thread.
pub trait Job: Serialize + DeserializeOwned + Send + 'static {
    /// The job's name: the registry's key on the web worker, and the native thread's name (`tiltpad-<NAME>`).
    const NAME: &'static str;
    /// What the job hands back (partial outputs and the last one).
    type Output: Serialize + DeserializeOwned + Send + 'static;
    /// What the runner keeps between the jobs of one slot.
    type Keep: Default + Send + 'static;

    /// One unit of work.
    ///
    /// # Errors
    /// [`JobError::Cancelled`] when `cancel` says so; [`JobError::Failed`] with the reason the view shows.
    fn step(&mut self, keep: &mut Self::Keep, cancel: &dyn Cancel) -> Result<Step<Self::Output>, JobError>;
}

/// What one step did.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub enum Step<O> {
    /// More to do; `output`: something to show already.
    More { progress: Progress, output: Option<O> },
    /// Finished, with the last output.
    Done(O),
}

/// How far a job is: `done` of `of` units of its own (stages, points, speeds), and what it works on.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, Default)]
pub struct Progress {
    pub done: f64,
    pub of: f64,
    /// What is under way ("equilibrium", "speed 12 of 41").
    pub label: String,
}

impl Progress {
    #[must_use]
    pub fn new(done: f64, of: f64, label: impl Into<String>) -> Self {
        Self { done, of, label: label.into() }
    }

    /// `done / of` in [0, 1] (0 when nothing is known).
    #[must_use]
    pub fn fraction(&self) -> f64 {
        if self.of > 0.0 {
            (self.done / self.of).clamp(0.0, 1.0)
        } else {
            0.0
        }
    }
}

/// Why a job stopped without finishing.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub enum JobError {
    /// A newer job of the same slot was submitted (or the slot was dropped): nobody waits for this one.
    Cancelled,
    /// The job failed; the view shows why.
    Failed(String),
}

impl JobError {
    /// A failure, from anything that says why.
    pub fn failed(e: impl std::fmt::Display) -> Self {
        Self::Failed(e.to_string())
    }
}

/// What a runner reports to the slot's owner (the latest job's only).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub enum Event<O> {
    Progress(Progress),
    /// An output to show while the job goes on.
    Partial(O),
    /// The job finished with this output.
    Done(O),
    Failed(String),
}

impl<O> Event<O> {
    /// The job ended (finished or failed).
    #[must_use]
    pub fn ends(&self) -> bool {
        matches!(self, Self::Done(_) | Self::Failed(_))
    }
}

/// Runs `job` to the end in the caller's thread (tests, and a job that must not wait): every output, in order.
///
/// # Errors
/// The job's failure.
pub fn run_to_end<J: Job>(mut job: J, keep: &mut J::Keep) -> Result<Vec<J::Output>, String> {
    let mut outputs = Vec::new();
    loop {
        match job.step(keep, &crate::bearing::NoCancel) {
            Ok(Step::More { output, .. }) => outputs.extend(output),
            Ok(Step::Done(o)) => {
                outputs.push(o);
                return Ok(outputs);
            }
            Err(JobError::Cancelled) => return Err("cancelled".into()),
            Err(JobError::Failed(e)) => return Err(e),
        }
    }
}
