//! Every validation path: the error names the key, the value and the allowed range; nothing panics.

use crate::common;

use tiltpad::model::{load_case, CaseError};

fn base() -> String {
    std::fs::read_to_string(common::case_path("compressor-bearing.toml")).unwrap()
}

fn err(set: &[&str]) -> CaseError {
    let set: Vec<String> = set.iter().map(|s| (*s).to_string()).collect();
    load_case(&base(), &set).expect_err("must be rejected")
}

fn assert_names(e: &CaseError, key: &str, fragments: &[&str]) {
    assert_eq!(e.key(), Some(key), "{e}");
    let msg = e.to_string();
    for f in fragments {
        assert!(msg.contains(f), "message `{msg}` lacks `{f}`");
    }
}

#[test]
fn shipped_cases_are_valid() {
    for entry in std::fs::read_dir(common::case_path("")).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "toml") {
            let text = std::fs::read_to_string(&path).unwrap();
            assert!(text.starts_with('#'), "{} must open with a comment citing its source", path.display());
            load_case(&text, &[]).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        }
    }
}

#[test]
fn non_positive_clearances() {
    assert_names(&err(&["bearing.assembled_clearance_um=0"]), "bearing.assembled_clearance_um", &["= 0", "(0,"]);
    assert_names(&err(&["bearing.assembled_clearance_um=-5"]), "bearing.assembled_clearance_um", &["-5"]);
    let e = err(&["bearing.pads.bore_radius_mm=", "bearing.pads.clearance_um=-1"]);
    assert_names(&e, "bearing.pads.clearance_um", &["-1"]);
}

#[test]
fn preload_must_be_below_one() {
    let e = err(&["bearing.pads.bore_radius_mm=", "bearing.pads.preload=1.0"]);
    assert_names(&e, "bearing.pads.preload", &["= 1", "[-1, 1)"]);
    let e = err(&["bearing.pads.bore_radius_mm=", "bearing.pads.preload=1.5"]);
    assert_names(&e, "bearing.pads.preload", &["1.5"]);
    // A pad clearance smaller than the assembled clearance is a preload ≥ 1... no: m = 1 − Cb/Cp < 0 is
    // allowed down to −1; a pad bore inside the journal is not.
    let e = err(&["bearing.pads.bore_radius_mm=50.7"]);
    assert_names(&e, "bearing.pads.bore_radius_mm", &["greater than the journal radius"]);
    // Two alternatives in one table of a file: `inconsistencies_are_typed_with_their_numbers`; overrides
    // replace one another (`an_alternative_pad_geometry_key_replaces_the_one_the_file_gives`).
}

#[test]
fn overlapping_pads() {
    let e = err(&["bearing.pads.pivot_deg=[60.0, 100.0, 204.0, 276.0, 348.0]"]);
    assert_names(&e, "bearing.pads.pivot_deg", &["overlap", "pads 0 and 1"]);
    let e = err(&["bearing.pads.arc_deg=80"]);
    assert_names(&e, "bearing.pads.arc_deg", &["80", "(0, 72]"]);
}

#[test]
fn orifice_outside_its_pad() {
    let e = err(&["bearing.pads.orifice=[{position_frac = 0.02, diameter_mm = 5.0, length_mm = 5.0}]"]);
    assert_names(&e, "bearing.pads.orifice[0].position_frac", &["outside its pad", "allowed position_frac in"]);
    let e = err(&[
        "bearing.pads.orifice=[{position_frac = 0.5, axial_frac = 0.97, diameter_mm = 5.0, length_mm = 5.0}]",
        "mesh.half_model=false",
    ]);
    assert_names(&e, "bearing.pads.orifice[0].axial_frac", &["outside its pad"]);
    let e = err(&[
        "bearing.pads.orifice=[{position_frac = 0.5, axial_frac = 0.3, diameter_mm = 5.0, length_mm = 5.0}]",
        "mesh.half_model=true",
    ]);
    assert_names(&e, "mesh.half_model", &["mid-plane"]);
}

#[test]
fn nan_and_infinity() {
    assert_names(&err(&["operating.speed_rpm=nan"]), "operating.speed_rpm", &["NaN", "finite"]);
    assert_names(&err(&["operating.load_n=inf"]), "operating.load_n", &["inf"]);
    assert_names(&err(&["lubricant.viscosity_pa_s=-inf"]), "lubricant.viscosity_pa_s", &["-inf"]);
}

