//! Dynamic coefficients: full stiffness, damping and inertia over journal and pad coordinates, and their
//! reduction to the journal at an excitation frequency.
//!
//! Full matrices, size `2 + Σ pad dofs` (docs/MODEL.md §7): `K = K_film + K_structural`, `C = C_film`, `M` the pads'
//! rigid-body inertia (zero on the journal block, which belongs to the rotor). The film parts come from the
//! analytic perturbation of each pad's film at the converged equilibrium.
//!
//! Reduction (dynamic condensation) at ω: `Z(ω) = K + iωC − ω²M`, `Z_red = Z_jj − Z_jp Z_pp⁻¹ Z_pj`,
//! `K_red = Re Z_red`, `C_red = Im Z_red / ω`. At ω = 0 the damping is the ω → 0 limit
//! `C_jj − C_jp K_pp⁻¹ K_pj − K_jp K_pp⁻¹ C_pj + K_jp K_pp⁻¹ C_pp K_pp⁻¹ K_pj`.

use nalgebra::{Complex, DMatrix};
use serde::{Deserialize, Serialize};

use crate::bearing::equilibrium::Equilibrium;
use crate::bearing::film::coordinates::{Coord, JOURNAL_DOFS};
use crate::bearing::film::model::BearingModel;

/// Full coefficient matrices and what each row means.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct FullCoefficients {
    /// The coordinate of each row and column: journal x, y, then each pad's coordinates.
    pub coords: Vec<Coord>,
    /// Stiffness [N/m, N/rad, N·m/m, N·m/rad by block].
    pub k: Vec<Vec<f64>>,
    /// Damping [N·s/m, …].
    pub c: Vec<Vec<f64>>,
    /// Pad inertia [kg, kg·m, kg·m²].
    pub m: Vec<Vec<f64>>,
}

impl FullCoefficients {
    /// Row (and column) of a coordinate.
    #[must_use]
    pub fn index(&self, c: Coord) -> Option<usize> {
        self.coords.iter().position(|x| *x == c)
    }
}

/// Reduced 2×2 journal coefficients (rows/cols x, y).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct ReducedCoefficients {
    /// Excitation frequency ω [rad/s].
    pub omega_rad_s: f64,
    pub k_n_per_m: [[f64; 2]; 2],
    pub c_ns_per_m: [[f64; 2]; 2],
}

fn to_rows(m: &DMatrix<f64>) -> Vec<Vec<f64>> {
    (0..m.nrows()).map(|i| (0..m.ncols()).map(|j| m[(i, j)]).collect()).collect()
}

/// Assembles the full matrices at an equilibrium: each pad's film block scattered through the model's
/// [`DofMap`](crate::bearing::film::coordinates::DofMap), plus its structural stiffness and inertia.
#[must_use]
pub fn full_coefficients(model: &BearingModel, eq: &Equilibrium) -> FullCoefficients {
    let n = model.n_dofs();
    let mut k = DMatrix::zeros(n, n);
    let mut c = DMatrix::zeros(n, n);
    let mut m = DMatrix::zeros(n, n);
    for (p, (pm, st)) in model.pads.iter().zip(&eq.pads).enumerate() {
        model.dofs.scatter_add(p, &st.lin.stiffness, &mut k);
        model.dofs.scatter_add(p, &st.lin.damping, &mut c);
        model.dofs.scatter_add_pad_block(p, &pm.structure.stiffness, &mut k);
        model.dofs.scatter_add_pad_block(p, &pm.structure.mass, &mut m);
    }
    FullCoefficients { coords: model.dofs.coords(), k: to_rows(&k), c: to_rows(&c), m: to_rows(&m) }
}

fn mat(rows: &[Vec<f64>]) -> DMatrix<f64> {
    let n = rows.len();
    DMatrix::from_fn(n, n, |i, j| rows[i][j])
}

