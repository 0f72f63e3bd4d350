//! Shaft assembly: the rotor's own mass, stiffness, gyroscopic and proportional damping matrices, built once
//! per rotor.
//!
//! `M q̈ + (C_p + Ω G) q̇ + K q = f` over the shaft coordinates `q = [x₀, y₀, a₀, b₀, x₁, …]` (node-major,
//! [`NODE_DOFS`] per node, see [`super::element`]). Shaft elements are summed at their shared nodes; a rigid disk
//! adds `m` on x, y, its transverse inertia `I_d` on a, b and its polar inertia to `G` (`G[a, b] = I_p`,
//! `G[b, a] = −I_p`). Linear supports add an isotropic `k`, `c` on x, y. Proportional damping
//! `C_p = αM + βK` (Rayleigh) is tuned so that the free–free flexible modes `ω₁`, `ω₂` the user names have the
//! damping ratio ζ: `α = 2ζω₁ω₂/(ω₁ + ω₂)`, `β = 2ζ/(ω₁ + ω₂)` (free–free: shaft stiffness and all the
//! rotor's mass, no bearings or supports, at rest).

use nalgebra::{DMatrix, SymmetricEigen};

use super::element::{element_matrices, NODE_DOFS};
use super::error::RotorError;
use crate::model::rotor::Rotor;

/// Slot of a shaft coordinate.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum NodeDof {
    X = 0,
    Y = 1,
    A = 2,
    B = 3,
}

/// Global index of a node's coordinate.
#[must_use]
pub fn shaft_index(node: usize, dof: NodeDof) -> usize {
    node * NODE_DOFS + dof as usize
}

/// The rotor's own matrices (no bearings).
#[derive(Debug, Clone)]
pub struct ShaftModel {
    pub n_nodes: usize,
    /// Axial node positions [m].
    pub z_m: Vec<f64>,
    pub mass: DMatrix<f64>,
    /// Shaft bending and shear stiffness plus the linear supports.
    pub stiffness: DMatrix<f64>,
    /// Gyroscopic matrix per unit spin speed [kg·m²].
    pub gyroscopic: DMatrix<f64>,
    /// Proportional damping plus the supports' damping.
    pub damping: DMatrix<f64>,
    /// Free–free flexible natural frequencies of one plane [rad/s] (ascending, rigid modes removed).
    pub free_free_rad_s: Vec<f64>,
    /// `None`: the matrices are over the nodal coordinates; `Some`: over the working coordinates of a
    /// reduced shaft ([`super::reduction`]), which the basis maps back to the nodal ones.
    pub basis: Option<Basis>,
}

/// The working coordinates of a reduced shaft ([`super::reduction`]) → nodal coordinates.
#[derive(Debug, Clone)]
pub struct Basis {
    /// Nodal indices kept as the first working coordinates, in order.
    pub boundary: Vec<usize>,
    /// `u_nodal = t q` (nodal × working).
    pub t: DMatrix<f64>,
    /// Frequencies of the kept fixed-interface modes [rad/s], ascending.
    pub modal_rad_s: Vec<f64>,
}

/// A nodal coordinate as a combination of working coordinates: `(working index, weight)` pairs.
pub type Weights = Vec<(usize, f64)>;

impl ShaftModel {
    /// Number of shaft coordinates (working coordinates of a reduced shaft).
    #[must_use]
    pub fn n_dofs(&self) -> usize {
        self.mass.nrows()
    }

    /// Node `node`'s coordinate `dof` over the working coordinates (itself on an unreduced shaft or a
    /// reduced shaft's boundary; a row of the basis otherwise).
    #[must_use]
    pub fn weights(&self, node: usize, dof: NodeDof) -> Weights {
        let i = shaft_index(node, dof);
        match &self.basis {
            None => vec![(i, 1.0)],
            Some(b) => match b.boundary.iter().position(|&j| j == i) {
                Some(k) => vec![(k, 1.0)],
                None => (0..b.t.ncols()).filter(|&j| b.t[(i, j)] != 0.0).map(|j| (j, b.t[(i, j)])).collect(),
            },
        }
    }

