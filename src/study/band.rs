//! Reduced coefficients sampled over a band of running speeds for a rotordynamics code that interpolates
//! them between the samples — ROSS fits a cubic spline through a bearing element's samples (its
//! `UnivariateSpline` with the default smoothing, which for coefficients of 10⁶–10⁹ N/m passes through every
//! sample) and evaluates it at every speed of its analysis, extrapolating the end polynomials past the band.
//!
//! Two things go wrong with a spline through coarse samples: it rings where the coefficients are not smooth
//! (a pad that starts or stops floating bends or breaks the curves; a cubic through samples on both sides
//! overshoots for several intervals), and it extrapolates wherever the analysis runs outside the band. So:
//!
//! - **Refinement** ([`BandParams::refine`]): every interval between neighbouring samples is checked by
//!   solving its midpoint and comparing each of the eight terms with the cubic through the nearest samples
//!   on either side (two each where the band has them):
//!   `err = max_term |K_cubic(Ω_m) − K(Ω_m)| / K_scale` (C terms against `C_scale`; the scales are the
//!   largest |K|, |C| term over the samples, so a cross-coupled term near zero is judged against the direct
//!   ones). An interval whose error exceeds [`BandParams::tolerance`], or whose ends differ in which pads
//!   float, is halved again, breadth first, while its halves are at least
//!   [`BandParams::min_width_fraction`] of the band wide (the finest interval is then between half that and
//!   that), up to [`BandParams::max_samples`] samples. The midpoint stays a sample either way. So samples gather where a
//!   pad changes state, and ROSS's spline meets the solved coefficients between samples within about the
//!   tolerance elsewhere.
//! - **Warnings** ([`BandWarning`]): the band does not cover the analysis range the caller names, or the
//!   coefficients jump between samples: at an interior sample the cubic through its neighbours (two on each
//!   side where there are) misses it by more than [`BandParams::jump_tolerance`] of the scale — a real
//!   discontinuity that refinement can only narrow (a pad whose tilt equilibrium folds), or an unrefined
//!   band too coarse for the curves; ROSS's spline overshoots around it. Where one interval's change stands
//!   out (twice any other's nearby), the warning names that interval: the discontinuity is there.
//!
//! Speeds are the case key's own unit (rpm, the value each point overrides); the samples carry the solved
//! speed in rad/s, as ROSS reads it. Points that fail are left out and listed; a cancelled solve stops the
//! sampling. The solve itself is the caller's ([`sample`] takes a closure; [`solve_point`] asks a study
//! [`Runner`]), so the command line's `--ross` export and the Python package's `tiltpad.ross.bearing_element`
//! sample identically.
//!
//! Each speed is solved from scratch (a cold [`Runner`], [`cold_runner`]): refinement solves speeds out of
//! order, and where the bearing has two equilibria at one speed (a pad that floats on one and carries load on
//! the other — the compressor bearing at preview fidelity has such a band near 7600–7800 rpm) a warm start
//! takes whichever branch the previously solved speed was on, so the samples would alternate between branches.
//! From scratch every sample is a function of its speed alone, and a branch change is one jump, narrowed by
//! refinement and warned.

use std::collections::VecDeque;

use crate::bearing::{Cancel, SolveError};
use crate::units::RPM;

use super::run::{PointError, Runner};

/// The reduced coefficients at one running speed.
#[derive(Debug, Clone, PartialEq)]
pub struct Sample {
    /// The speed as overridden [rpm] (the case key's value).
    pub speed_rpm: f64,
    /// The solved running speed [rad/s].
    pub speed_rad_s: f64,
    /// Excitation frequency of the reduction [rad/s] (the case's ratio ω/Ω times the speed).
    pub excitation_rad_s: f64,
    pub k_n_per_m: [[f64; 2]; 2],
    pub c_ns_per_m: [[f64; 2]; 2],
    /// The pads that float (carry no load) at this speed.
    pub floating: Vec<usize>,
}

