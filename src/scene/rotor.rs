//! Plain drawables of a rotor analysis ([`crate::rotor::analysis::AnalysisResult`]) for the rotor view:
//!
//! - Campbell diagram: damped natural frequency `f_d = Im λ / 2π` [Hz] of the first forward and backward
//!   modes against spin speed [rpm] (followed by eigenvector continuity, [`crate::rotor::campbell::track_modes`],
//!   so lines cross instead of swapping), the 1× line `f = N / 60` and the 1× critical speeds;
//! - stability map: logarithmic decrement `δ = −2π Re λ / Im λ` of the same modes against speed, the onset
//!   (δ = 0 crossing of the least damped mode) marked;
//! - mode shape: the real part of a mode's (x, y) amplitudes along the shaft at t = 0 and a quarter period
//!   later (scaled so the largest amplitude is 1), with its whirl;
//! - unbalance Bode: the orbit's major axis, peak to peak [µm], and x phase [deg] at the response nodes
//!   against speed, the API 617 limit `A = 25.4 √(12000/N)` µm;
//! - undamped critical-speed map: critical speeds [rpm] against the support stiffness at the bearings on a
//!   log axis (`log10 k` [N/m]), the bearings' direct stiffnesses k_xx, k_yy over speed on the same axes and
//!   their crossings with the mode lines;
//! - rotor sketch: shaft sections (axial position and diameters [mm]), disks, bearings, supports, unbalances.
//!
//! No egui here: the view ([`crate::app::views::rotor_view`]) only draws these.

use crate::model::rotor::{BearingSupport, Rotor};
use crate::rotor::analysis::AnalysisResult;
use crate::rotor::campbell::track_modes;
use crate::rotor::critical_map::CriticalSpeedMap;
use crate::rotor::eigen::Whirl;
use crate::rotor::stability::SpeedPoint;
use crate::units::{HZ_ANGULAR, MM, RPM, UM};

/// One curve against speed: points `[speed_rpm, value]`.
#[derive(Debug, Clone, PartialEq)]
pub struct Curve {
    pub name: String,
    pub whirl: Whirl,
    pub points: Vec<[f64; 2]>,
}

/// Campbell diagram and stability map of the first modes of each whirl direction.
#[derive(Debug, Clone, PartialEq)]
pub struct ModeCurves {
    /// Damped natural frequency [Hz] against speed [rpm].
    pub frequency_hz: Vec<Curve>,
    /// Logarithmic decrement [–] against speed [rpm].
    pub log_dec: Vec<Curve>,
    /// The 1× line over the sweep: `[speed_rpm, speed_rpm / 60]`.
    pub one_x: [[f64; 2]; 2],
    /// 1× critical speeds: `[speed_rpm, frequency_hz]`.
    pub critical: Vec<[f64; 2]>,
    /// Onset of instability [rpm], if inside the sweep.
    pub onset_rpm: Option<f64>,
    /// Operating speed range [rpm], if the rotor gives one.
    pub operating_rpm: Option<[f64; 2]>,
}

/// The first `ranks` forward and backward modes of `result` as curves.
#[must_use]
pub fn mode_curves(result: &AnalysisResult, rotor: &Rotor, ranks: usize) -> ModeCurves {
    let sweep: Vec<&SpeedPoint> = result.speeds.iter().map(|s| &s.point).collect();
    let mut tracks = track_modes(&sweep, 2 * ranks);
    tracks.retain(|t| t.rank < ranks);
    tracks.sort_by_key(|t| (t.whirl == Whirl::Backward, t.rank));
    let mut frequency_hz = Vec::new();
    let mut log_dec = Vec::new();
    for t in &tracks {
        let (mut f, mut d) = (Vec::new(), Vec::new());
        for (i, p) in sweep.iter().enumerate() {
            if let Some(m) = t.mode(&sweep, i) {
                let rpm = RPM.from_si(p.speed_rad_s);
                f.push([rpm, HZ_ANGULAR.from_si(m.imag_rad_s)]);
                d.push([rpm, m.log_dec]);
            }
        }
        let tag = if t.whirl == Whirl::Forward { "F" } else { "B" };
        let name = format!("{tag}{}", t.rank + 1);
        frequency_hz.push(Curve { name: name.clone(), whirl: t.whirl, points: f });
        log_dec.push(Curve { name, whirl: t.whirl, points: d });
    }
    // The synchronous line: a whirl at the running speed (rpm on the axis, Hz up the plot).
    let sync = |w: f64| [RPM.from_si(w), HZ_ANGULAR.from_si(w)];
    let first = result.speeds.first().map_or(0.0, |s| s.point.speed_rad_s);
    let last = result.speeds.last().map_or(0.0, |s| s.point.speed_rad_s);
    ModeCurves {
        frequency_hz,
        log_dec,
        one_x: [sync(first), sync(last)],
        critical: result
            .critical_speeds
            .iter()
            .map(|c| [RPM.from_si(c.speed_rad_s), HZ_ANGULAR.from_si(c.order * c.speed_rad_s)])
            .collect(),
        onset_rpm: result.onset.as_ref().map(|o| RPM.from_si(o.speed_rad_s)),
        operating_rpm: rotor.operating_range.map(|[a, b]| [RPM.from_si(a), RPM.from_si(b)]),
    }
}

