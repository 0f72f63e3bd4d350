//! The equilibrium stage: the isothermal static equilibrium — with the Hertz pivots' load iteration when
//! the pads have them ([`pivots::step_solve`]) — and its solution with the full linearisation, resumable
//! between frames (inside an equilibrium and between the pivots' load steps).
//!
//! Suspension is a return value: when the caller asks to pause ([`Cancel::suspend`]) the solve returns
//! its iterate, kept here under the inputs it works towards, and the next poll resumes from it; after
//! [`MAX_SUSPENSIONS`] it runs to the end (bounded work even if every part is slow). The last converged
//! coordinates warm-start the next solve on the same films.

use std::sync::Arc;

use crate::bearing::equilibrium::{pivots, step_equilibrium, Equilibrium, EquilibriumParams, Resume};
use crate::bearing::film::model::{BearingModel, OperatingPoint};
use crate::bearing::report::error::SolveError;
use crate::bearing::report::progress::{Cancel, NoSuspend, Progress};
use crate::bearing::report::SolveReport;
use crate::bearing::solution::assemble::assemble_solution;
use crate::bearing::solution::Solution;
use crate::bearing::stages::cache::Cached;
use crate::bearing::stages::films::{install_structure, FilmsInputs, FilmsStage};
use crate::bearing::stages::id::StageId;
use crate::bearing::stages::request::{Request, Start};
use crate::bearing::stages::stage::{Ctx, Poll, Stage};
use crate::bearing::stages::view;
use crate::model::{Bearing, Case, Feeding, Lubricant, Operating, Pad, Physics, Thermal};

/// Suspensions of one equilibrium before it must run to the end.
pub const MAX_SUSPENSIONS: usize = 40;

/// The inputs of the isothermal equilibrium: the case as it sees it ([`super::view`]).
#[derive(Debug, Clone, PartialEq)]
pub struct EquilibriumInputs {
    /// The films' view, and per pad its pivot stiffnesses and Hertz contact (their values: the structure's
    /// springs) and its preload (reported); the oil's viscosity law and density (flow regime, ram pressure,
    /// churning); the operating point but the supply temperature and the excitation ratio; every physics
    /// value; every tuning key (the equilibrium's and those of the stages after it, which key on this view);
    /// the churning factor of the feeding.
    pub case: Case,
}

impl EquilibriumInputs {
    /// Exhaustive over the case and its sub-structs (no `..`).
    #[must_use]
    pub fn of(case: &Case) -> Self {
        let Case {
            title: _,
            bearing,
            lubricant,
            operating,
            mesh: _, // the films'
            physics,
            thermal, // its feeding's churning factor (the rest: the thermal stage's)
            hydraulics: _,
            limits: _,
            tuning,
        } = case;
        let Lubricant {
            name: _,
            viscosity,
            density_kg_per_m3,
            specific_heat_j_per_kg_k: _,
            conductivity_w_per_m_k: _, // the thermal stage's
        } = lubricant;
        let Operating {
            speed_rad_s,
            load,
            supply_temperature_c: _, // the thermal stage's
            film_temperature_c,
            injection_pressure_pa,
            injection_temperature_c,
            supply_flow_m3_s,
            excitation_ratio: _, // the reduction's (the equilibrium's own reduced coefficients are static)
        } = operating;
        let Physics {
            cavitation: _,
            touchdown_film_m: _,
            pad_modes: _,
            turbulence: _,
            transition_reynolds: _,
            max_film_solves_per_pad: _,
            ram_pressure_coefficient: _, // the leading-edge pressure of every film solve
        } = physics; // kept whole below (pad_modes: the films'; turbulence: every film solve)
        let films = FilmsInputs::of(case).case;
        let blank = view::case();
        let case = Case {
            bearing: Bearing {
                pads: bearing.pads.iter().zip(&films.bearing.pads).map(|(p, f)| structure_pad(p, f)).collect(),
                ..films.bearing
            },
            lubricant: Lubricant { viscosity: *viscosity, density_kg_per_m3: *density_kg_per_m3, ..blank.lubricant },
            operating: Operating {
                speed_rad_s: *speed_rad_s,
                load: *load,
                film_temperature_c: *film_temperature_c,
                injection_pressure_pa: injection_pressure_pa.clone(),
                injection_temperature_c: *injection_temperature_c,
                supply_flow_m3_s: supply_flow_m3_s.clone(),
                ..blank.operating
            },
            physics: *physics,
            thermal: Thermal {
                feeding: Feeding::Flooded {
                    carry_over: view::BLANK,
                    churning_factor: thermal.feeding.churning_factor(),
                },
                ..blank.thermal
            },
            tuning: *tuning,
            ..films
        };
        Self { case }
    }

