//! Flow-regime checks of a solved film: is the laminar, smooth-surface Reynolds model it used valid here?
//!
//! The solver accepts every validated input, also physically absurd ones (a 1 nm clearance, 10⁶ rpm); it
//! then solves, and these checks say in the report where the model stops describing a real bearing:
//!
//! ```text
//! Re = ρ U h / µ           local film Reynolds number (U = Ω R, h and µ at each film node)
//!                          laminar below ≈ 1000–1500 (journal bearings): with physics.turbulence = "off",
//!                          past the transition band's start (physics.transition_reynolds_start, default
//!                          LAMINAR_REYNOLDS) the film is turbulent and the laminar model used there
//!                          underestimates friction loss, temperature rise and stiffness (warned); with
//!                          "auto" or "on" the film model is turbulent there (physics::turbulence), and the
//!                          report gives the share of the film in and past the band
//! Ta = Re √(h / R)         Taylor number: above 41.3 (Taylor, small-gap rotating cylinders) the
//!                          Couette flow develops Taylor vortices, before turbulence
//! h_min                    below ≈ 1 µm, the order of the combined roughness of journal and pad, the
//!                          surfaces touch through their asperities (mixed lubrication, not modelled)
//! Cb / R                   built bearings have clearance ratios of about 0.5–3 ‰; outside
//!                          [MIN_CLEARANCE_RATIO, MAX_CLEARANCE_RATIO] the case is unusual enough to say so
//! |ξ| / Cb                 a pivot spring deflecting by more than the assembled clearance moves the
//!                          journal as far: the linear spring, the pad's seat in its housing and the
//!                          film's small-displacement kinematics describe no built bearing there
//! ```
//!
//! The caller passes the case, the surface speed and the pad fields of a solution; the result is plain data
//! plus the warnings for the solve report.

use crate::model::{Case, Turbulence};

use crate::bearing::report::warning::Warning;
use crate::bearing::solution::result::PadResult;

/// Film Reynolds number above which the film is taken as no longer laminar (the low end of the
/// 1000–1500 transition range reported for journal bearings).
pub const LAMINAR_REYNOLDS: f64 = 1000.0;
/// Critical Taylor number of the flow between rotating cylinders with a small gap.
pub const CRITICAL_TAYLOR: f64 = 41.3;
/// Film thickness below which the surfaces' roughness matters (mixed lubrication) [m].
pub const ROUGHNESS_FILM_M: f64 = 1e-6;
/// Clearance ratios Cb/R outside this range are flagged as unusual.
pub const MIN_CLEARANCE_RATIO: f64 = 2e-4;
pub const MAX_CLEARANCE_RATIO: f64 = 1e-2;

pub use crate::bearing::solution::result::Regime;

impl Regime {
    /// The regime of the pad fields `pads` of a solve of `case` at journal surface speed `surface_speed`
    /// [m/s].
    #[must_use]
    pub fn of(case: &Case, surface_speed: f64, pads: &[PadResult]) -> Self {
        let rho = case.lubricant.density_kg_per_m3;
        let r = case.bearing.journal_radius_m;
        let u = surface_speed.abs();
        let [start, end] = case.physics.transition_reynolds;
        let mut out = Self {
            reynolds_max: 0.0,
            reynolds_pad: 0,
            turbulence: case.physics.turbulence,
            transition_reynolds: [start, end],
            transitional_fraction: 0.0,
            turbulent_fraction: 0.0,
            taylor_max: 0.0,
            h_min_m: f64::INFINITY,
            clearance_ratio: case.bearing.assembled_clearance_m / r,
            pivot_deflection_cb: 0.0,
            pivot_pad: 0,
        };
        let (mut nodes, mut above_start, mut above_end) = (0_usize, 0_usize, 0_usize);
        for p in pads {
            let f = &p.field;
            for (&h, &mu) in f.film_thickness_m.iter().zip(&f.viscosity_pa_s) {
                let re = rho * u * h / mu;
                nodes += 1;
                above_start += usize::from(re > start);
                above_end += usize::from(re >= end);
                if re > out.reynolds_max {
                    out.reynolds_max = re;
                    out.reynolds_pad = p.index;
                }
                out.taylor_max = out.taylor_max.max(re * (h / r).sqrt());
            }
            out.h_min_m = out.h_min_m.min(p.h_min_m);
            let xi = p.pivot_displacement_m.unwrap_or(0.0).abs() / case.bearing.assembled_clearance_m;
            if xi > out.pivot_deflection_cb {
                out.pivot_deflection_cb = xi;
                out.pivot_pad = p.index;
            }
        }
        if nodes > 0 {
            #[allow(clippy::cast_precision_loss)]
            let share = |k: usize| k as f64 / nodes as f64;
            out.transitional_fraction = share(above_start);
            out.turbulent_fraction = share(above_end);
        }
        out
    }

