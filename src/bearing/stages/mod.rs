//! # Stages: scene-driven, cached, steppable computation with typed inputs
//!
//! A [`Request`] names the stages whose results the open views show ([`StageId`]s; built in
//! [`crate::scene::request`]) and carries the case. [`Stages::step`] brings every needed stage up to date,
//! one unit of work per call, upstream stages first. Each stage's output is cached under its **inputs**: a
//! value that holds exactly what the output depends on, so an edit that does not enter a stage's inputs
//! never reruns it.
//!
//! | stage            | reads from the case (and the request)                                    | reads the outputs of |
//! |------------------|--------------------------------------------------------------------------|----------------------|
//! | `Films`          | R, L, C_b; per pad θ_le, β, θ_p, C_p, t, orifices and its coordinates (kind, which pivot stiffnesses are given); element counts, half model; with `physics.pad_modes > 0` the modes' E, ν, density, pad layers | — |
//! | `Equilibrium`    | Films + pivot stiffness values and Hertz pivot contacts, preloads (reported); µ(T), oil ρ (regime warnings); Ω, load, T_film, p_inj, T_inj; cavitation, touchdown film | Films |
//! | `Thermal`        | Equilibrium + pad radial elements; oil c_p, k; T_supply; every `[thermal]` value (with pad growth: the pads' E, ν) — THD cases only | Films, Equilibrium |
//! | `Coefficients`   | Equilibrium (+ Thermal for THD) + pad density (the inertia `M`)          | Equilibrium, Thermal |
//! | `Reduction`      | Coefficients + ω/Ω: the solution the views show                          | Coefficients         |
//! | `FrequencySweep` | Coefficients + the request's ratios ω/Ω                                  | Coefficients         |
//! | `SpeedSweep`     | Coefficients' inputs with Ω left out + ω/Ω + the request's speeds        | Films                |
//! | `Frf`            | Equilibrium + pad density + the pads each `[hydraulics]` port feeds      | Films, Equilibrium   |
//!
//! Each row is the `Inputs` struct of the stage's file, built by a function that destructures [`Case`] and
//! its sub-structs **exhaustively (no `..`)**: adding a field anywhere in `Case` is a compile error in
//! every builder until someone decides, stage by stage, whether it reads it.
//!
//! Read by no stage: the title and the case itself (stamped on the published solution), Young's modulus and
//! Poisson's ratio of rigid pads (`physics.pad_modes = 0`), the fidelity name (its element counts are read),
//! the oil's name, the node budget `mesh.max_nodes` (checked when the case is validated, before any stage
//! runs), and of the `[hydraulics]` section everything but the ports' pads (the valve, lines and rig enter
//! only the FRF view's frequency loop, run on the `Frf` stage's output), and the design limits `[limits]`
//! (checked on the published solution by [`crate::bearing::solution::limits`]).
//! Editing them runs nothing. The pivot stiffnesses and the pad density are not read by the films: the
//! stages that solve install the pads' structure in the films' model ([`films::install_structure`],
//! [`crate::bearing::BearingModel::set_structure`]) without rebuilding it; the density reaches only
//! `Coefficients` and the stages after it (and the speed sweep, whose points keep reduced coefficients).
//!
//! ## The contract of a stage ([`Stage`])
//! - `Inputs` (`PartialEq + Clone`) holds the values the output depends on, built by `Stage::inputs`, which
//!   **destructures [`Case`] and each of its sub-structs exhaustively, without `..`**: adding a field anywhere
//!   in `Case` is a compile error in every stage's builder until someone decides, stage by stage, whether it
//!   reads it. A stage that reads another's output nests that stage's inputs in its own, so its key covers
//!   everything upstream too.
//! - `poll` does one unit of work and returns [`Progress::Done`] with the output or [`Progress::Suspended`]
//!   with the fraction done (a paused equilibrium, one THD outer iteration, one sweep point): suspension is a
//!   return value, errors are failures. Resumable state lives in the stage value, keyed by the inputs it is
//!   for ([`Cached`]).
//! - Other stages' outputs are read through [`Ctx`], which refuses a stage not listed in `NEEDS` and an
//!   output that is not current for the request (an error naming both: a bug in the registration order).
//! - `publish` hands an output to the caller ([`Outcome`]); internal stages (the films) publish nothing.
//!
//! ## Adding a stage
//! 1. One file `stages/my_stage.rs`: `#[derive(Default)] pub struct MyStage` (its resumable state, if any) and
//!    `impl Stage for MyStage` — `Inputs` with their exhaustive builder, `Output`, `NEEDS`, `poll`,
//!    `publish`.
//! 2. One line in the `stages!` list below, after the stages it reads: `MyStage => my_stage::MyStage,`.
//!
//! Nothing else changes: the id, the slot, the label, the execution counter and the dependency order come
//! from that line. A view that shows the new result lists `StageId::MyStage` in its needs (a constant in
//! [`crate::scene::request`], chosen by `View::needs` in `app::state`) and reads it with
//! `outcome.get::<T>(StageId::MyStage)` (`T`: what `publish` returns, e.g. `Arc<MyResult>` → `get::<MyResult>`).
//!
//! The native worker loops over [`Stages::step`] on its thread; the web build calls it within a per-frame
//! time budget ([`Cancel::suspend`] asks long stages to pause). Execution counters ([`Stages::runs`]) let
//! tests assert what ran.

