//! `tiltpad sommerfeld` on the shipped cases: the chart of a plain 360° bearing lies close to the
//! short-bearing (Ocvirk) reference and follows the textbook trends; a tilting-pad bearing's chart fills
//! every point with no reference line; a bad point count is refused naming the flag and the range.

use std::process::{Command, Output};

use crate::common;

fn run(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_tiltpad")).args(args).output().unwrap()
}

fn scratch(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("tiltpad-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Largest difference of the attitude angle from the short bearing's at the same ε [deg] (measured 0.14°).
const ATTITUDE_TOL_DEG: f64 = 0.2;

fn curve(plot: &serde_json::Value, k: usize) -> Vec<[f64; 2]> {
    serde_json::from_value(plot["curves"][k]["points"].clone()).unwrap()
}

/// The shipped plain bearing (L/D = 0.1, standard fidelity, 12 loads): every point solved; each solved S
/// within 5 % of the short-bearing S at the same ε (measured 4.75 %: the finite length carries a little less
/// load than the L/D → 0 limit, so S is high, most at the largest ε); ε falls and the attitude angle rises
/// with S, as on every plain-bearing chart; h_min / Cb = 1 − ε; the CSV holds the same points as the JSON.
#[test]
fn the_plain_bearing_chart_follows_the_short_bearing_reference() {
    let dir = scratch("sommerfeld-plain");
    let (json, csv) = (dir.join("chart.json"), dir.join("chart.csv"));
    let case = common::case_path("plain-360-sommerfeld.toml");
    let o =
        run(&["sommerfeld", case.to_str().unwrap(), "--json", json.to_str().unwrap(), "--csv", csv.to_str().unwrap()]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{err}");
    assert!(err.contains("L/D = 0.100") && err.contains("of the short-bearing reference"), "{err}");
    let d: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    assert_eq!(d["swept"], "operating.load_n");
    assert_eq!(d["failed"].as_array().unwrap().len(), 0);
    assert!((d["reference"]["l_over_d"].as_f64().unwrap() - 0.1).abs() < 1e-12);
    let deviation = d["reference_deviation"].as_f64().unwrap();
    assert!(deviation > 0.0 && deviation < 0.05, "{deviation}");
    let plots = d["plots"].as_array().unwrap();
    assert_eq!(plots.len(), 5);
    let eps = curve(&plots[0], 0);
    let attitude = curve(&plots[1], 0);
    let h = curve(&plots[2], 0);
    assert_eq!((eps.len(), attitude.len(), h.len()), (12, 12, 12));
    // Sorted by S: ε falls, the attitude angle rises.
    assert!(eps.windows(2).all(|w| w[0][0] < w[1][0] && w[0][1] > w[1][1]), "{eps:?}");
    assert!(attitude.windows(2).all(|w| w[0][1] < w[1][1]), "{attitude:?}");
    for (e, h) in eps.iter().zip(&h) {
        assert!((h[1] - (1.0 - e[1])).abs() < 1e-3, "h_min/Cb {} at ε {}", h[1], e[1]);
    }
    // The sweep spans 0.2–3 times the load: S spans a factor 15.
    assert!((eps[11][0] / eps[0][0] - 15.0).abs() < 1e-6, "{} to {}", eps[0][0], eps[11][0]);
    // The attitude angle against the short-bearing one at the solved ε, tan φ = π √(1 − ε²) / (4 ε).
    let worst = eps
        .iter()
        .zip(&attitude)
        .map(|(e, a)| {
            let short = (std::f64::consts::PI * (1.0 - e[1] * e[1]).sqrt() / (4.0 * e[1])).atan().to_degrees();
            (a[1] - short).abs()
        })
        .fold(0.0, f64::max);
    assert!(worst < ATTITUDE_TOL_DEG, "attitude differs from the short bearing's by {worst:.3}°");
    let text = std::fs::read_to_string(&csv).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines[0], "plot,curve,sommerfeld,value");
    // 7 solved curves of 12 points and 3 reference lines of 19.
    assert_eq!(lines.len() - 1, 7 * 12 + 3 * 19);
    let first: Vec<&str> = lines[1].split(',').collect();
    assert_eq!(first[1], "\"ε\"");
    assert!((first[2].parse::<f64>().unwrap() - eps[0][0]).abs() < 1e-9 * eps[0][0]);
    assert!((first[3].parse::<f64>().unwrap() - eps[0][1]).abs() < 1e-12);
    std::fs::remove_dir_all(&dir).ok();
}

/// Tilting pads: every point of the compressor bearing's chart solves (preview fidelity); no reference line
/// and no deviation; the reduced direct stiffness K Cb / W is positive at every point.
#[test]
fn a_tilting_pad_chart_fills_every_point_without_a_reference() {
    let case = common::case_path("compressor-bearing.toml");
    let o = run(&[
        "sommerfeld",
        case.to_str().unwrap(),
        "--set",
        "mesh.fidelity=\"preview\"",
        "--points",
        "4",
        "--json",
        "-",
    ]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{err}");
    assert!(err.contains("no closed-form reference"), "{err}");
    let d: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert!(d["reference"].is_null() && d["reference_deviation"].is_null());
    assert_eq!(d["failed"].as_array().unwrap().len(), 0);
    for plot in d["plots"].as_array().unwrap() {
        assert!(plot["reference"].as_array().unwrap().is_empty());
        for c in plot["curves"].as_array().unwrap() {
            assert_eq!(c["points"].as_array().unwrap().len(), 4, "{}", plot["title"]);
        }
    }
    let kxx = curve(&d["plots"][3], 0);
    assert!(kxx.iter().all(|p| p[1] > 0.0), "{kxx:?}");
}

#[test]
fn a_bad_point_count_is_refused_naming_the_flag_and_the_range() {
    let case = common::case_path("plain-360-sommerfeld.toml");
    let o = run(&["sommerfeld", case.to_str().unwrap(), "--points", "1"]);
    assert!(!o.status.success());
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("--points 1") && err.contains("2 to 101"), "{err}");
}
