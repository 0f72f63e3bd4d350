//! Linear elasticity of a pad solid (docs/MODEL.md §5): stiffness and mass on the pad's 3-D mesh, supports, and
//! static solutions.
//!
//! ## Equation and weak form
//! ```text
//! ∇·σ + f = ρ ü,   σ = D ε(u)                      in the pad (small strain, isotropic E, ν)
//! ∫ ε(w)ᵀ D ε(u) dV + ∫ ρ w·ü dV = ∫ w·f dV + ∫_Γ w·t dA     for every admissible w
//! ```
//! discretised by [`crate::fem::solid8`] (hexahedra with incompatible modes, which do not lock in bending),
//! giving `K u = f` and `K v = ω² M v`.
//!
//! ## The solid and its supports
//! [`Solid`] is the pad mesh in Cartesian coordinates (bearing frame, z axial). Its nodes are those of
//! [`PadMesh`] (node `i` of layer 0 is film node `i`), so displacements on the film face are film fields
//! without interpolation. Supports ([`Supports`]) tie each nodal component to the reduced unknowns:
//! - fixed (clamped test beams; `u_z = 0` on the mid-plane of a half model),
//! - rigid rotation about an axial line through a point P: the pivot patch moves as `u = δ ẑ × (x − P)`, with
//!   one shared unknown δ (the pad's tilt) — docs/MODEL.md §5's pivot condition,
//! - free.
//!
//! The reduced matrices are `Tᵀ K T`, `Tᵀ M T` with `u = T q`, assembled directly into one sparse pattern
//! (lower triangle), so the Cholesky factorisation and the eigen-solution ([`crate::fem::eigen`]) work on
//! them as they are. Units: SI.

use crate::fem::eigen::{self, EigenError, EigenPairs, EigenParams};
use crate::fem::hex8::NODES;
use crate::fem::solid8::{Elastic, Formulation};
use crate::fem::{Pattern, SolverError, SpdSolver};
use crate::mesh::pad3d::PadMesh;

mod dissection;
mod shapes;

use dissection::pad_dissection;
use shapes::ElementShapes;

/// A hexahedral solid in Cartesian coordinates.
#[derive(Debug, Clone, PartialEq)]
pub struct Solid {
    /// Node positions (x, y, z) [m].
    pub nodes: Vec<[f64; 3]>,
    pub hexes: Vec<[usize; 8]>,
}

impl Solid {
    /// The Cartesian solid of a pad mesh (same node numbering). Element faces become bilinear patches
    /// through the exact corner positions of the cylindrical boxes.
    #[must_use]
    pub fn from_pad(mesh: &PadMesh) -> Self {
        let mut nodes = vec![[0.0; 3]; mesh.n_nodes()];
        for (hex, b) in mesh.hexes.iter().zip(&mesh.boxes) {
            for (a, &(xi, eta, zeta)) in NODES.iter().enumerate() {
                let r = b.r0 + 0.5 * (xi + 1.0) * b.dr;
                let theta = b.theta0 + 0.5 * (eta + 1.0) * b.dtheta;
                nodes[hex[a]] = [r * theta.cos(), r * theta.sin(), b.z0 + 0.5 * (zeta + 1.0) * b.dz];
            }
        }
        Self { nodes, hexes: mesh.hexes.clone() }
    }

    #[must_use]
    pub fn n_nodes(&self) -> usize {
        self.nodes.len()
    }

    fn element_nodes(&self, e: usize) -> [[f64; 3]; 8] {
        self.hexes[e].map(|n| self.nodes[n])
    }
}

/// How each nodal displacement component maps to the reduced unknowns.
#[derive(Debug, Clone, PartialEq)]
pub struct Supports {
    /// Per node component `3 node + c`: `Some((unknown, coefficient))` or `None` (fixed at zero).
    links: Vec<Option<(usize, f64)>>,
    n: usize,
    /// The rigid-rotation unknown, if there is one.
    pub rotation: Option<usize>,
}

