//! The modified Reynolds equation on one pad, with injection and cavitation.
//!
//! ## Equation
//! With `s = R (θ − θ_le)` along the journal surface, `z` axial, `U = Ω R`:
//!
//! ```text
//! ∂/∂s (h³/µ ∂p/∂s) + ∂/∂z (h³/µ ∂p/∂z) = 6 U ∂h/∂s + 12 ∂h/∂t + Σ_orifices 3 g (p − p_inj) / (µ_inj l0)
//! ```
//!
//! with `p = 0` (ambient) on the leading and trailing edges and the axial ends, `∂p/∂z = 0` on the symmetry
//! plane of a half model, and periodicity in `s` for a 360° sector.
//!
//! ## Weak form (bilinear rectangles, 2×2 Gauss), term by term
//! For every test function `N_i` vanishing on the Dirichlet boundary:
//!
//! ```text
//!   ∫ h³/µ ∇p·∇N_i dA                 (diffusion: Poiseuille flow)
//! + ∫ 3 g p N_i / (µ_inj l0) dA       (orifice: flow out of the film through the capillary)
//! = ∫ 6 U h ∂N_i/∂s dA                (Couette wedge, integrated by parts: −∫6U ∂h/∂s N_i)
//! − ∫ 12 ∂h/∂t N_i dA                 (squeeze)
//! + ∫ 3 g p_inj N_i / (µ_inj l0) dA   (orifice supply)
//! ```
//!
//! The left-hand side is symmetric positive definite, so a sparse Cholesky factorisation is used; its
//! symbolic part is built once per mesh. The orifice weight `g` is integrated with sub-cell quadrature on the
//! elements the hole touches (it has a kink at the hole's edge).
//!
//! ## Cavitation
//! - Gümbel: solve, then clip negative pressures to zero.
//! - Reynolds (Swift–Stieber): the linear complementarity problem `p ≥ 0`, `λ = A p − b ≥ 0`, `p·λ = 0`,
//!   solved exactly by a primal–dual active-set method (each step fixes the cavitated nodes at p = 0 and
//!   refactors numerically; warm-started from the previous active set).
//!
//! ## Outputs and conventions
//! - Film thickness is linear in the generalised coordinates q: `h = h0(θ, z) + Σ_k q_k φ_k(θ, z)`
//!   ([`FilmShape`]). The generalised film force is `Q_k = ∫ p φ_k dA` (virtual work of the pressure); with
//!   `φ_ex = −cos θ`, `Q_ex` is the film force on the journal in x.
//! - Perturbations (Lund's method, exact for a fixed cavitation boundary): `∂p/∂q_k` and `∂p/∂q̇_k` come from
//!   back-substitutions with the factorisation of the converged solve. Film stiffness `K = −∂Q/∂q`, damping
//!   `C = −∂Q/∂q̇` (symmetric).
//! - Flows come from the consistent nodal residual `r = A p − b`: the flow leaving through node i is
//!   `−r_i/12`; they satisfy the discrete mass balance exactly. Inside the film a non-zero residual only
//!   occurs at cavitated nodes: it is the flow that leaves the full film into the cavitated region.

use crate::fem::quad4::QuadPoint;
use crate::fem::{Pattern, RectElement, SolverError, SpdSolver};
use crate::mesh::grid::{NodeSite, PadGrid};
use crate::model::Cavitation;
use crate::physics::orifice::LocalOrifice;
use nalgebra::DMatrix;
use thiserror::Error;

mod injection;
pub use injection::InjectionResponse;

/// Largest number of active-set iterations for the Reynolds cavitation condition.
pub const MAX_ACTIVE_SET_ITERATIONS: usize = 60;
/// Sub-cells per direction for elements cut by an orifice edge.
const ORIFICE_SUBCELLS: usize = 6;

/// How the film thickness depends on position and on the generalised coordinates.
pub trait FilmShape {
    /// h0(θ, z): thickness with every generalised coordinate at zero [m].
    fn base(&self, theta: f64, z: f64) -> f64;
    /// Number of generalised coordinates.
    fn n_dofs(&self) -> usize;
    /// φ_k(θ, z) = ∂h/∂q_k.
    fn dof(&self, k: usize, theta: f64, z: f64) -> f64;
}

/// Values of a field at the quadrature points (4 per element) and at the nodes.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct SampledField {
    pub qp: Vec<[f64; 4]>,
    pub node: Vec<f64>,
}

/// The discretised orifice operator: `∫ 3 g N_i N_j / l0` (matrix, lower triangle in the pattern) and
/// `∫ 3 g N_i / l0` (vector), both sparse: only the nodes of the elements the hole touches, so the memory
/// of an operator follows the hole's footprint, not the mesh.
#[derive(Debug, Clone, PartialEq)]
pub struct OrificeOperator {
    pub orifice: LocalOrifice,
    /// (position in the pattern's values, value), positions increasing.
    pub matrix: Vec<(usize, f64)>,
    /// (node, value), nodes increasing.
    pub vector: Vec<(usize, f64)>,
    /// `∫ 3 g / l0 dA` over the modelled domain.
    pub total: f64,
}

/// Everything built once per pad mesh.
#[derive(Debug, Clone)]
pub struct FilmGeometry {
    pub grid: PadGrid,
    /// Journal radius R (s = R (θ − θ_le)).
    pub radius: f64,
    pub theta_le: f64,
    /// 2 for a half model (integrals over the modelled half are doubled), else 1.
    pub sym: f64,
    pub elements: Vec<[usize; 4]>,
    pub rects: Vec<RectElement>,
    pub qp: Vec<[QuadPoint; 4]>,
    pub qp_theta: Vec<[f64; 4]>,
    pub node_theta: Vec<f64>,
    pub node_z: Vec<f64>,
    pub pattern: Pattern,
    pub dirichlet: Vec<bool>,
    pub sites: Vec<NodeSite>,
    pub orifices: Vec<OrificeOperator>,
    pub base: SampledField,
    pub shapes: Vec<SampledField>,
    /// `f_k,i = ∫ φ_k N_i dA` over the modelled domain (no symmetry factor).
    pub loads: Vec<Vec<f64>>,
}

