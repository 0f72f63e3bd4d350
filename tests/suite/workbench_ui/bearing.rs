//! The bearing view: the solved compressor bearing to scale, and the design limits marked.

use egui_kittest::kittest::Queryable;

use super::harness::{edit_and_solve, snapshot, solved_app};

#[test]
fn bearing_view_shows_the_solved_compressor_bearing() {
    let mut h = solved_app(None, |_| {});
    let s = h.state().shown.clone().unwrap().solution;
    // The compressor bearing at 9000 rpm, 1918 N: a moderately loaded LOP bearing.
    assert!(s.eccentricity_ratio > 0.1 && s.eccentricity_ratio < 0.6, "{}", s.eccentricity_ratio);
    h.get_by_label_contains("To scale, except film");
    snapshot(&mut h, "bearing_view");
}

#[test]
fn design_limits_are_marked_in_the_results_panel_and_the_bearing_view() {
    let mut h = solved_app(None, |_| {});
    h.get_by_label("Within the design limits");
    // The compressor bearing at 18 kN: W/(L·D) = 18000 / (44.45 mm · 101.6 mm) = 3.986 MPa > 3.5 MPa.
    edit_and_solve(&mut h, "operating.load_n", |f| f.operating.load_n = Some(18000.0));
    h.get_by_label("Design limits exceeded:");
    h.get_by_label("W/(L·D) 3.986 MPa > limit 3.5 MPa");
    h.get_by_label("Exceeds design limit: W/(L·D) 3.986 MPa > limit 3.5 MPa");
    snapshot(&mut h, "bearing_view_limits_exceeded");
    // A limit raised in the case clears its marks (limits enter no solver stage: nothing is re-solved).
    edit_and_solve(&mut h, "limits.max_specific_load_mpa", |f| f.limits.max_specific_load_mpa = Some(5.0));
    assert!(!h.state().result_is_stale());
    assert!(h.query_by_label_contains("W/(L·D) 3.986 MPa >").is_none());
}
