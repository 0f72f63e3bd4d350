//! Editing the rotor from its sketch, as the case editor edits the bearing: a click on the sketch selects a
//! shaft section, a disk, a bearing or an unbalance ([`Selected`]); its values are edited in a row under the
//! sketch, each labelled with its unit, with the rotor-file schema's meaning, allowed values and key as
//! tooltip ([`crate::model::rotor_schema`]); disks and unbalances are added and removed; shaft sections are
//! split, appended at either end and removed, entries on removed nodes moving to the nearest remaining node
//! with a notice naming each ([`crate::model::rotor_sections`]); a bearing position given by numbers shows
//! its K, C rows (and their speeds) for editing; the rotor file is saved with its comments, order and number
//! style kept ([`crate::model::edit::write_preserving`]).
//!
//! Contract (the case editor's): a typed value is kept in the edited [`RotorFile`] whatever it is; the file
//! is validated after every edit by the same checks as the CLI ([`RotorFile::resolve`], bearing cases at
//! preview fidelity); an invalid value is framed in red with the message (key, value, allowed range) and the
//! view keeps the last valid rotor and its analysis until the file is valid again. Every valid edit bumps
//! [`RotorEdit::revision`], which re-runs the analysis in the rotor worker.

use std::path::{Path, PathBuf};

use egui::{DragValue, RichText, Ui};

use crate::app::presets::PRESETS;
use crate::model::edit::write_preserving;
use crate::model::rotor::{parse_rotor_file, DiskTable, Rotor, RotorFile, UnbalanceTable};
use crate::model::rotor_schema::ROTOR_KEYS;
use crate::model::rotor_sections::{append_section, remove_section, split_section, ShaftEnd};
use crate::model::CaseError;

use super::super::editor::widgets::flag_invalid_ui;
use crate::app::ink;

/// What is selected on the sketch: an entry of the rotor file's tables, by index.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Selected {
    Section(usize),
    Disk(usize),
    Bearing(usize),
    Unbalance(usize),
}

/// A save the view asks for: the suggested file name and the rotor file's text.
#[derive(Debug, Clone)]
pub struct SaveRequest {
    pub name: String,
    pub text: String,
}

/// The rotor being edited.
pub struct RotorEdit {
    pub name: String,
    /// Where the rotor file is (native): its bearing cases are read from beside it.
    path: Option<PathBuf>,
    /// The text the rotor was read from (comments kept on save).
    source: String,
    file: RotorFile,
    pub selected: Option<Selected>,
    /// Why the edited file is invalid, if it is.
    error: Option<CaseError>,
    /// The last valid rotor (bearing cases at preview fidelity), and its file.
    valid: Rotor,
    valid_file: RotorFile,
    /// Counts valid edits.
    pub revision: usize,
    /// What the last section change did besides itself (entries moved off removed nodes), or why it was
    /// refused.
    notice: Option<String>,
}

/// Resolves `file` with its bearing cases at preview fidelity, read from beside `path` (native) or among
/// the shipped cases.
fn resolve_preview(file: &RotorFile, path: Option<&Path>) -> Result<Rotor, CaseError> {
    let mut file = file.clone();
    for b in &mut file.rotor.bearing {
        if b.case.is_some() {
            b.set.push("mesh.fidelity=\"preview\"".into());
        }
    }
    let dir = path.and_then(Path::parent).map(Path::to_path_buf);
    let read = |name: &str| {
        #[cfg(not(target_arch = "wasm32"))]
        if let Some(d) = &dir {
            return std::fs::read_to_string(d.join(name)).map_err(|e| format!("{}: {e}", d.join(name).display()));
        }
        let _ = &dir;
        let base = name.rsplit('/').next().unwrap_or(name);
        PRESETS
            .iter()
            .find(|(n, _)| *n == base)
            .map(|(_, t)| (*t).to_string())
            .ok_or_else(|| format!("{name}: not a shipped case"))
    };
    file.resolve(&read)
}

