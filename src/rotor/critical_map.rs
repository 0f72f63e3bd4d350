//! Undamped critical-speed map: the rotor's undamped natural frequencies against a support stiffness `k`
//! put at every bearing node, and the bearings' own stiffness against speed drawn over it (where a
//! bearing's curve crosses a mode's line is that mode's undamped critical speed on those bearings).
//!
//! ```text
//! (K_shaft + k Σ_b e_b e_bᵀ) φ = ω² M φ      (one bending plane, x–a; no damping, no gyroscopics)
//! ```
//! `e_b` picks the lateral displacement of bearing node `b`. Returns ω [rad/s] of the first modes for each
//! `k` [N/m] of a logarithmic sweep. Limits: `k → 0` gives the free–free rotor (two rigid modes at 0, then
//! the free–free flexible modes), `k → ∞` the rotor pinned at its bearings. Synchronous critical speeds are
//! read where `ω` equals the spin speed, so frequency and speed share the axis.

use nalgebra::DMatrix;
use serde::Serialize;

use super::assembly::{shaft_index, undamped_frequencies, NodeDof, ShaftModel};
use super::bearings::BearingSet;
use super::coupling::BearingCoefficients;
use super::error::RotorError;
use crate::model::rotor::Rotor;

/// Support stiffnesses of the command line's map (`tiltpad rotor --critical-map`; logarithmic), which its
/// work estimate counts.
pub const MAP_POINTS: usize = 81;

/// The map: one row of frequencies per support stiffness.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CriticalMap {
    pub stiffness_n_per_m: Vec<f64>,
    /// `frequencies_rad_s[i][m]`: mode m at stiffness i.
    pub frequencies_rad_s: Vec<Vec<f64>>,
}

/// The map over `n` stiffnesses from `k_min` to `k_max` (logarithmic), the first `modes` modes.
///
/// # Errors
/// [`RotorError::StiffnessRange`] for a bad range; [`RotorError::SingularMass`].
pub fn critical_map(
    shaft: &ShaftModel,
    bearing_nodes: &[usize],
    k_min: f64,
    k_max: f64,
    n: usize,
    modes: usize,
) -> Result<CriticalMap, RotorError> {
    let mut sweep = StiffnessSweep::new(shaft, bearing_nodes, [k_min, k_max], n, modes)?;
    while sweep.step()? {}
    Ok(sweep.map)
}

/// [`critical_map`] one eigen-solution at a time: the caller may show progress or stop between them and
/// keep the stiffnesses done (the map then ends below `k_max`).
pub struct StiffnessSweep {
    /// One bending plane's stiffness and mass (x–a coordinates of every node).
    k0: DMatrix<f64>,
    m: DMatrix<f64>,
    /// Where the swept support adds its stiffness (the bearing nodes' x).
    slots: Vec<usize>,
    range: [f64; 2],
    n: usize,
    modes: usize,
    /// The stiffnesses done so far.
    map: CriticalMap,
}

impl StiffnessSweep {
    /// The sweep of `n` stiffnesses over `range` = `[k_min, k_max]` (see [`critical_map`]).
    ///
    /// # Errors
    /// [`RotorError::StiffnessRange`] for a bad range.
    pub fn new(
        shaft: &ShaftModel,
        bearing_nodes: &[usize],
        range: [f64; 2],
        n: usize,
        modes: usize,
    ) -> Result<Self, RotorError> {
        let [k_min, k_max] = range;
        if !(k_min > 0.0 && k_max > k_min && k_max.is_finite() && n >= 2) {
            return Err(RotorError::StiffnessRange { k_min, k_max, n });
        }
        let idx: Vec<usize> = (0..shaft.n_nodes)
            .flat_map(|node| [shaft_index(node, NodeDof::X), shaft_index(node, NodeDof::A)])
            .collect();
        let sub = |a: &DMatrix<f64>| DMatrix::from_fn(idx.len(), idx.len(), |i, j| a[(idx[i], idx[j])]);
        let (k0, m) = (sub(&shaft.stiffness), sub(&shaft.mass));
        let slots: Vec<usize> =
            bearing_nodes.iter().filter_map(|&b| idx.iter().position(|&i| i == shaft_index(b, NodeDof::X))).collect();
        let map = CriticalMap { stiffness_n_per_m: Vec::with_capacity(n), frequencies_rad_s: Vec::with_capacity(n) };
        Ok(Self { k0, m, slots, range, n, modes, map })
    }

