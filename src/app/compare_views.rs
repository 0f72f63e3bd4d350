//! The views' side of pins: which pin the bearing, pad field and coefficient views compare with (the
//! "Compare with" row above them), and getting that pin's result ([`super::pinned`]).

use egui::{Color32, Ui};

use super::pinned::Pinned;
use super::state::View;
use super::views::field_view::FieldCompare;
use super::{Shown, WorkbenchApp};
use crate::bearing::stages::StageId;

impl WorkbenchApp {
    /// The "Compare with" row (only when there are pins); returns the chosen pin's name and result with the
    /// stages in `needs`, or `None` (no pin chosen, or its result is still being solved: said in the view).
    pub(super) fn compare_with_ui(&mut self, ui: &mut Ui, needs: &[StageId]) -> Option<(String, Shown)> {
        let pins = &self.persisted.pins;
        if pins.is_empty() {
            return None;
        }
        if self.persisted.compare_with.as_ref().is_some_and(|n| !pins.iter().any(|p| p.name == *n)) {
            self.persisted.compare_with = None;
        }
        let fields = self.persisted.view == View::Fields;
        ui.horizontal_wrapped(|ui| {
            let label = ui.label("Compare with");
            let chosen = &mut self.persisted.compare_with;
            egui::ComboBox::from_id_salt("compare-with")
                .selected_text(chosen.clone().unwrap_or_else(|| "no pin".into()))
                .show_ui(ui, |ui| {
                    ui.selectable_value(chosen, None, "no pin");
                    for p in pins {
                        ui.selectable_value(chosen, Some(p.name.clone()), &p.name);
                    }
                })
                .response
                .labelled_by(label.id)
                .on_hover_text("Draw a pinned result with the live one (pin results in the results panel).");
            if fields && chosen.is_some() {
                ui.selectable_value(&mut self.persisted.field_compare, FieldCompare::SideBySide, "side by side");
                ui.selectable_value(&mut self.persisted.field_compare, FieldCompare::Difference, "difference map");
            }
        });
        let name = self.persisted.compare_with.clone()?;
        let pin = pins.iter().find(|p| p.name == name)?.clone();
        match self.pinned.want(&pin, needs) {
            Pinned::Ready(s) => Some((name, s.clone())),
            Pinned::Solving => {
                ui.horizontal(|ui| {
                    ui.spinner();
                    ui.label(format!("Solving the pinned case \"{name}\"…"));
                });
                None
            }
            Pinned::Failed(e) => {
                ui.colored_label(
                    Color32::from_rgb(230, 90, 80),
                    format!("The pinned case \"{name}\" does not solve: {e}"),
                );
                None
            }
        }
    }
}
