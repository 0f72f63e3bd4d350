//! Flowlines of the film's mean velocity on a pad (docs/MODEL.md §3a).
//!
//! ## What is integrated
//! The film's mean (across-thickness) velocity is `v̄ = q / h` with the flow rates per unit width
//!
//! ```text
//! q_s = −h³/(12µ) ∂p/∂s + U h / 2        (Poiseuille + Couette, U = Ω R)
//! q_z = −h³/(12µ) ∂p/∂z
//! ```
//!
//! Continuity reads `∂q_s/∂s + ∂q_z/∂z = v_inj` inside an orifice: the injection is a source of flowlines
//! while oil is injected and a sink when the film pressure exceeds the supply (injection off: oil leaves
//! through the hole). The source does not need to be added by hand: the solved pressure field already
//! carries it through `∇p`.
//!
//! ## How
//! Nodal pressure gradients by second-order finite differences on the (graded) grid, `v̄` at the nodes,
//! bilinear interpolation in between, and classical RK4 along the unit direction `v̄/|v̄|` with a step of
//! a fraction of the local cell size (so the trace is resolved where the mesh is refined around orifices).
//! Seeds: evenly across the leading edge (integrated downstream) and on a ring just outside each orifice
//! (downstream from a source; upstream from a sink, then reversed so every line points downstream).
//! A line stops when it leaves the pad, enters the cavitated region (where the full film has ruptured and
//! the mean velocity of the ruptured film is not modelled), reaches a stagnation point, or enters a sink.
//! An orifice open to ambient (no injection) holds its surroundings at p = 0, which the Reynolds
//! condition marks as cavitated: traces drawn towards such a sink end at the rim of that zone.

use crate::bearing::solution::{PadField, Solution};

use super::field::{bilinear, full_rows, full_values, locate};

/// Where a flowline starts.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Seed {
    LeadingEdge,
    /// On a ring around orifice k of the pad.
    Orifice(usize),
}

/// Why a flowline ends.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum End {
    LeftPad,
    Cavitation,
    Stagnation,
    /// Drained into a sink orifice (or, for an upstream trace, came out of a source).
    Orifice,
    MaxLength,
}

/// A polyline in pad coordinates `[s, z]` [m], ordered downstream.
#[derive(Debug, Clone, PartialEq)]
pub struct Flowline {
    pub points: Vec<[f64; 2]>,
    pub seed: Seed,
    pub end: End,
}

/// Seeding and integration settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FlowlineParams {
    /// Seeds across the leading edge.
    pub leading_edge_seeds: usize,
    /// Seeds on the ring around each orifice.
    pub orifice_seeds: usize,
    /// Step as a fraction of the local cell size.
    pub step_fraction: f64,
    pub max_steps: usize,
}

impl Default for FlowlineParams {
    fn default() -> Self {
        Self { leading_edge_seeds: 14, orifice_seeds: 16, step_fraction: 0.25, max_steps: 6000 }
    }
}

/// An orifice in pad coordinates, with the flow into the film through it [m³/s].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OrificeSite {
    pub s_m: f64,
    pub z_m: f64,
    pub radius_m: f64,
    pub flow_m3_per_s: f64,
}

/// The mean-velocity field of one pad on its full (mirrored) grid.
#[derive(Debug, Clone, PartialEq)]
pub struct VelocityField {
    pub s_m: Vec<f64>,
    pub z_m: Vec<f64>,
    /// Mean velocity components at the nodes [m/s], z fastest.
    pub vs: Vec<f64>,
    pub vz: Vec<f64>,
    /// 1 at cavitated nodes, 0 elsewhere (interpolated to find the rupture boundary).
    pub cavitation: Vec<f64>,
    pub surface_speed_m_s: f64,
}

/// Derivative of nodal values `f` along ascending nodes `x` at node `i` (second order on a graded grid,
/// one-sided at the ends).
fn derivative(x: &[f64], f: impl Fn(usize) -> f64, i: usize) -> f64 {
    let n = x.len();
    if n < 2 {
        return 0.0;
    }
    if i == 0 {
        return (f(1) - f(0)) / (x[1] - x[0]);
    }
    if i == n - 1 {
        return (f(n - 1) - f(n - 2)) / (x[n - 1] - x[n - 2]);
    }
    let (hm, hp) = (x[i] - x[i - 1], x[i + 1] - x[i]);
    ((f(i + 1) - f(i)) * hm / hp + (f(i) - f(i - 1)) * hp / hm) / (hm + hp)
}

