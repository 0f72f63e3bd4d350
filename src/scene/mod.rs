//! Results → plain drawables. The workbench's views draw what this module computes; nothing here knows
//! about egui, so every picture can be built and tested without a GPU (`cargo test --lib
//! --no-default-features` runs these tests).
//!
//! - [`compare`]: pinned solutions and their differences from the live one.
//! - [`colormap`]: perceptually uniform colour maps (viridis, inferno) as small tables.
//! - [`deformation`]: a flexible pad's deformed cross-section, displacement and film maps, mode gallery.
//! - [`field`]: a pad's scalar fields unwrapped onto (s, z), mirrored for half models, sampled and rasterised.
//! - [`field_compare`]: live against pinned pad fields (shared colour range, difference maps) and locked colour scales.
//! - [`flowlines`]: streamlines of the film's mean velocity (Couette + Poiseuille, orifices as sources or sinks).
//! - [`frf`]: Bode curves of the controllable bearing (G1, G2, G3, G, the rig's shaker chain), CSV.
//! - [`limits`]: design-limit checks as text.
//! - [`outline`]: the bearing cross-section to scale with an exaggerated clearance.
//! - [`plots`]: reduced coefficients against frequency ratio or speed, the full-matrix table.
//! - [`rotor`]: Campbell diagram, stability map, mode shapes, unbalance Bode (nodes named, the API 617 check in
//!   words) and the sketch of a rotor analysis.
//! - [`request`]: the stages the open views need, joined into the request the app sends.
//! - [`sommerfeld`]: the Sommerfeld chart of a load sweep (ε, attitude, h_min/Cb, reduced K and C against S)
//!   with the short-bearing reference of a plain 360° bearing.
//! - [`summary`]: the results panel's rows in display units (the table of outputs, section by section).
//! - [`summary_text`]: the same rows as the text `tiltpad solve` prints, with the pad table and the reports.
//! - [`sweep`]: any case key against any output columns (series, CSV) for the sweep view.
//! - [`export`]: CSV of the nodal fields, JSON of the results.
//! - [`fidelity`]: the measured time and error of each fidelity level (from the bench, `cargo xtask bench`).
//!
//! Positions are SI (metres, radians) in the solver's bearing frame or a pad's (s, z) frame; a view maps
//! them to the screen. Display units appear only in values meant to be read (legends, rows, plot series),
//! and their names say so.

pub mod colormap;
pub mod compare;
pub mod deformation;
pub mod export;
pub mod fidelity;
pub mod field;
pub mod field_compare;
pub mod flowlines;
pub mod frf;
pub mod limits;
pub mod outline;
pub mod plots;
pub mod request;
pub mod rotor;
pub mod sommerfeld;
pub mod summary;
pub mod summary_text;
pub mod sweep;
