//! File output shared by the command line and the workbench: safe writes ([`safe_write`], native only;
//! the web build downloads instead), VTK XML grids of the film and pad fields for ParaView ([`vtk`]), and
//! reduced coefficients for ROSS and as CSV ([`coefficients`]).
//!
//! Everything here turns results into bytes or puts bytes on disk; nothing here solves or draws.

pub mod coefficients;
#[cfg(not(target_arch = "wasm32"))]
pub mod safe_write;
pub mod vtk;

#[cfg(not(target_arch = "wasm32"))]
pub use safe_write::{write_file, write_with, SafeFile, WriteError};
