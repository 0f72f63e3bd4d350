//! `tiltpad fidelity`: the speed–accuracy trade measured on a user's own case — time and error per
//! fidelity level against a finer solve (twice the reference level's element counts), as a table, JSON and
//! CSV.

use crate::common;

use std::process::Command;

fn tiltpad() -> Command {
    Command::new(env!("CARGO_BIN_EXE_tiltpad"))
}

/// The two-pad test rig (isothermal, with its orifices): each finer level has more film nodes and a smaller
/// error in every quantity, the truth's errors are zero; the numbers are those of docs/PERFORMANCE.md's first
/// table for this case (ε 10.00 %, 3.20 %, 0.56 %), and the JSON, the CSV and the table agree.
#[test]
fn the_trade_of_a_case_falls_with_every_level_and_every_output_agrees() {
    let dir = std::env::temp_dir().join(format!("tiltpad-fidelity-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let json = dir.join("trade.json");
    let o = tiltpad()
        .args(["fidelity", common::case_path("test-rig.toml").to_str().unwrap(), "--repeats", "1", "--csv", "-"])
        .arg("--json")
        .arg(&json)
        .output()
        .unwrap();
    let (out, err) = (String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr));
    assert!(o.status.success(), "{err}");
    let j: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    assert_eq!(j["repeats"], 1);
    assert!(j["failed"].as_array().unwrap().is_empty(), "{j}");
    let rows = j["levels"].as_array().unwrap();
    let levels: Vec<&str> = rows.iter().map(|r| r["level"].as_str().unwrap()).collect();
    assert_eq!(levels, ["preview", "standard", "reference", "reference-fine (truth)"]);
    let nodes: Vec<u64> = rows.iter().map(|r| r["film_nodes"].as_u64().unwrap()).collect();
    assert_eq!(nodes, [810, 2244, 10062, 36340]);
    for key in ["err_eccentricity", "err_k", "err_c", "err_p_max", "err_flows"] {
        let e: Vec<f64> = rows.iter().map(|r| r[key].as_f64().unwrap()).collect();
        assert!(e[0] > e[1] && e[1] > e[2] && e[2] > 0.0 && e[3] == 0.0, "{key} falls with the level: {e:?}");
    }
    assert!(rows.iter().all(|r| r["err_t_max"].is_null()), "an isothermal case has no temperature rise");
    assert!(rows.iter().all(|r| r["median_ms"].as_f64().unwrap() > 0.0));
    let eps: Vec<f64> = rows.iter().map(|r| r["err_eccentricity"].as_f64().unwrap()).collect();
    for (e, documented) in eps.iter().zip([0.1000, 0.0320, 0.0056]) {
        assert!((e - documented).abs() < 0.0005, "ε error {e} against {documented}");
    }
    // The CSV on standard output: the same rows and numbers; the table went to standard error.
    let mut lines = out.lines();
    assert_eq!(
        lines.next(),
        Some("level,film_nodes,median_ms,err_eccentricity,err_k,err_c,err_p_max,err_t_max,err_flows,error")
    );
    for (line, row) in lines.zip(rows) {
        let cells: Vec<&str> = line.split(',').collect();
        assert_eq!(cells[0], row["level"].as_str().unwrap());
        let k: f64 = cells[4].parse().unwrap();
        assert!((k - row["err_k"].as_f64().unwrap()).abs() <= 1e-11 * k.abs().max(1e-12), "{line}");
        assert_eq!((cells[7], cells[9]), ("", ""), "{line}");
    }
    assert!(err.contains("preview") && err.contains("10.00 %") && err.contains("twice the reference"), "{err}");
    std::fs::remove_dir_all(&dir).ok();
}

/// A case that fixes an element count has one mesh at every level: refused before any solve, naming the key
/// and the value.
#[test]
fn an_explicit_element_count_is_refused_naming_the_key() {
    let o = tiltpad()
        .args(["fidelity", common::case_path("test-rig.toml").to_str().unwrap(), "--set", "mesh.axial_elements=20"])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(err.contains("`mesh.axial_elements` = 20: an explicit element count overrides mesh.fidelity"), "{err}");
    let o =
        tiltpad().args(["fidelity", common::case_path("plain-2groove-ld05.toml").to_str().unwrap()]).output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(err.contains("`mesh.circumferential_elements` ="), "{err}");
}