impl VelocityField {
    /// Mean velocity from a pad's pressure, thickness and viscosity fields at surface speed `U` [m/s].
    #[must_use]
    pub fn new(field: &PadField, surface_speed_m_s: f64) -> Self {
        let rows = full_rows(field);
        let p = full_values(field, &rows, &field.pressure_pa);
        let h = full_values(field, &rows, &field.film_thickness_m);
        let mu = full_values(field, &rows, &field.viscosity_pa_s);
        let cav = full_values(field, &rows, &field.cavitated);
        let s_m = field.s_m.clone();
        let z_m: Vec<f64> = rows.iter().map(|r| r.0).collect();
        let nz = z_m.len();
        let mut vs = Vec::with_capacity(p.len());
        let mut vz = Vec::with_capacity(p.len());
        for i in 0..s_m.len() {
            for j in 0..nz {
                let k = i * nz + j;
                let dpds = derivative(&s_m, |a| p[a * nz + j], i);
                let dpdz = derivative(&z_m, |b| p[i * nz + b], j);
                let a = h[k] * h[k] / (12.0 * mu[k]);
                vs.push(-a * dpds + 0.5 * surface_speed_m_s);
                vz.push(-a * dpdz);
            }
        }
        let cavitation = cav.iter().map(|&c| if c { 1.0 } else { 0.0 }).collect();
        Self { s_m, z_m, vs, vz, cavitation, surface_speed_m_s }
    }

    fn interpolate(&self, values: &[f64], s: f64, z: f64) -> Option<f64> {
        bilinear(&self.s_m, &self.z_m, |k| values[k], s, z)
    }

    /// Mean velocity at (s, z) [m/s], `None` outside the pad.
    #[must_use]
    pub fn velocity(&self, s: f64, z: f64) -> Option<[f64; 2]> {
        Some([self.interpolate(&self.vs, s, z)?, self.interpolate(&self.vz, s, z)?])
    }

    fn cavitated(&self, s: f64, z: f64) -> bool {
        self.interpolate(&self.cavitation, s, z).is_some_and(|c| c >= 0.5)
    }

    /// Smallest side of the cell containing (s, z).
    fn cell_size(&self, s: f64, z: f64) -> f64 {
        let (Some((i, _)), Some((j, _))) = (locate(&self.s_m, s), locate(&self.z_m, z)) else { return 0.0 };
        (self.s_m[i + 1] - self.s_m[i]).min(self.z_m[j + 1] - self.z_m[j])
    }
}

/// The orifices of pad `pad` of a solution, in pad coordinates, with their flows.
#[must_use]
pub fn orifice_sites(solution: &Solution, pad: usize) -> Vec<OrificeSite> {
    let (Some(p), Some(res)) = (solution.inputs.bearing.pads.get(pad), solution.pads.get(pad)) else {
        return Vec::new();
    };
    let r = solution.inputs.bearing.journal_radius_m;
    p.orifices
        .iter()
        .enumerate()
        .map(|(k, o)| OrificeSite {
            s_m: (o.angle_rad - p.leading_edge_rad) * r,
            z_m: o.axial_m,
            radius_m: 0.5 * o.diameter_m,
            flow_m3_per_s: res.orifice_flows_m3_per_s.get(k).copied().unwrap_or(0.0),
        })
        .collect()
}

/// Flowlines of pad `pad` of a solution.
#[must_use]
pub fn pad_flowlines(solution: &Solution, pad: usize, params: FlowlineParams) -> Vec<Flowline> {
    let Some(res) = solution.pads.get(pad) else { return Vec::new() };
    let u = solution.derived.speed_rad_s * solution.inputs.bearing.journal_radius_m;
    let field = VelocityField::new(&res.field, u);
    flowlines(&field, &orifice_sites(solution, pad), params)
}