mod cache;
mod wire;
use std::any::Any;
use std::sync::Arc;

use serde::{Deserialize, Serialize};

use crate::model::Case;

use crate::bearing::report::error::SolveError;
use crate::bearing::report::progress::{Cancel, Progress};
use crate::bearing::solution::Solution;

pub use cache::Cached;
pub use equilibrium::MAX_SUSPENSIONS;
pub use frequency_sweep::FrequencySweep;
pub use speed_sweep::{SpeedPoint, SweepValues};
pub use wire::{from_bytes, to_bytes, OutputData, UnnamedOutput, WireError};

/// One unit of a stage's work: its output, or paused with the fraction of the work done.
pub type Poll<T> = Progress<T, f64>;

/// An output handed to the caller (downcast with [`Outcome::get`]).
pub type Published = Arc<dyn Any + Send + Sync>;

/// A stage of the computation (module documentation).
pub trait Stage: Default + 'static {
    /// What the status bar says while it runs.
    const LABEL: &'static str;
    /// The stages whose outputs this one reads (upstream in the registration order).
    const NEEDS: &'static [StageId];
    /// Everything the output depends on.
    type Inputs: PartialEq + Clone + std::fmt::Debug;
    type Output: 'static;

    /// This stage's inputs for the request; `None` when it does not apply (a thermal stage of an isothermal
    /// case).
    fn inputs(req: &Request) -> Option<Self::Inputs>;

    /// One unit of work towards the output for `inputs`.
    ///
    /// # Errors
    /// The stage's failure (the caller keeps its last good outcome).
    fn poll(
        &mut self,
        inputs: &Self::Inputs,
        ctx: &mut Ctx<'_>,
        cancel: &dyn Cancel,
    ) -> Result<Poll<Self::Output>, SolveError>;

    /// The output as the caller sees it (`None`: internal).
    fn publish(&mut self, _output: &Self::Output, _req: &Request) -> Option<Published> {
        None
    }
}

/// Registration: the stage's id (implemented by `stages!`).
pub trait Registered: Stage {
    const ID: StageId;
}

