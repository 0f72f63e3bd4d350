//! Turbulent films: the Ng–Pan–Elrod linearised turbulence coefficients of the Reynolds and energy
//! equations, with a laminar–turbulent transition band in the local film Reynolds number (docs/MODEL.md §2.7).
//!
//! ## Equations
//! With the local film Reynolds number `Re = ρ U h / µ` (U = Ω R the journal surface speed), the turbulent
//! Reynolds equation of Ng & Pan (1965), in the form Elrod & Ng (1967) and Taylor & Dowson (1974) give it,
//! replaces the laminar `12` of the Poiseuille terms by a coefficient per direction:
//!
//! ```text
//! ∂/∂s (h³/(k_s µ) ∂p/∂s) + ∂/∂z (h³/(k_z µ) ∂p/∂z) = (U/2) ∂h/∂s + ∂h/∂t
//! k_s = 12 + 0.0136 Re^0.90        (along the sliding direction)
//! k_z = 12 + 0.0043 Re^0.96        (across it)
//! τ_journal = C_f µ U / h + (h/2) ∂p/∂s,   C_f = 1 + 0.0012 Re^0.94      (Couette shear factor)
//! ```
//!
//! (the curve fits of Taylor & Dowson to Ng & Pan's law-of-the-wall solution, 10³ ≲ Re ≲ 10⁵; at Re → 0 they
//! return the laminar 12, 12 and 1). The solver writes the equation with the laminar coefficient 12 and the
//! multipliers `G_s = 12/k_s`, `G_z = 12/k_z` on `h³/µ`.
//!
//! **Why Ng–Pan and not Constantinescu.** Both give the same form; Ng–Pan's coefficients come from Reichardt's
//! law of the wall for the eddy viscosity, the same closure the eddy diffusivity of the energy equation uses
//! below (one turbulence model for pressure and heat), and its linearisation of the pressure-driven flow
//! about the Couette flow is exact for the small pressure gradients of a journal bearing. It is also the
//! model of Taniguchi et al.'s (1990) analysis of large tilting-pad bearings. A test
//! integrates Reichardt's law across the film and recovers the three fits within their few per cent.
//!
//! ## Transition band
//! Between `Re_start` and `Re_end` (`physics.transition_reynolds_start`, `…_end`) the film is intermittent:
//! `k = 12 + γ (k_turbulent − 12)`, `C_f = 1 + γ (C_f,turbulent − 1)` with the intermittency
//! `γ = t² (3 − 2t)`, `t = (Re − Re_start)/(Re_end − Re_start)` clipped to [0, 1] (continuous with a
//! continuous derivative, so the equilibrium's Newton iteration sees a smooth film). Below the band γ = 0 and
//! every coefficient is laminar exactly. `physics.turbulence = "on"` takes γ = 1 everywhere.
//!
//! ## Energy equation: eddy diffusivity
//! Reichardt's eddy viscosity `ε_m/ν = κ [y⁺ − δ⁺ tanh(y⁺/δ⁺)]` (κ = 0.4, δ⁺ = 10.7, y⁺ from the nearer wall
//! with the shear velocity of the Couette flow, `h⁺ = √(C_f Re)`), and the eddy diffusivity of heat
//! `ε_h = ε_m / Pr_t` (turbulent Prandtl number [`TURBULENT_PRANDTL`]), make the film's conductivity
//! `κ_eff(y) = κ (1 + γ (Pr/Pr_t) ε_m/ν)`. The film-averaged energy equation takes two numbers from it:
//! - the in-plane conductivity (the `∇·(κ h ∇T)` term) scales with its mean across the film,
//!   `F_plane = 1 + γ (Pr/Pr_t) ⟨ε_m/ν⟩` (closed form);
//! - the conductance across the film (the pad and journal exchange of BC3) scales with the ratio of the
//!   laminar to the turbulent thermal resistance, `F_across = 1 / ∫₀¹ dη / (1 + γ (Pr/Pr_t) ε_m/ν)` (by
//!   quadrature: the viscous sublayers, where ε_m is small, hold almost all of it).
//!
//! Units: SI. All functions are pure.

use crate::model::Turbulence;