#[test]
fn unknown_keys() {
    let e = err(&["bearing.pads.arc=60"]);
    assert!(matches!(e, CaseError::UnknownKey { .. }), "{e:?}");
    assert_names(&e, "bearing.pads.arc", &["unknown key", "arc_deg"]);
    let e = err(&["operating.speed=3000"]);
    assert_names(&e, "operating.speed", &["speed_rpm"]);
    let e = err(&["thermal_model=1"]);
    assert_names(&e, "thermal_model", &["unknown key"]);
}

#[test]
fn missing_keys() {
    let e = err(&["lubricant.density_kg_per_m3="]);
    assert!(matches!(e, CaseError::MissingKey { .. }), "{e:?}");
    assert_names(&e, "lubricant.density_kg_per_m3", &["missing"]);
    let e = err(&["operating.load_n="]);
    assert_names(&e, "operating.load_n", &["missing"]);
    let e = err(&["bearing.pads.thickness_mm="]);
    assert_names(&e, "bearing.pads.thickness_mm", &["missing"]);
    let e = err(&["lubricant.viscosity2_pa_s="]);
    assert_names(&e, "lubricant.viscosity2_pa_s", &["missing"]);
}

#[test]
fn wrong_types_and_inconsistent_values() {
    let e = err(&["operating.speed_rpm=\"fast\""]);
    assert!(matches!(e, CaseError::WrongType { .. }), "{e:?}");
    assert_names(&e, "operating.speed_rpm", &[]);
    assert_names(
        &err(&["operating.injection_pressure_bar=[1.0, 2.0]"]),
        "operating.injection_pressure_bar",
        &["2 values for 5 pads"],
    );
    assert_names(&err(&["operating.eccentricity_ratio=0.5"]), "operating.eccentricity_ratio", &["not both"]);
    assert_names(&err(&["bearing.pads.count=0"]), "bearing.pads.count", &["[1, 24]"]);
    assert_names(
        &err(&["lubricant.viscosity2_pa_s=0.05"]),
        "lubricant.viscosity2_pa_s",
        &["must fall with temperature"],
    );
    assert_names(&err(&["mesh.axial_elements=15"]), "mesh.axial_elements", &["even"]);
}

#[test]
fn bad_overrides_and_syntax() {
    let set = vec!["speed".to_string()];
    assert!(matches!(load_case(&base(), &set), Err(CaseError::BadOverride { .. })));
    let set = vec!["operating.speed_rpm.x=1".to_string()];
    assert!(matches!(load_case(&base(), &set), Err(CaseError::BadOverride { .. })));
    assert!(matches!(load_case("[bearing\nx=1", &[]), Err(CaseError::Syntax { .. })));
    // Per-pad overrides index the array of pad tables.
    let text = base() + "\n[[bearing.pad]]\n[[bearing.pad]]\n[[bearing.pad]]\n[[bearing.pad]]\n[[bearing.pad]]\n";
    let (_, c) = load_case(&text, &["bearing.pad.2.offset=0.5".to_string()]).unwrap();
    assert_eq!(c.bearing.pads[2].offset, 0.5);
    assert_eq!(c.bearing.pads[1].offset, 0.6);
}

#[test]
fn units_are_converted_once() {
    let (file, c) = load_case(&base(), &[]).unwrap();
    assert!((c.bearing.journal_radius_m - 0.0508).abs() < 1e-15);
    assert!((c.bearing.assembled_clearance_m - 102e-6).abs() < 1e-18);
    assert!((c.bearing.pads[0].clearance_m - 121e-6).abs() < 1e-12);
    assert!((c.bearing.pads[3].pivot_rad - 276_f64.to_radians()).abs() < 1e-15);
    assert!((c.operating.speed_rad_s - 9000.0 * std::f64::consts::TAU / 60.0).abs() < 1e-9);
    // The file round-trips through TOML.
    let again = load_case(&file.to_toml().unwrap(), &[]).unwrap().1;
    assert_eq!(again, c);
}

