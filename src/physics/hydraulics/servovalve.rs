//! The servovalve, linearised about the centred spool (thesis §2.2.1, docs/MODEL.md §8).
//!
//! ## Equations
//! Spool (driven-flow) dynamics, with the spool position `x_V` measured in volts of command (the valve's
//! built-in spool-position signal, so that `x_V = u_V` in a steady state, as the thesis measured `G1` in V/V):
//!
//! ```text
//! ẍ_V + 2 ξ_V ω_V ẋ_V + ω_V² x_V = ω_V² u_V          G1(s) = x_V/u_V = ω_V² / (s² + 2 ξ_V ω_V s + ω_V²)
//! q_V = K_V x_V                                      driven flow
//! q'_k = q_leak + σ_k q_V − K_c σ_k Σ_j σ_j p0_j      port k (σ = +1 for A, −1 for B)
//! ```
//!
//! For the two ports A, B this is the thesis' `q'_A = q_leak + q_V + K_pq (p_A − p_B)`,
//! `q'_B = q_leak − q_V − K_pq (p_A − p_B)` with `K_pq = −K_c`: a rising load pressure lowers the flow into
//! the load, so `K_pq = ∂q_L/∂p_L` is negative for a real valve; the case gives the magnitude `K_c ≥ 0`.
//! The pressures `p0` are those at the valve's ports (the line's valve end).
//!
//! Flow gain from the datasheet (turbulent metering edges, Bernoulli, thesis eq. 2.14): rated flow `Q_N`
//! at full-scale signal `u_max` and rated valve drop `Δp_N`; at supply `P_s` and return `P_T` with the
//! load pressure at null, `K_V = (Q_N / u_max) √((P_s − P_T)/Δp_N)` [m³/s per V of spool signal].
//!
//! Valid for small signals (≲ 10 % of full scale, thesis §2.2.1); [`Servovalve::small_signal_limit`].
//! The constant leakage `q_leak` sets the static flow only; the linear responses do not depend on it.

use nalgebra::Complex;

/// Fraction of the full-scale signal up to which the linearised valve model holds (thesis §2.2.1).
pub const SMALL_SIGNAL_FRACTION: f64 = 0.1;

/// A linearised four-way servovalve at its operating point (SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Servovalve {
    /// ω_V [rad/s].
    pub natural_frequency_rad_s: f64,
    /// ξ_V.
    pub damping_ratio: f64,
    /// K_V: driven flow per volt of spool signal at the operating supply [m³/(s·V)].
    pub flow_gain: f64,
    /// K_c ≥ 0: flow lost per unit load pressure [m³/(s·Pa)].
    pub flow_pressure_coefficient: f64,
    /// Null leakage into each port [m³/s] (static only).
    pub leakage: f64,
    /// Full-scale control signal [V].
    pub full_scale_v: f64,
}

impl Servovalve {
    /// `G1(s) = x_V/u_V`.
    #[must_use]
    pub fn spool_response(&self, s: Complex<f64>) -> Complex<f64> {
        let w = self.natural_frequency_rad_s;
        let w2 = Complex::from(w * w);
        w2 / (s * s + s * (2.0 * self.damping_ratio * w) + w2)
    }

    /// Largest control amplitude [V] for which the small-signal model holds.
    #[must_use]
    pub fn small_signal_limit(&self) -> f64 {
        SMALL_SIGNAL_FRACTION * self.full_scale_v
    }
}

/// `K_V` from datasheet values: rated flow [m³/s] at full scale [V] and rated drop [Pa], at the operating
/// supply and return pressures [Pa]. Zero when the supply does not exceed the return.
#[must_use]
pub fn flow_gain(rated_flow: f64, full_scale_v: f64, rated_drop: f64, supply: f64, ret: f64) -> f64 {
    (rated_flow / full_scale_v) * ((supply - ret).max(0.0) / rated_drop).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn valve() -> Servovalve {
        Servovalve {
            natural_frequency_rad_s: std::f64::consts::TAU * 150.0,
            damping_ratio: 0.7,
            flow_gain: 1e-5,
            flow_pressure_coefficient: 0.0,
            leakage: 0.0,
            full_scale_v: 10.0,
        }
    }

    /// The second-order closed form: unit gain at rest, −90° and 1/(2ξ) at ω_V, −40 dB/decade far above.
    #[test]
    fn spool_response_is_the_second_order_closed_form() {
        let v = valve();
        let w = v.natural_frequency_rad_s;
        assert_eq!(v.spool_response(Complex::new(0.0, 0.0)), Complex::new(1.0, 0.0));
        let at = v.spool_response(Complex::new(0.0, w));
        assert!((at.arg() + std::f64::consts::FRAC_PI_2).abs() < 1e-14, "{at}");
        assert!((at.norm() - 1.0 / (2.0 * v.damping_ratio)).abs() < 1e-14);
        for f in [0.1, 0.5, 2.0, 10.0] {
            let r = f * w;
            let g = v.spool_response(Complex::new(0.0, r));
            let mag = 1.0 / (1.0 - f * f).hypot(2.0 * v.damping_ratio * f);
            let phase = -(2.0 * v.damping_ratio * f).atan2(1.0 - f * f);
            assert!((g.norm() / mag - 1.0).abs() < 1e-14 && (g.arg() - phase).abs() < 1e-14, "f/fV = {f}: {g}");
        }
    }

    /// Bernoulli scaling of the flow gain: four times the pressure drop doubles it.
    #[test]
    fn flow_gain_scales_with_the_root_of_the_drop() {
        let q = crate::units::L_PER_MIN.to_si(10.0);
        let k70 = flow_gain(q, 10.0, 70e5, 70e5, 0.0);
        assert!((k70 - q / 10.0).abs() < 1e-18);
        assert!((flow_gain(q, 10.0, 70e5, 280e5, 0.0) / k70 - 2.0).abs() < 1e-14);
        assert_eq!(flow_gain(q, 10.0, 70e5, 0.0, 1e5), 0.0);
    }
}