    /// Stiffnesses done.
    #[must_use]
    pub fn done(&self) -> usize {
        self.map.stiffness_n_per_m.len()
    }

    /// Stiffnesses of the whole sweep.
    #[must_use]
    pub fn len(&self) -> usize {
        self.n
    }

    /// Whether the sweep has no stiffness (never: it has at least two).
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.n == 0
    }

    /// The next stiffness's eigen-solution; `false` once every stiffness is done.
    ///
    /// # Errors
    /// [`RotorError::SingularMass`].
    pub fn step(&mut self) -> Result<bool, RotorError> {
        let i = self.done();
        if i >= self.n {
            return Ok(false);
        }
        let [k_min, k_max] = self.range;
        #[allow(clippy::cast_precision_loss)]
        let k = k_min * (k_max / k_min).powf(i as f64 / (self.n - 1) as f64);
        let mut kk = self.k0.clone();
        for &s in &self.slots {
            kk[(s, s)] += k;
        }
        let mut w = undamped_frequencies(&kk, &self.m)?;
        w.truncate(self.modes);
        self.map.stiffness_n_per_m.push(k);
        self.map.frequencies_rad_s.push(w);
        Ok(i + 1 < self.n)
    }

    /// The map of the stiffnesses done.
    #[must_use]
    pub fn finish(self) -> CriticalMap {
        self.map
    }
}

/// Where a bearing's direct stiffness curve crosses a mode's line of the map: an undamped critical speed on
/// that bearing.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Crossing {
    /// Mode of the map (0 = lowest).
    pub mode: usize,
    /// Bearing position (index in the rotor's bearings).
    pub bearing: usize,
    /// Which direct stiffness: 0 = k_xx, 1 = k_yy.
    pub direction: usize,
    pub speed_rad_s: f64,
    pub stiffness_n_per_m: f64,
}

/// Mode `mode`'s frequency at support stiffness `k`, interpolated linearly in log k (`None` outside the map).
#[must_use]
pub fn frequency_at(map: &CriticalMap, mode: usize, k: f64) -> Option<f64> {
    let ks = &map.stiffness_n_per_m;
    // a map stopped before its second stiffness has no line to read
    if ks.len() < 2 || !(k >= ks[0] && k <= ks[ks.len() - 1]) {
        return None;
    }
    let i = ks.partition_point(|&x| x <= k).clamp(1, ks.len() - 1);
    let t = (k.ln() - ks[i - 1].ln()) / (ks[i].ln() - ks[i - 1].ln());
    let (a, b) = (map.frequencies_rad_s[i - 1].get(mode)?, map.frequencies_rad_s[i].get(mode)?);
    Some(a + t * (b - a))
}

/// The crossings of every bearing curve (k_xx and k_yy) with every mode line: where `ω_m(k(Ω)) = Ω` between
/// two speeds of the curve (linear interpolation of the difference).
#[must_use]
pub fn crossings(map: &CriticalMap, curves: &[StiffnessCurve]) -> Vec<Crossing> {
    let modes = map.frequencies_rad_s.first().map_or(0, Vec::len);
    let mut out = Vec::new();
    for (bearing, curve) in curves.iter().enumerate() {
        for direction in 0..2 {
            let k = |p: &(f64, f64, f64)| if direction == 0 { p.1 } else { p.2 };
            for mode in 0..modes {
                for w in curve.windows(2) {
                    let (Some(f0), Some(f1)) = (frequency_at(map, mode, k(&w[0])), frequency_at(map, mode, k(&w[1])))
                    else {
                        continue;
                    };
                    let (g0, g1) = (f0 - w[0].0, f1 - w[1].0);
                    if g0 * g1 <= 0.0 && g0 != g1 {
                        let t = g0 / (g0 - g1);
                        out.push(Crossing {
                            mode,
                            bearing,
                            direction,
                            speed_rad_s: w[0].0 + t * (w[1].0 - w[0].0),
                            stiffness_n_per_m: k(&w[0]) + t * (k(&w[1]) - k(&w[0])),
                        });
                    }
                }
            }
        }
    }
    out.sort_by(|a, b| a.speed_rad_s.total_cmp(&b.speed_rad_s));
    out
}

/// A bearing position's synchronously reduced direct stiffnesses against speed: `(Ω [rad/s], k_xx, k_yy)`.
pub type StiffnessCurve = Vec<(f64, f64, f64)>;