#[test]
fn thermal_table() {
    // Defaults: isothermal unless asked; documented values otherwise.
    let (_, c) = load_case(&base(), &["thermal.model=\"thd\"".into()]).unwrap();
    assert_eq!(c.thermal.model, tiltpad::model::ThermalModelKind::Thd);
    assert_eq!(c.thermal.pad_film_bc, tiltpad::model::PadFilmBc::Bc1);
    assert!((c.thermal.ambient_temperature_c - c.operating.supply_temperature_c).abs() < 1e-12);
    assert_eq!(c.mesh.pad_radial_elements, 4);
    // BC2 needs its coefficient, and only BC2 takes one.
    assert_names(&err(&["thermal.pad_film_bc=\"bc2\""]), "thermal.h_oil_pad_w_per_m2_k", &["missing", "bc2"]);
    assert_names(&err(&["thermal.h_oil_pad_w_per_m2_k=4000"]), "thermal.h_oil_pad_w_per_m2_k", &["only used with"]);
    let (_, c) =
        load_case(&base(), &["thermal.pad_film_bc=\"bc2\"".into(), "thermal.h_oil_pad_w_per_m2_k=4000".into()])
            .unwrap();
    assert_eq!(c.thermal.pad_film_bc, tiltpad::model::PadFilmBc::Bc2 { h_w_per_m2_k: 4000.0 });
    // Ranges name key, value and the allowed interval.
    assert_names(&err(&["thermal.carry_over=1.2"]), "thermal.carry_over", &["1.2", "[0, 1]"]);
    assert_names(&err(&["thermal.pad_conductivity_w_per_m_k=0"]), "thermal.pad_conductivity_w_per_m_k", &["(0,"]);
    assert_names(&err(&["thermal.convection_w_per_m2_k=-5"]), "thermal.convection_w_per_m2_k", &["-5"]);
    assert_names(&err(&["thermal.journal_temperature_c=nan"]), "thermal.journal_temperature_c", &["finite"]);
    assert_names(&err(&["mesh.pad_radial_elements=0"]), "mesh.pad_radial_elements", &["[1, 200]"]);
    assert_names(
        &err(&["thermal.housing_expansion_ppm_per_k=150"]),
        "thermal.housing_expansion_ppm_per_k",
        &["150", "[0, 100]"],
    );
    assert_names(&err(&["thermal.housing_temperature_c=inf"]), "thermal.housing_temperature_c", &["finite"]);
    let e = err(&["thermal.model=\"hot\""]);
    assert_names(&e, "thermal.model", &[]);
    let e = err(&["thermal.pad_bc=\"bc1\""]);
    assert!(matches!(e, CaseError::UnknownKey { .. }), "{e:?}");
}

/// Massless pads are a key of their own (`massless = true`), not a tiny density; a density given with it
/// is refused with the key named.
#[test]
fn massless_pads_are_an_explicit_option() {
    let mass = |case: &tiltpad::model::Case| {
        let b = &case.bearing;
        tiltpad::bearing::film::coordinates::PadStructure::rigid(&b.pads[0], b.journal_radius_m, b.length_m).mass
    };
    let someya = common::case("someya-4pad-lbp.toml", &[]);
    assert!(someya.bearing.pads.iter().all(|p| p.massless));
    assert!(mass(&someya).iter().all(|&v| v == 0.0), "{:?}", mass(&someya));
    // The same bearing with steel pads has inertia.
    let steel = common::case("someya-4pad-lbp.toml", &["bearing.pads.massless=false"]);
    assert!(!steel.bearing.pads[0].massless && steel.bearing.pads[0].density_kg_per_m3 == 7800.0);
    assert!(mass(&steel).iter().any(|&v| v > 0.0));
    let e = err(&["bearing.pads.massless=true", "bearing.pads.density_kg_per_m3=7800"]);
    assert_names(&e, "bearing.pads.density_kg_per_m3", &["massless"]);
}

