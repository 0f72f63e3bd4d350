//! The closed-loop analysis over a speed range: at each speed the plant ([`Plant`]: bearings solved, the
//! valve chains linearised by the FRF stage), the poles with the loop open (gain 0) and closed, the Nyquist
//! check and margins at every actuator's input, and the unbalance response with and without control with the
//! actuator signals and nozzle pressures it needs; then the instability onset against the loop gain.
//!
//! Steppable: [`ControlAnalysis::step`] does one speed; [`run`] loops it and finishes.

use nalgebra::{Complex, DVector};
use serde::{Deserialize, Serialize};
use web_time::Instant;

use crate::bearing::Cancel;

use super::closed_loop::{broken, forced, poles, Poles};
use super::error::{ControlError, ControlWarning};
use super::law::design;
use super::lqr::LqrDesign;
use super::nyquist::{nyquist, Nyquist};
use super::plant::{ActuatorPlant, Plant, ValvePlant};
use super::state_space::StateSpace;
use super::tuning::{root_locus, PlantSweep, RootLocus};
use crate::bearing::film::coordinates::JOURNAL_DOFS;
use crate::model::control::{ActuatorKind, Axis, Control};
use crate::model::rotor::{BearingSupport, CoefficientModel, Rotor};
use crate::physics::hydraulics::servovalve::SMALL_SIGNAL_FRACTION;
use crate::rotor::analysis::{shaft_model, AnalysisReport, ONSET_PROBES};
use crate::rotor::assembly::{NodeDof, ShaftModel, Weights};
use crate::rotor::bearings::BearingSet;
use crate::rotor::coupling::{assemble, BearingCoefficients};
use crate::rotor::unbalance::{api617_limit_um, forces, Orbit};
use crate::study::estimate::Estimate;

/// Poles kept on a root locus: up to this frequency [Hz] (the valves' and lines' poles lie far above).
const LOCUS_MAX_HZ: f64 = 500.0;

/// A force actuator's linear range when none is given [V].
const FORCE_ACTUATOR_LIMIT_V: f64 = 10.0;

/// Settings of a closed-loop analysis.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ControlParams {
    /// Spin speeds [rad/s], ascending.
    pub speeds_rad_s: Vec<f64>,
    /// Loop gains whose onset speeds are found (the gain sweep; empty: the controller's gain only).
    pub gains: Vec<f64>,
    /// Relative bracket of the onset bisection.
    pub onset_tol: f64,
    /// Nyquist check and margins at every speed.
    pub nyquist: bool,
    /// Speed of a root locus over [`Self::gains`] (or over 0 to twice the controller's gain, 21 steps) [rad/s].
    pub root_locus_rad_s: Option<f64>,
}

impl ControlParams {
    #[must_use]
    pub fn new(speeds_rad_s: Vec<f64>) -> Self {
        Self { speeds_rad_s, gains: Vec::new(), onset_tol: 1e-3, nyquist: true, root_locus_rad_s: None }
    }

    /// The work of an analysis of `rotor` under `control` with these settings, before it starts: at each
    /// speed one bearing solve per bearing and the damped eigen-solutions open and closed loop, one per
    /// actuator for the Nyquist test and one per swept gain (other than 0 and the controller's); the onsets
    /// open, closed and at each swept gain bisect with up to [`ONSET_PROBES`] probes each (bearing solves
    /// and an eigen-solution); the root locus adds one per gain.
    #[must_use]
    pub fn estimate(&self, rotor: &Rotor, control: &Control) -> Estimate {
        let probes = (2 + self.gains.len()).saturating_mul(ONSET_PROBES);
        let swept = self.gains.iter().filter(|&&g| g != 0.0 && g != control.gain).count();
        let nyquist = if self.nyquist { control.actuators.len() } else { 0 };
        let locus = match self.root_locus_rad_s {
            Some(_) if self.gains.is_empty() => 21,
            Some(_) => self.gains.len(),
            None => 0,
        };
        Estimate::control(rotor, self.speeds_rad_s.len(), probes, 2 + nyquist + swept, probes + locus)
    }
}

/// The unbalance response at one speed, with the loop open and closed.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ResponsePoint {
    pub open: Vec<Orbit>,
    pub closed: Vec<Orbit>,
    /// Each actuator's signal amplitude [V].
    pub signal_v: Vec<f64>,
    /// Per actuator, per port, the nozzle pressure amplitude [Pa].
    pub nozzle_pressure_pa: Vec<Vec<f64>>,
}

