//! The rotor view: the compressor rotor's analysis and tabs, a rotor file, and edits on the rotor sketch.

use egui_kittest::kittest::Queryable;
use egui_kittest::Harness;
use tiltpad::app::views::rotor_view::RotorView;
use tiltpad::app::WorkbenchApp;
use tiltpad::model::rotor::CoefficientModel;
use tiltpad::scene::rotor::unbalance_bode;
use tiltpad::units::RPM;

use super::harness::{
    open_rotor, rotor, rotor_mut, snapshot, solved_app, solved_app_at, spin_button, text_of, two_bearing_shaft,
    wait_for_rotor,
};

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
    assert!(!view.is_idle() && !view.result_is_current(), "a new analysis runs; the full one is not current");
    h.get_by_label_contains("Analysing on the edited case");
    h.get_by_label_contains("the analysis of an earlier design");
}

/// The compressor case at preview fidelity (the rotor's analyses stay quick).
fn preview_compressor() -> &'static str {
    let text = include_str!("../../../cases/compressor-bearing.toml");
    Box::leak(text.replace("fidelity = \"standard\"", "fidelity = \"preview\"").into_boxed_str())
}

/// The onset the rotor view shows [rpm].
fn onset_rpm(h: &egui_kittest::Harness<'_, WorkbenchApp>) -> f64 {
    RPM.from_si(rotor(h).result().unwrap().onset.as_ref().expect("an onset in the sweep").speed_rad_s)
}

/// The rotor runs on the edited bearing, says so, and follows an edit of it: the assembled clearance
/// 102 → 130 µm through the editor re-runs the analysis (the earlier one stays on screen, said to be of an
/// earlier design, until it is done), every bearing position that names a case then has Cb = 130 µm, and the
/// onset moves.
#[test]
fn the_rotor_runs_on_the_edited_bearing_and_an_edit_of_it_moves_the_onset() {
    let mut h = solved_app(Some(preview_compressor()), |app| app.open::<RotorView>());
    wait_for_rotor(&mut h);
    let uses = rotor(&h).uses().unwrap().sentence();
    assert!(uses.starts_with("Bearings: the edited case test case (preview fidelity) at nodes 7, 49;"), "{uses}");
    h.get_by_label(&uses);
    let before = onset_rpm(&h);
    spin_button(&h, "Assembled clearance Cb").set_value_accesskit(130.0);
    h.run_steps(2);
    assert_eq!(h.state().doc.file().bearing.assembled_clearance_um, 130.0);
    assert!(!rotor(&h).result_is_current(), "the edit starts a new analysis");
    h.get_by_label_contains("the analysis of an earlier design");
    wait_for_rotor(&mut h);
    let clearances: Vec<f64> = rotor(&h)
        .analysed_rotor()
        .unwrap()
        .bearings
        .iter()
        .filter_map(|b| match &b.support {
            tiltpad::model::rotor::BearingSupport::Case { case, .. } => Some(case.bearing.assembled_clearance_m),
            tiltpad::model::rotor::BearingSupport::Numbers(_) => None,
        })
        .collect();
    assert_eq!(clearances, vec![130e-6, 130e-6]);
    let after = onset_rpm(&h);
    h.get_by_label_contains(&format!("Onset of instability: {after:.0} rpm"));
    // Measured: 9414 -> 11507 rpm (the looser bearing's lower cross-coupled stiffness outweighs its lower
    // damping on this rotor); the shipped cases' onset is what it was before the edit.
    assert!(after > 1.1 * before, "onset {before:.0} -> {after:.0} rpm");
    h.get_by_label(&rotor(&h).uses().unwrap().sentence());
}

