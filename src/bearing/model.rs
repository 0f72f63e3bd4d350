//! The bearing model built once per geometry and mesh: one film (mesh, quadrature, pattern, symbolic
//! factorisation, orifice operators, thickness shapes) per pad, and the global coordinate layout.
//!
//! Global coordinates: `u = [e_x, e_y, pad 0 dofs…, pad 1 dofs…, …]` (see [`super::geometry`]).
//! Changing the operating point (speed, load, viscosity, injection) never rebuilds this.

use crate::mesh::grid::{graded_nodes, PadGrid, Refinement};
use crate::model::{Case, LoadSpec};
use crate::physics::orifice::LocalOrifice;
use crate::physics::reynolds::{FilmGeometry, FilmInputs, PadFilm, Viscosity};
use crate::model::Cavitation;

use super::error::SolveError;
use super::geometry::{pad_dofs, pad_mass_matrix, PadDof, PadShape};

/// One pad: its film and where its coordinates live in the global vector.
#[derive(Debug, Clone)]
pub struct PadModel {
    pub film: PadFilm,
    pub dofs: Vec<PadDof>,
    /// Index of the pad's first coordinate in the global vector.
    pub offset: usize,
    /// Structural stiffness on each pad coordinate (pivot stiffness on the radial one, 0 for the tilt).
    pub structural_stiffness: Vec<f64>,
    /// Rigid-body inertia in the pad coordinates.
    pub mass: Vec<Vec<f64>>,
}

/// The model: built from a case's geometry and mesh.
#[derive(Debug, Clone)]
pub struct BearingModel {
    pub pads: Vec<PadModel>,
    /// Total number of global coordinates (2 + Σ pad dofs).
    pub n_dofs: usize,
    pub journal_radius: f64,
    pub assembled_clearance: f64,
    pub length: f64,
}

impl BearingModel {
    /// Builds meshes and films for every pad.
    ///
    /// # Errors
    /// If a symbolic factorisation fails.
    pub fn new(case: &Case) -> Result<Self, SolveError> {
        let b = &case.bearing;
        let r = b.journal_radius_m;
        let mut pads = Vec::with_capacity(b.pads.len());
        let mut offset = 2;
        for (k, pad) in b.pads.iter().enumerate() {
            let grid = pad_grid(case, k);
            let shape = PadShape::new(pad, r, b.assembled_clearance_m);
            let orifices: Vec<LocalOrifice> = pad
                .orifices
                .iter()
                .map(|o| LocalOrifice { s0: (o.angle_rad - pad.leading_edge_rad) * r, z0: o.axial_m, diameter: o.diameter_m, length: o.length_m })
                .collect();
            let geom = FilmGeometry::new(grid, r, pad.leading_edge_rad, &orifices, &shape);
            let film = PadFilm::new(geom).map_err(|e| SolveError::Film { pad: k, source: e })?;
            let dofs = pad_dofs(pad);
            let structural_stiffness = dofs
                .iter()
                .map(|d| match d {
                    PadDof::Tilt => 0.0,
                    PadDof::PivotRadial => pad.pivot_stiffness_n_per_m.unwrap_or(0.0),
                })
                .collect();
            let mass = pad_mass_matrix(pad, r, b.length_m);
            let n = dofs.len();
            pads.push(PadModel { film, dofs, offset, structural_stiffness, mass });
            offset += n;
        }
        Ok(Self { pads, n_dofs: offset, journal_radius: r, assembled_clearance: b.assembled_clearance_m, length: b.length_m })
    }

    /// Local coordinates of pad k, `[e_x, e_y, pad dofs…]`, from the global vector.
    #[must_use]
    pub fn local(&self, k: usize, u: &[f64]) -> Vec<f64> {
        let p = &self.pads[k];
        let mut q = Vec::with_capacity(2 + p.dofs.len());
        q.extend_from_slice(&u[..2]);
        q.extend_from_slice(&u[p.offset..p.offset + p.dofs.len()]);
        q
    }

