//! What a new user met in the release build (native, under Xvfb at 1280×720 and 1920×1080), each driven
//! headlessly (egui_kittest) as that user met it: a pin kept from an older workbench, the open dialog in a
//! folder with many sub-folders, the minimum-film labels of the two-pad test rig, the status bar. The
//! helpers are those of [`crate::workbench_ui::harness`].
#![cfg(feature = "gui")]

use egui::accesskit::Role;
use egui_kittest::kittest::Queryable;
use tiltpad::app::state::Persisted;
use tiltpad::app::views::bearing_view::BearingView;
use tiltpad::scene::compare::Pin;

use crate::common::painted_text::painted_texts;
use crate::workbench_ui::harness::{solved_app_at, solved_app_from, spin_button, text_of, wait_for_solve};

const SMALL: [f32; 2] = [1280.0, 720.0];

/// `pin` as an older workbench stored it: without the churning and total power-loss columns.
fn without_power_loss_columns(mut pin: Pin) -> Pin {
    for gone in ["churning_power_w", "total_power_loss_w"] {
        let k = pin.columns.iter().position(|c| c == gone).expect("the pin has the column");
        pin.columns.remove(k);
        pin.cells.remove(k);
    }
    pin
}

/// A pin made before the results had the churning and total power loss (kept across the restart) gets them
/// by solving its case again: the compressor's total 5.599 kW reads in the comparison, the same as the live
/// one (same case), and the pinned values it had stay as pinned (ε set to 0.5 here to tell). On main the
/// cells read "—" for as long as the pin lived.
#[test]
fn a_pin_from_an_older_workbench_gets_the_new_columns_from_its_case() {
    let h = solved_app_at(SMALL, None, |_| {});
    let live = h.state().shown.clone().unwrap().solution;
    let mut pin = without_power_loss_columns(Pin::new("old", &h.state().doc.text().unwrap(), &live));
    pin.cells[0] = Some(0.5);
    drop(h);
    let persisted = Persisted { pins: vec![pin], ..Persisted::default() };
    let h = solved_app_from(SMALL, persisted, |_| {});
    let pin = &h.state().persisted.pins[0];
    assert!(!pin.lacks_columns(), "{:?}", pin.columns);
    let total = pin.value("total_power_loss_w").unwrap();
    assert!((total - live.total_power_loss_w()).abs() <= 1e-9 * total, "{total} against {}", live.total_power_loss_w());
    assert!((total - 5599.1).abs() < 0.1, "the compressor's total power loss: {total} W");
    assert_eq!(pin.value("churning_power_w"), Some(live.churning_power_w()));
    assert_eq!(pin.value("eccentricity_ratio"), Some(0.5), "a pinned value stays");
    assert!(h.query_by_label("n/a").is_none(), "no cell left without its value");
}

/// A pin whose case no longer loads keeps its gaps, and the comparison says "n/a" (not in this pin) rather
/// than "—" (an output the result does not have, as the temperatures of an isothermal solve).
#[test]
fn a_pin_whose_case_does_not_load_says_not_in_this_pin() {
    let h = solved_app_at(SMALL, None, |_| {});
    let live = h.state().shown.clone().unwrap().solution;
    let pin = without_power_loss_columns(Pin::new("broken", "not a case", &live));
    drop(h);
    let persisted = Persisted { pins: vec![pin], ..Persisted::default() };
    let h = solved_app_from(SMALL, persisted, |_| {});
    assert!(h.state().persisted.pins[0].lacks_columns());
    assert_eq!(h.query_all_by_label("n/a").count(), 2, "churning and total");
}

/// In the open dialog the directory's TOML files come before its folders: in the repository's root (ten
/// folders) `Cargo.toml` is the first entry, where on main it sat under the folders, below the list's fold.
#[test]
fn the_open_dialog_lists_the_toml_files_before_the_folders() {
    let mut h = solved_app_at(SMALL, None, |_| {});
    h.state_mut().use_workbench_save_dialog();
    h.get_by_label("File").click();
    h.run_steps(2);
    h.get_by_label("Open case…").click();
    h.run_steps(3);
    h.get_by_role_and_label(Role::TextInput, "Directory").focus();
    h.run_steps(1);
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
    h.get_by_role_and_label(Role::TextInput, "Directory").type_text(env!("CARGO_MANIFEST_DIR"));
    h.run_steps(3);
    let file = h.get_by_label("Cargo.toml").rect();
    let folders: Vec<(String, egui::Rect)> =
        h.query_all_by_role(Role::Button).map(|n| (text_of(&n), n.rect())).filter(|(t, _)| t.ends_with('/')).collect();
    assert!(folders.iter().any(|(t, _)| t == "src/") && folders.iter().any(|(t, _)| t == "../"), "{folders:?}");
    for (name, r) in &folders {
        assert!(file.bottom() <= r.top(), "Cargo.toml at {file:?} below {name} at {r:?}");
    }
}

