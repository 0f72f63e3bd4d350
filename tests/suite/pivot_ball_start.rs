//! Ball pivots on a lightly loaded pad (`cases/compressor-bearing.toml` on ball-in-socket pivots, preview
//! mesh): the top pad (pivot 60°, load at 270°) floats or nearly so.
//!
//! - Each pivot's contact state carries the load the pad's film puts on it (the film force along the pivot
//!   line; at least the contact's floor load), also for a floating pad. Before, the load iteration took the
//!   spring force k ξ, and a floating pad's ξ is held where film pressure begins, not balanced by its film:
//!   on 12.7 mm balls the floating top pad's pivot "carried" 68.3 N, and on 40 mm balls in 41 mm sockets
//!   the iteration chased that phantom load for its 30 iterations without converging.
//! - The answer does not depend on the start: cold, and warm-started from the same bearing on rockers (top
//!   pad loaded) and from a tenth of the load (every pad loaded), the equilibria agree.

use crate::common::case;
use tiltpad::bearing::equilibrium::pivots::FLOOR;
use tiltpad::bearing::report::warning::Warning;
use tiltpad::bearing::{solve_case, NoCancel, Request, Solution, Stages};
use tiltpad::model::Case;

const CASE: &str = "compressor-bearing.toml";
const LOAD_N: f64 = 1918.0;

fn ball(extra: &[&str]) -> Case {
    let mut set = vec![
        "mesh.fidelity=preview",
        "bearing.pads.pivot_contact=\"ball\"",
        "bearing.pads.pivot_radius_mm=12.7",
        "bearing.pads.pivot_seat_radius_mm=13",
    ];
    set.extend_from_slice(extra);
    case(CASE, &set)
}

/// `c` solved from scratch, or warm-started from the equilibrium of `start` (the same films: solved first on
/// the same stages, whose warm start is the last converged state).
fn solve(c: &Case, start: Option<&Case>) -> Solution {
    let Some(start) = start else { return solve_case(c).expect("solve") };
    let mut stages = Stages::new();
    stages.solution(&Request::solution(start.clone()), &NoCancel).expect("start");
    std::sync::Arc::unwrap_or_clone(stages.solution(&Request::solution(c.clone()), &NoCancel).expect("solve"))
}

/// The film's force on pad k along its pivot line [N].
fn film_load(c: &Case, s: &Solution, k: usize) -> f64 {
    let t = c.bearing.pads[k].pivot_rad;
    -(s.pads[k].force_n[0] * t.cos() + s.pads[k].force_n[1] * t.sin())
}

fn assert_pivots_carry_the_film_loads(c: &Case, s: &Solution, tag: &str) {
    assert!(
        !s.report.warnings.iter().any(|w| matches!(w, Warning::PivotLoadsNotConverged { .. })),
        "{tag}: {:?}",
        s.report.warnings
    );
    for k in 0..s.pads.len() {
        let state = s.pads[k].pivot_contact.expect("contact state");
        let film = film_load(c, s, k);
        eprintln!("{tag} pad {k}: pivot {:.3} N, film {film:.3} N, floating {}", state.load_n, s.pads[k].unloaded);
        assert!(
            (state.load_n - film.max(FLOOR * LOAD_N)).abs() < 1e-4 * LOAD_N,
            "{tag} pad {k}: pivot {} N vs film {film} N",
            state.load_n
        );
    }
}

#[test]
fn a_floating_pad_puts_no_load_on_its_ball() {
    let c = ball(&[]);
    let s = solve(&c, None);
    eprintln!("{}; {:?}", s.report.method, s.report.warnings);
    assert!(s.pads[0].unloaded, "the top pad floats on 12.7 mm balls");
    assert_pivots_carry_the_film_loads(&c, &s, "12.7/13 mm");
    let wide = ball(&["bearing.pads.pivot_radius_mm=40", "bearing.pads.pivot_seat_radius_mm=41"]);
    let w = solve(&wide, None);
    eprintln!("{}; {:?}", w.report.method, w.report.warnings);
    assert_pivots_carry_the_film_loads(&wide, &w, "40/41 mm");
}

#[test]
fn the_ball_pivot_equilibrium_does_not_depend_on_the_start() {
    let c = ball(&[]);
    let cold = solve(&c, None);
    let rockers = ball(&[
        "bearing.pads.pivot_contact=\"rocker\"",
        "bearing.pads.pivot_radius_mm=40",
        "bearing.pads.pivot_seat_radius_mm=61.5",
    ]);
    let rocker = solve(&rockers, None);
    assert!(!rocker.pads[0].unloaded, "on rockers the top pad is loaded");
    let tenth = ball(&["operating.load_n=191.8"]);
    let light = solve(&tenth, None);
    assert!(light.pads.iter().all(|p| !p.unloaded), "at a tenth of the load every pad is loaded");
    for (tag, start) in [("from rockers", &rockers), ("from a tenth of the load", &tenth)] {
        let warm = solve(&c, Some(start));
        assert_pivots_carry_the_film_loads(&c, &warm, tag);
        assert_eq!(warm.pads[0].unloaded, cold.pads[0].unloaded, "{tag}");
        let scale = cold.coordinates[1].abs();
        for (a, b) in warm.coordinates[..2].iter().zip(&cold.coordinates[..2]) {
            assert!(
                (a - b).abs() < 1e-6 * scale,
                "{tag}: journal {:?} vs {:?}",
                &warm.coordinates[..2],
                &cold.coordinates[..2]
            );
        }
        for k in 0..c.bearing.pads.len() {
            assert!((film_load(&c, &warm, k) - film_load(&c, &cold, k)).abs() < 1e-4 * LOAD_N, "{tag} pad {k}");
        }
    }
}
