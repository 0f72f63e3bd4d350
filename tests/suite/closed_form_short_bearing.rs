//! Plain 360° bearing against the infinitely short bearing (Ocvirk) closed forms (docs/REFERENCES.md §2):
//! `D ω µ L³ / (8 c² W) = (1−ε²)² / (ε sqrt(16ε² + π²(1−ε²)))`, `tan φ = π sqrt(1−ε²) / (4ε)`.
//!
//! The finite-length solution differs from the short-bearing limit by O((L/D)²): at L/D = 0.1 the
//! mesh-converged solution is 1.4 % low at ε = 0.6, 2.0 % low at ε = 0.7 and 3.2 % low at ε = 0.8 (Reynolds
//! cavitation; Gümbel is further off), so the 2 % criterion is asserted at L/D = 0.1 for ε ≤ 0.6, and the whole
//! range ε 0.1–0.8 is asserted at L/D = 0.05 (1 %), together with the measured second-order approach to the
//! limit as L/D → 0.

use crate::common;

use std::f64::consts::PI;

use tiltpad::bearing::solve_case;
use tiltpad::model::load_case;

/// Relative load error and attitude error [deg] against Ocvirk at eccentricity ε and L [mm].
fn against_ocvirk(eps: f64, length_mm: f64, cavitation: &str) -> (f64, f64) {
    let set = vec![
        format!("operating.eccentricity_ratio={eps}"),
        format!("bearing.length_mm={length_mm}"),
        format!("physics.cavitation=\"{cavitation}\""),
    ];
    let (_, case) = load_case(common::PLAIN_360, &set).unwrap();
    let s = solve_case(&case).unwrap();
    let (r, l, c, mu) = (0.05, length_mm * 1e-3, 100e-6, 0.02);
    let w = 3000.0 / 60.0 * 2.0 * PI;
    let rhs = (1.0 - eps * eps).powi(2) / (eps * (16.0 * eps * eps + PI * PI * (1.0 - eps * eps)).sqrt());
    let load = 2.0 * r * w * mu * l.powi(3) / (8.0 * c * c * rhs);
    let phi = (PI * (1.0 - eps * eps).sqrt() / (4.0 * eps)).atan().to_degrees();
    (common::rel(s.load_magnitude_n, load), s.attitude_angle_deg - phi)
}

#[test]
fn short_bearing_load_and_attitude_at_ld_0_1() {
    for eps in [0.1, 0.3, 0.5, 0.6] {
        let (dw, dphi) = against_ocvirk(eps, 10.0, "reynolds");
        assert!(dw.abs() < 0.02, "ε = {eps}: load error {:.2} %", 100.0 * dw);
        assert!(dphi.abs() < 0.02 * 90.0, "ε = {eps}: attitude error {dphi:.2}°");
    }
}

#[test]
fn short_bearing_limit_over_full_range_at_ld_0_05() {
    for eps in [0.1, 0.2, 0.4, 0.6, 0.8] {
        let (dw, dphi) = against_ocvirk(eps, 5.0, "reynolds");
        assert!(dw.abs() < 0.01, "ε = {eps}: load error {:.2} %", 100.0 * dw);
        assert!(dphi.abs() < 0.3, "ε = {eps}: attitude error {dphi:.3}°");
    }
}

#[test]
fn finite_length_error_shrinks_as_ld_squared() {
    // Halving L/D divides the departure from the short-bearing limit by about 4.
    for cav in ["reynolds", "gumbel"] {
        let (d1, _) = against_ocvirk(0.8, 10.0, cav);
        let (d2, _) = against_ocvirk(0.8, 5.0, cav);
        let order = (d1 / d2).abs().log2();
        assert!(d1 < 0.0 && d2 < 0.0, "{cav}: finite bearings carry less than the short-bearing limit");
        assert!((1.7..2.3).contains(&order), "{cav}: observed order {order:.2} in L/D");
    }
}