/// A mode's deflected shaft.
#[derive(Debug, Clone, PartialEq)]
pub struct ModeShape {
    pub speed_rpm: f64,
    pub frequency_hz: f64,
    pub log_dec: f64,
    pub whirl: Whirl,
    /// Axial node positions [m].
    pub z_m: Vec<f64>,
    /// Deflection in x and y at t = 0 (real parts; the largest amplitude is 1).
    pub x: Vec<f64>,
    pub y: Vec<f64>,
}

/// The `index`-th mode (ascending frequency) at speed point `speed`, if both exist.
#[must_use]
pub fn mode_shape(result: &AnalysisResult, rotor: &Rotor, speed: usize, index: usize) -> Option<ModeShape> {
    let s = result.speeds.get(speed)?;
    let m = s.point.modes.modes.get(index)?;
    Some(ModeShape {
        speed_rpm: RPM.from_si(s.point.speed_rad_s),
        frequency_hz: m.frequency_hz(),
        log_dec: m.log_dec,
        whirl: m.whirl,
        z_m: rotor.node_positions(),
        x: m.shape.iter().map(|p| p[0].re).collect(),
        y: m.shape.iter().map(|p| p[1].re).collect(),
    })
}

/// Unbalance response at one node against speed.
#[derive(Debug, Clone, PartialEq)]
pub struct NodeResponse {
    pub node: usize,
    /// What the node is, for legends and sentences ([`node_name`]): `bearing 1`, `mid-span`, `shaft end`.
    pub name: String,
    /// Major axis of the orbit, peak to peak [µm], against speed [rpm].
    pub amplitude_um: Vec<[f64; 2]>,
    /// Phase of x [deg] against speed [rpm].
    pub phase_deg: Vec<[f64; 2]>,
}

/// Unbalance Bode plot with the API 617 limit.
#[derive(Debug, Clone, PartialEq)]
pub struct UnbalanceBode {
    pub nodes: Vec<NodeResponse>,
    /// API 617 limit [µm] against speed [rpm].
    pub api617_um: Vec<[f64; 2]>,
}

/// A node as a reader names it, with its axial position: `bearing 1 (210 mm)` (bearings that carry the
/// shaft numbered along it), `shaft end (0 mm)`, `mid-span (840 mm)` (within a tenth of the bearing span of the midpoint
/// between the outer bearings), else `node 31 (1020 mm)`; `, disk` is added where a disk sits.
#[must_use]
pub fn node_name(rotor: &Rotor, node: usize) -> String {
    let z = rotor.node_positions();
    let at = |n: usize| MM.from_si(z.get(n).copied().unwrap_or(0.0));
    // Bearings that carry the shaft: a bearing case, or numbers with direct stiffness. A cross-coupling
    // entered as a "bearing" (the compressor's aerodynamic cross-coupling at mid-span: skew-symmetric
    // stiffness only) is not numbered as one.
    let carries = |b: &&crate::model::rotor::BearingPosition| match &b.support {
        BearingSupport::Case { .. } => true,
        BearingSupport::Numbers(t) => t.k.iter().any(|k| k[0][0] > 0.0 || k[1][1] > 0.0),
    };
    let mut bearing_nodes: Vec<usize> = rotor.bearings.iter().filter(carries).map(|b| b.node).collect();
    bearing_nodes.sort_unstable();
    bearing_nodes.dedup();
    let what = if let Some(i) = bearing_nodes.iter().position(|&b| b == node) {
        format!("bearing {}", i + 1)
    } else if node == 0 || node + 1 == rotor.n_nodes() {
        "shaft end".to_string()
    } else {
        match (bearing_nodes.first(), bearing_nodes.last()) {
            (Some(&a), Some(&b)) if b > a && (at(node) - 0.5 * (at(a) + at(b))).abs() <= 0.1 * (at(b) - at(a)) => {
                "mid-span".to_string()
            }
            _ => format!("node {node}"),
        }
    };
    let disk = if rotor.disks.iter().any(|d| d.node == node) { ", disk" } else { "" };
    format!("{what}{disk} ({:.0} mm)", at(node))
}

