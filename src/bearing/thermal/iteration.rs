//! The pieces of one outer iteration of the thermal loop: each pad's thermal set-up, the nodal viscosity of
//! a temperature field, the equilibrium settings and warm-started equilibrium at the current field, the
//! pads' load shares, the film temperatures of all pads with the groove mixing, and the viscosity change
//! that decides convergence.

use crate::bearing::report::error::InternalError;
use crate::bearing::report::error::ThermalSystem;
use crate::bearing::thermal::model::{ThermalModel, ThermalParams};
use crate::bearing::thermal::resumable;

use crate::fem::supg::Stabilisation;
use crate::model::{Case, CavitatedFilm, PadFilmBc};
use crate::physics::energy::{Exchange, Injection, Oil};
use crate::physics::pad_conduction::PadMaterial;

use crate::bearing::equilibrium::{Equilibrium, EquilibriumParams};
use crate::bearing::film::model::{BearingModel, OperatingPoint};
use crate::bearing::report::error::SolveError;
use crate::bearing::report::progress::{Cancel, NoSuspend, Progress};
use crate::bearing::thermal::mixing::inlet_and_journal;
use crate::bearing::thermal::pad_system::{PadTemperatures, ThermalSetup};

pub(super) fn setup(case: &Case, op: &OperatingPoint, k: usize, stabilisation: Stabilisation) -> ThermalSetup {
    let l = &case.lubricant;
    let t = &case.thermal;
    ThermalSetup {
        oil: Oil {
            density: l.density_kg_per_m3,
            specific_heat: l.specific_heat_j_per_kg_k,
            conductivity: l.conductivity_w_per_m_k,
        },
        injection: Injection {
            pressure: op.injection_pressure[k],
            viscosity: op.injection_viscosity,
            temperature_c: case.operating.injection_temperature_c,
        },
        exchange: match t.pad_film_bc {
            PadFilmBc::Bc1 => Exchange::Adiabatic,
            PadFilmBc::Bc2 { h_w_per_m2_k } => Exchange::Convective { h: h_w_per_m2_k },
            PadFilmBc::Bc3 => Exchange::Parabolic,
        },
        material: PadMaterial {
            conductivity: t.pad_conductivity_w_per_m_k,
            convection: t.convection_w_per_m2_k,
            ambient_c: t.ambient_temperature_c,
        },
        stabilisation,
        striated: t.cavitated_film == CavitatedFilm::Striated,
    }
}

/// Viscosity at the film nodes for temperatures `t`; `uniform`: the viscosity at their mean instead.
pub(super) fn nodal_viscosity(law: &crate::model::ViscosityLaw, t: &[f64], uniform: bool) -> Vec<f64> {
    if uniform {
        #[allow(clippy::cast_precision_loss)]
        let mean = t.iter().sum::<f64>() / t.len().max(1) as f64;
        vec![law.at(mean); t.len()]
    } else {
        t.iter().map(|&x| law.at(x)).collect()
    }
}

/// Inexact early equilibria: while the viscosity field is still far from converged, solving the
/// equilibrium to 1e-9 is wasted; the tolerance follows the last viscosity change (full precision once the
/// change is within ten times the thermal tolerance, so the converged state is exact).
pub(super) fn equilibrium_params(last_change: f64, params: &ThermalParams) -> EquilibriumParams {
    let full = params.equilibrium;
    if last_change.is_finite() && last_change > 10.0 * params.viscosity_tol {
        EquilibriumParams {
            force_tol: (1e-3 * last_change).clamp(full.force_tol, 1e-4),
            pad_tol: (1e-4 * last_change).clamp(full.pad_tol, 1e-5),
            ..full
        }
    } else {
        full
    }
}

/// The equilibrium warm-started from `u`, retried from scratch if that fails, to its end: the resumable
/// form's rule ([`resumable::equilibrium_part`]) without pauses.
pub(super) fn warm_equilibrium(
    model: &mut BearingModel,
    op: &OperatingPoint,
    params: EquilibriumParams,
    u: Option<&[f64]>,
    cancel: &dyn Cancel,
) -> Result<Equilibrium, SolveError> {
    let pending = resumable::PendingEquilibrium::new(params, u.map(<[f64]>::to_vec));
    match resumable::equilibrium_part(model, op, pending, &NoSuspend(cancel))? {
        Progress::Done(eq) => Ok(eq),
        // NoSuspend never asks for a pause.
        Progress::Suspended(p) => Err(SolveError::Internal(InternalError::Paused {
            what: "thermal loop's equilibrium".into(),
            parts: p.parts(),
        })),
    }
}

/// Each pad's share of the total pad load.
pub(super) fn load_shares(eq: &Equilibrium) -> Vec<f64> {
    let total: f64 = eq.pads.iter().map(|p| p.forces[0].hypot(p.forces[1])).sum::<f64>().max(f64::MIN_POSITIVE);
    eq.pads.iter().map(|p| p.forces[0].hypot(p.forces[1]) / total).collect()
}

/// Thermal solves of every pad at the films' last state, then the inlet and journal temperatures:
/// (per-pad solutions, T_in per pad, T_j, film temperatures).
type FilmTemperatures = (Vec<PadTemperatures>, Vec<f64>, f64, Vec<Vec<f64>>);

pub(super) fn film_temperatures(
    model: &BearingModel,
    thermal: &mut ThermalModel,
    case: &Case,
    op: &OperatingPoint,
    params: &ThermalParams,
) -> Result<FilmTemperatures, SolveError> {
    let n = model.pads.len();
    let mut sols = Vec::with_capacity(n);
    for k in 0..n {
        let s = setup(case, op, k, params.stabilisation);
        let inp = op.film_inputs(k);
        let sol = thermal.pads[k].solve(&model.pads[k].film, &inp, &s).map_err(|error| SolveError::PadThermal {
            pad: k,
            system: ThermalSystem::Solve,
            error,
        })?;
        sols.push(sol);
    }
    let (t_in, t_j) = inlet_and_journal(case, &sols, &thermal.upstream)?;
    let t_new: Vec<Vec<f64>> = (0..n).map(|k| sols[k].film(t_in[k], t_j)).collect();
    if t_new.iter().flatten().any(|v| !v.is_finite()) {
        return Err(SolveError::NonFiniteTemperature);
    }
    Ok((sols, t_in, t_j, t_new))
}

/// Largest relative viscosity change between two temperature fields.
pub(super) fn viscosity_change(law: &crate::model::ViscosityLaw, a: &[Vec<f64>], b: &[Vec<f64>]) -> f64 {
    a.iter().flatten().zip(b.iter().flatten()).fold(0.0_f64, |m, (&x, &y)| m.max((law.at(x) / law.at(y) - 1.0).abs()))
}
