//! Every view of the list: its snapshots at 1280×720 in both themes, the layout at 1280×720, no text over
//! text at 1280×720 and 1920×1080, and what a view says when its case lacks what it draws.

use egui::accesskit::Role;
use egui_kittest::kittest::Queryable;
use tiltpad::app::views::deformation_view::DeformationView;
use tiltpad::app::views::field_view::FieldView;

use super::harness::{choose_light_theme, snapshot, snapshot_options, solved_app, solved_app_at};
use super::reading::{cut_texts_in_view, overlapping_texts, overlapping_widgets, texts_below_view};

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
fn views_without_their_inputs_say_what_is_missing() {
    let mut h = solved_app(None, |app| app.open::<DeformationView>());
    h.get_by_label_contains("bending modes");
    h.get_by_label("FRF").click();
    h.run();
    h.get_by_label_contains("no [hydraulics] section");
    snapshot(&mut h, "placeholder_frf");
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

/// Every view at 1280×720 names what a screen reader (and a test) finds in it: each plot says what it shows
/// (egui_plot left its area an unnamed node: four in the coefficient view, two in the FRF view, one in the
/// rotor view, three in the Control view), no control or picture is unnamed, every legend sample is
/// "legend: <name>" (the rotor's were "legend sample: …"), and an optional value whose default is a rule
/// says the rule without a unit ("unchecked: rigid pivot", not "rigid pivot N/m").
#[test]
fn every_view_names_its_plots_and_controls() {
    use egui_kittest::kittest::NodeT;
    let mut unnamed = Vec::new();
    let mut plots = std::collections::BTreeMap::new();
    for view in tiltpad::app::views::all() {
        let id = view.id();
        let h = solved_app_at([1280.0, 720.0], None, move |app| assert!(app.open_for_snapshot(id)));
        for n in h.query_all_by(|_| true) {
            let a = n.accesskit_node();
            let (role, label) = (a.role(), a.label().unwrap_or_default());
            let named = [
                Role::Unknown,
                Role::Image,
                Role::Button,
                Role::CheckBox,
                Role::ComboBox,
                Role::SpinButton,
                Role::Slider,
                Role::TextInput,
                Role::MultilineTextInput,
            ];
            if named.contains(&role) && label.trim().is_empty() {
                unnamed.push(format!("{id}: an unnamed {role:?} at {:?}", n.rect()));
            }
            if label.starts_with("legend sample") || label.contains("rigid pivot N/m") {
                unnamed.push(format!("{id}: {role:?} {label:?}"));
            }
            if let Some(plot) = label.strip_prefix("plot: ") {
                plots.entry(id).or_insert_with(Vec::new).push(plot.to_string());
            }
        }
    }
    assert!(unnamed.is_empty(), "{}", unnamed.join("\n"));
    let counts: Vec<(&str, usize)> = plots.iter().map(|(id, p)| (*id, p.len())).collect();
    assert_eq!(counts, [("coefficients", 4), ("control", 3), ("frf", 2), ("rotor", 1)], "{plots:#?}");
    assert!(plots["frf"].contains(&"|G| [V/V] of G1 against frequency [Hz]".to_string()), "{:?}", plots["frf"]);
}
