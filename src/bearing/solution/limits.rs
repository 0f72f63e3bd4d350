//! Checks a solution against the design limits of its case ([`crate::model::limits`]).
//!
//! ```text
//! h_min ≥ h_lim      T_pad,max ≤ T_lim      W/(L·D) ≤ w_lim      p_max ≤ p_lim      Re_max ≤ Re_lim
//! ```
//!
//! The caller passes the limits (the edited case's, which may be newer than the solved one: limits enter no
//! solver stage) and the solution; the result is the list of checks with the value, the limit and whether
//! it is exceeded. Quantities a solution does not have (temperatures of an isothermal solve) are not
//! checked and say so. Values in SI; [`crate::scene::limits`] writes them in engineering units.

use serde::Serialize;

use crate::model::limits::Limits;

use crate::bearing::solution::regime::Regime;
use crate::bearing::solution::result::Solution;

/// Which limit.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum LimitKind {
    MinFilmThickness,
    MaxPadTemperature,
    MaxSpecificLoad,
    MaxPeakPressure,
    MaxReynolds,
}

impl LimitKind {
    pub const ALL: [Self; 5] = [
        Self::MinFilmThickness,
        Self::MaxPadTemperature,
        Self::MaxSpecificLoad,
        Self::MaxPeakPressure,
        Self::MaxReynolds,
    ];

    /// Short name (CSV cells, JSON keys).
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::MinFilmThickness => "h_min",
            Self::MaxPadTemperature => "t_max_pad",
            Self::MaxSpecificLoad => "specific_load",
            Self::MaxPeakPressure => "p_max",
            Self::MaxReynolds => "reynolds",
        }
    }

    /// Label for people.
    #[must_use]
    pub fn label(self) -> &'static str {
        match self {
            Self::MinFilmThickness => "h_min",
            Self::MaxPadTemperature => "T_max pad",
            Self::MaxSpecificLoad => "W/(L·D)",
            Self::MaxPeakPressure => "p_max",
            Self::MaxReynolds => "Re_max",
        }
    }

    /// Display unit and the factor from SI to it.
    #[must_use]
    pub fn unit(self) -> (&'static str, f64) {
        match self {
            Self::MinFilmThickness => ("µm", 1e6),
            Self::MaxPadTemperature => ("°C", 1.0),
            Self::MaxSpecificLoad | Self::MaxPeakPressure => ("MPa", 1e-6),
            Self::MaxReynolds => ("", 1.0),
        }
    }

    /// A lower bound (the value must stay above it) rather than an upper one.
    #[must_use]
    pub fn is_minimum(self) -> bool {
        self == Self::MinFilmThickness
    }

    /// The limit's value in SI.
    #[must_use]
    pub fn limit(self, l: &Limits) -> f64 {
        match self {
            Self::MinFilmThickness => l.min_film_thickness_m,
            Self::MaxPadTemperature => l.max_pad_temperature_c,
            Self::MaxSpecificLoad => l.max_specific_load_pa,
            Self::MaxPeakPressure => l.max_peak_pressure_pa,
            Self::MaxReynolds => l.max_reynolds,
        }
    }
}

/// One limit checked on one solution.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Check {
    pub kind: LimitKind,
    /// The solution's value (SI); `None` when the solution does not have it (temperature, isothermal).
    pub value: Option<f64>,
    pub limit: f64,
    pub exceeded: bool,
}

/// The solution's value of a limited quantity (SI).
#[must_use]
pub fn value(kind: LimitKind, s: &Solution) -> Option<f64> {
    let b = &s.inputs.bearing;
    match kind {
        LimitKind::MinFilmThickness => Some(s.h_min_m),
        // Without pad solids (BC1 without conduction) the pad surface is the film: its maximum stands in.
        LimitKind::MaxPadTemperature => s.thermal.as_ref().map(|t| t.t_max_pad_c.unwrap_or(t.t_max_film_c)),
        LimitKind::MaxSpecificLoad => Some(s.load_magnitude_n / (b.length_m * 2.0 * b.journal_radius_m)),
        LimitKind::MaxPeakPressure => Some(s.p_max_pa),
        LimitKind::MaxReynolds => {
            Some(Regime::of(&s.inputs, s.derived.speed_rad_s * b.journal_radius_m, &s.pads).reynolds_max)
        }
    }
}

