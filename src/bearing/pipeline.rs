//! Scene-driven, cached, steppable computation.
//!
//! A [`Request`] says what the views on screen need (the solution at the case's operating point, a speed
//! sweep, a frequency-ratio sweep). The [`Pipeline`] computes it in stages, each cached under the inputs it
//! depends on, so that a change which does not enter a stage never recomputes it:
//!
//! | stage          | depends on                                             |
//! |----------------|--------------------------------------------------------|
//! | `Model`        | bearing geometry, mesh                                 |
//! | `Equilibrium`  | model inputs + lubricant, operating point (not ω/Ω), physics |
//! | `Thermal`      | equilibrium inputs + `[thermal]` (THD cases only; warm-started from the isothermal equilibrium; one outer iteration per step) |
//! | `Reduction`    | equilibrium (or thermal) + excitation ratio ω/Ω        |
//! | `FrequencySweep` | equilibrium + the list of ratios                     |
//! | `SpeedSweep`   | model inputs + everything but the speed, + the speeds  |
//!
//! [`Pipeline::step`] does one unit of work (one stage, or one sweep point) and returns; the native worker
//! loops over it on a thread, the web build calls it within a per-frame time budget. Execution counters
//! ([`StageCounters`]) let tests assert what ran.

use std::sync::Arc;

use serde::Serialize;

use crate::model::Case;

use super::coefficients::{reduce, ReducedCoefficients};
use super::equilibrium::{Cancel, EquilibriumParams, NoSuspend, Progress, SolveReport};
use super::error::SolveError;
use super::job::{assemble_thd_solution, solve_operating_point, solve_point, step_operating_point};
use super::model::{BearingModel, OperatingPoint};
use super::solution::Solution;
use super::thermal::{ThdRun, ThermalModel, ThermalParams};
use crate::model::ThermalModelKind;

/// What the caller wants computed.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Request {
    pub case: Option<Case>,
    /// Reduced coefficients at these excitation ratios ω/Ω.
    pub frequency_ratios: Option<Vec<f64>>,
    /// Solutions at these speeds [rpm] (everything else as in the case).
    pub speeds_rpm: Option<Vec<f64>>,
}

/// One point of a speed sweep.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SpeedPoint {
    pub speed_rpm: f64,
    /// `Err` text when this point failed (touchdown, …).
    pub result: Result<SweepValues, String>,
}

/// The scalar results a sweep keeps per point.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SweepValues {
    pub eccentricity_ratio: f64,
    pub attitude_angle_deg: f64,
    pub h_min_m: f64,
    pub p_max_pa: f64,
    pub friction_power_w: f64,
    pub reduced: ReducedCoefficients,
}

impl SweepValues {
    fn of(s: &Solution) -> Self {
        Self {
            eccentricity_ratio: s.eccentricity_ratio,
            attitude_angle_deg: s.attitude_angle_deg,
            h_min_m: s.h_min_m,
            p_max_pa: s.p_max_pa,
            friction_power_w: s.friction_power_w,
            reduced: s.reduced,
        }
    }
}

/// Reduced coefficients at each excitation ratio ω/Ω of a frequency sweep.
pub type FrequencySweep = Vec<(f64, ReducedCoefficients)>;

/// Everything computed for a request.
#[derive(Debug, Clone, Default)]
pub struct Outcome {
    pub solution: Option<Arc<Solution>>,
    pub frequency_sweep: Option<Arc<FrequencySweep>>,
    pub speed_sweep: Option<Arc<Vec<SpeedPoint>>>,
}

/// The stages, for counters and progress.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Stage {
    Model,
    Equilibrium,
    Thermal,
    Reduction,
    FrequencySweep,
    SpeedSweep,
}

/// How many times each stage ran (one per sweep point for the speed sweep).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize)]
pub struct StageCounters {
    pub model: usize,
    pub equilibrium: usize,
    /// THD solves (thermal loop around the equilibrium).
    pub thermal: usize,
    pub reduction: usize,
    pub frequency_sweep: usize,
    pub speed_sweep_points: usize,
}

/// Result of one step.
#[derive(Debug, Clone)]
pub enum Step {
    /// More work to do; the stage being worked on and its completed fraction.
    Pending { stage: Stage, fraction: f64 },
    Done(Outcome),
}

fn key<T: Serialize>(v: &T) -> String {
    serde_json::to_string(v).unwrap_or_default()
}

/// Cache key of the model: geometry and mesh.
fn model_key(c: &Case) -> String {
    key(&(&c.bearing, &c.mesh))
}

