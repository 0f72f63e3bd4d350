//! Ctrl-C on a long command: the first press asks the command to stop after the point it is solving (a
//! single long solve stops at its next safe point, through [`Interrupt`] as its [`Cancel`]); the command then
//! writes every point it finished, says how many and where they are, and exits with status 130
//! ([`Interrupted`]). A second press ends the process at once; rows already streamed stay in their
//! `.partial` files ([`crate::io::SafeFile`]).

use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::Mutex;

use web_time::Instant;

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
        with_state(|s| {
            s.command = format!("tiltpad {command}");
            s.started = Some(Instant::now());
        });
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

/// Safe points passed since the command started (an atomic of its own: every solver iteration counts one).
static SAFE_POINTS: AtomicU64 = AtomicU64::new(0);

/// A progress bar is drawn on the terminal (the heartbeat keeps quiet under it).
static BAR_SHOWN: AtomicBool = AtomicBool::new(false);

/// How far a command's points are: `done` of `total` `unit` (`points`, `speeds`, …).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Count {
    pub done: usize,
    pub total: usize,
    pub unit: &'static str,
}

/// What the heartbeat knows of the command, behind one lock.
struct Heartbeat {
    /// The command (`tiltpad sweep`), named while it has said nothing more precise.
    command: String,
    /// When the command started.
    started: Option<Instant>,
    /// What it is doing now ([`doing`]; empty: nothing said).
    doing: String,
    /// When [`doing`] was last called.
    doing_since: Option<Instant>,
    /// Its points done and to do ([`count`]; `None`: not a command over points, or between its phases).
    count: Option<Count>,
    /// When the last line of progress (or the command's start) was printed.
    last_line: Option<Instant>,
}

static STATE: Mutex<Heartbeat> = Mutex::new(Heartbeat {
    command: String::new(),
    started: None,
    doing: String::new(),
    doing_since: None,
    count: None,
    last_line: None,
});

/// Runs `f` on the heartbeat's state (a poisoned lock is taken as it is: the state is information only).
fn with_state<T>(f: impl FnOnce(&mut Heartbeat) -> T) -> T {
    let mut guard = STATE.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
    f(&mut guard)
}

/// Says what the command is doing now (e.g. `speed 3 of 10: eigen-solution of 3208 states, about 24 s`):
/// the heartbeat's `working:` line names it, with the time spent on it so far.
pub fn doing(what: impl Into<String>) {
    let what = what.into();
    with_state(|s| {
        s.doing = what;
        s.doing_since = Some(Instant::now());
    });
}

/// How many of the command's points are done ([`crate::cli`]'s progress display sets it at every point):
/// the heartbeat's `working:` line says it, so a long point still shows how far the command is. `None`
/// clears it.
pub fn count(count: Option<Count>) {
    with_state(|s| s.count = count);
}

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
/// (never a count of safe points that nothing passes); with the points done of those to do when the command
/// runs over points ([`count`]).
#[must_use]
pub fn heartbeat_line(command: &str, what: &str, since_s: f64, safe_points: u64, count: Option<Count>) -> String {
    let done = count.map_or(String::new(), |c| format!("{} of {} {} done, ", c.done, c.total, c.unit));
    if !what.is_empty() {
        format!("working: {what}; {done}{since_s:.0} s on it so far (Ctrl-C stops after it)")
    } else if safe_points > 0 {
        let done = count.map_or(String::new(), |c| format!("; {} of {} {} done", c.done, c.total, c.unit));
        format!(
            "working: {command}, safe point {safe_points} of the solver{done} (Ctrl-C stops after the point being \
             solved)"
        )
    } else {
        format!("working: {command}; {done}{since_s:.0} s so far (Ctrl-C stops after the point being solved)")
    }
}

/// A progress line was just printed: the next `working:` line waits [`HEARTBEAT_SECONDS`] from now.
pub fn line_printed() {
    with_state(|s| s.last_line = Some(Instant::now()));
}

