//! Reading a case: TOML text → `--set` overrides → [`CaseFile`] → validated SI [`Case`].
//!
//! Overrides use dotted keys as written in the file (`operating.speed_rpm=3000`,
//! `bearing.pads.preload=0.3`, `bearing.pad.2.offset=0.6`, `operating.injection_pressure_bar=[0,0,20,0,0]`);
//! the value is parsed as a TOML value, falling back to a string; an empty value (`operating.load_n=`)
//! removes the key.

use super::case::Case;
use super::error::CaseError;
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

/// Converts a TOML table into a [`CaseFile`], reporting the full key path of any schema error.
///
/// # Errors
/// Unknown keys, missing keys and wrong types.
pub fn from_table(table: toml::Table) -> Result<CaseFile, CaseError> {
    let value = toml::Value::Table(table);
    serde_path_to_error::deserialize::<_, CaseFile>(value).map_err(|e| {
        let path = e.path().to_string();
        let inner = e.into_inner().to_string();
        schema_error(&path, &inner)
    })
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

/// Applies one `key=value` override to the raw table.
fn apply_override(table: &mut toml::Table, text: &str) -> Result<(), CaseError> {
    let bad = |message: &str| CaseError::BadOverride { text: text.to_string(), message: message.to_string() };
    let (key, raw) = text.split_once('=').ok_or_else(|| bad("expected key=value"))?;
    let key = key.trim();
    let raw = raw.trim();
    if key.is_empty() {
        return Err(bad("empty key"));
    }
    // An empty value removes the key (e.g. to switch from `load_n` to `eccentricity_ratio`).
    let value = (!raw.is_empty()).then(|| parse_value(raw));
    let parts: Vec<&str> = key.split('.').collect();
    let mut node = table;
    for (i, part) in parts.iter().enumerate() {
        let last = i + 1 == parts.len();
        if last {
            match value {
                Some(v) => {
                    node.insert((*part).to_string(), v);
                }
                None => {
                    node.remove(*part);
                }
            }
            return Ok(());
        }
        // Next segment may index an array of tables (`bearing.pad.2.offset`).
        let next_is_index = parts[i + 1].parse::<usize>().is_ok();
        let entry = node.entry((*part).to_string()).or_insert_with(|| {
            if next_is_index {
                toml::Value::Array(Vec::new())
            } else {
                toml::Value::Table(toml::Table::new())
            }
        });
        match entry {
            toml::Value::Table(t) => node = t,
            toml::Value::Array(a) if next_is_index => {
                let idx: usize = parts[i + 1].parse().map_err(|_| bad("bad index"))?;
                if idx >= a.len() {
                    return Err(bad(&format!(
                        "`{}` has {} entries; index {idx} is out of range",
                        parts[..=i].join("."),
                        a.len()
                    )));
                }
                let rest = &parts[i + 2..];
                let toml::Value::Table(t) = &mut a[idx] else {
                    return Err(bad(&format!("`{}.{idx}` is not a table", parts[..=i].join("."))));
                };
                if rest.is_empty() {
                    return Err(bad("an override must end at a value, not a whole table"));
                }
                let sub = format!("{}={raw}", rest.join("."));
                return apply_override(t, &sub).map_err(|_| bad("cannot apply inside the array entry"));
            }
            _ => return Err(bad(&format!("`{}` is a value, not a table", parts[..=i].join(".")))),
        }
    }
    Ok(())
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
