//! The pressure-free range of a mass-conserving film along one coordinate (docs/MODEL.md §2.3): where a
//! floating pad's onset of pressure lies, found without a film solve.
//!
//! ## Equation
//! `p ≡ 0` solves the complementarity problem (`jfo.rs`) exactly when every free node cavitated leaves a
//! film fraction that nowhere fills the gap: with the thickness `h(x) = h₀ + x φ` along the coordinate `x`,
//!
//! ```text
//! T̃(x) θ = f   at the free nodes (θ_in at the inlet, outflow nodes copying their neighbour),   g(x) = max θ − 1 ≤ 0
//! T̃(x) = limit(T[h₀] + x T[φ]) + S,   f the orifice supply at zero film pressure
//! ```
//!
//! The Couette operator of the oil is upwinded, so along the sliding direction each column of nodes
//! receives oil only from the columns upstream of it: one sweep of the columns from the leading edge, each
//! column a tridiagonal solve over its nodes (the couplings between rows of a column; an outflow node's
//! column folded into the node it copies), solves the system; whatever the sweep lags (a squeeze, a
//! periodic sector, a reversed sliding direction) is taken by repeated sweeps until no film fraction
//! changes; a sweep that used no film fraction before updating it has solved the system exactly and ends it.
//! What each entry of a free node's row is to the sweep (the row's own unknown, its neighbour above or below
//! in the grid column, or a known film fraction) is found once per search. Each evaluation of `g` costs a
//! few passes over the matrix entries instead of a sparse LU.
//!
//! A film that is pressure-free under the Reynolds condition (`pressure_free_interval`, whose right-hand side
//! is `f − T̃ 1`) is pressure-free here too (the upwinded transport is monotone: `T̃ (1 − θ) ≥ 0` gives
//! `θ ≤ 1`), and the mass-conserving film stays pressure-free further on, as long as the oil that the
//! diverging part of the film has spread out does not fill the converging part. The end of the range is
//! bracketed from the Reynolds range's end to where the film closes, and found by regula falsi (Illinois)
//! on `g` to [`END_TOLERANCE`] of the bracket; the pressure-free side of the final bracket is returned.

use crate::physics::reynolds::jfo::{JfoState, ThetaRule};
use crate::physics::reynolds::{FilmInputs, Inlet, PadFilm};

/// Width of the final bracket of the range's end, relative to the distance from the Reynolds range's end
/// to where the film closes.
const END_TOLERANCE: f64 = 1e-8;

/// Most evaluations of `g` in the search for the end.
const MAX_EVALUATIONS: usize = 40;

/// Most sweeps of one all-cavitated transport solve.
const MAX_SWEEPS: usize = 60;

/// The operators of a film with its coordinate `x` free: `T[h₀]` (plus nothing), `T[φ]` and the squeeze,
/// in the full storage of the mass-conserving solver.
struct Family<'a> {
    state: &'a JfoState,
    t0: Vec<f64>,
    t1: Vec<f64>,
    /// The squeeze operator, if the film has a squeeze velocity.
    squeeze: Option<Vec<f64>>,
    f: Vec<f64>,
    inlet: Inlet,
    sym: f64,
    /// Grid columns from the leading edge in the sliding direction, each with its free nodes by row.
    columns: Vec<Vec<usize>>,
    /// The row of every free node, in the order of `columns`, as the transport sweep reads it: the entries of
    /// free node `a` are `links[link_ptr[a]..link_ptr[a + 1]]` (built once per search, [`Family::links`]).
    link_ptr: Vec<usize>,
    links: Vec<(usize, Link)>,
}

/// What an entry of a free node's row is to the column sweep (`Family::transport`): the unknown of the row,
/// of its neighbour above or below in the same grid column, or a film fraction taken as known (with whether
/// the sweep may not have updated it yet).
#[derive(Debug, Clone, Copy, PartialEq)]
enum Link {
    Diagonal,
    Above,
    Below,
    Known { node: usize, lags: bool },
}