/// Where a node's response exceeds the API 617 limit: the speed band and the worst point in it.
#[derive(Debug, Clone, PartialEq)]
pub struct Exceedance {
    pub name: String,
    /// First and last analysed speed above the limit [rpm].
    pub from_rpm: f64,
    pub to_rpm: f64,
    /// The largest ratio of amplitude to limit in the band, its speed [rpm], amplitude and limit [µm].
    pub worst_rpm: f64,
    pub worst_um: f64,
    pub limit_um: f64,
}

impl UnbalanceBode {
    /// Every band of analysed speeds where a node's amplitude exceeds the API 617 limit, node by node.
    #[must_use]
    pub fn exceedances(&self) -> Vec<Exceedance> {
        let limit_at = |rpm: f64| self.api617_um.iter().find(|p| (p[0] - rpm).abs() < 1e-9).map(|p| p[1]);
        let mut out = Vec::new();
        for n in &self.nodes {
            let mut band: Option<Exceedance> = None;
            for &[rpm, a] in &n.amplitude_um {
                match limit_at(rpm) {
                    Some(l) if a > l => {
                        let e = band.get_or_insert(Exceedance {
                            name: n.name.clone(),
                            from_rpm: rpm,
                            to_rpm: rpm,
                            worst_rpm: rpm,
                            worst_um: a,
                            limit_um: l,
                        });
                        e.to_rpm = rpm;
                        if a / l > e.worst_um / e.limit_um {
                            (e.worst_rpm, e.worst_um, e.limit_um) = (rpm, a, l);
                        }
                    }
                    _ => out.extend(band.take()),
                }
            }
            out.extend(band);
        }
        out
    }

    /// The API 617 check in words: each band over the limit, or that every node stays below it (with the
    /// closest approach).
    #[must_use]
    pub fn api617_sentence(&self) -> String {
        let over = self.exceedances();
        if over.is_empty() {
            let closest = self
                .nodes
                .iter()
                .flat_map(|n| {
                    n.amplitude_um.iter().filter_map(move |&[rpm, a]| {
                        self.api617_um.iter().find(|p| (p[0] - rpm).abs() < 1e-9).map(|p| (a / p[1], rpm, &n.name))
                    })
                })
                .max_by(|a, b| a.0.total_cmp(&b.0));
            return match closest {
                Some((ratio, rpm, name)) => format!(
                    "Below the API 617 limit at every node shown; closest: {name}, {:.0} % of the limit at {rpm:.0} rpm.",
                    100.0 * ratio
                ),
                None => "No API 617 limit at these speeds.".into(),
            };
        }
        let parts: Vec<String> = over
            .iter()
            .map(|e| {
                format!(
                    "{} from {:.0} to {:.0} rpm (worst {} µm against {} µm at {:.0} rpm)",
                    e.name,
                    e.from_rpm,
                    e.to_rpm,
                    crate::number::sig(e.worst_um, 3),
                    crate::number::sig(e.limit_um, 3),
                    e.worst_rpm
                )
            })
            .collect();
        format!("Exceeds the API 617 limit 25.4 sqrt(12000/N) µm: {}.", parts.join("; "))
    }
}

