//! Tuning keys: numbers the solver reads straight from their row of the key table.
//!
//! Most keys change what the model *is* (a pad's geometry, the cavitation model, the thermal boundary
//! condition), and each of those has a typed field in the file ([`super::file`]) and in the SI case
//! ([`super::case`]) so that every solver stage must say whether it reads it. A tuning key is a plain number
//! that one part of the solver reads as it is: an iteration budget, a convergence tolerance. Such a key is
//! *only* its row in [`super::schema`], marked `.tuning()`:
//!
//! - the file keeps its value in the section's table like any other key (`[thermal] viscosity_tolerance =
//!   1e-6`); the section's struct collects the keys it has no field for into [`TuningFile`];
//! - validation checks the value against the row (whole number or number, range, unit) and converts it to
//!   SI into [`Tuning`]; a key of the section that is neither a field nor a tuning row is an unknown key,
//!   with the section's keys as the hint, as before;
//! - the solver reads `case.tuning.value(key!("thermal.viscosity_tolerance"))` (or `.count(…)`); `key!`
//!   fails the build on a key without a row.
//!
//! Tuning keys live in `[physics]` and `[thermal]` ([`SECTIONS`]). The equilibrium stage keys its cache on
//! the whole [`Tuning`] (and the stages after it read the equilibrium's inputs), so a tuning key must be
//! read by the equilibrium, the thermal loop or what follows them; a key that changes a film mesh or a pad
//! solid is not a tuning key.

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};

use super::error::CaseError;
use super::file::{CaseFile, TuningFile};
use super::schema::{Allowed, Fallback, KeySpec, KEYS};

/// The sections that may hold tuning keys.
pub const SECTIONS: [&str; 2] = ["physics", "thermal"];

/// Number of tuning rows in the table.
const COUNT: usize = {
    let mut n = 0;
    let mut i = 0;
    while i < KEYS.len() {
        if KEYS[i].tuning {
            n += 1;
        }
        i += 1;
    }
    n
};

/// Every tuning key's value in SI, in the order of the table's tuning rows (absent keys: the row's
/// default).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tuning {
    values: [f64; COUNT],
}

impl Default for Tuning {
    fn default() -> Self {
        let mut values = [0.0; COUNT];
        for (v, row) in values.iter_mut().zip(rows()) {
            *v = default_si(row);
        }
        Self { values }
    }
}

impl Tuning {
    /// The tuning keys a file gives, checked against their rows and converted to SI.
    ///
    /// # Errors
    /// A key of a tuning section that has no row ([`CaseError::UnknownKey`], listing the section's keys), a
    /// value of the wrong type, or one outside the row's range.
    pub fn resolve(file: &CaseFile) -> Result<Self, CaseError> {
        let mut tuning = Self::default();
        for (section, table) in sections(file) {
            for (name, value) in table {
                let key = format!("{section}.{name}");
                let Some((i, row)) = rows().enumerate().find(|(_, r)| r.key == key) else {
                    return Err(unknown(section, key));
                };
                tuning.values[i] = read(row, &key, value)?;
            }
        }
        Ok(tuning)
    }

    /// The value of a tuning row in SI (its default when the row is not a tuning row, which the schema's
    /// tests rule out).
    #[must_use]
    pub fn value(&self, row: &KeySpec) -> f64 {
        rows().position(|r| r.key == row.key).map_or_else(|| default_si(row), |i| self.values[i])
    }

    /// The value of a whole-number tuning row.
    #[must_use]
    #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
    pub fn count(&self, row: &KeySpec) -> usize {
        self.value(row).round().max(0.0) as usize
    }

    /// `key = value` for every tuning row, in the table's order (keys as written, values in SI).
    pub fn iter(&self) -> impl Iterator<Item = (&'static str, f64)> + '_ {
        rows().zip(self.values).map(|(r, v)| (r.key, v))
    }
}

/// Checks the names of a file's tuning keys (values are checked when the case is resolved).
///
/// # Errors
/// [`CaseError::UnknownKey`] for a key of a tuning section that has no row.
pub fn check_names(file: &CaseFile) -> Result<(), CaseError> {
    for (section, table) in sections(file) {
        for name in table.keys() {
            let key = format!("{section}.{name}");
            if !rows().any(|r| r.key == key) {
                return Err(unknown(section, key));
            }
        }
    }
    Ok(())
}

fn sections(file: &CaseFile) -> [(&'static str, &TuningFile); 2] {
    [(SECTIONS[0], &file.physics.tuning), (SECTIONS[1], &file.thermal.tuning)]
}

fn rows() -> impl Iterator<Item = &'static KeySpec> {
    KEYS.iter().filter(|r| r.tuning)
}

/// A row's default in SI (a whole-number row's count as a number).
#[allow(clippy::cast_precision_loss)]
fn default_si(row: &KeySpec) -> f64 {
    match row.default {
        Fallback::Count(n) => n as f64,
        _ => row.default_number().map_or(0.0, |v| row.to_si(v)),
    }
}

/// A value as written, checked against its row, in SI.
#[allow(clippy::cast_precision_loss)]
fn read(row: &KeySpec, key: &str, value: &toml::Value) -> Result<f64, CaseError> {
    let wrong = |expected: &str| CaseError::WrongType {
        key: key.to_string(),
        message: format!("expected {expected}, found {}", value.type_str()),
    };
    match (row.allowed, value) {
        (Allowed::Integer { lo, hi }, toml::Value::Integer(n)) => match usize::try_from(*n) {
            Ok(n) => row.count_at(key, Some(n)).map(|n| n as f64),
            Err(_) => Err(CaseError::OutOfRange {
                key: key.to_string(),
                value: *n as f64,
                allowed: format!("an integer in [{lo}, {hi}]"),
            }),
        },
        (Allowed::Integer { .. }, _) => Err(wrong("a whole number")),
        (_, toml::Value::Integer(n)) => row.value_at(key, Some(*n as f64)),
        (_, toml::Value::Float(x)) => row.value_at(key, Some(*x)),
        _ => Err(wrong("a number")),
    }
}

/// An unknown key of a tuning section, with the section's keys (fields and tuning rows) as the hint.
fn unknown(section: &str, key: String) -> CaseError {
    let prefix = format!("{section}.");
    let names: Vec<String> = KEYS
        .iter()
        .filter_map(|r| r.key.strip_prefix(&prefix))
        .filter(|name| !name.contains('.'))
        .map(|name| format!("`{name}`"))
        .collect();
    CaseError::UnknownKey { key, hint: format!("expected one of {}", names.join(", ")) }
}

// The SI case is serialised with its tuning keys by name (as the result files write the case).
impl Serialize for Tuning {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.collect_map(self.iter())
    }
}

