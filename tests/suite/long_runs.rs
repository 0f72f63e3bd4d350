//! Long commands as a user meets them: refused before the first solve when their estimated work is over the
//! bound (with the estimate and the flag that raises it), progress lines on a pipe, and Ctrl-C that keeps
//! every point solved (written, named, exit status 130).

use std::io::{BufRead as _, BufReader};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use crate::common;

fn tiltpad() -> Command {
    Command::new(env!("CARGO_BIN_EXE_tiltpad"))
}

fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("tiltpad-long-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn rotor_path(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("cases/rotors").join(name)
}

/// Runs `args`, sends SIGINT once standard error shows `progress: K/` with K ≥ `after`, and returns the exit
/// code and standard error.
fn interrupted(args: &[&str], after: usize) -> (Option<i32>, String) {
    interrupted_when(args, move |line| {
        line.strip_prefix("progress: ")
            .and_then(|r| r.split('/').next())
            .and_then(|k| k.parse::<usize>().ok())
            .is_some_and(|k| k >= after)
    })
}

/// Runs `args`, sends SIGINT at the first line of standard error that `at` accepts, and returns the exit code
/// and standard error.
fn interrupted_when(args: &[&str], at: impl Fn(&str) -> bool + Send + 'static) -> (Option<i32>, String) {
    let mut child = tiltpad().args(args).stdout(Stdio::null()).stderr(Stdio::piped()).spawn().unwrap();
    let pid = child.id().to_string();
    let stderr = child.stderr.take().unwrap();
    let reader = std::thread::spawn(move || {
        let mut text = String::new();
        let mut sent = false;
        for line in BufReader::new(stderr).lines() {
            let line = line.unwrap();
            if !sent && at(&line) {
                let ok = Command::new("kill").args(["-INT", &pid]).status().unwrap().success();
                assert!(ok, "kill -INT {pid}");
                sent = true;
            }
            text.push_str(&line);
            text.push('\n');
        }
        (text, sent)
    });
    let start = Instant::now();
    let status = loop {
        if let Some(s) = child.try_wait().unwrap() {
            break s;
        }
        assert!(start.elapsed() < Duration::from_secs(600), "the command did not stop");
        std::thread::sleep(Duration::from_millis(50));
    };
    let (text, sent) = reader.join().unwrap();
    assert!(sent, "no line of standard error asked for the interrupt before the end:\n{text}");
    (status.code(), text)
}

/// `N of M` from the interruption message.
fn done_of(stderr: &str, what: &str) -> (usize, usize) {
    let tail = stderr.split("interrupted (Ctrl-C) after ").nth(1).unwrap_or_else(|| panic!("{stderr}"));
    let words: Vec<&str> = tail.split_whitespace().collect();
    assert_eq!((words[1], words[3].trim_end_matches(';')), ("of", what), "{stderr}");
    (words[0].parse().unwrap(), words[2].parse().unwrap())
}

fn csv_rows(path: &Path) -> usize {
    std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display())).lines().count() - 1
}

#[test]
fn ctrl_c_on_a_sweep_writes_every_finished_row_and_says_where() {
    let dir = temp_dir("sweep");
    let out = dir.join("rows.csv");
    let case = common::case_path("compressor-bearing.toml");
    let (code, err) = interrupted(
        &[
            "sweep",
            case.to_str().unwrap(),
            "--vary",
            "operating.speed_rpm=3000:12000:400",
            "--set",
            "mesh.fidelity=\"preview\"",
            "--csv",
            out.to_str().unwrap(),
        ],
        2,
    );
    assert_eq!(code, Some(130), "{err}");
    let (done, of) = done_of(&err, "points");
    assert_eq!(of, 400);
    assert!((2..400).contains(&done), "{err}");
    assert!(err.contains(&format!("their results are in {}", out.display())), "{err}");
    assert_eq!(csv_rows(&out), done, "one row per finished point");
}

#[test]
fn ctrl_c_on_coefficients_writes_the_speeds_solved() {
    let dir = temp_dir("coefficients");
    let out = dir.join("k.csv");
    let case = common::case_path("compressor-bearing.toml");
    let (code, err) = interrupted(
        &[
            "coefficients",
            case.to_str().unwrap(),
            "--speed-rpm",
            "3000:12000:400",
            "--set",
            "mesh.fidelity=\"preview\"",
            "--csv",
            out.to_str().unwrap(),
        ],
        2,
    );
    assert_eq!(code, Some(130), "{err}");
    let (done, of) = done_of(&err, "speeds");
    assert_eq!(of, 400);
    assert!((2..400).contains(&done), "{err}");
    assert_eq!(csv_rows(&out), done, "one row per solved speed");
}