    /// Assembles the shaft, disks, supports and proportional damping.
    ///
    /// # Errors
    /// [`RotorError::DampingMode`] when the damping names a mode the model does not have;
    /// [`RotorError::SingularMass`] when the mass matrix is not positive definite.
    pub fn new(rotor: &Rotor) -> Result<Self, RotorError> {
        let n_nodes = rotor.n_nodes();
        let n = n_nodes * NODE_DOFS;
        let (mut mass, mut stiffness, mut gyroscopic) =
            (DMatrix::zeros(n, n), DMatrix::zeros(n, n), DMatrix::zeros(n, n));
        for (e, section) in rotor.elements.iter().enumerate() {
            let em = element_matrices(section, rotor.theory);
            let base = e * NODE_DOFS;
            for i in 0..2 * NODE_DOFS {
                for j in 0..2 * NODE_DOFS {
                    mass[(base + i, base + j)] += em.mass[(i, j)];
                    stiffness[(base + i, base + j)] += em.stiffness[(i, j)];
                    gyroscopic[(base + i, base + j)] += em.gyroscopic[(i, j)];
                }
            }
        }
        for d in &rotor.disks {
            for (dof, v) in
                [(NodeDof::X, d.mass), (NodeDof::Y, d.mass), (NodeDof::A, d.transverse), (NodeDof::B, d.transverse)]
            {
                let i = shaft_index(d.node, dof);
                mass[(i, i)] += v;
            }
            let (a, b) = (shaft_index(d.node, NodeDof::A), shaft_index(d.node, NodeDof::B));
            gyroscopic[(a, b)] += d.polar;
            gyroscopic[(b, a)] -= d.polar;
        }
        let free_free_rad_s = plane_free_free(&mass, &stiffness, n_nodes)?;
        let mut damping = match rotor.damping {
            None => DMatrix::zeros(n, n),
            Some(d) => {
                let pick = |m: usize| {
                    free_free_rad_s
                        .get(m - 1)
                        .copied()
                        .ok_or(RotorError::DampingMode { mode: m, available: free_free_rad_s.len() })
                };
                let (w1, w2) = (pick(d.modes[0])?, pick(d.modes[1])?);
                let alpha = 2.0 * d.ratio * w1 * w2 / (w1 + w2);
                let beta = 2.0 * d.ratio / (w1 + w2);
                &mass * alpha + &stiffness * beta
            }
        };
        for s in &rotor.supports {
            for dof in [NodeDof::X, NodeDof::Y] {
                let i = shaft_index(s.node, dof);
                stiffness[(i, i)] += s.stiffness;
                damping[(i, i)] += s.damping;
            }
        }
        Ok(Self {
            n_nodes,
            z_m: rotor.node_positions(),
            mass,
            stiffness,
            gyroscopic,
            damping,
            free_free_rad_s,
            basis: None,
        })
    }
}

/// Undamped natural frequencies of the symmetric pencil (K, M) [rad/s], ascending (negative eigenvalues of
/// round-off size give 0).
///
/// # Errors
/// [`RotorError::SingularMass`] when M is not positive definite.
pub fn undamped_frequencies(k: &DMatrix<f64>, m: &DMatrix<f64>) -> Result<Vec<f64>, RotorError> {
    let l = m.clone().cholesky().ok_or(RotorError::SingularMass { size: m.nrows() })?;
    let linv = l.l().try_inverse().ok_or(RotorError::SingularMass { size: m.nrows() })?;
    let a = &linv * k * linv.transpose();
    let a = (&a + a.transpose()) * 0.5;
    let mut w: Vec<f64> = SymmetricEigen::new(a).eigenvalues.iter().map(|&l| l.max(0.0).sqrt()).collect();
    w.sort_by(f64::total_cmp);
    Ok(w)
}

/// Free–free flexible frequencies of the x–a plane (the y–b plane is identical): the two rigid-body modes
/// (translation and rotation) removed.
fn plane_free_free(mass: &DMatrix<f64>, stiffness: &DMatrix<f64>, n_nodes: usize) -> Result<Vec<f64>, RotorError> {
    let idx: Vec<usize> = (0..n_nodes).flat_map(|n| [shaft_index(n, NodeDof::X), shaft_index(n, NodeDof::A)]).collect();
    let sub = |a: &DMatrix<f64>| DMatrix::from_fn(idx.len(), idx.len(), |i, j| a[(idx[i], idx[j])]);
    let w = undamped_frequencies(&sub(stiffness), &sub(mass))?;
    Ok(w.into_iter().skip(2).collect())
}
