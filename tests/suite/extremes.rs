//! Numerical stability at the extremes: each configuration converges — and then passes the
//! conservation and sanity checks — or, where the physics says it cannot, fails with the physical error it
//! must (touchdown; no stiffness along the load); no NaN, no panic, no hang (the solver's iteration counts
//! are bounded and asserted).

use crate::common;

use tiltpad::bearing::report::warning::Warning;
use tiltpad::bearing::{solve_case, EquilibriumParams, Solution, SolveError};
use tiltpad::model::load_case;

/// Preview meshes keep the suite fast; the behaviour at the extremes does not depend on the mesh level.
fn run(case_file: &str, set: &[&str]) -> Result<Solution, SolveError> {
    let text = std::fs::read_to_string(common::case_path(case_file)).unwrap();
    let mut set: Vec<String> = set.iter().map(|s| (*s).to_string()).collect();
    if !set.iter().any(|s| s.starts_with("mesh.")) {
        set.push("mesh.fidelity=\"preview\"".into());
    }
    let (_, case) = load_case(&text, &set).unwrap_or_else(|e| panic!("{case_file} {set:?}: {e}"));
    solve_case(&case)
}

/// Largest relative mass-balance error of the consistent flows over every converged run here: round-off
/// (measured up to 3e-13, on the soft-pivot rig at 20 bar).
const MASS_BALANCE: f64 = 1e-12;

/// Checks a converged solution: finite everywhere, balanced to the solver's tolerance and to round-off,
/// bounded work.
fn sane(s: &Solution, what: &str) {
    let tol = EquilibriumParams::default().force_tol;
    assert!(
        s.report.residual <= tol,
        "{what}: residual {:.3e} above the solver's tolerance {tol:.0e}",
        s.report.residual
    );
    // A THD solve sums the Newton iterations of its loop's equilibria: Fillon A with preload 0.9 takes 280
    // outer iterations and 569 Newton iterations (the loop lingers near its fixed point where the rupture
    // between nodes still moves in small steps; 14 outer iterations before the rupture was interpolated).
    assert!(
        s.report.iterations < 600 && s.report.film_solves < 20_000,
        "{what}: unbounded work {:?}",
        (s.report.iterations, s.report.film_solves)
    );
    assert!(
        s.eccentricity_ratio.is_finite() && s.attitude_angle_deg.is_finite() && s.friction_power_w.is_finite(),
        "{what}"
    );
    assert!(
        s.flows_m3_per_s.mass_balance_error.abs() < MASS_BALANCE,
        "{what}: mass balance {:.3e}",
        s.flows_m3_per_s.mass_balance_error
    );
    for row in s.reduced.k_n_per_m.iter().chain(s.reduced.c_ns_per_m.iter()) {
        assert!(row.iter().all(|v| v.is_finite()), "{what}: reduced coefficients {:?}", s.reduced);
    }
    for p in &s.pads {
        assert!(p.h_min_m > 0.0 && p.p_max_pa.is_finite(), "{what}: pad {}", p.index);
        assert!(p.field.pressure_pa.iter().all(|v| v.is_finite() && *v >= 0.0), "{what}: pad {} pressure", p.index);
    }
}

/// Converges and passes [`sane`].
fn converges(case_file: &str, set: &[&str]) -> Solution {
    let what = format!("{case_file} {set:?}");
    let s = run(case_file, set).unwrap_or_else(|e| panic!("{what} must converge: {e}"));
    sane(&s, &what);
    s
}

/// Fails with touchdown (the film closes before the load is carried), with finite numbers in the message.
fn touches_down(case_file: &str, set: &[&str]) {
    match run(case_file, set) {
        Err(e @ SolveError::Touchdown { h_min_um, eccentricity_ratio, .. }) => {
            assert!(
                h_min_um.is_finite() && eccentricity_ratio.is_finite() && !e.to_string().to_lowercase().contains("nan"),
                "{e}"
            );
        }
        other => panic!("{case_file} {set:?}: expected touchdown, got {:?}", other.map(|s| s.eccentricity_ratio)),
    }
}

