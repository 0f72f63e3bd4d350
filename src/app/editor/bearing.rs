//! Editor groups for what the bearing is: geometry, pads, orifices.

use egui::Ui;

use super::widgets::{
    choice_ui, count_ui, error_row_ui, fields_ui, number_ui, opt_fields_ui, per_pad_ui, EditOutput, Field, Num,
    OptField, Pick,
};
use crate::app::document::Document;
use crate::model::file::{ContactKindFile, OneOrMany, OrificeFile, PadKindFile};
use crate::model::CaseFile;

const GEOMETRY: [Field; 3] = [
    Field {
        num: Num { key: "bearing.journal_radius_mm", label: "Journal radius R", decimals: 3 },
        get: |f| f.bearing.journal_radius_mm,
        set: |f, v| f.bearing.journal_radius_mm = v,
    },
    Field {
        num: Num { key: "bearing.length_mm", label: "Pad length L", decimals: 3 },
        get: |f| f.bearing.length_mm,
        set: |f, v| f.bearing.length_mm = v,
    },
    Field {
        num: Num { key: "bearing.assembled_clearance_um", label: "Assembled clearance Cb", decimals: 2 },
        get: |f| f.bearing.assembled_clearance_um,
        set: |f, v| f.bearing.assembled_clearance_um = v,
    },
];

pub fn geometry_ui(ui: &mut Ui, doc: &mut Document) -> EditOutput {
    fields_ui(ui, doc, &GEOMETRY)
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
    let (r, cb) = (f.bearing.journal_radius_mm, f.bearing.assembled_clearance_um);
    let p = &mut f.bearing.pads;
    let cp_um = match (p.preload, p.clearance_um, p.bore_radius_mm) {
        (_, Some(c), _) => c,
        (_, _, Some(rp)) => (rp - r) * 1e3,
        (Some(m), _, _) if m < 1.0 => cb / (1.0 - m),
        _ => cb,
    };
    p.preload = None;
    p.clearance_um = None;
    p.bore_radius_mm = None;
    match mode {
        ClearanceMode::Preload => p.preload = Some(if cp_um > 0.0 { 1.0 - cb / cp_um } else { 0.0 }),
        ClearanceMode::Clearance => p.clearance_um = Some(cp_um),
        ClearanceMode::BoreRadius => p.bore_radius_mm = Some(r + cp_um * 1e-3),
    }
}

/// The value row of each way of giving the pad clearance.
const CLEARANCE: [Field; 3] = [
    Field {
        num: Num { key: "bearing.pads.preload", label: "Preload m", decimals: 3 },
        get: |f| f.bearing.pads.preload.unwrap_or(0.0),
        set: |f, v| f.bearing.pads.preload = Some(v),
    },
    Field {
        num: Num { key: "bearing.pads.clearance_um", label: "Pad clearance Cp", decimals: 2 },
        get: |f| f.bearing.pads.clearance_um.unwrap_or(0.0),
        set: |f, v| f.bearing.pads.clearance_um = Some(v),
    },
    Field {
        num: Num { key: "bearing.pads.bore_radius_mm", label: "Pad bore radius Rp", decimals: 4 },
        get: |f| f.bearing.pads.bore_radius_mm.unwrap_or(0.0),
        set: |f, v| f.bearing.pads.bore_radius_mm = Some(v),
    },
];

const ARC_OFFSET: [Field; 2] = [
    Field {
        num: Num { key: "bearing.pads.arc_deg", label: "Pad arc β", decimals: 2 },
        get: |f| f.bearing.pads.arc_deg.unwrap_or(0.0),
        set: |f, v| f.bearing.pads.arc_deg = Some(v),
    },
    Field {
        num: Num { key: "bearing.pads.offset", label: "Pivot offset α", decimals: 3 },
        get: |f| f.bearing.pads.offset.unwrap_or(0.5),
        set: |f, v| f.bearing.pads.offset = Some(v),
    },
];

const THICKNESS: Field = Field {
    num: Num { key: "bearing.pads.thickness_mm", label: "Pad thickness t", decimals: 3 },
    get: |f| f.bearing.pads.thickness_mm.unwrap_or(0.0),
    set: |f, v| f.bearing.pads.thickness_mm = Some(v),
};

