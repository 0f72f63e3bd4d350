//! The converged state as a result: residuals, the full linearisation (stiffness and damping) at the
//! converged films, floating pads, touchdown, the report; and failures classified (a film last seen nearly
//! closed after every method failed is touchdown).
//!
//! ## Floating pads
//! A pad whose load share is below [`FLOATING_SHARE`] *floats*: its film is at the cavitation (ambient)
//! pressure almost everywhere — a zero-preload pad whose film is uniform, or a diverging film. A Lund-type
//! linearisation about it is ill-posed: any separating motion ruptures the film, which cannot carry tension,
//! while which nodes the active set calls "full" at p = 0 is decided by round-off (the damping of such
//! pads changed by 10× between meshes). The film of a floating pad is treated as cavitated: it contributes
//! no stiffness and no damping, so its coordinates decouple from the journal (only their structural
//! stiffness and inertia remain), identically on every mesh. The report lists the floating pads.

use crate::bearing::report::warning::Warning;
use crate::model::LoadSpec;
use crate::physics::reynolds::{FilmError, FilmLinearization};

use crate::bearing::equilibrium::eval::{account, external_load, min_film, Ctx};
use crate::bearing::equilibrium::journal::{nearest_normal, pads_surround};
use crate::bearing::equilibrium::state::{Equilibrium, Found, FLOATING_SHARE, TOUCHDOWN_FRACTION};
use crate::bearing::film::coordinates::PadDof;
use crate::bearing::film::model::BearingModel;
use crate::bearing::report::error::SolveError;

/// Pad residual (relative) above which a converged state is reported with a warning.
const PAD_RESIDUAL_WARNING: f64 = 1e3;
/// A minimum film below this multiple of the touchdown film is reported as close to touchdown.
const TOUCHDOWN_WARNING: f64 = 2.0;

/// Turns a found state into an [`Equilibrium`] (or touchdown).
pub(super) fn finish(model: &mut BearingModel, found: Found, mut ctx: Ctx<'_>) -> Result<Equilibrium, SolveError> {
    let Found { u, mut pads, force, method } = found;
    let op = ctx.op;
    let cb = model.assembled_clearance;
    let w = external_load(op, 1.0);
    ctx.report.residual = if matches!(op.load, LoadSpec::Force { .. }) {
        (force[0] + w[0]).hypot(force[1] + w[1]) / ctx.force_scale
    } else {
        0.0
    };
    ctx.report.method = method;
    for (k, p) in pads.iter_mut().enumerate() {
        // The films must hold the returned state (a search may have evaluated a pad elsewhere last).
        let local = model.local(k, &u);
        if model.pads[k].film.coordinates() != local.as_slice() {
            let film = &mut model.pads[k].film;
            film.set_coordinates(&local).map_err(|e| SolveError::Film { pad: k, error: e })?;
            let info = film.solve(&op.film_inputs(k), true).map_err(|e| SolveError::Film { pad: k, error: e })?;
            account(&mut ctx, k, info);
        }
        let share = ctx.share(p);
        let film = &mut model.pads[k].film;
        if share < FLOATING_SHARE {
            p.unloaded = true;
            let n = film.geom.n_dofs();
            p.lin = FilmLinearization {
                stiffness: nalgebra::DMatrix::zeros(n, n),
                damping: nalgebra::DMatrix::zeros(n, n),
            };
            ctx.report.floating_pads.push(k);
            ctx.report.warn(Warning::PadFloats { pad: k, share, tilting: !model.pads[k].dofs().is_empty() });
            if ctx.loaded_state_found.contains(&k) {
                ctx.report.warn(Warning::PadNearFold { pad: k });
            }
        } else {
            // Full linearisation (stiffness and damping) at the converged state: the films hold it.
            p.lin = film.linearize(&op.film_inputs(k));
            if p.residual > PAD_RESIDUAL_WARNING * ctx.params.pad_tol {
                ctx.report.warn(Warning::PadResidual { pad: k, residual: p.residual });
            }
        }
    }
    ctx.report.pad_residual = pads.iter().filter(|p| !p.unloaded).fold(0.0_f64, |m, p| m.max(p.residual));
    let (kmin, hmin) = min_film(model);
    if hmin < op.touchdown_film {
        return Err(SolveError::Touchdown {
            pad: kmin,
            h_min_um: crate::units::UM.from_si(hmin),
            eccentricity_ratio: u[0].hypot(u[1]) / cb,
        });
    }
    if hmin < TOUCHDOWN_WARNING * op.touchdown_film {
        ctx.report.warn(Warning::NearTouchdown { pad: kmin, h_min_m: hmin, touchdown_film_m: op.touchdown_film });
    }
    ctx.report.seconds = ctx.elapsed();
    Ok(Equilibrium { u, pads, film_force: force, report: ctx.report })
}

