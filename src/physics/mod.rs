//! One module per equation.
//!
//! - [`orifice`]: the injection capillary (Hagen–Poiseuille profile, the `g(x, z)` weight).
//! - [`reynolds`]: the modified Reynolds equation on one pad, with injection, cavitation (Gümbel or
//!   Reynolds/Swift–Stieber complementarity), flows, friction and analytic perturbations.
//! - [`viscosity`]: the two-point exponential viscosity law.

pub mod orifice;
pub mod reynolds;
pub mod viscosity;
