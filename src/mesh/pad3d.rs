//! The pad solid mesh: the film grid extruded through the pad thickness.
//!
//! Element choice: 8-node trilinear hexahedra that are boxes in cylindrical coordinates (r, θ, z)
//! ([`crate::fem::hex8`]); the thesis used 20-node serendipity bricks. Extruding the film grid makes the pad's
//! film-side face coincide node for node with the film mesh (node `i` of layer 0 *is* film node `i`), so the
//! film–pad coupling needs no interpolation, and the curved pad is represented exactly.
//!
//! Layout: layer k (k = 0 on the film side, r = Rp, up to k = n_r on the back, r = Rp + t) holds a copy of the
//! film grid's nodes; pad node id = `k · n_film + film node id`. Element layers are graded towards the film
//! face (geometric ratio [`RADIAL_GROWTH`] from the back to the face), where the temperature gradients are
//! largest. Hexahedron `l · n_elem + e` sits on film element `e` in layer `l`, its nodes ordered as in
//! [`crate::fem::hex8::NODES`] (film element nodes on the inner face, then the same on the outer face).
//!
//! Faces: the film face (r = Rp) carries the film–pad condition (BC1/BC2/BC3); the back (r = Rp + t), the
//! leading and trailing faces and the axial ends are free faces (convection to the surroundings); with a
//! half model the mid-plane z = 0 is a symmetry plane (adiabatic). The injection hole through the pad and
//! the pivot contact are not part of the conduction model.

use crate::fem::hex8::{CylBox, Face};
use crate::mesh::grid::PadGrid;

/// Ratio of neighbouring layer thicknesses (outer / inner).
pub const RADIAL_GROWTH: f64 = 1.3;

/// The mesh of one pad.
#[derive(Debug, Clone)]
pub struct PadMesh {
    /// Nodes per layer (= film nodes).
    pub n_film: usize,
    /// Element layers through the thickness.
    pub layers: usize,
    /// Layer radii, film face first [m].
    pub radii: Vec<f64>,
    pub hexes: Vec<[usize; 8]>,
    pub boxes: Vec<CylBox>,
    /// Free (convective) faces: (hexahedron, face).
    pub free_faces: Vec<(usize, Face)>,
}

impl PadMesh {
    /// Extrudes a (non-periodic) film grid of a pad whose bore radius is `bore_radius` and thickness
    /// `thickness`, with `layers` element layers. `theta_le` is the pad's leading-edge angle and `radius` the
    /// journal radius of the grid's arc-length coordinate (θ = θ_le + s/R).
    #[must_use]
    #[allow(clippy::cast_precision_loss)]
    pub fn extrude(
        grid: &PadGrid,
        radius: f64,
        theta_le: f64,
        bore_radius: f64,
        thickness: f64,
        layers: usize,
    ) -> Self {
        let layers = layers.max(1);
        let n_film = grid.n_nodes();
        // Graded layer thicknesses: d_k ∝ g^k, k = 0 at the film face.
        let weights: Vec<f64> = (0..layers).map(|k| RADIAL_GROWTH.powi(i32::try_from(k).unwrap_or(i32::MAX))).collect();
        let total: f64 = weights.iter().sum();
        let mut radii = Vec::with_capacity(layers + 1);
        radii.push(bore_radius);
        let mut r = bore_radius;
        for w in &weights {
            r += thickness * w / total;
            radii.push(r);
        }
        radii[layers] = bore_radius + thickness;
        let ncs = grid.s.len() - 1;
        let ncz = grid.z.len() - 1;
        let n_elem = ncs * ncz;
        let mut hexes = Vec::with_capacity(n_elem * layers);
        let mut boxes = Vec::with_capacity(n_elem * layers);
        let mut free_faces = Vec::new();
        for l in 0..layers {
            for (e, (i, j)) in grid.elements().enumerate() {
                let f = grid.element_nodes(i, j);
                let (lo, hi) = (l * n_film, (l + 1) * n_film);
                hexes.push([f[0] + lo, f[1] + lo, f[2] + lo, f[3] + lo, f[0] + hi, f[1] + hi, f[2] + hi, f[3] + hi]);
                boxes.push(CylBox {
                    r0: radii[l],
                    dr: radii[l + 1] - radii[l],
                    theta0: theta_le + grid.s[i] / radius,
                    dtheta: (grid.s[i + 1] - grid.s[i]) / radius,
                    z0: grid.z[j],
                    dz: grid.z[j + 1] - grid.z[j],
                });
                let h = l * n_elem + e;
                if l == layers - 1 {
                    free_faces.push((h, Face::Outer));
                }
                if i == 0 {
                    free_faces.push((h, Face::ThetaMin));
                }
                if i == ncs - 1 {
                    free_faces.push((h, Face::ThetaMax));
                }
                if j == 0 && !grid.half {
                    free_faces.push((h, Face::ZMin));
                }
                if j == ncz - 1 {
                    free_faces.push((h, Face::ZMax));
                }
            }
        }
        Self { n_film, layers, radii, hexes, boxes, free_faces }
    }

    /// Number of pad nodes.
    #[must_use]
    pub fn n_nodes(&self) -> usize {
        self.n_film * (self.layers + 1)
    }

    /// Pad volume [m³] (of the modelled part).
    #[must_use]
    pub fn volume(&self) -> f64 {
        self.boxes.iter().map(CylBox::volume).sum()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn extruded_mesh_is_a_sector_of_an_annulus() {
        let grid = PadGrid { s: vec![0.0, 0.01, 0.03, 0.05], z: vec![0.0, 0.01, 0.02], periodic: false, half: true };
        let (r, rp, t) = (0.05, 0.0501, 0.01);
        let m = PadMesh::extrude(&grid, r, 0.2, rp, t, 4);
        assert_eq!(m.n_nodes(), 12 * 5);
        assert_eq!(m.hexes.len(), 6 * 4);
        assert!((m.radii[0] - rp).abs() < 1e-15 && (m.radii[4] - rp - t).abs() < 1e-15);
        // Layers thicken away from the film face.
        assert!(m.radii[1] - m.radii[0] < m.radii[4] - m.radii[3]);
        let beta = 0.05 / r;
        let exact = 0.5 * beta * ((rp + t).powi(2) - rp * rp) * 0.02;
        assert!((m.volume() - exact).abs() < 1e-12 * exact);
        // Free faces: back (6), leading (2 × 4), trailing (2 × 4), one axial end (3 × 4); the mid-plane is a
        // symmetry plane.
        assert_eq!(m.free_faces.len(), 6 + 8 + 8 + 12);
        // Film node i is pad node i.
        assert_eq!(m.hexes[0][..4], grid.element_nodes(0, 0));
    }
}