impl FilmGeometry {
    /// Builds quadrature data, the sparsity pattern, the orifice operators and the sampled thickness shapes.
    #[must_use]
    pub fn new(grid: PadGrid, radius: f64, theta_le: f64, orifices: &[LocalOrifice], shape: &dyn FilmShape) -> Self {
        let n = grid.n_nodes();
        let mut elements = Vec::with_capacity(grid.n_elements());
        let mut rects = Vec::with_capacity(grid.n_elements());
        for (i, j) in grid.elements() {
            elements.push(grid.element_nodes(i, j));
            rects.push(RectElement { s0: grid.s[i], z0: grid.z[j], ds: grid.s[i + 1] - grid.s[i], dz: grid.z[j + 1] - grid.z[j] });
        }
        let qp: Vec<[QuadPoint; 4]> = rects.iter().map(RectElement::gauss_2x2).collect();
        let qp_theta: Vec<[f64; 4]> = qp.iter().map(|q| q.map(|p| theta_le + p.s / radius)).collect();
        let mut node_theta = vec![0.0; n];
        let mut node_z = vec![0.0; n];
        for i in 0..grid.n_cols() {
            for j in 0..grid.n_rows() {
                let k = grid.node(i, j);
                node_theta[k] = theta_le + grid.s[i] / radius;
                node_z[k] = grid.z[j];
            }
        }
        let pattern = Pattern::from_elements(n, &elements);
        let sites: Vec<NodeSite> = (0..n).map(|k| grid.site(k)).collect();
        let dirichlet: Vec<bool> = (0..n).map(|k| grid.is_dirichlet(k)).collect();
        let sample = |f: &dyn Fn(f64, f64) -> f64| SampledField {
            qp: qp.iter().zip(&qp_theta).map(|(q, t)| [0, 1, 2, 3].map(|a| f(t[a], q[a].z))).collect(),
            node: (0..n).map(|k| f(node_theta[k], node_z[k])).collect(),
        };
        let base = sample(&|t, z| shape.base(t, z));
        let shapes: Vec<SampledField> = (0..shape.n_dofs()).map(|k| sample(&|t, z| shape.dof(k, t, z))).collect();
        let loads = shapes
            .iter()
            .map(|f| {
                let mut v = vec![0.0; n];
                for (e, nodes) in elements.iter().enumerate() {
                    for (g, q) in qp[e].iter().enumerate() {
                        for a in 0..4 {
                            v[nodes[a]] += q.w * f.qp[e][g] * q.n[a];
                        }
                    }
                }
                v
            })
            .collect();
        let sym = if grid.half { 2.0 } else { 1.0 };
        let period = grid.periodic.then(|| *grid.s.last().unwrap_or(&0.0));
        let op_grid = OperatorGrid { grid: &grid, elements: &elements, rects: &rects, pattern: &pattern, period };
        let orifices = orifices.iter().map(|o| orifice_operator(o, op_grid)).collect();
        Self {
            grid,
            radius,
            theta_le,
            sym,
            elements,
            rects,
            qp,
            qp_theta,
            node_theta,
            node_z,
            pattern,
            dirichlet,
            sites,
            orifices,
            base,
            shapes,
            loads,
        }
    }

    #[must_use]
    pub fn n_nodes(&self) -> usize {
        self.pattern.n
    }
    #[must_use]
    pub fn n_dofs(&self) -> usize {
        self.shapes.len()
    }
}

fn orifice_operator(o: &LocalOrifice, geom: OperatorGrid<'_>) -> OrificeOperator {
    let OperatorGrid { grid, elements, rects, pattern, period } = geom;
    let mut matrix: Vec<(usize, f64)> = Vec::new();
    let mut vector: Vec<(usize, f64)> = Vec::new();
    let l0 = o.length;
    let r = 0.5 * o.diameter;
    let r2 = r * r;
    let ncz = grid.z.len() - 1;
    // Element rows the hole can touch (z is never periodic).
    let j0 = grid.z.partition_point(|&z| z <= o.z0 - r).saturating_sub(1);
    let j1 = grid.z.partition_point(|&z| z < o.z0 + r).min(ncz);
    for i in 0..grid.s.len() - 1 {
        // For a periodic sector, test the image of the orifice nearest to the column.
        let mut oo = *o;
        if let Some(p) = period {
            let mid = 0.5 * (grid.s[i] + grid.s[i + 1]);
            oo.s0 = o.s0 + p * ((mid - o.s0) / p).round();
        }
        if grid.s[i + 1] <= oo.s0 - r || grid.s[i] >= oo.s0 + r {
            continue;
        }
        for j in j0..j1 {
            let e = i * ncz + j;
            let rect = &rects[e];
            if !oo.touches(rect.s0, rect.s0 + rect.ds, rect.z0, rect.z0 + rect.dz) {
                continue;
            }
            // Inside the hole the integrands (paraboloid × bilinear × bilinear, degree 4 per direction) are
            // polynomials: 3×3 Gauss is exact. Only elements cut by the rim need sub-cells.
            let (s_a, s_b, z_a, z_b) = (rect.s0, rect.s0 + rect.ds, rect.z0, rect.z0 + rect.dz);
            let inside = [(s_a, z_a), (s_b, z_a), (s_a, z_b), (s_b, z_b)]
                .iter()
                .all(|&(s, z)| (s - oo.s0).powi(2) + (z - oo.z0).powi(2) <= r2);
            let nodes = elements[e];
            for q in rect.subcell_points(if inside { 1 } else { ORIFICE_SUBCELLS }) {
                let wg = 3.0 * oo.g(q.s, q.z) / l0 * q.w;
                if wg == 0.0 {
                    continue;
                }
                for a in 0..4 {
                    vector.push((nodes[a], wg * q.n[a]));
                    for b in 0..4 {
                        let pos = pattern.scatter[e][4 * a + b];
                        if pos != usize::MAX {
                            matrix.push((pos, wg * q.n[a] * q.n[b]));
                        }
                    }
                }
            }
        }
    }
    let vector = merge_sorted(vector);
    let total = vector.iter().map(|(_, v)| v).sum();
    OrificeOperator { orifice: *o, matrix: merge_sorted(matrix), vector, total }
}

