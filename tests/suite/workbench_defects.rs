//! Defects a new user met in the workbench, each driven headlessly (egui_kittest) as that user met it: a
//! long case title in the editor, the tab row when a view opens from its "More" menu, the status bar after
//! an edit, the minimum-film labels of the bearing view, the rotor's mass, the power loss in the results
//! panel, and the Control view's LQR page at 1280×720. The helpers are those of [`crate::workbench_ui::harness`].
#![cfg(feature = "gui")]

use egui::accesskit::Role;
use egui::epaint::{ColorMode, Shape};
use egui::{Color32, Pos2, Rect};
use egui_kittest::kittest::Queryable;
use egui_kittest::Harness;
use tiltpad::app::views::bearing_view::BearingView;
use tiltpad::app::WorkbenchApp;

use crate::common::painted_text;
use crate::workbench_ui::harness::{
    choose_light_theme, edit_and_solve, open_rotor, rotor, snapshot, solved_app_at, spin_button, text_of,
    two_bearing_shaft, wait_for_rotor, wait_for_solve,
};
use crate::workbench_ui::reading::{cut_texts_in_view, texts_below_view};

const SMALL: [f32; 2] = [1280.0, 720.0];

/// The compressor bearing's title (57 characters) reads whole in the editor's Title field at 1280×720: the
/// field wraps it over as many rows as it needs, and no row of it is cut at the field's edge.
#[test]
fn a_long_title_reads_whole_in_the_editor() {
    let h = solved_app_at(SMALL, None, |_| {});
    let title = h.state().doc.file().title.clone().expect("the shipped case has a title");
    assert!(title.chars().count() > 40, "{title}");
    let field = h.get_by_role_and_label(Role::MultilineTextInput, "Title").rect();
    let rows: Vec<painted_text::PaintedText> =
        painted_text::painted_texts(&h.output().shapes).into_iter().filter(|t| field.intersects(t.shown)).collect();
    for r in &rows {
        assert!(r.shown.width() + 1.0 >= r.full.width(), "{:?} shown {:?} of {:?}", r.text, r.shown, r.full);
    }
    // 200 points wide: two or three rows, not a column of syllables.
    assert!(field.width() >= 199.0 && (2..=3).contains(&rows.len()), "{field:?}: {rows:?}");
    let shown: String = rows.iter().map(|r| r.text.as_str()).collect::<String>().replace(' ', "");
    assert_eq!(shown, title.replace(' ', ""), "the field shows {rows:?}");
}

/// The buttons of the tab row (the views' tabs and the "More" menu's button) and where they are.
fn tab_row(h: &Harness<'_, WorkbenchApp>) -> Vec<(String, Rect)> {
    let top = h.get_by_role_and_label(Role::Button, "Bearing").rect().top();
    h.query_all_by_role(Role::Button)
        .filter(|n| (n.rect().top() - top).abs() < 1.0)
        .map(|n| (text_of(&n), n.rect()))
        .collect()
}

/// At 1280×720 the tab row holds the first views and a "More…" menu. Opening a view from that menu moves no
/// tab: every tab stays where the user saw it, and the menu's button reads as the open view's tab.
#[test]
fn opening_a_view_from_the_more_menu_moves_no_tab() {
    let mut h = solved_app_at(SMALL, None, |_| {});
    let before = tab_row(&h);
    let labels: Vec<&str> = tiltpad::app::views::all().iter().map(|v| v.label()).collect();
    let hidden: Vec<&str> = labels.iter().copied().filter(|l| !before.iter().any(|(t, _)| t == l)).collect();
    assert!(!hidden.is_empty() && before.iter().any(|(t, _)| t == "More…"), "{before:?}");
    let more = before.iter().find(|(t, _)| t == "More…").unwrap().1;
    h.get_by_role_and_label(Role::Button, "More…").click();
    h.run_steps(2);
    // The first view in the menu: on main its wider tab took the place of the last tabs of the row.
    h.get_by_role_and_label(Role::Button, hidden[0]).click();
    h.run_steps(3);
    assert_eq!(h.state().open_view().label(), hidden[0]);
    let after = tab_row(&h);
    for (label, rect) in before.iter().filter(|(t, _)| t != "More…") {
        let now = after.iter().find(|(t, _)| t == label).map(|t| t.1);
        assert_eq!(now, Some(*rect), "the {label} tab moved: {before:?} → {after:?}");
    }
    let named = hidden[0].to_string();
    let button = after.iter().find(|(t, _)| *t == named).unwrap_or_else(|| panic!("{named} in {after:?}")).1;
    assert!((button.left() - more.left()).abs() < 0.5, "{more:?} → {button:?}");
    assert_eq!(after.len(), before.len(), "{before:?} → {after:?}");
}

/// "Opened <file>" describes the case as opened: after an edit the status bar no longer says it.
#[test]
fn the_status_bar_drops_opened_file_after_an_edit() {
    let text = include_str!("../../cases/compressor-bearing.toml");
    let mut h = solved_app_at(SMALL, None, move |app| app.load_text("my-bearing.toml", None, text));
    h.get_by_label("Opened my-bearing.toml");
    spin_button(&h, "Speed").set_value_accesskit(6000.0);
    h.run_steps(2);
    wait_for_solve(&mut h);
    assert_eq!(h.state().doc.file().operating.speed_rpm, 6000.0);
    assert!(h.query_by_label("Opened my-bearing.toml").is_none());
    assert_eq!(h.state().notice, None);
}

