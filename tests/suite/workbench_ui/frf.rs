//! The FRF view on the test rig: the Bode plots and their limitations, the hydraulics rows of the editor, and
//! the controls clear of the legend at 1280×720.

use egui::accesskit::Role;
use egui_kittest::kittest::Queryable;
use tiltpad::app::views::frf_view::FrfView;

use super::harness::{snapshot, solved_app, solved_app_at, spin_button, text_of, wait_for_solve};

#[test]
fn frf_view_shows_the_bode_plots_of_the_rig_and_its_limitations() {
    let mut h = solved_app(Some(include_str!("../../../cases/test-rig-pub5.toml")), |app| app.open::<FrfView>());
    h.run_steps(3);
    h.get_by_label_contains("Bode — 1000 rpm");
    h.get_by_label_contains("§6.3");
    h.get_by_role_and_label(Role::Slider, "air fraction");
    h.get_by_label("Export CSV");
    snapshot(&mut h, "frf_rig_pub5");
}

/// The hydraulics group edits the valve, the lines and the rig; an air-fraction edit changes only the case's
/// line (the FRF stage reads the ports' pads, so nothing is re-solved: the FRF model stays the same object).
#[test]
fn hydraulics_editor_rows_edit_the_lines_without_a_new_solve() {
    let mut h = solved_app_at([1400.0, 2600.0], Some(include_str!("../../../cases/test-rig-pub5.toml")), |app| {
        app.open::<FrfView>()
    });
    let model = h.state().shown.clone().unwrap().frf.expect("the FRF view asks for the FRF stage");
    h.get_by_label("Hydraulics (controllable bearing)").click();
    h.run_steps(2);
    h.get_by_label("Line 0");
    spin_button(&h, "Supply pressure").set_value_accesskit(40.0);
    h.run_steps(2);
    assert_eq!(h.state().doc.file().hydraulics.as_ref().unwrap().supply_pressure_bar, 40.0);
    spin_button(&h, "Line 0 length").set_value_accesskit(1500.0);
    h.run_steps(2);
    wait_for_solve(&mut h);
    assert_eq!(h.state().doc.file().hydraulics.as_ref().unwrap().port[0].line_length_mm, 1500.0);
    let after = h.state().shown.clone().unwrap();
    assert!(std::sync::Arc::ptr_eq(&after.frf.unwrap(), &model), "an edit of the line re-linearised the bearing");
    assert_eq!(after.solution.inputs.hydraulics.as_ref().unwrap().ports[0].line_length_m, 1.5);
}

/// At 1280×720 the FRF view's controls and its legend do not cover one another (the legend is a row of its
/// own above the plots), and all of them lie inside the view, not under the results panel.
#[test]
fn frf_controls_and_legend_do_not_overlap_at_1280x720() {
    let mut h = solved_app_at([1280.0, 720.0], Some(include_str!("../../../cases/test-rig-pub5.toml")), |app| {
        app.open::<FrfView>();
    });
    h.run_steps(3);
    h.get_by_label_contains("Bode — 1000 rpm");
    let mut controls: Vec<(String, egui::Rect)> =
        ["air fraction", "line length [mm]", "valve ω_V/2π [Hz]", "signal [V]"]
            .iter()
            .map(|l| (l.to_string(), h.get_by_role_and_label(Role::Slider, l).rect()))
            .collect();
    for l in ["dB", "Export CSV", "|G| log scale"] {
        controls.push((l.to_string(), h.get_by_label(l).rect()));
    }
    controls.push(("unit selector".into(), h.get_by_role_and_label(Role::ComboBox, "Show").rect()));
    // Each entry: its line sample and its name.
    let mut legend: Vec<(String, egui::Rect)> = Vec::new();
    for sample in h.get_all_by_label_contains("legend: ") {
        let name = text_of(&sample).trim_start_matches("legend: ").to_string();
        legend.push((name.clone(), h.get_by_label(&name).rect()));
        legend.push((name, sample.rect()));
    }
    assert!(legend.len() >= 2, "{legend:?}");
    let view = h.state().view_rect().unwrap();
    for (name, c) in &controls {
        assert!(view.expand(1.0).contains_rect(*c), "{name} at {c:?} outside the view {view:?}");
        for (entry, l) in &legend {
            assert!(!c.intersects(*l), "{name} at {c:?} under the legend entry {entry} at {l:?}");
        }
    }
    snapshot(&mut h, "frf_rig_pub5_1280x720");
}