/// Whether a progress bar is drawn (see [`BAR_SHOWN`]).
pub fn bar_shown(shown: bool) {
    BAR_SHOWN.store(shown, Ordering::Relaxed);
    line_printed();
}

/// The `working:` line when one is due (nothing printed for [`HEARTBEAT_SECONDS`]), read under one lock.
fn due_line() -> Option<String> {
    with_state(|s| {
        let due = s.last_line.is_some_and(|t| t.elapsed().as_secs_f64() >= HEARTBEAT_SECONDS);
        due.then(|| {
            let since = if s.doing.is_empty() { s.started } else { s.doing_since };
            let since = since.map_or(0.0, |t| t.elapsed().as_secs_f64());
            heartbeat_line(&s.command, &s.doing, since, SAFE_POINTS.load(Ordering::Relaxed), s.count)
        })
    })
}

/// The heartbeat: a command that has printed nothing for [`HEARTBEAT_SECONDS`] (building a large mesh, a
/// long single solve, a first point that takes minutes) prints a `working:` line ([`heartbeat_line`]) and
/// again every [`HEARTBEAT_SECONDS`], so a run watched through a pipe or a log never looks hung; the line is
/// information only, no outcome depends on it. A thread of its own, which sleeps between checks and ends with
/// the process.
fn start_heartbeat() {
    line_printed();
    let spawned = std::thread::Builder::new().name("heartbeat".into()).spawn(|| loop {
        std::thread::sleep(std::time::Duration::from_millis(500));
        if BAR_SHOWN.load(Ordering::Relaxed) {
            continue;
        }
        if let Some(line) = due_line() {
            eprintln!("{line}");
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
    use super::{heartbeat_line, Count};

    #[test]
    fn the_heartbeat_names_what_runs_and_never_counts_safe_points_that_nothing_passes() {
        // A command that said what it does (a critical-speed map's eigen-solutions, a bench section).
        let line = heartbeat_line("tiltpad rotor", "critical-speed map: 81 undamped eigen-solutions", 12.4, 0, None);
        assert_eq!(
            line,
            "working: critical-speed map: 81 undamped eigen-solutions; 12 s on it so far (Ctrl-C stops after it)"
        );
        // A long single solve: its safe points.
        let line = heartbeat_line("tiltpad solve", "", 7.0, 42, None);
        assert!(line.contains("tiltpad solve, safe point 42 of the solver"), "{line}");
        // Work that passes no safe point of the solver (a map's cold solves, a critical-speed map): the command
        // and its time, not "safe point 0".
        let line = heartbeat_line("tiltpad convergence-map", "", 31.0, 0, None);
        assert_eq!(line, "working: tiltpad convergence-map; 31 s so far (Ctrl-C stops after the point being solved)");
        assert!(!line.contains("safe point"), "{line}");
    }

    #[test]
    fn the_heartbeat_of_a_command_over_points_says_how_many_are_done() {
        let count = Some(Count { done: 17, total: 288, unit: "points" });
        // the convergence map names the bearing it maps, and how far the whole map is
        let line =
            heartbeat_line("tiltpad convergence-map", "convergence map: bearing someya-4pad-lbp", 31.0, 0, count);
        assert_eq!(
            line,
            "working: convergence map: bearing someya-4pad-lbp; 17 of 288 points done, 31 s on it so far (Ctrl-C \
             stops after it)"
        );
        // a sweep's long point: the solver's safe points and the points done
        let count = Some(Count { done: 2, total: 400, unit: "points" });
        let line = heartbeat_line("tiltpad sweep", "", 9.0, 120, count);
        assert!(line.contains("safe point 120 of the solver; 2 of 400 points done"), "{line}");
        let line = heartbeat_line("tiltpad batch", "", 9.0, 0, Some(Count { done: 0, total: 12, unit: "designs" }));
        assert!(line.contains("tiltpad batch; 0 of 12 designs done, 9 s so far"), "{line}");
    }
}
