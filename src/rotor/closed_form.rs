//! Closed-form checks of the shaft model and the rotor analyses.
//!
//! - Beams (Euler–Bernoulli and Timoshenko, free–free and simply supported): the first four bending
//!   frequencies against the exact ones, and the measured convergence order under mesh halving.
//!   Euler–Bernoulli: `ω_n = (β_n L)² √(EI / (ρA L⁴))` with `β_n L` = 4.7300, 7.8532, 10.9956, 14.1372
//!   (free–free) and nπ (pinned–pinned). Timoshenko pinned–pinned with `w = W sin kz`, `θ = Θ cos kz`,
//!   `k = nπ/L`: `(ρAω² − κGAk²)(ρIω² − EIk² − κGA) − (κGAk)² = 0` (lower root).
//! - Jeffcott rotor (central disk, massless shaft, two isotropic bearings): `ω = √(k_e/m)`,
//!   `1/k_e = L³/(48EI) + 1/(2k_b)`.
//! - Overhung disk on a massless cantilever: `(k₁₁ − mω²)(k₂₂ − I_dω² + I_pΩω) − k₁₂² = 0` (ω > 0 forward,
//!   ω < 0 backward), tip stiffness `EI/L³ [[12, −6L], [−6L, 4L²]]`.
//! - Rigid rotor on two bearings with skew-symmetric cross-coupled stiffness `q = q′Ω`: the cylindrical
//!   forward mode becomes unstable at `q = c ω_n`, `ω_n = √(2k/m)`, i.e. `Ω* = c ω_n / q′`.

use std::f64::consts::PI;

use nalgebra::DMatrix;

use super::assembly::{shaft_index, undamped_frequencies, NodeDof, ShaftModel};
use super::coupling::BearingCoefficients;
use super::eigen::Whirl;
use super::element::{BeamSection, BeamTheory};
use super::stability::{modes_at, onset, SpeedPoint};
use crate::model::rotor::{CoefficientModel, Disk, Rotor};

pub(super) fn uniform(l: f64, d: f64, n: usize, density: f64, youngs: f64, theory: BeamTheory) -> Rotor {
    #[allow(clippy::cast_precision_loss)]
    let le = l / n as f64;
    let s = BeamSection {
        length_m: le,
        outer_diameter_m: d,
        inner_diameter_m: 0.0,
        density_kg_per_m3: density,
        youngs_modulus_pa: youngs,
        poisson_ratio: 0.3,
    };
    Rotor {
        title: String::new(),
        representative: false,
        theory,
        coefficients: CoefficientModel::Reduced,
        shaft_modes: 0,
        elements: vec![s; n],
        disks: Vec::new(),
        unbalances: Vec::new(),
        bearings: Vec::new(),
        supports: Vec::new(),
        damping: None,
        operating_range: None,
    }
}

/// Bending frequencies of the x–a plane with the displacement fixed at the listed nodes.
fn plane_frequencies(shaft: &ShaftModel, pinned: &[usize]) -> Vec<f64> {
    let idx: Vec<usize> = (0..shaft.n_nodes)
        .flat_map(|n| [shaft_index(n, NodeDof::X), shaft_index(n, NodeDof::A)])
        .filter(|&i| !pinned.iter().any(|&p| shaft_index(p, NodeDof::X) == i))
        .collect();
    let sub = |a: &DMatrix<f64>| DMatrix::from_fn(idx.len(), idx.len(), |i, j| a[(idx[i], idx[j])]);
    undamped_frequencies(&sub(&shaft.stiffness), &sub(&shaft.mass)).unwrap()
}

const L: f64 = 1.0;
const RHO: f64 = 7800.0;
const E: f64 = 2.0e11;
/// Density of a 'massless' shaft [kg/m³].
const LIGHT: f64 = 0.1;