#[test]
fn ctrl_c_on_rotor_and_control_writes_the_speeds_solved() {
    let dir = temp_dir("rotor");
    for (command, rotor) in [("rotor", "compressor-rotor.toml"), ("control", "compressor-rotor-active.toml")] {
        let out = dir.join(format!("{command}.csv"));
        let rotor = rotor_path(rotor);
        let (code, err) = interrupted(
            &[command, rotor.to_str().unwrap(), "--speeds", "1000:13000:300", "--csv", out.to_str().unwrap()],
            2,
        );
        assert_eq!(code, Some(130), "{command}: {err}");
        let (done, of) = done_of(&err, "speeds");
        assert_eq!(of, 300, "{command}");
        assert!((2..300).contains(&done), "{command}: {err}");
        assert_eq!(csv_rows(&out), done, "{command}: one row per solved speed");
    }
}

/// Ctrl-C during the control command's onset bisections (after every speed is solved) stops them: the
/// speeds are all written, the onsets left are named as not refined, and the exit status is 130.
#[test]
fn ctrl_c_during_the_control_onsets_stops_them_and_keeps_the_speeds() {
    let dir = temp_dir("control-onsets");
    let (csv, json) = (dir.join("speeds.csv"), dir.join("result.json"));
    let rotor = rotor_path("compressor-rotor-active.toml");
    let (code, err) = interrupted_when(
        &[
            "control",
            rotor.to_str().unwrap(),
            "--speeds",
            "6000:12000:4",
            "--gain-sweep",
            "0:2:6",
            "--csv",
            csv.to_str().unwrap(),
            "--json",
            json.to_str().unwrap(),
        ],
        |line| line.starts_with("onsets:"),
    );
    assert_eq!(code, Some(130), "{err}");
    assert_eq!(done_of(&err, "speeds"), (4, 4), "every speed was solved before the onsets");
    assert!(err.contains("(onsets not refined)"), "{err}");
    assert_eq!(csv_rows(&csv), 4, "one row per solved speed");
    let result: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    let unrefined: Vec<&serde_json::Value> =
        result["warnings"].as_array().unwrap().iter().filter(|w| w["kind"] == "onset_not_refined").collect();
    assert!(!unrefined.is_empty(), "the onsets left are named: {}", result["warnings"]);
    // the open loop's onset, when left, is the middle of the bracket its warning names
    if let Some(w) = unrefined.iter().find(|w| w["gain"].as_f64() == Some(0.0)) {
        let middle_rpm = 0.5 * (w["from_rpm"].as_f64().unwrap() + w["to_rpm"].as_f64().unwrap());
        let onset_rpm = result["onset_open"]["onset_rad_s"].as_f64().unwrap() * 60.0 / std::f64::consts::TAU;
        assert!((onset_rpm - middle_rpm).abs() < 1e-6 * middle_rpm, "{onset_rpm} rpm against {middle_rpm} rpm");
    }
    // 6 gains + open + closed, each refined to 10⁻³ from a 2000 rpm bracket, would take ~8 probes each
    let solves = result["bearing_solves"].as_u64().unwrap();
    assert!(solves < 4 * 2 + 8 * 2, "the bisections stopped ({solves} bearing solves)");
}

/// A single solve that prints nothing for a while (a large mesh: building it and the cold start take many
/// seconds before the first equilibrium iteration) shows a `working:` line through a pipe, and Ctrl-C then
/// stops it at its next safe point with nothing written.
#[test]
fn a_long_single_solve_says_it_is_working_and_stops_on_ctrl_c() {
    let case = common::case_path("compressor-bearing.toml");
    let (code, err) = interrupted_when(
        &[
            "solve",
            case.to_str().unwrap(),
            "--set",
            "mesh.half_model=false",
            "--set",
            "mesh.circumferential_elements=200",
            "--set",
            "mesh.axial_elements=100",
        ],
        // the heartbeat names the command (and the solver's safe points once it passes them)
        |line| line.starts_with("working: tiltpad solve"),
    );
    assert_eq!(code, Some(130), "{err}");
    assert_eq!(done_of(&err, "solves"), (0, 1), "{err}");
}