/// Von Kármán's constant in Reichardt's eddy viscosity.
pub const KARMAN: f64 = 0.4;
/// Reichardt's sublayer constant δ⁺.
pub const SUBLAYER: f64 = 10.7;
/// Turbulent Prandtl number ε_m/ε_h.
pub const TURBULENT_PRANDTL: f64 = 0.9;

/// The turbulence settings of a film solve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TurbulenceLaw {
    pub mode: Turbulence,
    /// Transition band [Re_start, Re_end] of the local film Reynolds number.
    pub re_start: f64,
    pub re_end: f64,
    /// Oil density ρ [kg/m³].
    pub density: f64,
}

impl TurbulenceLaw {
    /// A laminar film (the Reynolds equation's 12 everywhere).
    pub const LAMINAR: Self = Self { mode: Turbulence::Off, re_start: 1000.0, re_end: 1500.0, density: 0.0 };

    /// True when every coefficient is laminar whatever the Reynolds number.
    #[must_use]
    pub fn is_laminar(&self) -> bool {
        self.mode == Turbulence::Off
    }

    /// Local film Reynolds number ρ U h / µ.
    #[must_use]
    pub fn reynolds(&self, surface_speed: f64, h: f64, mu: f64) -> f64 {
        self.density * surface_speed.abs() * h / mu
    }

    /// Intermittency γ and dγ/dRe at `re`.
    #[must_use]
    pub fn intermittency(&self, re: f64) -> (f64, f64) {
        match self.mode {
            Turbulence::Off => (0.0, 0.0),
            Turbulence::On => (1.0, 0.0),
            Turbulence::Auto => {
                let w = self.re_end - self.re_start;
                let t = (re - self.re_start) / w;
                if t <= 0.0 {
                    (0.0, 0.0)
                } else if t >= 1.0 {
                    (1.0, 0.0)
                } else {
                    (t * t * (3.0 - 2.0 * t), 6.0 * t * (1.0 - t) / w)
                }
            }
        }
    }

    /// The coefficients at `re` (laminar exactly where γ = 0).
    #[must_use]
    pub fn factors(&self, re: f64) -> Factors {
        let (gamma, dgamma) = self.intermittency(re);
        if gamma == 0.0 {
            return Factors::LAMINAR;
        }
        let re = re.max(f64::MIN_POSITIVE);
        // The three power laws from one logarithm (the film solve evaluates this at every Gauss point).
        let ln = re.ln();
        let (vs, vz, vc) = (0.0136 * (0.90 * ln).exp(), 0.0043 * (0.96 * ln).exp(), 0.0012 * (0.94 * ln).exp());
        let (ks, dks) = blend(gamma, dgamma, (12.0 + vs, 0.90 * vs / re));
        let (kz, dkz) = blend(gamma, dgamma, (12.0 + vz, 0.96 * vz / re));
        let cf_t = 1.0 + vc;
        Factors {
            gamma,
            gs: 12.0 / ks,
            gz: 12.0 / kz,
            es: 3.0 - re * dks / ks,
            ez: 3.0 - re * dkz / kz,
            cf: 1.0 + gamma * (cf_t - 1.0),
        }
    }

    /// Eddy-diffusivity factors of the energy equation at `re` and Prandtl number `prandtl` = µ c_p / κ:
    /// (F_plane, F_across); (1, 1) where the film is laminar.
    #[must_use]
    pub fn thermal_factors(&self, re: f64, prandtl: f64) -> (f64, f64) {
        let (gamma, _) = self.intermittency(re);
        if gamma == 0.0 {
            return (1.0, 1.0);
        }
        eddy_conduction(re.max(0.0), gamma * prandtl / TURBULENT_PRANDTL)
    }
}

/// The turbulence multipliers at one point of the film.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Factors {
    /// Intermittency γ ∈ [0, 1].
    pub gamma: f64,
    /// `G_s = 12/k_s`, `G_z = 12/k_z` (1 laminar).
    pub gs: f64,
    pub gz: f64,
    /// `∂ ln(h³ G)/∂ ln h` per direction (3 laminar): the thickness derivative of the Poiseuille coefficient,
    /// for the film's linearisation.
    pub es: f64,
    pub ez: f64,
    /// Couette shear factor C_f (1 laminar).
    pub cf: f64,
}

