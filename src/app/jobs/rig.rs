//! The test rig's job (the Control view's rig page): the shipped rig (`cases/test-rig-pub5.toml`) linearised
//! for its injection port (the FRF stage: one bearing solve), then its loop closed by the shipped controller
//! (`cases/controllers/test-rig-pub5-control.toml`) over the band [`BAND_HZ`].

use serde::{Deserialize, Serialize};

use super::job::{Job, JobError, Progress, Step};
use crate::bearing::frf::model::{band, FrfModel};
use crate::bearing::{Cancel, NoSuspend, SolveError, Stages};
use crate::control::rig::{RigLoop, RigSweep};
use crate::model::control::{parse_control_file, PlantInfo};
use crate::model::{load_case, Case};

pub const CASE_NAME: &str = "test-rig-pub5.toml";
const CASE_TEXT: &str = include_str!("../../../cases/test-rig-pub5.toml");
pub const CONTROLLER_NAME: &str = "controllers/test-rig-pub5-control.toml";
const CONTROLLER_TEXT: &str = include_str!("../../../cases/controllers/test-rig-pub5-control.toml");
/// The band [Hz] and its points (1 Hz apart), as in the controller file's header.
pub const BAND_HZ: [f64; 2] = [10.0, 200.0];
pub const BAND_POINTS: usize = 191;

/// The rig's loop as computed for the page.
#[derive(Serialize, Deserialize)]
pub struct RigShown {
    pub title: String,
    pub sweep: RigSweep,
}

/// The job: the FRF stage, then the loop over the band.
#[derive(Serialize, Deserialize)]
pub struct RigJob {
    case: Option<Case>,
    #[serde(skip)]
    frf: Option<std::sync::Arc<FrfModel>>,
}

impl RigJob {
    /// The shipped rig and controller.
    ///
    /// # Errors
    /// The shipped case does not parse (a broken build).
    pub fn shipped() -> Result<Self, String> {
        let case = load_case(CASE_TEXT, &[]).map_err(|e| format!("{CASE_NAME}: {e}"))?.1;
        Ok(Self { case: Some(case), frf: None })
    }
}

impl Job for RigJob {
    const NAME: &'static str = "rig";
    type Output = RigShown;
    type Keep = ();

    fn step(&mut self, (): &mut (), cancel: &dyn Cancel) -> Result<Step<RigShown>, JobError> {
        let case = self.case.as_ref().ok_or_else(|| JobError::Failed("the rig job already finished".into()))?;
        let Some(frf) = &self.frf else {
            let frf = Stages::new().frf(case, &NoSuspend(cancel)).map_err(|e| match e {
                SolveError::Cancelled => JobError::Cancelled,
                e => JobError::Failed(format!("{CASE_NAME}: {e}")),
            })?;
            self.frf = Some(frf);
            return Ok(Step::More { progress: Progress::new(1.0, 2.0, "closing the loop"), output: None });
        };
        let file =
            parse_control_file(CONTROLLER_TEXT).map_err(|e| JobError::Failed(format!("{CONTROLLER_NAME}: {e}")))?;
        let control = file
            .control
            .resolve(&PlantInfo::rig(case))
            .map_err(|e| JobError::Failed(format!("{CONTROLLER_NAME}: {e}")))?;
        let sweep = RigLoop::new(case, frf, &control)
            .and_then(|l| l.sweep(&band(BAND_HZ[0], BAND_HZ[1], BAND_POINTS)))
            .map_err(|e| JobError::Failed(format!("closing the rig's loop: {e}")))?;
        let title = format!("{} — {CASE_NAME} closed by {CONTROLLER_NAME}", case.title);
        self.case = None;
        Ok(Step::Done(RigShown { title, sweep }))
    }
}
