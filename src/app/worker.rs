//! Background solving: the app submits a [`Request`]; the worker runs the cached, steppable
//! [`Stages`] and reports progress, results and failures as [`Event`]s.
//!
//! - Native: a named thread owns the stages; jobs arrive over a channel, events go back over another
//!   and wake the UI with `request_repaint`. A newer job cancels the running one: the stages'
//!   [`Cancel`] hook compares the job's id with the latest submitted id, so even a long equilibrium stops
//!   within one film solve.
//! - Web: a web worker owns the stages ([`super::web_solver`]); jobs and events cross as bytes. Where no
//!   worker can run, the app calls [`Worker::poll`] every frame and the stages step until a time budget is
//!   spent; one step is one stage, or the part of an equilibrium solve that fits the budget (the coupled
//!   Newton suspends between pad placements and iterations, [`crate::bearing::Cancel::suspend`], and the
//!   next frame resumes from its iterate), or one THD outer iteration or the part of its equilibrium that
//!   fits ([`crate::bearing::thermal::resumable`]).
//!
//! A job runs in two phases: first the solution and the frequency sweep (what most views need, so they
//! update as soon as possible), then the speed sweep if the coefficient view asked for it.

use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Arc;

use crate::bearing::stages::{Outcome, Request, StageId, Stages, Step};
use crate::bearing::{Cancel, SolveError};

/// What the worker reports.
#[derive(Debug, Clone, serde::Serialize, serde::Deserialize)]
pub enum Event {
    Progress {
        job: u64,
        stage: StageId,
        fraction: f64,
    },
    /// A phase finished: the outcome so far (the speed sweep only after the second phase).
    Solved {
        job: u64,
        outcome: Outcome,
        complete: bool,
    },
    Failed {
        job: u64,
        error: String,
    },
}

/// Cancels a job once a newer one has been submitted.
pub(super) struct Superseded {
    pub latest: Arc<AtomicU64>,
    pub job: u64,
}

impl Cancel for Superseded {
    fn cancelled(&self) -> bool {
        self.latest.load(Ordering::Relaxed) != self.job
    }
}

/// One job being worked on, stepped by either runner.
#[derive(Clone, serde::Serialize, serde::Deserialize)]
pub(super) struct Running {
    pub job: u64,
    request: Request,
    /// False while working on the first phase (no speed sweep).
    second_phase: bool,
}

impl Running {
    fn phase_request(&self) -> Request {
        if self.second_phase {
            self.request.clone()
        } else {
            let first: Vec<StageId> = StageId::ALL.iter().copied().filter(|s| *s != StageId::SpeedSweep).collect();
            self.request.only(&first)
        }
    }

    /// One step of the stages; returns the event to report and whether the job is finished.
    pub fn step(&mut self, stages: &mut Stages, cancel: &dyn Cancel) -> (Option<Event>, bool) {
        let job = self.job;
        match stages.step(&self.phase_request(), cancel) {
            Ok(Step::Pending { stage, fraction }) => (Some(Event::Progress { job, stage, fraction }), false),
            Ok(Step::Done(outcome)) => {
                let more = !self.second_phase && self.request.wanted.contains(&StageId::SpeedSweep);
                self.second_phase = true;
                (Some(Event::Solved { job, outcome, complete: !more }), !more)
            }
            Err(SolveError::Cancelled) => (None, true),
            Err(e) => (Some(Event::Failed { job, error: e.to_string() }), true),
        }
    }
}

/// The background solver.
pub struct Worker {
    latest: Arc<AtomicU64>,
    next_id: u64,
    busy_job: Option<u64>,
    #[cfg(not(target_arch = "wasm32"))]
    native: native::Thread,
    #[cfg(target_arch = "wasm32")]
    web: super::web_solver::Link,
}

impl Worker {
    /// Starts the worker; `repaint` wakes the UI when an event is ready.
    #[must_use]
    pub fn new(repaint: egui::Context) -> Self {
        let latest = Arc::new(AtomicU64::new(0));
        Self {
            #[cfg(not(target_arch = "wasm32"))]
            native: native::Thread::spawn(latest.clone(), repaint),
            #[cfg(target_arch = "wasm32")]
            web: super::web_solver::Link::new(repaint),
            latest,
            next_id: 0,
            busy_job: None,
        }
    }

    /// Submits a request, superseding (and cancelling) any running job. Returns the job id.
    pub fn submit(&mut self, request: Request) -> u64 {
        self.next_id += 1;
        let job = self.next_id;
        self.latest.store(job, Ordering::Relaxed);
        self.busy_job = Some(job);
        let running = Running { job, request, second_phase: false };
        #[cfg(not(target_arch = "wasm32"))]
        self.native.send(running);
        #[cfg(target_arch = "wasm32")]
        self.web.start(running);
        job
    }

    /// Events since the last call (on the web this is where the work happens, within `budget_s`).
    pub fn poll(&mut self, budget_s: f64) -> Vec<Event> {
        #[cfg(not(target_arch = "wasm32"))]
        let events = {
            let _ = budget_s;
            self.native.drain()
        };
        #[cfg(target_arch = "wasm32")]
        let events = self.web.poll(budget_s, &self.latest);
        let latest = self.latest.load(Ordering::Relaxed);
        for e in &events {
            match e {
                Event::Solved { job, complete: true, .. } | Event::Failed { job, .. } if *job == latest => {
                    self.busy_job = None
                }
                _ => {}
            }
        }
        events.into_iter().filter(|e| event_job(e) == latest).collect()
    }

