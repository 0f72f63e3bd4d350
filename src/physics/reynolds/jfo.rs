//! Mass-conserving (Jakobsson–Floberg–Olsson) cavitation: pressure `p` and film fraction `θ` as
//! complementary unknowns (docs/MODEL.md §2.3).
//!
//! ## Equation
//! With the film fraction `θ ∈ [0, 1]` (the part of the gap filled with oil; 1 in a full film), the mass
//! balance of the film is the Reynolds equation with the Couette and squeeze flows carried by the oil alone:
//!
//! ```text
//! ∇·(h³/µ ∇p) = 6 U ∂(θ h)/∂s + 12 θ ∂h/∂t + Σ_orifices 3 g (p − p_inj)/(µ_inj l0)
//! p ≥ 0,   1 − θ ≥ 0,   p (1 − θ) = 0
//! ```
//!
//! In a full film (`p > 0`) `θ = 1` and the equation is the Reynolds equation; in a ruptured zone `p = 0`
//! and the equation transports the oil striations, `∂(θ h)/∂s = 0` along the sliding direction with the
//! Couette flow `U θ h/2`. Rupture (where the full film's pressure would fall below zero) and reformation
//! (where the striations reach a pressurised film, or an orifice fills them) follow from the complementarity.
//!
//! ## Discretisation (nodal residual, bilinear elements)
//! ```text
//! r_i = Σ_j A_ij p_j + Σ_j (T̃_ij + S_ij) θ_j − f_i
//!   A_ij = ∫ h³/µ ∇N_i·∇N_j + ∫ 3 g N_i N_j /(µ_inj l0)      Poiseuille and orifice (the Reynolds matrix: the
//!                                                             orifice term lumped, δ_ij ∫ 3 g N_i, for a hole open
//!                                                             to ambient, consistent for an injecting one)
//!   T_ij = −∫ 6 U h N_j ∂N_i/∂s                               Couette flow of the oil, integrated by parts
//!   T̃    = T + D,  D_ij = −max(0, T_ij, T_ji) (i ≠ j), D_ii = −Σ_{j≠i} D_ij   (discrete upwinding)
//!   S_ij = ∫ 12 ∂h/∂t N_i N_j                                  squeeze of the oil
//!   f_i  = ∫ 3 g p_inj N_i /(µ_inj l0)                         orifice supply
//! ```
//! `D` is symmetric with zero row (and column) sums, the "discrete upwinding" of algebraic flux correction
//! (Kuzmin): it removes the positive off-diagonal entries of the Couette operator, so the transport of θ
//! through a ruptured zone is monotone (no oscillations at the jumps of θ at reformation), and
//! - with `θ ≡ 1` it adds nothing: in a full film the residual is exactly the Reynolds option's (the same
//!   pressures to round-off where neither model cavitates);
//! - its zero column sums keep the discrete conservation: `Σ_i r_i = Σ_i (A p)_i − Σ_i f_i` involves no θ, so
//!   the flows leaving through the boundary nodes (`−r_i/12`) balance the orifice flows to round-off, with
//!   rupture and reformation inside the pad, and no flow "into cavitation" remains at interior nodes.
//!
//! ## Complementarity: a primal–dual active set
//! Every free node is either pressurised (`P`: unknown `p`, `θ = 1`) or cavitated (`C`: `p = 0`, unknown `θ`).
//! For given sets the residual equations `r_i = 0` at the free nodes are one linear, non-symmetric system in
//! the mixed unknowns (`p` on `P`, `θ` on `C`), with the θ columns scaled to the pressure columns' size:
//!
//! ```text
//! [ A_PP   T̃_PC ] [ p_P ]   [ f_P − T̃_P· θ_known ]
//! [ A_CP   T̃_CC ] [ θ_C ] = [ f_C − T̃_C· θ_known ]
//! ```
//!
//! Whatever the sets, the matrix has the symmetric pattern of the Reynolds matrix, and its blocks need no
//! pivoting: `A_PP` is the Reynolds option's symmetric positive definite matrix on the pressurised nodes,
//! `T̃_CC` the upwinded transport (columns diagonally dominant), and the couplings `T̃_PC`, `A_CP` live on
//! the nodes next to rupture and reformation. So it is factorised `P M Pᵀ = L D U` without row exchanges on
//! the fill of the Reynolds matrix's Cholesky factor (`fem::ldu`: ordering and structure once per mesh; two
//! triangular solves per row, about twice a Cholesky factorisation), where a general sparse LU with row
//! pivoting bounds its fill by the structure of `MᵀM` (the compressor bearing's mass-conserving solve at the
//! reference level, least of 15 on a loaded machine: 3.6 s with the pivoting LU, 1.5 s without). A refused pivot or an inaccurate solve
//! falls back to the pivoting LU, counted in [`FilmSolveInfo::pivoted_factorizations`]. After the first step
//! of a solve, a step that moves few nodes corrects the factorisation by a low-rank update instead
//! (`jfo_update.rs`), and only the columns of the nodes that moved are filled again. Then nodes with
//! `p < 0` move to `C` and nodes with `θ > 1` to `P`, until no node moves; the residual of the unmodified
//! equations (the edge flows) is formed once, for the final sets. The start is the previous solve's sets
//! (warm) or the Reynolds (Swift–Stieber) active set, which places the ruptures nearly right; the iteration
//! typically ends after 2–4 steps. At convergence every node satisfies the complementarity conditions and the discrete mass
//! balance holds at every free node to round-off.
//!
//! ## Boundary film fraction
//! Ambient-pressure edges: the leading edge carries the inlet film fraction `θ_in` (1 flooded; with a
//! supply flow `Q`, `θ_in = min(1, Q/Q_cap)` with `Q_cap` the Couette inflow of a full inlet, so a starved
//! pad takes in `Q`); the trailing edge and axial ends carry the fraction of their inner neighbour
//! (zero-gradient outflow). The reactions at these nodes are the edge flows.
//!
//! ## Files
//! This file holds the state built once per mesh and the complementarity solve; `jfo_operators.rs` the
//! Couette, upwinding and squeeze operators and the inlet film fraction; `jfo_linearize.rs` the
//! perturbations about a converged solve (the stiffness and damping of the film, the FRF's influence
//! fields).

