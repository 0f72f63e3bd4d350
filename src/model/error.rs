//! Errors raised while reading, overriding or validating a case.
//!
//! Every variant names the key (dotted path as written in the case file, e.g. `bearing.pads.preload`),
//! and where it makes sense the offending value and the allowed range, so a message can be shown next to
//! the field it concerns.

use serde::{Deserialize, Serialize};
use thiserror::Error;

/// A problem with a case file or with one of its values.
#[derive(Debug, Clone, PartialEq, Error, Serialize, Deserialize)]
pub enum CaseError {
    /// The text is not valid TOML.
    #[error("case file is not valid TOML: {message}")]
    Syntax { message: String },
    /// A key the schema does not know (often a typo or a missing unit suffix).
    #[error("unknown key `{key}`{}", hint_suffix(.hint))]
    UnknownKey { key: String, hint: String },
    /// A required key is absent.
    #[error("missing required key `{key}` ({meaning})")]
    MissingKey { key: String, meaning: String },
    /// A key holds a value of the wrong type (string where a number is expected, …).
    #[error("`{key}`: {message}")]
    WrongType { key: String, message: String },
    /// A number outside its physical or numerical range, NaN or infinite.
    #[error("`{key}` = {value} is out of range: allowed {allowed}")]
    OutOfRange { key: String, value: f64, allowed: String },
    /// Values that are each fine but contradict one another (overlapping pads, orifice outside its pad, …).
    #[error("`{key}`: {message}")]
    Inconsistent { key: String, message: String },
    /// The meshes would need more nodes than the budget `mesh.max_nodes` allows (refused before anything is
    /// allocated; see [`crate::model::budget`]).
    #[error(
        "`mesh.max_nodes`: the meshes would need {needed} nodes ({film} film nodes over all pads, pad {largest_pad} \
         alone {largest_pad_film}; {pad_solid} pad-solid nodes; {orifices} orifices), more than the budget of {budget}; \
         coarsen mesh.circumferential_elements, mesh.axial_elements or mesh.orifice_elements (each orifice is refined \
         with mesh.orifice_elements across its diameter), mesh.pad_radial_elements for the thermal model, use fewer \
         orifices, or raise mesh.max_nodes"
    )]
    NodeBudget {
        needed: usize,
        budget: usize,
        film: usize,
        pad_solid: usize,
        largest_pad: usize,
        largest_pad_film: usize,
        orifices: usize,
    },
    /// A `--set key=value` override that cannot be applied.
    #[error("override `{text}`: {message}")]
    BadOverride { text: String, message: String },
}

fn hint_suffix(hint: &str) -> String {
    if hint.is_empty() {
        String::new()
    } else {
        format!(" ({hint})")
    }
}

impl CaseError {
    /// The dotted key the error concerns, if any (used by the editor to flag the field in place).
    #[must_use]
    pub fn key(&self) -> Option<&str> {
        match self {
            Self::Syntax { .. } | Self::BadOverride { .. } => None,
            Self::UnknownKey { key, .. }
            | Self::MissingKey { key, .. }
            | Self::WrongType { key, .. }
            | Self::OutOfRange { key, .. }
            | Self::Inconsistent { key, .. } => Some(key),
            Self::NodeBudget { .. } => Some("mesh.max_nodes"),
        }
    }
}

/// Checks that `value` is finite and inside `[lo, hi]` (bounds inclusive unless stated by `open_lo`/`open_hi`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Range {
    pub lo: f64,
    pub hi: f64,
    pub open_lo: bool,
    pub open_hi: bool,
}

impl Range {
    pub const fn closed(lo: f64, hi: f64) -> Self {
        Self { lo, hi, open_lo: false, open_hi: false }
    }
    pub const fn positive(hi: f64) -> Self {
        Self { lo: 0.0, hi, open_lo: true, open_hi: false }
    }
    pub const fn open_lo(lo: f64, hi: f64) -> Self {
        Self { lo, hi, open_lo: true, open_hi: false }
    }
    pub const fn open(lo: f64, hi: f64) -> Self {
        Self { lo, hi, open_lo: true, open_hi: true }
    }

    /// The interval as validation messages and `tiltpad schema` write it, e.g. `(0, 10000]`.
    #[must_use]
    pub fn describe(&self) -> String {
        let l = if self.open_lo { "(" } else { "[" };
        let r = if self.open_hi { ")" } else { "]" };
        format!("{l}{}, {}{r}", fmt_bound(self.lo), fmt_bound(self.hi))
    }

    pub fn check(&self, key: &str, value: f64) -> Result<f64, CaseError> {
        let below = if self.open_lo { value <= self.lo } else { value < self.lo };
        let above = if self.open_hi { value >= self.hi } else { value > self.hi };
        if !value.is_finite() || below || above {
            return Err(CaseError::OutOfRange {
                key: key.to_string(),
                value,
                allowed: format!("a finite number in {}", self.describe()),
            });
        }
        Ok(value)
    }
}

fn fmt_bound(x: f64) -> String {
    if x.is_infinite() {
        if x > 0.0 {
            "inf".into()
        } else {
            "-inf".into()
        }
    } else {
        crate::number::csv(x)
    }
}
