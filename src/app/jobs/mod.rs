//! Background work: one contract for every job the workbench runs off the UI thread ([`Job`], in [`job`]),
//! and one runner per platform behind [`Runner`]:
//!
//! - native: a named thread per slot ([`native`]);
//! - web: a web worker per slot ([`web`], the worker's side in [`remote`], [`worker_side`] and [`web_worker`]), or, where no
//!   worker starts, the job stepped inside the page's frames within a time budget ([`stepped`]).
//!
//! A **slot** is one [`Runner`]: the edited case's solve, the pins' re-solves, the sweep view's points, the
//! rotor view's analysis, the Control view's plants and its tuning each own one. Submitting a job supersedes
//! the slot's running job — everywhere the same way: the old job is cancelled at its next safe point and its
//! events are never reported. [`Runner::poll`] hands back the latest job's events only.
//!
//! The jobs, one file each: [`solve`] (a solver request, in two phases), [`sweep`] (a sweep's points),
//! [`rotor`] (a rotor analysis), [`control`] (the Control view's plants, and its loop closed at a tuning),
//! [`rig`] (the test rig's loop).
//! Adding a job: its file, and its line in [`registry`].

pub mod control;
pub mod job;
#[cfg(not(target_arch = "wasm32"))]
mod native;
pub mod registry;
pub mod remote;
pub mod rig;
pub mod rotor;
pub mod solve;
pub mod stepped;
pub mod sweep;
#[cfg(all(test, not(target_arch = "wasm32")))]
mod tests;
#[cfg(target_arch = "wasm32")]
mod web;
#[cfg(target_arch = "wasm32")]
pub mod web_worker;
pub mod worker_side;

pub use job::{Event, Job, JobError, Progress, Step};

/// One slot of background work: at most one job running, a newer one supersedes it.
pub struct Runner<J: Job> {
    repaint: egui::Context,
    next_id: u64,
    /// The latest job's id while it has not ended.
    running: Option<u64>,
    #[cfg(not(target_arch = "wasm32"))]
    thread: Option<Result<native::Thread<J>, String>>,
    #[cfg(target_arch = "wasm32")]
    link: web::Link<J>,
    /// A failure to report at the next poll (the thread could not start).
    failed: Option<String>,
}

impl<J: Job> Runner<J> {
    /// A slot; its thread or worker starts with its first job.
    #[must_use]
    pub fn new(repaint: &egui::Context) -> Self {
        Self {
            repaint: repaint.clone(),
            next_id: 0,
            running: None,
            #[cfg(not(target_arch = "wasm32"))]
            thread: None,
            #[cfg(target_arch = "wasm32")]
            link: web::Link::new(repaint.clone()),
            failed: None,
        }
    }

    /// Starts `job`, superseding the running one.
    pub fn submit(&mut self, job: J) {
        self.next_id += 1;
        let id = self.next_id;
        self.running = Some(id);
        #[cfg(not(target_arch = "wasm32"))]
        {
            let repaint = self.repaint.clone();
            match self.thread.get_or_insert_with(|| native::Thread::spawn(repaint)) {
                Ok(t) => t.send(id, job),
                Err(e) => self.failed = Some(e.clone()),
            }
        }
        #[cfg(target_arch = "wasm32")]
        self.link.submit(id, Some(job));
        self.repaint.request_repaint();
    }

    /// Stops the running job (nothing of it is reported any more).
    pub fn stop(&mut self) {
        if self.running.take().is_none() {
            return;
        }
        self.next_id += 1;
        #[cfg(not(target_arch = "wasm32"))]
        if let Some(Ok(t)) = &self.thread {
            t.cancel(self.next_id);
        }
        #[cfg(target_arch = "wasm32")]
        self.link.submit(self.next_id, None);
    }

    /// The latest job's events since the last call (on the web without a worker, its steps happen here,
    /// for up to `budget_s`).
    pub fn poll(&mut self, budget_s: f64) -> Vec<Event<J::Output>> {
        if let Some(e) = self.failed.take() {
            self.running = None;
            return vec![Event::Failed(e)];
        }
        #[cfg(not(target_arch = "wasm32"))]
        let events = {
            let _ = budget_s;
            self.thread.as_ref().and_then(|t| t.as_ref().ok()).map(native::Thread::drain).unwrap_or_default()
        };
        #[cfg(target_arch = "wasm32")]
        let events = self.link.poll(budget_s);
        let Some(latest) = self.running else { return Vec::new() };
        let events: Vec<Event<J::Output>> =
            events.into_iter().filter(|(id, _)| *id == latest).map(|(_, e)| e).collect();
        if events.iter().any(Event::ends) {
            self.running = None;
        }
        events
    }

    /// A job is running (or its end has not been polled yet).
    #[must_use]
    pub fn busy(&self) -> bool {
        self.running.is_some()
    }
}
