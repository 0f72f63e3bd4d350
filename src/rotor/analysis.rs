//! The rotor analysis over a speed range: damped modes at each speed (bearings solved at each speed through
//! [`BearingSet`]), the instability onset, the Campbell critical speeds (1×) and the unbalance response,
//! with a report (bearing solves, eigen-solutions, time, warnings).
//!
//! Steppable: [`Analysis::step`] does one speed and returns; [`run`] loops it to the end.

use serde::{Deserialize, Serialize};
use web_time::Instant;

use super::assembly::ShaftModel;
use super::bearings::BearingSet;
use super::campbell::{critical_speeds, CriticalSpeed};
use super::coupling::{assemble, BearingCoefficients};
use super::critical_map::StiffnessCurve;
use super::eigen::damped_modes;
use super::error::{RotorError, RotorWarning};
use super::reduction::reduce;
use super::stability::{onset, Onset, SpeedPoint};
use super::unbalance::{api617_limit_um, response, Orbit};
use crate::model::rotor::Rotor;

/// Speeds the onset bisection adds, at most, in a work estimate (the default relative bracket of 10⁻³ takes
/// ten halvings).
pub const ONSET_PROBES: usize = 12;

/// Settings of an analysis.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct AnalysisParams {
    /// Spin speeds [rad/s], ascending.
    pub speeds_rad_s: Vec<f64>,
    /// Relative bracket of the onset bisection.
    pub onset_tol: f64,
    /// Forward modes followed for the critical speeds.
    pub campbell_modes: usize,
}

impl AnalysisParams {
    #[must_use]
    pub fn new(speeds_rad_s: Vec<f64>) -> Self {
        Self { speeds_rad_s, onset_tol: 1e-3, campbell_modes: 4 }
    }
}

/// Results at one speed.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SpeedResult {
    pub point: SpeedPoint,
    /// Orbits at the response nodes (bearing and unbalance nodes).
    pub orbits: Vec<Orbit>,
    /// API 617 limit at this speed [µm peak-to-peak].
    pub api617_limit_um: f64,
}

/// Numbers about the run.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, Default)]
pub struct AnalysisReport {
    pub bearing_solves: usize,
    pub eigen_solutions: usize,
    pub system_dofs: usize,
    /// Fixed-interface shaft modes kept per bending plane (0: the full finite-element shaft).
    pub shaft_modes: usize,
    /// Wall time of the whole analysis, and the parts spent in bearing solves and in eigen-solutions
    /// (sweep and onset bisection) [s].
    pub seconds: f64,
    pub bearing_seconds: f64,
    pub eigen_seconds: f64,
    pub warnings: Vec<RotorWarning>,
}

/// Everything an analysis produces.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct AnalysisResult {
    pub title: String,
    pub representative: bool,
    pub speeds: Vec<SpeedResult>,
    pub onset: Option<Onset>,
    pub critical_speeds: Vec<CriticalSpeed>,
    /// Free–free flexible frequencies of the shaft (one plane) [rad/s].
    pub free_free_rad_s: Vec<f64>,
    pub response_nodes: Vec<usize>,
    /// Per bearing position, its synchronously reduced direct stiffnesses at the sweep's speeds
    /// (`(Ω [rad/s], k_xx, k_yy)`: the curves of the critical-speed map).
    pub bearing_stiffness: Vec<StiffnessCurve>,
    pub report: AnalysisReport,
}

/// A running analysis.
pub struct Analysis {
    rotor: Rotor,
    shaft: ShaftModel,
    bearings: BearingSet,
    params: AnalysisParams,
    nodes: Vec<usize>,
    done: Vec<SpeedResult>,
    stiffness: Vec<StiffnessCurve>,
    report: AnalysisReport,
    started: Instant,
}

/// Whether a step finished the sweep.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Step {
    More { done: usize, of: usize },
    Finished,
}

impl Analysis {
    /// Builds the shaft model and the bearing set.
    ///
    /// # Errors
    /// [`RotorError::Speeds`] for an empty, non-positive or unsorted speed list; assembly errors.
    pub fn new(rotor: &Rotor, params: AnalysisParams) -> Result<Self, RotorError> {
        let s = &params.speeds_rad_s;
        if s.is_empty() || s.iter().any(|w| !w.is_finite() || *w < 0.0) || s.windows(2).any(|w| w[1] <= w[0]) {
            return Err(RotorError::Speeds);
        }
        let mut report = AnalysisReport::default();
        let bearings = BearingSet::new(rotor);
        let shaft = shaft_model(rotor, &bearings.nodes, &mut report)?;
        let mut nodes: Vec<usize> =
            bearings.nodes.iter().copied().chain(rotor.unbalances.iter().map(|u| u.node)).collect();
        nodes.sort_unstable();
        nodes.dedup();
        Ok(Self {
            rotor: rotor.clone(),
            shaft,
            bearings,
            params,
            nodes,
            done: Vec::new(),
            stiffness: vec![Vec::new(); rotor.bearings.len()],
            report,
            started: Instant::now(),
        })
    }