/// What [`orifice_operator`] reads of a film mesh.
#[derive(Clone, Copy)]
struct OperatorGrid<'a> {
    grid: &'a PadGrid,
    elements: &'a [[usize; 4]],
    rects: &'a [RectElement],
    pattern: &'a Pattern,
    /// Period in s of a 360° sector.
    period: Option<f64>,
}

/// Sorts (index, value) contributions by index and adds up repeated indices; zero sums are dropped.
fn merge_sorted(mut entries: Vec<(usize, f64)>) -> Vec<(usize, f64)> {
    entries.sort_unstable_by_key(|&(k, _)| k);
    let mut out: Vec<(usize, f64)> = Vec::with_capacity(entries.len() / 4 + 1);
    for (k, v) in entries {
        match out.last_mut() {
            Some(last) if last.0 == k => last.1 += v,
            _ => out.push((k, v)),
        }
    }
    out.retain(|&(_, v)| v != 0.0);
    out
}

/// Operating-point inputs of one film solve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FilmInputs<'a> {
    /// Journal surface speed U = Ω R [m/s].
    pub surface_speed: f64,
    pub viscosity: Viscosity<'a>,
    /// Pressure at the orifice entries of this pad [Pa].
    pub injection_pressure: f64,
    /// Viscosity of the injected oil [Pa·s].
    pub injection_viscosity: f64,
    pub cavitation: Cavitation,
}

/// The film viscosity.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Viscosity<'a> {
    Uniform(f64),
    /// Nodal values, interpolated bilinearly to the quadrature points.
    Nodal(&'a [f64]),
}

/// Failure of a film solve.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum FilmError {
    /// The film thickness is zero or negative somewhere: the journal touches the pad.
    #[error("film thickness {h_min_m:.3e} m ≤ 0 at θ = {theta_deg:.1}°, z = {z_m:.4} m (contact)")]
    Contact { h_min_m: f64, theta_deg: f64, z_m: f64 },
    #[error("non-physical input: {0}")]
    Input(String),
    #[error(transparent)]
    Linear(#[from] SolverError),
}

/// What one solve did.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct FilmSolveInfo {
    pub factorizations: usize,
    pub active_set_iterations: usize,
    pub cavitated_nodes: usize,
    /// Largest complementarity violation relative to the peak pressure (0 when converged).
    pub complementarity: f64,
    pub warnings: Vec<String>,
}

/// Flows of one pad [m³/s], for the whole pad (symmetry already applied).
#[derive(Debug, Clone, Copy, Default, PartialEq, serde::Serialize)]
pub struct PadFlows {
    /// Into the film through the leading edge.
    pub leading_edge_in: f64,
    /// Out of the film through the trailing edge.
    pub trailing_edge_out: f64,
    /// Out through both axial ends.
    pub sides_out: f64,
    /// Into the film through the orifices (negative: the hole drains the film).
    pub orifice_in: f64,
    /// Out of the full film into cavitated regions (carried to the trailing edge as a ruptured film).
    pub to_cavitation: f64,
}

impl PadFlows {
    /// Inflow minus outflow; zero up to round-off for the consistent flows.
    #[must_use]
    pub fn imbalance(&self) -> f64 {
        self.leading_edge_in + self.orifice_in - self.trailing_edge_out - self.sides_out - self.to_cavitation
    }
    /// The through-flow scale used to judge an imbalance.
    #[must_use]
    pub fn throughput(&self) -> f64 {
        self.leading_edge_in.abs() + self.orifice_in.abs() + self.trailing_edge_out.abs() + self.sides_out.abs()
    }
}

/// Linearised film: stiffness and damping in the pad's generalised coordinates.
#[derive(Debug, Clone, PartialEq)]
pub struct FilmLinearization {
    /// K = −∂Q/∂q
    pub stiffness: DMatrix<f64>,
    /// C = −∂Q/∂q̇
    pub damping: DMatrix<f64>,
}

/// The film of one pad: geometry (mesh lifetime) plus the solver state (reused between solves).
#[derive(Debug, Clone)]
pub struct PadFilm {
    pub geom: FilmGeometry,
    solver: SpdSolver,
    a_raw: Vec<f64>,
    a_work: Vec<f64>,
    b: Vec<f64>,
    /// Film thickness at quadrature points and nodes [m].
    pub h: SampledField,
    mu_qp: Vec<[f64; 4]>,
    /// Pressure [Pa] (non-negative after cavitation).
    pub p: Vec<f64>,
    /// Unclipped pressure of the Gümbel solve.
    p_full: Vec<f64>,
    /// Cavitated nodes (active set or clipped).
    pub cavitated: Vec<bool>,
    fixed: Vec<bool>,
    r: Vec<f64>,
    solved_with: Option<Cavitation>,
    extra_h: Option<SampledField>,
    squeeze: Option<SampledField>,
    /// Coordinates of the current thickness.
    q: Vec<f64>,
}