use crate::fem::{GeneralPattern, LuSolver, StaticLdu};
use crate::mesh::grid::{NodeSite, PadGrid};
use crate::physics::reynolds::{FilmError, FilmGeometry, FilmSolveInfo, FilmWarning, Inlet, SampledField};

/// Largest number of active-set steps of the mass-conserving solve.
pub const MAX_JFO_ITERATIONS: usize = 80;

/// Relative tolerance of the complementarity test (pressure against the peak, θ against 1).
const TOL: f64 = 1e-10;

/// How the film fraction of a node is set when the node is not a free unknown.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum ThetaRule {
    /// A free node: 1 when pressurised, unknown when cavitated.
    Free,
    /// Leading-edge node: the inlet film fraction.
    Inlet,
    /// Outflow edge node: the fraction of the given (free) node.
    Copy(usize),
    /// Outflow edge node without a free neighbour (a one-element-wide pad): a full film.
    Full,
}

/// The correction of the base factorisation (`jfo_update.rs` makes and applies it): changed columns,
/// `W = M₀⁻¹ U` (column-major, n × k) and the LU of the capacitance matrix `I + E_Jᵀ W`.
#[derive(Debug, Clone)]
pub(super) struct Update {
    pub(super) nodes: Vec<usize>,
    pub(super) w: Vec<f64>,
    pub(super) capacitance: nalgebra::LU<f64, nalgebra::Dyn, nalgebra::Dyn>,
}

