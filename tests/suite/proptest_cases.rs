//! Property-based test over random case files, valid and invalid: reading never panics, a rejected
//! case names a key that one of its overrides set (or made inconsistent), and an accepted case either solves to finite, balanced results or fails with a typed
//! error — never NaN, never a panic.

use crate::common;

use proptest::prelude::*;
use tiltpad::bearing::solve_case;
use tiltpad::model::{load_case, CaseError};

/// The consistent flows of a converged solve balance to round-off (measured up to 3e-13 in tests/suite/extremes.rs).
const MASS_BALANCE: f64 = 1e-12;

/// Values a user might type: sensible, extreme, negative, non-finite.
fn number() -> impl Strategy<Value = String> {
    prop_oneof![
        (0.01f64..10.0).prop_map(|v| format!("{v}")),
        (-1e3f64..1e6).prop_map(|v| format!("{v}")),
        Just("0".to_string()),
        Just("-1".to_string()),
        Just("nan".to_string()),
        Just("inf".to_string()),
        Just("1e308".to_string()),
        Just("\"text\"".to_string()),
    ]
}

/// One override of the compressor case: a key from the schema (or a misspelt one) and a value.
fn override_() -> impl Strategy<Value = String> {
    let keys = prop::sample::select(vec![
        "bearing.journal_radius_mm",
        "bearing.length_mm",
        "bearing.assembled_clearance_um",
        "bearing.pads.count",
        "bearing.pads.arc_deg",
        "bearing.pads.offset",
        "bearing.pads.bore_radius_mm",
        "bearing.pads.thickness_mm",
        "bearing.pads.pivot_stiffness_n_per_m",
        "lubricant.viscosity_pa_s",
        "lubricant.viscosity2_pa_s",
        "operating.speed_rpm",
        "operating.load_n",
        "operating.load_angle_deg",
        "operating.injection_pressure_bar",
        "operating.excitation_ratio",
        "mesh.circumferential_elements",
        "mesh.orifice_elements",
        "bearing.pads.arcdeg",
    ]);
    (keys, number()).prop_map(|(k, v)| format!("{k}={v}"))
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 96, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn random_cases_never_panic_or_produce_nan(set in prop::collection::vec(override_(), 1..4)) {
        let text = std::fs::read_to_string(common::case_path("compressor-bearing.toml")).unwrap()
            .replace("fidelity = \"standard\"", "fidelity = \"preview\"");
        match load_case(&text, &set) {
            Err(e) => {
                // A rejection blames one of the overrides: it names the overridden key, or a key of the same
                // table whose value the override made inconsistent (a smaller journal radius invalidates the
                // clearance, a longer arc makes the pads overlap, a finer mesh exceeds the node budget).
                let blamed = match &e {
                    CaseError::BadOverride { text, .. } => text.split('=').next().unwrap_or_default().to_string(),
                    other => other.key().map(str::to_string).unwrap_or_default(),
                };
                let table = |k: &str| k.split('.').next().unwrap_or_default().to_string();
                prop_assert!(
                    set.iter().any(|o| table(o.split('=').next().unwrap_or_default()) == table(&blamed) && !blamed.is_empty()),
                    "{set:?} rejected with {e:?}, which blames none of the overrides"
                );
            }
            Ok((_, case)) => {
                // Keep meshes bounded so the property stays quick.
                prop_assume!(case.mesh.circumferential_elements <= 64 && case.mesh.orifice_elements <= 16);
                match solve_case(&case) {
                    Ok(s) => {
                        prop_assert!(s.eccentricity_ratio.is_finite() && s.friction_power_w.is_finite());
                        // The consistent flows balance to round-off.
                        prop_assert!(s.flows_m3_per_s.mass_balance_error.abs() < MASS_BALANCE, "{set:?}: {:e}", s.flows_m3_per_s.mass_balance_error);
                        prop_assert!(s.reduced.k_n_per_m.iter().flatten().all(|v| v.is_finite()));
                        prop_assert!(s.pads.iter().all(|p| p.field.pressure_pa.iter().all(|v| v.is_finite())));
                    }
                    Err(e) => prop_assert!(!e.to_string().to_lowercase().contains("nan"), "{e}"),
                }
            }
        }
    }

    /// Arbitrary text: the reader returns an error or a case, never panics.
    #[test]
    fn arbitrary_text_never_panics(text in "\\PC{0,400}") {
        let _ = load_case(&text, &[]);
    }

    /// Arbitrary mutations of a valid file (one line replaced by random text).
    #[test]
    fn mutated_files_never_panic(line in 0usize..60, junk in "[a-z_.=\\[\\]0-9\" -]{0,40}") {
        let text = std::fs::read_to_string(common::case_path("fillon-a.toml")).unwrap();
        let mut lines: Vec<&str> = text.lines().collect();
        if line < lines.len() {
            lines[line] = &junk;
        }
        let _ = load_case(&lines.join("\n"), &[]);
    }
}
