//! Flexible pads in the bearing model: which pads get bending modes, their shared solids and modes, and the
//! mesh-convergence table of the pad modes (thesis Table 3.1 style).
//!
//! A tilting pad with thickness gets `physics.pad_modes` bending modes ([`crate::physics::pad_modes`]) on the
//! pad solid extruded from its film grid with `mesh.pad_radial_elements` layers — the same solid the
//! thermal model conducts heat in. Each mode becomes the coordinate `PadDof::Mode(i)`: its film shape is the
//! sampled field, its modal mass and stiffness join the pad's [`crate::bearing::film::coordinates::PadStructure`]; the
//! equilibrium and the coefficients handle the extra coordinates as they handle any other.
//!
//! Modes depend on exactly [`ModeKey`]: the film grid, journal radius, bore, thickness, layers, pivot
//! position within the arc, material and count. Pads whose keys match up to round-off ([`ModeKey::matches`]; the usual
//! identical pads at other angles) share one computation.

use crate::bearing::report::error::ElasticWork;
use std::sync::Arc;

use serde::Serialize;

use crate::fem::solid8::Elastic;
use crate::mesh::grid::PadGrid;
use crate::mesh::pad3d::PadMesh;
use crate::model::{Case, PadKind};
use crate::physics::pad_modes::{FilmField, ModeKey, PadModes, PivotSupport};

use crate::bearing::film::coordinates::ModalProperties;
use crate::bearing::report::error::SolveError;

/// Modes computed so far in one model build, by key.
pub type ModeCache = Vec<(ModeKey, Arc<PadModes>)>;

/// A flexible pad's solid and modes.
#[derive(Debug, Clone)]
pub struct FlexPad {
    pub solid: Arc<PadMesh>,
    pub modes: Arc<PadModes>,
}

impl FlexPad {
    /// Modal mass, stiffness and couplings of each retained mode (no mass for a massless pad).
    #[must_use]
    pub fn properties(&self, massless: bool) -> Vec<ModalProperties> {
        modal_properties(&self.modes, massless)
    }

    /// The modes' film shapes on the pad's film grid.
    #[must_use]
    pub fn film_fields(&self, grid: &PadGrid, radius: f64, theta_le: f64) -> Vec<FilmField> {
        self.modes
            .modes
            .iter()
            .map(|m| FilmField { grid: grid.clone(), radius, theta_le, node: m.film_shape.clone() })
            .collect()
    }
}

/// Modal mass, stiffness and pivot-translation couplings of each of a pad's retained modes.
///
/// A **massless** pad (`bearing.pads.massless`, the databook convention) has no inertia in any of its
/// coordinates: its modes keep their stiffness `k = ω²m` — independent of the density, since the shapes do
/// not depend on a uniform density and `ω² ∝ 1/ρ`, `m ∝ ρ` — but carry no modal mass and no mass coupling
/// with the pivot translations, as its rigid tilt and translations carry none.
#[must_use]
pub fn modal_properties(modes: &PadModes, massless: bool) -> Vec<ModalProperties> {
    let inertia = if massless { 0.0 } else { 1.0 };
    modes
        .modes
        .iter()
        .map(|m| ModalProperties {
            mass: inertia * m.mass,
            stiffness: m.stiffness,
            momentum_pt: [inertia * m.momentum_pt[0], inertia * m.momentum_pt[1]],
        })
        .collect()
}

/// The material of pad k.
fn material(case: &Case, k: usize) -> Elastic {
    let pad = &case.bearing.pads[k];
    Elastic { youngs_modulus: pad.youngs_modulus_pa, poisson_ratio: pad.poisson_ratio, density: pad.density_kg_per_m3 }
}