impl Supports {
    /// Every component free except the given fixed ones (node, component); the nodes in `rotating` move as
    /// a rigid rotation about the axial line through `about` (x, y) with one shared unknown (numbered last).
    #[must_use]
    pub fn new(solid: &Solid, fixed: &[(usize, usize)], rotating: &[usize], about: [f64; 2]) -> Self {
        let n_comp = 3 * solid.n_nodes();
        let mut kind = vec![0u8; n_comp]; // 0 free, 1 fixed, 2 rotating
        for &(node, c) in fixed {
            kind[3 * node + c] = 1;
        }
        for &node in rotating {
            for c in 0..3 {
                kind[3 * node + c] = 2;
            }
        }
        let mut links = vec![None; n_comp];
        let mut n = 0;
        for (i, k) in kind.iter().enumerate() {
            if *k == 0 {
                links[i] = Some((n, 1.0));
                n += 1;
            }
        }
        let rotation = (!rotating.is_empty()).then_some(n);
        if let Some(r) = rotation {
            n += 1;
            for &node in rotating {
                let x = solid.nodes[node];
                // u = δ ẑ × (x − P) = δ (−(y − P_y), x − P_x, 0)
                links[3 * node] = Some((r, -(x[1] - about[1])));
                links[3 * node + 1] = Some((r, x[0] - about[0]));
                links[3 * node + 2] = None;
            }
        }
        Self { links, n, rotation }
    }

    /// Number of reduced unknowns.
    #[must_use]
    pub fn len(&self) -> usize {
        self.n
    }

    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.n == 0
    }

    /// Nodal displacements `u = T q`.
    #[must_use]
    pub fn expand(&self, q: &[f64]) -> Vec<f64> {
        self.links.iter().map(|l| l.map_or(0.0, |(i, c)| c * q[i])).collect()
    }

    /// Reduced load `Tᵀ f` of nodal forces.
    #[must_use]
    pub fn reduce(&self, f: &[f64]) -> Vec<f64> {
        let mut r = vec![0.0; self.n];
        for (l, fv) in self.links.iter().zip(f) {
            if let Some((i, c)) = l {
                r[*i] += c * fv;
            }
        }
        r
    }
}

/// Failure of the elastic model.
#[derive(Debug, Clone, PartialEq, thiserror::Error, serde::Serialize, serde::Deserialize)]
pub enum ElasticError {
    #[error("element {element} is inverted or degenerate")]
    Element { element: usize },
    #[error("the supported solid has no unknowns")]
    Empty,
    #[error("static solve: {0} (is the solid supported against rigid motion?)")]
    Factor(SolverError),
    #[error(transparent)]
    Eigen(#[from] EigenError),
}

/// The thermal-load operator of a solid, built with its stiffness ([`ElasticSystem::assemble_with_thermal_load`]):
/// each element's condensed load per unit α and unit nodal temperature rise
/// ([`crate::fem::solid8::element_matrices_and_thermal`]), so that a new temperature field costs one 24 × 8
/// product per element instead of an element integration.
#[derive(Debug, Clone)]
pub struct ThermalLoad {
    /// The operator of each distinct element shape ([`ElementShapes`]), and each element's shape and turn
    /// (cos, sin) from it.
    distinct: Vec<nalgebra::SMatrix<f64, 24, 8>>,
    shape_of: Vec<(usize, [f64; 2])>,
}

impl ThermalLoad {
    /// Equivalent nodal forces `∫ Bᵀ D α ΔT m dV` of the nodal temperature rise `dt` (all nodes) [K].
    #[must_use]
    pub fn forces(&self, solid: &Solid, alpha: f64, dt: &[f64]) -> Vec<f64> {
        let mut f = vec![0.0; 3 * solid.n_nodes()];
        for (&(i, [c, s]), hex) in self.shape_of.iter().zip(&solid.hexes) {
            let t = nalgebra::SVector::<f64, 8>::from_fn(|a, _| dt[hex[a]]);
            let fe = self.distinct[i] * t * alpha;
            for (a, &n) in hex.iter().enumerate() {
                let (fx, fy) = (fe[3 * a], fe[3 * a + 1]);
                f[3 * n] += c * fx - s * fy;
                f[3 * n + 1] += s * fx + c * fy;
                f[3 * n + 2] += fe[3 * a + 2];
            }
        }
        f
    }
}

/// Reduced stiffness and mass of a supported solid, on one sparse pattern.
#[derive(Debug, Clone)]
pub struct ElasticSystem {
    pub supports: Supports,
    pub pattern: Pattern,
    /// Lower triangle of `Tᵀ K T` [N/m].
    pub stiffness: Vec<f64>,
    /// Lower triangle of `Tᵀ M T` [kg].
    pub mass: Vec<f64>,
}

impl ElasticSystem {
    /// Assembles the reduced stiffness and mass.
    ///
    /// # Errors
    /// [`ElasticError::Element`] for an inverted element, [`ElasticError::Empty`] if nothing is free.
    pub fn assemble(
        solid: &Solid,
        material: &Elastic,
        form: Formulation,
        supports: Supports,
    ) -> Result<Self, ElasticError> {
        Self::assemble_with_thermal_load(solid, material, form, supports).map(|(system, _)| system)
    }