/// The schema row of an indexed key (`rotor.disk[2].mass_kg` → `rotor.disk[].mass_kg`; a row of a list,
/// `rotor.bearing[0].k_n_per_m[1]`, → `rotor.bearing[].k_n_per_m`): unit and tooltip.
fn schema(key: &str) -> (&'static str, String) {
    let generic = match (key.find('['), key.find(']')) {
        (Some(a), Some(b)) if a < b => format!("{}[]{}", &key[..a], &key[b + 1..]),
        _ => key.to_string(),
    };
    let generic = match generic.rfind('[') {
        Some(a) if generic.ends_with(']') && a + 2 < generic.len() => generic[..a].to_string(),
        _ => generic,
    };
    ROTOR_KEYS.iter().find(|s| s.key == generic).map_or(("", format!("Rotor key: {key}")), |s| {
        (s.unit, format!("{}\n\nAllowed: {}\nRotor key: {key}", s.meaning, s.allowed.describe()))
    })
}

impl RotorEdit {
    /// The rotor file `name` read from `text` (bearing cases beside `path`).
    ///
    /// # Errors
    /// The file's syntax or validation error (the key, the value and the allowed range).
    pub fn open(name: &str, path: Option<&Path>, text: &str) -> Result<Self, String> {
        let file = parse_rotor_file(text).map_err(|e| e.to_string())?;
        let valid = resolve_preview(&file, path).map_err(|e| e.to_string())?;
        Ok(Self {
            name: name.to_string(),
            path: path.map(Path::to_path_buf),
            source: text.to_string(),
            valid_file: file.clone(),
            file,
            selected: None,
            error: None,
            valid,
            revision: 0,
            notice: None,
        })
    }

    /// The last valid rotor.
    #[must_use]
    pub fn rotor(&self) -> &Rotor {
        &self.valid
    }

    /// The rotor as edited (its last valid file) with every bearing position that names a bearing case on the
    /// case `case_text` instead (each position's own `set` overrides kept; `preview`: at preview fidelity);
    /// positions given by numbers stay.
    ///
    /// # Errors
    /// The rotor file does not resolve with that case (a key, a value and its range).
    pub fn on_case(&self, case_text: &str, preview: bool) -> Result<Rotor, CaseError> {
        let mut file = self.valid_file.clone();
        if preview {
            for b in &mut file.rotor.bearing {
                if b.case.is_some() {
                    b.set.push("mesh.fidelity=\"preview\"".into());
                }
            }
        }
        file.resolve(&|_| Ok(case_text.to_string()))
    }

    /// Whether any bearing position names a bearing case (the rotor can run on the edited one).
    #[must_use]
    pub fn has_bearing_cases(&self) -> bool {
        self.valid_file.rotor.bearing.iter().any(|b| b.case.is_some())
    }

    /// The nodes of the bearing positions that name a bearing case.
    #[must_use]
    pub fn case_nodes(&self) -> Vec<usize> {
        self.valid_file.rotor.bearing.iter().filter(|b| b.case.is_some()).map(|b| b.node).collect()
    }

    /// The rotor file as edited.
    #[must_use]
    pub fn file(&self) -> &RotorFile {
        &self.file
    }

    /// Why the edited file is invalid (the analysis shown is of the last valid rotor).
    #[must_use]
    pub fn error(&self) -> Option<&CaseError> {
        self.error.as_ref()
    }

    /// The rotor file as TOML: the text it was read from with the edited values written in.
    ///
    /// # Errors
    /// A value TOML cannot hold.
    pub fn text(&self) -> Result<String, CaseError> {
        write_preserving(&self.file, &self.source)
    }

