//! The controller as a state-space system: from the sensors' readings `y` (SI: m, or m/s for a velocity
//! pickup) to the actuators' signals before the loop gain, `v = K(s) y` [V]; the loop applies
//! `u = −gain · v` (negative feedback, [`crate::model::control`]).
//!
//! Realisations (one filter state per roll-off; `ω_f` the roll-off [rad/s]):
//! ```text
//! PD on a displacement:  K = kp + kd s/(1 + s/ω_f):  ẋ = −ω_f x + y,  v = (kp + kd ω_f) y − kd ω_f² x
//! PD on a velocity:      K = kd/(1 + s/ω_f):          ẋ = −ω_f x + y,  v = kd ω_f x     (no roll-off: v = kd y)
//! transfer function:     K = N(s)/D(s), D monic:      controllable canonical form (D(s) of degree n: n states)
//! MIMO PD:               one roll-off state per sensor, v_a = Σ_s kp_as y_s + kd_as ẏ_f,s
//! LQR:                   designed on the plant at its design speed ([`super::lqr`]): [`design`]
//! ```

use nalgebra::DMatrix;

use super::error::ControlError;
use super::lqr::LqrDesign;
use super::plant::Plant;
use super::state_space::StateSpace;
use crate::model::control::{Control, Law, Quantity, Rule};

/// The controller of `control`, an LQR designed on the plant `plant_at(design speed)` returns (with the
/// speed it was built at [rad/s]; asked for only for an LQR).
///
/// # Errors
/// The plant's, and the LQR design's ([`ControlError::Lqr`]).
pub fn design(
    control: &Control,
    plant_at: impl FnOnce(Option<f64>) -> Result<(Plant, f64), ControlError>,
) -> Result<(StateSpace, Option<LqrDesign>), ControlError> {
    match (&control.law, realise(control)) {
        (_, Some(k)) => Ok((k, None)),
        (Law::Lqr(spec), None) => {
            let (plant, speed) = plant_at(spec.design_speed_rad_s)?;
            let (k, report) = super::lqr::design(&plant, &control.sensors, spec, speed)?;
            Ok((k, Some(report)))
        }
        (_, None) => Err(ControlError::NoController),
    }
}

/// The controller of `control` (sensors in, actuators out; without the loop gain); `None` for an LQR, which
/// needs its plant ([`design`]).
#[must_use]
pub fn realise(control: &Control) -> Option<StateSpace> {
    let ns = control.sensors.len();
    let na = control.actuators.len();
    Some(match &control.law {
        Law::Lqr(_) => return None,
        Law::Loops(loops) => {
            // one block per loop, stacked
            let blocks: Vec<(usize, usize, StateSpace)> = loops
                .iter()
                .map(|l| (l.actuator, l.sensor, siso(&l.rule, control.sensors[l.sensor].quantity)))
                .collect();
            let n: usize = blocks.iter().map(|b| b.2.states()).sum();
            let mut ss = StateSpace {
                a: DMatrix::zeros(n, n),
                b: DMatrix::zeros(n, ns),
                c: DMatrix::zeros(na, n),
                d: DMatrix::zeros(na, ns),
            };
            let mut at = 0;
            for (act, sen, k) in blocks {
                let m = k.states();
                ss.a.view_mut((at, at), (m, m)).copy_from(&k.a);
                for i in 0..m {
                    ss.b[(at + i, sen)] += k.b[(i, 0)];
                    ss.c[(act, at + i)] += k.c[(0, i)];
                }
                ss.d[(act, sen)] += k.d[(0, 0)];
                at += m;
            }
            ss
        }
        Law::Mimo { kp, kd, rolloff_rad_s } => {
            let filtered: Vec<usize> = match rolloff_rad_s {
                Some(_) => (0..ns).filter(|&s| (0..na).any(|a| kd[a][s] != 0.0)).collect(),
                None => Vec::new(),
            };
            let n = filtered.len();
            let w = rolloff_rad_s.unwrap_or(0.0);
            let mut ss = StateSpace {
                a: DMatrix::zeros(n, n),
                b: DMatrix::zeros(n, ns),
                c: DMatrix::zeros(na, n),
                d: DMatrix::zeros(na, ns),
            };
            for a in 0..na {
                for s in 0..ns {
                    ss.d[(a, s)] += kp[a][s];
                }
            }
            for (i, &s) in filtered.iter().enumerate() {
                ss.a[(i, i)] = -w;
                ss.b[(i, s)] = 1.0;
                for a in 0..na {
                    match control.sensors[s].quantity {
                        Quantity::Displacement => {
                            ss.d[(a, s)] += kd[a][s] * w;
                            ss.c[(a, i)] -= kd[a][s] * w * w;
                        }
                        Quantity::Velocity => ss.c[(a, i)] += kd[a][s] * w,
                    }
                }
            }
            // velocity sensors without a roll-off: a plain gain
            for s in (0..ns).filter(|s| !filtered.contains(s)) {
                if control.sensors[s].quantity == Quantity::Velocity {
                    for a in 0..na {
                        ss.d[(a, s)] += kd[a][s];
                    }
                }
            }
            ss
        }
    })
}