impl Family<'_> {
    /// `g(x)`: the largest film fraction of the all-cavitated film minus one; `None` when the transport
    /// solve does not settle.
    fn excess(&self, x: f64, t: &mut [f64], theta: &mut [f64]) -> Option<f64> {
        let s = self.state;
        let p = &s.pattern;
        for (k, v) in t.iter_mut().enumerate() {
            *v = self.t0[k] + x * self.t1[k];
        }
        limit_fresh(s, t);
        let theta_in = match self.inlet {
            Inlet::Flooded => 1.0,
            Inlet::Supply { flow_m3_s } => {
                let cap: f64 = (0..p.n)
                    .filter(|&j| s.rule[j] == ThetaRule::Inlet)
                    .map(|j| p.row_positions(j).iter().map(|&k| t[k]).sum::<f64>())
                    .sum();
                let q_cap = self.sym * cap / 12.0;
                if q_cap > 0.0 {
                    (flow_m3_s / q_cap).min(1.0)
                } else {
                    1.0
                }
            }
        };
        if let Some(squeeze) = &self.squeeze {
            for (v, sq) in t.iter_mut().zip(squeeze) {
                *v += sq;
            }
        }
        for (i, v) in theta.iter_mut().enumerate() {
            *v = match s.rule[i] {
                ThetaRule::Inlet => theta_in,
                ThetaRule::Full => 1.0,
                ThetaRule::Free | ThetaRule::Copy(_) => 0.0,
            };
        }
        self.transport(t, theta)?;
        (0..p.n).filter(|&i| s.rule[i] == ThetaRule::Free).map(|i| theta[i] - 1.0).reduce(f64::max)
    }

    /// The rows of the free nodes classified for the sweep (an outflow node's column belongs to the node it
    /// copies): the sweep then reads each entry once per evaluation without looking up its node.
    fn links(state: &JfoState, columns: &[Vec<usize>], column_at: &[usize]) -> (Vec<usize>, Vec<(usize, Link)>) {
        let p = &state.pattern;
        let mut col_of = vec![0; p.nnz()];
        for c in 0..p.n {
            col_of[p.col_ptr[c]..p.col_ptr[c + 1]].fill(c);
        }
        let (mut link_ptr, mut links) = (vec![0], Vec::new());
        for (at, free) in columns.iter().enumerate() {
            for (a, &r) in free.iter().enumerate() {
                let above = a.checked_sub(1).map(|b| free[b]);
                let below = free.get(a + 1).copied();
                for &k in p.row_positions(r) {
                    let c = match state.rule[col_of[k]] {
                        ThetaRule::Copy(j) => j,
                        _ => col_of[k],
                    };
                    let link = if c == r {
                        Link::Diagonal
                    } else if Some(c) == above {
                        Link::Above
                    } else if Some(c) == below {
                        Link::Below
                    } else {
                        Link::Known { node: c, lags: state.rule[c] == ThetaRule::Free && column_at[c] >= at }
                    };
                    links.push((k, link));
                }
                link_ptr.push(links.len());
            }
        }
        (link_ptr, links)
    }

    /// Solves `T̃ θ = f` at the free nodes by column sweeps (module documentation).
    fn transport(&self, t: &[f64], theta: &mut [f64]) -> Option<()> {
        let (mut lower, mut diag, mut upper, mut rhs) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
        for _ in 0..MAX_SWEEPS {
            let mut change = 0.0_f64;
            let mut size = 0.0_f64;
            // Whether the sweep used a film fraction it had not updated yet (then it is repeated).
            let mut lagged = false;
            let mut row = 0;
            for free in &self.columns {
                lower.clear();
                diag.clear();
                upper.clear();
                rhs.clear();
                for &r in free {
                    let (mut l, mut d, mut u, mut b) = (0.0, 0.0, 0.0, self.f[r]);
                    for &(k, link) in &self.links[self.link_ptr[row]..self.link_ptr[row + 1]] {
                        match link {
                            Link::Diagonal => d += t[k],
                            Link::Above => l += t[k],
                            Link::Below => u += t[k],
                            Link::Known { node, lags } => {
                                b -= t[k] * theta[node];
                                lagged |= t[k] != 0.0 && lags;
                            }
                        }
                    }
                    row += 1;
                    lower.push(l);
                    diag.push(d);
                    upper.push(u);
                    rhs.push(b);
                }
                // Thomas algorithm (the block is diagonally dominant by columns: no pivoting).
                for a in 1..free.len() {
                    let w = lower[a] / diag[a - 1];
                    diag[a] -= w * upper[a - 1];
                    rhs[a] -= w * rhs[a - 1];
                }
                for a in (0..free.len()).rev() {
                    let next = if a + 1 < free.len() { upper[a] * rhs[a + 1] } else { 0.0 };
                    rhs[a] = (rhs[a] - next) / diag[a];
                    let r = free[a];
                    change = change.max((rhs[a] - theta[r]).abs());
                    size = size.max(rhs[a].abs());
                    theta[r] = rhs[a];
                }
            }
            if !(change.is_finite() && size.is_finite()) {
                return None;
            }
            // A sweep that lagged nothing solved the system exactly (the usual upwinded film without squeeze).
            if !lagged || change <= 1e-14 * size.max(1.0) {
                return Some(());
            }
        }
        None
    }
}

/// The discrete upwinding of `jfo_operators.rs` with the branches chosen from `t` itself (the solver's
/// recorded branches are left alone).
fn limit_fresh(s: &JfoState, t: &mut [f64]) {
    let p = &s.pattern;
    for c in 0..p.n {
        for k in p.col_ptr[c]..p.col_ptr[c + 1] {
            let r = p.row_idx[k];
            if r <= c {
                continue;
            }
            let kt = s.transpose[k];
            let (own, tr) = (t[k], t[kt]);
            let d = if own >= tr && own > 0.0 {
                own
            } else if tr > own && tr > 0.0 {
                tr
            } else {
                0.0
            };
            if d != 0.0 {
                t[k] -= d;
                t[kt] -= d;
                t[p.diag[r]] += d;
                t[p.diag[c]] += d;
            }
        }
    }
}

