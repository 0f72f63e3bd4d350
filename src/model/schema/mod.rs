//! The case keys, one table: one row per key, the single place a key's unit, allowed values, default,
//! meaning and editor row are written.
//!
//! Everything else reads the row:
//! - validation ([`super::resolve`]) checks a value against the row's range, takes the row's default when the
//!   key is absent and converts with the row's [`Unit`](crate::units::Unit) (`key!("thermal.carry_over").value(t.carry_over)?`);
//! - `tiltpad schema` prints the table ([`text_table`], [`json_table`]);
//! - the workbench's editor draws every row that has an [`Editor`] in its [`Group`], with the row's label,
//!   widget, unit, tooltip (meaning, typical and allowed values) and default, and writes the value back under
//!   the row's key (as `--set` does); only the [`Widget::Custom`] rows have code of their own there.
//!
//! Rows live in one file per part of the case file (`bearing.rs`, `running.rs`, `numerics.rs`, `thermal.rs`,
//! `feeding.rs`, `hydraulics.rs`, `limits.rs`), in the order the editor shows them; [`KEYS`] joins them. Keys inside arrays
//! of tables are written with `[]` (`bearing.pads.orifice[].diameter_mm`); a per-pad override
//! `bearing.pad.<i>.<name>` takes the row of `bearing.pads.<name>` ([`spec`] maps both).
//!
//! # Adding a key
//! **A tuning key** (a number one part of the solver reads as it is: an iteration budget, a tolerance) is
//! one row, marked `.tuning()`, plus the physics that reads it. The THD loop's iteration budget, in
//! `thermal.rs`:
//! ```text
//! Key::integer("thermal.max_iterations", COUNT, 10, 100_000)
//!     .typical(100.0, 1000.0)
//!     .default(Fallback::Count(300))
//!     .tuning()
//!     .edit(Thermal, "Iteration budget", Optional(0))
//!     .when(thd)
//!     .meaning("Outer iterations the THD loop may take … raise it there."),
//! ```
//! and where the loop's settings are built, `case.tuning.count(key!("thermal.max_iterations"))`. The range
//! check and its error message (`` `thermal.max_iterations` = 5 is out of range: allowed an integer in [10,
//! 100000] ``), the default, the unit conversion, the file format, the `tiltpad schema` entry and the editor
//! row (checkbox, drag value, tooltip, shown with the thermal model only) follow from the row
//! ([`crate::model::tuning`] says where tuning keys may live and which stages read them).
//!
//! **A key that changes what the model is** (a geometry, a choice of model, anything a film mesh or a pad
//! solid depends on) also gets typed fields, so that every solver stage must decide whether it reads it:
//! 1. the row, as above without `.tuning()`;
//! 2. its field in the serde table of [`super::file`] (`pub carry_over: Option<f64>`, with its neighbours'
//!    serde attributes);
//! 3. its field in the SI case ([`super::case`]) and one line in [`super::resolve`] that takes range,
//!    default and unit from the row: `carry_over: key!("thermal.carry_over").value(t.carry_over)?`;
//! 4. the physics that reads it; the stages destructure the case structs without `..`, so the new field is a
//!    compile error in each stage's inputs until it is named there.
//!
//! Steps 2 and 3 are declarations the compiler checks (`key!` finds the row while building); what a key is
//! — its unit, range, default, meaning and editor row — is written once, in its row.
//!
//! A unit test sets every numeric key just outside its range and checks that validation rejects it with the
//! row's interval, and that every row's default lies inside its range; another checks that every key a shipped
//! case writes has a row and that the editor reads and writes every editor row's key.

mod bearing;
mod feeding;
mod hydraulics;
mod limits;
mod numerics;
mod row;
mod running;
mod thermal;

use std::fmt::Write as _;

use super::error::Range;

pub use row::{Allowed, Editor, Fallback, Group, KeySpec, Widget};

pub use bearing::MAX_CLEARANCE_RATIO;
pub use feeding::GROOVE_CARRY_OVER;
pub use numerics::{DEFAULT_MAX_NODES, MAX_TOUCHDOWN_RATIO, MAX_TRANSITION_REYNOLDS};

/// Temperatures [°C]: from arctic start-up to well above any oil's flash point.
const TEMPERATURE: Range = Range::closed(-60.0, 400.0);
/// Angles [°] from +x: ten turns either way.
const ANGLE: Range = Range::closed(-3600.0, 3600.0);

// ------------------------------------------------------------------------------------------ the table

/// Every case key, in the order the editor shows them (and `tiltpad schema` prints them).
pub const KEYS: &[KeySpec] = &join::<{ COUNT }>(PARTS);

const PARTS: &[&[KeySpec]] =
    &[bearing::KEYS, running::KEYS, numerics::KEYS, thermal::KEYS, feeding::KEYS, hydraulics::KEYS, limits::KEYS];
