//! The equilibrium's work counts: what the film solves did reaches the report.

use crate::bearing::equilibrium::{solve_equilibrium, EquilibriumParams};
use crate::bearing::film::model::{BearingModel, OperatingPoint};
use crate::bearing::report::progress::NoCancel;
use crate::model::load_case;

/// The preview compressor bearing with mass-conserving cavitation, its films made to refactorise every
/// mass-conserving matrix with the pivoting LU: the report counts those factorisations as pivoted (the
/// Reynolds active-set solves that start each pad's first mass-conserving solve are not), the ordinary solve
/// counts none, and both give the same equilibrium. Measured: 154 factorisations, 0 pivoted; forced, 132 of
/// 154 pivoted, the journals 1e-19 m apart.
#[test]
fn pivoted_factorisations_reach_the_report() {
    let text = include_str!("../../../cases/compressor-bearing.toml");
    let set = ["physics.cavitation=\"jfo\"", "mesh.fidelity=\"preview\"", "thermal.model=\"isothermal\""];
    let case = load_case(text, &set.map(str::to_string)).unwrap().1;
    let op = OperatingPoint::isothermal(&case);
    let solve = |pivot: bool| {
        let mut model = BearingModel::new(&case).unwrap();
        if pivot {
            model.pads.iter_mut().for_each(|p| p.film.always_pivot());
        }
        solve_equilibrium(&mut model, &op, EquilibriumParams::default(), None, &NoCancel).unwrap()
    };
    let (plain, pivoted) = (solve(false), solve(true));
    let (a, b) = (&plain.report, &pivoted.report);
    eprintln!(
        "plain {} factorisations, {} pivoted; forced {} of {}; journal {:.1e} m apart",
        a.factorizations,
        a.pivoted_factorizations,
        b.pivoted_factorizations,
        b.factorizations,
        (plain.u[0] - pivoted.u[0]).hypot(plain.u[1] - pivoted.u[1])
    );
    assert_eq!(a.pivoted_factorizations, 0, "{a:?}");
    assert!(b.pivoted_factorizations > b.factorizations / 2 && b.pivoted_factorizations < b.factorizations, "{b:?}");
    assert_eq!((a.iterations, a.film_solves), (b.iterations, b.film_solves));
    assert!((plain.u[0] - pivoted.u[0]).hypot(plain.u[1] - pivoted.u[1]) < 1e-12, "{:?} {:?}", plain.u, pivoted.u);
}
