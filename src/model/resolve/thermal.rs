//! The `[thermal]` and `[feeding]` tables resolved: the film model and the film–pad exchange (a BC2
//! coefficient only with BC2), the pads' conduction and surroundings, the thermal growth, and the feeding kind
//! with the one carry-over it uses.

use super::super::case::Bearing;
use super::super::case::{Feeding, PadFilmBc, Thermal};
use super::super::error::{CaseError, Inconsistency};
use super::super::file::{CaseFile, Cavitation, FeedingKind, PadFilmBcFile};
use super::{inconsistent, missing};
use crate::key;
use crate::units::DEG;
use std::f64::consts::TAU;

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
    let churning_key = key!("feeding.churning_factor");
    let churning = churning_key.optional(file.feeding.churning_factor)?;
    if churning.is_some() && kind != FeedingKind::Flooded {
        return Err(inconsistent(
            churning_key.key,
            Inconsistency::OnlyWithFlooded { kind: kind_word(kind).to_string() },
        ));
    }
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
                Feeding::Flooded { carry_over, churning_factor: churning_key.value(churning)? }
            } else {
                Feeding::SprayBar { carry_over }
            }
        }
    })
}

/// `feeding.ram_pressure_coefficient`: in its row's range, and only with a full (pressurised) inlet.
pub(super) fn resolve_ram_pressure(file: &CaseFile) -> Result<f64, CaseError> {
    let row = key!("feeding.ram_pressure_coefficient");
    let k = row.value(file.feeding.ram_pressure_coefficient)?;
    if k > 0.0 && file.physics.cavitation == Some(Cavitation::Jfo) {
        return Err(inconsistent(row.key, Inconsistency::RamPressureWithJfo));
    }
    Ok(k)
}

/// `feeding.groove_width_deg`: in its row's range, with a leading-edge groove only, and no wider than the
/// gap ahead of any pad (the next pad's leading edge less this pad's leading edge and arc, around the bore).
pub(super) fn check_groove_width(file: &CaseFile, bearing: &Bearing) -> Result<(), CaseError> {
    let row = key!("feeding.groove_width_deg");
    let Some(width) = row.optional(file.feeding.groove_width_deg)? else { return Ok(()) };
    if file.feeding.kind != Some(FeedingKind::LeadingEdgeGroove) {
        return Err(inconsistent(row.key, Inconsistency::OnlyWithGroove));
    }
    let pads = &bearing.pads;
    let mut order: Vec<usize> = (0..pads.len()).collect();
    order.sort_by(|&a, &b| {
        pads[a].leading_edge_rad.rem_euclid(TAU).total_cmp(&pads[b].leading_edge_rad.rem_euclid(TAU))
    });
    // The gap ahead of each pad: from the end of the pad before it (around the bore) to its leading edge.
    let (gap, pad) = (0..order.len())
        .map(|i| {
            let (prev, this) = (&pads[order[(i + order.len() - 1) % order.len()]], order[i]);
            let end = prev.leading_edge_rad + prev.arc_rad;
            ((pads[this].leading_edge_rad - end).rem_euclid(TAU), this)
        })
        .fold((f64::INFINITY, 0), |m, g| if g.0 < m.0 { g } else { m });
    // A full 360° sector leaves no gap (rem_euclid of a whole turn).
    let gap = if pads.iter().map(|p| p.arc_rad).sum::<f64>() >= TAU { 0.0 } else { gap };
    if width > gap * (1.0 + 1e-12) {
        // Rounded to a micro-degree, so that 72° − 60° reads 12.
        let gap_deg = (DEG.from_si(gap) * 1e6).round() / 1e6;
        return Err(inconsistent(
            row.key,
            Inconsistency::GrooveWiderThanGap { width_deg: (DEG.from_si(width) * 1e6).round() / 1e6, gap_deg, pad },
        ));
    }
    Ok(())
}

/// A feeding kind as the case file writes it.
fn kind_word(kind: FeedingKind) -> &'static str {
    match kind {
        FeedingKind::Flooded => "flooded",
        FeedingKind::LeadingEdgeGroove => "leading_edge_groove",
        FeedingKind::SprayBar => "spray_bar",
    }
}
