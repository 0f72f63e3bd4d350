//! One injection line between a valve port (x = 0) and a nozzle (x = l) (thesis §2.2.2 and Appendix C,
//! docs/MODEL.md §8).
//!
//! ## Equations
//! Flow `q(x, t)` and pressure `p(x, t)` in a line of area `A`, oil density `ρ`, wave speed `c0 = √(β/ρ)`,
//! with a linear friction `d` [1/s]:
//!
//! ```text
//! ∂p/∂t + (ρ c0²/A) ∂q/∂x = 0          continuity
//! ∂q/∂t + (A/ρ) ∂p/∂x = −d q           momentum; laminar friction d = 32 ν / D² (Hagen–Poiseuille)
//! q(0, t) = q0 (valve port flow),  p(l, t) = p_l (nozzle pressure)
//! ```
//!
//! Effective bulk modulus with an air volume fraction `r` and the wall's compliance (thesis eq. 2.24):
//! `β = [ (1 − r)/β_oil + r/β_air + C_wall ]⁻¹`, `β_air = n_poly p_abs` at the line's static pressure.
//!
//! **Modal model** (separation of variables, modes `H_i = sin(ω_i x / c0)` of the closed–open line,
//! `ω_i = (2i − 1) π c0 / (2l)`, projected with `∫₀ˡ H_i² dx = l/2`):
//!
//! ```text
//! γ̈_i + d γ̇_i + ω_i² γ_i = (2/l) [ c0 ω_i q0 − (A/ρ) ṗ_l (−1)^(i+1) ]      q(l) = Σ (−1)^(i+1) γ_i
//! p(0) = p_l + (ρ/A) (∂/∂t + d) Σ γ_i c0/ω_i                                 (momentum integrated over the line)
//! ```
//!
//! The thesis (eq. C.14) prints the modal equation without the factor `2/l`; that form is not
//! dimensionally consistent (its right-hand side has one length too many) and delivers `l/2` times the valve
//! flow at the nozzle in a steady state. With `2/l` the steady nozzle flow equals the port flow and the
//! modal sum converges to the distributed solution below (tests).
//!
//! Truncating at `n` modes loses the quasi-static part of the higher modes; the *static correction* adds it
//! back (the residual modes' steady response: the line's remaining compliance, inertance and friction), so
//! the truncated line is exact at zero frequency. Both are available ([`Truncation`]).
//!
//! **Distributed solution** (the same equations solved exactly, a transmission line): with
//! `Γ = √(s (s + d)) / c0` and `Z_c = ρ c0² Γ / (A s)`,
//! `q(l) = q0 / cosh Γl − p_l tanh(Γl)/Z_c`, `p(0) = Z_c tanh(Γl) q0 + p_l / cosh Γl`.
//!
//! Both are returned as a [`TwoPort`] in the Laplace variable `s`.

use std::f64::consts::PI;

use nalgebra::Complex;

type C64 = Complex<f64>;

/// The line as a two-port: `q_l = a q0 − b p_l`, `p0 = c q0 + e p_l` (flows towards the nozzle).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TwoPort {
    pub a: C64,
    /// [m³/(s·Pa)]
    pub b: C64,
    /// [Pa·s/m³]
    pub c: C64,
    pub e: C64,
}

/// How the modal sum is truncated.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Truncation {
    /// The first n modes only (the thesis' model).
    Plain,
    /// The first n modes plus the quasi-static response of the others (exact at zero frequency).
    StaticCorrection,
}

/// Effective bulk modulus [Pa] of oil with an air volume fraction `r` in a compliant pipe.
#[must_use]
pub fn effective_bulk_modulus(oil: f64, air_fraction: f64, air: f64, wall_compliance: f64) -> f64 {
    let air_term = if air_fraction > 0.0 { air_fraction / air } else { 0.0 };
    1.0 / ((1.0 - air_fraction) / oil + air_term + wall_compliance)
}

/// One injection line (SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Line {
    /// l [m]
    pub length: f64,
    /// A [m²]
    pub area: f64,
    /// ρ [kg/m³]
    pub density: f64,
    /// Effective bulk modulus β [Pa].
    pub bulk_modulus: f64,
    /// Linear friction d [1/s].
    pub friction: f64,
    /// Acoustic modes kept.
    pub modes: usize,
}

