//! Ctrl-C on a long command: the first press asks the command to stop after the point it is solving (a
//! single long solve stops at its next safe point, through [`Interrupt`] as its [`Cancel`]); the command then
//! writes every point it finished, says how many and where they are, and exits with status 130
//! ([`Interrupted`]). A second press ends the process at once; rows already streamed stay in their
//! `.partial` files ([`crate::io::SafeFile`]).

use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};

use crate::bearing::Cancel;

/// Set by the Ctrl-C handler.
static REQUESTED: AtomicBool = AtomicBool::new(false);

/// Exit status of an interrupted command (128 + SIGINT, what shells report for Ctrl-C).
pub const EXIT_STATUS: i32 = 130;

/// Installs the handler (once per process; a second call does nothing). `command`: what the heartbeat names
/// while the command has said nothing more precise ([`doing`], [`say`]).
pub fn install(command: &str) {
    static INSTALLED: std::sync::Once = std::sync::Once::new();
    INSTALLED.call_once(|| {
        if let Ok(mut c) = COMMAND.lock() {
            *c = format!("tiltpad {command}");
        }
        if let Ok(mut t) = STARTED.lock() {
            *t = Some(web_time::Instant::now());
        }
        start_heartbeat();
        let installed = ctrlc::set_handler(|| {
            if REQUESTED.swap(true, Ordering::SeqCst) {
                eprintln!("\ninterrupted again: stopping now (rows already written stay in their .partial files)");
                std::process::exit(EXIT_STATUS);
            }
            eprintln!(
                "\ninterrupt: finishing the current point, then writing what is solved (Ctrl-C again to quit now)"
            );
        });
        if let Err(e) = installed {
            eprintln!("note: Ctrl-C will end the command without writing its results ({e})");
        }
    });
}

/// Whether Ctrl-C was pressed.
#[must_use]
pub fn requested() -> bool {
    REQUESTED.load(Ordering::SeqCst)
}

/// A [`Cancel`] that stops a solve when Ctrl-C was pressed. Every solve of the command line asks it at each
/// of its safe points (an equilibrium iteration, an outer thermal iteration, a fallback step); it counts
/// them for the heartbeat ([`install`]).
pub struct Interrupt;

impl Cancel for Interrupt {
    fn cancelled(&self) -> bool {
        SAFE_POINTS.fetch_add(1, Ordering::Relaxed);
        requested()
    }
}

/// Seconds without a line on standard error after which the heartbeat prints `working: …`.
pub const HEARTBEAT_SECONDS: f64 = 5.0;

/// Safe points passed since the command started.
static SAFE_POINTS: AtomicU64 = AtomicU64::new(0);

/// What the command is doing now, for the heartbeat (set by [`doing`]; empty: the solver's safe points).
static DOING: std::sync::Mutex<String> = std::sync::Mutex::new(String::new());

/// Says what the command is doing now (e.g. `speed 3 of 10: eigen-solution of 3208 states, about 24 s`):
/// the heartbeat's `working:` line names it, with the time spent on it so far.
pub fn doing(what: impl Into<String>) {
    if let Ok(mut d) = DOING.lock() {
        *d = what.into();
    }
    if let Ok(mut t) = DOING_SINCE.lock() {
        *t = Some(web_time::Instant::now());
    }
}

/// When [`doing`] was last called.
static DOING_SINCE: std::sync::Mutex<Option<web_time::Instant>> = std::sync::Mutex::new(None);

/// The command running and when it started ([`install`]).
static COMMAND: std::sync::Mutex<String> = std::sync::Mutex::new(String::new());
static STARTED: std::sync::Mutex<Option<web_time::Instant>> = std::sync::Mutex::new(None);

/// A progress line of the command's own (e.g. `bench: rotor`): printed on standard error, and named by the
/// heartbeat's `working:` lines until the next one.
pub fn say(line: impl Into<String>) {
    let line = line.into();
    eprintln!("{line}");
    doing(line);
    line_printed();
}

/// The heartbeat's line: what the command said it is doing ([`doing`], [`say`]) and for how long; else the
/// solver's safe points when a solve asks for them ([`Interrupt`]); else the command and its time so far
/// (never a count of safe points that nothing passes).
#[must_use]
pub fn heartbeat_line(command: &str, what: &str, since_s: f64, safe_points: u64) -> String {
    if !what.is_empty() {
        format!("working: {what}; {since_s:.0} s on it so far (Ctrl-C stops after it)")
    } else if safe_points > 0 {
        format!(
            "working: {command}, safe point {safe_points} of the solver (Ctrl-C stops after the point being solved)"
        )
    } else {
        format!("working: {command}; {since_s:.0} s so far (Ctrl-C stops after the point being solved)")
    }
}

