//! The workbench driven headlessly (egui_kittest): every view rendered on a fixed case and compared with
//! the PNGs under `tests/snapshots/` (CPU rendering through wgpu: Mesa lavapipe or llvmpipe), and the
//! editor driven as a user would — change a value, wait for the background solve, check the displayed
//! result; type an invalid value, check the message and that the last result stays.
//!
//! Create or refresh the snapshots with `UPDATE_SNAPSHOTS=1 cargo test --test workbench_ui`.
#![cfg(feature = "gui")]

use std::time::Duration;

use web_time::Instant;

use egui::accesskit::Role;
use egui_kittest::kittest::{NodeT, Queryable};
use egui_kittest::{Harness, SnapshotOptions};
use tiltpad::app::state::Persisted;
use tiltpad::app::views::bearing_view::BearingView;
use tiltpad::app::views::coefficients_view::{CoefficientAxis, CoefficientsView};
use tiltpad::app::views::deformation_view::DeformationView;
use tiltpad::app::views::field_view::{FieldSettings, FieldView, PadChoice};
use tiltpad::app::views::frf_view::FrfView;
use tiltpad::app::views::rotor_view::RotorView;
use tiltpad::app::views::sweep_view::SweepView;
use tiltpad::app::WorkbenchApp;
use tiltpad::model::rotor::CoefficientModel;
use tiltpad::scene::field::{FieldKind, PadMap};
use tiltpad::scene::field_compare::difference_maps;
use tiltpad::scene::rotor::unbalance_bode;
use tiltpad::scene::summary::sig4;
use tiltpad::scene::sweep::SweepSpec;
use tiltpad::units::{L_PER_MIN, MPA, RPM, UM};

use crate::common::painted_text;

const SIZE: [f32; 2] = [1400.0, 860.0];

/// The app on a shipped case (the compressor bearing unless `preset_toml` is given), set up by `setup`
/// (before its first frame: the view to open, its settings), solved.
pub(crate) fn solved_app(
    preset_toml: Option<&'static str>,
    setup: impl FnOnce(&mut WorkbenchApp) + 'static,
) -> Harness<'static, WorkbenchApp> {
    solved_app_at(SIZE, preset_toml, setup)
}

/// [`solved_app`] in a window of `size` points.
pub(crate) fn solved_app_at(
    size: [f32; 2],
    preset_toml: Option<&'static str>,
    setup: impl FnOnce(&mut WorkbenchApp) + 'static,
) -> Harness<'static, WorkbenchApp> {
    let mut persisted = Persisted::default();
    if let Some(text) = preset_toml {
        persisted.case_toml = Some(text.to_string());
        persisted.case_name = "test case".into();
    }
    solved_app_from(size, persisted, setup)
}

/// The app restored from `persisted` in a window of `size` points, set up by `setup`, solved.
pub(crate) fn solved_app_from(
    size: [f32; 2],
    persisted: Persisted,
    setup: impl FnOnce(&mut WorkbenchApp) + 'static,
) -> Harness<'static, WorkbenchApp> {
    let mut h = Harness::builder().with_size(size).build_eframe(move |cc| {
        let mut app = WorkbenchApp::with_state(&cc.egui_ctx, persisted);
        app.hide_timings = true;
        setup(&mut app);
        app
    });
    wait_for_solve(&mut h);
    h
}

/// Opens the pad field view with `set` applied to its settings.
fn open_fields(app: &mut WorkbenchApp, set: impl FnOnce(&mut FieldSettings)) {
    app.open::<FieldView>();
    set(&mut app.view_mut::<FieldView>().unwrap().settings);
}

pub(crate) fn rotor<'a>(h: &'a Harness<'_, WorkbenchApp>) -> &'a RotorView {
    h.state().view::<RotorView>().unwrap()
}

fn rotor_mut<'a>(h: &'a mut Harness<'_, WorkbenchApp>) -> &'a mut RotorView {
    h.state_mut().view_mut::<RotorView>().unwrap()
}

/// Opens the rotor view on the rotor file `text` (before the first frame: the shipped rotor is not analysed).
pub(crate) fn open_rotor(app: &mut WorkbenchApp, text: &str) {
    app.open::<RotorView>();
    app.view_mut::<RotorView>().unwrap().open_file("shaft.toml", None, text);
}

fn sweep_view<'a>(h: &'a Harness<'_, WorkbenchApp>) -> &'a SweepView {
    h.state().view::<SweepView>().unwrap()
}

/// Steps frames until the worker is idle with a result on screen, then lets the UI settle.
pub(crate) fn wait_for_solve(h: &mut Harness<'_, WorkbenchApp>) {
    let start = Instant::now();
    // The first frames submit the job; then wait for the worker.
    h.step();
    h.step();
    while !(h.state().is_idle() && h.state().shown.is_some()) {
        assert!(start.elapsed() < Duration::from_secs(180), "solve did not finish: {:?}", h.state().status);
        std::thread::sleep(Duration::from_millis(10));
        h.step();
    }
    h.run_steps(3);
    // Until nothing asks for another frame (a plot whose data just arrived lays out its axes from the
    // frame before: under load the result can arrive in the last of the steps above).
    let _ = h.run_ok();
    h.run_steps(1);
}

/// The text of a label (AccessKit keeps a label's text in its value).
pub(crate) fn text_of(n: &egui_kittest::Node<'_>) -> String {
    n.value().or_else(|| n.accesskit_node().label()).unwrap_or_default()
}

pub(crate) fn snapshot_options() -> SnapshotOptions {
    SnapshotOptions::new().threshold(1.0).max_failed_pixels(40)
}

pub(crate) fn snapshot(h: &mut Harness<'_, WorkbenchApp>, name: &str) {
    h.snapshot_options(name, &snapshot_options());
}

/// Switches to the light theme as a user does: Edit → Theme → Light, then Escape closes the menu.
pub(crate) fn choose_light_theme(h: &mut Harness<'_, WorkbenchApp>) {
    h.get_by_label("Edit").click();
    h.run_steps(2);
    h.get_by_label("Light").click();
    h.run_steps(2);
    h.key_press(egui::Key::Escape);
    h.run_steps(4);
}

/// Every view of the list ([`tiltpad::app::views::all`]) at 1280×720, as it opens on the case it asks for
/// ([`tiltpad::app::views::View::snapshot_setup`]), its result and its own work finished, in the dark theme
/// (`tests/snapshots/view_<id>.png`) and in the light one (`view_<id>_light.png`). A view added to the list is snapshotted here with no change to this file.
#[test]
fn every_view_in_the_list_at_1280x720() {
    let mut results = egui_kittest::SnapshotResults::new();
    for view in tiltpad::app::views::all() {
        let id = view.id();
        let mut h = solved_app_at([1280.0, 720.0], None, move |app| assert!(app.open_for_snapshot(id)));
        assert_eq!(h.state().open_view().id(), id);
        assert!(h.state().shown.is_some() && h.state().is_idle(), "{id}: {:?}", h.state().status);
        h.get_by_role_and_label(Role::Button, view.label());
        assert!(h.query_by_label("Waiting for the first result…").is_none(), "{id}");
        // A few more frames: plots lay out their axes from the frame before.
        h.run_steps(4);
        assert_eq!(h.ctx.theme(), egui::Theme::Dark, "{id}: the snapshots start in the dark theme");
        results.add(h.try_snapshot_options(format!("view_{id}"), &snapshot_options()));
        // The same view in the light theme, chosen as a user does (Edit → Theme → Light).
        choose_light_theme(&mut h);
        assert_eq!(h.ctx.theme(), egui::Theme::Light, "{id}");
        results.add(h.try_snapshot_options(format!("view_{id}_light"), &snapshot_options()));
    }
}

#[test]
fn bearing_view_shows_the_solved_compressor_bearing() {
    let mut h = solved_app(None, |_| {});
    let s = h.state().shown.clone().unwrap().solution;
    // The compressor bearing at 9000 rpm, 1918 N: a moderately loaded LOP bearing.
    assert!(s.eccentricity_ratio > 0.1 && s.eccentricity_ratio < 0.6, "{}", s.eccentricity_ratio);
    h.get_by_label_contains("To scale, except film");
    snapshot(&mut h, "bearing_view");
}

#[test]
fn field_view_shows_pressure_of_all_pads_with_flowlines_and_a_hover_readout() {
    let mut h = solved_app(None, |app| app.open::<FieldView>());
    snapshot(&mut h, "fields_pressure_all_pads");
    // Hover over the loaded pad (pad 3, the fourth map): the readout names the pad and a pressure.
    let s = h.state().shown.clone().unwrap().solution;
    let p_max_mpa = MPA.from_si(s.pads[3].p_max_pa);
    h.get_by_label_contains("Hover over a pad");
    let below = h.get_by_label_contains("Rotation: left to right").rect();
    // Sweep the cursor over the maps (rows of pads under the note) until it is over pad 3.
    let mut found = None;
    // (A step of 28 points hits every map; one frame per position shows its readout.)
    for k in 0..200 {
        let (col, row) = (k % 20, k / 20);
        let pos = egui::pos2(below.left() + 20.0 + 28.0 * col as f32, below.bottom() + 40.0 + 30.0 * row as f32);
        h.hover_at(pos);
        h.run_steps(1);
        if let Some(n) = h.query_by_label_contains("Pad 3  θ") {
            found = Some(text_of(&n));
            break;
        }
    }
    let text = found.expect("a readout for pad 3");
    assert!(text.contains("pressure ="), "{text}");
    let value: f64 = text.split("pressure = ").nth(1).unwrap().split_whitespace().next().unwrap().parse().unwrap();
    assert!(value >= 0.0 && value <= p_max_mpa * 1.0001, "{value} vs p_max {p_max_mpa}");
}

#[test]
fn film_thickness_view_of_one_pad() {
    let mut h = solved_app(None, |app| {
        open_fields(app, |f| {
            f.field = FieldKind::FilmThickness;
            f.pads = PadChoice::One(3);
            f.flowlines = false;
        })
    });
    h.get_by_label_contains("Colour scale: Film thickness [µm]");
    snapshot(&mut h, "fields_film_thickness_pad3");
}

/// The fidelity selector shows what the chosen level costs and how accurate it is (measured by the bench).
#[test]
fn fidelity_group_shows_the_expected_error_and_time() {
    // A tall window, so that the opened group is inside the editor's visible area.
    let mut h = Harness::builder().with_size([1400.0, 2600.0]).build_eframe(|cc| {
        let mut app = WorkbenchApp::with_state(&cc.egui_ctx, Persisted::default());
        app.hide_timings = true;
        app
    });
    wait_for_solve(&mut h);
    h.get_by_label("Fidelity").click();
    h.run_steps(2);
    let note = h.get_by_label_contains("Expected (compressor bearing)");
    let text = text_of(&note);
    assert!(text.contains("isothermal:") && text.contains(" ms, ε ±"), "{text}");
}

/// Fillon's bearing A runs the thermal model (THD, BC1): the film temperature map of all pads, T_max and
/// the thermal group in the results.
#[test]
fn film_temperature_view_of_a_thermal_solve() {
    let mut h = solved_app(Some(include_str!("../../cases/fillon-a.toml")), |app| {
        open_fields(app, |f| {
            f.field = FieldKind::FilmTemperature;
            f.pads = PadChoice::All;
            f.flowlines = false;
        })
    });
    let s = h.state().shown.clone().unwrap().solution;
    let t = s.thermal.as_ref().expect("a THD solution");
    // Hotter than the 40 °C supply, well below a babbitt limit.
    assert!(t.t_max_film_c > 55.0 && t.t_max_film_c < 100.0, "{}", t.t_max_film_c);
    h.get_by_label_contains("Colour scale: Film temperature");
    // Film and pad maxima on rows of their own, each with its unit in view.
    h.get_by_label("T_max film");
    h.get_by_label("T_max pad");
    // Fillon's bearing has no orifices: no orifice flow is shown as if measured.
    h.get_by_label("— (no orifices)");
    assert!(h.query_all_by_label(&format!("{:.1}", t.t_max_film_c)).count() > 0, "T_max film {}", t.t_max_film_c);
    h.get_by_label_contains("Thermal (THD)");
    snapshot(&mut h, "fields_film_temperature_fillon");
}

