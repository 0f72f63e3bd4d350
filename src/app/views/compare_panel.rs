//! The "Compare" part of the results panel: pin the current result under a name (several pins, kept
//! across restarts with the persisted settings), and for each pin the live and pinned values of every
//! output column side by side with their differences ([`crate::scene::compare`]).

use egui::{Color32, Grid, RichText, Ui};

use crate::bearing::Solution;
use crate::scene::compare::{compare, pin_name, Pin};
use crate::scene::summary::sig4;

/// What the panel asks the app to do.
pub enum CompareAction {
    /// Export the pins and the live result as CSV.
    ExportCsv(String),
    /// The live result was pinned (the last pin).
    Pinned,
}

fn value(v: Option<f64>) -> String {
    v.map_or_else(|| "—".into(), sig4)
}

/// Draws the panel; `case_toml` is the edited case's text (stored with a new pin).
pub fn compare_ui(ui: &mut Ui, pins: &mut Vec<Pin>, live: &Solution, case_toml: Option<&str>) -> Option<CompareAction> {
    let mut action = None;
    egui::CollapsingHeader::new(RichText::new("Compare with pinned results").strong()).default_open(true).show(ui, |ui| {
        let id = ui.make_persistent_id("pin-name");
        let error_id = ui.make_persistent_id("pin-name-error");
        let mut name = ui.data_mut(|d| d.get_temp::<String>(id)).unwrap_or_default();
        let mut error = ui.data_mut(|d| d.get_temp::<String>(error_id));
        ui.horizontal(|ui| {
            let label = ui.label("Pin name");
            let hint = pin_name("", pins).unwrap_or_default();
            if ui.add(egui::TextEdit::singleline(&mut name).desired_width(120.0).hint_text(hint)).labelled_by(label.id).changed() {
                error = None;
            }
            if ui.button("Pin current result").on_hover_text("Keep this result as a named reference; the panel then shows live and pinned values with their differences.").clicked() {
                // Names pick pins in the views and name the rows of the export: refuse an ambiguous one.
                match pin_name(&name, pins) {
                    Ok(n) => {
                        pins.push(Pin::new(&n, case_toml.unwrap_or_default(), live));
                        action = Some(CompareAction::Pinned);
                        (name, error) = (String::new(), None);
                    }
                    Err(e) => error = Some(e.to_string()),
                }
            }
        });
        if let Some(e) = &error {
            ui.colored_label(ui.visuals().error_fg_color, e);
        }
        ui.data_mut(|d| {
            d.insert_temp(id, name);
            match error {
                Some(e) => {
                    d.insert_temp(error_id, e);
                }
                None => d.remove::<String>(error_id),
            }
        });
        if pins.is_empty() {
            return;
        }
        if ui.button("Export pins and live result as CSV").clicked() {
            action = Some(CompareAction::ExportCsv(crate::scene::compare::pins_csv(pins, Some(live))));
        }
        let mut remove = None;
        for (k, pin) in pins.iter().enumerate() {
            ui.separator();
            ui.horizontal(|ui| {
                ui.label(RichText::new(format!("Live vs \"{}\"", pin.name)).strong());
                if ui.small_button(format!("Remove \"{}\"", pin.name)).clicked() {
                    remove = Some(k);
                }
            });
            Grid::new(("compare", k)).num_columns(5).striped(true).show(ui, |ui| {
                for h in ["quantity", "live", "pinned", "Δ", "Δ %"] {
                    ui.label(RichText::new(h).small());
                }
                ui.end_row();
                for r in compare(live, pin) {
                    ui.label(if r.unit.is_empty() { r.label.clone() } else { format!("{} [{}]", r.label, r.unit) });
                    ui.label(RichText::new(value(r.live)).monospace());
                    ui.label(RichText::new(value(r.pinned)).monospace());
                    let changed = r.difference.is_some_and(|d| d != 0.0);
                    let color = if changed { Color32::from_rgb(240, 200, 90) } else { ui.visuals().weak_text_color() };
                    ui.label(RichText::new(value(r.difference)).monospace().color(color));
                    ui.label(RichText::new(r.relative.map_or_else(|| "—".into(), |x| format!("{:+.1}", 100.0 * x))).monospace().color(color));
                    ui.end_row();
                }
            });
        }
        if let Some(k) = remove {
            pins.remove(k);
        }
    });
    action
}
