//! The schema table against validation: every key's range is the one `resolve` enforces.

use super::*;
use crate::model::{load_case, CaseError};

#[test]
fn every_key_of_a_file_has_a_row_and_lookups_normalise_indices() {
    assert_eq!(spec("bearing.pads.orifice[2].diameter_mm").unwrap().key, "bearing.pads.orifice[].diameter_mm");
    assert_eq!(spec("bearing.pads.orifice.0.length_mm").unwrap().key, "bearing.pads.orifice[].length_mm");
    assert_eq!(spec("bearing.pad.3.offset").unwrap().key, "bearing.pads.offset");
    assert_eq!(spec("bearing.pads.pivot_deg[1]").unwrap().key, "bearing.pads.pivot_deg");
    assert_eq!(spec("operating.injection_pressure_bar[4]").unwrap().unit, "bar");
    assert!(spec("operating.speed").is_none());
    // Every key a shipped case writes is in the table.
    for (name, text) in crate::model::shipped_cases() {
        let table: toml::Table = text.parse().unwrap();
        for key in leaf_keys(&toml::Value::Table(table), "") {
            assert!(spec(&key).is_some(), "{name}: `{key}` has no schema row");
        }
    }
    // No key listed twice.
    for (i, a) in KEYS.iter().enumerate() {
        assert!(KEYS[i + 1..].iter().all(|b| b.key != a.key), "{} twice", a.key);
    }
}

fn leaf_keys(v: &toml::Value, prefix: &str) -> Vec<String> {
    let join = |k: &str| if prefix.is_empty() { k.to_string() } else { format!("{prefix}.{k}") };
    match v {
        toml::Value::Table(t) => t.iter().flat_map(|(k, v)| leaf_keys(v, &join(k))).collect(),
        toml::Value::Array(a) if a.iter().all(toml::Value::is_table) && !a.is_empty() => {
            a.iter().enumerate().flat_map(|(i, v)| leaf_keys(v, &format!("{prefix}[{i}]"))).collect()
        }
        _ => vec![prefix.to_string()],
    }
}

/// Overrides that make a key apply (BC2 needs its coefficient, the position mode its ratio, …).
fn context(key: &str) -> Vec<String> {
    match key {
        "thermal.h_oil_pad_w_per_m2_k" => vec!["thermal.pad_film_bc=\"bc2\"".into()],
        "feeding.groove_carry_over" => vec!["feeding.kind=\"leading_edge_groove\"".into()],
        "operating.eccentricity_ratio" | "operating.eccentricity_angle_deg" => {
            vec![
                "operating.load_n=".into(),
                "operating.load_angle_deg=".into(),
                "operating.eccentricity_ratio=0.3".into(),
            ]
        }
        "bearing.pads.preload" | "bearing.pads.clearance_um" => vec!["bearing.pads.bore_radius_mm=".into()],
        "lubricant.viscosity_coefficient_per_k" => {
            vec!["lubricant.viscosity2_pa_s=".into(), "lubricant.viscosity2_temperature_c=".into()]
        }
        "bearing.pads.pivot_radius_mm" => vec!["bearing.pads.pivot_contact=\"ball\"".into()],
        "bearing.pads.pivot_seat_radius_mm" => {
            vec!["bearing.pads.pivot_contact=\"ball\"".into(), "bearing.pads.pivot_radius_mm=10".into()]
        }
        "bearing.pads.pivot_length_mm"
        | "bearing.pads.pivot_seat_youngs_modulus_gpa"
        | "bearing.pads.pivot_seat_poisson_ratio" => vec![
            "bearing.pads.pivot_contact=\"rocker\"".into(),
            "bearing.pads.pivot_radius_mm=20".into(),
            "bearing.pads.pivot_seat_radius_mm=21".into(),
        ],
        _ => vec![],
    }
}

#[test]
fn validation_enforces_the_documented_ranges() {
    let compressor = include_str!("../../../cases/compressor-bearing.toml");
    let rig = include_str!("../../../cases/test-rig-pub5.toml");
    let mut checked = 0;
    for k in KEYS {
        let range = match k.allowed {
            Allowed::Number(r) | Allowed::NumberPerPad(r) => r,
            _ => continue,
        };
        let key = k.key.replace("[]", ".0");
        let outside: Vec<f64> = [
            if range.lo.is_finite() {
                Some(if range.open_lo { range.lo } else { range.lo - range.lo.abs().max(1.0) * 1e-3 })
            } else {
                None
            },
            if range.hi.is_finite() {
                Some(if range.open_hi { range.hi } else { range.hi + range.hi.abs().max(1.0) * 1e-3 })
            } else {
                None
            },
        ]
        .into_iter()
        .flatten()
        .collect();
        for v in outside {
            let mut set = context(k.key);
            set.push(format!("{key}={v:?}"));
            let text = if k.key.starts_with("hydraulics.") { rig } else { compressor };
            match load_case(text, &set) {
                Err(CaseError::OutOfRange { key: got, allowed, .. }) => {
                    assert!(spec(&got).is_some_and(|s| s.key == k.key), "{}: error names `{got}`", k.key);
                    assert!(
                        allowed.contains(&range.describe()),
                        "{}: validation allows {allowed}, the schema says {}",
                        k.key,
                        range.describe()
                    );
                    checked += 1;
                }
                other => panic!("{} = {v}: expected an out-of-range error, got {other:?}", k.key),
            }
        }
        // And a typical value inside the range passes this check.
        let (lo, hi) = k.typical.unwrap_or((range.lo, range.hi));
        assert!(range.check(k.key, 0.5 * (lo + hi)).is_ok(), "{}: typical range outside the allowed one", k.key);
    }
    assert!(checked > 60, "only {checked} bounds checked");
}