    /// A job is still running.
    #[must_use]
    pub fn busy(&self) -> bool {
        self.busy_job.is_some()
    }
}

pub(super) fn event_job(e: &Event) -> u64 {
    match e {
        Event::Progress { job, .. } | Event::Solved { job, .. } | Event::Failed { job, .. } => *job,
    }
}

#[cfg(not(target_arch = "wasm32"))]
mod native {
    use std::sync::atomic::{AtomicU64, Ordering};
    use std::sync::mpsc::{channel, Receiver, Sender};
    use std::sync::Arc;

    use super::{Event, Running, Superseded};
    use crate::bearing::stages::Stages;

    pub struct Thread {
        jobs: Sender<Running>,
        events: Receiver<Event>,
    }

    impl Thread {
        pub fn spawn(latest: Arc<AtomicU64>, repaint: egui::Context) -> Self {
            let (jobs, job_rx) = channel::<Running>();
            let (event_tx, events) = channel::<Event>();
            let spawned = std::thread::Builder::new().name("tiltpad-solver".into()).spawn(move || {
                let mut stages = Stages::new();
                while let Ok(mut running) = job_rx.recv() {
                    // Only the newest waiting job matters.
                    while let Ok(newer) = job_rx.try_recv() {
                        running = newer;
                    }
                    let cancel = Superseded { latest: latest.clone(), job: running.job };
                    loop {
                        if latest.load(Ordering::Relaxed) != running.job {
                            break;
                        }
                        let (event, finished) = running.step(&mut stages, &cancel);
                        if let Some(e) = event {
                            if event_tx.send(e).is_err() {
                                return;
                            }
                            repaint.request_repaint();
                        }
                        if finished {
                            break;
                        }
                    }
                }
            });
            if let Err(e) = spawned {
                log::error!("cannot start the solver thread: {e}");
            }
            Self { jobs, events }
        }

        pub fn send(&self, running: Running) {
            let _ = self.jobs.send(running);
        }

        pub fn drain(&self) -> Vec<Event> {
            self.events.try_iter().collect()
        }
    }
}

#[cfg(all(test, not(target_arch = "wasm32")))]
mod tests {
    use super::*;
    use crate::model::load_case;

    fn request(speed_rpm: f64, sweep: bool) -> Request {
        let set = [format!("operating.speed_rpm={speed_rpm}"), "mesh.fidelity=\"preview\"".to_string()];
        let case = load_case(include_str!("../../cases/compressor-bearing.toml"), &set).unwrap().1;
        let mut wanted = vec![StageId::Reduction, StageId::FrequencySweep];
        wanted.extend(sweep.then_some(StageId::SpeedSweep));
        Request {
            frequency_ratios: vec![0.5, 1.0],
            speeds_rad_s: if sweep {
                [8000.0, 9000.0].map(|n| crate::units::RPM.to_si(n)).to_vec()
            } else {
                Vec::new()
            },
            ..Request::of(case, &wanted)
        }
    }

    /// Polls until the latest job completes; returns every event seen.
    fn run_until_done(w: &mut Worker) -> Vec<Event> {
        let start = web_time::Instant::now();
        let mut seen = Vec::new();
        while w.busy() {
            assert!(start.elapsed().as_secs() < 120, "worker did not finish");
            seen.extend(w.poll(0.01));
            std::thread::sleep(std::time::Duration::from_millis(2));
        }
        seen
    }

    #[test]
    fn a_job_reports_progress_then_its_solution_then_the_speed_sweep() {
        let mut w = Worker::new(egui::Context::default());
        let job = w.submit(request(9000.0, true));
        let events = run_until_done(&mut w);
        assert!(events.iter().any(|e| matches!(e, Event::Progress { stage: StageId::Equilibrium, .. })));
        let solved: Vec<(bool, bool)> = events
            .iter()
            .filter_map(|e| match e {
                Event::Solved { job: j, outcome, complete } if *j == job => {
                    Some((*complete, outcome.speed_sweep().is_some()))
                }
                _ => None,
            })
            .collect();
        // First the solution without the sweep, then the complete outcome with it.
        assert_eq!(solved, vec![(false, false), (true, true)]);
    }

    #[test]
    fn a_newer_job_supersedes_the_running_one() {
        let mut w = Worker::new(egui::Context::default());
        let first = w.submit(request(9000.0, true));
        let second = w.submit(request(7000.0, false));
        assert!(second > first);
        let events = run_until_done(&mut w);
        // Only the newest job's events reach the app, and its solution is at its speed.
        assert!(events.iter().all(|e| event_job(e) == second));
        let speed = events.iter().find_map(|e| match e {
            Event::Solved { outcome, .. } => outcome.solution().map(|s| s.derived.speed_rpm),
            _ => None,
        });
        assert!((speed.unwrap() - 7000.0).abs() < 1e-9);
    }
}
