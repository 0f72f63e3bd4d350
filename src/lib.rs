//! # tiltpad — a workbench for tilting-pad journal bearings with controllable lubrication
//!
//! ## Conventions (used everywhere in the solver)
//! - **SI inside**: m, s, Pa, N, rad, W; temperatures in °C. Engineering units appear only at the edges
//!   (case files, CLI, GUI) and then in the name (`speed_rpm`, `clearance_um`).
//! - **Frame**: x horizontal, y vertical up; angles θ measured from +x counter-clockwise. The journal rotates
//!   counter-clockwise, so its surface moves towards +θ; a pad's leading edge is at its smallest θ.
//! - **Journal position** (e_x, e_y) is the displacement of the journal centre from the bearing centre.
//! - **Film thickness** of pad k (see [`bearing::geometry`] for the derivation and sign conventions):
//!   `h = Cp − (Cp − Cb) cos(θ − θp) − e_x cos θ − e_y sin θ − (Rp + t) δ sin(θ − θp) + ξ cos(θ − θp)`,
//!   δ the pad tilt (positive moves the trailing edge towards the journal), ξ the pivot's radial
//!   displacement (positive away from the journal).
//! - **Loads**: the static load W acts on the journal; the film force balances it: `F_film + W = 0`.
//!
//! ## Module map
//! - [`model`]: case files, validation, SI case.
//! - [`mesh`], [`fem`]: pad grids and the pad solids extruded from them, shape functions and quadrature
//!   (rectangles, isoparametric quadrilaterals, cylindrical hexahedra), sparse assembly, Cholesky and LU
//!   factorisation, the SUPG advection–diffusion kernel.
//! - [`physics`]: one module per equation (Reynolds with injection and cavitation, viscosity, orifice flow,
//!   film energy, pad heat conduction, pad elasticity and the pad's bending modes).
//! - [`bearing`]: geometry of the film, equilibrium (Newton), the thermal (THD) loop with the pads' and the
//!   journal's thermal growth (TEHD), flexible pads (modes as coordinates), dynamic coefficients,
//!   the solve job, and the cached, steppable stages (typed inputs, execution counters) the app asks through.
//! - [`scene`]: results → plain drawables for the workbench (colour fields, flowlines, the bearing outline,
//!   plot series, result rows, exports, the pad deformation) and the request the open views need; no GUI types, built and tested
//!   without the `gui` feature.
//! - [`study`]: sweeps over any case keys (grids) and design-space batches, one result row per point,
//!   failed points kept as rows with their error; no I/O.
//! - [`io`]: safe (atomic) writes, VTK `.vtu`/`.pvd` exports of the film and pad fields, reduced
//!   coefficients for ROSS and as CSV.
//! - [`app`] (feature `gui`): the eframe/egui workbench — editor, views, the background solve worker.
//! - [`number`]: numbers as text at the edges (significant digits, CSV cells, tick labels).
//! - [`units`]: the engineering units of the edges (rpm, bar, µm, L/min …), each conversion factor defined once.
//! - [`cli`]: the command line (`tiltpad solve`, `sweep`, `batch`, `coefficients`, `modes`, `frf`, `rotor`, `fidelity`, `schema`, …).
//!   The developers' bench that writes docs/PERFORMANCE.md is not here: it is `cargo xtask bench` (xtask/).

// Lints: `[lints]` in Cargo.toml. Library paths that user input reaches never unwrap or expect (test
// builds may; `[lints]` cannot tell test targets apart, so this one stays here).
#![cfg_attr(not(test), warn(clippy::unwrap_used, clippy::expect_used))]

#[cfg(feature = "gui")]
pub mod app;
pub mod bearing;
#[cfg(not(target_arch = "wasm32"))]
pub mod cli;
pub mod control;
pub mod fem;
pub mod io;
pub mod mesh;
pub mod model;
pub mod number;
pub mod physics;
pub mod rotor;
pub mod scene;
pub mod study;
pub mod units;