/// Cache key of the equilibrium: everything but the excitation ratio and the title.
fn equilibrium_key(c: &Case) -> String {
    let mut o = c.operating.clone();
    o.excitation_ratio = 0.0;
    key(&(&c.bearing, &c.mesh, &c.lubricant, &o, &c.physics))
}

/// Cache key of the THD solution: the equilibrium's inputs plus the thermal settings.
fn thermal_key(c: &Case) -> String {
    format!("{}|{}", equilibrium_key(c), key(&c.thermal))
}

fn sweep_key(c: &Case, speeds: &[f64]) -> String {
    let mut o = c.operating.clone();
    o.excitation_ratio = 0.0;
    o.speed_rad_s = 0.0;
    key(&(&c.bearing, &c.mesh, &c.lubricant, &o, &c.physics, &c.thermal, speeds))
}

struct SweepState {
    key: String,
    points: Vec<SpeedPoint>,
    start: Option<Vec<f64>>,
    model: BearingModel,
    thermal: Option<ThermalModel>,
    /// Suspensions of the current point (isothermal points only; THD points run to the end), and the pads
    /// its cold start had placed.
    suspensions: usize,
    placed_pads: usize,
}

/// Outer iterations a THD loop typically needs (for the progress fraction only).
const THERMAL_ITERATIONS_EXPECTED: f64 = 10.0;

/// Suspensions of one equilibrium before it must run to the end.
const MAX_SUSPENSIONS: usize = 40;

/// A suspended equilibrium solve: where to resume it, and the work of its parts so far (added to its final
/// report).
#[derive(Debug, Clone, Default)]
struct Suspensions {
    /// The equilibrium key it belongs to.
    key: String,
    coordinates: Vec<f64>,
    placed_pads: usize,
    suspensions: usize,
    report: SolveReport,
}

impl Suspensions {
    /// One more part of the solve has been suspended.
    fn add(&mut self, part: SolveReport) {
        self.suspensions += 1;
        let mut r = part;
        r.add_earlier(std::mem::take(&mut self.report));
        self.report = r;
    }

    /// The final report covers the whole solve: earlier parts' work first.
    fn merge_into(self, r: &mut SolveReport) {
        r.add_earlier(self.report);
        r.method = format!("{} (resumed {} times, one part per frame)", r.method, self.suspensions);
    }
}

/// Cached, steppable solver.
#[derive(Default)]
pub struct Pipeline {
    model: Option<(String, BearingModel)>,
    equilibrium: Option<(String, Arc<Solution>)>,
    /// Thermal model (pad meshes, thermal systems) under the model key, and the THD solution.
    thermal_model: Option<(String, ThermalModel)>,
    thermal: Option<(String, Arc<Solution>)>,
    /// A THD loop under way (one outer iteration per step), under its thermal key.
    thermal_run: Option<(String, ThdRun)>,
    reduction: Option<(String, Arc<Solution>)>,
    frequency_sweep: Option<(String, Arc<FrequencySweep>)>,
    speed_sweep: Option<SweepState>,
    speed_done: Option<(String, Arc<Vec<SpeedPoint>>)>,
    /// Last equilibrium coordinates, to warm-start the next solve of the same model.
    warm: Option<Vec<f64>>,
    /// An equilibrium paused by [`Cancel::suspend`].
    suspended: Option<Suspensions>,
    pub counters: StageCounters,
}

impl Pipeline {
    #[must_use]
    pub fn new() -> Self {
        Self::default()
    }

