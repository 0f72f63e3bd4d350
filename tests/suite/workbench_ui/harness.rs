//! The harness the workbench's UI tests share: the app on a case, solved; waiting for its solver, its rotor
//! analysis and its sweep; the editor's fields and the menus as a user reaches them; snapshots.

use std::time::Duration;

use egui::accesskit::Role;
use egui_kittest::kittest::{NodeT, Queryable};
use egui_kittest::{Harness, SnapshotOptions};
use tiltpad::app::state::Persisted;
use tiltpad::app::views::field_view::{FieldSettings, FieldView};
use tiltpad::app::views::rotor_view::RotorView;
use tiltpad::app::views::sweep_view::SweepView;
use tiltpad::app::WorkbenchApp;
use web_time::Instant;

pub(crate) const SIZE: [f32; 2] = [1400.0, 860.0];

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
pub(crate) fn open_fields(app: &mut WorkbenchApp, set: impl FnOnce(&mut FieldSettings)) {
    app.open::<FieldView>();
    set(&mut app.view_mut::<FieldView>().unwrap().settings);
}

pub(crate) fn rotor<'a>(h: &'a Harness<'_, WorkbenchApp>) -> &'a RotorView {
    h.state().view::<RotorView>().unwrap()
}

pub(crate) fn rotor_mut<'a>(h: &'a mut Harness<'_, WorkbenchApp>) -> &'a mut RotorView {
    h.state_mut().view_mut::<RotorView>().unwrap()
}

/// Opens the rotor view on the rotor file `text` (before the first frame: the shipped rotor is not analysed).
pub(crate) fn open_rotor(app: &mut WorkbenchApp, text: &str) {
    app.open::<RotorView>();
    app.view_mut::<RotorView>().unwrap().open_file("shaft.toml", None, text);
}

pub(crate) fn sweep_view<'a>(h: &'a Harness<'_, WorkbenchApp>) -> &'a SweepView {
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

pub(crate) fn spin_button<'a>(h: &'a Harness<'_, WorkbenchApp>, label: &'a str) -> egui_kittest::Node<'a> {
    h.get_by_role_and_label(Role::SpinButton, label)
}

/// Clicks File → Open preset → `name`.
pub(crate) fn open_preset(h: &mut Harness<'_, WorkbenchApp>, name: &str) {
    h.get_by_label("File").click();
    h.run_steps(2);
    h.get_by_label("Open preset").hover();
    h.run_steps(2);
    h.get_by_label(name).click();
    h.run_steps(2);
}

/// Steps frames until the rotor view's analysis has finished.
pub(crate) fn wait_for_rotor(h: &mut Harness<'_, WorkbenchApp>) {
    let start = Instant::now();
    h.run_steps(2);
    while !(rotor(h).is_idle() && rotor(h).result_is_current()) {
        assert!(start.elapsed() < Duration::from_secs(300), "rotor analysis did not finish");
        std::thread::sleep(Duration::from_millis(10));
        h.step();
    }
    h.run_steps(3);
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

/// Runs the sweep view's sweep (its spec set before) and waits for its last point.
pub(crate) fn run_sweep(h: &mut Harness<'_, WorkbenchApp>) -> tiltpad::scene::sweep::SweepTable {
    h.get_by_label("Run sweep").click();
    wait_for_sweep(h)
}

/// Steps frames until the sweep view's sweep has its last point; its table.
pub(crate) fn wait_for_sweep(h: &mut Harness<'_, WorkbenchApp>) -> tiltpad::scene::sweep::SweepTable {
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
