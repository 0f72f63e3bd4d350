//! Editor group for the thermal model (`[thermal]`): film energy equation, pad conduction, groove mixing.

use egui::Ui;

use super::widgets::{choice_ui, optional_ui, EditOutput, Num, Pick};
use crate::app::document::Document;
use crate::model::file::{CavitatedFilmFile, PadFilmBcFile, ThermalModelKind};

/// An optional number of `[thermal]`: its row and the default the solver uses when it is absent.
struct OptionalRow {
    num: Num<'static>,
    default: fn(&crate::model::CaseFile) -> f64,
    get: fn(&crate::model::CaseFile) -> Option<f64>,
    set: fn(&mut crate::model::CaseFile, Option<f64>),
}

const ROWS: [OptionalRow; 12] = [
    OptionalRow {
        num: Num { key: "thermal.h_oil_pad_w_per_m2_k", label: "Film–pad exchange H", decimals: 0 },
        default: |_| 4000.0,
        get: |f| f.thermal.h_oil_pad_w_per_m2_k,
        set: |f, v| f.thermal.h_oil_pad_w_per_m2_k = v,
    },
    OptionalRow {
        num: Num { key: "thermal.convection_w_per_m2_k", label: "Free convection H∞", decimals: 0 },
        default: |_| 100.0,
        get: |f| f.thermal.convection_w_per_m2_k,
        set: |f, v| f.thermal.convection_w_per_m2_k = v,
    },
    OptionalRow {
        num: Num { key: "thermal.ambient_temperature_c", label: "Surroundings T∞", decimals: 1 },
        default: |f| f.operating.supply_temperature_c,
        get: |f| f.thermal.ambient_temperature_c,
        set: |f, v| f.thermal.ambient_temperature_c = v,
    },
    OptionalRow {
        num: Num { key: "thermal.pad_conductivity_w_per_m_k", label: "Pad conductivity", decimals: 1 },
        default: |_| 45.0,
        get: |f| f.thermal.pad_conductivity_w_per_m_k,
        set: |f, v| f.thermal.pad_conductivity_w_per_m_k = v,
    },
    OptionalRow {
        num: Num { key: "thermal.carry_over", label: "Hot-oil carry-over λ", decimals: 2 },
        default: |_| 0.8,
        get: |f| f.thermal.carry_over,
        set: |f, v| f.thermal.carry_over = v,
    },
    OptionalRow {
        num: Num { key: "thermal.inlet_temperature_c", label: "Given inlet temperature", decimals: 1 },
        default: |f| f.operating.supply_temperature_c,
        get: |f| f.thermal.inlet_temperature_c,
        set: |f, v| f.thermal.inlet_temperature_c = v,
    },
    OptionalRow {
        num: Num { key: "thermal.journal_temperature_c", label: "Given journal temperature", decimals: 1 },
        default: |f| f.operating.supply_temperature_c + 10.0,
        get: |f| f.thermal.journal_temperature_c,
        set: |f, v| f.thermal.journal_temperature_c = v,
    },
    OptionalRow {
        num: Num { key: "thermal.pad_expansion_ppm_per_k", label: "Pad expansion α [10⁻⁶/K]", decimals: 1 },
        default: |_| 0.0,
        get: |f| f.thermal.pad_expansion_ppm_per_k,
        set: |f, v| f.thermal.pad_expansion_ppm_per_k = v,
    },
    OptionalRow {
        num: Num {
            key: "thermal.journal_expansion_ppm_per_k", label: "Journal expansion α [10⁻⁶/K]", decimals: 1
        },
        default: |_| 0.0,
        get: |f| f.thermal.journal_expansion_ppm_per_k,
        set: |f, v| f.thermal.journal_expansion_ppm_per_k = v,
    },
    OptionalRow {
        num: Num { key: "thermal.reference_temperature_c", label: "Clearance reference temperature", decimals: 1 },
        default: |f| f.operating.supply_temperature_c,
        get: |f| f.thermal.reference_temperature_c,
        set: |f, v| f.thermal.reference_temperature_c = v,
    },
    OptionalRow {
        num: Num {
            key: "thermal.housing_expansion_ppm_per_k", label: "Housing expansion α [10⁻⁶/K]", decimals: 1
        },
        default: |_| 0.0,
        get: |f| f.thermal.housing_expansion_ppm_per_k,
        set: |f, v| f.thermal.housing_expansion_ppm_per_k = v,
    },
    OptionalRow {
        num: Num { key: "thermal.housing_temperature_c", label: "Housing temperature", decimals: 1 },
        default: |f| f.operating.supply_temperature_c,
        get: |f| f.thermal.housing_temperature_c,
        set: |f, v| f.thermal.housing_temperature_c = v,
    },
];

pub fn thermal_ui(ui: &mut Ui, doc: &mut Document) -> EditOutput {
    let t = &doc.file().thermal;
    let (model, bc, cav) =
        (t.model.unwrap_or_default(), t.pad_film_bc.unwrap_or_default(), t.cavitated_film.unwrap_or_default());
    let mut out = choice_ui(
        ui,
        doc,
        Pick { key: "thermal.model", label: "Film model", tip: None },
        model,
        &[(ThermalModelKind::Isothermal, "Isothermal"), (ThermalModelKind::Thd, "Thermohydrodynamic (THD)")],
        |f, m| f.thermal.model = Some(m),
    );
    if model == ThermalModelKind::Isothermal {
        return out;
    }
    out.merge(choice_ui(
        ui,
        doc,
        Pick { key: "thermal.pad_film_bc", label: "Film–pad condition", tip: None },
        bc,
        &[
            (PadFilmBcFile::Bc1, "BC1 — adiabatic film"),
            (PadFilmBcFile::Bc2, "BC2 — exchange coefficient"),
            (PadFilmBcFile::Bc3, "BC3 — Knight & Barrett parabola"),
        ],
        |f, b| f.thermal.pad_film_bc = Some(b),
    ));
    out.merge(choice_ui(
        ui,
        doc,
        Pick { key: "thermal.cavitated_film", label: "Cavitated film", tip: None },
        cav,
        &[(CavitatedFilmFile::Striated, "Striated (film fraction)"), (CavitatedFilmFile::FullFilm, "Full film")],
        |f, c| f.thermal.cavitated_film = Some(c),
    ));
    for row in &ROWS {
        if row.num.key == "thermal.h_oil_pad_w_per_m2_k" && bc != PadFilmBcFile::Bc2 {
            continue;
        }
        let default = (row.default)(doc.file());
        out.merge(optional_ui(ui, doc, &row.num, default, row.get, row.set));
    }
    out
}