/// Points of the painted polylines stroked in `colors` (the bearing view's pad edges and pivots), every
/// half point along each segment.
fn stroked_points(h: &Harness<'_, WorkbenchApp>, colors: &[Color32]) -> Vec<Pos2> {
    let mut points = Vec::new();
    for c in &h.output().shapes {
        if let Shape::Path(p) = &c.shape {
            if !matches!(p.stroke.color, ColorMode::Solid(col) if colors.contains(&col)) {
                continue;
            }
            let mut line = p.points.clone();
            if p.closed {
                line.extend(p.points.first().copied());
            }
            for s in line.windows(2) {
                let n = (s[0].distance(s[1]) * 2.0).ceil().max(1.0);
                #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
                points.extend((0..=n as usize).map(|k| s[0].lerp(s[1], k as f32 / n)));
            }
        }
    }
    points
}

/// The bearing view at 1280×720 and 1920×1080: each pad's minimum film thickness label ("53.95 µm") keeps
/// clear of every pad outline and pivot (on main they were written 30 points out from the film surface,
/// over the pads).
#[test]
fn h_min_labels_keep_clear_of_the_pad_outlines() {
    for size in [SMALL, [1920.0, 1080.0]] {
        let mut h = solved_app_at(size, None, |app| app.open::<BearingView>());
        h.run_steps(2);
        let view = h.state().view_rect().unwrap();
        let outlines = stroked_points(&h, &[Color32::from_gray(40), Color32::from_gray(20)]);
        assert!(outlines.len() > 1000, "{}", outlines.len());
        let labels: Vec<painted_text::PaintedText> = painted_text::painted_texts(&h.output().shapes)
            .into_iter()
            .filter(|t| view.contains_rect(t.shown) && t.text.ends_with(" µm"))
            .collect();
        assert_eq!(labels.len(), 5, "one per pad: {labels:?}");
        for l in &labels {
            assert!(l.shown.width() + 1.0 >= l.full.width(), "{l:?} cut");
            let touching = outlines.iter().filter(|p| l.full.expand(1.0).contains(**p)).count();
            assert_eq!(touching, 0, "{size:?}: {:?} at {:?} touches the pads", l.text, l.full);
        }
    }
}

/// The rotor's mass in the rotor view's title in engineering notation with four digits, as every other
/// number: the two-bearing shaft (Ø 50 mm × 1000 mm of steel and a 20 kg disk) weighs 35.4 kg, which the
/// view wrote "35 kg".
#[test]
fn the_rotor_mass_reads_in_engineering_notation() {
    let text = two_bearing_shaft("mass check");
    let mut h = solved_app_at(SMALL, None, move |app| open_rotor(app, &text));
    wait_for_rotor(&mut h);
    let mass = rotor(&h).analysed_rotor().unwrap().mass();
    assert!((mass - 35.4).abs() < 0.1, "{mass}");
    let shown = text_of(&h.get_by_label_contains("mass check — "));
    assert_eq!(shown, format!("mass check — {} kg", tiltpad::number::sig(mass, 4)));
}

/// The flooded compressor bearing (isothermal, preview mesh): the results panel shows the films' friction,
/// the housing's churning and their total, in engineering notation with the one prefix of the largest (kW,
/// the churning's 147.3 W as 0.1473 kW), where it showed the friction alone as "Power loss".
#[test]
fn the_results_panel_shows_friction_churning_and_total_power_loss() {
    let text = include_str!("../../cases/compressor-bearing-power-loss.toml")
        .replace("model = \"thd\"", "model = \"isothermal\"")
        .replace("\"standard\"", "\"preview\"");
    let h = solved_app_at(SMALL, Some(Box::leak(text.into_boxed_str())), |_| {});
    let s = h.state().shown.clone().unwrap().solution;
    let (friction, churning) = (s.friction_power_w, s.churning_power_w());
    // 5459 W and 147.3 W here.
    assert!(churning > 0.0 && friction > 0.0, "{friction} {churning}");
    assert!(((friction + churning) / s.total_power_loss_w() - 1.0).abs() < 1e-12);
    assert!(h.query_by_label("Power loss").is_none());
    for (label, watts) in
        [("Film friction", friction), ("Churning", churning), ("Total power loss", s.total_power_loss_w())]
    {
        let row = h.get_by_role_and_label(Role::Label, label).rect();
        let (scale, unit) = tiltpad::number::eng_prefix(s.total_power_loss_w());
        let (value, unit) = ([tiltpad::number::sig(watts / scale, 4)], format!("{unit}W"));
        let at = |t: &str| {
            h.query_all_by_label(t).find(|n| (n.rect().center().y - row.center().y).abs() < 2.0).map(|n| n.rect())
        };
        assert!(at(&value[0]).is_some() && at(&unit).is_some(), "{label}: {} {unit}", value[0]);
    }
}