/// Flowlines of a velocity field with the given orifices.
#[must_use]
#[allow(clippy::cast_precision_loss)]
pub fn flowlines(field: &VelocityField, orifices: &[OrificeSite], params: FlowlineParams) -> Vec<Flowline> {
    let mut out = Vec::new();
    let (Some(&z0), Some(&z1), Some(&s1)) = (field.z_m.first(), field.z_m.last(), field.s_m.last()) else { return out };
    let s_start = 1e-4 * s1;
    for k in 0..params.leading_edge_seeds {
        let z = z0 + (z1 - z0) * (k as f64 + 0.5) / params.leading_edge_seeds as f64;
        let (points, end) = trace(field, [s_start, z], 1.0, orifices, params);
        if points.len() > 1 {
            out.push(Flowline { points, seed: Seed::LeadingEdge, end });
        }
    }
    // A flow below this is neither a source nor a sink worth drawing.
    let flow_scale = field.surface_speed_m_s * (s1 * (z1 - z0)).sqrt() * 1e-6;
    for (k, o) in orifices.iter().enumerate() {
        if o.flow_m3_per_s.abs() <= flow_scale.max(1e-12) {
            continue;
        }
        let source = o.flow_m3_per_s > 0.0;
        for m in 0..params.orifice_seeds {
            let a = std::f64::consts::TAU * (m as f64 + 0.5) / params.orifice_seeds as f64;
            let start = [o.s_m + 1.05 * o.radius_m * a.cos(), o.z_m + 1.05 * o.radius_m * a.sin()];
            let (mut points, end) = trace(field, start, if source { 1.0 } else { -1.0 }, orifices, params);
            if !source {
                points.reverse();
            }
            if points.len() > 1 {
                out.push(Flowline { points, seed: Seed::Orifice(k), end });
            }
        }
    }
    out
}

/// Integrates from `start` along `direction · v̄/|v̄|` (direction ±1) until a stop condition.
fn trace(
    field: &VelocityField,
    start: [f64; 2],
    direction: f64,
    orifices: &[OrificeSite],
    params: FlowlineParams,
) -> (Vec<[f64; 2]>, End) {
    let speed_floor = 1e-6 * field.surface_speed_m_s.abs().max(1e-9);
    let unit = |p: [f64; 2]| -> Option<[f64; 2]> {
        let v = field.velocity(p[0], p[1])?;
        let n = v[0].hypot(v[1]);
        (n > speed_floor).then(|| [direction * v[0] / n, direction * v[1] / n])
    };
    // Forward traces drain into sinks; upstream traces end where they come out of a source.
    let swallowed = |p: [f64; 2], from_start: bool| {
        orifices.iter().any(|o| {
            let wanted = if direction > 0.0 { o.flow_m3_per_s < 0.0 } else { o.flow_m3_per_s > 0.0 };
            wanted && !from_start && (p[0] - o.s_m).hypot(p[1] - o.z_m) < o.radius_m
        })
    };
    let mut points = vec![start];
    let mut p = start;
    if field.velocity(p[0], p[1]).is_none() {
        return (points, End::LeftPad);
    }
    for _ in 0..params.max_steps {
        if field.cavitated(p[0], p[1]) {
            return (points, End::Cavitation);
        }
        let h = params.step_fraction * field.cell_size(p[0], p[1]);
        let step = |a: [f64; 2], k: [f64; 2], f: f64| [a[0] + f * h * k[0], a[1] + f * h * k[1]];
        let Some(k1) = unit(p) else { return (points, End::Stagnation) };
        let Some(k2) = unit(step(p, k1, 0.5)) else { return (points, End::LeftPad) };
        let Some(k3) = unit(step(p, k2, 0.5)) else { return (points, End::LeftPad) };
        let Some(k4) = unit(step(p, k3, 1.0)) else { return (points, End::LeftPad) };
        let next = [
            p[0] + h / 6.0 * (k1[0] + 2.0 * k2[0] + 2.0 * k3[0] + k4[0]),
            p[1] + h / 6.0 * (k1[1] + 2.0 * k2[1] + 2.0 * k3[1] + k4[1]),
        ];
        if field.velocity(next[0], next[1]).is_none() {
            return (points, End::LeftPad);
        }
        points.push(next);
        p = next;
        if swallowed(p, false) {
            return (points, End::Orifice);
        }
    }
    (points, End::MaxLength)
}

