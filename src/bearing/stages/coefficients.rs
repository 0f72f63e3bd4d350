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
use crate::bearing::stages::films::StructureInputs;
use crate::bearing::stages::id::StageId;
use crate::bearing::stages::outcome::Published;
use crate::bearing::stages::request::Request;
use crate::bearing::stages::stage::{Ctx, Poll, Stage};
use crate::bearing::stages::thermal::{ThermalInputs, ThermalStage};
use crate::model::Case;

/// The inputs of the full coefficients.
#[derive(Debug, Clone, PartialEq)]
pub struct CoefficientsInputs {
    pub equilibrium: EquilibriumInputs,
    /// The THD solution's inputs (THD cases).
    pub thermal: Option<ThermalInputs>,
    /// Pad density per pad [kg/m³].
    pub density_kg_per_m3: Vec<f64>,
}

impl CoefficientsInputs {
    #[must_use]
    pub fn of(case: &Case) -> Self {
        Self {
            equilibrium: EquilibriumInputs::of(case),
            thermal: ThermalInputs::of(case),
            density_kg_per_m3: StructureInputs::of(case).density_kg_per_m3,
        }
    }
}

/// The full inertia matrix of a case's pads over the solution's coordinates (journal rows zero); a flexible
/// pad's modal masses and couplings come with the modes the solution carries.
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
    fn needs(req: &Request) -> &'static [StageId] {
        if ThermalInputs::of(&req.case).is_some() {
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
        let film =
            if inputs.thermal.is_some() { ctx.output::<ThermalStage>()? } else { ctx.output::<EquilibriumStage>()? };
        let mut s = Solution::clone(film);
        s.full.m = pad_inertia(ctx.case(), &s);
        Ok(Progress::Done(Arc::new(s)))
    }

    fn publish(&mut self, output: &Arc<Solution>, _req: &Request) -> Option<Published> {
        let out: Arc<Solution> = output.clone();
        Some(out)
    }
}
