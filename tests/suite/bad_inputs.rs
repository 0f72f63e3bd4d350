//! Bad and extreme inputs to every command, one test per finding: each is refused up front with a message that
//! names the flag or key, the value and what is allowed, before any work; no input file is changed; nothing
//! that was not computed exits 0. (The wider sweep over every key and command is `tests/harness/bad_inputs.py`.)

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use crate::common;

fn tiltpad(args: &[&str], dir: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_tiltpad")).args(args).current_dir(dir).output().unwrap()
}

/// A scratch directory with copies of the shipped cases (inputs the tests may try to overwrite).
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("tiltpad-bad-{name}-{}", std::process::id()));
    std::fs::create_dir_all(dir.join("rotors")).unwrap();
    for f in ["compressor-bearing.toml", "test-rig-pub5.toml", "designs-compressor.csv"] {
        std::fs::copy(common::case_path(f), dir.join(f)).unwrap();
    }
    std::fs::copy(common::case_path("rotors/compressor-rotor.toml"), dir.join("rotors/compressor-rotor.toml")).unwrap();
    dir
}

/// Fails (non-zero, not a panic), says each of `words` on standard error and prints no NaN or inf.
fn refused(o: &Output, words: &[&str]) -> String {
    let err = String::from_utf8_lossy(&o.stderr).to_string();
    assert!(!o.status.success(), "exit 0: {err}");
    assert_ne!(o.status.code(), Some(101), "panicked: {err}");
    for w in words {
        assert!(err.contains(w), "`{w}` not in: {err}");
    }
    assert!(!err.to_lowercase().contains("nan") && !err.contains("inf "), "{err}");
    err
}

const PREVIEW: &str = "mesh.fidelity=\"preview\"";

