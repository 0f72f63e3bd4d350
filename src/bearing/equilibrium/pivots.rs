//! Hertz pivots in the equilibrium: each pad's pivot stiffness evaluated at the load the pad carries.
//!
//! A pad with a pivot contact ([`crate::physics::hertz`]) has the radial pivot coordinate ξ like a pad with a
//! given pivot stiffness, but its spring is nonlinear: the pivot carries `F` with the Hertz approach
//! `ξ = δ(F)`. The equilibrium ([`crate::bearing::equilibrium`]) solves with linear pivot springs, so the load is
//! iterated around it (fixed point on the secant stiffness, with a secant step per pad: [`accelerated`]):
//!
//! ```text
//! k⁰ = F₀/δ(F₀)  (F₀ = |W|, the static load);   solve with kⁿ;   Fₖ = kⁿ ξₖ;   kⁿ⁺¹ = Fₖ / δ(Fₖ)
//! ```
//! until every secant stiffness changes by less than [`RTOL`]. At the fixed point each pivot carries its load
//! with exactly the Hertz approach (the secant spring through the same point of the F–δ curve). The
//! coefficients then use the **tangent** stiffness `dF/dδ` at that load (the linearisation of the
//! nonlinear spring: 3/2 of the secant for a ball, a little more than the secant for a rocker).
//!
//! A pivot contact carries compression only: a pad whose film pulls it off its seat (`Fₖ ≤ 0`, which a
//! film does not do at equilibrium) or carries less than [`FLOOR`] of the load is given the stiffness at
//! that floor, with a warning. The iteration count and any non-convergence are in the solve report.

use crate::bearing::report::error::InternalError;
use crate::model::{Case, LoadSpec};
use crate::physics::hertz::{ContactState, PivotContact};

use crate::bearing::equilibrium::solve::{solve_equilibrium, step_equilibrium};
use crate::bearing::equilibrium::state::{Equilibrium, EquilibriumParams, PadState};
use crate::bearing::film::coordinates::{Coord, PadDof};
use crate::bearing::film::model::{BearingModel, OperatingPoint};
use crate::bearing::report::error::SolveError;
use crate::bearing::report::progress::{Cancel, NoSuspend, Progress};
use crate::bearing::report::warning::Warning;
use crate::bearing::report::SolveReport;

/// Relative change of every secant stiffness at which the load iteration stops.
pub const RTOL: f64 = 1e-6;
/// Most load iterations (each is one equilibrium solve, warm-started from the previous one).
pub const MAX_ITERATIONS: usize = 30;
/// Smallest pivot load, as a fraction of the static load, at which a contact's stiffness is evaluated.
pub const FLOOR: f64 = 1e-3;

/// A pad whose pivot is a Hertz contact: where its spring lives.
#[derive(Debug, Clone, PartialEq)]
struct ContactPad {
    pad: usize,
    contact: PivotContact,
    /// Index of ξ in the pad's structure.
    local: usize,
}

/// The case's pads with a pivot contact.
fn contact_pads(model: &BearingModel, case: &Case) -> Result<Vec<ContactPad>, SolveError> {
    let mut out = Vec::new();
    for (pad, p) in case.bearing.pads.iter().enumerate() {
        let Some(contact) = p.pivot_contact else { continue };
        let global = model.dofs.index(Coord::Pad { pad, dof: PadDof::PivotRadial });
        let local = model.pads.get(pad).and_then(|pm| pm.structure.dofs.iter().position(|d| *d == PadDof::PivotRadial));
        match (global, local) {
            (Some(_), Some(local)) => out.push(ContactPad { pad, contact, local }),
            _ => return Err(SolveError::Internal(InternalError::ContactWithoutCoordinate { pad })),
        }
    }
    Ok(out)
}

/// The case has a pad with a Hertz pivot.
#[must_use]
pub fn has_contacts(case: &Case) -> bool {
    case.bearing.pads.iter().any(|p| p.pivot_contact.is_some())
}

