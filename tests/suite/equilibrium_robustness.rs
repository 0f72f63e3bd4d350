//! The equilibrium on the loads that used to fail: load on a pad of a four-pad bearing, pads that
//! float, every pad floating at the start, soft pivots under a heavy load, the pivot's transverse
//! coordinate, and a bounded slice of the convergence map (`tiltpad convergence-map` runs the whole map;
//! docs/VALIDATION.md has its table).

use crate::common;

use tiltpad::bearing::report::warning::Warning;
use tiltpad::bearing::{solve_case, Coord, EquilibriumParams, PadDof, Solution, SolveError};
use tiltpad::model::load_case;
use tiltpad::study::convergence::{family_member, map_bearing, Class, Counts, MapBearing, MapSpec};

fn run(case_file: &str, set: &[&str]) -> Result<Solution, SolveError> {
    let text = std::fs::read_to_string(common::case_path(case_file)).unwrap();
    let set: Vec<String> = set.iter().map(|s| (*s).to_string()).collect();
    let (_, case) = load_case(&text, &set).unwrap_or_else(|e| panic!("{case_file} {set:?}: {e}"));
    solve_case(&case)
}

fn converged(case_file: &str, set: &[&str]) -> Solution {
    let s = run(case_file, set).unwrap_or_else(|e| panic!("{case_file} {set:?} must converge: {e}"));
    let tol = EquilibriumParams::default().force_tol;
    assert!(s.report.residual <= tol, "{case_file} {set:?}: residual {:.2e}", s.report.residual);
    assert!(
        s.flows_m3_per_s.mass_balance_error.abs() < 1e-12,
        "{case_file}: mass balance {:.2e}",
        s.flows_m3_per_s.mass_balance_error
    );
    s
}

/// A reported failure, reproduced: Someya's bearing with the load on a pad (315°) at 3955 N failed with "line
/// search found no decrease". It converges; the two pads beside the loaded one carry load, the opposite
/// pads float and are reported, and the load is balanced.
#[test]
fn load_on_a_pad_of_a_four_pad_bearing() {
    let s = converged("someya-4pad-lbp.toml", &["operating.load_angle_deg=315", "operating.load_n=3955"]);
    let carried = s.load_n[0].hypot(s.load_n[1]);
    assert!((carried - 3955.0).abs() < 1e-6 * 3955.0, "carried {carried}");
    // Load on pad 3 (pivot 315°): it carries most of it.
    let fy: Vec<f64> = s.pads.iter().map(|p| p.force_n[0].hypot(p.force_n[1])).collect();
    let (imax, _) = fy.iter().enumerate().fold((0, 0.0), |m, (i, v)| if *v > m.1 { (i, *v) } else { m });
    assert_eq!(imax, 3, "pad forces {fy:?}");
    assert!(fy[3] > 0.7 * 3955.0, "pad forces {fy:?}");
    // One degree off the pad gives the same state to first order.
    let off = converged("someya-4pad-lbp.toml", &["operating.load_angle_deg=314", "operating.load_n=3955"]);
    assert!(
        (off.eccentricity_ratio - s.eccentricity_ratio).abs() < 0.02 * s.eccentricity_ratio,
        "{} vs {}",
        off.eccentricity_ratio,
        s.eccentricity_ratio
    );
}

/// Floating pads carry nothing, contribute no stiffness or damping (their full-coefficient rows are zero)
/// and are named in the report and its warnings — at every fidelity level, which agree on which pads float.
#[test]
fn floating_pads_are_reported_and_carry_nothing() {
    let mut sets = Vec::new();
    for fid in ["preview", "standard"] {
        let f = format!("mesh.fidelity=\"{fid}\"");
        let s = converged("someya-4pad-lbp.toml", &["operating.load_angle_deg=315", "operating.load_n=3955", &f]);
        assert!(!s.report.floating_pads.is_empty(), "{fid}: no floating pad reported");
        for &k in &s.report.floating_pads {
            assert!(
                s.report.warnings.iter().any(|w| matches!(w, Warning::PadFloats { pad, .. } if *pad == k)),
                "{fid}: {:?}",
                s.report.warnings
            );
            let p = &s.pads[k];
            assert!(p.force_n[0].hypot(p.force_n[1]) < 1e-4 * 3955.0, "{fid}: floating pad {k} force {:?}", p.force_n);
            for (i, c) in s.full.coords.iter().enumerate() {
                if matches!(c, Coord::Pad { pad, .. } if *pad == k) {
                    assert!(
                        s.full.k[i].iter().chain(&s.full.c[i]).all(|v| *v == 0.0),
                        "{fid}: pad {k} row {i} not zero"
                    );
                }
            }
        }
        sets.push(s.report.floating_pads.clone());
    }
    assert_eq!(sets[0], sets[1], "preview and standard disagree on the floating pads");
}

