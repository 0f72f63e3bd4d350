//! Hertz pivots in the equilibrium (`cases/compressor-bearing-rocker-pivot.toml`, preview mesh).
//!
//! - Each pivot carries its pad's film load with exactly the Hertz approach: `ξₖ = δ(Fₖ)`, `Fₖ` the pad's
//!   film force along its pivot line (independent of the spring the solver iterated on).
//! - The same bearing on linear springs equal to the converged secant stiffnesses `Fₖ/δ(Fₖ)` is the same
//!   equilibrium; its full stiffness differs on each ξₖ diagonal by `k_tangent − k_secant` only (the
//!   coefficients linearise the nonlinear spring).
//! - A ball-in-socket pivot is softer than the rocker, a smaller ball softer still: each sinks the journal
//!   further and softens the bearing.

mod common;

use common::case;
use tiltpad::bearing::coefficients::reduce;
use tiltpad::bearing::coordinates::{Coord, PadDof};
use tiltpad::bearing::solve_case;

const CASE: &str = "compressor-bearing-rocker-pivot.toml";
const PREVIEW: &str = "mesh.fidelity=preview";

#[test]
fn hertz_pivots_carry_their_loads_and_linearise_with_the_tangent() {
    let c = case(CASE, &[PREVIEW]);
    let s = solve_case(&c).expect("Hertz-pivot solve");
    eprintln!("{}", s.report.method);
    assert!(s.report.method.contains("Hertz pivots"));
    let mut springs = c.clone();
    for (k, (pad, res)) in c.bearing.pads.iter().zip(&s.pads).enumerate() {
        let contact = pad.pivot_contact.expect("contact pads");
        let state = res.pivot_contact.expect("contact state");
        let xi = res.pivot_displacement_m.expect("pivot coordinate");
        assert!(!res.unloaded, "pad {k} floats");
        // The film's load on the pad along its pivot line e_p (the force on the journal, reversed).
        let e_p = [pad.pivot_rad.cos(), pad.pivot_rad.sin()];
        let load = -(res.force_n[0] * e_p[0] + res.force_n[1] * e_p[1]);
        let hertz = contact.state(load).expect("in Hertz range");
        eprintln!(
            "pad {k}: load {load:.2} N (state {:.2}), ξ {:.4} µm vs δ(F) {:.4} µm, k_t {:.4e} N/m, secant {:.4e}",
            state.load_n,
            1e6 * xi,
            1e6 * hertz.approach_m,
            state.tangent_n_per_m,
            state.secant_n_per_m()
        );
        assert!((xi - hertz.approach_m).abs() < 1e-4 * hertz.approach_m, "pad {k}: ξ {xi} vs δ {}", hertz.approach_m);
        assert!((state.tangent_n_per_m / hertz.tangent_n_per_m - 1.0).abs() < 2e-4);
        springs.bearing.pads[k].pivot_contact = None;
        springs.bearing.pads[k].pivot_stiffness_n_per_m = Some(state.secant_n_per_m());
    }
    let lin = solve_case(&springs).expect("linear springs");
    for (a, b) in s.coordinates.iter().zip(&lin.coordinates) {
        assert!((a - b).abs() < 1e-4 * b.abs().max(1e-7), "coordinates {:?} vs {:?}", s.coordinates, lin.coordinates);
    }
    let n = s.full.k.len();
    let scale = s.full.k.iter().flatten().fold(0.0_f64, |m, v| m.max(v.abs()));
    for i in 0..n {
        for j in 0..n {
            let d = s.full.k[i][j] - lin.full.k[i][j];
            let expected = match s.full.coords[i] {
                Coord::Pad { pad, dof: PadDof::PivotRadial } if i == j => {
                    let st = s.pads[pad].pivot_contact.expect("state");
                    st.tangent_n_per_m - st.secant_n_per_m()
                }
                _ => 0.0,
            };
            assert!((d - expected).abs() < 1e-3 * scale, "K[{i}][{j}]: {d:.4e} vs {expected:.4e}");
        }
    }
    // The tangent is stiffer than the secant: the static (ω = 0) reduced stiffness lies above the secant
    // springs'. (Synchronously reduced it need not: where the film's ωC exceeds its K, Re of the series
    // impedance Z_f k/(Z_f + k) falls as k grows, since Re Z_f² < 0.)
    let (ks, kl) = (reduce(&s.full, 0.0).k_n_per_m[1][1], reduce(&lin.full, 0.0).k_n_per_m[1][1]);
    eprintln!("static K_yy Hertz {ks:.4e}, secant springs {kl:.4e}; synchronous {:.4e} {:.4e}", s.reduced.k_n_per_m[1][1], lin.reduced.k_n_per_m[1][1]);
    assert!(ks > kl);
}

#[test]
fn softer_pivots_soften_the_bearing() {
    let rigid = solve_case(&case("compressor-bearing.toml", &[PREVIEW])).expect("rigid pivots");
    let rocker = solve_case(&case(CASE, &[PREVIEW])).expect("rocker");
    let ball = |r: &str, seat: &str| {
        let set = [PREVIEW, "bearing.pads.pivot_contact=\"ball\"", r, seat];
        solve_case(&case(CASE, &set)).expect("ball")
    };
    let ball = [ball("bearing.pads.pivot_radius_mm=12.7", "bearing.pads.pivot_seat_radius_mm=13"), ball("bearing.pads.pivot_radius_mm=5", "bearing.pads.pivot_seat_radius_mm=6")];
    let kyy = |s: &tiltpad::bearing::Solution| s.reduced.k_n_per_m[1][1];
    let all = [&rigid, &rocker, &ball[0], &ball[1]];
    eprintln!("K_yy rigid, rocker, ball 12.7/13, ball 5/6: {:?}", all.map(kyy));
    eprintln!("e_y [µm]: {:?}", all.map(|s| 1e6 * s.coordinates[1]));
    for w in all.windows(2) {
        assert!(kyy(w[1]) < 0.995 * kyy(w[0]));
        assert!(w[1].coordinates[1] < w[0].coordinates[1]);
    }
}