#[test]
fn every_long_command_is_refused_up_front_with_its_estimate_and_the_flag_that_raises_the_bound() {
    let case = common::case_path("compressor-bearing.toml");
    let case = case.to_str().unwrap();
    let designs = Path::new(env!("CARGO_MANIFEST_DIR")).join("cases/designs-compressor.csv");
    let rotor = rotor_path("compressor-rotor.toml");
    let active = rotor_path("compressor-rotor-active.toml");
    let runs: Vec<Vec<&str>> = vec![
        // 10 000 THD points at reference fidelity: about 5.5 h by the work model.
        vec![
            "sweep",
            case,
            "--vary",
            "operating.speed_rpm=3000:12000:10000",
            "--set",
            "mesh.fidelity=\"reference\"",
            "--set",
            "thermal.model=\"thd\"",
        ],
        vec!["batch", designs.to_str().unwrap(), "--case", case, "--max-hours", "0.00001"],
        vec!["coefficients", case, "--speed-rpm", "3000:12000:100", "--max-hours", "0.00001"],
        vec!["rotor", rotor.to_str().unwrap(), "--speeds", "1000:13000:100", "--max-hours", "0.00001"],
        vec![
            "rotor",
            rotor.to_str().unwrap(),
            "--speeds",
            "1000:13000:100",
            "--critical-map",
            "--max-hours",
            "0.00001",
        ],
        vec!["control", active.to_str().unwrap(), "--speeds", "1000:13000:100", "--max-hours", "0.00001"],
    ];
    for args in runs {
        let start = Instant::now();
        let o = tiltpad().args(&args).output().unwrap();
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(1), "{args:?}: {err}");
        assert!(err.contains("bearing solves") && err.contains(", about "), "{args:?}: {err}");
        assert!(err.contains("more than the bound of"), "{args:?}: {err}");
        if args.contains(&"--critical-map") {
            // the map's 81 undamped eigen-solutions of one plane of the 55-element shaft (2 × 56 coordinates)
            assert!(err.contains("81 undamped eigen-solutions of 112 shaft coordinates"), "{args:?}: {err}");
        } else if args[0] == "rotor" {
            // the rotor's eigen-solutions are in the estimate (the compressor rotor: 34 coordinates)
            assert!(err.contains("eigen-solutions of 68 states"), "{args:?}: {err}");
        }
        assert!(err.contains("--max-hours"), "{args:?}: {err}");
        assert!(!err.contains("progress:"), "{args:?}: refused before the first solve: {err}");
        assert!(start.elapsed() < Duration::from_secs(60), "{args:?}: the refusal took {:?}", start.elapsed());
        if args[0] == "sweep" {
            assert!(err.contains("about 5.5 h") && err.contains("--max-hours 6"), "{err}");
        }
    }
}

/// `tiltpad control --json ROTOR` wrote its result over the rotor file it read (found by the bad-input
/// harness): refused like every other command's output onto an input, and the file is unchanged.
#[test]
fn control_never_writes_over_its_rotor_file() {
    let dir = temp_dir("control-onto");
    let rotor = dir.join("active.toml");
    std::fs::copy(rotor_path("compressor-rotor-active.toml"), &rotor).unwrap();
    // Refused before the rotor file is read: the bearing cases it names need not be there.
    let before = std::fs::read(&rotor).unwrap();
    for flag in ["--json", "--csv"] {
        let o = tiltpad()
            .args(["control", rotor.to_str().unwrap(), "--speeds", "7000:8000:2", flag, rotor.to_str().unwrap()])
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(1), "{err}");
        assert!(err.contains("never overwrites an input"), "{err}");
        assert_eq!(std::fs::read(&rotor).unwrap(), before, "{flag}: the rotor file changed");
    }
}

/// A generated rotor of `elements` elements on the full shaft (`tiltpad::study::rotor_cost::uniform_rotor`) in `dir`.
fn uniform_rotor(dir: &Path, elements: usize) -> PathBuf {
    let path = dir.join(format!("uniform-{elements}.toml"));
    let bearing = common::case_path("compressor-bearing.toml");
    std::fs::write(&path, tiltpad::study::rotor_cost::uniform_rotor(elements, &bearing)).unwrap();
    path
}

/// The rotor estimate counted the bearing solves only, so a 400-element full shaft (about 23 s of
/// eigen-solution per speed at the reference rate) was accepted for thousands of speeds: now its
/// eigen-solutions are counted, and the refusal names the settings that shrink them.
#[test]
fn a_large_full_shaft_is_refused_for_its_eigen_solutions_naming_the_shaft_settings() {
    let dir = temp_dir("large-shaft");
    let rotor = uniform_rotor(&dir, 400);
    let o = tiltpad().args(["rotor", rotor.to_str().unwrap(), "--speeds", "1000:13000:1000"]).output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    // 2 × (1604 shaft + 10 pad coordinates) states; 1012 eigen-solutions of ~23 s each: ~6.6 h
    assert!(err.contains("1012 eigen-solutions of 3228 states"), "{err}");
    assert!(err.contains("more than the bound of 4 h"), "{err}");
    assert!(err.contains("--shaft-modes") && err.contains("rotor.section[].elements"), "{err}");
    // The same speeds on the reduced shaft: the eigen-solutions shrink to milliseconds and the bearings
    // decide (accepted at this bound; checked with a bound too small for it, so nothing runs).
    let o = tiltpad()
        .args(["rotor", rotor.to_str().unwrap(), "--speeds", "1000:13000:1000", "--shaft-modes", "8"])
        .args(["--max-hours", "0.00001"])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("eigen-solutions of 64 states") && err.contains("mesh.fidelity"), "{err}");
}

