//! Hertz pivots in the stepped solve (the web build without a worker: every stage polled with a spent frame
//! budget): the pivots' load iteration pauses inside its equilibria and between its load steps, and the
//! resumed solve reaches the solution of the solve run in one go — isothermal and THD, on the rocker case.

use crate::bearing::report::progress::NoCancel;
use crate::bearing::solution::Solution;
use crate::bearing::stages::equilibrium::MAX_SUSPENSIONS;
use crate::bearing::stages::id::StageId;
use crate::bearing::stages::outcome::Step;
use crate::bearing::stages::registry::Stages;
use crate::bearing::stages::request::Request;
use crate::bearing::stages::tests::AlwaysSuspend;
use crate::model::{load_case, Case};

fn rocker(set: &[&str]) -> Case {
    let text = include_str!("../../../cases/compressor-bearing-rocker-pivot.toml");
    let set: Vec<String> =
        std::iter::once("mesh.fidelity=preview").chain(set.iter().copied()).map(str::to_string).collect();
    load_case(text, &set).unwrap().1
}

/// The solution stepped with a spent budget, and the steps each stage was pending.
fn stepped(req: &Request) -> (Solution, usize, usize) {
    let mut s = Stages::new();
    let (mut equilibrium, mut thermal) = (0, 0);
    let sol = loop {
        match s.step(req, &AlwaysSuspend).unwrap() {
            Step::Done(o) => break o.solution().unwrap(),
            Step::Pending { stage: StageId::Equilibrium, .. } => equilibrium += 1,
            Step::Pending { stage: StageId::Thermal, .. } => thermal += 1,
            Step::Pending { .. } => {}
        }
        assert!(equilibrium + thermal < 20_000, "the stepped solve ends");
    };
    (Solution::clone(&sol), equilibrium, thermal)
}

/// Largest coordinate difference of the journal and the loaded pads relative to the journal displacement,
/// the largest pivot-load difference relative to the case's load, and the largest coordinate difference of
/// the floating pads (unloaded: their tilt is weakly determined, set where film pressure begins, so it
/// agrees only to the equilibrium's tolerance on a pad without stiffness) [rad or m].
fn differences(a: &Solution, b: &Solution) -> (f64, f64, f64) {
    let scale = b.coordinates[0].hypot(b.coordinates[1]);
    let load = |p: &crate::bearing::solution::PadResult| p.pivot_contact.map_or(0.0, |c| c.load_n);
    let per_pad = (b.coordinates.len() - 2) / b.pads.len();
    let (mut du, mut floating) = (0.0_f64, 0.0_f64);
    for (i, (x, y)) in a.coordinates.iter().zip(&b.coordinates).enumerate() {
        let d = (x - y).abs();
        match i.checked_sub(2).map(|j| b.pads[j / per_pad].unloaded) {
            Some(true) => floating = floating.max(d),
            _ => du = du.max(d / scale),
        }
    }
    let df = a.pads.iter().zip(&b.pads).map(|(x, y)| (load(x) - load(y)).abs()).fold(0.0, f64::max);
    (du, df / 1918.0, floating)
}

#[test]
fn the_stepped_isothermal_solve_runs_the_hertz_load_iteration_in_parts_and_meets_the_direct_one() {
    let req = Request::solution(rocker(&["thermal.model=\"isothermal\""]));
    let direct = Stages::new().run(&req, &NoCancel).unwrap().solution().unwrap();
    let (parts, equilibrium_steps, _) = stepped(&req);
    let steps = parts.report.pivot_load_iterations.expect("Hertz load iteration");
    let direct_steps = direct.report.pivot_load_iterations.expect("Hertz load iteration");
    eprintln!(
        "stepped: {equilibrium_steps} equilibrium steps, {steps} load steps ({direct_steps} direct); {}",
        parts.report.method_text()
    );
    // The load iteration was split: more polls than load steps (each load step's equilibrium in parts), and
    // bounded by the suspensions the stage allows.
    assert!(equilibrium_steps > steps, "{equilibrium_steps} equilibrium steps for {steps} load steps");
    assert!(equilibrium_steps <= MAX_SUSPENSIONS + 1);
    assert!(parts.report.resumed_parts > 0, "{}", parts.report.method_text());
    assert_eq!(steps, direct_steps, "the same load steps");
    assert!(parts.report.residual < 1e-9, "converged: {:e}", parts.report.residual);
    let (du, df, floating) = differences(&parts, &direct);
    eprintln!("coordinates {du:.3e} of the journal displacement, pivot loads {df:.3e} of the load, floating pads {floating:.3e}");
    assert!(
        du < 1e-6 && df < 1e-6 && floating < 1e-8,
        "coordinates {du:.3e}, pivot loads {df:.3e}, floating {floating:.3e}"
    );
    let (ks, kd) = (parts.reduced.k_n_per_m[1][1], direct.reduced.k_n_per_m[1][1]);
    assert!(((ks - kd) / kd).abs() < 1e-5, "K_yy {ks} vs {kd}");
}

#[test]
fn the_stepped_thd_solve_with_hertz_pivots_meets_the_direct_one() {
    let req = Request::solution(rocker(&["thermal.model=\"thd\""]));
    let direct = Stages::new().run(&req, &NoCancel).unwrap().solution().unwrap();
    let (parts, _, thermal_steps) = stepped(&req);
    let (t, w) = (parts.thermal.as_ref().unwrap(), direct.thermal.as_ref().unwrap());
    eprintln!(
        "stepped THD: {thermal_steps} thermal steps, {} outer iterations ({} direct)",
        t.report.outer_iterations, w.report.outer_iterations
    );
    assert!(t.report.converged && w.report.converged);
    assert!(thermal_steps > t.report.outer_iterations, "the outer iterations' equilibria were split");
    let (du, df, floating) = differences(&parts, &direct);
    eprintln!(
        "coordinates {du:.3e} of the journal displacement, pivot loads {df:.3e} of the load, floating pads \
         {floating:.3e}, T_max {} vs {}",
        t.t_max_film_c, w.t_max_film_c
    );
    assert!(
        du < 1e-6 && df < 1e-6 && floating < 1e-8,
        "coordinates {du:.3e}, pivot loads {df:.3e}, floating {floating:.3e}"
    );
    assert!((t.t_max_film_c - w.t_max_film_c).abs() < 1e-6, "{} vs {}", t.t_max_film_c, w.t_max_film_c);
}