    /// Applies an edit and validates the file; a valid one becomes the rotor analysed.
    pub fn apply(&mut self, f: impl FnOnce(&mut RotorFile)) {
        let before = self.file.clone();
        f(&mut self.file);
        if self.file == before {
            return;
        }
        match resolve_preview(&self.file, self.path.as_deref()) {
            Ok(r) => {
                self.valid = r;
                self.valid_file = self.file.clone();
                self.error = None;
                self.revision += 1;
            }
            Err(e) => self.error = Some(e),
        }
    }

    /// What the last section change moved (or why it was refused).
    #[must_use]
    pub fn notice(&self) -> Option<&str> {
        self.notice.as_deref()
    }

    /// Splits the selected section, appends one at an end or removes the selected one
    /// ([`crate::model::rotor_sections`]); the selection follows (none after a removal), and the entries
    /// moved off removed nodes, or the refusal, become the notice.
    pub fn change_sections(&mut self, change: SectionChange) {
        let mut notice = None;
        let mut selected = self.selected;
        self.apply(|f| match change {
            SectionChange::Split(i) => match split_section(&mut f.rotor, i) {
                Ok(_) => selected = Some(Selected::Section(i)),
                Err(e) => notice = Some(e.to_string()),
            },
            SectionChange::Append(end) => selected = Some(Selected::Section(append_section(&mut f.rotor, end))),
            SectionChange::Remove(i) => match remove_section(&mut f.rotor, i) {
                Ok(moved) => {
                    selected = None;
                    if !moved.is_empty() {
                        let list: Vec<String> = moved.iter().map(ToString::to_string).collect();
                        notice = Some(format!("Removed rotor.section[{i}]; {}.", list.join(", ")));
                    }
                }
                Err(e) => notice = Some(e.to_string()),
            },
        });
        self.selected = selected;
        self.notice = notice;
    }

    /// The section (rotor-file table index) of every element of the last valid rotor.
    #[must_use]
    pub fn section_of_elements(&self) -> Vec<usize> {
        self.file.rotor.section.iter().enumerate().flat_map(|(i, s)| std::iter::repeat_n(i, s.elements)).collect()
    }

    /// The node of the selection (a section: its first node).
    fn selected_node(&self) -> Option<usize> {
        let r = &self.file.rotor;
        match self.selected? {
            Selected::Section(i) => Some(r.section.iter().take(i).map(|s| s.elements).sum()),
            Selected::Disk(i) => r.disk.get(i).map(|d| d.node),
            Selected::Bearing(i) => r.bearing.get(i).map(|b| b.node),
            Selected::Unbalance(i) => r.unbalance.get(i).map(|u| u.node),
        }
    }

    /// Is `key` (or one of its elements) the invalid one?
    fn invalid(&self, key: &str) -> bool {
        self.error.as_ref().and_then(CaseError::key).is_some_and(|k| k == key)
    }
}

/// A change of the shaft sections.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SectionChange {
    Split(usize),
    Append(ShaftEnd),
    Remove(usize),
}

/// Starts a new row of the wrapping strip when a label and its field, showing `shown`, would not both fit
/// on this one. egui wraps each widget on its own, and a field inside a scope not at all: at 1280×720 the
/// last field of a row ("C yy") ran past the view's edge.
fn keep_with_label_ui(ui: &mut Ui, label: &str, shown: &str) {
    let width = |text: &str, style: egui::TextStyle| {
        egui::WidgetText::from(text).into_galley(ui, Some(egui::TextWrapMode::Extend), f32::INFINITY, style).size().x
    };
    let spacing = ui.spacing();
    let field = (width(shown, egui::TextStyle::Button) + 2.0 * spacing.button_padding.x).max(spacing.interact_size.x);
    let needed = width(label, egui::TextStyle::Body) + spacing.item_spacing.x + field;
    let at_row_start = ui.cursor().min.x <= ui.max_rect().min.x + 0.5;
    if !at_row_start && ui.available_size_before_wrap().x < needed {
        ui.end_row();
    }
}