/// How densely to sample and when to warn.
#[derive(Debug, Clone, PartialEq)]
pub struct BandParams {
    /// Check every interval at its midpoint and halve where the cubic misses it.
    pub refine: bool,
    /// Largest midpoint miss of the cubic, as a fraction of the K (or C) scale, that ends refinement.
    pub tolerance: f64,
    /// Miss of the cubic through an interior sample's neighbours, as a fraction of the scale, that counts as
    /// a jump between samples (warned).
    pub jump_tolerance: f64,
    /// Narrowest interval refinement halves further, as a fraction of the band (its halves' midpoints are
    /// still solved, so the finest sample spacing is between half this and this).
    pub min_width_fraction: f64,
    /// Most samples (the requested ones included).
    pub max_samples: usize,
    /// The speed range of the rotor analysis these coefficients serve [rpm], if the caller knows it.
    pub analysis_rpm: Option<[f64; 2]>,
}

impl Default for BandParams {
    fn default() -> Self {
        Self {
            refine: true,
            tolerance: 0.005,
            jump_tolerance: 0.02,
            min_width_fraction: 1.0 / 512.0,
            max_samples: 400,
            analysis_rpm: None,
        }
    }
}

/// Why the samples may not serve the analysis as they are.
#[derive(Debug, Clone, PartialEq, thiserror::Error, serde::Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum BandWarning {
    /// The analysis runs outside the sampled band: the interpolating code extrapolates there.
    #[error(
        "the coefficients cover {band_from_rpm:.0}–{band_to_rpm:.0} rpm but the rotor analysis runs over \
         {analysis_from_rpm:.0}–{analysis_to_rpm:.0} rpm: outside the band ROSS extrapolates its spline (widen the \
         speeds to cover the analysis)"
    )]
    NarrowerThanAnalysis { band_from_rpm: f64, band_to_rpm: f64, analysis_from_rpm: f64, analysis_to_rpm: f64 },
    /// The coefficients change between these samples more than a cubic through them follows.
    #[error(
        "the coefficients jump between {from_rpm:.1} and {to_rpm:.1} rpm: {term} is {miss_percent:.1} % of its \
         scale off the cubic through the neighbouring samples{}; ROSS's spline overshoots around it{}",
        pads_text(.pads_changing),
        if *.refined { "" } else { " (sample more densely, or let tiltpad refine the band)" }
    )]
    Jump {
        from_rpm: f64,
        to_rpm: f64,
        /// The term that misses most (`kyy`, `cxy`, …).
        term: &'static str,
        miss_percent: f64,
        /// Pads that start or stop floating between these samples.
        pads_changing: Vec<usize>,
        /// Whether the band was refined (the jump is narrower than the refinement could resolve).
        refined: bool,
    },
    /// Refinement stopped at its sample budget with intervals still missing the tolerance.
    #[error(
        "refinement stopped at {samples} samples with {unresolved} intervals still off the cubic by more than \
         {tolerance_percent:.1} % (the first between {from_rpm:.1} and {to_rpm:.1} rpm)"
    )]
    Budget { samples: usize, unresolved: usize, tolerance_percent: f64, from_rpm: f64, to_rpm: f64 },
    /// A speed whose solve failed (left out of the samples).
    #[error("{speed_rpm} rpm left out: {error}")]
    PointFailed { speed_rpm: f64, error: String },
}

fn pads_text(pads: &[usize]) -> String {
    match pads {
        [] => String::new(),
        [p] => format!(" (pad {p} starts or stops floating there)"),
        _ => format!(
            " (pads {} start or stop floating there)",
            pads.iter().map(ToString::to_string).collect::<Vec<_>>().join(", ")
        ),
    }
}

/// The samples of a band, ascending in speed, and what the caller should know about them.
#[derive(Debug, Clone, PartialEq)]
pub struct Band {
    pub samples: Vec<Sample>,
    pub warnings: Vec<BandWarning>,
    /// Solves made (failed ones included).
    pub solves: usize,
}