/// Results at one speed.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SpeedResult {
    pub speed_rad_s: f64,
    /// Poles with the loop open (gain 0: rotor, actuators and controller apart).
    pub open: Poles,
    /// Poles with the loop closed at the controller's gain.
    pub closed: Poles,
    /// Per actuator, the loop broken at its input.
    pub loops: Vec<Nyquist>,
    pub response: Option<ResponsePoint>,
    /// API 617 limit at this speed [µm peak-to-peak].
    pub api617_limit_um: f64,
}

/// The onset speed at one gain.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct GainOnset {
    pub gain: f64,
    /// First stable → unstable crossing [rad/s]; `None`: none in the sweep.
    pub onset_rad_s: Option<f64>,
    /// Stable at the first speed of the sweep.
    pub stable_at_first: bool,
}

/// Everything a closed-loop analysis produces.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ControlResult {
    pub title: String,
    pub gain: f64,
    pub speeds: Vec<SpeedResult>,
    /// Onset with the loop open, and closed at the controller's gain.
    pub onset_open: GainOnset,
    pub onset_closed: GainOnset,
    /// Onset at each gain of the sweep.
    pub gain_sweep: Vec<GainOnset>,
    /// The root locus asked for ([`ControlParams::root_locus_rad_s`]).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub root_locus: Option<RootLocus>,
    /// The LQR designed on the reduced model (a `[control.lqr]` controller).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub lqr: Option<LqrDesign>,
    /// Each actuator's linear range [V].
    pub limit_v: Vec<f64>,
    pub response_nodes: Vec<usize>,
    /// States of the closed loop (at the last speed).
    pub states: usize,
    pub bearing_solves: usize,
    pub eigen_solutions: usize,
    pub seconds: f64,
    pub warnings: Vec<ControlWarning>,
}

/// A running closed-loop analysis.
pub struct ControlAnalysis {
    rotor: Rotor,
    control: Control,
    controller: StateSpace,
    lqr: Option<LqrDesign>,
    shaft: ShaftModel,
    bearings: BearingSet,
    params: ControlParams,
    nodes: Vec<usize>,
    limits: Vec<f64>,
    plants: Vec<Plant>,
    /// Plants at the onset bisections' probe speeds: every gain's bisection in the same bracket starts with
    /// the same probes.
    probes: Vec<(f64, Plant)>,
    done: Vec<SpeedResult>,
    eigen_solutions: usize,
    warnings: Vec<ControlWarning>,
    started: Instant,
}

impl ControlAnalysis {
    /// Builds the shaft model, the bearing set and the controller (an LQR designed on the plant at its design
    /// speed).
    ///
    /// # Errors
    /// Bad speeds or gains; a valve actuator with reduced bearing coefficients; assembly errors; an LQR
    /// without a design speed or that cannot be designed.
    pub fn new(rotor: &Rotor, control: &Control, params: ControlParams) -> Result<Self, ControlError> {
        let s = &params.speeds_rad_s;
        if s.is_empty() || s.iter().any(|w| !w.is_finite() || *w < 0.0) || s.windows(2).any(|w| w[1] <= w[0]) {
            return Err(crate::rotor::RotorError::Speeds.into());
        }
        if let Some(&gain) = params.gains.iter().find(|g| !g.is_finite()) {
            return Err(ControlError::Gain { gain });
        }
        let mut limits = Vec::new();
        for a in &control.actuators {
            let default = match a.kind {
                ActuatorKind::Valve { bearing } => {
                    if rotor.coefficients == CoefficientModel::Reduced {
                        return Err(ControlError::ValveNeedsFullCoefficients { bearing });
                    }
                    valve_full_scale(rotor, bearing) * SMALL_SIGNAL_FRACTION
                }
                ActuatorKind::Force { .. } => FORCE_ACTUATOR_LIMIT_V,
            };
            limits.push(a.max_voltage_v.unwrap_or(default));
        }
        let bearings = BearingSet::new(rotor);
        let mut report = AnalysisReport::default();
        let shaft = shaft_model(rotor, &bearings.nodes, &mut report)?;
        let mut nodes: Vec<usize> = bearings
            .nodes
            .iter()
            .copied()
            .chain(rotor.unbalances.iter().map(|u| u.node))
            .chain(control.sensors.iter().map(|s| s.node))
            .collect();
        nodes.sort_unstable();
        nodes.dedup();
        let mut analysis = Self {
            rotor: rotor.clone(),
            control: control.clone(),
            controller: StateSpace::gain(nalgebra::DMatrix::zeros(control.actuators.len(), control.sensors.len())),
            lqr: None,
            shaft,
            bearings,
            params,
            nodes,
            limits,
            plants: Vec::new(),
            probes: Vec::new(),
            done: Vec::new(),
            eigen_solutions: 0,
            warnings: Vec::new(),
            started: Instant::now(),
        };
        let (controller, lqr) = design(control, |speed| {
            let w = speed.ok_or_else(|| {
                crate::model::CaseError::missing("control.lqr.design_speed_rpm", "the speed the LQR is designed at")
            })?;
            Ok((analysis.plant_at(w)?, w))
        })?;
        analysis.controller = controller;
        analysis.lqr = lqr;
        Ok(analysis)
    }