/// Registers the stages, in the order they run (a stage after those it reads): declares each one's module,
/// its [`StageId`] and its slot.
macro_rules! stages {
    ($($(#[$doc:meta])* $id:ident => $module:ident :: $ty:ident,)*) => {
        $(pub mod $module;)*

        /// The stages, in the order they run.
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
        pub enum StageId { $($(#[$doc])* $id,)* }

        impl StageId {
            pub const ALL: &'static [StageId] = &[$(StageId::$id),*];

            /// What the status bar says while the stage runs.
            #[must_use]
            pub fn label(self) -> &'static str {
                match self { $(Self::$id => <$module::$ty as Stage>::LABEL,)* }
            }

            fn needs(self) -> &'static [StageId] {
                match self { $(Self::$id => <$module::$ty as Stage>::NEEDS,)* }
            }
        }

        $(impl Registered for $module::$ty { const ID: StageId = StageId::$id; })*

        fn registry() -> Vec<Option<Box<dyn AnySlot>>> {
            vec![$(Some(Box::new(Slot::<$module::$ty>::default()))),*]
        }
    };
}

stages! {
    /// Meshes and films of every pad, the coordinate layout.
    Films => films::FilmsStage,
    /// Isothermal equilibrium with the full linearisation.
    Equilibrium => equilibrium::EquilibriumStage,
    /// The thermal (THD) loop around the equilibrium.
    Thermal => thermal::ThermalStage,
    /// Full stiffness, damping and inertia.
    Coefficients => coefficients::CoefficientsStage,
    /// Reduced coefficients at the case's ω/Ω: the solution shown.
    Reduction => reduction::ReductionStage,
    /// Reduced coefficients over a range of ω/Ω.
    FrequencySweep => frequency_sweep::FrequencySweepStage,
    /// One solution per speed.
    SpeedSweep => speed_sweep::SpeedSweepStage,
    /// The bearing linearised for its injection ports (the FRFs' operating point).
    Frf => frf::FrfStage,
}

impl StageId {
    fn index(self) -> usize {
        Self::ALL.iter().position(|s| *s == self).unwrap_or(0)
    }
}

/// What the caller wants computed.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Request {
    pub case: Case,
    /// The stages whose results are wanted (the stages they read run too).
    pub wanted: Vec<StageId>,
    /// Excitation ratios ω/Ω of the frequency sweep.
    pub frequency_ratios: Vec<f64>,
    /// Speeds of the speed sweep [rpm] (everything else as in the case).
    pub speeds_rpm: Vec<f64>,
}

impl Request {
    /// The solution of a case and nothing else.
    #[must_use]
    pub fn solution(case: Case) -> Self {
        Self { case, wanted: vec![StageId::Reduction], frequency_ratios: Vec::new(), speeds_rpm: Vec::new() }
    }

    /// The same request restricted to `stages` (those of them it wants).
    #[must_use]
    pub fn only(&self, stages: &[StageId]) -> Self {
        Self { wanted: self.wanted.iter().copied().filter(|s| stages.contains(s)).collect(), ..self.clone() }
    }
}

/// The published results of the wanted stages.
#[derive(Debug, Clone, Default)]
pub struct Outcome {
    outputs: Vec<(StageId, Published)>,
}

impl Outcome {
    /// A stage's published output, if it was wanted and has one of type `T`.
    #[must_use]
    pub fn get<T: Any + Send + Sync>(&self, stage: StageId) -> Option<Arc<T>> {
        self.outputs.iter().find(|(s, _)| *s == stage).and_then(|(_, o)| o.clone().downcast::<T>().ok())
    }

    /// The solution at the case's operating point and excitation ratio.
    #[must_use]
    pub fn solution(&self) -> Option<Arc<Solution>> {
        self.get(StageId::Reduction)
    }

    #[must_use]
    pub fn frequency_sweep(&self) -> Option<Arc<FrequencySweep>> {
        self.get(StageId::FrequencySweep)
    }

    #[must_use]
    pub fn speed_sweep(&self) -> Option<Arc<Vec<SpeedPoint>>> {
        self.get(StageId::SpeedSweep)
    }
}

/// Result of one step.
#[derive(Debug, Clone)]
pub enum Step {
    /// More work to do: the stage worked on, and its completed fraction (1 when it just finished).
    Pending {
        stage: StageId,
        fraction: f64,
    },
    Done(Outcome),
}

/// A stage, its cached output and how often it ran.
struct Slot<S: Stage> {
    stage: S,
    output: Cached<S::Inputs, S::Output>,
    runs: usize,
}

impl<S: Stage> Default for Slot<S> {
    fn default() -> Self {
        Self { stage: S::default(), output: Cached::default(), runs: 0 }
    }
}

/// Where a slot stands for a request.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Standing {
    /// The stage does not apply to this request.
    Idle,
    Current,
    Stale,
}

/// A slot, with its stage type erased (the registry holds one per stage).
trait AnySlot {
    fn standing(&self, req: &Request) -> Standing;
    /// One unit of work; stores the output when the stage finishes.
    fn poll(&mut self, ctx: &mut Ctx<'_>, cancel: &dyn Cancel) -> Result<Poll<()>, SolveError>;
    fn publish(&mut self, req: &Request) -> Option<Published>;
    fn runs(&self) -> usize;
    fn as_any(&self) -> &dyn Any;
    fn as_any_mut(&mut self) -> &mut dyn Any;
}

impl<S: Registered> AnySlot for Slot<S> {
    fn standing(&self, req: &Request) -> Standing {
        match S::inputs(req) {
            None => Standing::Idle,
            Some(i) if self.output.get(&i).is_some() => Standing::Current,
            Some(_) => Standing::Stale,
        }
    }

    fn poll(&mut self, ctx: &mut Ctx<'_>, cancel: &dyn Cancel) -> Result<Poll<()>, SolveError> {
        let Some(inputs) = S::inputs(ctx.req) else { return Ok(Progress::Done(())) };
        Ok(match self.stage.poll(&inputs, ctx, cancel)? {
            Progress::Done(out) => {
                self.output.put(inputs, out);
                self.runs += 1;
                Progress::Done(())
            }
            Progress::Suspended(fraction) => Progress::Suspended(fraction),
        })
    }

    fn publish(&mut self, req: &Request) -> Option<Published> {
        let inputs = S::inputs(req)?;
        let Self { stage, output, .. } = self;
        stage.publish(output.get(&inputs)?, req)
    }

    fn runs(&self) -> usize {
        self.runs
    }

    fn as_any(&self) -> &dyn Any {
        self
    }

    fn as_any_mut(&mut self) -> &mut dyn Any {
        self
    }
}

/// What a running stage sees: the request, and the outputs of the stages it declared in `NEEDS`.
pub struct Ctx<'a> {
    slots: &'a mut [Option<Box<dyn AnySlot>>],
    req: &'a Request,
    reader: StageId,
}

impl Ctx<'_> {
    #[must_use]
    pub fn case(&self) -> &Case {
        &self.req.case
    }

    #[must_use]
    pub fn request(&self) -> &Request {
        self.req
    }

    fn refuse<S: Registered>(&self, why: &'static str) -> SolveError {
        SolveError::Invalid(format!("stage '{}' cannot read stage '{}': {why}", self.reader.label(), S::LABEL))
    }

    /// The slot of `S` and the inputs its output must have been computed for.
    fn check<S: Registered>(&self) -> Result<S::Inputs, SolveError> {
        if !self.reader.needs().contains(&S::ID) {
            return Err(self.refuse::<S>("not declared in NEEDS"));
        }
        S::inputs(self.req).ok_or_else(|| self.refuse::<S>("it does not apply to this request"))
    }

    /// The current output of stage `S`.
    ///
    /// # Errors
    /// [`SolveError::Invalid`] when `S` is not declared in the reader's `NEEDS` or its output is not
    /// current (a bug in the registration order).
    pub fn output<S: Registered>(&self) -> Result<&S::Output, SolveError> {
        let inputs = self.check::<S>()?;
        let slot = self.slots[S::ID.index()].as_ref().and_then(|s| s.as_any().downcast_ref::<Slot<S>>());
        slot.and_then(|s| s.output.get(&inputs)).ok_or_else(|| self.refuse::<S>("its output is not current"))
    }

    /// The current output of stage `S`, to update in place (the films keep their last state).
    ///
    /// # Errors
    /// As [`Self::output`].
    pub fn output_mut<S: Registered>(&mut self) -> Result<&mut S::Output, SolveError> {
        let inputs = self.check::<S>()?;
        let missing = self.refuse::<S>("its output is not current");
        let slot = self.slots[S::ID.index()].as_mut().and_then(|s| s.as_any_mut().downcast_mut::<Slot<S>>());
        slot.and_then(|s| s.output.get_mut(&inputs)).ok_or(missing)
    }

    /// The current outputs of two different stages, both to update in place.
    ///
    /// # Errors
    /// As [`Self::output`].
    pub fn outputs_mut<A: Registered, B: Registered>(
        &mut self,
    ) -> Result<(&mut A::Output, &mut B::Output), SolveError> {
        let (ia, ib) = (self.check::<A>()?, self.check::<B>()?);
        let (ea, eb) = (self.refuse::<A>("its output is not current"), self.refuse::<B>("its output is not current"));
        let (mut a, mut b) = (None, None);
        for slot in self.slots.iter_mut().flatten() {
            let any = slot.as_any_mut();
            if any.is::<Slot<A>>() {
                a = any.downcast_mut::<Slot<A>>().and_then(|s| s.output.get_mut(&ia));
            } else if let Some(s) = any.downcast_mut::<Slot<B>>() {
                b = s.output.get_mut(&ib);
            }
        }
        Ok((a.ok_or(ea)?, b.ok_or(eb)?))
    }
}

