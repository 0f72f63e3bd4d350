//! Bench section: the work estimates every command prints (and refuses on) before its first solve, against
//! the work it then does. Each command runs as a user runs it (the `tiltpad` binary, a child process, outputs to a
//! temporary directory) on the shipped cases; the estimate is computed by the same functions the command
//! calls ([`tiltpad::study::estimate`]). Measured: the wall time of the whole command (reading, solving,
//! writing), the bearing solves it made (from its JSON output where it reports them) and, for `solve`, the
//! film solves. The estimate is a property of the input at the reference rate, so on a loaded machine the
//! measured times run high by the load; the section states the load average it saw.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use anyhow::{bail, Context, Result};

use tiltpad::control::analysis::ControlParams;
use tiltpad::io::read::{read_controlled, read_rotor};
use tiltpad::model::load_case;
use tiltpad::rotor::analysis::ONSET_PROBES;
use tiltpad::rotor::critical_map::MAP_POINTS;
use tiltpad::study::estimate::{duration_text, point_cost, Estimate};
use tiltpad::study::rotor_cost::uniform_rotor;

/// Heading of the section in docs/PERFORMANCE.md.
pub const HEADING: &str = "## Work estimates";

/// One command to run: its arguments (`{OUT}` is the temporary output directory), its estimate, and where
/// its JSON output is (when it writes one).
struct Run {
    command: &'static str,
    label: String,
    args: Vec<String>,
    estimate: Estimate,
    json: Option<PathBuf>,
}

/// What a run did.
struct Measured {
    seconds: f64,
    /// CPU time of the child process (user and system) [s]; `None` where `/proc` does not tell.
    cpu_seconds: Option<f64>,
    eigen_solutions: Option<u64>,
    bearing_solves: Option<u64>,
    film_solves: Option<u64>,
}

fn case_of(path: &Path) -> Result<tiltpad::model::Case> {
    let text = std::fs::read_to_string(path).with_context(|| format!("cannot read {}", path.display()))?;
    Ok(load_case(&text, &[]).with_context(|| format!("invalid case {}", path.display()))?.1)
}

/// The first number under `key` anywhere in `v`.
fn find_count(v: &serde_json::Value, key: &str) -> Option<u64> {
    match v {
        serde_json::Value::Object(m) => {
            m.get(key).and_then(serde_json::Value::as_u64).or_else(|| m.values().find_map(|x| find_count(x, key)))
        }
        serde_json::Value::Array(a) => a.iter().find_map(|x| find_count(x, key)),
        _ => None,
    }
}

/// CPU time (user and system) of the children this process has waited for [s], from `/proc/self/stat`
/// (fields `cutime` and `cstime`, in clock ticks of 1/100 s, Linux's `USER_HZ`).
fn children_cpu_seconds() -> Option<f64> {
    let stat = std::fs::read_to_string("/proc/self/stat").ok()?;
    // the fields after the command name (which may hold spaces) closed by the last ')'
    let rest = &stat[stat.rfind(')')? + 1..];
    let f: Vec<&str> = rest.split_whitespace().collect();
    // fields 16 and 17 of the whole line are the 14th and 15th after the name
    let (u, s): (f64, f64) = (f.get(13)?.parse().ok()?, f.get(14)?.parse().ok()?);
    Some((u + s) / 100.0)
}

/// A command whose CPU time is shorter than this is run again, until the runs add up to it (at most
/// [`MAX_REPEATS`] runs), and their mean is taken: the children's CPU time is counted in ticks of 10 ms, so
/// one 20 ms run alone is known to ±50 % only.
const MIN_CPU_SECONDS: f64 = 0.5;
/// See [`MIN_CPU_SECONDS`].
const MAX_REPEATS: u32 = 25;

/// The product binary the commands run as: `$TILTPAD_BIN` when set, else `tiltpad` built now in this
/// program's profile (`cargo build --release --bin tiltpad` under the `xtask` alias: nothing to do when it is
/// current), beside this program in the workspace's target directory.
fn tiltpad_binary() -> Result<PathBuf> {
    if let Some(p) = std::env::var_os("TILTPAD_BIN") {
        return Ok(PathBuf::from(p));
    }
    let me = std::env::current_exe().context("cannot find this program")?;
    let dir = me.parent().context("this program has no directory")?;
    let mut build = std::process::Command::new(std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into()));
    // the workspace this program was built from, whatever `--root` the bench measures
    build.current_dir(Path::new(env!("CARGO_MANIFEST_DIR"))).args([
        "build",
        "--package",
        "tiltpad",
        "--bin",
        "tiltpad",
    ]);
    if dir.file_name().is_some_and(|n| n == "release") {
        build.arg("--release");
    }
    super::say("bench: estimates: building the tiltpad binary");
    let status = build.status().context("cannot run cargo to build the tiltpad binary")?;
    if !status.success() {
        bail!("bench estimates: building the tiltpad binary failed ({status})");
    }
    Ok(dir.join(format!("tiltpad{}", std::env::consts::EXE_SUFFIX)))
}