/// The large five-pad bearing in transition: the local Reynolds number ρUh/µ of every pad, highest in the
/// thick, unloaded films; the colour scale reaches the report's Re max.
#[test]
fn reynolds_field_view_of_the_large_bearing() {
    let mut h = solved_app(Some(include_str!("../../cases/large-5pad-transition.toml")), |app| {
        open_fields(app, |f| {
            f.field = FieldKind::Reynolds;
            f.pads = PadChoice::All;
            f.flowlines = false;
        })
    });
    let s = h.state().shown.clone().unwrap().solution;
    assert!(s.regime.reynolds_max > 1000.0, "{}", s.regime.reynolds_max);
    h.get_by_label_contains("Colour scale: Local Reynolds number");
    snapshot(&mut h, "fields_reynolds_large_bearing");
}

/// The test rig with 17 bar on the lower pad (Publication 4, Fig. 6): the flow reverses upstream of the
/// orifice. With injection off, the orifice is a sink.
#[test]
fn flowlines_show_the_injection_source_and_the_sink() {
    let rig = include_str!("../../cases/test-rig.toml")
        .replace("injection_pressure_bar = [10.0, 0.0]", "injection_pressure_bar = [17.0, 0.0]");
    let rig: &'static str = Box::leak(rig.into_boxed_str());
    let mut h = solved_app(Some(rig), |app| open_fields(app, |f| f.pads = PadChoice::All));
    let s = h.state().shown.clone().unwrap().solution;
    assert!(s.pads[0].orifice_flows_m3_per_s[0] > 0.0, "lower pad injects");
    assert!(s.pads[1].orifice_flows_m3_per_s[0] < 0.0, "upper pad's open orifice drains");
    snapshot(&mut h, "flowlines_test_rig_17bar");
}

#[test]
fn coefficient_view_plots_the_frequency_sweep_and_the_full_matrices() {
    let mut h = solved_app(None, |app| app.open::<CoefficientsView>());
    let shown = h.state().shown.clone().unwrap();
    let sweep = shown.frequency_sweep.unwrap();
    assert_eq!(sweep.len(), 31);
    // The synchronous point of the sweep is the case's own reduced coefficients.
    let sync = sweep.iter().find(|(r, _)| (*r - 1.0).abs() < 1e-12).unwrap().1;
    assert_eq!(sync.k_n_per_m, shown.solution.reduced.k_n_per_m);
    // Direct and cross terms on scales of their own, each legend above its plot.
    for title in
        ["Direct stiffness [MN/m]", "Cross stiffness [MN/m]", "Direct damping [kN·s/m]", "Cross damping [kN·s/m]"]
    {
        h.get_by_label(title);
    }
    for entry in ["Kxx", "Kyy", "Kxy", "Kyx", "Cxx", "Cyy"] {
        h.get_by_label(&format!("legend: {entry}"));
    }
    // Each of the four plots numbers its frequency-ratio axis (five ticks on a 190-point axis were all
    // left unlabelled by egui_plot) and its value axis.
    let top = h.get_by_label("Direct stiffness [MN/m]").rect().top();
    let ticks = tick_labels(&h, "excitation frequency ratio ω/Ω", top);
    assert_eq!(ticks.len(), 4, "{ticks:?}");
    for (x, y) in &ticks {
        assert!(x.len() >= 2 && y.len() >= 2, "x {x:?}, y {y:?}");
    }
    snapshot(&mut h, "coefficients_frequency");
    // The full matrices open under their header.
    assert!(h.query_by_label("pad 3 tilt [rad]").is_none());
    h.get_by_label_contains("Full coefficient matrices").click();
    h.run_steps(3);
    assert_eq!(h.get_all_by_label("pad 3 tilt [rad]").count(), 6, "row and column header in K, C and M");
}

#[test]
fn coefficient_view_against_speed_runs_a_background_sweep() {
    let mut h = solved_app(None, |app| {
        app.open::<CoefficientsView>();
        app.view_mut::<CoefficientsView>().unwrap().settings.axis = CoefficientAxis::Speed;
    });
    let sweep = h.state().shown.clone().unwrap().speed_sweep.expect("speed sweep");
    assert_eq!(sweep.len(), 11);
    // 4500 … 13 500 rpm. A point where the solver fails is listed in the view, not hidden.
    let ecc: Vec<f64> = sweep.iter().filter_map(|p| p.result.as_ref().ok()).map(|v| v.eccentricity_ratio).collect();
    assert_eq!(ecc.len(), 11, "every point converges: {sweep:?}");
    assert!(ecc.windows(2).all(|w| w[1] < w[0]), "the journal rises with speed: {ecc:?}");
    for p in sweep.iter().filter(|p| p.result.is_err()) {
        h.get_by_label_contains(&format!("No solution at {:.0}", tiltpad::units::RPM.from_si(p.speed_rad_s)));
    }
    snapshot(&mut h, "coefficients_speed");
}

#[test]
fn views_without_their_inputs_say_what_is_missing() {
    let mut h = solved_app(None, |app| app.open::<DeformationView>());
    h.get_by_label_contains("bending modes");
    h.get_by_label("FRF").click();
    h.run();
    h.get_by_label_contains("no [hydraulics] section");
    snapshot(&mut h, "placeholder_frf");
}

#[test]
fn frf_view_shows_the_bode_plots_of_the_rig_and_its_limitations() {
    let mut h = solved_app(Some(include_str!("../../cases/test-rig-pub5.toml")), |app| app.open::<FrfView>());
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
    let mut h = solved_app_at([1400.0, 2600.0], Some(include_str!("../../cases/test-rig-pub5.toml")), |app| {
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

/// The pad-deformation view of the flexible compressor bearing (two modes): the loaded pad's deformed
/// section, its displacement and film maps, the mode gallery with the solved frequencies; hovering the
/// displacement map reads a value in µm within the solved field's range.
#[test]
fn deformation_view_shows_the_loaded_pad_and_its_modes() {
    let text: &'static str =
        include_str!("../../cases/compressor-bearing-flexible.toml").replace("pad_modes = 1", "pad_modes = 2").leak();
    let mut h = solved_app(Some(text), |app| app.open::<DeformationView>());
    h.run_steps(3);
    let s = h.state().shown.clone().unwrap().solution;
    let pad = &s.pads[3];
    let modes = &pad.flex.as_ref().expect("flexible pads").modes.modes;
    assert_eq!(modes.len(), 2);
    h.get_by_label_contains("Pad 3: mid-plane section drawn");
    h.get_by_label_contains(&format!("mode 2 at {} Hz", tiltpad::scene::summary::sig4(modes[1].frequency_hz)));
    h.get_by_label("Automatic exaggeration");
    snapshot(&mut h, "deformation_compressor_pad3");
    let peak_um = UM.from_si(pad.elastic_displacement_m.iter().fold(0.0_f64, |m, v| m.max(v.abs())));
    let anchor = h.get_by_label("Automatic exaggeration").rect();
    let mut found = None;
    'sweep: for row in 0..12 {
        for col in 0..25 {
            let pos = egui::pos2(500.0 + 28.0 * col as f32, anchor.bottom() + 40.0 + 16.0 * row as f32);
            h.hover_at(pos);
            h.run_steps(1);
            if let Some(n) = h.query_by_label_contains("Film-face u (mechanical) at θ") {
                found = Some(text_of(&n));
                break 'sweep;
            }
        }
    }
    let text = found.expect("a readout over the displacement map");
    let value: f64 = text.rsplit(": ").next().unwrap().trim_end_matches(" µm").parse().unwrap();
    assert!(value.abs() <= peak_um * (1.0 + 1e-9), "{value} µm vs peak {peak_um} µm");
}

/// The colour-scale line of the deformation view: "Colour scale: KIND u from LO to HI µm".
fn deformation_scale(h: &Harness<'_, WorkbenchApp>) -> String {
    text_of(&h.get_by_label_contains("Colour scale: "))
}

/// TEHD (the flexible compressor bearing, THD with steel pads and journal growing from 20 °C, preview mesh):
/// the view opens on the mechanical displacement; selecting "Thermal" recolours it by the pad's thermal
/// growth, whose colour range (±its largest film-face value) is read from the result; "Total" is the sum.
/// Snapshot at 1280×720 with "Thermal" selected.
#[test]
fn deformation_view_switches_to_the_thermal_growth_of_a_tehd_solve_at_1280x720() {
    let text: &'static str = include_str!("../../cases/compressor-bearing-flexible.toml")
        .replace("fidelity = \"standard\"", "fidelity = \"preview\"")
        .replace(
            "model = \"isothermal\"",
            "model = \"thd\"\npad_expansion_ppm_per_k = 12.0\njournal_expansion_ppm_per_k = 11.0\nreference_temperature_c = 20.0",
        )
        .leak();
    let mut h = solved_app_at([1280.0, 720.0], Some(text), |app| {
        app.open::<DeformationView>();
        app.persisted.editor_open = false;
    });
    h.run_steps(3);
    let s = h.state().shown.clone().unwrap().solution;
    let pad = &s.pads[3];
    let peak = |v: &[f64]| UM.from_si(v.iter().fold(0.0_f64, |m, x| m.max(x.abs())));
    let mechanical_um = peak(&pad.elastic_displacement_m);
    let thermal_um = peak(&pad.thermal_growth.as_ref().expect("TEHD pads carry their growth").film_radial_m);
    let total: Vec<f64> = pad
        .elastic_displacement_m
        .iter()
        .zip(&pad.thermal_growth.as_ref().unwrap().film_radial_m)
        .map(|(a, b)| a + b)
        .collect();
    let total_um = peak(&total);
    println!("pad 3: mechanical {mechanical_um:.3} µm, thermal {thermal_um:.3} µm, total {total_um:.3} µm");
    assert!(thermal_um > 0.1 && (thermal_um - mechanical_um).abs() > 0.01 * thermal_um, "{thermal_um} {mechanical_um}");
    let expect = |kind: &str, um: f64| format!("Colour scale: {kind} u from {} to {} µm", sig4(-um), sig4(um));
    assert_eq!(deformation_scale(&h), expect("mechanical", mechanical_um));
    h.get_by_label("Thermal").click();
    h.run_steps(3);
    assert_eq!(deformation_scale(&h), expect("thermal", thermal_um));
    snapshot(&mut h, "deformation_tehd_thermal_1280x720");
    h.get_by_label("Total").click();
    h.run_steps(3);
    assert_eq!(deformation_scale(&h), expect("total", total_um));
}

pub(crate) fn spin_button<'a>(h: &'a Harness<'_, WorkbenchApp>, label: &'a str) -> egui_kittest::Node<'a> {
    h.get_by_role_and_label(Role::SpinButton, label)
}

#[test]
fn editing_the_speed_resolves_and_updates_the_results() {
    let mut h = solved_app(None, |_| {});
    let before = h.state().shown.clone().unwrap().solution;
    h.get_by_label(&format!("{:.4}", before.eccentricity_ratio));
    spin_button(&h, "Speed").set_value_accesskit(6000.0);
    h.run_steps(2);
    assert_eq!(h.state().doc.file().operating.speed_rpm, 6000.0);
    wait_for_solve(&mut h);
    let after = h.state().shown.clone().unwrap().solution;
    assert!((after.derived.speed_rpm - 6000.0).abs() < 1e-9);
    // Slower: less oil dragged into the wedge, the journal sinks.
    assert!(
        after.eccentricity_ratio > before.eccentricity_ratio + 0.01,
        "{} → {}",
        before.eccentricity_ratio,
        after.eccentricity_ratio
    );
    assert!(after.h_min_m < before.h_min_m);
    // The results panel shows the new numbers, not the old.
    h.get_by_label(&format!("{:.4}", after.eccentricity_ratio));
    assert!(h.query_by_label(&format!("{:.4}", before.eccentricity_ratio)).is_none());
    assert!(!h.state().result_is_stale());
    // Undo brings the old case and result back.
    h.get_by_label("Undo").click();
    h.run_steps(2);
    wait_for_solve(&mut h);
    assert!((h.state().shown.clone().unwrap().solution.eccentricity_ratio - before.eccentricity_ratio).abs() < 1e-6);
}

