//! The rotor-file keys, one table like the case keys' ([`super::schema`], built the same way): dotted key,
//! unit, allowed values, typical range, typed default and meaning. `tiltpad schema --rotor` prints it, and
//! [`super::rotor::RotorFile::resolve`] reads every range, default and unit from it (through [`rotor_row`]); a
//! test sets every numeric key just outside its range and checks that validation rejects it naming the key,
//! the value and the same interval. (The rotor file's editor, a view of its own, reads units and tooltips
//! from here by key; its rows are not drawn from the table.)

use super::error::Range;
use super::rotor::{
    RotorFile, DEFAULT_DENSITY_KG_PER_M3, DEFAULT_POISSON_RATIO, DEFAULT_SECTION_ELEMENTS, DEFAULT_SHAFT_MODES,
    DEFAULT_YOUNGS_MODULUS_GPA,
};
use super::schema::{Fallback, KeySpec};
use crate::units::{COUNT, DEG, GPA, G_MM, KG, KG_M2, KG_PER_M3, MM, NS_PER_M, N_PER_M, ONE, RPM};

type Key = KeySpec<RotorFile>;

const NODE: &str = "integer in [0, last node] (nodes counted from 0 at the first section's left end)";
const NONE: Fallback<RotorFile> = Fallback::Rule("none");

