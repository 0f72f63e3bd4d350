//! The pivot's Hertz contact keys of a pad (`pivot_contact`, `pivot_radius_mm`, `pivot_seat_radius_mm`,
//! `pivot_length_mm`, the seat's material) resolved into a [`PivotContact`]: a convex pivot of radius R1
//! in a seat of radius R2 > R1, the convex body of the pad's material; its law is in `physics::hertz`.

use super::super::case::PadKind;
use super::super::error::{CaseError, Range};
use super::super::file::{ContactKindFile, PadFile};
use super::{inconsistent, material, missing, PadKey, PadSource, MM};
use crate::physics::hertz::{ContactKind, PivotContact};

/// The pivot's Hertz contact (`pivot_contact` and its geometry keys); the convex body has the pad's
/// material `pad_material` (E [Pa], ν).
pub(super) fn resolve_contact(
    src: &PadSource<'_>,
    kind: PadKind,
    stiffness_given: bool,
    pad_material: (f64, f64),
    length: f64,
) -> Result<Option<PivotContact>, CaseError> {
    let geometry_keys: [PadKey; 5] = [
        ("pivot_radius_mm", |p| p.pivot_radius_mm),
        ("pivot_seat_radius_mm", |p| p.pivot_seat_radius_mm),
        ("pivot_length_mm", |p| p.pivot_length_mm),
        ("pivot_seat_youngs_modulus_gpa", |p| p.pivot_seat_youngs_modulus_gpa),
        ("pivot_seat_poisson_ratio", |p| p.pivot_seat_poisson_ratio),
    ];
    let Some((contact, ckey)) = src.get("pivot_contact", |p| p.pivot_contact) else {
        if let Some((_, key)) = geometry_keys.iter().find_map(|(name, f)| src.get(name, f)) {
            return Err(inconsistent(
                &key,
                "describes a pivot contact: give bearing.pads.pivot_contact (\"rocker\" or \"ball\") too, or remove it",
            ));
        }
        return Ok(None);
    };
    if kind == PadKind::Fixed {
        return Err(inconsistent(&ckey, "a fixed sector has no pivot"));
    }
    if stiffness_given {
        return Err(inconsistent(&ckey, "give either a pivot contact or pivot_stiffness_n_per_m, not both"));
    }
    let mm = |name: &str, f: fn(&PadFile) -> Option<f64>| -> Result<f64, CaseError> {
        let (v, key) =
            src.get(name, f).ok_or_else(|| missing(&PadSource::common_key(name), "pivot contact radius, mm"))?;
        Ok(Range::positive(1e4).check(&key, v)? * MM)
    };
    let r1 = mm("pivot_radius_mm", |p| p.pivot_radius_mm)?;
    let r2 = mm("pivot_seat_radius_mm", |p| p.pivot_seat_radius_mm)?;
    if r2 <= r1 {
        let key = src.get("pivot_seat_radius_mm", |p| p.pivot_seat_radius_mm).map(|(_, k)| k).unwrap_or_default();
        return Err(inconsistent(
            &key,
            format!("the seat ({:.4} mm) must be larger than the pivot radius ({:.4} mm)", r2 / MM, r1 / MM),
        ));
    }
    let contact_length = match src.get("pivot_length_mm", |p| p.pivot_length_mm) {
        Some((v, key)) => Range::positive(1e4).check(&key, v)? * MM,
        None => length,
    };
    let (seat_e, seat_nu) = material(
        src,
        ("pivot_seat_youngs_modulus_gpa", |p| p.pivot_seat_youngs_modulus_gpa),
        ("pivot_seat_poisson_ratio", |p| p.pivot_seat_poisson_ratio),
    )?;
    Ok(Some(PivotContact {
        kind: match contact {
            ContactKindFile::Rocker => ContactKind::Rocker,
            ContactKindFile::Ball => ContactKind::Ball,
        },
        pivot_radius_m: r1,
        seat_radius_m: r2,
        length_m: contact_length,
        pivot_youngs_modulus_pa: pad_material.0,
        pivot_poisson_ratio: pad_material.1,
        seat_youngs_modulus_pa: seat_e,
        seat_poisson_ratio: seat_nu,
    }))
}