impl Line {
    /// Laminar (Hagen–Poiseuille) friction `d = 32 µ / (ρ D²)` [1/s].
    #[must_use]
    pub fn laminar_friction(viscosity: f64, density: f64, diameter: f64) -> f64 {
        32.0 * viscosity / (density * diameter * diameter)
    }

    /// c0 = √(β/ρ) [m/s].
    #[must_use]
    pub fn wave_speed(&self) -> f64 {
        (self.bulk_modulus / self.density).sqrt()
    }

    /// ω_i = (2i − 1) π c0 / (2l) [rad/s], i = 1, 2, …
    #[must_use]
    pub fn mode_frequency(&self, i: usize) -> f64 {
        #[allow(clippy::cast_precision_loss)]
        let k = (2 * i - 1) as f64;
        k * PI * self.wave_speed() / (2.0 * self.length)
    }

    /// The truncated modal two-port at `s`.
    #[must_use]
    pub fn modal(&self, s: C64, truncation: Truncation) -> TwoPort {
        let (l, a_p, rho, d) = (self.length, self.area, self.density, self.friction);
        let c0 = self.wave_speed();
        let (mut a, mut b, mut c, mut e) = (C64::from(0.0), C64::from(0.0), C64::from(0.0), C64::from(1.0));
        // Partial sums of the steady parts, for the static correction.
        let (mut sa, mut s2, mut s3) = (0.0, 0.0, 0.0);
        let sd = s * (s + d);
        for i in 1..=self.modes {
            let w = self.mode_frequency(i);
            let sign = if i % 2 == 1 { 1.0 } else { -1.0 };
            let inv = (s * s + s * d + w * w).inv();
            a += inv * (2.0 / l * c0 * w * sign);
            b += inv * s * (2.0 * a_p / (rho * l));
            c += inv * (s + d) * (2.0 * rho * c0 * c0 / (a_p * l));
            e -= inv * sd * (2.0 * c0 * sign / (l * w));
            sa += 2.0 * c0 * sign / (l * w);
            s2 += 1.0 / (w * w);
            s3 += sign / (w * w * w);
        }
        if truncation == Truncation::StaticCorrection {
            // Σ_all (2 c0/l)(−1)^(i+1)/ω_i = 1, Σ_all 1/ω_i² = l²/(2 c0²), Σ_all (−1)^(i+1)/ω_i³ = l³/(4 c0³).
            let rest2 = l * l / (2.0 * c0 * c0) - s2;
            a += 1.0 - sa;
            b += s * (2.0 * a_p / (rho * l) * rest2);
            c += (s + d) * (2.0 * rho * c0 * c0 / (a_p * l) * rest2);
            e -= sd * (2.0 * c0 / l * (l * l * l / (4.0 * c0 * c0 * c0) - s3));
        }
        TwoPort { a, b, c, e }
    }

