//! The equilibrium of one THD outer iteration as a resumable computation, so that a caller without
//! threads (the web build) can spread even one outer iteration over frames: when the caller's
//! [`Cancel::suspend`] asks, the coupled Newton pauses ([`step_equilibrium`]) and [`equilibrium_part`]
//! returns where to resume ([`PendingEquilibrium`]); the next call continues from that iterate.
//!
//! Contract: the same result as [`crate::bearing::thermal::warm_equilibrium`] — a warm start that fails is retried from
//! scratch once; a suspended solve's parts add up in the final report ([`SolveReport::add_earlier`]); after
//! [`MAX_EQUILIBRIUM_PARTS`] parts the solve runs to its end (bounded work even when every part is slow).

use crate::bearing::equilibrium::{step_equilibrium, Equilibrium, EquilibriumParams};
use crate::bearing::film::model::{BearingModel, OperatingPoint};
use crate::bearing::report::error::SolveError;
use crate::bearing::report::progress::{Cancel, NoSuspend, Progress};
use crate::bearing::report::SolveReport;

/// Parts an outer iteration's equilibrium may be split into before it runs to its end.
pub const MAX_EQUILIBRIUM_PARTS: usize = 40;

/// A suspended equilibrium of an outer iteration: where it resumes and the work of its parts so far.
#[derive(Debug, Clone)]
pub struct PendingEquilibrium {
    /// Tolerances of this outer iteration's equilibrium (fixed when it started).
    pub params: EquilibriumParams,
    start: Option<Vec<f64>>,
    placed_pads: usize,
    parts: usize,
    /// The warm start failed (or there was none): this is the solve from scratch.
    cold: bool,
    work: SolveReport,
}

impl PendingEquilibrium {
    /// A new equilibrium with `params`, warm-started from `start` when given.
    #[must_use]
    pub fn new(params: EquilibriumParams, start: Option<Vec<f64>>) -> Self {
        let cold = start.is_none();
        Self { params, start, placed_pads: 0, parts: 0, cold, work: SolveReport::default() }
    }

    /// Parts suspended so far.
    #[must_use]
    pub fn parts(&self) -> usize {
        self.parts
    }
}

/// Advances `pending` until it is solved or `cancel` asks for a pause.
///
/// # Errors
/// As [`crate::bearing::equilibrium::solve_equilibrium`] (after the cold retry of a failed warm start).
pub fn equilibrium_part(
    model: &mut BearingModel,
    op: &OperatingPoint,
    mut pending: PendingEquilibrium,
    cancel: &dyn Cancel,
) -> Result<Progress<Equilibrium, PendingEquilibrium>, SolveError> {
    let no_suspend = NoSuspend(cancel);
    let cancel_part: &dyn Cancel = if pending.parts < MAX_EQUILIBRIUM_PARTS { cancel } else { &no_suspend };
    let params = EquilibriumParams { placed_pads: pending.placed_pads, ..pending.params };
    match step_equilibrium(model, op, params, pending.start.as_deref(), cancel_part) {
        Ok(Progress::Done(mut eq)) => {
            eq.report.add_earlier(pending.work);
            Ok(Progress::Done(eq))
        }
        Ok(Progress::Suspended(r)) => {
            let mut work = r.report;
            work.add_earlier(std::mem::take(&mut pending.work));
            pending.work = work;
            pending.start = Some(r.coordinates);
            pending.placed_pads = r.placed_pads;
            pending.parts += 1;
            Ok(Progress::Suspended(pending))
        }
        Err(SolveError::Cancelled) => Err(SolveError::Cancelled),
        // A failed warm start retries from scratch before giving up.
        Err(_) if !pending.cold => {
            let scratch = PendingEquilibrium { start: None, placed_pads: 0, cold: true, ..pending };
            equilibrium_part(model, op, scratch, cancel)
        }
        Err(e) => Err(e),
    }
}
