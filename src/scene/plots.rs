//! Coefficient plots and the full-matrix table.
//!
//! The reduced 2×2 journal coefficients (rows and columns x, y of the bearing frame) as series against
//! the excitation-frequency ratio ω/Ω (one equilibrium, dynamic condensation of the pad coordinates at each
//! ω; docs/MODEL.md §7) or against the running speed (one equilibrium per speed, synchronous or at the case's
//! ω/Ω). Display units: stiffness in MN/m, damping in kN·s/m.

use crate::bearing::solution::coefficients::{FullCoefficients, ReducedCoefficients};
use crate::bearing::stages::SpeedPoint;
use crate::units::{Unit, KNS_PER_M, MN_PER_M, RPM};
/// Names of the four entries, in the order of the series.
pub const ENTRIES: [&str; 4] = ["xx", "xy", "yx", "yy"];

/// One named curve.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    pub name: String,
    pub points: Vec<[f64; 2]>,
}

/// Stiffness and damping curves against one abscissa, and the current operating point.
#[derive(Debug, Clone, PartialEq)]
pub struct CoefficientPlot {
    pub x_label: &'static str,
    /// K_xx, K_xy, K_yx, K_yy [MN/m].
    pub stiffness: Vec<Series>,
    /// C_xx, C_xy, C_yx, C_yy [kN·s/m].
    pub damping: Vec<Series>,
    /// The case's own point: abscissa, then the four stiffness and four damping values.
    pub current: Option<(f64, [f64; 4], [f64; 4])>,
    /// Sweep points that failed, with the reason (touchdown, …).
    pub failures: Vec<(f64, String)>,
}

/// The four entries of `m` (SI) in `unit`.
fn entries(m: [[f64; 2]; 2], unit: Unit) -> [f64; 4] {
    [m[0][0], m[0][1], m[1][0], m[1][1]].map(|v| unit.from_si(v))
}

fn build(
    x_label: &'static str,
    points: &[(f64, ReducedCoefficients)],
    current: Option<(f64, ReducedCoefficients)>,
    failures: Vec<(f64, String)>,
) -> CoefficientPlot {
    let series = |prefix: &str, pick: &dyn Fn(&ReducedCoefficients) -> [f64; 4]| -> Vec<Series> {
        (0..4)
            .map(|e| Series {
                name: format!("{prefix}{}", ENTRIES[e]),
                points: points.iter().map(|(x, c)| [*x, pick(c)[e]]).collect(),
            })
            .collect()
    };
    let k = |c: &ReducedCoefficients| entries(c.k_n_per_m, MN_PER_M);
    let c = |c: &ReducedCoefficients| entries(c.c_ns_per_m, KNS_PER_M);
    CoefficientPlot {
        x_label,
        stiffness: series("K", &k),
        damping: series("C", &c),
        current: current.map(|(x, r)| (x, k(&r), c(&r))),
        failures,
    }
}

/// Reduced coefficients against ω/Ω from a frequency sweep; `current` is the case's ratio and values.
#[must_use]
pub fn frequency_plot(
    sweep: &[(f64, ReducedCoefficients)],
    current: Option<(f64, ReducedCoefficients)>,
) -> CoefficientPlot {
    build("excitation frequency ratio ω/Ω", sweep, current, Vec::new())
}

/// Reduced coefficients against speed [rpm] from a speed sweep.
#[must_use]
pub fn speed_plot(sweep: &[SpeedPoint], current: Option<(f64, ReducedCoefficients)>) -> CoefficientPlot {
    let ok: Vec<(f64, ReducedCoefficients)> =
        sweep.iter().filter_map(|p| p.result.as_ref().ok().map(|v| (RPM.from_si(p.speed_rad_s), v.reduced))).collect();
    let failures = sweep
        .iter()
        .filter_map(|p| p.result.as_ref().err().map(|e| (RPM.from_si(p.speed_rad_s), e.to_string())))
        .collect();
    build("speed [rpm]", &ok, current, failures)
}

