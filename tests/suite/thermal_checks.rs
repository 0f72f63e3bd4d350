//! Consistency checks of the thermal model's pieces against each other and against exact answers.

use crate::common;

use tiltpad::bearing::equilibrium::{solve_equilibrium, EquilibriumParams};
use tiltpad::bearing::thermal::pad_system::PadThermal;
use tiltpad::bearing::NoCancel;
use tiltpad::bearing::{BearingModel, OperatingPoint, ThermalModel};
use tiltpad::mesh::pad3d::PadMesh;
use tiltpad::physics::energy::{FilmEnergy, Injection, Oil};
use tiltpad::physics::pad_conduction::{PadConduction, PadDirichletSolver, PadMaterial};

/// The energy equation integrates the injected flow with the Reynolds solver's own orifice quadrature: the
/// flux field's nodal outflows add up to the orifice flows the film reports.
#[test]
fn injected_flow_matches_the_reynolds_orifice_flow() {
    let case = common::case("compressor-bearing.toml", &["operating.injection_pressure_bar=40"]);
    let mut model = BearingModel::new(&case).unwrap();
    let op = OperatingPoint::isothermal(&case);
    solve_equilibrium(&mut model, &op, EquilibriumParams::default(), None, &NoCancel).unwrap();
    let oil = Oil { density: 863.5, specific_heat: 1900.0, conductivity: 0.13 };
    for (k, pm) in model.pads.iter().enumerate() {
        let inp = op.film_inputs(k);
        let energy = FilmEnergy::new(&pm.film.geom);
        let inj =
            Injection { pressure: op.injection_pressure[k], viscosity: op.injection_viscosity, temperature_c: 50.0 };
        let st = energy.flow_state(&pm.film, &inp, &inj, &oil, true);
        let from_flux: f64 = pm.film.geom.sym * st.outflow.iter().sum::<f64>();
        let reynolds: f64 = (0..pm.film.geom.orifices.len()).map(|o| pm.film.orifice_flow(o, &inp)).sum();
        assert!((from_flux - reynolds).abs() < 1e-9 * reynolds.abs(), "pad {k}: {from_flux:.6e} vs {reynolds:.6e}");
    }
}

/// A pad without convection takes its film-side temperature everywhere (BC1), exactly.
#[test]
fn insulated_pad_takes_its_face_temperature() {
    let case = common::case("fillon-a.toml", &["mesh.fidelity=\"preview\""]);
    let model = BearingModel::new(&case).unwrap();
    let pad = &case.bearing.pads[2];
    let film = &model.pads[2].film;
    let mesh = PadMesh::extrude(
        &film.geom.grid,
        case.bearing.journal_radius_m,
        pad.leading_edge_rad,
        pad.bore_radius_m(case.bearing.journal_radius_m),
        pad.thickness_m,
        4,
    );
    let mut solver = PadDirichletSolver::new(&mesh).unwrap();
    let pt = PadThermal::new(film, Some(PadConduction::new(std::sync::Arc::new(mesh)))).unwrap();
    let face = vec![63.0; film.geom.n_nodes()];
    let t = pt
        .solve_pad_bc1(&mut solver, &face, &PadMaterial { conductivity: 45.0, convection: 0.0, ambient_c: 20.0 })
        .unwrap()
        .unwrap();
    assert!(t.iter().all(|v| (v - 63.0).abs() < 1e-9), "{:?}", t.iter().fold(f64::MAX, |m, &v| m.min(v)));
    // With convection the pad lies between the surroundings and its face, hottest on the face.
    let mat = PadMaterial { conductivity: 45.0, convection: 100.0, ambient_c: 20.0 };
    let t = pt.solve_pad_bc1(&mut solver, &face, &mat).unwrap().unwrap();
    assert_eq!(solver.factorizations, 2, "a new material refactors");
    let again = pt.solve_pad_bc1(&mut solver, &face, &mat).unwrap().unwrap();
    assert_eq!(solver.factorizations, 2, "the same material reuses the factorisation");
    assert_eq!(again, t);
    assert!(t.iter().all(|&v| v > 20.0 && v <= 63.0 + 1e-9));
    let cond = pt.conduction.as_ref().unwrap();
    // Heat to the surroundings is bounded by H∞ A (T_face − T∞).
    let q = cond.heat_to_surroundings(&mat, &t);
    assert!(q > 0.0 && q < 100.0 * cond.free_area() * 43.0);
}

/// No spurious undershoot in the film with strong injection: nowhere colder than the coldest oil that
/// enters it (tolerance 0.2 K, the SUPG scheme's measured undershoot at the orifice is about 0.1 K).
#[test]
fn film_temperature_stays_above_the_coldest_inflow() {
    let s = common::solve(
        "compressor-bearing.toml",
        &["thermal.model=\"thd\"", "operating.injection_pressure_bar=40", "mesh.fidelity=\"preview\""],
    );
    let t = s.thermal.as_ref().unwrap();
    let coldest = t.inlet_temperatures_c.iter().fold(s.inputs.operating.injection_temperature_c, |m, &v| m.min(v));
    for p in &s.pads {
        let tmin = p.field.film_temperature_c.as_ref().unwrap().iter().fold(f64::MAX, |m, &v| m.min(v));
        println!("pad {}: film min {tmin:.3} °C (coldest inflow {coldest:.3} °C)", p.index);
        assert!(tmin > coldest - 0.2, "pad {}: {tmin} °C", p.index);
    }
}

