//! A sweep under way or finished in the sweep view: its spec, the table of the points solved so far, and the
//! slot that solves them ([`crate::app::jobs::sweep::SweepJob`] in a [`Runner`]: a thread on native, a web
//! worker on the web). Dropping it (a new sweep, closing the app) stops the job.
//!
//! A sweep knows the design it belongs to: the document's revision when it started and the case it swept,
//! with the swept key set aside ([`SweepRun::is_for`]: an edit of the swept key itself leaves the sweep
//! current — the marker of the case moves along the curve — any other edit, an undo of one, or another case
//! makes it a sweep of an earlier design, which the view says and draws with that design's own geometry).

use super::jobs::sweep::SweepJob;
use super::jobs::{Event, Runner};
use crate::model::{load_case, Case};
use crate::scene::sweep::{point_override, SweepSpec, SweepSpecError, SweepTable};

/// The case `text` with the sweep's base overrides and the swept key at the range's start.
fn design(spec: &SweepSpec, text: &str) -> Option<Case> {
    let mut set = base_overrides(spec);
    set.extend(point_override(&spec.key, spec.from).into_iter().map(|(k, v)| format!("{k}={v}")));
    load_case(text, &set).ok().map(|(_, c)| c)
}

/// A sweep under way or finished.
pub struct SweepRun {
    pub spec: SweepSpec,
    pub table: SweepTable,
    total: usize,
    runner: Runner<SweepJob>,
    /// Why the job stopped before its last point (a failure of the job itself, not of a point).
    pub failed: Option<String>,
    /// The document's revision the sweep started at.
    pub revision: u64,
    /// The case swept, the swept key set to the range's start (`None`: it does not load at that value).
    design: Option<Case>,
}

fn base_overrides(spec: &SweepSpec) -> Vec<String> {
    if spec.preview {
        vec!["mesh.fidelity=\"preview\"".into()]
    } else {
        Vec::new()
    }
}

impl SweepRun {
    /// Starts sweeping the case `text` (TOML) as `spec` says.
    ///
    /// # Errors
    /// A spec that names no numeric key, an empty range or a bad count.
    pub fn start(
        text: String,
        spec: &SweepSpec,
        revision: u64,
        repaint: &egui::Context,
    ) -> Result<Self, SweepSpecError> {
        let values = spec.values()?;
        let total = values.len();
        let design = design(spec, &text);
        let mut runner = Runner::new(repaint);
        runner.submit(SweepJob::new(text, base_overrides(spec), &spec.key, values));
        Ok(Self {
            spec: spec.clone(),
            table: SweepTable::new(&spec.key),
            total,
            runner,
            failed: None,
            revision,
            design,
        })
    }

    /// The sweep belongs to the design of the case `text` (TOML): the same case apart from the swept key.
    #[must_use]
    pub fn is_for(&self, text: &str) -> bool {
        self.design.is_some() && design(&self.spec, text) == self.design
    }

    /// The case the sweep was run on (swept key at the range's start), e.g. for the chart's geometry.
    #[must_use]
    pub fn design(&self) -> Option<&Case> {
        self.design.as_ref()
    }

    /// Takes the rows solved since the last call (web without a worker: works on the points for the frame's
    /// budget).
    pub fn poll(&mut self) {
        for e in self.runner.poll(super::WEB_SOLVE_BUDGET_S) {
            match e {
                Event::Partial(rows) | Event::Done(rows) => self.table.points.extend(rows),
                Event::Failed(e) => self.failed = Some(e),
                Event::Progress(_) => {}
            }
        }
    }

    /// Points solved and points in all.
    #[must_use]
    pub fn progress(&self) -> (usize, usize) {
        (self.table.points.len(), self.total)
    }

    /// Every point is solved, or the job stopped.
    #[must_use]
    pub fn done(&self) -> bool {
        self.table.points.len() >= self.total || self.failed.is_some()
    }
}
