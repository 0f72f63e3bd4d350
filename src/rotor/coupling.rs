//! Rotor–bearing coupling: the system matrices at one spin speed.
//!
//! ```text
//! M_s ü + (C_s + Ω G + C_b) u̇ + (K_s + K_b) u = f,   u = [shaft coordinates…, appended pad coordinates…]
//! ```
//! A bearing at node n enters either with its **full** coefficients (docs/MODEL.md §7: `K`, `C`, `M` over the
//! journal x, y and every active pad coordinate): the journal block adds to node n's x, y; each pad
//! coordinate is appended to `u` with its row of K, C, M and its couplings to node n's x, y — or with
//! **reduced** 2×2 `K`, `C` (synchronous: condensed at the running speed Ω), added to node n's x, y only.
//! Signs: bearing coefficients are `−∂F/∂q` of the film forces on the journal and the generalised film forces
//! on the pad coordinates, so they add to the rotor's K and C as they are. Decoupled pad coordinates (a
//! floating pad whose film carries nothing) are left out, as the reduction leaves them out.

use nalgebra::DMatrix;

use super::assembly::{NodeDof, ShaftModel, Weights};
use crate::bearing::film::coordinates::{Coord, JOURNAL_DOFS};
use crate::bearing::solution::coefficients::{active_pad_dofs, reduce, FullCoefficients};

/// The coefficients of one bearing position at one speed.
#[derive(Debug, Clone, PartialEq)]
pub enum BearingCoefficients {
    /// 2×2 K [N/m], C [N·s/m] over (x, y).
    Reduced { k: [[f64; 2]; 2], c: [[f64; 2]; 2] },
    /// Full matrices over journal and pad coordinates.
    Full(FullCoefficients),
}

impl BearingCoefficients {
    /// Synchronous reduction at `omega` [rad/s] (a reduced set is returned as it is).
    #[must_use]
    pub fn reduced(&self, omega: f64) -> Self {
        match self {
            Self::Reduced { .. } => self.clone(),
            Self::Full(f) => {
                let r = reduce(f, omega);
                Self::Reduced { k: r.k_n_per_m, c: r.c_ns_per_m }
            }
        }
    }
}

/// One appended coordinate: which bearing position and which of its coordinates.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct AppendedDof {
    pub bearing: usize,
    pub coord: Coord,
}

/// System matrices at one speed.
#[derive(Debug, Clone)]
pub struct System {
    pub n_shaft: usize,
    pub appended: Vec<AppendedDof>,
    pub mass: DMatrix<f64>,
    pub damping: DMatrix<f64>,
    pub stiffness: DMatrix<f64>,
}

impl System {
    #[must_use]
    pub fn n_dofs(&self) -> usize {
        self.n_shaft + self.appended.len()
    }
}

fn mat(rows: &[Vec<f64>]) -> DMatrix<f64> {
    DMatrix::from_fn(rows.len(), rows.len(), |i, j| rows[i][j])
}

/// Adds `local[a][b]` entries of a bearing matrix over its coordinates `local` (placed at `rows`) to `target`.
fn scatter(target: &mut DMatrix<f64>, rows: &[Weights], local: &[usize], values: &[Vec<f64>]) {
    for (a, ra) in local.iter().zip(rows) {
        for (b, rb) in local.iter().zip(rows) {
            let v = values[*a][*b];
            if v == 0.0 {
                continue;
            }
            for &(i, wi) in ra {
                for &(j, wj) in rb {
                    target[(i, j)] += wi * wj * v;
                }
            }
        }
    }
}

/// Assembles the system at spin speed `omega` [rad/s] with bearing `i` at node `nodes[i]` carrying `bearings[i]`.
#[must_use]
pub fn assemble(shaft: &ShaftModel, nodes: &[usize], bearings: &[BearingCoefficients], omega: f64) -> System {
    let ns = shaft.n_dofs();
    // Which pad coordinates each bearing appends.
    let mut appended = Vec::new();
    let mut active = Vec::new();
    for (b, coeffs) in bearings.iter().enumerate() {
        let act = match coeffs {
            BearingCoefficients::Reduced { .. } => Vec::new(),
            BearingCoefficients::Full(f) => {
                let act = active_pad_dofs(&mat(&f.k), &mat(&f.c), &mat(&f.m));
                appended.extend(act.iter().map(|&i| AppendedDof { bearing: b, coord: f.coords[i] }));
                act
            }
        };
        active.push(act);
    }
    let n = ns + appended.len();
    let grow = |a: &DMatrix<f64>| {
        let mut g = DMatrix::zeros(n, n);
        g.view_mut((0, 0), (ns, ns)).copy_from(a);
        g
    };
    let mut mass = grow(&shaft.mass);
    let mut stiffness = grow(&shaft.stiffness);
    let mut damping = grow(&(&shaft.damping + &shaft.gyroscopic * omega));
    let mut next = ns;
    for ((&node, coeffs), act) in nodes.iter().zip(bearings).zip(&active) {
        // each local coordinate as working coordinates: the journal through the shaft's weights (one to one on
        // an unreduced shaft or a reduced one's boundary), the pad coordinates appended
        let journal = [shaft.weights(node, NodeDof::X), shaft.weights(node, NodeDof::Y)];
        match coeffs {
            BearingCoefficients::Reduced { k, c } => {
                let kv: Vec<Vec<f64>> = k.iter().map(|r| r.to_vec()).collect();
                let cv: Vec<Vec<f64>> = c.iter().map(|r| r.to_vec()).collect();
                let local = [0, 1];
                scatter(&mut stiffness, &journal, &local, &kv);
                scatter(&mut damping, &journal, &local, &cv);
            }
            BearingCoefficients::Full(f) => {
                // local index in f → working coordinates of the system
                let local: Vec<usize> = (0..JOURNAL_DOFS).chain(act.iter().copied()).collect();
                let rows: Vec<Weights> =
                    journal.iter().cloned().chain((next..next + act.len()).map(|g| vec![(g, 1.0)])).collect();
                scatter(&mut stiffness, &rows, &local, &f.k);
                scatter(&mut damping, &rows, &local, &f.c);
                scatter(&mut mass, &rows, &local, &f.m);
                next += act.len();
            }
        }
    }
    System { n_shaft: ns, appended, mass, damping, stiffness }
}