impl PadFilm {
    /// [`PadFilm::pressure_free_interval`] for mass-conserving cavitation (module documentation): the
    /// Reynolds condition's range `reynolds` with its upper end moved to where the oil first fills the gap.
    /// `None` before the first mass-conserving solve (no solver state yet), when a transport solve does not
    /// settle or the oil fills the gap already at the Reynolds range's end; the Reynolds range when its end is
    /// open or the film never closes along the coordinate.
    pub(super) fn jfo_pressure_free(
        &self,
        q: &[f64],
        slot: usize,
        inp: &FilmInputs<'_>,
        reynolds: (f64, f64),
    ) -> Option<(f64, f64)> {
        let state = self.jfo.as_deref()?;
        let g = &self.geom;
        let (lo, a0) = reynolds;
        // Thickness without the coordinate, at the quadrature points and the nodes.
        let h0_qp: Vec<[f64; 4]> = (0..g.elements.len())
            .map(|e| {
                std::array::from_fn(|k| {
                    let mut h = g.base.qp[e][k];
                    for (j, qj) in q.iter().enumerate().filter(|&(j, _)| j != slot) {
                        h += qj * g.shapes[j].qp[e][k];
                    }
                    h + self.extra_h.as_ref().map_or(0.0, |x| x.qp[e][k])
                })
            })
            .collect();
        let phi = &g.shapes[slot];
        // Where the film closes: h₀ + x φ = 0 at the first node or quadrature point with φ < 0.
        let close = h0_qp
            .iter()
            .flatten()
            .zip(phi.qp.iter().flatten())
            .filter(|&(_, &f)| f < 0.0)
            .map(|(&h, &f)| h / -f)
            .fold(f64::INFINITY, f64::min);
        if !a0.is_finite() || !close.is_finite() || close <= a0 {
            return Some(reynolds);
        }
        let nnz = state.pattern.nnz();
        let (mut t0, mut t1) = (vec![0.0; nnz], vec![0.0; nnz]);
        state.add_couette(g, inp.surface_speed, &h0_qp, &mut t0);
        state.add_couette(g, inp.surface_speed, &phi.qp, &mut t1);
        let squeeze = self.squeeze.as_ref().map(|sq| {
            let mut s = vec![0.0; nnz];
            state.add_squeeze(g, &sq.qp, &mut s);
            s
        });
        let mut f = vec![0.0; g.n_nodes()];
        if inp.injection_pressure != 0.0 {
            for o in &g.orifices {
                for &(i, v) in &o.vector {
                    f[i] += inp.injection_pressure * v / inp.injection_viscosity;
                }
            }
        }
        let grid = &g.grid;
        let mut columns: Vec<Vec<usize>> = (0..grid.n_cols())
            .map(|i| {
                (0..grid.n_rows()).map(|j| grid.node(i, j)).filter(|&r| state.rule[r] == ThetaRule::Free).collect()
            })
            .collect();
        let mut order: Vec<usize> = (0..grid.n_cols()).collect();
        if inp.surface_speed < 0.0 {
            columns.reverse();
            order.reverse();
        }
        let mut column_at = vec![0; g.n_nodes()];
        for (at, &i) in order.iter().enumerate() {
            for j in 0..grid.n_rows() {
                column_at[grid.node(i, j)] = at;
            }
        }
        let p = &state.pattern;
        let (link_ptr, links) = Family::links(state, &columns, &column_at);
        let family = Family { state, t0, t1, squeeze, f, inlet: inp.inlet, sym: g.sym, columns, link_ptr, links };
        let mut t = vec![0.0; nnz];
        let mut theta = vec![0.0; p.n];
        let mut g_at = |x: f64| family.excess(x, &mut t, &mut theta);
        // The bracket: pressure-free at the Reynolds end, filled just short of closing.
        let (mut a, mut b) = (a0, a0 + (close - a0) * (1.0 - 1e-9));
        let (mut ga, mut gb) = (g_at(a)?, g_at(b)?);
        if ga > 0.0 {
            return None;
        }
        if gb <= 0.0 {
            return Some((lo, b));
        }
        let tol = END_TOLERANCE * (b - a);
        let mut side = 0;
        for _ in 0..MAX_EVALUATIONS {
            if b - a <= tol {
                return Some((lo, a));
            }
            let x = if gb != ga { b - gb * (b - a) / (gb - ga) } else { 0.5 * (a + b) };
            let x = if x > a && x < b { x } else { 0.5 * (a + b) };
            let gx = g_at(x)?;
            if gx <= 0.0 {
                (a, ga) = (x, gx);
                if side == -1 {
                    gb *= 0.5;
                }
                side = -1;
            } else {
                (b, gb) = (x, gx);
                if side == 1 {
                    ga *= 0.5;
                }
                side = 1;
            }
        }
        Some((lo, a))
    }
}
