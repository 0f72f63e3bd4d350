//! Pins: a result pinned and compared with the live one, the comparison table's layout, the pin dialog.

use egui::accesskit::Role;
use egui_kittest::kittest::Queryable;
use egui_kittest::Harness;
use tiltpad::app::views::coefficients_view::CoefficientsView;
use tiltpad::app::WorkbenchApp;
use tiltpad::scene::field::{FieldKind, PadMap};
use tiltpad::scene::field_compare::difference_maps;
use tiltpad::scene::summary::sig4;
use tiltpad::units::MPA;

use crate::common::painted_text;

use super::harness::{open_fields, snapshot, solved_app_at, spin_button, text_of, wait_for_solve};
use super::reading::{colour_scale, overlapping_texts, overlapping_widgets, p_max_mpa};

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
    // Each quantity's name, wrapped onto as many lines as it takes, stays in its own row: "flow trailing
    // edges out [l/min]" took three lines in a row of two, its unit under "flow sides out".
    let names: Vec<(String, egui::Rect)> =
        comparison_cells(&h).into_iter().filter(|(t, _)| t.chars().next().is_some_and(char::is_alphabetic)).collect();
    assert!(names.len() > 10, "{names:?}");
    for (i, (a, ra)) in names.iter().enumerate() {
        for (b, rb) in &names[i + 1..] {
            assert!(
                ra.intersect(*rb).height() < 1.0 || ra.intersect(*rb).width() < 1.0,
                "{a:?} at {ra:?} over {b:?} at {rb:?}"
            );
        }
    }

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
        let load = cells.iter().find(|(t, _)| t == "Load [kN]").expect("the load row").1;
        let row: Vec<&str> = cells
            .iter()
            .filter(|(_, r)| (r.center().y - load.center().y).abs() < 1.0)
            .map(|(t, _)| t.as_str())
            .collect();
        assert_eq!(row[..3], ["Load [kN]", "1.918", "1.918"], "{size:?}");
        // Every quantity reads whole (a long name wraps): no cell is cut with "…".
        let view = h.state().view_rect().unwrap();
        let cut: Vec<String> = painted_text::painted_texts(&h.output().shapes)
            .into_iter()
            .filter(|t| t.shown.left() > view.right() && t.text.ends_with('…'))
            .map(|t| t.text)
            .collect();
        assert!(cut.is_empty(), "{size:?}: cut names {cut:?}");
        assert!(cells.iter().any(|(t, _)| t.starts_with("Eccentricity ε")), "{size:?}");
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

/// A pin of another bearing geometry is never drawn over the journal: pinned at Cb = 102 µm, then the
/// clearance edited to 130 µm, the bearing view draws the two side by side, each at its own scales, and says
/// why; back at 102 µm (another speed, the same geometry) the pin is overlaid again.
#[test]
fn a_pin_of_another_geometry_is_drawn_beside_the_bearing_not_over_it() {
    let mut h = solved_app_at([1280.0, 720.0], None, |_| {});
    h.get_by_label("Pin current result").click();
    h.run_steps(2);
    h.key_press(egui::Key::Escape);
    spin_button(&h, "Assembled clearance Cb").set_value_accesskit(130.0);
    wait_for_solve(&mut h);
    assert!(h.query_by_label_contains("Pinned \"pin 1\" (dashed").is_none(), "not overlaid");
    h.get_by_label(
        "Pinned \"pin 1\" is another bearing (its Cb 102 µm, this one's 130 µm): drawn beside this one at its own \
         scales, not over it; the results panel compares the numbers.",
    );
    h.get_by_label("Live");
    snapshot(&mut h, "compare_pin_other_geometry_1280x720");
    spin_button(&h, "Assembled clearance Cb").set_value_accesskit(102.0);
    spin_button(&h, "Speed").set_value_accesskit(6000.0);
    wait_for_solve(&mut h);
    h.get_by_label_contains("Pinned \"pin 1\" (dashed");
    assert!(h.query_by_label_contains("is another bearing").is_none());
}