#[test]
fn an_invalid_value_is_flagged_in_place_and_the_last_result_stays() {
    let mut h = solved_app(None, |_| {});
    let before = h.state().shown.clone().unwrap().solution;
    spin_button(&h, "Pad length L").set_value_accesskit(-5.0);
    h.run_steps(3);
    // The message sits in the editor, naming the key and the allowed range.
    // In place under the field, at the top of the editor and in the status bar.
    let messages: Vec<String> =
        h.get_all_by_label_contains("`bearing.length_mm` = -5 is out of range").map(|n| text_of(&n)).collect();
    assert_eq!(messages.len(), 3, "{messages:?}");
    let msg = &messages[0];
    assert!(msg.contains("(0, 10000]"), "{msg}");
    // Nothing new is solved; the old result stays on screen, marked as not matching the case.
    std::thread::sleep(Duration::from_millis(200));
    h.run_steps(3);
    let shown = h.state().shown.clone().unwrap().solution;
    assert!(std::sync::Arc::ptr_eq(&shown, &before));
    assert!(h.state().result_is_stale());
    // The status bar says the case is not solved, not "Solved" beside "Invalid case".
    assert!(h.query_by_label("Solved").is_none());
    h.get_by_label("Not solved");
    h.get_by_label(&format!("{:.4}", before.eccentricity_ratio));
    assert_eq!(
        h.get_all_by_label_contains("Showing the last valid result").count(),
        2,
        "bearing view and results panel"
    );
    snapshot(&mut h, "editor_invalid_value");
}

/// Clicks File → Open preset → `name`.
fn open_preset(h: &mut Harness<'_, WorkbenchApp>, name: &str) {
    h.get_by_label("File").click();
    h.run_steps(2);
    h.get_by_label("Open preset").hover();
    h.run_steps(2);
    h.get_by_label(name).click();
    h.run_steps(2);
}

#[test]
fn opening_a_preset_over_unsaved_changes_asks_first() {
    let mut h = solved_app(None, |_| {});
    spin_button(&h, "Load W").set_value_accesskit(2500.0);
    h.run_steps(2);
    assert!(h.state().doc.is_dirty());
    open_preset(&mut h, "test-rig.toml");
    // The guard holds the preset back until the user decides.
    h.get_by_label_contains("has changes that are not saved");
    assert_eq!(h.state().doc.name, "compressor-bearing.toml");
    h.get_by_label("Cancel").click();
    h.run_steps(2);
    assert!(h.query_by_label_contains("has changes that are not saved").is_none());
    assert_eq!(h.state().doc.file().operating.load_n, Some(2500.0));
    // Again, and discard this time.
    open_preset(&mut h, "test-rig.toml");
    h.get_by_label("Discard changes").click();
    h.run_steps(2);
    assert_eq!(h.state().doc.name, "test-rig.toml");
    assert!(!h.state().doc.is_dirty() && !h.state().doc.can_undo());
    wait_for_solve(&mut h);
    assert_eq!(h.state().shown.clone().unwrap().solution.pads.len(), 2);
}

/// A file dropped on the window, as the native integration hands it over.
#[derive(Debug)]
struct Dropped(std::path::PathBuf);

impl egui::DroppedFile for Dropped {
    fn path(&self) -> &std::path::Path {
        &self.0
    }
    fn bytes(&self) -> Result<Vec<u8>, String> {
        std::fs::read(&self.0).map_err(|e| e.to_string())
    }
}

#[test]
fn a_dropped_case_file_is_opened_and_solved() {
    let mut h = solved_app(None, |_| {});
    let path = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("cases/fillon-a.toml");
    h.input_mut().dropped_files.push(std::sync::Arc::new(Dropped(path)));
    h.run_steps(3);
    assert_eq!(h.state().doc.name, "fillon-a.toml");
    wait_for_solve(&mut h);
    let s = h.state().shown.clone().unwrap().solution;
    assert_eq!(s.pads.len(), 4);
    assert!((s.load_magnitude_n - 10_000.0).abs() < 1e-3 * 10_000.0);
}

/// eframe's storage, in memory.
#[derive(Default)]
struct MemoryStorage(std::collections::HashMap<String, String>);

impl eframe::Storage for MemoryStorage {
    fn get_string(&self, key: &str) -> Option<String> {
        self.0.get(key).cloned()
    }
    fn set_string(&mut self, key: &str, value: String) {
        self.0.insert(key.to_string(), value);
    }
    fn remove_string(&mut self, key: &str) {
        self.0.remove(key);
    }
    fn flush(&mut self) {}
}

#[test]
fn the_edited_case_and_the_view_survive_a_restart() {
    let mut h = solved_app(None, |app| open_fields(app, |f| f.pads = PadChoice::One(2)));
    spin_button(&h, "Speed").set_value_accesskit(7500.0);
    h.run_steps(2);
    let mut storage = MemoryStorage::default();
    eframe::App::save(h.state_mut(), &mut storage);
    let restored: Persisted = eframe::get_value(&storage, eframe::APP_KEY).expect("persisted state");
    assert_eq!(restored.view, "fields");
    let ctx = egui::Context::default();
    let app = WorkbenchApp::with_state(&ctx, restored);
    assert_eq!(app.open_view().label(), "Pad fields");
    assert_eq!(app.view::<FieldView>().unwrap().settings.pads, PadChoice::One(2), "the view's own settings");
    assert_eq!(app.doc.file().operating.speed_rpm, 7500.0);
    assert_eq!(app.doc.name, "compressor-bearing.toml");
    assert!(app.doc.is_dirty(), "the restored edit is still unsaved");
}

/// Steps frames until the rotor view's analysis has finished.
pub(crate) fn wait_for_rotor(h: &mut Harness<'_, WorkbenchApp>) {
    let start = Instant::now();
    h.run_steps(2);
    while !(rotor(h).is_idle() && rotor(h).result().is_some()) {
        assert!(start.elapsed() < Duration::from_secs(300), "rotor analysis did not finish");
        std::thread::sleep(Duration::from_millis(10));
        h.step();
    }
    h.run_steps(3);
}

/// The shipped compressor rotor, analysed once (its bearing cases at preview fidelity): the onset and the
/// critical speeds as the view states them, and every tab. Choosing reduced coefficients starts a new
/// analysis with them; that they overestimate the onset is checked through the library
/// (`tests/suite/rotor_compressor.rs`), so this test solves only once.
#[test]
fn rotor_view_analyses_the_compressor_rotor_and_shows_every_tab() {
    let mut h = solved_app(None, |app| app.open::<RotorView>());
    wait_for_rotor(&mut h);
    h.get_by_label_contains("representative shaft, not the thesis' rotor");
    let full = rotor(&h).result().unwrap().clone();
    let onset_full = RPM.from_si(full.onset.as_ref().expect("an onset inside the view's sweep").speed_rad_s);
    h.get_by_label_contains(&format!("Onset of instability: {onset_full:.0} rpm"));
    assert!(!full.critical_speeds.is_empty(), "the 1× line crosses a forward mode");
    snapshot(&mut h, "rotor_campbell");
    h.get_by_label("Stability map").click();
    h.run_steps(3);
    snapshot(&mut h, "rotor_stability");
    h.get_by_label("Mode shapes").click();
    h.run_steps(3);
    snapshot(&mut h, "rotor_mode_shape");
    h.get_by_label("Unbalance response").click();
    h.run_steps(3);
    // The check against API 617 in words, the nodes by name (bearings numbered along the shaft).
    let bode = unbalance_bode(rotor(&h).result().unwrap(), rotor(&h).analysed_rotor().unwrap());
    let sentence = bode.api617_sentence();
    h.get_by_label(&sentence);
    assert!(sentence.contains("API 617 limit"), "{sentence}");
    for name in ["bearing 1 (210 mm)", "bearing 2 (1470 mm)", "shaft end, disk (0 mm)", "mid-span, disk (780 mm)"] {
        // Each entry whole: its sample on the row of its name, just before it (at 1280×720 the legend
        // wraps, and "bearing 2" left its sample at the end of the first row).
        let sample = h.get_by_label(&format!("legend: {name}")).rect();
        let label = h.get_by_label(name).rect();
        assert!(
            (sample.center().y - label.center().y).abs() < 4.0
                && (0.0..20.0).contains(&(label.left() - sample.right())),
            "{name}: sample at {sample:?}, name at {label:?}"
        );
    }
    assert!(h.query_by_label_contains("node 7").is_none());
    snapshot(&mut h, "rotor_unbalance");
    h.get_by_label("Critical-speed map").click();
    h.run_steps(3);
    snapshot(&mut h, "rotor_critical_map");
    h.get_by_label("reduced 2×2").click();
    h.run_steps(2);
    let view = rotor(&h);
    assert_eq!(view.coefficients, CoefficientModel::Reduced);
    assert!(!view.is_idle() && view.result().is_none(), "a new analysis runs, the full one is not shown");
    h.get_by_label_contains("Analysing: speed");
}

/// A rotor file: a shaft 1000 mm long, Ø 50 mm, in 10 elements; a 20 kg disk at mid-span (node 5); bearings
/// given by numbers (constant K 1e7 N/m, C 1e3 N·s/m) at both ends.
pub(crate) fn two_bearing_shaft(title: &str) -> String {
    let bearing = "k_n_per_m = [[1e7, 0.0, 0.0, 1e7]]\nc_ns_per_m = [[1e3, 0.0, 0.0, 1e3]]\n";
    format!(
        "title = \"{title}\"\n[rotor]\n[[rotor.section]]\nlength_mm = 1000.0\nouter_diameter_mm = 50.0\nelements = 10\n\
         [[rotor.disk]]\nnode = 5\nmass_kg = 20.0\n[[rotor.bearing]]\nnode = 0\n{bearing}[[rotor.bearing]]\nnode = 10\n{bearing}"
    )
}

#[test]
fn a_rotor_file_opens_in_the_rotor_view_and_a_bad_one_names_key_value_and_range() {
    let text = two_bearing_shaft("opened two-bearing shaft");
    let opened = text.clone();
    let mut h = solved_app(None, move |app| open_rotor(app, &opened));
    wait_for_rotor(&mut h);
    h.get_by_label_contains("opened two-bearing shaft");
    assert!(rotor(&h).result().is_some_and(|r| !r.critical_speeds.is_empty()));
    rotor_mut(&mut h).open_file("bad.toml", None, &text.replace("node = 5", "node = 11"));
    h.run_steps(3);
    let shown = text_of(&h.get_by_label_contains("Cannot read the rotor"));
    assert!(shown.contains("rotor.disk[0].node") && shown.contains("11") && shown.contains("[0, 10]"), "{shown}");
}

/// Edits the case as the editor would, then waits for the result.
pub(crate) fn edit_and_solve(
    h: &mut Harness<'_, WorkbenchApp>,
    key: &str,
    f: impl FnOnce(&mut tiltpad::model::CaseFile),
) {
    h.state_mut().doc.edit(key, false, f);
    h.run_steps(2);
    wait_for_solve(h);
}

#[test]
fn design_limits_are_marked_in_the_results_panel_and_the_bearing_view() {
    let mut h = solved_app(None, |_| {});
    h.get_by_label("Within the design limits");
    // The compressor bearing at 18 kN: W/(L·D) = 18000 / (44.45 mm · 101.6 mm) = 3.986 MPa > 3.5 MPa.
    edit_and_solve(&mut h, "operating.load_n", |f| f.operating.load_n = Some(18000.0));
    h.get_by_label("Design limits exceeded:");
    h.get_by_label("W/(L·D) 3.986 MPa > limit 3.5 MPa");
    h.get_by_label("Exceeds design limit: W/(L·D) 3.986 MPa > limit 3.5 MPa");
    snapshot(&mut h, "bearing_view_limits_exceeded");
    // A limit raised in the case clears its marks (limits enter no solver stage: nothing is re-solved).
    edit_and_solve(&mut h, "limits.max_specific_load_mpa", |f| f.limits.max_specific_load_mpa = Some(5.0));
    assert!(!h.state().result_is_stale());
    assert!(h.query_by_label_contains("W/(L·D) 3.986 MPa >").is_none());
}