/// The eight terms, in table order: name, K (true) or C, row, column.
pub const TERMS: [(&str, bool, usize, usize); 8] = [
    ("kxx", true, 0, 0),
    ("kxy", true, 0, 1),
    ("kyx", true, 1, 0),
    ("kyy", true, 1, 1),
    ("cxx", false, 0, 0),
    ("cxy", false, 0, 1),
    ("cyx", false, 1, 0),
    ("cyy", false, 1, 1),
];

fn term(s: &Sample, k: bool, i: usize, j: usize) -> f64 {
    if k {
        s.k_n_per_m[i][j]
    } else {
        s.c_ns_per_m[i][j]
    }
}

/// Largest |K| and |C| term over the samples (never zero).
fn scales(samples: &[Sample]) -> (f64, f64) {
    let max = |k: bool| {
        samples
            .iter()
            .flat_map(|s| TERMS.iter().filter(|t| t.1 == k).map(move |&(_, k, i, j)| term(s, k, i, j).abs()))
            .fold(f64::MIN_POSITIVE, f64::max)
    };
    (max(true), max(false))
}

/// The polynomial through `(x, y)` points evaluated at `at` (Lagrange form; a handful of points).
fn lagrange(points: &[(f64, f64)], at: f64) -> f64 {
    let mut sum = 0.0;
    for (a, &(xa, ya)) in points.iter().enumerate() {
        let mut w = 1.0;
        for (b, &(xb, _)) in points.iter().enumerate() {
            if a != b {
                w *= (at - xb) / (xa - xb);
            }
        }
        sum += w * ya;
    }
    sum
}

/// The neighbours a cubic at `at` goes through: up to two samples below and two above (`skip` left out).
fn neighbours(samples: &[Sample], at: f64, skip: Option<usize>) -> Vec<&Sample> {
    let below: Vec<&Sample> =
        samples.iter().enumerate().filter(|&(i, s)| Some(i) != skip && s.speed_rpm < at).map(|(_, s)| s).collect();
    let above: Vec<&Sample> =
        samples.iter().enumerate().filter(|&(i, s)| Some(i) != skip && s.speed_rpm > at).map(|(_, s)| s).collect();
    below.iter().rev().take(2).rev().chain(above.iter().take(2)).copied().collect()
}

/// How far the cubic through `around` misses `actual`: the worst term and its miss as a fraction of its scale.
fn miss(around: &[&Sample], actual: &Sample, scale: (f64, f64)) -> (&'static str, f64) {
    let mut worst = ("kxx", 0.0);
    if around.len() < 2 {
        return worst;
    }
    for &(name, k, i, j) in &TERMS {
        let points: Vec<(f64, f64)> = around.iter().map(|s| (s.speed_rpm, term(s, k, i, j))).collect();
        let predicted = lagrange(&points, actual.speed_rpm);
        let m = (predicted - term(actual, k, i, j)).abs() / if k { scale.0 } else { scale.1 };
        if m > worst.1 {
            worst = (name, m);
        }
    }
    worst
}

fn insert(samples: &mut Vec<Sample>, s: Sample) {
    let at = samples.partition_point(|x| x.speed_rpm < s.speed_rpm);
    samples.insert(at, s);
}

fn sample_at(samples: &[Sample], rpm: f64) -> Option<&Sample> {
    samples.iter().find(|s| s.speed_rpm == rpm)
}

/// What a point solve gave: a sample, a failure to list, or the end (cancelled).
fn take(
    result: Result<Sample, PointError>,
    rpm: f64,
    warnings: &mut Vec<BandWarning>,
) -> Result<Option<Sample>, PointError> {
    match result {
        Ok(s) => Ok(Some(s)),
        Err(PointError::Solve(SolveError::Cancelled)) => Err(PointError::Solve(SolveError::Cancelled)),
        Err(e) => {
            warnings.push(BandWarning::PointFailed { speed_rpm: rpm, error: e.to_string() });
            Ok(None)
        }
    }
}