    /// The films it solves on.
    #[must_use]
    pub fn films(&self) -> FilmsInputs {
        FilmsInputs::of(&self.case)
    }
}

/// The films' view of a pad (`films`) with the pivot springs' values, its Hertz contact and its preload.
/// Exhaustive (no `..`).
fn structure_pad(pad: &Pad, films: &Pad) -> Pad {
    let Pad {
        kind: _,
        leading_edge_rad: _,
        arc_rad: _,
        pivot_rad: _,
        offset: _,
        clearance_m: _,
        thickness_m: _, // the films'
        preload,
        pivot_stiffness_n_per_m,
        pivot_transverse_stiffness_n_per_m,
        pivot_contact,
        density_kg_per_m3: _,
        massless: _, // the inertia: the coefficients' (the equilibrium's own mass matrix is the blank one)
        youngs_modulus_pa: _,
        poisson_ratio: _, // the films' when the pads bend; a contact's pivot material is in the contact
        orifices: _,
    } = pad;
    Pad {
        preload: *preload,
        pivot_stiffness_n_per_m: *pivot_stiffness_n_per_m,
        pivot_transverse_stiffness_n_per_m: *pivot_transverse_stiffness_n_per_m,
        pivot_contact: *pivot_contact,
        ..films.clone()
    }
}

/// A suspended solve: where to resume it, and the work of its parts so far (added to its final report).
#[derive(Debug, Clone, Default)]
struct Suspensions {
    coordinates: Vec<f64>,
    placed_pads: usize,
    /// With Hertz pivots: their load iteration under way.
    pivots: Option<pivots::PivotRun>,
    suspensions: usize,
    report: SolveReport,
}

/// Where a paused solve resumes: an equilibrium's iterate, or the pivots' load iteration.
enum Paused {
    Equilibrium(Resume),
    Pivots(Box<pivots::PivotRun>),
}

impl Suspensions {
    /// One more part of the solve has been suspended.
    fn add(&mut self, part: SolveReport) {
        self.suspensions += 1;
        let mut r = part;
        r.add_earlier(std::mem::take(&mut self.report));
        self.report = r;
    }

    /// The final report covers the whole solve: earlier parts' work first.
    fn merge_into(self, r: &mut SolveReport) {
        r.add_earlier(self.report);
        r.resumed_parts = self.suspensions;
    }
}

#[derive(Default)]
pub struct EquilibriumStage {
    /// A solve paused by [`Cancel::suspend`], under the inputs it works towards.
    suspended: Cached<EquilibriumInputs, Suspensions>,
    /// Last converged coordinates, under the films they were solved on.
    warm: Cached<FilmsInputs, Vec<f64>>,
}

impl Stage for EquilibriumStage {
    const LABEL: &'static str = "equilibrium";
    const NEEDS: &'static [StageId] = &[StageId::Films];
    type Inputs = EquilibriumInputs;
    type Output = Arc<Solution>;

    fn inputs(req: &Request) -> Option<EquilibriumInputs> {
        Some(EquilibriumInputs::of(&req.case))
    }

