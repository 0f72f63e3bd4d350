//! THD points of the convergence map that used to spend the thermal loop's iteration budget (issue 8): each
//! must now converge with its balances checked (the map's own classification: force, pad and mass
//! residuals; here also the energy balance and the loop's own viscosity tolerance) or end in a physical error.

mod common;

use tiltpad::bearing::{solve_point, BearingModel, NoCancel, ThermalParams};
use tiltpad::model::LoadSpec;
use tiltpad::study::convergence::{classify, load_for_sommerfeld, Class};

/// Solves one map point cold (as `convergence-map` does) and checks it.
fn map_point(case_file: &str, sommerfeld: f64, direction_deg: f64) {
    let mut case = common::case(case_file, &["mesh.fidelity=\"preview\""]);
    case.operating.load = LoadSpec::Force { magnitude_n: load_for_sommerfeld(&case, sommerfeld), angle_rad: direction_deg.to_radians() };
    let mut model = BearingModel::new(&case).unwrap();
    let result = solve_point(&mut model, &mut None, &case, None, &NoCancel);
    let (class, detail) = classify(&result);
    let at = format!("{case_file} at {direction_deg}°, S = {sommerfeld}");
    if class.is_physical() {
        return;
    }
    assert_eq!(class, Class::Converged, "{at}: {detail}");
    let solution = result.unwrap();
    let thermal = solution.thermal.as_ref().expect("a THD solution");
    let r = &thermal.report;
    // The last entry is the polishing equilibrium's (full tolerances on the converged field), the one before
    // it the loop's own test when the last equilibrium was inexact.
    let tol = ThermalParams::default().viscosity_tol;
    assert!(r.converged && r.viscosity_change.iter().rev().take(2).any(|&c| c < tol), "{at}: viscosity changes {:?}", r.viscosity_change);
    assert!(r.energy_balance_closure.abs() < 1e-12, "{at}: energy balance closes to {:.1e}", r.energy_balance_closure);
}

/// Taniguchi B (BC3) at S = 1 with the load 20° past a pivot: the Anderson extrapolation cycled at a
/// viscosity change of 3e-3 … 3e-2 for its 40 iterations; the safeguard that then applies converges it (46
/// outer iterations in all).
#[test]
fn taniguchi_b_at_s_1_converges() {
    map_point("taniguchi-b.toml", 1.0, 65.0);
}
