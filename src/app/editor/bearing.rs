//! Editor groups for what the bearing is: geometry, pads, orifices.

use egui::Ui;

use super::widgets::{choice_ui, count_ui, number_ui, optional_ui, per_pad_ui, EditOutput, Num};
use crate::app::document::Document;
use crate::model::file::{OneOrMany, OrificeFile, PadKindFile};
use crate::model::CaseFile;

pub fn geometry_ui(ui: &mut Ui, doc: &mut Document) -> EditOutput {
    let mut out = EditOutput::default();
    out.merge(number_ui(
        ui,
        doc,
        &Num {
            key: "bearing.journal_radius_mm",
            label: "Journal radius R",
            unit: "mm",
            range: (10.0, 500.0),
            decimals: 3,
            tip: "Radius of the shaft journal running in the bearing.",
        },
        |f| f.bearing.journal_radius_mm,
        |f, v| f.bearing.journal_radius_mm = v,
    ));
    out.merge(number_ui(
        ui,
        doc,
        &Num {
            key: "bearing.length_mm",
            label: "Pad length L",
            unit: "mm",
            range: (10.0, 400.0),
            decimals: 3,
            tip: "Axial length of the pads. With L/D below about 0.5 side leakage dominates and the load capacity falls quickly.",
        },
        |f| f.bearing.length_mm,
        |f, v| f.bearing.length_mm = v,
    ));
    out.merge(number_ui(
        ui,
        doc,
        &Num {
            key: "bearing.assembled_clearance_um",
            label: "Assembled clearance Cb",
            unit: "µm",
            range: (20.0, 400.0),
            decimals: 2,
            tip: "Radial clearance of the assembled bearing: the gap between the journal and the pads at their pivots with the journal centred. Typically 1–2 ‰ of the radius.",
        },
        |f| f.bearing.assembled_clearance_um,
        |f, v| f.bearing.assembled_clearance_um = v,
    ));
    out
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

#[allow(clippy::too_many_lines)]
pub fn pads_ui(ui: &mut Ui, doc: &mut Document) -> EditOutput {
    let mut out = EditOutput::default();
    let n = pad_count(doc.file());
    out.merge(count_ui(ui, doc, "bearing.pads.count", "Number of pads", "How many pads share the circumference. Changing it makes the pivots evenly spaced from the first one.", n, set_pad_count));
    let kind = doc.file().bearing.pads.kind.unwrap_or_default();
    out.merge(choice_ui(
        ui,
        doc,
        "bearing.pads.kind",
        "Pad kind",
        "Tilting pads rotate freely about their pivots (no cross-coupled stiffness from a symmetric bearing); fixed sectors do not tilt (lobed or plain bearings).",
        kind,
        &[(PadKindFile::Tilting, "tilting"), (PadKindFile::Fixed, "fixed sector")],
        |f, k| f.bearing.pads.kind = Some(k),
    ));
    out.merge(number_ui(
        ui,
        doc,
        &Num { key: "bearing.pads.arc_deg", label: "Pad arc β", unit: "°", range: (20.0, 120.0), decimals: 2, tip: "Angular extent of each pad." },
        |f| f.bearing.pads.arc_deg.unwrap_or(0.0),
        |f, v| f.bearing.pads.arc_deg = Some(v),
    ));
    let pivot = Num {
        key: "bearing.pads.pivot_deg",
        label: "Pivot angles",
        unit: "°",
        range: (0.0, 360.0),
        decimals: 2,
        tip: "Angle of each pad's pivot from +x (horizontal), counter-clockwise; the load usually acts at 270° (down). A pivot at 270° is load on pad, pivots at 225° and 315° load between pads.",
    };
    match doc.file().bearing.pads.pivot_deg.clone() {
        Some(OneOrMany::Many(list)) => out.merge(per_pad_ui(ui, doc, &pivot, &list, |f, k, v| {
            if let Some(OneOrMany::Many(l)) = &mut f.bearing.pads.pivot_deg {
                l[k] = v;
            }
        })),
        other => {
            let first = match other {
                Some(OneOrMany::One(v)) => v,
                _ => 0.0,
            };
            out.merge(number_ui(
                ui,
                doc,
                &Num { label: "First pivot (evenly spaced)", ..pivot },
                |_| first,
                |f, v| f.bearing.pads.pivot_deg = Some(OneOrMany::One(v)),
            ));
        }
    }
    out.merge(number_ui(
        ui,
        doc,
        &Num {
            key: "bearing.pads.offset",
            label: "Pivot offset α",
            unit: "–",
            range: (0.4, 0.7),
            decimals: 3,
            tip: "Pivot position as a fraction of the arc from the leading edge: 0.5 is centred (either rotation direction), 0.6 is the common offset that raises the film thickness and lowers the temperature.",
        },
        |f| f.bearing.pads.offset.unwrap_or(0.5),
        |f, v| f.bearing.pads.offset = Some(v),
    ));
    let mode = clearance_mode(doc.file());
    out.merge(choice_ui(
        ui,
        doc,
        "bearing.pads.clearance_input",
        "Pad geometry given by",
        "The pads' machined clearance Cp may be given as the preload m = 1 − Cb/Cp, as Cp itself or as the pad bore radius Rp = R + Cp.",
        mode,
        &[(ClearanceMode::Preload, "preload"), (ClearanceMode::Clearance, "pad clearance"), (ClearanceMode::BoreRadius, "pad bore radius")],
        set_clearance_mode,
    ));
    match mode {
        ClearanceMode::Preload => out.merge(number_ui(
            ui,
            doc,
            &Num {
                key: "bearing.pads.preload",
                label: "Preload m",
                unit: "–",
                range: (0.0, 0.7),
                decimals: 3,
                tip: "m = 1 − Cb/Cp: how much the pads' own curvature converges on the journal. Preload keeps unloaded pads working (a converging wedge) and raises stiffness.",
            },
            |f| f.bearing.pads.preload.unwrap_or(0.0),
            |f, v| f.bearing.pads.preload = Some(v),
        )),
        ClearanceMode::Clearance => out.merge(number_ui(
            ui,
            doc,
            &Num { key: "bearing.pads.clearance_um", label: "Pad clearance Cp", unit: "µm", range: (20.0, 600.0), decimals: 2, tip: "Machined radial clearance of the pads: pad bore radius minus journal radius." },
            |f| f.bearing.pads.clearance_um.unwrap_or(0.0),
            |f, v| f.bearing.pads.clearance_um = Some(v),
        )),
        ClearanceMode::BoreRadius => out.merge(number_ui(
            ui,
            doc,
            &Num { key: "bearing.pads.bore_radius_mm", label: "Pad bore radius Rp", unit: "mm", range: (10.0, 500.0), decimals: 4, tip: "Radius to which the pads are machined, Rp = R + Cp." },
            |f| f.bearing.pads.bore_radius_mm.unwrap_or(0.0),
            |f, v| f.bearing.pads.bore_radius_mm = Some(v),
        )),
    }
    out.merge(number_ui(
        ui,
        doc,
        &Num { key: "bearing.pads.thickness_mm", label: "Pad thickness t", unit: "mm", range: (3.0, 150.0), decimals: 3, tip: "Radial thickness of the pad; the pivot sits on its back, so t sets the lever of the tilt." },
        |f| f.bearing.pads.thickness_mm.unwrap_or(0.0),
        |f, v| f.bearing.pads.thickness_mm = Some(v),
    ));
    out.merge(optional_ui(
        ui,
        doc,
        &Num {
            key: "bearing.pads.pivot_stiffness_n_per_m",
            label: "Pivot stiffness",
            unit: "N/m",
            range: (1e6, 1e10),
            decimals: 0,
            tip: "Radial stiffness of the pivot contact (a rocker-back Hertz contact, a spring). Absent: rigid pivot. A soft pivot lowers the bearing's effective stiffness.",
        },
        2e7,
        |f| f.bearing.pads.pivot_stiffness_n_per_m,
        |f, v| f.bearing.pads.pivot_stiffness_n_per_m = v,
    ));
    out.merge(optional_ui(
        ui,
        doc,
        &Num { key: "bearing.pads.density_kg_per_m3", label: "Pad density", unit: "kg/m³", range: (1000.0, 9000.0), decimals: 0, tip: "Pad material density: sets the pad inertia that enters the frequency-dependent reduced coefficients." },
        7800.0,
        |f| f.bearing.pads.density_kg_per_m3,
        |f, v| f.bearing.pads.density_kg_per_m3 = v,
    ));
    out.merge(optional_ui(
        ui,
        doc,
        &Num { key: "bearing.pads.youngs_modulus_gpa", label: "Young's modulus E", unit: "GPa", range: (70.0, 220.0), decimals: 1, tip: "Pad material stiffness, for the pad flexibility model (steel 200 GPa, brass about 100 GPa). Not used by rigid pads." },
        200.0,
        |f| f.bearing.pads.youngs_modulus_gpa,
        |f, v| f.bearing.pads.youngs_modulus_gpa = v,
    ));
    out.merge(optional_ui(
        ui,
        doc,
        &Num { key: "bearing.pads.poisson_ratio", label: "Poisson ratio ν", unit: "–", range: (0.25, 0.35), decimals: 3, tip: "Pad material Poisson ratio, for the pad flexibility model." },
        0.3,
        |f| f.bearing.pads.poisson_ratio,
        |f, v| f.bearing.pads.poisson_ratio = v,
    ));
    if !doc.file().bearing.pad.is_empty() {
        ui.label("");
        ui.label(egui::RichText::new(format!("{} per-pad override table(s) from the file apply ([[bearing.pad]]); edit them in the TOML.", doc.file().bearing.pad.len())).weak().small());
        ui.end_row();
    }
    out
}

pub fn orifices_ui(ui: &mut Ui, doc: &mut Document) -> EditOutput {
    let mut out = EditOutput::default();
    let list = doc.file().bearing.pads.orifice.clone().unwrap_or_default();
    for (k, _) in list.iter().enumerate() {
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
            out.changed = true;
            ui.end_row();
            return out;
        }
        ui.end_row();
        // Keys name the list entry, as the validation does (`bearing.pads.orifice[0].diameter_mm`).
        let keys = ["position_frac", "axial_frac", "diameter_mm", "length_mm"].map(|field| format!("bearing.pads.orifice[{k}].{field}"));
        let get = move |f: &CaseFile| f.bearing.pads.orifice.as_ref().and_then(|l| l.get(k)).cloned();
        let set = move |f: &mut CaseFile, g: &dyn Fn(&mut OrificeFile)| {
            if let Some(o) = f.bearing.pads.orifice.as_mut().and_then(|l| l.get_mut(k)) {
                g(o);
            }
        };
        out.merge(number_ui(
            ui,
            doc,
            &Num { key: &keys[0], label: "Position along arc", unit: "–", range: (0.1, 0.9), decimals: 3, tip: "Circumferential position of the orifice centre as a fraction of the arc from the leading edge. Injection near the leading edge lifts the pad's leading edge and cools the film." },
            |f| get(f).map_or(0.5, |o| o.position_frac),
            |f, v| set(f, &|o| o.position_frac = v),
        ));
        out.merge(number_ui(
            ui,
            doc,
            &Num { key: &keys[1], label: "Axial position", unit: "–", range: (0.2, 0.8), decimals: 3, tip: "Axial position as a fraction of the length; 0.5 is the mid-plane (the half model needs every orifice there)." },
            |f| get(f).and_then(|o| o.axial_frac).unwrap_or(0.5),
            |f, v| set(f, &|o| o.axial_frac = Some(v)),
        ));
        out.merge(number_ui(
            ui,
            doc,
            &Num { key: &keys[2], label: "Diameter d0", unit: "mm", range: (1.0, 10.0), decimals: 3, tip: "Orifice diameter: the injected flow scales with d0⁴ (Hagen–Poiseuille)." },
            |f| get(f).map_or(0.0, |o| o.diameter_mm),
            |f, v| set(f, &|o| o.diameter_mm = v),
        ));
        out.merge(number_ui(
            ui,
            doc,
            &Num { key: &keys[3], label: "Capillary length l0", unit: "mm", range: (1.0, 20.0), decimals: 3, tip: "Length of the capillary through the pad: its hydraulic resistance, proportional to l0/d0⁴, throttles the injection." },
            |f| get(f).map_or(0.0, |o| o.length_mm),
            |f, v| set(f, &|o| o.length_mm = v),
        ));
    }
    ui.label("");
    if ui.button("Add orifice").on_hover_text("Add an injection orifice (at mid-arc, on the mid-plane) to every pad").clicked() {
        doc.edit("bearing.pads.orifice", false, |f| {
            f.bearing.pads.orifice.get_or_insert_with(Vec::new).push(OrificeFile { position_frac: 0.5, axial_frac: None, diameter_mm: 5.0, length_mm: 5.0 });
        });
        out.changed = true;
    }
    ui.end_row();
    super::widgets::error_row_ui(ui, doc, "bearing.pads.orifice");
    out
}

pub fn per_pad_count(f: &CaseFile) -> usize {
    pad_count(f)
}

pub fn pads_with_injection(f: &CaseFile) -> Vec<f64> {
    match &f.operating.injection_pressure_bar {
        Some(OneOrMany::Many(v)) => v.clone(),
        Some(OneOrMany::One(p)) => vec![*p; pad_count(f)],
        None => vec![0.0; pad_count(f)],
    }
}