fn exact_euler(d: f64, beta_l: &[f64]) -> Vec<f64> {
    let s = BeamSection {
        length_m: L,
        outer_diameter_m: d,
        inner_diameter_m: 0.0,
        density_kg_per_m3: RHO,
        youngs_modulus_pa: E,
        poisson_ratio: 0.3,
    };
    let c = (E * s.second_moment() / (RHO * s.area() * L.powi(4))).sqrt();
    beta_l.iter().map(|b| b * b * c).collect()
}

fn exact_timoshenko_pinned(d: f64, n_modes: usize) -> Vec<f64> {
    let s = BeamSection {
        length_m: L,
        outer_diameter_m: d,
        inner_diameter_m: 0.0,
        density_kg_per_m3: RHO,
        youngs_modulus_pa: E,
        poisson_ratio: 0.3,
    };
    let (a, i) = (s.area(), s.second_moment());
    let kga = s.shear_coefficient() * E / 2.6 * a;
    (1..=n_modes)
        .map(|n| {
            #[allow(clippy::cast_precision_loss)]
            let k = n as f64 * PI / L;
            // (ρA x − κGA k²)(ρI x − EI k² − κGA) − (κGA k)² = 0, x = ω²: a₂x² + a₁x + a₀ = 0
            let (p, q) = (RHO * a, kga * k * k);
            let (r, t) = (RHO * i, E * i * k * k + kga);
            let (a2, a1, a0) = (p * r, -(p * t + q * r), q * t - (kga * k).powi(2));
            let x = (-a1 - (a1 * a1 - 4.0 * a2 * a0).sqrt()) / (2.0 * a2);
            x.sqrt()
        })
        .collect()
}

/// Largest relative error over the first 4 modes, per mesh, and the orders between successive meshes.
fn study(theory: BeamTheory, d: f64, pinned: bool, exact: &[f64]) -> (Vec<f64>, Vec<f64>) {
    let errs: Vec<f64> = [8, 16, 32, 64]
        .iter()
        .map(|&n| {
            let shaft = ShaftModel::new(&uniform(L, d, n, RHO, E, theory)).unwrap();
            let f = if pinned {
                plane_frequencies(&shaft, &[0, n])
            } else {
                plane_frequencies(&shaft, &[]).into_iter().skip(2).collect()
            };
            (0..4).map(|m| ((f[m] - exact[m]) / exact[m]).abs()).fold(0.0, f64::max)
        })
        .collect();
    let orders = errs.windows(2).map(|w| (w[0] / w[1]).log2()).collect();
    (errs, orders)
}

#[test]
fn euler_bernoulli_free_free_and_pinned() {
    let d = 0.05;
    let ff = exact_euler(d, &[4.730_040_745, 7.853_204_624, 10.995_607_838, 14.137_165_491]);
    let (errs, orders) = study(BeamTheory::EulerBernoulli, d, false, &ff);
    eprintln!("EB free-free errors {errs:?} orders {orders:?}");
    assert!(errs[3] < 5e-3 && errs[2] < 5e-3, "{errs:?}");
    assert!(orders.iter().skip(1).all(|&p| (3.9..=4.1).contains(&p)), "{orders:?}");
    let pp = exact_euler(d, &[PI, 2.0 * PI, 3.0 * PI, 4.0 * PI]);
    let (errs, orders) = study(BeamTheory::EulerBernoulli, d, true, &pp);
    eprintln!("EB pinned errors {errs:?} orders {orders:?}");
    assert!(errs[3] < 5e-3 && errs[2] < 5e-3, "{errs:?}");
    assert!(orders.iter().skip(1).all(|&p| (3.9..=4.1).contains(&p)), "{orders:?}");
}