    /// The distributed (exact) two-port at `s`.
    #[must_use]
    pub fn exact(&self, s: C64) -> TwoPort {
        let (l, a_p, rho, d) = (self.length, self.area, self.density, self.friction);
        let c0 = self.wave_speed();
        if s.norm() == 0.0 {
            return TwoPort { a: 1.0.into(), b: 0.0.into(), c: (rho * d * l / a_p).into(), e: 1.0.into() };
        }
        let gamma = (s * (s + d)).sqrt() / c0;
        let zc = gamma * (rho * c0 * c0 / a_p) / s;
        let gl = gamma * l;
        let sech = gl.cosh().inv();
        let th = gl.tanh();
        TwoPort { a: sech, b: th / zc, c: zc * th, e: sech }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The Publication 5 line: 700 mm, 4 mm bore, VG22 at 40 °C, no air, stiff wall.
    fn line(modes: usize) -> Line {
        let d = 4e-3;
        Line {
            length: 0.7,
            area: PI * d * d / 4.0,
            density: 860.0,
            bulk_modulus: 1.5e9,
            friction: Line::laminar_friction(0.01892, 860.0, d),
            modes,
        }
    }

    fn at_hz(f: f64) -> C64 {
        C64::new(0.0, std::f64::consts::TAU * f)
    }

    /// Largest relative difference of the four two-port terms (each against its own magnitude).
    fn diff(x: &TwoPort, y: &TwoPort) -> f64 {
        [(x.a, y.a), (x.b, y.b), (x.c, y.c), (x.e, y.e)]
            .iter()
            .map(|(p, q)| (p - q).norm() / q.norm())
            .fold(0.0, f64::max)
    }

    /// The exact line's resonances with the nozzle end open are the quarter-wave frequencies
    /// `(2i − 1) c0 / (4l)` (docs/REFERENCES.md §5): the peaks of `|q_l/q0|` found by a golden-section search
    /// on the distributed solution lie within 0.5 % of them (measured: −2.8e-5 for the first, the laminar friction's shift; the test holds them to 1e-4).
    #[test]
    fn open_line_resonates_at_the_quarter_wave_frequencies() {
        let ln = line(8);
        let c0 = ln.wave_speed();
        for i in 1..=4 {
            #[allow(clippy::cast_precision_loss)]
            let f_qw = (2 * i - 1) as f64 * c0 / (4.0 * ln.length);
            let mag = |f: f64| -ln.exact(at_hz(f)).a.norm();
            let (mut lo, mut hi) = (0.8 * f_qw, 1.2 * f_qw);
            let g = 0.5 * (5f64.sqrt() - 1.0);
            for _ in 0..200 {
                let (x1, x2) = (hi - g * (hi - lo), lo + g * (hi - lo));
                if mag(x1) < mag(x2) {
                    hi = x2;
                } else {
                    lo = x1;
                }
            }
            let peak = 0.5 * (lo + hi);
            assert!((peak / f_qw - 1.0).abs() < 1e-4, "mode {i}: peak {peak} Hz vs quarter wave {f_qw} Hz");
            // The modal model has its natural frequencies there by construction.
            assert!((ln.mode_frequency(i) / std::f64::consts::TAU / f_qw - 1.0).abs() < 1e-14);
        }
        // docs/REFERENCES.md §5: oil only, 700 mm: first mode near 470 Hz.
        let f1 = c0 / (4.0 * ln.length);
        assert!((f1 / 470.0 - 1.0).abs() < 0.005, "first quarter-wave mode {f1} Hz");
    }

    /// docs/REFERENCES.md §5: about 1 % air at a few bar drops the 700 mm line's first mode near 110 Hz (measured 108.6 Hz at 5 bar gauge, polytropic 1.4).
    #[test]
    fn one_percent_air_drops_the_first_mode_near_110_hz() {
        let p_abs = 6e5; // 5 bar gauge
        let beta = effective_bulk_modulus(1.5e9, 0.01, 1.4 * p_abs, 0.0);
        let ln = Line { bulk_modulus: beta, ..line(4) };
        let f1 = ln.mode_frequency(1) / std::f64::consts::TAU;
        assert!((f1 / 110.0 - 1.0).abs() < 0.05, "first mode with 1 % air: {f1} Hz");
        assert_eq!(effective_bulk_modulus(1.5e9, 0.0, 1.0, 0.0), 1.5e9);
    }

    /// The modal model converges to the distributed solution as modes are added. Plain truncation: the
    /// terms alternate and decay like 1/i, so the error falls like n⁻¹ (measured orders 0.998–1.000); with the
    /// static correction the missing modes' steady response is restored and the error falls like n⁻³
    /// (measured 2.977–3.000). Both at 300 Hz (between the first two modes) with the laminar friction.
    #[test]
    fn modal_line_converges_to_the_transmission_line() {
        let s = at_hz(300.0);
        let exact = line(1).exact(s);
        let ns = [8usize, 16, 32, 64, 128];
        for (truncation, order, tol) in [(Truncation::Plain, 1.0, 0.005), (Truncation::StaticCorrection, 3.0, 0.025)] {
            let errs: Vec<f64> = ns.iter().map(|&n| diff(&line(n).modal(s, truncation), &exact)).collect();
            for w in errs.windows(2) {
                let measured = (w[0] / w[1]).log2();
                assert!((measured - order).abs() < tol, "{truncation:?}: errors {errs:?}, order {measured}");
            }
        }
    }

    /// At zero frequency the statically corrected line is exact (steady flow through, friction drop), while
    /// one plain mode delivers 4/π of the port flow.
    #[test]
    fn static_correction_is_exact_at_rest() {
        let zero = C64::new(0.0, 0.0);
        let exact = line(1).exact(zero);
        let corrected = line(1).modal(zero, Truncation::StaticCorrection);
        assert!(diff(&corrected, &exact) < 1e-14, "{corrected:?} vs {exact:?}");
        assert!((line(1).modal(zero, Truncation::Plain).a.re - 4.0 / PI).abs() < 1e-14);
    }
}
