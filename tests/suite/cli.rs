//! The command-line interface as a user runs it.

use crate::common;

use std::process::Command;

fn tiltpad() -> Command {
    Command::new(env!("CARGO_BIN_EXE_tiltpad"))
}

#[test]
fn solve_writes_self_describing_json() {
    let dir = std::env::temp_dir().join(format!("tiltpad-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let out = dir.join("r.json");
    let o = tiltpad()
        .args([
            "solve",
            common::case_path("compressor-bearing.toml").to_str().unwrap(),
            "--set",
            "operating.speed_rpm=7000",
            "--json",
        ])
        .arg(&out)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(text.contains("Eccentricity ε") && text.contains("reduced coefficients"), "{text}");
    let j: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&out).unwrap()).unwrap();
    for key in [
        "eccentricity_ratio",
        "attitude_angle_deg",
        "journal_position_m",
        "sommerfeld",
        "friction_power_w",
        "flows_m3_per_s",
        "report",
        "inputs",
    ] {
        assert!(j.get(key).is_some(), "missing {key}");
    }
    assert_eq!(j["reduced"]["k_n_per_m"].as_array().unwrap().len(), 2);
    assert_eq!(j["reduced"]["c_ns_per_m"][1].as_array().unwrap().len(), 2);
    let n = j["full"]["k"].as_array().unwrap().len();
    assert_eq!(n, 2 + 5, "journal + five tilts");
    assert_eq!(j["pads"].as_array().unwrap().len(), 5);
    for p in j["pads"].as_array().unwrap() {
        assert!(p["tilt_rad"].is_f64() && p["h_min_m"].as_f64().unwrap() > 0.0 && p["p_max_pa"].is_f64());
    }
    assert!(j["report"]["iterations"].as_u64().unwrap() > 0);
    assert!(j["report"]["residual"].as_f64().unwrap() < 1e-6);
    assert!(j["report"]["seconds"].as_f64().unwrap() > 0.0);
    // The result describes itself: resolved inputs in SI, with the override applied.
    assert!((j["inputs"]["speed_rpm"].as_f64().unwrap() - 7000.0).abs() < 1e-9);
    assert!((j["inputs"]["assembled_clearance_m"].as_f64().unwrap() - 102e-6).abs() < 1e-15);
    assert!((j["inputs"]["pad_clearances_m"][0].as_f64().unwrap() - 121e-6).abs() < 1e-12);
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn sweep_writes_csv() {
    let dir = std::env::temp_dir().join(format!("tiltpad-sweep-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let out = dir.join("s.csv");
    let o = tiltpad()
        .args([
            "sweep",
            common::case_path("compressor-bearing.toml").to_str().unwrap(),
            "--param",
            "operating.speed_rpm",
            "--from",
            "6000",
            "--to",
            "10000",
            "--steps",
            "3",
            "--csv",
        ])
        .arg(&out)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let csv = std::fs::read_to_string(&out).unwrap();
    let rows: Vec<&str> = csv.lines().collect();
    assert_eq!(rows.len(), 4);
    let col = rows[0].split(',').position(|h| h == "eccentricity_ratio").unwrap();
    let ecc: Vec<f64> = rows[1..].iter().map(|r| r.split(',').nth(col).unwrap().parse().unwrap()).collect();
    // Faster journal, thicker film: eccentricity falls with speed.
    assert!(ecc[0] > ecc[1] && ecc[1] > ecc[2], "{ecc:?}");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn invalid_case_is_a_clear_error() {
    let o = tiltpad()
        .args([
            "solve",
            common::case_path("compressor-bearing.toml").to_str().unwrap(),
            "--set",
            "bearing.pads.bore_radius_mm=",
            "--set",
            "bearing.pads.preload=1.2",
        ])
        .output()
        .unwrap();
    assert!(!o.status.success());
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("bearing.pads.preload") && err.contains("1.2") && err.contains("[-1, 1)"), "{err}");
}

#[test]
fn touchdown_is_reported_not_nan() {
    let o = tiltpad()
        .args([
            "solve",
            common::case_path("compressor-bearing.toml").to_str().unwrap(),
            "--set",
            "operating.load_n=5e6",
            "--set",
            "bearing.pads.orifice=[]",
        ])
        .output()
        .unwrap();
    assert!(!o.status.success());
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("touchdown"), "{err}");
    assert!(!err.to_lowercase().contains("nan"), "{err}");
}

#[test]
fn thermal_solve_reports_temperatures_in_json_and_summary() {
    let dir = std::env::temp_dir().join(format!("tiltpad-cli-thd-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let out = dir.join("t.json");
    let o = tiltpad()
        .args([
            "solve",
            common::case_path("fillon-a.toml").to_str().unwrap(),
            "--set",
            "mesh.fidelity=\"preview\"",
            "--json",
        ])
        .arg(&out)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(text.contains("thermal (Bc1)") && text.contains("journal") && text.contains("closure"), "{text}");
    let j: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&out).unwrap()).unwrap();
    let film = j["t_max_film_c"].as_f64().unwrap();
    let pad = j["t_max_pad_c"].as_f64().unwrap();
    assert!(
        film > 40.0 && pad > 40.0 && pad <= film + 1e-9,
        "BC1: the pad is never hotter than the film ({pad} vs {film})"
    );
    let t = &j["thermal"];
    assert!(t["report"]["outer_iterations"].as_u64().unwrap() > 1 && t["report"]["converged"].as_bool().unwrap());
    assert!(
        t["energy_balance_closure"].as_f64().unwrap().abs() < 1e-12,
        "closes to round-off: {}",
        t["energy_balance_closure"]
    );
    assert_eq!(t["inlet_temperatures_c"].as_array().unwrap().len(), 4);
    for key in [
        "journal_temperature_c",
        "t_mean_film_c",
        "heat_carried_by_oil_w",
        "heat_conducted_w",
        "heat_pads_to_surroundings_w",
    ] {
        assert!(t[key].is_f64(), "missing {key}");
    }
    assert!(j["pads"][2]["thermal"]["inlet_temperature_c"].is_f64());
    // An isothermal solve says so.
    let o = tiltpad()
        .args([
            "solve",
            common::case_path("fillon-a.toml").to_str().unwrap(),
            "--set",
            "thermal.model=\"isothermal\"",
            "--json",
        ])
        .arg(&out)
        .output()
        .unwrap();
    assert!(o.status.success());
    let j: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&out).unwrap()).unwrap();
    assert!(j["t_max_film_c"].is_null() && j["thermal"].is_null());
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn modes_lists_each_pads_bending_modes_as_json_and_csv() {
    let case = common::case_path("compressor-bearing-flexible.toml");
    let o = tiltpad().args(["modes", case.to_str().unwrap(), "--count", "2", "--json", "-"]).output().unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let j: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let rows = j["modes"].as_array().unwrap();
    assert_eq!(rows.len(), 5 * 2, "five pads, two modes each");
    let f = |i: usize| rows[i]["frequency_hz"].as_f64().unwrap();
    // Identical pads share one computation; modes ascend.
    for p in 1..5 {
        assert_eq!(f(2 * p), f(0));
    }
    assert!(f(1) > f(0) && f(0) > 1e3, "{} {}", f(0), f(1));
    for r in rows {
        let (m, k) = (r["modal_mass_kg"].as_f64().unwrap(), r["modal_stiffness_n_per_m"].as_f64().unwrap());
        let hz = (k / m).sqrt() / std::f64::consts::TAU;
        assert!((hz - r["frequency_hz"].as_f64().unwrap()).abs() < 1e-9 * hz);
        assert!(r["residual"].as_f64().unwrap() < 1e-6);
    }
    let o = tiltpad().args(["modes", case.to_str().unwrap(), "--count", "1", "--csv", "-"]).output().unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let csv = String::from_utf8_lossy(&o.stdout);
    assert!(csv.starts_with("pad,mode,frequency_hz,modal_mass_kg,modal_stiffness_n_per_m"), "{csv}");
    assert_eq!(csv.lines().count(), 1 + 5);
}

/// `tiltpad frf` writes every curve with its unit (CSV and JSON agree), the phase-lag note, the
/// small-signal warning and timings; a case without hydraulics is refused naming the section.
#[test]
fn frf_writes_curves_as_csv_and_json() {
    let dir = std::env::temp_dir().join(format!("tiltpad-frf-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (csv, json) = (dir.join("f.csv"), dir.join("f.json"));
    let o = tiltpad()
        .args([
            "frf",
            common::case_path("test-rig-pub5.toml").to_str().unwrap(),
            "--from",
            "10",
            "--to",
            "500",
            "--points",
            "20",
            "--amplitude-v",
            "2",
            "--csv",
        ])
        .arg(&csv)
        .arg("--json")
        .arg(&json)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("small-signal") && err.contains("§6.3"), "{err}");
    let text = std::fs::read_to_string(&csv).unwrap();
    let rows: Vec<&str> = text.lines().collect();
    assert_eq!(rows.len(), 21);
    let header: Vec<&str> = rows[0].split(',').collect();
    for name in [
        "G1_mag_V_per_V",
        "G2_A_mag_bar_per_V",
        "G2_B_phase_deg",
        "G3_A_y_mag_N_per_bar",
        "G_y_mag_N_per_V",
        "H_direct_mag_µm_per_N",
        "H_chain_mag_µm_per_N",
    ] {
        assert!(header.contains(&name), "{name} missing from {header:?}");
    }
    let j: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    let curves = j["curves"]["curves"].as_array().unwrap();
    let g = curves.iter().find(|c| c["name"] == "G_y").unwrap();
    let col = header.iter().position(|h| *h == "G_y_mag_N_per_V").unwrap();
    let last: f64 = rows[20].split(',').nth(col).unwrap().parse().unwrap();
    let from_json = g["magnitude"][19].as_f64().unwrap();
    assert!((last - from_json).abs() <= 1e-12 * from_json, "{last} vs {from_json}");
    assert!(j["seconds"]["frf"].as_f64().unwrap() > 0.0);
    let o = tiltpad().args(["frf", common::case_path("fillon-a.toml").to_str().unwrap()]).output().unwrap();
    assert!(!o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains("[hydraulics]"));
    std::fs::remove_dir_all(&dir).ok();
}

/// `--help` tells that no arguments opens the workbench, and every option of every command says what it does.
#[test]
fn help_names_the_workbench_and_describes_the_sweep_options() {
    let o = tiltpad().arg("--help").output().unwrap();
    assert!(o.status.success());
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(text.contains("without arguments opens the interactive workbench"), "{text}");
    let o = tiltpad().args(["sweep", "--help"]).output().unwrap();
    let text = String::from_utf8_lossy(&o.stdout);
    // clap prints an option's description on its line; an undescribed option's line ends after its value.
    for option in [
        "<CASE>",
        "--vary <KEY=VALUES>",
        "--param <KEY>",
        "--from <FROM>",
        "--to <TO>",
        "--steps <STEPS>",
        "--set <KEY=VALUE>",
        "--csv <OUT>",
        "--jsonl <OUT>",
        "--vtu <OUT.pvd>",
    ] {
        let line = text
            .lines()
            .find(|l| l.trim_start().starts_with(option))
            .unwrap_or_else(|| panic!("{option} missing: {text}"));
        assert!(line.trim().len() > option.len() + 4, "{option} has no description: {line:?}");
    }
    // Every argument and option of every command has a description: clap separates it from the option by
    // two or more spaces, so a line with none is only the option (and its value name).
    for command in
        ["solve", "fidelity", "sweep", "batch", "coefficients", "modes", "frf", "rotor", "schema", "convergence-map"]
    {
        let o = tiltpad().args([command, "--help"]).output().unwrap();
        assert!(o.status.success(), "{command}");
        let text = String::from_utf8_lossy(&o.stdout);
        let options: Vec<&str> =
            text.lines().map(str::trim).filter(|l| l.starts_with('-') || l.starts_with('<')).collect();
        assert!(!options.is_empty(), "{command}: {text}");
        for line in options {
            assert!(line.contains("  "), "`tiltpad {command}`: {line:?} has no description");
        }
    }
}

#[test]
fn rotor_critical_map_writes_the_map_the_bearing_curves_and_their_crossings() {
    let rotor = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("cases/rotors/compressor-rotor.toml");
    let dir = std::env::temp_dir().join(format!("tiltpad-rotor-map-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let csv = dir.join("map.csv");
    let o = tiltpad()
        .args([
            "rotor",
            rotor.to_str().unwrap(),
            "--speeds",
            "2000:14000:7",
            "--critical-map",
            "--json",
            "-",
            "--csv",
            csv.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let ks = v["map"]["stiffness_n_per_m"].as_array().unwrap();
    assert_eq!(ks.len(), 81);
    // two bearing cases with direct stiffness, one cross-coupling given by numbers (zero direct terms)
    let curves = v["bearing_curves"].as_array().unwrap();
    assert_eq!(curves.len(), 3);
    assert_eq!(curves[0].as_array().unwrap().len(), 7);
    let crossings = v["crossings"].as_array().unwrap();
    assert!(!crossings.is_empty(), "the bearings' stiffness crosses the first mode line");
    let rpm = std::f64::consts::PI / 30.0;
    for c in crossings {
        let w = c["speed_rad_s"].as_f64().unwrap();
        assert!((2000.0 * rpm..=14000.0 * rpm).contains(&w), "{c}");
        assert!(c["bearing"].as_u64().unwrap() < 2, "{c}");
    }
    let text = std::fs::read_to_string(&csv).unwrap();
    assert!(text.starts_with("series,stiffness_n_per_m,speed_rpm\n"));
    assert_eq!(text.lines().filter(|l| l.starts_with("crossing,")).count(), crossings.len());
    assert_eq!(text.lines().filter(|l| l.starts_with("mode1,")).count(), 81);
    let _ = std::fs::remove_dir_all(&dir);
}

/// The product ships what users run: `tiltpad --help` lists no bench (the developers' bench is `cargo xtask
/// bench`, in xtask/), no source file of the binary or the Python package is a bench, and no code there
/// names the xtask (comments may: they say where the bench went).
#[test]
fn the_product_and_the_python_package_do_not_contain_the_bench() {
    let o = tiltpad().arg("--help").output().unwrap();
    let text = String::from_utf8_lossy(&o.stdout);
    let commands: Vec<&str> = text
        .lines()
        .skip_while(|l| !l.starts_with("Commands:"))
        .skip(1)
        .take_while(|l| l.starts_with("  "))
        .filter_map(|l| l.split_whitespace().next())
        .collect();
    assert!(commands.contains(&"solve") && commands.contains(&"fidelity"), "{text}");
    assert!(!commands.iter().any(|c| c.contains("bench")), "{commands:?}");
    assert!(!tiltpad().args(["bench", "--help"]).output().unwrap().status.success());
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut stack = vec![root.join("src"), root.join("python/src")];
    let mut files = 0;
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(&dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                stack.push(path);
                continue;
            }
            files += 1;
            let name = path.strip_prefix(root).unwrap().display().to_string();
            assert!(!name.contains("bench"), "{name}: a bench in the product");
            let source = std::fs::read_to_string(&path).unwrap_or_default();
            for (i, line) in source.lines().enumerate() {
                let code = line.split("//").next().unwrap_or("");
                assert!(!code.contains("xtask"), "{name}:{}: names the xtask: {line}", i + 1);
            }
        }
    }
    assert!(files > 100, "{files} files read");
}
