//! Studies: many solves of one base case, each with some case keys changed — a sweep over a grid of any
//! keys ([`grid`]), or a design-space batch read from a table ([`designs`]) — and the table of results,
//! one row per point ([`columns`], [`run`]); and reduced coefficients sampled over a speed band for a
//! rotordynamics code that interpolates them ([`band`]).
//!
//! Contract: a study never stops at a bad point. Each point yields a [`Row`] holding either the output
//! columns (SI or engineering units, the unit in each column name; empty where a quantity does not exist,
//! such as temperatures of an isothermal solve) or the error that point met (an invalid value, a
//! touchdown, a non-converged solve). Rows come out one at a time, in order, so a caller can write each
//! as it completes. No I/O and no GUI here: the command line (`tiltpad sweep`, `tiltpad batch`) drives
//! it, and the workbench's "any input against any output" sweep can reuse it. [`convergence`] is the
//! equilibrium's convergence map over load direction and magnitude; [`fidelity`] the time and error of each
//! fidelity level of a case against a finer solve.
//!
//! Determinism: with warm starts off (batches), a row depends only on the base case and its own
//! overrides, so a batch split into shards gives the same rows as one run; only the `seconds` column (wall
//! time) differs between runs.

pub mod band;
pub mod columns;
pub mod convergence;
pub mod designs;
pub mod equilibrium_work;
pub mod estimate;
pub mod fidelity;
pub mod grid;
pub mod rotor_cost;
pub mod run;

pub use columns::{Column, COLUMNS};
pub use designs::{Designs, Shard};
pub use grid::Axis;
pub use run::{PointError, Row, Runner};

use thiserror::Error;

/// A study that cannot start (its description is wrong); errors of single points are in their [`Row`].
#[derive(Debug, Clone, PartialEq, Error)]
pub enum StudyError {
    #[error("`--vary {spec}`: {message}")]
    BadAxis { spec: String, message: String },
    #[error("designs table, line {line}: {message}")]
    BadDesigns { line: usize, message: String },
    #[error("`--shard {spec}`: {message}")]
    BadShard { spec: String, message: String },
}
