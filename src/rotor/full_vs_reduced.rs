//! Full against synchronously reduced bearing coefficients, on a Jeffcott rotor whose bearings carry one pad
//! coordinate each: the film (`k_f`, `c_f`) joins the journal's x to the pad, the pad (mass `m_p`) sits on its
//! pivot spring `k_p`. Reduction at Ω condenses the pad at the running speed; the full model keeps it. When
//! the pad's own frequencies (`√((k_f + k_p)/m_p)`, `(k_f + k_p)/c_f`) are far above the whirl frequency the
//! pad follows the journal quasi-statically and the two agree; the difference falls as `1/k_p`.

use super::assembly::ShaftModel;
use super::coupling::BearingCoefficients;
use super::element::{BeamSection, BeamTheory};
use super::stability::modes_at;
use crate::bearing::film::coordinates::{Coord, PadDof};
use crate::bearing::solution::coefficients::FullCoefficients;
use crate::model::rotor::{CoefficientModel, Disk, Rotor};

fn bearing(kf: f64, cf: f64, kp: f64, mp: f64) -> FullCoefficients {
    let pad = Coord::Pad { pad: 0, dof: PadDof::PivotRadial };
    FullCoefficients {
        coords: vec![Coord::X, Coord::Y, pad],
        k: vec![vec![kf, 0.0, -kf], vec![0.0, 2.0 * kf, 0.0], vec![-kf, 0.0, kf + kp]],
        c: vec![vec![cf, 0.0, -cf], vec![0.0, cf, 0.0], vec![-cf, 0.0, cf]],
        m: vec![vec![0.0; 3], vec![0.0; 3], vec![0.0, 0.0, mp]],
    }
}

/// Relative difference of the first mode's eigenvalue (full vs reduced) for a pivot stiffness `kp`.
fn difference(kp: f64) -> f64 {
    let n = 4;
    let s = BeamSection {
        length_m: 0.25,
        outer_diameter_m: 0.05,
        inner_diameter_m: 0.0,
        density_kg_per_m3: 7800.0,
        youngs_modulus_pa: 2e11,
        poisson_ratio: 0.3,
    };
    let rotor = Rotor {
        title: String::new(),
        representative: false,
        theory: BeamTheory::Timoshenko,
        coefficients: CoefficientModel::Full,
        shaft_modes: 0,
        elements: vec![s; n],
        disks: vec![Disk { node: 2, mass: 50.0, polar: 0.5, transverse: 0.3 }],
        unbalances: Vec::new(),
        bearings: Vec::new(),
        supports: Vec::new(),
        damping: None,
        operating_range: None,
    };
    let shaft = ShaftModel::new(&rotor).unwrap();
    let full = BearingCoefficients::Full(bearing(2e7, 2e4, kp, 0.5));
    let spin = 600.0;
    let mut pf = |_w: f64| Ok(vec![full.clone(), full.clone()]);
    let a = modes_at(&shaft, &[0, n], &mut pf, spin).unwrap();
    let red = full.reduced(spin);
    let mut pr = |_w: f64| Ok(vec![red.clone(), red.clone()]);
    let b = modes_at(&shaft, &[0, n], &mut pr, spin).unwrap();
    let (ma, mb) = (&a.modes.modes[0], &b.modes.modes[0]);
    let la = nalgebra::Complex::new(ma.real_per_s, ma.imag_rad_s);
    let lb = nalgebra::Complex::new(mb.real_per_s, mb.imag_rad_s);
    (la - lb).norm() / lb.norm()
}

#[test]
fn full_and_reduced_agree_when_pads_are_fast() {
    let kps = [2e8, 2e9, 2e10, 2e11];
    let d: Vec<f64> = kps.iter().map(|&k| difference(k)).collect();
    let orders: Vec<f64> = d.windows(2).map(|w| (w[0] / w[1]).log10()).collect();
    eprintln!("full vs reduced: {d:?}, orders {orders:?}");
    assert!(d[0] > 5e-4, "slow pads: the reduction at Ω must differ ({})", d[0]);
    assert!(d[3] < 2e-6, "fast pads: full and reduced agree ({})", d[3]);
    // measured 0.950, 0.995, 0.9995
    assert!(orders.iter().skip(1).all(|&p| (0.99..=1.01).contains(&p)), "difference ∝ 1/k_p: {orders:?}");
}
