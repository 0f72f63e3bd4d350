//! Budgets count work, never time: a solve stopped by its budget stops at the same film solve on an idle and
//! on a busy machine, says which budget and which case key raises it, and is never reported as touchdown;
//! touchdown is reported only with a positive film at a state the solver accepted.

use std::sync::atomic::{AtomicBool, Ordering};

use tiltpad::bearing::report::error::{Budget, Iteration};
use tiltpad::bearing::{solve_case, SolveError};

use crate::common;

/// The full-model compressor bearing on the 440 × 216 mesh, with `per_pad` film solves per pad.
fn full_model(per_pad: usize) -> tiltpad::model::Case {
    let mut case = common::case(
        "compressor-bearing.toml",
        &["mesh.half_model=false", "mesh.circumferential_elements=440", "mesh.axial_elements=216"],
    );
    case.physics.max_film_solves_per_pad = per_pad;
    case
}

/// Runs `f` while every core but one is kept busy by a spinning thread (and the test's own thread competes
/// with them), so a limit that read the clock would stop elsewhere.
fn under_load<T>(f: impl FnOnce() -> T) -> T {
    let stop = AtomicBool::new(false);
    let cores = std::thread::available_parallelism().map_or(2, std::num::NonZero::get);
    std::thread::scope(|scope| {
        for _ in 0..cores {
            scope.spawn(|| {
                let mut x = 0u64;
                while !stop.load(Ordering::Relaxed) {
                    x = std::hint::black_box(x.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1));
                }
            });
        }
        let out = f();
        stop.store(true, Ordering::Relaxed);
        out
    })
}

/// The 440 × 216 full model stopped by a small work budget gives the same error, bit for bit, idle and with
/// every core busy: the budget (film solves per pad × pads), the iterations and the residual where it stopped.
#[test]
fn the_full_model_stops_at_the_same_film_solve_idle_and_under_load() {
    let idle = solve_case(&full_model(2)).map(|s| s.report.film_solves);
    let loaded = under_load(|| solve_case(&full_model(2)).map(|s| s.report.film_solves));
    assert_eq!(idle, loaded);
    match idle {
        Err(e @ SolveError::BudgetExceeded { what: Iteration::Equilibrium, budget, residual, .. }) => {
            assert_eq!(budget, Budget::FilmSolves { per_pad: 2, pads: 5 });
            assert!(residual.is_finite() && residual > 1e-9, "{residual}");
            let text = e.to_string();
            assert!(text.contains("physics.max_film_solves_per_pad") && text.contains("10 film solves"), "{text}");
            assert!(!text.contains("touchdown"), "{text}");
        }
        other => panic!("expected the work budget, got {other:?}"),
    }
}

/// Cases the issue saw reported as touchdown: a pad 0.01 mm thick with its bending mode spends the work budget
/// (said as such), and 5000 bar of injection closes the film of a pad at every tilt tried (said as a closed
/// film at a trial, with h = 0, not as touchdown).
#[test]
fn spent_budgets_and_closed_trial_films_are_not_touchdown() {
    let preview = "mesh.fidelity=\"preview\"";
    let thin = solve_case(&common::case(
        "compressor-bearing.toml",
        &[preview, "bearing.pads.thickness_mm=0.01", "physics.pad_modes=1"],
    ));
    assert!(
        matches!(thin, Err(SolveError::BudgetExceeded { budget: Budget::FilmSolves { per_pad: 3000, pads: 5 }, .. })),
        "{thin:?}"
    );
    let injected =
        solve_case(&common::case("compressor-bearing.toml", &[preview, "operating.injection_pressure_bar=5000"]));
    match injected {
        // The pad's tilt search ends at the end of its admissible range, where the film just closes (h within
        // round-off of zero: 1.8e-5 µm here).
        Err(SolveError::FilmClosed { pad: 0, h_min_um, .. }) => assert!(h_min_um.abs() < 1e-3, "{h_min_um}"),
        other => panic!("expected a closed film, got {:?}", other.map(|s| s.report.method)),
    }
}

/// Touchdown where it is one: 5 MN on the compressor bearing leaves a positive film below 5 % of the clearance
/// at the last state accepted, on a named pad, with the journal beyond the assembled clearance.
#[test]
fn touchdown_is_reported_with_a_positive_film_on_a_named_pad() {
    let r =
        solve_case(&common::case("compressor-bearing.toml", &["mesh.fidelity=\"preview\"", "operating.load_n=5e6"]));
    match r {
        Err(SolveError::Touchdown { pad, h_min_um, eccentricity_ratio }) => {
            assert!(pad < 5);
            assert!(h_min_um > 0.0 && h_min_um < 0.05 * 102.0, "{h_min_um}");
            assert!(eccentricity_ratio > 1.0, "{eccentricity_ratio}");
        }
        other => panic!("expected touchdown, got {:?}", other.map(|s| s.report.method)),
    }
}