/// The thermal loop stops at its iteration budget and at its time budget, and says which (the time budget
/// also stops an equilibrium that is running when it is spent).
#[test]
fn thermal_loop_stops_at_its_budgets() {
    use tiltpad::bearing::report::error::{Budget, Iteration};
    use tiltpad::bearing::thermal::{solve_thd, ThdRun};
    use tiltpad::bearing::{SolveError, ThermalParams};
    let case = common::case("fillon-a.toml", &["mesh.fidelity=\"preview\""]);
    let mut model = BearingModel::new(&case).unwrap();
    let mut thermal = ThermalModel::new(&case, &model).unwrap();
    let tol = ThermalParams::default().viscosity_tol;
    let params = ThermalParams { max_iterations: 2, ..ThermalParams::default() };
    match solve_thd(&mut model, &mut thermal, &case, params, None, &NoCancel) {
        Err(SolveError::BudgetExceeded {
            what: Iteration::Thermal,
            budget: Budget::Iterations(2),
            iterations: 2,
            residual,
            ..
        }) => {
            assert!(residual > tol && residual.is_finite(), "{residual}");
        }
        other => panic!("expected the iteration budget, got {:?}", other.map(|s| s.report.outer_iterations)),
    }
    // Unbudgeted, the same loop converges in more than two iterations.
    let params = ThermalParams::default();
    let s = solve_thd(&mut model, &mut thermal, &case, params, None, &NoCancel).unwrap();
    assert!(s.report.converged && s.report.outer_iterations > 2, "{:?}", s.report.outer_iterations);
    // The equilibrium's work budget inside the loop: 5 film solves per pad do not place the pads of the first
    // (isothermal) equilibrium, and the loop answers with that budget, not with a touchdown or a restart.
    let mut equilibrium = params.equilibrium;
    equilibrium.max_film_solves_per_pad = 5;
    let params = ThermalParams { equilibrium, ..ThermalParams::default() };
    let mut run = ThdRun::new(&model, &mut thermal, &case, params, None);
    let err = run.step(&mut model, &mut thermal, &case, &NoCancel).map(|s| s.is_some()).unwrap_err();
    match err {
        SolveError::BudgetExceeded {
            what: Iteration::Equilibrium,
            budget: Budget::FilmSolves { per_pad: 5, pads },
            ..
        } => {
            assert_eq!(pads, case.bearing.pads.len());
            assert!(err.to_string().contains("physics.max_film_solves_per_pad"), "{err}");
        }
        other => panic!("expected the equilibrium's work budget, got {other:?}"),
    }
}

/// The case key `thermal.max_iterations` is the loop's budget: a whole solve through the stages stops at it
/// and names it; the default lets the same case converge.
#[test]
fn the_iteration_budget_is_a_case_key() {
    use tiltpad::bearing::report::error::{Budget, Iteration};
    use tiltpad::bearing::{solve_case, SolveError};
    let set = ["mesh.fidelity=\"preview\"", "thermal.max_iterations=10"];
    match solve_case(&common::case("fillon-a-tehd.toml", &set)) {
        Err(SolveError::BudgetExceeded { what: Iteration::Thermal, budget: Budget::Iterations(10), .. }) => {}
        other => {
            panic!("expected the budget of 10, got {:?}", other.map(|s| s.thermal.map(|t| t.report.outer_iterations)))
        }
    }
    let s = solve_case(&common::case("fillon-a-tehd.toml", &["mesh.fidelity=\"preview\""])).unwrap();
    assert!(s.thermal.unwrap().report.outer_iterations > 10);
}

/// The case key `thermal.viscosity_tolerance` is the loop's stopping rule: the loop stops at the first outer
/// iteration whose largest viscosity change is below it, so a tighter tolerance takes more iterations and
/// ends with a smaller change; the default is 1e-4.
#[test]
fn the_viscosity_tolerance_is_a_case_key() {
    use tiltpad::bearing::solve_case;
    let report = |tol: Option<&str>| {
        let mut set = vec!["mesh.fidelity=\"preview\"".to_string()];
        set.extend(tol.map(|t| format!("thermal.viscosity_tolerance={t}")));
        let set: Vec<&str> = set.iter().map(String::as_str).collect();
        solve_case(&common::case("fillon-a.toml", &set)).unwrap().thermal.unwrap().report
    };
    let (default, tight) = (report(None), report(Some("1e-7")));
    for (r, tol) in [(&default, 1e-4), (&tight, 1e-7)] {
        let stop = r.stop_reason.expect("converged");
        assert_eq!(stop.viscosity_tol, tol);
        assert!(stop.viscosity_change < tol, "{stop}");
        let before_last = r.viscosity_change[r.viscosity_change.len() - 2];
        assert!(before_last >= tol, "the loop stops at the first iteration below {tol} (previous {before_last:.1e})");
    }
    assert!(
        tight.outer_iterations > default.outer_iterations,
        "{} vs {}",
        tight.outer_iterations,
        default.outer_iterations
    );
}