/// A number of the rotor file: label with its unit, value; the edit is applied when it changed.
fn number_ui(
    ui: &mut Ui,
    edit: &mut RotorEdit,
    key: &str,
    label: &str,
    value: f64,
    set: impl FnOnce(&mut RotorFile, f64),
) {
    let (unit, tip) = schema(key);
    let text = if unit.is_empty() || unit == "–" { label.to_string() } else { format!("{label} [{unit}]") };
    let speed = (value.abs() * 0.005).max(1e-3);
    // The decimals the field shows (egui's rule for a drag value of this speed).
    #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
    let decimals = (f64::from(ui.input(egui::InputState::aim_radius)) / speed).log10().ceil().clamp(0.0, 6.0) as usize;
    let shown = ui.style().number_formatter.format(value, decimals..=6);
    keep_with_label_ui(ui, &text, &shown);
    let l = ui.add(egui::Label::new(text).extend()).on_hover_text(&tip);
    let mut v = value;
    let r = ui
        .scope(|ui| {
            flag_invalid_ui(ui, edit.invalid(key));
            ui.add(DragValue::new(&mut v).speed(speed).max_decimals(6).update_while_editing(false))
        })
        .inner
        .labelled_by(l.id)
        .on_hover_text(&tip);
    if r.changed() && v.to_bits() != value.to_bits() {
        edit.apply(|f| set(f, v));
    }
}

/// An integer of the rotor file (a node, a number of elements).
fn integer_ui(
    ui: &mut Ui,
    edit: &mut RotorEdit,
    key: &str,
    label: &str,
    value: usize,
    set: impl FnOnce(&mut RotorFile, usize),
) {
    let (_, tip) = schema(key);
    keep_with_label_ui(ui, label, &value.to_string());
    let l = ui.add(egui::Label::new(label).extend()).on_hover_text(&tip);
    let mut v = value;
    let r = ui
        .scope(|ui| {
            flag_invalid_ui(ui, edit.invalid(key));
            ui.add(DragValue::new(&mut v).speed(0.1).update_while_editing(false))
        })
        .inner
        .labelled_by(l.id)
        .on_hover_text(&tip);
    if r.changed() && v != value {
        edit.apply(|f| set(f, v));
    }
}

/// The selected item's values in one row.
fn selected_ui(ui: &mut Ui, edit: &mut RotorEdit, selected: Selected) {
    let r = edit.file.rotor.clone();
    match selected {
        Selected::Section(i) => {
            let Some(s) = r.section.get(i) else { return };
            ui.label(RichText::new(format!("Shaft section {}", i + 1)).strong());
            let k = |name: &str| format!("rotor.section[{i}].{name}");
            number_ui(ui, edit, &k("length_mm"), "length", s.length_mm, move |f, v| f.rotor.section[i].length_mm = v);
            number_ui(ui, edit, &k("outer_diameter_mm"), "outer diameter", s.outer_diameter_mm, move |f, v| {
                f.rotor.section[i].outer_diameter_mm = v
            });
            number_ui(ui, edit, &k("inner_diameter_mm"), "inner diameter", s.inner_diameter_mm, move |f, v| {
                f.rotor.section[i].inner_diameter_mm = v
            });
            integer_ui(ui, edit, &k("elements"), "elements", s.elements, move |f, v| f.rotor.section[i].elements = v);
        }
        Selected::Disk(i) => {
            let Some(d) = r.disk.get(i) else { return };
            ui.label(RichText::new(format!("Disk {}", i + 1)).strong());
            let k = |name: &str| format!("rotor.disk[{i}].{name}");
            integer_ui(ui, edit, &k("node"), "node", d.node, move |f, v| f.rotor.disk[i].node = v);
            number_ui(ui, edit, &k("mass_kg"), "mass", d.mass_kg, move |f, v| f.rotor.disk[i].mass_kg = v);
            number_ui(ui, edit, &k("polar_inertia_kg_m2"), "polar inertia", d.polar_inertia_kg_m2, move |f, v| {
                f.rotor.disk[i].polar_inertia_kg_m2 = v
            });
            number_ui(
                ui,
                edit,
                &k("transverse_inertia_kg_m2"),
                "transverse inertia",
                d.transverse_inertia_kg_m2,
                move |f, v| f.rotor.disk[i].transverse_inertia_kg_m2 = v,
            );
        }
        Selected::Bearing(i) => {
            let Some(b) = r.bearing.get(i) else { return };
            ui.label(RichText::new(format!("Bearing {}", i + 1)).strong());
            integer_ui(ui, edit, &format!("rotor.bearing[{i}].node"), "node", b.node, move |f, v| {
                f.rotor.bearing[i].node = v
            });
            match &b.case {
                Some(c) => {
                    ui.label(RichText::new(format!("bearing case {c} (edit it in the bearing editor)")).weak());
                }
                None => numbers_ui(ui, edit, i, b),
            }
        }
        Selected::Unbalance(i) => {
            let Some(u) = r.unbalance.get(i) else { return };
            ui.label(RichText::new(format!("Unbalance {}", i + 1)).strong());
            let k = |name: &str| format!("rotor.unbalance[{i}].{name}");
            integer_ui(ui, edit, &k("node"), "node", u.node, move |f, v| f.rotor.unbalance[i].node = v);
            number_ui(ui, edit, &k("amount_g_mm"), "amount", u.amount_g_mm, move |f, v| {
                f.rotor.unbalance[i].amount_g_mm = v
            });
            number_ui(ui, edit, &k("phase_deg"), "phase", u.phase_deg, move |f, v| f.rotor.unbalance[i].phase_deg = v);
        }
    }
}