/// The direct stiffnesses of every bearing position at `speeds` [rad/s] (reduced at ω = Ω; solved or taken
/// from the set's cache).
///
/// # Errors
/// A bearing solve that fails.
pub fn bearing_stiffness_curves(bearings: &mut BearingSet, speeds: &[f64]) -> Result<Vec<StiffnessCurve>, RotorError> {
    let mut curves: Vec<StiffnessCurve> = vec![Vec::new(); bearings.nodes.len()];
    for &w in speeds {
        add_speed(&mut curves, bearings, w)?;
    }
    Ok(curves)
}

/// Every bearing's direct stiffnesses at `w` [rad/s], added to its curve.
fn add_speed(curves: &mut [StiffnessCurve], bearings: &mut BearingSet, w: f64) -> Result<(), RotorError> {
    for (curve, c) in curves.iter_mut().zip(bearings.at(w)?) {
        if let BearingCoefficients::Reduced { k, .. } = c.reduced(w) {
            curve.push((w, k[0][0], k[1][1]));
        }
    }
    Ok(())
}

/// The map with the bearings' curves over it and their crossings: what `tiltpad rotor --critical-map` writes
/// and the rotor view draws.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CriticalSpeedMap {
    pub map: CriticalMap,
    /// Per bearing position that is a case or numbers: `(Ω [rad/s], k_xx, k_yy)` over the speeds.
    pub bearing_curves: Vec<StiffnessCurve>,
    pub crossings: Vec<Crossing>,
}

/// Stiffness range of the map: two decades either side of the bearings' direct stiffnesses (1e5–1e10 N/m
/// without bearings).
fn map_range(curves: &[StiffnessCurve]) -> (f64, f64) {
    let ks = curves.iter().flatten().flat_map(|p| [p.1, p.2]).filter(|k| *k > 0.0 && k.is_finite());
    let (lo, hi) = ks.fold((f64::INFINITY, 0.0_f64), |(lo, hi), k| (lo.min(k), hi.max(k)));
    if hi > 0.0 {
        (lo * 1e-2, hi * 1e2)
    } else {
        (1e5, 1e10)
    }
}

/// The undamped critical-speed map of `rotor` (`points` stiffnesses, the first `modes` modes; the swept
/// support at the bearings with direct stiffness), the bearings' stiffness curves at `speeds` [rad/s] and
/// their crossings.
///
/// # Errors
/// Assembly, bearing solves, the map's eigen-solutions.
pub fn critical_speed_map(
    rotor: &Rotor,
    speeds: &[f64],
    points: usize,
    modes: usize,
) -> Result<CriticalSpeedMap, RotorError> {
    let mut run = CriticalMapRun::new(rotor, speeds.to_vec(), points, modes);
    while run.step()? != MapStep::Done {}
    Ok(run.finish())
}

/// The map for bearing curves already known (one per bearing position of `rotor`, e.g. an analysis'
/// [`super::analysis::AnalysisResult::bearing_stiffness`]).
///
/// # Errors
/// Assembly and the map's eigen-solutions.
pub fn map_over_curves(
    rotor: &Rotor,
    bearing_curves: Vec<StiffnessCurve>,
    points: usize,
    modes: usize,
) -> Result<CriticalSpeedMap, RotorError> {
    let mut sweep = sweep_over(rotor, &bearing_curves, points, modes)?;
    while sweep.step()? {}
    let map = sweep.finish();
    let crossings = crossings(&map, &bearing_curves);
    Ok(CriticalSpeedMap { map, bearing_curves, crossings })
}

/// The stiffness sweep over the bearings' curves: the range two decades either side of them, the swept
/// support where a bearing carries direct stiffness (not at pure cross-coupling, e.g. seals or aerodynamic
/// excitation given by numbers with zero direct terms).
fn sweep_over(
    rotor: &Rotor,
    bearing_curves: &[StiffnessCurve],
    points: usize,
    modes: usize,
) -> Result<StiffnessSweep, RotorError> {
    let shaft = ShaftModel::new(rotor)?;
    let (k_min, k_max) = map_range(bearing_curves);
    let nodes: Vec<usize> = rotor
        .bearings
        .iter()
        .zip(bearing_curves)
        .filter(|(_, c)| c.iter().any(|p| p.1 > 0.0 || p.2 > 0.0))
        .map(|(b, _)| b.node)
        .collect();
    StiffnessSweep::new(&shaft, &nodes, [k_min, k_max], points, modes)
}

