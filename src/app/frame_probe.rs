//! Frame probe for the web build: with `?probe` in the page address the app repaints continuously and logs
//! to the browser console, every [`FRAMES_PER_REPORT`] frames and whenever the job under way changes, the
//! 50th and 95th percentiles and the maximum of
//! - the frame interval (time between two consecutive frames: what the user sees, including egui's
//!   tessellation and the browser's painting), and
//! - the frame's work (time spent inside the app's `ui`, the solver's per-frame budget included),
//!
//! with the job (idle, isothermal or THD solve and its stage, sweep, pin re-solve). Percentiles are by
//! nearest rank. It also logs two start-up milestones, in milliseconds since the page began loading (the
//! browser's clock, which includes downloading and compiling the program): the first frame drawn and the
//! first frame that shows a solution of the edited case. Frame times are measured here, never asserted in tests (docs/PERFORMANCE.md has them).

use std::fmt;

use web_time::Instant;

use crate::bearing::stages::StageId;
use crate::units::MS;

/// Frames per console line while one job lasts.
pub const FRAMES_PER_REPORT: usize = 60;

/// What the app is doing in a frame.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Job {
    Idle,
    /// Solving the edited case: THD or isothermal, the stage under way.
    Solve {
        thd: bool,
        stage: Option<StageId>,
    },
    /// The sweep view's points.
    Sweep,
    /// Re-solving a pinned case.
    Pin,
    /// The rotor view's analysis.
    Rotor,
    /// The Control view's sweep or its loop closed again.
    Control,
}

impl fmt::Display for Job {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Idle => write!(f, "idle"),
            Self::Solve { thd, stage } => {
                write!(f, "{} solve", if *thd { "THD" } else { "isothermal" })?;
                stage.map_or(Ok(()), |s| write!(f, " ({})", s.label()))
            }
            Self::Sweep => write!(f, "sweep"),
            Self::Rotor => write!(f, "rotor analysis"),
            Self::Control => write!(f, "closed-loop analysis"),
            Self::Pin => write!(f, "pin re-solve"),
        }
    }
}

/// Statistics of a run of frames of one job [s].
#[derive(Debug, Clone, PartialEq)]
pub struct Summary {
    pub job: Job,
    pub frames: usize,
    pub interval_p50_s: f64,
    pub interval_p95_s: f64,
    pub interval_max_s: f64,
    pub work_p95_s: f64,
    pub work_max_s: f64,
}

impl fmt::Display for Summary {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "frame probe: {} — {} frames, interval p50 {:.1} ms, p95 {:.1} ms, max {:.1} ms; work p95 {:.1} ms, max {:.1} ms",
            self.job,
            self.frames,
            MS.from_si(self.interval_p50_s),
            MS.from_si(self.interval_p95_s),
            MS.from_si(self.interval_max_s),
            MS.from_si(self.work_p95_s),
            MS.from_si(self.work_max_s)
        )
    }
}

/// Collects frame times and summarises them per job.
#[derive(Debug, Default)]
pub struct FrameProbe {
    last: Option<Instant>,
    job: Option<Job>,
    /// (interval, work) of the frames of the current job since the last summary [s].
    frames: Vec<(f64, f64)>,
    /// The start-up milestones already logged: the first frame, the first solution shown.
    first_frame_seen: bool,
    first_solution_seen: bool,
}

impl FrameProbe {
    /// A probe when the page's query string has a `probe` key (`?probe`, `?case=x&probe=1`).
    #[must_use]
    pub fn from_query(query: &str) -> Option<Self> {
        query.trim_start_matches('?').split('&').any(|kv| kv.split('=').next() == Some("probe")).then(Self::default)
    }

    /// Records a frame that started at `now`, spent `work_s` in the app and ran `job`; returns a summary when
    /// one is due (the job changed, or [`FRAMES_PER_REPORT`] frames of it were collected).
    pub fn frame(&mut self, now: Instant, work_s: f64, job: Job) -> Option<Summary> {
        let interval = self.last.map(|t| now.duration_since(t).as_secs_f64());
        self.last = Some(now);
        let changed = self.job.is_some_and(|j| j != job);
        let summary = if changed { self.summarise() } else { None };
        self.job = Some(job);
        // The first frame has no interval; after a change the interval belongs to the new job.
        if let Some(dt) = interval {
            self.frames.push((dt, work_s));
        }
        summary.or_else(|| (self.frames.len() >= FRAMES_PER_REPORT).then(|| self.summarise()).flatten())
    }

    /// The start-up milestones this frame reaches, as console lines: the first frame (at `page_ms` since the
    /// page began loading, its own work `work_s`) and the first frame with a solution shown.
    pub fn milestones(&mut self, page_ms: f64, work_s: f64, solution_shown: bool) -> Vec<String> {
        let mut lines = Vec::new();
        if !self.first_frame_seen {
            self.first_frame_seen = true;
            lines.push(format!(
                "start-up: first frame at {page_ms:.0} ms after the page began loading (the frame's work {:.0} ms)",
                MS.from_si(work_s)
            ));
        }
        if solution_shown && !self.first_solution_seen {
            self.first_solution_seen = true;
            lines.push(format!("start-up: first solution shown at {page_ms:.0} ms after the page began loading"));
        }
        lines
    }

