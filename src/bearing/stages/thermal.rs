//! The thermal stage (THD cases): the thermal loop ([`ThdRun`]) — equilibrium and temperatures together,
//! its first outer iteration the isothermal equilibrium — one outer iteration per poll, or, when the caller
//! asks to pause ([`Cancel::suspend`], the web build's frame budget), the part of its equilibrium that fits.
//! A warm request starts it from the last converged state on the same films and, if that run fails, once
//! more from a centred journal. The pad solids and thermal systems ([`ThermalModel`]) are kept under the
//! films and pad-mesh inputs they are built from.

use std::sync::Arc;

use crate::bearing::report::error::SolveError;
use crate::bearing::report::progress::{Cancel, Progress};
use crate::bearing::solution::assemble::assemble_thd_solution;
use crate::bearing::solution::Solution;
use crate::bearing::stages::cache::Cached;
use crate::bearing::stages::equilibrium::EquilibriumInputs;
use crate::bearing::stages::films::{install_structure, FilmsInputs, FilmsStage};
use crate::bearing::stages::id::StageId;
use crate::bearing::stages::request::{Request, Start};
use crate::bearing::stages::stage::{Ctx, Poll, Stage};
use crate::bearing::thermal::{ThdRun, ThermalModel, ThermalParams};
use crate::model::{Bearing, Case, Lubricant, MeshSpec, Operating, Pad, PadFilmBc, Thermal, ThermalModelKind};

/// Outer iterations a THD loop typically needs (for the progress fraction only).
const THERMAL_ITERATIONS_EXPECTED: f64 = 10.0;

/// The inputs of the THD solution: the case as it sees it ([`super::view`]).
#[derive(Debug, Clone, PartialEq)]
pub struct ThermalInputs {
    /// The equilibrium's view, the pad solids' element layers, the oil's c_p and k, the supply temperature
    /// and every `[thermal]` value; when the pads grow thermally (`thermal.pad_expansion_ppm_per_k ≠ 0`) also
    /// each pad's E, ν and density and the fidelity (the growth solid's layer step).
    pub case: Case,
}

/// What the pad solids and thermal systems are built from.
#[derive(Debug, Clone, PartialEq)]
pub struct PadSolidsInputs {
    pub films: FilmsInputs,
    pub pad_radial_elements: usize,
    /// Whether the film is adiabatic to the pad (BC1: a pad without a solid is allowed).
    pub bc1: bool,
}

impl ThermalInputs {
    /// Exhaustive over the case and its sub-structs (no `..`); `None` for an isothermal case.
    #[must_use]
    pub fn of(case: &Case) -> Option<Self> {
        let Case {
            title: _,
            bearing,
            lubricant,
            operating,
            mesh,
            physics: _,
            thermal,
            hydraulics: _,
            limits: _,
            tuning: _, // the equilibrium's view holds every tuning key
        } = case;
        let Lubricant { name: _, viscosity: _, density_kg_per_m3: _, specific_heat_j_per_kg_k, conductivity_w_per_m_k } =
            lubricant;
        let Operating {
            speed_rad_s: _,
            load: _,
            supply_temperature_c,
            film_temperature_c: _,
            injection_pressure_pa: _,
            injection_temperature_c: _,
            supply_flow_m3_s: _,
            excitation_ratio: _, // the rest: the equilibrium's
        } = operating;
        let MeshSpec {
            fidelity, // the growth solid's layer step
            circumferential_elements: _,
            axial_elements: _,
            orifice_elements: _,
            half_model: _,
            pad_radial_elements,
            max_nodes: _,
        } = mesh;
        // Every field is read (kept whole below).
        let Thermal {
            model,
            pad_film_bc: _,
            convection_w_per_m2_k: _,
            ambient_temperature_c: _,
            pad_conductivity_w_per_m_k: _,
            inlet_temperature_c: _,
            journal_temperature_c: _,
            cavitated_film: _,
            pad_expansion_per_k,
            journal_expansion_per_k: _,
            reference_temperature_c: _,
            housing_expansion_per_k: _,
            housing_temperature_c: _,
            feeding: _,
        } = thermal;
        if *model != ThermalModelKind::Thd {
            return None;
        }
        // Thermal growth of the pads reads their material and the fidelity besides the pad solids.
        let growth = *pad_expansion_per_k != 0.0;
        let equilibrium = EquilibriumInputs::of(case).case;
        let case = Case {
            bearing: Bearing {
                pads: bearing
                    .pads
                    .iter()
                    .zip(&equilibrium.bearing.pads)
                    .map(|(p, e)| if growth { growing_pad(p, e) } else { e.clone() })
                    .collect(),
                ..equilibrium.bearing
            },
            lubricant: Lubricant {
                specific_heat_j_per_kg_k: *specific_heat_j_per_kg_k,
                conductivity_w_per_m_k: *conductivity_w_per_m_k,
                ..equilibrium.lubricant
            },
            operating: Operating { supply_temperature_c: *supply_temperature_c, ..equilibrium.operating },
            mesh: MeshSpec {
                pad_radial_elements: *pad_radial_elements,
                fidelity: if growth { *fidelity } else { equilibrium.mesh.fidelity },
                ..equilibrium.mesh
            },
            thermal: *thermal,
            ..equilibrium
        };
        Some(Self { case })
    }

