//! Reading a case: TOML text → `--set` overrides → [`CaseFile`] → validated SI [`Case`].
//!
//! Overrides use dotted keys as written in the file (`operating.speed_rpm=3000`,
//! `bearing.pads.preload=0.3`, `bearing.pad.2.offset=0.6`, `operating.injection_pressure_bar=[0,0,20,0,0]`);
//! the value is parsed as a TOML value, falling back to a string; an empty value (`operating.load_n=`)
//! removes the key.
//!
//! The pad geometry has three alternative keys, [`PAD_GEOMETRY_KEYS`] (preload, pad clearance, pad bore
//! radius; a file gives exactly one per pad table). Setting one of them, by `--set`, a sweep or batch point
//! or the editor, replaces the others of the same table: `bearing.pads.preload=0.3` on a case that gives
//! `bearing.pads.bore_radius_mm` drops the bore radius. Likewise, setting `feeding.kind` drops the keys the
//! new kind does not use (each feeding has its own hot-oil carry-over: `thermal.carry_over` for the flooded
//! housing and the spray bar, `feeding.groove_carry_over` and `feeding.groove_width_deg` for the groove).
//! [`replaced_keys`] lists what a set of overrides replaced, so callers can say so.

use super::case::Case;
use super::error::{CaseError, OverrideProblem};
use super::file::CaseFile;

/// Parses case text, applies overrides and validates.
///
/// # Errors
/// Syntax errors, unknown or missing keys, bad overrides and every validation failure, each naming its key.
pub fn load_case(text: &str, overrides: &[String]) -> Result<(CaseFile, Case), CaseError> {
    let file = parse_case_file(text, overrides)?;
    let case = file.resolve()?;
    Ok((file, case))
}

/// Parses case text and applies overrides without validating values.
///
/// # Errors
/// Syntax errors, unknown keys, wrong types and bad overrides.
pub fn parse_case_file(text: &str, overrides: &[String]) -> Result<CaseFile, CaseError> {
    let mut table: toml::Table =
        text.parse().map_err(|e: toml::de::Error| CaseError::Syntax { message: e.to_string() })?;
    for o in overrides {
        apply_override(&mut table, o)?;
    }
    from_table(table)
}

/// The alternative ways to give a pad table's machined clearance: setting one removes the others.
pub const PAD_GEOMETRY_KEYS: [&str; 3] = ["preload", "clearance_um", "bore_radius_mm"];

/// A key of the case that an override removed because it set an alternative of it.
#[derive(Debug, Clone, PartialEq)]
pub struct Replaced {
    /// The key the override set (`bearing.pads.preload`).
    pub set: String,
    /// The key it removed (`bearing.pads.bore_radius_mm`).
    pub removed: String,
    /// The removed key's value as the case gave it.
    pub was: toml::Value,
}

impl std::fmt::Display for Replaced {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let why = if self.set == FEEDING_KIND {
            "a key the new feeding does not use"
        } else {
            "alternative pad-geometry keys"
        };
        write!(f, "{} replaces {} = {} ({why})", self.set, self.removed, self.was)
    }
}

const FEEDING_KIND: &str = "feeding.kind";

/// The keys only some feeding kinds use, with the kinds that use them (the file's words).
const FEEDING_KEYS: [(&str, &str, &[&str]); 4] = [
    ("thermal", "carry_over", &["flooded", "spray_bar"]),
    ("feeding", "groove_carry_over", &["leading_edge_groove"]),
    ("feeding", "groove_width_deg", &["leading_edge_groove"]),
    ("feeding", "churning_factor", &["flooded"]),
];

/// After `feeding.kind` was set to `kind`: removes the keys that kind does not use, returning them.
fn drop_unused_feeding_keys(table: &mut toml::Table, kind: &str) -> Vec<Replaced> {
    let mut replaced = Vec::new();
    for (section, name, users) in FEEDING_KEYS {
        if users.contains(&kind) {
            continue;
        }
        if let Some(toml::Value::Table(t)) = table.get_mut(section) {
            if let Some(was) = t.remove(name) {
                replaced.push(Replaced { set: FEEDING_KIND.to_string(), removed: format!("{section}.{name}"), was });
            }
        }
    }
    replaced
}

