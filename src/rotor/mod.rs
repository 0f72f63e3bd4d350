//! The rotor–bearing system (docs/MODEL.md §10): a finite-element shaft with rigid disks on bearings.
//!
//! ```text
//! M ü + (C + Ω G) u̇ + K u = f(t),   u = [x, y, a, b per shaft node…, appended pad coordinates…]
//! ```
//! - [`element`]: the Timoshenko (or Euler–Bernoulli) beam element with gyroscopic coupling;
//! - [`assembly`]: the shaft, disks, supports and proportional damping ([`assembly::ShaftModel`], once per rotor);
//! - [`reduction`]: the shaft reduced to its attached nodes and a few fixed-interface modes (Craig–Bampton);
//! - [`coupling`]: bearings at their nodes, full (pad coordinates appended) or synchronously reduced;
//! - [`eigen`]: damped modes (frequencies, logarithmic decrements, whirl, mode shapes);
//! - [`critical_map`]: undamped critical speeds against a swept support stiffness, bearings' stiffness over it.
//!
//! Units SI; Ω the spin speed [rad/s], counter-clockwise about +z as the bearing's journal turns. The
//! rotor's description (sections, disks, bearings…) is [`crate::model::rotor`].

pub mod analysis;
pub mod assembly;
pub mod bearings;
pub mod campbell;
#[cfg(test)]
mod closed_form;
pub mod coupling;
pub mod critical_map;
pub mod eigen;
pub mod element;
pub mod error;
#[cfg(test)]
mod full_vs_reduced;
pub mod reduction;
pub mod stability;
pub mod unbalance;
pub mod wire;

pub use error::RotorError;
