//! Editor groups for how the bearing runs and is modelled: lubricant, operating point, physics model,
//! fidelity.

use egui::Ui;

use super::bearing::{pads_with_injection, per_pad_count};
use super::widgets::{choice_ui, Pick, fields_ui, number_ui, opt_fields_ui, optional_ui, per_pad_ui, EditOutput, Field, Num, OptField};
use crate::app::document::Document;
use crate::model::file::{Cavitation, Fidelity, OneOrMany};
use crate::model::CaseFile;

const VISCOSITY_1: [Field; 2] = [
    Field {
        num: Num {
            key: "lubricant.viscosity_pa_s",
            label: "Viscosity µ1",
            unit: "Pa·s",
            range: (0.002, 0.1),
            decimals: 5,
            tip: "Dynamic viscosity at the first catalogue temperature (ISO VG32 ≈ 0.028 Pa·s at 40 °C). Pressure and load capacity scale with µ.",
        },
        get: |f| f.lubricant.viscosity_pa_s,
        set: |f, v| f.lubricant.viscosity_pa_s = v,
    },
    Field {
        num: Num { key: "lubricant.viscosity_temperature_c", label: "at temperature T1", unit: "°C", range: (20.0, 100.0), decimals: 1, tip: "Temperature of the first viscosity point." },
        get: |f| f.lubricant.viscosity_temperature_c,
        set: |f, v| f.lubricant.viscosity_temperature_c = v,
    },
];

const VISCOSITY_COEFFICIENT: Field = Field {
    num: Num {
        key: "lubricant.viscosity_coefficient_per_k",
        label: "Temperature coefficient η",
        unit: "1/K",
        range: (0.0, 0.06),
        decimals: 4,
        tip: "µ(T) = µ1 exp(−η (T − T1)): how fast the oil thins with temperature (mineral oils ≈ 0.03 /K).",
    },
    get: |f| f.lubricant.viscosity_coefficient_per_k.unwrap_or(0.0),
    set: |f, v| f.lubricant.viscosity_coefficient_per_k = Some(v),
};

const VISCOSITY_2: [Field; 2] = [
    Field {
        num: Num { key: "lubricant.viscosity2_pa_s", label: "Viscosity µ2", unit: "Pa·s", range: (0.001, 0.05), decimals: 5, tip: "Second catalogue viscosity point: with the first it fixes the exponential viscosity–temperature law." },
        get: |f| f.lubricant.viscosity2_pa_s.unwrap_or(0.0),
        set: |f, v| f.lubricant.viscosity2_pa_s = Some(v),
    },
    Field {
        num: Num { key: "lubricant.viscosity2_temperature_c", label: "at temperature T2", unit: "°C", range: (40.0, 120.0), decimals: 1, tip: "Temperature of the second viscosity point (e.g. 100 °C)." },
        get: |f| f.lubricant.viscosity2_temperature_c.unwrap_or(0.0),
        set: |f, v| f.lubricant.viscosity2_temperature_c = Some(v),
    },
];

const OIL_PROPERTIES: [Field; 3] = [
    Field {
        num: Num { key: "lubricant.density_kg_per_m3", label: "Density ρ", unit: "kg/m³", range: (800.0, 950.0), decimals: 1, tip: "Oil density (thermal model: heat carried by the flow)." },
        get: |f| f.lubricant.density_kg_per_m3,
        set: |f, v| f.lubricant.density_kg_per_m3 = v,
    },
    Field {
        num: Num { key: "lubricant.specific_heat_j_per_kg_k", label: "Specific heat c_p", unit: "J/(kg·K)", range: (1700.0, 2200.0), decimals: 0, tip: "Heat capacity of the oil (thermal model)." },
        get: |f| f.lubricant.specific_heat_j_per_kg_k,
        set: |f, v| f.lubricant.specific_heat_j_per_kg_k = v,
    },
    Field {
        num: Num { key: "lubricant.conductivity_w_per_m_k", label: "Conductivity κ", unit: "W/(m·K)", range: (0.1, 0.16), decimals: 3, tip: "Thermal conductivity of the oil (thermal model)." },
        get: |f| f.lubricant.conductivity_w_per_m_k,
        set: |f, v| f.lubricant.conductivity_w_per_m_k = v,
    },
];

/// A free-text row (names and titles); an empty text removes the key.
pub fn text_ui(ui: &mut Ui, doc: &mut Document, key: &'static str, label: &str, tip: &str, get: fn(&CaseFile) -> Option<String>, set: fn(&mut CaseFile, Option<String>)) -> EditOutput {
    let label = ui.label(label).on_hover_text(tip);
    let mut text = get(doc.file()).unwrap_or_default();
    let changed = ui.add_sized([200.0, 20.0], egui::TextEdit::singleline(&mut text)).labelled_by(label.id).on_hover_text(tip).changed();
    if changed {
        doc.edit(key, true, |f| set(f, (!text.is_empty()).then(|| text.clone())));
    }
    ui.label("");
    ui.end_row();
    EditOutput { changed, ..EditOutput::default() }
}

