//! The convergence map: does the static equilibrium converge for every load a bearing can carry?
//!
//! For a bearing, the load direction is swept around the circle and its magnitude over three decades of
//! Sommerfeld number (`S = µ N L D (R/Cb)² / W`, with the case's film viscosity and assembled clearance),
//! and every point is solved from a cold start. Each point is classified:
//!
//! - **converged**: the solve returned, and its balances check (force residual within the solver's
//!   tolerance, pad residuals within theirs, the film's discrete mass balance to round-off);
//! - **physical**: the solve said why the load cannot be carried — touchdown, or no stiffness along the
//!   load (tilting-pad forces pass through the pivots);
//! - **failure**: anything else (not converged, a budget, a film failure, a converged state whose balances
//!   do not check). The target is zero.
//!
//! The bearings are the shipped cases and a generated family ([`generated_family`]): 2–8 pads, preload
//! −0.3 … 0.8, pivot offset 0.5 … 0.7, pivots on and between the 5° grid of load directions. No I/O here:
//! the caller passes case texts (`tiltpad convergence-map` reads `cases/`, a test runs a subset).

use std::ops::ControlFlow;

use serde::Serialize;
use web_time::Instant;

use crate::bearing::{EquilibriumParams, NoCancel, Request, Solution, SolveError, Stages, Start};
use crate::model::{load_case, Case, CaseError, LoadSpec};

/// A bearing of the map: a case text and overrides.
#[derive(Debug, Clone, PartialEq)]
pub struct MapBearing {
    pub name: String,
    pub text: String,
    pub set: Vec<String>,
}

/// The points of the map.
#[derive(Debug, Clone, PartialEq)]
pub struct MapSpec {
    /// Step of the load direction around the circle [deg].
    pub direction_step_deg: f64,
    /// Sommerfeld numbers (three decades: 10 … 0.01).
    pub sommerfeld: Vec<f64>,
}

impl MapSpec {
    /// The full map: every 5°, S = 10, 1, 0.1, 0.01.
    #[must_use]
    pub fn full() -> Self {
        Self { direction_step_deg: 5.0, sommerfeld: vec![10.0, 1.0, 0.1, 0.01] }
    }

    /// Load directions [deg].
    #[must_use]
    pub fn directions_deg(&self) -> Vec<f64> {
        #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
        let n = (360.0 / self.direction_step_deg).round() as usize;
        #[allow(clippy::cast_precision_loss)]
        (0..n).map(|i| i as f64 * self.direction_step_deg).collect()
    }
}

/// How a point ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Class {
    Converged,
    Touchdown,
    NoStiffness,
    /// The force law jumps across the load (a pad with no loaded state carrying less).
    ForceGap,
    Failure,
}

impl Class {
    /// Touchdown and missing stiffness are what the physics says, not failures of the solver.
    #[must_use]
    pub fn is_physical(self) -> bool {
        matches!(self, Self::Touchdown | Self::NoStiffness | Self::ForceGap)
    }
}

/// One solved point.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MapPoint {
    pub bearing: String,
    pub direction_deg: f64,
    pub sommerfeld: f64,
    pub load_n: f64,
    pub class: Class,
    /// The error, or what did not check.
    pub detail: String,
    pub film_solves: usize,
    pub seconds: f64,
}

/// Discrete mass balance a converged film must close to (it closes to round-off).
const MASS_BALANCE_TOL: f64 = 1e-9;