impl PadFilm {
    /// Allocates the solver state for a geometry (symbolic factorisation included).
    ///
    /// # Errors
    /// If the symbolic factorisation fails.
    pub fn new(geom: FilmGeometry) -> Result<Self, FilmError> {
        let n = geom.n_nodes();
        let nnz = geom.pattern.nnz();
        let ne = geom.elements.len();
        let solver = SpdSolver::new(&geom.pattern)?;
        Ok(Self {
            solver,
            a_raw: vec![0.0; nnz],
            a_work: vec![0.0; nnz],
            b: vec![0.0; n],
            h: SampledField { qp: vec![[0.0; 4]; ne], node: vec![0.0; n] },
            mu_qp: vec![[0.0; 4]; ne],
            p: vec![0.0; n],
            p_full: vec![0.0; n],
            cavitated: vec![false; n],
            fixed: vec![false; n],
            r: vec![0.0; n],
            solved_with: None,
            extra_h: None,
            squeeze: None,
            q: Vec::new(),
            geom,
        })
    }

    /// Adds a thickness field independent of q (thermal growth, elastic deformation); `None` removes it.
    pub fn set_extra_thickness(&mut self, extra: Option<SampledField>) {
        self.extra_h = extra;
    }

    /// Generalised coordinates of the current film thickness (last [`Self::set_coordinates`]).
    #[must_use]
    pub fn coordinates(&self) -> &[f64] {
        &self.q
    }

    /// Sets a squeeze velocity field ∂h/∂t [m/s] (quadrature-point values are used); `None` removes it.
    pub fn set_squeeze(&mut self, dhdt: Option<SampledField>) {
        self.squeeze = dhdt;
    }

    /// Film thickness for generalised coordinates `q`.
    ///
    /// # Errors
    /// [`FilmError::Contact`] if h ≤ 0 anywhere.
    pub fn set_coordinates(&mut self, q: &[f64]) -> Result<(), FilmError> {
        let g = &self.geom;
        debug_assert_eq!(q.len(), g.n_dofs());
        if q.iter().any(|v| !v.is_finite()) {
            return Err(FilmError::Input(format!("non-finite coordinates {q:?}")));
        }
        self.q.clear();
        self.q.extend_from_slice(q);
        for (e, hq) in self.h.qp.iter_mut().enumerate() {
            for a in 0..4 {
                let mut h = g.base.qp[e][a];
                for (k, qk) in q.iter().enumerate() {
                    h += qk * g.shapes[k].qp[e][a];
                }
                if let Some(x) = &self.extra_h {
                    h += x.qp[e][a];
                }
                hq[a] = h;
            }
        }
        let mut worst = (f64::INFINITY, 0);
        for (i, hn) in self.h.node.iter_mut().enumerate() {
            let mut h = g.base.node[i];
            for (k, qk) in q.iter().enumerate() {
                h += qk * g.shapes[k].node[i];
            }
            if let Some(x) = &self.extra_h {
                h += x.node[i];
            }
            *hn = h;
            if h < worst.0 {
                worst = (h, i);
            }
        }
        let qp_min = self.h.qp.iter().flatten().fold(f64::INFINITY, |m, &v| m.min(v));
        if worst.0 <= 0.0 || qp_min <= 0.0 {
            return Err(FilmError::Contact {
                h_min_m: worst.0.min(qp_min),
                theta_deg: g.node_theta[worst.1].to_degrees(),
                z_m: g.node_z[worst.1],
            });
        }
        Ok(())
    }

    /// Nodal film thickness for coordinates `q` (without storing it).
    #[must_use]
    pub fn nodal_thickness(&self, q: &[f64]) -> Vec<f64> {
        let g = &self.geom;
        (0..g.n_nodes())
            .map(|i| {
                let mut h = g.base.node[i] + q.iter().enumerate().map(|(k, qk)| qk * g.shapes[k].node[i]).sum::<f64>();
                if let Some(x) = &self.extra_h {
                    h += x.node[i];
                }
                h
            })
            .collect()
    }

    /// The interval of coordinate `slot` (the others as in `q`) over which the film carries no pressure at
    /// all under the Reynolds condition: `p ≡ 0` solves the complementarity problem exactly when the
    /// right-hand side `b` is non-positive at every free node, and `b` is affine in the coordinate
    /// (`b = c + q_slot d`, only the Couette term depends on the thickness). `None` for Gümbel cavitation
    /// (whose pressure-free set needs a solve) or when no such coordinate value exists.
    #[must_use]
    pub fn pressure_free_interval(&self, q: &[f64], slot: usize, inp: &FilmInputs<'_>) -> Option<(f64, f64)> {
        if inp.cavitation != Cavitation::Reynolds {
            return None;
        }
        let g = &self.geom;
        let u = inp.surface_speed;
        let n = g.n_nodes();
        let (mut c, mut d) = (vec![0.0; n], vec![0.0; n]);
        for (e, nodes) in g.elements.iter().enumerate() {
            for (k, qp) in g.qp[e].iter().enumerate() {
                let mut h = g.base.qp[e][k];
                for (j, qj) in q.iter().enumerate() {
                    if j != slot {
                        h += qj * g.shapes[j].qp[e][k];
                    }
                }
                if let Some(x) = &self.extra_h {
                    h += x.qp[e][k];
                }
                let phi = g.shapes[slot].qp[e][k];
                for a in 0..4 {
                    c[nodes[a]] += qp.w * 6.0 * u * h * qp.dn_ds[a];
                    d[nodes[a]] += qp.w * 6.0 * u * phi * qp.dn_ds[a];
                    if let Some(sq) = &self.squeeze {
                        c[nodes[a]] -= 12.0 * qp.w * sq.qp[e][k] * qp.n[a];
                    }
                }
            }
        }
        if inp.injection_pressure != 0.0 {
            for o in &g.orifices {
                for &(i, v) in &o.vector {
                    c[i] += inp.injection_pressure * v / inp.injection_viscosity;
                }
            }
        }
        let scale = c.iter().chain(&d).fold(0.0_f64, |m, v| m.max(v.abs())).max(f64::MIN_POSITIVE);
        let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
        for i in (0..n).filter(|&i| !g.dirichlet[i]) {
            if d[i].abs() <= 1e-14 * scale {
                if c[i] > 1e-14 * scale {
                    return None;
                }
            } else if d[i] > 0.0 {
                hi = hi.min(-c[i] / d[i]);
            } else {
                lo = lo.max(-c[i] / d[i]);
            }
        }
        (lo <= hi).then_some((lo, hi))
    }

