//! Validation of a rotor file ([`RotorFile::resolve`]): every key checked against its row in
//! [`super::rotor_schema`] (ranges, defaults and units), nodes against the shaft, bearing cases read and
//! validated, coefficient tables checked row by row; the result is the SI [`Rotor`]. Errors name the key, the
//! value and the allowed range.

use super::error::{CaseError, Inconsistency, Range};
use super::rotor::{
    BearingPosition, BearingSupport, BearingTable, CoefficientTable, Disk, ModalDamping, Rotor, RotorFile, Support,
    Unbalance, MAX_SHAFT_ELEMENTS,
};
use super::rotor_schema::{rotor_key, rotor_row as row};
use super::shaft::BeamSection;

fn check_node(key: &str, node: usize, n_nodes: usize) -> Result<usize, CaseError> {
    if node < n_nodes {
        Ok(node)
    } else {
        #[allow(clippy::cast_precision_loss)]
        Err(CaseError::OutOfRange {
            key: key.into(),
            value: node as f64,
            allowed: format!("integer in [0, {}]", n_nodes - 1),
        })
    }
}

impl RotorFile {
    /// Validates and converts to SI; `read_case` returns the text of a bearing case file by the name written
    /// in the rotor file (the caller resolves it relative to the rotor file).
    ///
    /// # Errors
    /// The first invalid value, named by its key.
    #[allow(clippy::too_many_lines)]
    pub fn resolve(&self, read_case: &dyn Fn(&str) -> Result<String, String>) -> Result<Rotor, CaseError> {
        let r = &self.rotor;
        let density = rotor_key!("rotor.density_kg_per_m3").value(Some(r.density_kg_per_m3))?;
        let youngs = rotor_key!("rotor.youngs_modulus_gpa").value(Some(r.youngs_modulus_gpa))?;
        let nu = rotor_key!("rotor.poisson_ratio").value(Some(r.poisson_ratio))?;
        if r.section.is_empty() {
            return Err(CaseError::missing("rotor.section", "at least one shaft section"));
        }
        let mut elements = Vec::new();
        for (i, s) in r.section.iter().enumerate() {
            let key = |k: &str| format!("rotor.section[{i}].{k}");
            let l = rotor_key!("rotor.section[].length_mm").value_at(&key("length_mm"), Some(s.length_mm))?;
            let outer = rotor_key!("rotor.section[].outer_diameter_mm");
            let od = outer.value_at(&key("outer_diameter_mm"), Some(s.outer_diameter_mm))?;
            let id = outer
                .to_si(Range::open_hi(0.0, s.outer_diameter_mm).check(&key("inner_diameter_mm"), s.inner_diameter_mm)?);
            let n = rotor_key!("rotor.section[].elements").count_at(&key("elements"), Some(s.elements))?;
            #[allow(clippy::cast_precision_loss)]
            let le = l / n as f64;
            for _ in 0..n {
                elements.push(BeamSection {
                    length_m: le,
                    outer_diameter_m: od,
                    inner_diameter_m: id,
                    density_kg_per_m3: density,
                    youngs_modulus_pa: youngs,
                    poisson_ratio: nu,
                });
            }
        }
        if elements.len() > MAX_SHAFT_ELEMENTS {
            return Err(CaseError::inconsistent(
                "rotor.section",
                Inconsistency::ShaftElements { total: elements.len(), max: MAX_SHAFT_ELEMENTS },
            ));
        }
        let n_nodes = elements.len() + 1;
        let disks = r
            .disk
            .iter()
            .enumerate()
            .map(|(i, d)| {
                let key = |k: &str| format!("rotor.disk[{i}].{k}");
                Ok(Disk {
                    node: check_node(&key("node"), d.node, n_nodes)?,
                    mass: rotor_key!("rotor.disk[].mass_kg").value_at(&key("mass_kg"), Some(d.mass_kg))?,
                    polar: rotor_key!("rotor.disk[].polar_inertia_kg_m2")
                        .value_at(&key("polar_inertia_kg_m2"), Some(d.polar_inertia_kg_m2))?,
                    transverse: rotor_key!("rotor.disk[].transverse_inertia_kg_m2")
                        .value_at(&key("transverse_inertia_kg_m2"), Some(d.transverse_inertia_kg_m2))?,
                })
            })
            .collect::<Result<Vec<_>, CaseError>>()?;
        let unbalances = r
            .unbalance
            .iter()
            .enumerate()
            .map(|(i, u)| {
                let key = |k: &str| format!("rotor.unbalance[{i}].{k}");
                Ok(Unbalance {
                    node: check_node(&key("node"), u.node, n_nodes)?,
                    amount: rotor_key!("rotor.unbalance[].amount_g_mm")
                        .value_at(&key("amount_g_mm"), Some(u.amount_g_mm))?,
                    phase: rotor_key!("rotor.unbalance[].phase_deg").value_at(&key("phase_deg"), Some(u.phase_deg))?,
                })
            })
            .collect::<Result<Vec<_>, CaseError>>()?;
        let bearings = r
            .bearing
            .iter()
            .enumerate()
            .map(|(i, b)| resolve_bearing(i, b, n_nodes, read_case))
            .collect::<Result<Vec<_>, CaseError>>()?;
        let supports = r
            .support
            .iter()
            .enumerate()
            .map(|(i, s)| {
                let key = |k: &str| format!("rotor.support[{i}].{k}");
                Ok(Support {
                    node: check_node(&key("node"), s.node, n_nodes)?,
                    stiffness: rotor_key!("rotor.support[].stiffness_n_per_m")
                        .value_at(&key("stiffness_n_per_m"), Some(s.stiffness_n_per_m))?,
                    damping: rotor_key!("rotor.support[].damping_ns_per_m")
                        .value_at(&key("damping_ns_per_m"), Some(s.damping_ns_per_m))?,
                })
            })
            .collect::<Result<Vec<_>, CaseError>>()?;
        let damping = match &r.damping {
            None => None,
            Some(d) => {
                let ratio = rotor_key!("rotor.damping.ratio").value(Some(d.ratio))?;
                if d.modes[0] == 0 || d.modes[1] <= d.modes[0] || d.modes[1] > 20 {
                    return Err(CaseError::inconsistent(
                        "rotor.damping.modes",
                        Inconsistency::DampingModes { modes: d.modes },
                    ));
                }
                Some(ModalDamping { ratio, modes: d.modes })
            }
        };
        let shaft_modes = rotor_key!("rotor.shaft_modes");
        if let Err(CaseError::OutOfRange { key, value, allowed }) = shaft_modes.count(Some(r.shaft_modes)) {
            return Err(CaseError::OutOfRange { key, value, allowed: format!("{allowed} (0: full shaft)") });
        }
        let operating_range = match (r.min_speed_rpm, r.max_speed_rpm) {
            (Some(lo), Some(hi)) => {
                let min = rotor_key!("rotor.min_speed_rpm");
                let lo = min.check(min.key, lo)?;
                let top = min.allowed.range().map_or(f64::INFINITY, |r| r.hi);
                let hi = Range::open_lo(lo, top).check("rotor.max_speed_rpm", hi)?;
                Some([min.to_si(lo), min.to_si(hi)])
            }
            (None, None) => None,
            _ => return Err(CaseError::inconsistent("rotor.max_speed_rpm", Inconsistency::SpeedRangeHalf)),
        };
        Ok(Rotor {
            title: self.title.clone().unwrap_or_default(),
            representative: r.representative,
            theory: r.beam_theory,
            coefficients: r.coefficients,
            shaft_modes: r.shaft_modes,
            elements,
            disks,
            unbalances,
            bearings,
            supports,
            damping,
            operating_range,
        })
    }
}