#[test]
fn eccentricity_up_to_0_98_and_touchdown() {
    for e in ["0.9", "0.95", "0.98"] {
        let text = common::PLAIN_360.replace("circumferential_elements = 360", "circumferential_elements = 120");
        let (_, case) = load_case(&text, &[format!("operating.eccentricity_ratio={e}")]).unwrap();
        let s = solve_case(&case).unwrap_or_else(|err| panic!("ε = {e}: {err}"));
        sane(&s, &format!("plain ε = {e}"));
        assert!((s.eccentricity_ratio - e.parse::<f64>().unwrap()).abs() < 1e-9);
    }
    // Beyond what the film can carry above the touchdown threshold: a clear touchdown error.
    touches_down("fillon-a.toml", &["operating.load_n=5e6"]);
    // A prescribed position that closes the film is its own error (the position is given, not found), naming
    // the pad and its negative film.
    match run("fillon-a.toml", &["operating.load_n=", "operating.load_angle_deg=", "operating.eccentricity_ratio=2.5"])
    {
        Err(SolveError::PositionClosesFilm { h_min_um, eccentricity_ratio, .. }) => {
            assert!(h_min_um < 0.0 && h_min_um.is_finite(), "{h_min_um}");
            assert_eq!(eccentricity_ratio, 2.5);
        }
        other => panic!("expected PositionClosesFilm, got {:?}", other.map(|s| s.eccentricity_ratio)),
    }
}

#[test]
fn sommerfeld_number_from_0_005_to_10() {
    // Someya four-pad case: W = 1250 N / S. Every point converges (ε 0.02 … 1.34 of the assembled
    // clearance: the loaded pads' clearance is larger), and the journal sinks further at every heavier load.
    let mut last_e = f64::NEG_INFINITY;
    for s in [10.0, 1.0, 0.1, 0.02, 0.005] {
        let w = 1250.0 / s;
        let sol = converges("someya-4pad-lbp.toml", &[&format!("operating.load_n={w}")]);
        assert!((sol.sommerfeld.unwrap() / s - 1.0).abs() < 1e-9, "S = {s}: {:?}", sol.sommerfeld);
        assert!(sol.eccentricity_ratio > last_e, "S = {s}: ε {} after {last_e}", sol.eccentricity_ratio);
        last_e = sol.eccentricity_ratio;
    }
}

#[test]
fn length_to_diameter_from_0_1_to_2() {
    // The unit load W/(L D) of Fillon's bearing (10 kN on 70 mm) is kept: an L/D sweep at a fixed load
    // would only test touchdown on the shortest bearing.
    for l in [10.0, 25.0, 50.0, 100.0, 200.0] {
        let w = 10_000.0 * l / 70.0;
        converges("fillon-a.toml", &[&format!("bearing.length_mm={l}"), &format!("operating.load_n={w}")]);
    }
}

#[test]
fn peclet_number_up_to_a_million() {
    // Film Péclet number ρ c_p U h / κ: about 4e4 for the compressor bearing; a conductivity 50 times lower
    // and the speed doubled push it to ~4e6. The SUPG film solve and the THD loop must hold.
    let s = converges(
        "compressor-bearing.toml",
        &["thermal.model=\"thd\"", "lubricant.conductivity_w_per_m_k=0.0026", "operating.speed_rpm=18000"],
    );
    let t = s.thermal.as_ref().expect("thermal results");
    assert!(t.t_max_film_c.is_finite() && t.t_max_film_c > 50.0 && t.t_max_film_c < 250.0, "T max {}", t.t_max_film_c);
    // The film temperature never falls below the coldest oil that enters it (no SUPG undershoot beyond 0.5 K).
    let t_min =
        s.pads.iter().flat_map(|p| p.field.film_temperature_c.iter().flatten()).fold(f64::INFINITY, |m, &v| m.min(v));
    assert!(t_min > 50.0 - 0.5, "undershoot: T min {t_min}");
}

