//! The churning loss of a flooded housing in a solution ([`crate::physics::churning`], docs/MODEL.md §3.8):
//! one oil-filled gap ahead of each pad — from the trailing edge of the pad before it, around the bore, to its
//! leading edge — as deep as that pad's clearance and thickness, with the viscosity of the oil in it.

use std::f64::consts::TAU;

use crate::model::Case;
use crate::physics::churning::{gap_loss, Gap, GapLoss};

/// The churning of the gap ahead of each pad (indexed by that pad), with `viscosity(k)` the viscosity of the
/// oil in the gap ahead of pad `k` [Pa·s], at `speed_rad_s`; empty when the housing does not churn
/// (`feeding.churning_factor` 0, or a directed feeding) or the pads close the bore.
#[must_use]
pub fn churning(case: &Case, speed_rad_s: f64, viscosity: impl Fn(usize) -> f64) -> Vec<GapLoss> {
    let factor = case.thermal.feeding.churning_factor();
    let pads = &case.bearing.pads;
    if factor == 0.0 || pads.iter().map(|p| p.arc_rad).sum::<f64>() >= TAU {
        return Vec::new();
    }
    let b = &case.bearing;
    let mut order: Vec<usize> = (0..pads.len()).collect();
    order.sort_by(|&a, &c| {
        pads[a].leading_edge_rad.rem_euclid(TAU).total_cmp(&pads[c].leading_edge_rad.rem_euclid(TAU))
    });
    let mut out = vec![GapLoss { power_w: 0.0, reynolds: 0.0, shear_factor: 1.0 }; pads.len()];
    for (i, &k) in order.iter().enumerate() {
        let before = &pads[order[(i + order.len() - 1) % order.len()]];
        let arc = (pads[k].leading_edge_rad - before.trailing_edge_rad()).rem_euclid(TAU);
        let gap =
            Gap { arc_rad: arc, depth_m: pads[k].clearance_m + pads[k].thickness_m, viscosity_pa_s: viscosity(k) };
        out[k] = gap_loss(gap, b.journal_radius_m, b.length_m, speed_rad_s, case.lubricant.density_kg_per_m3, factor);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::load_case;

    /// The compressor bearing's five 60° pads leave five 12° gaps, 10.43 mm deep (10.312 mm pads, 121 µm
    /// clearance): each gap's power is the formula's, the five are equal, and a factor scales them.
    #[test]
    fn five_equal_gaps_of_the_compressor_bearing() {
        let text = include_str!("../../../cases/compressor-bearing.toml");
        let case = load_case(text, &[]).unwrap().1;
        let mu = 0.02;
        let omega = case.operating.speed_rad_s;
        let gaps = churning(&case, omega, |_| mu);
        assert_eq!(gaps.len(), 5);
        let (r, l, rho) = (0.0508, 0.04445, 863.5);
        let d = 10.312e-3 + 121e-6;
        let u = omega * r;
        let re = rho * u * d / mu;
        for g in &gaps {
            assert!((g.reynolds / re - 1.0).abs() < 1e-12, "{} vs {re}", g.reynolds);
            let f = crate::physics::churning::couette_shear_factor(re);
            let p = f * mu * u / d * u * r * 12f64.to_radians() * l;
            assert!((g.power_w / p - 1.0).abs() < 1e-12, "{} vs {p}", g.power_w);
        }
        let twice = load_case(text, &["feeding.churning_factor=2".into()]).unwrap().1;
        let g2 = churning(&twice, omega, |_| mu);
        assert!((g2[0].power_w / gaps[0].power_w - 2.0).abs() < 1e-12);
        let none = load_case(text, &["feeding.churning_factor=0".into()]).unwrap().1;
        assert!(churning(&none, omega, |_| mu).is_empty());
    }
}