/// The mass-conserving solver's state: built once per mesh, values refilled per solve.
#[derive(Debug, Clone)]
pub(super) struct JfoState {
    pub(super) pattern: GeneralPattern,
    /// The factorisation on the fill of the pattern's Cholesky factor (no row exchanges, `fem::ldu`).
    pub(super) ldu: StaticLdu,
    /// The pivoting LU, built on the first matrix the static factorisation refuses (`jfo_update.rs`).
    pub(super) lu: Option<LuSolver>,
    /// Whether the pivoting LU holds the current base factorisation.
    pub(super) base_pivoted: bool,
    /// Factorisations of the current solve that fell back to the pivoting LU.
    pub(super) fallbacks: usize,
    /// Always factorise with the pivoting LU (tests).
    pub(super) pivot_always: bool,
    /// Position of the transposed entry of every entry.
    pub(super) transpose: Vec<usize>,
    /// (full position of (r, c), full position of (c, r)) of every entry of the symmetric pattern.
    pub(super) sym_to_full: Vec<(usize, usize)>,
    pub(super) rule: Vec<ThetaRule>,
    /// For each outflow node j copying node k: (position of (r, j), position of (r, k)) for every row r of
    /// column j; the column of j is folded into the column of k when k is cavitated.
    pub(super) folds: Vec<(usize, Vec<(usize, usize)>)>,
    /// A (Poiseuille + orifices), full storage.
    pub(super) a: Vec<f64>,
    /// T̃ + S, full storage.
    pub(super) t: Vec<f64>,
    /// Limiter branch of each entry below the diagonal: 0 none, 1 the entry itself, 2 its transpose.
    pub(super) branch: Vec<u8>,
    /// The mixed system's values.
    pub(super) m: Vec<f64>,
    /// The values the LU factorisation holds, and the cavitated set they belong to (`jfo_update.rs`).
    pub(super) m_base: Vec<f64>,
    pub(super) base_cav: Vec<bool>,
    /// Low-rank correction of the factorisation for the columns changed since (`jfo_update.rs`).
    pub(super) update: Option<Update>,
    /// Scale of the θ columns [Pa]: the unknown of a cavitated node is `θ · scale`.
    pub(super) scale: f64,
    /// Inlet film fraction of the last solve.
    pub theta_in: f64,
    /// Couette inflow of a full inlet, modelled domain [m³/s · 12].
    pub(super) capacity12: f64,
    /// Supply flow of the last solve (whole pad) [m³/s], if starved.
    pub(super) supply: Option<f64>,
    /// Work storage of the perturbations' operators (`jfo_linearize.rs`), zero between uses.
    pub(super) scratch: Vec<f64>,
}

impl JfoState {
    pub(super) fn new(geom: &FilmGeometry) -> Result<Self, FilmError> {
        let n = geom.n_nodes();
        let pattern = GeneralPattern::from_groups(n, geom.elements.iter().map(|e| &e[..]));
        let ldu = StaticLdu::new(&pattern)?;
        let nnz = pattern.nnz();
        let mut transpose = vec![0; nnz];
        for c in 0..n {
            for k in pattern.col_ptr[c]..pattern.col_ptr[c + 1] {
                let r = pattern.row_idx[k];
                transpose[k] = pattern.position(c, r).ok_or_else(|| FilmError::Input("asymmetric pattern".into()))?;
            }
        }
        let sp = &geom.pattern;
        let mut sym_to_full = Vec::with_capacity(sp.nnz());
        for c in 0..n {
            for k in sp.col_ptr[c]..sp.col_ptr[c + 1] {
                let r = sp.row_idx[k];
                let rc = pattern.position(r, c).ok_or_else(|| FilmError::Input("pattern mismatch".into()))?;
                sym_to_full.push((rc, transpose[rc]));
            }
        }
        let rule = theta_rules(&geom.grid, &geom.sites);
        let mut folds = Vec::new();
        for (j, r) in rule.iter().enumerate() {
            if let ThetaRule::Copy(k) = *r {
                let pairs = (pattern.col_ptr[j]..pattern.col_ptr[j + 1])
                    .filter_map(|p| pattern.position(pattern.row_idx[p], k).map(|q| (p, q)))
                    .collect();
                folds.push((j, pairs));
            }
        }
        Ok(Self {
            ldu,
            lu: None,
            base_pivoted: false,
            fallbacks: 0,
            pivot_always: false,
            transpose,
            sym_to_full,
            rule,
            folds,
            a: vec![0.0; nnz],
            t: vec![0.0; nnz],
            branch: vec![0; nnz],
            m: vec![0.0; nnz],
            m_base: vec![0.0; nnz],
            base_cav: vec![false; n],
            update: None,
            scale: 1.0,
            theta_in: 1.0,
            capacity12: 0.0,
            supply: None,
            scratch: Vec::new(),
            pattern,
        })
    }
}