/// A bearing position's coefficients given by numbers: per row (one per speed, or one), its speed, then
/// K and C as [xx, xy, yx, yy]. Labels name the entry (`K xy`) and, for tabulated rows, the row's speed.
fn numbers_ui(ui: &mut Ui, edit: &mut RotorEdit, i: usize, b: &crate::model::rotor::BearingTable) {
    const ENTRIES: [&str; 4] = ["xx", "xy", "yx", "yy"];
    let rows = b.k_n_per_m.len().max(b.c_ns_per_m.len());
    for j in 0..rows {
        let row =
            |name: &str| if b.speeds_rpm.is_empty() { name.to_string() } else { format!("{name} (row {})", j + 1) };
        ui.end_row();
        if let Some(&s) = b.speeds_rpm.get(j) {
            number_ui(ui, edit, &format!("rotor.bearing[{i}].speeds_rpm[{j}]"), &row("speed"), s, move |f, v| {
                f.rotor.bearing[i].speeds_rpm[j] = v
            });
        }
        for (e, name) in ENTRIES.iter().enumerate() {
            if let Some(k) = b.k_n_per_m.get(j) {
                number_ui(
                    ui,
                    edit,
                    &format!("rotor.bearing[{i}].k_n_per_m[{j}]"),
                    &row(&format!("K {name}")),
                    k[e],
                    move |f, v| f.rotor.bearing[i].k_n_per_m[j][e] = v,
                );
            }
        }
        for (e, name) in ENTRIES.iter().enumerate() {
            if let Some(c) = b.c_ns_per_m.get(j) {
                number_ui(
                    ui,
                    edit,
                    &format!("rotor.bearing[{i}].c_ns_per_m[{j}]"),
                    &row(&format!("C {name}")),
                    c[e],
                    move |f, v| f.rotor.bearing[i].c_ns_per_m[j][e] = v,
                );
            }
        }
    }
}

