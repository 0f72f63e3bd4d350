//! Editor groups for how the bearing runs and is modelled: lubricant, operating point, physics model,
//! fidelity.

use egui::Ui;

use super::bearing::{pads_with_injection, per_pad_count};
use super::widgets::{
    choice_ui, fields_ui, number_ui, opt_fields_ui, optional_ui, per_pad_ui, EditOutput, Field, Num, OptField, Pick,
};
use crate::app::document::Document;
use crate::model::file::{Cavitation, Fidelity, OneOrMany};
use crate::model::CaseFile;

const VISCOSITY_1: [Field; 2] = [
    Field {
        num: Num { key: "lubricant.viscosity_pa_s", label: "Viscosity µ1", decimals: 5 },
        get: |f| f.lubricant.viscosity_pa_s,
        set: |f, v| f.lubricant.viscosity_pa_s = v,
    },
    Field {
        num: Num { key: "lubricant.viscosity_temperature_c", label: "at temperature T1", decimals: 1 },
        get: |f| f.lubricant.viscosity_temperature_c,
        set: |f, v| f.lubricant.viscosity_temperature_c = v,
    },
];

const VISCOSITY_COEFFICIENT: Field = Field {
    num: Num { key: "lubricant.viscosity_coefficient_per_k", label: "Temperature coefficient η", decimals: 4 },
    get: |f| f.lubricant.viscosity_coefficient_per_k.unwrap_or(0.0),
    set: |f, v| f.lubricant.viscosity_coefficient_per_k = Some(v),
};

const VISCOSITY_2: [Field; 2] = [
    Field {
        num: Num { key: "lubricant.viscosity2_pa_s", label: "Viscosity µ2", decimals: 5 },
        get: |f| f.lubricant.viscosity2_pa_s.unwrap_or(0.0),
        set: |f, v| f.lubricant.viscosity2_pa_s = Some(v),
    },
    Field {
        num: Num { key: "lubricant.viscosity2_temperature_c", label: "at temperature T2", decimals: 1 },
        get: |f| f.lubricant.viscosity2_temperature_c.unwrap_or(0.0),
        set: |f, v| f.lubricant.viscosity2_temperature_c = Some(v),
    },
];

const OIL_PROPERTIES: [Field; 3] = [
    Field {
        num: Num { key: "lubricant.density_kg_per_m3", label: "Density ρ", decimals: 1 },
        get: |f| f.lubricant.density_kg_per_m3,
        set: |f, v| f.lubricant.density_kg_per_m3 = v,
    },
    Field {
        num: Num { key: "lubricant.specific_heat_j_per_kg_k", label: "Specific heat c_p", decimals: 0 },
        get: |f| f.lubricant.specific_heat_j_per_kg_k,
        set: |f, v| f.lubricant.specific_heat_j_per_kg_k = v,
    },
    Field {
        num: Num { key: "lubricant.conductivity_w_per_m_k", label: "Conductivity κ", decimals: 3 },
        get: |f| f.lubricant.conductivity_w_per_m_k,
        set: |f, v| f.lubricant.conductivity_w_per_m_k = v,
    },
];

/// A free-text row (names and titles); an empty text removes the key.
pub fn text_ui(
    ui: &mut Ui,
    doc: &mut Document,
    key: &'static str,
    label: &str,
    get: fn(&CaseFile) -> Option<String>,
    set: fn(&mut CaseFile, Option<String>),
) -> EditOutput {
    let tip = super::widgets::key_tooltip(key);
    let label = ui.label(label).on_hover_text(&tip);
    let mut text = get(doc.file()).unwrap_or_default();
    let changed = ui
        .add_sized([200.0, 20.0], egui::TextEdit::singleline(&mut text))
        .labelled_by(label.id)
        .on_hover_text(&tip)
        .changed();
    if changed {
        doc.edit(key, true, |f| set(f, (!text.is_empty()).then(|| text.clone())));
    }
    ui.label("");
    ui.end_row();
    EditOutput { changed, ..EditOutput::default() }
}

