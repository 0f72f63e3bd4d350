//! A row of the key table drawn by its widget, reading and writing the case by the row's key (what
//! `--set key=value` does): nothing here knows a key.

use egui::Ui;

use super::widgets::{choice_ui, number_ui, optional_ui, text_ui, EditOutput, Num, Pick};
use crate::app::document::Document;
use crate::model::load::value_at;
use crate::model::schema::{Allowed, Fallback, KeySpec, Widget};
use crate::model::CaseFile;
use crate::number::sig;

/// The case as a table, to read values by key (one serialisation per group and frame, renewed after an
/// edit).
pub struct Values(toml::Table);

impl Values {
    #[must_use]
    pub fn of(file: &CaseFile) -> Self {
        Self(file.to_table().unwrap_or_default())
    }

    /// The number at `key` (an integer reads as a number).
    #[must_use]
    pub fn number(&self, key: &str) -> Option<f64> {
        number(&self.0, key)
    }

    #[must_use]
    pub fn word(&self, key: &str) -> Option<&str> {
        value_at(&self.0, key).and_then(toml::Value::as_str)
    }
}

#[allow(clippy::cast_precision_loss)]
fn number(table: &toml::Table, key: &str) -> Option<f64> {
    match value_at(table, key)? {
        toml::Value::Float(x) => Some(*x),
        toml::Value::Integer(i) => Some(*i as f64),
        _ => None,
    }
}

/// The number at `key` of a case.
fn read(file: &CaseFile, key: &str) -> Option<f64> {
    file.to_table().ok().and_then(|t| number(&t, key))
}

/// Sets (or, with `None`, removes) the value at `key`; a value the case cannot take leaves it unchanged.
pub fn write(file: &mut CaseFile, key: &str, value: Option<toml::Value>) {
    if let Ok(edited) = file.with_value(key, value) {
        *file = edited;
    }
}

/// A number as the row's key is written: whole numbers for integer keys.
#[allow(clippy::cast_possible_truncation)]
fn as_value(row: &KeySpec, x: f64) -> toml::Value {
    match row.allowed {
        Allowed::Integer { .. } => toml::Value::Integer(x.round().clamp(0.0, 9.0e15) as i64),
        _ => toml::Value::Float(x),
    }
}

/// What an absent key means, as the editor shows it, and the value a user who gives it starts from (the
/// default, else the middle of the typical range).
#[must_use]
pub fn absent(row: &KeySpec, file: &CaseFile) -> (String, f64) {
    let start = row.default_in(file).unwrap_or_else(|| row.typical.map_or(0.0, |(lo, hi)| 0.5 * (lo + hi)));
    let text = match row.default {
        Fallback::Rule(text) => text.to_string(),
        _ => sig(start, 6),
    };
    (text, start)
}

/// Draws `row` for the key `key` (the row's key, or an indexed form of it: `bearing.pads.orifice[1].…`)
/// with the label `label`. Rows the editor's own code draws ([`Widget::Custom`]) draw nothing here.
pub fn row_ui(ui: &mut Ui, doc: &mut Document, values: &Values, row: &KeySpec, key: &str, label: &str) -> EditOutput {
    let Some(editor) = row.editor else { return EditOutput::default() };
    match editor.widget {
        Widget::Number(decimals) => {
            let n = Num { key, label, decimals };
            let value = values.number(key).or_else(|| row.default_in(doc.file())).unwrap_or(0.0);
            number_ui(ui, doc, &n, value, |f, v| write(f, key, Some(as_value(row, v))))
        }
        Widget::Optional(decimals) => {
            let n = Num { key, label, decimals };
            let (text, start) = absent(row, doc.file());
            let current = values.number(key);
            optional_ui(
                ui,
                doc,
                &n,
                current,
                (&text, start),
                |f| read(f, key),
                |f, v| {
                    write(f, key, v.map(|x| as_value(row, x)));
                },
            )
        }
        Widget::Choice(labels) => {
            let Allowed::Choice(words) = row.allowed else { return EditOutput::default() };
            let fallback = match row.default {
                Fallback::Word(w) => w,
                _ => words.first().copied().unwrap_or_default(),
            };
            let current = values.word(key).and_then(|w| words.iter().copied().find(|&x| x == w)).unwrap_or(fallback);
            let options: Vec<(&str, &str)> = words.iter().copied().zip(labels.iter().copied()).collect();
            let pick = Pick { key, label, tip: None };
            choice_ui(ui, doc, pick, current, &options, |f, w| write(f, key, Some(toml::Value::String(w.into()))))
        }
        Widget::Text => {
            let current = values.word(key).unwrap_or_default().to_string();
            text_ui(ui, doc, (key, label), &current, |f, v| write(f, key, v.map(toml::Value::String)))
        }
        Widget::Custom => EditOutput::default(),
    }
}

/// Appends an entry to the array of tables `prefix` (`bearing.pads.orifice`) whose keys are `rows`: each
/// required number at the middle of its typical range, every other key absent (its default applies).
pub fn append_entry(file: &mut CaseFile, prefix: &str, rows: &[&KeySpec]) {
    let Ok(table) = file.to_table() else { return };
    let mut entries = value_at(&table, prefix).and_then(toml::Value::as_array).cloned().unwrap_or_default();
    let mut entry = toml::Table::new();
    for row in rows {
        if let (Fallback::Required, Some((lo, hi)), Some(name)) = (row.default, row.typical, row.key.rsplit('.').next())
        {
            entry.insert(name.to_string(), as_value(row, 0.5 * (lo + hi)));
        }
    }
    entries.push(toml::Value::Table(entry));
    write(file, prefix, Some(toml::Value::Array(entries)));
}
