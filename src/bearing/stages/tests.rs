//! Execution counters: what reruns on which edit; suspension and resumption.

use std::sync::Arc;

use crate::bearing::film::model::BearingModel;
use crate::bearing::report::progress::{Cancel, NoCancel};
use crate::bearing::solution::Solution;
use crate::bearing::stages::equilibrium::MAX_SUSPENSIONS;
use crate::bearing::stages::id::StageId;
use crate::bearing::stages::outcome::Step;
use crate::bearing::stages::registry::Stages;
use crate::bearing::stages::request::{Request, Start};
use crate::bearing::stages::stage::{Ctx, Solver};
use crate::bearing::stages::{coefficients, equilibrium, thermal};
use crate::model::{load_case, Case};

fn case(set: &[&str]) -> Case {
    let text = include_str!("../../../cases/fillon-a.toml");
    // These tests are about the isothermal stages; the thermal stage has its own test below.
    let set: Vec<String> =
        std::iter::once("thermal.model=\"isothermal\"").chain(set.iter().copied()).map(str::to_string).collect();
    load_case(&text.replace("fidelity = \"standard\"", "fidelity = \"preview\""), &set).unwrap().1
}

const RATIOS: [f64; 3] = [0.5, 1.0, 2.0];

fn with_sweep(case: Case) -> Request {
    Request {
        case,
        wanted: vec![StageId::Reduction, StageId::FrequencySweep],
        frequency_ratios: RATIOS.to_vec(),
        speeds_rad_s: Vec::new(),
        start: Start::Warm,
    }
}

/// Runs of (Films, Equilibrium, Thermal, Coefficients, Reduction, FrequencySweep, SpeedSweep); the FRF
/// stage has its own test.
fn runs(s: &Stages) -> [usize; 7] {
    let v: Vec<usize> = s.all_runs().into_iter().map(|(_, n)| n).collect();
    v[..7].try_into().unwrap()
}

/// The FRF stage reads the ports' pads, not the valve, lines or rig: the sliders of the FRF view (air
/// fraction, line length, valve bandwidth) rerun no stage; the load reruns the equilibrium and the FRF
/// stage; its model equals the one the CLI builds on its own.
#[test]
fn the_frf_stage_reads_the_ports_pads_only() {
    let rig = |set: &[&str]| {
        let set: Vec<String> = set.iter().map(|s| (*s).to_string()).collect();
        load_case(include_str!("../../../cases/test-rig-pub5.toml"), &set).unwrap().1
    };
    let req = |case: Case| Request::of(case, &[StageId::Reduction, StageId::Frf]);
    let mut s = Stages::new();
    let first = s.run(&req(rig(&[])), &NoCancel).unwrap();
    let model = first.get::<crate::bearing::frf::model::FrfModel>(StageId::Frf).unwrap();
    assert_eq!((s.runs(StageId::Equilibrium), s.runs(StageId::Frf)), (1, 1));
    for edit in [
        "hydraulics.port.0.air_fraction=0.01",
        "hydraulics.port.0.line_length_mm=1500",
        "hydraulics.valve.natural_frequency_hz=80",
        "hydraulics.supply_pressure_bar=40",
    ] {
        let o = s.run(&req(rig(&[edit])), &NoCancel).unwrap();
        assert_eq!((s.runs(StageId::Equilibrium), s.runs(StageId::Frf)), (1, 1), "{edit} ran a stage");
        assert!(Arc::ptr_eq(&o.get::<crate::bearing::frf::model::FrfModel>(StageId::Frf).unwrap(), &model));
    }
    s.run(&req(rig(&["operating.load_n=500"])), &NoCancel).unwrap();
    assert_eq!((s.runs(StageId::Equilibrium), s.runs(StageId::Frf)), (2, 2));
    // The CLI's model (the stage alone, on fresh stages) is the app's, to round-off.
    let alone = Stages::new().frf(&rig(&[]), &NoCancel).unwrap();
    let dk = (&alone.dynamics.k - &model.dynamics.k).norm() / model.dynamics.k.norm();
    let df =
        (&alone.dynamics.coupling.force - &model.dynamics.coupling.force).norm() / model.dynamics.coupling.force.norm();
    assert!(dk < 1e-9 && df < 1e-9, "{dk:e} {df:e}");
    assert!(model.dynamics.m.norm() > 0.0, "pad inertia");
}

