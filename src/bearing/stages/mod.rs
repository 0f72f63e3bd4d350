//! # Stages: the one entrance to the solver — cached, steppable computation with typed inputs
//!
//! Every caller (the workbench, the command line, sweeps and batches, the rotor, the bench, the
//! convergence map) asks [`Stages`] for what it needs with a [`Request`]: the case, the stages whose results
//! it wants ([`StageId`]s) and where solves start ([`Start`]). [`Stages::step`] brings every needed stage up
//! to date, one unit of work per call, upstream stages first; [`Stages::run`] runs to the end. Each stage's
//! output is cached under its **inputs**: a value that holds exactly what the output depends on, so an edit
//! that does not enter a stage's inputs never reruns it, and a caller that asks again (a rotor at the same
//! speed, a sweep returning to a value) gets the cached output ([`Stages::keeping`] keeps several).
//!
//! | stage            | reads from the case (and the request)                                    | reads the outputs of |
//! |------------------|--------------------------------------------------------------------------|----------------------|
//! | `Films`          | R, L, C_b; per pad θ_le, β, θ_p, C_p, t, orifices and its coordinates (kind, which pivot stiffnesses are given); element counts, half model; with `physics.pad_modes > 0` the modes' E, ν, density, pad layers | — |
//! | `Equilibrium`    | Films + pivot stiffness values and Hertz pivot contacts, preloads (reported); µ(T), oil ρ (regime warnings); Ω, load, T_film, p_inj, T_inj; cavitation, touchdown film | Films |
//! | `Thermal`        | Equilibrium's inputs + pad radial elements; oil c_p, k; T_supply; every `[thermal]` value (with pad growth: the pads' E, ν) — THD cases only | Films |
//! | `Coefficients`   | Equilibrium (or Thermal for THD) + pad density (the inertia `M`)         | Equilibrium or Thermal |
//! | `Reduction`      | Coefficients + ω/Ω: the solution the views show                          | Coefficients         |
//! | `FrequencySweep` | Coefficients + the request's ratios ω/Ω                                  | Coefficients         |
//! | `SpeedSweep`     | Coefficients' inputs with Ω left out + ω/Ω + the request's speeds        | (nested stages)      |
//! | `Frf`            | Equilibrium + pad density + the pads each `[hydraulics]` port feeds      | Films, Equilibrium   |
//!
//! Each row is the `Inputs` struct of the stage's file, built by a function that destructures the case and
//! its sub-structs **exhaustively (no `..`)**: adding a field anywhere in the case is a compile error in
//! every builder until someone decides, stage by stage, whether it reads it.
//!
//! Read by no stage: the title and the case itself (stamped on the published solution), Young's modulus and
//! Poisson's ratio of rigid pads (`physics.pad_modes = 0`), the fidelity name (its element counts are read),
//! the oil's name, the node budget `mesh.max_nodes` (checked when the case is validated, before any stage
//! runs), and of the `[hydraulics]` section everything but the ports' pads (the valve, lines and rig enter
//! only the FRF view's frequency loop, run on the `Frf` stage's output), and the design limits `[limits]`
//! (checked on the published solution by [`crate::bearing::solution::limits`]).
//! Editing them runs nothing. The pivot stiffnesses and the pad density are not read by the films: the
//! stages that solve install the pads' structure in the films' model ([`films::install_structure`],
//! [`crate::bearing::BearingModel::set_structure`]) without rebuilding it; the density reaches only
//! `Coefficients` and the stages after it (and the speed sweep, whose points keep reduced coefficients).
//!
//! The contract of a stage is in [`stage`]; the list of stages and how to add one in [`registry`]. The
//! native worker loops over [`Stages::step`] on its thread; the web build calls it within a per-frame time
//! budget ([`crate::bearing::Cancel::suspend`] asks long stages to pause). Execution counters
//! ([`Stages::runs`]) let tests assert what ran.

pub mod cache;
pub mod coefficients;
pub mod equilibrium;
pub mod films;
pub mod frequency_sweep;
pub mod frf;
pub mod id;
pub mod outcome;
pub mod reduction;
pub mod registry;
pub mod request;
pub mod speed_sweep;
pub mod stage;
pub mod sweeps;
pub mod thermal;
pub mod wire;

pub use cache::Cached;
pub use equilibrium::MAX_SUSPENSIONS;
pub use id::StageId;
pub use outcome::{Outcome, Published, Step};
pub use registry::{solve_case, Stages};
pub use request::{Request, Start};
pub use stage::{Ctx, Poll, Registered, Solver, Stage};
pub use sweeps::{FrequencySweep, SpeedPoint, SweepValues};
pub use wire::{from_bytes, to_bytes, OutputData, UnnamedOutput, WireError};

#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_hertz;
