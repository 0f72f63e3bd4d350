//! The films stage: meshes, films and the coordinate layout of every pad ([`BearingModel::new`]).
//!
//! Reads the geometry the films are built on and the element counts; not the pivot stiffness values nor
//! the pad density (they only enter the pads' structure, which the stages that solve install from their own
//! view with [`install_structure`]: the films' model holds blank springs until then), not the fidelity
//! name (its element counts are read) and not the node budget (checked when the case is validated). With
//! `physics.pad_modes > 0` the films also carry the pads' bending modes (their film shapes are
//! coordinates): then E, ν, the density and the pad solid's layers are read too, and only then — a rigid
//! case's films ignore them.

use crate::bearing::film::coordinates::PadStructure;
use crate::bearing::film::flex::modal_properties;
use crate::bearing::film::model::BearingModel;
use crate::bearing::report::error::SolveError;
use crate::bearing::stages::view;
use crate::model::{Bearing, Case, MeshSpec, Pad, Physics};

use crate::bearing::report::progress::{Cancel, Progress};
use crate::bearing::stages::id::StageId;
use crate::bearing::stages::request::Request;
use crate::bearing::stages::stage::{Ctx, Poll, Stage};

/// The inputs of the films: the case as they see it ([`super::view`]).
#[derive(Debug, Clone, PartialEq)]
pub struct FilmsInputs {
    /// R, L, C_b; per pad θ_le, β, θ_p, C_p, t, its orifices and which of its pivot stiffnesses and contact
    /// are given (its coordinates); the element counts and the half model; with bending modes
    /// (`physics.pad_modes > 0`) their count, the pad solid's layers and each pad's E, ν and density.
    pub case: Case,
}

impl FilmsInputs {
    /// Exhaustive over the case, the bearing, the mesh and the physics (no `..`).
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
            pad_radial_elements, // the pad solids of the modes (the thermal stage's too)
            max_nodes: _,        // checked when the case is validated
        } = mesh;
        let flexible = *pad_modes > 0;
        let blank = view::case();
        let case = Case {
            bearing: Bearing {
                journal_radius_m: *journal_radius_m,
                length_m: *length_m,
                assembled_clearance_m: *assembled_clearance_m,
                pads: pads.iter().map(|pad| film_pad(pad, flexible)).collect(),
            },
            mesh: MeshSpec {
                circumferential_elements: *circumferential_elements,
                axial_elements: *axial_elements,
                orifice_elements: *orifice_elements,
                half_model: *half_model,
                pad_radial_elements: if flexible { *pad_radial_elements } else { blank.mesh.pad_radial_elements },
                ..blank.mesh
            },
            physics: Physics { pad_modes: *pad_modes, ..blank.physics },
            ..blank
        };
        Self { case }
    }
}

/// What shapes one pad's film: its geometry, which pivot stiffnesses and contact it has (its coordinates),
/// and when the pads bend (`flexible`) the material of its modes. Exhaustive (no `..`).
fn film_pad(pad: &Pad, flexible: bool) -> Pad {
    let Pad {
        kind,
        leading_edge_rad,
        arc_rad,
        pivot_rad,
        offset: _, // enters through pivot_rad
        clearance_m,
        preload: _, // enters through clearance_m; reported by the equilibrium
        thickness_m,
        pivot_stiffness_n_per_m,
        pivot_transverse_stiffness_n_per_m, // whether given: coordinates (values: the structure)
        density_kg_per_m3,
        massless: _, // the structure's inertia (the modes take the material's density)
        youngs_modulus_pa,
        poisson_ratio, // the modes' material
        pivot_contact, // whether given: a coordinate (its values: the equilibrium's)
        orifices,
    } = pad;
    let blank = view::pad();
    let material = |value: f64, blank: f64| if flexible { value } else { blank };
    Pad {
        kind: *kind,
        leading_edge_rad: *leading_edge_rad,
        arc_rad: *arc_rad,
        pivot_rad: *pivot_rad,
        clearance_m: *clearance_m,
        thickness_m: *thickness_m,
        pivot_stiffness_n_per_m: pivot_stiffness_n_per_m.map(|_| view::BLANK),
        pivot_transverse_stiffness_n_per_m: pivot_transverse_stiffness_n_per_m.map(|_| view::BLANK),
        pivot_contact: pivot_contact.map(|_| view::contact()),
        density_kg_per_m3: material(*density_kg_per_m3, blank.density_kg_per_m3),
        youngs_modulus_pa: material(*youngs_modulus_pa, blank.youngs_modulus_pa),
        poisson_ratio: material(*poisson_ratio, blank.poisson_ratio),
        orifices: orifices.clone(),
        ..blank
    }
}

/// Installs the pad structures of a stage's view of the case (pivot springs and inertia) in a model built
/// for the same films (a flexible pad keeps the modal mass and stiffness of the modes the model holds).
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
        inputs: &FilmsInputs,
        _ctx: &mut Ctx<'_>,
        _cancel: &dyn Cancel,
    ) -> Result<Poll<BearingModel>, SolveError> {
        Ok(Progress::Done(BearingModel::new(&inputs.case)?))
    }
}