    /// Does one unit of work towards `req`.
    ///
    /// # Errors
    /// The first stage that fails (the caller keeps its last good outcome).
    pub fn step(&mut self, req: &Request, cancel: &dyn Cancel) -> Result<Step, SolveError> {
        let Some(case) = &req.case else { return Ok(Step::Done(Outcome::default())) };
        // Model.
        let mk = model_key(case);
        if self.model.as_ref().map(|m| &m.0) != Some(&mk) {
            let m = BearingModel::new(case)?;
            self.counters.model += 1;
            self.model = Some((mk, m));
            self.warm = None;
            return Ok(Step::Pending { stage: Stage::Model, fraction: 1.0 });
        }
        // Equilibrium (with the full coefficients).
        let ek = equilibrium_key(case);
        if self.equilibrium.as_ref().map(|e| &e.0) != Some(&ek) {
            let (_, model) = self.model.as_mut().ok_or_else(|| SolveError::Invalid("no model".into()))?;
            let op = OperatingPoint::isothermal(case);
            // A solve suspended in an earlier step for these inputs resumes from its iterate; after
            // MAX_SUSPENSIONS it runs to the end (bounded work even if every resumption is slow).
            let resumed = self.suspended.take().filter(|r| r.key == ek);
            let may_suspend = resumed.as_ref().is_none_or(|r| r.suspensions < MAX_SUSPENSIONS);
            let no_suspend = NoSuspend(cancel);
            let cancel: &dyn Cancel = if may_suspend { cancel } else { &no_suspend };
            let start = resumed.as_ref().map(|r| r.coordinates.as_slice()).or(self.warm.as_deref());
            let params = EquilibriumParams { placed_pads: resumed.as_ref().map_or(0, |r| r.placed_pads), ..EquilibriumParams::default() };
            let attempt = match step_operating_point(model, case, &op, start, params, cancel) {
                // A failed warm start retries cold before giving up.
                Err(e) if start.is_some() && !matches!(e, SolveError::Cancelled) => {
                    self.warm = None;
                    solve_operating_point(model, case, &op, None, cancel).map(Progress::Done)
                }
                r => r,
            };
            let mut sol = match attempt? {
                Progress::Done(s) => s,
                Progress::Suspended(r) => {
                    let mut so_far = resumed.unwrap_or_default();
                    so_far.add(r.report);
                    self.suspended = Some(Suspensions { key: ek, coordinates: r.coordinates, placed_pads: r.placed_pads, ..so_far });
                    return Ok(Step::Pending { stage: Stage::Equilibrium, fraction: 0.5 });
                }
            };
            if let Some(so_far) = resumed {
                so_far.merge_into(&mut sol.report);
            }
            self.counters.equilibrium += 1;
            self.warm = Some(sol.coordinates.clone());
            self.equilibrium = Some((ek, Arc::new(sol)));
            self.reduction = None;
            return Ok(Step::Pending { stage: Stage::Equilibrium, fraction: 1.0 });
        }
        let mut eq = self.equilibrium.as_ref().map(|e| e.1.clone()).ok_or_else(|| SolveError::Invalid("no equilibrium".into()))?;
        let mut ek = ek;
        // Thermal loop (THD cases), warm-started from the isothermal equilibrium.
        if case.thermal.model == ThermalModelKind::Thd {
            let tk = thermal_key(case);
            if self.thermal.as_ref().map(|t| &t.0) != Some(&tk) {
                let Self { model, thermal_model, thermal_run, .. } = self;
                let (mkey, model) = model.as_mut().ok_or_else(|| SolveError::Invalid("no model".into()))?;
                if thermal_model.as_ref().map(|t| &t.0) != Some(&*mkey) {
                    *thermal_model = Some((mkey.clone(), ThermalModel::new(case, model)?));
                }
                let (_, tm) = thermal_model.as_mut().ok_or_else(|| SolveError::Invalid("no thermal model".into()))?;
                // One outer iteration per step (a failed run is dropped; the next request starts afresh).
                let mut run = match thermal_run.take() {
                    Some((key, run)) if key == tk => run,
                    _ => ThdRun::new(model, tm, case, ThermalParams::default(), Some(&eq.coordinates)),
                };
                let Some(state) = run.step(model, tm, case, &NoSuspend(cancel))? else {
                    #[allow(clippy::cast_precision_loss)]
                    let fraction = (run.outer_iterations() as f64 / THERMAL_ITERATIONS_EXPECTED).min(0.95);
                    *thermal_run = Some((tk, run));
                    return Ok(Step::Pending { stage: Stage::Thermal, fraction });
                };
                let sol = assemble_thd_solution(model, case, &state);
                self.counters.thermal += 1;
                self.thermal = Some((tk, Arc::new(sol)));
                self.reduction = None;
                return Ok(Step::Pending { stage: Stage::Thermal, fraction: 1.0 });
            }
            eq = self.thermal.as_ref().map(|t| t.1.clone()).ok_or_else(|| SolveError::Invalid("no thermal solution".into()))?;
            ek = tk;
        }
        // Reduction at the case's excitation ratio.
        let rk = format!("{ek}|{}", case.operating.excitation_ratio);
        if self.reduction.as_ref().map(|r| &r.0) != Some(&rk) {
            let mut s = (*eq).clone();
            s.reduced = reduce(&s.full, case.operating.excitation_ratio * case.operating.speed_rad_s);
            s.title.clone_from(&case.title);
            s.inputs = case.clone();
            self.counters.reduction += 1;
            self.reduction = Some((rk, Arc::new(s)));
        }
        // Frequency sweep.
        if let Some(ratios) = &req.frequency_ratios {
            let fk = format!("{ek}|{}", key(ratios));
            if self.frequency_sweep.as_ref().map(|f| &f.0) != Some(&fk) {
                let w = case.operating.speed_rad_s;
                let v: FrequencySweep = ratios.iter().map(|&r| (r, reduce(&eq.full, r * w))).collect();
                self.counters.frequency_sweep += 1;
                self.frequency_sweep = Some((fk, Arc::new(v)));
                return Ok(Step::Pending { stage: Stage::FrequencySweep, fraction: 1.0 });
            }
        }
        // Speed sweep, one point per step.
        if let Some(speeds) = &req.speeds_rpm {
            let sk = sweep_key(case, speeds);
            if self.speed_done.as_ref().map(|d| &d.0) != Some(&sk) {
                if self.speed_sweep.as_ref().map(|s| &s.key) != Some(&sk) {
                    let model = match &self.model {
                        Some((_, m)) => m.clone(),
                        None => BearingModel::new(case)?,
                    };
                    self.speed_sweep = Some(SweepState { key: sk.clone(), points: Vec::new(), start: None, model, thermal: None, suspensions: 0, placed_pads: 0 });
                }
                let st = self.speed_sweep.as_mut().ok_or_else(|| SolveError::Invalid("no sweep".into()))?;
                let i = st.points.len();
                let rpm = speeds[i];
                let mut c = case.clone();
                c.operating.speed_rad_s = rpm * std::f64::consts::TAU / 60.0;
                let no_suspend = NoSuspend(cancel);
                let may_suspend = c.thermal.model == ThermalModelKind::Isothermal && st.suspensions < MAX_SUSPENSIONS;
                let point_cancel: &dyn Cancel = if may_suspend { cancel } else { &no_suspend };
                let solved = if may_suspend {
                    let params = EquilibriumParams { placed_pads: st.placed_pads, ..EquilibriumParams::default() };
                    step_operating_point(&mut st.model, &c, &OperatingPoint::isothermal(&c), st.start.as_deref(), params, point_cancel)
                } else {
                    solve_point(&mut st.model, &mut st.thermal, &c, st.start.as_deref(), point_cancel).map(Progress::Done)
                };
                let result = match solved {
                    Ok(Progress::Suspended(r)) => {
                        st.start = Some(r.coordinates);
                        st.placed_pads = r.placed_pads;
                        st.suspensions += 1;
                        #[allow(clippy::cast_precision_loss)]
                        let fraction = i as f64 / speeds.len() as f64;
                        return Ok(Step::Pending { stage: Stage::SpeedSweep, fraction });
                    }
                    Ok(Progress::Done(s)) => {
                        st.start = Some(s.coordinates.clone());
                        Ok(SweepValues::of(&s))
                    }
                    Err(SolveError::Cancelled) => return Err(SolveError::Cancelled),
                    Err(e) => {
                        st.start = None;
                        Err(e.to_string())
                    }
                };
                st.suspensions = 0;
                st.placed_pads = 0;
                st.points.push(SpeedPoint { speed_rpm: rpm, result });
                self.counters.speed_sweep_points += 1;
                #[allow(clippy::cast_precision_loss)]
                let fraction = st.points.len() as f64 / speeds.len() as f64;
                if st.points.len() == speeds.len() {
                    let done = std::mem::take(&mut st.points);
                    self.speed_sweep = None;
                    self.speed_done = Some((sk, Arc::new(done)));
                }
                return Ok(Step::Pending { stage: Stage::SpeedSweep, fraction });
            }
        }
        Ok(Step::Done(self.outcome(req)))
    }

