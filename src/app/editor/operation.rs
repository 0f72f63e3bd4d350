//! The editor's own code for how the bearing runs and is modelled: how the journal position is given (not a
//! key), the injection pressure (one value, or one per pad), the per-pad supply flow, the half model (automatic, or forced either
//! way) and what the chosen fidelity costs. Every other row of the lubricant, operating point, physics and
//! fidelity groups is drawn from the key table.

use egui::Ui;

use super::bearing::{pads_with_injection, per_pad_count};
use super::widgets::{choice_ui, number_ui, per_pad_ui, EditOutput, Num, Pick};
use crate::app::document::Document;
use crate::model::file::OneOrMany;
use crate::model::schema::KeySpec;
use crate::model::CaseFile;

/// What fixes the journal position.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum LoadMode {
    Force,
    Position,
}

/// Where a switch of the journal position's mode starts: a light load [N], or a moderate eccentricity ratio.
const START: (f64, f64) = (1000.0, 0.3);

/// Switches between a given load and a given position; the value of the new mode starts at [`START`], the
/// direction carries over.
fn set_load_mode(f: &mut CaseFile, mode: LoadMode) {
    let o = &mut f.operating;
    match mode {
        LoadMode::Force => {
            o.eccentricity_ratio = None;
            o.load_angle_deg = o.eccentricity_angle_deg.take();
            o.load_n = Some(START.0);
        }
        LoadMode::Position => {
            o.load_n = None;
            o.eccentricity_angle_deg = o.load_angle_deg.take();
            o.eccentricity_ratio = Some(START.1);
        }
    }
}

/// "Journal position from": not a key, the choice between a given load and a given position (the rows of
/// the keys of each follow; the table shows the ones given).
pub fn load_mode_ui(ui: &mut Ui, doc: &mut Document) -> EditOutput {
    let mode = if doc.file().operating.eccentricity_ratio.is_some() { LoadMode::Position } else { LoadMode::Force };
    choice_ui(
        ui,
        doc,
        Pick { key: "operating.load_mode", label: "Journal position from", tip: Some("Either give the static load and find where the journal settles, or prescribe the journal position and find the load it carries.") },
        mode,
        &[(LoadMode::Force, "load (find position)"), (LoadMode::Position, "eccentricity (find load)")],
        set_load_mode,
    )
}

/// Injection pressure: one for all pads, or one per pad.
pub fn injection_ui(ui: &mut Ui, doc: &mut Document, row: &'static KeySpec) -> EditOutput {
    let mut out = EditOutput::default();
    let label = row.editor.map_or(row.key, |e| e.label);
    let n = Num { key: row.key, label, decimals: 1 };
    let mut separate = matches!(doc.file().operating.injection_pressure_bar, Some(OneOrMany::Many(_)));
    ui.label("");
    if ui
        .checkbox(&mut separate, "Injection pressure per pad")
        .on_hover_text("Give each pad its own injection pressure (e.g. only the loaded pad injects).")
        .changed()
    {
        let count = per_pad_count(doc.file());
        doc.edit(n.key, false, |f| {
            let mut all = pads_with_injection(f);
            all.resize(count, 0.0);
            f.operating.injection_pressure_bar =
                Some(if separate { OneOrMany::Many(all) } else { OneOrMany::One(all.first().copied().unwrap_or(0.0)) });
        });
        out.changed = true;
    }
    ui.end_row();
    if separate {
        let values = pads_with_injection(doc.file());
        out.merge(per_pad_ui(ui, doc, &n, &values, |f, k, v| {
            if let Some(OneOrMany::Many(l)) = &mut f.operating.injection_pressure_bar {
                if let Some(x) = l.get_mut(k) {
                    *x = v;
                }
            }
        }));
    } else {
        let value = match doc.file().operating.injection_pressure_bar {
            Some(OneOrMany::One(p)) => p,
            _ => row.default_number().unwrap_or_default(),
        };
        out.merge(number_ui(ui, doc, &n, value, |f, v| f.operating.injection_pressure_bar = Some(OneOrMany::One(v))));
    }
    out
}

