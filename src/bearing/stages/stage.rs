//! The contract of a stage ([`Stage`]) and what a running stage sees ([`Ctx`]).
//!
//! - `Inputs` (`PartialEq + Clone`) holds everything the output depends on: the stage's view of the case
//!   ([`super::view`]: the fields it reads, every other one blank), built by `Stage::inputs`, which
//!   **destructures [`crate::model::Case`] and each sub-struct it looks into exhaustively, without `..`**, and
//!   what the stage takes from the request (the sweeps' grids). Adding a field anywhere in the case is a
//!   compile error in every builder until someone decides, stage by stage, whether it reads it.
//! - `poll` receives its inputs and, through [`Ctx`], the outputs of the stages it declared in `NEEDS` — not
//!   the case, not the request: the compiler, not care, guarantees that the cache key covers everything a
//!   stage reads. It does one unit of work and returns [`Progress::Done`] with the output or
//!   [`Progress::Suspended`] with the fraction done (a paused equilibrium, one THD outer iteration, one sweep
//!   point): suspension is a return value, errors are failures. Resumable state lives in the stage value,
//!   keyed by the inputs it is for ([`Cached`]).
//! - Another stage's output is read under that stage's inputs, which the reader derives from its own
//!   (`ctx.output::<FilmsStage>(&FilmsInputs::of(&inputs.case))`), so its key covers everything upstream.
//!   [`Ctx`] refuses a stage not listed in `NEEDS` and an output not computed for those inputs (an error
//!   naming both: a bug in the registration order or in a builder). `needs` may narrow `NEEDS` per input
//!   (the coefficients read the thermal loop's state for a THD case, the isothermal equilibrium otherwise),
//!   so a stage nobody reads does not run.
//! - Where solves start ([`Start`], [`Ctx::start`]) is the one thing of the request a stage sees besides its
//!   inputs, and by design no part of a key: a cold request reuses an output already cached for the same
//!   inputs.
//! - `publish` hands an output to the caller ([`Published`]); internal stages (the films) publish nothing.
//!   The registry, which knows the request, stamps its title and case on a published solution.

use std::any::Any;

use crate::bearing::report::error::{InternalError, SolveError};
use crate::bearing::report::progress::{Cancel, Progress};
use crate::bearing::stages::cache::Cached;
use crate::bearing::stages::id::StageId;
use crate::bearing::stages::outcome::{Published, Step};
use crate::bearing::stages::request::{Request, Start};

/// One unit of a stage's work: its output, or paused with the fraction of the work done.
pub type Poll<T> = Progress<T, f64>;

/// A stage of the computation (module documentation).
pub trait Stage: Default + Send + 'static {
    /// What the status bar says while it runs.
    const LABEL: &'static str;
    /// Every stage whose output this one may read (upstream in the registration order).
    const NEEDS: &'static [StageId];
    /// Whether more than one output is kept (under different inputs) when the caller asks for it
    /// ([`super::Stages::keeping`]); the films, large and rebuilt only with the geometry, keep one.
    const KEEP_MANY: bool = true;
    /// Everything the output depends on.
    type Inputs: PartialEq + Clone + std::fmt::Debug + Send;
    type Output: Send + 'static;

    /// This stage's inputs for the request; `None` when it does not apply (a thermal stage of an isothermal
    /// case).
    fn inputs(req: &Request) -> Option<Self::Inputs>;

    /// The stages this one reads for these inputs (a subset of `NEEDS`).
    fn needs(_inputs: &Self::Inputs) -> &'static [StageId] {
        Self::NEEDS
    }

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
    fn publish(&mut self, _output: &Self::Output) -> Option<Published> {
        None
    }
}

/// Registration: the stage's id (implemented in [`super::registry`]).
pub trait Registered: Stage {
    const ID: StageId;
}

/// A nested computation a stage can run whole requests on (the speed sweep's points): the stages
/// themselves, handed in by [`super::registry`] so that no stage file names the registry.
pub trait Solver: Send {
    /// One unit of work towards `req` ([`super::Stages::step`]).
    ///
    /// # Errors
    /// The failure of the stage worked on.
    fn step(&mut self, req: &Request, cancel: &dyn Cancel) -> Result<Step, SolveError>;
}

