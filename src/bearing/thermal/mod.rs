//! Thermohydrodynamic (THD) equilibrium: the static equilibrium and the thermal fields, iterated until the
//! viscosity field converges (docs/MODEL.md §6). This file holds the thermal model and its data (per-pad systems,
//! parameters, report); the outer loop is [`run`] ([`ThdRun`]).
//!
//! ## Loop
//! ```text
//! µ⁰ = µ(T_film of the case)                              (the isothermal equilibrium is iteration 0)
//! repeat k = 1, 2, …
//!   equilibrium with the nodal viscosity µᵏ⁻¹, warm-started from the previous journal/pad position
//!   per pad: film energy (+ pad conduction for BC2/BC3), one factorisation, three right-hand sides
//!            → film (and pad) temperatures affine in (T_in, T_j)           (thermal_pad.rs)
//!   all pads at once: groove mixing balance for every T_in and the journal condition for T_j
//!            (a dense (n_pads + 1) system: the pads' coupling through the grooves is solved exactly)
//!   T ← T_old + ω (T_new − T_old), Anderson-accelerated;  µᵏ = µ(T) at the film nodes
//! until max_nodes |µ(T_new) − µᵏ⁻¹| / µᵏ⁻¹ < tol
//! then (BC1) solve the pad conduction with the film temperature on its face; assemble the solution, whose
//! dynamic coefficients are the film's perturbation at the converged state (temperatures frozen).
//! ```
//!
//! ## Lightly loaded pads
//! The loop freezes the viscosity field at the film nodes while the equilibrium moves the pads. A lightly
//! loaded pad (offset pivot, thick diverging film) can have a moment curve whose maximum barely reaches zero;
//! the axial and circumferential viscosity variation can then remove its root altogether, and the pad force
//! jumps between a loaded and an unloaded branch, so no equilibrium exists for the frozen field. When that
//! happens, pads carrying less than [`LIGHT_PAD_SHARE`] of the load are given their mean film viscosity
//! (a uniform viscosity scales the pad's pressure and leaves its tilt root where the isothermal one is); the
//! report says which. Otherwise the temperature step is halved back towards the last field that worked.
//!
//! Inlet mixing and the journal temperature: [`crate::bearing::thermal::mixing`]; the acceleration: [`crate::bearing::thermal::anderson`].

pub mod anderson;
pub mod growth;
pub mod growth_solid;
mod iteration;
pub mod mixing;
pub mod model;
pub mod pad_system;
pub mod resumable;
mod run;

pub use model::{PadThermalState, ThdState, ThermalModel, ThermalParams, ThermalReport};
pub use run::{solve_thd, ThdRun};