pub fn lubricant_ui(ui: &mut Ui, doc: &mut Document) -> EditOutput {
    let mut out = text_ui(ui, doc, "lubricant.name", "Name", "Oil name, for the record (e.g. ISO VG32).", |f| f.lubricant.name.clone(), |f, v| f.lubricant.name = v);
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
    num: Num {
        key: "operating.speed_rpm",
        label: "Speed",
        unit: "rpm",
        range: (500.0, 15000.0),
        decimals: 0,
        tip: "Journal speed. Faster running drags more oil into the wedge: the journal rises towards the centre (smaller ε), power loss grows about with the square of speed.",
    },
    get: |f| f.operating.speed_rpm,
    set: |f, v| f.operating.speed_rpm = v,
};

const LOAD: (Field, OptField) = (
    Field {
        num: Num {
            key: "operating.load_n",
            label: "Load W",
            unit: "N",
            range: (0.0, 50000.0),
            decimals: 1,
            tip: "Static load on the journal (for example the rotor weight share). Specific loads of 0.5–3 MPa on the projected area L·D are usual.",
        },
        get: |f| f.operating.load_n.unwrap_or(0.0),
        set: |f, v| f.operating.load_n = Some(v),
    },
    OptField {
        num: Num { key: "operating.load_angle_deg", label: "Load direction", unit: "°", range: (0.0, 360.0), decimals: 1, tip: "Direction of the load from +x, counter-clockwise: 270° is straight down." },
        default: 270.0,
        get: |f| f.operating.load_angle_deg,
        set: |f, v| f.operating.load_angle_deg = v,
    },
);

const POSITION: (Field, OptField) = (
    Field {
        num: Num { key: "operating.eccentricity_ratio", label: "Eccentricity ε", unit: "–", range: (0.0, 0.9), decimals: 3, tip: "Prescribed journal displacement divided by the assembled clearance." },
        get: |f| f.operating.eccentricity_ratio.unwrap_or(0.0),
        set: |f, v| f.operating.eccentricity_ratio = Some(v),
    },
    OptField {
        num: Num { key: "operating.eccentricity_angle_deg", label: "Displacement direction", unit: "°", range: (0.0, 360.0), decimals: 1, tip: "Direction of the prescribed displacement from +x, counter-clockwise." },
        default: 270.0,
        get: |f| f.operating.eccentricity_angle_deg,
        set: |f, v| f.operating.eccentricity_angle_deg = v,
    },
);

const SUPPLY: Field = Field {
    num: Num { key: "operating.supply_temperature_c", label: "Supply temperature", unit: "°C", range: (20.0, 70.0), decimals: 1, tip: "Temperature of the oil fed to the bearing." },
    get: |f| f.operating.supply_temperature_c,
    set: |f, v| f.operating.supply_temperature_c = v,
};

/// Temperatures that default to the supply temperature.
const SUPPLY_DEFAULTED: [OptField; 2] = [
    OptField {
        num: Num {
            key: "operating.film_temperature_c",
            label: "Film temperature",
            unit: "°C",
            range: (20.0, 120.0),
            decimals: 1,
            tip: "The one temperature of the isothermal film (sets its viscosity). Unset: the supply temperature. A few tens of kelvin above supply is more realistic.",
        },
        default: f64::NAN,
        get: |f| f.operating.film_temperature_c,
        set: |f, v| f.operating.film_temperature_c = v,
    },
    OptField {
        num: Num {
            key: "operating.injection_temperature_c",
            label: "Injection temperature",
            unit: "°C",
            range: (20.0, 80.0),
            decimals: 1,
            tip: "Temperature of the injected oil: sets its viscosity in the orifice (and cools the film in the thermal model). Unset: the supply temperature.",
        },
        default: f64::NAN,
        get: |f| f.operating.injection_temperature_c,
        set: |f, v| f.operating.injection_temperature_c = v,
    },
];