/// Values that do not fit together come back as a typed [`Inconsistency`] with the numbers of the
/// condition, so a caller can match the condition rather than parse the text (which stays as it was).
#[test]
fn inconsistencies_are_typed_with_their_numbers() {
    use tiltpad::model::error::Inconsistency;
    let reason = |e: CaseError| match e {
        CaseError::Inconsistent { reason, .. } => reason,
        other => panic!("expected an inconsistency, got {other:?}"),
    };
    match reason(err(&["bearing.pads.pivot_deg=[60.0, 100.0, 204.0, 276.0, 348.0]"])) {
        // Pad 0 (pivot 60°, offset 0.6 of a 60° arc) spans 24°–84°; pad 1 starts at 100 − 36 = 64°.
        Inconsistency::PadsOverlap { first: 0, second: 1, first_from_deg, first_to_deg, second_from_deg } => {
            assert!((first_from_deg - 24.0).abs() < 1e-9 && (first_to_deg - 84.0).abs() < 1e-9, "{first_from_deg}");
            assert!((second_from_deg - 64.0).abs() < 1e-9, "{second_from_deg}");
        }
        other => panic!("{other:?}"),
    }
    // A 5 mm orifice on a 60° arc of a 50.8 mm journal (53.20 mm of arc) fits between 2.5/53.20 and 1 − that.
    let e = err(&["bearing.pads.orifice=[{position_frac = 0.02, diameter_mm = 5.0, length_mm = 5.0}]"]);
    match reason(e) {
        Inconsistency::OrificeOffArc { arc_length_mm, lowest, highest, position_frac, .. } => {
            let arc = 60_f64.to_radians() * 50.8;
            assert!((arc_length_mm - arc).abs() < 1e-9, "{arc_length_mm}");
            assert!((lowest - 2.5 / arc).abs() < 1e-12 && (highest - (1.0 - 2.5 / arc)).abs() < 1e-12, "{lowest}");
            assert_eq!(position_frac, 0.02);
        }
        other => panic!("{other:?}"),
    }
    assert_eq!(reason(err(&["operating.eccentricity_ratio=0.5"])), Inconsistency::LoadAndEccentricity);
    let e = err(&["bearing.pads.massless=true", "bearing.pads.density_kg_per_m3=7800"]);
    assert_eq!(reason(e), Inconsistency::MasslessWithDensity);
    assert_eq!(
        reason(err(&["operating.injection_pressure_bar=[1.0, 2.0]"])),
        Inconsistency::PerPadValues { given: 2, pads: 5 }
    );
    // Two alternatives written in one table of a file are refused (an override replaces instead, below).
    let both = base().replace("bore_radius_mm = 50.921", "bore_radius_mm = 50.921\npreload = 0.2");
    let e = load_case(&both, &[]).expect_err("two pad-geometry keys in one table");
    assert_eq!(reason(e), Inconsistency::PadGeometryTwice { given: vec!["preload".into(), "bore_radius_mm".into()] });
}

/// Setting one of the alternative pad-geometry keys (preload, clearance_um, bore_radius_mm) by an override
/// replaces the one the file gives, in that table only, and says so. The compressor bearing gives
/// Rp = 50.921 mm on R = 50.8 mm (Cp = 121 µm) and Cb = 102 µm.
#[test]
fn an_alternative_pad_geometry_key_replaces_the_one_the_file_gives() {
    use tiltpad::model::replaced_keys;
    let cb = 102e-6;
    let cp = |set: &[&str]| {
        let set: Vec<String> = set.iter().map(|s| (*s).to_string()).collect();
        let (_, case) = load_case(&base(), &set).unwrap_or_else(|e| panic!("{set:?}: {e}"));
        case.bearing.pads.iter().map(|p| p.clearance_m).collect::<Vec<_>>()
    };
    let close = |a: f64, b: f64| (a - b).abs() < 1e-12;
    assert!(cp(&[]).iter().all(|&c| close(c, 121e-6)), "{:?}", cp(&[]));
    // Preload m = 0.2: Cp = Cb / (1 − m) = 127.5 µm on every pad.
    assert!(cp(&["bearing.pads.preload=0.2"]).iter().all(|&c| close(c, cb / 0.8)));
    assert!(cp(&["bearing.pads.clearance_um=150"]).iter().all(|&c| close(c, 150e-6)));
    // Back and forth: the last one given wins.
    let last = cp(&["bearing.pads.preload=0.2", "bearing.pads.bore_radius_mm=50.95"]);
    assert!(last.iter().all(|&c| close(c, 150e-6)), "{last:?}");
    let notes = replaced_keys(&base(), &["bearing.pads.preload=0.2".into()]).unwrap();
    assert_eq!(notes.len(), 1);
    assert_eq!(
        notes[0].to_string(),
        "bearing.pads.preload replaces bearing.pads.bore_radius_mm = 50.921 (alternative pad-geometry keys)"
    );
    // Removing a key or setting another key replaces nothing.
    assert!(replaced_keys(&base(), &["bearing.pads.offset=0.5".into()]).unwrap().is_empty());
    assert!(replaced_keys(&base(), &["bearing.pads.bore_radius_mm=".into()]).unwrap().is_empty());
    // A per-pad table replaces within itself; the common table keeps its key for the other pads.
    let per_pad = base().replace(
        "[[bearing.pads.orifice]]",
        "[[bearing.pad]]\nbore_radius_mm = 50.93\n[[bearing.pad]]\n[[bearing.pad]]\n[[bearing.pad]]\n[[bearing.pad]]\n\n[[bearing.pads.orifice]]",
    );
    let set = vec!["bearing.pad.0.preload=0.2".to_string()];
    let notes = replaced_keys(&per_pad, &set).unwrap();
    assert_eq!(
        (notes[0].set.as_str(), notes[0].removed.as_str()),
        ("bearing.pad.0.preload", "bearing.pad.0.bore_radius_mm")
    );
    let (_, case) = load_case(&per_pad, &set).unwrap();
    assert!(close(case.bearing.pads[0].clearance_m, cb / 0.8));
    assert!(case.bearing.pads[1..].iter().all(|p| close(p.clearance_m, 121e-6)));
}

