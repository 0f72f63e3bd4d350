//! Saving a case into the user's own file: the edited [`CaseFile`] is written into the original TOML
//! document in place (with `toml_edit`), so only values that changed change. Comments (a case's source
//! citation), key order, blank lines, inline tables and number style (`9000` stays an integer) survive.
//!
//! Rules, applied recursively from the document root:
//! - a value equal to the new one (numbers compared by value: `60` equals `60.0`) is left as written;
//! - a changed value is replaced, keeping the comments and spacing around it; an integer stays an integer
//!   when the new value is whole; arrays of equal length are updated element by element;
//! - a key the case no longer has is removed (switching from a load to a prescribed eccentricity), a key
//!   it gained is appended to its table, an empty new table is not written;
//! - an array of tables (`[[bearing.pads.orifice]]`) of the same length is merged entry by entry, else
//!   rewritten.

use toml_edit::{DocumentMut, Item, TableLike, Value};

use super::error::CaseError;
use super::file::CaseFile;

fn syntax(e: impl std::fmt::Display) -> CaseError {
    CaseError::Syntax { message: e.to_string() }
}

impl CaseFile {
    /// This case written into `original` (the text it was read from), changing only what differs.
    ///
    /// # Errors
    /// `original` is not TOML, or a value cannot be written (non-finite numbers).
    pub fn to_toml_preserving(&self, original: &str) -> Result<String, CaseError> {
        write_preserving(self, original)
    }
}

/// Any file model (a case, a rotor file) written into `original` by the rules above.
///
/// # Errors
/// `original` is not TOML, `value` does not serialise to a table, or a value cannot be written.
pub fn write_preserving(value: &impl serde::Serialize, original: &str) -> Result<String, CaseError> {
    let mut doc: DocumentMut = original.parse().map_err(syntax)?;
    let new = toml::Value::try_from(value).map_err(syntax)?;
    let toml::Value::Table(new) = new else { return Err(syntax("a file model serialises to a table")) };
    merge_table(doc.as_table_mut(), &new)?;
    Ok(doc.to_string())
}

fn merge_table(old: &mut dyn TableLike, new: &toml::Table) -> Result<(), CaseError> {
    let gone: Vec<String> = old.iter().map(|(k, _)| k.to_string()).filter(|k| !new.contains_key(k)).collect();
    for k in gone {
        old.remove(&k);
    }
    for (key, value) in new {
        match old.get_mut(key) {
            Some(item) => merge_item(item, value)?,
            None => {
                if matches!(value, toml::Value::Table(t) if t.is_empty()) {
                    continue;
                }
                old.insert(key, to_item(value)?);
            }
        }
    }
    Ok(())
}

fn merge_item(item: &mut Item, new: &toml::Value) -> Result<(), CaseError> {
    match (item, new) {
        (item, toml::Value::Table(t)) if item.is_table_like() => {
            let Some(old) = item.as_table_like_mut() else { return Ok(()) };
            merge_table(old, t)
        }
        (Item::ArrayOfTables(old), toml::Value::Array(list))
            if old.len() == list.len() && list.iter().all(toml::Value::is_table) =>
        {
            for (o, n) in old.iter_mut().zip(list) {
                if let toml::Value::Table(t) = n {
                    merge_table(o, t)?;
                }
            }
            Ok(())
        }
        (Item::Value(old), new) if !matches!(new, toml::Value::Table(_)) => merge_value(old, new),
        (item, new) => {
            *item = to_item(new)?;
            Ok(())
        }
    }
}

fn merge_value(old: &mut Value, new: &toml::Value) -> Result<(), CaseError> {
    if same(old, new) {
        return Ok(());
    }
    if let (Value::Array(a), toml::Value::Array(b)) = (&mut *old, new) {
        if a.len() == b.len() {
            for (i, n) in b.iter().enumerate() {
                if let Some(o) = a.get_mut(i) {
                    merge_value(o, n)?;
                }
            }
            return Ok(());
        }
    }
    let mut value = to_value(new)?;
    // A whole number replacing an integer stays an integer.
    #[allow(clippy::cast_possible_truncation)]
    if let (Value::Integer(_), toml::Value::Float(x)) = (&*old, new) {
        if x.fract() == 0.0 && x.abs() < 9.0e15 {
            value = Value::from(*x as i64);
        }
    }
    let decor = old.decor().clone();
    *old = value;
    *old.decor_mut() = decor;
    Ok(())
}

/// Equal as data: numbers by value whatever their type, arrays and tables element by element.
fn same(old: &Value, new: &toml::Value) -> bool {
    #[allow(clippy::cast_precision_loss)]
    let number = |v: &Value| match v {
        Value::Integer(i) => Some(*i.value() as f64),
        Value::Float(f) => Some(*f.value()),
        _ => None,
    };
    #[allow(clippy::cast_precision_loss)]
    let new_number = match new {
        toml::Value::Integer(i) => Some(*i as f64),
        toml::Value::Float(f) => Some(*f),
        _ => None,
    };
    match (old, new) {
        (Value::String(a), toml::Value::String(b)) => a.value() == b,
        (Value::Boolean(a), toml::Value::Boolean(b)) => a.value() == b,
        (Value::Array(a), toml::Value::Array(b)) => a.len() == b.len() && a.iter().zip(b).all(|(x, y)| same(x, y)),
        (Value::InlineTable(a), toml::Value::Table(b)) => {
            a.len() == b.len() && b.iter().all(|(k, v)| a.get(k).is_some_and(|x| same(x, v)))
        }
        _ => matches!((number(old), new_number), (Some(a), Some(b)) if a == b),
    }
}

