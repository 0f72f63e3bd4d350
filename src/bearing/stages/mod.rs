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
//! | `Films`          | R, L, C_b; per pad θ_le, β, θ_p, C_p, t, orifices and its coordinates (kind, which pivot stiffnesses and contact are given); element counts, half model; with `physics.pad_modes > 0` the modes' count, E, ν, density, pad layers | — |
//! | `Equilibrium`    | Films' + pivot stiffness values and Hertz pivot contacts, preloads (reported); µ(T), oil ρ (ram pressure, churning, regime warnings); Ω, load, T_film, p_inj, T_inj, supply flows; every `[physics]` value; every tuning key; the feeding's churning factor | Films |
//! | `Thermal`        | Equilibrium's + pad radial elements; oil c_p, k; T_supply; every `[thermal]` value (with pad growth: the pads' E, ν, density and the fidelity) — THD cases only | Films |
//! | `Coefficients`   | Equilibrium's (or Thermal's for THD) + per pad whether massless, else its density (the inertia `M`) | Equilibrium or Thermal |
//! | `Reduction`      | Coefficients' + ω/Ω: the solution the views show                        | Coefficients         |
//! | `FrequencySweep` | Coefficients' + the request's ratios ω/Ω                                 | Coefficients         |
//! | `SpeedSweep`     | Reduction's with Ω left out + the request's speeds                       | (nested stages)      |
//! | `Frf`            | Equilibrium's + the pads' inertia (as `Coefficients`) + the pads each `[hydraulics]` port feeds | Films, Equilibrium |
//!
//! Each row is the stage's view of the case ([`view`]: those fields, every other one blank) in the `Inputs`
//! struct of the stage's file, built by a function that destructures the case and its sub-structs
//! **exhaustively (no `..`)**: adding a field anywhere in the case is a compile error in every builder until
//! someone decides, stage by stage, whether it reads it. A stage's `poll` receives its inputs and the outputs
//! of the last column — never the case or the request — so what a stage reads is what its row says, and the
//! cache, not care, decides what is stale.
//!
//! Read by no stage: the title and the case itself (the registry stamps the request's on a published
//! solution), Young's modulus and Poisson's ratio of rigid pads (`physics.pad_modes = 0`) that do not grow
//! thermally, the fidelity name (its element counts are read; the thermal growth reads its layer step), the
//! oil's name, the node budget `mesh.max_nodes` (checked when the case is validated, before any stage runs),
//! of the `[hydraulics]` section everything but the ports' pads (the valve, lines and rig enter only the FRF
//! view's frequency loop, run on the `Frf` stage's output), and the design limits `[limits]` (checked on the
//! published solution by [`crate::bearing::solution::limits`]). Editing them runs nothing. The pivot
//! stiffnesses and the pad density are not read by the films: the stages that solve install the pads'
//! structure from their own view in the films' model ([`films::install_structure`],
//! [`crate::bearing::BearingModel::set_structure`]) without rebuilding it; the density reaches only
//! `Coefficients`, `Frf` and the stages after them (and the speed sweep, whose points keep reduced
//! coefficients) — and the films of bending pads and the thermal loop of growing ones.
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
mod stamp;
pub mod sweeps;
pub mod thermal;
pub mod view;
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
#[cfg(test)]
mod tests_views;