/// The film-fraction rule of every node (module documentation, "Boundary film fraction").
fn theta_rules(grid: &PadGrid, sites: &[NodeSite]) -> Vec<ThetaRule> {
    let (nc, nr) = (grid.n_cols(), grid.n_rows());
    let side = |j: usize| j == nr - 1 || (!grid.half && j == 0);
    let inner = |j: usize| -> Option<usize> {
        if !side(j) {
            Some(j)
        } else if j == 0 {
            (nr > 1 && !side(1)).then_some(1)
        } else {
            (j >= 1 && !side(j - 1)).then(|| j - 1)
        }
    };
    (0..grid.n_nodes())
        .map(|k| {
            let (i, j) = grid.col_row(k);
            match sites[k] {
                NodeSite::Interior | NodeSite::Symmetry => ThetaRule::Free,
                NodeSite::Leading => ThetaRule::Inlet,
                NodeSite::Trailing => match (i.checked_sub(1), inner(j)) {
                    (Some(ii), Some(jj)) if ii > 0 => ThetaRule::Copy(grid.node(ii, jj)),
                    _ => ThetaRule::Full,
                },
                NodeSite::Side => match inner(j) {
                    Some(jj) if grid.periodic || (i > 0 && i + 1 < nc) => ThetaRule::Copy(grid.node(i, jj)),
                    _ => ThetaRule::Full,
                },
            }
        })
        .collect()
}

/// Inputs of one mass-conserving solve besides the film state.
pub(super) struct JfoSolve<'a> {
    pub geom: &'a FilmGeometry,
    pub a_raw: &'a [f64],
    /// Right-hand side of the orifice supply (no Couette, no squeeze).
    pub f: &'a [f64],
    pub h_qp: &'a [[f64; 4]],
    pub squeeze: Option<&'a SampledField>,
    pub surface_speed: f64,
    pub inlet: Inlet,
}

/// What one solve leaves behind.
pub(super) struct JfoResult<'a> {
    pub p: &'a mut [f64],
    pub theta: &'a mut [f64],
    pub cavitated: &'a mut [bool],
    pub r: &'a mut [f64],
}

