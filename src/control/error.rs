//! Errors and warnings of the closed-loop analysis.

use serde::{Deserialize, Serialize};
use thiserror::Error;

use crate::model::CaseError;
use crate::rotor::RotorError;

/// Why a closed-loop analysis failed.
#[derive(Debug, Error)]
pub enum ControlError {
    #[error(transparent)]
    Input(#[from] CaseError),
    #[error(transparent)]
    Rotor(#[from] RotorError),
    /// A valve acts on the pads too: its bearing must enter with its full coefficients.
    #[error(
        "`rotor.coefficients` = \"reduced\": a valve actuator (rotor.bearing[{bearing}]) acts on the pads; allowed: \
         \"full\""
    )]
    ValveNeedsFullCoefficients { bearing: usize },
    /// The rotor file has no `[control]`.
    #[error("the rotor file has no [control] section: nothing closes the loop")]
    NoController,
    /// The dense eigen-solver did not converge.
    #[error("eigen-solution failed ({size}×{size} closed-loop state matrix)")]
    Eigen { size: usize },
    /// The closed loop is singular at the forcing frequency.
    #[error("the closed loop is singular at {speed_rpm:.1} rpm")]
    Singular { speed_rpm: f64 },
    /// A rig controller that is not one loop from the journal's vertical motion to the bearing's valve.
    #[error("the rig's closed loop needs {what}")]
    NotARigLoop { what: &'static str },
    /// The LQR cannot be designed on the reduced model at the design speed.
    #[error("control.lqr: the plant at {speed_rpm:.0} rpm (control.lqr.design_speed_rpm): {reason}")]
    Lqr { speed_rpm: f64, reason: LqrFailure },
    /// A gain list that cannot be swept.
    #[error("--gain-sweep: gains must be finite (got {gain})")]
    Gain { gain: f64 },
}

/// Why an LQR design failed.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum LqrFailure {
    #[error(
        "no mode of the plant lies below control.lqr.max_frequency_hz = {max_frequency_hz} Hz; allowed: a value above \
         the rotor's first mode"
    )]
    NoModes { max_frequency_hz: f64 },
    #[error(
        "its unstable mode at {frequency_hz:.1} Hz is not moved by any actuator (the pair is not stabilisable): \
         choose another control.lqr.design_speed_rpm or other actuators"
    )]
    NotStabilisable { frequency_hz: f64 },
    #[error(
        "its unstable mode at {frequency_hz:.1} Hz is not seen by any sensor (not detectable): add a sensor that \
         reads it"
    )]
    NotDetectable { frequency_hz: f64 },
    #[error("the Riccati equation has no stabilising solution ({message}); check control.lqr.output_weight")]
    Riccati { message: String },
}

/// What a closed-loop analysis warns about.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum ControlWarning {
    /// The unbalance response asks an actuator for more than its linear range.
    Saturation { actuator: usize, speed_rpm: f64, amplitude_v: f64, limit_v: f64 },
    /// The closed loop is unstable at the first speed of the sweep.
    UnstableFromFirstSpeed { gain: f64 },
    /// The Nyquist count and the eigenvalues disagree at a speed (a loop too close to the critical point to
    /// decide, or a numerical failure): the eigenvalues are reported.
    NyquistDisagrees { speed_rpm: f64 },
    /// The onset bisection was stopped (Ctrl-C) with the onset between these speeds; the onset given is
    /// the middle of that bracket.
    OnsetNotRefined { gain: f64, from_rpm: f64, to_rpm: f64 },
}

impl std::fmt::Display for ControlWarning {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Saturation { actuator, speed_rpm, amplitude_v, limit_v } => write!(
                f,
                "actuator {actuator} saturates at {speed_rpm:.0} rpm: the unbalance response needs {amplitude_v:.3} V, \
                 its linear range is {limit_v:.3} V"
            ),
            Self::UnstableFromFirstSpeed { gain } => {
                write!(f, "gain {gain}: unstable from the first speed of the sweep: the onset lies below it")
            }
            Self::NyquistDisagrees { speed_rpm } => {
                write!(f, "at {speed_rpm:.0} rpm the Nyquist count and the eigenvalues disagree")
            }
            Self::OnsetNotRefined { gain, from_rpm, to_rpm } => write!(
                f,
                "gain {gain}: onset not refined (interrupted): between {from_rpm:.0} and {to_rpm:.0} rpm, \
                 reported as the middle"
            ),
        }
    }
}