fn measure(exe: &Path, run: &Run, out: &Path) -> Result<Measured> {
    let args: Vec<String> = run.args.iter().map(|a| a.replace("{OUT}", &out.display().to_string())).collect();
    let (mut seconds, mut cpu_seconds, mut runs) = (0.0, Some(0.0), 0_u32);
    loop {
        let cpu_before = children_cpu_seconds();
        let t = web_time::Instant::now();
        let status = std::process::Command::new(exe)
            .args(&args)
            .stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::null())
            .status()?;
        seconds += t.elapsed().as_secs_f64();
        let cpu = children_cpu_seconds().zip(cpu_before).map(|(a, b)| a - b);
        cpu_seconds = cpu_seconds.zip(cpu).map(|(a, b)| a + b);
        runs += 1;
        if !status.success() {
            bail!("bench estimates: `tiltpad {}` failed ({status})", args.join(" "));
        }
        if cpu_seconds.is_none_or(|c| c >= MIN_CPU_SECONDS) || runs >= MAX_REPEATS {
            break;
        }
    }
    let seconds = seconds / f64::from(runs);
    let cpu_seconds = cpu_seconds.map(|c| c / f64::from(runs));
    let json = match &run.json {
        Some(p) => {
            let p = PathBuf::from(p.display().to_string().replace("{OUT}", &out.display().to_string()));
            let text = std::fs::read_to_string(&p).with_context(|| format!("cannot read {}", p.display()))?;
            Some(serde_json::from_str::<serde_json::Value>(&text)?)
        }
        None => None,
    };
    // a thermal solve's film solves are its outer loop's total
    let film_solves = json.as_ref().and_then(|j| {
        j.get("thermal")
            .and_then(|t| t.get("report"))
            .and_then(|r| r.get("film_solves"))
            .and_then(serde_json::Value::as_u64)
            .or_else(|| j.get("report").and_then(|r| r.get("film_solves")).and_then(serde_json::Value::as_u64))
    });
    let bearing_solves = json.as_ref().and_then(|j| find_count(j, "bearing_solves"));
    let eigen_solutions = json.as_ref().and_then(|j| find_count(j, "eigen_solutions"));
    Ok(Measured { seconds, cpu_seconds, eigen_solutions, bearing_solves, film_solves })
}