    /// Does the next speed.
    ///
    /// # Errors
    /// Bearing solves and eigen-solutions that fail.
    pub fn step(&mut self) -> Result<Step, RotorError> {
        let of = self.params.speeds_rad_s.len();
        let Some(&omega) = self.params.speeds_rad_s.get(self.done.len()) else {
            return Ok(Step::Finished);
        };
        let t0 = Instant::now();
        let coeffs = self.bearings.at(omega)?;
        let t1 = Instant::now();
        self.report.bearing_seconds += t1.duration_since(t0).as_secs_f64();
        for (curve, c) in self.stiffness.iter_mut().zip(&coeffs) {
            if let BearingCoefficients::Reduced { k, .. } = c.reduced(omega) {
                curve.push((omega, k[0][0], k[1][1]));
            }
        }
        let sys = assemble(&self.shaft, &self.bearings.nodes, &coeffs, omega);
        self.report.system_dofs = self.report.system_dofs.max(sys.n_dofs());
        let modes = damped_modes(&sys, &self.shaft)?;
        self.report.eigen_seconds += t1.elapsed().as_secs_f64();
        self.report.eigen_solutions += 1;
        // the response uses the synchronously reduced bearings (identical to the full system at Ω)
        let orbits = if self.rotor.unbalances.is_empty() || omega == 0.0 {
            Vec::new()
        } else {
            response(&sys, &self.shaft, &self.rotor.unbalances, omega, &self.nodes)?
        };
        let rpm = crate::units::RPM.from_si(omega);
        self.done.push(SpeedResult {
            point: SpeedPoint { speed_rad_s: omega, modes },
            orbits,
            api617_limit_um: if rpm > 0.0 { api617_limit_um(rpm) } else { f64::INFINITY },
        });
        Ok(if self.done.len() == of { Step::Finished } else { Step::More { done: self.done.len(), of } })
    }

    /// Speeds the sweep was asked for (done or not).
    #[must_use]
    pub fn speeds_to_do(&self) -> usize {
        self.params.speeds_rad_s.len()
    }

    /// Stops the sweep at the speeds done so far: [`Analysis::finish`] then covers those only, skips the onset
    /// bisection (no more bearing solves) and warns ([`RotorWarning::Stopped`]).
    pub fn stop(&mut self) {
        let of = self.params.speeds_rad_s.len();
        let done = self.done.len();
        if done < of {
            self.params.speeds_rad_s.truncate(done);
            self.report.warnings.push(RotorWarning::Stopped { done, of });
        }
    }

    fn stopped(&self) -> bool {
        self.report.warnings.iter().any(|w| matches!(w, RotorWarning::Stopped { .. }))
    }

    /// Finishes: onset bisection, critical speeds, report.
    ///
    /// # Errors
    /// Bearing solves and eigen-solutions of the onset bisection.
    pub fn finish(mut self) -> Result<AnalysisResult, RotorError> {
        let sweep: Vec<SpeedPoint> = self.done.iter().map(|r| r.point.clone()).collect();
        let stopped = self.stopped();
        let nodes = self.bearings.nodes.clone();
        let bearings = &mut self.bearings;
        let mut bearing_seconds = 0.0;
        let mut provider = |w: f64| {
            let t = Instant::now();
            let c = bearings.at(w);
            bearing_seconds += t.elapsed().as_secs_f64();
            c
        };
        let t = Instant::now();
        let onset = if stopped || sweep.is_empty() {
            None
        } else {
            onset(&self.shaft, &nodes, &mut provider, &sweep, self.params.onset_tol)?
        };
        self.report.bearing_seconds += bearing_seconds;
        self.report.eigen_seconds += t.elapsed().as_secs_f64() - bearing_seconds;
        if let Some(o) = onset {
            self.report.eigen_solutions += o.probes;
        } else if sweep.first().is_some_and(|p| p.min_log_dec() <= 0.0) {
            self.report.warnings.push(RotorWarning::UnstableFromFirstSpeed);
        }
        let critical = critical_speeds(&sweep, 1.0, self.params.campbell_modes);
        self.report.bearing_solves = self.bearings.solves;
        self.report.seconds = self.started.elapsed().as_secs_f64();
        Ok(AnalysisResult {
            title: self.rotor.title.clone(),
            representative: self.rotor.representative,
            speeds: self.done,
            onset,
            critical_speeds: critical,
            free_free_rad_s: self.shaft.free_free_rad_s.clone(),
            response_nodes: self.nodes,
            bearing_stiffness: self.stiffness,
            report: self.report,
        })
    }
}

/// The shaft model of an analysis: reduced to the attached nodes and `rotor.shaft_modes` modes per plane, or
/// the full one (asked for, or — with a warning — when the attached nodes do not hold the shaft).
pub fn shaft_model(
    rotor: &Rotor,
    bearing_nodes: &[usize],
    report: &mut AnalysisReport,
) -> Result<ShaftModel, RotorError> {
    let full = ShaftModel::new(rotor)?;
    if rotor.shaft_modes == 0 {
        return Ok(full);
    }
    let attached: Vec<usize> = bearing_nodes
        .iter()
        .copied()
        .chain(rotor.supports.iter().map(|s| s.node))
        .chain(rotor.unbalances.iter().map(|u| u.node))
        .collect();
    match reduce(&full, &attached, rotor.shaft_modes) {
        Ok(r) => {
            report.shaft_modes = rotor.shaft_modes;
            Ok(r)
        }
        Err(RotorError::Reduction { attached }) => {
            report.warnings.push(RotorWarning::FullShaftModel { attached });
            Ok(full)
        }
        Err(e) => Err(e),
    }
}

/// Runs the whole analysis.
///
/// # Errors
/// As [`Analysis::new`], [`Analysis::step`] and [`Analysis::finish`].
pub fn run(rotor: &Rotor, params: AnalysisParams) -> Result<AnalysisResult, RotorError> {
    let mut a = Analysis::new(rotor, params)?;
    while a.step()? != Step::Finished {}
    a.finish()
}