/// The keys of `text` that `overrides` replaced by setting one of their alternatives ([`PAD_GEOMETRY_KEYS`]),
/// in the order the overrides are applied.
///
/// # Errors
/// Syntax errors and bad overrides, as [`parse_case_file`].
pub fn replaced_keys(text: &str, overrides: &[String]) -> Result<Vec<Replaced>, CaseError> {
    let mut table: toml::Table =
        text.parse().map_err(|e: toml::de::Error| CaseError::Syntax { message: e.to_string() })?;
    let mut all = Vec::new();
    for o in overrides {
        all.extend(apply_override(&mut table, o)?);
    }
    Ok(all)
}

/// Converts a TOML table into a [`CaseFile`], reporting the full key path of any schema error.
///
/// # Errors
/// Unknown keys, missing keys and wrong types.
pub fn from_table(table: toml::Table) -> Result<CaseFile, CaseError> {
    let value = toml::Value::Table(table);
    let file = serde_path_to_error::deserialize::<_, CaseFile>(value).map_err(|e| {
        let path = e.path().to_string();
        let inner = e.into_inner().to_string();
        schema_error(&path, &inner)
    })?;
    super::tuning::check_names(&file)?;
    Ok(file)
}

/// Turns a serde message into a typed error with a dotted key.
pub(crate) fn schema_error(path: &str, message: &str) -> CaseError {
    let path = path.trim_start_matches('.').replace(".[", "[").replace("[", ".").replace(']', "");
    let path = if path == "." { String::new() } else { path };
    let join = |leaf: &str| if path.is_empty() { leaf.to_string() } else { format!("{path}.{leaf}") };
    if let Some(rest) = message.strip_prefix("unknown field `") {
        let (name, tail) = rest.split_once('`').unwrap_or((rest, ""));
        let hint = tail.trim_start_matches(',').trim().to_string();
        // serde_path_to_error already appends the unknown field to the path.
        let key = if path.ends_with(name) { path.clone() } else { join(name) };
        return CaseError::UnknownKey { key, hint };
    }
    if let Some(rest) = message.strip_prefix("missing field `") {
        let name = rest.split('`').next().unwrap_or(rest);
        return CaseError::MissingKey { key: join(name), meaning: "required".into() };
    }
    CaseError::WrongType { key: if path.is_empty() { "(case)".into() } else { path }, message: message.to_string() }
}

/// Applies one `key=value` override to the raw table; returns the keys it replaced.
fn apply_override(table: &mut toml::Table, text: &str) -> Result<Vec<Replaced>, CaseError> {
    let bad = |problem| CaseError::BadOverride { text: text.to_string(), problem };
    let (key, raw) = text.split_once('=').ok_or_else(|| bad(OverrideProblem::NoEquals))?;
    let (key, raw) = (key.trim(), raw.trim());
    if key.is_empty() {
        return Err(bad(OverrideProblem::EmptyKey));
    }
    // An empty value removes the key (e.g. to switch from `load_n` to `eccentricity_ratio`).
    let value = (!raw.is_empty()).then(|| parse_value(raw));
    let kind = value.as_ref().and_then(|v| v.as_str().map(str::to_string)).filter(|_| key == FEEDING_KIND);
    let mut replaced = set_path(table, &key.split('.').collect::<Vec<_>>(), value).map_err(bad)?;
    if let Some(kind) = kind {
        replaced.extend(drop_unused_feeding_keys(table, &kind));
    }
    Ok(replaced)
}

