//! Active vibration control through the controllable bearing (docs/MODEL.md §14): the rotor–bearing system,
//! the actuators (the bearing's valve → lines → nozzles → film chain, or an ideal force), and a controller
//! from the rotor file's `[control]` ([`crate::model::control`]), closed into one linear system per speed.
//!
//! - [`state_space`]: state-space systems, balanced eigenvalues;
//! - [`law`]: the controller as a state-space system;
//! - [`riccati`], [`lqr`]: the LQR designed on a reduced model of the plant, with its observer;
//! - [`plant`]: the plant at one speed (rotor, pads, valve chains, force actuators);
//! - [`closed_loop`]: the loop closed (poles, forced response) and broken at one actuator's input;
//! - [`nyquist`]: the Nyquist criterion and the margins on the broken loop;
//! - [`tuning`]: the loop closed again on plants already built (another gain, the root locus);
//! - [`rig`]: the test rig's closed loop (X/F with control against without);
//! - [`analysis`]: the speed sweep, the onset against the gain, the unbalance response with and without.
//!
//! SI inside; the loop is negative feedback, `u = −g K(s) y`.

pub mod analysis;
#[cfg(test)]
mod closed_form;
pub mod closed_loop;
pub mod error;
pub mod law;
pub mod lqr;
pub mod nyquist;
pub mod plant;
pub mod riccati;
pub mod rig;
pub mod state_space;
pub mod tuning;

pub use error::{ControlError, ControlWarning};