/// Solid and `bending` modes of pad k on `grid` with `layers` element layers, through the cache.
///
/// # Errors
/// [`SolveError::PadElastic`] naming the pad if the elastic model fails.
pub fn pad_solid_modes(
    case: &Case,
    k: usize,
    grid: &PadGrid,
    layers: usize,
    bending: usize,
    cache: &mut ModeCache,
) -> Result<FlexPad, SolveError> {
    let b = &case.bearing;
    let pad = &b.pads[k];
    let r = b.journal_radius_m;
    let bore = pad.bore_radius_m(r);
    let solid = Arc::new(PadMesh::extrude(grid, r, pad.leading_edge_rad, bore, pad.thickness_m, layers));
    let mat = material(case, k);
    let key = ModeKey {
        grid: grid.clone(),
        radius: r,
        bore,
        thickness: pad.thickness_m,
        layers,
        pivot_from_le: pad.pivot_rad - pad.leading_edge_rad,
        material: mat,
        bending,
    };
    let support = PivotSupport { pivot_rad: pad.pivot_rad, lever: bore + pad.thickness_m, arc_rad: pad.arc_rad };
    let modes = PadModes::cached(cache, key, || PadModes::compute(&solid, support, &mat, bending, grid.half))
        .map_err(|error| SolveError::PadElastic { pad: k, what: ElasticWork::Modes, error })?;
    Ok(FlexPad { solid, modes })
}

/// The flexible-pad data of pad k when the case asks for bending modes and the pad can have them (a tilting
/// pad with thickness); `None` for a rigid pad.
///
/// # Errors
/// As [`pad_solid_modes`].
pub fn pad_modes(case: &Case, k: usize, grid: &PadGrid, cache: &mut ModeCache) -> Result<Option<FlexPad>, SolveError> {
    let pad = &case.bearing.pads[k];
    let n = case.physics.pad_modes;
    if n == 0 || pad.kind != PadKind::Tilting || pad.thickness_m <= 0.0 {
        return Ok(None);
    }
    pad_solid_modes(case, k, grid, case.mesh.pad_radial_elements, n, cache).map(Some)
}

/// One mesh of the pad-mode convergence table.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ModeTableRow {
    /// Film elements (circumferential × axial, modelled part) and solid elements.
    pub film_elements: usize,
    pub solid_elements: usize,
    pub circumferential: usize,
    pub axial: usize,
    pub layers: usize,
    /// Frequencies of the bending modes [Hz].
    pub frequencies_hz: Vec<f64>,
    /// Relative error of each against the finest mesh of the table.
    pub relative_error: Vec<f64>,
    /// Reduced unknowns of the pad solid and the eigen-solution's wall time [s].
    pub unknowns: usize,
    pub seconds: f64,
}

/// Bending-mode frequencies of pad k on uniform meshes `(circumferential, axial over the modelled part,
/// layers)`, with the relative error against the last (finest) one — the thesis's Table 3.1 study.
///
/// # Errors
/// As [`pad_solid_modes`].
pub fn mode_table(
    case: &Case,
    k: usize,
    meshes: &[(usize, usize, usize)],
    bending: usize,
) -> Result<Vec<ModeTableRow>, SolveError> {
    let b = &case.bearing;
    let pad = &b.pads[k];
    let half = case.mesh.half_model;
    let mut rows = Vec::with_capacity(meshes.len());
    for &(nc, nz, layers) in meshes {
        #[allow(clippy::cast_precision_loss)]
        let s: Vec<f64> = (0..=nc).map(|i| pad.arc_rad * b.journal_radius_m * i as f64 / nc as f64).collect();
        let (z0, z1) = if half { (0.0, 0.5 * b.length_m) } else { (-0.5 * b.length_m, 0.5 * b.length_m) };
        #[allow(clippy::cast_precision_loss)]
        let z: Vec<f64> = (0..=nz).map(|j| z0 + (z1 - z0) * j as f64 / nz as f64).collect();
        let grid = PadGrid { s, z, periodic: false, half };
        let flex = pad_solid_modes(case, k, &grid, layers, bending, &mut ModeCache::new())?;
        rows.push(ModeTableRow {
            film_elements: nc * nz,
            solid_elements: nc * nz * layers,
            circumferential: nc,
            axial: nz,
            layers,
            frequencies_hz: flex.modes.modes.iter().map(|m| m.frequency_hz).collect(),
            relative_error: Vec::new(),
            unknowns: flex.modes.report.unknowns,
            seconds: flex.modes.report.seconds,
        });
    }
    if let Some(finest) = rows.last().map(|r| r.frequencies_hz.clone()) {
        for r in &mut rows {
            r.relative_error = r.frequencies_hz.iter().zip(&finest).map(|(f, g)| (f - g).abs() / g).collect();
        }
    }
    Ok(rows)
}
