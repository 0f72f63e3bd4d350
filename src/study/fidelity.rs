//! The speed–accuracy trade of the fidelity levels on one case: each level (preview, standard, reference;
//! [`Fidelity`]) solved `repeats` times (mesh build, equilibrium — with the thermal loop of a THD case —,
//! full and synchronously reduced coefficients), its median wall time, and its errors against a finer
//! solve, the truth: the reference level with twice its element counts in every direction
//! ([`finer_overrides`]).
//!
//! Errors are relative: the eccentricity ratio and p_max each against the truth's value; the reduced K and C
//! as the Frobenius norm of the 2×2 difference over the truth's norm; T_max as the hottest film
//! temperature's rise above supply (THD only); the flows as the worst of the bearing's flows, each against
//! itself, over those that carry at least 1 % of the throughput ([`flow_error`]).
//!
//! [`FidelityTrade`] is steppable: one solve per [`FidelityTrade::step`] (the truth first), so a caller shows
//! progress, cancels between solves or inside one (through the [`Cancel`] it passes), and keeps the levels
//! finished. A level whose solve fails is kept as a failure with its error and the trade goes on; only the
//! truth failing ends it. `tiltpad fidelity` runs it on a user's case; the developers' bench runs it on the
//! shipped cases for docs/PERFORMANCE.md and `assets/fidelity.json` (what the editor shows beside the
//! fidelity selector, [`crate::scene::fidelity`]). Wall time is what is measured here: the same case gives
//! the same errors everywhere, and times that depend on the machine and its load.

use std::sync::Arc;

use serde::{Deserialize, Serialize};
use web_time::Instant;

use crate::bearing::solution::BearingFlows;
use crate::bearing::{Cancel, Request, Solution, SolveError, Stages};
use crate::model::{load_case, parse_case_file, Case, CaseError, Fidelity};
use crate::study::estimate::{point_cost, Estimate};

/// The levels compared, coarsest first.
pub const LEVELS: [Fidelity; 3] = [Fidelity::Preview, Fidelity::Standard, Fidelity::Reference];

/// The name of the truth's row.
pub const TRUTH: &str = "reference-fine (truth)";

/// One measured level of one case (or the truth, [`TRUTH`], whose errors are 0).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct LevelCost {
    pub case: String,
    pub level: String,
    pub film_nodes: usize,
    pub median_ms: f64,
    pub err_eccentricity: f64,
    pub err_k: f64,
    pub err_c: f64,
    pub err_p_max: f64,
    /// Relative error of the maximum film temperature rise above supply (THD rows only).
    #[serde(default)]
    pub err_t_max: Option<f64>,
    /// Worst relative error of the bearing's flows ([`flow_error`]; absent in tables measured before it).
    #[serde(default)]
    pub err_flows: Option<f64>,
}

impl LevelCost {
    /// The row of `level` of `case`: `solution` took `median_ms`, against `truth`.
    #[must_use]
    pub fn against(case: &str, level: &str, median_ms: f64, solution: &Solution, truth: &Solution) -> Self {
        Self {
            case: case.to_string(),
            level: level.to_string(),
            film_nodes: solution.derived.film_nodes,
            median_ms,
            err_eccentricity: relative(solution.eccentricity_ratio, truth.eccentricity_ratio),
            err_k: matrix_relative(solution.reduced.k_n_per_m, truth.reduced.k_n_per_m),
            err_c: matrix_relative(solution.reduced.c_ns_per_m, truth.reduced.c_ns_per_m),
            err_p_max: relative(solution.p_max_pa, truth.p_max_pa),
            err_t_max: temperature_rise(solution).zip(temperature_rise(truth)).map(|(a, b)| relative(a, b)),
            err_flows: flow_error(&solution.flows_m3_per_s, &truth.flows_m3_per_s),
        }
    }

    /// The largest of the row's errors (ε, K, C, p_max, T_max, flows).
    #[must_use]
    pub fn largest_error(&self) -> f64 {
        self.err_eccentricity
            .max(self.err_k)
            .max(self.err_c)
            .max(self.err_p_max)
            .max(self.err_t_max.unwrap_or(0.0))
            .max(self.err_flows.unwrap_or(0.0))
    }
}

/// |a − b| / |b|.
#[must_use]
pub fn relative(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs()
}

/// Frobenius norm of `a − b` over that of `b` (2×2 coefficient matrices).
#[must_use]
pub fn matrix_relative(a: [[f64; 2]; 2], b: [[f64; 2]; 2]) -> f64 {
    let mut d = 0.0;
    let mut n = 0.0;
    for i in 0..2 {
        for j in 0..2 {
            d += (a[i][j] - b[i][j]).powi(2);
            n += b[i][j].powi(2);
        }
    }
    (d / n).sqrt()
}