    /// One warning per check that fails.
    #[must_use]
    pub fn warnings(&self) -> Vec<Warning> {
        let mut w = Vec::new();
        // With turbulence modelled (auto, on) the film past the band is what the model describes: no warning.
        let start = self.transition_reynolds[0];
        if self.reynolds_max > start {
            if self.turbulence == Turbulence::Off {
                w.push(Warning::Turbulent { reynolds: self.reynolds_max, pad: self.reynolds_pad, limit: start });
            }
        } else if self.taylor_max > CRITICAL_TAYLOR {
            w.push(Warning::TaylorVortices { taylor: self.taylor_max, critical: CRITICAL_TAYLOR });
        }
        if self.h_min_m < ROUGHNESS_FILM_M {
            w.push(Warning::MixedLubrication { h_min_m: self.h_min_m, roughness_m: ROUGHNESS_FILM_M });
        }
        if !(MIN_CLEARANCE_RATIO..=MAX_CLEARANCE_RATIO).contains(&self.clearance_ratio) {
            w.push(Warning::UnusualClearance {
                ratio: self.clearance_ratio,
                usual: [MIN_CLEARANCE_RATIO, MAX_CLEARANCE_RATIO],
            });
        }
        if self.pivot_deflection_cb > 1.0 {
            w.push(Warning::PivotDeflection { pad: self.pivot_pad, clearances: self.pivot_deflection_cb });
        }
        w
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn regime(reynolds_max: f64, taylor_max: f64, h_min_m: f64, clearance_ratio: f64) -> Regime {
        Regime {
            reynolds_max,
            reynolds_pad: 2,
            turbulence: Turbulence::Off,
            transition_reynolds: [LAMINAR_REYNOLDS, 1500.0],
            transitional_fraction: 0.0,
            turbulent_fraction: 0.0,
            taylor_max,
            h_min_m,
            clearance_ratio,
            pivot_deflection_cb: 0.99,
            pivot_pad: 1,
        }
    }

    #[test]
    fn each_check_fires_on_its_own_side_of_its_limit() {
        assert!(regime(900.0, 40.0, 20e-6, 1.5e-3).warnings().is_empty());
        let text = |w: Vec<Warning>| w.iter().map(ToString::to_string).collect::<Vec<_>>();
        let turbulent = text(regime(1001.0, 60.0, 20e-6, 1.5e-3).warnings());
        assert_eq!(turbulent.len(), 1, "{turbulent:?}");
        assert!(turbulent[0].starts_with("turbulent film") && turbulent[0].contains("1001 (pad 2)"), "{turbulent:?}");
        // Modelled turbulence is no warning; the band's start is the limit.
        for mode in [Turbulence::Auto, Turbulence::On] {
            assert!(Regime { turbulence: mode, ..regime(1001.0, 60.0, 20e-6, 1.5e-3) }.warnings().is_empty());
        }
        let later = Regime { transition_reynolds: [1200.0, 1800.0], ..regime(1001.0, 30.0, 20e-6, 1.5e-3) };
        assert!(later.warnings().is_empty());
        let taylor = text(regime(999.0, 41.4, 20e-6, 1.5e-3).warnings());
        assert!(taylor.len() == 1 && taylor[0].starts_with("Taylor vortices"), "{taylor:?}");
        let thin = text(regime(1.0, 0.1, 0.99e-6, 1.5e-3).warnings());
        assert!(thin.len() == 1 && thin[0].contains("0.990 µm"), "{thin:?}");
        for ratio in [1.9e-4, 1.01e-2] {
            let w = regime(1.0, 0.1, 20e-6, ratio).warnings();
            assert!(matches!(w[..], [Warning::UnusualClearance { ratio: r, .. }] if r == ratio), "{ratio}: {w:?}");
        }
        let deflected = text(Regime { pivot_deflection_cb: 1.01, ..regime(1.0, 0.1, 20e-6, 1.5e-3) }.warnings());
        assert!(
            deflected.len() == 1 && deflected[0].starts_with("pad 1's pivot deflects by 1.0 times"),
            "{deflected:?}"
        );
    }
}