#[test]
fn a_load_sweep_plots_three_outputs_with_their_units() {
    let mut h = solved_app(None, |app| {
        app.open::<SweepView>();
        app.view_mut::<SweepView>().unwrap().spec = SweepSpec {
            key: "operating.load_n".into(),
            from: 1000.0,
            to: 4000.0,
            count: 4,
            outputs: vec!["eccentricity_ratio".into(), "h_min_um".into(), "p_max_mpa".into()],
            against_sommerfeld: false,
            preview: true,
            chart: false,
        };
    });
    let table = run_sweep(&mut h);
    let eps = table.series("eccentricity_ratio", false);
    assert_eq!(eps.iter().map(|p| p[0]).collect::<Vec<_>>(), [1000.0, 2000.0, 3000.0, 4000.0]);
    assert!(eps.windows(2).all(|w| w[1][1] > w[0][1]), "{eps:?}");
    for label in
        ["eccentricity ratio [–]", "h min [µm]", "p max [MPa]", "4 points of operating.load_n (preview fidelity)"]
    {
        h.get_by_label(label);
    }
    assert!(table.csv().lines().next().unwrap().contains("flow_sides_out_l_per_min"));
    assert_eq!(h.query_all_by_label("this case").count(), 3, "the case's load is marked on each plot");
    snapshot(&mut h, "sweep_load_three_outputs");
}

/// Runs the sweep view's sweep (its spec set before) and waits for its last point.
fn run_sweep(h: &mut Harness<'_, WorkbenchApp>) -> tiltpad::scene::sweep::SweepTable {
    h.get_by_label("Run sweep").click();
    wait_for_sweep(h)
}

/// Steps frames until the sweep view's sweep has its last point; its table.
fn wait_for_sweep(h: &mut Harness<'_, WorkbenchApp>) -> tiltpad::scene::sweep::SweepTable {
    h.step();
    let start = Instant::now();
    while !sweep_view(h).job.as_ref().is_some_and(|j| j.done()) {
        assert!(start.elapsed() < Duration::from_secs(300), "sweep did not finish");
        std::thread::sleep(Duration::from_millis(10));
        h.step();
    }
    h.run_steps(3);
    sweep_view(h).job.as_ref().unwrap().table.clone()
}

/// The teaching sweep: preload on the cases that give the pad bore radius (compressor) or the pad clearance
/// (Fillon). Each point's preload replaces the file's key, every point solves, and the view says what was
/// replaced. Cp = Cb / (1 − m) grows with m.
#[test]
fn a_preload_sweep_fills_every_point_of_the_compressor_and_fillon_cases() {
    for (text, replaced) in [
        (None, "bearing.pads.bore_radius_mm = 50.921"),
        (Some(include_str!("../../cases/fillon-a.toml")), "bearing.pads.clearance_um = 148.0"),
    ] {
        let mut h = solved_app(text, |app| {
            app.open::<SweepView>();
            app.view_mut::<SweepView>().unwrap().spec = SweepSpec {
                key: "bearing.pads.preload".into(),
                from: 0.1,
                to: 0.5,
                count: 3,
                outputs: vec!["h_min_um".into(), "kyy_n_per_m".into()],
                against_sommerfeld: false,
                preview: true,
                chart: false,
            };
        });
        let table = run_sweep(&mut h);
        assert!(table.failures().is_empty(), "{replaced}: {:?}", table.failures());
        let h_min = table.series("h_min_um", false);
        assert_eq!(h_min.iter().map(|p| p[0]).collect::<Vec<_>>(), [0.1, 0.30000000000000004, 0.5], "{replaced}");
        h.get_by_label(&format!(
            "Each point: bearing.pads.preload replaces {replaced} (alternative pad-geometry keys)."
        ));
        // The case gives no preload of its own: no "this case" mark, and no legend entry promising one.
        assert!(h.query_by_label("this case").is_none(), "{replaced}: a legend entry for a point not drawn");
    }
}

/// The Sommerfeld chart runs its own load sweep around the case's load (a fifth to three times 1918 N):
/// every point solves, S falls as the load grows while ε rises, and the chart says that a tilting-pad
/// bearing has no closed-form reference.
#[test]
fn the_sommerfeld_chart_runs_its_load_sweep() {
    let mut h = solved_app(None, |app| app.open::<SweepView>());
    h.get_by_label("Sommerfeld chart").click();
    let table = wait_for_sweep(&mut h);
    let spec = &sweep_view(&h).job.as_ref().unwrap().spec;
    assert_eq!((spec.key.as_str(), spec.from, spec.to), ("operating.load_n", 0.2 * 1918.0, 3.0 * 1918.0));
    assert_eq!(table.points.len(), 12);
    assert!(table.failures().is_empty(), "{:?}", table.failures());
    let eps = table.series("eccentricity_ratio", true);
    assert_eq!(eps.len(), 12);
    assert!(eps.windows(2).all(|w| w[1][0] < w[0][0] && w[1][1] > w[0][1]), "{eps:?}");
    h.get_by_label_contains("Sommerfeld chart, S = µ N L D / W (R/Cb)². No closed form for this geometry");
    for title in ["Eccentricity ratio ε [–]", "Reduced stiffness K Cb / W [–]", "Reduced damping C Cb Ω / W [–]"]
    {
        h.get_by_label(title);
    }
    h.run_steps(2);
    // Each of the five plots numbers both axes: S over about one decade (0.38 … 5.8 N·… here) reads at 1,
    // 2 and 5 × 10ⁿ, not a lone "1"; y has at least two numbers however short the plot.
    let top = h.get_by_label("Eccentricity ratio ε [–]").rect().top();
    let ticks = tick_labels(&h, "Sommerfeld number S [–]", top);
    assert_eq!(ticks.len(), 5, "{ticks:?}");
    for (x, y) in &ticks {
        assert!(x.len() >= 3 && y.len() >= 2, "x {x:?}, y {y:?}");
    }
    snapshot(&mut h, "sweep_sommerfeld_chart");
    // The same chart in the light theme.
    choose_light_theme(&mut h);
    assert_eq!(tick_labels(&h, "Sommerfeld number S [–]", top).len(), 5);
    snapshot(&mut h, "sweep_sommerfeld_chart_light");
}

/// After the Sommerfeld chart, choosing another input (preload, as a class does next) leaves the chart and
/// the S abscissa: a preload sweep at constant load moves S by a few per cent, and drawn against S its
/// points piled on one vertical line.
#[test]
fn another_input_after_the_sommerfeld_chart_is_drawn_against_itself() {
    let mut h = solved_app(None, |app| app.open::<SweepView>());
    h.get_by_label("Sommerfeld chart").click();
    wait_for_sweep(&mut h);
    assert!(sweep_view(&h).spec.chart && sweep_view(&h).spec.against_sommerfeld);
    h.get_by_role_and_label(Role::ComboBox, "Input").click();
    h.run_steps(2);
    h.get_by_label("bearing.pads.preload").click();
    h.run_steps(2);
    let spec = &sweep_view(&h).spec;
    assert_eq!(spec.key, "bearing.pads.preload");
    assert!(!spec.chart && !spec.against_sommerfeld, "{spec:?}");
    h.get_by_label("Run sweep").click();
    let table = wait_for_sweep(&mut h);
    assert!(table.failures().is_empty(), "{:?}", table.failures());
    h.run_steps(2);
    let axes: Vec<String> = painted_text::painted_texts(&h.output().shapes)
        .into_iter()
        .filter(|t| t.text.starts_with("bearing.pads.preload [") || t.text.starts_with("Sommerfeld number"))
        .map(|t| t.text)
        .collect();
    assert!(!axes.is_empty() && axes.iter().all(|t| t.starts_with("bearing.pads.preload")), "{axes:?}");
}

