//! The rotor description: shaft sections, rigid disks, unbalances, bearing positions (each a bearing case or
//! coefficients given by numbers), linear supports and proportional damping — as the user writes it (TOML,
//! engineering units in the key names) and validated into SI ([`Rotor`]).
//!
//! Layout (see `cases/rotors/*.toml`):
//!
//! ```toml
//! title = "…"
//! [rotor]                 # beam_theory, coefficients (full | reduced), shaft_modes, material, operating range, representative
//! [rotor.damping]         # ratio on the free–free flexible modes `modes` (1 = first flexible mode)
//! [[rotor.section]]       # length_mm, outer_diameter_mm, inner_diameter_mm, elements
//! [[rotor.disk]]          # node, mass_kg, polar_inertia_kg_m2, transverse_inertia_kg_m2
//! [[rotor.unbalance]]     # node, amount_g_mm, phase_deg
//! [[rotor.bearing]]       # node and either case = "bearing.toml" [set = ["key=value", …]] or k_n_per_m / c_ns_per_m [/ speeds_rpm]
//! [[rotor.support]]       # node, stiffness_n_per_m, damping_ns_per_m (isotropic linear support)
//! ```
//! Nodes are numbered from 0 at the first section's left end; section i ends at node `Σ elements`. A bearing
//! case path is relative to the rotor file. Coefficient rows are `[xx, xy, yx, yy]`, one per tabulated speed
//! (one row and no `speeds_rpm` for constant coefficients); between tabulated speeds they are interpolated
//! linearly, outside they are held at the end values.

use serde::{Deserialize, Serialize};

use super::control::PlantInfo;
use super::error::CaseError;
use super::shaft::{BeamSection, BeamTheory};
use super::Case;

/// Most shaft elements over all sections: 1604 coordinates, whose dense eigen-solution (the shaft's modes, or
/// the whole system per speed without reduction) takes seconds; 25 sections of 200 elements (20 004
/// coordinates) would allocate gigabytes before the first speed.
pub const MAX_SHAFT_ELEMENTS: usize = 400;

/// Which bearing coefficients enter the rotor equations.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum CoefficientModel {
    /// Full K, C, M over journal and pad coordinates (pad coordinates appended to the rotor's).
    #[default]
    Full,
    /// 2×2 K, C reduced at the running speed (synchronous reduction).
    Reduced,
}

/// The rotor file.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RotorFile {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub title: Option<String>,
    pub rotor: RotorTable,
    /// `[control]`: a controller acting on this rotor through its bearings ([`super::control`]); the rotor
    /// analysis ignores it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub control: Option<super::control::ControlTable>,
}

/// `[rotor]`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RotorTable {
    /// The rotor is a representative one (its data are not all published); shown with every result.
    #[serde(default, skip_serializing_if = "is_false")]
    pub representative: bool,
    #[serde(default)]
    pub beam_theory: BeamTheory,
    #[serde(default)]
    pub coefficients: CoefficientModel,
    #[serde(default = "default_density")]
    pub density_kg_per_m3: f64,
    #[serde(default = "default_youngs")]
    pub youngs_modulus_gpa: f64,
    #[serde(default = "default_poisson")]
    pub poisson_ratio: f64,
    /// Operating speed range (for the API 617 line and the separation margins).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub min_speed_rpm: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_speed_rpm: Option<f64>,
    /// Fixed-interface shaft modes kept per bending plane by the shaft reduction (Craig–Bampton); 0: the
    /// full finite-element shaft.
    #[serde(default = "default_shaft_modes")]
    pub shaft_modes: usize,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub damping: Option<DampingTable>,
    pub section: Vec<SectionTable>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub disk: Vec<DiskTable>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub unbalance: Vec<UnbalanceTable>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub bearing: Vec<BearingTable>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub support: Vec<SupportTable>,
}

