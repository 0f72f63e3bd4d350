//! One module per equation.
//!
//! - [`orifice`]: the injection capillary (Hagen–Poiseuille profile, the `g(x, z)` weight).
//! - [`reynolds`]: the modified Reynolds equation on one pad, with injection, cavitation (Gümbel or
//!   Reynolds/Swift–Stieber complementarity), flows, friction and analytic perturbations.
//! - [`turbulence`]: Ng–Pan turbulent coefficients of the Reynolds and energy equations, with the
//!   laminar–turbulent transition band.
//! - [`viscosity`]: the two-point exponential viscosity law.
//! - [`energy`]: the film energy equation (SUPG) with injection terms and film–pad exchange, and its balance.
//! - [`pad_elastic`]: linear elasticity of a pad solid (incompatible-mode hexahedra, pivot support, static
//!   solutions and modes).
//! - [`pad_modes`]: the pad's bending modes on its pivot as pseudo-modal coordinates (film shapes, modal
//!   mass and stiffness).
//! - [`pad_conduction`]: steady 3-D heat conduction in a pad, free convection on its free faces.
//! - [`hertz`]: Hertz contact of a pivot (rocker, ball in socket): approach and stiffness, nonlinear in load.
//! - [`hydraulics`]: servovalve, injection lines and nozzles of the controllable bearing, linearised.

pub mod churning;
pub mod energy;
pub mod hertz;
pub mod hydraulics;
pub mod orifice;
pub mod pad_conduction;
pub mod pad_elastic;
pub mod pad_modes;
pub mod reynolds;
pub mod turbulence;
pub mod viscosity;
