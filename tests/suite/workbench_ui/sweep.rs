//! The sweep view: a load sweep, a preload sweep of the shipped cases, and the Sommerfeld chart.

use egui::accesskit::Role;
use egui_kittest::kittest::Queryable;
use tiltpad::app::views::sweep_view::SweepView;
use tiltpad::scene::sweep::SweepSpec;

use crate::common::painted_text;

use super::harness::{choose_light_theme, run_sweep, snapshot, solved_app, sweep_view, wait_for_sweep};
use super::reading::tick_labels;

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

/// The teaching sweep: preload on the cases that give the pad bore radius (compressor) or the pad clearance
/// (Fillon). Each point's preload replaces the file's key, every point solves, and the view says what was
/// replaced. Cp = Cb / (1 − m) grows with m.
#[test]
fn a_preload_sweep_fills_every_point_of_the_compressor_and_fillon_cases() {
    for (text, replaced) in [
        (None, "bearing.pads.bore_radius_mm = 50.921"),
        (Some(include_str!("../../../cases/fillon-a.toml")), "bearing.pads.clearance_um = 148.0"),
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

/// A sweep knows the design it belongs to. The Sommerfeld chart of the compressor at Cb = 130 µm, then the
/// edit undone (Cb back to 102 µm): the view says the sweep is of an earlier design, marks nothing of the
/// edited case on it and keeps normalising it with the swept design's Cb (re-normalised with 102 µm its
/// h_min/Cb would read 130/102 times too high); one click runs it again for the design on screen. Opening
/// another case does the same; an edit of the swept key itself keeps the sweep current.
#[test]
fn a_sweep_of_an_earlier_design_is_said_to_be_one_and_never_renormalised() {
    use super::harness::{open_preset, spin_button, wait_for_solve};
    let mut h = solved_app(None, |app| app.open::<SweepView>());
    spin_button(&h, "Assembled clearance Cb").set_value_accesskit(130.0);
    wait_for_solve(&mut h);
    h.get_by_label("Sommerfeld chart").click();
    let table = wait_for_sweep(&mut h);
    assert_eq!(sweep_view(&h).shows_edited_design(), Some(true));
    let cb =
        |h: &egui_kittest::Harness<'_, tiltpad::app::WorkbenchApp>| sweep_view(h).chart_geometry().unwrap().clearance_m;
    assert!((cb(&h) - 130e-6).abs() < 1e-12);
    assert!(h.query_by_label_contains("belongs to an earlier design").is_none());
    // An edit of the swept key (the load) keeps the sweep current: its marker moves along the curves.
    spin_button(&h, "Load W").set_value_accesskit(2500.0);
    wait_for_solve(&mut h);
    assert_eq!(sweep_view(&h).shows_edited_design(), Some(true));

    // Undo the load, then the clearance: the chart stays the 130 µm design's and says so.
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
    wait_for_solve(&mut h);
    assert_eq!(h.state().doc.file().bearing.assembled_clearance_um, 102.0);
    assert_eq!(sweep_view(&h).shows_edited_design(), Some(false));
    h.get_by_label_contains("This sweep belongs to an earlier design");
    assert!((cb(&h) - 130e-6).abs() < 1e-12, "normalised with the swept design's Cb, not the edited one's");
    let h_min_over_cb = |g| {
        let plots = tiltpad::scene::sommerfeld::chart(&table, &g);
        let p = plots.iter().find(|p| p.title.contains("h_min / Cb")).expect("an h_min/Cb plot");
        p.curves[0].1.iter().fold(0.0_f64, |m, q| m.max(q[1]))
    };
    let drawn = h_min_over_cb(sweep_view(&h).chart_geometry().unwrap());
    let renormalised = h_min_over_cb(tiltpad::scene::sommerfeld::ChartGeometry::of(
        &h.state().shown.as_ref().unwrap().solution.inputs,
    ));
    assert!((renormalised / drawn - 130.0 / 102.0).abs() < 1e-9, "{drawn} {renormalised}");

    // Run again: the chart of the design on screen.
    h.get_by_label("Run it again for this design").click();
    wait_for_sweep(&mut h);
    assert_eq!(sweep_view(&h).shows_edited_design(), Some(true));
    assert!((cb(&h) - 102e-6).abs() < 1e-12);
    assert!(h.query_by_label_contains("belongs to an earlier design").is_none());

    // Another case opened: the sweep is of the compressor's design.
    open_preset(&mut h, "fillon-a.toml");
    wait_for_solve(&mut h);
    assert_eq!(sweep_view(&h).shows_edited_design(), Some(false));
    h.get_by_label_contains("This sweep belongs to an earlier design");
}
