//! The sweep job: the points of a sweep — each the case text with the sweep's base overrides and the swept
//! key at the point's value — solved one after another, each handed back as a row of the study table
//! ([`Row`]) as soon as it is finished. Each point is a solution request to the steppable stages, so a point
//! (an equilibrium, a THD outer iteration, or the part of either that fits a web frame's budget) can spread
//! over several steps; the stages keep the films while the mesh stays and start each point from the last
//! converged one. A point that fails (validation or solve) is a row with its error, and the sweep goes on.
//!
//! The job's stages are its own (not the slot's): a sweep's rows do not depend on what was swept before.

use std::collections::VecDeque;

use serde::{Deserialize, Serialize};
use web_time::Instant;

use super::job::{Job, JobError, Progress, Step};
use crate::bearing::report::error::InternalError;
use crate::bearing::stages::{Request, StageId, Stages, Step as StageStep};
use crate::bearing::{Cancel, SolveError};
use crate::scene::sweep::point_override;
use crate::study::{PointError, Row, Runner};

/// A sweep's points.
#[derive(Serialize, Deserialize)]
pub struct SweepJob {
    /// The case as TOML, the overrides every point gets, the swept key and its values.
    pub text: String,
    pub overrides: Vec<String>,
    pub key: String,
    values: VecDeque<f64>,
    /// Points finished, and in all.
    solved: usize,
    total: usize,
    /// Time spent on the point under way so far [s].
    seconds: f64,
    #[serde(skip)]
    state: Option<(Runner, Stages)>,
}

impl SweepJob {
    #[must_use]
    pub fn new(text: String, overrides: Vec<String>, key: &str, values: Vec<f64>) -> Self {
        let total = values.len();
        Self {
            text,
            overrides,
            key: key.to_string(),
            values: values.into(),
            solved: 0,
            total,
            seconds: 0.0,
            state: None,
        }
    }
}

impl Job for SweepJob {
    const NAME: &'static str = "sweep";
    /// The points finished in the step, as `(value, row)`.
    type Output = Vec<(f64, Row)>;
    type Keep = ();

    fn step(&mut self, (): &mut (), cancel: &dyn Cancel) -> Result<Step<Self::Output>, JobError> {
        let (runner, stages) = self
            .state
            .get_or_insert_with(|| (Runner::new(self.text.clone(), self.overrides.clone(), true), Stages::new()));
        let mut rows = Vec::new();
        if let Some(&x) = self.values.front() {
            let overrides = point_override(&self.key, x);
            let t0 = Instant::now();
            let finished = match runner.case(&overrides) {
                Err(e) => Some(Err(PointError::from(e))),
                Ok(case) => match stages.step(&Request::solution(case), cancel) {
                    Ok(StageStep::Pending { .. }) => None,
                    Ok(StageStep::Done(o)) => Some(o.solution().ok_or_else(|| {
                        PointError::from(SolveError::Internal(InternalError::Unpublished {
                            stage: StageId::Reduction.label().into(),
                        }))
                    })),
                    Err(SolveError::Cancelled) => return Err(JobError::Cancelled),
                    Err(e) => Some(Err(PointError::from(e))),
                },
            };
            self.seconds += t0.elapsed().as_secs_f64();
            if let Some(result) = finished {
                self.values.pop_front();
                let row = match result {
                    Ok(s) => Row::of(self.solved, &overrides, Ok(&s), self.seconds),
                    Err(e) => Row::of(self.solved, &overrides, Err(e), self.seconds),
                };
                rows.push((x, row));
                self.solved += 1;
                self.seconds = 0.0;
            }
        }
        if self.values.is_empty() {
            return Ok(Step::Done(rows));
        }
        #[allow(clippy::cast_precision_loss)]
        let progress = Progress::new(
            self.solved as f64,
            self.total as f64,
            format!("point {} of {}", self.solved + 1, self.total),
        );
        Ok(Step::More { progress, output: (!rows.is_empty()).then_some(rows) })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::app::jobs::stepped::Stepped;
    use crate::app::jobs::Event;
    use crate::study::COLUMNS;

    fn base() -> (String, Vec<String>) {
        (
            include_str!("../../../cases/compressor-bearing.toml").to_string(),
            vec!["mesh.fidelity=\"preview\"".into(), "thermal.model=\"isothermal\"".into()],
        )
    }

    /// Points stepped with no budget (every solve pauses wherever it may) give the study runner's rows; a
    /// point that fails validation is a row with its error, and the sweep goes on.
    #[test]
    fn stepped_points_give_the_study_runners_rows() {
        let (text, overrides) = base();
        let values = vec![1000.0, 4000.0, -5.0, 8000.0];
        let mut stepped = Stepped::<SweepJob>::default();
        stepped.start(SweepJob::new(text.clone(), overrides.clone(), "operating.load_n", values.clone()));
        let mut rows = Vec::new();
        let mut polls = 0;
        while stepped.busy() {
            for e in stepped.run_for(0.0) {
                match e {
                    Event::Partial(r) | Event::Done(r) => rows.extend(r),
                    Event::Progress(_) => {}
                    Event::Failed(e) => panic!("{e}"),
                }
            }
            polls += 1;
            assert!(polls < 10_000, "the sweep ends");
        }
        assert_eq!(rows.len(), values.len());
        assert!(polls > 2 * values.len(), "points were split over polls: {polls}");
        let mut native = Runner::new(text, overrides, true);
        let eps = COLUMNS.iter().position(|c| c.name == "eccentricity_ratio").unwrap();
        for (i, (x, row)) in rows.iter().enumerate() {
            assert_eq!((*x, row.index), (values[i], i));
            let (expected, _) = native.row(i, &point_override("operating.load_n", values[i]));
            assert_eq!(row.inputs, expected.inputs);
            match (&row.result, &expected.result) {
                (Ok(a), Ok(b)) => {
                    let (a, b) = (a[eps].unwrap(), b[eps].unwrap());
                    assert!(((a - b) / b).abs() < 1e-6, "{x} N: ε {a} vs {b}");
                    assert_eq!(row.limits_exceeded, expected.limits_exceeded);
                }
                (Err(a), Err(b)) => assert_eq!(a.to_string(), b.to_string()),
                (a, b) => panic!("{x} N: {a:?} vs {b:?}"),
            }
        }
        assert!(rows[2].1.result.as_ref().is_err_and(|e| e.to_string().contains("load")), "{:?}", rows[2].1.result);
    }
}