/// Taniguchi's bearing with five times its load on a pad converges with the thermal model.
#[test]
fn taniguchi_five_times_load_on_a_pad_thd() {
    let s = converged(
        "taniguchi-b.toml",
        &["operating.load_angle_deg=315", "operating.load_n=90000", "mesh.fidelity=\"preview\""],
    );
    assert!(s.thermal.is_some());
    assert!(s.eccentricity_ratio > 0.3 && s.eccentricity_ratio < 1.0, "ε {}", s.eccentricity_ratio);
}

/// A negative-preload four-pad bearing: at the centred start every pad floats (no stiffness anywhere);
/// the journal walks along the load until pads pick it up. Before, the budget ran out.
#[test]
fn every_pad_floating_at_the_start() {
    let b = family_member(4, -0.3, 0.5, false);
    let (_, case) = load_case(&b.text, &[b.set.clone(), vec!["operating.load_angle_deg=30".into()]].concat()).unwrap();
    let s = solve_case(&case).unwrap_or_else(|e| panic!("{e}"));
    assert!(s.report.residual <= EquilibriumParams::default().force_tol);
    assert!(s.report.film_solves < 1000, "{} film solves", s.report.film_solves);
    assert!(!s.report.floating_pads.is_empty());
}

/// Soft pivots (2e7 N/m) under a heavy load (Sommerfeld 0.01): the journal moves ~40 clearances with its
/// pads. The step limit grows while capped steps are taken whole, so this converges in a few iterations
/// (it ran out of iterations at 0.4 Cb per step).
///
/// Onto either pad (the map's S = 0.01 load, the loaded pivot deflecting 42 Cb): at 270° the lower pad's
/// load pushes the journal 6 mm away from the upper pad, which floats and was carried along with a stray
/// film force of 0.08 N (7e-7 of the load), sideways where the bearing has no stiffness; the solve spent
/// its budget (the map's one test-rig failure) until such a pad is placed again at its onset. At 90° the
/// lower pad does not float: its 10 bar injection pushes the journal up with 68 N.
#[test]
fn soft_pivots_under_a_heavy_load() {
    let (w, k) = (118_447.0, 2e7);
    for (angle, loaded, floating) in [(90, 1, vec![]), (270, 0, vec![1])] {
        let s = converged(
            "test-rig.toml",
            &[
                &format!("operating.load_angle_deg={angle}"),
                &format!("operating.load_n={w}"),
                "mesh.fidelity=\"preview\"",
            ],
        );
        // The pivot spring carries its pad's film force: k ξ = |F|; the two pads' forces balance the load.
        let deflection = s.pads[loaded].pivot_displacement_m.expect("the pad has a pivot spring").abs();
        let f: Vec<f64> = s.pads.iter().map(|p| p.force_n[0].hypot(p.force_n[1])).collect();
        eprintln!(
            "{angle}°: k ξ {:.6} N, pad forces {f:?} N; {} iterations, {} film solves",
            k * deflection,
            s.report.iterations,
            s.report.film_solves
        );
        assert!(
            (k * deflection - f[loaded]).abs() < 1e-9 * w,
            "{angle}°: k ξ {} N vs film {} N",
            k * deflection,
            f[loaded]
        );
        assert!((f[loaded] - f[1 - loaded] - w).abs() < 1e-9 * w, "{angle}°: pad forces {f:?}");
        assert!(s.report.iterations < 40, "{angle}°: {} iterations", s.report.iterations);
        assert_eq!(s.report.floating_pads, floating, "{angle}°");
        // 5.9 mm = 42 Cb: the report says no built bearing allows it.
        assert!(
            s.report
                .warnings
                .iter()
                .any(|m| m.to_string().starts_with(&format!("pad {loaded}'s pivot deflects by 42.3 times"))),
            "{angle}°: {:?}",
            s.report.warnings
        );
    }
}