    /// The controller the loop closes through (designed, for an LQR).
    #[must_use]
    pub fn controller(&self) -> &StateSpace {
        &self.controller
    }

    /// What the LQR design produced (`None` for another law).
    #[must_use]
    pub fn lqr(&self) -> Option<&LqrDesign> {
        self.lqr.as_ref()
    }

    /// The plant at `omega` [rad/s].
    ///
    /// # Errors
    /// Bearing solves; a singular mass matrix.
    pub fn plant_at(&mut self, omega: f64) -> Result<Plant, ControlError> {
        let coeffs = self.bearings.at(omega)?;
        let sys = assemble(&self.shaft, &self.bearings.nodes, &coeffs, omega);
        let mut actuators = Vec::new();
        for a in &self.control.actuators {
            actuators.push(match a.kind {
                ActuatorKind::Force { node, direction, gain_n_per_v, dynamics } => {
                    ActuatorPlant::Force { weights: self.place(node, direction), gain_n_per_v, dynamics }
                }
                ActuatorKind::Valve { bearing } => {
                    let BearingCoefficients::Full(full) = &coeffs[bearing] else {
                        return Err(ControlError::ValveNeedsFullCoefficients { bearing });
                    };
                    let frf = self.bearings.frf_at(bearing, omega)?.ok_or(ControlError::NoController)?;
                    let case_hydraulics = match &self.rotor.bearings[bearing].support {
                        BearingSupport::Case { case, .. } => case.hydraulics.clone(),
                        BearingSupport::Numbers(_) => None,
                    }
                    .ok_or(ControlError::NoController)?;
                    let node = self.bearings.nodes[bearing];
                    let coordinates = full
                        .coords
                        .iter()
                        .enumerate()
                        .map(|(c, coord)| match c {
                            0 => Some(self.shaft.weights(node, NodeDof::X)),
                            1 => Some(self.shaft.weights(node, NodeDof::Y)),
                            _ => sys
                                .appended
                                .iter()
                                .position(|d| d.bearing == bearing && d.coord == *coord)
                                .map(|i| vec![(sys.n_shaft + i, 1.0)]),
                        })
                        .collect();
                    debug_assert!(full.coords.len() >= JOURNAL_DOFS);
                    ActuatorPlant::Valve(Box::new(ValvePlant {
                        hydraulics: frf.hydraulics(&case_hydraulics),
                        coupling: frf.dynamics.coupling.clone(),
                        coordinates,
                    }))
                }
            });
        }
        let shaft = &self.shaft;
        let place = |node: usize, axis: Axis| shaft.weights(node, dof(axis));
        Plant::new(&sys, &place, &self.control.sensors, &actuators)
    }

    /// The speeds analysed so far.
    #[must_use]
    pub fn done(&self) -> &[SpeedResult] {
        &self.done
    }

    /// The plants of the speeds analysed so far with their unbalance forces: the loop can be closed again
    /// through another controller or gain without a bearing solve ([`super::tuning`]).
    #[must_use]
    pub fn sweep(&self) -> PlantSweep {
        let forces = self
            .done
            .iter()
            .zip(&self.plants)
            .map(|(s, p)| {
                (s.response.is_some())
                    .then(|| forces(p.coordinates.nrows(), &self.shaft, &self.rotor.unbalances, s.speed_rad_s))
            })
            .collect();
        let nodes = self
            .nodes
            .iter()
            .map(|&n| (n, self.shaft.weights(n, NodeDof::X), self.shaft.weights(n, NodeDof::Y)))
            .collect();
        PlantSweep {
            speeds_rad_s: self.done.iter().map(|s| s.speed_rad_s).collect(),
            plants: self.plants.clone(),
            forces,
            nodes,
            limits_v: self.limits.clone(),
        }
    }

    fn place(&self, node: usize, axis: Axis) -> Weights {
        self.shaft.weights(node, dof(axis))
    }

