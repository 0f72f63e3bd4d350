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

/// Installs the handler (once per process; a second call does nothing).
pub fn install() {
    static INSTALLED: std::sync::Once = std::sync::Once::new();
    INSTALLED.call_once(|| {
        line_printed();
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
/// of its safe points (an equilibrium iteration, an outer thermal iteration, a fallback step), so it also
/// keeps a long single solve from looking hung: once a solve has run [`HEARTBEAT_SECONDS`] without a line on
/// standard error, it prints `working: safe point N` (N counts the safe points since the command started, the
/// same for the same input on any machine) and again every [`HEARTBEAT_SECONDS`].
pub struct Interrupt;

impl Cancel for Interrupt {
    fn cancelled(&self) -> bool {
        heartbeat();
        requested()
    }
}

/// Seconds between two `working:` lines of a long solve.
pub const HEARTBEAT_SECONDS: f64 = 5.0;

/// Safe points passed since the command started.
static SAFE_POINTS: AtomicU64 = AtomicU64::new(0);

/// When the last `working:` line (or the command's start) was.
static LAST_LINE: std::sync::Mutex<Option<web_time::Instant>> = std::sync::Mutex::new(None);

/// A progress line was just printed: the next `working:` line waits [`HEARTBEAT_SECONDS`] from now.
pub fn line_printed() {
    if let Ok(mut last) = LAST_LINE.lock() {
        *last = Some(web_time::Instant::now());
    }
}

fn heartbeat() {
    let n = SAFE_POINTS.fetch_add(1, Ordering::Relaxed) + 1;
    let Ok(mut last) = LAST_LINE.lock() else { return };
    let now = web_time::Instant::now();
    match *last {
        None => *last = Some(now),
        Some(t) if now.duration_since(t).as_secs_f64() >= HEARTBEAT_SECONDS => {
            eprintln!("working: safe point {n} of the solve (Ctrl-C stops it)");
            *last = Some(now);
        }
        Some(_) => {}
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
