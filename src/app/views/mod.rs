//! The views of the central area and the results panel. Each reads drawables from [`crate::scene`];
//! none computes physics.

pub mod bearing_view;
pub mod coefficients_view;
pub mod compare_panel;
pub mod deformation_view;
pub mod field_view;
pub mod frf_view;
pub mod limits_view;
pub mod results_panel;
pub mod rotor_edit;
pub mod rotor_view;
pub mod sweep_view;
