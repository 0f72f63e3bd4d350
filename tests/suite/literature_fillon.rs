//! Fillon, Bligoud & Frêne, "Experimental study of tilting-pad journal bearings — comparison with
//! theoretical thermoelastohydrodynamic results", ASME J. Tribology 114 (1992) — bearing A (docs/REFERENCES.md §3),
//! as modelled in the thesis' Publication 3 (Table 1; docs/MODEL.md §13): four pads, load between pads, 4000 rpm,
//! 10 kN. Measured maximum pad surface temperature 76.5 °C; Fillon's TEHD model 72.9 °C. Publication 3 computes
//! the shaft temperature as the mean film temperature and reports about 52 °C.
//!
//! The case file holds the published thermal model (BC1, H∞ 100, pad κ 45, carry-over 0.85); nothing here is
//! adjusted to the measurement.

use crate::common;

use tiltpad::bearing::Solution;

fn thd(set: &[&str]) -> Solution {
    let s = common::solve("fillon-a.toml", set);
    let t = s.thermal.as_ref().expect("fillon-a.toml is a THD case");
    assert!(t.report.converged, "{:?}", t.report);
    assert!(
        t.energy_balance_closure.abs() < 1e-12,
        "energy balance closure {:.2e} (round-off expected)",
        t.energy_balance_closure
    );
    s
}

fn pad_max(s: &Solution) -> f64 {
    s.thermal.as_ref().and_then(|t| t.t_max_pad_c).expect("pad temperatures")
}

/// Not met (reported in docs/THERMAL.md): the model as published here is THD — rigid pads, no thermal or
/// elastic deformation — and gives a maximum pad surface temperature about 9 °C below the measurement.
#[test]
#[ignore = "not met: the THD model (no pad/journal deformation) gives 67.2 °C vs the measured 76.5 °C (−9.3 °C); \
            published TEHD models give 72.9 °C; with thermal growth (fillon-a-tehd.toml) it is met, tested below"]
fn fillon_a_max_pad_temperature_within_5_degrees_of_measurement() {
    let s = thd(&[]);
    let t = pad_max(&s);
    assert!((t - 76.5).abs() < 5.0, "max pad surface temperature {t:.1} °C vs measured 76.5 °C");
}

/// With thermal growth of the pads and the journal (TEHD, `cases/fillon-a-tehd.toml`: steel, clearances at
/// 20 °C; docs/THERMAL.md) the maximum pad surface temperature at 4000 rpm meets the measurement (76.9 °C on
/// the standard mesh). Its rise from 1000 rpm (12.1 K against > 20 K measured) is short with BC1; BC3 meets
/// both criteria (tested below, docs/THERMAL.md).
#[test]
fn fillon_a_tehd_max_pad_temperature_within_5_degrees_of_measurement() {
    let s = common::solve("fillon-a-tehd.toml", &[]);
    let t = s.thermal.as_ref().expect("a THD case");
    assert!(t.report.converged, "{:?}", t.report);
    assert!(t.energy_balance_closure.abs() < 1e-12, "energy balance closure {:.2e}", t.energy_balance_closure);
    let max = pad_max(&s);
    println!("TEHD: max pad surface temperature {max:.2} °C, journal {:.2} °C", t.journal_temperature_c);
    assert!((max - 76.5).abs() < 5.0, "max pad surface temperature {max:.1} °C vs measured 76.5 °C");
}

#[test]
fn fillon_a_shaft_temperature_as_published() {
    // Publication 3: the mean film temperature, "in this case equal to 52 degrees Celsius" (BC1 model).
    let s = thd(&[]);
    let t = s.thermal.as_ref().unwrap();
    println!(
        "journal {:.2} °C, film max {:.2} °C, pad max {:.2} °C",
        t.journal_temperature_c,
        t.t_max_film_c,
        pad_max(&s)
    );
    assert!((t.journal_temperature_c - 52.0).abs() < 1.0, "journal {:.2} °C", t.journal_temperature_c);
    // BC1: the pad surface takes the film temperature, so the pad's hottest point is the film's.
    assert!((pad_max(&s) - t.t_max_film_c).abs() < 1e-9);
}

#[test]
fn fillon_a_temperatures_rise_with_speed() {
    let mut last = f64::NEG_INFINITY;
    for rpm in [1000, 2000, 3000, 4000] {
        let s = thd(&[&format!("operating.speed_rpm={rpm}")]);
        let t = pad_max(&s);
        println!(
            "{rpm} rpm: max pad temperature {t:.2} °C, journal {:.2} °C",
            s.thermal.as_ref().unwrap().journal_temperature_c
        );
        assert!(t > last, "{rpm} rpm: {t:.2} °C after {last:.2} °C");
        last = t;
    }
}

/// One model for all speeds that meets both Fillon criteria (docs/THERMAL.md, "Where the heat goes"):
/// TEHD with the film–pad conduction coupled (BC3) instead of BC1's adiabatic film, every other input as in
/// `fillon-a-tehd.toml` (the shipped `fillon-a-tehd-bc3.toml`), nothing changed per speed. The pad's hottest point rises with speed by more than the
/// measured 20 K from 1000 to 4000 rpm (24.4 K on the standard mesh) and is within 5 °C of the measured 76.5 °C
/// at 4000 rpm (74.2 °C). BC1 gives 12.1 K: at 1000 rpm its film keeps the 8 % of the friction power that BC3
/// conducts into the pads.
#[test]
fn fillon_a_tehd_bc3_rises_with_speed_like_the_measurement() {
    let mut maxima = Vec::new();
    for rpm in [1000, 2000, 3000, 4000] {
        let s = common::solve("fillon-a-tehd-bc3.toml", &[&format!("operating.speed_rpm={rpm}")]);
        let t = s.thermal.as_ref().expect("a THD case");
        assert!(t.report.converged, "{rpm} rpm: {:?}", t.report);
        assert!(
            t.energy_balance_closure.abs() < 1e-12,
            "{rpm} rpm: energy balance closure {:.2e}",
            t.energy_balance_closure
        );
        // BC3: the heat conducted into the pads is what they give to the surroundings (steady pads).
        assert!(
            (t.heat.heat_to_pad_w - t.heat_pads_to_surroundings_w).abs() < 1e-12 * t.heat.power_in(),
            "{rpm} rpm: pad heat balance"
        );
        maxima.push(pad_max(&s));
    }
    println!("BC3 TEHD max pad temperature at 1000–4000 rpm: {maxima:.2?} °C");
    assert!(maxima.windows(2).all(|w| w[1] > w[0]), "not rising: {maxima:?}");
    let rise = maxima[3] - maxima[0];
    assert!(rise > 20.0, "rise {rise:.1} K from 1000 to 4000 rpm, measured more than 20 K");
    assert!((maxima[3] - 76.5).abs() < 5.0, "max pad temperature {:.1} °C at 4000 rpm vs measured 76.5 °C", maxima[3]);
}
