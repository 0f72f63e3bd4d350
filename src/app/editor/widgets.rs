//! Editor rows: a label with its physical meaning as tooltip, a value, the unit, and the validation
//! message in place when the case's first error concerns this key.
//!
//! A typed value is taken when the user presses Enter or leaves the field (not at every keystroke, which
//! would start a solve for each intermediate number). Values are not clamped to their sensible range: a user
//! may type anything, and the validation of the case (the same checks as the CLI) says what is wrong, next
//! to the field. The sensible range sets the drag speed and is shown in the tooltip.
//!
//! A row's unit, tooltip (physical meaning, typical and allowed values) and drag range come from the case
//! schema ([`crate::model::schema`]) by key, the same table `tiltpad schema` prints.

use egui::{DragValue, RichText, Ui};

use crate::app::document::Document;
use crate::model::schema::{spec, KeySpec};
use crate::model::CaseFile;
use crate::number::sig;

/// A numeric case value as the editor shows it; unit, meaning and typical range are the schema's.
#[derive(Debug, Clone, Copy)]
pub struct Num<'a> {
    /// Dotted key as written in the case file (a schema key, indices allowed).
    pub key: &'a str,
    pub label: &'a str,
    pub decimals: usize,
}

/// The schema row of a key the editor shows (every editor key has one: a unit test checks them).
fn schema_row(key: &str) -> Option<&'static KeySpec> {
    spec(key)
}

/// The tooltip of a case key: its meaning, typical and allowed values, and the key itself.
#[must_use]
pub fn key_tooltip(key: &str) -> String {
    match schema_row(key) {
        Some(s) => {
            let unit = if s.unit.is_empty() { String::new() } else { format!(" {}", s.unit) };
            let typical = s
                .typical
                .map_or_else(String::new, |(lo, hi)| format!("Typical: {} – {}{unit}\n", sig(lo, 6), sig(hi, 6)));
            format!("{}\n\n{typical}Allowed: {}\nCase key: {key}", s.meaning, s.allowed.describe())
        }
        None => format!("Case key: {key}"),
    }
}

impl Num<'_> {
    /// Unit of the value, as the schema gives it.
    #[must_use]
    pub fn unit(&self) -> &'static str {
        schema_row(self.key).map_or("", |s| s.unit)
    }

    fn tooltip(&self) -> String {
        key_tooltip(self.key)
    }

    /// Drag speed per point at `value`: half a percent of the value, so a drag changes a value by a share
    /// of itself (1918 N moves by about 10 N per point, not the 100 N a 400th of the typical range gave);
    /// at least a 40 000th and at most a 400th of the typical range (values at or near zero still move).
    fn speed(&self, value: f64) -> f64 {
        let (lo, hi) = schema_row(self.key).and_then(|s| s.typical).unwrap_or((0.0, 1.0));
        let span = (hi - lo).abs().max(1e-12);
        (0.005 * value.abs()).clamp(span / 40_000.0, span / 400.0)
    }

    /// A dragged value kept inside the key's allowed range: onto a closed bound, or a drag step inside an
    /// open one (a load drags down to just above 0 N, never below). Typed values are not clamped (the
    /// validation says what is wrong, in place).
    #[must_use]
    pub fn clamp_dragged(&self, value: f64, step: f64) -> f64 {
        let Some(r) = schema_row(self.key).and_then(|s| s.allowed.range()) else { return value };
        let lo = if r.open_lo { r.lo + step.min(0.5 * (r.hi - r.lo)) } else { r.lo };
        let hi = if r.open_hi { r.hi - step.min(0.5 * (r.hi - r.lo)) } else { r.hi };
        if lo <= hi {
            value.clamp(lo, hi)
        } else {
            value
        }
    }
}

/// What the editor did this frame.
#[derive(Debug, Clone, Copy, Default)]
pub struct EditOutput {
    pub changed: bool,
    /// A value is being dragged (the app may solve at preview fidelity meanwhile).
    pub dragging: bool,
    /// A drag ended this frame.
    pub drag_released: bool,
}

impl EditOutput {
    pub fn merge(&mut self, other: Self) {
        self.changed |= other.changed;
        self.dragging |= other.dragging;
        self.drag_released |= other.drag_released;
    }
}

/// The label cell of a row.
pub fn label_ui(ui: &mut Ui, text: &str, tooltip: &str) -> egui::Response {
    ui.label(text).on_hover_text(tooltip)
}

/// The validation message under a row, when the case's error concerns `key`.
pub fn error_row_ui(ui: &mut Ui, doc: &Document, key: &str) {
    if let Some(e) = doc.error_for(key) {
        ui.label("");
        ui.scope(|ui| {
            ui.set_max_width(220.0);
            ui.add(egui::Label::new(RichText::new(format!("{e}")).color(crate::app::ink::ERROR.of(ui)).small()).wrap());
        });
        ui.end_row();
    }
}