    /// Runs `step` until done.
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

    fn outcome(&self, req: &Request) -> Outcome {
        Outcome {
            solution: self.reduction.as_ref().map(|r| r.1.clone()),
            frequency_sweep: req.frequency_ratios.as_ref().and(self.frequency_sweep.as_ref().map(|f| f.1.clone())),
            speed_sweep: req.speeds_rpm.as_ref().and(self.speed_done.as_ref().map(|d| d.1.clone())),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bearing::NoCancel;
    use crate::model::load_case;

    fn case(set: &[&str]) -> Case {
        let text = include_str!("../../cases/fillon-a.toml");
        // These tests are about the isothermal stages; the thermal stage has its own test below.
        let mut set: Vec<String> = std::iter::once("thermal.model=\"isothermal\"").chain(set.iter().copied()).map(str::to_string).collect();
        set.dedup();
        load_case(&text.replace("fidelity = \"standard\"", "fidelity = \"preview\""), &set).unwrap().1
    }

    #[test]
    fn stages_rerun_only_when_their_inputs_change() {
        let mut p = Pipeline::new();
        let mut req = Request { case: Some(case(&[])), frequency_ratios: Some(vec![0.5, 1.0, 2.0]), speeds_rpm: None };
        p.run(&req, &NoCancel).unwrap();
        assert_eq!(p.counters, StageCounters { model: 1, equilibrium: 1, thermal: 0, reduction: 1, frequency_sweep: 1, speed_sweep_points: 0 });
        // Same request: nothing runs.
        p.run(&req, &NoCancel).unwrap();
        assert_eq!(p.counters.equilibrium, 1);
        assert_eq!(p.counters.reduction, 1);
        // The title and the excitation ratio do not enter the equilibrium.
        req.case = Some(case(&["title=\"renamed\"", "operating.excitation_ratio=0.5"]));
        let o = p.run(&req, &NoCancel).unwrap();
        assert_eq!((p.counters.model, p.counters.equilibrium, p.counters.reduction, p.counters.frequency_sweep), (1, 1, 2, 1));
        assert_eq!(o.solution.unwrap().title, "renamed");
        // The load changes the equilibrium and the sweep, not the model.
        req.case = Some(case(&["operating.load_n=8000"]));
        p.run(&req, &NoCancel).unwrap();
        assert_eq!((p.counters.model, p.counters.equilibrium, p.counters.frequency_sweep), (1, 2, 2));
        // The mesh changes everything.
        req.case = Some(case(&["mesh.circumferential_elements=20"]));
        p.run(&req, &NoCancel).unwrap();
        assert_eq!((p.counters.model, p.counters.equilibrium), (2, 3));
    }

    /// Asks every solve to pause as soon as it may (the web stepper with a spent frame budget).
    struct AlwaysSuspend;
    impl Cancel for AlwaysSuspend {
        fn cancelled(&self) -> bool {
            false
        }
        fn suspend(&self) -> bool {
            true
        }
    }

    #[test]
    fn a_suspended_equilibrium_resumes_from_its_iterate_and_reaches_the_same_solution() {
        let req = Request { case: Some(case(&["operating.load_n=12000"])), frequency_ratios: None, speeds_rpm: None };
        let whole = Pipeline::new().run(&req, &NoCancel).unwrap().solution.unwrap();
        let mut p = Pipeline::new();
        let mut equilibrium_steps = 0;
        let parts = loop {
            match p.step(&req, &AlwaysSuspend).unwrap() {
                Step::Done(o) => break o.solution.unwrap(),
                Step::Pending { stage: Stage::Equilibrium, .. } => equilibrium_steps += 1,
                Step::Pending { .. } => {}
            }
            assert!(equilibrium_steps <= MAX_SUSPENSIONS + 1, "suspensions are bounded");
        };
        // The cold start places one pad per step, then one Newton iteration per step (the last converges).
        let pads = parts.pads.len();
        assert!(equilibrium_steps > pads, "the solve was split: {equilibrium_steps} steps for {pads} pads");
        assert_eq!(p.counters.equilibrium, 1);
        assert!(parts.report.method.contains("resumed"), "{}", parts.report.method);
        assert!(parts.report.iterations + pads >= equilibrium_steps, "the report counts every part: {}", parts.report.iterations);
        assert_eq!(parts.report.residual_history.len(), parts.report.iterations);
        assert!(parts.report.residual < 1e-9, "converged: {:e}", parts.report.residual);
        let rel = |a: f64, b: f64| ((a - b) / b).abs();
        assert!(rel(parts.eccentricity_ratio, whole.eccentricity_ratio) < 1e-6, "{} vs {}", parts.eccentricity_ratio, whole.eccentricity_ratio);
        assert!(rel(parts.reduced.k_n_per_m[1][1], whole.reduced.k_n_per_m[1][1]) < 1e-5);
    }

    #[test]
    fn suspended_speed_sweep_points_resume_and_match_whole_ones() {
        let req = Request { case: Some(case(&[])), frequency_ratios: None, speeds_rpm: Some(vec![2000.0, 3000.0, 4000.0]) };
        let whole = Pipeline::new().run(&req, &NoCancel).unwrap().speed_sweep.unwrap();
        let mut p = Pipeline::new();
        let mut sweep_steps = 0;
        let parts = loop {
            match p.step(&req, &AlwaysSuspend).unwrap() {
                Step::Done(o) => break o.speed_sweep.unwrap(),
                Step::Pending { stage: Stage::SpeedSweep, .. } => sweep_steps += 1,
                Step::Pending { .. } => {}
            }
            assert!(sweep_steps <= 3 * (MAX_SUSPENSIONS + 1), "suspensions are bounded");
        };
        assert!(sweep_steps > 3, "points were split: {sweep_steps} steps");
        assert_eq!(p.counters.speed_sweep_points, 3);
        for (a, b) in parts.iter().zip(whole.iter()) {
            let (ea, eb) = (a.result.as_ref().unwrap().eccentricity_ratio, b.result.as_ref().unwrap().eccentricity_ratio);
            assert!(((ea - eb) / eb).abs() < 1e-6, "{} rpm: {ea} vs {eb}", a.speed_rpm);
        }
    }

    #[test]
    fn speed_sweep_runs_point_by_point_and_is_cached() {
        let mut p = Pipeline::new();
        let req = Request { case: Some(case(&[])), frequency_ratios: None, speeds_rpm: Some(vec![2000.0, 3000.0, 4000.0]) };
        let mut steps = 0;
        let out = loop {
            steps += 1;
            match p.step(&req, &NoCancel).unwrap() {
                Step::Done(o) => break o,
                Step::Pending { .. } => {}
            }
        };
        // model, equilibrium, three sweep points, done.
        assert_eq!(steps, 6);
        let sweep = out.speed_sweep.unwrap();
        assert_eq!(sweep.len(), 3);
        let e: Vec<f64> = sweep.iter().map(|p| p.result.as_ref().unwrap().eccentricity_ratio).collect();
        assert!(e[0] > e[1] && e[1] > e[2], "eccentricity falls with speed: {e:?}");
        p.run(&req, &NoCancel).unwrap();
        assert_eq!(p.counters.speed_sweep_points, 3);
    }

    #[test]
    fn thermal_stage_runs_after_the_equilibrium_and_is_cached() {
        let thd = |extra: &[&str]| {
            let mut set = vec!["thermal.model=\"thd\""];
            set.extend_from_slice(extra);
            case(&set)
        };
        let mut p = Pipeline::new();
        let mut req = Request { case: Some(thd(&[])), frequency_ratios: None, speeds_rpm: None };
        // The loop runs one outer iteration per step.
        let mut thermal_steps = 0;
        let o = loop {
            match p.step(&req, &NoCancel).unwrap() {
                Step::Done(o) => break o,
                Step::Pending { stage: Stage::Thermal, .. } => thermal_steps += 1,
                Step::Pending { .. } => {}
            }
        };
        assert_eq!((p.counters.model, p.counters.equilibrium, p.counters.thermal, p.counters.reduction), (1, 1, 1, 1));
        let s = o.solution.unwrap();
        let t = s.thermal.as_ref().expect("thermal results");
        assert!(t.report.converged && t.t_max_film_c > 40.0);
        assert_eq!(thermal_steps, t.report.outer_iterations, "one step per outer iteration");
        assert!(thermal_steps > 2);
        // The same state as the loop run in one go.
        let mut m = BearingModel::new(req.case.as_ref().unwrap()).unwrap();
        let whole = crate::bearing::solve_point(&mut m, &mut None, req.case.as_ref().unwrap(), None, &NoCancel).unwrap();
        let w = whole.thermal.as_ref().unwrap();
        assert!((w.t_max_film_c - t.t_max_film_c).abs() < 1e-3, "{} vs {}", w.t_max_film_c, t.t_max_film_c);
        assert!(s.pads.iter().all(|p| p.field.film_temperature_c.is_some() && p.field.pad_surface_temperature_c.is_some()));
        // A thermal setting reruns only the thermal stage (and the reduction after it).
        req.case = Some(thd(&["thermal.convection_w_per_m2_k=150"]));
        p.run(&req, &NoCancel).unwrap();
        assert_eq!((p.counters.model, p.counters.equilibrium, p.counters.thermal, p.counters.reduction), (1, 1, 2, 2));
        // The excitation ratio reruns only the reduction.
        req.case = Some(thd(&["thermal.convection_w_per_m2_k=150", "operating.excitation_ratio=0.5"]));
        p.run(&req, &NoCancel).unwrap();
        assert_eq!((p.counters.equilibrium, p.counters.thermal, p.counters.reduction), (1, 2, 3));
    }
}
