//! The representative compressor rotor (cases/rotors/compressor-rotor.toml) on two compressor bearings
//! (thesis Publications 1–2): full coefficients (pad coordinates appended) give a lower instability onset
//! than synchronously reduced ones — the thesis' finding that reduced coefficients overestimate the stable
//! range. The shaft is representative (not published), so the onset speeds themselves are not the thesis'.

use std::path::Path;

use tiltpad::cli::rotor::{parse_speeds, read_rotor};
use tiltpad::model::rotor::CoefficientModel;
use tiltpad::rotor::analysis::{run, AnalysisParams};

fn onset_rpm(model: CoefficientModel) -> f64 {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("cases/rotors/compressor-rotor.toml");
    let mut rotor = read_rotor(&path).unwrap();
    assert!(rotor.representative);
    assert!((rotor.mass() - 391.0).abs() < 1.0, "published mass 391 kg, got {}", rotor.mass());
    rotor.coefficients = model;
    let r = run(&rotor, AnalysisParams::new(parse_speeds("6000:16000:6").unwrap())).unwrap();
    assert!(r.report.warnings.is_empty(), "{:?}", r.report.warnings);
    // identical bearing cases share their solves: one per speed (plus the onset probes)
    assert_eq!(r.report.bearing_solves, r.report.eigen_solutions);
    r.onset.expect("an onset inside 6000–16000 rpm").speed_rad_s * 30.0 / std::f64::consts::PI
}

#[test]
fn full_coefficients_lower_the_onset() {
    let full = onset_rpm(CoefficientModel::Full);
    let reduced = onset_rpm(CoefficientModel::Reduced);
    eprintln!("onset: full {full:.0} rpm, reduced {reduced:.0} rpm");
    assert!(full < 0.95 * reduced, "full {full:.0} rpm, reduced {reduced:.0} rpm");
}
