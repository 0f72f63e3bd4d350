//! The node budget: how many mesh nodes a case would allocate, counted from the case alone, before any mesh
//! is built.
//!
//! ## What is counted
//! ```text
//! N = Σ_pads n_s,k · n_z,k                      film nodes (graded grids, refined around every orifice)
//!   + Σ_pads n_s,k · n_z,k · (n_r + 1)          pad-solid nodes (thermal model, pads with a thickness)
//! ```
//! with `n_s`, `n_z` the node columns and rows the graded grid of each pad will have (the same grading as
//! the solver's meshes: [`crate::mesh::grid`]) and `n_r` the element layers through the pad. Memory and time
//! grow with N (every node carries a row of the film's sparse factorisation, whose fill grows faster than
//! N), so N is what the budget `mesh.max_nodes` bounds. The orifice operators add nothing per mesh node: they
//! are sparse over each hole's footprint.
//!
//! A case whose N exceeds the budget is refused by validation ([`CaseError::NodeBudget`]) with the count
//! and the keys that change it; nothing is allocated beyond the 1-D node spacings counted here.

use crate::mesh::grid::{graded_cells, orifice_zone, Refinement};

use super::case::{Case, Pad, ThermalModelKind};
use super::error::CaseError;

/// Default of `mesh.max_nodes`, with its key's row (the measurements behind it are there).
pub use super::schema::DEFAULT_MAX_NODES;
/// Allowed values of `mesh.max_nodes`.
pub const MAX_NODES_RANGE: (usize, usize) = (1_000, 50_000_000);

/// The nodes a case's meshes would have.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct NodeCount {
    /// Film nodes of each pad.
    pub film_per_pad: Vec<usize>,
    /// Pad-solid nodes over all pads (0 without the thermal model).
    pub pad_solid: usize,
}

impl NodeCount {
    /// Film nodes over all pads.
    #[must_use]
    pub fn film(&self) -> usize {
        self.film_per_pad.iter().sum()
    }
    /// Everything the budget bounds.
    #[must_use]
    pub fn total(&self) -> usize {
        self.film().saturating_add(self.pad_solid)
    }
}

/// Node columns (along the arc) and rows (axial) of pad `k`'s film grid.
#[must_use]
pub fn film_grid_size(case: &Case, k: usize) -> (usize, usize) {
    let b = &case.bearing;
    let pad = &b.pads[k];
    let m = &case.mesh;
    let r = b.journal_radius_m;
    let (zones_s, zones_z) = orifice_zones(pad, r, m.orifice_elements);
    let cells_s = graded_cells(0.0, pad.arc_rad * r, m.circumferential_elements, &zones_s);
    let half_len = 0.5 * b.length_m;
    let cells_z = if m.half_model {
        graded_cells(0.0, half_len, m.axial_elements / 2, &zones_z)
    } else {
        graded_cells(-half_len, half_len, m.axial_elements, &zones_z)
    };
    let cols = if pad.is_full_circle() { cells_s } else { cells_s + 1 };
    (cols, cells_z + 1)
}

/// The refinement zones of a pad's orifices along the arc (arc length from the leading edge) and axially.
#[must_use]
pub fn orifice_zones(pad: &Pad, journal_radius_m: f64, elements_across: usize) -> (Vec<Refinement>, Vec<Refinement>) {
    let along = |o: &super::Orifice| {
        orifice_zone((o.angle_rad - pad.leading_edge_rad) * journal_radius_m, o.diameter_m, elements_across)
    };
    let axial = |o: &super::Orifice| orifice_zone(o.axial_m, o.diameter_m, elements_across);
    (pad.orifices.iter().map(along).collect(), pad.orifices.iter().map(axial).collect())
}

/// Counts the nodes of every mesh a solve of `case` would build.
#[must_use]
pub fn count(case: &Case) -> NodeCount {
    let film_per_pad: Vec<usize> = (0..case.bearing.pads.len())
        .map(|k| {
            let (cols, rows) = film_grid_size(case, k);
            cols.saturating_mul(rows)
        })
        .collect();
    let thd = case.thermal.model == ThermalModelKind::Thd;
    let layers = case.mesh.pad_radial_elements.max(1);
    let pad_solid = if thd {
        case.bearing
            .pads
            .iter()
            .zip(&film_per_pad)
            .filter(|(p, _)| p.thickness_m > 0.0)
            .map(|(_, &n)| n.saturating_mul(layers + 1))
            .sum()
    } else {
        0
    };
    NodeCount { film_per_pad, pad_solid }
}

/// Refuses a case whose meshes would exceed `mesh.max_nodes`.
///
/// # Errors
/// [`CaseError::NodeBudget`] with the count, the budget and the keys that change them.
pub fn check(case: &Case) -> Result<NodeCount, CaseError> {
    let n = count(case);
    if n.total() > case.mesh.max_nodes {
        let film = n.film();
        let (largest_pad, largest) =
            n.film_per_pad.iter().copied().enumerate().max_by_key(|&(_, v)| v).unwrap_or((0, 0));
        return Err(CaseError::NodeBudget {
            needed: n.total(),
            budget: case.mesh.max_nodes,
            film,
            pad_solid: n.pad_solid,
            largest_pad,
            largest_pad_film: largest,
            orifices: case.bearing.pads.iter().map(|p| p.orifices.len()).sum(),
        });
    }
    Ok(n)
}