/// One SISO law (one input, one output).
fn siso(rule: &Rule, q: Quantity) -> StateSpace {
    let one = |v: f64| DMatrix::from_element(1, 1, v);
    match (rule, q) {
        (Rule::Pd { kp, kd, rolloff_rad_s: Some(w) }, Quantity::Displacement) if *kd != 0.0 => {
            StateSpace { a: one(-w), b: one(1.0), c: one(-kd * w * w), d: one(kp + kd * w) }
        }
        (Rule::Pd { kp, .. }, Quantity::Displacement) => StateSpace::gain(one(*kp)),
        (Rule::Pd { kd, rolloff_rad_s: Some(w), .. }, Quantity::Velocity) => {
            StateSpace { a: one(-w), b: one(1.0), c: one(kd * w), d: one(0.0) }
        }
        (Rule::Pd { kd, rolloff_rad_s: None, .. }, Quantity::Velocity) => StateSpace::gain(one(*kd)),
        (Rule::TransferFunction { numerator, denominator }, _) => canonical(numerator, denominator),
    }
}

/// Controllable canonical form of `N(s)/D(s)` (highest power first, `D` monic, `deg N ≤ deg D`).
fn canonical(numerator: &[f64], denominator: &[f64]) -> StateSpace {
    let n = denominator.len() - 1;
    // numerator padded to n + 1 coefficients
    let mut b = vec![0.0; n + 1 - numerator.len().min(n + 1)];
    b.extend_from_slice(numerator);
    let d0 = b[0];
    let mut ss = StateSpace {
        a: DMatrix::zeros(n, n),
        b: DMatrix::zeros(n, 1),
        c: DMatrix::zeros(1, n),
        d: DMatrix::from_element(1, 1, d0),
    };
    if n == 0 {
        return ss;
    }
    // states x_1..x_n with ẋ_i = x_{i+1}, ẋ_n = −Σ a_{n−j} x_{j+1} + u; y = Σ (b_{n−j} − a_{n−j} b_0) x_{j+1} + b_0 u
    for i in 0..n - 1 {
        ss.a[(i, i + 1)] = 1.0;
    }
    for j in 0..n {
        let a = denominator[n - j];
        ss.a[(n - 1, j)] = -a;
        ss.c[(0, j)] = b[n - j] - a * d0;
    }
    ss.b[(n - 1, 0)] = 1.0;
    ss
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::control::state_space::C64;

    /// The canonical form returns N(s)/D(s): (2s² + 3s + 1)/(s² + 4s + 5) and (s + 7)/(s³ + 2s² + 3s + 4)
    /// at s = 0.3 + 2i to 1e-14.
    #[test]
    fn canonical_form_returns_the_transfer_function() {
        let s = C64::new(0.3, 2.0);
        let poly = |p: &[f64]| p.iter().fold(C64::from(0.0), |acc, &c| acc * s + c);
        for (num, den) in [(vec![2.0, 3.0, 1.0], vec![1.0, 4.0, 5.0]), (vec![1.0, 7.0], vec![1.0, 2.0, 3.0, 4.0])] {
            let g = canonical(&num, &den).response(s).unwrap()[(0, 0)];
            let want = poly(&num) / poly(&den);
            assert!((g - want).norm() < 1e-14 * want.norm(), "{g} vs {want}");
        }
    }

    /// The PD realisation on a displacement is kp + kd s/(1 + s/ω_f) (to 1e-14 at 50 Hz).
    #[test]
    fn pd_with_rolloff() {
        let (kp, kd, w) = (2.0, 3e-3, 2000.0);
        let k = siso(&Rule::Pd { kp, kd, rolloff_rad_s: Some(w) }, Quantity::Displacement);
        let s = C64::new(0.0, std::f64::consts::TAU * 50.0);
        let want = kp + kd * s / (1.0 + s / w);
        let g = k.response(s).unwrap()[(0, 0)];
        assert!((g - want).norm() < 1e-14 * want.norm(), "{g} vs {want}");
    }
}