/// Buttons that change the shaft sections: split and remove the selected one, append at either end.
fn sections_ui(ui: &mut Ui, edit: &mut RotorEdit) {
    if let Some(Selected::Section(i)) = edit.selected {
        if ui
            .button("Split section")
            .on_hover_text(
                "Two sections in its place, the elements shared between them (one element: two of half the length)",
            )
            .clicked()
        {
            edit.change_sections(SectionChange::Split(i));
        }
        let tip = "Removes the section; disks, unbalances, bearings and supports on its nodes move to the nearest remaining node (listed under the strip)";
        if ui
            .add_enabled(edit.file.rotor.section.len() > 1, egui::Button::new("Remove section"))
            .on_hover_text(tip)
            .on_disabled_hover_text("The only shaft section")
            .clicked()
        {
            edit.change_sections(SectionChange::Remove(i));
        }
    }
    let tip = |end: &str| {
        format!(
            "A {} mm section with the diameters of the {end} section",
            crate::model::rotor_sections::APPENDED_LENGTH_MM
        )
    };
    if ui.button("Add section at start").on_hover_text(tip("first")).clicked() {
        edit.change_sections(SectionChange::Append(ShaftEnd::Start));
    }
    if ui.button("Add section at end").on_hover_text(tip("last")).clicked() {
        edit.change_sections(SectionChange::Append(ShaftEnd::End));
    }
}

/// The editing strip under the sketch: the selection's values, add/remove, save; the validation message.
/// Returns a save the user asked for.
pub fn edit_ui(ui: &mut Ui, edit: &mut RotorEdit) -> Option<SaveRequest> {
    let mut save = None;
    ui.horizontal_wrapped(|ui| {
        match edit.selected {
            Some(s) => selected_ui(ui, edit, s),
            None => {
                ui.label(RichText::new("Click a shaft section, disk, bearing or unbalance (red dot) in the sketch to edit it.").weak());
            }
        }
        ui.separator();
        let node = edit.selected_node().unwrap_or(edit.valid.n_nodes() / 2);
        if ui.button("Add disk").on_hover_text(format!("A 10 kg disk at node {node} (the selection's node)")).clicked() {
            edit.apply(|f| f.rotor.disk.push(DiskTable { node, mass_kg: 10.0, polar_inertia_kg_m2: 0.0, transverse_inertia_kg_m2: 0.0 }));
            edit.selected = Some(Selected::Disk(edit.file.rotor.disk.len() - 1));
        }
        if ui.button("Add unbalance").on_hover_text(format!("100 g·mm at node {node} (the selection's node)")).clicked() {
            edit.apply(|f| f.rotor.unbalance.push(UnbalanceTable { node, amount_g_mm: 100.0, phase_deg: 0.0 }));
            edit.selected = Some(Selected::Unbalance(edit.file.rotor.unbalance.len() - 1));
        }
        sections_ui(ui, edit);
        match edit.selected {
            Some(Selected::Disk(i)) if ui.button("Remove disk").clicked() => {
                edit.apply(|f| {
                    f.rotor.disk.remove(i);
                });
                edit.selected = None;
            }
            Some(Selected::Unbalance(i)) if ui.button("Remove unbalance").clicked() => {
                edit.apply(|f| {
                    f.rotor.unbalance.remove(i);
                });
                edit.selected = None;
            }
            _ => {}
        }
        if ui.button("Save rotor…").on_hover_text("Write the rotor file (comments kept); an existing file is replaced only after you confirm. Bearing case paths are relative to the rotor file.").clicked() {
            match edit.text() {
                Ok(text) => save = Some(SaveRequest { name: edit.name.clone(), text }),
                Err(e) => edit.error = Some(e),
            }
        }
    });
    if let Some(n) = &edit.notice {
        ui.label(RichText::new(n).weak());
    }
    if let Some(e) = &edit.error {
        ui.label(
            RichText::new(format!("Invalid rotor: {e}. The sketch and results are of the last valid rotor."))
                .color(ink::ERROR.of(ui)),
        );
    }
    save
}

#[cfg(test)]
mod tests {
    use super::*;

    const ROTOR: &str = include_str!("../../../cases/rotors/compressor-rotor.toml");