const PAD_MATERIAL: [OptField; 5] = [
    OptField {
        num: Num { key: "bearing.pads.pivot_stiffness_n_per_m", label: "Pivot stiffness", decimals: 0 },
        default: 2e7,
        get: |f| f.bearing.pads.pivot_stiffness_n_per_m,
        set: |f, v| f.bearing.pads.pivot_stiffness_n_per_m = v,
    },
    OptField {
        num: Num {
            key: "bearing.pads.pivot_transverse_stiffness_n_per_m",
            label: "Pivot transverse stiffness",
            decimals: 0,
        },
        default: 1e8,
        get: |f| f.bearing.pads.pivot_transverse_stiffness_n_per_m,
        set: |f, v| f.bearing.pads.pivot_transverse_stiffness_n_per_m = v,
    },
    OptField {
        num: Num { key: "bearing.pads.density_kg_per_m3", label: "Pad density", decimals: 0 },
        default: 7800.0,
        get: |f| f.bearing.pads.density_kg_per_m3,
        set: |f, v| f.bearing.pads.density_kg_per_m3 = v,
    },
    OptField {
        num: Num { key: "bearing.pads.youngs_modulus_gpa", label: "Young's modulus E", decimals: 1 },
        default: 200.0,
        get: |f| f.bearing.pads.youngs_modulus_gpa,
        set: |f, v| f.bearing.pads.youngs_modulus_gpa = v,
    },
    OptField {
        num: Num { key: "bearing.pads.poisson_ratio", label: "Poisson ratio ν", decimals: 3 },
        default: 0.3,
        get: |f| f.bearing.pads.poisson_ratio,
        set: |f, v| f.bearing.pads.poisson_ratio = v,
    },
];

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

const PIVOTS: Num<'static> = Num { key: "bearing.pads.pivot_deg", label: "Pivot angles", decimals: 2 };

fn pivots_ui(ui: &mut Ui, doc: &mut Document) -> EditOutput {
    match doc.file().bearing.pads.pivot_deg.clone() {
        Some(OneOrMany::Many(list)) => per_pad_ui(ui, doc, &PIVOTS, &list, |f, k, v| {
            if let Some(OneOrMany::Many(l)) = &mut f.bearing.pads.pivot_deg {
                l[k] = v;
            }
        }),
        other => {
            let first = match other {
                Some(OneOrMany::One(v)) => v,
                _ => 0.0,
            };
            let num = Num { label: "First pivot (evenly spaced)", ..PIVOTS };
            number_ui(ui, doc, &num, |_| first, |f, v| f.bearing.pads.pivot_deg = Some(OneOrMany::One(v)))
        }
    }
}

pub fn pads_ui(ui: &mut Ui, doc: &mut Document) -> EditOutput {
    let mut out = EditOutput::default();
    let n = pad_count(doc.file());
    let note = "Changing it makes the pivots evenly spaced from the first one.";
    out.merge(count_ui(ui, doc, "bearing.pads.count", "Number of pads", note, n, set_pad_count));
    let kind = doc.file().bearing.pads.kind.unwrap_or_default();
    out.merge(choice_ui(
        ui,
        doc,
        Pick { key: "bearing.pads.kind", label: "Pad kind", tip: None },
        kind,
        &[(PadKindFile::Tilting, "tilting"), (PadKindFile::Fixed, "fixed sector")],
        |f, k| f.bearing.pads.kind = Some(k),
    ));
    out.merge(fields_ui(ui, doc, &ARC_OFFSET[..1]));
    out.merge(pivots_ui(ui, doc));
    out.merge(fields_ui(ui, doc, &ARC_OFFSET[1..]));
    let mode = clearance_mode(doc.file());
    out.merge(choice_ui(
        ui,
        doc,
        Pick { key: "bearing.pads.clearance_input", label: "Pad geometry given by", tip: Some("The pads' machined clearance Cp may be given as the preload m = 1 − Cb/Cp, as Cp itself or as the pad bore radius Rp = R + Cp.") },
        mode,
        &[(ClearanceMode::Preload, "preload"), (ClearanceMode::Clearance, "pad clearance"), (ClearanceMode::BoreRadius, "pad bore radius")],
        set_clearance_mode,
    ));
    out.merge(fields_ui(ui, doc, &[CLEARANCE[mode as usize], THICKNESS]));
    let massless = doc.file().bearing.pads.massless.unwrap_or(false);
    out.merge(choice_ui(
        ui,
        doc,
        Pick { key: "bearing.pads.massless", label: "Pad inertia", tip: None },
        massless,
        &[(false, "from the density"), (true, "massless pads")],
        |f, m| {
            f.bearing.pads.massless = m.then_some(true);
            if m {
                f.bearing.pads.density_kg_per_m3 = None;
            }
        },
    ));
    // Massless pads have no density row (the validation refuses one); a contact pivot no stiffness row.
    let contact = doc.file().bearing.pads.pivot_contact;
    let material: Vec<OptField> = PAD_MATERIAL
        .into_iter()
        .filter(|f| !(massless && f.num.key == "bearing.pads.density_kg_per_m3"))
        .filter(|f| !(contact.is_some() && f.num.key == "bearing.pads.pivot_stiffness_n_per_m"))
        .collect();
    out.merge(opt_fields_ui(ui, doc, &material));
    out.merge(pivot_contact_ui(ui, doc, contact));
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
    out
}

