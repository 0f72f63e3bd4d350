//! What every solve hands back besides its result: the report of the work done ([`SolveReport`]), the typed
//! errors ([`error::SolveError`]) and warnings ([`warning::Warning`]) it can end with, and the contract by
//! which a caller cancels or suspends a solve ([`progress::Cancel`], [`progress::Progress`]). Nothing here
//! imports any other part of the bearing.

pub mod error;
pub mod progress;
pub mod solve_report;
pub mod warning;

pub use solve_report::SolveReport;