/// What a step of a [`CriticalMapRun`] did.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MapStep {
    /// The bearings at one more speed: `done` of `of`.
    Speed { done: usize, of: usize },
    /// The shaft model built (`done` = 0) or one more stiffness's eigen-solution: `done` of `of`.
    Stiffness { done: usize, of: usize },
    /// Nothing left.
    Done,
}

/// [`critical_speed_map`] one step at a time (a speed's bearing solves, the shaft model, one eigen-solution
/// of the map), so that a caller can show progress and stop between steps, keeping what is done: the curves
/// of the speeds solved and the map's stiffnesses so far ([`Self::finish`]).
pub struct CriticalMapRun<'r> {
    rotor: &'r Rotor,
    bearings: BearingSet,
    speeds: Vec<f64>,
    curves: Vec<StiffnessCurve>,
    speeds_done: usize,
    points: usize,
    modes: usize,
    sweep: Option<StiffnessSweep>,
}

impl<'r> CriticalMapRun<'r> {
    /// The run over `speeds` [rad/s], `points` stiffnesses and the first `modes` modes.
    #[must_use]
    pub fn new(rotor: &'r Rotor, speeds: Vec<f64>, points: usize, modes: usize) -> Self {
        let bearings = BearingSet::new(rotor);
        let curves = vec![Vec::new(); bearings.nodes.len()];
        Self { rotor, bearings, speeds, curves, speeds_done: 0, points, modes, sweep: None }
    }

    /// The next step (see [`MapStep`]).
    ///
    /// # Errors
    /// A bearing solve, the shaft's assembly, an eigen-solution.
    pub fn step(&mut self) -> Result<MapStep, RotorError> {
        if let Some(&w) = self.speeds.get(self.speeds_done) {
            add_speed(&mut self.curves, &mut self.bearings, w)?;
            self.speeds_done += 1;
            return Ok(MapStep::Speed { done: self.speeds_done, of: self.speeds.len() });
        }
        match &mut self.sweep {
            None => {
                let sweep = sweep_over(self.rotor, &self.curves, self.points, self.modes)?;
                self.sweep = Some(sweep);
                Ok(MapStep::Stiffness { done: 0, of: self.points })
            }
            Some(sweep) => {
                if sweep.done() == sweep.len() {
                    return Ok(MapStep::Done);
                }
                sweep.step()?;
                Ok(MapStep::Stiffness { done: sweep.done(), of: sweep.len() })
            }
        }
    }

    /// Speeds whose bearings are solved.
    #[must_use]
    pub fn speeds_done(&self) -> usize {
        self.speeds_done
    }

    /// The map's stiffnesses done.
    #[must_use]
    pub fn stiffnesses_done(&self) -> usize {
        self.sweep.as_ref().map_or(0, StiffnessSweep::done)
    }