const EXCITATION: OptField = OptField {
    num: Num {
        key: "operating.excitation_ratio",
        label: "Excitation ratio ω/Ω",
        unit: "–",
        range: (0.0, 3.0),
        decimals: 3,
        tip: "Frequency at which the pad coordinates are condensed out of the coefficients, relative to the running speed. 1 = synchronous (unbalance response); sub-synchronous values matter for stability.",
    },
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
        Pick { key: "operating.load_mode", label: "Journal position from", tip: "Either give the static load and find where the journal settles, or prescribe the journal position and find the load it carries." },
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
    let n = Num {
        key: "operating.injection_pressure_bar",
        label: "Injection pressure",
        unit: "bar",
        range: (0.0, 100.0),
        decimals: 1,
        tip: "Pressure at the orifice entry (controllable lubrication). 0: the orifice is open to ambient and acts as a sink where the film pressure is higher. High pressure lifts the pad and reverses the film flow upstream of the orifice.",
    };
    let mut separate = matches!(doc.file().operating.injection_pressure_bar, Some(OneOrMany::Many(_)));
    ui.label("");
    if ui.checkbox(&mut separate, "Injection pressure per pad").on_hover_text("Give each pad its own injection pressure (e.g. only the loaded pad injects).").changed() {
        let count = per_pad_count(doc.file());
        doc.edit(n.key, false, |f| {
            let mut all = pads_with_injection(f);
            all.resize(count, 0.0);
            f.operating.injection_pressure_bar = Some(if separate { OneOrMany::Many(all) } else { OneOrMany::One(all.first().copied().unwrap_or(0.0)) });
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
        Pick { key: "physics.cavitation", label: "Cavitation", tip: "Where the film diverges the pressure would fall below ambient; oil cannot sustain that and the film ruptures. Reynolds (Swift–Stieber): p ≥ 0 with zero flux gradient at the rupture boundary, solved exactly. Gümbel: solve, then clip negative pressures (simpler, violates mass conservation)." },
        cav,
        &[(Cavitation::Reynolds, "Reynolds (Swift–Stieber)"), (Cavitation::Gumbel, "Gümbel (half-Sommerfeld)")],
        |f, c| f.physics.cavitation = Some(c),
    );
    let touchdown = Num {
        key: "physics.touchdown_film_um",
        label: "Touchdown film",
        unit: "µm",
        range: (0.1, 10.0),
        decimals: 2,
        tip: "Smallest film thickness accepted at equilibrium; below it the solve reports touchdown (contact through the surface roughness).",
    };
    let cb = doc.file().bearing.assembled_clearance_um;
    out.merge(optional_ui(ui, doc, &touchdown, 0.01 * cb, |f| f.physics.touchdown_film_um, |f, v| f.physics.touchdown_film_um = v));
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
type CountRow = (&'static str, &'static str, fn(Fidelity) -> usize, fn(&CaseFile) -> Option<usize>, fn(&mut CaseFile, Option<usize>));
const COUNTS: [CountRow; 4] = [
    ("mesh.circumferential_elements", "Circumferential elements", |l| l.elements().0, |f| f.mesh.circumferential_elements, |f, v| f.mesh.circumferential_elements = v),
    ("mesh.axial_elements", "Axial elements", |l| l.elements().1, |f| f.mesh.axial_elements, |f, v| f.mesh.axial_elements = v),
    ("mesh.orifice_elements", "Elements across an orifice", |l| l.elements().2, |f| f.mesh.orifice_elements, |f, v| f.mesh.orifice_elements = v),
    ("mesh.pad_radial_elements", "Pad layers (thermal)", Fidelity::pad_radial_elements, |f| f.mesh.pad_radial_elements, |f, v| f.mesh.pad_radial_elements = v),
];

pub fn fidelity_ui(ui: &mut Ui, doc: &mut Document) -> EditOutput {
    let fid = doc.file().mesh.fidelity.unwrap_or_default();
    let mut out = choice_ui(
        ui,
        doc,
        Pick { key: "mesh.fidelity", label: "Mesh fidelity", tip: "Element counts per pad: preview 16×8 (fast, a few % error), standard 36×16, reference 96×48 (for convergence checks). Each orifice is refined further." },
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
        Pick { key: "mesh.half_model", label: "Half model", tip: "Model half the pad length with a symmetry plane (half the cost). Automatic: used when every orifice is on the mid-plane, the only case where the film is symmetric." },
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
    #[allow(clippy::cast_precision_loss, clippy::cast_possible_truncation, clippy::cast_sign_loss)]
    for (key, label, level, get, set) in COUNTS {
        let num = Num { key, label, unit: "", range: (2.0, 200.0), decimals: 0, tip: "Explicit element count, overriding the fidelity level." };
        out.merge(optional_ui(ui, doc, &num, level(fid) as f64, |f| get(f).map(|v| v as f64), |f, v| set(f, v.map(|x| x.round().max(0.0) as usize))));
    }
    let budget = Num {
        key: "mesh.max_nodes",
        label: "Node budget",
        unit: "nodes",
        range: (1e4, 1e7),
        decimals: 0,
        tip: "Most mesh nodes a solve may allocate: film nodes over all pads plus, with the thermal model, the pad solids' nodes. A case whose meshes (element counts, orifice refinement) would need more is refused before anything is built; memory and time grow faster than the node count.",
    };
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