/// Every limit checked on `s`.
#[must_use]
pub fn check(limits: &Limits, s: &Solution) -> Vec<Check> {
    LimitKind::ALL
        .iter()
        .map(|&kind| {
            let v = value(kind, s);
            let limit = kind.limit(limits);
            let exceeded = v.is_some_and(|v| if kind.is_minimum() { v < limit } else { v > limit });
            Check { kind, value: v, limit, exceeded }
        })
        .collect()
}

/// Only the exceeded checks.
#[must_use]
pub fn exceeded(limits: &Limits, s: &Solution) -> Vec<Check> {
    check(limits, s).into_iter().filter(|c| c.exceeded).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::limits::LimitsFile;

    /// An example: h_min 6.6 µm, T_max 132 °C, p_max 24 MPa, values that once passed without a word. A real THD
    /// solve of the compressor bearing is within the default limits; with the three values set on it, each
    /// is flagged with its value and limit, and the others are not.
    #[test]
    fn an_example_over_three_limits_is_flagged_by_the_default_limits() {
        let mut s = crate::bearing::stages::registry::compressor_preview(&["thermal.model=\"thd\""]);
        let limits = Limits::default();
        assert_eq!(limits.max_reynolds, crate::bearing::solution::regime::LAMINAR_REYNOLDS);
        assert!(exceeded(&limits, &s).is_empty(), "{:?}", exceeded(&limits, &s));
        s.h_min_m = 6.6e-6;
        s.p_max_pa = 24e6;
        if let Some(t) = s.thermal.as_mut() {
            t.t_max_pad_c = Some(132.0);
        }
        let flagged: Vec<LimitKind> = exceeded(&limits, &s).iter().map(|c| c.kind).collect();
        assert_eq!(flagged, [LimitKind::MinFilmThickness, LimitKind::MaxPadTemperature, LimitKind::MaxPeakPressure]);
        let texts: Vec<String> = exceeded(&limits, &s).iter().map(crate::scene::limits::text).collect();
        assert_eq!(texts[0], "h_min 6.6 µm < limit 10 µm");
        assert_eq!(texts[1], "T_max pad 132 °C > limit 120 °C");
        assert_eq!(texts[2], "p_max 24 MPa > limit 20 MPa");
    }

    /// Specific load and Reynolds number from their definitions, and limits set in the file apply.
    #[test]
    fn specific_load_and_reynolds_against_configured_limits() {
        let s = crate::bearing::stages::registry::compressor_preview(&[]);
        let b = &s.inputs.bearing;
        let w = value(LimitKind::MaxSpecificLoad, &s).unwrap();
        assert!((w * b.length_m * 2.0 * b.journal_radius_m / s.load_magnitude_n - 1.0).abs() < 1e-12);
        let re = value(LimitKind::MaxReynolds, &s).unwrap();
        // Re_max = ρ Ω R h / µ is at most ρ Ω R h_max / µ_min over the film.
        let h_max = s.pads.iter().flat_map(|p| p.field.film_thickness_m.iter().copied()).fold(0.0, f64::max);
        let bound = s.inputs.lubricant.density_kg_per_m3 * s.derived.speed_rad_s * b.journal_radius_m * h_max
            / s.derived.film_viscosity_pa_s;
        assert!(re > 0.0 && re <= bound * (1.0 + 1e-12), "{re} vs {bound}");
        let file = LimitsFile {
            max_specific_load_mpa: Some(crate::units::MPA.from_si(0.5 * w)),
            max_reynolds: Some(0.5 * re),
            ..LimitsFile::default()
        };
        let limits = crate::model::limits::resolve_limits(&file).unwrap();
        let flagged: Vec<LimitKind> = exceeded(&limits, &s).iter().map(|c| c.kind).collect();
        assert_eq!(flagged, [LimitKind::MaxSpecificLoad, LimitKind::MaxReynolds]);
        // An isothermal solve has no temperature to check.
        let t = check(&limits, &s).into_iter().find(|c| c.kind == LimitKind::MaxPadTemperature).unwrap();
        assert_eq!((t.value, t.exceeded, crate::scene::limits::value_text(&t)), (None, false, "—".to_string()));
    }
}