    /// [`Self::assemble`] and the solid's [`ThermalLoad`] from the same element integrations.
    ///
    /// # Errors
    /// As [`Self::assemble`].
    pub fn assemble_with_thermal_load(
        solid: &Solid,
        material: &Elastic,
        form: Formulation,
        supports: Supports,
    ) -> Result<(Self, ThermalLoad), ElasticError> {
        if supports.is_empty() {
            return Err(ElasticError::Empty);
        }
        // Per element: (local component, unknown, coefficient) of its linked components.
        let linked: Vec<Vec<(usize, usize, f64)>> = solid
            .hexes
            .iter()
            .map(|hex| (0..24).filter_map(|l| supports.links[3 * hex[l / 3] + l % 3].map(|(i, c)| (l, i, c))).collect())
            .collect();
        let groups: Vec<Vec<usize>> = linked.iter().map(|g| g.iter().map(|t| t.1).collect()).collect();
        let (pattern, scatter) = Pattern::from_groups(supports.len(), groups.iter().map(Vec::as_slice));
        let mut stiffness = vec![0.0; pattern.nnz()];
        let mut mass = vec![0.0; pattern.nnz()];
        let mut offset = 0;
        let mut shapes = ElementShapes::default();
        let mut shape_of = Vec::with_capacity(solid.hexes.len());
        for (e, g) in linked.iter().enumerate() {
            let (shape, turn) =
                shapes.element(&solid.element_nodes(e), material, form).ok_or(ElasticError::Element { element: e })?;
            shape_of.push((shape, turn));
            // The mass of a turned copy is the same (each nodal block is a multiple of the identity).
            let (ke, me) = (shapes.stiffness(shape, turn), &shapes.shapes[shape].1);
            let len = g.len();
            for (a, &(la, _, ca)) in g.iter().enumerate() {
                for (b, &(lb, _, cb)) in g.iter().enumerate() {
                    let pos = scatter[offset + a * len + b];
                    if pos != usize::MAX {
                        stiffness[pos] += ca * cb * ke[(la, lb)];
                        mass[pos] += ca * cb * me[(la, lb)];
                    }
                }
            }
            offset += len * len;
        }
        Ok((
            Self { supports, pattern, stiffness, mass },
            ThermalLoad { distinct: shapes.shapes.into_iter().map(|s| s.2).collect(), shape_of },
        ))
    }

    /// Orders the unknowns of a pad solid (cylindrical element boxes about the z axis) for the Cholesky
    /// factorisation by nested dissection ([`pad_dissection`]); unknowns not tied to one node (a rigid
    /// rotation) come last.
    pub fn order_as_pad(&mut self, solid: &Solid) {
        let mut order = Vec::with_capacity(self.supports.len());
        let mut placed = vec![false; self.supports.len()];
        for node in pad_dissection(solid) {
            for c in 0..3 {
                if let Some((i, _)) = self.supports.links[3 * node + c] {
                    if !placed[i] && self.supports.rotation != Some(i) {
                        placed[i] = true;
                        order.push(i);
                    }
                }
            }
        }
        order.extend((0..placed.len()).filter(|&i| !placed[i]));
        self.pattern.ordering = Some(order);
    }

    /// Nodal displacements under nodal forces `f` (3 per node) [m].
    ///
    /// # Errors
    /// [`ElasticError::Factor`] if the supports leave a rigid motion free.
    pub fn static_solve(&self, f: &[f64]) -> Result<Vec<f64>, ElasticError> {
        let mut solver = SpdSolver::new(&self.pattern).map_err(ElasticError::Factor)?;
        solver.factor(&self.pattern, &self.stiffness).map_err(ElasticError::Factor)?;
        let mut q = self.supports.reduce(f);
        solver.solve_in_place(&mut q);
        Ok(self.supports.expand(&q))
    }

    /// The `wanted` lowest modes `K v = ω² M v` (reduced unknowns; expand with [`Supports::expand`]).
    /// The shift is a tiny negative fraction of the largest diagonal ratio, so free rigid motions (zero
    /// eigenvalues) are allowed.
    ///
    /// # Errors
    /// [`ElasticError::Eigen`].
    pub fn modes(&self, wanted: usize) -> Result<EigenPairs, ElasticError> {
        let scale = self.pattern.diag.iter().map(|&d| self.stiffness[d] / self.mass[d]).fold(0.0, f64::max);
        Ok(eigen::lowest(&self.pattern, &self.stiffness, &self.mass, wanted, -1e-8 * scale, EigenParams::default())?)
    }
}

#[cfg(test)]
mod tests;
