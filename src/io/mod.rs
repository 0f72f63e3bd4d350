//! Files shared by the command line, the workbench and the Python package: safe writes ([`safe_write`],
//! native only; the web build downloads instead), VTK XML grids of the film and pad fields for ParaView
//! ([`vtk`]), reduced coefficients for ROSS and as CSV ([`coefficients`]), the rotor analysis as text and CSV
//! ([`rotor_text`]), and input files read under a size cap, rotor files with their bearing cases ([`read`],
//! native only).
//!
//! Everything here turns results into bytes, puts bytes on disk or reads them; nothing here solves or draws.

pub mod coefficients;
#[cfg(not(target_arch = "wasm32"))]
pub mod read;
pub mod rotor_text;
#[cfg(not(target_arch = "wasm32"))]
pub mod safe_write;
pub mod vtk;

#[cfg(not(target_arch = "wasm32"))]
pub use safe_write::{write_file, write_with, SafeFile, WriteError};
