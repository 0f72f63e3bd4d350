//! The Control view's two jobs, and what they hand the view:
//!
//! - [`Build`]: the bearings solved and the plants built at each of the sweep's [`SPEEDS`] speeds
//!   ([`ControlAnalysis`], one speed a step), with the loop-open results ([`Built`]);
//! - [`Tune`]: on those plants, the loop closed at the sliders' [`Tuning`] — per speed an eigen-solution and a
//!   complex solve, no bearing solve — with the root locus over [`GAIN_RANGE`] at one speed and the gain and
//!   phase margins at each valve's input (Nyquist, the loop broken there) ([`Tuned`]).

use std::sync::Arc;

use serde::{Deserialize, Serialize};

use super::job::{Job, JobError, Progress, Step};
use crate::bearing::Cancel;
use crate::control::analysis::{ControlAnalysis, ControlParams};
use crate::control::closed_loop::broken;
use crate::control::law::realise;
use crate::control::nyquist::nyquist;
use crate::control::tuning::{onset_on_grid, root_locus, PlantSweep, RootLocus, TunedSpeed};
use crate::model::control::Control;
use crate::model::rotor::Rotor;

/// Speeds of the sweep.
pub const SPEEDS: usize = 25;
/// The loop gain's slider range and the root locus' gains over it.
pub const GAIN_RANGE: [f64; 2] = [-2.0, 4.0];
const LOCUS_GAINS: usize = 25;
/// The root locus shows poles up to this frequency [Hz].
pub const LOCUS_MAX_HZ: f64 = 150.0;

/// The sliders: what the loop is closed at.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Tuning {
    pub gain: f64,
    /// The PD gains of every loop (`None`: the controller is not PD loops; the file's law is kept).
    pub kp_v_per_um: Option<f64>,
    pub kd_v_per_mm_s: Option<f64>,
    /// Speed of the root locus and the margins (index in the sweep).
    pub locus_at: usize,
}

/// The sweep's plants and the loop-open results.
#[derive(Serialize, Deserialize)]
pub struct Built {
    pub sweep: PlantSweep,
    /// Loop open: per speed, the smallest log decrement and the unbalance orbits.
    pub open_log_dec: Vec<f64>,
    pub open_orbits: Vec<Vec<crate::rotor::unbalance::Orbit>>,
    pub api617_um: Vec<f64>,
    /// The analysis' controller (the file's; an LQR as designed).
    pub controller: crate::control::state_space::StateSpace,
    /// What the LQR design produced (`None` for another law).
    pub lqr: Option<crate::control::lqr::LqrDesign>,
}

/// The loop closed at one [`Tuning`].
#[derive(Serialize, Deserialize)]
pub struct Tuned {
    pub tuning: Tuning,
    pub speeds: Vec<TunedSpeed>,
    pub onset_rad_s: Option<f64>,
    pub locus: RootLocus,
    /// Per actuator at the locus speed, the loop broken at its input: gain margin [dB], phase margin [deg]
    /// and the broken loop's unstable poles (the Nyquist plot must then encircle −1 that often).
    pub margins: Vec<(Option<f64>, Option<f64>, usize)>,
}

/// The first job: the bearings solved and the plants built at every speed.
#[derive(Serialize, Deserialize)]
pub struct Build {
    pub rotor: Rotor,
    pub control: Control,
    pub params: ControlParams,
    #[serde(skip)]
    analysis: Option<ControlAnalysis>,
}

impl Build {
    #[must_use]
    pub fn new(rotor: Rotor, control: Control, params: ControlParams) -> Self {
        Self { rotor, control, params, analysis: None }
    }
}

impl Job for Build {
    const NAME: &'static str = "control-build";
    type Output = Arc<Built>;
    type Keep = ();

