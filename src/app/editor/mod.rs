//! The editor panel: every case value, grouped as an engineer thinks about a bearing, with units,
//! tooltips that explain the physics, and validation messages in place.
//!
//! The rows are the case's key table ([`crate::model::schema::KEYS`]): each row with an editor entry is drawn
//! in its group, in table order, by its widget ([`rows::row_ui`]), which reads and writes the value under the
//! row's key. A new key therefore appears here without code. What is left here is the editor's own code,
//! listed in `HOOKS`: rows whose widget is `Custom` (lists with one value per pad, choices that change other
//! keys), the entries of arrays of tables (orifices, injection lines), and rows that are not keys (how the
//! pad clearance or the journal position is given).

mod bearing;
mod hydraulics;
mod operation;
pub mod rows;
pub mod widgets;

use egui::{CollapsingHeader, Grid, RichText, Ui};

use super::document::Document;
use crate::model::schema::{Group, KeySpec, Widget, KEYS};
use rows::Values;
pub use widgets::EditOutput;

/// Draws part of a group: rows that are not keys, or a few keys drawn together.
type PartUi = fn(&mut Ui, &mut Document) -> EditOutput;
/// Draws the row of a key whose widget is [`Widget::Custom`].
type CustomUi = fn(&mut Ui, &mut Document, &'static KeySpec) -> EditOutput;
/// Draws every entry of an array of tables, given the rows of its keys (`prefix[].name`, in table order).
type ArrayUi = fn(&mut Ui, &mut Document, &[&'static KeySpec]) -> EditOutput;

/// The editor's own code, by where it goes.
enum Hook {
    /// Draws the row of this key (its widget is `Custom`).
    Custom(&'static str, CustomUi),
    /// Drawn just before the row of this key, whether that row is shown or not.
    Before(&'static str, PartUi),
    /// Draws the array of tables whose keys start with this prefix (`bearing.pads.orifice`).
    Array(&'static str, ArrayUi),
    /// Drawn at the start of a group.
    Start(Group, PartUi),
    /// Drawn at the end of a group.
    End(Group, PartUi),
}

const HOOKS: &[Hook] = &[
    Hook::Custom("bearing.pads.count", bearing::pad_count_ui),
    Hook::Custom("bearing.pads.pivot_deg", bearing::pivots_ui),
    Hook::Before("bearing.pads.preload", bearing::clearance_input_ui),
    Hook::Custom("bearing.pads.massless", bearing::massless_ui),
    Hook::Custom("bearing.pads.pivot_contact", bearing::pivot_contact_ui),
    Hook::End(Group::Pads, bearing::per_pad_note_ui),
    Hook::Array("bearing.pads.orifice", bearing::orifices_ui),
    Hook::Before("operating.load_n", operation::load_mode_ui),
    Hook::Custom("operating.injection_pressure_bar", operation::injection_ui),
    Hook::Custom("operating.pad_supply_flow_l_per_min", operation::pad_supply_ui),
    Hook::Custom("mesh.half_model", operation::half_model_ui),
    Hook::Before("mesh.circumferential_elements", operation::fidelity_note_ui),
    Hook::Start(Group::Hydraulics, hydraulics::absent_ui),
    Hook::Array("hydraulics.port", hydraulics::ports_ui),
];

/// Draws the editor; returns what changed.
pub fn editor_ui(ui: &mut Ui, doc: &mut Document) -> EditOutput {
    let mut out = Grid::new("title").num_columns(3).show(ui, |ui| group_ui(ui, doc, Group::Title)).inner;
    if let Err(e) = doc.validation() {
        ui.label(RichText::new(format!("Invalid case: {e}")).color(crate::app::ink::ERROR.of(ui)))
            .on_hover_text("The views keep showing the last valid result until the case is valid again.");
    }
    for group in Group::SECTIONS {
        let title = group.title();
        CollapsingHeader::new(RichText::new(title).strong()).default_open(group.open()).show(ui, |ui| {
            Grid::new(title).num_columns(3).striped(true).spacing([8.0, 4.0]).show(ui, |ui| {
                out.merge(group_ui(ui, doc, group));
            });
        });
    }
    out
}

/// The rows of `group`, in table order.
fn group_rows(group: Group) -> impl Iterator<Item = &'static KeySpec> {
    KEYS.iter().filter(move |row| row.editor.is_some_and(|e| e.group == group))
}

/// The array prefix of an array-of-tables key (`bearing.pads.orifice[].diameter_mm` → `bearing.pads.orifice`).
fn array_prefix(key: &str) -> Option<&str> {
    key.split_once("[]").map(|(prefix, _)| prefix)
}

/// Draws every row of a group, and the editor's own code where [`HOOKS`] places it.
fn group_ui(ui: &mut Ui, doc: &mut Document, group: Group) -> EditOutput {
    let mut out = EditOutput::default();
    for hook in HOOKS {
        if let Hook::Start(g, part) = hook {
            if *g == group {
                out.merge(part(ui, doc));
            }
        }
    }
    let mut values = Values::of(doc.file());
    let mut arrays_drawn: Vec<&str> = Vec::new();
    for row in group_rows(group) {
        let mut o = EditOutput::default();
        for hook in HOOKS {
            if let Hook::Before(key, part) = hook {
                if *key == row.key {
                    o.merge(part(ui, doc));
                }
            }
        }
        if let Some(prefix) = array_prefix(row.key) {
            if !arrays_drawn.contains(&prefix) {
                arrays_drawn.push(prefix);
                let rows: Vec<&'static KeySpec> = KEYS.iter().filter(|r| array_prefix(r.key) == Some(prefix)).collect();
                if let Some(Hook::Array(_, draw)) =
                    HOOKS.iter().find(|h| matches!(h, Hook::Array(p, _) if *p == prefix))
                {
                    o.merge(draw(ui, doc, &rows));
                }
            }
        } else if let Some(editor) = row.editor.filter(|e| (e.when)(doc.file())) {
            if editor.widget == Widget::Custom {
                if let Some(Hook::Custom(_, draw)) =
                    HOOKS.iter().find(|h| matches!(h, Hook::Custom(k, _) if *k == row.key))
                {
                    o.merge(draw(ui, doc, row));
                }
            } else {
                o.merge(rows::row_ui(ui, doc, &values, row, row.key, editor.label));
            }
        }
        if o.changed {
            values = Values::of(doc.file());
        }
        out.merge(o);
    }
    for hook in HOOKS {
        if let Hook::End(g, part) = hook {
            if *g == group {
                out.merge(part(ui, doc));
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::{array_prefix, Hook, HOOKS};
    use crate::model::schema::{Allowed, Widget, KEYS};

    /// Every row the editor's own code must draw has that code, every hook names a key of the table, and
    /// every choice row has one label per word.
    #[test]
    fn every_custom_row_has_its_code_and_every_hook_its_key() {
        for row in KEYS {
            let Some(editor) = row.editor else { continue };
            match (array_prefix(row.key), editor.widget) {
                (Some(prefix), _) => assert!(
                    HOOKS.iter().any(|h| matches!(h, Hook::Array(p, _) if *p == prefix)),
                    "array `{prefix}` has no code to draw its entries"
                ),
                (None, Widget::Custom) => assert!(
                    HOOKS.iter().any(|h| matches!(h, Hook::Custom(k, _) if *k == row.key)),
                    "`{}` is drawn by the editor's own code, which is missing",
                    row.key
                ),
                (None, Widget::Choice(labels)) => {
                    let Allowed::Choice(words) = row.allowed else {
                        panic!("{}: a choice widget needs words", row.key)
                    };
                    assert_eq!(labels.len(), words.len(), "{}: one label per word", row.key);
                }
                _ => {}
            }
        }
        for hook in HOOKS {
            let key = match hook {
                Hook::Custom(k, _) | Hook::Before(k, _) => *k,
                Hook::Array(prefix, _) => {
                    assert!(KEYS.iter().any(|r| array_prefix(r.key) == Some(prefix)), "no rows for array `{prefix}`");
                    continue;
                }
                Hook::Start(..) | Hook::End(..) => continue,
            };
            let row = KEYS.iter().find(|r| r.key == key).unwrap_or_else(|| panic!("hook for unknown key `{key}`"));
            assert!(row.editor.is_some(), "hook for `{key}`, which has no editor row");
            if matches!(hook, Hook::Custom(..)) {
                assert_eq!(row.editor.map(|e| e.widget), Some(Widget::Custom), "`{key}` is not a custom row");
            }
        }
    }
}