const COUNT: usize = {
    let mut n = 0;
    let mut i = 0;
    while i < PARTS.len() {
        n += PARTS[i].len();
        i += 1;
    }
    n
};

/// The rows of `parts`, one after another.
const fn join<const N: usize>(parts: &[&[KeySpec]]) -> [KeySpec; N] {
    let mut out = [parts[0][0]; N];
    let (mut i, mut k) = (0, 0);
    while i < parts.len() {
        let mut j = 0;
        while j < parts[i].len() {
            out[k] = parts[i][j];
            k += 1;
            j += 1;
        }
        i += 1;
    }
    out
}

/// The row of `key` (its exact row key, `[]` for array entries), found while compiling: a key that has no
/// row fails the build (`cargo build`, `cargo test`; `cargo check` does not evaluate constants). Use it
/// through [`key!`](crate::key).
#[must_use]
pub const fn row(key: &str) -> &'static KeySpec {
    let mut i = 0;
    while i < KEYS.len() {
        if same_text(KEYS[i].key, key) {
            return &KEYS[i];
        }
        i += 1;
    }
    panic!("no row in model::schema::KEYS for this key")
}

/// `a == b`, while compiling.
pub(crate) const fn same_text(a: &str, b: &str) -> bool {
    let (a, b) = (a.as_bytes(), b.as_bytes());
    if a.len() != b.len() {
        return false;
    }
    let mut i = 0;
    while i < a.len() {
        if a[i] != b[i] {
            return false;
        }
        i += 1;
    }
    true
}

/// The row of a case key, looked up while compiling (`key!("thermal.carry_over")`): validation reads its
/// range, default and unit from there.
#[macro_export]
macro_rules! key {
    ($key:literal) => {
        const { $crate::model::schema::row($key) }
    };
}

/// The row of a key as written in a file, a `--set` override or a validation message:
/// `bearing.pads.orifice[2].diameter_mm` and `bearing.pads.orifice.2.diameter_mm` find
/// `bearing.pads.orifice[].diameter_mm`; `bearing.pad.3.offset` and `bearing.pads.pivot_deg[1]` find
/// their `bearing.pads` rows.
#[must_use]
pub fn spec(key: &str) -> Option<&'static KeySpec> {
    let normal = normalise(key);
    KEYS.iter().find(|s| s.key == normal)
}

/// A key in its row's form: indices as `[]`, per-pad overrides as their common key, a list element as the
/// list.
#[must_use]
pub fn normalise(key: &str) -> String {
    // `a[3].b` → `a.3.b`, then every numeric segment becomes `[]` on the segment before it.
    let dotted = key.replace('[', ".").replace(']', "");
    let mut out: Vec<String> = Vec::new();
    for part in dotted.split('.').filter(|p| !p.is_empty()) {
        if part.parse::<usize>().is_ok() {
            if let Some(last) = out.last_mut() {
                last.push_str("[]");
            }
        } else {
            out.push(part.to_string());
        }
    }
    let mut k = out.join(".");
    // Per-pad overrides share the rows of the common pad table.
    if let Some(rest) = k.strip_prefix("bearing.pad[].") {
        k = format!("bearing.pads.{rest}");
    }
    // A list element (`pivot_deg[1]`) is the list's key.
    k.strip_suffix("[]").map_or(k.clone(), str::to_string)
}

/// The table as plain text: one block per key.
#[must_use]
pub fn text_table() -> String {
    text_table_of(KEYS)
}

/// A table of keys (the case's, or the rotor file's: [`super::rotor_schema::ROTOR_KEYS`]) as plain text.
#[must_use]
pub fn text_table_of<F>(keys: &[KeySpec<F>]) -> String {
    let mut s = String::new();
    for k in keys {
        let unit = if k.unit.is_empty() { "–" } else { k.unit };
        let default = k.default_text();
        let default = if default.is_empty() { "required".to_string() } else { default };
        let _ = writeln!(s, "{}  [{unit}]\n  allowed: {}\n  default: {default}", k.key, k.allowed.describe());
        if let Some((lo, hi)) = k.typical {
            let _ = writeln!(s, "  typical: {lo} – {hi}");
        }
        let _ = writeln!(s, "  {}\n", k.meaning);
    }
    s
}

/// The table as JSON (one object per key).
#[must_use]
pub fn json_table() -> serde_json::Value {
    json_table_of(KEYS)
}

/// A table of keys as JSON (one object per key).
#[must_use]
pub fn json_table_of<F>(keys: &[KeySpec<F>]) -> serde_json::Value {
    serde_json::Value::Array(
        keys.iter()
            .map(|k| {
                serde_json::json!({
                    "key": k.key,
                    "unit": k.unit,
                    "allowed": k.allowed.describe(),
                    "typical": k.typical.map(|(a, b)| [a, b]),
                    "required": matches!(k.default, Fallback::Required),
                    "default": k.default_text(),
                    "meaning": k.meaning,
                })
            })
            .collect(),
    )
}

#[cfg(test)]
mod tests;
