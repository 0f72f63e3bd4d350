//! The views of the central area, one file each, and [`all`]: the one list where they are registered.
//!
//! Each view implements [`View`] ([`view`]): its id and tab label, the solver stages whose results it draws,
//! how it draws them from a [`ViewContext`] (the result on screen, the edited case, the pins), its
//! placeholder while the result is missing, the settings it keeps between sessions and how the UI test
//! snapshots it. Each reads drawables from [`crate::scene`]; none computes physics.
//!
//! **Adding a view**: a new file here implementing [`View`] for a `Default` type, and its line in the
//! list below. The workbench then shows its tab, solves what it needs while it is open, saves its settings,
//! and `tests/workbench_ui.rs` snapshots it (`tests/snapshots/view_<id>.png`).
//!
//! Parts of views and panels that are not tabs: [`compare_panel`], [`limits_view`], [`results_panel`],
//! [`rotor_edit`].

pub mod compare_panel;
pub mod limits_view;
pub mod results_panel;
pub mod rotor_edit;
pub mod view;

pub use view::{View, ViewContext};

/// Declares each view's module and lists the views in tab order.
macro_rules! views {
    ($($module:ident :: $view:ident,)*) => {
        $(pub mod $module;)*

        /// Every view, in tab order, as the workbench starts.
        #[must_use]
        pub fn all() -> Vec<Box<dyn View>> {
            vec![$(Box::<$module::$view>::default()),*]
        }
    };
}

views! {
    bearing_view::BearingView,
    field_view::FieldView,
    coefficients_view::CoefficientsView,
    deformation_view::DeformationView,
    frf_view::FrfView,
    rotor_view::RotorView,
    sweep_view::SweepView,
    pivot_loads::PivotLoadView,
}