    /// The films it solves on.
    #[must_use]
    pub fn films(&self) -> FilmsInputs {
        FilmsInputs::of(&self.case)
    }

    /// What the pad solids and thermal systems are built from.
    #[must_use]
    pub fn solids(&self) -> PadSolidsInputs {
        PadSolidsInputs {
            films: self.films(),
            pad_radial_elements: self.case.mesh.pad_radial_elements,
            bc1: matches!(self.case.thermal.pad_film_bc, PadFilmBc::Bc1),
        }
    }
}

/// The equilibrium's view of a pad (`equilibrium`) with the material its thermal growth reads. Exhaustive
/// (no `..`).
fn growing_pad(pad: &Pad, equilibrium: &Pad) -> Pad {
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
        massless: _,
        pivot_contact: _,
        orifices: _, // the equilibrium's view
        density_kg_per_m3,
        youngs_modulus_pa,
        poisson_ratio,
    } = pad;
    Pad {
        density_kg_per_m3: *density_kg_per_m3,
        youngs_modulus_pa: *youngs_modulus_pa,
        poisson_ratio: *poisson_ratio,
        ..equilibrium.clone()
    }
}

/// A loop under way: the run, and whether it started from a previous state (a failure then retries cold).
struct Running {
    run: ThdRun,
    warm: bool,
}

#[derive(Default)]
pub struct ThermalStage {
    solids: Cached<PadSolidsInputs, ThermalModel>,
    /// A loop under way, under the inputs it works towards (a failed run is dropped).
    run: Cached<ThermalInputs, Running>,
    /// Last converged coordinates, under the films they were solved on.
    warm: Cached<FilmsInputs, Vec<f64>>,
}

impl Stage for ThermalStage {
    const LABEL: &'static str = "thermal (THD) loop";
    const NEEDS: &'static [StageId] = &[StageId::Films];
    type Inputs = ThermalInputs;
    type Output = Arc<Solution>;

    fn inputs(req: &Request) -> Option<ThermalInputs> {
        ThermalInputs::of(&req.case)
    }

    fn poll(
        &mut self,
        inputs: &ThermalInputs,
        ctx: &mut Ctx<'_>,
        cancel: &dyn Cancel,
    ) -> Result<Poll<Arc<Solution>>, SolveError> {
        let case = &inputs.case;
        let solids = inputs.solids();
        let cold = ctx.start() == Start::Cold;
        let model = ctx.output_mut::<FilmsStage>(&solids.films)?;
        install_structure(model, case)?;
        let tm = self.solids.get_or_try_insert(&solids, || ThermalModel::new(case, model))?;
        let mut running = match self.run.take(inputs) {
            Some(r) => r,
            None => {
                let start = if cold { None } else { self.warm.get(&solids.films).cloned() };
                let warm = start.is_some();
                Running { run: ThdRun::new(model, tm, case, ThermalParams::of(case), start.as_deref()), warm }
            }
        };
        let state = match running.run.step(model, tm, case, cancel) {
            Ok(Some(state)) => state,
            Ok(None) => {
                #[allow(clippy::cast_precision_loss)]
                let fraction = (running.run.outer_iterations() as f64 / THERMAL_ITERATIONS_EXPECTED).min(0.95);
                self.run.put(inputs.clone(), running);
                return Ok(Progress::Suspended(fraction));
            }
            // A failed warm start retries from a centred journal (the next poll starts it).
            Err(e) if running.warm && !matches!(e, SolveError::Cancelled) => {
                self.warm.clear();
                return Ok(Progress::Suspended(0.0));
            }
            Err(e) => return Err(e),
        };
        let solution = assemble_thd_solution(model, case, &state);
        self.warm.put(solids.films, solution.coordinates.clone());
        Ok(Progress::Done(Arc::new(solution)))
    }
}