/// The next secant stiffness from the fixed-point map `T(k)` (the secant at the load that `k` gives):
/// a secant step on `g(k) = T(k) − k` through the previous iterate, kept within a factor 3 of the plain
/// fixed-point value `T(k)` (and `T(k)` itself on the first step or a flat `g`). A lightly loaded pad, whose
/// load depends strongly on its pivot's give, contracts slowly under the plain map (≈ 1/3 per step on the
/// compressor's top pad); the secant step takes a few.
fn accelerated(k: f64, mapped: f64, previous: Option<(f64, f64)>) -> f64 {
    let Some((k0, mapped0)) = previous else { return mapped };
    let (g, g0) = (mapped - k, mapped0 - k0);
    if (g - g0).abs() <= 1e-12 * mapped.abs() || (k - k0).abs() <= 1e-12 * k.abs() {
        return mapped;
    }
    let next = k - g * (k - k0) / (g - g0);
    if next.is_finite() && next > mapped / 3.0 && next < 3.0 * mapped {
        next
    } else {
        mapped
    }
}

/// The load pad `c` puts on its pivot: its film's force on the pad along the pivot line [N]. For a loaded pad
/// at equilibrium this is the spring force `k ξ`; a floating pad's coordinates are held where film pressure
/// begins (not balanced by the film), so its spring force would be a load that nothing supplies — taking it
/// made the load iteration chase that phantom load (the compressor's top pad on 12.7 mm balls: 68 N on a pad
/// carrying nothing; on 40 mm balls in 41 mm sockets 30 iterations without converging).
fn pivot_load(case: &Case, c: &ContactPad, eq: &Equilibrium) -> f64 {
    let theta = case.bearing.pads[c.pad].pivot_rad;
    let f = eq.pads.get(c.pad).map_or([0.0, 0.0], PadState::journal_force);
    -(f[0] * theta.cos() + f[1] * theta.sin())
}

fn state(c: &ContactPad, load_n: f64) -> Result<ContactState, SolveError> {
    c.contact.state(load_n).map_err(|error| SolveError::PivotContact { pad: c.pad, error })
}

/// The load iteration of a case's Hertz pivots (module docs): each contact pad's secant spring, the previous
/// iterate of its secant step, and the contact states at the loads of the last equilibrium.
#[derive(Debug, Clone, PartialEq)]
pub struct HertzPivots {
    pads: Vec<ContactPad>,
    /// Loads below this get the stiffness at it [N] ([`FLOOR`] of the static load).
    floor: f64,
    /// The secant stiffness each contact's spring has in the next equilibrium [N/m].
    secant: Vec<f64>,
    /// The previous iterate's (stiffness, mapped stiffness) per pad, for the secant acceleration.
    previous: Vec<Option<(f64, f64)>>,
    /// Contact states at the loads of the last equilibrium given to [`HertzPivots::update`].
    states: Vec<ContactState>,
    /// Warnings of that last update (loads under the floor).
    warnings: Vec<Warning>,
    /// Load steps taken ([`HertzPivots::update`] calls).
    iterations: usize,
    /// The last load step changed no secant stiffness by [`RTOL`] or more.
    converged: bool,
}

impl HertzPivots {
    /// The iteration for the case's contact pads, each spring starting at the secant of the static load;
    /// `None` when no pad has a contact.
    ///
    /// # Errors
    /// [`SolveError::PivotContact`] for a contact outside Hertz theory at the static load.
    pub fn new(model: &BearingModel, case: &Case) -> Result<Option<Self>, SolveError> {
        let pads = contact_pads(model, case)?;
        if pads.is_empty() {
            return Ok(None);
        }
        let scale = match case.operating.load {
            LoadSpec::Force { magnitude_n, .. } => magnitude_n.abs(),
            LoadSpec::Position { .. } => 0.0,
        }
        .max(1.0);
        let secant = pads.iter().map(|c| state(c, scale).map(|s| s.secant_n_per_m())).collect::<Result<Vec<_>, _>>()?;
        let n = pads.len();
        Ok(Some(Self {
            pads,
            floor: FLOOR * scale,
            secant,
            previous: vec![None; n],
            states: Vec::new(),
            warnings: Vec::new(),
            iterations: 0,
            converged: false,
        }))
    }

