//! The leading-edge (ram) pressure of the film solve: closed forms and the linearisation.

use crate::mesh::grid::PadGrid;
use crate::model::Cavitation;
use crate::physics::reynolds::{FilmGeometry, FilmInputs, FilmShape, Inlet, PadFilm, Viscosity};
use std::f64::consts::PI;

/// Journal radius [m] (the pad's arc is 1 rad: arc length R), length [m], film [m], viscosity, speed.
const R: f64 = 0.05;
const L: f64 = 0.04;
const H0: f64 = 30e-6;
const MU: f64 = 0.02;
const U: f64 = 20.0;
const P_LE: f64 = 2.0e5;

/// `h = H0 (1 + slope (1 − θ) + bowl 4 (θ − ½)²)` plus one coordinate `q` with shape `φ = −R (θ − 0.6)` (a tilt about 0.6 rad).
struct Wedge {
    slope: f64,
    bowl: f64,
}
impl FilmShape for Wedge {
    fn base(&self, theta: f64, _z: f64) -> f64 {
        H0 * (1.0 + self.slope * (1.0 - theta) + self.bowl * 4.0 * (theta - 0.5).powi(2))
    }
    fn n_dofs(&self) -> usize {
        1
    }
    fn dof(&self, _k: usize, theta: f64, _z: f64) -> f64 {
        -R * (theta - 0.6)
    }
}

fn film(slope: f64, bowl: f64, ns: usize, nz: usize) -> PadFilm {
    let at = |a: f64, b: f64, n: usize| -> Vec<f64> {
        (0..=n)
            .map(|i| a + (b - a) * f64::from(u32::try_from(i).unwrap()) / f64::from(u32::try_from(n).unwrap()))
            .collect()
    };
    let grid = PadGrid { s: at(0.0, R, ns), z: at(-0.5 * L, 0.5 * L, nz), periodic: false, half: false };
    PadFilm::new(FilmGeometry::new(grid, R, 0.0, &[], &Wedge { slope, bowl })).unwrap()
}

fn inputs(cavitation: Cavitation, p_le: f64) -> FilmInputs<'static> {
    FilmInputs {
        surface_speed: U,
        viscosity: Viscosity::Uniform(MU),
        injection_pressure: 0.0,
        injection_viscosity: MU,
        cavitation,
        turbulence: crate::physics::turbulence::TurbulenceLaw::LAMINAR,
        inlet: Inlet::Flooded,
        leading_edge_pressure: p_le,
    }
}

/// `∫ p dA` over the pad.
fn load(f: &PadFilm) -> f64 {
    let g = &f.geom;
    g.elements
        .iter()
        .zip(&g.qp)
        .map(|(nodes, qp)| qp.iter().map(|q| q.w * (0..4).map(|a| q.n[a] * f.p[nodes[a]]).sum::<f64>()).sum::<f64>())
        .sum()
}

fn solve(f: &mut PadFilm, q: f64, inp: &FilmInputs<'_>) {
    f.set_coordinates(&[q]).unwrap();
    f.solve(inp, false).unwrap();
}

/// A parallel film carries no wedge pressure, so the ram pressure alone loads it: `p = p_le w` with
/// `∇²w = 0`, `w = cos(π z/L)` on the leading edge and 0 on the other three sides of the B × L rectangle:
/// `w = cos(π z/L) sinh(π (B − s)/L) / sinh(π B/L)`, whose integral is `∫w dA = 2 L²/π² tanh(π B/(2L))`.
/// The leading-edge inflow is the Couette flow `U H0 L/2` plus `H0³/(12µ) p_le ∫ −∂w/∂s dz` at `s = 0`,
/// `2 coth(π B/L)`: finite, as the profile is continuous to the ambient ends (a uniform edge pressure's jump
/// at the corners has a corner flow that grows without bound as the mesh is refined).
/// Measured, load and inflow: 6.8e-4 and 1.8e-4 at 40 × 32 elements, 1.7e-4 and 9.0e-5 at 80 × 64, 4.2e-5
/// and 4.6e-5 at 160 × 128: the load at order 2, the inflow at order 1 (each corner node's reaction, counted
/// with the leading edge, holds a share of the side flow proportional to the element size).
#[test]
fn a_parallel_film_carries_the_ram_pressure_of_the_laplace_solution() {
    let exact = 2.0 * L * L / (PI * PI) * (PI * R / (2.0 * L)).tanh() * P_LE;
    let inflow = U * H0 * L / 2.0 + H0.powi(3) / (12.0 * MU) * P_LE * 2.0 / (PI * R / L).tanh();
    let mut last = (f64::NAN, f64::NAN);
    for ((ns, nz), tol, tol_q) in [((40, 32), 7.5e-4, 2.0e-4), ((80, 64), 1.9e-4, 1.0e-4), ((160, 128), 4.8e-5, 5.0e-5)]
    {
        let mut f = film(0.0, 0.0, ns, nz);
        let inp = inputs(Cavitation::Reynolds, P_LE);
        solve(&mut f, 0.0, &inp);
        let err = (load(&f) - exact).abs() / exact;
        let q_le = f.flows(&inp).leading_edge_in;
        let err_q = (q_le - inflow).abs() / inflow;
        eprintln!(
            "{ns} × {nz}: ∫p dA {:.6e} N against {exact:.6e} N ({err:.2e}); inflow {q_le:.6e} against {inflow:.6e} m³/s ({err_q:.2e})",
            load(&f)
        );
        assert!(err < tol, "{ns} × {nz}: load's relative error {err:.2e}");
        assert!(err_q < tol_q, "{ns} × {nz}: inflow's relative error {err_q:.2e}");
        assert!(last.0.is_nan() || last.0 / err > 3.8, "load converges at order > 1.9: {:.2e} → {err:.2e}", last.0);
        assert!(
            last.1.is_nan() || last.1 / err_q > 1.9,
            "inflow converges at order > 0.9: {:.2e} → {err_q:.2e}",
            last.1
        );
        last = (err, err_q);
        // The leading edge carries p_le cos(π z/L) exactly; its corners and every other edge stay ambient.
        let g = &f.geom;
        for k in 0..g.n_nodes() {
            let (i, j) = g.grid.col_row(k);
            let on_end = j == 0 || j == g.grid.n_rows() - 1;
            if i == 0 && !on_end {
                assert!((f.p[k] - P_LE * (PI * g.grid.z[j] / L).cos()).abs() <= 1e-12 * P_LE, "{}", f.p[k]);
            } else if i == 0 || g.dirichlet[k] {
                assert_eq!(f.p[k], 0.0);
            }
        }
    }
}