/// Temperature rise of the hottest film point above supply [K] (THD solutions; `None` isothermal).
#[must_use]
pub fn temperature_rise(s: &Solution) -> Option<f64> {
    s.thermal.as_ref().map(|t| t.t_max_film_c - s.inputs.operating.supply_temperature_c)
}

/// Worst relative error over the bearing's flows (leading edges in, trailing edges out, sides out,
/// orifices in, into cavitation), each against its own truth value, over the flows that carry at least
/// 1 % of the throughput (smaller ones are round-off of a balance); `None` when no flow does.
#[must_use]
pub fn flow_error(flows: &BearingFlows, truth: &BearingFlows) -> Option<f64> {
    worst_flow(flows, truth).map(|(e, _)| e)
}

/// [`flow_error`] and the name of the flow it is (`"orifices"`, `"into cavitation"`, …).
#[must_use]
pub fn worst_flow(flows: &BearingFlows, truth: &BearingFlows) -> Option<(f64, &'static str)> {
    let parts = |f: &BearingFlows| {
        [
            ("leading edges", f.leading_edges_in),
            ("trailing edges", f.trailing_edges_out),
            ("sides", f.sides_out),
            ("orifices", f.orifices_in),
            ("into cavitation", f.to_cavitation),
        ]
    };
    let (a, t) = (parts(flows), parts(truth));
    let throughput: f64 = t.iter().map(|(_, v)| v.abs()).sum();
    a.iter()
        .zip(&t)
        .filter(|(_, (_, t))| throughput > 0.0 && t.abs() >= 0.01 * throughput)
        .map(|((name, a), (_, t))| (((a - t) / t).abs(), *name))
        .reduce(|w, x| if x.0 > w.0 { x } else { w })
}

/// The name of a level as the case file spells it (`preview`, `standard`, `reference`).
#[must_use]
pub fn level_name(level: Fidelity) -> &'static str {
    match level {
        Fidelity::Preview => "preview",
        Fidelity::Standard => "standard",
        Fidelity::Reference => "reference",
    }
}

/// `set` and the override of `level`.
#[must_use]
pub fn level_overrides(set: &[String], level: Fidelity) -> Vec<String> {
    let mut out = set.to_vec();
    out.push(format!("mesh.fidelity=\"{}\"", level_name(level)));
    out
}

/// `set` and the overrides of the truth's mesh for `case` (any level of it): twice the reference level's
/// element counts. The reference level refines a pad longer than [`crate::model::case::LEVEL_ARC_RAD`]
/// with its arc, and an explicit count applies to every pad alike, so the truth's circumferential count is
/// twice the reference level's on the longest pad (the others get more).
#[must_use]
pub fn finer_overrides(case: &Case, set: &[String]) -> Vec<String> {
    let (_, nz, no) = Fidelity::Reference.elements();
    let nx = Fidelity::Reference.circumferential_elements(case.bearing.longest_arc_rad());
    let mut out = level_overrides(set, Fidelity::Reference);
    out.extend([
        format!("mesh.circumferential_elements={}", 2 * nx),
        format!("mesh.axial_elements={}", 2 * nz),
        format!("mesh.orifice_elements={}", 2 * no),
        // Twice the reference mesh exceeds the default node budget with the pad solids of the thermal model.
        "mesh.max_nodes=2000000".into(),
    ]);
    out
}

/// A trade that cannot start or cannot go on.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum FidelityError {
    #[error(transparent)]
    Case(#[from] CaseError),
    /// The case fixes an element count, which overrides `mesh.fidelity`: every level would be one mesh.
    #[error(
        "`{key}` = {value}: an explicit element count overrides mesh.fidelity, so every level would solve the same \
         mesh; remove it (from the case or the overrides) to compare the levels"
    )]
    ExplicitMesh { key: &'static str, value: usize },
    /// The truth did not solve: nothing to measure the levels against.
    #[error("the finer solve (the truth: twice the reference level's element counts) failed: {error}")]
    Truth { error: SolveError },
    /// The caller cancelled.
    #[error("cancelled")]
    Cancelled,
}

/// A level whose solve failed.
#[derive(Debug, Clone, PartialEq)]
pub struct LevelFailure {
    pub level: Fidelity,
    pub error: SolveError,
}

/// What one [`FidelityTrade::step`] left to do.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TradeStep {
    /// `done` solves of `of` made.
    More {
        done: usize,
        of: usize,
    },
    Done,
}

/// The trade of one case, step by step (see the module).
pub struct FidelityTrade {
    label: String,
    repeats: usize,
    truth_case: Case,
    level_cases: Vec<(Fidelity, Case)>,
    truth: Option<(Arc<Solution>, f64)>,
    /// The level being solved (index into `level_cases`) and its times so far [ms].
    level: usize,
    times_ms: Vec<f64>,
    rows: Vec<LevelCost>,
    failed: Vec<LevelFailure>,
}