#[test]
fn stages_rerun_only_when_their_inputs_change() {
    let mut s = Stages::new();
    let mut req = with_sweep(case(&[]));
    s.run(&req, &NoCancel).unwrap();
    assert_eq!(runs(&s), [1, 1, 0, 1, 1, 1, 0]);
    // Same request: nothing runs.
    s.run(&req, &NoCancel).unwrap();
    assert_eq!(runs(&s), [1, 1, 0, 1, 1, 1, 0]);
    // The title and the excitation ratio do not enter the equilibrium.
    req.case = case(&["title=\"renamed\"", "operating.excitation_ratio=0.5"]);
    let o = s.run(&req, &NoCancel).unwrap();
    assert_eq!(runs(&s), [1, 1, 0, 1, 2, 1, 0]);
    let sol = o.solution().unwrap();
    assert_eq!(sol.title, "renamed");
    assert_eq!(sol.inputs, req.case);
    // The load changes the equilibrium and everything after it, not the films.
    req.case = case(&["operating.load_n=8000"]);
    s.run(&req, &NoCancel).unwrap();
    assert_eq!(runs(&s), [1, 2, 0, 2, 3, 2, 0]);
    // The mesh changes everything.
    req.case = case(&["operating.load_n=8000", "mesh.circumferential_elements=20"]);
    s.run(&req, &NoCancel).unwrap();
    assert_eq!(runs(&s), [2, 3, 0, 3, 4, 3, 0]);
    // A tuning key reruns the equilibrium and what follows it (they key on every tuning value), not the films.
    req.case = case(&["operating.load_n=8000", "mesh.circumferential_elements=20", "thermal.max_iterations=50"]);
    s.run(&req, &NoCancel).unwrap();
    assert_eq!(runs(&s), [2, 4, 0, 4, 5, 4, 0]);
}

#[test]
fn edits_that_no_stage_reads_run_nothing() {
    let mut s = Stages::new();
    let base = case(&[]);
    let first = s.run(&with_sweep(base.clone()), &NoCancel).unwrap().solution().unwrap();
    assert_eq!(runs(&s), [1, 1, 0, 1, 1, 1, 0]);
    for edit in [
        "bearing.pads.youngs_modulus_gpa=100",
        "bearing.pads.poisson_ratio=0.25",
        "mesh.max_nodes=5000000",
        "lubricant.name=\"another oil\"",
    ] {
        let edited = case(&[edit]);
        assert_ne!(edited, base, "{edit} edits the case");
        let again = s.run(&with_sweep(edited.clone()), &NoCancel).unwrap().solution().unwrap();
        assert_eq!(runs(&s), [1, 1, 0, 1, 1, 1, 0], "{edit} ran a stage");
        // The published solution carries the edited case, with the same numbers.
        assert_eq!(again.inputs, edited);
        assert_eq!(again.eccentricity_ratio.to_bits(), first.eccentricity_ratio.to_bits());
    }
}

#[test]
fn pad_density_reruns_only_what_depends_on_inertia() {
    let mut s = Stages::new();
    let light = s.run(&with_sweep(case(&[])), &NoCancel).unwrap().solution().unwrap();
    let heavy =
        s.run(&with_sweep(case(&["bearing.pads.density_kg_per_m3=15600"])), &NoCancel).unwrap().solution().unwrap();
    // Films, equilibrium untouched; coefficients, reduction and the frequency sweep rerun.
    assert_eq!(runs(&s), [1, 1, 0, 2, 2, 2, 0]);
    // The inertia is proportional to the density; the film's K and C are unchanged.
    let m_max = light.full.m.iter().flatten().fold(0.0_f64, |a, &x| a.max(x.abs()));
    assert!(m_max > 0.0);
    for (a, b) in light.full.m.iter().flatten().zip(heavy.full.m.iter().flatten()) {
        assert!((b - 2.0 * a).abs() <= 1e-12 * m_max, "{b} vs 2 × {a}");
    }
    assert_eq!(light.full.k, heavy.full.k);
    assert_eq!(light.full.c, heavy.full.c);
    // The same inertia as a solve from scratch of the heavy case.
    let fresh = crate::bearing::stages::registry::solve_case(&case(&["bearing.pads.density_kg_per_m3=15600"])).unwrap();
    for (a, b) in fresh.full.m.iter().flatten().zip(heavy.full.m.iter().flatten()) {
        assert!((a - b).abs() <= 1e-12 * m_max, "{a} vs {b}");
    }
}

