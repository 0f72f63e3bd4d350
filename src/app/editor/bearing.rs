//! The editor's own code for what the bearing is: the pad count and pivot angles (lists with one value per
//! pad), how the pad clearance is given, the pads' inertia and pivot contact (choices that change other keys),
//! and the orifice array. Every other row of the geometry, pads and orifices is drawn from the key table.

use egui::Ui;

use super::rows::{append_entry, row_ui, Values};
use super::widgets::{choice_ui, count_ui, error_row_ui, number_ui, per_pad_ui, EditOutput, Num, Pick};
use crate::app::document::Document;
use crate::key;
use crate::model::file::{ContactKindFile, OneOrMany};
use crate::model::schema::KeySpec;
use crate::model::CaseFile;

/// The label of a key's editor row.
fn label(row: &KeySpec) -> &'static str {
    row.editor.map_or(row.key, |e| e.label)
}

/// Pad clearance is given one of three ways.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum ClearanceMode {
    Preload,
    Clearance,
    BoreRadius,
}

fn clearance_mode(f: &CaseFile) -> ClearanceMode {
    let p = &f.bearing.pads;
    if p.clearance_um.is_some() {
        ClearanceMode::Clearance
    } else if p.bore_radius_mm.is_some() {
        ClearanceMode::BoreRadius
    } else {
        ClearanceMode::Preload
    }
}

/// Switches the clearance input, converting the current value so the geometry does not change.
fn set_clearance_mode(f: &mut CaseFile, mode: ClearanceMode) {
    // Cp [µm] and the radii [mm], through the rows' units.
    let (um, mm) = (key!("bearing.pads.clearance_um"), key!("bearing.pads.bore_radius_mm"));
    let to_um = |x_mm: f64| um.from_si(mm.to_si(x_mm));
    let (r, cb) = (f.bearing.journal_radius_mm, f.bearing.assembled_clearance_um);
    let p = &mut f.bearing.pads;
    let cp_um = match (p.preload, p.clearance_um, p.bore_radius_mm) {
        (_, Some(c), _) => c,
        (_, _, Some(rp)) => to_um(rp - r),
        (Some(m), _, _) if m < 1.0 => cb / (1.0 - m),
        _ => cb,
    };
    p.preload = None;
    p.clearance_um = None;
    p.bore_radius_mm = None;
    match mode {
        ClearanceMode::Preload => p.preload = Some(if cp_um > 0.0 { 1.0 - cb / cp_um } else { 0.0 }),
        ClearanceMode::Clearance => p.clearance_um = Some(cp_um),
        ClearanceMode::BoreRadius => p.bore_radius_mm = Some(r + mm.from_si(um.to_si(cp_um))),
    }
}

/// "Pad geometry given by": not a key, the choice of which of the three keys gives the pad clearance (their
/// rows follow; the table shows the one given).
pub fn clearance_input_ui(ui: &mut Ui, doc: &mut Document) -> EditOutput {
    let mode = clearance_mode(doc.file());
    choice_ui(
        ui,
        doc,
        Pick {
            key: "bearing.pads.clearance_input",
            label: "Pad geometry given by",
            tip: Some("The pads' machined clearance Cp may be given as the preload m = 1 − Cb/Cp, as Cp itself or as the pad bore radius Rp = R + Cp."),
        },
        mode,
        &[(ClearanceMode::Preload, "preload"), (ClearanceMode::Clearance, "pad clearance"), (ClearanceMode::BoreRadius, "pad bore radius")],
        set_clearance_mode,
    )
}

/// Number of pads as the case gives it (count, per-pad entries or the pivot list).
fn pad_count(f: &CaseFile) -> usize {
    let p = &f.bearing.pads;
    p.count.or((!f.bearing.pad.is_empty()).then_some(f.bearing.pad.len())).unwrap_or(match &p.pivot_deg {
        Some(OneOrMany::Many(v)) => v.len(),
        _ => 0,
    })
}

/// Changes the pad count; per-pad lists would no longer match, so pivots become "first + evenly spaced"
/// and per-pad injection pressures are padded with zeros or cut.
fn set_pad_count(f: &mut CaseFile, n: usize) {
    f.bearing.pads.count = Some(n);
    if let Some(OneOrMany::Many(v)) = &f.bearing.pads.pivot_deg {
        f.bearing.pads.pivot_deg = Some(OneOrMany::One(v.first().copied().unwrap_or(0.0)));
    }
    if let Some(OneOrMany::Many(v)) = &mut f.operating.injection_pressure_bar {
        v.resize(n, 0.0);
    }
}

pub fn pad_count_ui(ui: &mut Ui, doc: &mut Document, row: &'static KeySpec) -> EditOutput {
    let n = pad_count(doc.file());
    let note = "Changing it makes the pivots evenly spaced from the first one.";
    count_ui(ui, doc, (row.key, label(row), note), n, set_pad_count)
}

/// Pivot angles: one per pad, or the first one with the others evenly spaced.
pub fn pivots_ui(ui: &mut Ui, doc: &mut Document, row: &'static KeySpec) -> EditOutput {
    let pivots = Num { key: row.key, label: label(row), decimals: 2 };
    match doc.file().bearing.pads.pivot_deg.clone() {
        Some(OneOrMany::Many(list)) => per_pad_ui(ui, doc, &pivots, &list, |f, k, v| {
            if let Some(OneOrMany::Many(l)) = &mut f.bearing.pads.pivot_deg {
                l[k] = v;
            }
        }),
        other => {
            let first = match other {
                Some(OneOrMany::One(v)) => v,
                _ => 0.0,
            };
            let num = Num { label: "First pivot (evenly spaced)", ..pivots };
            number_ui(ui, doc, &num, first, |f, v| f.bearing.pads.pivot_deg = Some(OneOrMany::One(v)))
        }
    }
}

