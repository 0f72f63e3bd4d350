//! The coefficient view: the frequency sweep with the full matrices, and the background speed sweep.

use egui_kittest::kittest::Queryable;
use tiltpad::app::views::coefficients_view::{CoefficientAxis, CoefficientsView};

use super::harness::{snapshot, solved_app};
use super::reading::tick_labels;

#[test]
fn coefficient_view_plots_the_frequency_sweep_and_the_full_matrices() {
    let mut h = solved_app(None, |app| app.open::<CoefficientsView>());
    let shown = h.state().shown.clone().unwrap();
    let sweep = shown.frequency_sweep.unwrap();
    assert_eq!(sweep.len(), 31);
    // The synchronous point of the sweep is the case's own reduced coefficients.
    let sync = sweep.iter().find(|(r, _)| (*r - 1.0).abs() < 1e-12).unwrap().1;
    assert_eq!(sync.k_n_per_m, shown.solution.reduced.k_n_per_m);
    // Direct and cross terms on scales of their own, each legend above its plot.
    for title in
        ["Direct stiffness [MN/m]", "Cross stiffness [MN/m]", "Direct damping [kN·s/m]", "Cross damping [kN·s/m]"]
    {
        h.get_by_label(title);
    }
    for entry in ["Kxx", "Kyy", "Kxy", "Kyx", "Cxx", "Cyy"] {
        h.get_by_label(&format!("legend: {entry}"));
    }
    // Each of the four plots numbers its frequency-ratio axis (five ticks on a 190-point axis were all
    // left unlabelled by egui_plot) and its value axis.
    let top = h.get_by_label("Direct stiffness [MN/m]").rect().top();
    let ticks = tick_labels(&h, "excitation frequency ratio ω/Ω", top);
    assert_eq!(ticks.len(), 4, "{ticks:?}");
    for (x, y) in &ticks {
        assert!(x.len() >= 2 && y.len() >= 2, "x {x:?}, y {y:?}");
    }
    snapshot(&mut h, "coefficients_frequency");
    // The full matrices open under their header.
    assert!(h.query_by_label("pad 3 tilt [rad]").is_none());
    h.get_by_label_contains("Full coefficient matrices").click();
    h.run_steps(3);
    assert_eq!(h.get_all_by_label("pad 3 tilt [rad]").count(), 6, "row and column header in K, C and M");
}

#[test]
fn coefficient_view_against_speed_runs_a_background_sweep() {
    let mut h = solved_app(None, |app| {
        app.open::<CoefficientsView>();
        app.view_mut::<CoefficientsView>().unwrap().settings.axis = CoefficientAxis::Speed;
    });
    let sweep = h.state().shown.clone().unwrap().speed_sweep.expect("speed sweep");
    assert_eq!(sweep.len(), 11);
    // 4500 … 13 500 rpm. A point where the solver fails is listed in the view, not hidden.
    let ecc: Vec<f64> = sweep.iter().filter_map(|p| p.result.as_ref().ok()).map(|v| v.eccentricity_ratio).collect();
    assert_eq!(ecc.len(), 11, "every point converges: {sweep:?}");
    assert!(ecc.windows(2).all(|w| w[1] < w[0]), "the journal rises with speed: {ecc:?}");
    for p in sweep.iter().filter(|p| p.result.is_err()) {
        h.get_by_label_contains(&format!("No solution at {:.0}", tiltpad::units::RPM.from_si(p.speed_rad_s)));
    }
    snapshot(&mut h, "coefficients_speed");
}