pub fn lubricant_ui(ui: &mut Ui, doc: &mut Document) -> EditOutput {
    let mut out = text_ui(ui, doc, "lubricant.name", "Name", |f| f.lubricant.name.clone(), |f, v| f.lubricant.name = v);
    out.merge(fields_ui(ui, doc, &VISCOSITY_1));
    if doc.file().lubricant.viscosity_coefficient_per_k.is_some() {
        out.merge(fields_ui(ui, doc, &[VISCOSITY_COEFFICIENT]));
    } else {
        out.merge(fields_ui(ui, doc, &VISCOSITY_2));
    }
    out.merge(fields_ui(ui, doc, &OIL_PROPERTIES));
    out
}

/// What fixes the journal position.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum LoadMode {
    Force,
    Position,
}

fn set_load_mode(f: &mut CaseFile, mode: LoadMode) {
    let o = &mut f.operating;
    match mode {
        LoadMode::Force => {
            o.eccentricity_ratio = None;
            o.load_angle_deg = o.eccentricity_angle_deg.take();
            o.load_n = Some(1000.0);
        }
        LoadMode::Position => {
            o.load_n = None;
            o.eccentricity_angle_deg = o.load_angle_deg.take();
            o.eccentricity_ratio = Some(0.3);
        }
    }
}

const SPEED: Field = Field {
    num: Num { key: "operating.speed_rpm", label: "Speed", decimals: 0 },
    get: |f| f.operating.speed_rpm,
    set: |f, v| f.operating.speed_rpm = v,
};

const LOAD: (Field, OptField) = (
    Field {
        num: Num { key: "operating.load_n", label: "Load W", decimals: 1 },
        get: |f| f.operating.load_n.unwrap_or(0.0),
        set: |f, v| f.operating.load_n = Some(v),
    },
    OptField {
        num: Num { key: "operating.load_angle_deg", label: "Load direction", decimals: 1 },
        default: 270.0,
        get: |f| f.operating.load_angle_deg,
        set: |f, v| f.operating.load_angle_deg = v,
    },
);

const POSITION: (Field, OptField) = (
    Field {
        num: Num { key: "operating.eccentricity_ratio", label: "Eccentricity ε", decimals: 3 },
        get: |f| f.operating.eccentricity_ratio.unwrap_or(0.0),
        set: |f, v| f.operating.eccentricity_ratio = Some(v),
    },
    OptField {
        num: Num { key: "operating.eccentricity_angle_deg", label: "Displacement direction", decimals: 1 },
        default: 270.0,
        get: |f| f.operating.eccentricity_angle_deg,
        set: |f, v| f.operating.eccentricity_angle_deg = v,
    },
);

const SUPPLY: Field = Field {
    num: Num { key: "operating.supply_temperature_c", label: "Supply temperature", decimals: 1 },
    get: |f| f.operating.supply_temperature_c,
    set: |f, v| f.operating.supply_temperature_c = v,
};

/// Temperatures that default to the supply temperature.
const SUPPLY_DEFAULTED: [OptField; 2] = [
    OptField {
        num: Num { key: "operating.film_temperature_c", label: "Film temperature", decimals: 1 },
        default: f64::NAN,
        get: |f| f.operating.film_temperature_c,
        set: |f, v| f.operating.film_temperature_c = v,
    },
    OptField {
        num: Num { key: "operating.injection_temperature_c", label: "Injection temperature", decimals: 1 },
        default: f64::NAN,
        get: |f| f.operating.injection_temperature_c,
        set: |f, v| f.operating.injection_temperature_c = v,
    },
];

const EXCITATION: OptField = OptField {
    num: Num { key: "operating.excitation_ratio", label: "Excitation ratio ω/Ω", decimals: 3 },
    default: 1.0,
    get: |f| f.operating.excitation_ratio,
    set: |f, v| f.operating.excitation_ratio = v,
};

