//! The editor panel: every case value, grouped as an engineer thinks about a bearing, with units,
//! tooltips that explain the physics, and validation messages in place.

mod bearing;
mod hydraulics;
mod limits;
mod operation;
mod thermal;
pub mod widgets;

use egui::{CollapsingHeader, Grid, RichText, Ui};

use super::document::Document;
pub use widgets::EditOutput;

/// The groups, in order: title, function that draws the rows, open by default.
type GroupUi = fn(&mut Ui, &mut Document) -> EditOutput;
const GROUPS: [(&str, GroupUi, bool); 10] = [
    ("Geometry", bearing::geometry_ui, true),
    ("Pads", bearing::pads_ui, true),
    ("Orifices", bearing::orifices_ui, false),
    ("Lubricant", operation::lubricant_ui, false),
    ("Operating point", operation::operating_ui, true),
    ("Physics model", operation::physics_ui, false),
    ("Thermal model", thermal::thermal_ui, false),
    ("Fidelity", operation::fidelity_ui, false),
    ("Hydraulics (controllable bearing)", hydraulics::hydraulics_ui, false),
    ("Design limits", limits::limits_ui, false),
];

/// Draws the editor; returns what changed.
pub fn editor_ui(ui: &mut Ui, doc: &mut Document) -> EditOutput {
    let mut out = Grid::new("title")
        .num_columns(3)
        .show(ui, |ui| operation::text_ui(ui, doc, "title", "Title", |f| f.title.clone(), |f, v| f.title = v))
        .inner;
    if let Err(e) = doc.validation() {
        ui.label(RichText::new(format!("Invalid case: {e}")).color(widgets::ERROR_COLOR))
            .on_hover_text("The views keep showing the last valid result until the case is valid again.");
    }
    for (title, group_ui, open) in GROUPS {
        CollapsingHeader::new(RichText::new(title).strong()).default_open(open).show(ui, |ui| {
            Grid::new(title).num_columns(3).striped(true).spacing([8.0, 4.0]).show(ui, |ui| {
                out.merge(group_ui(ui, doc));
            });
        });
    }
    out
}

#[cfg(test)]
mod tests {
    /// Every case key an editor row names has a schema row (its unit, tooltip and drag range come from
    /// there); only the editor's own choices (how a value is given) have none.
    #[test]
    fn every_editor_key_has_a_schema_row() {
        let sources = [
            include_str!("bearing.rs"),
            include_str!("operation.rs"),
            include_str!("thermal.rs"),
            include_str!("hydraulics.rs"),
            include_str!("limits.rs"),
        ];
        let mut keys = 0;
        for src in sources {
            for part in src.split("key: \"").skip(1) {
                let key = part.split('"').next().unwrap_or_default();
                if matches!(key, "bearing.pads.clearance_input" | "operating.load_mode") {
                    continue;
                }
                assert!(crate::model::schema::spec(key).is_some(), "editor key `{key}` has no schema row");
                keys += 1;
            }
        }
        for key in [
            "hydraulics.port[1].air_fraction",
            "mesh.circumferential_elements",
            "bearing.pads.orifice[0].diameter_mm",
            "title",
            "lubricant.name",
            "bearing.pads.count",
        ] {
            assert!(crate::model::schema::spec(key).is_some(), "{key}");
        }
        assert!(keys > 40, "found only {keys} editor keys");
    }
}
