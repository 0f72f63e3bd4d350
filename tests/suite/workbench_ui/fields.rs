//! The pad field view: pressure, film thickness, temperatures and the local Reynolds number of every pad, the
//! hover readout, flowlines, and the field selector after another case.

use egui::accesskit::Role;
use egui_kittest::kittest::Queryable;
use egui_kittest::Harness;
use tiltpad::app::state::Persisted;
use tiltpad::app::views::field_view::{FieldView, PadChoice};
use tiltpad::app::WorkbenchApp;
use tiltpad::scene::field::FieldKind;
use tiltpad::units::MPA;

use super::harness::{open_fields, open_preset, snapshot, solved_app, solved_app_from, text_of, wait_for_solve, SIZE};

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

/// Fillon's bearing A runs the thermal model (THD, BC1): the film temperature map of all pads, T_max and
/// the thermal group in the results.
#[test]
fn film_temperature_view_of_a_thermal_solve() {
    let mut h = solved_app(Some(include_str!("../../../cases/fillon-a.toml")), |app| {
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
    let mut h = solved_app(Some(include_str!("../../../cases/large-5pad-transition.toml")), |app| {
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
    let rig = include_str!("../../../cases/test-rig.toml")
        .replace("injection_pressure_bar = [10.0, 0.0]", "injection_pressure_bar = [17.0, 0.0]");
    let rig: &'static str = Box::leak(rig.into_boxed_str());
    let mut h = solved_app(Some(rig), |app| open_fields(app, |f| f.pads = PadChoice::All));
    let s = h.state().shown.clone().unwrap().solution;
    assert!(s.pads[0].orifice_flows_m3_per_s[0] > 0.0, "lower pad injects");
    assert!(s.pads[1].orifice_flows_m3_per_s[0] < 0.0, "upper pad's open orifice drains");
    snapshot(&mut h, "flowlines_test_rig_17bar");
}

/// A thermal field chosen on a THD case, then an isothermal case: the selector names the field drawn
/// (pressure), not the one the isothermal result does not have.
#[test]
fn the_field_selector_names_the_drawn_field_after_switching_to_an_isothermal_case() {
    let persisted = Persisted {
        case_toml: Some(include_str!("../../../cases/fillon-a.toml").into()),
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