pub fn operating_ui(ui: &mut Ui, doc: &mut Document) -> EditOutput {
    let mut out = fields_ui(ui, doc, &[SPEED]);
    let mode = if doc.file().operating.eccentricity_ratio.is_some() { LoadMode::Position } else { LoadMode::Force };
    out.merge(choice_ui(
        ui,
        doc,
        Pick { key: "operating.load_mode", label: "Journal position from", tip: Some("Either give the static load and find where the journal settles, or prescribe the journal position and find the load it carries.") },
        mode,
        &[(LoadMode::Force, "load (find position)"), (LoadMode::Position, "eccentricity (find load)")],
        set_load_mode,
    ));
    let (value, direction) = if mode == LoadMode::Force { LOAD } else { POSITION };
    out.merge(fields_ui(ui, doc, &[value]));
    out.merge(opt_fields_ui(ui, doc, &[direction]));
    out.merge(fields_ui(ui, doc, &[SUPPLY]));
    let supply = doc.file().operating.supply_temperature_c;
    out.merge(opt_fields_ui(ui, doc, &SUPPLY_DEFAULTED.map(|f| OptField { default: supply, ..f })));
    out.merge(injection_ui(ui, doc));
    out.merge(opt_fields_ui(ui, doc, &[EXCITATION]));
    out
}

/// Injection pressure: one for all pads, or one per pad.
fn injection_ui(ui: &mut Ui, doc: &mut Document) -> EditOutput {
    let mut out = EditOutput::default();
    let n = Num { key: "operating.injection_pressure_bar", label: "Injection pressure", decimals: 1 };
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
        let get = |f: &CaseFile| match f.operating.injection_pressure_bar {
            Some(OneOrMany::One(p)) => p,
            _ => 0.0,
        };
        out.merge(number_ui(ui, doc, &n, get, |f, v| f.operating.injection_pressure_bar = Some(OneOrMany::One(v))));
    }
    out
}

pub fn physics_ui(ui: &mut Ui, doc: &mut Document) -> EditOutput {
    let cav = doc.file().physics.cavitation.unwrap_or_default();
    let mut out = choice_ui(
        ui,
        doc,
        Pick { key: "physics.cavitation", label: "Cavitation", tip: None },
        cav,
        &[(Cavitation::Reynolds, "Reynolds (Swift–Stieber)"), (Cavitation::Gumbel, "Gümbel (half-Sommerfeld)")],
        |f, c| f.physics.cavitation = Some(c),
    );
    let touchdown = Num { key: "physics.touchdown_film_um", label: "Touchdown film", decimals: 2 };
    let cb = doc.file().bearing.assembled_clearance_um;
    out.merge(optional_ui(
        ui,
        doc,
        &touchdown,
        0.01 * cb,
        |f| f.physics.touchdown_film_um,
        |f, v| f.physics.touchdown_film_um = v,
    ));
    let modes = Num { key: "physics.pad_modes", label: "Pad bending modes", decimals: 0 };
    #[allow(clippy::cast_precision_loss, clippy::cast_possible_truncation, clippy::cast_sign_loss)]
    out.merge(optional_ui(
        ui,
        doc,
        &modes,
        0.0,
        |f| f.physics.pad_modes.map(|v| v as f64),
        |f, v| f.physics.pad_modes = v.map(|x| x.round().max(0.0) as usize),
    ));
    out
}

/// Use of the symmetry plane.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Half {
    Auto,
    On,
    Off,
}