/// A converging film runs full, so the film equation is linear and the ram pressure superposes: the load
/// rises by `p_le ∫w dA` for every `p_le` (checked as F(2p) − F(0) = 2 (F(p) − F(0))), with both cavitation
/// options that keep a pressure boundary; the flows still balance.
#[test]
fn in_a_full_film_the_ram_pressure_adds_a_load_proportional_to_it() {
    for cav in [Cavitation::Reynolds, Cavitation::Gumbel] {
        let mut f = film(1.0, 0.0, 40, 16);
        let mut at = |p| {
            solve(&mut f, 0.0, &inputs(cav, p));
            assert_eq!(f.cavitated.iter().filter(|c| **c).count(), 0);
            let flows = f.flows(&inputs(cav, p));
            assert!(flows.imbalance().abs() < 1e-12 * flows.throughput(), "{flows:?}");
            load(&f)
        };
        let (f0, f1, f2) = (at(0.0), at(P_LE), at(2.0 * P_LE));
        eprintln!("{cav:?}: load {f0:.3} N; + {:.3} N with p_le, + {:.3} N with 2 p_le", f1 - f0, f2 - f0);
        assert!(f1 > f0 * 1.01);
        assert!(((f2 - f0) / (f1 - f0) - 2.0).abs() < 1e-9);
    }
}

/// With a ram pressure the stiffness of the tilt coordinate still is the derivative of its force: the
/// lifted leading-edge values enter `∂A/∂q p` (analytic K against central differences of solves). The film
/// (a bowl) diverges behind its minimum, so the Reynolds cavitation boundary is present.
#[test]
fn the_stiffness_with_a_ram_pressure_matches_differences_of_solves() {
    let mut f = film(0.0, 1.0, 60, 16);
    let inp = inputs(Cavitation::Reynolds, P_LE);
    let q0 = 1.0e-4;
    let force = |f: &mut PadFilm, q: f64| {
        solve(f, q, &inp);
        f.generalized_forces()[0]
    };
    solve(&mut f, q0, &inp);
    assert!(f.cavitated.iter().any(|c| *c), "the boundary is present");
    let k = f.linearize(&inp).stiffness[(0, 0)];
    let dq = 1e-8;
    let fd = -(force(&mut f, q0 + dq) - force(&mut f, q0 - dq)) / (2.0 * dq);
    eprintln!("K analytic {k:.6e}, differences {fd:.6e}");
    assert!((k - fd).abs() < 1e-5 * fd.abs(), "K {k:.6e} against {fd:.6e}");
    // Without the lifted values in the perturbation the stiffness would differ by far more than that.
    let k0 = {
        solve(&mut f, q0, &inputs(Cavitation::Reynolds, 0.0));
        f.linearize(&inputs(Cavitation::Reynolds, 0.0)).stiffness[(0, 0)]
    };
    assert!((k - k0).abs() > 1e-3 * k.abs());
}

/// The mass-conserving inlet is a film fraction: a leading-edge pressure with it is refused, as is a
/// negative or non-finite one.
#[test]
fn a_ram_pressure_is_refused_with_the_mass_conserving_inlet() {
    let mut f = film(1.0, 0.0, 20, 8);
    f.set_coordinates(&[0.0]).unwrap();
    assert!(f.solve(&inputs(Cavitation::Jfo, P_LE), false).is_err());
    assert!(f.solve(&inputs(Cavitation::Reynolds, -1.0), false).is_err());
    assert!(f.solve(&inputs(Cavitation::Reynolds, f64::NAN), false).is_err());
}