    /// The summary of the frames collected for the current job (emptied), if any.
    fn summarise(&mut self) -> Option<Summary> {
        let job = self.job?;
        if self.frames.is_empty() {
            return None;
        }
        let mut intervals: Vec<f64> = self.frames.iter().map(|f| f.0).collect();
        let mut work: Vec<f64> = self.frames.iter().map(|f| f.1).collect();
        intervals.sort_by(f64::total_cmp);
        work.sort_by(f64::total_cmp);
        self.frames.clear();
        Some(Summary {
            job,
            frames: intervals.len(),
            interval_p50_s: percentile(&intervals, 0.5),
            interval_p95_s: percentile(&intervals, 0.95),
            interval_max_s: intervals[intervals.len() - 1],
            work_p95_s: percentile(&work, 0.95),
            work_max_s: work[work.len() - 1],
        })
    }
}

/// Nearest-rank percentile of sorted, non-empty values (`p` in (0, 1]).
fn percentile(sorted: &[f64], p: f64) -> f64 {
    #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss, clippy::cast_precision_loss)]
    let rank = (p * sorted.len() as f64).ceil() as usize;
    sorted[rank.clamp(1, sorted.len()) - 1]
}

#[cfg(test)]
mod tests {
    use std::time::Duration;

    use super::*;

    #[test]
    fn the_query_string_turns_the_probe_on() {
        assert!(FrameProbe::from_query("?probe").is_some());
        assert!(FrameProbe::from_query("?case=fillon-a&probe=1").is_some());
        assert!(FrameProbe::from_query("?case=probe").is_none());
        assert!(FrameProbe::from_query("").is_none());
    }

    #[test]
    fn nearest_rank_percentiles() {
        let v: Vec<f64> = (1..=20).map(f64::from).collect();
        assert_eq!(percentile(&v, 0.5), 10.0);
        assert_eq!(percentile(&v, 0.95), 19.0);
        assert_eq!(percentile(&v, 1.0), 20.0);
        assert_eq!(percentile(&[3.0], 0.5), 3.0);
    }

    /// Each milestone is logged once: the first frame at once, the first solution when one is shown.
    #[test]
    fn start_up_milestones_are_logged_once() {
        let mut probe = FrameProbe::default();
        let first = probe.milestones(812.4, 0.2504, false);
        assert_eq!(first, ["start-up: first frame at 812 ms after the page began loading (the frame's work 250 ms)"]);
        assert!(probe.milestones(900.0, 0.01, false).is_empty());
        assert_eq!(
            probe.milestones(1500.6, 0.01, true),
            ["start-up: first solution shown at 1501 ms after the page began loading"]
        );
        assert!(probe.milestones(1600.0, 0.01, true).is_empty());
    }

    /// Frames 1..=n ms apart: a summary per job change and per FRAMES_PER_REPORT frames.
    #[test]
    fn frames_are_summarised_per_job_and_per_report_length() {
        let mut probe = FrameProbe::default();
        let t0 = Instant::now();
        let solve = Job::Solve { thd: true, stage: Some(StageId::Equilibrium) };
        let mut t = t0;
        // Idle: first frame (no interval), then intervals of 1, 2, …, 10 ms.
        assert!(probe.frame(t, 0.001, Job::Idle).is_none());
        for ms in 1..=10 {
            t += Duration::from_millis(ms);
            assert!(probe.frame(t, 0.001, Job::Idle).is_none());
        }
        // The job changes: the idle frames are summarised.
        t += Duration::from_millis(40);
        let idle = probe.frame(t, 0.030, solve).unwrap();
        assert_eq!((idle.job, idle.frames), (Job::Idle, 10));
        assert!((idle.interval_p50_s - 0.005).abs() < 1e-9, "{idle}");
        assert!((idle.interval_p95_s - 0.010).abs() < 1e-9);
        assert!((idle.interval_max_s - 0.010).abs() < 1e-9);
        // The solve's first interval (40 ms) is the solve's; its 60th frame closes a summary.
        for _ in 0..FRAMES_PER_REPORT - 2 {
            t += Duration::from_millis(20);
            assert!(probe.frame(t, 0.012, solve).is_none());
        }
        t += Duration::from_millis(20);
        let s = probe.frame(t, 0.012, solve).unwrap();
        assert_eq!((s.job, s.frames), (solve, FRAMES_PER_REPORT));
        assert!((s.interval_p50_s - 0.020).abs() < 1e-9 && (s.interval_max_s - 0.040).abs() < 1e-9);
        assert!((s.work_max_s - 0.030).abs() < 1e-12 && (s.work_p95_s - 0.012).abs() < 1e-12);
        assert!(s.to_string().contains("THD solve (equilibrium"), "{s}");
    }
}