    /// Nodal change of film thickness for a change `dq` of the coordinates.
    #[must_use]
    pub fn nodal_thickness_delta(&self, dq: &[f64]) -> Vec<f64> {
        let g = &self.geom;
        (0..g.n_nodes()).map(|i| dq.iter().enumerate().map(|(k, d)| d * g.shapes[k].node[i]).sum()).collect()
    }

    fn set_viscosity(&mut self, v: Viscosity<'_>) -> Result<(), FilmError> {
        match v {
            Viscosity::Uniform(mu) => {
                if !(mu > 0.0 && mu.is_finite()) {
                    return Err(FilmError::Input(format!("viscosity {mu} Pa·s")));
                }
                for m in &mut self.mu_qp {
                    *m = [mu; 4];
                }
            }
            Viscosity::Nodal(values) => {
                if values.len() != self.geom.n_nodes() || values.iter().any(|m| !(*m > 0.0 && m.is_finite())) {
                    return Err(FilmError::Input("nodal viscosity field has the wrong length or a non-positive value".into()));
                }
                for (e, nodes) in self.geom.elements.iter().enumerate() {
                    for (g, q) in self.geom.qp[e].iter().enumerate() {
                        self.mu_qp[e][g] = (0..4).map(|a| q.n[a] * values[nodes[a]]).sum();
                    }
                }
            }
        }
        Ok(())
    }

    /// Assembles the matrix (lower triangle) and the right-hand side for the current thickness.
    fn assemble(&mut self, inp: &FilmInputs<'_>) {
        let g = &self.geom;
        let u = inp.surface_speed;
        self.a_raw.fill(0.0);
        self.b.fill(0.0);
        for (e, nodes) in g.elements.iter().enumerate() {
            let map = &g.pattern.scatter[e];
            for (k, q) in g.qp[e].iter().enumerate() {
                let h = self.h.qp[e][k];
                // Diffusion coefficient h³/µ times the quadrature weight.
                let kd = q.w * h * h * h / self.mu_qp[e][k];
                for a in 0..4 {
                    // Couette wedge, integrated by parts: ∫ 6 U h ∂N_a/∂s.
                    self.b[nodes[a]] += q.w * 6.0 * u * h * q.dn_ds[a];
                    for bb in 0..4 {
                        let pos = map[4 * a + bb];
                        if pos != usize::MAX {
                            self.a_raw[pos] += kd * (q.dn_ds[a] * q.dn_ds[bb] + q.dn_dz[a] * q.dn_dz[bb]);
                        }
                    }
                }
            }
        }
        // Squeeze: −∫ 12 ∂h/∂t N_a.
        if let Some(sq) = &self.squeeze {
            for (e, nodes) in g.elements.iter().enumerate() {
                for (k, q) in g.qp[e].iter().enumerate() {
                    for a in 0..4 {
                        self.b[nodes[a]] -= 12.0 * q.w * sq.qp[e][k] * q.n[a];
                    }
                }
            }
        }
        // Orifices: 3 g (p − p_inj) / (µ_inj l0).
        let mu_inj = inp.injection_viscosity;
        for o in &g.orifices {
            for &(pos, v) in &o.matrix {
                self.a_raw[pos] += v / mu_inj;
            }
            if inp.injection_pressure != 0.0 {
                for &(i, v) in &o.vector {
                    self.b[i] += inp.injection_pressure * v / mu_inj;
                }
            }
        }
    }

    /// Solves the film for the thickness set by [`Self::set_coordinates`].
    ///
    /// `warm`: start the active-set iteration from the previous cavitated set.
    ///
    /// # Errors
    /// Invalid inputs or a failed factorisation (never returns NaN pressures).
    pub fn solve(&mut self, inp: &FilmInputs<'_>, warm: bool) -> Result<FilmSolveInfo, FilmError> {
        if !(inp.surface_speed.is_finite() && inp.injection_pressure.is_finite()) {
            return Err(FilmError::Input("non-finite speed or injection pressure".into()));
        }
        if !(inp.injection_viscosity > 0.0 && inp.injection_viscosity.is_finite()) {
            return Err(FilmError::Input(format!("injection viscosity {}", inp.injection_viscosity)));
        }
        self.set_viscosity(inp.viscosity)?;
        self.assemble(inp);
        let info = match inp.cavitation {
            Cavitation::Gumbel => self.solve_gumbel()?,
            Cavitation::Reynolds => self.solve_reynolds(warm && self.solved_with == Some(Cavitation::Reynolds))?,
        };
        self.solved_with = Some(inp.cavitation);
        if self.p.iter().any(|v| !v.is_finite()) {
            return Err(FilmError::Input("pressure is not finite (ill-conditioned film)".into()));
        }
        Ok(info)
    }