/// The runs: `solve` on every shipped case as shipped, and each multi-point command on its shipped case
/// (`dir`: where generated inputs go).
fn runs(root: &Path, dir: &Path) -> Result<Vec<Run>> {
    let cases = root.join("cases");
    let mut out = Vec::new();
    for n in &super::shipped_names(root)? {
        let path = cases.join(n);
        let estimate = Estimate::points("solve", 1, point_cost(&case_of(&path)?));
        out.push(Run {
            command: "solve",
            label: format!("`{n}`"),
            args: vec!["solve".into(), path.display().to_string(), "--json".into(), "{OUT}/s.json".into()],
            estimate,
            json: Some("{OUT}/s.json".into()),
        });
    }
    let compressor = cases.join("compressor-bearing.toml");
    let cost = point_cost(&case_of(&compressor)?);
    let c = compressor.display().to_string();
    out.push(Run {
        command: "sweep",
        label: "compressor, 6 speeds".into(),
        args: vec![
            "sweep".into(),
            c.clone(),
            "--vary".into(),
            "operating.speed_rpm=4000:12000:6".into(),
            "--csv".into(),
            "{OUT}/p.csv".into(),
        ],
        estimate: Estimate::points("sweep", 6, cost),
        json: None,
    });
    out.push(Run {
        command: "coefficients",
        label: "compressor, 6 speeds".into(),
        args: vec![
            "coefficients".into(),
            c.clone(),
            "--speed-rpm".into(),
            "4000:12000:6".into(),
            "--csv".into(),
            "{OUT}/k.csv".into(),
        ],
        estimate: Estimate::points("coefficients", 6, cost),
        json: None,
    });
    let designs = cases.join("designs-compressor.csv");
    let rows = std::fs::read_to_string(&designs)?.lines().filter(|l| !l.starts_with('#')).count().saturating_sub(1);
    out.push(Run {
        command: "batch",
        label: format!("`designs-compressor.csv`, {rows} designs"),
        args: vec![
            "batch".into(),
            designs.display().to_string(),
            "--case".into(),
            c.clone(),
            "--csv".into(),
            "{OUT}/b.csv".into(),
        ],
        estimate: Estimate::points("batch", rows, cost),
        json: None,
    });
    let active = cases.join("compressor-bearing-active.toml");
    out.push(Run {
        command: "frf",
        label: "`compressor-bearing-active.toml`".into(),
        args: vec!["frf".into(), active.display().to_string(), "--csv".into(), "{OUT}/f.csv".into()],
        estimate: Estimate::points("frf", 1, point_cost(&case_of(&active)?)),
        json: None,
    });
    let flexible = cases.join("compressor-bearing-flexible.toml");
    out.push(Run {
        command: "modes",
        label: "`compressor-bearing-flexible.toml`".into(),
        args: vec!["modes".into(), flexible.display().to_string(), "--csv".into(), "{OUT}/m.csv".into()],
        estimate: Estimate::pad_modes(&case_of(&flexible)?, 3, &[]),
        json: None,
    });
    let uniform = dir.join("uniform-400.toml");
    // the rotor file is in a temporary directory: its bearing case by an absolute path
    let bearing =
        std::fs::canonicalize(&compressor).with_context(|| format!("cannot find {}", compressor.display()))?;
    std::fs::write(&uniform, uniform_rotor(400, &bearing))?;
    let uniform_200 = dir.join("uniform-200.toml");
    std::fs::write(&uniform_200, uniform_rotor(200, &bearing))?;
    for (command, file, speeds, shaft) in [
        ("rotor", cases.join("rotors/compressor-rotor.toml"), "1000:13000:25", None),
        ("rotor", cases.join("rotors/compressor-rotor.toml"), "1000:13000:25", Some(0)),
        ("rotor", uniform, "3000:4000:2", None),
        ("rotor --critical-map", uniform_200, "3000:4000:2", None),
        ("control", cases.join("rotors/compressor-rotor-active.toml"), "6000:12000:13", None),
    ] {
        let path = file;
        let mut rotor = read_rotor(&path)?;
        let mut extra = Vec::new();
        if let Some(m) = shaft {
            rotor.shaft_modes = m;
            extra = vec!["--shaft-modes".to_string(), m.to_string()];
        }
        let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
        let file = if path.starts_with(&cases) { format!("rotors/{name}") } else { format!("{name} (generated)") };
        let speeds_rad_s = super::speeds(speeds)?;
        let n = speeds_rad_s.len();
        // as the commands estimate
        let estimate = match command {
            "rotor" => Estimate::rotor(command, &rotor, n, ONSET_PROBES),
            "rotor --critical-map" => {
                extra.push("--critical-map".into());
                Estimate::critical_map(&rotor, n, MAP_POINTS)
            }
            _ => {
                let (_, control) = read_controlled(&path)?;
                ControlParams::new(speeds_rad_s).estimate(&rotor, &control)
            }
        };
        let full = if rotor.shaft_modes == 0 { ", full shaft" } else { "" };
        let program = command.split(' ').next().unwrap_or(command);
        let mut args =
            vec![program.into(), path.display().to_string(), "--speeds".into(), speeds.into(), "--json".into()];
        args.push("{OUT}/r.json".into());
        args.extend(extra);
        out.push(Run {
            command,
            label: format!("`{file}`, {} elements{full}, {n} speeds", rotor.elements.len()),
            args,
            estimate,
            json: Some("{OUT}/r.json".into()),
        });
    }
    Ok(out)
}

/// The estimate of the work a run made: for a rotor, the same cost model with the bearing solves and
/// eigen-solutions it reports (bisections stop early, bearings sharing a case share a solve); otherwise the
/// estimate itself.
fn made_estimate(e: &Estimate, m: &Measured) -> f64 {
    let (Some(eigen), Some(solves), Some(solutions)) = (e.eigen, m.bearing_solves, m.eigen_solutions) else {
        return e.seconds;
    };
    #[allow(clippy::cast_precision_loss)]
    let per_solve = if e.solves == 0 { 0.0 } else { (e.seconds - eigen.seconds()) / e.solves as f64 };
    #[allow(clippy::cast_precision_loss)]
    let made = solves as f64 * per_solve + solutions as f64 * eigen.seconds_each + eigen.shaft_seconds;
    made
}

