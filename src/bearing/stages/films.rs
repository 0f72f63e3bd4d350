//! The films stage: meshes, films and the coordinate layout of every pad ([`BearingModel::new`]).
//!
//! Reads the geometry the films are built on and the element counts; not the pivot stiffness values nor
//! the pad density (they only enter the pads' structure, installed by the stages that solve with
//! [`install_structure`]), not the fidelity name (its element counts are read) and not the node budget
//! (checked when the case is validated). With `physics.pad_modes > 0` the films also carry the pads'
//! bending modes (their film shapes are coordinates): then E, ν, the density and the pad solid's layers
//! are read too ([`FlexInputs`]), and only then — a rigid case's films ignore them.

use crate::bearing::film::coordinates::{pad_dofs, PadDof, PadStructure};
use crate::bearing::film::flex::modal_properties;
use crate::bearing::film::model::BearingModel;
use crate::bearing::report::error::SolveError;
use crate::model::{Bearing, Case, MeshSpec, Orifice, Pad, Physics};
use crate::physics::hertz::PivotContact;

use crate::bearing::report::progress::{Cancel, Progress};
use crate::bearing::stages::id::StageId;
use crate::bearing::stages::request::Request;
use crate::bearing::stages::stage::{Ctx, Poll, Stage};

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
    /// What the pads' bending modes read; `None` for rigid pads (`physics.pad_modes = 0`).
    pub flex: Option<FlexInputs>,
}

/// What the pads' bending modes read besides the films' geometry (computed once per distinct pad and shared;
/// an edit of speed, load or oil keeps them).
#[derive(Debug, Clone, PartialEq)]
pub struct FlexInputs {
    /// Bending modes per pad.
    pub pad_modes: usize,
    /// Element layers of the pad solid through the thickness.
    pub pad_radial_elements: usize,
    /// Per pad: Young's modulus [Pa], Poisson's ratio, density [kg/m³].
    pub materials: Vec<[f64; 3]>,
}

impl FlexInputs {
    /// Exhaustive over the pad's material fields (no `..`); `None` without modes.
    fn of(pads: &[Pad], pad_modes: usize, pad_radial_elements: usize) -> Option<Self> {
        let materials = pads
            .iter()
            .map(|pad| {
                let Pad {
                    kind: _,
                    leading_edge_rad: _,
                    arc_rad: _,
                    pivot_rad: _,
                    offset: _,
                    clearance_m: _,
                    preload: _,
                    thickness_m: _, // in PadFilmInputs
                    pivot_stiffness_n_per_m: _,
                    pivot_transverse_stiffness_n_per_m: _, // the modes are computed on a rigid pivot
                    density_kg_per_m3,
                    youngs_modulus_pa,
                    poisson_ratio,
                    orifices: _,
                    massless: _, // the inertia's (structure: no rigid or modal mass); the mode shapes take the material's density
                    pivot_contact: _, // the modes are computed on a rigid pivot
                } = pad;
                [*youngs_modulus_pa, *poisson_ratio, *density_kg_per_m3]
            })
            .collect();
        (pad_modes > 0).then_some(Self { pad_modes, pad_radial_elements, materials })
    }
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
            poisson_ratio: _, // FlexInputs, when the pads bend
            pivot_contact: _, // whether one is given: dofs (its values: StructureInputs)
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
        let Case {
            title: _,
            bearing,
            lubricant: _,
            operating: _,
            mesh,
            physics,
            thermal: _,
            hydraulics: _,
            limits: _,
            tuning: _,
        } = case;
        let Physics {
            cavitation: _,
            touchdown_film_m: _,
            pad_modes,
            turbulence: _,
            transition_reynolds: _,
            max_film_solves_per_pad: _,
            ram_pressure_coefficient: _,
        } = physics; // the equilibrium's (cavitation, turbulence); the modes
        let Bearing { journal_radius_m, length_m, assembled_clearance_m, pads } = bearing;
        let MeshSpec {
            fidelity: _, // its element counts are read
            circumferential_elements,
            axial_elements,
            orifice_elements,
            half_model,
            pad_radial_elements, // the pad solids (the modes' here; the thermal stage's too)
            max_nodes: _,        // checked when the case is validated
        } = mesh;
        Self {
            journal_radius_m: *journal_radius_m,
            length_m: *length_m,
            assembled_clearance_m: *assembled_clearance_m,
            pads: pads.iter().map(PadFilmInputs::of).collect(),
            elements: [*circumferential_elements, *axial_elements, *orifice_elements],
            half_model: *half_model,
            flex: FlexInputs::of(pads, *pad_modes, *pad_radial_elements),
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
    /// Hertz pivot contact per pad (geometry and both materials; its stiffness follows the pad's load).
    pub contacts: Vec<Option<PivotContact>>,
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
                poisson_ratio: _, // a contact's pivot material: copied into pivot_contact
                orifices: _,
                pivot_contact,
            } = pad;
            // The density of the inertia: none for massless pads.
            let density = if *massless { 0.0 } else { *density_kg_per_m3 };
            (([*pivot_stiffness_n_per_m, *pivot_transverse_stiffness_n_per_m], density), *pivot_contact)
        });
        let (springs, contacts): (Vec<_>, Vec<_>) = fields.unzip();
        let (stiffness_n_per_m, density_kg_per_m3) = springs.into_iter().unzip();
        Self { stiffness_n_per_m, density_kg_per_m3, contacts }
    }
}

/// Installs the case's pad structures in a model built for the same films (a flexible pad keeps the
/// modal mass and stiffness of the modes the model holds).
///
/// # Errors
/// A model built for other coordinates.
pub fn install_structure(model: &mut BearingModel, case: &Case) -> Result<(), SolveError> {
    let b = &case.bearing;
    let structures = b
        .pads
        .iter()
        .zip(&model.pads)
        .map(|(p, pm)| {
            let rigid = PadStructure::rigid(p, b.journal_radius_m, b.length_m);
            match &pm.modes {
                Some(modes) => rigid.with_modes(&modal_properties(modes, p.massless)),
                None => rigid,
            }
        })
        .collect();
    model.set_structure(structures)
}

#[derive(Default)]
pub struct FilmsStage;

impl Stage for FilmsStage {
    const LABEL: &'static str = "meshes and films";
    const NEEDS: &'static [StageId] = &[];
    const KEEP_MANY: bool = false;
    type Inputs = FilmsInputs;
    type Output = BearingModel;

    fn inputs(req: &Request) -> Option<FilmsInputs> {
        Some(FilmsInputs::of(&req.case))
    }

    fn poll(
        &mut self,
        _inputs: &FilmsInputs,
        ctx: &mut Ctx<'_>,
        _cancel: &dyn Cancel,
    ) -> Result<Poll<BearingModel>, SolveError> {
        Ok(Progress::Done(BearingModel::new(ctx.case())?))
    }
}
