//! Work and memory of a command, estimated from its inputs alone before the first solve, and the bound that
//! refuses a command whose estimate is too large.
//!
//! ## The work model
//! One bearing point (mesh, equilibrium, full and reduced coefficients) costs, at the reference rate,
//! ```text
//! t = t_ref · (N_film / N_ref)^a · f_thermal · f_cavitation
//! ```
//! with `N_film` the film nodes the case's meshes will have ([`crate::model::budget::count`], counted from
//! the case without building a mesh), `N_ref = 4940`, `t_ref = 43.2 ms` (the isothermal compressor bearing at
//! standard fidelity) and `a = 1.19` (the fitted growth of the time with the node count), the thermal factor
//! 7.4 for THD with an adiabatic film (BC1) and 23 with a film–pad exchange (BC2, BC3), and 3 for the
//! mass-conserving cavitation model — all measured on the reference machine of docs/PERFORMANCE.md. The
//! estimate is a property of the input, not of the machine or its load: the same command gets the same
//! estimate and the same verdict everywhere (a machine twice as slow takes twice as long). Against the
//! measured table it is exact at the reference point and at THD standard fidelity, 6 % high for the isothermal
//! reference fidelity and 29 % low for THD at reference fidelity (the pad solids' share grows with the
//! mesh): good enough to refuse hours of work up front, not a prediction to plan by.
//!
//! Memory of a point: about 2 kB per mesh node (film and pad solid; docs/PERFORMANCE.md and
//! [`crate::model::budget`]). The rotor's shaft model holds dense matrices of its `n = 4 (elements + 1)`
//! coordinates and the eigen-solution dense complex matrices of the `2n` states: `224 n²` bytes.

use std::fmt;

use crate::model::budget;
use crate::model::rotor::{BearingSupport, Rotor};
use crate::model::{Case, Cavitation, PadFilmBc, ThermalModelKind};

/// Film nodes of the reference point.
const REF_NODES: f64 = 4940.0;
/// Time of the reference point at the reference rate [s].
const REF_SECONDS: f64 = 0.0432;
/// Growth of the time with the film nodes.
const EXPONENT: f64 = 1.19;
/// Memory per mesh node [bytes].
const BYTES_PER_NODE: f64 = 2048.0;

/// Default bound on a command's estimated work [h] (`--max-hours` raises it).
pub const DEFAULT_MAX_HOURS: f64 = 4.0;
/// Memory no command may plan to use [bytes]; beyond it the command is refused with the keys that shrink it.
pub const MAX_BYTES: f64 = 8.0 * 1024.0 * 1024.0 * 1024.0;

/// What one bearing point of a case costs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PointCost {
    /// Film nodes over all pads.
    pub film_nodes: usize,
    /// Every mesh node (film and pad solids).
    pub nodes: usize,
    /// Time at the reference rate [s].
    pub seconds: f64,
    /// Peak memory [bytes].
    pub bytes: f64,
}

/// The cost of one solve of `case`.
#[must_use]
pub fn point_cost(case: &Case) -> PointCost {
    let n = budget::count(case);
    #[allow(clippy::cast_precision_loss)]
    let film = n.film() as f64;
    let thermal = match (case.thermal.model, case.thermal.pad_film_bc) {
        (ThermalModelKind::Isothermal, _) => 1.0,
        (ThermalModelKind::Thd, PadFilmBc::Bc1) => 7.4,
        (ThermalModelKind::Thd, PadFilmBc::Bc2 { .. } | PadFilmBc::Bc3) => 23.0,
    };
    let cavitation = if case.physics.cavitation == Cavitation::Jfo { 3.0 } else { 1.0 };
    #[allow(clippy::cast_precision_loss)]
    let bytes = n.total() as f64 * BYTES_PER_NODE;
    PointCost {
        film_nodes: n.film(),
        nodes: n.total(),
        seconds: REF_SECONDS * (film / REF_NODES).powf(EXPONENT) * thermal * cavitation,
        bytes,
    }
}

/// The estimate of a whole command.
#[derive(Debug, Clone, PartialEq)]
pub struct Estimate {
    /// What the command solves (`sweep`, `rotor`, …).
    pub what: &'static str,
    /// Bearing solves it will make.
    pub solves: usize,
    /// Time at the reference rate [s].
    pub seconds: f64,
    /// Peak memory [bytes].
    pub bytes: f64,
}

impl Estimate {
    /// `solves` points of cost `cost` each (a command that holds one point's meshes at a time).
    #[must_use]
    pub fn points(what: &'static str, solves: usize, cost: PointCost) -> Self {
        #[allow(clippy::cast_precision_loss)]
        let seconds = solves as f64 * cost.seconds;
        Self { what, solves, seconds, bytes: cost.bytes }
    }

    /// The rotor analysis of `rotor` over `speeds` speeds: each speed solves every bearing given by a case;
    /// the onset bisection adds up to `extra_speeds` more; memory is the shaft's and the eigen-solution's
    /// dense matrices plus the bearings' meshes (all held at once).
    #[must_use]
    pub fn rotor(what: &'static str, rotor: &Rotor, speeds: usize, extra_speeds: usize) -> Self {
        let costs: Vec<PointCost> = rotor
            .bearings
            .iter()
            .filter_map(|b| match &b.support {
                BearingSupport::Case { case, .. } => Some(point_cost(case)),
                BearingSupport::Numbers(_) => None,
            })
            .collect();
        let per_speed: f64 = costs.iter().map(|c| c.seconds).sum();
        let n = 4.0 * (rotor.elements.len() as f64 + 1.0);
        let bytes = 224.0 * n * n + costs.iter().map(|c| c.bytes).sum::<f64>();
        let all = speeds.saturating_add(extra_speeds);
        #[allow(clippy::cast_precision_loss)]
        let seconds = all as f64 * per_speed;
        Self { what, solves: all.saturating_mul(costs.len()), seconds, bytes }
    }

