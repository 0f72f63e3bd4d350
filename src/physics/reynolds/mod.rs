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
//! plane of a half model, and periodicity in `s` for a 360° sector. The leading edge may instead carry a
//! given pressure `p_le cos(π z/L)` (the ram pressure, peak `p_le` on the mid-plane, ambient at the axial
//! ends; docs/MODEL.md §2.2), imposed by lifting: the known nodal values move to the right-hand side,
//! `A_ff p_f = b_f − A_fd p_d`.
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
//!
//! ## Files
//! This file holds the inputs, the solver state and the film thickness; `geometry.rs` what is built once
//! per mesh (quadrature, pattern, sampled shapes, orifice operators); `solve.rs` assembly and both
//! cavitation solves; `linearize.rs` forces and their perturbations; `outputs.rs` flows, friction and
//! extrema; `injection.rs` the response to the injection pressure; `jfo.rs`, `jfo_operators.rs` and
//! `jfo_linearize.rs` the mass-conserving (JFO) solve, its operators and its linearisation,
//! `jfo_update.rs` the low-rank updates of its factorisation between active-set steps and `jfo_onset.rs`
//! its pressure-free range along a coordinate (a floating pad's onset of pressure).

use crate::fem::{SolverError, SpdSolver};
use crate::mesh::grid::NodeSite;
use crate::model::Cavitation;
use crate::physics::turbulence::{Factors, TurbulenceLaw};
use nalgebra::DMatrix;
use serde::{Deserialize, Serialize};
use thiserror::Error;

mod geometry;
mod injection;
mod jfo;
mod jfo_exchange;
mod jfo_linearize;
mod jfo_onset;
mod jfo_operators;
#[cfg(test)]
mod jfo_tests;
mod jfo_update;
mod linearize;
mod outputs;
mod solve;
pub use geometry::{FilmGeometry, OrificeOperator};
pub use injection::InjectionResponse;
pub use jfo::MAX_JFO_ITERATIONS;
pub use jfo_exchange::NodeExchange;

/// Largest number of active-set iterations for the Reynolds cavitation condition.
pub const MAX_ACTIVE_SET_ITERATIONS: usize = 60;

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
    /// Laminar or turbulent Poiseuille and Couette coefficients ([`crate::physics::turbulence`]).
    pub turbulence: TurbulenceLaw,
    /// Oil supply at the leading edge (read by the mass-conserving cavitation option only).
    pub inlet: Inlet,
    /// Peak pressure on the leading edge [Pa] (the ram pressure of the oil entering the gap; 0: ambient),
    /// on the pad's mid-plane: the edge carries `p_le cos(π z/L)`, ambient at the axial ends (`z = ±L/2`).
    /// Reynolds and Gümbel cavitation only.
    pub leading_edge_pressure: f64,
}

/// Oil supply at a pad's leading edge.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum Inlet {
    /// The leading edge is bathed in oil: the film enters full (film fraction 1).
    #[default]
    Flooded,
    /// The pad is offered this flow [m³/s, whole pad]: the inlet film fraction is the flow over the Couette
    /// inflow of a full inlet, at most 1 (docs/MODEL.md §2.3).
    Supply { flow_m3_s: f64 },
}

/// The film viscosity.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Viscosity<'a> {
    Uniform(f64),
    /// Nodal values, interpolated bilinearly to the quadrature points.
    Nodal(&'a [f64]),
}

/// Failure of a film solve.
#[derive(Debug, Clone, PartialEq, Error, Serialize, Deserialize)]
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
    /// Mass-conserving cavitation: factorisations (of `factorizations`) that the factorisation without row
    /// exchanges refused or solved inaccurately, done again with the pivoting LU (`jfo_update.rs`).
    pub pivoted_factorizations: usize,
    /// Largest complementarity violation relative to the peak pressure (0 when converged).
    pub complementarity: f64,
    pub warnings: Vec<FilmWarning>,
}

/// What a film solve warns about.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum FilmWarning {
    /// The cavitation active set still changed after the iteration limit: the set of the last factorisation
    /// is kept, with the largest complementarity violation (relative).
    ActiveSetChanging { iterations: usize, changed_nodes: usize, complementarity: f64 },
}

impl std::fmt::Display for FilmWarning {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::ActiveSetChanging { iterations, changed_nodes, complementarity } => write!(
                f,
                "cavitation active set still changing after {iterations} iterations ({changed_nodes} nodes); \
                 largest complementarity violation {complementarity:.2e} (relative)"
            ),
        }
    }
}