// Defaults left out when a rotor file is written (an edited file keeps the keys its author left out).
#[allow(clippy::trivially_copy_pass_by_ref)] // serde's skip_serializing_if passes a reference
fn is_false(b: &bool) -> bool {
    !b
}
#[allow(clippy::trivially_copy_pass_by_ref)]
fn is_zero(x: &f64) -> bool {
    *x == 0.0
}
/// Defaults of the shaft's material (a steel), which the rows of [`super::rotor_schema`] give as theirs.
pub const DEFAULT_DENSITY_KG_PER_M3: f64 = 7850.0;
pub const DEFAULT_YOUNGS_MODULUS_GPA: f64 = 211.0;
pub const DEFAULT_POISSON_RATIO: f64 = 0.3;
fn default_density() -> f64 {
    DEFAULT_DENSITY_KG_PER_M3
}
fn default_youngs() -> f64 {
    DEFAULT_YOUNGS_MODULUS_GPA
}
fn default_poisson() -> f64 {
    DEFAULT_POISSON_RATIO
}
/// Default shaft reduction (modes per plane), chosen by measurement (docs/PERFORMANCE.md, compressor rotor
/// on preview bearings): its errors against the full shaft (first damped frequencies ~1e-4 relative, log
/// decrements ~1e-3, the onset within the bisection's bracket) lie far below the bearing model's own, at a
/// small fraction of the full shaft's eigen-solution time.
pub const DEFAULT_SHAFT_MODES: usize = 8;
fn default_shaft_modes() -> usize {
    DEFAULT_SHAFT_MODES
}

/// `[rotor.damping]`: Rayleigh damping `C = αM + βK` giving `ratio` on two free–free flexible modes.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DampingTable {
    pub ratio: f64,
    #[serde(default = "default_modes")]
    pub modes: [usize; 2],
}

fn default_modes() -> [usize; 2] {
    [1, 2]
}

/// `[[rotor.section]]`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SectionTable {
    pub length_mm: f64,
    pub outer_diameter_mm: f64,
    #[serde(default, skip_serializing_if = "is_zero")]
    pub inner_diameter_mm: f64,
    #[serde(default = "one")]
    pub elements: usize,
}

/// Default element count of a shaft section (its row's default in [`super::rotor_schema`]).
pub const DEFAULT_SECTION_ELEMENTS: usize = 1;
fn one() -> usize {
    DEFAULT_SECTION_ELEMENTS
}

/// `[[rotor.disk]]`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DiskTable {
    pub node: usize,
    pub mass_kg: f64,
    #[serde(default, skip_serializing_if = "is_zero")]
    pub polar_inertia_kg_m2: f64,
    #[serde(default, skip_serializing_if = "is_zero")]
    pub transverse_inertia_kg_m2: f64,
}

/// `[[rotor.unbalance]]`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct UnbalanceTable {
    pub node: usize,
    pub amount_g_mm: f64,
    #[serde(default)]
    pub phase_deg: f64,
}

/// `[[rotor.bearing]]`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BearingTable {
    pub node: usize,
    /// Bearing case file (relative to the rotor file).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub case: Option<String>,
    /// Overrides applied to the bearing case, as `--set` takes them (`"mesh.fidelity=preview"`).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub set: Vec<String>,
    /// Stiffness rows `[xx, xy, yx, yy]`, one per speed in `speeds_rpm` (or one row).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub k_n_per_m: Vec<[f64; 4]>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub c_ns_per_m: Vec<[f64; 4]>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub speeds_rpm: Vec<f64>,
}

/// `[[rotor.support]]`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SupportTable {
    pub node: usize,
    pub stiffness_n_per_m: f64,
    #[serde(default, skip_serializing_if = "is_zero")]
    pub damping_ns_per_m: f64,
}

// ---------------------------------------------------------------------------------------------- SI form

/// A rigid disk at a node [kg, kg·m²].
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Disk {
    pub node: usize,
    pub mass: f64,
    pub polar: f64,
    pub transverse: f64,
}

/// An unbalance `m e` [kg·m] at a node, at angle `phase` [rad] from +x at t = 0.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Unbalance {
    pub node: usize,
    pub amount: f64,
    pub phase: f64,
}