/// At 1280×720 the FRF view's controls and its legend do not cover one another (the legend is a row of its
/// own above the plots), and all of them lie inside the view, not under the results panel.
#[test]
fn frf_controls_and_legend_do_not_overlap_at_1280x720() {
    let mut h = solved_app_at([1280.0, 720.0], Some(include_str!("../../cases/test-rig-pub5.toml")), |app| {
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

/// Dragging the load down stops at the smallest valid load (0 N), never below; a drag moves it by half
/// a percent of itself per point (1918 N: about 9.6 N per point, where it was 125 N).
#[test]
fn a_load_drag_cannot_leave_the_valid_range() {
    let mut h = solved_app(None, |_| {});
    let load = |h: &Harness<'_, WorkbenchApp>| h.state().doc.file().operating.load_n.unwrap();
    assert_eq!(load(&h), 1918.0);
    let start = spin_button(&h, "Load W").rect().center();
    h.hover_at(start);
    h.step();
    h.drag_at(start);
    h.step();
    h.hover_at(start - egui::vec2(10.0, 0.0));
    h.step();
    let after_ten = load(&h);
    // At most twice the 96 N ten points ask for (egui may count the press threshold); a 400th of the
    // typical range per point moved it 1250 N.
    assert!(after_ten < 1918.0 && after_ten > 1918.0 - 200.0, "10 points moved the load to {after_ten} N");
    for k in 1..=20 {
        h.hover_at(start - egui::vec2(10.0 + 150.0 * k as f32, 0.0));
        h.step();
        assert!(load(&h) >= 0.0, "{} N", load(&h));
    }
    h.drop_at(start - egui::vec2(3010.0, 0.0));
    h.run_steps(2);
    assert_eq!(load(&h), 0.0);
}

/// The colour-scale label of the field view: "… from LO to HI (…)" as two numbers.
fn colour_scale(h: &Harness<'_, WorkbenchApp>) -> (String, String) {
    let t = text_of(&h.get_by_label_contains("Colour scale: "));
    let range = t.split(" from ").nth(1).unwrap().split(" (").next().unwrap().to_string();
    let (lo, hi) = range.split_once(" to ").unwrap();
    (lo.to_string(), hi.to_string())
}

/// The largest pressure of a result, as the field view's colour range reaches it [MPa].
fn p_max_mpa(s: &tiltpad::bearing::Solution) -> f64 {
    MPA.from_si(PadMap::all(s, FieldKind::Pressure).iter().map(|m| m.max).fold(0.0, f64::max))
}

/// Pin the 9000 rpm result, solve 6000 rpm: the results panel lists both with their difference; the
/// bearing view draws the pinned outline over the live one; the pad field view shows both side by side on
/// one colour scale (from 0 to the larger of the two peak pressures), then their difference on a symmetric
/// scale (±the largest nodal |Δp|); the coefficient view re-solves the pin for its curves and overlays them.
#[test]
fn pinning_a_result_compares_it_with_the_live_one_at_1280x720() {
    let mut h = solved_app_at([1280.0, 720.0], None, |_| {});
    let fast = h.state().shown.clone().unwrap().solution;
    h.get_by_label("Pin current result").click();
    h.run_steps(2);
    assert_eq!(h.state().persisted.pins.len(), 1);
    assert_eq!(h.state().persisted.pins[0].name, "pin 1");
    assert_eq!(h.state().persisted.compare_with.as_deref(), Some("pin 1"), "the views compare with the new pin");
    spin_button(&h, "Speed").set_value_accesskit(6000.0);
    h.run_steps(2);
    wait_for_solve(&mut h);
    let slow = h.state().shown.clone().unwrap().solution;
    h.get_by_label("Live vs \"pin 1\"");
    // The ε row: live and pinned (at 1280 points the panel shows Δ % and keeps Δ for its hover).
    for v in [slow.eccentricity_ratio, fast.eccentricity_ratio] {
        assert!(h.query_all_by_label(&sig4(v)).next().is_some(), "{} not shown", sig4(v));
    }
    h.get_by_label_contains("Pinned \"pin 1\" (dashed");
    // The pin button keeps the focus of its click, or loses it in a frame that drops it (how many frames the
    // solve took): Escape clears it, so the picture does not depend on timing.
    h.key_press(egui::Key::Escape);
    h.run_steps(2);
    snapshot(&mut h, "compare_pinned_1280x720");

    open_fields(h.state_mut(), |f| f.flowlines = false);
    h.run_steps(3);
    let shared = p_max_mpa(&slow).max(p_max_mpa(&fast));
    assert_eq!(colour_scale(&h), (sig4(0.0), sig4(shared)));
    snapshot(&mut h, "compare_fields_side_by_side_1280x720");
    // Both panels open, the live and pinned pads side by side: no angle label over another.
    let texts = overlapping_texts(&h);
    assert!(texts.is_empty(), "{}", texts.join("\n"));
    h.get_by_label("difference map").click();
    h.run_steps(3);
    let live = PadMap::all(&slow, FieldKind::Pressure);
    let pinned = PadMap::all(&fast, FieldKind::Pressure);
    let (_, (lo, hi)) = difference_maps(&live, &pinned).unwrap();
    assert!(hi > 0.0 && lo == -hi);
    assert_eq!(colour_scale(&h), (sig4(MPA.from_si(lo)), sig4(MPA.from_si(hi))));
    h.get_by_label_contains("Colour scale: Δ Pressure [MPa]");
    snapshot(&mut h, "compare_fields_difference_1280x720");

    h.state_mut().open::<CoefficientsView>();
    h.run_steps(2);
    wait_for_solve(&mut h);
    h.get_by_label("Wide faint dashed curves: pinned \"pin 1\".");

    h.get_by_label("Remove \"pin 1\"").click();
    h.run_steps(2);
    assert!(h.state().persisted.pins.is_empty());
    assert!(h.query_by_label_contains("Wide faint dashed").is_none());
}

/// The numbers a plot shows on its axes, found from its x-axis title `axis` (each plot with that title,
/// below `below` points, so a control of the same text above the plots is not taken for one): per plot,
/// (the numeric labels just above the title: x ticks; the numeric labels left of its middle between the
/// title and the nearest words above, its legend: y ticks). Tick labels read as numbers after a prefix
/// (k, M) or a degree sign is dropped.
fn tick_labels(h: &Harness<'_, WorkbenchApp>, axis: &str, below: f32) -> Vec<(Vec<String>, Vec<String>)> {
    let texts = painted_text::painted_texts(&h.output().shapes);
    let view = h.state().view_rect().expect("a view on screen");
    let numeric = |t: &str| t.trim_end_matches(['k', 'M', 'G', '°']).replace('−', "-").parse::<f64>().is_ok();
    texts
        .iter()
        .filter(|t| t.text == axis && t.shown.top() > below)
        .map(|a| {
            let (mid, top) = (a.shown.center().x, a.shown.top());
            let column = |t: &&painted_text::PaintedText| {
                view.contains_rect(t.shown) && (t.shown.center().x - mid).abs() < 200.0
            };
            let x: Vec<String> = texts
                .iter()
                .filter(|t| numeric(&t.text) && (t.shown.center().x - mid).abs() < 130.0)
                .filter(|t| t.shown.center().y < top && t.shown.center().y > top - 24.0)
                .map(|t| t.text.clone())
                .collect();
            let legend = texts
                .iter()
                .filter(column)
                // Words written across (a rotated y-axis title spans the plot's height).
                .filter(|t| !numeric(&t.text) && t.shown.width() > t.shown.height() && t.shown.bottom() < top - 24.0)
                .map(|t| t.shown.bottom())
                .fold(f32::MIN, f32::max);
            let y: Vec<String> = texts
                .iter()
                .filter(column)
                .filter(|t| numeric(&t.text) && t.shown.center().x < mid - 40.0)
                .filter(|t| t.shown.center().y < top - 24.0 && t.shown.center().y > legend)
                .map(|t| t.text.clone())
                .collect();
            (x, y)
        })
        .collect()
}

/// The comparison table's cells: (text, rect) of every label right of the view, below the "Live vs" line.
fn comparison_cells(h: &Harness<'_, WorkbenchApp>) -> Vec<(String, egui::Rect)> {
    let view = h.state().view_rect().unwrap();
    let below = h.get_by_label_contains("Live vs").rect().bottom();
    h.query_all_by_role(Role::Label)
        .map(|n| (text_of(&n), n.rect()))
        .filter(|(_, r)| r.left() > view.right() && r.top() > below)
        .collect()
}

/// In the frame right after "Pin current result" (before any other input), at 1280×720 and 1920×1080:
/// the comparison table's cells cover nothing, every column of the table lies inside the results panel
/// (fixed widths: nothing to scroll sideways to), the quantities read with their prefixed units, and
/// the whole window has no text over text. At 1280 the Δ column gives way to Δ % (Δ on its hover).
#[test]
fn a_new_pin_lays_out_its_table_inside_the_results_panel_at_once() {
    for (size, columns) in [([1280.0, 720.0], 4), ([1920.0, 1080.0], 5)] {
        let mut h = solved_app_at(size, None, |_| {});
        h.get_by_label("Pin current result").click();
        h.run_steps(1);
        assert_eq!(h.state().persisted.pins.len(), 1);
        let screen = h.ctx.content_rect();
        let cells = comparison_cells(&h);
        let header: Vec<&str> =
            cells.iter().filter(|(_, r)| (r.top() - cells[0].1.top()).abs() < 1.0).map(|(t, _)| t.as_str()).collect();
        assert_eq!(header.len(), columns, "{size:?}: {header:?}");
        assert_eq!(header.contains(&"Δ"), columns == 5, "{size:?}: {header:?}");
        for (text, r) in &cells {
            assert!(
                r.right() <= screen.right() - 4.0,
                "{size:?}: {text:?} at {r:?} past the panel's edge {}",
                screen.right()
            );
        }
        // The compressor carries 1.918 kN: the load row reads in kN, live and pinned alike.
        let load = cells.iter().find(|(t, _)| t == "load [kN]").expect("the load row").1;
        let row: Vec<&str> = cells
            .iter()
            .filter(|(_, r)| (r.center().y - load.center().y).abs() < 1.0)
            .map(|(t, _)| t.as_str())
            .collect();
        assert_eq!(row[..3], ["load [kN]", "1.918", "1.918"], "{size:?}");
        // Every quantity reads whole (a long name wraps): no cell is cut with "…".
        let view = h.state().view_rect().unwrap();
        let cut: Vec<String> = painted_text::painted_texts(&h.output().shapes)
            .into_iter()
            .filter(|t| t.shown.left() > view.right() && t.text.ends_with('…'))
            .map(|t| t.text)
            .collect();
        assert!(cut.is_empty(), "{size:?}: cut names {cut:?}");
        assert!(cells.iter().any(|(t, _)| t.starts_with("eccentricity ratio")), "{size:?}");
        let widgets = overlapping_widgets(&h);
        assert!(widgets.is_empty(), "{size:?}: {}", widgets.join("\n"));
        let texts = overlapping_texts(&h);
        assert!(texts.is_empty(), "{size:?}: {}", texts.join("\n"));
    }
}

/// The pin dialog refuses "live" (the export's name for the live row) and a name already pinned, saying
/// why, and pins nothing; another name is pinned.
#[test]
fn the_pin_dialog_refuses_ambiguous_names() {
    let mut h = solved_app_at([1280.0, 720.0], None, |_| {});
    let pin_as = |h: &mut Harness<'_, WorkbenchApp>, typed: &str| {
        h.get_by_role_and_label(Role::TextInput, "Pin name").click();
        h.run_steps(1);
        h.get_by_role_and_label(Role::TextInput, "Pin name").type_text(typed);
        h.run_steps(1);
        h.get_by_label("Pin current result").click();
        h.run_steps(2);
    };
    pin_as(&mut h, "live");
    h.get_by_label_contains("the pin name \"live\" is refused: the exported CSV names the live result's row");
    assert!(h.state().persisted.pins.is_empty());
    // Typing again clears the message; " 2" makes the name "live 2", which is allowed.
    pin_as(&mut h, " 2");
    assert!(h.query_by_label_contains("is refused").is_none());
    assert_eq!(h.state().persisted.pins.iter().map(|p| p.name.as_str()).collect::<Vec<_>>(), ["live 2"]);
    pin_as(&mut h, "live 2");
    h.get_by_label_contains("a pin named \"live 2\" exists already");
    assert_eq!(h.state().persisted.pins.len(), 1);
}

/// Locked, the pad field colour scale stays through two edits that change the peak pressure; unlocked, it
/// follows the result again.
#[test]
fn a_locked_colour_scale_survives_two_edits() {
    let mut h = solved_app(None, |app| open_fields(app, |f| f.flowlines = false));
    let first = colour_scale(&h);
    assert_eq!(first.1, sig4(p_max_mpa(&h.state().shown.clone().unwrap().solution)));
    h.get_by_label("Lock colour scale").click();
    h.run_steps(2);
    edit_and_solve(&mut h, "operating.speed_rpm", |f| f.operating.speed_rpm = 6000.0);
    edit_and_solve(&mut h, "operating.load_n", |f| f.operating.load_n = f.operating.load_n.map(|w| 1.5 * w));
    let now = sig4(p_max_mpa(&h.state().shown.clone().unwrap().solution));
    assert_ne!(now, first.1, "the edits change the peak pressure");
    assert_eq!(colour_scale(&h), first);
    h.get_by_label_contains("Lock colour scale (").click();
    h.run_steps(2);
    assert_eq!(colour_scale(&h).1, now);
    assert!(h.state().view::<FieldView>().unwrap().settings.locks.is_empty());
}

/// The bearing view's scales lock on the first result (a class sees the field change, not the scale), stay
/// through two edits, follow the result once unlocked, and say so when they change.
#[test]
fn locked_scales_survive_two_edits() {
    let mut h = solved_app(None, |_| {});
    h.get_by_label_contains("journal displacement × 50");
    let lock = h.state().view::<BearingView>().unwrap().settings.outline_lock;
    assert_eq!(lock.map(|l| l.exaggeration), Some(50.0), "locked by default");
    // Edit 1: pads bored to the assembled clearance (Cp = 102 µm): unlocked, 50.8 mm / 6 / 102 µm ≈ 83 → × 100.
    edit_and_solve(&mut h, "bearing.pads.bore_radius_mm", |f| f.bearing.pads.bore_radius_mm = Some(50.902));
    // Edit 2: another speed.
    edit_and_solve(&mut h, "operating.speed_rpm", |f| f.operating.speed_rpm = 6000.0);
    h.get_by_label_contains("journal displacement × 50");
    h.get_by_label_contains("Lock scales (film × 50").click();
    h.run_steps(2);
    h.get_by_label_contains("journal displacement × 100");
    assert!(h.state().view::<BearingView>().unwrap().settings.unlocked);
    // Unlocked, a result with another peak pressure changes the pressure scale, and the view says so.
    assert!(h.query_by_label_contains("Scales changed with this result").is_none());
    edit_and_solve(&mut h, "operating.load_n", |f| f.operating.load_n = f.operating.load_n.map(|w| 2.0 * w));
    h.run_steps(2);
    h.get_by_label_contains("Scales changed with this result: pressure");
}

/// Without a desktop portal, an export asks for a name in the workbench's own dialog: nothing is written
/// before a name is typed, and an existing file is replaced only after the user confirms.
#[test]
fn exports_without_a_portal_ask_for_a_name_and_never_overwrite_silently() {
    let mut h = solved_app(None, |_| {});
    h.state_mut().use_workbench_save_dialog();
    let dir = std::env::temp_dir().join(format!("tiltpad-save-as-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let written = |dir: &std::path::Path| -> Vec<String> {
        let mut names: Vec<String> =
            std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
        names.sort();
        names
    };
    let export = |h: &mut Harness<'_, WorkbenchApp>| {
        h.get_by_label("File").click();
        h.run_steps(2);
        h.get_by_label("Export results as JSON…").click();
        h.run_steps(3);
        // Point the dialog at the test's directory (it opens on the working directory).
        h.get_by_role_and_label(Role::TextInput, "Directory").focus();
        h.run_steps(1);
        h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
        h.get_by_role_and_label(Role::TextInput, "Directory").type_text(&dir.display().to_string());
        h.run_steps(2);
    };
    export(&mut h);
    h.get_by_label_contains("Nothing is written until you do");
    // No name typed: Save is disabled (clicking it does nothing), and nothing is written.
    let save = h.get_by_role_and_label(Role::Button, "Save");
    assert!(save.accesskit_node().is_disabled());
    save.click();
    h.run_steps(2);
    assert!(written(&dir).is_empty());
    h.get_by_role_and_label(Role::TextInput, "File name").focus();
    h.run_steps(1);
    h.get_by_role_and_label(Role::TextInput, "File name").type_text("run1");
    h.run_steps(2);
    h.get_by_label_contains(&format!("Writes {}", dir.join("run1.json").display()));
    h.get_by_role_and_label(Role::Button, "Save").click();
    h.run_steps(3);
    assert_eq!(written(&dir), ["run1.json"]);
    let first = std::fs::read_to_string(dir.join("run1.json")).unwrap();
    assert!(first.contains("eccentricity"), "{first}");
    h.get_by_label_contains("Exported");
    // The same name again: the dialog asks; "Keep it" leaves the file as it was.
    std::fs::write(dir.join("run1.json"), "kept").unwrap();
    export(&mut h);
    h.get_by_role_and_label(Role::TextInput, "File name").focus();
    h.run_steps(1);
    h.get_by_role_and_label(Role::TextInput, "File name").type_text("run1.json");
    h.run_steps(2);
    h.get_by_role_and_label(Role::Button, "Save").click();
    h.run_steps(2);
    h.get_by_label_contains("run1.json exists. Replace it?");
    h.get_by_label("Keep it").click();
    h.run_steps(2);
    assert_eq!(std::fs::read_to_string(dir.join("run1.json")).unwrap(), "kept");
    // Save again, and replace this time.
    h.get_by_role_and_label(Role::Button, "Save").click();
    h.run_steps(2);
    h.get_by_label("Replace").click();
    h.run_steps(3);
    assert_eq!(std::fs::read_to_string(dir.join("run1.json")).unwrap(), first);
    assert_eq!(written(&dir), ["run1.json"], "no temporary file left");
    assert!(h.query_by_label("Save as").is_none(), "the dialog closed");
    std::fs::remove_dir_all(&dir).ok();
}

/// A thermal field chosen on a THD case, then an isothermal case: the selector names the field drawn
/// (pressure), not the one the isothermal result does not have.
#[test]
fn the_field_selector_names_the_drawn_field_after_switching_to_an_isothermal_case() {
    let persisted = Persisted {
        case_toml: Some(include_str!("../../cases/fillon-a.toml").into()),
        case_name: "test case".into(),
        case_saved: true,
        ..Persisted::default()
    };
    let mut h = solved_app_from(SIZE, persisted, |app| {
        open_fields(app, |f| {
            f.field = FieldKind::PadTemperature;
            f.flowlines = false;
        })
    });
    let selected = |h: &Harness<'_, WorkbenchApp>| h.get_by_role_and_label(Role::ComboBox, "Field").value();
    assert_eq!(selected(&h).as_deref(), Some("Pad surface temperature"));
    h.get_by_label_contains("Colour scale: Pad surface temperature");
    open_preset(&mut h, "compressor-bearing.toml");
    wait_for_solve(&mut h);
    assert!(h.state().shown.clone().unwrap().solution.thermal.is_none());
    assert_eq!(selected(&h).as_deref(), Some("Pressure"));
    h.get_by_label_contains("Colour scale: Pressure");
}

/// At 1280×720 the side panels leave the view a third of the window, the tabs keep to one row inside it
/// and nothing of it lies under the results panel; either side panel can be collapsed for more room.
#[test]
fn the_layout_fits_1280_by_720() {
    let mut h = solved_app_at([1280.0, 720.0], None, |app| app.open::<FieldView>());
    snapshot(&mut h, "layout_1280x720");
    let results_left = h.get_by_role_and_label(Role::Label, "Results").rect().left();
    let view = h.state().view_rect().expect("a view");
    // The editor and results panels grow to their content (about 450 and 390 points): the view keeps a third.
    assert!(view.width() > 0.32 * 1280.0, "{view:?}");
    assert!(view.right() <= results_left, "view {view:?} under the results panel at {results_left}");
    // The tabs keep to one row inside the view; those that do not fit are under "More…".
    let tabs: Vec<(String, egui::Rect)> = tiltpad::app::views::all()
        .iter()
        .filter_map(|v| h.query_by_role_and_label(Role::Button, v.label()).map(|n| (v.label().to_string(), n.rect())))
        .collect();
    assert!(tabs.iter().any(|t| t.0 == "Pad fields"), "the open view's tab is shown: {tabs:?}");
    for (tab, r) in &tabs {
        assert!(r.right() <= results_left && r.left() >= view.left() - 1.0, "{tab} tab at {r:?}");
        assert!((r.top() - tabs[0].1.top()).abs() < 1.0, "{tab} tab on another row: {tabs:?}");
    }
    if tabs.len() < tiltpad::app::views::all().len() {
        let more = h.get_by_label("More…").rect();
        assert!(more.right() <= results_left && (more.top() - tabs[0].1.top()).abs() < 1.0, "{more:?}");
    }
    let legend = h.get_by_label_contains("Colour scale: Pressure").rect();
    assert!(legend.right() <= results_left, "{legend:?}");
    // Collapsing the results panel gives the view its width.
    h.get_by_label("Show results").click();
    h.run();
    let wider = h.state().view_rect().unwrap();
    assert!(wider.width() > view.width() + 200.0, "{view:?} → {wider:?}");
    assert!(h.query_by_role_and_label(Role::Label, "Results").is_none());
}

/// On [`two_bearing_shaft`] (bearings by numbers: each analysis is quick), the disk picked on the sketch.
#[test]
fn a_disk_selected_on_the_rotor_sketch_made_heavier_lowers_the_first_natural_frequency() {
    use tiltpad::app::views::rotor_edit::Selected;
    use tiltpad::app::views::rotor_view::first_mode_at_top_speed;
    let mut h = shaft_with_numbered_bearings();
    // The lowest mode at the sweep's last speed (the file gives no operating range), lightly damped there.
    let first_hz = |h: &Harness<'_, WorkbenchApp>| {
        let view = rotor(h);
        first_mode_at_top_speed(view.result().unwrap(), view.edit().unwrap().rotor()).unwrap()
    };
    let before = first_hz(&h);
    // The 20 kg disk sits at node 5, z = 500 mm of the 1000 mm shaft.
    click_sketch(&mut h, 500.0, 1000.0, 0.0);
    assert_eq!(rotor(&h).edit().unwrap().selected, Some(Selected::Disk(0)));
    // An invalid mass is kept, named with its range, and the last analysis stays.
    spin_button(&h, "mass [kg]").set_value_accesskit(-1.0);
    h.run_steps(3);
    let shown = text_of(&h.get_by_label_contains("Invalid rotor"));
    assert!(shown.contains("rotor.disk[0].mass_kg") && shown.contains("-1"), "{shown}");
    assert!(rotor(&h).is_idle() && first_hz(&h) == before);
    // Twice the mass: every frequency of the rotor–bearing system falls (Rayleigh: more kinetic energy for
    // the same strain energy), the first one too.
    spin_button(&h, "mass [kg]").set_value_accesskit(40.0);
    h.run_steps(2);
    wait_for_rotor(&mut h);
    assert_eq!(rotor(&h).edit().unwrap().file().rotor.disk[0].mass_kg, 40.0);
    let after = first_hz(&h);
    assert_eq!(after.0, before.0, "the same speed");
    assert!(
        after.1 < before.1,
        "heavier disk: first natural frequency {:.3} → {:.3} Hz at {:.0} rpm",
        before.1,
        after.1,
        after.0
    );
    h.get_by_label_contains(&format!("{:.3} Hz", after.1));
    assert!(h.query_by_label_contains("Invalid rotor").is_none());
    snapshot(&mut h, "rotor_edit_disk_selected_1280x720");
}

/// [`two_bearing_shaft`] opened in the rotor view at 1280×720, analysed.
fn shaft_with_numbered_bearings() -> Harness<'static, WorkbenchApp> {
    let mut h =
        solved_app_at([1280.0, 720.0], None, |app| open_rotor(app, &two_bearing_shaft("edited two-bearing shaft")));
    wait_for_rotor(&mut h);
    h
}