fn resolve_bearing(
    i: usize,
    b: &BearingTable,
    n_nodes: usize,
    read_case: &dyn Fn(&str) -> Result<String, String>,
) -> Result<BearingPosition, CaseError> {
    let key = |k: &str| format!("rotor.bearing[{i}].{k}");
    let node = check_node(&key("node"), b.node, n_nodes)?;
    let numbers = !b.k_n_per_m.is_empty() || !b.c_ns_per_m.is_empty();
    let support = match (&b.case, numbers) {
        (Some(name), false) => {
            let text = read_case(name).map_err(|reason| {
                CaseError::inconsistent(key("case"), Inconsistency::CaseUnreadable { name: name.clone(), reason })
            })?;
            let (_, case) = super::load_case(&text, &b.set).map_err(|e| {
                CaseError::inconsistent(
                    key("case"),
                    Inconsistency::CaseInvalid { name: name.clone(), error: Box::new(e) },
                )
            })?;
            let name = if b.set.is_empty() { name.clone() } else { format!("{name} [{}]", b.set.join(", ")) };
            BearingSupport::Case { name, case: Box::new(case) }
        }
        (None, true) => {
            let rows = b.k_n_per_m.len();
            let expected = if b.speeds_rpm.is_empty() { 1 } else { b.speeds_rpm.len() };
            for (k, n) in [("k_n_per_m", rows), ("c_ns_per_m", b.c_ns_per_m.len())] {
                if n != expected {
                    return Err(CaseError::inconsistent(key(k), Inconsistency::CoefficientRows { rows: n, expected }));
                }
            }
            let speed = rotor_key!("rotor.bearing[].speeds_rpm");
            let mut speeds: Vec<f64> = Vec::new();
            for (j, &s) in b.speeds_rpm.iter().enumerate() {
                let range = speeds.last().map_or(Range::closed(0.0, 1e6), |&p| Range::open_lo(speed.from_si(p), 1e6));
                speeds.push(speed.to_si(range.check(&format!("{}[{j}]", key("speeds_rpm")), s)?));
            }
            let mat = |row: &[f64; 4], k: &str, j: usize| -> Result<[[f64; 2]; 2], CaseError> {
                for &v in row {
                    Range::closed(-1e15, 1e15).check(&format!("{}[{j}]", key(k)), v)?;
                }
                Ok([[row[0], row[1]], [row[2], row[3]]])
            };
            let k =
                b.k_n_per_m.iter().enumerate().map(|(j, r)| mat(r, "k_n_per_m", j)).collect::<Result<Vec<_>, _>>()?;
            let c =
                b.c_ns_per_m.iter().enumerate().map(|(j, r)| mat(r, "c_ns_per_m", j)).collect::<Result<Vec<_>, _>>()?;
            BearingSupport::Numbers(CoefficientTable { speeds, k, c })
        }
        _ => return Err(CaseError::inconsistent(key("case"), Inconsistency::CaseOrNumbers)),
    };
    Ok(BearingPosition { node, support })
}