/// Samples the band: the requested speeds (ascending, duplicates dropped), refined and checked as the
/// module says. `solve` gives the sample at a speed [rpm].
///
/// # Errors
/// Only a cancelled solve ([`SolveError::Cancelled`]); failed points are warnings.
pub fn sample(
    speeds_rpm: &[f64],
    params: &BandParams,
    solve: &mut dyn FnMut(f64) -> Result<Sample, PointError>,
) -> Result<Band, PointError> {
    let mut speeds: Vec<f64> = speeds_rpm.iter().copied().filter(|v| v.is_finite()).collect();
    speeds.sort_by(f64::total_cmp);
    speeds.dedup();
    let mut warnings = Vec::new();
    let mut samples: Vec<Sample> = Vec::new();
    let mut solves = 0;
    for &rpm in &speeds {
        solves += 1;
        if let Some(s) = take(solve(rpm), rpm, &mut warnings)? {
            samples.push(s);
        }
    }
    let (lo, hi) = match (samples.first(), samples.last()) {
        (Some(a), Some(b)) => (a.speed_rpm, b.speed_rpm),
        _ => return Ok(Band { samples, warnings, solves }),
    };
    if params.refine && samples.len() >= 2 {
        let min_width = (hi - lo) * params.min_width_fraction;
        let mut pending: VecDeque<(f64, f64)> = samples.windows(2).map(|w| (w[0].speed_rpm, w[1].speed_rpm)).collect();
        let mut unresolved: Vec<(f64, f64)> = Vec::new();
        while let Some((a, b)) = pending.pop_front() {
            if samples.len() >= params.max_samples {
                unresolved.push((a, b));
                continue;
            }
            let m = 0.5 * (a + b);
            solves += 1;
            let Some(mid) = take(solve(m), m, &mut warnings)? else { continue };
            let scale = scales(&samples);
            let (_, off) = miss(&neighbours(&samples, m, None), &mid, scale);
            let changes = match (sample_at(&samples, a), sample_at(&samples, b)) {
                (Some(x), Some(y)) => x.floating != y.floating,
                _ => false,
            };
            insert(&mut samples, mid);
            if (off > params.tolerance || changes) && 0.5 * (b - a) >= min_width {
                pending.push_back((a, m));
                pending.push_back((m, b));
            }
        }
        if let Some(&(from_rpm, to_rpm)) = unresolved.first() {
            warnings.push(BandWarning::Budget {
                samples: samples.len(),
                unresolved: unresolved.len(),
                tolerance_percent: 100.0 * params.tolerance,
                from_rpm,
                to_rpm,
            });
        }
    }
    warnings.extend(jumps(&samples, params));
    if let Some([from, to]) = params.analysis_rpm {
        if from < lo || to > hi {
            warnings.push(BandWarning::NarrowerThanAnalysis {
                band_from_rpm: lo,
                band_to_rpm: hi,
                analysis_from_rpm: from,
                analysis_to_rpm: to,
            });
        }
    }
    Ok(Band { samples, warnings, solves })
}