/// Milliseconds below a second, else [`duration_text`].
fn short_duration(seconds: f64) -> String {
    if seconds < 1.0 {
        format!("{:.0} ms", 1e3 * seconds)
    } else {
        duration_text(seconds)
    }
}

fn load_average() -> String {
    std::fs::read_to_string("/proc/loadavg")
        .ok()
        .and_then(|s| s.split_whitespace().next().map(str::to_string))
        .unwrap_or_else(|| "unknown".into())
}

/// The markdown section.
///
/// # Errors
/// A missing case, or a command that fails.
pub fn section(root: &Path) -> Result<String> {
    super::say("bench: estimates");
    let exe = tiltpad_binary()?;
    let dir = std::env::temp_dir().join(format!("tiltpad-bench-estimates-{}", std::process::id()));
    std::fs::create_dir_all(&dir)?;
    let load_before = load_average();
    let mut table = String::new();
    let mut ratios = Vec::new();
    for run in runs(root, &dir)? {
        super::say(format!("bench: estimates: {} {}", run.command, run.label));
        let m = measure(&exe, &run, &dir)?;
        let made = made_estimate(&run.estimate, &m);
        let ratio = m.cpu_seconds.unwrap_or(m.seconds) / made;
        ratios.push(ratio);
        let made_solves = match (run.command, m.bearing_solves) {
            (_, Some(n)) => n.to_string(),
            ("solve" | "frf", None) => "1".into(),
            ("modes", None) => "0".into(),
            _ => format!("{} (one per point)", run.estimate.solves),
        };
        let eigen = match (&run.estimate.eigen, m.eigen_solutions) {
            (Some(e), Some(n)) => format!("{} of {} states / {n}", e.solutions, e.states),
            (Some(e), None) if e.undamped => format!("{} undamped of {} coordinates", e.solutions, e.states),
            _ => "—".into(),
        };
        let estimated = if (made - run.estimate.seconds).abs() > 1e-9 * made {
            format!("{} ({} for the work made)", short_duration(run.estimate.seconds), short_duration(made))
        } else {
            short_duration(run.estimate.seconds)
        };
        let _ = writeln!(
            table,
            "| `{}` | {} | {} / {made_solves} | {eigen} | {} | {estimated} | {} | {} | {ratio:.2} |",
            run.command,
            run.label,
            run.estimate.solves,
            m.film_solves.map_or("—".into(), |n| n.to_string()),
            short_duration(m.seconds),
            m.cpu_seconds.map_or("—".into(), short_duration),
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
    let load_after = load_average();
    ratios.sort_by(f64::total_cmp);
    let (lo, hi) = (ratios.first().copied().unwrap_or(0.0), ratios.last().copied().unwrap_or(0.0));
    let median = ratios.get(ratios.len() / 2).copied().unwrap_or(0.0);
    let mut md = format!(
        "\n{HEADING} (`cargo xtask bench --only estimates`)\n\nEvery command estimates its work from its inputs before the first \
         solve (bearing solves, and seconds at the reference rate of the cost-growth table: `src/study/estimate.rs`) \
         and refuses what is over `--max-hours` or 8 GB; a rotor's estimate adds its dense eigen-solutions \
         (the cube of the state size, once per speed and bisection probe) and a flexible pad's its modal \
         solution. Here each command runs as a user runs it, on the shipped cases (and one generated \
         400-element full shaft, the largest the rotor file allows), and its CPU time (user and system, \
         reading, solving, writing: what a quiet machine's wall time would be, the solver being \
         single-threaded below 2500 film nodes per pad) is set against the estimate (a command under 0.5 s of CPU time is run again until its runs add up to 0.5 s, at most 25 \
         times, and the mean is given: the CPU time is counted in ticks of 10 ms). *Bearing solves*: \
         estimated / made (rotor, control: the estimate counts every bearing at every speed and the most \
         probes a bisection may take, an upper bound: bearings that share a case share a solve); \
         *eigen-solutions*: estimated (states) / made; *film solves*: those of the equilibrium (and of every \
         outer thermal iteration). For a rotor the ratio is taken against the estimate of the work it made \
         (the same cost model with the solves and eigen-solutions it reports). CPU / estimated: median \
         {median:.2}, from {lo:.2} to {hi:.2}; load average {load_before} before and {load_after} after the run \
         (wall times run high by about the load; CPU times far less).\n\n| command | input | bearing solves | \
         eigen-solutions | film solves | estimated time | wall time | CPU time | CPU / estimated |\n\
         |---|---|---|---|---|---|---|---|---|\n"
    );
    md.push_str(&table);
    Ok(md)
}
