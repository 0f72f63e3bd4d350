//! The film's linear response to the injection pressure (the influence fields of docs/MODEL.md §8).
//!
//! ## Equations
//! The Reynolds equation is linear in the orifice entry pressures: with the converged factorisation `A`
//! (cavitated and Dirichlet nodes fixed), orifice `o` contributes `p_inj,o v_o / µ_inj` to the right-hand
//! side (`v_o,i = ∫ 3 g_o N_i / l0 dA`), so
//!
//! ```text
//! ∂p/∂p_inj,o = A⁻¹ v_o / µ_inj                                  one back-substitution per orifice
//! ∂Q_k/∂p_inj,o = ∫ φ_k ∂p/∂p_inj,o dA                            generalised film force (B)
//! q_o = ∫ g_o (p_inj,o − p) / (4 µ_inj l0) dA                       orifice flow into the film
//! ∂q_o/∂p_inj,o' = (δ_oo' ∫ 3 g_o/l0 − v_o·∂p/∂p_inj,o') / (12 µ_inj)   nozzle admittance (Y)
//! ∂q_o/∂q_k = −v_o·∂p/∂q_k / (12 µ_inj),  ∂q_o/∂q̇_k likewise       flow pushed by motion (D, E)
//! ```
//!
//! `∂p/∂q_k`, `∂p/∂q̇_k` are the perturbation fields of [`PadFilm::linearize`]. Because `A` is symmetric and
//! the squeeze right-hand side of `q̇_k` is `−12 ∫ φ_k N dA`, `∂q_o/∂q̇_k = ∂Q_k/∂p_inj,o` exactly (E = Bᵀ):
//! a test, since the two are computed along different paths. Exact for a fixed cavitation boundary, like
//! the stiffness and damping; all quantities for the whole pad (symmetry applied). Requires a preceding
//! [`PadFilm::solve`] with the same inputs.

use nalgebra::DMatrix;

use crate::physics::reynolds::{FilmInputs, PadFilm};

/// One pad's film response to its orifices' entry pressures, in the pad's local coordinates
/// `[e_x, e_y, pad coordinates…]` (rows/columns) and its orifices (the "ports"): `force` = B = ∂Q/∂p_inj,
/// `admittance` = Y = ∂q/∂p_inj, `displacement` = D = ∂q/∂u, `velocity` = E = ∂q/∂u̇, `static_flow`.
pub type InjectionResponse = crate::physics::hydraulics::NozzleCoupling;

impl PadFilm {
    /// The film's response to the injection pressures about the last solve (see the module doc).
    #[must_use]
    pub fn injection_response(&mut self, inp: &FilmInputs<'_>) -> InjectionResponse {
        let n = self.geom.n_nodes();
        let m = self.geom.n_dofs();
        let no = self.geom.orifices.len();
        let mu = inp.injection_viscosity;
        // ∂p/∂p_inj,o, one column per orifice.
        let mut dp = vec![0.0; n * no];
        for (o, op) in self.geom.orifices.iter().enumerate() {
            for &(i, v) in &op.vector {
                dp[o * n + i] = v / mu;
            }
        }
        self.back_substitute(&mut dp);
        let motion = self.perturbation_fields(inp, true);
        let g = &self.geom;
        let dot = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(x, y)| x * y).sum::<f64>();
        let sparse_dot = |o: usize, field: &[f64]| g.orifices[o].vector.iter().map(|&(i, v)| v * field[i]).sum::<f64>();
        let col = |f: &[f64], k: usize| f[k * n..(k + 1) * n].to_vec();
        let force = DMatrix::from_fn(m, no, |k, o| g.sym * dot(&g.loads[k], &dp[o * n..(o + 1) * n]));
        let admittance = DMatrix::from_fn(no, no, |o, o2| {
            let own = if o == o2 { g.orifices[o].total } else { 0.0 };
            g.sym * (own - sparse_dot(o, &col(&dp, o2))) / (12.0 * mu)
        });
        let displacement = DMatrix::from_fn(no, m, |o, k| -g.sym * sparse_dot(o, &col(&motion, k)) / (12.0 * mu));
        let velocity = DMatrix::from_fn(no, m, |o, k| -g.sym * sparse_dot(o, &col(&motion, m + k)) / (12.0 * mu));
        let static_flow = (0..no).map(|o| self.orifice_flow(o, inp)).collect();
        InjectionResponse { admittance, displacement, velocity, force, static_flow }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::grid::PadGrid;
    use crate::model::Cavitation;
    use crate::physics::orifice::LocalOrifice;
    use crate::physics::reynolds::{FilmGeometry, FilmShape, SampledField, Viscosity};

    /// A converging pad (50 mm radius, 60° arc, 40 mm long) with two coordinates: a tilt-like and a
    /// translation-like shape.
    struct Wedge;
    impl FilmShape for Wedge {
        fn base(&self, theta: f64, _z: f64) -> f64 {
            80e-6 - 40e-6 * theta
        }
        fn n_dofs(&self) -> usize {
            2
        }
        fn dof(&self, k: usize, theta: f64, z: f64) -> f64 {
            if k == 0 {
                -0.06 * (theta - 0.5).sin()
            } else {
                (theta - 0.5).cos() + 2.0 * z
            }
        }
    }

