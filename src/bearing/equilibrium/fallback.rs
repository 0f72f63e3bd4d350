//! Fallbacks after the coupled Newton, all on the journal position with every pad solved inside (Lund's
//! pad assembly, so the journal force `F(e)` is the bearing's static force law):
//!
//! 1. Newton on `F(e) + W = 0` with the pad-condensed stiffness, from the initial guess.
//! 2. The polar bracketing search ([`crate::bearing::equilibrium::polar`]): converges for any continuous restoring force law,
//!    including the non-smooth ones of zero-preload pads whose film is uniform.
//! 3. A scan along the load for the first stable crossing (negative-stiffness regions and folds, e.g.
//!    hydrostatic pads on soft pivots), then Newton.
//! 4. Load continuation from a centred journal.
//!
//! Each returns a converged state or why it stopped; the last failure becomes the error.

use nalgebra::Vector2;

use crate::physics::reynolds::FilmError;

use crate::bearing::equilibrium::eval::{external_load, load_direction, min_film, Ctx};
use crate::bearing::equilibrium::journal::{bearing_stiffness, journal_step, pads_surround};
use crate::bearing::equilibrium::pad::{assemble_u, solve_all_pads, solve_all_pads_open};
use crate::bearing::equilibrium::polar::polar_search;
use crate::bearing::equilibrium::state::{Found, Stall, SUFFICIENT_DECREASE, TOUCHDOWN_FRACTION};
use crate::bearing::film::model::BearingModel;
use crate::bearing::report::error::SolveError;
use crate::bearing::report::error::StallReason;
use crate::bearing::report::progress::Cancel;
use crate::bearing::report::warning::{Method, Warning};

/// Backtracking halvings of a journal Newton step.
const LINE_SEARCH_HALVINGS: usize = 14;
/// Load steps of the continuation.
const CONTINUATION_STEPS: usize = 12;
/// Step of the scan along the load, as a fraction of the assembled clearance, and its extent.
const SCAN_STEP: f64 = 0.1;
const SCAN_STEPS: usize = 100;

/// Runs the fallbacks in turn from `u0`.
pub(super) fn run(
    model: &mut BearingModel,
    u0: &[f64],
    ctx: &mut Ctx<'_>,
    cancel: &dyn Cancel,
) -> Result<Found, SolveError> {
    let named = |r: Result<Found, Stall>, method: Method| r.map(|f| Found { method, ..f });
    let failed = |method, s: Stall, next| Warning::MethodFailed { method, reason: s.reason, next };
    match named(newton_journal(model, u0, 1.0, ctx, cancel)?, Method::PadAssemblyNewton) {
        Ok(f) => return Ok(f),
        Err(s) => ctx.report.warn(failed(Method::PadAssemblyNewton, s, Method::PolarSearch)),
    }
    if let Some((axis_deg, load_component_n)) = ctx.no_stiffness {
        // Outside the cone of the pads no search can find stiffness: that is the answer.
        if !pads_surround(&model.pads, external_load(ctx.op, 1.0)) {
            return Err(SolveError::NoStiffness { axis_deg, load_component_n });
        }
    }
    // The searches below start from a centred journal, with the pads where `u0` has them (pads held by an
    // outer thermal loop keep their coordinates).
    let mut centred = u0.to_vec();
    centred[..2].fill(0.0);
    match named(polar_search(model, &centred, ctx, cancel)?, Method::PolarSearch) {
        Ok(f) => return Ok(f),
        Err(s) => ctx.report.warn(failed(Method::PolarSearch, s, Method::ScanAlongLoad)),
    }
    if let Some((pad, below_n, above_n)) = ctx.force_gap {
        // The force along the load jumps from below it to above it (the ray's bracket): the scan and the
        // continuation would meet the same jump (every fraction of the load falls in it too).
        let w = external_load(ctx.op, 1.0);
        return Err(SolveError::ForceGap { pad, below_n, above_n, load_n: w[0].hypot(w[1]) });
    }
    if let Some(u_scan) = scan_along_load(model, &centred, ctx, cancel)? {
        match named(newton_journal(model, &u_scan, 1.0, ctx, cancel)?, Method::ScanAlongLoad) {
            Ok(f) => return Ok(f),
            Err(s) => ctx.report.warn(failed(Method::ScanAlongLoad, s, Method::LoadContinuation)),
        }
    }
    continuation(model, &centred, ctx, cancel)
}