    fn factor_and_solve(&mut self) -> Result<(), FilmError> {
        let g = &self.geom;
        g.pattern.fix_rows(&self.a_raw, &self.fixed, &mut self.a_work);
        self.solver.factor(&g.pattern, &self.a_work)?;
        for i in 0..self.p.len() {
            self.p[i] = if self.fixed[i] { 0.0 } else { self.b[i] };
        }
        self.solver.solve_in_place(&mut self.p);
        // Residual of the unmodified equations: reactions at fixed nodes, ~0 elsewhere.
        g.pattern.sym_matvec(&self.a_raw, &self.p, &mut self.r);
        for (r, b) in self.r.iter_mut().zip(&self.b) {
            *r -= b;
        }
        Ok(())
    }

    fn solve_gumbel(&mut self) -> Result<FilmSolveInfo, FilmError> {
        self.fixed.copy_from_slice(&self.geom.dirichlet);
        self.factor_and_solve()?;
        self.p_full.copy_from_slice(&self.p);
        let mut n_cav = 0;
        for i in 0..self.p.len() {
            self.cavitated[i] = self.p[i] < 0.0;
            if self.cavitated[i] {
                self.p[i] = 0.0;
                n_cav += 1;
            }
        }
        // Residual of the clipped field (flows).
        let g = &self.geom;
        g.pattern.sym_matvec(&self.a_raw, &self.p, &mut self.r);
        for (r, b) in self.r.iter_mut().zip(&self.b) {
            *r -= b;
        }
        Ok(FilmSolveInfo { factorizations: 1, active_set_iterations: 1, cavitated_nodes: n_cav, ..Default::default() })
    }

    /// Primal–dual active set for p ≥ 0, λ = A p − b ≥ 0, p λ = 0.
    fn solve_reynolds(&mut self, warm: bool) -> Result<FilmSolveInfo, FilmError> {
        let n = self.p.len();
        if !warm {
            self.cavitated.fill(false);
        }
        let mut info = FilmSolveInfo::default();
        let mut next = self.cavitated.clone();
        loop {
            info.active_set_iterations += 1;
            for i in 0..n {
                self.fixed[i] = self.geom.dirichlet[i] || self.cavitated[i];
            }
            self.factor_and_solve()?;
            info.factorizations += 1;
            let p_scale = self.p.iter().fold(0.0_f64, |m, v| m.max(v.abs())).max(f64::MIN_POSITIVE);
            let r_scale = self.b.iter().fold(0.0_f64, |m, v| m.max(v.abs())).max(f64::MIN_POSITIVE);
            let mut changed = 0;
            for i in 0..n {
                if self.geom.dirichlet[i] {
                    next[i] = false;
                    continue;
                }
                // Stay cavitated while the multiplier is non-negative; enter when the pressure goes negative.
                next[i] = if self.cavitated[i] { self.r[i] > -1e-11 * r_scale } else { self.p[i] < -1e-11 * p_scale };
                if next[i] != self.cavitated[i] {
                    changed += 1;
                }
            }
            if changed == 0 {
                break;
            }
            if info.active_set_iterations >= MAX_ACTIVE_SET_ITERATIONS {
                // Keep the set that matches the last factorisation; report how far from complementarity.
                let viol_p = self.p.iter().fold(0.0_f64, |m, &v| m.max(-v)) / p_scale;
                let viol_r = (0..n).filter(|&i| self.cavitated[i]).fold(0.0_f64, |m, i| m.max(-self.r[i])) / r_scale;
                info.complementarity = viol_p.max(viol_r);
                info.warnings.push(format!(
                    "cavitation active set still changing after {} iterations ({changed} nodes); \
                     largest complementarity violation {:.2e} (relative)",
                    info.active_set_iterations, info.complementarity
                ));
                for v in &mut self.p {
                    *v = v.max(0.0);
                }
                break;
            }
            std::mem::swap(&mut self.cavitated, &mut next);
        }
        info.cavitated_nodes = self.cavitated.iter().filter(|&&c| c).count();
        Ok(info)
    }

    /// Generalised film forces `Q_k = ∫ p φ_k dA` (whole pad).
    #[must_use]
    pub fn generalized_forces(&self) -> Vec<f64> {
        let g = &self.geom;
        g.loads.iter().map(|f| g.sym * f.iter().zip(&self.p).map(|(a, b)| a * b).sum::<f64>()).collect()
    }

    /// Film stiffness and damping in the pad's generalised coordinates (analytic perturbation about the
    /// last solve; requires a preceding [`Self::solve`] with the same inputs).
    #[must_use]
    pub fn linearize(&mut self, inp: &FilmInputs<'_>) -> FilmLinearization {
        self.linearize_impl(inp, true)
    }

    /// As [`Self::linearize`] but the stiffness only (the damping is returned as zeros): half the
    /// back-substitutions, for Newton iterations.
    #[must_use]
    pub fn linearize_stiffness(&mut self, inp: &FilmInputs<'_>) -> FilmLinearization {
        self.linearize_impl(inp, false)
    }

    fn linearize_impl(&mut self, inp: &FilmInputs<'_>, with_damping: bool) -> FilmLinearization {
        let fields = self.perturbation_fields(inp, with_damping);
        let g = &self.geom;
        let n = g.n_nodes();
        let m = g.n_dofs();
        let mut stiffness = DMatrix::zeros(m, m);
        let mut damping = DMatrix::zeros(m, m);
        for j in 0..m {
            for k in 0..m {
                let dk = &fields[k * n..(k + 1) * n];
                stiffness[(j, k)] = -g.sym * g.loads[j].iter().zip(dk).map(|(a, b)| a * b).sum::<f64>();
                if with_damping {
                    let dc = &fields[(m + k) * n..(m + k + 1) * n];
                    damping[(j, k)] = -g.sym * g.loads[j].iter().zip(dc).map(|(a, b)| a * b).sum::<f64>();
                }
            }
        }
        FilmLinearization { stiffness, damping }
    }

