//! Steady heat conduction in one pad (docs/MODEL.md §4).
//!
//! ## Equation and boundary conditions
//! ```text
//! κ_pad ∇²T_pad = 0                                          in the pad
//! −κ_pad ∂T_pad/∂n = H∞ (T_pad − T∞)                          back, leading, trailing faces, axial ends
//! ∂T_pad/∂n = 0                                              mid-plane of a half model (symmetry)
//! film-side face, by the case's exchange model:
//!   BC1   T_pad = T_film                                     (Dirichlet: the film temperature)
//!   BC2   κ_pad ∂T_pad/∂n_in = θ H (T_film − T_pad)
//!   BC3   κ_pad ∂T_pad/∂n_in = θ (2κ/h)(3 T_film − T_j − 2 T_pad)   (Knight & Barrett, energy::Exchange)
//! ```
//!
//! ## Weak form, term by term (Galerkin, test functions N_a of the pad mesh)
//! ```text
//!   ∫ κ_pad ∇T·∇N_a dV                   conduction (fem::hex8, exact curved geometry)
//! + ∫_free H∞ T N_a dA                   convection to the surroundings
//! + ∫_film β T N_a dA − ∫_film γ T_film N_a dA     film-side exchange (BC2/BC3; β, γ from energy::Exchange)
//! = ∫_free H∞ T∞ N_a dA − ∫_film φ T_j N_a dA
//! ```
//! The film-side integrals use the film's own quadrature points and weights (per unit journal area), so the
//! heat the film loses to the pad is exactly the heat the pad receives.
//!
//! The conduction and convection matrices depend only on the mesh and the material, and are built once.
//! With BC1 the pad problem alone is symmetric positive definite: [`PadDirichletSolver`] solves it by
//! sparse Cholesky (fill-reducing AMD ordering, symbolic factorisation once). With BC2/BC3 the pad rows join
//! the film's non-symmetric system (`bearing::thermal_pad`).
//! Units: SI, °C, W.

use crate::fem::hex8::{CylBox, Face};
use crate::fem::{GeneralPattern, Pattern, SolverError, SpdSolver};
use crate::mesh::pad3d::PadMesh;
use crate::physics::reynolds::FilmGeometry;

/// Pad material and surroundings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PadMaterial {
    /// κ_pad [W/(m K)]
    pub conductivity: f64,
    /// H∞ [W/(m² K)]
    pub convection: f64,
    /// T∞ [°C]
    pub ambient_c: f64,
}

/// The pad's conduction problem: mesh and element matrices (built once per geometry).
#[derive(Debug, Clone)]
pub struct PadConduction {
    /// The pad solid, shared with the elastic model ([`crate::bearing::film::model::PadModel::solid`]).
    pub mesh: std::sync::Arc<PadMesh>,
    /// Unit-conductivity element matrices, one per hexahedron.
    conduction: Vec<[[f64; 8]; 8]>,
    /// Unit-coefficient face mass matrices of the free faces (same order as `mesh.free_faces`).
    faces: Vec<[[f64; 8]; 8]>,
}

/// Where the pad rows go in the coupled sparse system.
#[derive(Debug, Clone, Copy)]
pub struct PadLayout {
    /// Unknown index of pad node 0 (pad node k is unknown `offset + k`).
    pub offset: usize,
    /// Group index of hexahedron 0 (groups `hex_groups + h`, 8 nodes each).
    pub hex_groups: usize,
    /// Group index of the coupling group of film element 0 (`[film nodes…, pad face nodes…]`).
    pub coupling_groups: usize,
}

impl PadConduction {
    #[must_use]
    pub fn new(mesh: std::sync::Arc<PadMesh>) -> Self {
        let conduction = mesh.boxes.iter().map(|b| b.conduction(1.0)).collect();
        let faces = mesh.free_faces.iter().map(|&(h, f)| mesh.boxes[h].face_mass(f)).collect();
        Self { mesh, conduction, faces }
    }