/// The jumps between samples: interior samples the cubic through their neighbours misses by more than the
/// jump tolerance, neighbouring ones merged into one warning (the worst miss named).
fn jumps(samples: &[Sample], params: &BandParams) -> Vec<BandWarning> {
    let scale = scales(samples);
    let mut out: Vec<BandWarning> = Vec::new();
    let mut last_flagged: Option<usize> = None;
    for i in 1..samples.len().saturating_sub(1) {
        let (name, off) = miss(&neighbours(samples, samples[i].speed_rpm, Some(i)), &samples[i], scale);
        if off <= params.jump_tolerance {
            continue;
        }
        let (from, to) = (i - 1, i + 1);
        let merge = last_flagged.is_some_and(|l| l + 2 >= i);
        last_flagged = Some(i);
        if merge {
            if let Some(BandWarning::Jump { to_rpm, term, miss_percent, .. }) = out.last_mut() {
                *to_rpm = samples[to].speed_rpm;
                if 100.0 * off > *miss_percent {
                    *term = name;
                    *miss_percent = 100.0 * off;
                }
            }
        } else {
            out.push(BandWarning::Jump {
                from_rpm: samples[from].speed_rpm,
                to_rpm: samples[to].speed_rpm,
                term: name,
                miss_percent: 100.0 * off,
                pads_changing: Vec::new(),
                refined: params.refine,
            });
        }
    }
    for w in &mut out {
        if let BandWarning::Jump { from_rpm, to_rpm, pads_changing, .. } = w {
            if let Some((a, b)) = step_within(samples, *from_rpm, *to_rpm, scale) {
                (*from_rpm, *to_rpm) = (a, b);
            }
            let inside: Vec<&Sample> =
                samples.iter().filter(|s| s.speed_rpm >= *from_rpm && s.speed_rpm <= *to_rpm).collect();
            let mut pads: Vec<usize> = inside
                .windows(2)
                .flat_map(|p| {
                    let (a, b) = (&p[0].floating, &p[1].floating);
                    a.iter().filter(|x| !b.contains(x)).chain(b.iter().filter(|x| !a.contains(x))).copied()
                })
                .collect();
            pads.sort_unstable();
            pads.dedup();
            *pads_changing = pads;
        }
    }
    out
}

/// The interval of `[from, to]` where the coefficients step: the neighbouring samples whose largest change
/// (any term, over its scale) is at least twice that of every other neighbouring pair in the range — a
/// discontinuity is there. `None` when no pair stands out so (a kink, or curves too coarse for the samples).
fn step_within(samples: &[Sample], from: f64, to: f64, scale: (f64, f64)) -> Option<(f64, f64)> {
    let inside: Vec<&Sample> = samples.iter().filter(|s| s.speed_rpm >= from && s.speed_rpm <= to).collect();
    let change = |a: &Sample, b: &Sample| {
        TERMS
            .iter()
            .map(|&(_, k, i, j)| (term(b, k, i, j) - term(a, k, i, j)).abs() / if k { scale.0 } else { scale.1 })
            .fold(0.0, f64::max)
    };
    let changes: Vec<f64> = inside.windows(2).map(|p| change(p[0], p[1])).collect();
    let (at, &largest) = changes.iter().enumerate().max_by(|a, b| a.1.total_cmp(b.1))?;
    let others = changes.iter().enumerate().filter(|&(i, _)| i != at).map(|(_, &c)| c).fold(0.0, f64::max);
    (largest >= 2.0 * others).then(|| (inside[at].speed_rpm, inside[at + 1].speed_rpm))
}

/// The sample at `speed_rpm` solved by a study runner (the point overrides `operating.speed_rpm`).
///
/// # Errors
/// The point's case or solve error.
pub fn solve_point(runner: &mut Runner, speed_rpm: f64, cancel: &dyn Cancel) -> Result<Sample, PointError> {
    let s = runner.solve_with(&[("operating.speed_rpm".into(), format!("{speed_rpm:?}"))], cancel)?;
    Ok(Sample {
        speed_rpm,
        speed_rad_s: s.derived.speed_rad_s,
        excitation_rad_s: s.reduced.omega_rad_s,
        k_n_per_m: s.reduced.k_n_per_m,
        c_ns_per_m: s.reduced.c_ns_per_m,
        floating: s.pads.iter().filter(|p| p.unloaded).map(|p| p.index).collect(),
    })
}

/// The runner a band samples with: each speed from scratch, on `text` with `base` overrides (see the module).
#[must_use]
pub fn cold_runner(text: impl Into<String>, base: Vec<String>) -> Runner {
    Runner::new(text, base, false)
}