    /// The pressure perturbation fields `∂p/∂q_k` (columns `0..m`) and, with `with_damping`, `∂p/∂q̇_k`
    /// (columns `m..2m`), each of length n, by back-substitution with the factorisation of the last solve.
    fn perturbation_fields(&mut self, inp: &FilmInputs<'_>, with_damping: bool) -> Vec<f64> {
        let g = &self.geom;
        let n = g.n_nodes();
        let m = g.n_dofs();
        let u = inp.surface_speed;
        let gumbel = self.solved_with == Some(Cavitation::Gumbel);
        let pg = if gumbel { &self.p_full } else { &self.p };
        let cols = if with_damping { 2 * m } else { m };
        let mut rhs = vec![0.0; n * cols];
        for (e, nodes) in g.elements.iter().enumerate() {
            for (k, q) in g.qp[e].iter().enumerate() {
                let h = self.h.qp[e][k];
                let mu = self.mu_qp[e][k];
                let (mut dps, mut dpz) = (0.0, 0.0);
                for a in 0..4 {
                    dps += q.dn_ds[a] * pg[nodes[a]];
                    dpz += q.dn_dz[a] * pg[nodes[a]];
                }
                for a in 0..4 {
                    // ∂b/∂q_k − (∂A/∂q_k) p, per unit φ_k:
                    //   6 U ∂N_a/∂s − 3 h²/µ ∇p·∇N_a
                    let c = q.w * (6.0 * u * q.dn_ds[a] - 3.0 * h * h / mu * (dps * q.dn_ds[a] + dpz * q.dn_dz[a]));
                    // Squeeze: −12 N_a per unit φ_k q̇_k.
                    let d = -12.0 * q.w * q.n[a];
                    for (s, shape) in g.shapes.iter().enumerate() {
                        let phi = shape.qp[e][k];
                        rhs[s * n + nodes[a]] += phi * c;
                        if with_damping {
                            rhs[(m + s) * n + nodes[a]] += phi * d;
                        }
                    }
                }
            }
        }
        self.back_substitute(&mut rhs);
        rhs
    }

    /// Solves `A x = r` for every column of `rhs` (length n each) with the factorisation of the last solve:
    /// fixed rows zeroed first; under Gümbel cavitation the clipped nodes are zeroed after.
    fn back_substitute(&mut self, rhs: &mut [f64]) {
        let n = self.geom.n_nodes();
        for col in rhs.chunks_mut(n) {
            for i in 0..n {
                if self.fixed[i] {
                    col[i] = 0.0;
                }
            }
        }
        self.solver.solve_many_in_place(rhs, n);
        if self.solved_with == Some(Cavitation::Gumbel) {
            for col in rhs.chunks_mut(n) {
                for i in 0..n {
                    if self.cavitated[i] {
                        col[i] = 0.0;
                    }
                }
            }
        }
    }

    /// Consistent flows of the last solve (whole pad).
    #[must_use]
    pub fn flows(&self, inp: &FilmInputs<'_>) -> PadFlows {
        let g = &self.geom;
        let mut f = PadFlows::default();
        for (i, r) in self.r.iter().enumerate() {
            let out = -g.sym * r / 12.0;
            match g.sites[i] {
                NodeSite::Leading => f.leading_edge_in -= out,
                NodeSite::Trailing => f.trailing_edge_out += out,
                NodeSite::Side => f.sides_out += out,
                NodeSite::Interior | NodeSite::Symmetry => f.to_cavitation += out,
            }
        }
        f.orifice_in = (0..g.orifices.len()).map(|k| self.orifice_flow(k, inp)).sum();
        f
    }

    /// Flow into the film through orifice `k` [m³/s] (negative when the hole drains the film).
    #[must_use]
    pub fn orifice_flow(&self, k: usize, inp: &FilmInputs<'_>) -> f64 {
        let g = &self.geom;
        let o = &g.orifices[k];
        let gp: f64 = o.vector.iter().map(|&(i, v)| v * self.p[i]).sum();
        g.sym * (inp.injection_pressure * o.total - gp) / (12.0 * inp.injection_viscosity)
    }