/// Classifies a solve (a converged one only if its balances check).
#[must_use]
pub fn classify(result: &Result<Solution, SolveError>) -> (Class, String) {
    let params = EquilibriumParams::default();
    match result {
        Ok(s) => {
            let r = &s.report;
            if r.residual > params.force_tol {
                (Class::Failure, format!("force residual {:.1e} above tolerance", r.residual))
            } else if r.pad_residual > 1e3 * params.pad_tol {
                (Class::Failure, format!("pad residual {:.1e} above tolerance", r.pad_residual))
            } else if s.flows_m3_per_s.mass_balance_error.abs() > MASS_BALANCE_TOL {
                (Class::Failure, format!("mass balance {:.1e}", s.flows_m3_per_s.mass_balance_error))
            } else {
                (Class::Converged, String::new())
            }
        }
        Err(SolveError::Touchdown { .. }) => {
            (Class::Touchdown, result.as_ref().err().map(ToString::to_string).unwrap_or_default())
        }
        Err(e @ SolveError::NoStiffness { .. }) => (Class::NoStiffness, e.to_string()),
        Err(e @ (SolveError::ForceGap { .. } | SolveError::ForceGap2d { .. })) => (Class::ForceGap, e.to_string()),
        Err(e) => (Class::Failure, e.to_string()),
    }
}

/// The load that gives Sommerfeld number `s` with the case's film viscosity and assembled clearance [N].
#[must_use]
pub fn load_for_sommerfeld(case: &Case, s: f64) -> f64 {
    let b = &case.bearing;
    let (r, l, c) = (b.journal_radius_m, b.length_m, b.assembled_clearance_m);
    let mu = case.lubricant.viscosity.at(case.operating.film_temperature_c);
    mu * case.operating.speed_rev_s() * l * 2.0 * r * (r / c).powi(2) / s
}

/// Solves every point of the map for one bearing, cold from a centred journal each time (the stages build
/// the films, and the pads' thermal systems for THD cases, once).
///
/// # Errors
/// The bearing's case is invalid.
pub fn map_bearing(bearing: &MapBearing, spec: &MapSpec) -> Result<Vec<MapPoint>, CaseError> {
    map_bearing_points(bearing, spec, &|_, _| true, &|_| ControlFlow::Continue(()))
}

/// [`map_bearing`] at the points `keep(direction_deg, sommerfeld)` accepts only (each solved cold, so a
/// subset gives the same answer at each point as the whole map); `each` sees every point as it is solved
/// (a progress display) and may stop the map after it (`Break`: the points so far are returned).
///
/// # Errors
/// The case text does not load.
pub fn map_bearing_points(
    bearing: &MapBearing,
    spec: &MapSpec,
    keep: &(dyn Fn(f64, f64) -> bool + Sync),
    each: &(dyn Fn(&MapPoint) -> ControlFlow<()> + Sync),
) -> Result<Vec<MapPoint>, CaseError> {
    let (_, base) = load_case(&bearing.text, &bearing.set)?;
    let mut stages = Stages::new();
    let mut points = Vec::new();
    for &s in &spec.sommerfeld {
        let load_n = load_for_sommerfeld(&base, s);
        for direction_deg in spec.directions_deg().into_iter().filter(|&d| keep(d, s)) {
            let mut case = base.clone();
            case.operating.load = LoadSpec::Force { magnitude_n: load_n, angle_rad: direction_deg.to_radians() };
            let t0 = Instant::now();
            let result = stages
                .solution(&Request::solution(case).starting(Start::Cold), &NoCancel)
                .map(std::sync::Arc::unwrap_or_clone);
            let seconds = t0.elapsed().as_secs_f64();
            let (class, detail) = classify(&result);
            let film_solves = result
                .as_ref()
                .map_or(0, |s| s.thermal.as_ref().map_or(s.report.film_solves, |t| t.report.film_solves));
            let point = MapPoint {
                bearing: bearing.name.clone(),
                direction_deg,
                sommerfeld: s,
                load_n,
                class,
                detail,
                film_solves,
                seconds,
            };
            let next = each(&point);
            points.push(point);
            if next.is_break() {
                return Ok(points);
            }
        }
    }
    Ok(points)
}

