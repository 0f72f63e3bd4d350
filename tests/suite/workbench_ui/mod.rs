//! The workbench driven headlessly (egui_kittest), one file per view or concern: every view rendered on a
//! fixed case and compared with the PNGs under `tests/snapshots/` (CPU rendering through wgpu: Mesa lavapipe
//! or llvmpipe), and the editor driven as a user would — change a value, wait for the background solve,
//! check the displayed result; type an invalid value, check the message and that the last result stays.
//!
//! [`harness`] builds and drives the app; [`reading`] reads what a frame shows (tick labels, overlaps).
//! Create or refresh the snapshots with `UPDATE_SNAPSHOTS=1 cargo test --test suite workbench_ui`.
#![cfg(feature = "gui")]

pub(crate) mod harness;
pub(crate) mod reading;

mod bearing;
mod coefficients;
mod control;
mod deformation;
mod editor;
mod fields;
mod files;
mod frf;
mod pins;
mod rotor;
mod scale_locks;
mod sweep;
mod views;
