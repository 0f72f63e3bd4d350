//! Design limits (`[limits]`): the values a designer does not want a solution to cross.
//!
//! ```text
//! h_min        ≥ min_film_thickness      smallest film thickness on any pad
//! T_pad,max    ≤ max_pad_temperature     hottest pad point (THD; the film maximum without pad solids)
//! W / (L D)    ≤ max_specific_load       load per projected area
//! p_max        ≤ max_peak_pressure       largest film pressure
//! Re_max       ≤ max_reynolds            largest local film Reynolds number ρ Ω R h / µ (laminar model)
//! ```
//!
//! Every key is optional; an absent key takes the default below. The defaults are **conventions** of
//! common practice for babbitted, oil-lubricated industrial journal bearings, not standards and not
//! properties of a material; a design review replaces them with the machine's own values:
//!
//! - `min_film_thickness_um` = 10 µm: ISO 7902-3 lists permissible minimum film thicknesses that grow with
//!   journal diameter and sliding speed, of about 3–20 µm for 25–1000 mm journals; 10 µm is a convention for
//!   the 100–250 mm turbomachinery class (it leaves room for roughness, misalignment and particles).
//! - `max_pad_temperature_c` = 120 °C: tin babbitt loses fatigue strength and creeps above roughly
//!   120–130 °C; alarm levels of about 115–120 °C and trips at 125–130 °C are common (Nicholas, *Tilting Pad
//!   Bearing Design*, Turbomachinery Symposium 1994, on metal-temperature limits).
//! - `max_specific_load_mpa` = 3.5 MPa: tilting-pad journal bearings commonly run at 1–3.5 MPa unit load
//!   W/(L·D) (Nicholas 1994 on load limits); the upper end of that range.
//! - `max_peak_pressure_mpa` = 20 MPa: a convention for babbitt fatigue; published allowables vary widely
//!   with babbitt thickness and temperature (roughly 15–35 MPa). Checked against published data: the
//!   fatigue strength of steel-backed tin-based white metal is about 15 MPa for a 0.2 mm lining and about
//!   28 MPa for a 0.04 mm one (lead handbook chapter "Pb–Sb–Sn", CRC Press, doi:10.1201/9781482276909-61,
//!   from fatigue tests under dynamic load). 20 MPa sits between the two; tilting-pad linings are commonly
//!   thicker than 0.2 mm, so under a dynamic load it would not be conservative. Under the steady load this
//!   solver models, the peak pressure alone is a weak fatigue criterion (the pressure variation a lining
//!   element sees matters more: "Hydrodynamic Aspects of Fatigue in Plain Journal Bearings", ASME J.
//!   Lubrication Technology 103(1), 1981, p. 150). So 20 MPa stays a screening value, stated as such; a
//!   design review replaces it by the bearing maker's figure for its lining.
//! - `max_reynolds` = 1000: the low end of the 1000–1500 laminar–turbulent transition reported for
//!   journal bearings (the regime check's laminar limit, `bearing::solution::regime::LAMINAR_REYNOLDS`); above it the
//!   laminar model this solver uses underestimates loss and temperature.
//!
//! The values, ranges and units are the rows of [`super::schema`] (`limits.*`); this module is the file
//! table and its SI form.

use serde::{Deserialize, Serialize};

use super::error::CaseError;
use crate::key;

/// `[limits]` as written: every value optional (default: the convention in the module doc).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct LimitsFile {
    /// Smallest acceptable film thickness h_min.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub min_film_thickness_um: Option<f64>,
    /// Highest acceptable pad (babbitt) temperature.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_pad_temperature_c: Option<f64>,
    /// Highest acceptable specific load W/(L·D).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_specific_load_mpa: Option<f64>,
    /// Highest acceptable peak film pressure.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_peak_pressure_mpa: Option<f64>,
    /// Highest acceptable local film Reynolds number.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_reynolds: Option<f64>,
}

impl LimitsFile {
    /// No key given (the section is then not written back).
    #[must_use]
    pub fn is_empty(&self) -> bool {
        *self == Self::default()
    }
}

/// Design limits, SI (temperatures °C).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Limits {
    pub min_film_thickness_m: f64,
    pub max_pad_temperature_c: f64,
    pub max_specific_load_pa: f64,
    pub max_peak_pressure_pa: f64,
    pub max_reynolds: f64,
}

impl Default for Limits {
    /// The conventions of the module doc (the rows' defaults).
    fn default() -> Self {
        resolve_limits(&LimitsFile::default()).unwrap_or(Self {
            min_film_thickness_m: 0.0,
            max_pad_temperature_c: f64::INFINITY,
            max_specific_load_pa: f64::INFINITY,
            max_peak_pressure_pa: f64::INFINITY,
            max_reynolds: f64::INFINITY,
        })
    }
}

/// Validates `[limits]` and converts to SI.
///
/// # Errors
/// A value outside its range, naming its key.
pub fn resolve_limits(file: &LimitsFile) -> Result<Limits, CaseError> {
    Ok(Limits {
        min_film_thickness_m: key!("limits.min_film_thickness_um").value(file.min_film_thickness_um)?,
        max_pad_temperature_c: key!("limits.max_pad_temperature_c").value(file.max_pad_temperature_c)?,
        max_specific_load_pa: key!("limits.max_specific_load_mpa").value(file.max_specific_load_mpa)?,
        max_peak_pressure_pa: key!("limits.max_peak_pressure_mpa").value(file.max_peak_pressure_mpa)?,
        max_reynolds: key!("limits.max_reynolds").value(file.max_reynolds)?,
    })
}