    /// Pad node groups (hexahedra) in unknown numbering.
    pub fn hex_groups(&self, offset: usize) -> impl Iterator<Item = [usize; 8]> + '_ {
        self.mesh.hexes.iter().map(move |h| h.map(|k| k + offset))
    }

    /// Adds the conduction and convection rows of every pad node (film-face condition not included) to
    /// `values` and right-hand-side column 0 (`rhs[..]`, the first `pattern.n` entries).
    pub fn assemble_body(
        &self,
        mat: &PadMaterial,
        pattern: &GeneralPattern,
        layout: PadLayout,
        values: &mut [f64],
        rhs: &mut [f64],
    ) {
        for (h, k) in self.conduction.iter().enumerate() {
            let pos = pattern.group_positions(layout.hex_groups + h);
            for a in 0..8 {
                for b in 0..8 {
                    values[pos[8 * a + b]] += mat.conductivity * k[a][b];
                }
            }
        }
        for (&(h, _), m) in self.mesh.free_faces.iter().zip(&self.faces) {
            let pos = pattern.group_positions(layout.hex_groups + h);
            let nodes = self.mesh.hexes[h];
            for a in 0..8 {
                let mut row = 0.0;
                for b in 0..8 {
                    values[pos[8 * a + b]] += mat.convection * m[a][b];
                    row += m[a][b];
                }
                rhs[layout.offset + nodes[a]] += mat.convection * mat.ambient_c * row;
            }
        }
    }

    /// BC1: the film-face rows become `T_pad,i − T_film,i = 0` (replacing what [`Self::assemble_body`] put
    /// there).
    pub fn film_face_dirichlet(
        &self,
        pattern: &GeneralPattern,
        layout: PadLayout,
        values: &mut [f64],
        rhs: &mut [f64],
        columns: usize,
    ) {
        for i in 0..self.mesh.n_film {
            let r = layout.offset + i;
            pattern.set_identity_row(values, r);
            if let Some(p) = pattern.position(r, i) {
                values[p] = -1.0;
            }
            for c in 0..columns {
                rhs[c * pattern.n + r] = 0.0;
            }
        }
    }

    /// BC2/BC3: the film-face exchange `q_pad = γ T_film − β T_pad − φ T_j` integrated with the film's
    /// quadrature. `coef(e, k)` gives (γ, β, φ) at point k of film element e; the T_j term goes to
    /// right-hand-side column 2.
    pub fn film_face_exchange(
        &self,
        geom: &FilmGeometry,
        coef: &dyn Fn(usize, usize) -> (f64, f64, f64),
        pattern: &GeneralPattern,
        layout: PadLayout,
        values: &mut [f64],
        rhs: &mut [f64],
    ) {
        let n = pattern.n;
        for (e, nodes) in geom.elements.iter().enumerate() {
            let pos = pattern.group_positions(layout.coupling_groups + e);
            for (k, q) in geom.qp[e].iter().enumerate() {
                let (gamma, beta, phi) = coef(e, k);
                for a in 0..4 {
                    rhs[2 * n + layout.offset + nodes[a]] -= q.w * phi * q.n[a];
                    for b in 0..4 {
                        let nn = q.w * q.n[a] * q.n[b];
                        values[pos[8 * (4 + a) + 4 + b]] += beta * nn;
                        values[pos[8 * (4 + a) + b]] -= gamma * nn;
                    }
                }
            }
        }
    }

    /// Heat given to the surroundings through the free faces [W] (modelled part), for pad temperatures `t`.
    #[must_use]
    pub fn heat_to_surroundings(&self, mat: &PadMaterial, t: &[f64]) -> f64 {
        let mut q = 0.0;
        for (&(h, _), m) in self.mesh.free_faces.iter().zip(&self.faces) {
            let nodes = self.mesh.hexes[h];
            for a in 0..8 {
                for b in 0..8 {
                    q += mat.convection * m[a][b] * (t[nodes[b]] - mat.ambient_c);
                }
            }
        }
        q
    }

    /// Total area of the free faces [m²] (modelled part).
    #[must_use]
    pub fn free_area(&self) -> f64 {
        self.faces.iter().map(|m| m.iter().flatten().sum::<f64>()).sum()
    }

    /// The element boxes (for post-processing).
    #[must_use]
    pub fn boxes(&self) -> &[CylBox] {
        &self.mesh.boxes
    }

    /// Which faces are free.
    #[must_use]
    pub fn free_faces(&self) -> &[(usize, Face)] {
        &self.mesh.free_faces
    }
}

/// BC1 pad solve: conduction + convection with the film-face nodes fixed, lower-triangular storage. The
/// matrix depends only on the mesh and the material, so its numeric factorisation is kept until the material
/// changes, and one solver serves every pad with the same mesh (identical pads).
pub struct PadDirichletSolver {
    pattern: Pattern,
    solver: SpdSolver,
    /// Value position of entry (a, b) of hexahedron h, `usize::MAX` above the diagonal.
    hex_pos: Vec<[usize; 64]>,
    values: Vec<f64>,
    work: Vec<f64>,
    /// The material the current factorisation is for.
    factored: Option<PadMaterial>,
    /// Numeric factorisations done.
    pub factorizations: usize,
}