/// Every default lies in its key's allowed values (a number in its range, a count in its interval, a word
/// among the choices), so an absent key never resolves to a value the key itself would refuse. (A default
/// that applies only where the key does not: a fixed sector's thickness 0, no pad body, is exempt.)
#[test]
fn every_default_is_an_allowed_value() {
    let file = crate::model::parse_case_file(include_str!("../../../cases/compressor-bearing.toml"), &[]).unwrap();
    let mut checked = 0;
    for k in KEYS.iter().filter(|k| !matches!(k.default, Fallback::Sometimes { .. })) {
        let value = k.default_in(&file);
        match (k.allowed, k.default) {
            (_, Fallback::Word(w)) => {
                let Allowed::Choice(words) = k.allowed else { panic!("{}: a word default without a choice", k.key) };
                assert!(words.contains(&w), "{}: default `{w}` is not one of {words:?}", k.key);
            }
            (Allowed::Integer { lo, hi }, _) => {
                if let Some(v) = value {
                    assert!(v.fract() == 0.0 && (lo as f64..=hi as f64).contains(&v), "{}: default {v}", k.key);
                }
            }
            (a, _) => {
                if let (Some(r), Some(v)) = (a.range(), value) {
                    assert!(r.contains(v), "{}: default {v} outside {}", k.key, r.describe());
                }
            }
        }
        checked += usize::from(value.is_some());
    }
    assert!(checked > 40, "only {checked} numeric defaults");
}

/// A case with every table the editor draws: the test rig (orifices, hydraulics with two lines and a rig).
fn full_case() -> crate::model::CaseFile {
    crate::model::parse_case_file(include_str!("../../../cases/test-rig-pub5.toml"), &[]).unwrap()
}

/// Every editor row's key is a key of the file format: the editor writes it by key (as `--set` does) and
/// reads the same value back, whatever the row's widget; an indexed row is written in its first entry.
#[test]
fn the_editor_reads_and_writes_every_row_by_its_key() {
    let base = full_case();
    let mut written = 0;
    for k in KEYS.iter().filter(|k| k.editor.is_some()) {
        let key = k.key.replace("[]", "[0]");
        let value = match k.allowed {
            Allowed::Choice(words) => toml::Value::String(words[words.len() - 1].into()),
            Allowed::Bool => toml::Value::Boolean(true),
            Allowed::Text => toml::Value::String("a name".into()),
            Allowed::Integer { lo, hi } => toml::Value::Integer(i64::try_from((lo + hi) / 2).unwrap()),
            Allowed::NumberPerPad(_) | Allowed::Number(_) | Allowed::NumberWhere(..) | Allowed::Rule(_) => {
                let (lo, hi) = k.typical.unwrap_or((0.0, 1.0));
                toml::Value::Float(0.25 * lo + 0.75 * hi)
            }
        };
        let edited = base.with_value(&key, Some(value.clone())).unwrap_or_else(|e| panic!("{key}: {e}"));
        let table = edited.to_table().unwrap();
        assert_eq!(crate::model::load::value_at(&table, &key), Some(&value), "{key}");
        // Removing an optional key leaves a file that still reads.
        if !matches!(k.default, Fallback::Required) {
            let removed = edited.with_value(&key, None).unwrap_or_else(|e| panic!("{key} removed: {e}"));
            assert!(crate::model::load::value_at(&removed.to_table().unwrap(), &key).is_none(), "{key}");
        }
        written += 1;
    }
    assert!(written > 80, "only {written} editor rows");
}

/// The file's choice enums default (`#[default]`, what validation takes for an absent key) to their rows'
/// default words (what `tiltpad schema` and the editor show); so do the rotor file's.
#[test]
fn the_file_enums_default_to_their_rows_word() {
    use crate::model::file::{
        CavitatedFilmFile, Cavitation, FeedingKind, Fidelity, PadFilmBcFile, PadKindFile, ThermalModelKind, Turbulence,
    };
    use crate::model::rotor::CoefficientModel;
    use crate::model::shaft::BeamTheory;
    fn word<T: serde::Serialize + Default>() -> String {
        toml::Value::try_from(T::default()).unwrap().as_str().unwrap().to_string()
    }
    let case = [
        ("bearing.pads.kind", word::<PadKindFile>()),
        ("mesh.fidelity", word::<Fidelity>()),
        ("physics.cavitation", word::<Cavitation>()),
        ("physics.turbulence", word::<Turbulence>()),
        ("thermal.model", word::<ThermalModelKind>()),
        ("thermal.pad_film_bc", word::<PadFilmBcFile>()),
        ("thermal.cavitated_film", word::<CavitatedFilmFile>()),
        ("feeding.kind", word::<FeedingKind>()),
    ];
    for (key, w) in &case {
        assert!(matches!(spec(key).unwrap().default, Fallback::Word(d) if d == *w), "{key}: the enum defaults to {w}");
    }
    let rotor = [("rotor.beam_theory", word::<BeamTheory>()), ("rotor.coefficients", word::<CoefficientModel>())];
    for (key, w) in rotor {
        let row = crate::model::rotor_schema::ROTOR_KEYS.iter().find(|k| k.key == key).unwrap();
        assert!(matches!(row.default, Fallback::Word(d) if d == w), "{key}: the enum defaults to {w}");
    }
    // Every choice row with a default word has been compared.
    let words = KEYS.iter().filter(|k| matches!(k.default, Fallback::Word(_))).count();
    assert_eq!(words, case.len());
}