/// The pivot's transverse coordinate: very stiff gives the result without it; the coordinate appears in
/// the full coefficients. A pressure film's force on a circular pad passes through the pad's centre of
/// curvature and (moment balance) through the pivot, so it is radial and a soft transverse spring carries
/// no load: the displacement stays at round-off of the pad force over the spring.
#[test]
fn transverse_pivot_coordinate() {
    let base = converged("test-rig.toml", &["mesh.fidelity=\"preview\""]);
    let stiff = converged(
        "test-rig.toml",
        &["mesh.fidelity=\"preview\"", "bearing.pads.pivot_transverse_stiffness_n_per_m=1e13"],
    );
    assert!(stiff.full.coords.iter().any(|c| matches!(c, Coord::Pad { dof: PadDof::PivotTransverse, .. })));
    assert!(!base.full.coords.iter().any(|c| matches!(c, Coord::Pad { dof: PadDof::PivotTransverse, .. })));
    let rel = (stiff.eccentricity_ratio - base.eccentricity_ratio).abs() / base.eccentricity_ratio;
    assert!(rel < 1e-4, "ε {} vs {} ({rel:.1e})", stiff.eccentricity_ratio, base.eccentricity_ratio);
    let k_t = 1e6;
    let soft = converged(
        "test-rig.toml",
        &["mesh.fidelity=\"preview\"", "bearing.pads.pivot_transverse_stiffness_n_per_m=1e6"],
    );
    for p in &soft.pads {
        let eta = p.pivot_transverse_displacement_m.expect("transverse coordinate");
        let f = p.force_n[0].hypot(p.force_n[1]);
        assert!(
            (eta * k_t).abs() < 1e-6 * f.max(1.0),
            "pad {}: transverse spring force {:.3e} N of a pad force {f:.3e} N",
            p.index,
            eta * k_t
        );
    }
}

/// Two pads at 0° and 180° cannot carry a load across them: a typed error naming the axis and the load.
#[test]
fn no_stiffness_is_a_typed_answer_only_outside_the_pads() {
    let b = family_member(2, 0.0, 0.5, true);
    let (_, case) = load_case(&b.text, &[b.set.clone(), vec!["operating.load_angle_deg=0".into()]].concat()).unwrap();
    match solve_case(&case) {
        Err(SolveError::NoStiffness { axis_deg, load_component_n }) => {
            assert!((axis_deg.rem_euclid(180.0)).abs() < 1.0, "axis {axis_deg}");
            assert!((load_component_n - 1000.0).abs() < 1.0, "component {load_component_n}");
        }
        other => panic!("expected NoStiffness, got {:?}", other.map(|s| s.eccentricity_ratio)),
    }
}

/// A slice of the convergence map: Someya's bearing every 30° at two loads, and negative-preload four-pad
/// family members at light load — with the pivot past mid-pad (α 0.6) the pads' loaded states exist only
/// beyond a fold, so a pressure-free placement leaves the load unsupported until every floating pad is
/// searched for its loaded state: no failures.
#[test]
fn convergence_map_slice() {
    let text = std::fs::read_to_string(common::case_path("someya-4pad-lbp.toml")).unwrap();
    let spec = MapSpec { direction_step_deg: 30.0, sommerfeld: vec![1.0, 0.1] };
    let mut points =
        map_bearing(&MapBearing { name: "someya".into(), text, set: vec!["mesh.fidelity=\"preview\"".into()] }, &spec)
            .unwrap();
    let light = MapSpec { direction_step_deg: 90.0, sommerfeld: vec![10.0] };
    points.extend(map_bearing(&family_member(4, -0.3, 0.5, true), &light).unwrap());
    let fold = MapSpec { direction_step_deg: 90.0, sommerfeld: vec![10.0, 1.0] };
    points.extend(map_bearing(&family_member(4, -0.3, 0.6, false), &fold).unwrap());
    let counts = Counts::of(&points);
    let failures: Vec<String> = points
        .iter()
        .filter(|p| p.class == Class::Failure)
        .map(|p| format!("{} {}° S {}: {}", p.bearing, p.direction_deg, p.sommerfeld, p.detail))
        .collect();
    assert!(failures.is_empty(), "{failures:#?}");
    assert_eq!(counts.total(), 36);
    assert!(counts.converged >= 32, "{counts:?}");
}

