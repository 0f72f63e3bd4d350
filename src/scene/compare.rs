//! Pinned solutions: the live result compared with named references, as plain rows.
//!
//! A [`Pin`] keeps what a comparison needs and survives a restart (it is serialisable and small): its
//! name, the case text it was solved from, and the output cells of [`crate::study::COLUMNS`] (ε, attitude,
//! load, S, h_min, p_max, temperatures, power loss, flows, K and C terms). [`compare`] lines the live
//! cells up with a pin's, column by column, with the difference `live − pinned` and, for a magnitude whose
//! pinned value is not zero, the relative difference `(live − pinned) / |pinned|`; how each quantity compares,
//! its label, its unit and its group (whose values share one unit prefix) are the table of outputs'
//! ([`crate::bearing::solution::outputs`]): an angle or a Celsius temperature compares by its difference.
//! [`pins_csv`] writes the pins and the live result as one table (one row each, every column); [`pin_name`]
//! keeps the rows' names unambiguous (no pin named [`LIVE_ROW`], no two pins of one name).

use serde::{Deserialize, Serialize};

use crate::bearing::solution::outputs::{Compare, Digits};
use crate::bearing::Solution;
use crate::scene::summary::shared_prefix;
use crate::study::{Column, COLUMNS};

/// A named reference solution.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Pin {
    pub name: String,
    /// The case as TOML when it was pinned (to reopen it).
    pub case_toml: String,
    /// Column names, in the order of `cells` (kept so a pin read after the columns changed still lines up).
    pub columns: Vec<String>,
    pub cells: Vec<Option<f64>>,
}

impl Pin {
    /// Pins `solution` (solved from `case_toml`) under `name`.
    #[must_use]
    pub fn new(name: &str, case_toml: &str, solution: &Solution) -> Self {
        Self {
            name: name.to_string(),
            case_toml: case_toml.to_string(),
            columns: COLUMNS.iter().map(|c| c.name.to_string()).collect(),
            cells: crate::study::columns::outputs(solution),
        }
    }

    /// The pinned value of a column.
    #[must_use]
    pub fn value(&self, column: &str) -> Option<f64> {
        self.columns.iter().position(|c| c == column).and_then(|k| self.cells.get(k).copied().flatten())
    }

    /// The pin holds `column` (a pin made before an output column existed does not).
    #[must_use]
    pub fn has(&self, column: &str) -> bool {
        self.columns.iter().any(|c| c == column)
    }

    /// Some output column is not in the pin: it was made by a workbench that did not have it yet.
    #[must_use]
    pub fn lacks_columns(&self) -> bool {
        COLUMNS.iter().any(|c| !self.has(c.name))
    }

    /// Adds the columns the pin lacks, taken from `solution` (its case solved again); the columns it holds
    /// keep their pinned values.
    pub fn complete_from(&mut self, solution: &Solution) {
        let cells = crate::study::columns::outputs(solution);
        for (c, v) in COLUMNS.iter().zip(cells) {
            if !self.has(c.name) {
                self.columns.push(c.name.to_string());
                self.cells.push(v);
            }
        }
    }
}

/// One line of a comparison: values in the column's unit, shown divided by `scale` in `unit`.
#[derive(Debug, Clone, PartialEq)]
pub struct CompareRow {
    pub column: &'static str,
    /// The quantity's label (the table of outputs', as in the results panel).
    pub label: &'static str,
    /// The unit as shown: a prefixed SI unit shares the prefix of its group, chosen by the group's largest
    /// live or pinned magnitude (Kxx and Kyy both in MN/m).
    pub unit: String,
    /// What a value is divided by to read in `unit` (1e6 for MN/m).
    pub scale: f64,
    pub live: Option<f64>,
    pub pinned: Option<f64>,
    /// The pin does not hold this column (made before it existed; see [`Pin::complete_from`]).
    pub not_in_pin: bool,
    /// How the two compare: relatively (magnitudes) or by their difference (angles, temperatures).
    pub rule: Compare,
    /// How a value of the quantity is written (a difference is written so too).
    pub digits: Digits,
    /// live − pinned.
    pub difference: Option<f64>,
    /// (live − pinned) / |pinned|, when the pinned value is not zero and the quantity compares relatively.
    pub relative: Option<f64>,
}

impl CompareRow {
    /// The difference, with round-off (the same value given twice, below 1e-9 of the values) as 0.
    #[must_use]
    pub fn change(&self) -> Option<f64> {
        let size = self.live.unwrap_or(0.0).abs().max(self.pinned.unwrap_or(0.0).abs());
        self.difference.map(|d| if d.abs() <= 1e-9 * size { 0.0 } else { d })
    }