/// Arrowheads along a drawn flowline: `(tip, unit direction)` every `spacing` of its length (in the
/// points' units), the first at `phase · spacing` (phase in [0, 1)).
///
/// Give each line its own phase ([`arrow_phase`]): lines seeded on one ring around a weakly injecting
/// orifice bend into the main flow within a few radii, and with a common phase their first arrowheads sit
/// at one distance from the hole, drawing a ring that reads as another orifice.
#[must_use]
pub fn arrowheads(points: &[[f64; 2]], spacing: f64, phase: f64) -> Vec<([f64; 2], [f64; 2])> {
    let mut out = Vec::new();
    if spacing.is_nan() || spacing <= 0.0 {
        return out;
    }
    let mut next = phase.rem_euclid(1.0) * spacing;
    let mut run = 0.0;
    for w in points.windows(2) {
        let d = [w[1][0] - w[0][0], w[1][1] - w[0][1]];
        let len = d[0].hypot(d[1]);
        if len <= 0.0 {
            continue;
        }
        let dir = [d[0] / len, d[1] / len];
        while run + len >= next {
            let t = next - run;
            out.push(([w[0][0] + dir[0] * t, w[0][1] + dir[1] * t], dir));
            next += spacing;
        }
        run += len;
    }
    out
}

/// The arrowhead phase of the `index`-th line: the golden-ratio sequence, evenly spread for any count.
#[must_use]
#[allow(clippy::cast_precision_loss)]
pub fn arrow_phase(index: usize) -> f64 {
    (0.5 + index as f64 * 0.618_033_988_749_895).fract()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A uniform grid over s ∈ [0, 0.06], z ∈ [−0.02, 0.02] with a pressure function.
    fn field(p: impl Fn(f64, f64) -> f64) -> PadField {
        let s_m: Vec<f64> = (0..=60).map(|i| f64::from(i) * 1e-3).collect();
        let z_m: Vec<f64> = (0..=40).map(|j| -0.02 + f64::from(j) * 1e-3).collect();
        let mut pressure = Vec::new();
        for &s in &s_m {
            for &z in &z_m {
                pressure.push(p(s, z));
            }
        }
        let n = pressure.len();
        PadField {
            theta_rad: s_m.iter().map(|s| s / 0.05).collect(),
            s_m,
            z_m,
            half: false,
            periodic: false,
            pressure_pa: pressure,
            film_thickness_m: vec![50e-6; n],
            cavitated: vec![false; n],
            viscosity_pa_s: vec![0.02; n],
            ..PadField::default()
        }
    }

    #[test]
    fn pure_couette_flowlines_run_straight_at_half_the_surface_speed() {
        let f = VelocityField::new(&field(|_, _| 0.0), 10.0);
        let v = f.velocity(0.03, 0.005).unwrap();
        assert!((v[0] - 5.0).abs() < 1e-12 && v[1].abs() < 1e-12);
        let lines = flowlines(&f, &[], FlowlineParams::default());
        assert_eq!(lines.len(), 14);
        for l in &lines {
            assert_eq!(l.end, End::LeftPad);
            let (a, b) = (l.points[0], *l.points.last().unwrap());
            assert!((a[1] - b[1]).abs() < 1e-12, "stays at its axial position");
            assert!(b[0] > 0.059, "reaches the trailing edge: {b:?}");
        }
    }

    #[test]
    fn poiseuille_velocity_follows_the_pressure_gradient() {
        // p = G s: v̄_s = U/2 − h² G/(12 µ).
        let g = 1e7;
        let f = VelocityField::new(&field(|s, _| g * s), 10.0);
        let v = f.velocity(0.03, 0.0).unwrap();
        let expected = 5.0 - 50e-6 * 50e-6 * g / (12.0 * 0.02);
        assert!((v[0] - expected).abs() < 1e-9, "{} vs {expected}", v[0]);
    }

    #[test]
    fn a_strong_source_reverses_the_flow_upstream_and_a_sink_swallows_lines() {
        // A pressure peak at an orifice (s0, 0) of radius 2 mm: oil spreads out of it in every direction,
        // against the Couette flow upstream.
        let (s0, r0) = (0.03, 2e-3);
        let peak = |s: f64, z: f64| 4e6 * (-((s - s0).powi(2) + z * z) / (6e-3_f64).powi(2)).exp();
        let f = VelocityField::new(&field(peak), 2.0);
        let src = OrificeSite { s_m: s0, z_m: 0.0, radius_m: r0, flow_m3_per_s: 1e-5 };
        let lines = flowlines(&f, &[src], FlowlineParams::default());
        let from_hole: Vec<&Flowline> = lines.iter().filter(|l| l.seed == Seed::Orifice(0)).collect();
        assert_eq!(from_hole.len(), 16);
        // Reversal: lines that first run upstream, well ahead of the hole, before the Couette flow turns them.
        let upstream = from_hole
            .iter()
            .filter(|l| l.points.iter().map(|p| p[0]).fold(f64::INFINITY, f64::min) < s0 - 3.0 * r0)
            .count();
        assert!(upstream >= 2, "some lines leave against the rotation: {upstream}");
        // Lines from the leading edge are pushed aside by the source, none enters it.
        assert!(lines.iter().filter(|l| l.seed == Seed::LeadingEdge).all(|l| l.end != End::Orifice));

        // Without a pressure peak but with a sink of the same size, the line that meets it ends inside.
        let f = VelocityField::new(&field(|_, _| 0.0), 2.0);
        let sink = OrificeSite { flow_m3_per_s: -1e-6, ..src };
        let lines = flowlines(&f, &[sink], FlowlineParams { leading_edge_seeds: 41, ..FlowlineParams::default() });
        let centre = lines.iter().filter(|l| l.seed == Seed::LeadingEdge && l.end == End::Orifice).count();
        assert!(centre >= 1, "the line through the hole is swallowed");
        // Sink rings are traced upstream and reversed: they end at the hole.
        for l in lines.iter().filter(|l| l.seed == Seed::Orifice(0)) {
            let last = *l.points.last().unwrap();
            assert!((last[0] - s0).hypot(last[1]) < 1.1 * r0, "{last:?}");
        }
    }

    #[test]
    fn lines_stop_at_the_cavitation_boundary() {
        let mut pf = field(|_, _| 0.0);
        let nz = pf.z_m.len();
        for i in 40..pf.s_m.len() {
            for j in 0..nz {
                pf.cavitated[i * nz + j] = true;
            }
        }
        let lines = flowlines(&VelocityField::new(&pf, 10.0), &[], FlowlineParams::default());
        for l in &lines {
            assert_eq!(l.end, End::Cavitation);
            let s_end = l.points.last().unwrap()[0];
            assert!((0.038..0.0405).contains(&s_end), "{s_end}");
        }
    }

    #[test]
    fn arrowheads_of_lines_from_one_ring_do_not_draw_a_ring() {
        // 16 radial lines from a ring of radius 1 (the seeds around a source), 10 long, arrowheads every 7.
        let lines: Vec<Vec<[f64; 2]>> = (0..16)
            .map(|k| {
                let a = std::f64::consts::TAU * f64::from(k) / 16.0;
                (0..=100).map(|i| 1.0 + 0.1 * f64::from(i)).map(|r| [r * a.cos(), r * a.sin()]).collect()
            })
            .collect();
        let first_radius = |l: &[[f64; 2]], phase: f64| {
            let heads = arrowheads(l, 7.0, phase);
            heads[0].0[0].hypot(heads[0].0[1])
        };
        let common: Vec<f64> = lines.iter().map(|l| first_radius(l, 0.5)).collect();
        assert!(common.iter().all(|r| (r - 4.5).abs() < 1e-9), "one phase: one ring {common:?}");
        let spread: Vec<f64> = lines.iter().enumerate().map(|(k, l)| first_radius(l, arrow_phase(k))).collect();
        let (lo, hi) = spread.iter().fold((f64::INFINITY, 0.0_f64), |(a, b), &r| (a.min(r), b.max(r)));
        assert!(hi - lo > 0.8 * 7.0, "staggered phases spread the first arrowheads: {spread:?}");
        // Along one line the arrowheads are one spacing apart and point downstream.
        let heads = arrowheads(&lines[0], 7.0, 0.1);
        assert_eq!(heads.len(), 2);
        assert!((heads[1].0[0] - heads[0].0[0] - 7.0).abs() < 1e-9 && (heads[0].1[0] - 1.0).abs() < 1e-12);
    }
}
