//! The editor's own code for the controllable bearing's hydraulics (`[hydraulics]`): the note when the case
//! has no such section, and one block per injection line (port). The supply, valve and rig rows are drawn
//! from the key table; each line's rows too, under its header, which shows the line's valve port and pads
//! (edited in the case file: a list editor would hide which pad is which).

use egui::{RichText, Ui};

use super::rows::{row_ui, Values};
use super::widgets::{label_ui, EditOutput};
use crate::app::document::Document;
use crate::model::hydraulics::ValvePort;
use crate::model::schema::KeySpec;

/// The note shown instead of the rows when the case has no `[hydraulics]`.
pub fn absent_ui(ui: &mut Ui, doc: &mut Document) -> EditOutput {
    if doc.file().hydraulics.is_none() {
        ui.label(
            RichText::new(
                "No [hydraulics] section: a passive bearing. The shipped \"Test rig, Publ. 5\" case has one.",
            )
            .weak(),
        );
        ui.end_row();
    }
    EditOutput::default()
}

/// Every `[[hydraulics.port]]`: a header naming its valve port and pads, then the rows of its keys
/// (`hydraulics.port[i].<name>`, labelled "Line i <label>").
pub fn ports_ui(ui: &mut Ui, doc: &mut Document, rows: &[&'static KeySpec]) -> EditOutput {
    let mut out = EditOutput::default();
    let Some(file) = doc.file().hydraulics.clone() else { return out };
    let mut values = Values::of(doc.file());
    for (i, p) in file.port.iter().enumerate() {
        let pads: Vec<String> = p.pads.iter().map(ToString::to_string).collect();
        let side = match p.valve_port {
            ValvePort::A => "A",
            ValvePort::B => "B",
        };
        let tip = format!(
            "{}\n\nEdit the port's pads and valve port in the case file.",
            super::widgets::key_tooltip("hydraulics.port[].pads")
        );
        let label = label_ui(ui, &format!("Line {i}"), &tip);
        ui.label(RichText::new(format!("valve port {side}, feeds pads {}", pads.join(", "))).strong())
            .labelled_by(label.id);
        ui.label("");
        ui.end_row();
        for row in rows {
            let Some(editor) = row.editor else { continue };
            let key = row.key.replace("[]", &format!("[{i}]"));
            let o = row_ui(ui, doc, &values, row, &key, &format!("Line {i} {}", editor.label));
            if o.changed {
                values = Values::of(doc.file());
            }
            out.merge(o);
        }
    }
    out
}
