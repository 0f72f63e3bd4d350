//! The speed sweep: one solution per speed of the request (everything else as in the case), one point per
//! poll, each warm-started from the previous one. An isothermal point may itself be suspended between
//! frames and resumed from its iterate (at most [`MAX_SUSPENSIONS`] times); a THD point runs to the end.

use std::sync::Arc;

use serde::{Deserialize, Serialize};

use crate::bearing::solution::coefficients::ReducedCoefficients;
use crate::bearing::equilibrium::EquilibriumParams;
use crate::bearing::report::error::SolveError;
use crate::bearing::solution::assemble::{solve_point, step_operating_point};
use crate::bearing::film::model::{BearingModel, OperatingPoint};
use crate::bearing::report::progress::{Cancel, NoSuspend};
use crate::bearing::solution::Solution;
use crate::bearing::thermal::ThermalModel;
use crate::model::{Case, ThermalModelKind};

use crate::bearing::stages::coefficients::CoefficientsInputs;
use crate::bearing::stages::equilibrium::MAX_SUSPENSIONS;
use crate::bearing::stages::films::{install_structure, FilmsStage};
use crate::bearing::stages::{Cached, Ctx, Poll, Progress, Published, Request, Stage, StageId};

/// One point of a speed sweep.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SpeedPoint {
    pub speed_rpm: f64,
    /// `Err` text when this point failed (touchdown, …).
    pub result: Result<SweepValues, String>,
}

/// The scalar results a sweep keeps per point.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
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

/// The inputs of the speed sweep: what the coefficients read with the case's speed left out, the
/// excitation ratio, and the request's speeds.
#[derive(Debug, Clone, PartialEq)]
pub struct SpeedSweepInputs {
    pub coefficients: CoefficientsInputs,
    pub excitation_ratio: f64,
    pub speeds_rpm: Vec<f64>,
}

impl SpeedSweepInputs {
    fn of(req: &Request) -> Self {
        let mut c = req.case.clone();
        c.operating.speed_rad_s = 0.0;
        Self { coefficients: CoefficientsInputs::of(&c), excitation_ratio: c.operating.excitation_ratio, speeds_rpm: req.speeds_rpm.clone() }
    }
}

/// A sweep under way.
struct SweepRun {
    points: Vec<SpeedPoint>,
    start: Option<Vec<f64>>,
    model: BearingModel,
    thermal: Option<ThermalModel>,
    /// Suspensions of the current point, and the pads its cold start had placed.
    suspensions: usize,
    placed_pads: usize,
}

#[derive(Default)]
pub struct SpeedSweepStage {
    run: Cached<SpeedSweepInputs, SweepRun>,
}

impl SpeedSweepStage {
    /// Solves (or advances) point `i`: `None` while it is suspended.
    fn point(st: &mut SweepRun, case: &Case, rpm: f64, cancel: &dyn Cancel) -> Result<Option<SpeedPoint>, SolveError> {
        let mut c = case.clone();
        c.operating.speed_rad_s = rpm * std::f64::consts::TAU / 60.0;
        let may_suspend = c.thermal.model == ThermalModelKind::Isothermal && st.suspensions < MAX_SUSPENSIONS;
        let no_suspend = NoSuspend(cancel);
        let solved = if may_suspend {
            let params = EquilibriumParams { placed_pads: st.placed_pads, ..EquilibriumParams::default() };
            step_operating_point(&mut st.model, &c, &OperatingPoint::isothermal(&c), st.start.as_deref(), params, cancel)
        } else {
            solve_point(&mut st.model, &mut st.thermal, &c, st.start.as_deref(), &no_suspend).map(Progress::Done)
        };
        let result = match solved {
            Ok(Progress::Suspended(r)) => {
                st.start = Some(r.coordinates);
                st.placed_pads = r.placed_pads;
                st.suspensions += 1;
                return Ok(None);
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
        Ok(Some(SpeedPoint { speed_rpm: rpm, result }))
    }
}

impl Stage for SpeedSweepStage {
    const LABEL: &'static str = "speed sweep";
    const NEEDS: &'static [StageId] = &[StageId::Films];
    type Inputs = SpeedSweepInputs;
    type Output = Arc<Vec<SpeedPoint>>;

    fn inputs(req: &Request) -> Option<SpeedSweepInputs> {
        Some(SpeedSweepInputs::of(req))
    }

    fn poll(&mut self, inputs: &SpeedSweepInputs, ctx: &mut Ctx<'_>, cancel: &dyn Cancel) -> Result<Poll<Arc<Vec<SpeedPoint>>>, SolveError> {
        let case = ctx.case().clone();
        let mut st = match self.run.take(inputs) {
            Some(st) => st,
            None => {
                let mut model = ctx.output::<FilmsStage>()?.clone();
                install_structure(&mut model, &case)?;
                SweepRun { points: Vec::new(), start: None, model, thermal: None, suspensions: 0, placed_pads: 0 }
            }
        };
        let n = inputs.speeds_rpm.len();
        if let Some(&rpm) = inputs.speeds_rpm.get(st.points.len()) {
            if let Some(p) = Self::point(&mut st, &case, rpm, cancel)? {
                st.points.push(p);
            }
        }
        if st.points.len() == n {
            return Ok(Progress::Done(Arc::new(st.points)));
        }
        #[allow(clippy::cast_precision_loss)]
        let fraction = st.points.len() as f64 / n as f64;
        self.run.put(inputs.clone(), st);
        Ok(Progress::Suspended(fraction))
    }

    fn publish(&mut self, output: &Arc<Vec<SpeedPoint>>, _req: &Request) -> Option<Published> {
        Some(output.clone())
    }
}
