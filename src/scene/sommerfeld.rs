//! The Sommerfeld chart: a load sweep (or an eccentricity sweep, for a case that prescribes the journal
//! position) drawn against the Sommerfeld number S = µ N L D / W (R/Cb)², with the outputs made
//! dimensionless the classical way, so bearings of any size read on one chart:
//!
//! - ε = e / Cb and the attitude angle φ;
//! - h_min / Cb;
//! - reduced stiffness K̄ = K Cb / W and damping C̄ = C Cb Ω / W (xx and yy terms).
//!
//! Reference lines where a closed form exists for the geometry: a plain 360° bearing (one fixed pad round
//! the whole journal) against the infinitely short bearing (Ocvirk; docs/REFERENCES.md §2):
//! S = f(ε) / (π (L/D)²) with f(ε) = (1 − ε²)² / (ε √(16 ε² + π² (1 − ε²))), tan φ = π √(1 − ε²) / (4 ε),
//! h_min / Cb = 1 − ε. The short-bearing limit is approached as O((L/D)²): close at L/D = 0.1, a rough guide
//! at L/D = 0.5. Tilting-pad bearings have no such closed form; their chart has no reference line.

use std::f64::consts::PI;

use crate::model::{Case, LoadSpec, PadKind};
use crate::scene::sweep::{SweepSpec, SweepTable};
use crate::study::COLUMNS;
use crate::units::UM;

/// What the chart needs of the case besides the sweep's rows.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ChartGeometry {
    /// Assembled clearance Cb [m].
    pub clearance_m: f64,
    /// Running speed Ω [rad/s].
    pub speed_rad_s: f64,
    /// L/D of a plain 360° bearing (the short-bearing reference applies), else `None`.
    pub plain_360_l_over_d: Option<f64>,
}

impl ChartGeometry {
    #[must_use]
    pub fn of(case: &Case) -> Self {
        let b = &case.bearing;
        let plain = b.pads.len() == 1
            && b.pads[0].kind == PadKind::Fixed
            && (b.pads[0].arc_rad - 2.0 * PI).abs() < 1e-6
            && (b.pads[0].clearance_m - b.assembled_clearance_m).abs() <= 1e-9 * b.assembled_clearance_m;
        let l_over_d = case.bearing.length_m / (2.0 * b.journal_radius_m);
        Self {
            clearance_m: b.assembled_clearance_m,
            speed_rad_s: case.operating.speed_rad_s,
            plain_360_l_over_d: plain.then_some(l_over_d),
        }
    }
}