    /// Edge flows by direct integration of `q_s = −h³/(12µ) ∂p/∂s + U h/2` and `q_z = −h³/(12µ) ∂p/∂z`
    /// across the pad boundary, with element gradients (an independent check of [`Self::flows`]):
    /// (leading edge in, trailing edge out, sides out).
    #[must_use]
    pub fn direct_edge_flows(&self, inp: &FilmInputs<'_>) -> (f64, f64, f64) {
        let g = &self.geom;
        let grid = &g.grid;
        let ncs = grid.s.len() - 1;
        let ncz = grid.z.len() - 1;
        let u = inp.surface_speed;
        let gauss = [-0.577_350_269_189_625_8, 0.577_350_269_189_625_8];
        let mut le = 0.0;
        let mut te = 0.0;
        let mut side = 0.0;
        let eval = |e: usize, xi: f64, eta: f64| -> (f64, f64, f64, f64) {
            let r = &g.rects[e];
            let q = r.quad_point(xi, eta, 1.0);
            let nodes = g.elements[e];
            let (mut h, mut ps, mut pz, mut mu) = (0.0, 0.0, 0.0, 0.0);
            for a in 0..4 {
                h += q.n[a] * self.h.node[nodes[a]];
                ps += q.dn_ds[a] * self.p[nodes[a]];
                pz += q.dn_dz[a] * self.p[nodes[a]];
            }
            for k in 0..4 {
                mu += 0.25 * self.mu_qp[e][k];
            }
            (h, ps, pz, mu)
        };
        if !grid.periodic {
            for j in 0..ncz {
                for &eta in &gauss {
                    let e0 = j; // column 0
                    let (h, ps, _, mu) = eval(e0, -1.0, eta);
                    le += 0.5 * g.rects[e0].dz * (-h * h * h / (12.0 * mu) * ps + 0.5 * u * h);
                    let e1 = (ncs - 1) * ncz + j;
                    let (h, ps, _, mu) = eval(e1, 1.0, eta);
                    te += 0.5 * g.rects[e1].dz * (-h * h * h / (12.0 * mu) * ps + 0.5 * u * h);
                }
            }
        }
        for i in 0..ncs {
            for &xi in &gauss {
                let top = i * ncz + (ncz - 1);
                let (h, _, pz, mu) = eval(top, xi, 1.0);
                side += 0.5 * g.rects[top].ds * (-h * h * h / (12.0 * mu) * pz);
                if !grid.half {
                    let bot = i * ncz;
                    let (h, _, pz, mu) = eval(bot, xi, -1.0);
                    side += 0.5 * g.rects[bot].ds * (h * h * h / (12.0 * mu) * pz);
                }
            }
        }
        (g.sym * le, g.sym * te, g.sym * side)
    }

    /// Viscous drag on the journal and the power it dissipates, `P = U ∫ (µ U/h + (h/2) ∂p/∂s) dA`
    /// (full film assumed in cavitated regions, a conservative choice) → (force N, power W).
    #[must_use]
    pub fn friction(&self, inp: &FilmInputs<'_>) -> (f64, f64) {
        let g = &self.geom;
        let u = inp.surface_speed;
        let mut force = 0.0;
        for (e, nodes) in g.elements.iter().enumerate() {
            for (k, q) in g.qp[e].iter().enumerate() {
                let h = self.h.qp[e][k];
                let dps: f64 = (0..4).map(|a| q.dn_ds[a] * self.p[nodes[a]]).sum();
                force += q.w * (self.mu_qp[e][k] * u / h + 0.5 * h * dps);
            }
        }
        (g.sym * force, g.sym * force * u)
    }

    /// Largest nodal pressure [Pa].
    #[must_use]
    pub fn p_max(&self) -> f64 {
        self.p.iter().fold(0.0_f64, |m, &v| m.max(v))
    }

    /// Smallest nodal film thickness [m] and its node.
    #[must_use]
    pub fn h_min(&self) -> (f64, usize) {
        self.h.node.iter().enumerate().fold((f64::INFINITY, 0), |m, (i, &v)| if v < m.0 { (v, i) } else { m })
    }

    /// Viscosity at the quadrature points of the last solve.
    #[must_use]
    pub fn viscosity_qp(&self) -> &[[f64; 4]] {
        &self.mu_qp
    }

    /// Nodal residual `A p − b` of the last solve.
    #[must_use]
    pub fn residual(&self) -> &[f64] {
        &self.r
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    struct Uniform;
    impl FilmShape for Uniform {
        fn base(&self, _theta: f64, _z: f64) -> f64 {
            100e-6
        }
        fn n_dofs(&self) -> usize {
            0
        }
        fn dof(&self, _k: usize, _theta: f64, _z: f64) -> f64 {
            0.0
        }
    }

    /// A 360° sector (R = 1, 40 × 20 cells of 1 mm) with one 3 mm orifice centred at arc length `s0`.
    fn sector(s0: f64) -> FilmGeometry {
        let s: Vec<f64> = (0..=40).map(|i| 1e-3 * f64::from(i)).collect();
        let z: Vec<f64> = (0..=20).map(|j| -0.01 + 1e-3 * f64::from(j)).collect();
        let grid = PadGrid { s, z, periodic: true, half: false };
        FilmGeometry::new(grid, 1.0, 0.0, &[LocalOrifice { s0, z0: 0.0, diameter: 3e-3, length: 5e-3 }], &Uniform)
    }

    /// The operator only holds the hole's nodes, integrates ∫ 3 g / l0 = 3 π d⁴ / (32 l0), and is the same
    /// for a hole across the seam of a 360° sector as for one in the middle (shifted by 20 columns).
    #[test]
    fn orifice_operator_is_local_and_wraps_across_the_seam() {
        let (mid, seam) = (sector(0.02), sector(0.0));
        let (a, b) = (&mid.orifices[0], &seam.orifices[0]);
        let exact = 3.0 * std::f64::consts::PI * (3e-3_f64).powi(4) / (32.0 * 5e-3);
        // Sub-cell quadrature on the rim: measured −1.8e-5.
        assert!((a.total / exact - 1.0).abs() < 5e-5, "{} vs {exact}", a.total);
        assert!((a.total - b.total).abs() < 1e-12 * a.total, "{} vs {}", a.total, b.total);
        // The hole (radius 1.5 cells) touches 4 × 4 elements: 5 × 5 nodes.
        assert_eq!((a.vector.len(), b.vector.len()), (25, 25));
        let shifted = |k: usize| mid.grid.node((mid.grid.col_row(k).0 + 20) % 40, mid.grid.col_row(k).1);
        for &(ka, va) in &a.vector {
            let vb = b.vector.iter().find(|(k, _)| *k == shifted(ka)).map_or(f64::NAN, |e| e.1);
            assert!((va - vb).abs() < 1e-12 * a.total, "node {ka}: {va} vs {vb}");
        }
    }
}