/// Clicks the rotor sketch at `z_mm` along a shaft `length_mm` long, `below` points under the axis (the
/// sketch maps the shaft onto its width less 12-point margins, the axis 50 points below its top; bearings
/// are drawn 24 points under it).
fn click_sketch(h: &mut Harness<'_, WorkbenchApp>, z_mm: f32, length_mm: f32, below: f32) {
    let rect = h.get_by_label("rotor sketch").rect();
    let pos = egui::pos2(rect.left() + 12.0 + (rect.width() - 24.0) * z_mm / length_mm, rect.top() + 50.0 + below);
    h.hover_at(pos);
    h.drag_at(pos);
    h.step();
    h.drop_at(pos);
    h.run_steps(2);
}

/// The first free–free flexible frequency [rad/s] the CLI gives for the rotor file `text`.
fn cli_first_free_free(text: &str) -> f64 {
    let path = std::env::temp_dir().join(format!("tiltpad-ui-edited-rotor-{}.toml", std::process::id()));
    std::fs::write(&path, text).unwrap();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_tiltpad"))
        .args(["rotor", path.to_str().unwrap(), "--speeds", "1000:2000:2", "--json", "-"])
        .output()
        .unwrap();
    std::fs::remove_file(&path).ok();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    json["free_free_rad_s"][0].as_f64().unwrap()
}

#[test]
fn shaft_sections_added_and_removed_on_the_sketch_change_mass_and_free_free_frequency_as_the_cli_says() {
    use tiltpad::app::views::rotor_edit::Selected;
    let mut h = shaft_with_numbered_bearings();
    let view = |h: &Harness<'_, WorkbenchApp>| {
        let v = rotor(h);
        (v.edit().unwrap().rotor().mass(), v.result().unwrap().free_free_rad_s[0])
    };
    let (mass, free_free) = view(&h);
    // A 100 mm section of the end section's diameter appended at the end: mass + ρ π d²/4 · 0.1 m, and a
    // longer shaft bends more easily (lower first free–free frequency), as the CLI finds on the saved file.
    h.get_by_label("Add section at end").click();
    wait_for_rotor(&mut h);
    let (longer_mass, longer_ff) = view(&h);
    let section = 7850.0 * std::f64::consts::PI / 4.0 * 0.05_f64.powi(2) * 0.1;
    assert!((longer_mass - mass - section).abs() < 1e-12 * mass, "{mass} → {longer_mass} kg");
    assert!(longer_ff < free_free, "{free_free} → {longer_ff} rad/s");
    let cli = cli_first_free_free(&rotor(&h).edit().unwrap().text().unwrap());
    assert!((cli - longer_ff).abs() < 1e-9 * cli, "view {longer_ff} vs CLI {cli} rad/s");
    // Split the original section (clicked at 250 mm of 1100) in two: the mesh and the mass are unchanged.
    click_sketch(&mut h, 250.0, 1100.0, 0.0);
    assert_eq!(rotor(&h).edit().unwrap().selected, Some(Selected::Section(0)));
    h.get_by_label("Split section").click();
    wait_for_rotor(&mut h);
    assert_eq!(rotor(&h).edit().unwrap().file().rotor.section.len(), 3);
    let (split_mass, split_ff) = view(&h);
    assert!(
        (split_mass - longer_mass).abs() < 1e-14 * mass && (split_ff - longer_ff).abs() < 1e-9 * longer_ff,
        "{longer_ff} → {split_ff} rad/s"
    );
    // Remove its first half (nodes 0–5): the bearing on the removed free end moves to the new end, and the
    // strip says so; the shaft loses 500 mm of Ø 50 mm.
    h.get_by_label("Remove section").click();
    wait_for_rotor(&mut h);
    h.get_by_label_contains("rotor.bearing[0] (on removed node 0) now at node 0");
    let (shorter_mass, shorter_ff) = view(&h);
    assert!((longer_mass - shorter_mass - 5.0 * section).abs() < 1e-12 * mass, "{longer_mass} → {shorter_mass} kg");
    assert_eq!(rotor(&h).edit().unwrap().file().rotor.bearing.iter().map(|b| b.node).collect::<Vec<_>>(), vec![0, 5]);
    let cli = cli_first_free_free(&rotor(&h).edit().unwrap().text().unwrap());
    assert!((cli - shorter_ff).abs() < 1e-9 * cli, "view {shorter_ff} vs CLI {cli} rad/s");
    assert!(shorter_ff > longer_ff, "a shorter shaft is stiffer: {longer_ff} → {shorter_ff} rad/s");
}