/// One plot of the chart: its title, the swept points `[S, value]` per curve, and the reference line.
#[derive(Debug, Clone, PartialEq)]
pub struct ChartPlot {
    pub title: &'static str,
    /// `(name, points)`: the solver's values against S.
    pub curves: Vec<(&'static str, Vec<[f64; 2]>)>,
    /// The closed form of the geometry against S, if there is one.
    pub reference: Vec<[f64; 2]>,
}

/// The output columns a chart sweep needs.
pub const CHART_COLUMNS: [&str; 8] = [
    "eccentricity_ratio",
    "attitude_angle_deg",
    "h_min_um",
    "load_n",
    "kxx_n_per_m",
    "kyy_n_per_m",
    "cxx_ns_per_m",
    "cyy_ns_per_m",
];

/// The chart's sweep, with the chart (the sweep itself knows nothing of the chart).
impl SweepSpec {
    /// The sweep of the Sommerfeld chart for `case`: its load from a fifth to three times its value (S
    /// from about five times to a third of the case's), or, for a case that prescribes the journal
    /// position, ε from 0.1 to 0.85; 12 points at preview fidelity.
    #[must_use]
    pub fn sommerfeld_chart(case: &Case) -> Self {
        let (key, from, to) = match case.operating.load {
            LoadSpec::Force { magnitude_n, .. } => ("operating.load_n", 0.2 * magnitude_n, 3.0 * magnitude_n),
            LoadSpec::Position { .. } => ("operating.eccentricity_ratio", 0.1, 0.85),
        };
        Self {
            key: key.into(),
            from,
            to,
            count: 12,
            outputs: CHART_COLUMNS.iter().map(|c| (*c).to_string()).collect(),
            against_sommerfeld: true,
            preview: true,
            chart: true,
        }
    }
}

/// The short-bearing (Ocvirk) Sommerfeld number and attitude angle [deg] of a plain 360° bearing at ε.
#[must_use]
pub fn short_bearing(eps: f64, l_over_d: f64) -> (f64, f64) {
    let q = 1.0 - eps * eps;
    let f = q * q / (eps * (16.0 * eps * eps + PI * PI * q).sqrt());
    (f / (PI * l_over_d * l_over_d), (PI * q.sqrt() / (4.0 * eps)).atan().to_degrees())
}

/// The chart of a sweep's solved points (failed points left out), sorted by S.
#[must_use]
pub fn chart(table: &SweepTable, g: &ChartGeometry) -> Vec<ChartPlot> {
    let col = |name: &str| COLUMNS.iter().position(|c| c.name == name);
    let (Some(s), Some(e), Some(a), Some(h), Some(w)) =
        (col("sommerfeld"), col("eccentricity_ratio"), col("attitude_angle_deg"), col("h_min_um"), col("load_n"))
    else {
        return Vec::new();
    };
    let k = ["kxx_n_per_m", "kyy_n_per_m", "cxx_ns_per_m", "cyy_ns_per_m"].map(col);
    let mut rows: Vec<&Vec<Option<f64>>> = table.points.iter().filter_map(|(_, r)| r.result.as_ref().ok()).collect();
    rows.retain(|c| c[s].is_some_and(|x| x > 0.0) && c[w].is_some_and(|x| x > 0.0));
    rows.sort_by(|a, b| a[s].unwrap_or(0.0).total_cmp(&b[s].unwrap_or(0.0)));
    let series = |value: &dyn Fn(&Vec<Option<f64>>) -> Option<f64>| -> Vec<[f64; 2]> {
        rows.iter().filter_map(|c| Some([c[s]?, value(c)?])).collect()
    };
    let (cb, omega) = (g.clearance_m, g.speed_rad_s);
    let stiffness = |i: usize| move |c: &Vec<Option<f64>>| Some(c[k[i]?]? * cb / c[w]?);
    let damping = |i: usize| move |c: &Vec<Option<f64>>| Some(c[k[i]?]? * cb * omega / c[w]?);
    // Reference: ε from 0.05 to 0.95 mapped to S (S falls as ε grows).
    let reference = |value: &dyn Fn(f64, f64) -> f64| -> Vec<[f64; 2]> {
        g.plain_360_l_over_d.map_or_else(Vec::new, |ld| {
            let mut pts: Vec<[f64; 2]> = (1..=19)
                .map(|i| 0.05 * f64::from(i))
                .map(|eps| {
                    let (sn, phi) = short_bearing(eps, ld);
                    [sn, value(eps, phi)]
                })
                .collect();
            pts.reverse();
            pts
        })
    };
    vec![
        ChartPlot {
            title: "Eccentricity ratio ε [–]",
            curves: vec![("ε", series(&|c| c[e]))],
            reference: reference(&|eps, _| eps),
        },
        ChartPlot {
            title: "Attitude angle [°]",
            curves: vec![("attitude", series(&|c| c[a]))],
            reference: reference(&|_, phi| phi),
        },
        ChartPlot {
            title: "Minimum film thickness h_min / Cb [–]",
            curves: vec![("h_min / Cb", series(&|c| Some(UM.to_si(c[h]?) / cb)))],
            reference: reference(&|eps, _| 1.0 - eps),
        },
        ChartPlot {
            title: "Reduced stiffness K Cb / W [–]",
            curves: vec![("Kxx", series(&stiffness(0))), ("Kyy", series(&stiffness(1)))],
            reference: Vec::new(),
        },
        ChartPlot {
            title: "Reduced damping C Cb Ω / W [–]",
            curves: vec![("Cxx", series(&damping(2))), ("Cyy", series(&damping(3)))],
            reference: Vec::new(),
        },
    ]
}

/// Name of the reference curve in the exports.
pub const REFERENCE_NAME: &str = "short bearing (Ocvirk)";

/// The chart as CSV, long form: one row per drawn point, `plot,curve,sommerfeld,value` (the reference line's
/// rows named [`REFERENCE_NAME`]).
#[must_use]
pub fn chart_csv(plots: &[ChartPlot]) -> String {
    let mut out = String::from("plot,curve,sommerfeld,value\n");
    for p in plots {
        let named = p.curves.iter().map(|(n, pts)| (*n, pts)).chain(std::iter::once((REFERENCE_NAME, &p.reference)));
        for (curve, pts) in named {
            for [s, v] in pts {
                out.push_str(&format!("\"{}\",\"{curve}\",{s:e},{v:e}\n", p.title));
            }
        }
    }
    out
}

/// The chart as JSON: the swept key, the geometry, the points that failed (value and why), the largest
/// deviation from the reference ([`reference_deviation`]) and each plot with its curves and reference line.
#[must_use]
pub fn chart_json(plots: &[ChartPlot], g: &ChartGeometry, table: &SweepTable) -> serde_json::Value {
    let deviation = reference_deviation(plots, g);
    let plots: Vec<serde_json::Value> = plots
        .iter()
        .map(|p| {
            serde_json::json!({
                "title": p.title,
                "curves": p.curves.iter().map(|(n, pts)| serde_json::json!({"name": n, "points": pts})).collect::<Vec<_>>(),
                "reference": p.reference,
            })
        })
        .collect();
    serde_json::json!({
        "swept": table.key,
        "clearance_um": UM.from_si(g.clearance_m),
        "speed_rad_s": g.speed_rad_s,
        "reference": g.plain_360_l_over_d.map(|ld| serde_json::json!({"name": REFERENCE_NAME, "l_over_d": ld})),
        "reference_deviation": deviation,
        "failed": table.failures().iter().map(|(x, why)| serde_json::json!({"value": x, "error": why})).collect::<Vec<_>>(),
        "plots": plots,
    })
}

fn plots_eps(plots: &[ChartPlot]) -> Vec<[f64; 2]> {
    plots.first().and_then(|p| p.curves.first()).map(|(_, pts)| pts.clone()).unwrap_or_default()
}

fn reference_deviation_of(eps_points: Vec<[f64; 2]>, g: &ChartGeometry) -> Option<f64> {
    let ld = g.plain_360_l_over_d?;
    eps_points
        .iter()
        .filter(|[_, eps]| *eps > 0.0 && *eps < 1.0)
        .map(|&[s, eps]| {
            let s_ref = short_bearing(eps, ld).0;
            ((s - s_ref) / s_ref).abs()
        })
        .reduce(f64::max)
}

/// The largest relative difference in S between the solved points and the short-bearing reference at the
/// same ε (plain 360° bearings only; `None` for other geometries or no solved point).
#[must_use]
pub fn reference_deviation(plots: &[ChartPlot], g: &ChartGeometry) -> Option<f64> {
    reference_deviation_of(plots_eps(plots), g)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::study::Runner;

    /// Ocvirk's closed form at ε = 0.5, L/D = 0.5, written out: f = 0.75² / (0.5 √(4 + 0.75 π²)) = 0.33317,
    /// S = f / (0.25 π) = 0.42420, φ = atan(π √0.75 / 2) = 53.68°.
    #[test]
    fn the_short_bearing_closed_form() {
        let (s, phi) = short_bearing(0.5, 0.5);
        let f = 0.5625 / (0.5 * (4.0 + 0.75 * PI * PI).sqrt());
        assert!((s - f / (0.25 * PI)).abs() < 1e-12 && (s - 0.424_20).abs() < 5e-6, "{s}");
        assert!((phi - 53.68).abs() < 0.01, "{phi}");
    }

    const PLAIN_360: &str = "[bearing]\njournal_radius_mm = 50.0\nlength_mm = 10.0\nassembled_clearance_um = 100.0\n\
        [bearing.pads]\ncount = 1\nkind = \"fixed\"\narc_deg = 360.0\npivot_deg = 0.0\npreload = 0.0\n\
        [lubricant]\nviscosity_pa_s = 0.02\nviscosity_temperature_c = 40.0\nviscosity_coefficient_per_k = 0.0\n\
        density_kg_per_m3 = 860.0\nspecific_heat_j_per_kg_k = 2000.0\nconductivity_w_per_m_k = 0.13\n\
        [operating]\nspeed_rpm = 3000.0\neccentricity_ratio = 0.5\nsupply_temperature_c = 40.0\n\
        [mesh]\ncircumferential_elements = 360\naxial_elements = 32\n";

    /// A plain 360° bearing of L/D = 0.1 swept in ε: on the chart each solved point lies on the short-bearing
    /// reference within what the finite length allows (the solution carries 1.4 % less load than the
    /// short-bearing limit at ε = 0.6, so S is up to about 2 % high), and the reduced values follow from the
    /// columns: h_min / Cb = 1 − ε, K̄ = K Cb / W.
    #[test]
    fn a_plain_bearing_lies_on_the_short_bearing_reference() {
        let case = crate::model::load_case(PLAIN_360, &[]).unwrap().1;
        let g = ChartGeometry::of(&case);
        assert!(g.plain_360_l_over_d.is_some_and(|ld| (ld - 0.1).abs() < 1e-12), "{g:?}");
        let mut runner = Runner::new(PLAIN_360, Vec::new(), false);
        let mut table = SweepTable::new("operating.eccentricity_ratio");
        for (i, eps) in [0.3, 0.6].into_iter().enumerate() {
            let (row, _) = runner.row(i, &[("operating.eccentricity_ratio".into(), format!("{eps:?}"))]);
            table.points.push((eps, row));
        }
        let plots = chart(&table, &g);
        let eps_curve = &plots[0].curves[0].1;
        assert_eq!(eps_curve.len(), 2);
        for &[s, eps] in eps_curve {
            let (s_ref, _) = short_bearing(eps, 0.1);
            assert!(((s - s_ref) / s_ref).abs() < 0.025, "ε = {eps}: S = {s}, short bearing {s_ref}");
        }
        for (&[_, h], &[_, eps]) in plots[2].curves[0].1.iter().zip(eps_curve) {
            assert!((h - (1.0 - eps)).abs() < 1e-3, "h_min / Cb = {h} at ε = {eps}");
        }
        // The reference runs from high S (small ε) to low S, sorted by S.
        assert!(plots[0].reference.windows(2).all(|w| w[0][0] < w[1][0]));
        // Tilting pads: no closed form, no reference line.
        let tilting = crate::model::load_case(include_str!("../../cases/compressor-bearing.toml"), &[]).unwrap().1;
        assert_eq!(ChartGeometry::of(&tilting).plain_360_l_over_d, None);
    }
}