impl Factors {
    pub const LAMINAR: Self = Self { gamma: 0.0, gs: 1.0, gz: 1.0, es: 3.0, ez: 3.0, cf: 1.0 };
}

/// `12 + γ (k − 12)` and its Re-derivative for `(k, dk/dRe)`.
fn blend(gamma: f64, dgamma: f64, (k, dk): (f64, f64)) -> (f64, f64) {
    (12.0 + gamma * (k - 12.0), dgamma * (k - 12.0) + gamma * dk)
}

/// Ng–Pan k_s = 12 + 0.0136 Re^0.90 and its derivative.
#[must_use]
pub fn ng_pan_ks(re: f64) -> (f64, f64) {
    power_law(re, 0.0136, 0.90, 12.0)
}

/// Ng–Pan k_z = 12 + 0.0043 Re^0.96 and its derivative.
#[must_use]
pub fn ng_pan_kz(re: f64) -> (f64, f64) {
    power_law(re, 0.0043, 0.96, 12.0)
}

/// Couette shear factor C_f = 1 + 0.0012 Re^0.94 and its derivative.
#[must_use]
pub fn ng_pan_cf(re: f64) -> (f64, f64) {
    power_law(re, 0.0012, 0.94, 1.0)
}

fn power_law(re: f64, a: f64, n: f64, base: f64) -> (f64, f64) {
    if re <= 0.0 {
        return (base, 0.0);
    }
    let v = a * re.powf(n);
    (base + v, n * v / re)
}

/// Reichardt's eddy viscosity ratio ε_m/ν at wall distance y⁺.
#[must_use]
pub fn reichardt(y_plus: f64) -> f64 {
    KARMAN * (y_plus - SUBLAYER * (y_plus / SUBLAYER).tanh())
}

/// ∫₀^y ε_m/ν dy⁺ in closed form.
fn reichardt_integral(y: f64) -> f64 {
    // ln cosh x = |x| + ln(1 + e^{−2|x|}) − ln 2, stable for large x.
    let x = y / SUBLAYER;
    let lncosh = x.abs() + (-2.0 * x.abs()).exp().ln_1p() - std::f64::consts::LN_2;
    KARMAN * (0.5 * y * y - SUBLAYER * SUBLAYER * lncosh)
}

/// Segments of the cross-film quadrature (two Gauss points each, graded towards the wall).
const ACROSS_SEGMENTS: usize = 24;

/// (F_plane, F_across) for Reynolds number `re` and `a = γ Pr/Pr_t` (module documentation).
#[must_use]
pub fn eddy_conduction(re: f64, a: f64) -> (f64, f64) {
    let (cf, _) = ng_pan_cf(re);
    let h_plus = (cf * re).sqrt();
    let half = 0.5 * h_plus;
    if half <= 0.0 || a <= 0.0 {
        return (1.0, 1.0);
    }
    let plane = 1.0 + a * reichardt_integral(half) / half;
    let resistance = wall_integral(half, ACROSS_SEGMENTS, |y| 1.0 / (1.0 + a * reichardt(y)));
    (plane, half / resistance)
}

/// `∫₀^half f(y⁺) dy⁺` on `segments` cubically graded segments (fine at the wall, where the viscous sublayer
/// holds the variation), two Gauss points each.
#[must_use]
pub fn wall_integral(half: f64, segments: usize, f: impl Fn(f64) -> f64) -> f64 {
    let g = 0.5 / 3.0_f64.sqrt();
    let mut sum = 0.0;
    #[allow(clippy::cast_precision_loss)]
    for i in 0..segments {
        let y0 = half * (i as f64 / segments as f64).powi(3);
        let y1 = half * ((i + 1) as f64 / segments as f64).powi(3);
        let (mid, len) = (0.5 * (y0 + y1), y1 - y0);
        for y in [mid - g * len, mid + g * len] {
            sum += 0.5 * len * f(y);
        }
    }
    sum
}

#[cfg(test)]
mod tests {
    use super::*;

    fn auto() -> TurbulenceLaw {
        TurbulenceLaw { mode: Turbulence::Auto, re_start: 1000.0, re_end: 1500.0, density: 860.0 }
    }