/// A pad near a fold: the compressor bearing with α 0.6, Cb 102 µm at 7000 rpm has upper pads that either
/// float or carry a light load. On the standard mesh no equilibrium with pad 0 loaded is reached and the
/// solution has it floating; the report must say that a loaded state exists (the reference mesh converges
/// with it loaded, ε 0.389 against 0.358: the batch bench's largest error comes from this design).
#[test]
fn a_pad_near_a_fold_is_reported() {
    let s = converged(
        "compressor-bearing.toml",
        &["mesh.fidelity=\"standard\"", "bearing.pads.offset=0.6", "operating.speed_rpm=7000"],
    );
    assert!(s.report.floating_pads.contains(&0), "{:?}", s.report.floating_pads);
    assert!(s.report.warnings.contains(&Warning::PadNearFold { pad: 0 }), "{:#?}", s.report.warnings);
}

/// Films that close where no method can open them are touchdown, the physical answer, not a film error:
/// Fillon's bearing A with thermal growth (TEHD) at S = 0.1 grows its loaded pads into the journal (the
/// map's 24 TEHD points at S ≤ 0.1 reported "film thickness … ≤ 0 (contact)" before). The flexible
/// compressor bearing at S = 0.01 (333 kN, 173 times its load), with and without thermal growth, presses
/// its loaded pad 3 onto the journal: along the load the film force reaches 0.44 of the load where the film
/// is down to the touchdown film (1.02 µm at ε ≈ 0.97, isothermal with growth), and further on the pad
/// solves found states with h_min ≈ 1e-16 m whose force ran from 0.1 to 3 times the load. Before, the
/// polar search took the open end of a ray whose bracket collapsed onto a closed film for the ray's root
/// and spent the 15 000 film solves of the work budget with the force residual at 0.998 (the map's 72
/// budget failures at S = 0.01); now it is touchdown on pad 3 with a positive film.
#[test]
fn closing_films_are_touchdown() {
    let iso = "thermal.model=\"isothermal\"";
    for (file, s, extra) in [
        ("fillon-a-tehd.toml", 0.1, None),
        ("compressor-bearing-flexible.toml", 0.01, None),
        ("compressor-bearing-tehd.toml", 0.01, Some(iso)),
    ] {
        let text = std::fs::read_to_string(common::case_path(file)).unwrap();
        let (_, case) = load_case(&text, &["mesh.fidelity=\"preview\"".to_string()]).unwrap();
        let load = tiltpad::study::convergence::load_for_sommerfeld(&case, s);
        let mut set = vec![
            "mesh.fidelity=\"preview\"".to_string(),
            format!("operating.load_n={load}"),
            "operating.load_angle_deg=270".to_string(),
        ];
        set.extend(extra.map(str::to_string));
        let set: Vec<&str> = set.iter().map(String::as_str).collect();
        match run(file, &set) {
            Err(SolveError::Touchdown { pad, h_min_um, eccentricity_ratio }) => {
                eprintln!(
                    "{file} at S = {s}: touchdown on pad {pad}, h_min {h_min_um:.3} µm, ε {eccentricity_ratio:.4}"
                );
                let cb_um = case.bearing.assembled_clearance_m * 1e6;
                assert!(
                    h_min_um > 0.0 && h_min_um < 0.05 * cb_um && eccentricity_ratio.is_finite(),
                    "{file}: h_min {h_min_um} µm, ε {eccentricity_ratio}"
                );
                if file != "fillon-a-tehd.toml" {
                    assert_eq!(pad, 3, "{file}: the loaded pad");
                }
            }
            other => panic!("{file} at S = {s}: got {other:?}", other = other.map(|s| s.eccentricity_ratio)),
        }
    }
}

/// Solves a generated family member at load `load_n` along `angle_deg`.
fn family_solve(
    pads: usize,
    preload: f64,
    offset: f64,
    lop: bool,
    load_n: f64,
    angle_deg: f64,
) -> Result<Solution, SolveError> {
    let b = family_member(pads, preload, offset, lop);
    let mut set = b.set.clone();
    set.push(format!("operating.load_n={load_n}"));
    set.push(format!("operating.load_angle_deg={angle_deg}"));
    let (_, case) = load_case(&b.text, &set).unwrap();
    solve_case(&case)
}