impl<'de> Deserialize<'de> for Tuning {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let given = BTreeMap::<String, f64>::deserialize(deserializer)?;
        let mut tuning = Self::default();
        for (v, row) in tuning.values.iter_mut().zip(rows()) {
            if let Some(x) = given.get(row.key) {
                *v = *x;
            }
        }
        Ok(tuning)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::key;
    use crate::model::load::parse_case_file;

    const CASE: &str = include_str!("../../cases/fillon-a.toml");

    fn with(section_line: &str) -> Result<crate::model::Case, CaseError> {
        parse_case_file(CASE, &[section_line.to_string()])?.resolve()
    }

    #[test]
    fn every_tuning_row_is_a_number_with_a_default_in_a_tuning_section() {
        assert!(rows().next().is_some(), "the table has its tuning rows");
        for row in rows() {
            let section = row.key.split('.').next().unwrap_or_default();
            assert!(SECTIONS.contains(&section), "{}: tuning keys live in {SECTIONS:?}", row.key);
            assert_eq!(row.key.matches('.').count(), 1, "{}: a tuning key is a key of its section's table", row.key);
            let range = match row.allowed {
                Allowed::Integer { lo, hi } => {
                    #[allow(clippy::cast_precision_loss)]
                    let r = (lo as f64, hi as f64);
                    r
                }
                Allowed::Number(r) => (r.lo, r.hi),
                other => panic!("{}: a tuning key is a number, not {other:?}", row.key),
            };
            let d = default_si(row) / row.si;
            assert!(d >= range.0 && d <= range.1, "{}: default {d} outside {range:?}", row.key);
            assert_eq!(Tuning::default().value(row), default_si(row), "{}", row.key);
        }
    }

    #[test]
    fn a_tuning_key_is_checked_converted_and_read_through_its_row() {
        let iters = key!("thermal.max_iterations");
        assert_eq!(with("mesh.fidelity=\"preview\"").unwrap().tuning.count(iters), 300, "absent: the row's default");
        assert_eq!(with("thermal.max_iterations=55").unwrap().tuning.count(iters), 55);

        let e = with("thermal.max_iterations=5").unwrap_err().to_string();
        assert_eq!(e, "`thermal.max_iterations` = 5 is out of range: allowed an integer in [10, 100000]");
        let e = with("thermal.max_iterations=-5").unwrap_err().to_string();
        assert_eq!(e, "`thermal.max_iterations` = -5 is out of range: allowed an integer in [10, 100000]");
        let e = with("thermal.max_iterations=2.5").unwrap_err().to_string();
        assert_eq!(e, "`thermal.max_iterations`: expected a whole number, found float");
        let e = with("thermal.max_iterations=\"many\"").unwrap_err().to_string();
        assert_eq!(e, "`thermal.max_iterations`: expected a whole number, found string");
    }

    #[test]
    fn an_unknown_key_of_a_tuning_section_is_refused_with_the_section_keys() {
        for line in ["thermal.max_iteration=50", "physics.cavitations=\"jfo\""] {
            let e = parse_case_file(CASE, &[line.to_string()]).unwrap_err();
            let CaseError::UnknownKey { key, hint } = &e else { panic!("{line}: {e}") };
            assert_eq!(key, line.split('=').next().unwrap());
            assert!(hint.contains("`max_iterations`") || hint.contains("`cavitation`"), "{hint}");
        }
    }

    #[test]
    fn a_tuning_key_round_trips_through_the_file_and_the_si_case() {
        let file = parse_case_file(CASE, &["thermal.max_iterations=77".to_string()]).unwrap();
        let text = file.to_toml().unwrap();
        assert!(text.contains("max_iterations = 77"), "{text}");
        let again = parse_case_file(&text, &[]).unwrap();
        assert_eq!(again, file);
        let case = file.resolve().unwrap();
        let json = serde_json::to_string(&case).unwrap();
        let back: crate::model::Case = serde_json::from_str(&json).unwrap();
        assert_eq!(back.tuning, case.tuning);
        assert_eq!(back.tuning.count(key!("thermal.max_iterations")), 77);
    }
}