/// 2×2 coefficients given by numbers, constant or tabulated against speed [SI].
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CoefficientTable {
    /// Speeds [rad/s]; empty for constant coefficients (one row).
    pub speeds: Vec<f64>,
    pub k: Vec<[[f64; 2]; 2]>,
    pub c: Vec<[[f64; 2]; 2]>,
}

impl CoefficientTable {
    /// Constant coefficients.
    #[must_use]
    pub fn constant(k: [[f64; 2]; 2], c: [[f64; 2]; 2]) -> Self {
        Self { speeds: Vec::new(), k: vec![k], c: vec![c] }
    }

    /// K, C at speed `omega` [rad/s]: linear interpolation, held at the ends.
    #[must_use]
    pub fn at(&self, omega: f64) -> ([[f64; 2]; 2], [[f64; 2]; 2]) {
        let n = self.speeds.len();
        if n < 2 {
            return (self.k[0], self.c[0]);
        }
        let i = self.speeds.partition_point(|&s| s <= omega).clamp(1, n - 1);
        let t = ((omega - self.speeds[i - 1]) / (self.speeds[i] - self.speeds[i - 1])).clamp(0.0, 1.0);
        let lerp = |a: &[[f64; 2]; 2], b: &[[f64; 2]; 2]| {
            let mut r = [[0.0; 2]; 2];
            for p in 0..2 {
                for q in 0..2 {
                    r[p][q] = a[p][q] + t * (b[p][q] - a[p][q]);
                }
            }
            r
        };
        (lerp(&self.k[i - 1], &self.k[i]), lerp(&self.c[i - 1], &self.c[i]))
    }
}

/// What a bearing position holds.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub enum BearingSupport {
    /// A bearing case, solved at each speed; `name` is the path as written (identical names share solves).
    Case { name: String, case: Box<Case> },
    /// Coefficients given by numbers.
    Numbers(CoefficientTable),
}

/// A bearing at a node.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct BearingPosition {
    pub node: usize,
    pub support: BearingSupport,
}

/// An isotropic linear support [N/m, N·s/m].
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Support {
    pub node: usize,
    pub stiffness: f64,
    pub damping: f64,
}

/// Proportional damping: `ratio` on the free–free flexible modes `modes` (1-based).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct ModalDamping {
    pub ratio: f64,
    pub modes: [usize; 2],
}

/// A validated rotor [SI].
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Rotor {
    pub title: String,
    pub representative: bool,
    pub theory: BeamTheory,
    pub coefficients: CoefficientModel,
    /// Fixed-interface shaft modes per bending plane (0: full finite-element shaft).
    pub shaft_modes: usize,
    /// One per element, in order along the shaft.
    pub elements: Vec<BeamSection>,
    pub disks: Vec<Disk>,
    pub unbalances: Vec<Unbalance>,
    pub bearings: Vec<BearingPosition>,
    pub supports: Vec<Support>,
    pub damping: Option<ModalDamping>,
    /// Operating speed range [rad/s].
    pub operating_range: Option<[f64; 2]>,
}

impl Rotor {
    /// Number of shaft nodes.
    #[must_use]
    pub fn n_nodes(&self) -> usize {
        self.elements.len() + 1
    }

    /// Axial position of every node [m].
    #[must_use]
    pub fn node_positions(&self) -> Vec<f64> {
        let mut z = vec![0.0];
        for e in &self.elements {
            z.push(z[z.len() - 1] + e.length_m);
        }
        z
    }

    /// Total mass (shaft and disks) [kg].
    #[must_use]
    pub fn mass(&self) -> f64 {
        self.elements.iter().map(BeamSection::mass).sum::<f64>() + self.disks.iter().map(|d| d.mass).sum::<f64>()
    }
}

/// The controller's plant on a rotor (the rotor file holds the controller's table, so the rotor, not the
/// controller, knows both).
impl<'a> PlantInfo<'a> {
    /// The rotor's: its nodes, and each bearing position's node and case.
    #[must_use]
    pub fn rotor(rotor: &'a Rotor) -> Self {
        let bearings = rotor
            .bearings
            .iter()
            .map(|b| {
                let case = match &b.support {
                    BearingSupport::Case { case, .. } => Some(case.as_ref()),
                    BearingSupport::Numbers(_) => None,
                };
                (b.node, case)
            })
            .collect();
        Self { n_nodes: rotor.n_nodes(), bearings }
    }
}

