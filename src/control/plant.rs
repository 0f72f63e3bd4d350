//! The plant at one spin speed: the rotor–bearing system with its actuators, from the actuators' signals
//! [V] to the sensors' readings (m, m/s), as one state-space system (docs/MODEL.md §14).
//!
//! ## States
//! ```text
//! x = [p; z; actuator states…]      rotor: u = L⁻ᵀ p, u̇ = σ L⁻ᵀ z  (M = LLᵀ, σ the scale of rotor::eigen)
//! ṗ = σ z,  ż = −(K̃/σ) p − C̃ z + L⁻¹ f / σ                          f: generalised forces on u
//! ```
//! the rotor's own first-order form ([`crate::rotor::eigen::state_matrix`]: the same matrix `tiltpad rotor`
//! takes the eigenvalues of, so the open loop reproduces it to round-off), with the forces of the actuators
//! added to `f`.
//!
//! **Force actuator** (node, direction, `g` [N/V]): `f = g G(s) u` on that coordinate; `G = 1` (flat) or
//! `G = ω_a²/(s² + 2ζ_a ω_a s + ω_a²)` (two states).
//!
//! **Valve actuator** (the controllable bearing at a bearing position, docs/MODEL.md §8): the spool
//! `ẍ_V + 2ξω_V ẋ_V + ω_V² x_V = ω_V² u` (two states); per port k (sign σ_k) its line as `M` lumped segments
//! — `M + 1` pressure nodes (compliance `A l/(β M)`, halved at the two ends) joined by `M` flows (inertance
//! `ρ l/(A M)`, friction `d`):
//! ```text
//! C₀ ṗ₀ = q0 − q₁,    q0 = σ_k K_V x_V − K_c σ_k Σ_j σ_j p₀,j                       valve end
//! C ṗ_i = q_i − q_{i+1},   L q̇_i = p_{i−1} − p_i − L d q_i                         along the line
//! C_M ṗ_M = q_M − (Σ_j Y_kj p_M,j + Σ_c (D_kc u_c + E_kc u̇_c))                      nozzle end (the film's flow)
//! f_c += Σ_k B_ck p_M,k                                                              the film's force
//! ```
//! with the nozzle–film influence `Y, D, E, B` of the FRF stage ([`crate::physics::hydraulics::NozzleCoupling`])
//! over the bearing's full coordinates (journal x, y at the bearing's node, the appended pad coordinates).
//! The chain exactly matches the FRF stage's at zero frequency (same compliance, inertance and friction in
//! total) and converges to its distributed line as `M` grows; `M = 2 × modes` of the port (at least 4).

use nalgebra::DMatrix;

use super::error::ControlError;
use super::state_space::StateSpace;
use crate::bearing::frf::dynamics::Hydraulics;
use crate::model::control::{Axis, Quantity, SecondOrder, Sensor};
use crate::physics::hydraulics::NozzleCoupling;
use crate::rotor::assembly::Weights;
use crate::rotor::coupling::System;
use crate::rotor::eigen::state_matrix;

/// Where an actuator acts, ready for one speed.
#[derive(Debug, Clone)]
pub enum ActuatorPlant {
    /// `f = gain · G(s) u` on the coordinates `weights`.
    Force { weights: Weights, gain_n_per_v: f64, dynamics: Option<SecondOrder> },
    /// The valve chain of one bearing.
    Valve(Box<ValvePlant>),
}

/// One bearing's valve chain at one speed.
#[derive(Debug, Clone)]
pub struct ValvePlant {
    pub hydraulics: Hydraulics,
    pub coupling: NozzleCoupling,
    /// Per full coordinate of the bearing (the coupling's columns), its weights over the system's coordinates
    /// (`None`: a coordinate the system leaves out, decoupled).
    pub coordinates: Vec<Option<Weights>>,
}

/// The plant at one speed.
#[derive(Debug, Clone, serde::Serialize, serde::Deserialize)]
pub struct Plant {
    /// Inputs: the actuators' signals [V]; outputs: the sensors' readings [m, m/s].
    pub ss: StateSpace,
    /// State derivative per unit generalised force on each system coordinate (columns).
    pub force: DMatrix<f64>,
    /// System coordinates from the state (`u = U x`).
    pub coordinates: DMatrix<f64>,
    /// Per actuator, per port, the state index of the nozzle-end pressure (empty for a force actuator).
    pub nozzle_pressure: Vec<Vec<usize>>,
}

