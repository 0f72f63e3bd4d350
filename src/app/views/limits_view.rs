//! The design-limit marks of the results panel: one line when every limit is met (the checks in its
//! tooltip), else one red line per exceeded limit with its value and limit ([`crate::bearing::solution::limits`]).

use egui::{Color32, RichText, Ui};

use crate::bearing::solution::limits::Check;

pub const EXCEEDED: Color32 = Color32::from_rgb(235, 70, 60);

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
        ui.label(RichText::new("Within the design limits").color(Color32::from_rgb(120, 200, 120))).on_hover_text(tip);
        return;
    }
    ui.label(RichText::new("Design limits exceeded:").color(EXCEEDED).strong()).on_hover_text(tip);
    for c in bad {
        ui.label(RichText::new(crate::scene::limits::text(c)).color(EXCEEDED));
    }
}