#[test]
fn a_rotor_file_opens_in_the_rotor_view_and_a_bad_one_names_key_value_and_range() {
    let text = two_bearing_shaft("opened two-bearing shaft");
    let opened = text.clone();
    let mut h = solved_app(None, move |app| open_rotor(app, &opened));
    wait_for_rotor(&mut h);
    h.get_by_label_contains("opened two-bearing shaft");
    assert!(rotor(&h).result().is_some_and(|r| !r.critical_speeds.is_empty()));
    // Its bearings are its own (numbers): said so, and no choice of the edited case is offered.
    h.get_by_label_contains("Bearings: the rotor file's bearings (given by numbers) at nodes 0, 10;");
    assert!(h.query_by_label_contains("on the rotor file's cases").is_none());
    rotor_mut(&mut h).open_file("bad.toml", None, &text.replace("node = 5", "node = 11"));
    h.run_steps(3);
    let shown = text_of(&h.get_by_label_contains("Cannot read the rotor"));
    assert!(shown.contains("rotor.disk[0].node") && shown.contains("11") && shown.contains("[0, 10]"), "{shown}");
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

/// At 1280×720 the unbalance response's two plots lie inside the view (side by side there), each with its
/// axis titles whole and its numbered ticks: stacked, the phase plot's lower half (its −180° and its speed
/// axis) ran past the view's bottom.
#[test]
fn the_unbalance_response_keeps_both_plots_inside_the_view_at_1280x720() {
    let mut h = solved_app_at([1280.0, 720.0], None, |app| app.open::<RotorView>());
    wait_for_rotor(&mut h);
    h.get_by_label("Unbalance response").click();
    h.run_steps(3);
    let view = h.state().view_rect().unwrap();
    for plot in ["orbit p-p [µm]", "phase of x [°]"] {
        let r = h.get_by_label(&format!("plot: unbalance response, {plot} against speed [rpm]")).rect();
        // (Every rotor plot's frame reaches 2.5 points into the panel's right margin, inside its clip.)
        assert!(view.expand2(egui::vec2(3.0, 0.0)).contains_rect(r), "{plot} plot at {r:?} outside the view {view:?}");
    }
    // Their speed axes' titles too, whole; and numbered ticks: on the amplitude axis, and every 90° of phase.
    let texts = crate::common::painted_text::painted_texts(&h.output().shapes);
    let titles: Vec<egui::Rect> = texts.iter().filter(|t| t.text == "speed [rpm]").map(|t| t.full).collect();
    assert!(titles.len() == 2 && titles.iter().all(|t| view.contains_rect(*t)), "{titles:?} in {view:?}");
    for title in ["orbit p-p [µm]", "phase of x [°]"] {
        let t = texts.iter().find(|t| t.text == title).unwrap();
        // (A rotated axis title starts 2 points into the panel's left margin, inside its clip.)
        let view = view.expand2(egui::vec2(3.0, 0.0));
        assert!(view.contains_rect(t.full) && t.shown.height() + 1.0 >= t.full.height(), "{title}: {t:?}");
    }
    let y_ticks = |plot: &str| {
        let r = h.get_by_label(&format!("plot: unbalance response, {plot} against speed [rpm]")).rect();
        let mut ticks: Vec<String> = texts
            .iter()
            .filter(|t| {
                view.contains_rect(t.full) && t.full.right() <= r.left() + 1.0 && t.full.left() > r.left() - 50.0
            })
            .filter(|t| r.y_range().contains(t.full.center().y))
            .filter(|t| t.text.trim_end_matches('°').parse::<f64>().is_ok())
            .map(|t| t.text.clone())
            .collect();
        ticks.sort();
        ticks
    };
    assert!(y_ticks("orbit p-p [µm]").len() >= 2, "{:?}", y_ticks("orbit p-p [µm]"));
    assert_eq!(y_ticks("phase of x [°]"), ["-180°", "-90°", "0°", "180°", "90°"]);
    snapshot(&mut h, "rotor_unbalance_1280x720");
}

/// At 1280×720 every field of a bearing given by numbers lies inside the view: a label and its field move
/// to the next row together (the last field, "C yy", ran past the view's right edge).
#[test]
fn the_fields_of_a_bearing_given_by_numbers_lie_inside_the_view_at_1280x720() {
    use tiltpad::app::views::rotor_edit::Selected;
    let mut h = shaft_with_numbered_bearings();
    click_sketch(&mut h, 0.0, 1000.0, 24.0);
    assert_eq!(rotor(&h).edit().unwrap().selected, Some(Selected::Bearing(0)));
    let view = h.state().view_rect().unwrap();
    for matrix in ["K", "C"] {
        for entry in ["xx", "xy", "yx", "yy"] {
            let unit = if matrix == "K" { "N/m" } else { "N·s/m" };
            let label = format!("{matrix} {entry} [{unit}]");
            let field = spin_button(&h, &label).rect();
            let name = h.get_by_label(&label).rect();
            assert!(view.contains_rect(field), "{label}: field at {field:?} outside the view {view:?}");
            assert!((name.center().y - field.center().y).abs() < 4.0, "{label}: name at {name:?}, field at {field:?}");
        }
    }
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
