//! Pad fields of the live result against a pinned one, and colour scales that stay put.
//!
//! Side by side, the live and the pinned maps share one colour range, the union of both:
//! `[min(lo_live, lo_pin), max(hi_live, hi_pin)]`, so one colour means one value in both pictures.
//!
//! The difference map is `Δf(s, z) = f_live(s, z) − f_pin(s, z)` at the live mesh's nodes; the pinned field
//! is interpolated bilinearly at those nodes ([`PadMap::sample`]), so two meshes of different fidelity
//! still subtract. It needs the same pads (count, arc length and axial length within 1e-9 relative);
//! otherwise there is no point-by-point difference and [`difference_maps`] says why. Its colour range is
//! symmetric about zero, `[−max|Δf|, max|Δf|]`, drawn with the diverging map (grey = no change).
//!
//! A [`FieldScaleLock`] keeps the colour range of one field kind fixed (SI values) across edits: locked,
//! the range drawn is the locked one whatever the solution's values (values outside clamp to the ends).

use serde::{Deserialize, Serialize};

use super::field::{FieldKind, PadMap};
use crate::units::MM;

/// A locked colour range of one field kind [SI].
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct FieldScaleLock {
    pub kind: FieldKind,
    pub lo: f64,
    pub hi: f64,
}

/// The lock of `kind` among `locks`, if any.
#[must_use]
pub fn lock_for(locks: &[FieldScaleLock], kind: FieldKind) -> Option<FieldScaleLock> {
    locks.iter().copied().find(|l| l.kind == kind)
}

/// Locks `kind` at `range`, or unlocks it (`range` = `None`).
pub fn set_lock(locks: &mut Vec<FieldScaleLock>, kind: FieldKind, range: Option<(f64, f64)>) {
    locks.retain(|l| l.kind != kind);
    if let Some((lo, hi)) = range {
        locks.push(FieldScaleLock { kind, lo, hi });
    }
}

/// The range to draw: the locked one for `kind` if there is one, else `auto`.
#[must_use]
pub fn drawn_range(locks: &[FieldScaleLock], kind: FieldKind, auto: (f64, f64)) -> (f64, f64) {
    lock_for(locks, kind).map_or(auto, |l| (l.lo, l.hi))
}

/// The union of two colour ranges (live and pinned side by side).
#[must_use]
pub fn shared_range(a: (f64, f64), b: (f64, f64)) -> (f64, f64) {
    (a.0.min(b.0), a.1.max(b.1))
}

/// Why two results have no point-by-point difference.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Mismatch {
    #[error("the live result has {live} pads, the pinned one {pinned}")]
    PadCount { live: usize, pinned: usize },
    #[error("pad {pad} differs in size (arc {live_arc_mm:.3} mm vs {pinned_arc_mm:.3} mm, length {live_len_mm:.3} mm vs {pinned_len_mm:.3} mm)")]
    PadSize { pad: usize, live_arc_mm: f64, pinned_arc_mm: f64, live_len_mm: f64, pinned_len_mm: f64 },
}

fn same(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-9 * a.abs().max(b.abs())
}