    /// Total film nodes over all pads.
    #[must_use]
    pub fn film_nodes(&self) -> usize {
        self.pads.iter().map(|p| p.film.geom.n_nodes()).sum()
    }
}

/// The graded grid of pad k: refined around its orifices, halved when the case uses the half model.
#[must_use]
pub fn pad_grid(case: &Case, k: usize) -> PadGrid {
    let b = &case.bearing;
    let pad = &b.pads[k];
    let r = b.journal_radius_m;
    let m = &case.mesh;
    let zones_s: Vec<Refinement> = pad
        .orifices
        .iter()
        .map(|o| Refinement {
            centre: (o.angle_rad - pad.leading_edge_rad) * r,
            half_width: 0.6 * o.diameter_m,
            fine: o.diameter_m / m.orifice_elements as f64,
        })
        .collect();
    let zones_z: Vec<Refinement> = pad
        .orifices
        .iter()
        .map(|o| Refinement { centre: o.axial_m, half_width: 0.6 * o.diameter_m, fine: o.diameter_m / m.orifice_elements as f64 })
        .collect();
    let periodic = pad.is_full_circle();
    let s = graded_nodes(0.0, pad.arc_rad * r, m.circumferential_elements, &zones_s);
    let half_len = 0.5 * b.length_m;
    let z = if m.half_model {
        graded_nodes(0.0, half_len, m.axial_elements / 2, &zones_z)
    } else {
        graded_nodes(-half_len, half_len, m.axial_elements, &zones_z)
    };
    PadGrid { s, z, periodic, half: m.half_model }
}

/// Operating-point data the films need (per pad where it differs).
#[derive(Debug, Clone, PartialEq)]
pub struct OperatingPoint {
    /// U = Ω R [m/s].
    pub surface_speed: f64,
    pub speed_rad_s: f64,
    /// Uniform film viscosity [Pa·s], unless a nodal field is given for the pad.
    pub viscosity: f64,
    /// Optional nodal viscosity per pad (thermal model).
    pub nodal_viscosity: Vec<Option<Vec<f64>>>,
    pub injection_pressure: Vec<f64>,
    pub injection_viscosity: f64,
    pub cavitation: Cavitation,
    pub load: LoadSpec,
    /// Film thickness below which an equilibrium is touchdown [m].
    pub touchdown_film: f64,
    /// Pads whose coordinates are held at their start values (an unloaded pad's tilt is not determined by
    /// its film; an outer thermal loop holds it so that the pad does not flip between equivalent states).
    pub held_pads: Vec<bool>,
}

impl OperatingPoint {
    /// Isothermal operating point of a case (viscosity at the film temperature).
    #[must_use]
    pub fn isothermal(case: &Case) -> Self {
        let o = &case.operating;
        let law = &case.lubricant.viscosity;
        Self {
            surface_speed: o.speed_rad_s * case.bearing.journal_radius_m,
            speed_rad_s: o.speed_rad_s,
            viscosity: law.at(o.film_temperature_c),
            nodal_viscosity: vec![None; case.bearing.pads.len()],
            injection_pressure: o.injection_pressure_pa.clone(),
            injection_viscosity: law.at(o.injection_temperature_c),
            cavitation: case.physics.cavitation,
            load: o.load,
            touchdown_film: case.physics.touchdown_film_m,
            held_pads: vec![false; case.bearing.pads.len()],
        }
    }

    /// Film inputs of pad k.
    #[must_use]
    pub fn film_inputs(&self, k: usize) -> FilmInputs<'_> {
        FilmInputs {
            surface_speed: self.surface_speed,
            viscosity: match &self.nodal_viscosity[k] {
                Some(v) => Viscosity::Nodal(v),
                None => Viscosity::Uniform(self.viscosity),
            },
            injection_pressure: self.injection_pressure[k],
            injection_viscosity: self.injection_viscosity,
            cavitation: self.cavitation,
        }
    }
}