/// Three pads with negative preload and the pivot past mid-pad, lightly loaded (S = 10, 125 N): every pad
/// floats around the centre, and a pad that engages does so beyond a fold of its tilt equilibrium, already
/// carrying several hundred newtons. Along the load the force law jumps from zero across the load, so no
/// static position balances it (the map's 24 points used to spend the 9000-film-solve budget). Ten times the
/// load (S = 1) converges on the same bearing, which shows the gap is the bearing's, not the search's.
#[test]
fn a_load_inside_the_force_gap_has_no_static_equilibrium() {
    for angle in [0.0, 30.0, 90.0] {
        match family_solve(3, -0.3, 0.6, true, 125.0, angle) {
            Err(SolveError::ForceGap { below_n, above_n, load_n, .. }) => {
                assert!(below_n.abs() < 1e-6 * load_n, "{angle}°: force before the jump {below_n} N");
                assert!(
                    above_n > 2.0 * load_n,
                    "{angle}°: force after the jump {above_n} N against the load {load_n} N"
                );
                let s = family_solve(3, -0.3, 0.6, true, 10.0 * load_n, angle)
                    .unwrap_or_else(|e| panic!("{angle}°: ten times the load must converge: {e}"));
                assert!(
                    s.report.residual <= EquilibriumParams::default().force_tol,
                    "{angle}°: residual {:.2e}",
                    s.report.residual
                );
            }
            other => panic!("{angle}°: expected a force gap, got {:?}", other.map(|s| s.eccentricity_ratio)),
        }
    }
}

/// Two pads with negative preload, the load on one pad (S = 1): the opposite, unloaded pad is pressed onto the
/// journal by its own film at one edge over its whole tilt range (the map's 4 points stalled there with a pad
/// residual of 4 %): its film closed (h = 0 at the edge), said as such on that pad — not touchdown, which
/// is a load the films cannot carry. The same bearing loaded across its pivot line still answers that it has
/// no stiffness there, whatever the search met on the way.
#[test]
fn an_unloaded_pad_leaning_on_its_edge_closes_its_film() {
    match family_solve(2, -0.3, 0.5, true, 1250.0, 90.0) {
        Err(SolveError::FilmClosed { pad, h_min_um, .. }) => {
            assert!(pad == 0 && h_min_um.abs() < 1e-3, "pad {pad}, h_min {h_min_um} µm")
        }
        other => panic!("expected the unloaded pad's closed film, got {:?}", other.map(|s| s.eccentricity_ratio)),
    }
    match family_solve(2, -0.3, 0.5, true, 1250.0, 30.0) {
        Err(SolveError::NoStiffness { axis_deg, load_component_n }) => {
            assert!((axis_deg.rem_euclid(180.0)).min(180.0 - axis_deg.rem_euclid(180.0)) < 1e-6, "axis {axis_deg}°");
            assert!(
                (load_component_n - 1250.0 * 30f64.to_radians().cos()).abs() < 1e-6 * 1250.0,
                "component {load_component_n} N"
            );
        }
        other => panic!("expected no stiffness across the pivot line, got {:?}", other.map(|s| s.eccentricity_ratio)),
    }
}

/// The same bearing between the two (S = 1, and 581 N and 700 N along 0°, which the check along the load
/// missed): the loaded pad's force runs along its pivot line, 20° off the load, and the neighbour that would
/// balance the rest would have to carry less than its own fold load. The journal positions that balance the
/// load along their own direction break off where that neighbour engages: the residual force jumps over zero
/// there (`ForceGap2d`). Mirror-image loads about the pad at 30° (20° and 40°) meet mirror-image jumps at
/// mirror-image pads; ten times the load converges.
#[test]
fn a_load_inside_a_two_dimensional_force_gap_has_no_static_equilibrium() {
    let gap = |load_n: f64, angle: f64| match family_solve(3, -0.3, 0.6, true, load_n, angle) {
        Err(SolveError::ForceGap2d { pad, angle_deg, before_n, after_n, load_n: w }) => {
            assert!((w - load_n).abs() < 1e-9 * load_n);
            assert!(
                before_n * after_n < 0.0 && (before_n - after_n).abs() > 1e-2 * load_n,
                "{angle}°: jump {before_n} → {after_n} N"
            );
            (pad, angle_deg)
        }
        other => panic!(
            "{load_n} N at {angle}°: expected a two-dimensional force gap, got {:?}",
            other.map(|s| s.eccentricity_ratio)
        ),
    };
    let (pad20, at20) = gap(1250.0, 20.0);
    let (pad40, at40) = gap(1250.0, 40.0);
    // Pads at 270° (0), 30° (1), 150° (2): the mirror about 30° swaps pads 0 and 2.
    assert_eq!((pad20, pad40), (0, 2));
    assert!((at20 + at40 - 60.0).abs() < 1e-3, "jumps at {at20}° and {at40}° are not mirror images about 30°");
    for load_n in [581.0, 700.0] {
        gap(load_n, 0.0);
    }
    let s = family_solve(3, -0.3, 0.6, true, 12_500.0, 20.0)
        .unwrap_or_else(|e| panic!("ten times the load must converge: {e}"));
    assert!(s.report.residual <= EquilibriumParams::default().force_tol, "residual {:.2e}", s.report.residual);
}