impl std::fmt::Debug for PadDirichletSolver {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("PadDirichletSolver").field("n", &self.pattern.n).finish()
    }
}

impl Clone for PadDirichletSolver {
    fn clone(&self) -> Self {
        Self {
            pattern: self.pattern.clone(),
            solver: self.solver.clone(),
            hex_pos: self.hex_pos.clone(),
            values: self.values.clone(),
            work: self.work.clone(),
            factored: self.factored,
            factorizations: self.factorizations,
        }
    }
}

impl PadDirichletSolver {
    /// Pattern and symbolic Cholesky of a pad mesh.
    ///
    /// # Errors
    /// If the symbolic factorisation fails.
    pub fn new(mesh: &PadMesh) -> Result<Self, SolverError> {
        let (pattern, flat) = Pattern::from_groups(mesh.n_nodes(), mesh.hexes.iter().map(|h| &h[..]));
        let hex_pos = flat.chunks_exact(64).map(|c| std::array::from_fn(|k| c[k])).collect();
        let nnz = pattern.nnz();
        let solver = SpdSolver::new(&pattern)?;
        Ok(Self {
            pattern,
            solver,
            hex_pos,
            values: vec![0.0; nnz],
            work: vec![0.0; nnz],
            factored: None,
            factorizations: 0,
        })
    }
}

impl PadMesh {
    /// True if two pad meshes have the same elements up to a rotation about the axis (identical pads; sizes
    /// equal to 1e-9 relative, as grids built from different pad angles differ by round-off).
    #[must_use]
    pub fn same_shape(&self, o: &Self) -> bool {
        let close = |a: f64, b: f64| (a - b).abs() <= 1e-9 * a.abs().max(b.abs());
        self.n_film == o.n_film
            && self.hexes == o.hexes
            && self.free_faces == o.free_faces
            && self.radii.iter().zip(&o.radii).all(|(&a, &b)| close(a, b))
            && self.boxes.iter().zip(&o.boxes).all(|(a, b)| {
                close(a.r0, b.r0)
                    && close(a.dr, b.dr)
                    && close(a.dtheta, b.dtheta)
                    && close(a.z0, b.z0)
                    && close(a.dz, b.dz)
            })
    }
}

impl PadConduction {
    /// BC1: pad temperatures with the film-side face held at `face` (one value per film node).
    ///
    /// # Errors
    /// A failed factorisation (never NaN temperatures).
    pub fn solve_dirichlet(
        &self,
        s: &mut PadDirichletSolver,
        mat: &PadMaterial,
        face: &[f64],
    ) -> Result<Vec<f64>, SolverError> {
        let n = s.pattern.n;
        let refactor = s.factored != Some(*mat);
        if refactor {
            s.values.fill(0.0);
            for (h, k) in self.conduction.iter().enumerate() {
                for a in 0..8 {
                    for b in 0..8 {
                        let p = s.hex_pos[h][8 * a + b];
                        if p != usize::MAX {
                            s.values[p] += mat.conductivity * k[a][b];
                        }
                    }
                }
            }
        }
        let mut rhs = vec![0.0; n];
        for (&(h, _), m) in self.mesh.free_faces.iter().zip(&self.faces) {
            let nodes = self.mesh.hexes[h];
            for a in 0..8 {
                for b in 0..8 {
                    if refactor {
                        let p = s.hex_pos[h][8 * a + b];
                        if p != usize::MAX {
                            s.values[p] += mat.convection * m[a][b];
                        }
                    }
                    rhs[nodes[a]] += mat.convection * mat.ambient_c * m[a][b];
                }
            }
        }
        // Move the known face temperatures to the right-hand side, then fix those rows.
        let mut known = vec![0.0; n];
        known[..face.len()].copy_from_slice(face);
        let mut k_known = vec![0.0; n];
        s.pattern.sym_matvec(&s.values, &known, &mut k_known);
        let fixed: Vec<bool> = (0..n).map(|i| i < self.mesh.n_film).collect();
        for i in 0..n {
            rhs[i] = if fixed[i] { known[i] } else { rhs[i] - k_known[i] };
        }
        if refactor {
            s.factored = None;
            s.pattern.fix_rows(&s.values, &fixed, &mut s.work);
            s.solver.factor(&s.pattern, &s.work)?;
            s.factored = Some(*mat);
            s.factorizations += 1;
        }
        s.solver.solve_in_place(&mut rhs);
        if rhs.iter().any(|v| !v.is_finite()) {
            return Err(SolverError::NotPositiveDefinite);
        }
        Ok(rhs)
    }
}
