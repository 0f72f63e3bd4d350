//! Work and memory of a command, estimated from its inputs alone before the first solve, and the bound that
//! refuses a command whose estimate is too large.
//!
//! ## The work model
//! One bearing point (mesh, equilibrium, full and reduced coefficients) costs, at the reference rate,
//! ```text
//! t = t_ref · (N_film / N_ref)^a · f_cavitation · (f_thermal · coordinates + floating)
//! ```
//! with `N_film` the film nodes the case's meshes will have ([`crate::model::budget::count`], counted from
//! the case without building a mesh), `N_ref = 4940`, `t_ref = 43.2 ms` (the isothermal compressor bearing at
//! standard fidelity) and `a = 1.19` (the fitted growth of the time with the node count), the thermal factor
//! 7.4 for THD with an adiabatic film (BC1) and 23 with a film–pad exchange (BC2, BC3), and 3 for the
//! mass-conserving cavitation model — all measured on the reference machine of docs/PERFORMANCE.md.
//! `coordinates` and `floating` count what the equilibrium has to find ([`super::equilibrium_work`]: the
//! mean coordinates per pad, and the share of pads that float at the cold start); both are 1 and 0 at the
//! reference point. The
//! estimate is a property of the input, not of the machine or its load: the same command gets the same
//! estimate and the same verdict everywhere (a machine twice as slow takes twice as long). Against the
//! measured table it is exact at the reference point and at THD standard fidelity, 6 % high for the isothermal
//! reference fidelity and 29 % low for THD at reference fidelity (the pad solids' share grows with the
//! mesh): good enough to refuse hours of work up front, not a prediction to plan by.
//!
//! Memory of a point: at most 2.3 kB per mesh node (film and pad solid; measured peaks in [`BYTES_PER_NODE`],
//! docs/PERFORMANCE.md and [`crate::model::budget`]). The rotor's shaft model holds dense matrices of its `n = 4 (elements + 1)`
//! coordinates and the eigen-solution dense complex matrices of the `2n` states: `224 n²` bytes.
//!
//! ## Flexible pads
//! With `physics.pad_modes = m > 0` a solve first builds each distinct pad solid (identical pads share one;
//! `u = 3 n_film (layers + 1)` unknowns) and its lowest modes by subspace iteration, then carries `m` more
//! coordinates per pad through the equilibrium (in `coordinates` above: `1 + m` for a pad on a rigid pivot):
//! ```text
//! t = t_rigid · (1 + m) + Σ_distinct pads  t_modes,   t_modes = 0.29 s · (u / 14 820)^1.4 · (m + 1.5) / 4.5
//! ```
//! measured on the compressor's flexible pads at standard fidelity (CPU time, release build): 4940 solid nodes
//! per pad (14 820 unknowns as counted here; 14 337 after the supports) take 0.17 s for one mode and 0.29 s
//! for three, and the 8-layer table mesh (96 897 unknowns) 15 times as long. `tiltpad modes` is the modal
//! term alone (and its `--table` the table's seven meshes).
//!
//! ## The rotor's eigen-solutions
//! At each speed (and each probe of the onset bisection) the rotor analysis solves the damped eigen-problem
//! of the whole system in first-order form: a dense non-symmetric eigen-decomposition with eigenvectors of
//! the `s = 2 n_sys` states, `n_sys` the shaft's working coordinates (all `4 (elements + 1)` for the full
//! shaft, the attached nodes' x, y and `2 · shaft_modes` modes for the reduced one) plus the pad coordinates
//! the full bearing coefficients append. Its work grows as `s³` whatever the machine, so the work unit is
//! one `s³` and its time at the reference rate is the measured constant [`EIGEN_SECONDS_PER_UNIT`]:
//! ```text
//! t_eigen = c_eig · s³   per speed,        t_shaft = c_shaft · n³   once (free–free modes, reduction)
//! ```
//! with `c_eig = 7e-10 s` (measured per speed, CPU time of the release build: 6.8e-10 at 1788 states,
//! 7.1e-10 at 3108) and `c_shaft = 1.3e-9 s` (the reduction of a 385-element shaft; the full shaft only
//! computes one plane's free–free modes, `(n/2)³`).
//! A 400-element full shaft (s ≈ 3200) costs tens of seconds per speed this way, far more than its bearings.