/// Every method failed with the films last seen close to contact (a positive film thinner than
/// [`TOUCHDOWN_FRACTION`] of the clearance at the last film the solver accepted): the load cannot be carried,
/// which is touchdown, on the pad named. A film that closes (h ≤ 0) at a trial position of a search is not a
/// state of the bearing and is not called touchdown ([`SolveError::FilmClosed`]); a spent work budget is
/// reported as the budget, whatever the films looked like when it ran out.
///
/// A tilting-pad bearing whose pads do not surround the load cannot carry it whatever a search met on its
/// way (an unloaded pad pressed onto the journal by its own film while the journal wandered along the
/// unsupported direction): a touchdown or closed film there is reported as the missing stiffness it follows from.
pub(super) fn classify_failure(model: &BearingModel, ctx: &Ctx<'_>, e: SolveError) -> SolveError {
    match classify_contact(model, e) {
        e @ (SolveError::Touchdown { .. } | SolveError::FilmClosed { .. }) => unsupported_load(model, ctx).unwrap_or(e),
        e => e,
    }
}

/// The missing stiffness of a bearing of tilting pads whose pads do not surround the load: the direction
/// met during the search, else the one across the pad normal nearest the load.
fn unsupported_load(model: &BearingModel, ctx: &Ctx<'_>) -> Option<SolveError> {
    let w = external_load(ctx.op, 1.0);
    let tilting = model.pads.iter().all(|pm| pm.dofs().contains(&PadDof::Tilt));
    if !tilting || w[0].hypot(w[1]) == 0.0 || pads_surround(&model.pads, w) {
        return None;
    }
    if let Some((axis_deg, load_component_n)) = ctx.no_stiffness {
        return Some(SolveError::NoStiffness { axis_deg, load_component_n });
    }
    let n = nearest_normal(&model.pads, w)?;
    let across = [-n[1], n[0]];
    let component = w[0] * across[0] + w[1] * across[1];
    Some(SolveError::NoStiffness {
        axis_deg: across[1].atan2(across[0]).to_degrees().rem_euclid(180.0),
        load_component_n: component.abs(),
    })
}

fn classify_contact(model: &BearingModel, e: SolveError) -> SolveError {
    let cb = model.assembled_clearance;
    let journal_ecc = || {
        let e = model.pads.first().map_or(&[0.0, 0.0][..], |p| p.film.coordinates());
        e[0].hypot(e[1]) / cb
    };
    match e {
        SolveError::NotConverged { .. } => {
            let (pad, hmin) = min_film(model);
            if hmin > 0.0 && hmin < TOUCHDOWN_FRACTION * cb {
                SolveError::Touchdown {
                    pad,
                    h_min_um: crate::units::UM.from_si(hmin),
                    eccentricity_ratio: journal_ecc(),
                }
            } else {
                e
            }
        }
        SolveError::Film { pad, error: FilmError::Contact { h_min_m, theta_deg, .. } } => SolveError::FilmClosed {
            pad,
            h_min_um: crate::units::UM.from_si(h_min_m),
            theta_deg,
            eccentricity_ratio: journal_ecc(),
        },
        e => e,
    }
}