    #[test]
    fn below_the_band_every_coefficient_is_laminar_exactly() {
        let law = auto();
        for re in [0.0, 10.0, 999.999, 1000.0] {
            assert_eq!(law.factors(re), Factors::LAMINAR, "Re = {re}");
            assert_eq!(law.thermal_factors(re, 300.0), (1.0, 1.0));
        }
        let inside = law.factors(1250.0);
        assert!((inside.gamma - 0.5).abs() < 1e-15, "smoothstep at mid-band: {}", inside.gamma);
        assert!(inside.gs < 1.0 && inside.gz < 1.0 && inside.cf > 1.0);
        assert_eq!(law.factors(1500.0).gamma, 1.0);
    }

    #[test]
    fn turbulent_factors_are_the_named_fits() {
        let law = TurbulenceLaw { mode: Turbulence::On, ..auto() };
        for re in [0.5, 800.0, 5000.0, 4e4] {
            let f = law.factors(re);
            let close = |a: f64, b: f64| (a / b - 1.0).abs() < 1e-13;
            assert!(close(f.gs, 12.0 / ng_pan_ks(re).0) && close(f.gz, 12.0 / ng_pan_kz(re).0), "Re {re}: {f:?}");
            assert!(close(f.cf, ng_pan_cf(re).0), "Re {re}: {f:?}");
        }
    }

    #[test]
    fn intermittency_is_continuously_differentiable() {
        let law = auto();
        for re in [1000.0, 1100.0, 1250.0, 1499.0, 1500.0] {
            let d = 1e-4;
            let fd = (law.intermittency(re + d).0 - law.intermittency(re - d).0) / (2.0 * d);
            assert!((fd - law.intermittency(re).1).abs() < 1e-6, "Re {re}: {fd} vs {}", law.intermittency(re).1);
        }
    }

    #[test]
    fn elasticities_are_the_log_derivative_of_h3_g() {
        // ∂ln(h³ G)/∂ln h at fixed µ (Re ∝ h), by central differences in h.
        let law = auto();
        for re in [1200.0, 1490.0, 3000.0, 30000.0] {
            let f = law.factors(re);
            let d = 1e-6;
            let lg = |r: f64, dir: usize| {
                let x = law.factors(r);
                (if dir == 0 { x.gs } else { x.gz }).ln()
            };
            for (dir, e) in [(0, f.es), (1, f.ez)] {
                let fd = 3.0 + (lg(re * (1.0 + d), dir) - lg(re * (1.0 - d), dir)) / (2.0 * d);
                assert!((fd - e).abs() < 1e-6, "Re {re} dir {dir}: {fd} vs {e}");
            }
        }
    }

