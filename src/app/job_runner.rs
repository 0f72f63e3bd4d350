//! Runs a view's work off the UI thread: any steppable [`Work`] (the Control view's speed sweep that solves
//! the bearings and builds the plants, its loop closed again at the sliders' gains, its test-rig loop; the
//! rotor view's analysis, [`super::rotor_worker`]).
//!
//! - Native: one named thread per job loops [`Work::step`], reports progress over a channel and wakes the UI
//!   with `request_repaint`; a newer job (or dropping the runner) raises the old job's cancel flag, checked
//!   between steps.
//! - Web (no threads): [`Runner::poll`] does steps for up to [`WEB_FRAME_BUDGET_S`] of each frame and asks
//!   for the next frame (a bearing solve is not split between frames).

/// A job done in steps.
pub trait Work: Send + 'static {
    type Output: Send + 'static;
    /// One step: `Ok(None)` while there is more to do, `Ok(Some(_))` when finished.
    ///
    /// # Errors
    /// Why the job failed, for the view to show.
    fn step(&mut self) -> Result<Option<Self::Output>, String>;
    /// Steps done and in all.
    fn progress(&self) -> (usize, usize);
    /// The name of the native thread that runs it.
    const THREAD: &'static str = "tiltpad-work";
}

/// What a job reports.
#[derive(Debug, Clone)]
pub enum Event<T> {
    Progress { done: usize, of: usize },
    Done(Result<T, String>),
}

/// Time a web frame spends on steps [s].
#[cfg(target_arch = "wasm32")]
const WEB_FRAME_BUDGET_S: f64 = 0.03;

/// One background job at a time.
pub struct Runner<W: Work> {
    repaint: egui::Context,
    #[cfg(not(target_arch = "wasm32"))]
    job: Option<native::Job<W::Output>>,
    #[cfg(target_arch = "wasm32")]
    work: Option<W>,
    busy: bool,
}

impl<W: Work> Runner<W> {
    #[must_use]
    pub fn new(repaint: egui::Context) -> Self {
        Self {
            repaint,
            #[cfg(not(target_arch = "wasm32"))]
            job: None,
            #[cfg(target_arch = "wasm32")]
            work: None,
            busy: false,
        }
    }

    /// Starts `work`, cancelling a running job.
    pub fn start(&mut self, work: W) {
        self.busy = true;
        #[cfg(not(target_arch = "wasm32"))]
        {
            self.job = Some(native::Job::spawn(work, self.repaint.clone()));
        }
        #[cfg(target_arch = "wasm32")]
        {
            self.work = Some(work);
        }
        self.repaint.request_repaint();
    }

    /// Events since the last call (on the web, the steps happen here).
    pub fn poll(&mut self) -> Vec<Event<W::Output>> {
        #[cfg(not(target_arch = "wasm32"))]
        let events: Vec<Event<W::Output>> = self.job.as_ref().map(native::Job::drain).unwrap_or_default();
        #[cfg(target_arch = "wasm32")]
        let events = self.poll_web();
        if events.iter().any(|e| matches!(e, Event::Done(_))) {
            self.busy = false;
        }
        events
    }

    #[cfg(target_arch = "wasm32")]
    fn poll_web(&mut self) -> Vec<Event<W::Output>> {
        let Some(work) = self.work.as_mut() else { return Vec::new() };
        let start = web_time::Instant::now();
        loop {
            match work.step() {
                Ok(None) if start.elapsed().as_secs_f64() < WEB_FRAME_BUDGET_S => {}
                Ok(None) => {
                    let (done, of) = work.progress();
                    self.repaint.request_repaint();
                    return vec![Event::Progress { done, of }];
                }
                Ok(Some(out)) => {
                    self.work = None;
                    return vec![Event::Done(Ok(out))];
                }
                Err(e) => {
                    self.work = None;
                    return vec![Event::Done(Err(e))];
                }
            }
        }
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

    use super::{Event, Work};

    /// One job on its own thread.
    pub struct Job<T> {
        events: Receiver<Event<T>>,
        cancel: Arc<AtomicBool>,
    }

    impl<T: Send + 'static> Job<T> {
        pub fn spawn<W: Work<Output = T>>(mut work: W, repaint: egui::Context) -> Self {
            let (tx, events) = channel();
            let cancel = Arc::new(AtomicBool::new(false));
            let flag = cancel.clone();
            let spawned = std::thread::Builder::new().name(W::THREAD.into()).spawn(move || {
                while !flag.load(Ordering::Relaxed) {
                    let event = match work.step() {
                        Ok(None) => {
                            let (done, of) = work.progress();
                            Event::Progress { done, of }
                        }
                        Ok(Some(out)) => Event::Done(Ok(out)),
                        Err(e) => Event::Done(Err(e)),
                    };
                    let done = matches!(event, Event::Done(_));
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
                let _ = tx.send(Event::Done(Err(format!("cannot start the thread {}: {e}", W::THREAD))));
                return Self { events, cancel };
            }
            Self { events, cancel }
        }

        pub fn drain(&self) -> Vec<Event<T>> {
            self.events.try_iter().collect()
        }
    }

    impl<T> Drop for Job<T> {
        fn drop(&mut self) {
            self.cancel.store(true, Ordering::Relaxed);
        }
    }
}