/// A speed of a large full shaft takes seconds to minutes in its eigen-solution: the heartbeat names the
/// speed and the eigen-solution being computed, and Ctrl-C stops after it with the speed kept.
#[test]
fn a_long_rotor_speed_says_which_speed_and_eigen_solution_it_is_working_on() {
    let dir = temp_dir("long-speed");
    // 300 elements: 2 × (1204 + 10) = 2428 states, about 10 s per speed at the reference rate
    let rotor = uniform_rotor(&dir, 300);
    let out = dir.join("r.csv");
    let (code, err) = interrupted_when(
        &["rotor", rotor.to_str().unwrap(), "--speeds", "3000:4000:3", "--csv", out.to_str().unwrap()],
        |line| line.starts_with("working: speed 1 of 3 (3000 rpm)"),
    );
    assert!(err.contains("an eigen-solution of 2428 states (about"), "{err}");
    assert_eq!(code, Some(130), "{err}");
    assert_eq!(done_of(&err, "speeds"), (1, 3), "{err}");
    assert_eq!(csv_rows(&out), 1, "{err}");
}

/// `rotor --critical-map` was estimated as a rotor run (one damped eigen-solution per speed), not as what it
/// does: the bearings at each speed, then 81 undamped eigen-solutions of one plane of the shaft. Measured CPU
/// time of the whole command (release build, 2 speeds, uniform full shafts): 4.6 s at 200 elements, 36.2 s at
/// 400; the estimate is within 20 % of both, and a large map is refused naming the shaft's elements.
#[test]
fn the_critical_speed_map_counts_its_undamped_eigen_solutions() {
    use tiltpad::study::estimate::Estimate;
    let dir = temp_dir("critical-map");
    for (elements, measured) in [(200, 4.6), (400, 36.2)] {
        let rotor = tiltpad::io::read::read_rotor(&uniform_rotor(&dir, elements)).unwrap();
        let e = Estimate::critical_map(&rotor, 2, 81);
        let eigen = e.eigen.unwrap();
        assert!(eigen.undamped);
        assert_eq!((eigen.solutions, eigen.states), (81, 2 * (elements + 1)));
        assert!((e.seconds / measured - 1.0).abs() < 0.2, "{elements} elements: {} s against {measured} s", e.seconds);
    }
    let rotor = uniform_rotor(&dir, 400);
    let o = tiltpad()
        .args(["rotor", rotor.to_str().unwrap(), "--speeds", "3000:4000:2", "--critical-map", "--max-hours", "0.001"])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(err.contains("81 undamped eigen-solutions of 802 shaft coordinates"), "{err}");
    assert!(err.contains("rotor.section[].elements") && !err.contains("--shaft-modes"), "{err}");
}

/// `control` makes two damped eigen-solutions per speed (open and closed loop) and one per actuator for the
/// Nyquist test, where its estimate counted one: the estimate now bounds what the analysis makes.
#[test]
fn the_control_estimate_counts_the_eigen_solutions_the_analysis_makes() {
    use tiltpad::control::analysis::{ControlAnalysis, ControlParams};
    let (rotor, control) = tiltpad::io::read::read_controlled(&rotor_path("compressor-rotor-active.toml")).unwrap();
    let speeds: Vec<f64> = (0..13).map(|i| tiltpad::units::RPM.to_si(6000.0 + 500.0 * f64::from(i))).collect();
    let params = ControlParams::new(speeds);
    let e = params.estimate(&rotor, &control);
    let mut a = ControlAnalysis::new(&rotor, &control, params).unwrap();
    while !a.step().unwrap() {}
    let made = a.finish().unwrap().eigen_solutions;
    let estimated = e.eigen.unwrap().solutions;
    // per speed: open, closed and one Nyquist test per actuator
    let per_speed = 2 + control.actuators.len();
    assert!(made >= 13 * per_speed, "made {made}");
    assert!(made <= estimated, "made {made} eigen-solutions, estimated {estimated}");
    // the bound is the bisections' most probes (2 onsets × 12) beyond the speeds' own
    assert_eq!(estimated, 13 * per_speed + 2 * 12, "{e}");
}

