//! What is built once per pad mesh for the Reynolds film solve: quadrature data, the sparsity pattern, the
//! sampled thickness shapes `h0`, `φ_k` and their loads `f_k,i = ∫ φ_k N_i dA`, and the orifice operators.
//!
//! ```text
//! M_ij = ∫ 3 g N_i N_j / l0 dA,   v_i = ∫ 3 g N_i / l0 dA          (g: the hole's paraboloid weight)
//! ```
//! A hole open to ambient (entry pressure at or below the cavitation pressure) takes M lumped on the diagonal
//! (`M_ii = v_i`, the row sums): the term is about 10⁸ times the film's `h³/µ` per element, and the
//! consistent form's positive off-diagonal weights make the pressure undershoot below the rim, which the
//! cavitation condition turns into a spurious cavitated ring (docs/MODEL.md §2.4). An injecting hole keeps
//! the consistent form, which converges faster there (the pressure peaks at the hole, no undershoot reaches
//! the cavitation pressure).
//! The orifice weight has a kink at the hole's edge, so the elements the hole touches are integrated with
//! sub-cell quadrature; the operators are stored sparse (only the hole's footprint), and a hole across the
//! seam of a 360° sector wraps.

use crate::fem::quad4::QuadPoint;
use crate::fem::{Pattern, RectElement};
use crate::mesh::grid::{NodeSite, PadGrid};
use crate::physics::orifice::LocalOrifice;
use crate::physics::reynolds::{FilmShape, SampledField};

/// Sub-cells per direction for elements cut by an orifice edge.
const ORIFICE_SUBCELLS: usize = 6;

/// The discretised orifice operator: `∫ 3 g N_i N_j / l0` (matrix, consistent and lumped, positions in the
/// pattern) and as a vector, both sparse: only the nodes of the elements the hole touches, so the memory
/// of an operator follows the hole's footprint, not the mesh.
#[derive(Debug, Clone, PartialEq)]
pub struct OrificeOperator {
    pub orifice: LocalOrifice,
    /// The consistent `∫ 3 g N_i N_j / l0`: (position in the pattern's values, value), positions increasing.
    pub matrix: Vec<(usize, f64)>,
    /// The lumped `∫ 3 g N_i / l0` on the diagonal (positions in the pattern's values), for a hole open to
    /// ambient ([`OrificeOperator::entries`]).
    pub lumped: Vec<(usize, f64)>,
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
            rects.push(RectElement {
                s0: grid.s[i],
                z0: grid.z[j],
                ds: grid.s[i + 1] - grid.s[i],
                dz: grid.z[j + 1] - grid.z[j],
            });
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
    let mut diagonal: Vec<(usize, f64)> = Vec::new();
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
                    let pos = pattern.scatter[e][4 * a + a];
                    if pos != usize::MAX {
                        diagonal.push((pos, wg * q.n[a]));
                    }
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
    OrificeOperator { orifice: *o, matrix: merge_sorted(matrix), lumped: merge_sorted(diagonal), vector, total }
}

impl OrificeOperator {
    /// Whether a hole whose entry pressure is `injection_pressure` [Pa] takes the lumped capillary term: when
    /// it is open to ambient (`≤ 0`); an injecting hole takes the consistent one (module documentation). The
    /// one place the rule lives: the film's matrix ([`Self::entries`]) and the energy equation's pumping
    /// power both ask here.
    #[must_use]
    pub fn lumped_at(injection_pressure: f64) -> bool {
        injection_pressure <= 0.0
    }

    /// The matrix entries for a hole whose entry pressure is `injection_pressure` [Pa]: lumped or consistent
    /// as [`Self::lumped_at`] says.
    #[must_use]
    pub fn entries(&self, injection_pressure: f64) -> &[(usize, f64)] {
        if Self::lumped_at(injection_pressure) {
            &self.lumped
        } else {
            &self.matrix
        }
    }
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