/// Segments of a line with `modes` acoustic modes asked for.
#[must_use]
pub fn segments(modes: usize) -> usize {
    (2 * modes).max(4)
}

impl Plant {
    /// Builds the plant of `sys` (the rotor–bearing system at this speed); `place(node, axis)`: a node's
    /// displacement as weights over the system's coordinates.
    ///
    /// # Errors
    /// A singular mass matrix.
    pub fn new(
        sys: &System,
        place: &dyn Fn(usize, Axis) -> Weights,
        sensors: &[Sensor],
        actuators: &[ActuatorPlant],
    ) -> Result<Self, ControlError> {
        let n = sys.n_dofs();
        let (ar, back) = state_matrix(sys)?;
        let sigma = if n > 0 { ar[(0, n)] } else { 1.0 };
        let extra: usize = actuators.iter().map(states_of).sum();
        let total = 2 * n + extra;
        let mut a = DMatrix::zeros(total, total);
        a.view_mut((0, 0), (2 * n, 2 * n)).copy_from(&ar);
        // u = L⁻ᵀ p, u̇ = σ L⁻ᵀ z, ż += L⁻¹ f/σ
        let mut coordinates = DMatrix::zeros(n, total);
        coordinates.view_mut((0, 0), (n, n)).copy_from(&back);
        let mut velocity = DMatrix::zeros(n, total);
        velocity.view_mut((0, n), (n, n)).copy_from(&(&back * sigma));
        let mut force = DMatrix::zeros(total, n);
        force.view_mut((n, 0), (n, n)).copy_from(&(back.transpose() / sigma));
        let row = |m: &DMatrix<f64>, w: &Weights| {
            let mut r = DMatrix::zeros(1, total);
            for &(j, c) in w {
                r += m.row(j) * c;
            }
            r
        };
        let column = |w: &Weights, scale: f64| {
            let mut c = DMatrix::zeros(total, 1);
            for &(j, v) in w {
                c += force.column(j) * (v * scale);
            }
            c
        };
        let mut b = DMatrix::zeros(total, actuators.len());
        let mut nozzle_pressure = Vec::new();
        let mut at = 2 * n;
        for (k, act) in actuators.iter().enumerate() {
            let mut pressures = Vec::new();
            match act {
                ActuatorPlant::Force { weights, gain_n_per_v, dynamics: None } => {
                    b.column_mut(k).copy_from(&column(weights, *gain_n_per_v));
                }
                ActuatorPlant::Force { weights, gain_n_per_v, dynamics: Some(d) } => {
                    let (w, z) = (d.natural_frequency_rad_s, d.damping_ratio);
                    // φ̈ = ω²(u − φ) − 2ζω φ̇, with the states φ and φ̇/ω
                    a[(at, at + 1)] = w;
                    a[(at + 1, at)] = -w;
                    a[(at + 1, at + 1)] = -2.0 * z * w;
                    b[(at + 1, k)] = w;
                    let f = column(weights, *gain_n_per_v);
                    for j in 0..2 * n {
                        a[(j, at)] += f[j];
                    }
                }
                ActuatorPlant::Valve(v) => {
                    valve(&mut a, &mut b, k, at, v, &coordinates, &velocity, &force, &mut pressures);
                }
            }
            nozzle_pressure.push(pressures);
            at += states_of(act);
        }
        let mut c = DMatrix::zeros(sensors.len(), total);
        for (i, s) in sensors.iter().enumerate() {
            let w = place(s.node, s.direction);
            let r = match s.quantity {
                Quantity::Displacement => row(&coordinates, &w),
                Quantity::Velocity => row(&velocity, &w),
            };
            c.row_mut(i).copy_from(&r);
        }
        let d = DMatrix::zeros(sensors.len(), actuators.len());
        Ok(Self { ss: StateSpace { a, b, c, d }, force, coordinates, nozzle_pressure })
    }
}

fn states_of(a: &ActuatorPlant) -> usize {
    match a {
        ActuatorPlant::Force { dynamics: None, .. } => 0,
        ActuatorPlant::Force { dynamics: Some(_), .. } => 2,
        ActuatorPlant::Valve(v) => 2 + v.hydraulics.ports.iter().map(|p| 2 * segments(p.line.modes) + 1).sum::<usize>(),
    }
}