#[test]
fn pivot_stiffness_reruns_the_equilibrium_on_the_same_films() {
    let mut s = Stages::new();
    let soft = case(&["bearing.pads.pivot_stiffness_n_per_m=2e8"]);
    let stiff = case(&["bearing.pads.pivot_stiffness_n_per_m=2e9"]);
    let a = s.run(&Request::solution(soft), &NoCancel).unwrap().solution().unwrap();
    let b = s.run(&Request::solution(stiff.clone()), &NoCancel).unwrap().solution().unwrap();
    // The films are kept (their coordinates are the same); everything from the equilibrium on reruns.
    assert_eq!(runs(&s), [1, 2, 0, 2, 2, 0, 0]);
    // The stiffer spring moves the pivots less, and the result is the one of a solve from scratch.
    let pivot = |s: &Solution| s.pads.iter().map(|p| p.pivot_displacement_m.unwrap().abs()).fold(0.0, f64::max);
    assert!(pivot(&b) < 0.5 * pivot(&a), "{} vs {}", pivot(&b), pivot(&a));
    let fresh = crate::bearing::stages::registry::solve_case(&stiff).unwrap();
    let rel = |x: f64, y: f64| ((x - y) / y).abs();
    assert!(
        rel(b.eccentricity_ratio, fresh.eccentricity_ratio) < 1e-6,
        "{} vs {}",
        b.eccentricity_ratio,
        fresh.eccentricity_ratio
    );
    assert!(rel(pivot(&b), pivot(&fresh)) < 1e-5);
    assert!(rel(b.reduced.k_n_per_m[1][1], fresh.reduced.k_n_per_m[1][1]) < 1e-5);
    // Removing the spring changes the pads' coordinates: new films.
    s.run(&Request::solution(case(&[])), &NoCancel).unwrap();
    assert_eq!(runs(&s)[0], 2);
}

fn flexible(set: &[&str]) -> Case {
    let text = include_str!("../../../cases/compressor-bearing-flexible.toml");
    let set: Vec<String> =
        std::iter::once("mesh.fidelity=preview").chain(set.iter().copied()).map(str::to_string).collect();
    load_case(text, &set).unwrap().1
}

/// The modes of every pad of a solution (`None` for a rigid pad).
fn modes_of(s: &Solution) -> Vec<Option<Arc<crate::physics::pad_modes::PadModes>>> {
    s.pads.iter().map(|p| p.flex.as_ref().map(|f| f.modes.clone())).collect()
}