/// Whether `p` lies in a triangle of a mesh painted in `color` (the bearing view fills each pad so).
fn in_mesh_of(shapes: &[egui::epaint::ClippedShape], color: egui::Color32, p: egui::Pos2) -> bool {
    let inside = |a: egui::Pos2, b: egui::Pos2, c: egui::Pos2| {
        let side = |u: egui::Pos2, v: egui::Pos2| (v.x - u.x) * (p.y - u.y) - (v.y - u.y) * (p.x - u.x);
        let (d1, d2, d3) = (side(a, b), side(b, c), side(c, a));
        (d1 >= 0.0 && d2 >= 0.0 && d3 >= 0.0) || (d1 <= 0.0 && d2 <= 0.0 && d3 <= 0.0)
    };
    shapes.iter().any(|c| match &c.shape {
        egui::Shape::Mesh(m) if m.vertices.first().is_some_and(|v| v.color == color) => m.indices.chunks(3).any(|t| {
            let v = |k: u32| m.vertices[k as usize].pos;
            inside(v(t[0]), v(t[1]), v(t[2]))
        }),
        _ => false,
    })
}

/// The test rig (two thick pads, top and bottom) at 1280×720: each pad's minimum-film label sits outside
/// the pads. On main the top pad's "216.9 µm" was written inside the pad, between its outlines, which the
/// label placement only kept from crossing.
#[test]
fn the_test_rigs_h_min_labels_are_not_written_inside_a_pad() {
    let mut h =
        solved_app_at(SMALL, Some(include_str!("../../cases/test-rig-pub5.toml")), |app| app.open::<BearingView>());
    h.run_steps(2);
    let view = h.state().view_rect().unwrap();
    let shapes = h.output().shapes.clone();
    let labels: Vec<_> =
        painted_texts(&shapes).into_iter().filter(|t| view.contains_rect(t.shown) && t.text.ends_with(" µm")).collect();
    assert_eq!(labels.len(), 2, "one per pad: {labels:?}");
    let pad_fill = egui::Color32::from_rgb(150, 135, 110);
    for l in &labels {
        assert!(!in_mesh_of(&shapes, pad_fill, l.full.center()), "{:?} at {:?} inside a pad", l.text, l.full);
    }
}

/// Without a desktop portal, File → Open case… over unsaved changes: after "Discard changes" the typed-path
/// dialog shows in the frames the workbench asks for itself, with no further input. On main the request
/// for the dialog went out without asking for a frame, and under Xvfb the dialog appeared only when the
/// mouse next moved.
#[test]
fn the_open_dialog_shows_after_discarding_changes_without_another_input() {
    let mut h = solved_app_at(SMALL, None, |_| {});
    h.state_mut().use_workbench_save_dialog();
    spin_button(&h, "Speed").set_value_accesskit(6000.0);
    h.run_steps(2);
    wait_for_solve(&mut h);
    assert!(h.state().doc.is_dirty());
    h.get_by_label("File").click();
    h.run_steps(2);
    h.get_by_label("Open case…").click();
    h.run_steps(2);
    h.get_by_label("Discard changes").click();
    // Only the frames the app asks for: the click's frame, then whatever it requested.
    let _ = h.run_ok();
    assert!(h.query_by_label("Open a case").is_some(), "the dialog waits for an input");
}

/// A failed solve's message (it names the cause, so it is long) is cut at the frame-time label in the
/// status bar, whole on hover, not written under it: the test rig with its load turned to 99° (between its
/// two pads, where no pad carries it) at 1280×720. On main the message ran on under "UI … ms/frame".
#[test]
fn a_long_failure_message_stops_short_of_the_frame_time_in_the_status_bar() {
    let mut h = solved_app_at(SMALL, Some(include_str!("../../cases/test-rig-pub5.toml")), |_| {});
    h.state_mut().hide_timings = false;
    spin_button(&h, "Load direction").set_value_accesskit(99.0);
    h.run_steps(2);
    wait_for_solve(&mut h);
    assert!(matches!(h.state().status, tiltpad::app::Status::Failed(_)), "{:?}", h.state().status);
    let texts = painted_texts(&h.output().shapes);
    let failed = texts.iter().find(|t| t.text.starts_with("Solve failed")).expect("the failure is said").shown;
    let timing = texts.iter().find(|t| t.text.starts_with("UI ")).expect("the frame time").shown;
    assert!(failed.right() <= timing.left(), "the failure at {failed:?} runs under the frame time at {timing:?}");
    assert!((failed.center().y - timing.center().y).abs() < 2.0, "one row");
}