/// Sets (`Some`) or removes (`None`) the value at a dotted path; a numeric segment indexes an array of
/// tables (`bearing.pad.2.offset`). Missing tables on the way are created. Setting one of a pad table's
/// [`PAD_GEOMETRY_KEYS`] removes the others from that table; the removed keys are returned.
fn set_path(
    table: &mut toml::Table,
    parts: &[&str],
    value: Option<toml::Value>,
) -> Result<Vec<Replaced>, OverrideProblem> {
    let Some((last, parents)) = parts.split_last() else { return Err(OverrideProblem::EmptyKey) };
    let mut node = table;
    let mut i = 0;
    while i < parents.len() {
        let index = parts[i + 1].parse::<usize>().ok();
        let entry = node.entry(parts[i].to_string()).or_insert_with(|| {
            if index.is_some() {
                toml::Value::Array(Vec::new())
            } else {
                toml::Value::Table(toml::Table::new())
            }
        });
        match (entry, index) {
            (toml::Value::Table(t), _) => {
                node = t;
                i += 1;
            }
            (toml::Value::Array(a), Some(index)) => {
                let array = parts[..=i].join(".");
                let len = a.len();
                if i + 1 == parents.len() {
                    return Err(OverrideProblem::WholeTable);
                }
                match a.get_mut(index) {
                    None => return Err(OverrideProblem::IndexOutOfRange { array, len, index }),
                    Some(toml::Value::Table(t)) => node = t,
                    Some(_) => return Err(OverrideProblem::EntryNotATable { path: format!("{array}.{index}") }),
                }
                i += 2;
            }
            _ => return Err(OverrideProblem::ValueNotATable { path: parts[..=i].join(".") }),
        }
    }
    let mut replaced = Vec::new();
    match value {
        Some(v) => {
            let in_pad_table = matches!(parents, ["bearing", "pads"] | ["bearing", "pad", _]);
            if in_pad_table && PAD_GEOMETRY_KEYS.contains(last) {
                let table = parents.join(".");
                for other in PAD_GEOMETRY_KEYS.iter().filter(|k| *k != last) {
                    if let Some(was) = node.remove(*other) {
                        let (set, removed) = (format!("{table}.{last}"), format!("{table}.{other}"));
                        replaced.push(Replaced { set, removed, was });
                    }
                }
            }
            node.insert((*last).to_string(), v);
        }
        None => {
            node.remove(*last);
        }
    }
    Ok(replaced)
}

/// The value at a key in a file's table: `bearing.pads.orifice[1].diameter_mm` (or `…orifice.1…`).
#[must_use]
pub fn value_at<'a>(table: &'a toml::Table, key: &str) -> Option<&'a toml::Value> {
    let dotted = key.replace('[', ".").replace(']', "");
    let mut parts = dotted.split('.').filter(|p| !p.is_empty());
    let mut value = table.get(parts.next()?)?;
    for part in parts {
        value = match (value, part.parse::<usize>()) {
            (toml::Value::Array(a), Ok(i)) => a.get(i)?,
            (toml::Value::Table(t), _) => t.get(part)?,
            _ => return None,
        };
    }
    Some(value)
}

impl CaseFile {
    /// The case as a TOML table (what `to_toml` writes), to read values by key ([`value_at`]).
    ///
    /// # Errors
    /// Only if a value cannot be represented in TOML.
    pub fn to_table(&self) -> Result<toml::Table, CaseError> {
        match toml::Value::try_from(self) {
            Ok(toml::Value::Table(t)) => Ok(t),
            Ok(_) => Err(CaseError::Syntax { message: "a case file serialises to a table".into() }),
            Err(e) => Err(CaseError::Syntax { message: e.to_string() }),
        }
    }

    /// This case with the value at `key` set (`Some`) or removed (`None`): what `--set key=value` does, for
    /// editors. `key` may index arrays as validation names them (`bearing.pads.orifice[1].diameter_mm`).
    ///
    /// # Errors
    /// A path through a value or past an array's end, or a value of the wrong type for its key.
    pub fn with_value(&self, key: &str, value: Option<toml::Value>) -> Result<Self, CaseError> {
        let mut table = self.to_table()?;
        let dotted = key.replace('[', ".").replace(']', "");
        let parts: Vec<&str> = dotted.split('.').filter(|p| !p.is_empty()).collect();
        set_path(&mut table, &parts, value)
            .map_err(|problem| CaseError::BadOverride { text: key.to_string(), problem })?;
        from_table(table)
    }
}

/// Parses an override value as TOML (number, bool, array, quoted string), else as a bare string.
fn parse_value(raw: &str) -> toml::Value {
    let doc = format!("v = {raw}");
    match doc.parse::<toml::Table>() {
        Ok(mut t) => t.remove("v").unwrap_or_else(|| toml::Value::String(raw.to_string())),
        Err(_) => toml::Value::String(raw.to_string()),
    }
}

impl CaseFile {
    /// Serialises the case back to TOML (engineering units, as written by the user).
    ///
    /// # Errors
    /// Only if a value cannot be represented in TOML (non-finite numbers).
    pub fn to_toml(&self) -> Result<String, CaseError> {
        toml::to_string_pretty(self).map_err(|e| CaseError::Syntax { message: e.to_string() })
    }
}