/// Parses a rotor file's text.
///
/// # Errors
/// [`CaseError::Syntax`] or a schema error naming the key.
pub fn parse_rotor_file(text: &str) -> Result<RotorFile, CaseError> {
    let table: toml::Table = text.parse().map_err(|e: toml::de::Error| CaseError::Syntax { message: e.to_string() })?;
    serde_path_to_error::deserialize::<_, RotorFile>(toml::Value::Table(table)).map_err(|e| {
        let path = e.path().to_string();
        super::load::schema_error(&path, &e.into_inner().to_string())
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::error::Inconsistency;

    const MINIMAL: &str = "[rotor]\n[[rotor.section]]\nlength_mm = 500.0\nouter_diameter_mm = 50.0\nelements = 4\n";

    fn resolve(text: &str) -> Result<Rotor, CaseError> {
        parse_rotor_file(text)?.resolve(&|name| Err(format!("no file {name}")))
    }

    #[test]
    fn minimal_rotor_resolves_in_si() {
        let r = resolve(MINIMAL).unwrap();
        assert_eq!(r.n_nodes(), 5);
        assert!((r.node_positions()[4] - 0.5).abs() < 1e-15);
        let mass = 7850.0 * std::f64::consts::PI / 4.0 * 0.05_f64.powi(2) * 0.5;
        assert!((r.mass() - mass).abs() < 1e-12 * mass);
    }

    #[test]
    fn errors_name_the_key_and_the_range() {
        let bad_node = format!("{MINIMAL}[[rotor.disk]]\nnode = 5\nmass_kg = 1.0\n");
        match resolve(&bad_node) {
            Err(CaseError::OutOfRange { key, value, allowed }) => {
                assert_eq!((key.as_str(), value, allowed.as_str()), ("rotor.disk[0].node", 5.0, "integer in [0, 4]"));
            }
            other => panic!("{other:?}"),
        }
        let typo = MINIMAL.replace("length_mm", "length");
        assert!(matches!(resolve(&typo), Err(CaseError::UnknownKey { key, .. }) if key.contains("rotor.section")));
        let rows = format!("{MINIMAL}[[rotor.bearing]]\nnode = 0\nk_n_per_m = [[1.0, 0.0, 0.0, 1.0]]\nc_ns_per_m = [[1.0, 0.0, 0.0, 1.0], [1.0, 0.0, 0.0, 1.0]]\n");
        assert!(
            matches!(resolve(&rows), Err(CaseError::Inconsistent { key, .. }) if key == "rotor.bearing[0].c_ns_per_m")
        );
        let missing = format!("{MINIMAL}[[rotor.bearing]]\nnode = 0\ncase = \"b.toml\"\n");
        assert!(
            matches!(resolve(&missing), Err(CaseError::Inconsistent { key, reason: Inconsistency::CaseUnreadable { reason, .. } }) if key == "rotor.bearing[0].case" && reason.contains("no file b.toml"))
        );
        let id = MINIMAL.replace("elements = 4", "elements = 4\ninner_diameter_mm = 50.0");
        assert!(
            matches!(resolve(&id), Err(CaseError::OutOfRange { key, .. }) if key == "rotor.section[0].inner_diameter_mm")
        );
    }

    #[test]
    fn tabulated_coefficients_interpolate_and_hold() {
        let t = CoefficientTable {
            speeds: vec![100.0, 200.0],
            k: vec![[[1.0, 2.0], [3.0, 4.0]], [[3.0, 2.0], [3.0, 8.0]]],
            c: vec![[[0.0; 2]; 2], [[2.0, 0.0], [0.0, 2.0]]],
        };
        let (k, c) = t.at(150.0);
        assert_eq!((k, c), ([[2.0, 2.0], [3.0, 6.0]], [[1.0, 0.0], [0.0, 1.0]]));
        assert_eq!(t.at(50.0).0, t.k[0]);
        assert_eq!(t.at(500.0).0, t.k[1]);
    }
}
