//! The coefficients stage: the full stiffness, damping and inertia of the film solution (THD when the case
//! is, else isothermal). The film's `K` and `C` come with the solution; the inertia `M` is the pads'
//! (`M_s = ∫ρ v_a·v_b dV` over each pad's rigid motions, [`PadStructure::rigid`]), set here so that an edit
//! of the pad density reruns this stage and those after it, never the equilibrium.

use std::sync::Arc;

use crate::bearing::film::coordinates::{Coord, PadStructure};
use crate::bearing::film::flex::modal_properties;
use crate::bearing::report::error::SolveError;
use crate::bearing::report::progress::{Cancel, Progress};
use crate::bearing::solution::Solution;
use crate::bearing::stages::equilibrium::{EquilibriumInputs, EquilibriumStage};
use crate::bearing::stages::id::StageId;
use crate::bearing::stages::outcome::Published;
use crate::bearing::stages::request::Request;
use crate::bearing::stages::stage::{Ctx, Poll, Stage};
use crate::bearing::stages::thermal::{ThermalInputs, ThermalStage};
use crate::model::{Bearing, Case, Pad};

/// The inputs of the full coefficients: the case as they see it ([`super::view`]).
#[derive(Debug, Clone, PartialEq)]
pub struct CoefficientsInputs {
    /// The view of the film solution they read (the thermal loop's for a THD case, else the equilibrium's)
    /// with each pad's density and whether it is massless (the inertia `M`).
    pub case: Case,
}

impl CoefficientsInputs {
    #[must_use]
    pub fn of(case: &Case) -> Self {
        let film = match ThermalInputs::of(case) {
            Some(thermal) => thermal.case,
            None => EquilibriumInputs::of(case).case,
        };
        Self { case: with_inertia(film, case) }
    }

    /// The film solution they read: the THD solution's inputs for a THD case, else `None`.
    #[must_use]
    pub fn thermal(&self) -> Option<ThermalInputs> {
        ThermalInputs::of(&self.case)
    }
}

/// A stage's view of the case (`view`) with what the pads' inertia reads besides their geometry: whether each
/// pad is massless and, if not, its density. Exhaustive over the pad (no `..`).
#[must_use]
pub(super) fn with_inertia(view: Case, case: &Case) -> Case {
    let pads = case
        .bearing
        .pads
        .iter()
        .zip(&view.bearing.pads)
        .map(|(pad, seen)| {
            let Pad {
                kind: _,
                leading_edge_rad: _,
                arc_rad: _,
                pivot_rad: _,
                offset: _,
                clearance_m: _,
                preload: _,
                thickness_m: _,
                pivot_stiffness_n_per_m: _,
                pivot_transverse_stiffness_n_per_m: _,
                pivot_contact: _,
                orifices: _, // the geometry and the coordinates: the films' view
                youngs_modulus_pa: _,
                poisson_ratio: _, // a flexible pad's modal masses come with the modes of the solution
                density_kg_per_m3,
                massless,
            } = pad;
            // A massless pad's density is read by nothing.
            let density_kg_per_m3 = if *massless { seen.density_kg_per_m3 } else { *density_kg_per_m3 };
            Pad { density_kg_per_m3, massless: *massless, ..seen.clone() }
        })
        .collect();
    Case { bearing: Bearing { pads, ..view.bearing }, ..view }
}

/// The full inertia matrix of a case's pads (a view with [`with_inertia`]) over the solution's coordinates
/// (journal rows zero); a flexible pad's modal masses and couplings come with the modes the solution carries.
pub(super) fn pad_inertia(case: &Case, solution: &Solution) -> Vec<Vec<f64>> {
    let coords = &solution.full.coords;
    let n = coords.len();
    let mut m = vec![vec![0.0; n]; n];
    let b = &case.bearing;
    for (k, pad) in b.pads.iter().enumerate() {
        let mut s = PadStructure::rigid(pad, b.journal_radius_m, b.length_m);
        if let Some(flex) = solution.pads.get(k).and_then(|p| p.flex.as_ref()) {
            s = s.with_modes(&modal_properties(&flex.modes, pad.massless));
        }
        let at = |dof| coords.iter().position(|c| *c == Coord::Pad { pad: k, dof });
        for (i, &di) in s.dofs.iter().enumerate() {
            for (j, &dj) in s.dofs.iter().enumerate() {
                if let (Some(gi), Some(gj)) = (at(di), at(dj)) {
                    m[gi][gj] = s.mass[(i, j)];
                }
            }
        }
    }
    m
}

#[derive(Default)]
pub struct CoefficientsStage;

impl Stage for CoefficientsStage {
    const LABEL: &'static str = "coefficients";
    const NEEDS: &'static [StageId] = &[StageId::Equilibrium, StageId::Thermal];
    type Inputs = CoefficientsInputs;
    type Output = Arc<Solution>;

    fn inputs(req: &Request) -> Option<CoefficientsInputs> {
        Some(CoefficientsInputs::of(&req.case))
    }

    /// The thermal loop's state for a THD case, the isothermal equilibrium otherwise.
    fn needs(inputs: &CoefficientsInputs) -> &'static [StageId] {
        if inputs.thermal().is_some() {
            &[StageId::Thermal]
        } else {
            &[StageId::Equilibrium]
        }
    }

    fn poll(
        &mut self,
        inputs: &CoefficientsInputs,
        ctx: &mut Ctx<'_>,
        _cancel: &dyn Cancel,
    ) -> Result<Poll<Arc<Solution>>, SolveError> {
        let film = match inputs.thermal() {
            Some(thermal) => ctx.output::<ThermalStage>(&thermal)?,
            None => ctx.output::<EquilibriumStage>(&EquilibriumInputs::of(&inputs.case))?,
        };
        let mut s = Solution::clone(film);
        s.full.m = pad_inertia(&inputs.case, &s);
        Ok(Progress::Done(Arc::new(s)))
    }

    fn publish(&mut self, output: &Arc<Solution>) -> Option<Published> {
        let out: Arc<Solution> = output.clone();
        Some(out)
    }
}