#[test]
fn pad_modes_are_computed_once_per_pad_shape_and_kept_across_operating_edits() {
    let mut s = Stages::new();
    let first = s.run(&Request::solution(flexible(&[])), &NoCancel).unwrap().solution().unwrap();
    // The staged solution is the one-shot solve (the modal masses reach the reduced coefficients).
    let fresh = crate::bearing::stages::registry::solve_case(&flexible(&[])).unwrap();
    assert_eq!(first.eccentricity_ratio.to_bits(), fresh.eccentricity_ratio.to_bits());
    assert_eq!(first.full.m, fresh.full.m);
    assert_eq!(first.reduced.k_n_per_m, fresh.reduced.k_n_per_m);
    let modes = modes_of(&first);
    // Five identical pads: one computation, shared.
    let m0 = modes[0].clone().expect("flexible pads");
    assert!(
        modes.iter().all(|m| m.as_ref().is_some_and(|m| Arc::ptr_eq(m, &m0))),
        "identical pads share one computation"
    );
    // Speed and load: the films (and the modes in them) are kept; the very same modes are used.
    for edit in ["operating.speed_rpm=7000", "operating.load_n=3000"] {
        let again = s.run(&Request::solution(flexible(&[edit])), &NoCancel).unwrap().solution().unwrap();
        assert_eq!(runs(&s)[0], 1, "{edit} rebuilt the films");
        assert!(
            modes_of(&again).iter().all(|m| m.as_ref().is_some_and(|m| Arc::ptr_eq(m, &m0))),
            "{edit} recomputed the modes"
        );
        assert_ne!(again.eccentricity_ratio, first.eccentricity_ratio, "{edit} changes the solution");
    }
    // What the modes read recomputes them: E (frequency ∝ √E) and density (∝ 1/√ρ).
    let f0 = m0.modes[0].frequency_hz;
    let stiff = s
        .run(&Request::solution(flexible(&["bearing.pads.youngs_modulus_gpa=800"])), &NoCancel)
        .unwrap()
        .solution()
        .unwrap();
    assert_eq!(runs(&s)[0], 2);
    let f = modes_of(&stiff)[0].as_ref().unwrap().modes[0].frequency_hz;
    assert!((f / f0 - 2.0).abs() < 1e-9, "E × 4 doubles the frequency: {f} / {f0}");
    let light = s
        .run(&Request::solution(flexible(&["bearing.pads.density_kg_per_m3=1950"])), &NoCancel)
        .unwrap()
        .solution()
        .unwrap();
    assert_eq!(runs(&s)[0], 3);
    let f = modes_of(&light)[0].as_ref().unwrap().modes[0].frequency_hz;
    assert!((f / f0 - 2.0).abs() < 1e-9, "ρ / 4 doubles the frequency: {f} / {f0}");
    // Rigid pads (no modes): E and ν are read by no stage (see edits_that_no_stage_reads_run_nothing).
    let rigid = s.run(&Request::solution(flexible(&["physics.pad_modes=0"])), &NoCancel).unwrap().solution().unwrap();
    assert!(modes_of(&rigid).iter().all(Option::is_none));
}

/// Asks every solve to pause as soon as it may (the web stepper with a spent frame budget).
pub(super) struct AlwaysSuspend;
impl Cancel for AlwaysSuspend {
    fn cancelled(&self) -> bool {
        false
    }
    fn suspend(&self) -> bool {
        true
    }
}

#[test]
fn a_suspended_equilibrium_resumes_from_its_iterate_and_reaches_the_same_solution() {
    let req = Request::solution(case(&["operating.load_n=12000"]));
    let whole = Stages::new().run(&req, &NoCancel).unwrap().solution().unwrap();
    let mut s = Stages::new();
    let mut equilibrium_steps = 0;
    let parts = loop {
        match s.step(&req, &AlwaysSuspend).unwrap() {
            Step::Done(o) => break o.solution().unwrap(),
            Step::Pending { stage: StageId::Equilibrium, .. } => equilibrium_steps += 1,
            Step::Pending { .. } => {}
        }
        assert!(equilibrium_steps <= MAX_SUSPENSIONS + 1, "suspensions are bounded");
    };
    // The cold start places one pad per step, then one Newton iteration per step (the last converges).
    let pads = parts.pads.len();
    assert!(equilibrium_steps > pads, "the solve was split: {equilibrium_steps} steps for {pads} pads");
    assert_eq!(s.runs(StageId::Equilibrium), 1);
    assert!(parts.report.resumed_parts > 0, "{}", parts.report.method_text());
    assert!(parts.report.method_text().contains("resumed"), "{}", parts.report.method_text());
    assert!(
        parts.report.iterations + pads >= equilibrium_steps,
        "the report counts every part: {}",
        parts.report.iterations
    );
    assert_eq!(parts.report.residual_history.len(), parts.report.iterations);
    assert!(parts.report.residual < 1e-9, "converged: {:e}", parts.report.residual);
    let rel = |a: f64, b: f64| ((a - b) / b).abs();
    assert!(
        rel(parts.eccentricity_ratio, whole.eccentricity_ratio) < 1e-6,
        "{} vs {}",
        parts.eccentricity_ratio,
        whole.eccentricity_ratio
    );
    assert!(rel(parts.reduced.k_n_per_m[1][1], whole.reduced.k_n_per_m[1][1]) < 1e-5);
}