/// Pad inertia: from the density, or massless pads (which take no density: choosing them removes it).
pub fn massless_ui(ui: &mut Ui, doc: &mut Document, row: &'static KeySpec) -> EditOutput {
    let massless = doc.file().bearing.pads.massless.unwrap_or(false);
    choice_ui(
        ui,
        doc,
        Pick { key: row.key, label: label(row), tip: None },
        massless,
        &[(false, "from the density"), (true, "massless pads")],
        |f, m| {
            f.bearing.pads.massless = m.then_some(true);
            if m {
                f.bearing.pads.density_kg_per_m3 = None;
            }
        },
    )
}

/// A contact to start from when one is chosen: a conformal rocker or ball of 20 mm in a 21 mm seat [mm].
const START_CONTACT_MM: (f64, f64) = (20.0, 21.0);

/// The pivot: a given stiffness (or rigid), or a Hertz contact. Choosing a contact drops the stiffness key
/// and gives the two radii the validation requires ([`START_CONTACT_MM`]); choosing none drops the contact's
/// keys. Its geometry rows follow from the table.
pub fn pivot_contact_ui(ui: &mut Ui, doc: &mut Document, row: &'static KeySpec) -> EditOutput {
    let contact = doc.file().bearing.pads.pivot_contact;
    choice_ui(
        ui,
        doc,
        Pick { key: row.key, label: label(row), tip: None },
        contact,
        &[
            (None, "stiffness given (or rigid)"),
            (Some(ContactKindFile::Rocker), "Hertz rocker"),
            (Some(ContactKindFile::Ball), "Hertz ball in socket"),
        ],
        |f, c| {
            let p = &mut f.bearing.pads;
            p.pivot_contact = c;
            if c.is_some() {
                p.pivot_stiffness_n_per_m = None;
                p.pivot_radius_mm = p.pivot_radius_mm.or(Some(START_CONTACT_MM.0));
                p.pivot_seat_radius_mm = p.pivot_seat_radius_mm.or(Some(START_CONTACT_MM.1));
            } else {
                (p.pivot_radius_mm, p.pivot_seat_radius_mm, p.pivot_length_mm) = (None, None, None);
                (p.pivot_seat_youngs_modulus_gpa, p.pivot_seat_poisson_ratio) = (None, None);
            }
        },
    )
}

/// The per-pad override tables of the file, which the editor shows but does not edit.
pub fn per_pad_note_ui(ui: &mut Ui, doc: &mut Document) -> EditOutput {
    if !doc.file().bearing.pad.is_empty() {
        ui.label("");
        ui.label(
            egui::RichText::new(format!(
                "{} per-pad override table(s) from the file apply ([[bearing.pad]]); edit them in the TOML.",
                doc.file().bearing.pad.len()
            ))
            .weak()
            .small(),
        );
        ui.end_row();
    }
    EditOutput::default()
}

/// The orifices on every pad (`[[bearing.pads.orifice]]`): per orifice a header with its remove button and
/// the rows of its keys (`bearing.pads.orifice[k].<name>`, as the validation names them); then a button that
/// adds one ([`append_entry`]).
pub fn orifices_ui(ui: &mut Ui, doc: &mut Document, rows: &[&'static KeySpec]) -> EditOutput {
    let mut out = EditOutput::default();
    let count = doc.file().bearing.pads.orifice.as_ref().map_or(0, Vec::len);
    let mut values = Values::of(doc.file());
    for k in 0..count {
        ui.label(egui::RichText::new(format!("Orifice {k} (on every pad)")).strong());
        if ui.button("Remove").on_hover_text("Remove this orifice from every pad").clicked() {
            doc.edit("bearing.pads.orifice", false, |f| {
                if let Some(l) = &mut f.bearing.pads.orifice {
                    l.remove(k);
                    if l.is_empty() {
                        f.bearing.pads.orifice = None;
                    }
                }
            });
            ui.end_row();
            return EditOutput { changed: true, ..out };
        }
        ui.end_row();
        for row in rows {
            let key = row.key.replace("[]", &format!("[{k}]"));
            let o = row_ui(ui, doc, &values, row, &key, label(row));
            if o.changed {
                values = Values::of(doc.file());
            }
            out.merge(o);
        }
    }
    ui.label("");
    if ui
        .button("Add orifice")
        .on_hover_text("Add an injection orifice (at mid-arc, on the mid-plane) to every pad")
        .clicked()
    {
        doc.edit("bearing.pads.orifice", false, |f| append_entry(f, "bearing.pads.orifice", rows));
        out.changed = true;
    }
    ui.end_row();
    error_row_ui(ui, doc, "bearing.pads.orifice");
    out
}

/// Number of pads (for per-pad lists elsewhere in the editor).
pub fn per_pad_count(f: &CaseFile) -> usize {
    pad_count(f)
}

/// The injection pressure of every pad [bar].
pub fn pads_with_injection(f: &CaseFile) -> Vec<f64> {
    match &f.operating.injection_pressure_bar {
        Some(OneOrMany::Many(v)) => v.clone(),
        Some(OneOrMany::One(p)) => vec![*p; pad_count(f)],
        None => vec![0.0; pad_count(f)],
    }
}