    /// The change as the table reads it, by the quantity's rule: a relative one in per cent (`+24.2%`), a
    /// difference in the quantity's unit (`-10.9°`); `—` without both values. At most [`CHANGE_CHARS`]
    /// characters (fewer decimals where more would not fit), so the column stays narrow.
    #[must_use]
    pub fn change_text(&self) -> String {
        let Some(d) = self.change() else { return "—".into() };
        match (self.rule, self.relative) {
            (Compare::Difference, _) => {
                let decimals = match self.digits {
                    Digits::Decimals(n) => n,
                    _ => 3,
                };
                fitted(d / self.scale, decimals, &self.unit)
            }
            (_, Some(x)) => fitted(if d == 0.0 { 0.0 } else { 100.0 * x }, 1, "%"),
            (_, None) => "—".into(),
        }
    }
}

/// Most characters of a change ([`CompareRow::change_text`]).
pub const CHANGE_CHARS: usize = 6;

/// `x` with a sign, at most `decimals` decimals and `unit` right after it, in [`CHANGE_CHARS`] characters
/// where fewer decimals make it fit (`-10.9°` rather than `-10.90°`).
fn fitted(x: f64, decimals: usize, unit: &str) -> String {
    let text = |n: usize| format!("{x:+.n$}{unit}");
    (0..=decimals).rev().map(text).find(|t| t.chars().count() <= CHANGE_CHARS).unwrap_or_else(|| text(0))
}

/// The live solution against a pin, every compared output column (solver bookkeeping left out).
#[must_use]
pub fn compare(live: &Solution, pin: &Pin) -> Vec<CompareRow> {
    let cells = crate::study::columns::outputs(live);
    let compared: Vec<(&Column, Option<f64>, Option<f64>)> = COLUMNS
        .iter()
        .zip(cells)
        .filter(|(c, _)| c.output.compare != Compare::Not)
        .map(|(c, live)| (c, live, pin.value(c.name)))
        .collect();
    compared
        .iter()
        .map(|&(c, live, pinned)| {
            let o = c.output;
            let (scale, unit) = if o.digits == Digits::Prefixed {
                // The group's values, live and pinned, choose its one prefix.
                let peers = compared
                    .iter()
                    .filter(|(p, ..)| p.name == c.name || (o.group.is_some() && p.output.group == o.group));
                shared_prefix(peers.flat_map(|(_, a, b)| [*a, *b]).flatten(), o.unit.symbol)
            } else {
                (1.0, o.unit.symbol.to_string())
            };
            let difference = live.zip(pinned).map(|(a, b)| a - b);
            let relative = difference
                .zip(pinned)
                .filter(|_| o.compare == Compare::Relative)
                .and_then(|(d, b)| (b != 0.0).then(|| d / b.abs()));
            CompareRow {
                column: c.name,
                label: o.label,
                unit,
                scale,
                live,
                pinned,
                not_in_pin: !pin.has(c.name),
                rule: o.compare,
                digits: o.digits,
                difference,
                relative,
            }
        })
        .collect()
}

/// The name of the live result's row in [`pins_csv`].
pub const LIVE_ROW: &str = "live";

/// A pin name that would make the export or the views ambiguous.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum PinNameError {
    #[error(
        "the pin name \"{0}\" is refused: the exported CSV names the live result's row \"live\"; choose another name"
    )]
    Reserved(String),
    #[error("a pin named \"{0}\" exists already: choose another name, or remove that pin first")]
    Taken(String),
}

/// The name a new pin gets from what the user typed (trimmed): `pin N` (the first free N from the pin
/// count + 1) when nothing was typed.
///
/// # Errors
/// A name equal to [`LIVE_ROW`] (in any case) or to an existing pin's name.
pub fn pin_name(typed: &str, pins: &[Pin]) -> Result<String, PinNameError> {
    let taken = |n: &str| pins.iter().any(|p| p.name == n);
    let name = typed.trim();
    if name.is_empty() {
        let free = (pins.len() + 1..).map(|k| format!("pin {k}")).find(|n| !taken(n));
        return Ok(free.unwrap_or_default());
    }
    if name.eq_ignore_ascii_case(LIVE_ROW) {
        return Err(PinNameError::Reserved(name.to_string()));
    }
    if taken(name) {
        return Err(PinNameError::Taken(name.to_string()));
    }
    Ok(name.to_string())
}

