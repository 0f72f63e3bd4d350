//! The views' side of pins: which pin the bearing, pad field and coefficient views compare with (the
//! "Compare with" row above them), and getting that pin's result ([`super::pinned`]).

use egui::{Color32, Ui};

use super::pinned::Pinned;
use super::views::view::ViewContext;
use super::Shown;
use crate::bearing::stages::StageId;

impl ViewContext<'_> {
    /// The "Compare with" row (only when there are pins), with the view's own options for the comparison
    /// (`extra`, drawn in the row once a pin is chosen); returns the chosen pin's name and result with the
    /// stages in `needs`, or `None` (no pin chosen, or its result is still being solved: said in the view).
    pub fn compare_with_ui(
        &mut self,
        ui: &mut Ui,
        needs: &[StageId],
        extra: impl FnOnce(&mut Ui),
    ) -> Option<(String, Shown)> {
        let pins = self.pins;
        if pins.is_empty() {
            return None;
        }
        if self.compare_with.as_ref().is_some_and(|n| !pins.iter().any(|p| p.name == *n)) {
            *self.compare_with = None;
        }
        ui.horizontal_wrapped(|ui| {
            let label = ui.label("Compare with");
            let chosen = &mut *self.compare_with;
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
            if chosen.is_some() {
                extra(ui);
            }
        });
        let name = self.compare_with.clone()?;
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