/// Newton on the journal position for load fraction `fraction`, from `u0`.
pub(super) fn newton_journal(
    model: &mut BearingModel,
    u0: &[f64],
    fraction: f64,
    ctx: &mut Ctx<'_>,
    cancel: &dyn Cancel,
) -> Result<Result<Found, Stall>, SolveError> {
    let w = external_load(ctx.op, fraction);
    let cb = model.assembled_clearance;
    let mut journal = [u0[0], u0[1]];
    let mut u = u0.to_vec();
    let (mut states, mut f) = match solve_all_pads_open(model, journal, &u, ctx) {
        Ok(x) => x,
        Err((_, FilmError::Contact { .. })) => {
            // Start from the centre if the guess closes a film.
            journal = [0.0, 0.0];
            u[..2].fill(0.0);
            solve_all_pads(model, journal, &u, ctx).map_err(|(k, e)| ctx.film_error(k, e))?
        }
        Err((k, e)) => return Err(ctx.film_error(k, e)),
    };
    let tol = ctx.params.force_tol * ctx.force_scale;
    let stall = |journal: [f64; 2], r: Vector2<f64>, reason: StallReason, scale: f64| Stall {
        journal,
        residual: r.norm() / scale,
        reason,
    };
    for _ in 0..ctx.params.max_iterations {
        if cancel.cancelled() {
            return Err(SolveError::Cancelled);
        }
        ctx.report.iterations += 1;
        let r = Vector2::new(f[0] + w[0], f[1] + w[1]);
        ctx.report.residual_history.push(r.norm() / ctx.force_scale);
        u = assemble_u(model, journal, &states);
        if r.norm() <= tol {
            return Ok(Ok(Found { u, pads: states, force: f, method: Method::None }));
        }
        let mut step = match journal_step(&bearing_stiffness(&model.pads, &states), &r, tol) {
            Ok((step, _)) => step,
            Err(reason) => {
                if let StallReason::NoStiffnessAlong { axis_deg, component_n } = reason {
                    ctx.no_stiffness = Some((axis_deg, component_n));
                }
                return Ok(Err(stall(journal, r, reason, ctx.force_scale)));
            }
        };
        let max = ctx.params.max_step * cb;
        if step.norm() > max {
            step *= max / step.norm();
        }
        let mut alpha = 1.0;
        let mut accepted = None;
        for _ in 0..LINE_SEARCH_HALVINGS {
            let trial = [journal[0] + alpha * step[0], journal[1] + alpha * step[1]];
            match solve_all_pads_open(model, trial, &u, ctx) {
                Ok((st2, f2)) => {
                    let r2 = Vector2::new(f2[0] + w[0], f2[1] + w[1]);
                    if r2.norm() < (1.0 - SUFFICIENT_DECREASE * alpha) * r.norm() || r2.norm() <= tol {
                        accepted = Some((trial, st2, f2));
                        break;
                    }
                }
                Err((_, FilmError::Contact { .. })) => {}
                Err((k, e)) => return Err(ctx.film_error(k, e)),
            }
            alpha *= 0.5;
        }
        let Some((j, s, ff)) = accepted else {
            // Leave the films at the last accepted point.
            let _ = solve_all_pads(model, journal, &u, ctx);
            return Ok(Err(stall(journal, r, StallReason::NoDecrease, ctx.force_scale)));
        };
        journal = j;
        states = s;
        f = ff;
    }
    let r = Vector2::new(f[0] + w[0], f[1] + w[1]);
    Ok(Err(stall(journal, r, StallReason::IterationLimit(ctx.params.max_iterations), ctx.force_scale)))
}