use std::fmt;

pub use super::rotor_cost::{
    rotor_coordinates, EigenWork, EIGEN_SECONDS_PER_UNIT, SHAFT_SECONDS_PER_UNIT, UNDAMPED_SECONDS_PER_UNIT,
};

pub use super::equilibrium_work::{equilibrium_work, EquilibriumWork};

use super::rotor_cost::appended_coordinates;
use crate::model::budget;
use crate::model::rotor::{BearingSupport, Rotor};
use crate::model::{Case, Cavitation, PadFilmBc, PadKind, ThermalModelKind};

/// Film nodes of the reference point.
const REF_NODES: f64 = 4940.0;
/// Time of the reference point at the reference rate [s].
const REF_SECONDS: f64 = 0.0432;
/// Growth of the time with the film nodes.
const EXPONENT: f64 = 1.19;
/// Memory per mesh node [bytes]: an upper bound on the measured peaks (release build, `/usr/bin/time -v`):
/// 2.0 kB per node for the 478 485-node full compressor mesh (0.94 GB), 1.95 kB already before the first
/// equilibrium iteration of the 3.98 M-node one (7.74 GB; the fill of the sparse factorisations grows a little
/// faster than the nodes), whose peak, by the smaller mesh's rise from that point to its peak (×1.10), is
/// about 8.5 GB, over the 8 GB bound. With 2.3 kB planned the 3.98 M-node mesh is refused up front.
const BYTES_PER_NODE: f64 = 2355.0;
/// Pad-solid unknowns of the modal reference point and its time for three modes [s].
const MODES_REF_UNKNOWNS: f64 = 14_820.0;
const MODES_REF_SECONDS: f64 = 0.29;
/// Growth of the modal solution's time with the pad solid's unknowns.
const MODES_EXPONENT: f64 = 1.4;

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
    let modes = case.physics.pad_modes;
    let solids = flexible_solids(case);
    // the film's pad solids (THD) are the flexible pads' solids: counted once
    let solid_nodes: usize = if n.pad_solid > 0 { 0 } else { solids.iter().map(|s| s.nodes * s.pads).sum() };
    #[allow(clippy::cast_precision_loss)]
    let bytes = n.total().saturating_add(solid_nodes) as f64 * BYTES_PER_NODE;
    let work = equilibrium_work(case, !solids.is_empty());
    let film_solve = REF_SECONDS * (film / REF_NODES).powf(EXPONENT) * cavitation;
    PointCost {
        film_nodes: n.film(),
        nodes: n.total().saturating_add(solid_nodes),
        seconds: film_solve * (thermal * work.coordinates + work.floating)
            + solids.iter().map(|s| modes_seconds(s.unknowns(), modes)).sum::<f64>(),
        bytes,
    }
}

/// One distinct flexible pad solid of a case: its nodes and how many pads share it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PadSolid {
    /// Nodes of the solid (film grid × (layers + 1)).
    pub nodes: usize,
    /// Pads with this solid (they share one modal solution).
    pub pads: usize,
    /// What makes two pads' solids the same (film grid, arc, thickness, bore, pivot, material).
    key: [u64; 9],
}

impl PadSolid {
    /// Displacement unknowns (three per node).
    #[must_use]
    pub fn unknowns(&self) -> usize {
        3 * self.nodes
    }
}

