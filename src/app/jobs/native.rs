//! The native runner of one slot: a named thread (`tiltpad-<job name>`) that owns the slot's
//! [`Job::Keep`], takes jobs from a channel and sends their events back, waking the UI with
//! `request_repaint`. A newer job supersedes the running one: the job's cancel hook compares its id with the
//! latest submitted id, so even a long equilibrium stops within one film solve; only the newest waiting job
//! is started. Dropping the runner cancels the running job and ends the thread.

use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::mpsc::{channel, Receiver, Sender};
use std::sync::Arc;

use super::job::{Event, Job, JobError, Step};
use crate::bearing::Cancel;

/// No job: the id the latest-job counter holds once the runner is dropped.
const DROPPED: u64 = u64::MAX;

/// Cancels a job once a newer one has been submitted.
pub(super) struct Superseded<'a> {
    pub latest: &'a AtomicU64,
    pub id: u64,
}

impl Cancel for Superseded<'_> {
    fn cancelled(&self) -> bool {
        self.latest.load(Ordering::Relaxed) != self.id
    }
}

/// A slot's thread.
pub(super) struct Thread<J: Job> {
    jobs: Sender<(u64, J)>,
    events: Receiver<(u64, Event<J::Output>)>,
    latest: Arc<AtomicU64>,
}

impl<J: Job> Thread<J> {
    /// Starts the thread; why it cannot start.
    pub fn spawn(repaint: egui::Context) -> Result<Self, String> {
        let (jobs, job_rx) = channel::<(u64, J)>();
        let (event_tx, events) = channel();
        let latest = Arc::new(AtomicU64::new(0));
        let flag = latest.clone();
        let spawned = std::thread::Builder::new().name(format!("tiltpad-{}", J::NAME)).spawn(move || {
            let mut keep = J::Keep::default();
            while let Ok(mut next) = job_rx.recv() {
                // Only the newest waiting job matters.
                while let Ok(newer) = job_rx.try_recv() {
                    next = newer;
                }
                let (id, mut job) = next;
                let cancel = Superseded { latest: &flag, id };
                while !cancel.cancelled() {
                    let (event, ends) = match job.step(&mut keep, &cancel) {
                        Ok(Step::More { progress, output }) => {
                            if let Some(o) = output {
                                if event_tx.send((id, Event::Partial(o))).is_err() {
                                    return;
                                }
                            }
                            (Some(Event::Progress(progress)), false)
                        }
                        Ok(Step::Done(o)) => (Some(Event::Done(o)), true),
                        Err(JobError::Cancelled) => (None, true),
                        Err(JobError::Failed(e)) => (Some(Event::Failed(e)), true),
                    };
                    if let Some(e) = event {
                        if event_tx.send((id, e)).is_err() {
                            return;
                        }
                        repaint.request_repaint();
                    }
                    if ends {
                        break;
                    }
                }
            }
        });
        match spawned {
            Ok(_) => Ok(Self { jobs, events, latest }),
            Err(e) => Err(format!("cannot start the thread tiltpad-{}: {e}", J::NAME)),
        }
    }

    /// Sends job `id`, superseding the running one.
    pub fn send(&self, id: u64, job: J) {
        self.latest.store(id, Ordering::Relaxed);
        let _ = self.jobs.send((id, job));
    }

    /// Cancels the running job without starting another.
    pub fn cancel(&self, id: u64) {
        self.latest.store(id, Ordering::Relaxed);
    }

    /// Events since the last call, with the id of the job each is of.
    pub fn drain(&self) -> Vec<(u64, Event<J::Output>)> {
        self.events.try_iter().collect()
    }
}

impl<J: Job> Drop for Thread<J> {
    fn drop(&mut self) {
        self.latest.store(DROPPED, Ordering::Relaxed);
    }
}
