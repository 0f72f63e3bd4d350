//! The rotor's share of a command's work estimate ([`super::estimate`]): the dense eigen-solutions per speed
//! (damped, over the shaft's and the appended pad coordinates) and of the critical-speed map (undamped, one
//! plane of the shaft), each costing the cube of its size at a measured rate, and the shaft model built once.
//! The rates were measured on a generated uniform shaft ([`uniform_rotor`]), which the bench of the
//! estimates and the tests of the rotor's progress generate again.

use crate::model::rotor::{BearingSupport, CoefficientModel, Rotor};
use crate::model::PadKind;

/// Time of one work unit (the cube of the state size) of a rotor's damped eigen-solution at the reference
/// rate [s]: measured with the full 400-element shaft, release build (docs/PERFORMANCE.md, work estimates).
pub const EIGEN_SECONDS_PER_UNIT: f64 = 7.0e-10;
/// Time of one work unit of the shaft built once [s]: the cube of the nodal shaft coordinates when it is
/// reduced (the fixed-interface modes and the projection: 385 elements, 1544 coordinates, took 4.8 s of CPU
/// time), of half of them for the full shaft (only the free–free modes of one plane).
pub const SHAFT_SECONDS_PER_UNIT: f64 = 1.3e-9;

/// Time of one work unit (the cube of the coordinates) of an undamped eigen-solution of one plane of the
/// shaft (`rotor --critical-map`: Cholesky of the mass, the symmetric eigen-problem with its vectors) at the
/// reference rate [s] (see the module: 8.6e-10 measured at 402 coordinates, 8.5e-10 at 802).
pub const UNDAMPED_SECONDS_PER_UNIT: f64 = 8.5e-10;

/// The rotor's dense eigen-solutions in an estimate (see the module).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EigenWork {
    /// Eigen-solutions (speeds and bisection probes).
    pub solutions: usize,
    /// States of each (twice the system's coordinates); for the undamped map, the coordinates of one
    /// plane of the shaft.
    pub states: usize,
    /// Undamped, symmetric eigen-problems (`rotor --critical-map`) rather than damped ones.
    pub undamped: bool,
    /// Time of one at the reference rate [s].
    pub seconds_each: f64,
    /// Time of the shaft model built once [s].
    pub shaft_seconds: f64,
}

impl EigenWork {
    /// Time of all of them and of the shaft [s].
    #[must_use]
    pub fn seconds(&self) -> f64 {
        #[allow(clippy::cast_precision_loss)]
        let n = self.solutions as f64;
        n * self.seconds_each + self.shaft_seconds
    }
}

/// The working coordinates of a rotor's system at one speed: the shaft's (full or reduced, as
/// [`crate::rotor::analysis::shaft_model`] builds it) and the pad coordinates the full bearing coefficients
/// append (every coordinate of every tilting pad; decoupled ones are left out by the analysis, so this is an
/// upper bound).
#[must_use]
pub fn rotor_coordinates(rotor: &Rotor) -> usize {
    let full = 4 * (rotor.elements.len() + 1);
    let mut attached: Vec<usize> = rotor
        .bearings
        .iter()
        .map(|b| b.node)
        .chain(rotor.supports.iter().map(|s| s.node))
        .chain(rotor.unbalances.iter().map(|u| u.node))
        .collect();
    attached.sort_unstable();
    attached.dedup();
    // the reduction holds the shaft with two attached nodes or a support; otherwise the full shaft is kept
    let holds = attached.len() >= 2 || !rotor.supports.is_empty();
    let shaft = if rotor.shaft_modes == 0 || !holds {
        full
    } else {
        let boundary = 2 * attached.len();
        boundary + (2 * rotor.shaft_modes).min(full.saturating_sub(boundary))
    };
    shaft + appended_coordinates(rotor)
}

/// The pad coordinates the full bearing coefficients append to the shaft's (see [`rotor_coordinates`]).
pub(super) fn appended_coordinates(rotor: &Rotor) -> usize {
    match rotor.coefficients {
        CoefficientModel::Reduced => 0,
        CoefficientModel::Full => rotor
            .bearings
            .iter()
            .filter_map(|b| match &b.support {
                BearingSupport::Case { case, .. } => Some(
                    case.bearing.pads.iter().filter(|p| p.kind == PadKind::Tilting).count()
                        * (1 + case.physics.pad_modes),
                ),
                BearingSupport::Numbers(_) => None,
            })
            .sum(),
    }
}

/// A rotor file: a uniform shaft of `elements` elements (four equal sections, `elements` a multiple of 4 up
/// to the file's 400) with one impeller and its unbalance at mid-span, on two bearings given by the case
/// `bearing` (an absolute path), analysed on the full shaft (`shaft_modes = 0`): the eigen-solutions are
/// most of its work.
#[must_use]
pub fn uniform_rotor(elements: usize, bearing: &std::path::Path) -> String {
    let section = elements / 4;
    let mut t = format!(
        "title = \"Uniform shaft, {elements} elements, full shaft (generated)\"\n\n[rotor]\nshaft_modes = 0\n\
         coefficients = \"full\"\n"
    );
    for _ in 0..4 {
        t.push_str(&format!(
            "\n[[rotor.section]]\nlength_mm = 300.0\nouter_diameter_mm = 101.6\nelements = {section}\n"
        ));
    }
    let (a, mid, b) = (elements / 20, elements / 2, elements - elements / 20);
    t.push_str(&format!(
        "\n[[rotor.disk]]\nnode = {mid}\nmass_kg = 46.0\npolar_inertia_kg_m2 = 0.92\ntransverse_inertia_kg_m2 = 0.47\n\
         \n[[rotor.unbalance]]\nnode = {mid}\namount_g_mm = 720.0\n"
    ));
    for node in [a, b] {
        t.push_str(&format!("\n[[rotor.bearing]]\nnode = {node}\ncase = {:?}\n", bearing.display().to_string()));
    }
    t
}
