//! The pad solid of the thermal growth (TEHD, docs/MODEL.md §5–§7; used by [`crate::bearing::thermal::growth`]): the pad's 3-D
//! temperature strains it, and its film-face radial displacement opens the film.
//!
//! ## Equations
//! ```text
//! K u = f_th,  f_th = ∫ Bᵀ D α_p (T − T_ref) m dV   pad solid (physics::pad_elastic), m = [1 1 1 0 0 0]ᵀ,
//!                                                  supported statically determinately at its pivot line
//! u_p = u · e_r on the film face                   positive away from the journal (opens the film)
//! ```
//! `T` is the pad's 3-D temperature on the pad mesh (the thermal model's, same mesh as the elastic one).
//!
//! Supports: the pivot line (the back-face node column nearest the pivot) is pinned in x and y; u_z = 0 on
//! the mid-plane of a half model (else at the pivot line's node nearest z = 0); one in-plane component of the
//! film-face node in that column, at the mid-plane, is fixed. These only remove rigid motions, so the pad
//! expands freely (a uniform temperature rise is stress-free: a similarity about the pivot line). The last
//! support fixes the pad's rotation about the pivot line, which is its tilt coordinate (the equilibrium
//! solves the tilt); the rotation a Cartesian component leaves is removed afterwards, so that the node under
//! the pivot moves only along the line through it (a uniform rise then gives the similarity exactly). Clamping the whole
//! contact patch instead would restrain the back face's expansion and bend the pad (by about a third of the
//! thickness growth on Fillon's pad). When no node column lies on the pivot, the pad is pinned at the nearest
//! one: its thermal growth then carries the pivot's offset from it times the local strain (below α ΔT times
//! half a column width).
//!
//! Identical pads (same mesh shape up to rotation, pivot position within the arc and material) share one
//! factorised stiffness: the radial component of the displacement does not depend on the pad's angle.
//!
//! Below the reference fidelity the growth solid takes every second element layer of the pad mesh (from four
//! even layers up, [`growth_layer_step`]); the pad conduction keeps all. The temperatures of the kept node
//! layers load it, and the displacement of the skipped node layers is interpolated linearly in r (the
//! trilinear elements' own interpolation). Its factorisation then has 3/5 of the unknowns. Measured on the
//! compressor bearing's TEHD at the standard film mesh against 8 pad layers with every layer in the solid
//! (`cargo xtask bench --only flex`, docs/PERFORMANCE.md): 4 layers with the merged growth solid err by 0.05 % in
//! ε and h_min and 0.12 % in C, 4 layers with all by 0.04 %, 0.03 % and 0.11 % — a thirtieth of the standard
//! film mesh's own error (ε 1.56 %), for 0.25 s less (growth set-up and steps). Fillon's bearing A (TEHD,
//! 4000 rpm, standard): h_min 23.580 µm merged, 23.576 µm with all 4 layers, 23.575 µm with 8; pad T_max
//! 76.631 / 76.634 / 76.635 °C (measured before the rupture was placed between nodes). On Fillon's pad under a conducted temperature field alone the film-face growth
//! of 2 layers differs from that of 8 by 15 % of its largest value at worst (rms 3.6 %), that of 4 layers by 5
//! % (rms 1.1 %) (test `every_second_layer_against_all_layers` compares 2 with 4); in the coupled solve the
//! film closes much of that difference (above).

use crate::fem::solid8::{Elastic, Formulation};
use crate::fem::SpdSolver;
use crate::mesh::pad3d::PadMesh;
use crate::model::Fidelity;
use crate::physics::pad_elastic::{ElasticError, ElasticSystem, Solid, Supports, ThermalLoad};

/// The element layers of the pad mesh that make one layer of the growth solid: 2 from four (even) layers up
/// below the reference fidelity (the reference keeps every layer: it is what the levels are measured
/// against); else 1.
#[must_use]
pub fn growth_layer_step(fidelity: Fidelity, layers: usize) -> usize {
    if fidelity != Fidelity::Reference && layers >= 4 && layers % 2 == 0 {
        2
    } else {
        1
    }
}

/// `step` if it divides the mesh's layers, else 1.
pub(super) fn effective_step(mesh: &PadMesh, step: usize) -> usize {
    if step > 1 && mesh.layers % step == 0 {
        step
    } else {
        1
    }
}