/// Walks the journal along the load direction from the centre in steps of 0.1 Cb until the residual along
/// the load changes sign with a restoring slope; returns the coordinates there (or `None`).
fn scan_along_load(
    model: &mut BearingModel,
    centred: &[f64],
    ctx: &mut Ctx<'_>,
    cancel: &dyn Cancel,
) -> Result<Option<Vec<f64>>, SolveError> {
    let w = external_load(ctx.op, 1.0);
    let dir = load_direction(ctx.op);
    if dir == [0.0, 0.0] {
        return Ok(None);
    }
    let cb = model.assembled_clearance;
    let mut u = centred.to_vec();
    let mut prev: Option<(f64, Vec<f64>)> = None;
    for i in 0..=SCAN_STEPS {
        if cancel.cancelled() {
            return Err(SolveError::Cancelled);
        }
        #[allow(clippy::cast_precision_loss)]
        let e = SCAN_STEP * cb * i as f64;
        let journal = [e * dir[0], e * dir[1]];
        let Ok((states, f)) = solve_all_pads_open(model, journal, &u, ctx) else { return Ok(None) };
        let g = (f[0] + w[0]) * dir[0] + (f[1] + w[1]) * dir[1];
        u = assemble_u(model, journal, &states);
        if let Some((gp, up)) = &prev {
            if *gp > 0.0 && g <= 0.0 {
                // Linear interpolation between the bracketing points.
                let t = gp / (gp - g);
                return Ok(Some(up.iter().zip(&u).map(|(a, b)| a + t * (b - a)).collect()));
            }
        }
        prev = Some((g, u.clone()));
    }
    Ok(None)
}

/// Load continuation from a centred journal; touchdown when a step fails with a film nearly closed.
fn continuation(
    model: &mut BearingModel,
    centred: &[f64],
    ctx: &mut Ctx<'_>,
    cancel: &dyn Cancel,
) -> Result<Found, SolveError> {
    let cb = model.assembled_clearance;
    let mut u = centred.to_vec();
    let mut last = Stall { journal: [0.0; 2], residual: 0.0, reason: StallReason::None };
    for s in 1..=CONTINUATION_STEPS {
        #[allow(clippy::cast_precision_loss)]
        let frac = s as f64 / CONTINUATION_STEPS as f64;
        match newton_journal(model, &u, frac, ctx, cancel)? {
            Ok(found) if s == CONTINUATION_STEPS => return Ok(Found { method: Method::LoadContinuation, ..found }),
            Ok(found) => u = found.u,
            Err(stall) => {
                let (pad, hmin) = min_film(model);
                if hmin < TOUCHDOWN_FRACTION * cb {
                    let ecc = stall.journal[0].hypot(stall.journal[1]) / cb;
                    return Err(SolveError::Touchdown {
                        pad,
                        h_min_um: crate::units::UM.from_si(hmin),
                        eccentricity_ratio: ecc,
                    });
                }
                last = stall;
                break;
            }
        }
    }
    if let Some((pad, angle_rad, before_n, after_n)) = ctx.gap_2d {
        // The polar search met the jump off the load direction, and neither the scan nor the continuation
        // found a state beyond it.
        let w = external_load(ctx.op, 1.0);
        return Err(SolveError::ForceGap2d {
            pad,
            angle_deg: angle_rad.to_degrees(),
            before_n,
            after_n,
            load_n: w[0].hypot(w[1]),
        });
    }
    if let Some(b) = ctx.exhausted() {
        return Err(ctx.budget_error(b));
    }
    if let Some((pad, hmin, ecc)) = ctx.closes_before_balance.filter(|c| c.1 > 0.0) {
        return Err(SolveError::Touchdown { pad, h_min_um: crate::units::UM.from_si(hmin), eccentricity_ratio: ecc });
    }
    if let Some((axis_deg, load_component_n)) = ctx.no_stiffness {
        if !pads_surround(&model.pads, external_load(ctx.op, 1.0)) {
            return Err(SolveError::NoStiffness { axis_deg, load_component_n });
        }
        // Pads surround the load, so some pad can carry it: the missing stiffness is where the search
        // stopped, not an answer.
        last.reason = StallReason::StoppedWithoutStiffness { reason: Box::new(last.reason), axis_deg };
    }
    Err(SolveError::NotConverged { iterations: ctx.report.iterations, residual: last.residual, reason: last.reason })
}