impl JfoState {
    /// Solves the complementarity problem (module documentation), starting from the cavitated set in
    /// `out.cavitated`.
    pub(super) fn solve(&mut self, inp: &JfoSolve<'_>, out: &mut JfoResult<'_>) -> Result<FilmSolveInfo, FilmError> {
        let g = inp.geom;
        let n = g.n_nodes();
        // Operators of this thickness.
        self.a.fill(0.0);
        for (k, &(rc, cr)) in self.sym_to_full.iter().enumerate() {
            self.a[rc] = inp.a_raw[k];
            self.a[cr] = inp.a_raw[k];
        }
        let mut t = std::mem::take(&mut self.t);
        t.fill(0.0);
        self.add_couette(g, inp.surface_speed, inp.h_qp, &mut t);
        self.limit(&mut t, true);
        self.t = t;
        self.set_inlet(inp.inlet, g.sym);
        if let Some(sq) = inp.squeeze {
            let mut t = std::mem::take(&mut self.t);
            self.add_squeeze(g, &sq.qp, &mut t);
            self.t = t;
        }
        let (mut sa, mut st) = (0.0, 0.0);
        for i in 0..n {
            sa += self.a[self.pattern.diag[i]].abs();
            st += self.t[self.pattern.diag[i]].abs();
        }
        self.scale = if sa > 0.0 && st > 0.0 { st / sa } else { 1.0 };
        for i in 0..n {
            if self.rule[i] != ThetaRule::Free {
                out.cavitated[i] = false;
            }
        }
        let mut info = FilmSolveInfo::default();
        self.fallbacks = 0;
        let mut rhs = vec![0.0; n];
        let mut known = vec![0.0; n];
        let mut next = out.cavitated.to_vec();
        // The sets the mixed matrix was last filled for (its columns of other nodes are kept).
        let mut filled = out.cavitated.to_vec();
        let mut stalled = false;
        loop {
            info.active_set_iterations += 1;
            let first = info.active_set_iterations == 1;
            self.fill_matrix(out.cavitated, (!first).then_some(&filled[..]));
            filled.copy_from_slice(out.cavitated);
            info.factorizations += self.solve_sets(inp, out, &mut rhs, &mut known, first)?;
            let p_scale = out.p.iter().fold(0.0_f64, |m, v| m.max(v.abs())).max(f64::MIN_POSITIVE);
            let mut changed = 0;
            for i in (0..n).filter(|&i| self.rule[i] == ThetaRule::Free) {
                // Stay cavitated while the oil does not fill the gap; rupture where the pressure goes negative.
                next[i] = if out.cavitated[i] { out.theta[i] <= 1.0 + TOL } else { out.p[i] < -TOL * p_scale };
                if next[i] != out.cavitated[i] {
                    changed += 1;
                }
            }
            if changed == 0 {
                break;
            }
            if info.active_set_iterations >= MAX_JFO_ITERATIONS {
                let viol_p = out.p.iter().fold(0.0_f64, |m, &v| m.max(-v)) / p_scale;
                let viol_t = out.theta.iter().fold(0.0_f64, |m, &v| m.max(v - 1.0));
                info.complementarity = viol_p.max(viol_t);
                info.warnings.push(FilmWarning::ActiveSetChanging {
                    iterations: info.active_set_iterations,
                    changed_nodes: changed,
                    complementarity: info.complementarity,
                });
                stalled = true;
                break;
            }
            out.cavitated.copy_from_slice(&next);
        }
        // Residual of the unmodified equations: reactions at the boundary, ~0 at free nodes.
        self.pattern.matvec(&self.a, out.p, out.r);
        self.pattern.matvec(&self.t, out.theta, &mut rhs);
        for i in 0..n {
            out.r[i] += rhs[i] - inp.f[i];
        }
        if stalled {
            for v in out.p.iter_mut() {
                *v = v.max(0.0);
            }
        }
        info.cavitated_nodes = out.cavitated.iter().filter(|&&c| c).count();
        info.pivoted_factorizations = self.fallbacks;
        Ok(info)
    }

