//! The rotor-file keys, one table like the case keys' ([`super::schema`]): dotted key, unit, allowed values,
//! typical range, default and meaning. `tiltpad schema --rotor` prints it. The allowed ranges are the ones
//! [`super::rotor::RotorFile::resolve`] enforces; a test sets every numeric key just outside its range and
//! checks that validation rejects it naming the key, the value and the same interval.

use super::error::Range;
use super::schema::{Allowed, KeySpec};

const fn num(
    key: &'static str,
    unit: &'static str,
    range: Range,
    typical: (f64, f64),
    default: &'static str,
    meaning: &'static str,
) -> KeySpec {
    KeySpec { key, unit, allowed: Allowed::Number(range), typical: Some(typical), default, meaning }
}

const fn other(
    key: &'static str,
    unit: &'static str,
    allowed: Allowed,
    default: &'static str,
    meaning: &'static str,
) -> KeySpec {
    KeySpec { key, unit, allowed, typical: None, default, meaning }
}

const NODE: Allowed = Allowed::Rule("integer in [0, last node] (nodes counted from 0 at the first section's left end)");
/// [`DEFAULT_SHAFT_MODES`] as written (a test keeps them equal).
const SHAFT_MODES_DEFAULT: &str = "8";

/// Every rotor-file key, in file order.
pub const ROTOR_KEYS: &[KeySpec] = &[
    other("title", "", Allowed::Text, "empty", "Free text shown with every result."),
    other("rotor.representative", "", Allowed::Bool, "false", "The rotor's data are not all published (chosen here); every result is marked so."),
    other("rotor.beam_theory", "", Allowed::Choice(&["timoshenko", "euler_bernoulli"]), "\"timoshenko\"", "Shaft elements with shear deformation and rotary inertia (Nelson & McVaugh), or without."),
    other(
        "rotor.coefficients",
        "",
        Allowed::Choice(&["full", "reduced"]),
        "\"full\"",
        "Bearing cases enter with their full K, C, M over journal and pad coordinates, or synchronously reduced to 2×2 at the running speed (overestimates the stable range).",
    ),
    other(
        "rotor.shaft_modes",
        "",
        Allowed::Integer { lo: 0, hi: 400 },
        SHAFT_MODES_DEFAULT,
        "Shaft reduction (Craig–Bampton): fixed-interface modes kept per bending plane besides the x, y of the attached nodes; 0 keeps the full finite-element shaft. Time and error per level in docs/PERFORMANCE.md.",
    ),
    num("rotor.density_kg_per_m3", "kg/m³", Range::positive(1e5), (2000.0, 9000.0), "7850", "Density of the shaft material."),
    num("rotor.youngs_modulus_gpa", "GPa", Range::positive(1e4), (70.0, 220.0), "211", "Young's modulus of the shaft material."),
    num("rotor.poisson_ratio", "–", Range::closed(0.0, 0.5), (0.25, 0.35), "0.3", "Poisson's ratio (the shear modulus of the Timoshenko elements)."),
    num("rotor.min_speed_rpm", "rpm", Range::positive(1e6), (1000.0, 20000.0), "none", "Lower end of the operating speed range (drawn in the views; give both ends or neither)."),
    other("rotor.max_speed_rpm", "rpm", Allowed::Rule("(rotor.min_speed_rpm, 1e6]"), "none", "Upper end of the operating speed range."),
    num("rotor.damping.ratio", "–", Range::closed(0.0, 0.5), (0.0, 0.05), "no damping", "Proportional (Rayleigh) damping: this damping ratio on the two free–free flexible modes named by rotor.damping.modes."),
    other("rotor.damping.modes", "", Allowed::Rule("two increasing flexible-mode numbers in [1, 20]"), "[1, 2]", "Free–free flexible modes (1 = first) that get the damping ratio."),
    num("rotor.section[].length_mm", "mm", Range::positive(1e5), (10.0, 2000.0), "", "Length of a shaft section (split into `elements` equal elements)."),
    num("rotor.section[].outer_diameter_mm", "mm", Range::positive(1e4), (20.0, 500.0), "", "Outer diameter of the section."),
    other("rotor.section[].inner_diameter_mm", "mm", Allowed::Rule("[0, outer_diameter_mm)"), "0", "Bore of a hollow section."),
    other("rotor.section[].elements", "", Allowed::Integer { lo: 1, hi: 200 }, "1", "Finite elements in the section; section i ends at node Σ elements."),
    other("rotor.disk[].node", "", NODE, "", "Node carrying a rigid disk (impeller, coupling hub, collar)."),
    num("rotor.disk[].mass_kg", "kg", Range::closed(0.0, 1e6), (1.0, 500.0), "", "Mass of the disk."),
    num("rotor.disk[].polar_inertia_kg_m2", "kg·m²", Range::closed(0.0, 1e6), (0.01, 10.0), "0", "Polar moment of inertia (gyroscopic coupling)."),
    num("rotor.disk[].transverse_inertia_kg_m2", "kg·m²", Range::closed(0.0, 1e6), (0.01, 10.0), "0", "Transverse (diametral) moment of inertia."),
    other("rotor.unbalance[].node", "", NODE, "", "Node carrying an unbalance."),
    num("rotor.unbalance[].amount_g_mm", "g·mm", Range::closed(0.0, 1e9), (10.0, 10000.0), "", "Unbalance m·e."),
    num("rotor.unbalance[].phase_deg", "deg", Range::closed(-360.0, 360.0), (0.0, 360.0), "0", "Angle of the unbalance from +x at t = 0."),
    other("rotor.bearing[].node", "", NODE, "", "Node where the bearing (or coefficients given by numbers) acts on the shaft."),
    other("rotor.bearing[].case", "", Allowed::Text, "— (or k_n_per_m)", "Bearing case file, relative to the rotor file, solved at each speed; the same file at several positions is solved once per speed."),
    other("rotor.bearing[].set", "", Allowed::Rule("list of \"key=value\" overrides as --set takes them"), "none", "Overrides applied to the bearing case (e.g. \"mesh.fidelity=\\\"preview\\\"\")."),
    other(
        "rotor.bearing[].k_n_per_m",
        "N/m",
        Allowed::Rule("rows [xx, xy, yx, yy], each entry in [-1e15, 1e15]; one row per speeds_rpm entry, or one row"),
        "— (or case)",
        "Stiffness given by numbers (seals, aerodynamic cross-coupling, coefficients from elsewhere).",
    ),
    other("rotor.bearing[].c_ns_per_m", "N·s/m", Allowed::Rule("as k_n_per_m; required with it"), "— (or case)", "Damping given by numbers."),
    other("rotor.bearing[].speeds_rpm", "rpm", Allowed::Rule("strictly ascending, in [0, 1e6]"), "constant coefficients", "Speeds of the coefficient rows (linear interpolation between, held outside)."),
    other("rotor.support[].node", "", NODE, "", "Node of an isotropic linear support."),
    num("rotor.support[].stiffness_n_per_m", "N/m", Range::closed(0.0, 1e15), (1e5, 1e9), "", "Stiffness of the support in x and y."),
    num("rotor.support[].damping_ns_per_m", "N·s/m", Range::closed(0.0, 1e12), (0.0, 1e5), "0", "Damping of the support in x and y."),
];

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::error::CaseError;
    use crate::model::rotor::{parse_rotor_file, DEFAULT_SHAFT_MODES};

    /// A rotor with one of every table, written so each numeric key can be set.
    const BASE: &str = r#"