    /// Puts the current secant springs into the model (before each equilibrium: a stage that rebuilds the
    /// pad structures resets them).
    pub fn install(&self, model: &mut BearingModel) {
        for (c, k) in self.pads.iter().zip(&self.secant) {
            model.pads[c.pad].structure.stiffness[(c.local, c.local)] = *k;
        }
    }

    /// One load step after an equilibrium `eq` solved with the installed springs: each contact's state at
    /// its pad's load, and the next secant stiffness. Returns the largest relative difference between the
    /// installed secants and the ones the loads give (the iteration has converged when it is small).
    ///
    /// # Errors
    /// [`SolveError::PivotContact`] for a contact outside Hertz theory at its load.
    pub fn update(&mut self, case: &Case, eq: &Equilibrium) -> Result<f64, SolveError> {
        self.iterations += 1;
        self.states.clear();
        self.warnings.clear();
        let mut change = 0.0_f64;
        for ((c, k), prev) in self.pads.iter().zip(self.secant.iter_mut()).zip(self.previous.iter_mut()) {
            let load = pivot_load(case, c, eq);
            if load < self.floor {
                self.warnings.push(Warning::PivotLoadBelowFloor {
                    pad: c.pad,
                    load_n: load,
                    floor_n: self.floor,
                    floor_share: FLOOR,
                });
            }
            let s = state(c, load.max(self.floor))?;
            let mapped = s.secant_n_per_m();
            change = change.max((mapped - *k).abs() / mapped);
            let next = accelerated(*k, mapped, *prev);
            *prev = Some((*k, mapped));
            *k = next;
            self.states.push(s);
        }
        self.converged = change < RTOL;
        Ok(change)
    }

    /// Load steps taken so far.
    #[must_use]
    pub fn iterations(&self) -> usize {
        self.iterations
    }

    /// Puts each contact's **tangent** stiffness at its last load into the model, for the linearisation
    /// (the model keeps them: a later linearisation on it sees the same coefficients; the next solve starts
    /// its own iteration).
    pub fn install_tangents(&self, model: &mut BearingModel) {
        for (c, s) in self.pads.iter().zip(&self.states) {
            model.pads[c.pad].structure.stiffness[(c.local, c.local)] = s.tangent_n_per_m;
        }
    }

    /// Each contact pad's state at the loads of the last equilibrium given to [`HertzPivots::update`].
    pub fn states(&self) -> impl Iterator<Item = (usize, ContactState)> + '_ {
        self.pads.iter().zip(&self.states).map(|(c, s)| (c.pad, *s))
    }

    /// The warnings of the last load step, and one when the loads have not converged.
    #[must_use]
    pub fn warnings(&self) -> Vec<Warning> {
        let mut w = self.warnings.clone();
        if !self.converged {
            w.push(Warning::PivotLoadsNotConverged { iterations: MAX_ITERATIONS, tolerance: RTOL });
        }
        w
    }
}

/// Solves the operating point with each Hertz pivot's stiffness at its pad's load (module docs): the
/// equilibrium, and the load iteration (`None` without pivot contacts) whose states and tangents the
/// solution takes ([`crate::bearing::solution::assemble::assemble_solution`]). The same iteration as
/// [`step_solve`], run without pauses.
///
/// # Errors
/// The equilibrium's errors; [`SolveError::PivotContact`] for a contact outside Hertz theory at its load.
pub fn solve(
    model: &mut BearingModel,
    case: &Case,
    op: &OperatingPoint,
    start: Option<&[f64]>,
    params: EquilibriumParams,
    cancel: &dyn Cancel,
) -> Result<(Equilibrium, Option<HertzPivots>), SolveError> {
    let Some(run) = PivotRun::new(model, case, start)? else {
        return Ok((solve_equilibrium(model, op, params, start, cancel)?, None));
    };
    match step_solve(model, case, op, run, params, &NoSuspend(cancel))? {
        Progress::Done((eq, pivots)) => Ok((eq, Some(pivots))),
        // NoSuspend never asks for a pause.
        Progress::Suspended(r) => Err(SolveError::Internal(InternalError::Paused {
            what: "Hertz pivot load iteration".into(),
            parts: r.part.iterations,
        })),
    }
}