    fn step(&mut self, (): &mut (), cancel: &dyn Cancel) -> Result<Step<Arc<Built>>, JobError> {
        if cancel.cancelled() {
            return Err(JobError::Cancelled);
        }
        if self.analysis.is_none() {
            let a = ControlAnalysis::new(&self.rotor, &self.control, self.params.clone()).map_err(JobError::failed)?;
            self.analysis = Some(a);
        }
        let Some(analysis) = self.analysis.as_mut() else { return Err(JobError::Failed("no analysis".into())) };
        if !analysis.step().map_err(JobError::failed)? {
            let done = analysis.done().len();
            #[allow(clippy::cast_precision_loss)]
            let progress = Progress::new(done as f64, SPEEDS as f64, format!("speed {done} of {SPEEDS}"));
            return Ok(Step::More { progress, output: None });
        }
        let done = analysis.done();
        Ok(Step::Done(Arc::new(Built {
            sweep: analysis.sweep(),
            open_log_dec: done.iter().map(|s| s.open.min_log_dec()).collect(),
            open_orbits: done.iter().map(|s| s.response.as_ref().map(|r| r.open.clone()).unwrap_or_default()).collect(),
            api617_um: done.iter().map(|s| s.api617_limit_um).collect(),
            controller: analysis.controller().clone(),
            lqr: analysis.lqr().cloned(),
        })))
    }
}

/// The second job: the loop closed at a tuning on the built plants.
#[derive(Serialize, Deserialize)]
pub struct Tune {
    pub built: Arc<Built>,
    pub control: Control,
    pub tuning: Tuning,
    speeds: Vec<TunedSpeed>,
}

impl Tune {
    #[must_use]
    pub fn new(built: Arc<Built>, control: Control, tuning: Tuning) -> Self {
        Self { built, control, tuning, speeds: Vec::new() }
    }
}

impl Job for Tune {
    const NAME: &'static str = "control-tune";
    type Output = Arc<Tuned>;
    type Keep = ();

    fn step(&mut self, (): &mut (), cancel: &dyn Cancel) -> Result<Step<Arc<Tuned>>, JobError> {
        if cancel.cancelled() {
            return Err(JobError::Cancelled);
        }
        // the sliders' PD gains, or the designed LQR (its loop gain still slides)
        let controller = realise(&self.control).unwrap_or_else(|| self.built.controller.clone());
        let sweep = &self.built.sweep;
        let gain = self.tuning.gain;
        if self.speeds.len() < sweep.len() {
            self.speeds.push(sweep.at(self.speeds.len(), &controller, gain).map_err(JobError::failed)?);
            #[allow(clippy::cast_precision_loss)]
            let progress = Progress::new(self.speeds.len() as f64, (sweep.len() + 1) as f64, "closing the loop");
            return Ok(Step::More { progress, output: None });
        }
        let at = self.tuning.locus_at.min(sweep.len().saturating_sub(1));
        let gains = locus_gains();
        let locus = root_locus(&sweep.plants[at], &controller, sweep.speeds_rad_s[at], &gains, LOCUS_MAX_HZ)
            .map_err(JobError::failed)?;
        let mut margins = Vec::new();
        for a in 0..sweep.limits_v.len() {
            let n = nyquist(&broken(&sweep.plants[at], &controller, gain, a)).map_err(JobError::failed)?;
            margins.push((n.gain_margin.map(|g| 20.0 * g.log10()), n.phase_margin_deg, n.open_unstable));
        }
        let log_dec: Vec<f64> = self.speeds.iter().map(|s| s.poles.min_log_dec()).collect();
        Ok(Step::Done(Arc::new(Tuned {
            tuning: self.tuning,
            onset_rad_s: onset_on_grid(&sweep.speeds_rad_s, &log_dec),
            speeds: std::mem::take(&mut self.speeds),
            locus,
            margins,
        })))
    }
}

fn locus_gains() -> Vec<f64> {
    #[allow(clippy::cast_precision_loss)]
    (0..LOCUS_GAINS)
        .map(|i| GAIN_RANGE[0] + (GAIN_RANGE[1] - GAIN_RANGE[0]) * i as f64 / (LOCUS_GAINS - 1) as f64)
        .collect()
}