fn speed_request(case: Case) -> Request {
    let speeds_rad_s = [2000.0, 3000.0, 4000.0].map(|n| crate::units::RPM.to_si(n)).to_vec();
    Request { speeds_rad_s, ..Request::of(case, &[StageId::SpeedSweep]) }
}

#[test]
fn suspended_speed_sweep_points_resume_and_match_whole_ones() {
    let req = speed_request(case(&[]));
    let whole = Stages::new().run(&req, &NoCancel).unwrap().speed_sweep().unwrap();
    let mut s = Stages::new();
    let mut sweep_steps = 0;
    let parts = loop {
        match s.step(&req, &AlwaysSuspend).unwrap() {
            Step::Done(o) => break o.speed_sweep().unwrap(),
            Step::Pending { stage: StageId::SpeedSweep, .. } => sweep_steps += 1,
            Step::Pending { .. } => {}
        }
        assert!(sweep_steps <= 3 * (MAX_SUSPENSIONS + 1), "suspensions are bounded");
    };
    assert!(sweep_steps > 3, "points were split: {sweep_steps} steps");
    assert_eq!(s.runs(StageId::SpeedSweep), 1);
    assert_eq!(parts.len(), 3);
    for (a, b) in parts.iter().zip(whole.iter()) {
        let (ea, eb) = (a.result.as_ref().unwrap().eccentricity_ratio, b.result.as_ref().unwrap().eccentricity_ratio);
        assert!(((ea - eb) / eb).abs() < 1e-6, "{} rad/s: {ea} vs {eb}", a.speed_rad_s);
    }
}

#[test]
fn speed_sweep_runs_point_by_point_and_is_cached() {
    let mut s = Stages::new();
    let req = speed_request(case(&[]));
    let mut steps = 0;
    let out = loop {
        steps += 1;
        match s.step(&req, &NoCancel).unwrap() {
            Step::Done(o) => break o,
            Step::Pending { .. } => {}
        }
    };
    // Three sweep points, done: the sweep does not wait for the equilibrium at the case's speed, and its
    // nested stages build their own films.
    assert_eq!(steps, 4);
    assert_eq!(runs(&s), [0, 0, 0, 0, 0, 0, 1]);
    let sweep = out.speed_sweep().unwrap();
    assert_eq!(sweep.len(), 3);
    let e: Vec<f64> = sweep.iter().map(|p| p.result.as_ref().unwrap().eccentricity_ratio).collect();
    assert!(e[0] > e[1] && e[1] > e[2], "eccentricity falls with speed: {e:?}");
    // The 4000 rpm point is the case's own solution.
    let own = crate::bearing::stages::registry::solve_case(&req.case).unwrap();
    assert!(
        ((e[2] - own.eccentricity_ratio) / own.eccentricity_ratio).abs() < 1e-6,
        "{} vs {}",
        e[2],
        own.eccentricity_ratio
    );
    // Cached; the case's speed is not an input of the sweep.
    s.run(&req, &NoCancel).unwrap();
    s.run(&speed_request(case(&["operating.speed_rpm=3000"])), &NoCancel).unwrap();
    assert_eq!(s.runs(StageId::SpeedSweep), 1);
}

