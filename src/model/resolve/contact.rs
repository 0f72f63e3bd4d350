//! The pivot's Hertz contact keys of a pad (`pivot_contact`, `pivot_radius_mm`, `pivot_seat_radius_mm`,
//! `pivot_length_mm`, the seat's material) resolved into a [`PivotContact`]: a convex pivot of radius R1
//! in a seat of radius R2 > R1, the convex body of the pad's material; its law is in `physics::hertz`.

use super::super::case::{ContactKind, PadKind, PivotContact};
use super::super::error::{CaseError, Inconsistency};
use super::super::file::{ContactKindFile, PadFile};
use super::{inconsistent, missing, pad_name, PadSource};
use crate::key;
use crate::model::schema::KeySpec;

/// A numeric key of the pad tables and how to read it.
type PadNumber = (&'static KeySpec, fn(&PadFile) -> Option<f64>);

/// The pivot's Hertz contact (`pivot_contact` and its geometry keys); the convex body has the pad's
/// material `pad_material` (E [Pa], ν).
pub(super) fn resolve_contact(
    src: &PadSource<'_>,
    kind: PadKind,
    stiffness_given: bool,
    pad_material: (f64, f64),
) -> Result<Option<PivotContact>, CaseError> {
    let radius = key!("bearing.pads.pivot_radius_mm");
    let seat = key!("bearing.pads.pivot_seat_radius_mm");
    let length = key!("bearing.pads.pivot_length_mm");
    let seat_youngs = key!("bearing.pads.pivot_seat_youngs_modulus_gpa");
    let seat_poisson = key!("bearing.pads.pivot_seat_poisson_ratio");
    let geometry: [PadNumber; 5] = [
        (radius, |p| p.pivot_radius_mm),
        (seat, |p| p.pivot_seat_radius_mm),
        (length, |p| p.pivot_length_mm),
        (seat_youngs, |p| p.pivot_seat_youngs_modulus_gpa),
        (seat_poisson, |p| p.pivot_seat_poisson_ratio),
    ];
    let Some((contact, ckey)) = src.get("pivot_contact", |p| p.pivot_contact) else {
        if let Some((_, key)) = geometry.iter().find_map(|(row, f)| src.get(pad_name(row), f)) {
            return Err(inconsistent(key, Inconsistency::ContactWithoutKind));
        }
        return Ok(None);
    };
    if kind == PadKind::Fixed {
        return Err(inconsistent(ckey, Inconsistency::FixedSectorPivot));
    }
    if stiffness_given {
        return Err(inconsistent(ckey, Inconsistency::ContactAndStiffness));
    }
    let required = |(row, f): PadNumber| -> Result<f64, CaseError> {
        src.si(row, f)?.ok_or_else(|| missing(row.key, "pivot contact radius, mm"))
    };
    let [r, s, l, e, nu] = geometry;
    let (r1, r2) = (required(r)?, required(s)?);
    if r2 <= r1 {
        let key = src.get(pad_name(seat), |p| p.pivot_seat_radius_mm).map(|(_, k)| k).unwrap_or_default();
        return Err(inconsistent(
            key,
            Inconsistency::SeatNotLarger { seat_mm: seat.from_si(r2), pivot_mm: radius.from_si(r1) },
        ));
    }
    Ok(Some(PivotContact {
        kind: match contact {
            ContactKindFile::Rocker => ContactKind::Rocker,
            ContactKindFile::Ball => ContactKind::Ball,
        },
        pivot_radius_m: r1,
        seat_radius_m: r2,
        // Default: the bearing length (the row's).
        length_m: required(l)?,
        pivot_youngs_modulus_pa: pad_material.0,
        pivot_poisson_ratio: pad_material.1,
        seat_youngs_modulus_pa: required(e)?,
        seat_poisson_ratio: required(nu)?,
    }))
}