    /// Shear velocity of turbulent Couette flow by Reichardt's law: solves `U/u* = 2∫₀^{h⁺/2} dy⁺/(1 + ε/ν)`
    /// with `Re = h⁺ U/u*` for h⁺ (bisection), independently of the fits.
    fn couette_h_plus(re: f64, eddy: impl Fn(f64) -> f64) -> f64 {
        let velocity_ratio = |hp: f64| {
            let n = 4000;
            let dy = 0.5 * hp / f64::from(n);
            (0..n).map(|i| 2.0 * dy / (1.0 + eddy((f64::from(i) + 0.5) * dy))).sum::<f64>()
        };
        let (mut lo, mut hi) = (1e-3_f64, 1e4_f64);
        for _ in 0..200 {
            let mid = (lo * hi).sqrt();
            if mid * velocity_ratio(mid) < re {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        lo
    }

    /// k for a pressure-driven perturbation with effective viscosity ratio `nu(y⁺)` across the film:
    /// `(ν_eff) dw/dη = (η − ½)` scaled, `k = −1/∫₀¹ w dη`.
    fn poiseuille_k(h_plus: f64, nu: impl Fn(f64) -> f64) -> f64 {
        let n = 4000;
        let d = 1.0 / f64::from(n);
        let (mut w, mut q) = (0.0, 0.0);
        for i in 0..n {
            let eta = (f64::from(i) + 0.5) * d;
            let y_plus = h_plus * eta.min(1.0 - eta);
            let w_next = w + d * (eta - 0.5) / nu(y_plus);
            q += 0.5 * d * (w + w_next);
            w = w_next;
        }
        -1.0 / q
    }

    /// The published curves of the model: Ng & Pan's coefficients follow from Reichardt's eddy viscosity
    /// across a Couette film (C_f from the wall shear; k_z from an axial pressure flow seeing the same eddy
    /// viscosity; k_s from a pressure flow along the shear, which also changes the local shear stress the
    /// eddy viscosity depends on: with `ε/ν = f(y⁺)`, `y⁺ ∝ √τ`, the perturbation sees the tangent viscosity
    /// `ν (1 + f)² / (1 + f − y⁺ f′/2)`). Integrating them numerically here, independently of the fits, gives
    /// (integrated / fit − 1), measured: C_f +3.8, +4.9, +0.7, −10.1 %; k_z −0.2, +4.9, +4.4, −4.7 %;
    /// k_s −1.6, +4.2, +4.6, −0.5 % at Re = 2·10³, 5·10³, 10⁴, 3·10⁴ — the fits' few-per-cent scatter,
    /// and C_f's fit drifting above the integration at the top of its range. The tolerances sit just above.
    #[test]
    fn ng_pan_fits_match_the_law_of_the_wall_integration() {
        for (re, tol_cf, tol_k) in
            [(2000.0, 0.05, 0.02), (5000.0, 0.055, 0.055), (10000.0, 0.05, 0.05), (30000.0, 0.11, 0.05)]
        {
            let hp = couette_h_plus(re, reichardt);
            let cf_int = hp * hp / re;
            let cf_fit = ng_pan_cf(re).0;
            assert!((cf_int / cf_fit - 1.0).abs() < tol_cf, "Re {re}: C_f integrated {cf_int:.3} vs fit {cf_fit:.3}");
            let kz_int = poiseuille_k(hp, |y| 1.0 + reichardt(y));
            let kz_fit = ng_pan_kz(re).0;
            assert!((kz_int / kz_fit - 1.0).abs() < tol_k, "Re {re}: k_z integrated {kz_int:.2} vs fit {kz_fit:.2}");
            let tangent = |y: f64| {
                let f = reichardt(y);
                let df = KARMAN * (y / SUBLAYER).tanh().powi(2);
                (1.0 + f) * (1.0 + f) / (1.0 + f - 0.5 * y * df)
            };
            let ks_int = poiseuille_k(hp, tangent);
            let ks_fit = ng_pan_ks(re).0;
            assert!((ks_int / ks_fit - 1.0).abs() < tol_k, "Re {re}: k_s integrated {ks_int:.2} vs fit {ks_fit:.2}");
        }
    }

    /// The fits' values at Re = 10⁴, worked by hand (a guard on the constants): k_s = 12 + 0.0136·10^3.6,
    /// k_z = 12 + 0.0043·10^3.84, C_f = 1 + 0.0012·10^3.76.
    #[test]
    fn ng_pan_values_at_ten_thousand() {
        assert!((ng_pan_ks(1e4).0 - 66.14).abs() < 0.01, "{}", ng_pan_ks(1e4).0);
        assert!((ng_pan_kz(1e4).0 - 41.75).abs() < 0.01, "{}", ng_pan_kz(1e4).0);
        assert!((ng_pan_cf(1e4).0 - 7.905).abs() < 0.001, "{}", ng_pan_cf(1e4).0);
    }

    #[test]
    fn eddy_conduction_grows_with_reynolds_and_prandtl() {
        let (p1, a1) = eddy_conduction(2000.0, 100.0);
        let (p2, a2) = eddy_conduction(10000.0, 100.0);
        let (_, a3) = eddy_conduction(2000.0, 300.0);
        assert!(p1 > 1.0 && a1 > 1.0 && p2 > p1 && a2 > a1 && a3 > a1, "{p1} {a1} {p2} {a2} {a3}");
        // The cross-film factor is bounded by the in-plane (mean) one (harmonic ≤ arithmetic mean).
        assert!(a1 < p1 && a2 < p2);
        assert_eq!(eddy_conduction(2000.0, 0.0), (1.0, 1.0));
    }
}