/// Evenly spaced ratios for the frequency sweep: `n` points on `[lo, hi]`, always including 1 (synchronous).
#[must_use]
#[allow(clippy::cast_precision_loss)]
pub fn frequency_ratios(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    let n = n.max(2);
    let mut v: Vec<f64> = (0..n).map(|i| lo + (hi - lo) * i as f64 / (n - 1) as f64).collect();
    if lo <= 1.0 && hi >= 1.0 && !v.iter().any(|x| (x - 1.0).abs() < 1e-12) {
        v.push(1.0);
        v.sort_by(f64::total_cmp);
    }
    v
}

/// Speeds for the speed sweep around the case's speed: `n` points on `[0.5, 1.5] × rpm` (positive).
#[must_use]
#[allow(clippy::cast_precision_loss)]
pub fn sweep_speeds(speed: f64, n: usize) -> Vec<f64> {
    let n = n.max(2);
    let (lo, hi) = (0.5 * speed, 1.5 * speed);
    (0..n).map(|i| lo + (hi - lo) * i as f64 / (n - 1) as f64).filter(|&s| s > 0.0).collect()
}

/// The full matrices as a table: coordinate names with units, rows of values (SI).
#[derive(Debug, Clone, PartialEq)]
pub struct MatrixTable {
    /// `x [m]`, `y [m]`, `pad 0 tilt [rad]`, …
    pub headers: Vec<String>,
    pub k: Vec<Vec<f64>>,
    pub c: Vec<Vec<f64>>,
    pub m: Vec<Vec<f64>>,
}

/// Headers with the unit of each coordinate.
#[must_use]
pub fn matrix_table(full: &FullCoefficients) -> MatrixTable {
    let headers = full.coords.iter().map(|c| format!("{} [{}]", c.label(), c.unit())).collect();
    MatrixTable { headers, k: full.k.clone(), c: full.c.clone(), m: full.m.clone() }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bearing::stages::SweepValues;

    fn rc(k: f64, c: f64) -> ReducedCoefficients {
        ReducedCoefficients {
            omega_rad_s: 1.0,
            k_n_per_m: [[k, 2.0 * k], [3.0 * k, 4.0 * k]],
            c_ns_per_m: [[c, 0.0], [0.0, c]],
        }
    }

    #[test]
    fn series_carry_display_units_and_order() {
        let p = frequency_plot(&[(0.5, rc(1e8, 1e5)), (1.0, rc(2e8, 2e5))], Some((1.0, rc(2e8, 2e5))));
        assert_eq!(p.stiffness.iter().map(|s| s.name.as_str()).collect::<Vec<_>>(), ["Kxx", "Kxy", "Kyx", "Kyy"]);
        assert_eq!(p.stiffness[1].points, vec![[0.5, 200.0], [1.0, 400.0]]);
        assert_eq!(p.damping[3].points[0], [0.5, 100.0]);
        assert_eq!(p.current.unwrap().1, [200.0, 400.0, 600.0, 800.0]);
    }

    #[test]
    fn failed_speed_points_are_kept_apart() {
        let v = |k| {
            Ok(SweepValues {
                eccentricity_ratio: 0.1,
                attitude_angle_deg: 0.0,
                h_min_m: 1e-5,
                p_max_pa: 1e6,
                friction_power_w: 1.0,
                reduced: rc(k, 1e4),
            })
        };
        let sweep = vec![
            SpeedPoint { speed_rad_s: RPM.to_si(1000.0), result: Err(crate::bearing::SolveError::Cancelled) },
            SpeedPoint { speed_rad_s: RPM.to_si(2000.0), result: v(1e8) },
        ];
        let p = speed_plot(&sweep, None);
        assert!((p.stiffness[0].points[0][0] - 2000.0).abs() < 1e-9 && p.stiffness[0].points[0][1] == 100.0);
        assert!(
            (p.failures[0].0 - 1000.0).abs() < 1e-9
                && p.failures[0].1.starts_with("solve cancelled (stopped from outside")
        );
    }

    #[test]
    fn sweep_grids() {
        let r = frequency_ratios(0.0, 3.0, 4);
        assert_eq!(r, vec![0.0, 1.0, 2.0, 3.0]);
        assert!(frequency_ratios(0.0, 2.5, 6).contains(&1.0));
        assert_eq!(sweep_speeds(1000.0, 3), vec![500.0, 1000.0, 1500.0]);
    }
}