/// The unbalance response of `result` per response node, each named on `rotor` ([`node_name`]).
#[must_use]
pub fn unbalance_bode(result: &AnalysisResult, rotor: &Rotor) -> UnbalanceBode {
    let nodes = result
        .response_nodes
        .iter()
        .map(|&node| {
            let (mut a, mut p) = (Vec::new(), Vec::new());
            for s in &result.speeds {
                if let Some(o) = s.orbits.iter().find(|o| o.node == node) {
                    let rpm = RPM.from_si(s.point.speed_rad_s);
                    a.push([rpm, UM.from_si(o.major_pp_m)]);
                    p.push([rpm, o.x_phase_rad.to_degrees()]);
                }
            }
            NodeResponse { node, name: node_name(rotor, node), amplitude_um: a, phase_deg: p }
        })
        .collect();
    let api617_um = result
        .speeds
        .iter()
        .filter(|s| s.api617_limit_um.is_finite())
        .map(|s| [RPM.from_si(s.point.speed_rad_s), s.api617_limit_um])
        .collect();
    UnbalanceBode { nodes, api617_um }
}

/// The critical-speed map as drawn: every point `[log10(k [N/m]), speed [rpm]]`.
#[derive(Debug, Clone, PartialEq)]
pub struct MapDrawing {
    /// One line per mode of the map.
    pub modes: Vec<Vec<[f64; 2]>>,
    /// `(name, points)` per bearing position and direction that has positive direct stiffness.
    pub bearings: Vec<(String, Vec<[f64; 2]>)>,
    pub crossings: Vec<[f64; 2]>,
}

/// The drawable map of `m` for `rotor` (bearing names carry their node).
#[must_use]
pub fn map_drawing(m: &CriticalSpeedMap, rotor: &Rotor) -> MapDrawing {
    let modes = (0..m.map.frequencies_rad_s.first().map_or(0, Vec::len))
        .map(|mode| {
            m.map
                .stiffness_n_per_m
                .iter()
                .zip(&m.map.frequencies_rad_s)
                .filter_map(|(k, f)| f.get(mode).map(|w| [k.log10(), RPM.from_si(*w)]))
                .collect()
        })
        .collect();
    let mut bearings = Vec::new();
    for (b, curve) in m.bearing_curves.iter().enumerate() {
        for (d, tag) in ["k_xx", "k_yy"].iter().enumerate() {
            let points: Vec<[f64; 2]> = curve
                .iter()
                .map(|p| (p.0, if d == 0 { p.1 } else { p.2 }))
                .filter(|(_, k)| *k > 0.0)
                .map(|(w, k)| [k.log10(), RPM.from_si(w)])
                .collect();
            if !points.is_empty() {
                let node = rotor.bearings.get(b).map_or(0, |p| p.node);
                bearings.push((format!("bearing at node {node}: {tag}"), points));
            }
        }
    }
    let crossings = m.crossings.iter().map(|c| [c.stiffness_n_per_m.log10(), RPM.from_si(c.speed_rad_s)]).collect();
    MapDrawing { modes, bearings, crossings }
}

/// What sits at a node of the sketch.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SketchItem {
    Disk,
    /// A bearing case solved per speed.
    Bearing,
    /// Coefficients given by numbers (seal, aerodynamic cross-coupling, …).
    Numbers,
    Support,
    /// An unbalance (drawn above the shaft).
    Unbalance,
}

/// The rotor as drawn: sections and what sits on the shaft [mm].
#[derive(Debug, Clone, PartialEq)]
pub struct RotorSketch {
    /// `[z_start, z_end, outer diameter, inner diameter]` per element [mm].
    pub sections: Vec<[f64; 4]>,
    /// `(z [mm], item, node)`; the items of one rotor table (disks; bearings and numbers; supports;
    /// unbalances) in the table's order.
    pub items: Vec<(f64, SketchItem, usize)>,
    pub length_mm: f64,
    pub max_diameter_mm: f64,
}