#[test]
fn preload_from_minus_0_5_to_0_9() {
    for m in ["-0.5", "0.0", "0.5", "0.9"] {
        converges("fillon-a.toml", &["bearing.pads.clearance_um=", &format!("bearing.pads.preload={m}")]);
    }
}

#[test]
fn two_to_twelve_pads() {
    for (n, arc) in [(3, 100), (5, 60), (8, 40), (12, 25)] {
        converges(
            "fillon-a.toml",
            &[&format!("bearing.pads.count={n}"), &format!("bearing.pads.arc_deg={arc}"), "bearing.pads.pivot_deg=0.0"],
        );
    }
    // Two pads at 0° and 180° have no stiffness along the vertical load: the solve says so.
    let e = run("fillon-a.toml", &["bearing.pads.count=2", "bearing.pads.arc_deg=150", "bearing.pads.pivot_deg=0.0"])
        .map(|s| s.eccentricity_ratio)
        .unwrap_err();
    assert!(e.to_string().contains("no stiffness"), "{e}");
}

#[test]
fn unloaded_and_fully_cavitated_pads() {
    // Taniguchi bearing B: two pads fully cavitated (thesis, Publication 3).
    let s = converges("taniguchi-b.toml", &[]);
    let unloaded = s.pads.iter().filter(|p| p.unloaded).count();
    assert_eq!(unloaded, 2, "two upper pads unloaded");
    assert!(s.report.warnings.iter().any(|w| matches!(w, Warning::PadFloats { tilting: true, .. })));
    // Zero load on a symmetric bearing: the journal stays centred.
    let s = converges("fillon-a.toml", &["operating.load_n=0"]);
    assert!(s.eccentricity_ratio < 1e-12, "ε = {}", s.eccentricity_ratio);
}

#[test]
fn zero_speed_with_injection_is_hydrostatic() {
    // Capillary restrictors (0.3 mm × 10 mm, conductance comparable to the film's) on every pad, journal
    // not turning: a hydrostatic bearing with positive stiffness.
    let restrictor = "bearing.pads.orifice=[{position_frac = 0.5, diameter_mm = 0.3, length_mm = 10.0}]";
    let set = ["operating.speed_rpm=0", "operating.injection_pressure_bar=40", restrictor, "operating.load_n=500"];
    let s = converges("fillon-a.toml", &set);
    assert!(s.friction_power_w.abs() < 1e-9, "no shear at zero speed");
    assert!(s.flows_m3_per_s.orifices_in > 0.0);
    // Nothing enters at the leading edges by Couette flow; oil leaves on every edge.
    assert!(s.flows_m3_per_s.leading_edges_in <= 1e-12);
    let k = s.reduced.k_n_per_m;
    assert!(k[1][1] > 0.0 && k[0][0] > 0.0, "hydrostatic stiffness {k:?}");
    assert!(s.journal_position_m[1] < 0.0, "the journal moves with the load");
    assert!(!s.report.warnings.iter().any(|w| matches!(w, Warning::StaticallyUnstable { .. })));
    // With an oversized, unrestricted orifice the pocket pressure does not depend on the gap: no
    // hydrostatic stiffness, and an equilibrium found there is reported as statically unstable.
    let open = "bearing.pads.orifice=[{position_frac = 0.5, diameter_mm = 1.5, length_mm = 10.0}]";
    let s = converges(
        "fillon-a.toml",
        &["operating.speed_rpm=0", "operating.injection_pressure_bar=40", open, "operating.load_n=500"],
    );
    assert!(
        s.report
            .warnings
            .iter()
            .any(|w| matches!(w, Warning::StaticallyUnstable { principal_n_per_m } if *principal_n_per_m < 0.0)),
        "{:?}",
        s.report.warnings
    );
}

