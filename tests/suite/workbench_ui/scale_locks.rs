//! Locked scales: the field view's colour scale and the bearing view's film exaggeration and pressure scale
//! stay across edits and across opening a variant of the same bearing; another bearing's case drops them.

use egui_kittest::kittest::Queryable;
use tiltpad::app::views::bearing_view::BearingView;
use tiltpad::app::views::field_view::FieldView;
use tiltpad::scene::summary::sig4;

use super::harness::{edit_and_solve, open_fields, open_preset, solved_app, wait_for_solve};
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

/// Opening a case locks nothing of the case before it onto another bearing: with the compressor's pressure
/// colour scale locked (0 to 1.996 MPa) and the bearing view locked on its first result, opening the overloaded
/// compressor (File → Open preset; the same bearing at 18 kN, as a class compares) keeps both, as an edit of
/// the load would; opening Fillon's bearing drops them: the field view draws Fillon's own range, unlocked, and
/// the bearing view locks again on Fillon's first result (its film exaggeration and pressure scale). The file
/// menu, a dropped file and the web page's `?case=` open a case through the same path.
#[test]
fn opening_another_bearing_drops_the_locked_scales_and_the_same_bearing_keeps_them() {
    let mut h = solved_app(None, |_| {});
    let compressor = h.state().shown.clone().unwrap().solution;
    let outline_lock = |h: &egui_kittest::Harness<'_, tiltpad::app::WorkbenchApp>| {
        h.state().view::<BearingView>().unwrap().settings.outline_lock
    };
    let first_lock = outline_lock(&h);
    assert!(first_lock.is_some(), "the bearing view locks on the first result");
    open_fields(h.state_mut(), |f| f.flowlines = false);
    h.run_steps(3);
    h.get_by_label("Lock colour scale").click();
    h.run_steps(2);
    let locked = colour_scale(&h);
    assert_eq!(locked.1, sig4(p_max_mpa(&compressor)));

    open_preset(&mut h, "compressor-overload.toml");
    wait_for_solve(&mut h);
    let overload = h.state().shown.clone().unwrap().solution;
    assert_eq!(overload.inputs.bearing, compressor.inputs.bearing, "the same bearing");
    assert!(p_max_mpa(&overload) > 2.0 * p_max_mpa(&compressor));
    assert_eq!(colour_scale(&h), locked, "the same bearing keeps the locked colour scale");
    assert_eq!(outline_lock(&h), first_lock, "the same bearing keeps the bearing view's scales");

    open_preset(&mut h, "fillon-a.toml");
    wait_for_solve(&mut h);
    let fillon = h.state().shown.clone().unwrap().solution;
    assert_ne!(fillon.inputs.bearing, compressor.inputs.bearing);
    assert_eq!(colour_scale(&h), (sig4(0.0), sig4(p_max_mpa(&fillon))), "Fillon's own pressure range");
    assert!(h.state().view::<FieldView>().unwrap().settings.locks.is_empty());
    h.get_by_label("Lock colour scale");
    h.state_mut().open::<BearingView>();
    h.run_steps(3);
    let own = tiltpad::scene::outline::bearing_outline_with(&fillon.inputs, Some(&fillon), None).scales();
    assert_ne!(Some(own), first_lock, "Fillon's bearing has scales of its own");
    assert_eq!(outline_lock(&h), Some(own), "locked again on Fillon's first result");
    h.get_by_label_contains(&format!("journal displacement × {}", own.exaggeration));
}