/// A stage, its cached output and how often it ran.
pub(super) struct Slot<S: Stage> {
    pub stage: S,
    pub output: Cached<S::Inputs, S::Output>,
    pub runs: usize,
}

impl<S: Stage> Slot<S> {
    pub fn new(keep: usize) -> Self {
        Self { stage: S::default(), output: Cached::keeping(if S::KEEP_MANY { keep } else { 1 }), runs: 0 }
    }
}

/// Where a slot stands for a request.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Standing {
    /// The stage does not apply to this request.
    Idle,
    Current,
    Stale,
}

/// A slot, with its stage type erased (the registry holds one per stage).
pub(super) trait AnySlot: Send {
    fn standing(&self, req: &Request) -> Standing;
    /// One unit of work towards `req`'s output; stores the output when the stage finishes.
    fn poll(&mut self, req: &Request, ctx: &mut Ctx<'_>, cancel: &dyn Cancel) -> Result<Poll<()>, SolveError>;
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

    fn poll(&mut self, req: &Request, ctx: &mut Ctx<'_>, cancel: &dyn Cancel) -> Result<Poll<()>, SolveError> {
        let Some(inputs) = S::inputs(req) else { return Ok(Progress::Done(())) };
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
        stage.publish(output.get(&inputs)?)
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

/// The stage that is running, as [`Ctx`] checks its reads.
#[derive(Debug, Clone, Copy)]
pub(super) struct Reader {
    pub label: &'static str,
    pub needs: &'static [StageId],
}

/// What a running stage sees: the outputs of the stages it declared in `NEEDS`, where solves start, and a way
/// to run nested requests ([`Ctx::nested`]). Not the request: a stage reads the case only through its inputs.
pub struct Ctx<'a> {
    pub(super) slots: &'a mut [Option<Box<dyn AnySlot>>],
    pub(super) reader: Reader,
    pub(super) start: Start,
    pub(super) nested: fn() -> Box<dyn Solver>,
}

impl Ctx<'_> {
    /// Where the request's solves start (not part of any key: module documentation).
    #[must_use]
    pub fn start(&self) -> Start {
        self.start
    }

    /// A fresh computation of its own, to run whole requests on (the speed sweep's points).
    #[must_use]
    pub fn nested(&self) -> Box<dyn Solver> {
        (self.nested)()
    }

    fn refuse<S: Registered>(&self, why: &'static str) -> SolveError {
        SolveError::Internal(InternalError::StageRead {
            reader: self.reader.label.into(),
            stage: S::LABEL.into(),
            why: why.into(),
        })
    }

    fn declared<S: Registered>(&self) -> Result<(), SolveError> {
        if self.reader.needs.contains(&S::ID) {
            Ok(())
        } else {
            Err(self.refuse::<S>("not declared in NEEDS"))
        }
    }

    /// The output of stage `S` computed for `inputs` (derived from the reader's own inputs).
    ///
    /// # Errors
    /// [`InternalError::StageRead`] when `S` is not declared in the reader's `NEEDS` or has no output for
    /// `inputs` (a bug in the registration order or in a builder).
    pub fn output<S: Registered>(&self, inputs: &S::Inputs) -> Result<&S::Output, SolveError> {
        self.declared::<S>()?;
        let slot = self.slots[S::ID.index()].as_ref().and_then(|s| s.as_any().downcast_ref::<Slot<S>>());
        slot.and_then(|s| s.output.get(inputs)).ok_or_else(|| self.refuse::<S>("its output is not current"))
    }

    /// The output of stage `S` computed for `inputs`, to update in place (the films keep their last state).
    ///
    /// # Errors
    /// As [`Self::output`].
    pub fn output_mut<S: Registered>(&mut self, inputs: &S::Inputs) -> Result<&mut S::Output, SolveError> {
        self.declared::<S>()?;
        let missing = self.refuse::<S>("its output is not current");
        let slot = self.slots[S::ID.index()].as_mut().and_then(|s| s.as_any_mut().downcast_mut::<Slot<S>>());
        slot.and_then(|s| s.output.get_mut(inputs)).ok_or(missing)
    }
}
