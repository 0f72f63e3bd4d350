//! Flexible pads (docs/MODEL.md §5–§7): bending modes as pad coordinates in the equilibrium and the coefficients.
//!
//! - With `physics.pad_modes = 0` nothing changes (same coordinates, same numbers as a case without the key).
//! - Each retained mode is one more coordinate per tilting pad; the full coefficient matrices grow by them.
//! - Consistency: as the pads stiffen (E → ∞) the flexible solution tends to the rigid one, at first order in
//!   1/E (the modal displacement is the modal force over a modal stiffness ∝ E).
//! - Thesis trend (Publication 2, conclusion 4): flexibility raises the synchronously reduced stiffness and
//!   lowers the damping — checked on the compressor bearing.

use crate::common::{case, solve};
use tiltpad::bearing::film::coordinates::{Coord, PadDof};
use tiltpad::bearing::{solve_case, Solution};

const PREVIEW: &str = "mesh.fidelity=preview";

fn direct(s: &Solution) -> (f64, f64) {
    let k = s.reduced.k_n_per_m;
    let c = s.reduced.c_ns_per_m;
    (k[1][1], c[1][1])
}

#[test]
fn no_modes_is_the_rigid_solve() {
    let rigid = solve("compressor-bearing.toml", &[PREVIEW]);
    let zero = solve("compressor-bearing.toml", &[PREVIEW, "physics.pad_modes=0"]);
    assert_eq!(rigid.coordinates, zero.coordinates);
    assert_eq!(rigid.full.coords, zero.full.coords);
    assert_eq!(rigid.reduced.k_n_per_m, zero.reduced.k_n_per_m);
}

#[test]
fn modes_are_coordinates_and_stiff_pads_tend_to_rigid() {
    let rigid = solve("compressor-bearing.toml", &[PREVIEW]);
    let flex = |e_gpa: f64| {
        let mut c = case("compressor-bearing.toml", &[PREVIEW, "physics.pad_modes=1"]);
        for p in &mut c.bearing.pads {
            p.youngs_modulus_pa = e_gpa * 1e9;
        }
        solve_case(&c).expect("flexible solve")
    };
    let soft = flex(200.0);
    let n_rigid = rigid.full.coords.len();
    assert_eq!(soft.full.coords.len(), n_rigid + 5, "one mode per pad");
    assert!(soft.full.coords.contains(&Coord::Pad { pad: 3, dof: PadDof::Mode(0) }));
    assert_eq!(soft.full.k.len(), n_rigid + 5);
    // Deformation output: one amplitude per mode; the film-face field peaks at the amplitude (unit shapes).
    for p in &soft.pads {
        assert_eq!(p.mode_amplitudes_m.len(), 1);
        let peak = p.elastic_displacement_m.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
        assert!(
            (peak - p.mode_amplitudes_m[0].abs()).abs() <= 1e-12 * peak.max(1e-30),
            "{peak} {:?}",
            p.mode_amplitudes_m
        );
    }
    eprintln!("loaded pad (4) mode amplitude {:.3} µm", 1e6 * soft.pads[3].mode_amplitudes_m[0]);
    let stiff = flex(2000.0);
    let stiffer = flex(20000.0);
    let d = |s: &Solution| (s.eccentricity_ratio - rigid.eccentricity_ratio).abs();
    let dk = |s: &Solution| (direct(s).0 - direct(&rigid).0).abs();
    eprintln!(
        "ε rigid {:.6}, E 200/2000/20000 GPa: {:.6} {:.6} {:.6}; K_yy {:.4e} vs {:.4e} {:.4e} {:.4e}; C_yy {:.4e} vs {:.4e}",
        rigid.eccentricity_ratio,
        soft.eccentricity_ratio,
        stiff.eccentricity_ratio,
        stiffer.eccentricity_ratio,
        direct(&rigid).0,
        direct(&soft).0,
        direct(&stiff).0,
        direct(&stiffer).0,
        direct(&rigid).1,
        direct(&soft).1
    );
    // Thesis trends (steel pads, E = 200 GPa; measured on the preview mesh: ε 0.3437 → 0.3341,
    // K_yy +6.0 %, C_yy −8.5 %): smaller eccentricity, stiffer, less damped.
    assert!(soft.eccentricity_ratio < rigid.eccentricity_ratio - 0.005);
    assert!(direct(&soft).0 > 1.04 * direct(&rigid).0);
    assert!(direct(&soft).1 < 0.94 * direct(&rigid).1);
    // First order in 1/E: a tenfold stiffer pad moves ten times less.
    let ratio_e = d(&stiff) / d(&stiffer);
    let ratio_k = dk(&stiff) / dk(&stiffer);
    assert!((ratio_e - 10.0).abs() < 0.5, "ε: {ratio_e}");
    assert!((ratio_k - 10.0).abs() < 0.5, "K: {ratio_k}");
}

/// Massless pads (`bearing.pads.massless`) carry no inertia on any coordinate, their bending modes
/// included: the full inertia matrix vanishes, while the modal stiffness (ω²m, independent of the density)
/// and the film matrices are those of the pads with mass.
#[test]
fn massless_flexible_pads_have_no_modal_mass() {
    let heavy = solve("compressor-bearing-flexible.toml", &[PREVIEW]);
    let light = solve(
        "compressor-bearing-flexible.toml",
        &[PREVIEW, "bearing.pads.density_kg_per_m3=", "bearing.pads.massless=true"],
    );
    let mode = heavy.full.index(Coord::Pad { pad: 3, dof: PadDof::Mode(0) }).expect("mode coordinate");
    assert!(heavy.full.m[mode][mode] > 0.0, "the steel pad's mode has a modal mass");
    assert!(light.full.m.iter().flatten().all(|v| *v == 0.0), "massless: no inertia anywhere");
    assert_eq!(heavy.full.coords, light.full.coords);
    for (a, b) in heavy.full.k.iter().flatten().zip(light.full.k.iter().flatten()) {
        assert!((a - b).abs() <= 1e-9 * a.abs().max(1.0), "{a} vs {b}");
    }
}