#[test]
fn timoshenko_pinned() {
    let d = 0.2; // L/d = 5: shear and rotary inertia lower the 4th frequency by tens of per cent
    let exact = exact_timoshenko_pinned(d, 4);
    let euler = exact_euler(d, &[PI, 2.0 * PI, 3.0 * PI, 4.0 * PI]);
    assert!(exact[3] < 0.7 * euler[3], "a thick beam: {exact:?} vs {euler:?}");
    let (errs, orders) = study(BeamTheory::Timoshenko, d, true, &exact);
    eprintln!("Timoshenko pinned errors {errs:?} orders {orders:?}");
    // Φ = 12EI/(κGA h²) grows as the mesh is refined, the interpolation tends to linear w and θ, and the
    // frequencies converge at order 2 (measured 2.010, 2.005, 2.001 at 8→16→32→64 elements).
    assert!(errs[2] < 5e-3 && errs[3] < 1e-3, "{errs:?}");
    assert!(orders.iter().all(|&p| (1.95..=2.05).contains(&p)), "{orders:?}");
}

fn numbers(k: f64, c: f64) -> BearingCoefficients {
    BearingCoefficients::Reduced { k: [[k, 0.0], [0.0, k]], c: [[c, 0.0], [0.0, c]] }
}

#[test]
fn jeffcott_critical_speed() {
    let (d, n, m, kb) = (0.03, 8, 25.0, 2.0e6);
    let mut rotor = uniform(L, d, n, LIGHT, E, BeamTheory::EulerBernoulli);
    rotor.disks.push(Disk { node: n / 2, mass: m, polar: 0.0, transverse: 0.0 });
    let shaft = ShaftModel::new(&rotor).unwrap();
    let i = rotor.elements[0].second_moment();
    let ke = 1.0 / (L.powi(3) / (48.0 * E * i) + 1.0 / (2.0 * kb));
    let exact = (ke / m).sqrt();
    let mut provider = |_w: f64| Ok(vec![numbers(kb, 0.0), numbers(kb, 0.0)]);
    let p = modes_at(&shaft, &[0, n], &mut provider, 0.0).unwrap();
    let w = p.modes.modes[0].imag_rad_s;
    eprintln!("Jeffcott {w} vs {exact}: {:.2e}", (w - exact) / exact);
    // what remains: the light shaft's own mass (7e-5 kg on 25 kg) and round-off (measured −2.9e-6)
    assert!(((w - exact) / exact).abs() < 5e-6, "{w} vs {exact}");
    // both planes: a double root
    assert!(((p.modes.modes[1].imag_rad_s - exact) / exact).abs() < 5e-6);
}

/// The shaft with node 0 clamped (its four coordinates removed; the other nodes renumbered from 0).
fn clamp_first_node(shaft: &ShaftModel) -> ShaftModel {
    let n = shaft.n_dofs() - 4;
    let cut = |a: &DMatrix<f64>| a.view((4, 4), (n, n)).into_owned();
    ShaftModel {
        n_nodes: shaft.n_nodes - 1,
        z_m: shaft.z_m[1..].to_vec(),
        mass: cut(&shaft.mass),
        stiffness: cut(&shaft.stiffness),
        gyroscopic: cut(&shaft.gyroscopic),
        damping: cut(&shaft.damping),
        free_free_rad_s: Vec::new(),
        basis: None,
    }
}

/// Roots ω of the overhung-disk frequency equation in (lo, hi), by sign changes on a fine scan and bisection.
fn roots(f: &dyn Fn(f64) -> f64, lo: f64, hi: f64) -> Vec<f64> {
    let n = 20_000;
    let mut out = Vec::new();
    #[allow(clippy::cast_precision_loss)]
    let at = |i: usize| lo + (hi - lo) * i as f64 / n as f64;
    for i in 0..n {
        let (mut a, mut b) = (at(i), at(i + 1));
        if f(a) * f(b) < 0.0 {
            for _ in 0..200 {
                let c = 0.5 * (a + b);
                if f(a) * f(c) <= 0.0 {
                    b = c;
                } else {
                    a = c;
                }
            }
            out.push(0.5 * (a + b));
        }
    }
    out
}