#[test]
fn thermal_stage_runs_the_loop_one_outer_iteration_per_step_and_is_cached() {
    let thd = |extra: &[&str]| {
        let mut set = vec!["thermal.model=\"thd\""];
        set.extend_from_slice(extra);
        case(&set)
    };
    let mut s = Stages::new();
    let mut req = Request::solution(thd(&[]));
    // The loop runs one outer iteration per step.
    let mut thermal_steps = 0;
    let o = loop {
        match s.step(&req, &NoCancel).unwrap() {
            Step::Done(o) => break o,
            Step::Pending { stage: StageId::Thermal, .. } => thermal_steps += 1,
            Step::Pending { .. } => {}
        }
    };
    // The isothermal equilibrium is the loop's first outer iteration: no equilibrium stage of its own.
    assert_eq!(runs(&s), [1, 0, 1, 1, 1, 0, 0]);
    let sol = o.solution().unwrap();
    let t = sol.thermal.as_ref().expect("thermal results");
    assert!(t.report.converged && t.t_max_film_c > 40.0);
    assert_eq!(thermal_steps, t.report.outer_iterations, "one step per outer iteration");
    assert!(thermal_steps > 2);
    // The same state as the thermal loop run in one go on its own model.
    let mut m = BearingModel::new(&req.case).unwrap();
    crate::bearing::stages::films::install_structure(&mut m, &req.case).unwrap();
    let mut tm = crate::bearing::thermal::ThermalModel::new(&req.case, &m).unwrap();
    let whole = crate::bearing::thermal::solve_thd(
        &mut m,
        &mut tm,
        &req.case,
        crate::bearing::thermal::ThermalParams::default(),
        None,
        &NoCancel,
    )
    .unwrap();
    let w_max = whole.pads.iter().flat_map(|p| p.film_c.iter().copied()).fold(f64::NEG_INFINITY, f64::max);
    assert!((w_max - t.t_max_film_c).abs() < 1e-9, "{w_max} vs {}", t.t_max_film_c);
    assert_eq!(whole.report.outer_iterations, t.report.outer_iterations);
    assert!(sol
        .pads
        .iter()
        .all(|p| p.field.film_temperature_c.is_some() && p.field.pad_surface_temperature_c.is_some()));
    // The headline report is the whole loop's: every equilibrium of it and its time, not the last one's.
    let r = &sol.report;
    assert_eq!((r.iterations, r.film_solves), (t.report.equilibrium_iterations, t.report.film_solves));
    assert!(r.factorizations > t.report.equilibrium_factorizations);
    assert_eq!(r.seconds, t.report.seconds);
    // A thermal setting reruns only the thermal stage (and those after it).
    req.case = thd(&["thermal.convection_w_per_m2_k=150"]);
    s.run(&req, &NoCancel).unwrap();
    assert_eq!(runs(&s), [1, 0, 2, 2, 2, 0, 0]);
    // The excitation ratio reruns only the reduction.
    req.case = thd(&["thermal.convection_w_per_m2_k=150", "operating.excitation_ratio=0.5"]);
    s.run(&req, &NoCancel).unwrap();
    assert_eq!(runs(&s), [1, 0, 2, 2, 3, 0, 0]);
}

/// The web stepper with a spent budget: each THD outer iteration's equilibrium is split into parts (one
/// step each), and the loop reaches the state of the loop run without pauses.
#[test]
fn a_suspended_thermal_loop_splits_its_equilibria_and_reaches_the_same_state() {
    let req = Request::solution(case(&["thermal.model=\"thd\""]));
    let whole = Stages::new().run(&req, &NoCancel).unwrap().solution().unwrap();
    let mut s = Stages::new();
    let mut thermal_steps = 0;
    let parts = loop {
        match s.step(&req, &AlwaysSuspend).unwrap() {
            Step::Done(o) => break o.solution().unwrap(),
            Step::Pending { stage: StageId::Thermal, .. } => thermal_steps += 1,
            Step::Pending { .. } => {}
        }
        assert!(thermal_steps < 10_000, "the loop ends");
    };
    let (t, w) = (parts.thermal.as_ref().unwrap(), whole.thermal.as_ref().unwrap());
    assert!(t.report.converged);
    let outer = t.report.outer_iterations;
    assert!(thermal_steps > outer, "{thermal_steps} steps for {outer} outer iterations");
    assert!(thermal_steps <= outer * (crate::bearing::thermal::resumable::MAX_EQUILIBRIUM_PARTS + 1));
    assert_eq!(outer, w.report.outer_iterations);
    assert!((t.t_max_film_c - w.t_max_film_c).abs() < 1e-6, "{} vs {}", t.t_max_film_c, w.t_max_film_c);
    assert!(((parts.eccentricity_ratio - whole.eccentricity_ratio) / whole.eccentricity_ratio).abs() < 1e-6);
}

