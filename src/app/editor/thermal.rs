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

const ROWS: [OptionalRow; 7] = [
    OptionalRow {
        num: Num { key: "thermal.h_oil_pad_w_per_m2_k", label: "Film–pad exchange H", unit: "W/(m²·K)", range: (100.0, 20_000.0), decimals: 0, tip: "BC2 only: heat flux from the film into the pad surface per kelvin of difference. A single coefficient cannot describe the laminar film well (the thesis shows BC2 is poor); offered for comparison." },
        default: |_| 4000.0,
        get: |f| f.thermal.h_oil_pad_w_per_m2_k,
        set: |f, v| f.thermal.h_oil_pad_w_per_m2_k = v,
    },
    OptionalRow {
        num: Num { key: "thermal.convection_w_per_m2_k", label: "Free convection H∞", unit: "W/(m²·K)", range: (10.0, 1000.0), decimals: 0, tip: "Heat-transfer coefficient from the pads' free faces (back, sides, edges) to the surrounding oil at T∞." },
        default: |_| 100.0,
        get: |f| f.thermal.convection_w_per_m2_k,
        set: |f, v| f.thermal.convection_w_per_m2_k = v,
    },
    OptionalRow {
        num: Num { key: "thermal.ambient_temperature_c", label: "Surroundings T∞", unit: "°C", range: (0.0, 150.0), decimals: 1, tip: "Temperature of the oil around the pads (default: the supply temperature)." },
        default: |f| f.operating.supply_temperature_c,
        get: |f| f.thermal.ambient_temperature_c,
        set: |f, v| f.thermal.ambient_temperature_c = v,
    },
    OptionalRow {
        num: Num { key: "thermal.pad_conductivity_w_per_m_k", label: "Pad conductivity", unit: "W/(m·K)", range: (1.0, 400.0), decimals: 1, tip: "Thermal conductivity of the pad material (steel ≈ 45, brass ≈ 109, bronze ≈ 60)." },
        default: |_| 45.0,
        get: |f| f.thermal.pad_conductivity_w_per_m_k,
        set: |f, v| f.thermal.pad_conductivity_w_per_m_k = v,
    },
    OptionalRow {
        num: Num { key: "thermal.carry_over", label: "Hot-oil carry-over λ", unit: "–", range: (0.0, 1.0), decimals: 2, tip: "Fraction of the hot oil leaving a pad's trailing edge that enters the next pad (typically 0.7–0.9); fresh supply oil makes up the rest of the leading-edge inflow." },
        default: |_| 0.8,
        get: |f| f.thermal.carry_over,
        set: |f, v| f.thermal.carry_over = v,
    },
    OptionalRow {
        num: Num { key: "thermal.inlet_temperature_c", label: "Given inlet temperature", unit: "°C", range: (0.0, 150.0), decimals: 1, tip: "Leading-edge oil temperature of every pad, when measured. Unset: from the groove mixing balance." },
        default: |f| f.operating.supply_temperature_c,
        get: |f| f.thermal.inlet_temperature_c,
        set: |f, v| f.thermal.inlet_temperature_c = v,
    },
    OptionalRow {
        num: Num { key: "thermal.journal_temperature_c", label: "Given journal temperature", unit: "°C", range: (0.0, 150.0), decimals: 1, tip: "Journal surface temperature, when known. Unset: from zero net heat flux into the journal." },
        default: |f| f.operating.supply_temperature_c + 10.0,
        get: |f| f.thermal.journal_temperature_c,
        set: |f, v| f.thermal.journal_temperature_c = v,
    },
];

pub fn thermal_ui(ui: &mut Ui, doc: &mut Document) -> EditOutput {
    let t = &doc.file().thermal;
    let (model, bc, cav) = (t.model.unwrap_or_default(), t.pad_film_bc.unwrap_or_default(), t.cavitated_film.unwrap_or_default());
    let mut out = choice_ui(
        ui,
        doc,
        Pick { key: "thermal.model", label: "Film model", tip: "Isothermal: one viscosity, at the film temperature. THD: the film energy equation (shear heating, convection, conduction, injection), 3-D pad conduction and the groove mixing between pads, iterated with the equilibrium until the viscosity field converges. THD lowers stiffness and damping." },
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
        Pick { key: "thermal.pad_film_bc", label: "Film–pad condition", tip: "BC1: adiabatic film, the pad surface takes the film temperature (decoupled, fast; laminar bearings). BC2: convective exchange with a constant coefficient. BC3 (Knight & Barrett): parabolic temperature across the film, coupled with the pad and the journal (near the laminar limit)." },
        bc,
        &[(PadFilmBcFile::Bc1, "BC1 — adiabatic film"), (PadFilmBcFile::Bc2, "BC2 — exchange coefficient"), (PadFilmBcFile::Bc3, "BC3 — Knight & Barrett parabola")],
        |f, b| f.thermal.pad_film_bc = Some(b),
    ));
    out.merge(choice_ui(
        ui,
        doc,
        Pick { key: "thermal.cavitated_film", label: "Cavitated film", tip: "Striated: in a ruptured zone oil fills only the fraction of the gap that carries the flow entering it (mass conservation of the Couette flow); shear and heat capacity scale with it. Full film: as the thesis assumes." },
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