/// The cached, steppable computation: one slot per registered stage.
pub struct Stages {
    slots: Vec<Option<Box<dyn AnySlot>>>,
}

impl Default for Stages {
    fn default() -> Self {
        Self::new()
    }
}

impl Stages {
    #[must_use]
    pub fn new() -> Self {
        Self { slots: registry() }
    }

    /// The wanted stages and every stage they read, transitively (indexed by [`StageId`] order).
    fn needed(wanted: &[StageId]) -> Vec<bool> {
        let mut needed = vec![false; StageId::ALL.len()];
        let mut stack: Vec<StageId> = wanted.to_vec();
        while let Some(s) = stack.pop() {
            if !std::mem::replace(&mut needed[s.index()], true) {
                stack.extend_from_slice(s.needs());
            }
        }
        needed
    }

    /// Does one unit of work towards `req`: the first needed stage that is not current, upstream first.
    ///
    /// # Errors
    /// The failure of the stage worked on (the caller keeps its last good outcome).
    pub fn step(&mut self, req: &Request, cancel: &dyn Cancel) -> Result<Step, SolveError> {
        let needed = Self::needed(&req.wanted);
        for (i, &id) in StageId::ALL.iter().enumerate() {
            let stale = needed[i] && self.slots[i].as_ref().is_some_and(|s| s.standing(req) == Standing::Stale);
            if !stale {
                continue;
            }
            let Some(mut slot) = self.slots[i].take() else { continue };
            let mut ctx = Ctx { slots: &mut self.slots, req, reader: id };
            let result = slot.poll(&mut ctx, cancel);
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
                outputs.push((id, o));
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

#[cfg(test)]
mod tests;
