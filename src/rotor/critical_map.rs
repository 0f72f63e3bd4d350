//! Undamped critical-speed map: the rotor's undamped natural frequencies against a support stiffness `k`
//! put at every bearing node, and the bearings' own stiffness against speed drawn over it (where a
//! bearing's curve crosses a mode's line is that mode's undamped critical speed on those bearings).
//!
//! ```text
//! (K_shaft + k Σ_b e_b e_bᵀ) φ = ω² M φ      (one bending plane, x–a; no damping, no gyroscopics)
//! ```
//! `e_b` picks the lateral displacement of bearing node `b`. Returns ω [rad/s] of the first modes for each
//! `k` [N/m] of a logarithmic sweep. Limits: `k → 0` gives the free–free rotor (two rigid modes at 0, then
//! the free–free flexible modes), `k → ∞` the rotor pinned at its bearings. Synchronous critical speeds are
//! read where `ω` equals the spin speed, so frequency and speed share the axis.

use nalgebra::DMatrix;
use serde::Serialize;

use super::assembly::{shaft_index, undamped_frequencies, NodeDof, ShaftModel};
use super::bearings::BearingSet;
use super::coupling::BearingCoefficients;
use super::error::RotorError;

/// The map: one row of frequencies per support stiffness.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CriticalMap {
    pub stiffness_n_per_m: Vec<f64>,
    /// `frequencies_rad_s[i][m]`: mode m at stiffness i.
    pub frequencies_rad_s: Vec<Vec<f64>>,
}

/// The map over `n` stiffnesses from `k_min` to `k_max` (logarithmic), the first `modes` modes.
///
/// # Errors
/// [`RotorError::Speeds`] for a bad range; [`RotorError::SingularMass`].
pub fn critical_map(shaft: &ShaftModel, bearing_nodes: &[usize], k_min: f64, k_max: f64, n: usize, modes: usize) -> Result<CriticalMap, RotorError> {
    if !(k_min > 0.0 && k_max > k_min && k_max.is_finite() && n >= 2) {
        return Err(RotorError::Speeds(format!("critical-speed map: needs 0 < k_min < k_max and n ≥ 2 (got {k_min:e}, {k_max:e}, {n})")));
    }
    let idx: Vec<usize> = (0..shaft.n_nodes).flat_map(|node| [shaft_index(node, NodeDof::X), shaft_index(node, NodeDof::A)]).collect();
    let sub = |a: &DMatrix<f64>| DMatrix::from_fn(idx.len(), idx.len(), |i, j| a[(idx[i], idx[j])]);
    let (k0, m) = (sub(&shaft.stiffness), sub(&shaft.mass));
    let slots: Vec<usize> = bearing_nodes.iter().filter_map(|&b| idx.iter().position(|&i| i == shaft_index(b, NodeDof::X))).collect();
    let mut out = CriticalMap { stiffness_n_per_m: Vec::with_capacity(n), frequencies_rad_s: Vec::with_capacity(n) };
    for i in 0..n {
        #[allow(clippy::cast_precision_loss)]
        let k = k_min * (k_max / k_min).powf(i as f64 / (n - 1) as f64);
        let mut kk = k0.clone();
        for &s in &slots {
            kk[(s, s)] += k;
        }
        let mut w = undamped_frequencies(&kk, &m)?;
        w.truncate(modes);
        out.stiffness_n_per_m.push(k);
        out.frequencies_rad_s.push(w);
    }
    Ok(out)
}

/// A bearing position's synchronously reduced direct stiffnesses against speed: `(Ω [rad/s], k_xx, k_yy)`.
pub type StiffnessCurve = Vec<(f64, f64, f64)>;

/// The direct stiffnesses of every bearing position at `speeds` [rad/s] (reduced at ω = Ω; solved or taken
/// from the set's cache).
///
/// # Errors
/// A bearing solve that fails.
pub fn bearing_stiffness_curves(bearings: &mut BearingSet, speeds: &[f64]) -> Result<Vec<StiffnessCurve>, RotorError> {
    let mut curves: Vec<StiffnessCurve> = vec![Vec::new(); bearings.nodes.len()];
    for &w in speeds {
        for (curve, c) in curves.iter_mut().zip(bearings.at(w)?) {
            if let BearingCoefficients::Reduced { k, .. } = c.reduced(w) {
                curve.push((w, k[0][0], k[1][1]));
            }
        }
    }
    Ok(curves)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::rotor::Rotor;
    use crate::rotor::element::BeamTheory;
    use std::f64::consts::PI;

    fn beam(n: usize) -> Rotor {
        crate::rotor::closed_form::uniform(1.0, 0.05, n, 7800.0, 2e11, BeamTheory::EulerBernoulli)
    }

    #[test]
    fn soft_supports_give_the_rigid_bounce_and_stiff_ones_the_pinned_beam() {
        let rotor = beam(20);
        let shaft = ShaftModel::new(&rotor).unwrap();
        let map = critical_map(&shaft, &[0, 20], 1e2, 1e13, 23, 3).unwrap();
        let (m, ei, rho_a) = (rotor.mass(), 2e11 * PI * 0.05f64.powi(4) / 64.0, 7800.0 * PI * 0.05f64.powi(2) / 4.0);
        // soft: rigid bounce √(2k/m) and pitch √(6k/m) of a uniform bar supported at its ends, up to the shaft's
        // own sag between the supports relative to the springs' deflection, 10 k L³ / (384 EI) (4e-5 here)
        let (k, w) = (map.stiffness_n_per_m[0], &map.frequencies_rad_s[0]);
        let bounce = (2.0 * k / m).sqrt();
        let pitch = (6.0 * k / m).sqrt();
        eprintln!("bounce {:.2e}, pitch {:.2e}", w[0] / bounce - 1.0, w[1] / pitch - 1.0);
        let sag = 10.0 * k / (384.0 * ei);
        assert!((w[0] / bounce - 1.0).abs() < sag, "{} vs {bounce}", w[0]);
        assert!((w[1] / pitch - 1.0).abs() < sag, "{} vs {pitch}", w[1]);
        // stiff: pinned–pinned Euler–Bernoulli, (π/L)² √(EI/ρA)
        let pinned = PI * PI * (ei / rho_a).sqrt();
        let w = &map.frequencies_rad_s[22];
        eprintln!("pinned {:.2e}", w[0] / pinned - 1.0);
        assert!((w[0] / pinned - 1.0).abs() < 1e-5, "{} vs {pinned}", w[0]);
        // each mode rises monotonically with the support stiffness
        for i in 1..map.stiffness_n_per_m.len() {
            for mode in 0..3 {
                assert!(map.frequencies_rad_s[i][mode] >= map.frequencies_rad_s[i - 1][mode] * (1.0 - 1e-12));
            }
        }
    }

    #[test]
    fn a_bad_range_is_refused() {
        let shaft = ShaftModel::new(&beam(4)).unwrap();
        assert!(matches!(critical_map(&shaft, &[0, 4], 1e6, 1e5, 10, 2), Err(RotorError::Speeds(_))));
    }
}