/// The pad mesh with every `step` element layers merged into one (`step` divides the layers): node layer l of
/// the result is node layer `step · l` of `mesh`.
fn merged_layers(mesh: &PadMesh, step: usize) -> PadMesh {
    if step <= 1 {
        return mesh.clone();
    }
    let (nf, layers) = (mesh.n_film, mesh.layers / step);
    let n_elem = mesh.hexes.len() / mesh.layers;
    let radii: Vec<f64> = mesh.radii.iter().step_by(step).copied().collect();
    let mut hexes = Vec::with_capacity(n_elem * layers);
    let mut boxes = Vec::with_capacity(n_elem * layers);
    for l in 0..layers {
        for e in 0..n_elem {
            let (h, b) = (mesh.hexes[step * l * n_elem + e], mesh.boxes[step * l * n_elem + e]);
            let lo = step * l * nf;
            hexes.push(std::array::from_fn(|a| h[a % 4] - lo + if a < 4 { l * nf } else { (l + 1) * nf }));
            boxes.push(crate::fem::hex8::CylBox { r0: radii[l], dr: radii[l + 1] - radii[l], ..b });
        }
    }
    // Free faces of the merged layers: the sides of the layers kept, the back of the last one.
    let free_faces = mesh
        .free_faces
        .iter()
        .filter_map(|&(h, f)| {
            let (l, e) = (h / n_elem, h % n_elem);
            match f {
                crate::fem::hex8::Face::Outer => (l == mesh.layers - 1).then_some(((layers - 1) * n_elem + e, f)),
                _ => (l % step == 0).then_some((l / step * n_elem + e, f)),
            }
        })
        .collect();
    PadMesh { n_film: nf, layers, radii, hexes, boxes, free_faces }
}

/// A factorised pad solid, supported statically determinately at its pivot line (module documentation).
pub(super) struct GrowthSolver {
    solid: Solid,
    system: ElasticSystem,
    solver: SpdSolver,
    /// Thermal-load operator (built once: each outer iteration's load is a product).
    load: ThermalLoad,
    pub(super) material: Elastic,
    /// Pivot position within the arc [rad] (sharing key with the mesh shape and material).
    pub(super) pivot_from_le: f64,
    /// The pad mesh (temperatures and displacements live on its nodes) and the growth solid's layer step
    /// ([`growth_layer_step`]; the solid is `merged_layers(mesh, step)`).
    pub(super) mesh: std::sync::Arc<PadMesh>,
    pub(super) step: usize,
    /// The pinned pivot line (x, y) [m] and the film-face node whose tangential displacement the rotation
    /// support sets to zero.
    pin: [f64; 2],
    anchor: usize,
}

impl GrowthSolver {
    pub(super) fn new(
        mesh: std::sync::Arc<PadMesh>,
        step: usize,
        pivot_rad: f64,
        pivot_from_le: f64,
        material: Elastic,
        half: bool,
    ) -> Result<Self, ElasticError> {
        let step = effective_step(&mesh, step);
        let coarse = merged_layers(&mesh, step);
        let solid = Solid::from_pad(&coarse);
        let (fixed, pin, anchor) = determinate_supports(&coarse, &solid, pivot_rad, half);
        let supports = Supports::new(&solid, &fixed, &[], [0.0, 0.0]);
        let (mut system, load) =
            ElasticSystem::assemble_with_thermal_load(&solid, &material, Formulation::Incompatible, supports)?;
        system.order_as_pad(&solid);
        let mut solver = SpdSolver::new(&system.pattern).map_err(ElasticError::Factor)?;
        solver.factor(&system.pattern, &system.stiffness).map_err(ElasticError::Factor)?;
        Ok(Self { solid, system, solver, load, material, pivot_from_le, mesh, step, pin, anchor })
    }

    /// Reduced unknowns of the solid.
    pub(super) fn unknowns(&self) -> usize {
        self.system.supports.len()
    }

    /// The reduced thermal load of the temperature rise `dt` (all pad mesh nodes) [K]: the growth solid's
    /// nodes are every `step`-th node layer of the mesh, and take their temperatures. (Restricting the pad
    /// mesh's own nodal loads instead, the transpose of the interpolation in r, moved the compressor bearing's
    /// growth as much from the all-layer one, moved ε 4 times as much and cost 30 ms more set-up.)
    pub(super) fn reduced_load(&self, alpha: f64, dt: &[f64]) -> Vec<f64> {
        let nf = self.mesh.n_film;
        let kept: Vec<f64> = (0..self.solid.n_nodes()).map(|i| dt[(i / nf) * self.step * nf + i % nf]).collect();
        self.system.supports.reduce(&self.load.forces(&self.solid, alpha, &kept))
    }

    /// The pad's displacements for several reduced loads at once (column-major, one column per pad): one
    /// pass of the factor serves them all.
    pub(super) fn displacements(&mut self, mut loads: Vec<f64>) -> Vec<PadGrowth> {
        let n = self.unknowns();
        self.solver.solve_many_in_place(&mut loads, n);
        loads.chunks_exact(n).map(|q| self.displacement(q)).collect()
    }

