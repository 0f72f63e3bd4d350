//! The design-limit marks of the results panel: one line when every limit is met (the checks in its
//! tooltip), else one red line per exceeded limit with its value and limit ([`crate::bearing::solution::limits`]).

use egui::{RichText, Ui};

use crate::app::ink;

use crate::bearing::solution::limits::Check;

/// Draws the marks of `checks`.
pub fn limits_ui(ui: &mut Ui, checks: &[Check]) {
    let all: Vec<String> = checks.iter().map(crate::scene::limits::text).collect();
    let tip = format!(
        "Design limits (case section [limits]; unset values are conventions of common practice, see the editor's \
         \"Design limits\" group):\n{}",
        all.join("\n")
    );
    let bad: Vec<&Check> = checks.iter().filter(|c| c.exceeded).collect();
    if bad.is_empty() {
        ui.label(RichText::new("Within the design limits").color(ink::GOOD.of(ui))).on_hover_text(tip);
        return;
    }
    ui.label(RichText::new("Design limits exceeded:").color(ink::EXCEEDED.of(ui)).strong()).on_hover_text(tip);
    for c in bad {
        ui.label(RichText::new(crate::scene::limits::text(c)).color(ink::EXCEEDED.of(ui)));
    }
}
