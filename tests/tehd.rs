//! Thermal growth of the pads and the journal inside the THD loop (TEHD; model.md §5–§7,
//! `src/bearing/tehd.rs`), on Fillon bearing A (validation.md §3) at the preview mesh.
//!
//! - Zero expansion coefficients are the THD solve, bit for bit.
//! - With steel pads (12 × 10⁻⁶/K) and journal (11 × 10⁻⁶/K) from a 20 °C assembly, the loop converges in
//!   the growth as well as in the viscosity, the journal grows by exactly α_j R (T_j − T_ref), the energy
//!   balance still closes to round-off, and the closed film runs thinner and hotter than the rigid one.

mod common;

use tiltpad::bearing::Solution;

const PREVIEW: &str = "mesh.fidelity=preview";
const STEEL: [&str; 3] = ["thermal.pad_expansion_ppm_per_k=12", "thermal.journal_expansion_ppm_per_k=11", "thermal.reference_temperature_c=20"];

fn pad_max(s: &Solution) -> f64 {
    s.thermal.as_ref().and_then(|t| t.t_max_pad_c).expect("pad temperatures")
}

#[test]
fn zero_expansion_is_the_thd_solve() {
    let thd = common::solve("fillon-a.toml", &[PREVIEW]);
    let zero = common::solve("fillon-a.toml", &[PREVIEW, "thermal.pad_expansion_ppm_per_k=0", "thermal.journal_expansion_ppm_per_k=0"]);
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
    assert!(last <= tiltpad::bearing::tehd::GROWTH_TOL * clearance, "growth change {last:.2e} m");
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
