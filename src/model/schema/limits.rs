//! Rows of `[limits]`: the design limits results are checked against. Every default is a convention of common
//! practice, not a property; [`crate::model::limits`] says where each comes from.

use super::Fallback::Convention;
use super::Group::Limits;
use super::Widget::Optional;
use super::{KeySpec, TEMPERATURE};
use crate::model::error::Range;
use crate::units::{CELSIUS, MPA, ONE, UM};

type Key = KeySpec;

pub(super) const KEYS: &[Key] = &[
    Key::number("limits.min_film_thickness_um", UM, Range::positive(1000.0))
        .typical(5.0, 30.0)
        .default(Convention(10.0))
        .edit(Limits, "Minimum film h_min", Optional(1))
        .meaning("Smallest acceptable film thickness on any pad. ISO 7902-3 permits about 3–20 µm depending on journal diameter and speed; 10 µm is a convention for 100–250 mm journals."),
    Key::number("limits.max_pad_temperature_c", CELSIUS, TEMPERATURE)
        .typical(90.0, 130.0)
        .default(Convention(120.0))
        .edit(Limits, "Maximum pad temperature", Optional(1))
        .meaning("Hottest acceptable pad (babbitt) temperature; checked on THD solves (the film maximum when the pads have no solid). Tin babbitt softens above about 120–130 °C."),
    Key::number("limits.max_specific_load_mpa", MPA, Range::positive(1000.0))
        .typical(1.0, 5.0)
        .default(Convention(3.5))
        .edit(Limits, "Maximum specific load", Optional(2))
        .meaning("Highest acceptable unit load W/(L·D). Tilting-pad journal bearings commonly run at 1–3.5 MPa."),
    Key::number("limits.max_peak_pressure_mpa", MPA, Range::positive(10_000.0))
        .typical(10.0, 40.0)
        .default(Convention(20.0))
        .edit(Limits, "Maximum peak pressure", Optional(1))
        .meaning("Highest acceptable film pressure (babbitt fatigue). Published allowables range from about 15 to 35 MPa with babbitt thickness and temperature."),
    Key::number("limits.max_reynolds", ONE, Range::positive(1e7))
        .typical(500.0, 2000.0)
        .default(Convention(1000.0))
        .edit(Limits, "Maximum film Reynolds number", Optional(0))
        .meaning("Highest acceptable local film Reynolds number ρ Ω R h / µ: above the laminar–turbulent transition (1000–1500) the laminar model underestimates loss and temperature."),
];