/// The convergence map counted nothing through a pipe (its bar draws only on a terminal, and the heartbeat
/// said "288 points; N s on it so far" with no count done): it now prints `progress: K/N` lines over all its
/// points, and Ctrl-C stops it after the points being solved, writes them to the CSV and says how many.
#[test]
fn the_convergence_map_counts_its_points_and_stops_on_ctrl_c_keeping_them() {
    let dir = temp_dir("convergence-map");
    let root = env!("CARGO_MANIFEST_DIR");
    // three points: every one counted, the last line 3/3
    let out = dir.join("three.csv");
    let o = tiltpad()
        .args(["convergence-map", "--root", root, "--only", "someya", "--only-points", "0@10,90@10,180@10"])
        .args(["--csv", out.to_str().unwrap()])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(0), "{err}");
    assert!(err.lines().any(|l| l.starts_with("progress: 3/3")), "{err}");
    assert_eq!(csv_rows(&out), 3);
    // the whole map of one bearing (72 directions × 4 loads), stopped once two or more points are counted
    let out = dir.join("map.csv");
    let (code, err) =
        interrupted(&["convergence-map", "--root", root, "--only", "someya", "--csv", out.to_str().unwrap()], 2);
    assert_eq!(code, Some(130), "{err}");
    let (done, of) = done_of(&err, "points");
    assert_eq!(of, 288, "{err}");
    assert!((2..288).contains(&done), "{err}");
    assert!(err.contains(&format!("their results are in {}", out.display())), "{err}");
    assert_eq!(csv_rows(&out), done, "one row per point solved");
}

/// `rotor --critical-map` did not look at Ctrl-C between its 81 eigen-solutions (nor count them): it now
/// counts the bearings' speeds and then the eigen-solutions, and Ctrl-C stops it at the next one, writing
/// the map up to the stiffness reached (exit status 130, how many said).
#[test]
fn ctrl_c_on_the_critical_speed_map_stops_at_the_next_eigen_solution_and_keeps_the_map_so_far() {
    let dir = temp_dir("critical-map-stop");
    // 200 elements: 81 undamped eigen-solutions of 402 coordinates, about 4.6 s in all in release
    let rotor = uniform_rotor(&dir, 200);
    let out = dir.join("map.csv");
    let (code, err) = interrupted_when(
        &[
            "rotor",
            rotor.to_str().unwrap(),
            "--speeds",
            "3000:4000:2",
            "--critical-map",
            "--csv",
            out.to_str().unwrap(),
        ],
        |line| line.starts_with("progress: ") && line.contains("/81"),
    );
    assert!(err.contains("progress: 2/2"), "the speeds are counted: {err}");
    assert_eq!(code, Some(130), "{err}");
    let (done, of) = done_of(&err, "eigen-solutions");
    assert_eq!(of, 81, "{err}");
    assert!((1..81).contains(&done), "{err}");
    // the CSV: each mode line has one row per stiffness done; both bearings' curves at both speeds are kept
    let text = std::fs::read_to_string(&out).unwrap();
    assert_eq!(text.lines().filter(|l| l.starts_with("mode1,")).count(), done, "{text}");
    assert_eq!(text.lines().filter(|l| l.starts_with("bearing0_kxx,")).count(), 2, "{text}");
}

/// `sommerfeld` did not look at Ctrl-C between its points (up to 101 solves): it now stops after the point
/// being solved, writes the chart of the points finished and says how many (exit status 130).
#[test]
fn ctrl_c_on_the_sommerfeld_chart_writes_the_chart_of_the_points_solved() {
    let dir = temp_dir("sommerfeld");
    let out = dir.join("chart.json");
    let case = common::case_path("compressor-bearing.toml");
    let (code, err) = interrupted(
        &[
            "sommerfeld",
            case.to_str().unwrap(),
            "--points",
            "101",
            "--set",
            "mesh.fidelity=\"preview\"",
            "--json",
            out.to_str().unwrap(),
        ],
        2,
    );
    assert_eq!(code, Some(130), "{err}");
    let (done, of) = done_of(&err, "points");
    assert_eq!(of, 101, "{err}");
    assert!((2..101).contains(&done), "{err}");
    assert!(err.contains(&format!("their results are in {}", out.display())), "{err}");
    let chart: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&out).unwrap()).unwrap();
    let first = &chart["plots"][0]["curves"][0]["points"];
    assert_eq!(first.as_array().map(Vec::len), Some(done), "one chart point per point solved: {first}");
}