    /// What is done: the curves of the speeds solved, the map's stiffnesses so far (none when stopped before
    /// the map) and the crossings within them.
    #[must_use]
    pub fn finish(self) -> CriticalSpeedMap {
        let map = self.sweep.map_or(
            CriticalMap { stiffness_n_per_m: Vec::new(), frequencies_rad_s: Vec::new() },
            StiffnessSweep::finish,
        );
        let crossings = crossings(&map, &self.curves);
        CriticalSpeedMap { map, bearing_curves: self.curves, crossings }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rotor::element::BeamTheory;
    use std::f64::consts::PI;

    fn beam(n: usize) -> Rotor {
        crate::rotor::closed_form::uniform(1.0, 0.05, n, 7800.0, 2e11, BeamTheory::EulerBernoulli)
    }

    #[test]
    fn soft_supports_give_the_rigid_bounce_and_stiff_ones_the_pinned_beam() {
        let rotor = beam(20);
        let shaft = ShaftModel::new(&rotor).unwrap();
        let map = critical_map(&shaft, &[0, 20], 1e2, 1e13, 23, 3).unwrap();
        let (m, ei, rho_a) = (rotor.mass(), 2e11 * PI * 0.05f64.powi(4) / 64.0, 7800.0 * PI * 0.05f64.powi(2) / 4.0);
        // soft: rigid bounce √(2k/m) and pitch √(6k/m) of a uniform bar supported at its ends, up to the shaft's
        // own sag between the supports relative to the springs' deflection, 10 k L³ / (384 EI) (4e-5 here)
        let (k, w) = (map.stiffness_n_per_m[0], &map.frequencies_rad_s[0]);
        let bounce = (2.0 * k / m).sqrt();
        let pitch = (6.0 * k / m).sqrt();
        eprintln!("bounce {:.2e}, pitch {:.2e}", w[0] / bounce - 1.0, w[1] / pitch - 1.0);
        let sag = 10.0 * k / (384.0 * ei);
        assert!((w[0] / bounce - 1.0).abs() < sag, "{} vs {bounce}", w[0]);
        assert!((w[1] / pitch - 1.0).abs() < sag, "{} vs {pitch}", w[1]);
        // stiff: pinned–pinned Euler–Bernoulli, (π/L)² √(EI/ρA)
        let pinned = PI * PI * (ei / rho_a).sqrt();
        let w = &map.frequencies_rad_s[22];
        eprintln!("pinned {:.2e}", w[0] / pinned - 1.0);
        assert!((w[0] / pinned - 1.0).abs() < 1e-5, "{} vs {pinned}", w[0]);
        // each mode rises monotonically with the support stiffness
        for i in 1..map.stiffness_n_per_m.len() {
            for mode in 0..3 {
                assert!(map.frequencies_rad_s[i][mode] >= map.frequencies_rad_s[i - 1][mode] * (1.0 - 1e-12));
            }
        }
    }

    #[test]
    fn a_constant_bearing_crosses_each_mode_where_the_map_gives_its_frequency() {
        let rotor = beam(10);
        let shaft = ShaftModel::new(&rotor).unwrap();
        let map = critical_map(&shaft, &[0, 10], 1e5, 1e10, 41, 3).unwrap();
        let kb = 3e7;
        let speeds: Vec<f64> = (0..400).map(|i| 10.0 * f64::from(i)).collect();
        let curve: StiffnessCurve = speeds.iter().map(|&w| (w, kb, 2.0 * kb)).collect();
        let found = crossings(&map, &[curve]);
        // the exact critical speeds on that stiffness: the map's own eigen-solution at k = kb
        let exact = critical_map(&shaft, &[0, 10], kb, 2.0 * kb, 2, 3).unwrap().frequencies_rad_s;
        for c in &found {
            let truth = exact[c.direction][c.mode];
            eprintln!("mode {} dir {}: {} vs {truth}", c.mode, c.direction, c.speed_rad_s);
            // the map interpolates linearly in log k between points 0.125 decades apart: measured ≤ 6.8e-4
            assert!((c.speed_rad_s / truth - 1.0).abs() < 1e-3, "{} vs {truth}", c.speed_rad_s);
        }
        let below: usize = exact.iter().map(|w| w.iter().filter(|&&w| w < 3990.0).count()).sum();
        assert_eq!(found.len(), below);
    }

    #[test]
    fn a_sweep_stopped_early_keeps_the_stiffnesses_done_and_reads_no_line_before_two() {
        let rotor = beam(10);
        let shaft = ShaftModel::new(&rotor).unwrap();
        let whole = critical_map(&shaft, &[0, 10], 1e5, 1e10, 21, 3).unwrap();
        let mut sweep = StiffnessSweep::new(&shaft, &[0, 10], [1e5, 1e10], 21, 3).unwrap();
        assert!(sweep.step().unwrap());
        // one stiffness: no line to interpolate on, and no crossing
        let one = CriticalMap {
            stiffness_n_per_m: whole.stiffness_n_per_m[..1].to_vec(),
            frequencies_rad_s: whole.frequencies_rad_s[..1].to_vec(),
        };
        assert_eq!(frequency_at(&one, 0, 1e5), None);
        let flat: StiffnessCurve = vec![(0.0, 1e5, 1e5), (1e4, 1e5, 1e5)];
        assert!(crossings(&one, &[flat]).is_empty());
        for _ in 0..6 {
            assert!(sweep.step().unwrap());
        }
        assert_eq!((sweep.done(), sweep.len()), (7, 21));
        let part = sweep.finish();
        // the same stiffnesses and frequencies as the whole map's first seven
        assert_eq!(part.stiffness_n_per_m, whole.stiffness_n_per_m[..7]);
        assert_eq!(part.frequencies_rad_s, whole.frequencies_rad_s[..7]);
    }

    #[test]
    fn a_bad_range_is_refused() {
        let shaft = ShaftModel::new(&beam(4)).unwrap();
        assert!(matches!(critical_map(&shaft, &[0, 4], 1e6, 1e5, 10, 2), Err(RotorError::StiffnessRange { .. })));
    }
}