/// `n` evenly spaced speeds from `from` to `to` [rpm].
#[must_use]
pub fn linspace_rpm(from: f64, to: f64, n: usize) -> Vec<f64> {
    #[allow(clippy::cast_precision_loss)]
    (0..n).map(|i| if n < 2 { from } else { from + (to - from) * i as f64 / (n - 1) as f64 }).collect()
}

/// The speed in rad/s of `rpm`.
#[must_use]
pub fn rad_s(rpm: f64) -> f64 {
    RPM.to_si(rpm)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A bearing-like sample: K grows smoothly with speed; `f` shapes kyy.
    fn synthetic(rpm: f64, kyy: impl Fn(f64) -> f64, floating: Vec<usize>) -> Sample {
        let x = rpm / 1000.0;
        Sample {
            speed_rpm: rpm,
            speed_rad_s: rad_s(rpm),
            excitation_rad_s: rad_s(rpm),
            k_n_per_m: [[1e8 * (1.0 + 0.1 * x), 2e6 * x], [-3e6 * x, kyy(rpm)]],
            c_ns_per_m: [[2e5 / (1.0 + 0.05 * x), 0.0], [0.0, 3e5 / (1.0 + 0.05 * x)]],
            floating,
        }
    }

    fn run(speeds: &[f64], params: &BandParams, f: impl Fn(f64) -> Sample) -> Band {
        sample(speeds, params, &mut |rpm| Ok(f(rpm))).unwrap()
    }

    #[test]
    fn smooth_coefficients_need_one_check_per_interval_and_warn_nothing() {
        let speeds = linspace_rpm(3000.0, 12000.0, 10);
        let band = run(&speeds, &BandParams::default(), |r| synthetic(r, |r| 2e8 * (1.0 + r / 20_000.0), vec![]));
        // Ten requested speeds and nine checked midpoints, all met within the tolerance.
        assert_eq!(band.samples.len(), 19);
        assert_eq!(band.solves, 19);
        assert!(band.warnings.is_empty(), "{:?}", band.warnings);
        for s in &speeds {
            assert!(band.samples.iter().any(|x| x.speed_rpm == *s), "{s} kept");
        }
        assert!(band.samples.windows(2).all(|w| w[0].speed_rpm < w[1].speed_rpm));
    }

    /// A pad that starts floating at 7100 rpm bends kyy there (a kink): refinement gathers samples around the
    /// kink, the cubic then meets every further midpoint, and no jump is left to warn about.
    #[test]
    fn a_pad_changing_state_draws_samples_to_it() {
        let kink = 7100.0;
        let kyy = move |r: f64| 2e8 + if r > kink { 4e4 * (r - kink) } else { 0.0 };
        let f = move |r: f64| synthetic(r, kyy, if r > kink { vec![2] } else { vec![] });
        let speeds = linspace_rpm(3000.0, 12000.0, 10);
        let band = run(&speeds, &BandParams::default(), f);
        let near = band.samples.iter().filter(|s| (s.speed_rpm - kink).abs() < 100.0).count();
        let far = band.samples.iter().filter(|s| (s.speed_rpm - 4000.0).abs() < 500.0).count();
        assert!(near >= 6, "{near} samples within 100 rpm of the kink");
        assert!(far <= 3, "{far} samples around 4000 rpm, where the curves are smooth");
        let width = (12000.0 - 3000.0) / 512.0;
        let closest = band.samples.windows(2).find(|w| w[0].speed_rpm <= kink && w[1].speed_rpm > kink).unwrap();
        assert!(closest[1].speed_rpm - closest[0].speed_rpm <= width * 1.0001, "{closest:?}");
        assert!(band.warnings.is_empty(), "{:?}", band.warnings);
        // Without refinement the same ten speeds leave the kink between two samples: a jump is warned.
        let coarse = run(&speeds, &BandParams { refine: false, ..BandParams::default() }, f);
        assert_eq!(coarse.samples.len(), 10);
        let jump = coarse.warnings.iter().find_map(|w| match w {
            BandWarning::Jump { from_rpm, to_rpm, term, pads_changing, refined, .. } => {
                Some((*from_rpm, *to_rpm, *term, pads_changing.clone(), *refined))
            }
            _ => None,
        });
        let (from, to, term, pads, refined) = jump.expect("the kink is warned");
        assert!(from < kink && to > kink, "{from}–{to}");
        assert_eq!((term, pads, refined), ("kyy", vec![2], false));
    }

    /// A real discontinuity survives refinement: it is narrowed to the finest interval and warned.
    #[test]
    fn a_jump_is_narrowed_and_warned() {
        let at = 8333.0;
        let f = move |r: f64| synthetic(r, |r| if r > at { 2.6e8 } else { 2e8 }, vec![]);
        let band = run(&linspace_rpm(3000.0, 12000.0, 10), &BandParams::default(), f);
        let jumps: Vec<&BandWarning> = band.warnings.iter().filter(|w| matches!(w, BandWarning::Jump { .. })).collect();
        assert_eq!(jumps.len(), 1, "{:?}", band.warnings);
        let BandWarning::Jump { from_rpm, to_rpm, term, miss_percent, refined, .. } = jumps[0] else { unreachable!() };
        // Located to the one finest interval that holds the step.
        assert!(*from_rpm < at && *to_rpm > at && to_rpm - from_rpm <= 9000.0 / 512.0 + 1e-9, "{from_rpm}–{to_rpm}");
        assert_eq!(*term, "kyy");
        assert!(*miss_percent > 2.0 && *refined, "{miss_percent}");
        assert!(jumps[0].to_string().contains("kyy"), "{}", jumps[0]);
    }

    #[test]
    fn an_analysis_beyond_the_band_is_warned_and_failed_points_are_listed() {
        let params = BandParams { analysis_rpm: Some([1000.0, 12000.0]), refine: false, ..BandParams::default() };
        let mut solve = |r: f64| {
            if r == 5000.0 {
                Err(PointError::Solve(SolveError::NoHydraulics))
            } else {
                Ok(synthetic(r, |_| 2e8, vec![]))
            }
        };
        let band = sample(&[3000.0, 5000.0, 9000.0, 11000.0], &params, &mut solve).unwrap();
        assert_eq!(band.samples.len(), 3);
        assert!(band
            .warnings
            .iter()
            .any(|w| matches!(w, BandWarning::PointFailed { speed_rpm, .. } if *speed_rpm == 5000.0)));
        let narrow = band.warnings.iter().find(|w| matches!(w, BandWarning::NarrowerThanAnalysis { .. })).unwrap();
        assert!(narrow.to_string().contains("3000–11000 rpm") && narrow.to_string().contains("1000–12000"), "{narrow}");
        let inside = BandParams { analysis_rpm: Some([3000.0, 11000.0]), ..params };
        let band = sample(&[3000.0, 9000.0, 11000.0], &inside, &mut solve).unwrap();
        assert!(band.warnings.is_empty(), "{:?}", band.warnings);
        // A cancelled solve ends the sampling.
        let mut cancelled = |_| Err(PointError::Solve(SolveError::Cancelled));
        assert!(sample(&[3000.0, 4000.0], &BandParams::default(), &mut cancelled).is_err());
    }

    #[test]
    fn refinement_keeps_to_its_budget() {
        let f = |r: f64| synthetic(r, |r| 2e8 * (1.0 + (r / 137.0).sin() * 0.2), vec![]);
        let params = BandParams { max_samples: 40, ..BandParams::default() };
        let band = run(&linspace_rpm(3000.0, 12000.0, 10), &params, f);
        assert_eq!(band.samples.len(), 40);
        assert!(
            band.warnings.iter().any(|w| matches!(w, BandWarning::Budget { samples: 40, .. })),
            "{:?}",
            band.warnings
        );
    }
}