/// Paints an error frame around the next widgets when their value is invalid (also the rotor editor's).
pub fn flag_invalid_ui(ui: &mut Ui, invalid: bool) {
    if invalid {
        let error = crate::app::ink::ERROR.of(ui);
        let w = &mut ui.visuals_mut().widgets;
        for s in [&mut w.inactive, &mut w.hovered, &mut w.active] {
            s.bg_stroke = egui::Stroke::new(1.5, error);
        }
    }
}

/// A drag value for `value`, labelled by `label`; returns what happened.
fn drag_ui(
    ui: &mut Ui,
    doc: &mut Document,
    n: &Num<'_>,
    label: egui::Response,
    value: f64,
    set: impl FnOnce(&mut CaseFile, f64),
) -> EditOutput {
    let mut v = value;
    let invalid = doc.error_for(n.key).is_some();
    let r = ui
        .scope(|ui| {
            flag_invalid_ui(ui, invalid);
            ui.add(
                DragValue::new(&mut v)
                    .speed(n.speed(value))
                    .max_decimals(n.decimals)
                    .min_decimals(0)
                    .update_while_editing(false),
            )
        })
        .inner
        .labelled_by(label.id)
        .on_hover_text(n.tooltip());
    let mut out = EditOutput { dragging: r.dragged(), drag_released: r.drag_stopped(), ..EditOutput::default() };
    if r.dragged() {
        v = n.clamp_dragged(v, n.speed(value));
    }
    if r.changed() && v.to_bits() != value.to_bits() {
        let continuing = r.dragged() && !r.drag_started();
        doc.edit(n.key, continuing, |f| set(f, v));
        out.changed = true;
    }
    if r.drag_stopped() {
        doc.end_gesture();
    }
    out
}

/// A required number: label, value, unit, and the error in place.
pub fn number_ui(
    ui: &mut Ui,
    doc: &mut Document,
    n: &Num<'_>,
    value: f64,
    set: impl FnOnce(&mut CaseFile, f64),
) -> EditOutput {
    let label = label_ui(ui, n.label, &n.tooltip());
    let out = drag_ui(ui, doc, n, label, value, set);
    ui.label(n.unit());
    ui.end_row();
    error_row_ui(ui, doc, n.key);
    out
}

/// An optional number: a checkbox gives it a value (starting from `start`); unchecked, the default applies
/// and `absent` says what it is. `current` is the value now; `get` reads it again after the checkbox changed
/// the case.
#[allow(clippy::too_many_arguments)]
pub fn optional_ui(
    ui: &mut Ui,
    doc: &mut Document,
    n: &Num<'_>,
    current: Option<f64>,
    (absent, start): (&str, f64),
    get: impl Fn(&CaseFile) -> Option<f64>,
    set: impl Fn(&mut CaseFile, Option<f64>),
) -> EditOutput {
    let mut on = current.is_some();
    let mut out = EditOutput::default();
    let label = ui
        .horizontal(|ui| {
            // A default given as a number has the unit; one given as a rule ("rigid pivot") has none.
            let numeric = absent.parse::<f64>().is_ok();
            let unit = if n.unit().is_empty() || !numeric { String::new() } else { format!(" {}", n.unit()) };
            if ui
                .checkbox(&mut on, "")
                .on_hover_text(format!("Give {} explicitly (unchecked: {absent}{unit})", n.label))
                .changed()
            {
                let value = on.then(|| current.unwrap_or(start));
                doc.edit(n.key, false, |f| set(f, value));
                out.changed = true;
            }
            label_ui(ui, n.label, &n.tooltip())
        })
        .inner;
    let shown = if out.changed { get(doc.file()) } else { current };
    match shown {
        Some(v) => out.merge(drag_ui(ui, doc, n, label, v, |f, x| set(f, Some(x)))),
        None => {
            ui.label(RichText::new(format!("{absent} (default)")).weak()).labelled_by(label.id);
        }
    }
    ui.label(n.unit());
    ui.end_row();
    error_row_ui(ui, doc, n.key);
    out
}

/// An integer count (pads, elements); `note` adds what the editor does on a change to the schema's tooltip.
pub fn count_ui(
    ui: &mut Ui,
    doc: &mut Document,
    (key, text, note): (&str, &str, &str),
    value: usize,
    set: impl FnOnce(&mut CaseFile, usize),
) -> EditOutput {
    let tip = format!("{}\n\n{note}", key_tooltip(key));
    let label = label_ui(ui, text, &tip);
    let mut v = value;
    let invalid = doc.error_for(key).is_some();
    let r = ui
        .scope(|ui| {
            flag_invalid_ui(ui, invalid);
            ui.add(DragValue::new(&mut v).speed(0.05).update_while_editing(false))
        })
        .inner
        .labelled_by(label.id)
        .on_hover_text(&tip);
    let mut out = EditOutput { dragging: r.dragged(), drag_released: r.drag_stopped(), ..EditOutput::default() };
    if v != value {
        doc.edit(key, r.dragged() && !r.drag_started(), |f| set(f, v));
        out.changed = true;
    }
    ui.label("");
    ui.end_row();
    error_row_ui(ui, doc, key);
    out
}

