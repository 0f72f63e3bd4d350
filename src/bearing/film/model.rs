//! The bearing model built once per geometry and mesh: one film (mesh, quadrature, pattern, symbolic
//! factorisation, orifice operators, thickness shapes) per pad, and the global coordinate layout.
//!
//! Global coordinates: `u = [e_x, e_y, pad 0 coordinates…, pad 1 coordinates…, …]`, laid out by the
//! model's [`DofMap`] (see [`crate::bearing::film::coordinates`]). Changing the operating point (speed, load, viscosity,
//! injection) never rebuilds this.

use crate::bearing::report::error::InternalError;
use std::sync::Arc;

use crate::mesh::grid::{graded_nodes, PadGrid};
use crate::mesh::pad3d::PadMesh;
use crate::model::budget::orifice_zones;
use crate::model::Cavitation;
use crate::model::{Case, LoadSpec};
use crate::physics::orifice::LocalOrifice;
use crate::physics::reynolds::{FilmGeometry, FilmInputs, Inlet, PadFilm, Viscosity};
use crate::physics::turbulence::TurbulenceLaw;

use crate::bearing::film::coordinates::{DofMap, PadDof, PadStructure};
use crate::bearing::film::flex::{pad_modes, ModeCache};
use crate::bearing::film::geometry::PadShape;
use crate::bearing::report::error::SolveError;

/// One pad: its film and its structure (coordinates, structural stiffness and inertia).
#[derive(Debug, Clone)]
pub struct PadModel {
    pub film: PadFilm,
    pub structure: PadStructure,
    /// The pad solid (film grid extruded through the thickness), shared by the elastic and thermal models;
    /// built here when the pad is flexible, else by the thermal model when it needs one.
    pub solid: Option<Arc<PadMesh>>,
    /// The pad's retained bending modes (`PadDof::Mode(i)` is entry i), shared by identical pads.
    pub modes: Option<Arc<crate::physics::pad_modes::PadModes>>,
}

impl PadModel {
    /// The pad's coordinates, in its local order (after the journal's two).
    #[must_use]
    pub fn dofs(&self) -> &[PadDof] {
        &self.structure.dofs
    }
}

/// The model: built from a case's geometry and mesh.
#[derive(Debug, Clone)]
pub struct BearingModel {
    pub pads: Vec<PadModel>,
    /// Layout of the global coordinate vector.
    pub dofs: DofMap,
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
        let mut cache = ModeCache::new();
        for (k, pad) in b.pads.iter().enumerate() {
            let grid = pad_grid(case, k);
            let flexible = pad_modes(case, k, &grid, &mut cache)?;
            let mut structure = PadStructure::rigid(pad, r, b.length_m);
            let mut fields = Vec::new();
            if let Some(f) = &flexible {
                structure = structure.with_modes(&f.properties(pad.massless));
                fields = f.film_fields(&grid, r, pad.leading_edge_rad);
            }
            let shape = PadShape::new(pad, r, b.assembled_clearance_m, &structure.dofs).with_modes(fields);
            let orifices: Vec<LocalOrifice> = pad
                .orifices
                .iter()
                .map(|o| LocalOrifice {
                    s0: (o.angle_rad - pad.leading_edge_rad) * r,
                    z0: o.axial_m,
                    diameter: o.diameter_m,
                    length: o.length_m,
                })
                .collect();
            let geom = FilmGeometry::new(grid, r, pad.leading_edge_rad, &orifices, &shape);
            let film = PadFilm::new(geom).map_err(|e| SolveError::Film { pad: k, error: e })?;
            let (solid, modes) = flexible.map_or((None, None), |f| (Some(f.solid), Some(f.modes)));
            pads.push(PadModel { film, structure, solid, modes });
        }
        let dofs = DofMap::new(pads.iter().map(|p| p.structure.dofs.clone()).collect());
        Ok(Self { pads, dofs, journal_radius: r, assembled_clearance: b.assembled_clearance_m, length: b.length_m })
    }

    /// Replaces every pad's structure (pivot springs, inertia) without rebuilding the films: an edit of a
    /// pivot stiffness or of the pad density keeps the meshes and factorisations.
    ///
    /// # Errors
    /// If a structure's coordinates differ from the model's (they shape the films: rebuild the model).
    pub fn set_structure(&mut self, structures: Vec<PadStructure>) -> Result<(), SolveError> {
        if structures.len() != self.pads.len() {
            return Err(SolveError::Internal(InternalError::StructureCount {
                structures: structures.len(),
                pads: self.pads.len(),
            }));
        }
        for (k, (pm, s)) in self.pads.iter_mut().zip(structures).enumerate() {
            if s.dofs != pm.structure.dofs {
                return Err(SolveError::Internal(InternalError::StructureCoordinates { pad: k }));
            }
            pm.structure = s;
        }
        Ok(())
    }

    /// Length of the global coordinate vector.
    #[must_use]
    pub fn n_dofs(&self) -> usize {
        self.dofs.len()
    }

    /// Local coordinates of pad k, `[e_x, e_y, pad coordinates…]`, from the global vector.
    #[must_use]
    pub fn local(&self, k: usize, u: &[f64]) -> Vec<f64> {
        self.dofs.gather(k, u)
    }

    /// Total film nodes over all pads.
    #[must_use]
    pub fn film_nodes(&self) -> usize {
        self.pads.iter().map(|p| p.film.geom.n_nodes()).sum()
    }
}