    fn poll(
        &mut self,
        inputs: &EquilibriumInputs,
        ctx: &mut Ctx<'_>,
        cancel: &dyn Cancel,
    ) -> Result<Poll<Arc<Solution>>, SolveError> {
        let case = &inputs.case;
        let films = inputs.films();
        let cold = ctx.start() == Start::Cold;
        let model = ctx.output_mut::<FilmsStage>(&films)?;
        install_structure(model, case)?;
        let op = OperatingPoint::isothermal(case);
        let resumed = self.suspended.take(inputs);
        let may_suspend = resumed.as_ref().is_none_or(|r| r.suspensions < MAX_SUSPENSIONS);
        let no_suspend = NoSuspend(cancel);
        let cancel: &dyn Cancel = if may_suspend { cancel } else { &no_suspend };
        let warm = if cold { None } else { self.warm.get(&films).cloned() };
        let start = resumed.as_ref().map(|r| r.coordinates.clone()).or(warm);
        let params = EquilibriumParams {
            placed_pads: resumed.as_ref().map_or(0, |r| r.placed_pads),
            ..EquilibriumParams::of(case)
        };
        let run = resumed.as_ref().and_then(|r| r.pivots.clone());
        let attempt = match solve(model, case, &op, start.as_deref(), run, params, cancel) {
            // A failed warm start retries cold before giving up.
            Err(e) if start.is_some() && !matches!(e, SolveError::Cancelled) => {
                self.warm.clear();
                solve(model, case, &op, None, None, EquilibriumParams::of(case), &NoSuspend(cancel))
            }
            r => r,
        };
        let (eq, contacts) = match attempt? {
            Progress::Done(found) => found,
            Progress::Suspended(paused) => {
                let mut so_far = resumed.unwrap_or_default();
                let next = match paused {
                    Paused::Equilibrium(r) => {
                        so_far.add(r.report);
                        Suspensions { coordinates: r.coordinates, placed_pads: r.placed_pads, pivots: None, ..so_far }
                    }
                    Paused::Pivots(mut run) => {
                        so_far.add(std::mem::take(&mut run.part));
                        Suspensions { pivots: Some(*run), ..so_far }
                    }
                };
                self.suspended.put(inputs.clone(), next);
                return Ok(Progress::Suspended(0.5));
            }
        };
        let mut sol = assemble_solution(model, case, &op, &eq, contacts.as_ref());
        if let Some(so_far) = resumed {
            so_far.merge_into(&mut sol.report);
        }
        self.warm.put(films, sol.coordinates.clone());
        Ok(Progress::Done(Arc::new(sol)))
    }
}

/// The equilibrium of an operating point, resumable when `cancel` asks to pause ([`Cancel::suspend`]): with
/// Hertz pivots their load iteration (resumed from `run` when given), otherwise the equilibrium alone.
fn solve(
    model: &mut BearingModel,
    case: &Case,
    op: &OperatingPoint,
    start: Option<&[f64]>,
    run: Option<pivots::PivotRun>,
    params: EquilibriumParams,
    cancel: &dyn Cancel,
) -> Result<Progress<(Equilibrium, Option<pivots::HertzPivots>), Paused>, SolveError> {
    let run = match run {
        Some(r) => Some(r),
        None => pivots::PivotRun::new(model, case, start)?,
    };
    if let Some(run) = run {
        return Ok(match pivots::step_solve(model, case, op, run, params, cancel)? {
            Progress::Done((eq, p)) => Progress::Done((eq, Some(p))),
            Progress::Suspended(r) => Progress::Suspended(Paused::Pivots(Box::new(r))),
        });
    }
    Ok(match step_equilibrium(model, op, params, start, cancel)? {
        Progress::Done(eq) => Progress::Done((eq, None)),
        Progress::Suspended(r) => Progress::Suspended(Paused::Equilibrium(r)),
    })
}
