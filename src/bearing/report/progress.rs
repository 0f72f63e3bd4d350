//! Stopping and pausing long solves. A superseded job is *cancelled* (an error: its result is not wanted);
//! a solve that must hand the thread back for now (the web build, at the end of a frame's time budget) is
//! *suspended* — a return value ([`Progress::Suspended`]) carrying what is needed to resume, never an error.

/// Something that can stop a solve (a superseded job) or ask it to hand its work back for now.
pub trait Cancel {
    /// Stop: the result is no longer wanted.
    fn cancelled(&self) -> bool;
    /// Pause at the next safe point (the web build, which has no threads, when a frame's time budget is
    /// spent). Only solves whose caller can resume them look at this.
    fn suspend(&self) -> bool {
        false
    }
}

/// Forwards cancellation but never suspends (solves whose caller cannot resume them).
pub struct NoSuspend<'a>(pub &'a dyn Cancel);
impl Cancel for NoSuspend<'_> {
    fn cancelled(&self) -> bool {
        self.0.cancelled()
    }
}

/// Suspends once a frame's time budget, counted from `start`, is spent (the web build); cancels when `inner`
/// does.
pub struct FrameBudget<'a> {
    inner: &'a dyn Cancel,
    start: web_time::Instant,
    budget_s: f64,
}

impl<'a> FrameBudget<'a> {
    #[must_use]
    pub fn new(inner: &'a dyn Cancel, start: web_time::Instant, budget_s: f64) -> Self {
        Self { inner, start, budget_s }
    }
}

impl Cancel for FrameBudget<'_> {
    fn cancelled(&self) -> bool {
        self.inner.cancelled()
    }
    fn suspend(&self) -> bool {
        self.start.elapsed().as_secs_f64() >= self.budget_s
    }
}

/// Never cancels.
pub struct NoCancel;
impl Cancel for NoCancel {
    fn cancelled(&self) -> bool {
        false
    }
}

/// A step of a resumable computation: finished, or paused with the state to resume from.
#[derive(Debug, Clone, PartialEq)]
pub enum Progress<T, R> {
    Done(T),
    Suspended(R),
}

impl<T, R> Progress<T, R> {
    /// The result, if finished.
    pub fn done(self) -> Option<T> {
        match self {
            Self::Done(t) => Some(t),
            Self::Suspended(_) => None,
        }
    }
}