/// The generated family's base: R 50 mm, L 50 mm, Cb 100 µm, 15 mm pads, 0.02 Pa·s, 3000 rpm, isothermal,
/// Reynolds cavitation, preview meshes.
pub const FAMILY_BASE: &str = r#"
title = "convergence-map family"
[bearing]
journal_radius_mm = 50.0
length_mm = 50.0
assembled_clearance_um = 100.0
[bearing.pads]
count = 4
arc_deg = 70.0
pivot_deg = 270.0
offset = 0.5
preload = 0.0
thickness_mm = 15.0
[lubricant]
viscosity_pa_s = 0.02
viscosity_temperature_c = 40.0
viscosity_coefficient_per_k = 0.0
density_kg_per_m3 = 860.0
specific_heat_j_per_kg_k = 2000.0
conductivity_w_per_m_k = 0.13
[operating]
speed_rpm = 3000.0
load_n = 1000.0
supply_temperature_c = 40.0
[mesh]
fidelity = "preview"
[physics]
cavitation = "reynolds"
"#;

/// One member of the generated family: `pads` pads of arc 0.75 × 360°/n (at most 150°), preload,
/// offset, and the first pivot at 270° (load on pad for the downward grid direction) or half a pitch off.
#[must_use]
pub fn family_member(pads: usize, preload: f64, offset: f64, load_on_pad: bool) -> MapBearing {
    #[allow(clippy::cast_precision_loss)]
    let pitch = 360.0 / pads as f64;
    let arc = (0.75 * pitch).min(150.0);
    let first = if load_on_pad { 270.0 } else { 270.0 + 0.5 * pitch };
    let name = format!("{pads} pads, m {preload}, α {offset}, {}", if load_on_pad { "LOP" } else { "LBP" });
    let set = vec![
        format!("bearing.pads.count={pads}"),
        format!("bearing.pads.arc_deg={arc}"),
        format!("bearing.pads.pivot_deg={first}"),
        format!("bearing.pads.preload={preload}"),
        format!("bearing.pads.offset={offset}"),
    ];
    MapBearing { name, text: FAMILY_BASE.to_string(), set }
}

/// The generated family: 2, 3, 4, 5, 6, 8 pads × preload −0.3, 0, 0.4, 0.8 × offset 0.5, 0.6, 0.7 × LOP, LBP.
#[must_use]
pub fn generated_family() -> Vec<MapBearing> {
    let mut v = Vec::new();
    for pads in [2, 3, 4, 5, 6, 8] {
        for preload in [-0.3, 0.0, 0.4, 0.8] {
            for offset in [0.5, 0.6, 0.7] {
                for lop in [true, false] {
                    v.push(family_member(pads, preload, offset, lop));
                }
            }
        }
    }
    v
}

/// Counts per class.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize)]
pub struct Counts {
    pub converged: usize,
    pub touchdown: usize,
    pub no_stiffness: usize,
    pub force_gap: usize,
    pub failure: usize,
}

impl Counts {
    #[must_use]
    pub fn of(points: &[MapPoint]) -> Self {
        let mut c = Self::default();
        for p in points {
            match p.class {
                Class::Converged => c.converged += 1,
                Class::Touchdown => c.touchdown += 1,
                Class::NoStiffness => c.no_stiffness += 1,
                Class::ForceGap => c.force_gap += 1,
                Class::Failure => c.failure += 1,
            }
        }
        c
    }

    #[must_use]
    pub fn total(&self) -> usize {
        self.converged + self.touchdown + self.no_stiffness + self.force_gap + self.failure
    }
}

/// Failures next to a converged point at the same load (one direction step either side): the ones the
/// map counts as unexplained.
#[must_use]
pub fn failures_beside_converged<'a>(points: &'a [MapPoint], spec: &MapSpec) -> Vec<&'a MapPoint> {
    let step = spec.direction_step_deg;
    let neighbours = |p: &MapPoint, q: &MapPoint| {
        let d = (q.direction_deg - p.direction_deg).rem_euclid(360.0);
        q.bearing == p.bearing
            && q.sommerfeld == p.sommerfeld
            && ((d - step).abs() < 1e-9 || (d - (360.0 - step)).abs() < 1e-9)
    };
    points
        .iter()
        .filter(|p| p.class == Class::Failure && points.iter().any(|q| q.class == Class::Converged && neighbours(p, q)))
        .collect()
}