/// The pivot's Hertz contact rows (`bearing.pads.pivot_*`), shown when a contact is chosen.
const PIVOT_CONTACT: [OptField; 5] = [
    OptField {
        num: Num { key: "bearing.pads.pivot_radius_mm", label: "Pivot radius", decimals: 3 },
        default: 20.0,
        get: |f| f.bearing.pads.pivot_radius_mm,
        set: |f, v| f.bearing.pads.pivot_radius_mm = v,
    },
    OptField {
        num: Num { key: "bearing.pads.pivot_seat_radius_mm", label: "Pivot seat radius", decimals: 3 },
        default: 21.0,
        get: |f| f.bearing.pads.pivot_seat_radius_mm,
        set: |f, v| f.bearing.pads.pivot_seat_radius_mm = v,
    },
    OptField {
        num: Num { key: "bearing.pads.pivot_length_mm", label: "Rocker contact length", decimals: 3 },
        default: 40.0,
        get: |f| f.bearing.pads.pivot_length_mm,
        set: |f, v| f.bearing.pads.pivot_length_mm = v,
    },
    OptField {
        num: Num { key: "bearing.pads.pivot_seat_youngs_modulus_gpa", label: "Seat Young's modulus", decimals: 1 },
        default: 200.0,
        get: |f| f.bearing.pads.pivot_seat_youngs_modulus_gpa,
        set: |f, v| f.bearing.pads.pivot_seat_youngs_modulus_gpa = v,
    },
    OptField {
        num: Num { key: "bearing.pads.pivot_seat_poisson_ratio", label: "Seat Poisson ratio", decimals: 3 },
        default: 0.3,
        get: |f| f.bearing.pads.pivot_seat_poisson_ratio,
        set: |f, v| f.bearing.pads.pivot_seat_poisson_ratio = v,
    },
];

/// The pivot: a given stiffness (or rigid), or a Hertz contact with its geometry rows. Choosing a contact
/// drops the stiffness key and fills the two radii the validation requires.
fn pivot_contact_ui(ui: &mut Ui, doc: &mut Document, contact: Option<ContactKindFile>) -> EditOutput {
    let mut out = choice_ui(
        ui,
        doc,
        Pick { key: "bearing.pads.pivot_contact", label: "Pivot contact", tip: None },
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
                p.pivot_radius_mm = p.pivot_radius_mm.or(Some(20.0));
                p.pivot_seat_radius_mm = p.pivot_seat_radius_mm.or(Some(21.0));
            } else {
                (p.pivot_radius_mm, p.pivot_seat_radius_mm, p.pivot_length_mm) = (None, None, None);
                (p.pivot_seat_youngs_modulus_gpa, p.pivot_seat_poisson_ratio) = (None, None);
            }
        },
    );
    if contact.is_some() {
        let rows: Vec<OptField> = PIVOT_CONTACT
            .into_iter()
            .filter(|f| contact == Some(ContactKindFile::Rocker) || f.num.key != "bearing.pads.pivot_length_mm")
            .collect();
        out.merge(opt_fields_ui(ui, doc, &rows));
    }
    out
}

/// A value of an orifice entry; its key is `bearing.pads.orifice[k].<field>`, as the validation names it
/// (unit, tooltip and drag range from the schema row `bearing.pads.orifice[].<field>`).
struct OrificeRow {
    field: &'static str,
    label: &'static str,
    get: fn(&OrificeFile) -> f64,
    set: fn(&mut OrificeFile, f64),
}

const ORIFICE_ROWS: [OrificeRow; 4] = [
    OrificeRow {
        field: "position_frac",
        label: "Position along arc",
        get: |o| o.position_frac,
        set: |o, v| o.position_frac = v,
    },
    OrificeRow {
        field: "axial_frac",
        label: "Axial position",
        get: |o| o.axial_frac.unwrap_or(0.5),
        set: |o, v| o.axial_frac = Some(v),
    },
    OrificeRow { field: "diameter_mm", label: "Diameter d0", get: |o| o.diameter_mm, set: |o, v| o.diameter_mm = v },
    OrificeRow { field: "length_mm", label: "Capillary length l0", get: |o| o.length_mm, set: |o, v| o.length_mm = v },
];

pub fn orifices_ui(ui: &mut Ui, doc: &mut Document) -> EditOutput {
    let mut out = EditOutput::default();
    let count = doc.file().bearing.pads.orifice.as_ref().map_or(0, Vec::len);
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
        for row in &ORIFICE_ROWS {
            let key = format!("bearing.pads.orifice[{k}].{}", row.field);
            let num = Num { key: &key, label: row.label, decimals: 3 };
            let read = |f: &CaseFile| f.bearing.pads.orifice.as_ref().and_then(|l| l.get(k)).map_or(0.0, row.get);
            out.merge(number_ui(ui, doc, &num, read, |f, v| {
                if let Some(o) = f.bearing.pads.orifice.as_mut().and_then(|l| l.get_mut(k)) {
                    (row.set)(o, v);
                }
            }));
        }
    }
    ui.label("");
    if ui
        .button("Add orifice")
        .on_hover_text("Add an injection orifice (at mid-arc, on the mid-plane) to every pad")
        .clicked()
    {
        doc.edit("bearing.pads.orifice", false, |f| {
            f.bearing.pads.orifice.get_or_insert_with(Vec::new).push(OrificeFile {
                position_frac: 0.5,
                axial_frac: None,
                diameter_mm: 5.0,
                length_mm: 5.0,
            });
        });
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