/// Pad coordinates that take part in the condensation: those connected to the journal through non-zero
/// stiffness, damping or inertia couplings (directly or through other pad coordinates). The others — the
/// coordinates of a floating pad, whose film carries nothing — are decoupled and dropped.
pub(crate) fn active_pad_dofs(k: &DMatrix<f64>, c: &DMatrix<f64>, m: &DMatrix<f64>) -> Vec<usize> {
    let n = k.nrows();
    let scale = [k, c, m]
        .iter()
        .map(|a| a.iter().fold(0.0_f64, |s, v| s.max(v.abs())))
        .fold(0.0_f64, f64::max)
        .max(f64::MIN_POSITIVE);
    let coupled = |i: usize, j: usize| {
        [k, c, m].iter().any(|a| a[(i, j)].abs() > 1e-14 * scale || a[(j, i)].abs() > 1e-14 * scale)
    };
    let mut reached = vec![false; n];
    let mut stack: Vec<usize> = (0..JOURNAL_DOFS).collect();
    for &j in &stack {
        reached[j] = true;
    }
    while let Some(i) = stack.pop() {
        for j in JOURNAL_DOFS..n {
            if !reached[j] && coupled(i, j) {
                reached[j] = true;
                stack.push(j);
            }
        }
    }
    (JOURNAL_DOFS..n).filter(|&i| reached[i]).collect()
}

/// Reduces the full matrices to the journal at excitation frequency `omega` [rad/s].
#[must_use]
pub fn reduce(full: &FullCoefficients, omega: f64) -> ReducedCoefficients {
    let (k, c, m) = (mat(&full.k), mat(&full.c), mat(&full.m));
    let p = active_pad_dofs(&k, &c, &m);
    let np = p.len();
    let sub = |a: &DMatrix<f64>, rows: &[usize], cols: &[usize]| {
        DMatrix::from_fn(rows.len(), cols.len(), |i, j| a[(rows[i], cols[j])])
    };
    let j = [0usize, 1];
    let mut kr = [[k[(0, 0)], k[(0, 1)]], [k[(1, 0)], k[(1, 1)]]];
    let mut cr = [[c[(0, 0)], c[(0, 1)]], [c[(1, 0)], c[(1, 1)]]];
    if np == 0 {
        return ReducedCoefficients { omega_rad_s: omega, k_n_per_m: kr, c_ns_per_m: cr };
    }
    if omega > 0.0 {
        let z = |a: &[usize], b: &[usize]| {
            let (ks, cs, ms) = (sub(&k, a, b), sub(&c, a, b), sub(&m, a, b));
            DMatrix::from_fn(a.len(), b.len(), |i, jj| {
                Complex::new(ks[(i, jj)] - omega * omega * ms[(i, jj)], omega * cs[(i, jj)])
            })
        };
        let (zjj, zjp, zpj, zpp) = (z(&j, &j), z(&j, &p), z(&p, &j), z(&p, &p));
        if let Some(x) = zpp.lu().solve(&zpj) {
            let zr = zjj - zjp * x;
            for a in 0..2 {
                for b in 0..2 {
                    kr[a][b] = zr[(a, b)].re;
                    cr[a][b] = zr[(a, b)].im / omega;
                }
            }
        }
    } else {
        let (kjj, kjp, kpj, kpp) = (sub(&k, &j, &j), sub(&k, &j, &p), sub(&k, &p, &j), sub(&k, &p, &p));
        let (cjj, cjp, cpj, cpp) = (sub(&c, &j, &j), sub(&c, &j, &p), sub(&c, &p, &j), sub(&c, &p, &p));
        let lu = kpp.lu();
        if let (Some(a), Some(bt)) = (lu.solve(&kpj), lu.solve(&cpj)) {
            // a = K_pp⁻¹ K_pj, bt = K_pp⁻¹ C_pj
            let kred = &kjj - &kjp * &a;
            let cred =
                &cjj - &cjp * &a - &kjp * &bt + &kjp * lu.solve(&(&cpp * &a)).unwrap_or_else(|| DMatrix::zeros(np, 2));
            for x in 0..2 {
                for y in 0..2 {
                    kr[x][y] = kred[(x, y)];
                    cr[x][y] = cred[(x, y)];
                }
            }
        }
    }
    ReducedCoefficients { omega_rad_s: omega, k_n_per_m: kr, c_ns_per_m: cr }
}