    /// The pad's displacement from the solved reduced unknowns `q`.
    fn displacement(&self, q: &[f64]) -> PadGrowth {
        let u = self.system.supports.expand(q);
        // Remove the rotation δ about the pivot line that the Cartesian rotation support leaves: the anchor
        // node (under the pivot line) then has no displacement across the line–anchor direction.
        let p = self.pin;
        let xa = self.solid.nodes[self.anchor];
        let (d, len) = ([xa[0] - p[0], xa[1] - p[1]], (xa[0] - p[0]).hypot(xa[1] - p[1]));
        let across = [-d[1] / len, d[0] / len];
        let delta = (u[3 * self.anchor] * across[0] + u[3 * self.anchor + 1] * across[1]) / len;
        // u − δ ẑ × (x − P), in polar components (u_r, u_θ, u_z) at every node.
        let nodal_polar_m: Vec<f64> = (0..self.solid.n_nodes())
            .flat_map(|i| {
                let x = self.solid.nodes[i];
                let (s, c) = x[1].atan2(x[0]).sin_cos();
                let ux = u[3 * i] + delta * (x[1] - p[1]);
                let uy = u[3 * i + 1] - delta * (x[0] - p[0]);
                [ux * c + uy * s, -ux * s + uy * c, u[3 * i + 2]]
            })
            .collect();
        let film_m = (0..self.mesh.n_film).map(|i| nodal_polar_m[3 * i]).collect();
        PadGrowth { film_m, nodal_polar_m: self.on_mesh(&nodal_polar_m) }
    }

    /// A nodal field of the solid (3 components per node) on every node of the pad mesh: the node layers the
    /// solid skipped by linear interpolation in r between the kept ones around them.
    fn on_mesh(&self, field: &[f64]) -> Vec<f64> {
        if self.step == 1 {
            return field.to_vec();
        }
        let (nf, r) = (self.mesh.n_film, &self.mesh.radii);
        let mut out = Vec::with_capacity(3 * self.mesh.n_nodes());
        for layer in 0..=self.mesh.layers {
            let (l, rem) = (layer / self.step, layer % self.step);
            let below = &field[3 * l * nf..3 * (l + 1) * nf];
            if rem == 0 {
                out.extend_from_slice(below);
                continue;
            }
            let above = &field[3 * (l + 1) * nf..3 * (l + 2) * nf];
            let (r0, r1) = (r[l * self.step], r[(l + 1) * self.step]);
            let w = (r[layer] - r0) / (r1 - r0);
            out.extend(below.iter().zip(above).map(|(a, b)| a + w * (b - a)));
        }
        out
    }
}

/// The thermal displacement of one pad solid.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct PadGrowth {
    /// Radial displacement of the film face at each film node [m] (positive away from the journal).
    pub film_m: Vec<f64>,
    /// (u_r, u_θ, u_z) at every pad node (pad node = layer · film nodes + film node, film face first) [m].
    pub nodal_polar_m: Vec<f64>,
}

/// Pivot line pinned in x, y; u_z on the mid-plane (half model) or at one pivot-line node; one in-plane
/// component of the film-face node under the pivot line at the mid-plane (the rotation about the line).
/// Returns the fixed components, the pinned line (x, y) and the film-face anchor node.
fn determinate_supports(
    mesh: &PadMesh,
    solid: &Solid,
    pivot_rad: f64,
    half: bool,
) -> (Vec<(usize, usize)>, [f64; 2], usize) {
    let angle = |n: usize| {
        let x = solid.nodes[n];
        ((x[1].atan2(x[0]) - pivot_rad + std::f64::consts::PI).rem_euclid(std::f64::consts::TAU) - std::f64::consts::PI)
            .abs()
    };
    let back = mesh.layers * mesh.n_film..mesh.n_nodes();
    let nearest = back.clone().map(angle).fold(f64::INFINITY, f64::min);
    let line: Vec<usize> = back.filter(|&n| angle(n) <= nearest + 1e-9).collect();
    let mid = |nodes: &mut dyn Iterator<Item = usize>| {
        nodes.min_by(|&a, &b| solid.nodes[a][2].abs().total_cmp(&solid.nodes[b][2].abs()))
    };
    let mut fixed: Vec<(usize, usize)> = line.iter().flat_map(|&n| [(n, 0), (n, 1)]).collect();
    if half {
        fixed.extend((0..solid.n_nodes()).filter(|&n| solid.nodes[n][2].abs() < 1e-12).map(|n| (n, 2)));
    } else if let Some(n) = mid(&mut line.iter().copied()) {
        fixed.push((n, 2));
    }
    // The film-face node under the pivot line (same column), at the mid-plane: its component closest to the
    // tangent stops the rotation about the line.
    let anchor = mid(&mut (0..mesh.n_film).filter(|&n| angle(n) <= nearest + 1e-9)).unwrap_or(0);
    let c = if pivot_rad.sin().abs() >= pivot_rad.cos().abs() { 0 } else { 1 };
    fixed.push((anchor, c));
    let pin = line.first().map_or([0.0, 0.0], |&n| [solid.nodes[n][0], solid.nodes[n][1]]);
    (fixed, pin, anchor)
}