/// A new value as `toml_edit` writes it.
fn to_value(v: &toml::Value) -> Result<Value, CaseError> {
    match to_item(v)? {
        Item::Value(v) => Ok(v),
        _ => Err(syntax("expected a value")),
    }
}

/// A new value, table or array of tables, formatted as a fresh file would have it.
fn to_item(v: &toml::Value) -> Result<Item, CaseError> {
    let mut wrapper = toml::Table::new();
    wrapper.insert("v".into(), v.clone());
    let text = toml::to_string(&wrapper).map_err(syntax)?;
    let mut doc: DocumentMut = text.parse().map_err(syntax)?;
    let mut item = doc.remove("v").ok_or_else(|| syntax("lost a value while formatting it"))?;
    forget_positions(&mut item);
    Ok(item)
}

/// Tables taken from the scratch document forget where they stood there, so they are written after the
/// tables the user's file already has.
fn forget_positions(item: &mut Item) {
    match item {
        Item::Table(t) => {
            t.set_position(None);
            for (_, child) in t.iter_mut() {
                forget_positions(child);
            }
        }
        Item::ArrayOfTables(a) => {
            for t in a.iter_mut() {
                t.set_position(None);
                for (_, child) in t.iter_mut() {
                    forget_positions(child);
                }
            }
        }
        _ => {}
    }
}

#[cfg(test)]
mod tests {
    use crate::model::file::OneOrMany;
    use crate::model::parse_case_file;

    /// Lines of `b` that differ from `a` (same number of lines expected).
    fn changed_lines(a: &str, b: &str) -> Vec<(String, String)> {
        assert_eq!(a.lines().count(), b.lines().count(), "line count changed:\n{b}");
        a.lines().zip(b.lines()).filter(|(x, y)| x != y).map(|(x, y)| (x.to_string(), y.to_string())).collect()
    }

    #[test]
    fn one_edit_changes_one_line_of_every_shipped_case() {
        for (name, text) in crate::model::shipped_cases() {
            let mut file = parse_case_file(&text, &[]).unwrap();
            // Unchanged: the text comes back byte for byte.
            assert_eq!(file.to_toml_preserving(&text).unwrap(), text, "{name}: an unedited save changed the file");
            let old = file.operating.speed_rpm;
            file.operating.speed_rpm = old + 1234.5;
            let saved = file.to_toml_preserving(&text).unwrap();
            let diff = changed_lines(&text, &saved);
            assert_eq!(diff.len(), 1, "{name}: {diff:?}");
            let (before, after) = &diff[0];
            assert!(before.trim_start().starts_with("speed_rpm"), "{name}: {before}");
            let value: f64 = after.split('=').nth(1).unwrap().split('#').next().unwrap().trim().parse().unwrap();
            assert_eq!(value, old + 1234.5, "{name}: {after}");
            // The file still reads as the edited case.
            assert_eq!(parse_case_file(&saved, &[]).unwrap(), file, "{name}");
        }
    }

    #[test]
    fn integers_stay_integers_and_comments_stay_put() {
        let text = "# source: a paper\n[bearing]\njournal_radius_mm = 50 # R\nlength_mm = 40.0\nassembled_clearance_um = 100\n\n[bearing.pads]\ncount = 4\narc_deg = 80\npivot_deg = [45, 135, 225, 315]  # LBP\noffset = 0.5\npreload = 0.0\nthickness_mm = 10\n\n[lubricant]\nviscosity_pa_s = 0.03\nviscosity_temperature_c = 40\nviscosity_coefficient_per_k = 0.03\ndensity_kg_per_m3 = 860\nspecific_heat_j_per_kg_k = 2000\nconductivity_w_per_m_k = 0.13\n\n[operating]\nspeed_rpm = 3000 # rig\nload_n = 1000\nsupply_temperature_c = 40\n";
        let mut f = parse_case_file(text, &[]).unwrap();
        f.bearing.journal_radius_mm = 60.0;
        f.bearing.pads.pivot_deg = Some(OneOrMany::Many(vec![45.0, 135.0, 225.0, 300.5]));
        let saved = f.to_toml_preserving(text).unwrap();
        assert!(saved.contains("journal_radius_mm = 60 # R"), "{saved}");
        assert!(saved.contains("pivot_deg = [45, 135, 225, 300.5]  # LBP"), "{saved}");
        assert!(saved.starts_with("# source: a paper\n"));
        // Switching to a prescribed position removes the load and adds the eccentricity.
        f.operating.load_n = None;
        f.operating.eccentricity_ratio = Some(0.4);
        let saved = f.to_toml_preserving(text).unwrap();
        assert!(!saved.contains("load_n") && saved.contains("eccentricity_ratio = 0.4"), "{saved}");
        assert!(saved.contains("speed_rpm = 3000 # rig"), "{saved}");
        assert_eq!(parse_case_file(&saved, &[]).unwrap(), f);
        // A table the file did not have is appended; empty ones are not written.
        f.thermal.model = Some(crate::model::ThermalModelKind::Thd);
        let saved = f.to_toml_preserving(text).unwrap();
        assert!(
            saved.contains("[thermal]\nmodel = \"thd\"") && !saved.contains("[physics]") && !saved.contains("[mesh]"),
            "{saved}"
        );
        assert_eq!(parse_case_file(&saved, &[]).unwrap(), f);
    }
}