/// A load iteration under way ([`step_solve`]): the springs and where the current equilibrium resumes.
#[derive(Debug, Clone, PartialEq)]
pub struct PivotRun {
    /// The springs.
    pivots: HertzPivots,
    /// Where the current equilibrium starts or resumes (the previous load step's coordinates, or the
    /// caller's warm start), and the pads its cold start has placed.
    start: Option<Vec<f64>>,
    placed_pads: usize,
    /// Work of the load steps finished since the last pause (reported with the next part).
    finished: Option<SolveReport>,
    /// Work of the part that paused: the caller adds it to the final report.
    pub part: SolveReport,
}

impl PivotRun {
    /// A new iteration for the case's contact pads (each spring at the secant of the static load), its first
    /// equilibrium warm-started from `start` when given; `None` when no pad has a contact.
    ///
    /// # Errors
    /// As [`HertzPivots::new`].
    pub fn new(model: &BearingModel, case: &Case, start: Option<&[f64]>) -> Result<Option<Self>, SolveError> {
        Ok(HertzPivots::new(model, case)?.map(|pivots| Self {
            pivots,
            start: start.map(<[f64]>::to_vec),
            placed_pads: 0,
            finished: None,
            part: SolveReport::default(),
        }))
    }

    /// Load steps finished so far.
    #[must_use]
    pub fn load_steps(&self) -> usize {
        self.pivots.iterations()
    }
}

/// The load iteration of [`solve`], resumable: it pauses when `cancel` asks for it ([`Cancel::suspend`]),
/// inside an equilibrium (the coupled Newton's own safe points) or between load steps, and returns the run
/// to resume from (its [`PivotRun::part`] holds the work of the part that paused). Resumed until done it
/// takes the same load steps, each from the same start, as the run without pauses.
///
/// # Errors
/// As [`solve`].
pub fn step_solve(
    model: &mut BearingModel,
    case: &Case,
    op: &OperatingPoint,
    mut run: PivotRun,
    params: EquilibriumParams,
    cancel: &dyn Cancel,
) -> Result<Progress<(Equilibrium, HertzPivots), PivotRun>, SolveError> {
    run.part = SolveReport::default();
    loop {
        run.pivots.install(model);
        let p = EquilibriumParams { placed_pads: run.placed_pads, ..params };
        let mut eq = match step_equilibrium(model, op, p, run.start.as_deref(), cancel)? {
            Progress::Done(eq) => eq,
            Progress::Suspended(r) => {
                let mut part = r.report;
                if let Some(f) = run.finished.take() {
                    part.add_earlier(f);
                }
                run.part = part;
                run.start = Some(r.coordinates);
                run.placed_pads = r.placed_pads;
                return Ok(Progress::Suspended(run));
            }
        };
        let change = run.pivots.update(case, &eq)?;
        if let Some(r) = run.finished.take() {
            eq.report.add_earlier(r);
        }
        if change < RTOL || run.pivots.iterations() >= MAX_ITERATIONS {
            // `eq` was solved with the previous secant stiffnesses; the states hold the loads it produced.
            return Ok(Progress::Done((eq, run.pivots)));
        }
        run.start = Some(eq.u.clone());
        run.placed_pads = 0;
        run.finished = Some(eq.report);
        if cancel.suspend() {
            run.part = run.finished.take().unwrap_or_default();
            return Ok(Progress::Suspended(run));
        }
    }
}