/// The distinct flexible pad solids of `case` (empty for rigid pads: `physics.pad_modes = 0`, pivoted pads
/// other than tilting ones, pads without thickness).
#[must_use]
pub fn flexible_solids(case: &Case) -> Vec<PadSolid> {
    if case.physics.pad_modes == 0 {
        return Vec::new();
    }
    let layers = case.mesh.pad_radial_elements.max(1);
    let mut out: Vec<PadSolid> = Vec::new();
    for (k, pad) in case.bearing.pads.iter().enumerate() {
        if pad.kind != PadKind::Tilting || pad.thickness_m <= 0.0 {
            continue;
        }
        let (cols, rows) = budget::film_grid_size(case, k);
        let nodes = cols.saturating_mul(rows).saturating_mul(layers + 1);
        let pivot = (pad.pivot_rad - pad.leading_edge_rad) / pad.arc_rad;
        // compared in single precision: identical pads at other angles differ in the last bits
        #[allow(clippy::cast_precision_loss, clippy::cast_possible_truncation)]
        let key = [
            nodes as f64,
            pad.arc_rad,
            pad.thickness_m,
            pad.clearance_m,
            pad.preload,
            pivot,
            pad.youngs_modulus_pa,
            pad.poisson_ratio,
            pad.density_kg_per_m3,
        ]
        .map(|v| (v as f32).to_bits().into());
        match out.iter_mut().find(|s| s.key == key) {
            Some(s) => s.pads += 1,
            None => out.push(PadSolid { nodes, pads: 1, key }),
        }
    }
    out
}

/// Time of one pad solid's `modes` lowest modes at the reference rate [s] (see the module).
#[must_use]
pub fn modes_seconds(unknowns: usize, modes: usize) -> f64 {
    #[allow(clippy::cast_precision_loss)]
    let (u, m) = (unknowns as f64, modes as f64);
    MODES_REF_SECONDS * (u / MODES_REF_UNKNOWNS).powf(MODES_EXPONENT) * (m + 1.5) / 4.5
}

/// The estimate of a whole command.
#[derive(Debug, Clone, PartialEq)]
pub struct Estimate {
    /// What the command solves (`sweep`, `rotor`, …).
    pub what: &'static str,
    /// Bearing solves it will make.
    pub solves: usize,
    /// Time at the reference rate [s] (bearing solves and, for a rotor, its eigen-solutions).
    pub seconds: f64,
    /// Peak memory [bytes].
    pub bytes: f64,
    /// A rotor's eigen-solutions (`None` for a bearing command).
    pub eigen: Option<EigenWork>,
}

impl Estimate {
    /// `solves` points of cost `cost` each (a command that holds one point's meshes at a time).
    #[must_use]
    pub fn points(what: &'static str, solves: usize, cost: PointCost) -> Self {
        #[allow(clippy::cast_precision_loss)]
        let seconds = solves as f64 * cost.seconds;
        Self { what, solves, seconds, bytes: cost.bytes, eigen: None }
    }

    /// `tiltpad modes`: `count` modes of each distinct flexible pad solid of `case`, and of the extra solids
    /// of `extra_unknowns` (the convergence table's meshes); no bearing solve.
    #[must_use]
    pub fn pad_modes(case: &Case, count: usize, extra_unknowns: &[usize]) -> Self {
        let mut flexible = case.clone();
        flexible.physics.pad_modes = count.max(1);
        let solids = flexible_solids(&flexible);
        let seconds = solids.iter().map(|s| modes_seconds(s.unknowns(), count)).sum::<f64>()
            + extra_unknowns.iter().map(|&u| modes_seconds(u, count)).sum::<f64>();
        #[allow(clippy::cast_precision_loss)]
        let bytes = solids.iter().map(|s| s.nodes).chain(extra_unknowns.iter().map(|u| u / 3)).max().unwrap_or(0)
            as f64
            * BYTES_PER_NODE;
        Self { what: "modes", solves: 0, seconds, bytes, eigen: None }
    }