    /// Does the next speed.
    ///
    /// # Errors
    /// Bearing solves, eigen-solutions and responses that fail.
    pub fn step(&mut self) -> Result<bool, ControlError> {
        let Some(&omega) = self.params.speeds_rad_s.get(self.done.len()) else {
            return Ok(true);
        };
        let plant = self.plant_at(omega)?;
        let gain = self.control.gain;
        let open = poles(&plant, &self.controller, 0.0)?;
        let closed = poles(&plant, &self.controller, gain)?;
        self.eigen_solutions += 2;
        let mut loops = Vec::new();
        if self.params.nyquist {
            for a in 0..self.control.actuators.len() {
                let n = nyquist(&broken(&plant, &self.controller, gain, a))?;
                self.eigen_solutions += 1;
                if n.stable() != closed.stable() {
                    self.warnings
                        .push(ControlWarning::NyquistDisagrees { speed_rpm: crate::units::RPM.from_si(omega) });
                }
                loops.push(n);
            }
        }
        let response =
            if self.rotor.unbalances.is_empty() || omega == 0.0 { None } else { Some(self.response(&plant, omega)?) };
        let rpm = crate::units::RPM.from_si(omega);
        self.done.push(SpeedResult {
            speed_rad_s: omega,
            open,
            closed,
            loops,
            response,
            api617_limit_um: if rpm > 0.0 { api617_limit_um(rpm) } else { f64::INFINITY },
        });
        self.plants.push(plant);
        Ok(self.done.len() == self.params.speeds_rad_s.len())
    }

    fn response(&mut self, plant: &Plant, omega: f64) -> Result<ResponsePoint, ControlError> {
        let n = plant.coordinates.nrows();
        let f: DVector<Complex<f64>> = forces(n, &self.shaft, &self.rotor.unbalances, omega);
        let (shaft, nodes) = (&self.shaft, &self.nodes);
        let orbits = |u: &DVector<Complex<f64>>| -> Vec<Orbit> {
            let at = |node: usize, axis: Axis| {
                shaft.weights(node, dof(axis)).iter().fold(Complex::new(0.0, 0.0), |acc, &(j, c)| acc + u[j] * c)
            };
            nodes.iter().map(|&node| Orbit::from_amplitudes(node, at(node, Axis::X), at(node, Axis::Y))).collect()
        };
        let open = forced(plant, &self.controller, 0.0, omega, &f)?;
        let closed = forced(plant, &self.controller, self.control.gain, omega, &f)?;
        let signal_v: Vec<f64> = closed.signals.iter().map(|z| z.norm()).collect();
        let (open, closed_orbits) = (orbits(&open.coordinates), orbits(&closed.coordinates));
        for (a, (&v, &limit)) in signal_v.iter().zip(&self.limits).enumerate() {
            if v > limit {
                self.warnings.push(ControlWarning::Saturation {
                    actuator: a,
                    speed_rpm: crate::units::RPM.from_si(omega),
                    amplitude_v: v,
                    limit_v: limit,
                });
            }
        }
        Ok(ResponsePoint {
            open,
            closed: closed_orbits,
            signal_v,
            nozzle_pressure_pa: closed.pressures.iter().map(|p| p.iter().map(|z| z.norm()).collect()).collect(),
        })
    }

    /// The onset at `gain`: the first stable → unstable crossing of the sweep, refined by bisection.
    ///
    /// # Errors
    /// Bearing solves and eigen-solutions of the probes.
    pub fn onset(&mut self, gain: f64) -> Result<GainOnset, ControlError> {
        self.onset_until(gain, &crate::bearing::NoCancel)
    }

