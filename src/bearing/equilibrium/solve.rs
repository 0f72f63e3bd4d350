//! The equilibrium solve: the prescribed-position case, then the coupled Newton from the initial guess, then
//! the fallbacks ([`super::fallback`]); the converged state is finished ([`super::finish`]) or the failure
//! classified.

use crate::bearing::report::error::InternalError;
use crate::bearing::report::warning::Method;
use crate::bearing::report::warning::Warning;
use web_time::Instant;

use crate::bearing::equilibrium::state::{Equilibrium, EquilibriumParams, Found, Resume};
use crate::bearing::equilibrium::{coupled, eval, fallback, finish, pad};
use crate::bearing::film::model::{BearingModel, OperatingPoint};
use crate::bearing::report::error::SolveError;
use crate::bearing::report::progress::{Cancel, NoSuspend, Progress};
use crate::model::LoadSpec;
use crate::physics::reynolds::FilmError;

/// Solves the static equilibrium (or, for a prescribed position, the pads and the load) to the end.
///
/// `start`: a previous solution's global coordinates to warm-start from (sweeps).
///
/// # Errors
/// Touchdown, non-convergence, budgets, film failures or cancellation.
pub fn solve_equilibrium(
    model: &mut BearingModel,
    op: &OperatingPoint,
    params: EquilibriumParams,
    start: Option<&[f64]>,
    cancel: &dyn Cancel,
) -> Result<Equilibrium, SolveError> {
    match step_equilibrium(model, op, params, start, &NoSuspend(cancel))? {
        Progress::Done(eq) => Ok(eq),
        // NoSuspend never asks for a pause.
        Progress::Suspended(r) => {
            Err(SolveError::Internal(InternalError::Paused { what: "equilibrium".into(), parts: r.report.iterations }))
        }
    }
}

/// As [`solve_equilibrium`], but pauses when `cancel` asks for it ([`Cancel::suspend`]): the coupled Newton
/// pauses between its cold-start pad placements and between iterations; resume by calling again with
/// `start = resume.coordinates` and `params.placed_pads = resume.placed_pads`.
///
/// # Errors
/// As [`solve_equilibrium`].
pub fn step_equilibrium(
    model: &mut BearingModel,
    op: &OperatingPoint,
    params: EquilibriumParams,
    start: Option<&[f64]>,
    cancel: &dyn Cancel,
) -> Result<Progress<Equilibrium, Resume>, SolveError> {
    let t0 = Instant::now();
    let mut ctx = eval::Ctx::new(model, op, params, t0);
    let result = solve_inner(model, &mut ctx, start, cancel);
    match result {
        Ok(Progress::Done(found)) => finish::finish(model, found, ctx).map(Progress::Done),
        Ok(Progress::Suspended(mut r)) => {
            r.report = std::mem::take(&mut ctx.report);
            r.report.seconds = t0.elapsed().as_secs_f64();
            Ok(Progress::Suspended(r))
        }
        Err(e) => Err(finish::classify_failure(model, &ctx, e)),
    }
}

/// Tries the methods in turn.
fn solve_inner(
    model: &mut BearingModel,
    ctx: &mut eval::Ctx<'_>,
    start: Option<&[f64]>,
    cancel: &dyn Cancel,
) -> Result<Progress<Found, Resume>, SolveError> {
    let cb = model.assembled_clearance;
    let n = model.n_dofs();
    if let LoadSpec::Position { eccentricity_ratio, angle_rad } = ctx.op.load {
        let journal = [eccentricity_ratio * cb * angle_rad.cos(), eccentricity_ratio * cb * angle_rad.sin()];
        let mut u = start.filter(|s| s.len() == n).map_or_else(|| vec![0.0; n], <[f64]>::to_vec);
        u[..2].copy_from_slice(&journal);
        let (pads, force) = pad::solve_all_pads(model, journal, &u, ctx).map_err(|(k, e)| match e {
            FilmError::Contact { h_min_m, theta_deg, .. } => SolveError::PositionClosesFilm {
                pad: k,
                h_min_um: crate::units::UM.from_si(h_min_m),
                theta_deg,
                eccentricity_ratio,
            },
            e => ctx.film_error(k, e),
        })?;
        let u = pad::assemble_u(model, journal, &pads);
        return Ok(Progress::Done(Found { u, pads, force, method: Method::PrescribedPosition }));
    }

    // A journal that does not turn, without injection, has no pressure source: no film solve can carry a load.
    let w = eval::external_load(ctx.op, 1.0);
    if ctx.op.speed_rad_s == 0.0 && ctx.op.injection_pressure.iter().all(|p| *p <= 0.0) && w[0].hypot(w[1]) > 0.0 {
        return Err(SolveError::NoRotation { load_n: w[0].hypot(w[1]) });
    }

    // Initial guess: previous solution, else a small displacement along the load.
    let warm = start.filter(|s| s.len() == n && s.iter().all(|v| v.is_finite()));
    let u0 = warm.map_or_else(
        || {
            let mut u = vec![0.0; n];
            let dir = eval::load_direction(ctx.op);
            u[0] = 0.2 * cb * dir[0];
            u[1] = 0.2 * cb * dir[1];
            u
        },
        <[f64]>::to_vec,
    );
    let cold = ctx.params.placed_pads > 0 || warm.is_none();
    match coupled::coupled_newton(model, &u0, cold, ctx, cancel)? {
        Progress::Suspended(r) => return Ok(Progress::Suspended(r)),
        Progress::Done(Ok(found)) => return Ok(Progress::Done(found)),
        Progress::Done(Err(fail)) => ctx.report.warn(Warning::MethodFailed {
            method: Method::CoupledNewton,
            reason: fail.reason,
            next: Method::Fallbacks,
        }),
    }
    // The fallbacks run to the end once started (their state is not a single iterate to resume from).
    fallback::run(model, &u0, ctx, &NoSuspend(cancel)).map(Progress::Done)
}
