//! Manufactured-solution convergence of the Reynolds solver (bilinear elements, expected order 2).
//!
//! On one pad of arc length `a` and axial half-length `b` (half model, symmetry at z = 0) we impose
//! `p*(s, z) = P sin(π s/a) cos(π z/(2b))` (zero on the edges, symmetric in z) with a converging film
//! `h(s) = h1 − (h1 − h0) s/a` and speed U. The squeeze term is set so that p* solves the equation exactly:
//! `12 ∂h/∂t = ∇·(h³/µ ∇p*) − 6 U ∂h/∂s`. The nodal maximum error must fall as h² under refinement.

use std::f64::consts::PI;

use tiltpad::mesh::grid::PadGrid;
use tiltpad::model::Cavitation;
use tiltpad::physics::reynolds::{FilmGeometry, FilmInputs, FilmShape, PadFilm, SampledField, Viscosity};

const A: f64 = 0.06; // arc length [m]
const B: f64 = 0.02; // half length [m]
const H0: f64 = 40e-6;
const H1: f64 = 120e-6;
const MU: f64 = 0.03;
const U: f64 = 20.0;
const P: f64 = 2e6;

struct Wedge;
impl FilmShape for Wedge {
    fn base(&self, theta: f64, _z: f64) -> f64 {
        // θ = s / R with R = 1 m, θ_le = 0.
        H1 - (H1 - H0) * theta / A
    }
    fn n_dofs(&self) -> usize {
        0
    }
    fn dof(&self, _k: usize, _t: f64, _z: f64) -> f64 {
        0.0
    }
}

fn exact(s: f64, z: f64) -> f64 {
    P * (PI * s / A).sin() * (PI * z / (2.0 * B)).cos()
}

/// ∂h/∂t that makes `exact` a solution.
fn squeeze(s: f64, z: f64) -> f64 {
    let h = H1 - (H1 - H0) * s / A;
    let hs = -(H1 - H0) / A;
    let (ks, kz) = (PI / A, PI / (2.0 * B));
    let ps = P * ks * (ks * s).cos() * (kz * z).cos();
    let pss = -P * ks * ks * (ks * s).sin() * (kz * z).cos();
    let pzz = -P * kz * kz * (ks * s).sin() * (kz * z).cos();
    let div = (3.0 * h * h * hs * ps + h * h * h * (pss + pzz)) / MU;
    (div - 6.0 * U * hs) / 12.0
}

fn max_error(n: usize) -> f64 {
    let s: Vec<f64> = (0..=n).map(|i| A * i as f64 / n as f64).collect();
    let z: Vec<f64> = (0..=n / 2).map(|j| B * j as f64 / (n / 2) as f64).collect();
    let grid = PadGrid { s, z, periodic: false, half: true };
    let geom = FilmGeometry::new(grid, 1.0, 0.0, &[], &Wedge);
    let sq = SampledField {
        qp: geom.qp.iter().map(|q| q.map(|p| squeeze(p.s, p.z))).collect(),
        node: (0..geom.n_nodes()).map(|k| squeeze(geom.node_theta[k], geom.node_z[k])).collect(),
    };
    let mut film = PadFilm::new(geom).unwrap();
    film.set_coordinates(&[]).unwrap();
    film.set_squeeze(Some(sq));
    let inp = FilmInputs {
        surface_speed: U,
        viscosity: Viscosity::Uniform(MU),
        injection_pressure: 0.0,
        injection_viscosity: MU,
        cavitation: Cavitation::Reynolds,
        turbulence: tiltpad::physics::turbulence::TurbulenceLaw::LAMINAR,
        inlet: tiltpad::physics::reynolds::Inlet::Flooded,
        leading_edge_pressure: 0.0,
    };
    film.solve(&inp, false).unwrap();
    let g = &film.geom;
    (0..g.n_nodes()).map(|k| (film.p[k] - exact(g.node_theta[k], g.node_z[k])).abs()).fold(0.0, f64::max) / P
}

#[test]
fn reynolds_solver_converges_at_second_order() {
    let errs: Vec<f64> = [8, 16, 32, 64].iter().map(|&n| max_error(n)).collect();
    let orders: Vec<f64> = errs.windows(2).map(|w| (w[0] / w[1]).log2()).collect();
    assert!(errs[3] < 2e-3, "finest error {:.2e}", errs[3]);
    for (i, o) in orders.iter().enumerate().skip(1) {
        assert!((1.8..2.4).contains(o), "order {o:.3} between meshes {i} and {} (errors {errs:?})", i + 1);
    }
}
