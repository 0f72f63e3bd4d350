//! Hydraulics of the controllable bearing (docs/MODEL.md §8): the servovalve, the injection lines and the
//! nozzles that couple them to the film, linearised about the static state and evaluated at a complex
//! frequency `s` (the frequency responses use `s = i 2π f`).
//!
//! - [`servovalve`]: the spool's second-order response to the control signal and the port flow law.
//! - [`pipeline`]: one injection line, as the thesis' truncated modal model and as the exact distributed
//!   (transmission-line) solution of the same equations, both as a two-port; the effective bulk modulus
//!   with entrained air and wall compliance.
//! - [`nozzle`]: the line's far end: the nozzle flow into the film, linear in the line-end pressure and in
//!   the bearing's coordinates and velocities (the film's influence fields).
//!
//! Sign conventions: flows are positive towards the bearing; pressures are gauge [Pa]; a port's sign
//! `σ = +1` (valve port A) or `−1` (port B) says which way the spool drives it.

pub mod nozzle;
pub mod pipeline;
pub mod servovalve;

pub use nozzle::NozzleCoupling;
pub use pipeline::{effective_bulk_modulus, Line, TwoPort};
pub use servovalve::Servovalve;