#[test]
fn outputs_never_overwrite_an_input_or_each_other() {
    let d = scratch("outputs");
    let case = std::fs::read(d.join("compressor-bearing.toml")).unwrap();
    let o = tiltpad(&["solve", "compressor-bearing.toml", "--json", "compressor-bearing.toml"], &d);
    refused(&o, &["--json compressor-bearing.toml", "never overwrites"]);
    let o = tiltpad(&["solve", "compressor-bearing.toml", "--json", "./compressor-bearing.toml"], &d);
    refused(&o, &["never overwrites"]);
    let o = tiltpad(
        &["batch", "designs-compressor.csv", "--case", "compressor-bearing.toml", "--csv", "designs-compressor.csv"],
        &d,
    );
    refused(&o, &["designs table", "never overwrites"]);
    let o = tiltpad(
        &["rotor", "rotors/compressor-rotor.toml", "--speeds", "7000:8000:2", "--json", "rotors/compressor-rotor.toml"],
        &d,
    );
    refused(&o, &["rotor file"]);
    assert_eq!(std::fs::read(d.join("compressor-bearing.toml")).unwrap(), case);
    let vary = "operating.speed_rpm=7000:8000:2";
    let o = tiltpad(&["sweep", "compressor-bearing.toml", "--vary", vary, "--csv", "x", "--jsonl", "x"], &d);
    refused(&o, &["--csv and --jsonl both write x"]);
    let o = tiltpad(&["sweep", "compressor-bearing.toml", "--vary", vary, "--csv", "-", "--jsonl", "-"], &d);
    refused(&o, &["both write standard output"]);
    let o = tiltpad(&["modes", "compressor-bearing.toml", "--json", "m", "--csv", "./m"], &d);
    refused(&o, &["--json and --csv"]);
    assert!(!d.join("x").exists() && !d.join("m").exists());
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn a_key_varied_twice_or_misspelt_is_refused_before_the_first_solve() {
    let d = scratch("keys");
    let o = tiltpad(
        &[
            "sweep",
            "compressor-bearing.toml",
            "--vary",
            "operating.speed_rpm=7000,8000",
            "--vary",
            "operating.speed_rpm=9000",
        ],
        &d,
    );
    refused(&o, &["the same key twice", "operating.speed_rpm"]);
    let o = tiltpad(&["sweep", "compressor-bearing.toml", "--vary", "operating.sped_rpm=7000:9000:3"], &d);
    let err = refused(&o, &["operating.sped_rpm", "unknown"]);
    assert!(!err.contains("point 0"), "a point was solved: {err}");
    std::fs::write(d.join("typo.csv"), "bearing.pads.prelaod\n0.3\n0.5\n").unwrap();
    let o = tiltpad(&["batch", "typo.csv", "--case", "compressor-bearing.toml"], &d);
    let err = refused(&o, &["bearing.pads.prelaod", "header of typo.csv"]);
    assert!(!err.contains("design 0"), "a design was solved: {err}");
    std::fs::write(d.join("empty.csv"), "operating.speed_rpm\n").unwrap();
    let o = tiltpad(&["batch", "empty.csv", "--case", "compressor-bearing.toml"], &d);
    refused(&o, &["empty.csv has a header but no design rows"]);
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn frf_of_lines_that_feed_no_orifice_and_a_supply_below_the_injection_are_refused() {
    let d = scratch("frf");
    let o = tiltpad(&["frf", "test-rig-pub5.toml", "--set", "bearing.pads.orifice=[]", "--set", PREVIEW], &d);
    refused(&o, &["hydraulics.port[0].pads", "has no orifice"]);
    let o = tiltpad(&["frf", "test-rig-pub5.toml", "--set", "hydraulics.supply_pressure_bar=5", "--set", PREVIEW], &d);
    // The rig holds 10 bar on its fed pads: a 5 bar supply cannot.
    refused(&o, &["hydraulics.supply_pressure_bar", "5 bar is below pad", "injection pressure of 10 bar"]);
    for a in ["nan", "-1", "0", "inf"] {
        let o = tiltpad(&["frf", "test-rig-pub5.toml", &format!("--amplitude-v={a}")], &d);
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(
            o.status.code() == Some(2) && err.contains("--amplitude-v") && err.contains("finite positive"),
            "{err}"
        );
    }
    let o = tiltpad(&["frf", "test-rig-pub5.toml", "--from", "-5"], &d);
    refused(&o, &["--from -5"]);
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn counts_and_ranges_out_of_bounds_are_refused_not_clamped() {
    let d = scratch("counts");
    for n in ["0", "7", "1000000"] {
        let o = tiltpad(&["modes", "compressor-bearing.toml", &format!("--count={n}")], &d);
        refused(&o, &["--count", n, "1..=6"]);
    }
    let rotor = "rotors/compressor-rotor.toml";
    let o = tiltpad(&["rotor", rotor, "--speeds", "1000:1e9:3"], &d);
    refused(&o, &["--speeds", "1000000 rpm", "operating.speed_rpm"]);
    let o = tiltpad(&["rotor", rotor, "--speeds", "1000:2000:3", "--shaft-modes", "10000"], &d);
    refused(&o, &["--shaft-modes", "10000", "0..=400"]);
    let o = tiltpad(&["coefficients", "compressor-bearing.toml", "--excitation-ratio=-1:2:3"], &d);
    refused(&o, &["--excitation-ratio", "-1 is not allowed", "at least 0"]);
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn work_beyond_the_bound_is_refused_up_front_with_the_setting_that_raises_it() {
    let d = scratch("work");
    let o = tiltpad(&["sweep", "compressor-bearing.toml", "--vary", "operating.speed_rpm=1000:9000:1000000"], &d);
    refused(&o, &["1000000 points", "--max-points 1000000"]);
    let o = tiltpad(&["coefficients", "compressor-bearing.toml", "--speed-rpm", "6000:11000:1000000"], &d);
    refused(&o, &["1000000 points", "--max-points"]);
    let o = tiltpad(&["rotor", "rotors/compressor-rotor.toml", "--speeds", "1000:13000:10001"], &d);
    refused(&o, &["10001 points", "--max-points 10001"]);
    // 25 sections of 200 elements would allocate gigabytes: refused by validation with the count and the cap.
    let mut huge = std::fs::read_to_string(d.join("rotors/compressor-rotor.toml")).unwrap();
    for _ in 0..25 {
        huge.push_str("\n[[rotor.section]]\nlength_mm = 10.0\nouter_diameter_mm = 50.0\nelements = 200\n");
    }
    std::fs::write(d.join("rotors/huge.toml"), huge).unwrap();
    let o = tiltpad(&["rotor", "rotors/huge.toml", "--speeds", "7000:8000:2"], &d);
    refused(&o, &["rotor.section", "shaft elements in all", "at most 400"]);
    #[cfg(unix)]
    {
        let o = tiltpad(&["solve", "/dev/zero"], &d);
        refused(&o, &["case file /dev/zero is larger than 64 MiB"]);
    }
    std::fs::remove_dir_all(&d).ok();
}

/// A `.pvd` reached through a symlink gets its `.vtu` files beside the file it names, so its relative
/// references resolve.
#[cfg(unix)]
#[test]
fn a_symlinked_collection_keeps_its_grids_beside_it() {
    let d = scratch("pvd");
    std::fs::create_dir_all(d.join("real")).unwrap();
    std::os::unix::fs::symlink(d.join("real/s.pvd"), d.join("s.pvd")).unwrap();
    std::fs::write(d.join("real/s.pvd"), "").unwrap();
    let o = tiltpad(
        &[
            "sweep",
            "compressor-bearing.toml",
            "--vary",
            "operating.speed_rpm=7000,8000",
            "--set",
            PREVIEW,
            "--vtu",
            "s.pvd",
        ],
        &d,
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let pvd = std::fs::read_to_string(d.join("real/s.pvd")).unwrap();
    for i in 0..2 {
        let name = format!("s-{i:04}.vtu");
        assert!(pvd.contains(&name), "{pvd}");
        assert!(d.join("real").join(&name).is_file() && !d.join(&name).exists(), "{name} not beside the collection");
    }
    assert!(std::fs::symlink_metadata(d.join("s.pvd")).unwrap().file_type().is_symlink());
    std::fs::remove_dir_all(&d).ok();
}

/// An error whose cause is part of its message is printed once (a bearing's failure inside a rotor run, an
/// OS error of a write).
#[test]
fn messages_say_their_cause_once() {
    let d = scratch("once");
    let o = tiltpad(&["solve", "compressor-bearing.toml", "--set", PREVIEW, "--json", "/nonexistent-dir/r.json"], &d);
    let err = refused(&o, &["cannot write /nonexistent-dir/r.json"]);
    assert_eq!(err.matches("No such file or directory").count(), 1, "{err}");
    // At 0 rpm the bearing's solve fails: its message appears once in the rotor's.
    let o = tiltpad(&["rotor", "rotors/compressor-rotor.toml", "--speeds", "0:100:2"], &d);
    let err = refused(&o, &["bearing `../compressor-bearing.toml` at 0 rpm"]);
    let line = err.lines().find(|l| l.starts_with("error:")).unwrap();
    let parts: Vec<&str> = line.split(": ").filter(|p| p.len() > 20).collect();
    for (i, p) in parts.iter().enumerate() {
        assert!(!parts[..i].contains(p), "said twice: {line}");
    }
    std::fs::remove_dir_all(&d).ok();
}

/// A prescribed journal position beyond what the pads allow closes a film: that is a position the bearing
/// cannot take, reported as such with the pad and the (negative) film, never as a touchdown of a load.
#[test]
fn a_prescribed_position_that_closes_the_film_is_not_called_touchdown() {
    let at = |eccentricity_ratio: f64| {
        let mut case = common::case("compressor-bearing.toml", &["mesh.fidelity=\"preview\""]);
        case.operating.load = tiltpad::model::LoadSpec::Position { eccentricity_ratio, angle_rad: 0.3 };
        case
    };
    let case = at(3.0);
    match tiltpad::bearing::solve_case(&case) {
        Err(e @ tiltpad::bearing::SolveError::PositionClosesFilm { h_min_um, .. }) => {
            assert!(h_min_um <= 0.0, "{e}");
            let text = e.to_string();
            assert!(text.contains("operating.eccentricity_ratio") && !text.contains("touchdown"), "{text}");
        }
        other => panic!("expected the closed film of a prescribed position, got {other:?}"),
    }
    // A position inside the clearance still solves.
    let s = tiltpad::bearing::solve_case(&at(0.5)).expect("ε = 0.5 is a position the bearing can take");
    assert!((s.eccentricity_ratio - 0.5).abs() < 1e-12, "{}", s.eccentricity_ratio);
}

/// A loaded journal at 0 rpm without injection has no film pressure to carry it: refused before the first
/// film solve (it used to spend the whole work budget, 15 000 film solves, at a residual of 2e-17).
#[test]
fn a_loaded_journal_at_zero_speed_without_injection_is_refused_before_the_first_film_solve() {
    let case = common::case("compressor-bearing.toml", &["operating.speed_rpm=0", "mesh.fidelity=\"preview\""]);
    match tiltpad::bearing::solve_case(&case) {
        Err(e @ tiltpad::bearing::SolveError::NoRotation { load_n }) => {
            assert!((load_n - case_load(&case)).abs() <= 1e-9 * load_n, "{e}");
            assert!(e.to_string().contains("operating.speed_rpm"), "{e}");
        }
        other => panic!("expected the no-rotation error, got {other:?}"),
    }
    // Any rotation at all is a pressure source again: 10 rpm is not refused up front.
    let slow = common::case("compressor-bearing.toml", &["operating.speed_rpm=10", "mesh.fidelity=\"preview\""]);
    assert!(!matches!(tiltpad::bearing::solve_case(&slow), Err(tiltpad::bearing::SolveError::NoRotation { .. })));
}

fn case_load(case: &tiltpad::model::Case) -> f64 {
    match case.operating.load {
        tiltpad::model::LoadSpec::Force { magnitude_n, .. } => magnitude_n,
        tiltpad::model::LoadSpec::Position { .. } => 0.0,
    }
}

/// The full compressor model on a 1260 × 630 grid (3.98 M film nodes, under its raised node cap) plans about
/// 8.7 GB: `solve` refused it up front, but `coefficients` without `--speed-rpm` (and with
/// `--excitation-ratio`) and `sommerfeld` built its meshes and ran towards 8 GB. Every bearing command now
/// refuses it before building anything, naming the keys that shrink it. (A child still running after 60 s
/// is stopped and the test fails: the refusal takes milliseconds.)
#[test]
fn a_mesh_over_the_memory_plan_is_refused_by_every_bearing_command_before_it_is_built() {
    let d = scratch("mesh-memory");
    let mesh = [
        "--set",
        "mesh.half_model=false",
        "--set",
        "mesh.circumferential_elements=1260",
        "--set",
        "mesh.axial_elements=630",
        "--set",
        "mesh.max_nodes=4000000",
    ];
    let c = "compressor-bearing.toml";
    for head in [
        vec!["solve", c],
        vec!["coefficients", c],
        vec!["coefficients", c, "--excitation-ratio", "0.5,1,2"],
        vec!["coefficients", c, "--speed-rpm", "6000:7000:2"],
        vec!["sommerfeld", c, "--points", "2"],
        vec!["sweep", c, "--vary", "operating.speed_rpm=6000:7000:2"],
        vec!["frf", c],
    ] {
        let mut child = Command::new(env!("CARGO_BIN_EXE_tiltpad"))
            .args(&head)
            .args(mesh)
            .current_dir(&d)
            .stdout(std::process::Stdio::piped())
            .stderr(std::process::Stdio::piped())
            .spawn()
            .unwrap();
        let start = std::time::Instant::now();
        while child.try_wait().unwrap().is_none() {
            if start.elapsed() > std::time::Duration::from_secs(60) {
                child.kill().ok();
                panic!("{head:?}: still running after 60 s: the mesh was not refused up front");
            }
            std::thread::sleep(std::time::Duration::from_millis(50));
        }
        let o = child.wait_with_output().unwrap();
        refused(&o, &["peak memory about 8.7 GB", "mesh.max_nodes"]);
    }
    std::fs::remove_dir_all(&d).ok();
}

/// `--vary bearing.pads.preload=… --vary bearing.pads.clearance_um=…` solved every point at the clearance
/// (the later alternative pad-geometry key replaces the earlier) and labelled the rows with preloads that
/// were not solved, exit 0 (found by the bad-input harness, round 6); a batch table with both columns did
/// the same. Both are refused before the first solve, naming the two keys.
#[test]
fn alternative_geometry_keys_varied_together_are_refused_before_the_first_solve() {
    let d = scratch("alternatives");
    let o = tiltpad(
        &[
            "sweep",
            "compressor-bearing.toml",
            "--vary",
            "bearing.pads.preload=0.2,0.3",
            "--vary",
            "bearing.pads.clearance_um=120",
            "--set",
            PREVIEW,
        ],
        &d,
    );
    let err = refused(&o, &["--vary bearing.pads.clearance_um replaces --vary bearing.pads.preload", "vary one"]);
    assert!(!err.contains("progress:") && o.stdout.is_empty(), "a point was solved: {err}");
    std::fs::write(d.join("both.csv"), "bearing.pads.preload,bearing.pads.clearance_um\n0.3,120\n").unwrap();
    let o = tiltpad(&["batch", "both.csv", "--case", "compressor-bearing.toml", "--set", PREVIEW], &d);
    let err =
        refused(&o, &["header of both.csv", "column bearing.pads.clearance_um replaces column bearing.pads.preload"]);
    assert!(!err.contains("progress:") && o.stdout.is_empty(), "a design was solved: {err}");
    // one alternative alone still replaces the case's own (with its note) and solves
    let o = tiltpad(
        &["sweep", "compressor-bearing.toml", "--vary", "bearing.pads.clearance_um=120,130", "--set", PREVIEW],
        &d,
    );
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success() && err.contains("replaces bearing.pads.bore_radius_mm"), "{err}");
    std::fs::remove_dir_all(&d).ok();
}
