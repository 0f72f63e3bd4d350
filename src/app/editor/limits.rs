//! Editor group for the design limits (`[limits]`): each optional, unchecked = the convention the schema
//! and [`crate::model::limits`] state. Limits enter no solver stage: editing them re-checks, never re-solves.

use egui::Ui;

use super::widgets::{opt_fields_ui, EditOutput, Num, OptField};
use crate::app::document::Document;
use crate::model::limits::{
    DEFAULT_MAX_PAD_TEMPERATURE_C, DEFAULT_MAX_PEAK_PRESSURE_MPA, DEFAULT_MAX_REYNOLDS, DEFAULT_MAX_SPECIFIC_LOAD_MPA,
    DEFAULT_MIN_FILM_UM,
};

const FIELDS: [OptField; 5] = [
    OptField {
        num: Num { key: "limits.min_film_thickness_um", label: "Minimum film h_min", decimals: 1 },
        default: DEFAULT_MIN_FILM_UM,
        get: |f| f.limits.min_film_thickness_um,
        set: |f, v| f.limits.min_film_thickness_um = v,
    },
    OptField {
        num: Num { key: "limits.max_pad_temperature_c", label: "Maximum pad temperature", decimals: 1 },
        default: DEFAULT_MAX_PAD_TEMPERATURE_C,
        get: |f| f.limits.max_pad_temperature_c,
        set: |f, v| f.limits.max_pad_temperature_c = v,
    },
    OptField {
        num: Num { key: "limits.max_specific_load_mpa", label: "Maximum specific load", decimals: 2 },
        default: DEFAULT_MAX_SPECIFIC_LOAD_MPA,
        get: |f| f.limits.max_specific_load_mpa,
        set: |f, v| f.limits.max_specific_load_mpa = v,
    },
    OptField {
        num: Num { key: "limits.max_peak_pressure_mpa", label: "Maximum peak pressure", decimals: 1 },
        default: DEFAULT_MAX_PEAK_PRESSURE_MPA,
        get: |f| f.limits.max_peak_pressure_mpa,
        set: |f, v| f.limits.max_peak_pressure_mpa = v,
    },
    OptField {
        num: Num { key: "limits.max_reynolds", label: "Maximum film Reynolds number", decimals: 0 },
        default: DEFAULT_MAX_REYNOLDS,
        get: |f| f.limits.max_reynolds,
        set: |f, v| f.limits.max_reynolds = v,
    },
];

pub fn limits_ui(ui: &mut Ui, doc: &mut Document) -> EditOutput {
    opt_fields_ui(ui, doc, &FIELDS)
}