/// Flows of one pad [m³/s], for the whole pad (symmetry already applied).
#[derive(Debug, Clone, Copy, Default, PartialEq, serde::Serialize, serde::Deserialize)]
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
    /// Turbulence multipliers at the quadrature points of the last solve (empty: laminar film).
    turb_qp: Vec<[Factors; 4]>,
    /// Pressure [Pa] (non-negative after cavitation).
    pub p: Vec<f64>,
    /// Unclipped pressure of the Gümbel solve.
    p_full: Vec<f64>,
    /// Cavitated nodes (active set or clipped).
    pub cavitated: Vec<bool>,
    /// Film fraction θ at the nodes: the mass-conserving solve's (1 in full film, the oil's share of the gap
    /// in ruptured zones); 1 everywhere after a Reynolds or Gümbel solve, which do not compute it.
    pub theta: Vec<f64>,
    /// The mass-conserving solver (built on its first use).
    jfo: Option<Box<jfo::JfoState>>,
    fixed: Vec<bool>,
    /// Leading-edge nodes that carry the leading-edge pressure (the corners on the axial ends excluded), each
    /// with its share `cos(π z/L)` of the peak.
    leading: Vec<(usize, f64)>,
    /// The peak leading-edge pressure of the last solve [Pa].
    leading_edge_pressure: f64,
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
        let last_row = geom.grid.n_rows() - 1;
        let leading = (0..n)
            .filter_map(|k| {
                let (_, j) = geom.grid.col_row(k);
                let on_edge = geom.sites[k] == NodeSite::Leading && j != last_row && (geom.grid.half || j != 0);
                on_edge.then(|| (k, ram_profile(&geom.grid, j)))
            })
            .collect();
        Ok(Self {
            solver,
            a_raw: vec![0.0; nnz],
            a_work: vec![0.0; nnz],
            b: vec![0.0; n],
            h: SampledField { qp: vec![[0.0; 4]; ne], node: vec![0.0; n] },
            mu_qp: vec![[0.0; 4]; ne],
            turb_qp: Vec::new(),
            p: vec![0.0; n],
            p_full: vec![0.0; n],
            cavitated: vec![false; n],
            theta: vec![1.0; n],
            jfo: None,
            fixed: vec![false; n],
            leading,
            leading_edge_pressure: 0.0,
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
    /// (whose pressure-free set needs a solve), for a pressurised leading edge (never pressure-free) or when no
    /// such coordinate value exists. Mass-conserving cavitation: the range where the all-cavitated film's
    /// fraction nowhere exceeds one, which extends the Reynolds condition's range (`jfo_onset.rs`).
    #[must_use]
    pub fn pressure_free_interval(&self, q: &[f64], slot: usize, inp: &FilmInputs<'_>) -> Option<(f64, f64)> {
        if inp.leading_edge_pressure != 0.0 {
            return None;
        }
        match inp.cavitation {
            Cavitation::Reynolds => self.reynolds_pressure_free(q, slot, inp),
            Cavitation::Jfo => self.jfo_pressure_free(q, slot, inp, self.reynolds_pressure_free(q, slot, inp)?),
            Cavitation::Gumbel => None,
        }
    }

    /// The Reynolds condition's pressure-free range (the right-hand side non-positive at every free node).
    fn reynolds_pressure_free(&self, q: &[f64], slot: usize, inp: &FilmInputs<'_>) -> Option<(f64, f64)> {
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

    /// The turbulence multipliers at the quadrature points for the current thickness and viscosity; left
    /// empty for a laminar film (and where every point lies below the transition band), so that the laminar
    /// solve runs exactly the laminar arithmetic.
    fn set_turbulence(&mut self, inp: &FilmInputs<'_>) -> Result<(), FilmError> {
        self.turb_qp.clear();
        let law = &inp.turbulence;
        if law.is_laminar() {
            return Ok(());
        }
        if !(law.density > 0.0 && law.density.is_finite() && law.re_start < law.re_end) {
            return Err(FilmError::Input(format!(
                "turbulence needs a positive density and a transition band start < end (ρ {}, band {}–{})",
                law.density, law.re_start, law.re_end
            )));
        }
        let u = inp.surface_speed;
        let (h, mu) = (&self.h.qp, &self.mu_qp);
        let re = |e: usize, k: usize| law.reynolds(u, h[e][k], mu[e][k]);
        // A film below the band everywhere keeps the laminar path (and allocates nothing).
        if !(0..h.len()).any(|e| (0..4).any(|k| law.intermittency(re(e, k)).0 > 0.0)) {
            return Ok(());
        }
        self.turb_qp.extend((0..h.len()).map(|e| std::array::from_fn(|k| law.factors(re(e, k)))));
        Ok(())
    }

    /// Turbulence multipliers at the quadrature points of the last solve; `None` when the film was laminar
    /// everywhere.
    #[must_use]
    pub fn turbulence_qp(&self) -> Option<&[[Factors; 4]]> {
        (!self.turb_qp.is_empty()).then_some(&self.turb_qp)
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
                    return Err(FilmError::Input(
                        "nodal viscosity field has the wrong length or a non-positive value".into(),
                    ));
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
}

/// The leading-edge pressure's share at row `j`: `cos(π z/L)`, 1 on the pad's mid-plane (`z = 0`, where a
/// half model starts) and 0 at the axial ends (`z = ±L/2`). The oil brought to rest against the leading edge
/// escapes sideways at the ends, which are ambient; a profile continuous to ambient there has finite flows at
/// the corners, where a uniform edge pressure would meet the ends' ambient in a jump whose corner flow has no
/// mesh limit (docs/MODEL.md §2.2).
fn ram_profile(grid: &crate::mesh::grid::PadGrid, j: usize) -> f64 {
    let (first, last) = (grid.z[0], grid.z[grid.z.len() - 1]);
    let (mid, length) = if grid.half { (0.0, 2.0 * last) } else { (0.5 * (first + last), last - first) };
    (std::f64::consts::PI * (grid.z[j] - mid) / length).cos()
}