/// The sketch of `rotor`.
#[must_use]
pub fn sketch(rotor: &Rotor) -> RotorSketch {
    let z: Vec<f64> = rotor.node_positions().iter().map(|z| MM.from_si(*z)).collect();
    let sections: Vec<[f64; 4]> = rotor
        .elements
        .iter()
        .enumerate()
        .map(|(i, e)| [z[i], z[i + 1], MM.from_si(e.outer_diameter_m), MM.from_si(e.inner_diameter_m)])
        .collect();
    let mut items: Vec<(f64, SketchItem, usize)> =
        rotor.disks.iter().map(|d| (z[d.node], SketchItem::Disk, d.node)).collect();
    for b in &rotor.bearings {
        let kind = match b.support {
            BearingSupport::Case { .. } => SketchItem::Bearing,
            BearingSupport::Numbers(_) => SketchItem::Numbers,
        };
        items.push((z[b.node], kind, b.node));
    }
    items.extend(rotor.supports.iter().map(|s| (z[s.node], SketchItem::Support, s.node)));
    items.extend(rotor.unbalances.iter().map(|u| (z[u.node], SketchItem::Unbalance, u.node)));
    RotorSketch {
        max_diameter_mm: sections.iter().map(|s| s[2]).fold(0.0, f64::max),
        length_mm: z.last().copied().unwrap_or(0.0),
        sections,
        items,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::rotor::parse_rotor_file;
    use crate::rotor::analysis::{run, AnalysisParams};
    use crate::rotor::campbell::nth_mode;

    const JEFFCOTT: &str = r#"
title = "two-bearing shaft"
[rotor]
density_kg_per_m3 = 7850.0
youngs_modulus_gpa = 211.0
poisson_ratio = 0.3
[[rotor.section]]
length_mm = 1000.0
outer_diameter_mm = 50.0
elements = 10
[[rotor.disk]]
node = 5
mass_kg = 20.0
polar_inertia_kg_m2 = 0.2
transverse_inertia_kg_m2 = 0.1
[[rotor.unbalance]]
node = 5
amount_g_mm = 100.0
[[rotor.bearing]]
node = 0
k_n_per_m = [[1e7, 0.0, 0.0, 1e7]]
c_ns_per_m = [[1e3, 0.0, 0.0, 1e3]]
[[rotor.bearing]]
node = 10
k_n_per_m = [[1e7, 0.0, 0.0, 1e7]]
c_ns_per_m = [[1e3, 0.0, 0.0, 1e3]]
"#;

    fn analysed() -> (Rotor, AnalysisResult) {
        let rotor = parse_rotor_file(JEFFCOTT).unwrap().resolve(&|_| Err("no cases".into())).unwrap();
        let speeds = (0..=20).map(|i| RPM.to_si(f64::from(i) * 300.0)).collect();
        let r = run(&rotor, AnalysisParams::new(speeds)).unwrap();
        (rotor, r)
    }

    #[test]
    fn curves_follow_the_analysis_and_the_critical_speed_lies_on_the_one_x_line() {
        let (rotor, r) = analysed();
        let c = mode_curves(&r, &rotor, 2);
        assert_eq!(c.frequency_hz.len(), 4);
        let f1 = &c.frequency_hz[0];
        assert_eq!(f1.points.len(), r.speeds.len());
        let (w, _) = nth_mode(&r.speeds[7].point, Whirl::Forward, 0).unwrap();
        assert!((f1.points[7][1] - HZ_ANGULAR.from_si(w)).abs() < 1e-12);
        assert!(!c.critical.is_empty());
        for [rpm, hz] in &c.critical {
            assert!((hz - rpm / 60.0).abs() < 1e-9 * hz, "{rpm} rpm, {hz} Hz");
        }
    }

    #[test]
    fn mode_shape_is_normalised_and_unbalance_peaks_near_the_critical_speed() {
        let (rotor, r) = analysed();
        let s = mode_shape(&r, &rotor, 10, 0).unwrap();
        assert_eq!(s.z_m.len(), rotor.n_nodes());
        let biggest = s.x.iter().chain(&s.y).fold(0.0_f64, |m, v| m.max(v.abs()));
        assert!(biggest <= 1.0 + 1e-12 && biggest > 0.5, "{biggest}");
        let b = unbalance_bode(&r, &rotor);
        let mid = b.nodes.iter().find(|n| n.node == 5).unwrap();
        // Bearings at nodes 0 and 10 of a 1 m shaft; the disk and unbalance at node 5 in between.
        assert_eq!(mid.name, "mid-span, disk (500 mm)");
        let names: Vec<&str> = b.nodes.iter().map(|n| n.name.as_str()).collect();
        assert_eq!(names, ["bearing 1 (0 mm)", "mid-span, disk (500 mm)", "bearing 2 (1000 mm)"]);
        let peak = mid.amplitude_um.iter().max_by(|a, b| a[1].total_cmp(&b[1])).unwrap()[0];
        let critical = mode_curves(&r, &rotor, 1).critical[0][0];
        assert!((peak - critical).abs() <= 300.0, "peak at {peak} rpm, critical {critical} rpm");
        assert_eq!(b.api617_um.len(), r.speeds.len() - 1);
    }

    /// The API 617 check in words, on a made-up response: a bearing over its limit from 4000 to 5000 rpm
    /// (worst 60 µm against 40 µm at 4000 rpm), the other node below it.
    #[test]
    fn the_api617_check_names_the_node_and_the_speed_band() {
        let limit = |rpm: f64| 25.4 * (12000.0 / rpm).sqrt();
        let speeds = [3000.0, 4000.0, 5000.0, 6000.0];
        let node = |name: &str, a: [f64; 4]| NodeResponse {
            node: 0,
            name: name.into(),
            amplitude_um: speeds.iter().zip(a).map(|(&r, a)| [r, a]).collect(),
            phase_deg: Vec::new(),
        };
        let mut b = UnbalanceBode {
            nodes: vec![node("bearing 1 (210 mm)", [10.0, 60.0, 40.0, 10.0]), node("mid-span (840 mm)", [5.0; 4])],
            api617_um: speeds.iter().map(|&r| [r, limit(r)]).collect(),
        };
        let e = b.exceedances();
        assert_eq!(e.len(), 1);
        assert_eq!((e[0].from_rpm, e[0].to_rpm, e[0].worst_rpm, e[0].worst_um), (4000.0, 5000.0, 4000.0, 60.0));
        assert_eq!(
            b.api617_sentence(),
            "Exceeds the API 617 limit 25.4 sqrt(12000/N) µm: bearing 1 (210 mm) from 4000 to 5000 rpm (worst 60 µm against 44 µm at 4000 rpm)."
        );
        b.nodes.truncate(0);
        b.nodes.push(node("mid-span (840 mm)", [5.0, 5.0, 5.0, 20.0]));
        assert!(b.exceedances().is_empty());
        // 20 µm against 25.4·√2 = 35.92 µm at 6000 rpm: 56 %.
        assert_eq!(
            b.api617_sentence(),
            "Below the API 617 limit at every node shown; closest: mid-span (840 mm), 56 % of the limit at 6000 rpm."
        );
    }

    #[test]
    fn map_drawing_puts_crossings_on_the_bearing_curves() {
        let (rotor, r) = analysed();
        let m = crate::rotor::critical_map::map_over_curves(&rotor, r.bearing_stiffness.clone(), 41, 3).unwrap();
        let d = map_drawing(&m, &rotor);
        assert_eq!(d.modes.len(), 3);
        // constant 1e7 N/m bearings: both curves are the vertical line log10 k = 7, and every crossing lies on it
        assert_eq!(d.bearings.len(), 4);
        assert!(d.bearings.iter().all(|(_, p)| p.iter().all(|q| (q[0] - 7.0).abs() < 1e-12)));
        assert!(!d.crossings.is_empty());
        assert!(d.crossings.iter().all(|c| (c[0] - 7.0).abs() < 1e-12), "{:?}", d.crossings);
    }

    #[test]
    fn sketch_places_disks_and_bearings_at_their_nodes() {
        let (rotor, _) = analysed();
        let s = sketch(&rotor);
        assert_eq!(s.sections.len(), 10);
        assert!((s.length_mm - 1000.0).abs() < 1e-9);
        assert!(s
            .items
            .iter()
            .any(|&(z, item, node)| item == SketchItem::Disk && node == 5 && (z - 500.0).abs() < 1e-9));
        assert_eq!(s.items.iter().filter(|i| i.1 == SketchItem::Numbers).count(), 2);
        assert!(s
            .items
            .iter()
            .any(|&(z, item, node)| item == SketchItem::Unbalance && node == 5 && (z - 500.0).abs() < 1e-9));
    }
}
