//! Injection orifice: fully developed laminar (Hagen–Poiseuille) flow in a capillary of diameter `d0` and
//! length `l0`, fed at pressure `p_inj`, discharging into the film at pressure `p`.
//!
//! Over the hole's footprint, centred at (s0, z0), the injected velocity is
//!
//! `v_inj(s, z) = g(s, z) (p_inj − p) / (4 µ_inj l0)`,  `g = d0²/4 − (s − s0)² − (z − z0)²` inside, 0 outside,
//!
//! which enters the Reynolds equation as `3 g (p − p_inj)/(µ_inj l0)` (docs/MODEL.md §2). With a uniform film
//! pressure over the hole, `∫ g dS = π d0⁴/32` and the flow is `q = π d0⁴ (p_inj − p) / (128 µ_inj l0)`.

use std::f64::consts::PI;

/// An orifice in pad-local film coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LocalOrifice {
    /// Centre, arc length from the leading edge [m].
    pub s0: f64,
    /// Centre, axial from the mid-plane [m].
    pub z0: f64,
    pub diameter: f64,
    pub length: f64,
}

impl LocalOrifice {
    /// The paraboloid weight g(s, z) ≥ 0 (zero outside the hole) [m²].
    #[must_use]
    pub fn g(&self, s: f64, z: f64) -> f64 {
        let r2 = 0.25 * self.diameter * self.diameter;
        (r2 - (s - self.s0).powi(2) - (z - self.z0).powi(2)).max(0.0)
    }

    /// True if the rectangle [s_a, s_b] × [z_a, z_b] touches the hole.
    #[must_use]
    pub fn touches(&self, s_a: f64, s_b: f64, z_a: f64, z_b: f64) -> bool {
        let r = 0.5 * self.diameter;
        let ds = (self.s0.clamp(s_a, s_b) - self.s0).abs();
        let dz = (self.z0.clamp(z_a, z_b) - self.z0).abs();
        ds * ds + dz * dz < r * r
    }
}

/// Hagen–Poiseuille flow through a capillary [m³/s] for a pressure drop `dp` [Pa].
#[must_use]
pub fn hagen_poiseuille_flow(diameter: f64, length: f64, viscosity: f64, dp: f64) -> f64 {
    PI * diameter.powi(4) * dp / (128.0 * viscosity * length)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paraboloid_integral_matches_closed_form() {
        // Midpoint rule on a fine grid: ∫ g dS = π d⁴/32.
        let o = LocalOrifice { s0: 0.0, z0: 0.0, diameter: 5e-3, length: 5e-3 };
        let n = 1000;
        let h = o.diameter / n as f64;
        let mut sum = 0.0;
        for i in 0..n {
            for j in 0..n {
                let s = -0.5 * o.diameter + (i as f64 + 0.5) * h;
                let z = -0.5 * o.diameter + (j as f64 + 0.5) * h;
                sum += o.g(s, z) * h * h;
            }
        }
        let exact = PI * o.diameter.powi(4) / 32.0;
        assert!((sum / exact - 1.0).abs() < 1e-4, "{sum} vs {exact}");
        // So the velocity profile integrates to Hagen–Poiseuille.
        let (mu, dp) = (0.02, 2e6);
        let q = sum * dp / (4.0 * mu * o.length);
        let q_hp = hagen_poiseuille_flow(o.diameter, o.length, mu, dp);
        assert!((q / q_hp - 1.0).abs() < 1e-4);
    }
}