    /// The rotor analysis of `rotor` over `speeds` speeds: each speed solves every bearing given by a case
    /// and the system's damped eigen-problem; the onset bisection adds up to `extra_speeds` more of both;
    /// memory is the shaft's and the eigen-solution's dense matrices plus the bearings' meshes (all held at
    /// once).
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
        #[allow(clippy::cast_precision_loss)]
        let n = 4.0 * (rotor.elements.len() as f64 + 1.0);
        let bytes = 224.0 * n * n + costs.iter().map(|c| c.bytes).sum::<f64>();
        let all = speeds.saturating_add(extra_speeds);
        let states = 2 * rotor_coordinates(rotor);
        let reduced = 4 * (rotor.elements.len() + 1) > rotor_coordinates(rotor) - appended_coordinates(rotor);
        let shaft_unit = if reduced { n } else { 0.5 * n };
        #[allow(clippy::cast_precision_loss)]
        let eigen = EigenWork {
            solutions: all,
            states,
            seconds_each: EIGEN_SECONDS_PER_UNIT * (states as f64).powi(3),
            shaft_seconds: SHAFT_SECONDS_PER_UNIT * shaft_unit.powi(3),
            undamped: false,
        };
        #[allow(clippy::cast_precision_loss)]
        let seconds = all as f64 * per_speed + eigen.seconds();
        Self { what, solves: all.saturating_mul(costs.len()), seconds, bytes, eigen: Some(eigen) }
    }

    /// `rotor --critical-map` over `speeds` speeds: every bearing given by a case solved once per speed (its
    /// stiffness curve), the shaft model built once, then `points` undamped eigen-solutions of one plane of
    /// the shaft (see the module).
    #[must_use]
    pub fn critical_map(rotor: &Rotor, speeds: usize, points: usize) -> Self {
        let bearings = Self::rotor("rotor --critical-map", rotor, speeds, 0);
        let Some(damped) = bearings.eigen else { return bearings };
        let coordinates = 2 * (rotor.elements.len() + 1);
        #[allow(clippy::cast_precision_loss)]
        let eigen = EigenWork {
            solutions: points,
            states: coordinates,
            seconds_each: UNDAMPED_SECONDS_PER_UNIT * (coordinates as f64).powi(3),
            shaft_seconds: damped.shaft_seconds,
            undamped: true,
        };
        let seconds = bearings.seconds - damped.seconds() + eigen.seconds();
        Self { seconds, eigen: Some(eigen), ..bearings }
    }

    /// `control` over `speeds` speeds: the rotor's bearing solves at every speed and at `probes` bisection
    /// probes, and `per_speed` damped eigen-solutions at each speed (open and closed loop, the Nyquist tests,
    /// the swept gains) plus `extra` more (one per probe, the root locus's gains) — the rotor's estimate with
    /// the eigen-solutions the analysis makes.
    #[must_use]
    pub fn control(rotor: &Rotor, speeds: usize, probes: usize, per_speed: usize, extra: usize) -> Self {
        let mut e = Self::rotor("control", rotor, speeds, probes);
        if let Some(eigen) = e.eigen.as_mut() {
            let before = eigen.seconds();
            eigen.solutions = speeds.saturating_mul(per_speed).saturating_add(extra);
            e.seconds += eigen.seconds() - before;
        }
        e
    }

    /// What raises or lowers this estimate's work, for the refusal: the rotor's eigen-solutions when they are
    /// most of it, the bearing solves otherwise.
    #[must_use]
    pub fn settings(&self) -> &'static str {
        match self.eigen {
            Some(e) if e.undamped && e.seconds() >= 0.5 * self.seconds => {
                "fewer elements per section (rotor.section[].elements): the map solves one plane of the whole \
                 shaft whatever rotor.shaft_modes"
            }
            Some(e) if e.seconds() >= 0.5 * self.seconds => {
                "fewer speeds (--speeds FROM:TO:N), a reduced shaft (--shaft-modes M or rotor.shaft_modes; 0 is \
                 the full shaft, the default 8 keeps a few dozen coordinates) or fewer elements per section \
                 (rotor.section[].elements)"
            }
            _ => "narrow the range or lower the fidelity (mesh.fidelity)",
        }
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
    if seconds < 1.0 {
        format!("{:.0} ms", (seconds * 1000.0).max(1.0))
    } else if seconds < 60.0 {
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
        write!(f, "{}: {} bearing solves", self.what, self.solves)?;
        if let Some(e) = &self.eigen {
            let (kind, size) = if e.undamped { ("undamped ", "shaft coordinates") } else { ("", "states") };
            write!(
                f,
                " and {} {kind}eigen-solutions of {} {size} ({} each)",
                e.solutions,
                e.states,
                duration_text(e.seconds_each)
            )?;
        }
        write!(
            f,
            ", about {} at the reference rate (docs/PERFORMANCE.md), peak memory about {}",
            duration_text(self.seconds),
            bytes_text(self.bytes)
        )
    }
}

