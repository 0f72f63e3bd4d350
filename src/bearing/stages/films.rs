//! The films stage: meshes, films and the coordinate layout of every pad ([`BearingModel::new`]).
//!
//! Reads the geometry the films are built on and the element counts; not the pivot stiffness values nor
//! the pad density (they only enter the pads' structure, installed by the stages that solve with
//! [`install_structure`]), not E or ν, not the fidelity name (its element counts are read) and not the
//! node budget (checked when the case is validated).

use crate::bearing::coordinates::{pad_dofs, PadDof, PadStructure};
use crate::bearing::error::SolveError;
use crate::bearing::model::BearingModel;
use crate::model::{Bearing, Case, MeshSpec, Orifice, Pad};

use super::{Ctx, Poll, Progress, Request, Stage, StageId};
use crate::bearing::progress::Cancel;

/// What shapes one pad's film.
#[derive(Debug, Clone, PartialEq)]
pub struct PadFilmInputs {
    /// Tilt and the free pivot translations (kind, and which pivot stiffnesses are given).
    pub dofs: Vec<PadDof>,
    pub leading_edge_rad: f64,
    pub arc_rad: f64,
    pub pivot_rad: f64,
    pub clearance_m: f64,
    /// The lever of the pivot translations (and the pad solid of the thermal model).
    pub thickness_m: f64,
    pub orifices: Vec<Orifice>,
}

/// The inputs of the films.
#[derive(Debug, Clone, PartialEq)]
pub struct FilmsInputs {
    pub journal_radius_m: f64,
    pub length_m: f64,
    pub assembled_clearance_m: f64,
    pub pads: Vec<PadFilmInputs>,
    /// Circumferential, axial and orifice element counts.
    pub elements: [usize; 3],
    pub half_model: bool,
}

impl PadFilmInputs {
    /// Exhaustive (no `..`): a new pad field does not compile here until it is placed.
    fn of(pad: &Pad) -> Self {
        let Pad {
            kind: _,
            leading_edge_rad,
            arc_rad,
            pivot_rad,
            offset: _, // enters through pivot_rad
            clearance_m,
            preload: _, // enters through clearance_m; reported by the equilibrium
            thickness_m,
            pivot_stiffness_n_per_m: _,
            pivot_transverse_stiffness_n_per_m: _, // kind and which stiffnesses are given: dofs
            density_kg_per_m3: _,                  // structure (coefficients)
            massless: _,                           // structure (coefficients)
            youngs_modulus_pa: _,
            poisson_ratio: _, // read by no stage until the pads deform
            orifices,
        } = pad;
        Self {
            dofs: pad_dofs(pad),
            leading_edge_rad: *leading_edge_rad,
            arc_rad: *arc_rad,
            pivot_rad: *pivot_rad,
            clearance_m: *clearance_m,
            thickness_m: *thickness_m,
            orifices: orifices.clone(),
        }
    }
}

impl FilmsInputs {
    /// Exhaustive over the case, the bearing and the mesh (no `..`).
    #[must_use]
    pub fn of(case: &Case) -> Self {
        let Case { title: _, bearing, lubricant: _, operating: _, mesh, physics: _, thermal: _, hydraulics: _ } = case;
        let Bearing { journal_radius_m, length_m, assembled_clearance_m, pads } = bearing;
        let MeshSpec {
            fidelity: _, // its element counts are read
            circumferential_elements,
            axial_elements,
            orifice_elements,
            half_model,
            pad_radial_elements: _, // the thermal stage's pad solids
            max_nodes: _,           // checked when the case is validated
        } = mesh;
        Self {
            journal_radius_m: *journal_radius_m,
            length_m: *length_m,
            assembled_clearance_m: *assembled_clearance_m,
            pads: pads.iter().map(PadFilmInputs::of).collect(),
            elements: [*circumferential_elements, *axial_elements, *orifice_elements],
            half_model: *half_model,
        }
    }
}

/// The per-pad structural values (pivot stiffnesses, density) of a case, as the stages that install the
/// structure key them.
#[derive(Debug, Clone, PartialEq)]
pub struct StructureInputs {
    /// Radial and transverse pivot stiffness per pad [N/m].
    pub stiffness_n_per_m: Vec<[Option<f64>; 2]>,
    /// Pad density per pad [kg/m³] (inertia only; 0 for massless pads).
    pub density_kg_per_m3: Vec<f64>,
}

impl StructureInputs {
    /// Exhaustive over the pad (no `..`).
    #[must_use]
    pub fn of(case: &Case) -> Self {
        let fields = case.bearing.pads.iter().map(|pad| {
            let Pad {
                kind: _,
                leading_edge_rad: _,
                arc_rad: _,
                pivot_rad: _,
                offset: _,
                clearance_m: _,
                preload: _,
                thickness_m: _, // all in FilmsInputs
                pivot_stiffness_n_per_m,
                pivot_transverse_stiffness_n_per_m,
                density_kg_per_m3,
                massless,
                youngs_modulus_pa: _,
                poisson_ratio: _,
                orifices: _,
            } = pad;
            // The density of the inertia: none for massless pads.
            let density = if *massless { 0.0 } else { *density_kg_per_m3 };
            ([*pivot_stiffness_n_per_m, *pivot_transverse_stiffness_n_per_m], density)
        });
        let (stiffness_n_per_m, density_kg_per_m3) = fields.unzip();
        Self { stiffness_n_per_m, density_kg_per_m3 }
    }
}

/// Installs the case's pad structures in a model built for the same films.
///
/// # Errors
/// A model built for other coordinates.
pub fn install_structure(model: &mut BearingModel, case: &Case) -> Result<(), SolveError> {
    let b = &case.bearing;
    model.set_structure(b.pads.iter().map(|p| PadStructure::rigid(p, b.journal_radius_m, b.length_m)).collect())
}

#[derive(Default)]
pub struct FilmsStage;

impl Stage for FilmsStage {
    const LABEL: &'static str = "meshes and films";
    const NEEDS: &'static [StageId] = &[];
    type Inputs = FilmsInputs;
    type Output = BearingModel;

    fn inputs(req: &Request) -> Option<FilmsInputs> {
        Some(FilmsInputs::of(&req.case))
    }

    fn poll(&mut self, _inputs: &FilmsInputs, ctx: &mut Ctx<'_>, _cancel: &dyn Cancel) -> Result<Poll<BearingModel>, SolveError> {
        Ok(Progress::Done(BearingModel::new(ctx.case())?))
    }
}