/// Three pads with negative preload and centre pivots, heavily loaded (S = 0.01) 15° off the pad at 30°: a
/// tilting pad's force runs along its pivot line, so the neighbour at 270° must carry W sin 15° / sin 120°.
/// The walk along the unsupported direction used to carry that floating neighbour rigidly with the journal,
/// its film diverging and without pressure until it closed, and the solve spent its budget (the map's 54
/// points); the walk now searches the approached pad for its loaded state. The third pad floats.
#[test]
fn a_heavy_load_beside_a_pad_engages_its_negative_preload_neighbour() {
    let w = 125_000.0;
    let s = family_solve(3, -0.3, 0.5, true, w, 15.0).unwrap_or_else(|e| panic!("must converge: {e}"));
    assert!(s.report.residual <= EquilibriumParams::default().force_tol, "residual {:.2e}", s.report.residual);
    let f: Vec<f64> = s.pads.iter().map(|p| p.force_n[0].hypot(p.force_n[1])).collect();
    // The force lines pass through the displaced journal centre, not the bearing centre: e/R ≈ 0.4 % of angle.
    let expected = w * 15f64.to_radians().sin() / 120f64.to_radians().sin();
    assert!((f[0] - expected).abs() < 1e-3 * expected, "pad 0 carries {} N, statics {expected} N", f[0]);
    assert!(
        f[2] < 1e-4 * w && s.report.floating_pads == vec![2],
        "pad forces {f:?}, floating {:?}",
        s.report.floating_pads
    );
}

/// Four pads, zero preload, α 0.6, load on a pad (first pivot at 270°), 125 kN (S = 0.01) at 35°: pads 1
/// (pivot 0°) and 2 (pivot 90°) carry it, each along its pivot line, so statics give W cos 35° and
/// W sin 35° (to the force tolerance, 1e-9 of the load). Newton reaches 3.4e-8 and then no step decreases the residual: the film force is only
/// piecewise smooth where a cavitation-boundary node changes state. Before the Newton step was taken anyway
/// near such a kink (`KINK_RESIDUAL`), this point (and its mirror, 80° on the load-between-pads bearing) spent
/// the work budget in the map while 30° and 40° converged.
#[test]
fn a_newton_step_across_a_cavitation_kink_converges() {
    let w = 125_000.0;
    let s = family_solve(4, 0.0, 0.6, true, w, 35.0).unwrap_or_else(|e| panic!("must converge: {e}"));
    assert!(s.report.residual <= EquilibriumParams::default().force_tol, "residual {:.2e}", s.report.residual);
    let (a, c) = (w * 35f64.to_radians().cos(), w * 35f64.to_radians().sin());
    let f: Vec<[f64; 2]> = s.pads.iter().map(|p| p.force_n).collect();
    eprintln!("pad forces {f:?}; statics {a} N, {c} N; {} iterations", s.report.iterations);
    assert!((f[1][0] + a).abs() < 1e-9 * w && f[1][1].abs() < 1e-9 * w, "pad 1 {:?}, statics {a}", f[1]);
    assert!((f[2][1] + c).abs() < 1e-9 * w && f[2][0].abs() < 1e-9 * w, "pad 2 {:?}, statics {c}", f[2]);
    assert_eq!(s.report.floating_pads, vec![0, 3]);
}