/// A command refused before its first solve.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum TooMuchWork {
    #[error(
        "{estimate}: more than the bound of {max_hours} h; {}, or raise the bound with --max-hours {}",
        estimate.settings(),
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
    use crate::model::rotor::CoefficientModel;

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

    fn rotor(name: &str, set: impl Fn(&mut crate::model::rotor::RotorFile)) -> Rotor {
        let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/cases/rotors/");
        let text = std::fs::read_to_string(format!("{dir}{name}")).unwrap();
        let mut file = crate::model::rotor::parse_rotor_file(&text).unwrap();
        set(&mut file);
        file.resolve(&|n: &str| std::fs::read_to_string(format!("{dir}{n}")).map_err(|e| e.to_string())).unwrap()
    }

    #[test]
    fn the_rotor_counts_the_coordinates_its_eigen_problem_will_have() {
        // The compressor rotor's system sizes as the analysis reports them (docs/PERFORMANCE.md, rotor table):
        // 224 shaft coordinates + 10 pad tilts in full; 8 boundary coordinates + 2 modes per plane each kept.
        for (modes, dofs) in [(0, 234), (2, 22), (4, 26), (8, 34), (16, 50), (32, 82)] {
            let r = rotor("compressor-rotor.toml", |f| f.rotor.shaft_modes = modes);
            assert_eq!(rotor_coordinates(&r), dofs, "shaft_modes = {modes}");
        }
        // reduced bearing coefficients append nothing
        let r = rotor("compressor-rotor.toml", |f| f.rotor.coefficients = CoefficientModel::Reduced);
        assert_eq!(rotor_coordinates(&r), 24);
    }

    #[test]
    fn a_full_shaft_s_eigen_solutions_are_counted_and_refused_naming_the_shaft_settings() {
        // The compressor rotor with its sections' elements ×4 (220 elements, the full shaft: 884 + 10
        // coordinates, 1788 states), 4 speeds: measured 15.2 s of CPU time (release, 2026-11-26), nearly all of
        // it the four eigen-solutions (each bearing solve takes ~0.05 s); 2 speeds: 7.5 s. The model:
        // 7e-10 · 1788³ = 4.0 s per speed. (Its sections ×7 with the impeller section split, 385 elements,
        // 3108 states: 42.6 s for 2 speeds measured, 42.0 s by the model.)
        let r = rotor("compressor-rotor.toml", |f| {
            f.rotor.shaft_modes = 0;
            for s in &mut f.rotor.section {
                s.elements *= 4;
            }
        });
        for (speeds, measured) in [(2, 7.46), (4, 15.19)] {
            let e = Estimate::rotor("rotor", &r, speeds, 0);
            let eigen = e.eigen.unwrap();
            assert_eq!((eigen.solutions, eigen.states), (speeds, 1788));
            // the constant is fitted over both sizes (6.8e-10 here, 7.1e-10 at 3108 states): 15 %
            assert!((e.seconds / measured - 1.0).abs() < 0.15, "{} s against {measured} s measured", e.seconds);
        }
        // The same shaft reduced (8 modes per plane, 68 states): the reduction is most of the work, measured
        // 1.25 s of CPU time for 2 speeds; the model gives 1.3e-9 · 884³ = 0.90 s for it and 0.17 s for the
        // bearings.
        let mut reduced = r.clone();
        reduced.shaft_modes = 8;
        let e = Estimate::rotor("rotor", &reduced, 2, 0);
        assert_eq!(e.eigen.unwrap().states, 68);
        assert!((e.seconds / 1.25 - 1.0).abs() < 0.2, "{} s against 1.25 s measured", e.seconds);
        // 5000 speeds (and the bisection's probes) of it: about 5.6 h, refused, naming the settings that
        // shrink it.
        let err = Estimate::rotor("rotor", &r, 5000, 12).check(DEFAULT_MAX_HOURS).unwrap_err().to_string();
        assert!(err.contains("eigen-solutions of 1788 states") && err.contains("--shaft-modes"), "{err}");
        assert!(err.contains("rotor.section[].elements") && err.contains("--speeds"), "{err}");
        // The reduced shaft (8 modes per plane): 34 coordinates, the eigen-solutions negligible, the bearings
        // named instead.
        let reduced = rotor("compressor-rotor.toml", |_| ());
        let e = Estimate::rotor("rotor", &reduced, 1000, 12);
        assert!(e.eigen.unwrap().seconds() < 0.01 * e.seconds, "{e}");
        assert!(e.settings().contains("mesh.fidelity"), "{e}");
    }

    #[test]
    fn flexible_pads_add_their_modal_solution_and_coordinates() {
        // Measured CPU times (release, 2026-11-26): the rigid compressor bearing 0.05 s, its flexible variant
        // (one bending mode per pad; five identical pads share one modal solution of 14 337 unknowns) 0.27 s;
        // `tiltpad modes` on it: 0.17 s for one mode, 0.29 s for three, 4.5 s with the convergence table.
        let text =
            std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/cases/compressor-bearing-flexible.toml"))
                .unwrap();
        let flexible = crate::model::load_case(&text, &[]).unwrap().1;
        let solids = flexible_solids(&flexible);
        assert_eq!((solids.len(), solids[0].pads, solids[0].unknowns()), (1, 5, 14_820));
        let within = |estimate: f64, measured: f64| (estimate / measured - 1.0).abs() < 0.2;
        let cost = point_cost(&flexible);
        assert!(within(cost.seconds, 0.27), "{} s against 0.27 s", cost.seconds);
        for (count, measured) in [(1, 0.17), (3, 0.29)] {
            let e = Estimate::pad_modes(&flexible, count, &[]);
            assert!(within(e.seconds, measured), "{count} modes: {} s against {measured} s", e.seconds);
        }
        // A pad with another thickness has a solid of its own.
        let mut two = flexible.clone();
        two.bearing.pads[0].thickness_m *= 1.5;
        assert_eq!(flexible_solids(&two).len(), 2);
        // Rigid pads: no modal term.
        let rigid = crate::model::load_case(&text, &["physics.pad_modes=0".to_string()]).unwrap().1;
        assert!(flexible_solids(&rigid).is_empty());
        assert!((point_cost(&rigid).seconds - 0.0432).abs() < 1e-12);
    }

    #[test]
    fn memory_beyond_the_cap_is_refused_with_the_keys_that_shrink_it() {
        let mut cost = point_cost(&case(&[]));
        cost.bytes = 9.0 * 1024.0 * 1024.0 * 1024.0;
        let err = Estimate::points("solve", 1, cost).check(DEFAULT_MAX_HOURS).unwrap_err().to_string();
        assert!(err.contains("9.0 GB") && err.contains("mesh.max_nodes"), "{err}");
    }
}
