//! The sweep view's points solved in steps, for the web build (no threads): each point is a solution
//! request to the steppable stages ([`Stages::step`]), so one point — an equilibrium, a THD outer iteration
//! or the part of either that fits the frame's budget — spreads over frames like the edited case's solve
//! (see [`crate::app::worker`]). The stages keep the films while the mesh stays, and start each point's
//! equilibrium from the last converged one. Native builds solve the points on a thread with
//! [`crate::study::Runner`] instead; both give the same rows (unit test below).

use std::collections::VecDeque;

use web_time::Instant;

use crate::bearing::report::error::InternalError;
use crate::bearing::stages::{Request, StageId, Stages, Step};
use crate::bearing::{Cancel, FrameBudget, NoCancel, SolveError};
use crate::scene::sweep::point_override;
use crate::study::{PointError, Row, Runner};

/// The points of a sweep still to solve, and the stages that solve them.
pub struct SteppedPoints {
    /// Makes each point's case (the sweep's base overrides and the point's value), as the native runner.
    runner: Runner,
    stages: Stages,
    key: String,
    left: VecDeque<f64>,
    solved: usize,
    /// Time spent on the point under way so far [s].
    seconds: f64,
}

impl SteppedPoints {
    /// The points `values` of `key`, their cases made by `runner`.
    #[must_use]
    pub fn new(runner: Runner, key: &str, values: Vec<f64>) -> Self {
        Self { runner, stages: Stages::new(), key: key.to_string(), left: values.into(), solved: 0, seconds: 0.0 }
    }

    /// Numbers the rows from `first` on (the rest of a sweep whose first points were solved elsewhere).
    #[must_use]
    pub fn numbered_from(mut self, first: usize) -> Self {
        self.solved = first;
        self
    }

    /// All points are solved.
    #[must_use]
    pub fn finished(&self) -> bool {
        self.left.is_empty()
    }

    /// Works on the next points until `budget_s` is spent (at least one step); returns the points finished,
    /// as `(value, row)`.
    pub fn poll(&mut self, budget_s: f64) -> Vec<(f64, Row)> {
        let cancel = FrameBudget::new(&NoCancel, Instant::now(), budget_s);
        let mut rows = Vec::new();
        while let Some(&x) = self.left.front() {
            let overrides = point_override(&self.key, x);
            let t0 = Instant::now();
            let finished = match self.runner.case(&overrides) {
                Err(e) => Some(Err(PointError::from(e))),
                Ok(case) => match self.stages.step(&Request::solution(case), &cancel) {
                    Ok(Step::Pending { .. }) => None,
                    Ok(Step::Done(o)) => Some(o.solution().ok_or_else(|| {
                        PointError::from(SolveError::Internal(InternalError::Unpublished {
                            stage: StageId::Reduction.label().into(),
                        }))
                    })),
                    Err(e) => Some(Err(PointError::from(e))),
                },
            };
            self.seconds += t0.elapsed().as_secs_f64();
            if let Some(result) = finished {
                self.left.pop_front();
                let row = match result {
                    Ok(s) => Row::of(self.solved, &overrides, Ok(&s), self.seconds),
                    Err(e) => Row::of(self.solved, &overrides, Err(e), self.seconds),
                };
                rows.push((x, row));
                self.solved += 1;
                self.seconds = 0.0;
            }
            if cancel.suspend() {
                break;
            }
        }
        rows
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::study::COLUMNS;

    fn runner() -> Runner {
        Runner::new(
            include_str!("../../cases/compressor-bearing.toml"),
            vec!["mesh.fidelity=\"preview\"".into(), "thermal.model=\"isothermal\"".into()],
            true,
        )
    }

    /// Points stepped with no budget (every solve pauses wherever it may) give the native runner's rows;
    /// a point that fails validation is a row with its error, and the sweep goes on.
    #[test]
    fn stepped_points_give_the_runners_rows() {
        let values = vec![1000.0, 4000.0, -5.0, 8000.0];
        let mut stepped = SteppedPoints::new(runner(), "operating.load_n", values.clone());
        let mut rows = Vec::new();
        let mut polls = 0;
        while rows.len() < values.len() {
            rows.extend(stepped.poll(0.0));
            polls += 1;
            assert!(polls < 10_000, "the sweep ends");
        }
        assert!(polls > 2 * values.len(), "points were split over polls: {polls}");
        let mut native = runner();
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
