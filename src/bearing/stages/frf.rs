//! The FRF stage: the bearing linearised for its injection ports at the isothermal equilibrium
//! ([`FrfModel`]: full `K`, `C`, `M` over journal and pad coordinates and the nozzle coupling — one extra
//! right-hand side per port in the films' factorisations, see [`crate::bearing::frf::injection`]).
//!
//! It reads which pads each port feeds and nothing else of `[hydraulics]`: the valve, the lines, the air
//! fraction and the rig are cheap and enter only the frequency loop ([`FrfModel::sweep`]), which the FRF view
//! and the CLI run on the published model, so a slider on air fraction, line length or valve bandwidth
//! reruns no stage. Thermal cases are linearised at their isothermal equilibrium (the injected oil's
//! temperature sets the injection viscosity).

use std::sync::Arc;

use web_time::Instant;

use crate::bearing::film::model::OperatingPoint;
use crate::bearing::frf::model::FrfModel;
use crate::bearing::report::error::SolveError;
use crate::bearing::report::progress::{Cancel, Progress};
use crate::bearing::stages::coefficients::{pad_inertia, with_inertia};
use crate::bearing::stages::equilibrium::{EquilibriumInputs, EquilibriumStage};
use crate::bearing::stages::films::FilmsStage;
use crate::bearing::stages::id::StageId;
use crate::bearing::stages::outcome::Published;
use crate::bearing::stages::request::Request;
use crate::bearing::stages::stage::{Ctx, Poll, Stage};
use crate::model::hydraulics::{Hydraulics, Port};
use crate::model::Case;

/// The inputs of the linearisation for the ports: the case as it sees it ([`super::view`]) and the ports.
#[derive(Debug, Clone, PartialEq)]
pub struct FrfInputs {
    /// The equilibrium's view with the pads' inertia (their density, whether massless).
    pub case: Case,
    /// The pads each port feeds.
    pub port_pads: Vec<Vec<usize>>,
}

impl FrfInputs {
    /// `None` without `[hydraulics]`. Exhaustive over the hydraulics (no `..`).
    #[must_use]
    pub fn of(case: &Case) -> Option<Self> {
        let Hydraulics { supply_pressure_pa: _, return_pressure_pa: _, valve: _, ports, rig: _ } =
            case.hydraulics.as_ref()?;
        let port_pads = ports
            .iter()
            .map(|port| {
                let Port {
                    sign: _,
                    pads,
                    line_length_m: _,
                    line_diameter_m: _,
                    oil_bulk_modulus_pa: _,
                    air_fraction: _,
                    wall_compliance_per_pa: _,
                    modes: _,
                } = port;
                pads.clone()
            })
            .collect();
        Some(Self { case: with_inertia(EquilibriumInputs::of(case).case, case), port_pads })
    }
}

#[derive(Default)]
pub struct FrfStage;

impl Stage for FrfStage {
    const LABEL: &'static str = "FRF linearisation";
    const NEEDS: &'static [StageId] = &[StageId::Films, StageId::Equilibrium];
    type Inputs = FrfInputs;
    type Output = Arc<FrfModel>;

    fn inputs(req: &Request) -> Option<FrfInputs> {
        FrfInputs::of(&req.case)
    }

    fn poll(
        &mut self,
        inputs: &FrfInputs,
        ctx: &mut Ctx<'_>,
        _cancel: &dyn Cancel,
    ) -> Result<Poll<Arc<FrfModel>>, SolveError> {
        let case = &inputs.case;
        let equilibrium = EquilibriumInputs::of(case);
        let sol = Arc::clone(ctx.output::<EquilibriumStage>(&equilibrium)?);
        let model = ctx.output_mut::<FilmsStage>(&equilibrium.films())?;
        let t0 = Instant::now();
        let op = OperatingPoint::isothermal(case);
        let m = pad_inertia(case, &sol);
        let frf = FrfModel::linearise(model, &op, case, &sol, m, &inputs.port_pads)?;
        Ok(Progress::Done(Arc::new(FrfModel { linearise_seconds: t0.elapsed().as_secs_f64(), ..frf })))
    }

    fn publish(&mut self, output: &Arc<FrfModel>) -> Option<Published> {
        Some(output.clone())
    }
}