impl FidelityTrade {
    /// The trade of the case `text` with the overrides `set`, each level solved `repeats` times (at least
    /// once); its rows are labelled `label`. Every case is resolved here, before any solve.
    ///
    /// # Errors
    /// An invalid case or override; an explicit element count in the case ([`FidelityError::ExplicitMesh`]).
    pub fn new(label: &str, text: &str, set: &[String], repeats: usize) -> Result<Self, FidelityError> {
        let file = parse_case_file(text, set)?;
        let explicit = [
            ("mesh.circumferential_elements", file.mesh.circumferential_elements),
            ("mesh.axial_elements", file.mesh.axial_elements),
            ("mesh.orifice_elements", file.mesh.orifice_elements),
        ];
        if let Some((key, Some(value))) = explicit.into_iter().find(|(_, v)| v.is_some()) {
            return Err(FidelityError::ExplicitMesh { key, value });
        }
        let level_cases: Vec<(Fidelity, Case)> = LEVELS
            .iter()
            .map(|&l| Ok((l, load_case(text, &level_overrides(set, l))?.1)))
            .collect::<Result<_, CaseError>>()?;
        let truth_case = load_case(text, &finer_overrides(&level_cases[0].1, set))?.1;
        Ok(Self {
            label: label.to_string(),
            repeats: repeats.max(1),
            truth_case,
            level_cases,
            truth: None,
            level: 0,
            times_ms: Vec::new(),
            rows: Vec::new(),
            failed: Vec::new(),
        })
    }

    /// Every solve the trade makes: the truth once, each level `repeats` times.
    #[must_use]
    pub fn solves(&self) -> usize {
        1 + self.level_cases.len() * self.repeats
    }

    /// Solves made so far.
    #[must_use]
    pub fn done(&self) -> usize {
        if self.truth.is_none() {
            return 0;
        }
        1 + self.level * self.repeats + self.times_ms.len()
    }

    /// The work before it starts ([`crate::study::estimate`]): the truth and each level's solves; the memory
    /// of the largest (the truth's).
    #[must_use]
    pub fn estimate(&self) -> Estimate {
        let truth = point_cost(&self.truth_case);
        let levels: f64 = self.level_cases.iter().map(|(_, c)| point_cost(c).seconds).sum();
        #[allow(clippy::cast_precision_loss)]
        let seconds = truth.seconds + self.repeats as f64 * levels;
        Estimate { what: "fidelity", solves: self.solves(), seconds, bytes: truth.bytes, eigen: None }
    }

    /// What the next step solves (`None` when done): the truth or a level, and the case.
    #[must_use]
    pub fn next(&self) -> Option<(&'static str, &Case)> {
        if self.truth.is_none() {
            return Some((TRUTH, &self.truth_case));
        }
        self.level_cases.get(self.level).map(|(l, c)| (level_name(*l), c))
    }

    /// Makes one solve.
    ///
    /// # Errors
    /// The truth failed ([`FidelityError::Truth`]); `cancel` stopped a solve ([`FidelityError::Cancelled`]).
    pub fn step(&mut self, cancel: &dyn Cancel) -> Result<TradeStep, FidelityError> {
        let Some((_, case)) = self.next() else { return Ok(TradeStep::Done) };
        let t0 = Instant::now();
        let solved = Stages::new().solution(&Request::solution(case.clone()), cancel);
        let ms = t0.elapsed().as_secs_f64() * 1e3;
        match solved {
            Err(SolveError::Cancelled) => return Err(FidelityError::Cancelled),
            Err(error) if self.truth.is_none() => return Err(FidelityError::Truth { error }),
            Ok(s) if self.truth.is_none() => self.truth = Some((s, ms)),
            Ok(s) => {
                self.times_ms.push(ms);
                if self.times_ms.len() == self.repeats {
                    self.close_level(&s);
                }
            }
            Err(error) => {
                self.failed.push(LevelFailure { level: self.level_cases[self.level].0, error });
                self.times_ms.clear();
                self.level += 1;
            }
        }
        Ok(if self.next().is_some() {
            TradeStep::More { done: self.done(), of: self.solves() }
        } else {
            TradeStep::Done
        })
    }

    /// The level's row from its median time and its last solution.
    fn close_level(&mut self, s: &Solution) {
        let Some((truth, _)) = &self.truth else { return };
        self.times_ms.sort_by(f64::total_cmp);
        let median = self.times_ms[self.times_ms.len() / 2];
        let level = level_name(self.level_cases[self.level].0);
        self.rows.push(LevelCost::against(&self.label, level, median, s, truth));
        self.times_ms.clear();
        self.level += 1;
    }