    /// Refuses an estimate over `max_hours` of work or over [`MAX_BYTES`] of memory.
    ///
    /// # Errors
    /// [`TooMuchWork`] naming the estimate, the bound and the setting that raises it.
    pub fn check(&self, max_hours: f64) -> Result<(), TooMuchWork> {
        if self.bytes > MAX_BYTES {
            return Err(TooMuchWork::Memory { estimate: self.clone() });
        }
        if self.seconds > max_hours * 3600.0 {
            return Err(TooMuchWork::Time { estimate: self.clone(), max_hours });
        }
        Ok(())
    }
}

/// A duration for people: seconds, minutes or hours.
#[must_use]
pub fn duration_text(seconds: f64) -> String {
    if seconds < 60.0 {
        format!("{seconds:.1} s")
    } else if seconds < 3600.0 {
        format!("{:.1} min", seconds / 60.0)
    } else {
        format!("{:.1} h", seconds / 3600.0)
    }
}

/// Memory for people.
#[must_use]
pub fn bytes_text(bytes: f64) -> String {
    if bytes < 1024.0 * 1024.0 * 1024.0 {
        format!("{:.0} MB", bytes / (1024.0 * 1024.0))
    } else {
        format!("{:.1} GB", bytes / (1024.0 * 1024.0 * 1024.0))
    }
}

impl fmt::Display for Estimate {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}: {} bearing solves, about {} at the reference rate (docs/PERFORMANCE.md), peak memory about {}",
            self.what,
            self.solves,
            duration_text(self.seconds),
            bytes_text(self.bytes)
        )
    }
}

/// A command refused before its first solve.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum TooMuchWork {
    #[error(
        "{estimate}: more than the bound of {max_hours} h; narrow the range or lower the fidelity \
         (mesh.fidelity), or raise the bound with --max-hours {}",
        (estimate.seconds / 3600.0).ceil()
    )]
    Time { estimate: Estimate, max_hours: f64 },
    #[error(
        "{estimate}: more than the {} any command may plan to use; coarsen the meshes (mesh.fidelity, \
         mesh.max_nodes) or the shaft (fewer elements, rotor.shaft_modes)",
        bytes_text(MAX_BYTES)
    )]
    Memory { estimate: Estimate },
}

#[cfg(test)]
mod tests {
    use super::*;

    fn case(set: &[&str]) -> Case {
        let text =
            std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/cases/compressor-bearing.toml")).unwrap();
        let set: Vec<String> = set.iter().map(|s| (*s).to_string()).collect();
        crate::model::load_case(&text, &set).unwrap().1
    }

    #[test]
    fn the_reference_point_costs_its_measured_time_and_the_model_scales_from_it() {
        // The compressor bearing at standard fidelity is the reference point: 4940 film nodes, 43.2 ms.
        let standard = point_cost(&case(&["mesh.fidelity=\"standard\""]));
        assert_eq!(standard.film_nodes, 4940);
        assert!((standard.seconds - 0.0432).abs() < 1e-12, "{}", standard.seconds);
        // Isothermal at reference fidelity: 23010 film nodes, measured 254.1 ms; the model gives 269.6 ms (6 %).
        let iso = point_cost(&case(&["mesh.fidelity=\"reference\""]));
        assert_eq!(iso.film_nodes, 23010);
        assert!((iso.seconds / 0.2541 - 1.0).abs() < 0.07, "{} s against 0.2541 s measured", iso.seconds);
        // THD BC1 at reference fidelity: measured 2.809 s; the model (film nodes only, the thermal factor of
        // standard fidelity) gives 1.995 s, 29 % low: the pad solids' share grows with the mesh. An estimate
        // for refusing work up front, not a prediction.
        let thd = point_cost(&case(&["mesh.fidelity=\"reference\"", "thermal.model=\"thd\""]));
        let model = 0.0432 * (23010.0_f64 / 4940.0).powf(1.19) * 7.4;
        assert!((thd.seconds - model).abs() < 1e-12);
        assert!((thd.seconds / 2.809 - 1.0).abs() < 0.30, "{} s against 2.809 s measured", thd.seconds);
        assert!(thd.bytes > 2048.0 * 23010.0, "pad solids add to the film nodes");
    }

    #[test]
    fn a_long_command_is_refused_with_its_estimate_and_the_setting_that_raises_the_bound() {
        let cost = point_cost(&case(&["mesh.fidelity=\"reference\"", "thermal.model=\"thd\""]));
        let e = Estimate::points("sweep", 10_000, cost);
        let err = e.check(DEFAULT_MAX_HOURS).unwrap_err().to_string();
        assert!(err.contains("10000 bearing solves") && err.contains("about 5.5 h"), "{err}");
        assert!(err.contains("--max-hours 6"), "{err}");
        assert!(e.check(6.0).is_ok());
        // A preview sweep of the same length is well inside the bound.
        assert!(Estimate::points("sweep", 10_000, point_cost(&case(&[]))).check(DEFAULT_MAX_HOURS).is_ok());
    }

    #[test]
    fn memory_beyond_the_cap_is_refused_with_the_keys_that_shrink_it() {
        let mut cost = point_cost(&case(&[]));
        cost.bytes = 9.0 * 1024.0 * 1024.0 * 1024.0;
        let err = Estimate::points("solve", 1, cost).check(DEFAULT_MAX_HOURS).unwrap_err().to_string();
        assert!(err.contains("9.0 GB") && err.contains("mesh.max_nodes"), "{err}");
    }
}
