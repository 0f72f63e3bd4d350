//! The list of stages and the computation that runs them ([`Stages`]): the one entrance to the solver.
//!
//! ## Adding a stage
//! 1. One file `stages/my_stage.rs`: `#[derive(Default)] pub struct MyStage` (its resumable state, if any) and
//!    `impl Stage for MyStage` — `Inputs` (its view of the case, [`super::view`], and what it takes from the
//!    request) with their exhaustive builder, `Output`, `NEEDS`, `poll`, `publish`.
//! 2. Its name in [`StageId`] (`stages/id.rs`), after the stages it reads, and one line in the `stages!`
//!    list below: `MyStage => my_stage::MyStage,`.
//!
//! The slot, the label, the execution counter and the dependency order come from that line. A view that
//! shows the new result lists `StageId::MyStage` in its needs and reads it with
//! `outcome.get::<T>(StageId::MyStage)` (`T`: what `publish` returns, e.g. `Arc<MyResult>` → `get::<MyResult>`).

use std::sync::Arc;

use crate::bearing::frf::model::FrfModel;
use crate::bearing::report::error::{InternalError, SolveError};
use crate::bearing::report::progress::{Cancel, NoCancel, Progress};
use crate::bearing::solution::Solution;
use crate::bearing::stages::id::StageId;
use crate::bearing::stages::outcome::{Outcome, Step};
use crate::bearing::stages::request::Request;
use crate::bearing::stages::stage::{AnySlot, Reader, Registered, Slot, Solver, Stage, Standing};
use crate::bearing::stages::stamp::Stamp;
use crate::bearing::stages::{
    coefficients, equilibrium, films, frequency_sweep, frf, reduction, speed_sweep, stage::Ctx, thermal,
};
use crate::model::Case;

/// Registers the stages: each one's id, label, needs and slot.
macro_rules! stages {
    ($($id:ident => $module:ident :: $ty:ident,)*) => {
        $(impl Registered for $module::$ty { const ID: StageId = StageId::$id; })*

        impl StageId {
            /// What the status bar says while the stage runs.
            #[must_use]
            pub fn label(self) -> &'static str {
                match self { $(Self::$id => <$module::$ty as Stage>::LABEL,)* }
            }

            /// Every stage it may read.
            pub(super) fn declared(self) -> &'static [StageId] {
                match self { $(Self::$id => <$module::$ty as Stage>::NEEDS,)* }
            }

            /// The stages it reads for this request (none when it does not apply).
            pub(super) fn needs(self, req: &Request) -> &'static [StageId] {
                match self {
                    $(Self::$id => <$module::$ty as Stage>::inputs(req).map_or(&[], |i| <$module::$ty as Stage>::needs(&i)),)*
                }
            }
        }

        fn registry(keep: usize) -> Vec<Option<Box<dyn AnySlot>>> {
            let mut slots: Vec<Option<Box<dyn AnySlot>>> = StageId::ALL.iter().map(|_| None).collect();
            $(slots[StageId::$id.index()] = Some(Box::new(Slot::<$module::$ty>::new(keep)));)*
            slots
        }
    };
}

stages! {
    Films => films::FilmsStage,
    Equilibrium => equilibrium::EquilibriumStage,
    Thermal => thermal::ThermalStage,
    Coefficients => coefficients::CoefficientsStage,
    Reduction => reduction::ReductionStage,
    FrequencySweep => frequency_sweep::FrequencySweepStage,
    SpeedSweep => speed_sweep::SpeedSweepStage,
    Frf => frf::FrfStage,
}

/// The cached, steppable computation: one slot per registered stage, each keeping its output under the
/// inputs it was computed for.
pub struct Stages {
    pub(super) slots: Vec<Option<Box<dyn AnySlot>>>,
    /// Per slot: its last published solution with the request's title and case on it.
    stamps: Vec<Stamp>,
}

impl Default for Stages {
    fn default() -> Self {
        Self::new()
    }
}

impl Stages {
    /// Keeps one output per stage: the last one (the workbench, a study).
    #[must_use]
    pub fn new() -> Self {
        Self::keeping(1)
    }

    /// Keeps up to `outputs` outputs per stage (the films: one), so a caller that returns to earlier inputs
    /// finds them (a rotor analysis probing speeds it solved before).
    #[must_use]
    pub fn keeping(outputs: usize) -> Self {
        Self { slots: registry(outputs.max(1)), stamps: StageId::ALL.iter().map(|_| Stamp::default()).collect() }
    }

    /// The wanted stages and every stage they read for this request, transitively (by [`StageId`] order).
    pub(super) fn needed(req: &Request) -> Vec<bool> {
        let mut needed = vec![false; StageId::ALL.len()];
        let mut stack: Vec<StageId> = req.wanted.clone();
        while let Some(s) = stack.pop() {
            if !std::mem::replace(&mut needed[s.index()], true) {
                stack.extend_from_slice(s.needs(req));
            }
        }
        needed
    }