/// `live − pinned` per pad on the live nodes (pinned interpolated), with the symmetric range `(−m, m)`.
///
/// # Errors
/// [`Mismatch`] when the pads differ in number or size.
pub fn difference_maps(live: &[PadMap], pinned: &[PadMap]) -> Result<(Vec<PadMap>, (f64, f64)), Mismatch> {
    if live.len() != pinned.len() {
        return Err(Mismatch::PadCount { live: live.len(), pinned: pinned.len() });
    }
    let mut out = Vec::with_capacity(live.len());
    for (a, b) in live.iter().zip(pinned) {
        if !(same(a.arc_length_m(), b.arc_length_m()) && same(a.length_m(), b.length_m())) {
            return Err(Mismatch::PadSize {
                pad: a.pad,
                live_arc_mm: MM.from_si(a.arc_length_m()),
                pinned_arc_mm: MM.from_si(b.arc_length_m()),
                live_len_mm: MM.from_si(a.length_m()),
                pinned_len_mm: MM.from_si(b.length_m()),
            });
        }
        let values: Vec<f64> = if a.s_m == b.s_m && a.z_m == b.z_m {
            a.values.iter().zip(&b.values).map(|(x, y)| x - y).collect()
        } else {
            // Node (i, j) of the live grid, offset from its corner onto the pinned grid (same rectangle,
            // checked above; clamped against rounding at the edges).
            let (nz, (s_end, z_end)) = (a.z_m.len(), (b.s_m[b.s_m.len() - 1], b.z_m[b.z_m.len() - 1]));
            (0..a.values.len())
                .map(|k| {
                    let s = (b.s_m[0] + a.s_m[k / nz] - a.s_m[0]).clamp(b.s_m[0], s_end);
                    let z = (b.z_m[0] + a.z_m[k % nz] - a.z_m[0]).clamp(b.z_m[0], z_end);
                    a.values[k] - b.sample(s, z).unwrap_or(a.values[k])
                })
                .collect()
        };
        let (min, max) = values.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &v| (lo.min(v), hi.max(v)));
        out.push(PadMap { values, cavitated: vec![false; a.cavitated.len()], min, max, ..a.clone() });
    }
    let m = out.iter().map(|d| d.min.abs().max(d.max.abs())).fold(0.0, f64::max);
    Ok((out, (-m, m)))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pad_map(solution: &crate::bearing::Solution) -> Vec<PadMap> {
        PadMap::all(solution, FieldKind::Pressure)
    }

    /// The 6000 rpm pressure minus the 9000 rpm one, on the compressor bearing: the difference at a node
    /// is the two nodal values' difference (same mesh), a result minus itself is exactly zero, and the
    /// range is symmetric and reaches the largest |Δp|; a different pad count is a clear mismatch.
    #[test]
    fn differences_are_nodal_on_one_mesh_and_interpolated_across_meshes() {
        let fast = crate::bearing::stages::registry::compressor_preview(&[]);
        let slow = crate::bearing::stages::registry::compressor_preview(&["operating.speed_rpm=6000"]);
        let (a, b) = (pad_map(&slow), pad_map(&fast));
        let (d, (lo, hi)) = difference_maps(&a, &b).unwrap();
        for (k, dm) in d.iter().enumerate() {
            for n in [0, dm.values.len() / 2, dm.values.len() - 1] {
                assert_eq!(dm.values[n], a[k].values[n] - b[k].values[n], "pad {k} node {n}");
            }
        }
        let largest = d.iter().flat_map(|m| m.values.iter()).fold(0.0_f64, |m, v| m.max(v.abs()));
        assert!(largest > 1e5, "the speed change moves the pressure by {largest} Pa");
        assert_eq!((lo, hi), (-largest, largest));
        let (zero, range) = difference_maps(&a, &a).unwrap();
        assert!(zero.iter().all(|m| m.values.iter().all(|&v| v == 0.0)));
        assert_eq!(range, (0.0, 0.0));
        assert!(matches!(difference_maps(&a, &b[..1]), Err(Mismatch::PadCount { live: 3.., pinned: 1 })));
    }

    /// A linear field on one grid minus the same field plus one on a coarser grid: bilinear interpolation
    /// is exact for a linear field, so the difference is −1 at every live node (to rounding).
    #[test]
    fn meshes_of_different_fidelity_subtract_by_interpolation() {
        let map = |s_m: Vec<f64>, z_m: Vec<f64>, offset: f64| {
            let values: Vec<f64> =
                s_m.iter().flat_map(|&s| z_m.iter().map(move |&z| 2.0 * s + 3.0 * z + offset)).collect();
            let n = values.len();
            PadMap {
                pad: 0,
                kind: FieldKind::Pressure,
                s_m,
                z_m,
                radius_m: 0.05,
                theta_le_rad: 0.0,
                values,
                cavitated: vec![false; n],
                min: 0.0,
                max: 1.0,
            }
        };
        let live = map(vec![0.0, 0.01, 0.03], vec![-0.02, 0.0, 0.01, 0.02], 0.0);
        let pinned = map(vec![0.0, 0.015, 0.03], vec![-0.02, 0.02], 1.0);
        let (d, (lo, hi)) = difference_maps(&[live], &[pinned]).unwrap();
        assert!(d[0].values.iter().all(|v| (v + 1.0).abs() < 1e-14), "{:?}", d[0].values);
        assert!((lo + 1.0).abs() < 1e-14 && (hi - 1.0).abs() < 1e-14);
        let longer = map(vec![0.0, 0.04], vec![-0.02, 0.02], 0.0);
        assert!(matches!(difference_maps(&d, &[longer]), Err(Mismatch::PadSize { pad: 0, .. })));
    }

    #[test]
    fn a_lock_holds_its_kind_only_and_ranges_join() {
        let mut locks = Vec::new();
        set_lock(&mut locks, FieldKind::Pressure, Some((0.0, 2e6)));
        assert_eq!(drawn_range(&locks, FieldKind::Pressure, (1.0, 5e6)), (0.0, 2e6));
        assert_eq!(drawn_range(&locks, FieldKind::FilmThickness, (1e-5, 4e-5)), (1e-5, 4e-5));
        set_lock(&mut locks, FieldKind::Pressure, Some((0.0, 3e6)));
        assert_eq!(locks.len(), 1);
        set_lock(&mut locks, FieldKind::Pressure, None);
        assert!(locks.is_empty());
        assert_eq!(shared_range((1.0, 4.0), (0.5, 3.0)), (0.5, 4.0));
    }
}