#[test]
fn a_bearing_stiffness_given_by_numbers_edited_on_the_sketch_raises_the_first_natural_frequency() {
    use tiltpad::app::views::rotor_edit::Selected;
    use tiltpad::app::views::rotor_view::first_mode_at_top_speed;
    let mut h = shaft_with_numbered_bearings();
    let first_hz = |h: &Harness<'_, WorkbenchApp>| {
        let view = rotor(h);
        first_mode_at_top_speed(view.result().unwrap(), view.edit().unwrap().rotor()).unwrap()
    };
    let before = first_hz(&h);
    click_sketch(&mut h, 0.0, 1000.0, 24.0);
    assert_eq!(rotor(&h).edit().unwrap().selected, Some(Selected::Bearing(0)));
    // An out-of-range stiffness is kept as typed and named with its range; the last analysis stays.
    spin_button(&h, "K xx [N/m]").set_value_accesskit(2e15);
    h.run_steps(3);
    let shown = text_of(&h.get_by_label_contains("Invalid rotor"));
    assert!(
        shown.contains("rotor.bearing[0].k_n_per_m[0]")
            && shown.contains("2000000000000000")
            && shown.contains("[-1e15, 1e15]"),
        "{shown}"
    );
    assert_eq!(rotor(&h).edit().unwrap().file().rotor.bearing[0].k_n_per_m[0][0], 2e15);
    assert!(rotor(&h).is_idle() && first_hz(&h) == before);
    // Ten times stiffer in both directions: every mode of the shaft on these bearings stiffens (Rayleigh:
    // more strain energy for the same kinetic energy), the first one too.
    spin_button(&h, "K xx [N/m]").set_value_accesskit(1e8);
    h.run_steps(2);
    spin_button(&h, "K yy [N/m]").set_value_accesskit(1e8);
    h.run_steps(2);
    wait_for_rotor(&mut h);
    assert_eq!(rotor(&h).edit().unwrap().file().rotor.bearing[0].k_n_per_m[0], [1e8, 0.0, 0.0, 1e8]);
    let after = first_hz(&h);
    assert_eq!(after.0, before.0, "the same speed");
    assert!(
        after.1 > before.1,
        "stiffer bearing: first natural frequency {:.3} → {:.3} Hz at {:.0} rpm",
        before.1,
        after.1,
        after.0
    );
    h.get_by_label_contains(&format!("{:.3} Hz", after.1));
    assert!(h.query_by_label_contains("Invalid rotor").is_none());
    snapshot(&mut h, "rotor_edit_bearing_numbers_1280x720");
}

/// Without a desktop portal, "Open case…" and "Open rotor…" ask for the path in the workbench's own dialog
/// (as the save does): the directory's TOML files are listed to pick from; a file that cannot be read keeps
/// the dialog open with its name and leaves the case on screen; a read case replaces the edited one and a
/// read rotor opens in the Rotor view.
#[test]
fn opening_without_a_portal_asks_for_the_path_in_the_workbench() {
    let mut h = solved_app(None, |_| {});
    h.state_mut().use_workbench_save_dialog();
    let dir = std::env::temp_dir().join(format!("tiltpad-open-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("rig.toml"), include_str!("../../cases/test-rig.toml")).unwrap();
    std::fs::write(dir.join("notes.txt"), "not listed").unwrap();
    let open = |h: &mut Harness<'_, WorkbenchApp>, item: &str| {
        h.get_by_label("File").click();
        h.run_steps(2);
        h.get_by_label(item).click();
        h.run_steps(3);
        h.get_by_role_and_label(Role::TextInput, "Directory").focus();
        h.run_steps(1);
        h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
        h.get_by_role_and_label(Role::TextInput, "Directory").type_text(&dir.display().to_string());
        h.run_steps(2);
    };
    open(&mut h, "Open case…");
    h.get_by_label("Open a case");
    h.get_by_label("TOML files in this directory (1):");
    assert!(h.query_by_label("notes.txt").is_none());
    // Nothing typed: Open is disabled.
    assert!(h.get_by_role_and_label(Role::Button, "Open").accesskit_node().is_disabled());
    // A missing file: the dialog stays with the message; the case on screen is the same.
    h.get_by_role_and_label(Role::TextInput, "File name").focus();
    h.run_steps(1);
    h.get_by_role_and_label(Role::TextInput, "File name").type_text("missing.toml");
    h.run_steps(2);
    h.get_by_role_and_label(Role::Button, "Open").click();
    h.run_steps(2);
    h.get_by_label_contains(&format!("cannot read {}", dir.join("missing.toml").display()));
    assert_eq!(h.state().doc.name, "compressor-bearing.toml");
    // Pick the listed file and open it.
    h.get_by_label("rig.toml").click();
    h.run_steps(2);
    h.get_by_role_and_label(Role::Button, "Open").click();
    h.run_steps(3);
    assert!(h.query_by_label("Open a case").is_none(), "the dialog closed");
    assert_eq!(h.state().doc.name, "rig.toml");
    assert_eq!(h.state().doc.path.as_deref(), Some(std::fs::canonicalize(dir.join("rig.toml")).unwrap().as_path()));
    // A rotor: typed as a full path (the directory field is ignored for an absolute name).
    let rotor_path = std::fs::canonicalize("cases/rotors/compressor-rotor.toml").unwrap();
    open(&mut h, "Open rotor…");
    h.get_by_label("Open a rotor");
    h.get_by_role_and_label(Role::TextInput, "File name").focus();
    h.run_steps(1);
    h.get_by_role_and_label(Role::TextInput, "File name").type_text(&rotor_path.display().to_string());
    h.run_steps(2);
    h.key_press(egui::Key::Enter);
    h.run_steps(3);
    assert_eq!(h.state().open_view().id(), "rotor");
    assert_eq!(h.state().notice.as_deref(), Some(format!("Opened rotor {}", rotor_path.display()).as_str()));
    assert_eq!(rotor(&h).preset, tiltpad::app::views::rotor_view::ROTOR_PRESETS.len());
    std::fs::remove_dir_all(&dir).ok();
}

/// The Control view on the shipped active compressor rotor: with the shipped loop (gain 1) the closed-loop
/// onset lies above the open loop's; the loop-gain slider moved to −1 (the loop's sign flipped) brings it
/// below, without solving a bearing again.
#[test]
fn control_view_gain_slider_moves_the_onset() {
    use tiltpad::app::views::control_view::ControlView;
    let mut h = solved_app_at([1280.0, 720.0], None, |app| app.open::<ControlView>());
    let view = |h: &Harness<'_, WorkbenchApp>| {
        let v = h.state().view::<ControlView>().unwrap();
        let t = v.tuned().expect("the loop closed at the sliders");
        (v.onset_open_rad_s().unwrap(), t.tuning.gain, t.onset_rad_s.unwrap())
    };
    let (open, gain, closed) = view(&h);
    eprintln!("onset open {:.0} rpm, gain {gain}: {:.0} rpm", RPM.from_si(open), RPM.from_si(closed));
    assert_eq!(gain, 1.0);
    assert!(closed > 1.02 * open, "{open} {closed}");
    h.get_by_role_and_label(Role::Slider, "loop gain").set_value_accesskit(-1.0);
    wait_for_solve(&mut h);
    let (open2, gain, flipped) = view(&h);
    eprintln!("gain {gain}: {:.0} rpm", RPM.from_si(flipped));
    assert_eq!((gain, open2), (-1.0, open));
    assert!(flipped < 0.98 * open, "{open} {flipped}");
    h.get_by_label_contains("Onset of instability: loop open");
}

/// Strings that cover one another in the last frame, anywhere in the window, as "a" / "b" at their rects.
pub(crate) fn overlapping_texts(h: &Harness<'_, WorkbenchApp>) -> Vec<String> {
    let texts = painted_text::painted_texts(&h.output().shapes);
    let screen = h.ctx.content_rect();
    painted_text::overlapping(&texts, screen, 2.0)
        .into_iter()
        .map(|(a, b)| format!("{:?} at {:?} / {:?} at {:?}", a.text, a.shown, b.text, b.shown))
        .collect()
}

/// Widgets (labels, buttons, fields, boxes, sliders) that cover one another in the last frame: in the
/// editor, the view and the results panel, each widget whole inside its area (a widget scrolled partly
/// out of its panel is laid out where it would be, not where it shows).
fn overlapping_widgets(h: &Harness<'_, WorkbenchApp>) -> Vec<String> {
    let Some(view) = h.state().view_rect() else { return Vec::new() };
    let (screen, top) = (h.ctx.content_rect(), h.get_by_label("File").rect().bottom());
    let areas = [
        egui::Rect::from_min_max(egui::pos2(screen.left(), top), egui::pos2(view.left() - 1.0, view.bottom())),
        view,
        egui::Rect::from_min_max(egui::pos2(view.right() + 1.0, top), egui::pos2(screen.right(), view.bottom())),
    ];
    let roles =
        [Role::Label, Role::Button, Role::CheckBox, Role::ComboBox, Role::SpinButton, Role::TextInput, Role::Slider];
    let nodes: Vec<(String, egui::Rect)> = roles
        .iter()
        .flat_map(|&role| h.query_all_by_role(role).map(move |n| (format!("{role:?} {:?}", text_of(&n)), n.rect())))
        .collect();
    let mut found = Vec::new();
    for area in areas {
        let inside: Vec<&(String, egui::Rect)> = nodes.iter().filter(|(_, r)| area.contains_rect(*r)).collect();
        for (i, a) in inside.iter().enumerate() {
            // Two labels: a label wrapped beside another spans both lines; their glyphs are checked by
            // `overlapping_texts`.
            for b in inside[i + 1..].iter().filter(|b| !(a.0.starts_with("Label") && b.0.starts_with("Label"))) {
                let common = a.1.intersect(b.1);
                if common.width() > 1.0 && common.height() > 1.0 {
                    found.push(format!("{} at {:?} / {} at {:?}", a.0, a.1, b.0, b.1));
                }
            }
        }
    }
    found
}

/// Strings of the open view cut by their clip rectangle (drawn past the edge of what holds them): those
/// shown inside the view, and those that begin in it and run past its edge (a slider's name past the
/// results panel's edge shows partly outside the view).
pub(crate) fn cut_texts_in_view(h: &Harness<'_, WorkbenchApp>) -> Vec<String> {
    let Some(view) = h.state().view_rect() else { return Vec::new() };
    painted_text::painted_texts(&h.output().shapes)
        .into_iter()
        .filter(|t| view.contains_rect(t.shown) || view.contains(t.full.left_top()))
        .filter(|t| t.shown.width() + 1.0 < t.full.width())
        .map(|t| format!("{:?} shown {:?} of {:?}", t.text, t.shown, t.full))
        .collect()
}

/// Strings inside the open view laid out past its bottom edge (a footer line pushed out of the window).
pub(crate) fn texts_below_view(h: &Harness<'_, WorkbenchApp>) -> Vec<String> {
    let Some(view) = h.state().view_rect() else { return Vec::new() };
    painted_text::painted_texts(&h.output().shapes)
        .into_iter()
        .filter(|t| t.full.left() >= view.left() && t.full.right() <= view.right() + 1.0)
        .filter(|t| t.full.top() < view.bottom() && t.full.bottom() > view.bottom() + 1.0)
        .map(|t| format!("{:?} at {:?} past the view's bottom {}", t.text, t.full, view.bottom()))
        .collect()
}

