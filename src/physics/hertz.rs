//! Hertz contact of a pad's pivot: the pivot's radial approach δ under the load F it carries, and its
//! stiffness — nonlinear in the load.
//!
//! The pivot is a convex body of radius `R₁` (the pad's rocker back, or the ball) in a concave seat of radius
//! `R₂ > R₁` (the housing's seat or socket). Materials: the convex body has the pad's E₁, ν₁, the seat E₂,
//! ν₂. Contact modulus and (conformal) relative radius:
//!
//! ```text
//! 1/E* = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂,        R = R₁ R₂ / (R₂ − R₁)   (1/R = 1/R₁ − 1/R₂)
//! ```
//!
//! **Ball in socket** (sphere in a spherical seat; Johnson, *Contact Mechanics*, 1985, §4.2, the point contact
//! of solids of revolution):
//! ```text
//! a³ = 3FR / (4E*),   δ = a²/R = (9F² / (16 R E*²))^{1/3},   F = (4/3) E* √R δ^{3/2},
//! k = dF/dδ = 2 E* a = (6 F R E*²)^{1/3}   (tangent),   F/δ = (2/3) k   (secant)
//! ```
//!
//! **Rocker** (cylinder in a cylindrical seat along the pad's length `L`, line contact; Johnson 1985, §4.3
//! for the contact half-width; the approach of the two cylinders' axes in the form of Johnson's 2-D
//! compression of a cylinder, each body's term `cᵢ(2 ln(4Rᵢ/a) − 1)`): with the load per length `P = F/L`,
//! ```text
//! a² = 4 P R / (π E*),
//! δ = (P/π) Σᵢ cᵢ (2 ln(4Rᵢ/a) − 1),     cᵢ = (1 − νᵢ²)/Eᵢ,   i = pivot (R₁), seat (R₂)
//! dδ/dP = (1/π) Σᵢ cᵢ (2 ln(4Rᵢ/a) − 2)   (a ∝ √P),     k = L / (dδ/dP)
//! ```
//! δ is the approach of the two axes of curvature; a line contact has no approach without such a datum, and
//! the seat's centre of curvature is the natural one for a pivot. The formula holds while `a ≪ Rᵢ` (checked:
//! [`HertzError::ContactTooWide`] when `a > 0.2 R₁`).
//!
//! Contract: SI in and out; F > 0 (a pivot carries compression only; the caller floors the load).

use serde::{Deserialize, Serialize};
use thiserror::Error;

// The contact's data belong to the case (`model`); this module is its law.
pub use crate::model::case::{ContactKind, PivotContact};

/// A contact outside the formula's validity.
#[derive(Debug, Clone, PartialEq, Error, Serialize, Deserialize)]
pub enum HertzError {
    #[error("pivot contact half-width {half_width_m:.3e} m exceeds 0.2 of the pivot radius {pivot_radius_m:.3e} m at load {load_n:.4e} N: Hertz theory does not hold")]
    ContactTooWide { half_width_m: f64, pivot_radius_m: f64, load_n: f64 },
    #[error("pivot load {load_n} N: a pivot contact carries compression only")]
    NotCompressive { load_n: f64 },
}

/// The contact's state at one load.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct ContactState {
    pub load_n: f64,
    /// Approach δ [m].
    pub approach_m: f64,
    /// Tangent stiffness dF/dδ [N/m].
    pub tangent_n_per_m: f64,
    /// Contact half-width (rocker) or radius (ball) a [m].
    pub half_width_m: f64,
}

impl ContactState {
    /// Secant stiffness F/δ [N/m]: the linear spring that carries the load with the same approach.
    #[must_use]
    pub fn secant_n_per_m(&self) -> f64 {
        self.load_n / self.approach_m
    }
}

impl PivotContact {
    fn compliance(e: f64, nu: f64) -> f64 {
        (1.0 - nu * nu) / e
    }

    /// Contact modulus E* [Pa].
    #[must_use]
    pub fn contact_modulus_pa(&self) -> f64 {
        1.0 / (Self::compliance(self.pivot_youngs_modulus_pa, self.pivot_poisson_ratio)
            + Self::compliance(self.seat_youngs_modulus_pa, self.seat_poisson_ratio))
    }