#[test]
fn every_stage_reads_only_stages_registered_before_it() {
    for (i, s) in StageId::ALL.iter().enumerate() {
        assert_eq!(s.index(), i);
        for n in s.declared() {
            assert!(n.index() < i, "{s:?} reads {n:?}, registered after it");
        }
    }
    // What a wanted stage pulls in for a request: the reduction of an isothermal case reads the films, the
    // equilibrium and the coefficients; of a THD case the thermal loop instead of the equilibrium; the FRF
    // stage the equilibrium — of a case with `[hydraulics]`: where it does not apply it pulls in nothing; the
    // speed sweep runs nested stages and reads none.
    let needed = |req: &Request| -> Vec<StageId> {
        Stages::needed(req).iter().zip(StageId::ALL).filter(|(n, _)| **n).map(|(_, s)| *s).collect()
    };
    use StageId::*;
    let iso = case(&[]);
    let thd = case(&["thermal.model=\"thd\""]);
    assert_eq!(needed(&Request::solution(iso.clone())), vec![Films, Equilibrium, Coefficients, Reduction]);
    assert_eq!(needed(&Request::solution(thd.clone())), vec![Films, Thermal, Coefficients, Reduction]);
    assert_eq!(
        needed(&Request::of(thd.clone(), &[Reduction, Frf])),
        vec![Films, Thermal, Coefficients, Reduction, Frf]
    );
    let mut rig = load_case(include_str!("../../../cases/test-rig-pub5.toml"), &[]).unwrap().1;
    rig.thermal = thd.thermal;
    assert_eq!(
        needed(&Request::of(rig, &[Reduction, Frf])),
        vec![Films, Equilibrium, Thermal, Coefficients, Reduction, Frf]
    );
    assert_eq!(needed(&Request::of(iso, &[SpeedSweep])), vec![SpeedSweep]);
}

#[test]
fn a_stage_reads_only_what_it_declared_and_only_when_current() {
    let mut s = Stages::new();
    let req = Request::solution(case(&[]));
    let reader = |id: StageId| crate::bearing::stages::stage::Reader { label: id.label(), needs: id.declared() };
    let nested = || -> Box<dyn Solver> { Box::new(Stages::new()) };
    let coefficients = |req: &Request| coefficients::CoefficientsInputs::of(&req.case);
    let refusal = |id: StageId, s: &mut Stages, req: &Request| -> String {
        let ctx = Ctx { slots: &mut s.slots, reader: reader(id), start: Start::Warm, nested };
        match id {
            StageId::Films => {
                ctx.output::<equilibrium::EquilibriumStage>(&equilibrium::EquilibriumInputs::of(&req.case)).map(|_| ())
            }
            StageId::Coefficients => {
                let thd = case(&["thermal.model=\"thd\""]);
                ctx.output::<thermal::ThermalStage>(&thermal::ThermalInputs::of(&thd).unwrap()).map(|_| ())
            }
            _ => ctx.output::<coefficients::CoefficientsStage>(&coefficients(req)).map(|_| ()),
        }
        .map_or_else(|e| e.to_string(), |()| "read".into())
    };
    // The films declare no upstream stage.
    assert!(refusal(StageId::Films, &mut s, &req).contains("not declared in NEEDS"));
    // Declared, but not computed yet.
    assert!(refusal(StageId::Reduction, &mut s, &req).contains("not current"));
    s.run(&req, &NoCancel).unwrap();
    assert_eq!(refusal(StageId::Reduction, &mut s, &req), "read");
    // The thermal stage has not run for this isothermal case.
    assert!(refusal(StageId::Coefficients, &mut s, &req).contains("not current"));
    // An edit that changes the coefficients' inputs makes the old output unreadable.
    let edited = Request::solution(case(&["operating.load_n=8000"]));
    assert!(refusal(StageId::Reduction, &mut s, &edited).contains("not current"));
}