#[test]
fn injection_up_to_pad_lift_off() {
    // Soft pivots and rising injection: the pads ride out on their pivots; the solver follows (scan + Newton
    // through the negative-stiffness region) at every pressure (the valve's supply raised above it: a supply
    // below the injection pressure is refused).
    for p in ["20", "40", "80", "160"] {
        let set = [format!("operating.injection_pressure_bar={p}"), "hydraulics.supply_pressure_bar=200".to_string()];
        let s = converges("test-rig-pub5.toml", &[&set[0], &set[1]]);
        if p == "40" {
            assert!(s.pads.iter().all(|p| p.pivot_displacement_m.unwrap() > 100e-6), "pads pushed out");
        }
    }
}

#[test]
fn very_high_and_very_low_viscosity() {
    // High viscosity carries the load easily; very low viscosity (200 times lower) touches down.
    converges("fillon-a.toml", &["lubricant.viscosity_pa_s=1.0", "lubricant.viscosity2_pa_s=0.2"]);
    touches_down("fillon-a.toml", &["lubricant.viscosity_pa_s=1e-4", "lubricant.viscosity2_pa_s=2e-5"]);
    // 2000 times lower: touchdown as well, within the default work budget (the search counts a film thinner
    // than the touchdown film as closed); with a small budget the work runs out first, and is said as the
    // budget, never as touchdown.
    let thin = ["lubricant.viscosity_pa_s=1e-5", "lubricant.viscosity2_pa_s=2e-6"];
    touches_down("fillon-a.toml", &thin);
    match run("fillon-a.toml", &[thin[0], thin[1], "physics.max_film_solves_per_pad=100"]) {
        Err(e @ SolveError::BudgetExceeded { .. }) => assert!(e.to_string().contains("max_film_solves_per_pad"), "{e}"),
        other => panic!("expected the spent work budget, got {:?}", other.map(|s| s.eccentricity_ratio)),
    }
}

#[test]
fn absurd_but_valid_inputs_solve_with_a_warning() {
    // A 1 nm clearance (pads at preload 0.5): the film is thinner than any surface's roughness.
    let s = converges("someya-4pad-lbp.toml", &["bearing.assembled_clearance_um=0.001", "bearing.pads.preload=0.5"]);
    let has = |s: &Solution, what: &str| s.report.warnings.iter().any(|w| w.to_string().contains(what));
    assert!(has(&s, "mixed lubrication") && has(&s, "clearance ratio Cb/R = 2.00e-8"), "{:?}", s.report.warnings);
    // 10⁶ rpm: a film Reynolds number far past laminar.
    let s = converges("fillon-a.toml", &["operating.speed_rpm=1e6", "thermal.model=\"isothermal\""]);
    let re = s
        .report
        .warnings
        .iter()
        .find_map(|w| match w {
            Warning::Turbulent { reynolds, .. } => Some(*reynolds),
            _ => None,
        })
        .unwrap_or_else(|| panic!("{:?}", s.report.warnings));
    // ρ U h / µ with U = 5236 m/s, h ≈ Cp = 148 µm, µ = 0.0277 Pa·s: about 2.4e4 at the thickest film.
    assert!(re > 1e4 && re < 2.5e4, "Re = {re}");
    // The shipped cases at their design points are laminar and of ordinary proportions (Taniguchi's
    // 4000 rpm bearing, published as running in the laminar and turbulent regimes, is the exception).
    for case in ["compressor-bearing.toml", "someya-4pad-lbp.toml", "test-rig.toml"] {
        let s = converges(case, &[]);
        assert!(
            !["turbulent", "Taylor", "mixed lubrication", "clearance ratio"].iter().any(|w| has(&s, w)),
            "{case}: {:?}",
            s.report.warnings
        );
    }
}