/// The Control view's LQR page at 1280×720: no text is cut (the last speed tick, "20 000" on main shown as
/// "200", and the "root locus at" slider's name), nothing runs below the view, and with the design's
/// table collapsed the stability map gets its room.
#[test]
fn the_control_views_lqr_page_fits_1280x720() {
    use tiltpad::app::views::control_view::{ControlView, System};
    let mut h = solved_app_at(SMALL, None, |app| {
        app.open::<ControlView>();
        app.view_mut::<ControlView>().unwrap().system = System::RotorLqr;
    });
    wait_for_solve(&mut h);
    h.run_steps(4);
    let cut: Vec<String> = cut_texts_in_view(&h).into_iter().chain(texts_below_view(&h)).collect();
    assert!(cut.is_empty(), "{}", cut.join("\n"));
    // The stability map: from below its legend to its axis title.
    let texts = painted_text::painted_texts(&h.output().shapes);
    let legend = h.query_all_by_label("open (dashed)").map(|n| n.rect().bottom()).fold(f32::INFINITY, f32::min);
    let axis = texts.iter().filter(|t| t.text == "speed [rpm]").map(|t| t.full.top()).fold(f32::INFINITY, f32::min);
    eprintln!("stability map from {legend} to {axis}: {} points", axis - legend);
    assert!(axis - legend > 150.0, "the stability map is {} points tall", axis - legend);
    // Each legend entry on one line: "API 617 (dotted)" broke after "API".
    let api = h.get_by_label("API 617 (dotted)").rect();
    assert!(api.height() < 20.0, "{api:?}");
    // The light theme (the dark one is `control_lqr.png`): nothing cut either.
    choose_light_theme(&mut h);
    let cut: Vec<String> = cut_texts_in_view(&h).into_iter().chain(texts_below_view(&h)).collect();
    assert!(cut.is_empty(), "{}", cut.join("\n"));
    snapshot(&mut h, "control_lqr_1280x720_light");
}

/// The compressor bearing at 2920 N unloads pad 0 (a round-off force of about 1e-7 N): the pads table wrote
/// its force "7.485e-11" kN, wider than the column, over the orifice flow beside it. The column now shares
/// the decimals of its largest value: 0.000 kN.
#[test]
fn an_unloaded_pads_force_reads_zero_in_the_pads_table() {
    let mut h = solved_app_at(SMALL, None, |_| {});
    edit_and_solve(&mut h, "operating.load_n", |f| f.operating.load_n = Some(2920.0));
    let s = h.state().shown.clone().unwrap().solution;
    let pads = tiltpad::scene::summary::summary(&s).pads;
    assert!(pads[0].unloaded && pads[0].load_n.abs() < 1e-3, "pad 0: {:?}", pads[0]);
    let (row, column) = (h.get_by_label("0 *").rect(), h.get_by_label("load\n[kN]").rect());
    let in_row: Vec<String> = h
        .query_all_by_role(Role::Label)
        .filter(|n| (n.rect().center().y - row.center().y).abs() < 2.0)
        .map(|n| text_of(&n))
        .collect();
    assert!(in_row.iter().all(|t| !t.contains("e-")), "a number in e-notation: {in_row:?}");
    let force: Vec<String> = h
        .query_all_by_role(Role::Label)
        .filter(|n| (n.rect().center().y - row.center().y).abs() < 2.0)
        .filter(|n| n.rect().left() >= column.left() - 1.0 && n.rect().left() < column.right())
        .map(|n| text_of(&n))
        .collect();
    assert_eq!(force, ["0.000"]);
}

/// The pad deformation view at 1280×720 in both themes (its shipped flexible-pad case): no text lies on a
/// pivot's wedge. The retained mode's title ("Mode 1: 10889 Hz, amplitude 2.183 µm") ran over the wedge
/// of its section, 12 points tall above the pad's back, which the drawing had not left room for.
#[test]
fn no_text_lies_on_a_pivot_wedge_of_the_deformation_view() {
    let mut h = solved_app_at(SMALL, None, |app| assert!(app.open_for_snapshot("pad_deformation")));
    h.run_steps(4);
    for theme in [egui::Theme::Dark, egui::Theme::Light] {
        if theme == egui::Theme::Light {
            choose_light_theme(&mut h);
        }
        let wedges: Vec<Rect> = h
            .output()
            .shapes
            .iter()
            .filter_map(|c| match &c.shape {
                Shape::Path(p) if p.closed && p.points.len() == 3 && p.fill == Color32::from_gray(120) => {
                    Some(Rect::from_points(&p.points))
                }
                _ => None,
            })
            .collect();
        // The loaded pad's section and one per retained mode.
        assert!(wedges.len() >= 2, "{wedges:?}");
        for t in painted_text::painted_texts(&h.output().shapes) {
            for w in &wedges {
                let common = t.shown.intersect(w.shrink(0.5));
                assert!(!common.is_positive(), "{theme:?}: {:?} at {:?} on the wedge at {w:?}", t.text, t.shown);
            }
        }
    }
}
