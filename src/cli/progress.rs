//! The progress of a long command on standard error: indicatif's bar on a terminal; elsewhere (a pipe, a
//! log file, a batch job) a plain line per finished point, at most one a second, so that a run watched
//! through a pipe shows it is working. Either way the heartbeat's `working:` lines during a long point say
//! how many points are done of how many ([`super::interrupt::count`]).

use std::io::IsTerminal as _;

use indicatif::{ProgressBar, ProgressStyle};
use web_time::Instant;

/// A progress display over `len` points (see the module).
pub struct Progress {
    bar: Option<ProgressBar>,
    pos: u64,
    len: u64,
    /// What a point is (`points`, `speeds`, …), for the heartbeat.
    unit: &'static str,
    message: String,
    last_line: Option<Instant>,
}

impl Progress {
    /// A display over `len` points (each one `unit`: `points`, `speeds`, …): a bar on a terminal, lines
    /// otherwise.
    #[must_use]
    pub fn new(len: usize, unit: &'static str) -> Self {
        let bar = std::io::stderr().is_terminal().then(|| {
            let pb = ProgressBar::new(len as u64);
            pb.set_style(
                ProgressStyle::with_template("{bar:40} {pos}/{len} {elapsed_precise} eta {eta} {msg}")
                    .unwrap_or_else(|_| ProgressStyle::default_bar()),
            );
            // the elapsed time keeps moving through a long point (a large rotor's eigen-solution)
            pb.enable_steady_tick(std::time::Duration::from_millis(500));
            pb
        });
        super::interrupt::bar_shown(bar.is_some());
        let p = Self { bar, pos: 0, len: len as u64, unit, message: String::new(), last_line: None };
        p.count();
        p
    }

    /// Tells the heartbeat how far the points are.
    fn count(&self) {
        #[allow(clippy::cast_possible_truncation)]
        let (done, total) = (self.pos as usize, self.len as usize);
        super::interrupt::count(Some(super::interrupt::Count { done, total, unit: self.unit }));
    }

    fn line(&mut self) {
        if self.bar.is_some() {
            return;
        }
        let due = self.last_line.is_none_or(|t| t.elapsed().as_secs_f64() >= 1.0) || self.pos == self.len;
        if due && self.pos > 0 {
            eprintln!("progress: {}/{} {}", self.pos, self.len, self.message);
            super::interrupt::line_printed();
            self.last_line = Some(Instant::now());
        }
    }

    /// What is being solved now.
    pub fn set_message(&mut self, message: impl Into<String>) {
        self.message = message.into();
        if let Some(b) = &self.bar {
            b.set_message(self.message.clone());
        }
    }

    /// One more point done.
    pub fn inc(&mut self, n: u64) {
        self.set_position(self.pos + n);
    }

    /// `pos` points done.
    pub fn set_position(&mut self, pos: u64) {
        self.pos = pos;
        if let Some(b) = &self.bar {
            b.set_position(pos);
        }
        self.count();
        self.line();
    }

    /// More points than planned (a refined band).
    pub fn inc_length(&mut self, n: u64) {
        self.len += n;
        if let Some(b) = &self.bar {
            b.inc_length(n);
        }
        self.count();
    }

    /// A line above the bar.
    pub fn println(&self, text: impl AsRef<str>) {
        match &self.bar {
            Some(b) => b.println(text.as_ref()),
            None => eprintln!("{}", text.as_ref()),
        }
    }

    /// Removes the bar (and the count from the heartbeat).
    pub fn finish_and_clear(&self) {
        if let Some(b) = &self.bar {
            b.finish_and_clear();
        }
        super::interrupt::count(None);
        super::interrupt::bar_shown(false);
    }
}