/// The graded grid of pad k: refined around its orifices ([`orifice_zones`], the zones the node budget of
/// validation counts), halved when the case uses the half model.
#[must_use]
pub fn pad_grid(case: &Case, k: usize) -> PadGrid {
    let b = &case.bearing;
    let pad = &b.pads[k];
    let r = b.journal_radius_m;
    let m = &case.mesh;
    // The same refinement zones the node budget counts (one place decides the grid).
    let (zones_s, zones_z) = orifice_zones(pad, r, m.orifice_elements);
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
    /// Laminar or turbulent film coefficients.
    pub turbulence: TurbulenceLaw,
    /// Oil supply at each pad's leading edge (flooded, or a share of the bearing's supply flow).
    pub inlet: Vec<Inlet>,
    /// Peak pressure on every pad's leading edge [Pa], on its mid-plane: the ram pressure `k_ram ρ U²/2`
    /// (the edge carries it times `cos(π z/L)`; docs/MODEL.md §2.2).
    pub leading_edge_pressure: f64,
    pub load: LoadSpec,
    /// Film thickness below which an equilibrium is touchdown [m].
    pub touchdown_film: f64,
    /// Pads whose coordinates are held at their start values (an unloaded pad's tilt is not determined by
    /// its film; an outer thermal loop holds it so that the pad does not flip between equivalent states).
    pub held_pads: Vec<bool>,
}

/// Each pad's leading-edge supply: flooded, or its supply flow (the bearing's shared equally, or its own;
/// docs/MODEL.md §2.3).
#[must_use]
pub fn pad_inlets(case: &Case) -> Vec<Inlet> {
    match &case.operating.supply_flow_m3_s {
        None => vec![Inlet::Flooded; case.bearing.pads.len()],
        Some(q) => q.iter().map(|&flow_m3_s| Inlet::Supply { flow_m3_s }).collect(),
    }
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
            turbulence: turbulence_law(case),
            inlet: pad_inlets(case),
            leading_edge_pressure: ram_pressure(case),
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
            turbulence: self.turbulence,
            inlet: self.inlet[k],
            leading_edge_pressure: self.leading_edge_pressure,
        }
    }
}

/// The ram pressure on the pads' leading edges [Pa] (docs/MODEL.md §2.2): the dynamic pressure of the journal
/// surface speed, `ρ U²/2`, times `feeding.ram_pressure_coefficient` (0 without it).
#[must_use]
pub fn ram_pressure(case: &Case) -> f64 {
    let u = case.operating.speed_rad_s * case.bearing.journal_radius_m;
    case.physics.ram_pressure_coefficient * 0.5 * case.lubricant.density_kg_per_m3 * u * u
}

/// The turbulence law of a case's films (docs/MODEL.md §2.7).
#[must_use]
pub fn turbulence_law(case: &Case) -> TurbulenceLaw {
    let [re_start, re_end] = case.physics.transition_reynolds;
    TurbulenceLaw { mode: case.physics.turbulence, re_start, re_end, density: case.lubricant.density_kg_per_m3 }
}