/// Every rotor-file key, in file order.
pub const ROTOR_KEYS: &[Key] = &[
    Key::text("title").meaning("Free text shown with every result."),
    Key::flag("rotor.representative")
        .default(Fallback::Flag(false))
        .meaning("The rotor's data are not all published (chosen here); every result is marked so."),
    Key::choice("rotor.beam_theory", &["timoshenko", "euler_bernoulli"])
        .default(Fallback::Word("timoshenko"))
        .meaning("Shaft elements with shear deformation and rotary inertia (Nelson & McVaugh), or without."),
    Key::choice("rotor.coefficients", &["full", "reduced"])
        .default(Fallback::Word("full"))
        .meaning("Bearing cases enter with their full K, C, M over journal and pad coordinates, or synchronously reduced to 2×2 at the running speed (overestimates the stable range)."),
    Key::integer("rotor.shaft_modes", COUNT, 0, 400)
        .default(Fallback::Count(DEFAULT_SHAFT_MODES))
        .meaning("Shaft reduction (Craig–Bampton): fixed-interface modes kept per bending plane besides the x, y of the attached nodes; 0 keeps the full finite-element shaft. Time and error per level in docs/PERFORMANCE.md."),
    Key::number("rotor.density_kg_per_m3", KG_PER_M3, Range::positive(1e5))
        .typical(2000.0, 9000.0)
        .or(DEFAULT_DENSITY_KG_PER_M3)
        .meaning("Density of the shaft material."),
    Key::number("rotor.youngs_modulus_gpa", GPA, Range::positive(1e4))
        .typical(70.0, 220.0)
        .or(DEFAULT_YOUNGS_MODULUS_GPA)
        .meaning("Young's modulus of the shaft material."),
    Key::number("rotor.poisson_ratio", ONE, Range::closed(0.0, 0.5))
        .typical(0.25, 0.35)
        .or(DEFAULT_POISSON_RATIO)
        .meaning("Poisson's ratio (the shear modulus of the Timoshenko elements)."),
    Key::number("rotor.min_speed_rpm", RPM, Range::positive(1e6))
        .typical(1000.0, 20000.0)
        .default(NONE)
        .meaning("Lower end of the operating speed range (drawn in the views; give both ends or neither)."),
    Key::rule("rotor.max_speed_rpm", RPM, "(rotor.min_speed_rpm, 1e6]")
        .default(NONE)
        .meaning("Upper end of the operating speed range."),
    Key::number("rotor.damping.ratio", ONE, Range::closed(0.0, 0.5))
        .typical(0.0, 0.05)
        .default(Fallback::Rule("no damping"))
        .meaning("Proportional (Rayleigh) damping: this damping ratio on the two free–free flexible modes named by rotor.damping.modes."),
    Key::rule("rotor.damping.modes", COUNT, "two increasing flexible-mode numbers in [1, 20]")
        .default(Fallback::Rule("[1, 2]"))
        .meaning("Free–free flexible modes (1 = first) that get the damping ratio."),
    Key::number("rotor.section[].length_mm", MM, Range::positive(1e5))
        .typical(10.0, 2000.0)
        .meaning("Length of a shaft section (split into `elements` equal elements)."),
    Key::number("rotor.section[].outer_diameter_mm", MM, Range::positive(1e4))
        .typical(20.0, 500.0)
        .meaning("Outer diameter of the section."),
    Key::rule("rotor.section[].inner_diameter_mm", MM, "[0, outer_diameter_mm)").or(0.0).meaning("Bore of a hollow section."),
    Key::integer("rotor.section[].elements", COUNT, 1, 200)
        .default(Fallback::Count(DEFAULT_SECTION_ELEMENTS))
        .meaning("Finite elements in the section; section i ends at node Σ elements."),
    Key::rule("rotor.disk[].node", COUNT, NODE).meaning("Node carrying a rigid disk (impeller, coupling hub, collar)."),
    Key::number("rotor.disk[].mass_kg", KG, Range::closed(0.0, 1e6)).typical(1.0, 500.0).meaning("Mass of the disk."),
    Key::number("rotor.disk[].polar_inertia_kg_m2", KG_M2, Range::closed(0.0, 1e6))
        .typical(0.01, 10.0)
        .or(0.0)
        .meaning("Polar moment of inertia (gyroscopic coupling)."),
    Key::number("rotor.disk[].transverse_inertia_kg_m2", KG_M2, Range::closed(0.0, 1e6))
        .typical(0.01, 10.0)
        .or(0.0)
        .meaning("Transverse (diametral) moment of inertia."),
    Key::rule("rotor.unbalance[].node", COUNT, NODE).meaning("Node carrying an unbalance."),
    Key::number("rotor.unbalance[].amount_g_mm", G_MM, Range::closed(0.0, 1e9)).typical(10.0, 10000.0).meaning("Unbalance m·e."),
    Key::number("rotor.unbalance[].phase_deg", DEG, Range::closed(-360.0, 360.0))
        .typical(0.0, 360.0)
        .or(0.0)
        .meaning("Angle of the unbalance from +x at t = 0."),
    Key::rule("rotor.bearing[].node", COUNT, NODE)
        .meaning("Node where the bearing (or coefficients given by numbers) acts on the shaft."),
    Key::text("rotor.bearing[].case")
        .default(Fallback::Rule("— (or k_n_per_m)"))
        .meaning("Bearing case file, relative to the rotor file, solved at each speed; the same file at several positions is solved once per speed."),
    Key::rule("rotor.bearing[].set", COUNT, "list of \"key=value\" overrides as --set takes them")
        .default(NONE)
        .meaning("Overrides applied to the bearing case (e.g. \"mesh.fidelity=\\\"preview\\\"\")."),
    Key::rule(
        "rotor.bearing[].k_n_per_m",
        N_PER_M,
        "rows [xx, xy, yx, yy], each entry in [-1e15, 1e15]; one row per speeds_rpm entry, or one row",
    )
    .default(Fallback::Rule("— (or case)"))
    .meaning("Stiffness given by numbers (seals, aerodynamic cross-coupling, coefficients from elsewhere)."),
    Key::rule("rotor.bearing[].c_ns_per_m", NS_PER_M, "as k_n_per_m; required with it")
        .default(Fallback::Rule("— (or case)"))
        .meaning("Damping given by numbers."),
    Key::rule("rotor.bearing[].speeds_rpm", RPM, "strictly ascending, in [0, 1e6]")
        .default(Fallback::Rule("constant coefficients"))
        .meaning("Speeds of the coefficient rows (linear interpolation between, held outside)."),
    Key::rule("rotor.support[].node", COUNT, NODE).meaning("Node of an isotropic linear support."),
    Key::number("rotor.support[].stiffness_n_per_m", N_PER_M, Range::closed(0.0, 1e15))
        .typical(1e5, 1e9)
        .meaning("Stiffness of the support in x and y."),
    Key::number("rotor.support[].damping_ns_per_m", NS_PER_M, Range::closed(0.0, 1e12))
        .typical(0.0, 1e5)
        .or(0.0)
        .meaning("Damping of the support in x and y."),
];

/// The row of a rotor-file key (its row key, `[]` for array entries), found while compiling:
/// `const { rotor_row("rotor.poisson_ratio") }`; a key without a row fails the build.
#[must_use]
pub const fn rotor_row(key: &str) -> &'static Key {
    let mut i = 0;
    while i < ROTOR_KEYS.len() {
        if super::schema::same_text(ROTOR_KEYS[i].key, key) {
            return &ROTOR_KEYS[i];
        }
        i += 1;
    }
    panic!("no row in model::rotor_schema::ROTOR_KEYS for this key")
}

/// The row of a rotor-file key, found while compiling (a key without a row fails the build); `rotor_row`
/// must be in scope as `row` where it is used.
macro_rules! rotor_key {
    ($key:literal) => {
        const { row($key) }
    };
}
pub(super) use rotor_key;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::error::CaseError;
    use crate::model::rotor::parse_rotor_file;
    use crate::model::schema::Allowed;

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
                ("rotor.shaft_modes", 401.0, "an integer in [0, 400] (0: full shaft)")
            ),
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn every_key_of_the_shipped_rotor_has_a_row() {
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
