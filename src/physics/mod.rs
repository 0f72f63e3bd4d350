//! One module per equation.
//!
//! - [`orifice`]: the injection capillary (Hagen–Poiseuille profile, the `g(x, z)` weight).
//! - [`reynolds`]: the modified Reynolds equation on one pad, with injection, cavitation (Gümbel or
//!   Reynolds/Swift–Stieber complementarity), flows, friction and analytic perturbations.
//! - [`viscosity`]: the two-point exponential viscosity law.
//! - [`energy`]: the film energy equation (SUPG) with injection terms and film–pad exchange, and its balance.
//! - [`pad_thermal`]: steady 3-D heat conduction in a pad, free convection on its free faces.
//! - [`hydraulics`]: servovalve, injection lines and nozzles of the controllable bearing, linearised.

pub mod energy;
pub mod hydraulics;
pub mod orifice;
pub mod pad_thermal;
pub mod reynolds;
pub mod viscosity;