/// The pins and the live result as CSV: `name` then every output column.
#[must_use]
pub fn pins_csv(pins: &[Pin], live: Option<&Solution>) -> String {
    let mut w = csv::WriterBuilder::new().from_writer(Vec::new());
    let mut ok = w.write_record(std::iter::once("name").chain(COLUMNS.iter().map(|c| c.name))).is_ok();
    let cell = |v: Option<f64>| v.map_or_else(String::new, |x| format!("{x:?}"));
    for p in pins {
        ok &= w
            .write_record(std::iter::once(p.name.clone()).chain(COLUMNS.iter().map(|c| cell(p.value(c.name)))))
            .is_ok();
    }
    if let Some(s) = live {
        ok &= w
            .write_record(
                std::iter::once(LIVE_ROW.to_string()).chain(crate::study::columns::outputs(s).into_iter().map(cell)),
            )
            .is_ok();
    }
    let bytes = w.into_inner().unwrap_or_default();
    if ok {
        String::from_utf8_lossy(&bytes).into_owned()
    } else {
        String::new()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Pin the 9000 rpm solution, compare the 6000 rpm one: the differences are the values' differences,
    /// a pin compared with its own solution differs by exactly zero, and a pin round-trips through JSON.
    #[test]
    fn a_pin_compares_column_by_column_and_round_trips() {
        let fast = crate::bearing::stages::registry::compressor_preview(&[]);
        let slow = crate::bearing::stages::registry::compressor_preview(&["operating.speed_rpm=6000"]);
        let pin = Pin::new("9000 rpm", "title = \"x\"", &fast);
        let rows = compare(&slow, &pin);
        let eps = rows.iter().find(|r| r.column == "eccentricity_ratio").unwrap();
        assert_eq!(eps.pinned, Some(fast.eccentricity_ratio));
        assert_eq!(eps.difference, Some(slow.eccentricity_ratio - fast.eccentricity_ratio));
        assert!(eps.difference.unwrap() > 0.0, "slower, the journal sinks");
        assert_eq!(eps.relative, Some((slow.eccentricity_ratio - fast.eccentricity_ratio) / fast.eccentricity_ratio));
        // Isothermal: no temperatures on either side, no difference.
        let t = rows.iter().find(|r| r.column == "t_max_film_c").unwrap();
        assert_eq!((t.live, t.pinned, t.difference), (None, None, None));
        assert!(!rows.iter().any(|r| r.column == "iterations"));
        assert!(compare(&fast, &pin).iter().all(|r| r.difference.is_none_or(|d| d == 0.0)));
        // Through JSON (serde_json's float parsing may differ in the last bit).
        let back: Pin = serde_json::from_str(&serde_json::to_string(&pin).unwrap()).unwrap();
        assert_eq!((&back.name, &back.case_toml, &back.columns), (&pin.name, &pin.case_toml, &pin.columns));
        for (a, b) in back.cells.iter().zip(&pin.cells) {
            assert_eq!(a.is_some(), b.is_some());
            assert!(a.zip(*b).is_none_or(|(a, b)| (a - b).abs() <= 1e-15 * b.abs()), "{a:?} {b:?}");
        }
        let csv = pins_csv(&[pin], Some(&slow));
        assert_eq!(csv.lines().count(), 3);
        assert!(
            csv.lines().nth(1).unwrap().starts_with("9000 rpm,") && csv.lines().nth(2).unwrap().starts_with("live,")
        );
    }

    /// The −542.9 % of an attitude angle: pinned at 2°, live at −8.9°, the angle changed by −10.90° and reads
    /// so (a relative change of an angle, whose zero is a convention, means nothing); a magnitude (ε) keeps
    /// its per cent.
    #[test]
    fn angles_compare_by_their_difference() {
        let mut live = crate::bearing::stages::registry::compressor_preview(&[]);
        let mut pin = Pin::new("2°", "", &live);
        let k = pin.columns.iter().position(|c| c == "attitude_angle_deg").unwrap();
        pin.cells[k] = Some(2.0);
        let e = pin.columns.iter().position(|c| c == "eccentricity_ratio").unwrap();
        pin.cells[e] = Some(0.5);
        live.attitude_angle_deg = -8.9;
        let rows = compare(&live, &pin);
        let angle = rows.iter().find(|r| r.column == "attitude_angle_deg").unwrap();
        assert_eq!((angle.rule, angle.relative, angle.unit.as_str()), (Compare::Difference, None, "°"));
        assert!((angle.difference.unwrap() + 10.9).abs() < 1e-12, "{angle:?}");
        assert_eq!(angle.change_text(), "-10.9°");
        let eps = rows.iter().find(|r| r.column == "eccentricity_ratio").unwrap();
        let percent = 100.0 * (live.eccentricity_ratio - 0.5) / 0.5;
        assert_eq!(eps.change_text(), format!("{percent:+.1}%"));
        assert_eq!(fitted(315.52, 1, "%"), "+316%");
        assert_eq!(fitted(5.23, 1, "°C"), "+5.2°C");
        assert_eq!(fitted(-12.34, 1, "°C"), "-12°C");
        // Celsius temperatures compare by their difference as well.
        for c in ["t_max_film_c", "t_max_pad_c", "t_journal_c"] {
            assert_eq!(rows.iter().find(|r| r.column == c).unwrap().rule, Compare::Difference, "{c}");
        }
    }

    /// Kxx live at 46 MN/m, Kyy pinned at 1.95 GN/m: the four terms of the stiffness matrix read in GN/m
    /// (they read in MN/m and GN/m row by row); the damping terms keep their own prefix.
    #[test]
    fn a_matrix_compares_in_one_prefix() {
        let mut live = crate::bearing::stages::registry::compressor_preview(&[]);
        live.reduced.k_n_per_m = [[4.636e7, -1.839e6], [2.2e5, 4.0e7]];
        let mut pin = Pin::new("stiff", "", &live);
        let k = pin.columns.iter().position(|c| c == "kyy_n_per_m").unwrap();
        pin.cells[k] = Some(1.95e9);
        let rows = compare(&live, &pin);
        for c in ["kxx_n_per_m", "kxy_n_per_m", "kyx_n_per_m", "kyy_n_per_m"] {
            let r = rows.iter().find(|r| r.column == c).unwrap();
            assert_eq!((r.unit.as_str(), r.scale), ("GN/m", 1e9), "{c}");
        }
        let c = rows.iter().find(|r| r.column == "cxx_ns_per_m").unwrap();
        assert_eq!(c.unit, "kN·s/m");
    }

    /// A pin written before the power-loss columns existed lacks them: the comparison says so, and
    /// completing it from its case's solution adds them and leaves the pinned columns as they were.
    #[test]
    fn a_pin_made_before_a_column_existed_is_completed_from_its_solution() {
        let fast = crate::bearing::stages::registry::compressor_preview(&[]);
        let mut pin = Pin::new("old", "title = \"x\"", &fast);
        for gone in ["churning_power_w", "total_power_loss_w"] {
            let k = pin.columns.iter().position(|c| c == gone).unwrap();
            pin.columns.remove(k);
            pin.cells.remove(k);
        }
        pin.cells[0] = Some(0.5);
        assert!(pin.lacks_columns());
        let rows = compare(&fast, &pin);
        let total = rows.iter().find(|r| r.column == "total_power_loss_w").unwrap();
        assert!(total.not_in_pin && total.pinned.is_none() && total.live.is_some());
        assert!(!rows.iter().find(|r| r.column == "friction_power_w").unwrap().not_in_pin);
        pin.complete_from(&fast);
        assert!(!pin.lacks_columns());
        assert_eq!(pin.value("total_power_loss_w"), Some(fast.total_power_loss_w()));
        assert_eq!(pin.value("churning_power_w"), Some(fast.churning_power_w()));
        assert_eq!(pin.value("eccentricity_ratio"), Some(0.5), "a pinned column keeps its value");
    }

    /// "live" names the live row of the export: refused, as is a second pin of one name; nothing typed
    /// gives the first free "pin N".
    #[test]
    fn pin_names_keep_the_export_unambiguous() {
        let pin = |n: &str| Pin { name: n.into(), case_toml: String::new(), columns: Vec::new(), cells: Vec::new() };
        let pins = [pin("pin 2"), pin("baseline")];
        assert_eq!(pin_name("  ", &[]), Ok("pin 1".into()));
        assert_eq!(pin_name("", &pins), Ok("pin 3".into()));
        assert_eq!(pin_name("", &[pin("a"), pin("pin 3")]), Ok("pin 4".into()));
        assert_eq!(pin_name(" preload 0.5 ", &pins), Ok("preload 0.5".into()));
        for typed in ["live", " Live", "LIVE "] {
            assert_eq!(pin_name(typed, &pins), Err(PinNameError::Reserved(typed.trim().into())));
        }
        assert_eq!(pin_name("baseline", &pins), Err(PinNameError::Taken("baseline".into())));
        assert_eq!(pin_name("live 2", &pins), Ok("live 2".into()));
        let message = pin_name("live", &pins).unwrap_err().to_string();
        assert!(message.contains("\"live\"") && message.contains("choose another name"), "{message}");
    }
}