    fn film(orifices: &[LocalOrifice]) -> PadFilm {
        let r = 0.05;
        let arc = 1.0;
        let s: Vec<f64> = (0..=40).map(|i| arc * r * f64::from(i) / 40.0).collect();
        let z: Vec<f64> = (0..=16).map(|j| -0.02 + 0.04 * f64::from(j) / 16.0).collect();
        let grid = PadGrid { s, z, periodic: false, half: false };
        PadFilm::new(FilmGeometry::new(grid, r, 0.0, orifices, &Wedge)).unwrap()
    }

    fn inputs(p_inj: f64, cavitation: Cavitation) -> FilmInputs<'static> {
        FilmInputs {
            surface_speed: 5.0,
            viscosity: Viscosity::Uniform(0.02),
            injection_pressure: p_inj,
            injection_viscosity: 0.02,
            cavitation,
            turbulence: crate::physics::turbulence::TurbulenceLaw::LAMINAR,
            inlet: crate::physics::reynolds::Inlet::Flooded,
            leading_edge_pressure: 0.0,
        }
    }

    const HOLES: [LocalOrifice; 2] = [
        LocalOrifice { s0: 0.015, z0: 0.0, diameter: 6e-3, length: 10e-3 },
        LocalOrifice { s0: 0.035, z0: 0.004, diameter: 4e-3, length: 8e-3 },
    ];

    /// Forces and flows of a solve at `q` with injection `p`.
    fn state(f: &mut PadFilm, q: &[f64], p: f64, cav: Cavitation) -> (Vec<f64>, Vec<f64>) {
        f.set_coordinates(q).unwrap();
        let inp = inputs(p, cav);
        f.solve(&inp, false).unwrap();
        (f.generalized_forces(), (0..HOLES.len()).map(|o| f.orifice_flow(o, &inp)).collect())
    }

    /// Every influence coefficient equals the difference of full film solves. A full film: the pressure is
    /// exactly linear in the injection pressure and the squeeze velocity, so those differences are exact up
    /// to round-off (measured: B 4e-12, Y 4e-10, static flow 1.7e-11, E 2e-8); the displacement terms carry
    /// the O(δ²) of the central difference (measured ≤ 1.2e-7, falling 25× for a 5× smaller step). E = Bᵀ
    /// to round-off (measured ≤ 1.7e-15).
    #[test]
    fn influence_coefficients_match_film_solves() {
        let cav = Cavitation::Reynolds;
        let q0 = [0.0, 0.0];
        let p0 = 30e5;
        let mut f = film(&HOLES);
        state(&mut f, &q0, p0, cav);
        assert_eq!(f.cavitated.iter().filter(|&&c| c).count(), 0, "a full film");
        let r = f.injection_response(&inputs(p0, cav));
        // All orifices of a pad share its injection pressure: the sums over orifices are the checkable ones.
        let dp = 1e4;
        let (fp, qp) = state(&mut f, &q0, p0 + dp, cav);
        let (fm, qm) = state(&mut f, &q0, p0 - dp, cav);
        let rel = |a: f64, b: f64| (a - b).abs() / b.abs().max(1e-300);
        for k in 0..2 {
            let fd = (fp[k] - fm[k]) / (2.0 * dp);
            let b: f64 = r.force.row(k).sum();
            assert!(rel(b, fd) < 1e-10, "B[{k}] {b} vs {fd}");
        }
        for o in 0..2 {
            let fd = (qp[o] - qm[o]) / (2.0 * dp);
            let y: f64 = r.admittance.row(o).sum();
            assert!(rel(y, fd) < 3e-9, "Y[{o}] {y} vs {fd}");
            assert!(
                rel(r.static_flow[o], qp[o] - dp * fd) < 1e-11,
                "static flow {o}: {} vs {}",
                r.static_flow[o],
                qp[o] - dp * fd
            );
        }
        // Displacements: q_o(u ± δ) at fixed injection.
        for k in 0..2 {
            let d = if k == 0 { 2e-6 } else { 2e-8 };
            let mut qa = q0;
            qa[k] += d;
            let (_, qplus) = state(&mut f, &qa, p0, cav);
            qa[k] -= 2.0 * d;
            let (_, qminus) = state(&mut f, &qa, p0, cav);
            for o in 0..2 {
                let fd = (qplus[o] - qminus[o]) / (2.0 * d);
                assert!(rel(r.displacement[(o, k)], fd) < 3e-7, "D[{o},{k}] {} vs {fd}", r.displacement[(o, k)]);
            }
        }
        // Velocities: a squeeze field ḣ = φ_k u̇ is linear; reciprocity E = Bᵀ to round-off.
        for k in 0..2 {
            for o in 0..2 {
                let (e, b) = (r.velocity[(o, k)], r.force[(k, o)]);
                assert!(rel(e, b) < 1e-13, "E[{o},{k}] {e} vs B[{k},{o}] {b}");
            }
        }
        state(&mut f, &q0, p0, cav);
        let u_dot = 1e-3;
        for k in 0..2 {
            let shape = &f.geom.shapes[k];
            let sq = SampledField {
                qp: shape.qp.iter().map(|v| v.map(|x| x * u_dot)).collect(),
                node: shape.node.iter().map(|x| x * u_dot).collect(),
            };
            f.set_squeeze(Some(sq));
            let (_, qv) = state(&mut f, &q0, p0, cav);
            f.set_squeeze(None);
            let (_, q_rest) = state(&mut f, &q0, p0, cav);
            for o in 0..2 {
                let fd = (qv[o] - q_rest[o]) / u_dot;
                assert!(rel(r.velocity[(o, k)], fd) < 1e-7, "E[{o},{k}] {} vs {fd}", r.velocity[(o, k)]);
            }
        }
    }
}
