//! The views of the central area, one file each, and [`all`]: the one list where they are registered.
//!
//! Each view implements [`View`] ([`view`]): its id and tab label, the solver stages whose results it draws,
//! how it draws them from a [`ViewContext`] (the result on screen, the edited case, the pins), its
//! placeholder while the result is missing, the settings it keeps between sessions and how the UI test
//! snapshots it. Each reads drawables from [`crate::scene`]; none computes physics.
//!
//! **Adding a view**: a new file here implementing [`View`] for a `Default` type, and its line in the
//! list below. The workbench then shows its tab, solves what it needs while it is open, saves its settings,
//! and `tests/suite/workbench_ui/views.rs` snapshots it (`tests/snapshots/view_<id>.png`).
//!
//! Parts of views and panels that are not tabs: [`compare_panel`], [`control_plots`], [`control_rig`], [`field_paint`], [`limits_view`], [`results_panel`],
//! [`rotor_edit`], [`rotor_plots`], [`rotor_sketch`]; [`plot_kit`]: what the plots share (the legend above the plot, decade and phase ticks,
//! the palette).

pub mod compare_panel;
pub mod control_plots;
pub mod control_rig;
pub mod field_paint;
pub mod limits_view;
pub mod plot_kit;
pub mod results_panel;
pub mod rotor_edit;
pub mod rotor_plots;
pub mod rotor_sketch;
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
    control_view::ControlView,
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::app::state::Persisted;
    use crate::app::WorkbenchApp;

    #[test]
    fn every_view_has_its_own_id_and_label() {
        let views = all();
        let ids: std::collections::BTreeSet<&str> = views.iter().map(|v| v.id()).collect();
        let labels: std::collections::BTreeSet<&str> = views.iter().map(|v| v.label()).collect();
        assert_eq!((ids.len(), labels.len()), (views.len(), views.len()));
        // Ids are stored between sessions and name snapshot files: plain lower-case words.
        assert!(ids.iter().all(|id| id.chars().all(|c| c.is_ascii_lowercase() || c == '_')), "{ids:?}");
    }

    #[test]
    fn settings_read_back_and_settings_that_do_not_read_leave_them_unchanged() {
        for mut v in all() {
            let id = v.id();
            let Some(settings) = v.settings() else { continue };
            let json = settings.to_json().expect("settings write as JSON");
            assert!(settings.read_json(&json), "{id}: {json}");
            assert!(!settings.read_json("{\"not\": json"), "{id}");
            assert_eq!(settings.to_json().as_deref(), Some(json.as_str()), "{id}");
        }
    }

    /// Stored settings are restored view by view: a partial entry fills in defaults, an entry that does not
    /// read (an older layout) leaves the view's defaults, and the rest of the stored state stays.
    #[test]
    fn the_app_restores_each_views_settings_and_keeps_the_defaults_of_unreadable_ones() {
        use super::coefficients_view::{CoefficientAxis, CoefficientsView};
        use super::field_view::{FieldSettings, FieldView, PadChoice};
        let mut persisted =
            Persisted { view: "PadDeformation".into(), case_name: "kept".into(), ..Persisted::default() };
        persisted.view_settings.insert("fields".into(), r#"{"flowlines": false, "pads": {"One": 2}}"#.into());
        persisted.view_settings.insert("coefficients".into(), r#"{"axis": "Sideways"}"#.into());
        persisted.view_settings.insert("gone".into(), "{}".into());
        let app = WorkbenchApp::with_state(&egui::Context::default(), persisted);
        let fields = &app.view::<FieldView>().unwrap().settings;
        assert_eq!(*fields, FieldSettings { flowlines: false, pads: PadChoice::One(2), ..FieldSettings::default() });
        assert_eq!(app.view::<CoefficientsView>().unwrap().settings.axis, CoefficientAxis::FrequencyRatio);
        assert_eq!(app.open_view().id(), "pad_deformation");
        assert_eq!(app.persisted.case_name, "kept");
    }
}