/// Writes the valve chain's equations into `a`, `b` from state `at` on (input column `k`).
#[allow(clippy::too_many_arguments, clippy::many_single_char_names)]
fn valve(
    a: &mut DMatrix<f64>,
    b: &mut DMatrix<f64>,
    k: usize,
    at: usize,
    v: &ValvePlant,
    coordinates: &DMatrix<f64>,
    velocity: &DMatrix<f64>,
    force: &DMatrix<f64>,
    pressures: &mut Vec<usize>,
) {
    let h = &v.hydraulics;
    let sv = &h.valve;
    let (w, z) = (sv.natural_frequency_rad_s, sv.damping_ratio);
    // spool: x_V and ẋ_V/ω_V
    let (xv, vv) = (at, at + 1);
    a[(xv, vv)] = w;
    a[(vv, xv)] = -w;
    a[(vv, vv)] = -2.0 * z * w;
    b[(vv, k)] = w;
    // per port: pressures p_0..p_M, then flows q_1..q_M
    let mut start = at + 2;
    let layout: Vec<(usize, usize)> = h
        .ports
        .iter()
        .map(|p| {
            let m = segments(p.line.modes);
            let s = start;
            start += 2 * m + 1;
            (s, m)
        })
        .collect();
    let pressure = |port: usize, i: usize| layout[port].0 + i;
    let flow = |port: usize, i: usize| layout[port].0 + layout[port].1 + i; // i = 1..=M
    for (kp, port) in h.ports.iter().enumerate() {
        let (_, m) = layout[kp];
        #[allow(clippy::cast_precision_loss)]
        let mf = m as f64;
        let line = &port.line;
        let compliance = line.area * line.length / (line.bulk_modulus * mf);
        let inertance = line.density * line.length / (line.area * mf);
        let node_c = |i: usize| if i == 0 || i == m { compliance / 2.0 } else { compliance };
        // valve end: C₀ ṗ₀ = σ K_V x_V − K_c σ Σ σ_j p₀,j − q₁
        let c0 = node_c(0);
        a[(pressure(kp, 0), xv)] += port.sign * sv.flow_gain / c0;
        for (j, other) in h.ports.iter().enumerate() {
            a[(pressure(kp, 0), pressure(j, 0))] -= sv.flow_pressure_coefficient * port.sign * other.sign / c0;
        }
        for i in 0..=m {
            let ci = node_c(i);
            if i >= 1 {
                a[(pressure(kp, i), flow(kp, i))] += 1.0 / ci;
            }
            if i < m {
                a[(pressure(kp, i), flow(kp, i + 1))] -= 1.0 / ci;
            }
        }
        for i in 1..=m {
            a[(flow(kp, i), pressure(kp, i - 1))] = 1.0 / inertance;
            a[(flow(kp, i), pressure(kp, i))] = -1.0 / inertance;
            a[(flow(kp, i), flow(kp, i))] = -line.friction;
        }
        // nozzle end: the film's flow Y p + D u + E u̇ leaves the line
        let cm = node_c(m);
        let r = pressure(kp, m);
        for j in 0..h.ports.len() {
            a[(r, pressure(j, layout[j].1))] -= v.coupling.admittance[(kp, j)] / cm;
        }
        for (c, wc) in v.coordinates.iter().enumerate() {
            let Some(wc) = wc else { continue };
            let (dk, ek) = (v.coupling.displacement[(kp, c)], v.coupling.velocity[(kp, c)]);
            for &(j, wj) in wc {
                let row = coordinates.row(j) * (dk * wj / cm) + velocity.row(j) * (ek * wj / cm);
                let mut target = a.row_mut(r);
                target -= row;
            }
        }
        // the film's force on the bearing's coordinates
        for (c, wc) in v.coordinates.iter().enumerate() {
            let Some(wc) = wc else { continue };
            let bk = v.coupling.force[(c, kp)];
            for &(j, wj) in wc {
                let col = force.column(j) * (bk * wj);
                let mut target = a.column_mut(r);
                target += col;
            }
        }
        pressures.push(r);
    }
}