    /// Relative radius of the conformal contact R = R₁R₂/(R₂ − R₁) [m].
    #[must_use]
    pub fn relative_radius_m(&self) -> f64 {
        self.pivot_radius_m * self.seat_radius_m / (self.seat_radius_m - self.pivot_radius_m)
    }

    /// Approach, tangent stiffness and contact size at load `load_n` > 0.
    ///
    /// # Errors
    /// [`HertzError`] for a load that is not compressive or a contact too wide for the formula.
    pub fn state(&self, load_n: f64) -> Result<ContactState, HertzError> {
        if load_n.is_nan() || load_n <= 0.0 || load_n.is_infinite() {
            return Err(HertzError::NotCompressive { load_n });
        }
        let e = self.contact_modulus_pa();
        let r = self.relative_radius_m();
        let state = match self.kind {
            ContactKind::Ball => {
                let a = (3.0 * load_n * r / (4.0 * e)).cbrt();
                ContactState { load_n, approach_m: a * a / r, tangent_n_per_m: 2.0 * e * a, half_width_m: a }
            }
            ContactKind::Rocker => {
                let p = load_n / self.length_m;
                let a = (4.0 * p * r / (std::f64::consts::PI * e)).sqrt();
                let c = [
                    (Self::compliance(self.pivot_youngs_modulus_pa, self.pivot_poisson_ratio), self.pivot_radius_m),
                    (Self::compliance(self.seat_youngs_modulus_pa, self.seat_poisson_ratio), self.seat_radius_m),
                ];
                let sum = |shift: f64| c.iter().map(|&(ci, ri)| ci * (2.0 * (4.0 * ri / a).ln() - shift)).sum::<f64>();
                let approach = p / std::f64::consts::PI * sum(1.0);
                let d_approach_dp = sum(2.0) / std::f64::consts::PI;
                ContactState {
                    load_n,
                    approach_m: approach,
                    tangent_n_per_m: self.length_m / d_approach_dp,
                    half_width_m: a,
                }
            }
        };
        if state.half_width_m > 0.2 * self.pivot_radius_m {
            return Err(HertzError::ContactTooWide {
                half_width_m: state.half_width_m,
                pivot_radius_m: self.pivot_radius_m,
                load_n,
            });
        }
        Ok(state)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn steel(kind: ContactKind, r1: f64, r2: f64) -> PivotContact {
        PivotContact {
            kind,
            pivot_radius_m: r1,
            seat_radius_m: r2,
            length_m: 0.04,
            pivot_youngs_modulus_pa: 200e9,
            pivot_poisson_ratio: 0.3,
            seat_youngs_modulus_pa: 200e9,
            seat_poisson_ratio: 0.3,
        }
    }

    /// Ball: a 25 mm ball in a 26 mm socket, steel, 10 kN — against the closed form worked by hand:
    /// E* = 200e9 / (2 · 0.91) = 1.0989e11 Pa, R = 0.025 · 0.026 / 0.001 = 0.65 m,
    /// a = (3 · 1e4 · 0.65 / (4 · 1.0989e11))^{1/3} = 3.5400e-3 m, δ = a²/R = 1.9280e-5 m,
    /// k = 2E*a = 7.7803e8 N/m; and the two stiffnesses against the derivative of δ(F).
    #[test]
    fn ball_in_socket_matches_hertz() {
        let c = steel(ContactKind::Ball, 0.025, 0.026);
        let s = c.state(1e4).unwrap();
        let e_star = 200e9 / (2.0 * 0.91);
        let r: f64 = 0.65;
        let a = (3.0 * 1e4 * r / (4.0 * e_star)).cbrt();
        assert!((c.contact_modulus_pa() / e_star - 1.0).abs() < 1e-14);
        assert!((c.relative_radius_m() / r - 1.0).abs() < 1e-12);
        assert!((s.half_width_m / 3.5400e-3 - 1.0).abs() < 1e-4, "{}", s.half_width_m);
        assert!((s.approach_m / 1.9280e-5 - 1.0).abs() < 1e-4, "{}", s.approach_m);
        assert!((s.tangent_n_per_m / 7.7803e8 - 1.0).abs() < 1e-4, "{}", s.tangent_n_per_m);
        // δ = (9F²/(16RE*²))^{1/3} and k = (6FRE*²)^{1/3}, the two other closed forms.
        assert!((s.approach_m / (9.0 * 1e8 / (16.0 * r * e_star * e_star)).cbrt() - 1.0).abs() < 1e-12);
        assert!((s.tangent_n_per_m / (6.0 * 1e4 * r * e_star * e_star).cbrt() - 1.0).abs() < 1e-12);
        assert!((a - s.half_width_m).abs() < 1e-15);
        // Nonlinear: k ∝ F^{1/3}, the secant is 2/3 of the tangent.
        let s8 = c.state(1.25e3).unwrap();
        assert!((s.tangent_n_per_m / s8.tangent_n_per_m - 2.0).abs() < 1e-12);
        assert!((s.secant_n_per_m() / s.tangent_n_per_m - 2.0 / 3.0).abs() < 1e-12);
        let h = 1.0;
        let fd = 2.0 * h / (c.state(1e4 + h).unwrap().approach_m - c.state(1e4 - h).unwrap().approach_m);
        assert!((fd / s.tangent_n_per_m - 1.0).abs() < 1e-6, "{fd}");
    }

    /// Rocker: a 20 mm rocker in a 21 mm seat, 40 mm long, steel, 10 kN, against the line-contact form
    /// evaluated by hand: P = 2.5e5 N/m, R = 0.42 m, a = √(4PR/πE*) = 1.1030e-3 m,
    /// δ = (P/π)(1 − ν²)/E [(2 ln(4R₁/a) − 1) + (2 ln(4R₂/a) − 1)] = 5.5157e-6 m,
    /// k = πL / ((1 − ν²)/E · [(2 ln(4R₁/a) − 2) + (2 ln(4R₂/a) − 2)]) = 2.0870e9 N/m; tangent against the
    /// derivative of δ(F); stiffening with load.
    #[test]
    fn rocker_line_contact_matches_hertz() {
        let c = steel(ContactKind::Rocker, 0.020, 0.021);
        let s = c.state(1e4).unwrap();
        let (e_star, ci) = (200e9 / (2.0 * 0.91), 0.91 / 200e9);
        let a = (4.0 * 2.5e5 * 0.42 / (std::f64::consts::PI * e_star)).sqrt();
        let ln = |r: f64| 2.0 * (4.0 * r / a).ln();
        let delta = 2.5e5 / std::f64::consts::PI * ci * (ln(0.020) - 1.0 + ln(0.021) - 1.0);
        let k = std::f64::consts::PI * 0.04 / (ci * (ln(0.020) - 2.0 + ln(0.021) - 2.0));
        eprintln!("rocker: a {a:.5e} m, δ {delta:.5e} m, k {k:.5e} N/m");
        assert!((s.half_width_m / 1.1030e-3 - 1.0).abs() < 1e-4, "{}", s.half_width_m);
        assert!((s.approach_m / 5.5157e-6 - 1.0).abs() < 1e-4, "{}", s.approach_m);
        assert!((s.tangent_n_per_m / 2.0870e9 - 1.0).abs() < 1e-4, "{}", s.tangent_n_per_m);
        assert!((s.approach_m / delta - 1.0).abs() < 1e-12 && (s.tangent_n_per_m / k - 1.0).abs() < 1e-12);
        let h = 1.0;
        let fd = 2.0 * h / (c.state(1e4 + h).unwrap().approach_m - c.state(1e4 - h).unwrap().approach_m);
        assert!((fd / s.tangent_n_per_m - 1.0).abs() < 1e-6, "{fd}");
        // Stiffens with load, more slowly than a ball (logarithmically).
        assert!(c.state(4e4).unwrap().tangent_n_per_m > 1.05 * s.tangent_n_per_m);
    }

    #[test]
    fn invalid_loads_and_wide_contacts_are_errors() {
        let c = steel(ContactKind::Ball, 0.025, 0.026);
        assert!(matches!(c.state(0.0), Err(HertzError::NotCompressive { .. })));
        assert!(matches!(c.state(f64::NAN), Err(HertzError::NotCompressive { .. })));
        let conformal = steel(ContactKind::Ball, 0.025, 0.02501);
        assert!(matches!(conformal.state(1e6), Err(HertzError::ContactTooWide { .. })));
    }
}
