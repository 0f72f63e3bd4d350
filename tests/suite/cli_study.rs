//! The command line as tools around it use it: sweeps that lose nothing, sharded batches, JSON on
//! standard output, errors on standard error, the schema, ROSS and CSV coefficients, and safe writes on a
//! read-only directory and a full disk.

use crate::common;

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn tiltpad() -> Command {
    Command::new(env!("CARGO_BIN_EXE_tiltpad"))
}

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("tiltpad-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn run(args: &[&str]) -> Output {
    tiltpad().args(args).output().unwrap()
}

fn case(name: &str) -> String {
    common::case_path(name).to_str().unwrap().to_string()
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// CSV rows as cells (the files are written by the csv crate; no cell here holds a comma).
fn rows(text: &str) -> Vec<Vec<String>> {
    let mut r = csv::Reader::from_reader(text.as_bytes());
    let header: Vec<String> = r.headers().unwrap().iter().map(str::to_string).collect();
    std::iter::once(header).chain(r.records().map(|rec| rec.unwrap().iter().map(str::to_string).collect())).collect()
}

fn col(rows: &[Vec<String>], name: &str) -> usize {
    rows[0].iter().position(|h| h == name).unwrap_or_else(|| panic!("no column {name} in {:?}", rows[0]))
}

const PREVIEW: &str = "mesh.fidelity=\"preview\"";

#[test]
fn a_sweep_with_an_invalid_point_in_the_middle_keeps_every_other_row() {
    let dir = scratch("sweep-bad");
    let (csv_path, jsonl_path) = (dir.join("s.csv"), dir.join("s.jsonl"));
    let o = run(&[
        "sweep",
        &case("compressor-bearing.toml"),
        "--set",
        PREVIEW,
        "--vary",
        "operating.speed_rpm=6000,7000,-5,9000,10000",
        "--csv",
        csv_path.to_str().unwrap(),
        "--jsonl",
        jsonl_path.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let r = rows(&std::fs::read_to_string(&csv_path).unwrap());
    assert_eq!(r.len(), 6, "header and five rows");
    let (ecc, err, speed) = (col(&r, "eccentricity_ratio"), col(&r, "error"), col(&r, "operating.speed_rpm"));
    assert_eq!(r[3][speed], "-5");
    assert!(
        r[3][ecc].is_empty() && r[3][err].contains("operating.speed_rpm") && r[3][err].contains("-5"),
        "{:?}",
        r[3]
    );
    assert!([1, 2, 4, 5].iter().all(|&i| r[i][err].is_empty() && r[i][ecc].parse::<f64>().unwrap() > 0.0));
    // The other rows are exactly those of the sweep without the invalid point (but for wall time).
    let o2 = run(&[
        "sweep",
        &case("compressor-bearing.toml"),
        "--set",
        PREVIEW,
        "--vary",
        "operating.speed_rpm=6000,7000,9000,10000",
        "--csv",
        "-",
    ]);
    assert!(o2.status.success(), "{}", stderr(&o2));
    let clean = rows(&String::from_utf8_lossy(&o2.stdout));
    let seconds = col(&r, "seconds");
    let strip = |row: &Vec<String>| {
        row.iter().enumerate().filter(|(k, _)| *k != 0 && *k != seconds).map(|(_, v)| v.clone()).collect::<Vec<_>>()
    };
    for (i, j) in [(1, 1), (2, 2), (4, 3), (5, 4)] {
        assert_eq!(strip(&r[i]), strip(&clean[j]), "row {i}");
    }
    // Isothermal: the temperature columns exist and are empty.
    assert!(r[1][col(&r, "t_max_film_c")].is_empty());
    assert!(stderr(&o).contains("1 of 5 points failed"), "{}", stderr(&o));
    let lines: Vec<serde_json::Value> =
        std::fs::read_to_string(&jsonl_path).unwrap().lines().map(|l| serde_json::from_str(l).unwrap()).collect();
    assert_eq!(lines.len(), 5);
    assert!(lines[2]["error"].as_str().unwrap().contains("operating.speed_rpm"));
    assert_eq!(lines[3]["inputs"]["operating.speed_rpm"].as_f64(), Some(9000.0));
    assert_eq!(lines[3]["outputs"]["eccentricity_ratio"].as_f64().unwrap().to_string(), r[4][ecc]);
    // Nothing else is left beside the outputs.
    let mut names: Vec<String> =
        std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    names.sort();
    assert_eq!(names, ["s.csv", "s.jsonl"]);
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_sweep_whose_every_point_fails_exits_non_zero_with_its_rows() {
    let dir = scratch("sweep-all-bad");
    let out = dir.join("s.csv");
    let o = run(&[
        "sweep",
        &case("compressor-bearing.toml"),
        "--vary",
        "operating.speed_rpm=-1,-2",
        "--csv",
        out.to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    assert!(stderr(&o).contains("every point of the sweep failed"), "{}", stderr(&o));
    let r = rows(&std::fs::read_to_string(&out).unwrap());
    assert_eq!(r.len(), 3);
    assert!(r[1..].iter().all(|row| row.last().unwrap().contains("out of range")));
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_sweep_over_two_keys_is_a_grid_on_standard_output() {
    let o = run(&[
        "sweep",
        &case("compressor-bearing.toml"),
        "--set",
        PREVIEW,
        "--vary",
        "bearing.pads.offset=0.5,0.6",
        "--vary",
        "operating.speed_rpm=7000:9000:2",
        "--csv",
        "-",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let r = rows(&String::from_utf8_lossy(&o.stdout));
    let (a, b) = (col(&r, "bearing.pads.offset"), col(&r, "operating.speed_rpm"));
    let grid: Vec<(String, String)> = r[1..].iter().map(|row| (row[a].clone(), row[b].clone())).collect();
    assert_eq!(
        grid,
        [("0.5", "7000"), ("0.5", "9000"), ("0.6", "7000"), ("0.6", "9000")]
            .map(|(x, y)| (x.to_string(), y.to_string()))
    );
    // A centred pivot carries the load on a thinner film than the 0.6 offset at the same speed.
    let h = col(&r, "h_min_um");
    let hv = |i: usize| r[i][h].parse::<f64>().unwrap();
    assert!(hv(1) < hv(3) && hv(2) < hv(4), "{:?}", (hv(1), hv(2), hv(3), hv(4)));
}

/// A preload sweep on cases that give the pad bore radius (compressor) or the pad clearance (Fillon):
/// each point's preload replaces the file's key, every point solves, and standard error says what was
/// replaced. The rows are those of the same sweep with the file's key removed by hand, number for number.
#[test]
fn a_preload_sweep_replaces_the_bore_radius_or_the_pad_clearance() {
    for (name, replaced) in [
        ("compressor-bearing.toml", "bearing.pads.bore_radius_mm = 50.921"),
        ("fillon-a.toml", "bearing.pads.clearance_um = 148.0"),
    ] {
        let o =
            run(&["sweep", &case(name), "--set", PREVIEW, "--vary", "bearing.pads.preload=0.1:0.5:3", "--csv", "-"]);
        assert!(o.status.success(), "{name}: {}", stderr(&o));
        let note = format!("note: bearing.pads.preload replaces {replaced} (alternative pad-geometry keys)");
        assert_eq!(stderr(&o).matches(&note).count(), 1, "{name}: {}", stderr(&o));
        let r = rows(&String::from_utf8_lossy(&o.stdout));
        assert_eq!(r.len(), 4, "{name}: {r:?}");
        let (h, err) = (col(&r, "h_min_um"), col(&r, "error"));
        assert!(r[1..].iter().all(|row| row[err].is_empty()), "{name}: {r:?}");
        let key = replaced.split(" = ").next().unwrap();
        let removed = format!("{key}=");
        let by_hand = run(&[
            "sweep",
            &case(name),
            "--set",
            PREVIEW,
            "--set",
            &removed,
            "--vary",
            "bearing.pads.preload=0.1:0.5:3",
            "--csv",
            "-",
        ]);
        assert!(by_hand.status.success() && !stderr(&by_hand).contains("note:"), "{}", stderr(&by_hand));
        let by_hand = rows(&String::from_utf8_lossy(&by_hand.stdout));
        let column = |t: &[Vec<String>]| t[1..].iter().map(|row| row[h].clone()).collect::<Vec<_>>();
        assert_eq!(column(&r), column(&by_hand), "{name}");
        // The preload acts: the three points differ.
        let v: Vec<f64> = column(&r).iter().map(|x| x.parse().unwrap()).collect();
        assert!((v[0] - v[1]).abs() > 0.5 && (v[1] - v[2]).abs() > 0.5, "{name}: h_min {v:?}");
    }
}

#[test]
fn a_batch_in_three_shards_concatenated_equals_the_whole_batch() {
    let dir = scratch("batch");
    let designs = case("designs-compressor.csv");
    let base = case("compressor-bearing.toml");
    let whole = dir.join("all.csv");
    let o = run(&["batch", &designs, "--case", &base, "--set", PREVIEW, "--csv", whole.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let mut joined: Vec<Vec<String>> = Vec::new();
    for i in 1..=3 {
        let part = dir.join(format!("part-{i}.csv"));
        let jsonl = dir.join(format!("part-{i}.jsonl"));
        let o = run(&[
            "batch",
            &designs,
            "--case",
            &base,
            "--set",
            PREVIEW,
            "--shard",
            &format!("{i}/3"),
            "--csv",
            part.to_str().unwrap(),
            "--jsonl",
            jsonl.to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{}", stderr(&o));
        let r = rows(&std::fs::read_to_string(&part).unwrap());
        assert_eq!(r.len(), 1 + 4, "12 designs in 3 shards of 4");
        if joined.is_empty() {
            joined.push(r[0].clone());
        }
        joined.extend(r.into_iter().skip(1));
        assert_eq!(std::fs::read_to_string(&jsonl).unwrap().lines().count(), 4);
    }
    let all = rows(&std::fs::read_to_string(&whole).unwrap());
    assert_eq!(all.len(), 13);
    assert_eq!(all[0], joined[0]);
    let seconds = col(&all, "seconds");
    let drop_time = |r: &Vec<String>| {
        r.iter().enumerate().filter(|(k, _)| *k != seconds).map(|(_, v)| v.clone()).collect::<Vec<_>>()
    };
    for (a, b) in all.iter().zip(&joined).skip(1) {
        assert_eq!(drop_time(a), drop_time(b), "row differs between the sharded and the whole run");
    }
    // Each row carries its design's inputs beside its results.
    let (design, offset, speed) =
        (col(&all, "design"), col(&all, "bearing.pads.offset"), col(&all, "operating.speed_rpm"));
    assert_eq!((all[12][design].as_str(), all[12][offset].as_str(), all[12][speed].as_str()), ("11", "0.6", "10000"));
    assert!(all[1..].iter().all(|r| r.last().unwrap().is_empty()), "every design solves");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn json_goes_to_standard_output_and_the_summary_to_standard_error() {
    let o = run(&["solve", &case("compressor-bearing.toml"), "--set", PREVIEW, "--json", "-"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let j: serde_json::Value = serde_json::from_slice(&o.stdout).expect("standard output is exactly one JSON document");
    assert!(j["eccentricity_ratio"].as_f64().unwrap() > 0.0);
    assert!(stderr(&o).contains("reduced coefficients"), "{}", stderr(&o));
}

#[test]
fn bad_arguments_are_errors_on_standard_error() {
    for args in [
        vec!["sweep", "CASE", "--vary", "operating.speed_rpm=1:2:0"],
        vec!["batch", "DESIGNS", "--case", "CASE", "--shard", "4/3"],
        vec!["solve", "CASE", "--set", "operating.speed_rpm=abc"],
    ] {
        let args: Vec<String> = args
            .iter()
            .map(|a| match *a {
                "CASE" => case("compressor-bearing.toml"),
                "DESIGNS" => case("designs-compressor.csv"),
                x => x.to_string(),
            })
            .collect();
        let o = tiltpad().args(&args).output().unwrap();
        assert!(!o.status.success(), "{args:?}");
        assert!(o.stdout.is_empty(), "{args:?}: {}", String::from_utf8_lossy(&o.stdout));
        let e = stderr(&o);
        assert!(e.starts_with("error:"), "{e}");
        assert!(e.contains("1:2:0") || e.contains("4/3") || e.contains("operating.speed_rpm"), "{e}");
    }
}

#[test]
fn schema_lists_every_key_with_unit_range_and_meaning() {
    let o = run(&["schema"]);
    assert!(o.status.success());
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(text.contains("operating.speed_rpm  [rpm]") && text.contains("allowed: [0, 1000000]"), "{text}");
    let o = run(&["schema", "--json", "-"]);
    let j: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let keys = j.as_array().unwrap();
    assert_eq!(keys.len(), tiltpad::model::schema::KEYS.len());
    let preload = keys.iter().find(|k| k["key"] == "bearing.pads.preload").unwrap();
    assert_eq!(preload["allowed"], "[-1, 1)");
    assert_eq!(preload["unit"], "–");
    assert!(preload["meaning"].as_str().unwrap().contains("1 − Cb/Cp"));
}

fn toml_list(t: &toml::Table, key: &str) -> Vec<f64> {
    t[key].as_array().unwrap().iter().map(|v| v.as_float().unwrap()).collect()
}

#[test]
fn coefficients_over_speed_and_frequency_for_ross_and_csv() {
    let dir = scratch("coef");
    let (ross, csv_path) = (dir.join("brg.toml"), dir.join("brg.csv"));
    let base = case("compressor-bearing.toml");
    let o = run(&[
        "coefficients",
        &base,
        "--set",
        PREVIEW,
        "--speed-rpm",
        "6000:10000:3",
        "--node",
        "8",
        "--no-refine",
        "--ross",
        ross.to_str().unwrap(),
        "--csv",
        csv_path.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let doc: toml::Table = std::fs::read_to_string(&ross).unwrap().parse().unwrap();
    let t = doc["BearingElement_tiltpad"].as_table().unwrap();
    assert_eq!(t["n"].as_integer(), Some(8));
    let f = toml_list(t, "frequency");
    let expected: Vec<f64> = [6000.0f64, 8000.0, 10000.0].iter().map(|n| n * std::f64::consts::TAU / 60.0).collect();
    assert!(f.iter().zip(&expected).all(|(a, b)| (a - b).abs() < 1e-9 * b), "{f:?}");
    // The same numbers as a cold solve at 8000 rpm (warm starts converge to the same equilibrium).
    let s = common::solve("compressor-bearing.toml", &["mesh.fidelity=\"preview\"", "operating.speed_rpm=8000"]);
    for (k, i, j) in [("kxx", 0, 0), ("kxy", 0, 1), ("kyx", 1, 0), ("kyy", 1, 1)] {
        let v = toml_list(t, k)[1];
        assert!(
            (v - s.reduced.k_n_per_m[i][j]).abs() <= 1e-6 * s.reduced.k_n_per_m[1][1].abs(),
            "{k}: {v} vs {}",
            s.reduced.k_n_per_m[i][j]
        );
    }
    let c = rows(&std::fs::read_to_string(&csv_path).unwrap());
    assert_eq!(c.len(), 4);
    assert_eq!(c[2][col(&c, "cyy_ns_per_m")].parse::<f64>().unwrap(), toml_list(t, "cyy")[1]);
    // Frequency-dependent at one speed: ω = ratio · Ω, and ratio 1 is the solve's synchronous reduction.
    let o = run(&[
        "coefficients",
        &base,
        "--set",
        PREVIEW,
        "--set",
        "operating.speed_rpm=8000",
        "--excitation-ratio",
        "0.5,1,2",
        "--csv",
        "-",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let c = rows(&String::from_utf8_lossy(&o.stdout));
    let omega = 8000.0 * std::f64::consts::TAU / 60.0;
    let w: Vec<f64> = c[1..].iter().map(|r| r[col(&c, "frequency_rad_s")].parse().unwrap()).collect();
    assert!((w[0] - 0.5 * omega).abs() < 1e-9 && (w[2] - 2.0 * omega).abs() < 1e-9, "{w:?}");
    let kxx: f64 = c[2][col(&c, "kxx_n_per_m")].parse().unwrap();
    assert_eq!(kxx, s.reduced.k_n_per_m[0][0]);
    let cxx: Vec<f64> = c[1..].iter().map(|r| r[col(&c, "cxx_ns_per_m")].parse().unwrap()).collect();
    assert!(cxx[0] != cxx[2], "pad inertia and tilt make the damping frequency dependent: {cxx:?}");
    std::fs::remove_dir_all(&dir).ok();
}

/// The `--ross` band is refined where ROSS's spline would miss the coefficients, one element per node, with
/// warnings on standard error where the coefficients jump between samples (at preview fidelity pad 1 of the
/// compressor bearing floats between about 8052 and 8194 rpm, and pad 0 stops floating near 8407 rpm) and
/// where the band misses the analysis range.
#[test]
fn ross_export_refines_the_band_writes_every_node_and_warns() {
    let dir = scratch("ross-band");
    let ross = dir.join("brg.toml");
    let base = case("compressor-bearing.toml");
    let args = |speeds: &str, extra: &[&str]| {
        let mut a: Vec<String> = ["coefficients", &base, "--set", PREVIEW, "--speed-rpm", speeds, "--ross"]
            .iter()
            .map(ToString::to_string)
            .collect();
        a.push(ross.to_str().unwrap().to_string());
        a.extend(extra.iter().map(ToString::to_string));
        a
    };
    let run_args = |a: &[String]| run(&a.iter().map(String::as_str).collect::<Vec<_>>());
    // A smooth band: refined (every interval checked at its midpoint), no warning, one element per node.
    let o = run_args(&args("9000,10000,11000", &["--node", "7,49", "--tag", "de,nde"]));
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(!stderr(&o).contains("warning"), "{}", stderr(&o));
    let doc: toml::Table = std::fs::read_to_string(&ross).unwrap().parse().unwrap();
    let (de, nde) = (doc["BearingElement_de"].as_table().unwrap(), doc["BearingElement_nde"].as_table().unwrap());
    assert_eq!((de["n"].as_integer(), nde["n"].as_integer()), (Some(7), Some(49)));
    let f = toml_list(de, "frequency");
    assert_eq!(f, toml_list(nde, "frequency"));
    assert_eq!(toml_list(de, "kxx"), toml_list(nde, "kxx"));
    assert!(f.len() >= 5 && f.windows(2).all(|w| w[0] < w[1]), "{f:?}");
    for n in [9000.0f64, 10000.0, 11000.0] {
        assert!(f.iter().any(|w| (w - n * std::f64::consts::TAU / 60.0).abs() < 1e-9), "{n} rpm kept: {f:?}");
    }
    // Across the floating pad: the jumps are narrowed to the finest interval (1000/512 rpm) and warned.
    let o = run_args(&args("8000,9000", &["--analysis-rpm", "7000:9000"]));
    assert!(o.status.success(), "{}", stderr(&o));
    let err = stderr(&o);
    let warnings: Vec<&str> = err.lines().filter(|l| l.starts_with("warning: ")).collect();
    let jumps: Vec<&&str> = warnings.iter().filter(|w| w.contains("coefficients jump between")).collect();
    assert!(!jumps.is_empty() && jumps.iter().any(|w| w.contains("pad 1")), "{warnings:?}");
    // Each located to one finest interval: "between 8051.8 and 8052.7 rpm".
    for w in &jumps {
        let words: Vec<&str> = w.split_whitespace().collect();
        let at = words.iter().position(|x| *x == "between").unwrap();
        let (a, b): (f64, f64) = (words[at + 1].parse().unwrap(), words[at + 3].trim_end_matches(':').parse().unwrap());
        assert!(b - a < 1000.0 / 1024.0 + 0.1, "{w}");
    }
    assert!(warnings.iter().any(|w| w.contains("cover 8000–9000 rpm") && w.contains("7000–9000 rpm")), "{warnings:?}");
    let doc: toml::Table = std::fs::read_to_string(&ross).unwrap().parse().unwrap();
    let f = toml_list(doc["BearingElement_tiltpad"].as_table().unwrap(), "frequency");
    let finest = f.windows(2).map(|w| (w[1] - w[0]) * 60.0 / std::f64::consts::TAU).fold(f64::MAX, f64::min);
    // Intervals are halved while they are at least 1/512 of the band wide: the finest is 1/1024 of it.
    assert!((finest - 1000.0 / 1024.0).abs() < 1e-6, "finest interval {finest} rpm");
    // One tag per node or one for all.
    let o = run_args(&args("8000,9000", &["--node", "1,2,3", "--tag", "a,b"]));
    assert!(!o.status.success() && stderr(&o).contains("2 tags for 3 nodes"), "{}", stderr(&o));
    std::fs::remove_dir_all(&dir).ok();
}

/// Runs `script` as root of a new user and mount namespace (so it may mount a small tmpfs without
/// privileges) with `$BIN` and `$CASE` set; returns its standard output.
fn in_namespace(script: &str) -> String {
    let o = Command::new("unshare")
        .args(["--user", "--map-root-user", "--mount", "sh", "-c", script])
        .env("BIN", env!("CARGO_BIN_EXE_tiltpad"))
        .env("CASE", case("compressor-bearing.toml"))
        .output()
        .expect("unshare (util-linux) runs the safe-write tests in a mount namespace");
    assert!(
        o.status.success(),
        "namespace script failed: {}\n{}",
        String::from_utf8_lossy(&o.stdout),
        String::from_utf8_lossy(&o.stderr)
    );
    String::from_utf8_lossy(&o.stdout).into_owned()
}

#[test]
fn writes_onto_a_full_disk_and_a_read_only_directory_keep_the_old_file() {
    let dir = scratch("fs");
    let script = format!(
        r#"set -u
D="{d}"
mount -t tmpfs -o size=8k tmpfs "$D" || exit 3
echo old > "$D/out.json"
"$BIN" solve "$CASE" --set 'mesh.fidelity="preview"' --json "$D/out.json" >/dev/null 2>"$D/../full.err"
echo "full rc=$?"
echo "full content=$(cat "$D/out.json")"
echo "full files=$(ls -A "$D" | tr '\n' ' ')"
mount -o remount,ro "$D" || exit 4
"$BIN" solve "$CASE" --set 'mesh.fidelity="preview"' --json "$D/out.json" >/dev/null 2>"$D/../ro.err"
echo "ro rc=$?"
echo "ro content=$(cat "$D/out.json")"
echo "ro files=$(ls -A "$D" | tr '\n' ' ')"
"#,
        d = dir.join("mnt").display()
    );
    std::fs::create_dir_all(dir.join("mnt")).unwrap();
    let out = in_namespace(&script);
    let target = dir.join("mnt").join("out.json");
    for kind in ["full", "ro"] {
        assert!(out.contains(&format!("{kind} rc=1")), "{kind}: {out}");
        assert!(out.contains(&format!("{kind} content=old")), "{kind}: the old file changed: {out}");
        assert!(out.contains(&format!("{kind} files=out.json \n")), "{kind}: something left behind: {out}");
        let err = std::fs::read_to_string(dir.join(format!("{kind}.err"))).unwrap();
        assert!(err.contains(&target.display().to_string()), "{kind}: the message does not name the path: {err}");
    }
    assert!(std::fs::read_to_string(dir.join("full.err")).unwrap().contains("No space left"));
    assert!(std::fs::read_to_string(dir.join("ro.err")).unwrap().contains("Read-only file system"));
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn json_onto_a_symlink_writes_through_it() {
    let dir = scratch("link");
    let real = dir.join("real.json");
    let link = dir.join("link.json");
    std::fs::write(&real, "old").unwrap();
    std::os::unix::fs::symlink(&real, &link).unwrap();
    let o = run(&["solve", &case("compressor-bearing.toml"), "--set", PREVIEW, "--json", link.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(std::fs::symlink_metadata(&link).unwrap().file_type().is_symlink());
    let j: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&real).unwrap()).unwrap();
    assert!(j["h_min_m"].as_f64().unwrap() > 0.0);
    // A directory as the target: an error naming it, the directory untouched.
    let o = run(&["solve", &case("compressor-bearing.toml"), "--set", PREVIEW, "--json", dir.to_str().unwrap()]);
    assert!(
        !o.status.success() && stderr(&o).contains(&dir.display().to_string()) && stderr(&o).contains("directory"),
        "{}",
        stderr(&o)
    );
    let mut names: Vec<String> =
        std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    names.sort();
    assert_eq!(names, ["link.json", "real.json"]);
    std::fs::remove_dir_all(&dir).ok();
}

fn point_array(piece: &vtkio::model::UnstructuredGridPiece, name: &str) -> Vec<f64> {
    piece
        .data
        .point
        .iter()
        .find_map(|a| match a {
            vtkio::model::Attribute::DataArray(d) if d.name == name => d.data.clone().cast_into::<f64>(),
            _ => None,
        })
        .unwrap_or_else(|| panic!("no point array {name}"))
}

fn read_vtu(path: &Path) -> vtkio::model::UnstructuredGridPiece {
    let vtk = vtkio::Vtk::import(path).unwrap_or_else(|e| panic!("{}: {e:?}", path.display()));
    match vtk.data {
        vtkio::model::DataSet::UnstructuredGrid { mut pieces, .. } => match pieces.remove(0) {
            vtkio::model::Piece::Inline(p) => *p,
            _ => panic!("piece not inline"),
        },
        _ => panic!("not an unstructured grid"),
    }
}

#[test]
fn vtu_files_read_back_with_their_nodes_and_values() {
    let dir = scratch("vtu");
    let out = dir.join("fillon.vtu");
    let json = dir.join("fillon.json");
    let o = run(&[
        "solve",
        &case("fillon-a.toml"),
        "--set",
        PREVIEW,
        "--vtu",
        out.to_str().unwrap(),
        "--json",
        json.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let s = common::solve("fillon-a.toml", &["mesh.fidelity=\"preview\""]);
    let j: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    // Film: every pad's grid, the half model mirrored to the full length.
    let film = read_vtu(&out);
    let nodes: usize = s
        .pads
        .iter()
        .map(|p| p.field.s_m.len() * (if p.field.half { 2 * p.field.z_m.len() - 1 } else { p.field.z_m.len() }))
        .sum();
    assert_eq!(film.num_points(), nodes);
    let p = point_array(&film, "pressure_pa");
    assert_eq!(p.len(), nodes);
    assert_eq!(p.iter().copied().fold(f64::NEG_INFINITY, f64::max), j["p_max_pa"].as_f64().unwrap());
    let h = point_array(&film, "film_thickness_m");
    assert_eq!(h.iter().copied().fold(f64::INFINITY, f64::min), j["h_min_m"].as_f64().unwrap());
    let t = point_array(&film, "film_temperature_c");
    assert_eq!(t.iter().copied().fold(f64::NEG_INFINITY, f64::max), j["t_max_film_c"].as_f64().unwrap());
    assert_eq!(point_array(&film, "mean_velocity_m_s").len(), 3 * nodes);
    // Points lie on the pad surfaces: a film thickness outside the journal surface.
    let pts = film.points.clone().cast_into::<f64>().unwrap();
    let (ex, ey) = (s.journal_position_m[0], s.journal_position_m[1]);
    let r = s.inputs.bearing.journal_radius_m;
    for (k, xyz) in pts.chunks(3).enumerate().step_by(97) {
        let radius = (xyz[0] - ex).hypot(xyz[1] - ey);
        assert!((radius - (r + h[k])).abs() < 1e-12, "node {k}: {radius} vs {}", r + h[k]);
    }
    // Pads: the 3-D temperature field.
    let pads = read_vtu(&dir.join("fillon-pads.vtu"));
    let layers = s.pads[0].thermal.as_ref().unwrap().solid.as_ref().unwrap().radii_m.len();
    assert_eq!(pads.num_points(), nodes * layers);
    let tp = point_array(&pads, "pad_temperature_c");
    assert_eq!(tp.iter().copied().fold(f64::NEG_INFINITY, f64::max), j["t_max_pad_c"].as_f64().unwrap());
    // Rigid pads: no deformation field.
    assert!(film
        .data
        .point
        .iter()
        .all(|a| !matches!(a, vtkio::model::Attribute::DataArray(d) if d.name == "elastic_radial_displacement_m")));
    // Flexible pads: the film face's elastic radial displacement, its extremes those of the solution's pads.
    let flex = dir.join("flex.vtu");
    let o =
        run(&["solve", &case("compressor-bearing-flexible.toml"), "--set", PREVIEW, "--vtu", flex.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let s = common::solve("compressor-bearing-flexible.toml", &["mesh.fidelity=\"preview\""]);
    let u = point_array(&read_vtu(&flex), "elastic_radial_displacement_m");
    let peak = |v: &mut dyn Iterator<Item = f64>| v.fold(0.0_f64, |m, x| m.max(x.abs()));
    let solved = peak(&mut s.pads.iter().flat_map(|p| p.elastic_displacement_m.iter().copied()));
    assert!(solved > 0.0);
    assert_eq!(peak(&mut u.iter().copied()), solved);
    // Flexible isothermal pads: the solid grid with the mechanical displacement vector; on the film face
    // (each pad's first layer) its radial component is the film grid's elastic displacement.
    let solid = read_vtu(&dir.join("flex-pads.vtu"));
    let layers = s.pads[0].flex.as_ref().unwrap().radii_m.len();
    let per_layer = u.len() / s.pads.len();
    assert_eq!(solid.num_points(), u.len() * layers);
    let d = point_array(&solid, "pad_displacement_m");
    assert_eq!(d.len(), 3 * solid.num_points());
    let pts = solid.points.clone().cast_into::<f64>().unwrap();
    let (ex, ey) = (s.journal_position_m[0], s.journal_position_m[1]);
    for pad in 0..s.pads.len() {
        for n in 0..per_layer {
            let p = pad * per_layer * layers + n;
            let th = (pts[3 * p + 1] - ey).atan2(pts[3 * p] - ex);
            let radial = d[3 * p] * th.cos() + d[3 * p + 1] * th.sin();
            let film = u[pad * per_layer + n];
            assert!((radial - film).abs() <= 1e-9 * solved, "pad {pad} node {n}: {radial} vs {film}");
        }
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_sweep_writes_a_paraview_collection() {
    let dir = scratch("pvd");
    let pvd = dir.join("speed.pvd");
    let o = run(&[
        "sweep",
        &case("compressor-bearing.toml"),
        "--set",
        PREVIEW,
        "--vary",
        "operating.speed_rpm=7000,9000",
        "--csv",
        dir.join("s.csv").to_str().unwrap(),
        "--vtu",
        pvd.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&pvd).unwrap();
    assert!(
        text.contains("timestep=\"7e3\"")
            && text.contains("file=\"speed-0000.vtu\"")
            && text.contains("file=\"speed-0001.vtu\""),
        "{text}"
    );
    let a = read_vtu(&dir.join("speed-0000.vtu"));
    let b = read_vtu(&dir.join("speed-0001.vtu"));
    assert_eq!(a.num_points(), b.num_points());
    let pa = point_array(&a, "pressure_pa");
    let pb = point_array(&b, "pressure_pa");
    assert!(pa != pb);
    std::fs::remove_dir_all(&dir).ok();
}

/// Design limits in the sweep CSV and in `solve`'s summary and JSON: the compressor bearing at its own load
/// is within the conventions; at 18 kN its specific load W/(L·D) = 18000 / (44.45 mm · 101.6 mm) = 3.99 MPa
/// exceeds the 3.5 MPa convention; a limit set on the command line applies.
#[test]
fn sweeps_and_solves_mark_the_exceeded_design_limits() {
    let o = run(&[
        "sweep",
        &case("compressor-bearing.toml"),
        "--set",
        PREVIEW,
        "--vary",
        "operating.load_n=1918,18000",
        "--csv",
        "-",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let r = rows(&String::from_utf8_lossy(&o.stdout));
    let k = col(&r, "limits_exceeded");
    assert_eq!(r[1][k], "", "{:?}", r[1]);
    assert!(r[2][k].split(';').any(|n| n == "specific_load"), "{:?}", r[2]);
    let o = run(&[
        "solve",
        &case("compressor-overload.toml"),
        "--set",
        PREVIEW,
        "--set",
        "limits.max_peak_pressure_mpa=1",
        "--json",
        "-",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let summary = stderr(&o);
    assert!(
        summary.contains("DESIGN LIMITS EXCEEDED") && summary.contains("W/(L·D) 3.986 MPa > limit 3.5 MPa"),
        "{summary}"
    );
    assert!(summary.contains("> limit 1 MPa"), "{summary}");
    let j: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let checks = j["design_limits"]["checks"].as_array().unwrap();
    let p = checks.iter().find(|c| c["kind"] == "max_peak_pressure").unwrap();
    assert_eq!((p["limit"].as_f64(), p["exceeded"].as_bool()), (Some(1e6), Some(true)));
    assert_eq!(j["design_limits"]["limits"]["max_specific_load_pa"].as_f64(), Some(3.5e6));
}