    /// The rows of the levels finished (coarsest first), then the truth's (when it was solved); and the
    /// levels that failed.
    #[must_use]
    pub fn finish(self) -> (Vec<LevelCost>, Vec<LevelFailure>) {
        let mut rows = self.rows;
        if let Some((truth, ms)) = &self.truth {
            rows.push(LevelCost::against(&self.label, TRUTH, *ms, truth, truth));
        }
        (rows, self.failed)
    }

    /// Runs the whole trade without cancelling: the rows of [`Self::finish`].
    ///
    /// # Errors
    /// As [`Self::step`]; the first level that failed, with its error.
    pub fn run(mut self) -> Result<Vec<LevelCost>, LevelRunError> {
        while self.step(&crate::bearing::NoCancel).map_err(LevelRunError::Trade)? != TradeStep::Done {}
        match self.finish() {
            (rows, failed) if failed.is_empty() => Ok(rows),
            (_, mut failed) => Err(LevelRunError::Level(failed.swap_remove(0))),
        }
    }
}

/// Why [`FidelityTrade::run`] has no table.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum LevelRunError {
    #[error(transparent)]
    Trade(FidelityError),
    #[error("{} level: {}", level_name(.0.level), .0.error)]
    Level(LevelFailure),
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn flow_error_is_the_worst_flow_that_matters() {
        let truth = BearingFlows {
            leading_edges_in: 10.0,
            trailing_edges_out: 6.0,
            sides_out: 3.0,
            orifices_in: 1.0,
            to_cavitation: 0.1,
            mass_balance_error: 0.0,
        };
        // The orifice flow 30 % off dominates; the flow into cavitation (0.5 % of the throughput) is left out.
        let coarse = BearingFlows { leading_edges_in: 10.1, orifices_in: 1.3, to_cavitation: 0.2, ..truth };
        let e = flow_error(&coarse, &truth).unwrap();
        assert!((e - 0.3).abs() < 1e-12, "{e}");
        assert_eq!(worst_flow(&coarse, &truth).map(|(_, name)| name), Some("orifices"));
        assert_eq!(flow_error(&truth, &truth), Some(0.0));
        assert_eq!(flow_error(&truth, &BearingFlows::default()), None);
    }

    #[test]
    fn matrix_errors_are_relative_to_the_truths_norm() {
        let truth = [[3.0, 0.0], [0.0, 4.0]];
        assert!((matrix_relative([[3.0, 0.0], [0.0, 4.5]], truth) - 0.1).abs() < 1e-15);
        assert_eq!(matrix_relative(truth, truth), 0.0);
        assert!((relative(0.9, 1.0) - 0.1).abs() < 1e-15);
    }

    /// The finer mesh doubles the reference counts; an explicit count in the case or the overrides is refused,
    /// naming the key and its value, before any solve.
    #[test]
    fn explicit_element_counts_are_refused_and_the_truth_doubles_the_reference_mesh() {
        let text = include_str!("../../cases/compressor-bearing.toml");
        let trade = FidelityTrade::new("c", text, &[], 2).unwrap();
        let (nx, nz, _) = Fidelity::Reference.elements();
        assert_eq!(
            (trade.truth_case.mesh.circumferential_elements, trade.truth_case.mesh.axial_elements),
            (2 * nx, 2 * nz)
        );
        assert_eq!((trade.solves(), trade.done(), trade.next().map(|n| n.0)), (7, 0, Some(TRUTH)));
        // A 360° sleeve: the reference level has 4.5 times its 96 elements around; the truth twice that.
        let sleeve = FidelityTrade::new("s", include_str!("../../cases/plain-360-sommerfeld.toml"), &[], 1).unwrap();
        let reference = &sleeve.level_cases[2].1;
        assert_eq!(
            (reference.mesh.fidelity, sleeve.truth_case.mesh.circumferential_elements),
            (Fidelity::Reference, 864)
        );
        let film = |c: &Case| crate::model::budget::count(c).film();
        assert!(film(&sleeve.truth_case) > 3 * film(reference), "{} {}", film(&sleeve.truth_case), film(reference));
        let e = trade.estimate();
        assert_eq!((e.what, e.solves), ("fidelity", 7));
        assert!(e.seconds > point_cost(&trade.truth_case).seconds);
        let set = ["mesh.axial_elements=20".to_string()];
        let e = FidelityTrade::new("c", text, &set, 1).err().unwrap();
        assert_eq!(e, FidelityError::ExplicitMesh { key: "mesh.axial_elements", value: 20 });
        let fixed = text.replace("[mesh]\n", "[mesh]\ncircumferential_elements = 40\n");
        let e = FidelityTrade::new("c", &fixed, &[], 1).err().unwrap().to_string();
        assert!(e.starts_with("`mesh.circumferential_elements` = 40: an explicit element count"), "{e}");
    }
}