/// Every view of the list at 1280×720 and 1920×1080, in the dark and the light theme (the light one
/// chosen as a user does, Edit → Theme → Light): no two strings cover one another anywhere in the window
/// (editor, tabs, view, results), no two widgets in the editor, the view or the results panel, and no
/// string in the view is cut at the edge of its area or laid out past its bottom.
#[test]
fn no_text_covers_another_in_any_view_at_1280x720_and_1920x1080_in_both_themes() {
    let mut found = Vec::new();
    for size in [[1280.0, 720.0], [1920.0, 1080.0]] {
        for view in tiltpad::app::views::all() {
            let id = view.id();
            let mut h = solved_app_at(size, None, move |app| assert!(app.open_for_snapshot(id)));
            h.run_steps(4);
            for theme in [egui::Theme::Dark, egui::Theme::Light] {
                if theme == egui::Theme::Light {
                    choose_light_theme(&mut h);
                }
                assert_eq!(h.ctx.theme(), theme, "{id}");
                for o in overlapping_texts(&h) {
                    found.push(format!("{id} at {size:?}, {theme:?}: overlap {o}"));
                }
                for o in overlapping_widgets(&h) {
                    found.push(format!("{id} at {size:?}, {theme:?}: widgets {o}"));
                }
                for c in cut_texts_in_view(&h).into_iter().chain(texts_below_view(&h)) {
                    found.push(format!("{id} at {size:?}, {theme:?}: cut {c}"));
                }
            }
        }
    }
    assert!(found.is_empty(), "{}", found.join("\n"));
}

/// The Control view on the test rig: X/F with control against without, magnitude and phase, from the FRF
/// stage off the UI thread — the same numbers `tiltpad frf --control` writes (run here as a user runs it):
/// at the rig's resonance (60.3 Hz on the band's logarithmic grid) the loop cuts X/F from 167.07 to 96.89 µm/kN,
/// and the closed loop's own peak is 104.97 µm/kN at 64.3 Hz (docs/VALIDATION.md gives the peaks on a 1 Hz grid:
/// 166.8 and 104.9).
#[test]
fn control_view_draws_the_rigs_xf_with_and_without_control_as_the_cli_gives() {
    use tiltpad::app::views::control_view::{ControlView, System};
    let mut h = solved_app_at([1280.0, 720.0], None, |app| {
        app.open::<ControlView>();
        app.view_mut::<ControlView>().unwrap().system = System::Rig;
    });
    wait_for_solve(&mut h);
    let out = std::env::temp_dir().join(format!("tiltpad-rig-loop-{}.json", std::process::id()));
    let status = std::process::Command::new(env!("CARGO_BIN_EXE_tiltpad"))
        .args(["frf", "cases/test-rig-pub5.toml", "--from", "10", "--to", "200", "--points", "191"])
        .args(["--control", "cases/controllers/test-rig-pub5-control.toml", "--json"])
        .arg(&out)
        .status()
        .unwrap();
    assert!(status.success());
    let cli: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&out).unwrap()).unwrap();
    std::fs::remove_file(&out).ok();
    let cli_points = cli["rig_loop"]["points"].as_array().unwrap();
    let view = h.state().view::<ControlView>().unwrap();
    let shown = view.rig.shown().expect("the rig's loop is shown");
    let points = &shown.sweep.points;
    assert_eq!(points.len(), 191);
    assert_eq!(cli_points.len(), points.len());
    let per_kn = |x: f64| UM.from_si(x) * 1000.0;
    let ((open, f_open), (closed, f_closed)) = (shown.sweep.peak(false), shown.sweep.peak(true));
    let at = |f: f64| points.iter().position(|p| p.frequency_hz == f).unwrap();
    let (i_open, i_closed) = (at(f_open), at(f_closed));
    let cli_at = |i: usize, key: &str| cli_points[i][key].as_f64().unwrap();
    eprintln!(
        "view: open peak {:.2} µm/kN at {f_open} Hz (closed there {:.2}), closed peak {:.2} at {f_closed} Hz; \
         CLI at the resonance: open {:.2}, closed {:.2}",
        per_kn(open),
        per_kn(points[i_open].closed_m_per_n),
        per_kn(closed),
        per_kn(cli_at(i_open, "open_m_per_n")),
        per_kn(cli_at(i_open, "closed_m_per_n"))
    );
    // the same numbers as the command, at the resonance and at the closed loop's peak, magnitude and phase
    for i in [i_open, i_closed] {
        let p = &points[i];
        assert_eq!(p.frequency_hz, cli_at(i, "frequency_hz"));
        for (view, key) in [
            (p.open_m_per_n, "open_m_per_n"),
            (p.closed_m_per_n, "closed_m_per_n"),
            (p.open_phase_deg, "open_phase_deg"),
            (p.closed_phase_deg, "closed_phase_deg"),
        ] {
            let c = cli_at(i, key);
            assert!((view - c).abs() <= 1e-12 * c.abs(), "{key} at {} Hz: view {view}, CLI {c}", p.frequency_hz);
        }
    }
    // the curves differ at the resonance by what the command gives (its numbers to 0.01 µm/kN)
    // (the band's points are spaced logarithmically, as the command's: 60.3 and 64.3 Hz are the grid's)
    assert!((f_open - 60.3).abs() < 0.05 && (f_closed - 64.3).abs() < 0.05, "{f_open} {f_closed}");
    assert!((per_kn(open) - 167.07).abs() < 0.005, "{}", per_kn(open));
    assert!((per_kn(points[i_open].closed_m_per_n) - 96.89).abs() < 0.005, "{}", per_kn(points[i_open].closed_m_per_n));
    assert!((per_kn(closed) - 104.97).abs() < 0.005, "{}", per_kn(closed));
    assert!(shown.sweep.stable);
    // both curves drawn, their legend above the plots, the axes named with their units
    h.get_by_label("legend: without control (dashed)");
    h.get_by_label("legend: with control");
    h.get_by_label_contains(
        "X/F peak: without control 167.1 µm/kN at 60 Hz, with control 105.0 µm/kN at 64 Hz (-37 %)",
    );
    assert_eq!(text_of(&h.get_by_role_and_label(Role::ComboBox, "System")), "Test rig, X/F with and without control");
    snapshot(&mut h, "control_rig_xf");
}

/// The Control view on the LQR rotor (`cases/rotors/compressor-rotor-lqr.toml`): the weights, the designed
/// compensator's gains in a table with units, and the closed loop as for the other kinds — its onset is the
/// one `tiltpad control` gives on the view's speeds with the same (preview) bearings, within the
/// interpolation between two of the sweep's speeds (764 rpm apart) that the view does and the command's
/// bisection does not: measured 18 812 against 18 818 rpm closed (0.03 %), 8661 against 8755 rpm open (1.1 %,
/// where the smallest log decrement bends between the grid's speeds).
#[test]
fn control_view_shows_the_lqr_design_and_the_onset_the_cli_gives() {
    use tiltpad::app::views::control_view::{ControlView, System};
    let mut h = solved_app_at([1280.0, 720.0], None, |app| {
        app.open::<ControlView>();
        app.view_mut::<ControlView>().unwrap().system = System::RotorLqr;
    });
    wait_for_solve(&mut h);
    // the command on the same rotor with its bearings at preview fidelity, on the view's speeds
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("cases");
    let text = std::fs::read_to_string(root.join("rotors/compressor-rotor-lqr.toml")).unwrap();
    let bearing = root.join("compressor-bearing-active.toml");
    let text = text.replace(
        "case = \"../compressor-bearing-active.toml\"",
        &format!("case = {:?}\nset = [\"mesh.fidelity=\\\"preview\\\"\"]", bearing.display().to_string()),
    );
    let dir = std::env::temp_dir().join(format!("tiltpad-lqr-view-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("lqr.toml"), text).unwrap();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_tiltpad"))
        .arg("control")
        .arg(dir.join("lqr.toml"))
        .args(["--speeds", "2000:20340:25", "--json", "-"])
        .output()
        .unwrap();
    std::fs::remove_dir_all(&dir).ok();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let cli: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let cli_onset = |key: &str| cli[key]["onset_rad_s"].as_f64().unwrap();
    let view = h.state().view::<ControlView>().unwrap();
    let design = view.lqr().expect("the LQR design");
    let tuned = view.tuned().unwrap();
    let (open, closed) = (view.onset_open_rad_s().unwrap(), tuned.onset_rad_s.unwrap());
    eprintln!(
        "LQR: view onset open {:.0} closed {:.0} rpm; CLI open {:.0} closed {:.0} rpm; reduced {} of {} states",
        RPM.from_si(open),
        RPM.from_si(closed),
        RPM.from_si(cli_onset("onset_open")),
        RPM.from_si(cli_onset("onset_closed")),
        design.reduced_states,
        design.full_states
    );
    assert_eq!((design.reduced_states, design.full_states), (20, 108));
    assert_eq!(cli["lqr"]["reduced_states"].as_u64(), Some(20));
    assert!((closed / cli_onset("onset_closed") - 1.0).abs() < 1e-3, "{closed} {}", cli_onset("onset_closed"));
    assert!((open / cli_onset("onset_open") - 1.0).abs() < 1.5e-2, "{open} {}", cli_onset("onset_open"));
    assert!(closed > 2.0 * open);
    h.get_by_label_contains("Onset of instability: loop open");
    snapshot(&mut h, "control_lqr");
    // the weights and the gains' table with units, one click away
    h.get_by_label_contains("LQR design at 9000 rpm").click();
    h.run_steps(3);
    h.get_by_label_contains("On 20 of the plant's 108 states");
    h.get_by_label("valve 1 at 150 Hz");
    h.get_by_label("node 26 y");
    assert_eq!(h.query_all_by_label_contains(" V/µm, ").count(), 12);
    assert_eq!(h.query_all_by_label("1 1/V²").count(), 2);
    // the journal-0 vertical probe to valve 0 at 150 Hz, in V/µm (the design's compensator)
    h.get_by_label("0.1175 V/µm, +40°");
}

/// The per-pad supply flow row (`operating.pad_supply_flow_l_per_min`) on the starved compressor bearing
/// (mass-conserving films, 25 l/min): ticking "Supply flow per pad" replaces the bearing's supply by its five
/// equal shares (the two keys exclude each other); editing pad 2's field changes that pad's flow alone, and
/// the re-solve offers pad 2 its new flow.
#[test]
fn the_per_pad_supply_flow_row_edits_one_pads_flow() {
    let text = include_str!("../../cases/compressor-bearing-starved.toml").replace("\"standard\"", "\"preview\"");
    let mut h = solved_app_at([1400.0, 2600.0], Some(Box::leak(text.into_boxed_str())), |_| {});
    let per_pad = |h: &Harness<'_, WorkbenchApp>| h.state().doc.file().operating.pad_supply_flow_l_per_min.clone();
    assert_eq!(per_pad(&h), None);
    h.get_by_label("Supply flow per pad").click();
    h.run_steps(2);
    assert_eq!(h.state().doc.file().operating.supply_flow_l_per_min, None);
    assert_eq!(per_pad(&h), Some(tiltpad::model::file::OneOrMany::Many(vec![5.0; 5])));
    // The pads group's per-pad pivot angles come first; the supply row's fields are the operating group's.
    let fields: Vec<_> = h.get_all_by_role_and_label(Role::SpinButton, "pad 2").collect();
    assert_eq!(fields.len(), 2, "pivot angle and supply flow of pad 2");
    fields[1].set_value_accesskit(4.0);
    h.run_steps(2);
    assert_eq!(per_pad(&h), Some(tiltpad::model::file::OneOrMany::Many(vec![5.0, 5.0, 4.0, 5.0, 5.0])));
    wait_for_solve(&mut h);
    let s = h.state().shown.clone().unwrap().solution;
    let offered: Vec<f64> = s
        .inputs
        .operating
        .supply_flow_m3_s
        .clone()
        .expect("per-pad supply")
        .iter()
        .map(|q| L_PER_MIN.from_si(*q))
        .collect();
    for (k, (q, want)) in offered.iter().zip([5.0, 5.0, 4.0, 5.0, 5.0]).enumerate() {
        assert!((q - want).abs() < 1e-9, "pad {k}: {q} l/min");
    }
}