    /// One linear solve for the sets the mixed matrix was filled for: fills p and θ. The first step of a
    /// solve factorises; later steps update the factorisation when few columns changed (`jfo_update.rs`).
    /// Returns how many times it factorised (0, 1, or 2 after a refused factorisation without row exchanges).
    fn solve_sets(
        &mut self,
        inp: &JfoSolve<'_>,
        out: &mut JfoResult<'_>,
        rhs: &mut [f64],
        known: &mut [f64],
        first: bool,
    ) -> Result<usize, FilmError> {
        let n = self.pattern.n;
        let factorised = self.update_or_factor(out.cavitated, first)?;
        // Known film fractions (1 on P, θ_in at the inlet, copies of those) and known pressures (0).
        self.known_theta(out.cavitated, known);
        self.pattern.matvec(&self.t, known, rhs);
        for i in 0..n {
            rhs[i] = if self.rule[i] == ThetaRule::Free { inp.f[i] - rhs[i] } else { 0.0 };
        }
        let refactorised = self.solve_checked(rhs, out.cavitated)?;
        for i in 0..n {
            if self.rule[i] != ThetaRule::Free {
                out.p[i] = 0.0;
            } else if out.cavitated[i] {
                out.p[i] = 0.0;
                out.theta[i] = rhs[i] / self.scale;
            } else {
                out.p[i] = rhs[i];
                out.theta[i] = 1.0;
            }
        }
        self.boundary_theta(out.cavitated, out.theta);
        Ok(usize::from(factorised) + usize::from(refactorised))
    }

    /// The mixed matrix for the cavitated set `cav`: A columns for pressurised nodes, scaled T̃ + S columns
    /// for cavitated ones (with the columns of the outflow nodes that copy them folded in), identity rows
    /// for the boundary nodes. With `filled`, the sets the matrix holds now, only the columns of the nodes
    /// that changed set are filled again (the same values as a full fill, entry by entry).
    pub(super) fn fill_matrix(&mut self, cav: &[bool], filled: Option<&[bool]>) {
        let p = &self.pattern;
        let changed = |c: usize| filled.is_none_or(|f| f[c] != cav[c]);
        for c in (0..p.n).filter(|&c| changed(c)) {
            let range = p.col_ptr[c]..p.col_ptr[c + 1];
            match (self.rule[c], cav[c]) {
                (ThetaRule::Free, false) => self.m[range.clone()].copy_from_slice(&self.a[range]),
                (ThetaRule::Free, true) => {
                    for k in range {
                        self.m[k] = self.t[k] / self.scale;
                    }
                }
                _ => self.m[range].fill(0.0),
            }
        }
        for (j, pairs) in &self.folds {
            let ThetaRule::Copy(k) = self.rule[*j] else { continue };
            if cav[k] && changed(k) {
                for &(pj, pk) in pairs {
                    self.m[pk] += self.t[pj] / self.scale;
                }
            }
        }
        if filled.is_none() {
            for r in 0..p.n {
                if self.rule[r] != ThetaRule::Free {
                    p.set_identity_row(&mut self.m, r);
                }
            }
        } else {
            // The refilled columns' entries in the boundary rows (the identity rows are kept).
            for c in (0..p.n).filter(|&c| changed(c)) {
                for k in p.col_ptr[c]..p.col_ptr[c + 1] {
                    if self.rule[p.row_idx[k]] != ThetaRule::Free {
                        self.m[k] = 0.0;
                    }
                }
            }
        }
    }

    /// Film fractions known for the sets `cav` (0 where θ is an unknown).
    fn known_theta(&self, cav: &[bool], known: &mut [f64]) {
        for (i, v) in known.iter_mut().enumerate() {
            *v = match self.rule[i] {
                ThetaRule::Free => f64::from(u8::from(!cav[i])),
                ThetaRule::Inlet => self.theta_in,
                ThetaRule::Copy(k) => f64::from(u8::from(!cav[k])),
                ThetaRule::Full => 1.0,
            };
        }
    }

    /// The boundary nodes' film fractions from the free ones.
    fn boundary_theta(&self, cav: &[bool], theta: &mut [f64]) {
        for i in 0..theta.len() {
            theta[i] = match self.rule[i] {
                ThetaRule::Free => theta[i],
                ThetaRule::Inlet => self.theta_in,
                ThetaRule::Copy(k) => {
                    if cav[k] {
                        theta[k]
                    } else {
                        1.0
                    }
                }
                ThetaRule::Full => 1.0,
            };
        }
    }
}
