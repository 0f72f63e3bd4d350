//! Locked scales: the field view's colour scale and the bearing view's film exaggeration and pressure scale
//! stay across edits.

use egui_kittest::kittest::Queryable;
use tiltpad::app::views::bearing_view::BearingView;
use tiltpad::app::views::field_view::FieldView;
use tiltpad::scene::summary::sig4;

use super::harness::{edit_and_solve, open_fields, solved_app};
use super::reading::{colour_scale, p_max_mpa};

/// Locked, the pad field colour scale stays through two edits that change the peak pressure; unlocked, it
/// follows the result again.
#[test]
fn a_locked_colour_scale_survives_two_edits() {
    let mut h = solved_app(None, |app| open_fields(app, |f| f.flowlines = false));
    let first = colour_scale(&h);
    assert_eq!(first.1, sig4(p_max_mpa(&h.state().shown.clone().unwrap().solution)));
    h.get_by_label("Lock colour scale").click();
    h.run_steps(2);
    edit_and_solve(&mut h, "operating.speed_rpm", |f| f.operating.speed_rpm = 6000.0);
    edit_and_solve(&mut h, "operating.load_n", |f| f.operating.load_n = f.operating.load_n.map(|w| 1.5 * w));
    let now = sig4(p_max_mpa(&h.state().shown.clone().unwrap().solution));
    assert_ne!(now, first.1, "the edits change the peak pressure");
    assert_eq!(colour_scale(&h), first);
    h.get_by_label_contains("Lock colour scale (").click();
    h.run_steps(2);
    assert_eq!(colour_scale(&h).1, now);
    assert!(h.state().view::<FieldView>().unwrap().settings.locks.is_empty());
}

/// The bearing view's scales lock on the first result (a class sees the field change, not the scale), stay
/// through two edits, follow the result once unlocked, and say so when they change.
#[test]
fn locked_scales_survive_two_edits() {
    let mut h = solved_app(None, |_| {});
    h.get_by_label_contains("journal displacement × 50");
    let lock = h.state().view::<BearingView>().unwrap().settings.outline_lock;
    assert_eq!(lock.map(|l| l.exaggeration), Some(50.0), "locked by default");
    // Edit 1: pads bored to the assembled clearance (Cp = 102 µm): unlocked, 50.8 mm / 6 / 102 µm ≈ 83 → × 100.
    edit_and_solve(&mut h, "bearing.pads.bore_radius_mm", |f| f.bearing.pads.bore_radius_mm = Some(50.902));
    // Edit 2: another speed.
    edit_and_solve(&mut h, "operating.speed_rpm", |f| f.operating.speed_rpm = 6000.0);
    h.get_by_label_contains("journal displacement × 50");
    h.get_by_label_contains("Lock scales (film × 50").click();
    h.run_steps(2);
    h.get_by_label_contains("journal displacement × 100");
    assert!(h.state().view::<BearingView>().unwrap().settings.unlocked);
    // Unlocked, a result with another peak pressure changes the pressure scale, and the view says so.
    assert!(h.query_by_label_contains("Scales changed with this result").is_none());
    edit_and_solve(&mut h, "operating.load_n", |f| f.operating.load_n = f.operating.load_n.map(|w| 2.0 * w));
    h.run_steps(2);
    h.get_by_label_contains("Scales changed with this result: pressure");
}
