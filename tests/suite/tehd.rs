//! Thermal growth of the pads and the journal inside the THD loop (TEHD; docs/MODEL.md §5–§7,
//! `src/bearing/thermal/growth.rs`), on Fillon bearing A (docs/REFERENCES.md §3) at the preview mesh.
//!
//! - Zero expansion coefficients are the THD solve, bit for bit.
//! - With steel pads (12 × 10⁻⁶/K) and journal (11 × 10⁻⁶/K) from a 20 °C assembly, the loop converges in
//!   the growth as well as in the viscosity, the journal grows by exactly α_j R (T_j − T_ref), the energy
//!   balance still closes to round-off, and the closed film runs thinner and hotter than the rigid one.

use crate::common;

use tiltpad::bearing::report::warning::Warning;
use tiltpad::bearing::Solution;

const PREVIEW: &str = "mesh.fidelity=preview";
const STEEL: [&str; 3] = [
    "thermal.pad_expansion_ppm_per_k=12",
    "thermal.journal_expansion_ppm_per_k=11",
    "thermal.reference_temperature_c=20",
];

fn pad_max(s: &Solution) -> f64 {
    s.thermal.as_ref().and_then(|t| t.t_max_pad_c).expect("pad temperatures")
}

#[test]
fn zero_expansion_is_the_thd_solve() {
    let thd = common::solve("fillon-a.toml", &[PREVIEW]);
    let zero = common::solve(
        "fillon-a.toml",
        &[PREVIEW, "thermal.pad_expansion_ppm_per_k=0", "thermal.journal_expansion_ppm_per_k=0"],
    );
    assert_eq!(thd.eccentricity_ratio.to_bits(), zero.eccentricity_ratio.to_bits());
    assert_eq!(pad_max(&thd).to_bits(), pad_max(&zero).to_bits());
    assert!(zero.thermal.as_ref().unwrap().report.growth_change_m.is_empty());
}

#[test]
fn growth_converges_closes_the_film_and_keeps_the_energy_balance() {
    let thd = common::solve("fillon-a.toml", &[PREVIEW]);
    let mut set = vec![PREVIEW];
    set.extend(STEEL);
    let tehd = common::solve("fillon-a.toml", &set);
    let t = tehd.thermal.as_ref().unwrap();
    let r = &t.report;
    println!(
        "outer iterations {}, growth change {:?} m, journal growth {:?} m, pad growth {:?} m",
        r.outer_iterations, r.growth_change_m, r.journal_growth_m, r.pad_growth_range_m
    );
    assert!(r.converged, "{r:?}");
    let clearance = tehd.inputs.bearing.assembled_clearance_m;
    let last = *r.growth_change_m.last().unwrap();
    assert!(last <= tiltpad::bearing::thermal::growth::GROWTH_TOL * clearance, "growth change {last:.2e} m");
    // Journal growth from the converged journal temperature.
    let expected = 11e-6 * tehd.inputs.bearing.journal_radius_m * (t.journal_temperature_c - 20.0);
    let journal = r.journal_growth_m.unwrap();
    assert!((journal - expected).abs() <= 1e-3 * expected.abs(), "{journal:.4e} vs {expected:.4e}");
    assert!(t.energy_balance_closure.abs() < 1e-12, "energy balance {:.2e}", t.energy_balance_closure);
    // Thermal growth closes the film: thinner and hotter than the rigid THD solution.
    println!(
        "h_min {:.2} → {:.2} µm, pad max {:.2} → {:.2} °C, journal {:.2} → {:.2} °C",
        thd.h_min_m * 1e6,
        tehd.h_min_m * 1e6,
        pad_max(&thd),
        pad_max(&tehd),
        thd.thermal.as_ref().unwrap().journal_temperature_c,
        t.journal_temperature_c
    );
    assert!(tehd.h_min_m < thd.h_min_m);
    assert!(pad_max(&tehd) > pad_max(&thd));
}

/// Housing growth (a case option, at a given housing temperature) moves every pivot out along its line by
/// α_h R_p (T_h − T_ref), R_p = R + Cb + t: the bearing is then the one assembled with that much more
/// clearance (the pads' bores unchanged). Journal position, h_min, the pads' hottest point and the stiffness
/// agree with that bearing's THD solve to the interpolation of cos(θ − θ_p) between film nodes (steel housing
/// 20 K above assembly: δ_h = 16.8 µm; measured 1.6e-4 of e, 2.0e-4 in h_min, 1.3e-3 K, 1.05e-4 in K_yy).
#[test]
fn housing_growth_is_a_larger_assembled_clearance() {
    let grown = common::solve(
        "fillon-a.toml",
        &[
            PREVIEW,
            "thermal.housing_expansion_ppm_per_k=12",
            "thermal.housing_temperature_c=40",
            "thermal.reference_temperature_c=20",
        ],
    );
    let b = &grown.inputs.bearing;
    let r = &grown.thermal.as_ref().unwrap().report;
    assert!(r.converged, "{r:?}");
    assert_eq!(r.housing_growth_m.len(), b.pads.len());
    let mut delta = 0.0;
    for (d, pad) in r.housing_growth_m.iter().zip(&b.pads) {
        delta = 12e-6 * (b.journal_radius_m + b.assembled_clearance_m + pad.thickness_m) * 20.0;
        assert!((d - delta).abs() <= 1e-14 * delta, "{d:.6e} vs {delta:.6e}");
    }
    let cb_um = format!("bearing.assembled_clearance_um={}", (b.assembled_clearance_m + delta) * 1e6);
    let wider = common::solve("fillon-a.toml", &[PREVIEW, &cb_um]);
    let (x, y) = (grown.journal_position_m, wider.journal_position_m);
    let e = x[0].hypot(x[1]);
    let de = (x[0] - y[0]).hypot(x[1] - y[1]) / e;
    let dh = common::rel(grown.h_min_m, wider.h_min_m);
    let dt = pad_max(&grown) - pad_max(&wider);
    let dk = common::rel(grown.reduced.k_n_per_m[1][1], wider.reduced.k_n_per_m[1][1]);
    println!(
        "housing growth {:.3} µm: journal {de:.2e} of e, h_min {dh:.2e}, pad max {dt:.2e} K, K_yy {dk:.2e}",
        delta * 1e6
    );
    assert!(
        de.abs() < 2e-4 && dh.abs() < 2.5e-4 && dt.abs() < 2e-3 && dk.abs() < 1.5e-4,
        "{de:.2e} {dh:.2e} {dt:.2e} {dk:.2e}"
    );
    // The preload falls from 0.47 to 0.36 and the upper pads become lightly loaded: both solves give them their
    // mean film viscosity (the housing's growth is in the films from the loop's first equilibrium, which decides).
    let light = |s: &Solution| -> Vec<usize> {
        s.thermal
            .as_ref()
            .unwrap()
            .report
            .warnings
            .iter()
            .filter_map(|w| match w {
                Warning::MeanViscosity { pad, .. } | Warning::MeanViscosityAfterFailure { pad, .. } => Some(*pad),
                _ => None,
            })
            .collect()
    };
    assert!(!light(&wider).is_empty());
    assert_eq!(light(&grown), light(&wider));
    // And it is not a negligible change: h_min moves by more than 1 % against the bearing as assembled.
    let plain = common::solve("fillon-a.toml", &[PREVIEW]);
    assert!((grown.h_min_m - plain.h_min_m).abs() > 1e-2 * plain.h_min_m, "{} vs {}", grown.h_min_m, plain.h_min_m);
}