/// Explicit element counts, overriding the fidelity level: key, label, the level's count, accessors.
type CountRow = (
    &'static str,
    &'static str,
    fn(Fidelity) -> usize,
    fn(&CaseFile) -> Option<usize>,
    fn(&mut CaseFile, Option<usize>),
);
const COUNTS: [CountRow; 4] = [
    (
        "mesh.circumferential_elements",
        "Circumferential elements",
        |l| l.elements().0,
        |f| f.mesh.circumferential_elements,
        |f, v| f.mesh.circumferential_elements = v,
    ),
    (
        "mesh.axial_elements",
        "Axial elements",
        |l| l.elements().1,
        |f| f.mesh.axial_elements,
        |f, v| f.mesh.axial_elements = v,
    ),
    (
        "mesh.orifice_elements",
        "Elements across an orifice",
        |l| l.elements().2,
        |f| f.mesh.orifice_elements,
        |f, v| f.mesh.orifice_elements = v,
    ),
    (
        "mesh.pad_radial_elements",
        "Pad layers (thermal)",
        Fidelity::pad_radial_elements,
        |f| f.mesh.pad_radial_elements,
        |f, v| f.mesh.pad_radial_elements = v,
    ),
];

pub fn fidelity_ui(ui: &mut Ui, doc: &mut Document) -> EditOutput {
    let fid = doc.file().mesh.fidelity.unwrap_or_default();
    let mut out = choice_ui(
        ui,
        doc,
        Pick { key: "mesh.fidelity", label: "Mesh fidelity", tip: None },
        fid,
        &[(Fidelity::Preview, "preview"), (Fidelity::Standard, "standard"), (Fidelity::Reference, "reference")],
        |f, v| f.mesh.fidelity = Some(v),
    );
    let half = match doc.file().mesh.half_model {
        None => Half::Auto,
        Some(true) => Half::On,
        Some(false) => Half::Off,
    };
    out.merge(choice_ui(
        ui,
        doc,
        Pick { key: "mesh.half_model", label: "Half model", tip: None },
        half,
        &[(Half::Auto, "automatic"), (Half::On, "half length"), (Half::Off, "full length")],
        |f, h| {
            f.mesh.half_model = match h {
                Half::Auto => None,
                Half::On => Some(true),
                Half::Off => Some(false),
            }
        },
    ));
    // What this level costs and how accurate it is (measured by `tiltpad bench`).
    if let Some(table) = crate::scene::fidelity::shipped() {
        let name = format!("{fid:?}").to_lowercase();
        let lines = table.describe(&name);
        if !lines.is_empty() {
            ui.label("");
            ui.label(egui::RichText::new(format!("Expected ({}):\n{}", "compressor bearing", lines.join("\n"))).weak().small())
                .on_hover_text(format!("Measured by `tiltpad bench` on {} ({}): median wall time of a complete solve and the error against a reference-fine mesh. Other bearings scale with their number of film nodes.", table.machine, table.generated));
            ui.end_row();
        }
    }
    // The level's circumferential count grows with the longest pad arc (Fidelity::circumferential_elements).
    let longest_arc = doc.validation().as_ref().map_or(0.0, |c| c.bearing.longest_arc_rad());
    #[allow(clippy::cast_precision_loss, clippy::cast_possible_truncation, clippy::cast_sign_loss)]
    for (key, label, level, get, set) in COUNTS {
        let num = Num { key, label, decimals: 0 };
        let default =
            if key == "mesh.circumferential_elements" { fid.circumferential_elements(longest_arc) } else { level(fid) };
        out.merge(optional_ui(
            ui,
            doc,
            &num,
            default as f64,
            |f| get(f).map(|v| v as f64),
            |f, v| set(f, v.map(|x| x.round().max(0.0) as usize)),
        ));
    }
    let budget = Num { key: "mesh.max_nodes", label: "Node budget", decimals: 0 };
    #[allow(clippy::cast_precision_loss, clippy::cast_possible_truncation, clippy::cast_sign_loss)]
    out.merge(optional_ui(
        ui,
        doc,
        &budget,
        crate::model::budget::DEFAULT_MAX_NODES as f64,
        |f| f.mesh.max_nodes.map(|v| v as f64),
        |f, v| f.mesh.max_nodes = v.map(|x| x.round().max(0.0) as usize),
    ));
    out
}
