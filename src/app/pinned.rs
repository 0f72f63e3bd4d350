//! The pinned results the views overlay: runtime state, never persisted.
//!
//! A [`Pin`] keeps only its name, case text and scalar cells (small, so pins persist with the settings
//! and export with the results). A view that overlays a pin needs more (the pad outline and film, the
//! pressure field, the coefficient curves), so the workbench keeps the pinned result itself:
//! - pinned in this session: the result on screen is shared (an `Arc`, no copy, no solve);
//! - after a restart, or when a view needs a stage the pinned result lacks (the coefficient curves of a
//!   pin made in the bearing view): the pin's case text is solved once, in the background, by a second
//!   solve slot ([`SolveJob`] in a [`Runner`] of its own; on the web without a worker it steps only in
//!   frames where the main solve is idle), and cached.
//!
//! Re-solving rather than storing drawables keeps every overlay exact (the same scene code draws live
//! and pinned) and works for views added later, at the cost of one solve per pin and session.

use crate::bearing::stages::{Request, StageId};
use crate::scene::compare::Pin;

use super::jobs::solve::SolveJob;
use super::jobs::{Event, Runner};
use super::Shown;

/// The identity of a pin: its name and the case it was solved from.
type Key = (String, String);

fn key(pin: &Pin) -> Key {
    (pin.name.clone(), pin.case_toml.clone())
}

/// Whether `k` is the key of `pin` (without building one: [`PinnedResults::want`] runs every frame).
fn is_key_of(k: &Key, pin: &Pin) -> bool {
    k.0 == pin.name && k.1 == pin.case_toml
}

/// What a view gets for a pin.
pub enum Pinned<'a> {
    Ready(&'a Shown),
    Solving,
    Failed(&'a str),
}

/// The pinned results kept for overlays, and the worker that re-solves pins.
pub struct PinnedResults {
    worker: Runner<SolveJob>,
    cache: Vec<(Key, Shown)>,
    solving: Option<(Key, Request)>,
    failed: Vec<(Key, String)>,
}

/// The result holds every stage in `needs`.
fn covers(shown: &Shown, needs: &[StageId]) -> bool {
    needs.iter().all(|s| match s {
        StageId::FrequencySweep => shown.frequency_sweep.is_some(),
        StageId::SpeedSweep => shown.speed_sweep.is_some(),
        StageId::Frf => shown.frf.is_some(),
        _ => true,
    })
}

impl PinnedResults {
    #[must_use]
    pub fn new(ctx: egui::Context) -> Self {
        Self { worker: Runner::new(&ctx), cache: Vec::new(), solving: None, failed: Vec::new() }
    }

    /// Keeps the result on screen as the pinned result of `pin` (just pinned).
    pub fn remember(&mut self, pin: &Pin, shown: &Shown) {
        let k = key(pin);
        self.cache.retain(|(c, _)| *c != k);
        self.cache.push((k, shown.clone()));
    }

    /// The result of `pin` with the stages in `needs`; starts its solve when it is not at hand.
    pub fn want(&mut self, pin: &Pin, needs: &[StageId]) -> Pinned<'_> {
        if let Some(i) = self.cache.iter().position(|(c, s)| is_key_of(c, pin) && covers(s, needs)) {
            return Pinned::Ready(&self.cache[i].1);
        }
        if let Some(i) = self.failed.iter().position(|(c, _)| is_key_of(c, pin)) {
            return Pinned::Failed(&self.failed[i].1);
        }
        if self.solving.as_ref().is_none_or(|(c, r)| !is_key_of(c, pin) || !needs.iter().all(|s| r.wanted.contains(s)))
        {
            match crate::model::load_case(&pin.case_toml, &[]) {
                Ok((_, case)) => {
                    let request = crate::scene::request::request(case, [needs]);
                    self.worker.submit(SolveJob::new(request.clone()));
                    self.solving = Some((key(pin), request));
                }
                Err(e) => {
                    self.failed.push((key(pin), format!("the pinned case does not load: {e}")));
                    return Pinned::Failed(&self.failed[self.failed.len() - 1].1);
                }
            }
        }
        Pinned::Solving
    }

    /// Takes in the worker's results (on the web: steps it within `budget_s`).
    pub fn poll(&mut self, budget_s: f64) {
        if !self.worker.busy() {
            return;
        }
        for event in self.worker.poll(budget_s) {
            let Some((k, _)) = &self.solving else { continue };
            let (outcome, complete) = match event {
                Event::Progress(_) => continue,
                Event::Partial(o) => (o, false),
                Event::Done(o) => (o, true),
                Event::Failed(error) => {
                    self.failed.push((k.clone(), error));
                    self.solving = None;
                    continue;
                }
            };
            if let Some(solution) = outcome.solution() {
                let shown = Shown {
                    solution,
                    frequency_sweep: outcome.frequency_sweep(),
                    speed_sweep: outcome.speed_sweep(),
                    frf: outcome.get(StageId::Frf),
                };
                let k = k.clone();
                self.cache.retain(|(c, _)| *c != k);
                self.cache.push((k, shown));
            }
            if complete {
                // Never asked again in a loop: a finished solve with no solution counts as failed.
                if !self.cache.iter().any(|(c, _)| c == k) {
                    self.failed.push((k.clone(), "the solve gave no solution".into()));
                }
                self.solving = None;
            }
        }
    }

    /// Completes one pin made before some output columns existed ([`Pin::complete_from`]): from its
    /// result when at hand, else by solving its case when this worker is free (a view's pin goes first).
    /// A pin whose case no longer solves keeps its gaps (the results panel says "not in this pin").
    pub fn complete(&mut self, pins: &mut [Pin]) {
        let Some(pin) =
            pins.iter_mut().find(|p| p.lacks_columns() && !self.failed.iter().any(|(k, _)| is_key_of(k, p)))
        else {
            return;
        };
        if let Some((_, shown)) = self.cache.iter().find(|(k, _)| is_key_of(k, pin)) {
            pin.complete_from(&shown.solution);
        } else if !self.worker.busy() {
            // The results panel's columns include the reduced coefficients.
            let _ = self.want(pin, &[StageId::Reduction]);
        }
    }

    /// A pin is being solved.
    #[must_use]
    pub fn busy(&self) -> bool {
        self.worker.busy()
    }

    /// Forgets the results of pins no longer in `pins`.
    pub fn retain(&mut self, pins: &[Pin]) {
        let keys: Vec<Key> = pins.iter().map(key).collect();
        self.cache.retain(|(k, _)| keys.contains(k));
        self.failed.retain(|(k, _)| keys.contains(k));
    }
}