/// Absent keys take their rows' defaults, and every value is converted to SI by its row's unit: the
/// numbers here are the documented defaults and the unit factors written out.
#[test]
fn defaults_and_units_come_from_the_key_table() {
    let removed = [
        "thermal.model=\"thd\"",
        "thermal.pad_conductivity_w_per_m_k=",
        "thermal.convection_w_per_m2_k=",
        "thermal.carry_over=",
        "bearing.pads.density_kg_per_m3=",
        "bearing.pads.youngs_modulus_gpa=",
        "bearing.pads.poisson_ratio=",
        "operating.load_angle_deg=",
        "operating.injection_pressure_bar=",
    ];
    let (_, c) = load_case(&base(), &removed.map(String::from)).unwrap();
    assert_eq!(c.thermal.pad_conductivity_w_per_m_k, 45.0);
    assert_eq!(c.thermal.convection_w_per_m2_k, 100.0);
    assert_eq!(c.thermal.feeding, tiltpad::model::Feeding::Flooded { carry_over: 0.8, churning_factor: 1.0 });
    assert_eq!(c.thermal.ambient_temperature_c, 50.0, "the supply temperature");
    let pad = &c.bearing.pads[0];
    assert_eq!((pad.density_kg_per_m3, pad.youngs_modulus_pa, pad.poisson_ratio), (7800.0, 200e9, 0.3));
    assert!((c.physics.touchdown_film_m - 0.01 * 102e-6).abs() < 1e-18, "1 % of the assembled clearance");
    assert_eq!(c.operating.injection_pressure_pa, vec![0.0; 5]);
    let tiltpad::model::LoadSpec::Force { angle_rad, .. } = c.operating.load else { panic!("{:?}", c.operating.load) };
    assert!((angle_rad - 1.5 * std::f64::consts::PI).abs() < 1e-15, "270°");
    // The rig's valve: 120 Hz, 5 L/min at 70 bar, K_c 0.012 L/(min·bar), leakage 0.3 L/min.
    let rig = std::fs::read_to_string(common::case_path("test-rig-pub5.toml")).unwrap();
    let (_, c) = load_case(&rig, &[]).unwrap();
    let v = c.hydraulics.unwrap().valve;
    assert!((v.natural_frequency_rad_s - 240.0 * std::f64::consts::PI).abs() < 1e-9);
    assert!((v.rated_flow_m3_s - 5e-3 / 60.0).abs() < 1e-18);
    assert!((v.rated_drop_pa - 70e5).abs() < 1e-6);
    assert!((v.flow_pressure_coefficient - 0.012e-3 / 60.0 / 1e5).abs() < 1e-24);
    assert!((v.leakage_m3_s - 0.3e-3 / 60.0).abs() < 1e-18);
}

/// The transition band: each end in its range, the end above the start; a band upside down names the end
/// key, its value and the interval the start leaves it.
#[test]
fn transition_band_upside_down() {
    let e = err(&["physics.transition_reynolds_start=2000", "physics.transition_reynolds_end=1500"]);
    assert_names(&e, "physics.transition_reynolds_end", &["1500", "(2000, 100000]"]);
    let e = err(&["physics.transition_reynolds_start=0.5"]);
    assert_names(&e, "physics.transition_reynolds_start", &["0.5", "[1, 100000]"]);
    let e = err(&["physics.turbulence=\"sometimes\""]);
    assert_eq!(e.key(), Some("physics.turbulence"), "{e}");
    assert!(e.to_string().contains("sometimes"), "{e}");
}
