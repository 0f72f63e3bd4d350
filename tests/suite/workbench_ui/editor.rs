//! The editor: an edit re-solves, an invalid value is flagged in place, a drag stays in the valid range, the
//! fidelity group and the per-pad supply flow row.

use std::time::Duration;

use egui::accesskit::Role;
use egui_kittest::kittest::Queryable;
use egui_kittest::Harness;
use tiltpad::app::state::Persisted;
use tiltpad::app::WorkbenchApp;
use tiltpad::units::L_PER_MIN;
use web_time::Instant;

use super::harness::{snapshot, solved_app, solved_app_at, spin_button, text_of, wait_for_solve};

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

/// The per-pad supply flow row (`operating.pad_supply_flow_l_per_min`) on the starved compressor bearing
/// (mass-conserving films, 25 l/min): ticking "Supply flow per pad" replaces the bearing's supply by its five
/// equal shares (the two keys exclude each other); editing pad 2's field changes that pad's flow alone, and
/// the re-solve offers pad 2 its new flow.
#[test]
fn the_per_pad_supply_flow_row_edits_one_pads_flow() {
    let text = include_str!("../../../cases/compressor-bearing-starved.toml").replace("\"standard\"", "\"preview\"");
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

/// The status bar says what the drawing shows. A load dragged on (two steps a frame apart, three times) waits
/// for the running preview solve of the value before it; each frame with the pointer held still, "Solved" is
/// shown only while the drawn result is of the edited load, otherwise the bar says the previous result is
/// shown. (It said "Solved" for a frame after each waited-for solve, over the result of the older value.)
/// After the release, "Solved" is the case's own mesh.
#[test]
fn the_status_bar_says_solved_only_when_the_drawn_result_is_of_the_edited_case() {
    let mut h = solved_app(None, |_| {});
    let drawn_is_edited = |h: &Harness<'_, WorkbenchApp>| {
        let s = h.state().shown.clone().unwrap().solution;
        h.state().doc.validation().as_ref().is_ok_and(|c| s.inputs.operating == c.operating)
    };
    let start = spin_button(&h, "Load W").rect().center();
    h.hover_at(start);
    h.step();
    h.drag_at(start);
    h.step();
    let (mut stale_solved, mut previous_said) = (Vec::new(), 0);
    let mut x = 0.0;
    for _ in 0..3 {
        for _ in 0..2 {
            x += 4.0;
            h.hover_at(start + egui::vec2(x, 0.0));
            h.step();
        }
        let waiting = Instant::now();
        loop {
            std::thread::sleep(Duration::from_millis(5));
            h.step();
            let load = h.state().doc.file().operating.load_n;
            if h.query_by_label_contains("Solved").is_some() && !drawn_is_edited(&h) {
                let drawn = h.state().shown.clone().unwrap().solution.inputs.operating.load;
                stale_solved.push(format!("\"Solved\" over the result of {drawn:?}, the load is {load:?} N"));
            }
            if h.query_by_label_contains("(showing the previous result)").is_some() {
                previous_said += 1;
            }
            if drawn_is_edited(&h) && h.state().is_idle() {
                break;
            }
            assert!(waiting.elapsed() < Duration::from_secs(120), "the drag's solve did not come back");
        }
    }
    assert!(stale_solved.is_empty(), "{}", stale_solved.join("\n"));
    assert!(previous_said > 0, "the bar never said that the previous result is shown");
    assert!(h.state().doc.file().operating.load_n.unwrap() > 1918.0 + 20.0, "the drag moved the load");
    h.drop_at(start + egui::vec2(x, 0.0));
    h.run_steps(2);
    wait_for_solve(&mut h);
    h.get_by_label("Solved");
    let s = h.state().shown.clone().unwrap().solution;
    assert_eq!(Ok(&s.inputs), h.state().doc.validation().as_ref(), "the case's own mesh");
}

/// Large values read in engineering notation (the exponent a multiple of three): the test rig's pivot stiffness
/// 2e7 N/m shows as "20e6" (it showed "20000000"); typed as plain digits, 35000000 is taken and shows as
/// "35e6". Values of everyday size keep their plain form (the speed "3000").
#[test]
fn large_editor_values_read_in_engineering_notation_and_plain_digits_are_taken() {
    let mut h = solved_app_at([1400.0, 2600.0], Some(include_str!("../../../cases/test-rig.toml")), |_| {});
    let shown = |h: &Harness<'_, WorkbenchApp>, label: &str| text_of(&spin_button(h, label));
    assert_eq!(h.state().doc.file().bearing.pads.pivot_stiffness_n_per_m, Some(2e7));
    assert_eq!(shown(&h, "Pivot stiffness"), "20e6");
    assert_eq!(shown(&h, "Speed"), "3000");
    spin_button(&h, "Pivot stiffness").focus();
    h.run_steps(2);
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
    h.event(egui::Event::Text("35000000".into()));
    h.run_steps(1);
    h.key_press(egui::Key::Enter);
    h.run_steps(3);
    assert_eq!(h.state().doc.file().bearing.pads.pivot_stiffness_n_per_m, Some(3.5e7));
    assert_eq!(shown(&h, "Pivot stiffness"), "35e6");
}