/// Fields of a per-pad list on one line of its cell.
const PADS_PER_LINE: usize = 2;

/// A list of one number per pad: small fields named "pad k", [`PADS_PER_LINE`] to a line of a grid of
/// its own. (A wrapping row inside the editor's grid let its last line fall over the row below: the
/// outer grid sized the row before the wrap.)
pub fn per_pad_ui(
    ui: &mut Ui,
    doc: &mut Document,
    n: &Num<'_>,
    values: &[f64],
    set: impl Fn(&mut CaseFile, usize, f64),
) -> EditOutput {
    let mut out = EditOutput::default();
    label_ui(ui, n.label, &n.tooltip());
    egui::Grid::new((n.key, "per-pad")).num_columns(2 * PADS_PER_LINE).spacing([4.0, 2.0]).show(ui, |ui| {
        for (k, &value) in values.iter().enumerate() {
            let pad_label = ui.label(format!("pad {k}"));
            out.merge(drag_ui(ui, doc, n, pad_label, value, |f, x| set(f, k, x)));
            if (k + 1) % PADS_PER_LINE == 0 {
                ui.end_row();
            }
        }
    });
    ui.label(n.unit());
    ui.end_row();
    error_row_ui(ui, doc, n.key);
    out
}

/// A choice of the case file: its key (for undo grouping and errors) and label; its meaning is the
/// schema's, or `tip` for a choice that is the editor's own (how a value is given, not a case key).
#[derive(Debug, Clone, Copy)]
pub struct Pick<'a> {
    pub key: &'a str,
    pub label: &'a str,
    pub tip: Option<&'static str>,
}

/// A choice among named options.
pub fn choice_ui<T: PartialEq + Copy>(
    ui: &mut Ui,
    doc: &mut Document,
    pick: Pick<'_>,
    current: T,
    options: &[(T, &str)],
    set: impl FnOnce(&mut CaseFile, T),
) -> EditOutput {
    let Pick { key, label: text, tip } = pick;
    let tip = tip.map_or_else(|| key_tooltip(key), str::to_string);
    let label = label_ui(ui, text, &tip);
    let mut chosen = current;
    let name = options.iter().find(|o| o.0 == current).map_or("?", |o| o.1);
    egui::ComboBox::from_id_salt(key)
        .selected_text(name)
        .show_ui(ui, |ui| {
            for (value, name) in options {
                ui.selectable_value(&mut chosen, *value, *name);
            }
        })
        .response
        .labelled_by(label.id)
        .on_hover_text(&tip);
    let mut out = EditOutput::default();
    if chosen != current {
        doc.edit(key, false, |f| set(f, chosen));
        out.changed = true;
    }
    ui.label("");
    ui.end_row();
    error_row_ui(ui, doc, key);
    out
}

/// Width of a free-text field [points]: the editor's value column at its narrowest.
const TEXT_WIDTH: f32 = 200.0;

/// A free-text row (names and titles); an empty text removes the key.
pub fn text_ui(
    ui: &mut Ui,
    doc: &mut Document,
    (key, label): (&str, &str),
    current: &str,
    set: impl FnOnce(&mut CaseFile, Option<String>),
) -> EditOutput {
    let tip = key_tooltip(key);
    let label = ui.label(label).on_hover_text(&tip);
    let mut text = current.to_string();
    // One line of text that wraps onto as many rows as it needs, so a long title reads whole; Enter
    // ends the edit rather than breaking the line (a key's text is one line).
    let changed = ui
        .add(
            egui::TextEdit::multiline(&mut text)
                .desired_rows(1)
                .desired_width(TEXT_WIDTH)
                // In a grid the first frame offers the cell no width: without a floor the field would
                // wrap the text a few letters a row and keep that width.
                .min_size(egui::vec2(TEXT_WIDTH, 0.0))
                .return_key(None),
        )
        .labelled_by(label.id)
        .on_hover_text(&tip)
        .changed();
    if changed {
        text.retain(|c| c != '\n' && c != '\r');
        doc.edit(key, true, |f| set(f, (!text.is_empty()).then(|| text.clone())));
    }
    ui.label("");
    ui.end_row();
    EditOutput { changed, ..EditOutput::default() }
}