    /// Does one unit of work towards `req`: the first needed stage that is not current, upstream first.
    ///
    /// # Errors
    /// The failure of the stage worked on (the caller keeps its last good outcome).
    pub fn step(&mut self, req: &Request, cancel: &dyn Cancel) -> Result<Step, SolveError> {
        let needed = Self::needed(req);
        for (i, &id) in StageId::ALL.iter().enumerate() {
            let stale = needed[i] && self.slots[i].as_ref().is_some_and(|s| s.standing(req) == Standing::Stale);
            if !stale {
                continue;
            }
            let Some(mut slot) = self.slots[i].take() else { continue };
            let reader = Reader { label: id.label(), needs: id.declared() };
            let mut ctx = Ctx { slots: &mut self.slots, reader, start: req.start, nested: nested_stages };
            let result = slot.poll(req, &mut ctx, cancel);
            self.slots[i] = Some(slot);
            let fraction = match result? {
                Progress::Done(()) => 1.0,
                Progress::Suspended(f) => f,
            };
            return Ok(Step::Pending { stage: id, fraction });
        }
        let mut outputs = Vec::new();
        for &id in &req.wanted {
            if let Some(o) = self.slots[id.index()].as_mut().and_then(|s| s.publish(req)) {
                outputs.push((id, self.stamps[id.index()].stamp(o, &req.case)));
            }
        }
        Ok(Step::Done(Outcome { outputs }))
    }

    /// Runs [`Self::step`] until done.
    ///
    /// # Errors
    /// As [`Self::step`].
    pub fn run(&mut self, req: &Request, cancel: &dyn Cancel) -> Result<Outcome, SolveError> {
        loop {
            if let Step::Done(o) = self.step(req, cancel)? {
                return Ok(o);
            }
        }
    }

    /// The solution of `req`'s case ([`Request::solution`] and its start).
    ///
    /// # Errors
    /// As [`Self::step`].
    pub fn solution(&mut self, req: &Request, cancel: &dyn Cancel) -> Result<Arc<Solution>, SolveError> {
        let req = Request { wanted: vec![StageId::Reduction], ..req.clone() };
        self.run(&req, cancel)?.solution().ok_or(unpublished(StageId::Reduction))
    }

    /// The solution of `req`'s case with its full coefficients, inertia included ([`Request::coefficients`]
    /// and its start).
    ///
    /// # Errors
    /// As [`Self::step`].
    pub fn coefficients(&mut self, req: &Request, cancel: &dyn Cancel) -> Result<Arc<Solution>, SolveError> {
        let req = Request { wanted: vec![StageId::Coefficients], ..req.clone() };
        self.run(&req, cancel)?.coefficients().ok_or(unpublished(StageId::Coefficients))
    }

    /// The bearing of `case` linearised for its injection ports ([`Request::frf`]).
    ///
    /// # Errors
    /// [`SolveError::NoHydraulics`] for a case without `[hydraulics]`; the equilibrium's errors.
    pub fn frf(&mut self, case: &Case, cancel: &dyn Cancel) -> Result<Arc<FrfModel>, SolveError> {
        if case.hydraulics.is_none() {
            return Err(SolveError::NoHydraulics);
        }
        self.run(&Request::frf(case.clone()), cancel)?.frf().ok_or(unpublished(StageId::Frf))
    }

    /// How many times a stage has run to its output (a speed sweep counts once per sweep).
    #[must_use]
    pub fn runs(&self, stage: StageId) -> usize {
        self.slots[stage.index()].as_ref().map_or(0, |s| s.runs())
    }

    /// Runs of every stage, in [`StageId::ALL`] order.
    #[must_use]
    pub fn all_runs(&self) -> Vec<(StageId, usize)> {
        StageId::ALL.iter().map(|&s| (s, self.runs(s))).collect()
    }
}

impl Solver for Stages {
    fn step(&mut self, req: &Request, cancel: &dyn Cancel) -> Result<Step, SolveError> {
        Stages::step(self, req, cancel)
    }
}

fn nested_stages() -> Box<dyn Solver> {
    Box::new(Stages::new())
}

fn unpublished(stage: StageId) -> SolveError {
    SolveError::Internal(InternalError::Unpublished { stage: stage.label().into() })
}

/// Solves a case from scratch: the three-line form of [`Stages::solution`] for one case.
///
/// # Errors
/// See [`SolveError`].
pub fn solve_case(case: &Case) -> Result<Solution, SolveError> {
    let solution = Stages::new().solution(&Request::solution(case.clone()), &NoCancel)?;
    Ok(Arc::unwrap_or_clone(solution))
}

/// A preview-fidelity solve of the shipped compressor bearing with `set` overrides (tests of the result
/// checks and comparisons).
#[cfg(test)]
pub(crate) fn compressor_preview(set: &[&str]) -> Solution {
    let mut set: Vec<String> = set.iter().map(|s| (*s).to_string()).collect();
    set.push("mesh.fidelity=\"preview\"".into());
    let (_, case) = crate::model::load_case(include_str!("../../../cases/compressor-bearing.toml"), &set).unwrap();
    solve_case(&case).unwrap()
}
