//! What every command checks before it starts (its input files are read under a size cap by
//! [`crate::io::read`]): outputs that would overwrite an input or each other refused, and the work of a
//! command (points to solve) bounded up front with the setting that raises the bound.

use std::path::{Path, PathBuf};

use anyhow::{bail, Result};

/// Default bound on the points one command solves (sweep points, designs, speeds, frequencies); each
/// command's `--max-points` raises it.
pub const DEFAULT_MAX_POINTS: usize = 10_000;

/// A file's identity: the device and inode of what the path names (through symlinks) when it exists, else
/// its absolute path with the directory resolved.
#[derive(Debug, PartialEq, Eq)]
enum Identity {
    #[cfg(unix)]
    Inode(u64, u64),
    Path(PathBuf),
}

fn identity(path: &Path) -> Identity {
    #[cfg(unix)]
    if let Ok(m) = std::fs::metadata(path) {
        use std::os::unix::fs::MetadataExt;
        return Identity::Inode(m.dev(), m.ino());
    }
    let absolute = std::path::absolute(path).unwrap_or_else(|_| path.to_path_buf());
    let resolved = match (absolute.parent(), absolute.file_name()) {
        (Some(dir), Some(name)) => std::fs::canonicalize(dir).map_or(absolute.clone(), |d| d.join(name)),
        _ => absolute,
    };
    Identity::Path(resolved)
}

/// Refuses outputs that would overwrite an input or each other. `inputs`: (what, path); `outputs`: (flag,
/// path), `-` meaning standard output (which only one output may take).
///
/// # Errors
/// The first collision, naming both.
pub fn check_outputs(inputs: &[(&str, &Path)], outputs: &[(&str, Option<&Path>)]) -> Result<()> {
    let outputs: Vec<(&str, &Path)> = outputs.iter().filter_map(|(f, p)| p.map(|p| (*f, p))).collect();
    for (i, (flag, out)) in outputs.iter().enumerate() {
        let stdout = out.as_os_str() == "-";
        for (other, earlier) in &outputs[..i] {
            let both_stdout = stdout && earlier.as_os_str() == "-";
            if both_stdout || (!stdout && earlier.as_os_str() != "-" && identity(out) == identity(earlier)) {
                bail!(
                    "{other} and {flag} both write {}: one would overwrite the other; give them different files",
                    if both_stdout { "standard output".to_string() } else { out.display().to_string() }
                );
            }
        }
        if stdout {
            continue;
        }
        let id = identity(out);
        for (what, input) in inputs {
            if identity(input) == id {
                bail!(
                    "{flag} {} is the {what} this command reads; tiltpad never overwrites an input: write the \
                     result to another file",
                    out.display()
                );
            }
        }
    }
    Ok(())
}

/// `--max-hours`: a finite positive number of hours.
///
/// # Errors
/// Anything else, with the value.
pub fn parse_hours(s: &str) -> std::result::Result<f64, String> {
    let v: f64 = s.trim().parse().map_err(|e| format!("`{s}` is not a number: {e}"))?;
    if !(v.is_finite() && v > 0.0) {
        return Err(format!("{v}: the bound on the estimated work must be a finite positive number of hours"));
    }
    Ok(v)
}

/// Refuses a command whose estimated work exceeds `max_hours` (or whose memory exceeds the cap) before its
/// first solve; a long one (a minute or more) is announced with its estimate on standard error.
///
/// # Errors
/// [`crate::study::estimate::TooMuchWork`], with the estimate and the setting that raises the bound.
pub fn check_work(estimate: &crate::study::estimate::Estimate, max_hours: f64) -> Result<()> {
    estimate.check(max_hours)?;
    if estimate.seconds >= 60.0 {
        eprintln!("estimate: {estimate}");
    }
    Ok(())
}

/// The costliest point of a study among `points` (the base case and a few of its points, whichever
/// resolve), for its estimate.
pub fn costliest(
    runner: &crate::study::Runner,
    points: &[&[(String, String)]],
) -> Option<crate::study::estimate::PointCost> {
    points
        .iter()
        .filter_map(|p| runner.case(p).ok())
        .map(|c| crate::study::estimate::point_cost(&c))
        .max_by(|a, b| a.seconds.total_cmp(&b.seconds))
}

/// Refuses `points` beyond `max` (the command's `--max-points`), before the first solve.
///
/// # Errors
/// More points than `max`, with the count and the flag that raises the bound.
pub fn check_points(what: &str, points: usize, max: usize) -> Result<()> {
    if points > max {
        bail!(
            "{what}: {points} points to solve, more than the bound of {max} (a preview solve takes tens of \
             milliseconds, a standard THD solve seconds: {points} points could take hours); narrow the range, or \
             raise the bound with --max-points {points}"
        );
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn outputs_never_overwrite_inputs_or_each_other() {
        let dir = tempfile::tempdir().unwrap();
        let case = dir.path().join("case.toml");
        std::fs::write(&case, "x").unwrap();
        let link = dir.path().join("link.toml");
        #[cfg(unix)]
        std::os::unix::fs::symlink(&case, &link).unwrap();
        let inputs = [("case file", case.as_path())];
        let e = check_outputs(&inputs, &[("--json", Some(&case))]).unwrap_err().to_string();
        assert!(e.contains("--json") && e.contains("never overwrites"), "{e}");
        #[cfg(unix)]
        assert!(check_outputs(&inputs, &[("--json", Some(&link))]).is_err());
        // The same new file by two spellings, and standard output twice.
        let a = dir.path().join("out.csv");
        let b = dir.path().join(".").join("out.csv");
        let e = check_outputs(&inputs, &[("--csv", Some(&a)), ("--jsonl", Some(&b))]).unwrap_err().to_string();
        assert!(e.contains("--csv and --jsonl"), "{e}");
        let dash = Path::new("-");
        assert!(check_outputs(&inputs, &[("--csv", Some(dash)), ("--jsonl", Some(dash))]).is_err());
        assert!(check_outputs(&inputs, &[("--csv", Some(dash)), ("--jsonl", Some(&a)), ("--vtu", None)]).is_ok());
    }

    #[test]
    fn points_are_bounded_with_the_flag_that_raises_the_bound() {
        assert!(check_points("sweep", 10_001, 10_000).unwrap_err().to_string().contains("--max-points 10001"));
        assert!(check_points("sweep", 10_000, 10_000).is_ok());
    }
}
