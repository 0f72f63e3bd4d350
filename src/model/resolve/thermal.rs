//! The `[thermal]` and `[feeding]` tables resolved: the film model and the film–pad exchange (a BC2
//! coefficient only with BC2), the pads' conduction and surroundings, the thermal growth, and the feeding kind
//! with the one carry-over it uses.

use super::super::case::{Feeding, PadFilmBc, Thermal};
use super::super::error::{CaseError, Inconsistency};
use super::super::file::{CaseFile, FeedingKind, PadFilmBcFile};
use super::{inconsistent, missing};
use crate::key;

/// `[thermal]`: the defaults are the rows' (isothermal model, BC1, H∞ = 100 W/(m² K), T∞ = supply
/// temperature, pad conductivity 45 W/(m K), carry-over λ = 0.8, inlet and journal temperatures computed,
/// striated cavitated film, no thermal growth).
pub(super) fn resolve_thermal(file: &CaseFile) -> Result<Thermal, CaseError> {
    let t = &file.thermal;
    let h = key!("thermal.h_oil_pad_w_per_m2_k");
    let pad_film_bc = match (t.pad_film_bc.unwrap_or_default(), t.h_oil_pad_w_per_m2_k) {
        (PadFilmBcFile::Bc2, Some(v)) => PadFilmBc::Bc2 { h_w_per_m2_k: h.value(Some(v))? },
        (PadFilmBcFile::Bc2, None) => {
            return Err(missing(h.key, "film–pad exchange coefficient for pad_film_bc = \"bc2\", W/(m² K)"));
        }
        (_, Some(_)) => return Err(inconsistent(h.key, Inconsistency::OnlyWithBc2)),
        (PadFilmBcFile::Bc1, None) => PadFilmBc::Bc1,
        (PadFilmBcFile::Bc3, None) => PadFilmBc::Bc3,
    };
    Ok(Thermal {
        model: t.model.unwrap_or_default(),
        pad_film_bc,
        convection_w_per_m2_k: key!("thermal.convection_w_per_m2_k").value(t.convection_w_per_m2_k)?,
        ambient_temperature_c: key!("thermal.ambient_temperature_c").value_in(file, t.ambient_temperature_c)?,
        pad_conductivity_w_per_m_k: key!("thermal.pad_conductivity_w_per_m_k").value(t.pad_conductivity_w_per_m_k)?,
        inlet_temperature_c: key!("thermal.inlet_temperature_c").optional(t.inlet_temperature_c)?,
        journal_temperature_c: key!("thermal.journal_temperature_c").optional(t.journal_temperature_c)?,
        cavitated_film: t.cavitated_film.unwrap_or_default(),
        pad_expansion_per_k: key!("thermal.pad_expansion_ppm_per_k").value(t.pad_expansion_ppm_per_k)?,
        journal_expansion_per_k: key!("thermal.journal_expansion_ppm_per_k").value(t.journal_expansion_ppm_per_k)?,
        reference_temperature_c: key!("thermal.reference_temperature_c").optional(t.reference_temperature_c)?,
        housing_expansion_per_k: key!("thermal.housing_expansion_ppm_per_k").value(t.housing_expansion_ppm_per_k)?,
        housing_temperature_c: key!("thermal.housing_temperature_c").optional(t.housing_temperature_c)?,
        feeding: resolve_feeding(file)?,
    })
}

/// `[feeding]` with the carry-over of its kind: `thermal.carry_over` for the flooded housing and the spray bar,
/// `feeding.groove_carry_over` for the leading-edge groove; a carry-over given for another kind is an error
/// (it would be ignored).
fn resolve_feeding(file: &CaseFile) -> Result<Feeding, CaseError> {
    let kind = file.feeding.kind.unwrap_or_default();
    let (flooded_key, groove_key) = (key!("thermal.carry_over"), key!("feeding.groove_carry_over"));
    // Ranges first: a value out of range is named as such whatever the feeding.
    let flooded = flooded_key.optional(file.thermal.carry_over)?;
    let groove = groove_key.optional(file.feeding.groove_carry_over)?;
    let unused = |key: &str, used: &str| {
        inconsistent(
            key,
            Inconsistency::CarryOverOfOtherFeeding { kind: kind_word(kind).to_string(), used: used.to_string() },
        )
    };
    Ok(match kind {
        FeedingKind::LeadingEdgeGroove => {
            if flooded.is_some() {
                return Err(unused(flooded_key.key, groove_key.key));
            }
            Feeding::LeadingEdgeGroove { carry_over: groove_key.value(groove)? }
        }
        FeedingKind::Flooded | FeedingKind::SprayBar => {
            if groove.is_some() {
                return Err(unused(groove_key.key, flooded_key.key));
            }
            let carry_over = flooded_key.value(flooded)?;
            if kind == FeedingKind::Flooded {
                Feeding::Flooded { carry_over }
            } else {
                Feeding::SprayBar { carry_over }
            }
        }
    })
}

/// A feeding kind as the case file writes it.
fn kind_word(kind: FeedingKind) -> &'static str {
    match kind {
        FeedingKind::Flooded => "flooded",
        FeedingKind::LeadingEdgeGroove => "leading_edge_groove",
        FeedingKind::SprayBar => "spray_bar",
    }
}
