//! The pad deformation view: the loaded pad of the flexible bearing with its modes, and the thermal growth of a
//! TEHD solve.

use egui_kittest::kittest::Queryable;
use egui_kittest::Harness;
use tiltpad::app::views::deformation_view::DeformationView;
use tiltpad::app::WorkbenchApp;
use tiltpad::scene::summary::sig4;
use tiltpad::units::UM;

use super::harness::{snapshot, solved_app, solved_app_at, text_of};

/// The pad-deformation view of the flexible compressor bearing (two modes): the loaded pad's deformed
/// section, its displacement and film maps, the mode gallery with the solved frequencies; hovering the
/// displacement map reads a value in µm within the solved field's range.
#[test]
fn deformation_view_shows_the_loaded_pad_and_its_modes() {
    let text: &'static str = include_str!("../../../cases/compressor-bearing-flexible.toml")
        .replace("pad_modes = 1", "pad_modes = 2")
        .leak();
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
    let text: &'static str = include_str!("../../../cases/compressor-bearing-flexible.toml")
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