/// A progress bar is drawn on the terminal (the heartbeat keeps quiet under it).
static BAR_SHOWN: AtomicBool = AtomicBool::new(false);

/// When the last line of progress (or the command's start) was.
static LAST_LINE: std::sync::Mutex<Option<web_time::Instant>> = std::sync::Mutex::new(None);

/// A progress line was just printed: the next `working:` line waits [`HEARTBEAT_SECONDS`] from now.
pub fn line_printed() {
    if let Ok(mut last) = LAST_LINE.lock() {
        *last = Some(web_time::Instant::now());
    }
}

/// Whether a progress bar is drawn (see [`BAR_SHOWN`]).
pub fn bar_shown(shown: bool) {
    BAR_SHOWN.store(shown, Ordering::Relaxed);
    line_printed();
}

/// The heartbeat: a command that has printed nothing for [`HEARTBEAT_SECONDS`] (building a large mesh, a
/// long single solve, a first point that takes minutes) prints a `working:` line ([`heartbeat_line`]) and
/// again every [`HEARTBEAT_SECONDS`], so a run watched through a pipe or a log never looks hung; the line is
/// information only, no outcome depends on it. A thread of its own, which sleeps between checks and ends with the process.
fn start_heartbeat() {
    line_printed();
    let spawned = std::thread::Builder::new().name("heartbeat".into()).spawn(|| loop {
        std::thread::sleep(std::time::Duration::from_millis(500));
        if BAR_SHOWN.load(Ordering::Relaxed) {
            continue;
        }
        let due =
            LAST_LINE.lock().ok().and_then(|l| *l).is_some_and(|t| t.elapsed().as_secs_f64() >= HEARTBEAT_SECONDS);
        if due {
            let what = DOING.lock().map(|d| d.clone()).unwrap_or_default();
            let since = if what.is_empty() { &STARTED } else { &DOING_SINCE };
            let since = since.lock().ok().and_then(|t| *t).map_or(0.0, |t| t.elapsed().as_secs_f64());
            let command = COMMAND.lock().map(|c| c.clone()).unwrap_or_default();
            eprintln!("{}", heartbeat_line(&command, &what, since, SAFE_POINTS.load(Ordering::Relaxed)));
            line_printed();
        }
    });
    if let Err(e) = spawned {
        eprintln!("note: no heartbeat on standard error ({e})");
    }
}

/// A command stopped by Ctrl-C after writing what it had solved (`main` exits with [`EXIT_STATUS`]).
#[derive(Debug, thiserror::Error)]
#[error("interrupted (Ctrl-C) after {done} of {of} {what}; {kept}")]
pub struct Interrupted {
    /// Points finished.
    pub done: usize,
    /// Points asked for.
    pub of: usize,
    /// What a point is (`points`, `speeds`, …).
    pub what: &'static str,
    /// Where the finished points are (or that there were none).
    pub kept: String,
}

impl Interrupted {
    /// The error for `done` of `of` points whose results went to `outputs` (empty: nothing written).
    #[must_use]
    pub fn new(done: usize, of: usize, what: &'static str, outputs: &[&std::path::Path]) -> Self {
        let names: Vec<String> = outputs
            .iter()
            .map(|p| if p.as_os_str() == "-" { "standard output".to_string() } else { p.display().to_string() })
            .collect();
        let kept = if done == 0 || names.is_empty() {
            "nothing was solved to write".to_string()
        } else {
            format!("their results are in {}", names.join(" and "))
        };
        Self { done, of, what, kept }
    }
}

#[cfg(test)]
mod tests {
    use super::heartbeat_line;

    #[test]
    fn the_heartbeat_names_what_runs_and_never_counts_safe_points_that_nothing_passes() {
        // A command that said what it does (a critical-speed map's eigen-solutions, a bench section).
        let line = heartbeat_line("tiltpad rotor", "critical-speed map: 81 undamped eigen-solutions", 12.4, 0);
        assert_eq!(
            line,
            "working: critical-speed map: 81 undamped eigen-solutions; 12 s on it so far (Ctrl-C stops after it)"
        );
        // A long single solve: its safe points.
        let line = heartbeat_line("tiltpad solve", "", 7.0, 42);
        assert!(line.contains("tiltpad solve, safe point 42 of the solver"), "{line}");
        // Work that passes no safe point of the solver (a map's cold solves, a bench section): the command and
        // its time, not "safe point 0".
        let line = heartbeat_line("tiltpad bench", "", 31.0, 0);
        assert_eq!(line, "working: tiltpad bench; 31 s so far (Ctrl-C stops after the point being solved)");
        assert!(!line.contains("safe point"), "{line}");
    }
}