#[test]
fn overhung_disk_whirl_split() {
    let (d, n, m, id, ip) = (0.04, 6, 20.0, 0.2, 0.4);
    let l = 0.5;
    let mut rotor = uniform(l, d, n, LIGHT, E, BeamTheory::EulerBernoulli);
    rotor.disks.push(Disk { node: n, mass: m, polar: ip, transverse: id });
    let shaft = clamp_first_node(&ShaftModel::new(&rotor).unwrap());
    let ei = E * rotor.elements[0].second_moment();
    let (k11, k12, k22) = (12.0 * ei / l.powi(3), -6.0 * ei / l.powi(2), 4.0 * ei / l);
    let mut provider = |_w: f64| Ok(vec![]);
    for spin in [0.0, 500.0, 2000.0] {
        let f = |w: f64| (k11 - m * w * w) * (k22 - id * w * w + ip * spin * w) - k12 * k12;
        let fwd = roots(&f, 1.0, 20_000.0);
        let bwd: Vec<f64> = roots(&f, -20_000.0, -1.0).iter().map(|w| -w).rev().collect();
        let p = modes_at(&shaft, &[], &mut provider, spin).unwrap();
        if spin == 0.0 {
            // at rest forward and backward coincide (a double root per frequency; the split is arbitrary)
            let all: Vec<f64> = p.modes.modes.iter().map(|m| m.imag_rad_s).take(4).collect();
            for (fe, cf) in all.iter().zip([fwd[0], fwd[0], fwd[1], fwd[1]]) {
                assert!(((fe - cf) / cf).abs() < 1e-5, "Ω 0: {fe} vs {cf}");
            }
            assert!(((fwd[0] - bwd[0]) / fwd[0]).abs() < 1e-12);
            continue;
        }
        let fe_f: Vec<f64> =
            p.modes.modes.iter().filter(|m| m.whirl == Whirl::Forward).map(|m| m.imag_rad_s).take(2).collect();
        let fe_b: Vec<f64> =
            p.modes.modes.iter().filter(|m| m.whirl == Whirl::Backward).map(|m| m.imag_rad_s).take(2).collect();
        eprintln!("Ω {spin}: forward {fe_f:?} vs {fwd:?}; backward {fe_b:?} vs {bwd:?}");
        for (fe, cf) in fe_f.iter().zip(&fwd).chain(fe_b.iter().zip(&bwd)) {
            assert!(((fe - cf) / cf).abs() < 1e-5, "Ω {spin}: {fe} vs {cf}");
        }
        assert_eq!((fe_f.len(), fe_b.len()), (2, 2));
        assert!(fe_f[1] > fe_b[1] * 1.05, "the gyroscopic split: forward stiffens, backward softens");
    }
}

#[test]
fn cross_coupling_onset() {
    let (d, n) = (0.1, 4);
    // a rigid shaft (E huge): the cylindrical mode is the Jeffcott mode of the whole mass on 2k
    let rotor = uniform(L, d, n, RHO, 1e16, BeamTheory::EulerBernoulli);
    let shaft = ShaftModel::new(&rotor).unwrap();
    let (k, c, q_per_rad_s) = (1.0e7, 2.0e3, 1000.0);
    let m = rotor.mass();
    let exact = c * (2.0 * k / m).sqrt() / q_per_rad_s;
    let mut provider = |w: f64| {
        let q = q_per_rad_s * w;
        let b = BearingCoefficients::Reduced { k: [[k, q], [-q, k]], c: [[c, 0.0], [0.0, c]] };
        Ok(vec![b.clone(), b])
    };
    let speeds: Vec<f64> = (0..=10).map(|i| 200.0 * f64::from(i)).collect();
    let sweep: Vec<SpeedPoint> = speeds.iter().map(|&w| modes_at(&shaft, &[0, n], &mut provider, w).unwrap()).collect();
    let o = onset(&shaft, &[0, n], &mut provider, &sweep, 1e-9).unwrap().unwrap();
    eprintln!("onset {} vs {exact} ({:.2e}), {} probes", o.speed_rad_s, (o.speed_rad_s - exact) / exact, o.probes);
    assert!(((o.speed_rad_s - exact) / exact).abs() < 1e-6, "{} vs {exact}", o.speed_rad_s);
}