/// Supply flow per pad: absent (the bearing's supply, or flooded pads), or one value per pad [l/min]. Ticking
/// it starts every pad at its equal share of the bearing's supply (which it replaces: the two keys exclude
/// each other), or at the key's lowest typical value when there is none.
pub fn pad_supply_ui(ui: &mut Ui, doc: &mut Document, row: &'static KeySpec) -> EditOutput {
    let mut out = EditOutput::default();
    let label = row.editor.map_or(row.key, |e| e.label);
    let n = Num { key: row.key, label, decimals: 2 };
    let mut separate = doc.file().operating.pad_supply_flow_l_per_min.is_some();
    ui.label("");
    if ui
        .checkbox(&mut separate, "Supply flow per pad")
        .on_hover_text("Give each pad its own oil supply (e.g. a groove per pad with its own orifice).")
        .changed()
    {
        let count = per_pad_count(doc.file());
        let first = row.typical.map_or(1.0, |(lo, _)| lo);
        doc.edit(n.key, false, |f| {
            let o = &mut f.operating;
            if separate {
                #[allow(clippy::cast_precision_loss)]
                let share = o.supply_flow_l_per_min.take().map_or(first, |q| q / count.max(1) as f64);
                o.pad_supply_flow_l_per_min = Some(OneOrMany::Many(vec![share; count]));
            } else {
                o.pad_supply_flow_l_per_min = None;
            }
        });
        out.changed = true;
    }
    ui.end_row();
    if separate {
        let values = pad_supply(doc.file());
        out.merge(per_pad_ui(ui, doc, &n, &values, |f, k, v| {
            let count = per_pad_count(f);
            let mut all = pad_supply(f);
            all.resize(count, all.last().copied().unwrap_or(v));
            if let Some(x) = all.get_mut(k) {
                *x = v;
            }
            f.operating.pad_supply_flow_l_per_min = Some(OneOrMany::Many(all));
        }));
    }
    out
}

/// The supply flow of every pad as the file gives it [l/min] (one value repeated for every pad).
fn pad_supply(f: &CaseFile) -> Vec<f64> {
    match &f.operating.pad_supply_flow_l_per_min {
        Some(OneOrMany::Many(v)) => v.clone(),
        Some(OneOrMany::One(q)) => vec![*q; per_pad_count(f)],
        None => Vec::new(),
    }
}

/// Use of the symmetry plane.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Half {
    Auto,
    On,
    Off,
}

/// The half model: automatic (the key absent), or forced on or off.
pub fn half_model_ui(ui: &mut Ui, doc: &mut Document, row: &'static KeySpec) -> EditOutput {
    let half = match doc.file().mesh.half_model {
        None => Half::Auto,
        Some(true) => Half::On,
        Some(false) => Half::Off,
    };
    choice_ui(
        ui,
        doc,
        Pick { key: row.key, label: row.editor.map_or(row.key, |e| e.label), tip: None },
        half,
        &[(Half::Auto, "automatic"), (Half::On, "half length"), (Half::Off, "full length")],
        |f, h| {
            f.mesh.half_model = match h {
                Half::Auto => None,
                Half::On => Some(true),
                Half::Off => Some(false),
            }
        },
    )
}

/// What the chosen level costs and how accurate it is (measured on the compressor bearing by the developers'
/// bench; `tiltpad fidelity` measures it on any case).
pub fn fidelity_note_ui(ui: &mut Ui, doc: &mut Document) -> EditOutput {
    let fid = doc.file().mesh.fidelity.unwrap_or_default();
    if let Some(table) = crate::scene::fidelity::shipped() {
        let name = format!("{fid:?}").to_lowercase();
        let lines = table.describe(&name);
        if !lines.is_empty() {
            ui.label("");
            ui.label(egui::RichText::new(format!("Expected ({}):\n{}", "compressor bearing", lines.join("\n"))).weak().small())
                .on_hover_text(format!("Measured on {} ({}): median wall time of a complete solve and the error against a reference-fine mesh. Other bearings scale with their number of film nodes; `tiltpad fidelity CASE` measures your case.", table.machine, table.generated));
            ui.end_row();
        }
    }
    EditOutput::default()
}
