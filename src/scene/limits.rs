//! Design-limit checks ([`crate::bearing::solution::limits`]) as text in engineering units, for the results panel,
//! the bearing view and the command line's summary.

use crate::bearing::solution::limits::{Check, LimitKind};

use super::summary::sig4;

fn display(kind: LimitKind, x: f64) -> String {
    let (unit, scale) = kind.unit();
    let v = sig4(x * scale);
    if unit.is_empty() {
        v
    } else {
        format!("{v} {unit}")
    }
}

/// The checked value in display units (`—` when the solution does not have it).
#[must_use]
pub fn value_text(c: &Check) -> String {
    c.value.map_or_else(|| "—".into(), |v| display(c.kind, v))
}

/// `h_min 6.6 µm < limit 10 µm` for an exceeded check, `h_min 12 µm (≥ 10 µm)` otherwise.
#[must_use]
pub fn text(c: &Check) -> String {
    let (bad, ok) = if c.kind.is_minimum() { ("<", "≥") } else { (">", "≤") };
    let (value, limit) = (value_text(c), display(c.kind, c.limit));
    if c.exceeded {
        format!("{} {value} {bad} limit {limit}", c.kind.label())
    } else {
        format!("{} {value} ({ok} {limit})", c.kind.label())
    }
}