    /// [`Self::onset`], stopping the bisection when `cancel` says so (Ctrl-C): the onset is then the middle
    /// of the bracket reached, and a warning gives the bracket.
    fn onset_until(&mut self, gain: f64, cancel: &dyn Cancel) -> Result<GainOnset, ControlError> {
        let plants = std::mem::take(&mut self.plants);
        let mut stable = Vec::with_capacity(plants.len());
        for (p, done) in plants.iter().zip(&self.done) {
            // the sweep's own poles at gain 0 and at the controller's gain are known
            if gain == 0.0 {
                stable.push(done.open.stable());
            } else if gain == self.control.gain {
                stable.push(done.closed.stable());
            } else {
                stable.push(poles(p, &self.controller, gain)?.stable());
                self.eigen_solutions += 1;
            }
        }
        self.plants = plants;
        let stable_at_first = stable.first().copied().unwrap_or(false);
        if !stable_at_first {
            self.warnings.push(ControlWarning::UnstableFromFirstSpeed { gain });
        }
        let Some(i) = stable.windows(2).position(|w| w[0] && !w[1]) else {
            return Ok(GainOnset { gain, onset_rad_s: None, stable_at_first });
        };
        let speeds = &self.params.speeds_rad_s;
        let (mut lo, mut hi) = (speeds[i], speeds[i + 1]);
        let mut probes = 0;
        while hi - lo > self.params.onset_tol * hi && probes < 60 {
            if cancel.cancelled() {
                self.warnings.push(ControlWarning::OnsetNotRefined {
                    gain,
                    from_rpm: crate::units::RPM.from_si(lo),
                    to_rpm: crate::units::RPM.from_si(hi),
                });
                break;
            }
            let mid = 0.5 * (lo + hi);
            let i = match self.probes.iter().position(|p| p.0 == mid) {
                Some(i) => i,
                None => {
                    let plant = self.plant_at(mid)?;
                    self.probes.push((mid, plant));
                    self.probes.len() - 1
                }
            };
            self.eigen_solutions += 1;
            if poles(&self.probes[i].1, &self.controller, gain)?.stable() {
                lo = mid;
            } else {
                hi = mid;
            }
            probes += 1;
        }
        Ok(GainOnset { gain, onset_rad_s: Some(0.5 * (lo + hi)), stable_at_first })
    }

    /// Finishes: onsets open, closed and over the gain sweep.
    ///
    /// # Errors
    /// As [`Self::onset`].
    pub fn finish(self) -> Result<ControlResult, ControlError> {
        self.finish_until(&crate::bearing::NoCancel)
    }

    /// [`Self::finish`], with onset bisections that stop when `cancel` says so (Ctrl-C on the command line):
    /// each onset not yet refined is then the middle of its bracket, named by a
    /// [`ControlWarning::OnsetNotRefined`]; the speeds solved are all kept.
    ///
    /// # Errors
    /// As [`Self::onset`].
    pub fn finish_until(mut self, cancel: &dyn Cancel) -> Result<ControlResult, ControlError> {
        let onset_open = self.onset_until(0.0, cancel)?;
        let onset_closed = self.onset_until(self.control.gain, cancel)?;
        let gains = self.params.gains.clone();
        let gain_sweep = gains.iter().map(|&g| self.onset_until(g, cancel)).collect::<Result<Vec<_>, _>>()?;
        let root_locus = match self.params.root_locus_rad_s {
            Some(w) => {
                let locus_gains = if gains.is_empty() {
                    let top = if self.control.gain == 0.0 { 2.0 } else { 2.0 * self.control.gain };
                    (0..=20).map(|i| top * f64::from(i) / 20.0).collect()
                } else {
                    gains
                };
                let plant = self.plant_at(w)?;
                self.eigen_solutions += locus_gains.len();
                Some(root_locus(&plant, &self.controller, w, &locus_gains, LOCUS_MAX_HZ)?)
            }
            None => None,
        };
        let states = self.plants.last().map_or(0, |p| p.ss.states() + self.controller.states());
        self.warnings.dedup();
        Ok(ControlResult {
            title: self.rotor.title.clone(),
            gain: self.control.gain,
            speeds: self.done,
            onset_open,
            onset_closed,
            gain_sweep,
            root_locus,
            lqr: self.lqr,
            limit_v: self.limits,
            response_nodes: self.nodes,
            states,
            bearing_solves: self.bearings.solves,
            eigen_solutions: self.eigen_solutions,
            seconds: self.started.elapsed().as_secs_f64(),
            warnings: self.warnings,
        })
    }
}

fn dof(axis: Axis) -> NodeDof {
    match axis {
        Axis::X => NodeDof::X,
        Axis::Y => NodeDof::Y,
    }
}

/// Full-scale signal of the valve of the case at bearing position `b` [V] (validation checked it has one).
fn valve_full_scale(rotor: &Rotor, b: usize) -> f64 {
    match &rotor.bearings[b].support {
        BearingSupport::Case { case, .. } => case.hydraulics.as_ref().map_or(10.0, |h| h.valve.full_scale_v),
        BearingSupport::Numbers(_) => 10.0,
    }
}

/// Runs the whole analysis.
///
/// # Errors
/// As [`ControlAnalysis::new`], [`ControlAnalysis::step`] and [`ControlAnalysis::finish`].
pub fn run(rotor: &Rotor, control: &Control, params: ControlParams) -> Result<ControlResult, ControlError> {
    let mut a = ControlAnalysis::new(rotor, control, params)?;
    while !a.step()? {}
    a.finish()
}