    #[test]
    fn an_invalid_edit_is_kept_and_named_and_the_last_valid_rotor_stays() {
        let mut e = RotorEdit::open("compressor-rotor.toml", None, ROTOR).unwrap();
        let mass = e.rotor().mass();
        e.apply(|f| f.rotor.disk[3].mass_kg = -1.0);
        assert_eq!(e.file().rotor.disk[3].mass_kg, -1.0, "the typed value is kept");
        let msg = e.error().unwrap().to_string();
        assert!(msg.contains("rotor.disk[3].mass_kg") && msg.contains("-1") && msg.contains("[0, 1000000]"), "{msg}");
        assert_eq!((e.rotor().mass(), e.revision), (mass, 0));
        e.apply(|f| f.rotor.disk[3].mass_kg = 92.0);
        assert!(e.error().is_none());
        assert!((e.rotor().mass() - mass - 46.0).abs() < 1e-9 * mass);
        assert_eq!(e.revision, 1);
    }

    #[test]
    fn a_saved_rotor_changes_only_the_edited_value_and_reads_back() {
        let mut e = RotorEdit::open("compressor-rotor.toml", None, ROTOR).unwrap();
        e.apply(|f| f.rotor.disk[3].mass_kg = 92.5);
        let text = e.text().unwrap();
        let changed: Vec<(&str, &str)> = ROTOR.lines().zip(text.lines()).filter(|(a, b)| a != b).collect();
        assert_eq!(ROTOR.lines().count(), text.lines().count());
        assert_eq!(changed, vec![("mass_kg = 46.0", "mass_kg = 92.5")]);
        assert_eq!(parse_rotor_file(&text).unwrap(), *e.file());
    }

    #[test]
    fn schema_rows_give_units_of_indexed_keys() {
        assert_eq!(schema("rotor.disk[12].mass_kg").0, "kg");
        assert_eq!(schema("rotor.unbalance[0].amount_g_mm").0, "g·mm");
        assert!(schema("rotor.section[3].outer_diameter_mm").1.contains("Allowed: (0, 10000]"));
        assert_eq!(schema("rotor.bearing[2].k_n_per_m[1]").0, "N/m");
        assert_eq!(schema("rotor.bearing[0].speeds_rpm[0]").0, "rpm");
    }

    #[test]
    fn removing_the_coupling_stub_moves_the_hub_and_its_unbalance_and_says_so() {
        // Section 0 (210 mm, Ø 101.6 mm, nodes 0–7): the coupling hub (disk 0) and the coupling unbalance
        // (unbalance 1) sit on its free end; bearing 1 sits on node 7, which section 1 keeps.
        let mut e = RotorEdit::open("compressor-rotor.toml", None, ROTOR).unwrap();
        let mass = e.rotor().mass();
        e.selected = Some(Selected::Section(0));
        e.change_sections(SectionChange::Remove(0));
        assert!(e.error().is_none());
        assert_eq!(e.notice(), Some("Removed rotor.section[0]; rotor.disk[0] (on removed node 0) now at node 0, rotor.unbalance[1] (on removed node 0) now at node 0."));
        let r = &e.file().rotor;
        assert_eq!((r.bearing[0].node, r.bearing[1].node, r.disk[1].node), (0, 42, 9));
        let stub = 7850.0 * std::f64::consts::PI / 4.0 * 0.1016_f64.powi(2) * 0.21;
        assert!((mass - e.rotor().mass() - stub).abs() < 1e-9 * mass, "{mass} − {} ≠ {stub}", e.rotor().mass());
        assert_eq!((e.selected, e.revision), (None, 1));
        // Down to one section, the last one is refused and nothing changes.
        for _ in 0..3 {
            e.change_sections(SectionChange::Remove(0));
        }
        let before = e.file().clone();
        e.change_sections(SectionChange::Remove(0));
        assert_eq!(e.notice(), Some("rotor.section[0] is the only shaft section; a rotor needs at least one"));
        assert_eq!((e.file(), e.revision), (&before, 4));
    }
}