[rotor]
min_speed_rpm = 1000.0
max_speed_rpm = 2000.0
[rotor.damping]
ratio = 0.01
[[rotor.section]]
length_mm = 500.0
outer_diameter_mm = 50.0
elements = 4
[[rotor.disk]]
node = 2
mass_kg = 10.0
[[rotor.unbalance]]
node = 2
amount_g_mm = 100.0
[[rotor.support]]
node = 0
stiffness_n_per_m = 1e7
"#;

    /// Sets `rotor.section[].length_mm` (first entry) etc. in the base file.
    fn with(key: &str, value: f64) -> String {
        let mut doc: toml::Table = BASE.parse().unwrap();
        let parts: Vec<&str> = key.split('.').collect();
        let mut table = &mut doc;
        for part in &parts[..parts.len() - 1] {
            table = match part.strip_suffix("[]") {
                Some(array) => table
                    .get_mut(array)
                    .and_then(toml::Value::as_array_mut)
                    .and_then(|a| a.first_mut())
                    .and_then(toml::Value::as_table_mut)
                    .unwrap(),
                None => table.get_mut(*part).and_then(toml::Value::as_table_mut).unwrap(),
            };
        }
        table.insert(parts[parts.len() - 1].to_string(), toml::Value::Float(value));
        toml::to_string(&doc).unwrap()
    }

    #[test]
    fn validation_enforces_the_documented_ranges_and_names_key_value_and_range() {
        assert!(parse_rotor_file(BASE).unwrap().resolve(&|_| Err("no cases".into())).is_ok());
        let mut checked = 0;
        for k in ROTOR_KEYS {
            let Allowed::Number(range) = k.allowed else { continue };
            for v in [
                if range.open_lo { range.lo } else { range.lo - range.lo.abs().max(1.0) * 1e-3 },
                if range.open_hi { range.hi } else { range.hi + range.hi.abs().max(1.0) * 1e-3 },
            ] {
                let text = with(k.key, v);
                match parse_rotor_file(&text).and_then(|f| f.resolve(&|_| Err("no cases".into()))) {
                    Err(CaseError::OutOfRange { key, value, allowed }) => {
                        assert_eq!(key.replace("[0]", "[]"), k.key);
                        assert_eq!(value, v, "{key}");
                        assert!(
                            allowed.contains(&range.describe()),
                            "{key}: validation allows {allowed}, the table says {}",
                            range.describe()
                        );
                        checked += 1;
                    }
                    other => panic!("{} = {v}: expected an out-of-range error, got {other:?}", k.key),
                }
            }
        }
        assert_eq!(checked, 2 * ROTOR_KEYS.iter().filter(|k| matches!(k.allowed, Allowed::Number(_))).count());
        // whole-number keys: the error names the key, the value and the interval
        let too_many = BASE.replace("[rotor]\n", "[rotor]\nshaft_modes = 401\n");
        match parse_rotor_file(&too_many).unwrap().resolve(&|_| Err("no cases".into())) {
            Err(CaseError::OutOfRange { key, value, allowed }) => assert_eq!(
                (key.as_str(), value, allowed.as_str()),
                ("rotor.shaft_modes", 401.0, "integer in [0, 400] (0: full shaft)")
            ),
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn every_key_of_the_shipped_rotor_has_a_row() {
        assert_eq!(SHAFT_MODES_DEFAULT, DEFAULT_SHAFT_MODES.to_string());
        let text = include_str!("../../cases/rotors/compressor-rotor.toml");
        let table: toml::Table = text.parse().unwrap();
        let mut keys = Vec::new();
        leaf_keys(&toml::Value::Table(table), "", &mut keys);
        for key in keys {
            assert!(ROTOR_KEYS.iter().any(|k| k.key == key), "`{key}` has no row");
        }
    }

    fn leaf_keys(v: &toml::Value, prefix: &str, out: &mut Vec<String>) {
        let join = |k: &str| if prefix.is_empty() { k.to_string() } else { format!("{prefix}.{k}") };
        match v {
            toml::Value::Table(t) => t.iter().for_each(|(k, v)| leaf_keys(v, &join(k), out)),
            toml::Value::Array(a) if !a.is_empty() && a.iter().all(toml::Value::is_table) => {
                a.iter().for_each(|v| leaf_keys(v, &format!("{prefix}[]"), out))
            }
            _ => out.push(prefix.to_string()),
        }
    }
}
