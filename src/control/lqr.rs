//! A linear–quadratic regulator designed by tiltpad on a reduced model of the plant (docs/MODEL.md §14,
//! "LQR on the reduced model"), realised as an output-feedback controller (an observer-based compensator) and
//! then closed on the full plant like any other controller.
//!
//! 1. **Reduction** ([`reduce`]): the plant at the design speed (rotor + pads + valve chains, [`Plant`]) in
//!    modal coordinates, keeping every mode with `|λ| ≤ ω_max` and every mode with `Re λ ≥ 0` (an unstable
//!    mode is never truncated). A complex pair `λ = σ ± iω` with right vector `v` and left vector `w`
//!    (`W = V⁻¹`) becomes two real states `ξ = [Re(w x), Im(w x)]`:
//!    ```text
//!    ξ̇ = [[σ, −ω], [ω, σ]] ξ + [Re(wB); Im(wB)] u,     y ≈ C [2 Re v, −2 Im v] ξ
//!    ```
//!    Each kept mode is then scaled so that its input row and output column have the same size.
//! 2. **Regulator** on the reduced model: minimise `∫ Σ_s q_s y_s² + Σ_a r_a u_a² dt` with the readings in µm
//!    (mm/s for a velocity pickup) and the signals in volts — `Q = C_rᵀ diag(q) C_r`, `R = diag(r)` — by the
//!    Riccati equation ([`super::riccati`]): `u = −K ξ`.
//! 3. **Observer**: the sensors do not read `ξ`; a Kalman–Bucy filter on the reduced model estimates it,
//!    designed by the dual Riccati equation with a unit-intensity disturbance at every actuator input
//!    (`B_r B_rᵀ`) and a sensor noise of intensity `ν` (`control.lqr.sensor_noise`, in reading units² per V²):
//!    `L = P C_rᵀ / ν`. The compensator, from the sensors (SI) to the signals, is
//!    ```text
//!    ξ̂̇ = (A_r − B_r K − L C_r) ξ̂ + L y,     v = K ξ̂      (u = −g v, g = control.gain, 1 as designed)
//!    ```
//!    On the reduced model itself the closed loop's poles are those of `A_r − B_r K` and of `A_r − L C_r`
//!    (the separation principle; the unit test checks it to round-off on a model kept whole). On the full
//!    plant the truncated modes are left to the analysis: the closed loop is evaluated with every state.

use nalgebra::DMatrix;
use serde::{Deserialize, Serialize};

use super::error::{ControlError, LqrFailure};
use super::plant::Plant;
use super::riccati::{care, RiccatiError};
use super::state_space::{eigen, StateSpace, C64};
use crate::model::control::{LqrSpec, Sensor};

/// The reduced model and how it was cut.
#[derive(Debug, Clone, PartialEq)]
pub struct Reduced {
    /// Inputs: the actuators' signals [V]; outputs: the readings in µm (mm/s).
    pub ss: StateSpace,
    /// The kept modes' natural frequencies `|λ|/2π` [Hz] (one per pair or real pole).
    pub kept_hz: Vec<f64>,
    /// States of the full plant.
    pub full_states: usize,
}

/// What the design produced, for the report.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct LqrDesign {
    pub design_speed_rad_s: f64,
    /// States of the reduced model / of the full plant.
    pub reduced_states: usize,
    pub full_states: usize,
    /// The kept modes' frequencies [Hz].
    pub kept_hz: Vec<f64>,
    /// The regulator's poles on the reduced model (eigenvalues of `A_r − B_r K`): (Re [1/s], Im [rad/s]).
    pub regulator_poles: Vec<(f64, f64)>,
    /// The observer's poles (eigenvalues of `A_r − L C_r`).
    pub observer_poles: Vec<(f64, f64)>,
}

/// The plant's modes kept below `max_rad_s` (and every unstable one), in real modal coordinates, its outputs
/// in µm (mm/s) per `sensors`.
///
/// # Errors
/// [`ControlError::Eigen`].
pub fn reduce(plant: &Plant, sensors: &[Sensor], max_rad_s: f64) -> Result<Reduced, ControlError> {
    let p = &plant.ss;
    let n = p.states();
    let (values, v) = eigen(&p.a)?;
    let w = v.clone().try_inverse().ok_or(ControlError::Eigen { size: n })?;
    let cb = p.b.map(C64::from);
    let cc = DMatrix::from_fn(p.c.nrows(), n, |i, j| C64::from(p.c[(i, j)] / sensors[i].quantity.reading_unit()));
    let wb = &w * cb;
    let cv = cc * &v;
    // kept: real poles and the upper member of each pair
    let mut kept: Vec<usize> = (0..n)
        .filter(|&k| {
            let l = values[k];
            let real = l.im.abs() <= 1e-9 * l.norm().max(1e-300);
            (real || l.im > 0.0) && (l.norm() <= max_rad_s || l.re >= 0.0)
        })
        .collect();
    kept.sort_by(|&i, &j| values[i].norm().total_cmp(&values[j].norm()));
    let order: usize =
        kept.iter().map(|&k| if values[k].im.abs() <= 1e-9 * values[k].norm().max(1e-300) { 1 } else { 2 }).sum();
    let (na, ns) = (p.b.ncols(), p.c.nrows());
    let mut ss = StateSpace {
        a: DMatrix::zeros(order, order),
        b: DMatrix::zeros(order, na),
        c: DMatrix::zeros(ns, order),
        d: p.d.clone(),
    };
    let mut at = 0;
    let mut kept_hz = Vec::new();
    for &k in &kept {
        let l = values[k];
        kept_hz.push(l.norm() / std::f64::consts::TAU);
        if l.im.abs() <= 1e-9 * l.norm().max(1e-300) {
            ss.a[(at, at)] = l.re;
            for j in 0..na {
                ss.b[(at, j)] = wb[(k, j)].re;
            }
            for i in 0..ns {
                ss.c[(i, at)] = cv[(i, k)].re;
            }
            at += 1;
        } else {
            ss.a[(at, at)] = l.re;
            ss.a[(at, at + 1)] = -l.im;
            ss.a[(at + 1, at)] = l.im;
            ss.a[(at + 1, at + 1)] = l.re;
            for j in 0..na {
                ss.b[(at, j)] = wb[(k, j)].re;
                ss.b[(at + 1, j)] = wb[(k, j)].im;
            }
            for i in 0..ns {
                ss.c[(i, at)] = 2.0 * cv[(i, k)].re;
                ss.c[(i, at + 1)] = -2.0 * cv[(i, k)].im;
            }
            at += 2;
        }
    }
    // balance each mode: the same size for its input rows and its output columns
    let mut i = 0;
    for &k in &kept {
        let m = if values[k].im.abs() <= 1e-9 * values[k].norm().max(1e-300) { 1 } else { 2 };
        let rb = ss.b.rows(i, m).norm();
        let cc = ss.c.columns(i, m).norm();
        if rb > 0.0 && cc > 0.0 {
            let s = (cc / rb).sqrt();
            let mut rows = ss.b.rows_mut(i, m);
            rows *= s;
            let mut cols = ss.c.columns_mut(i, m);
            cols /= s;
        }
        i += m;
    }
    Ok(Reduced { ss, kept_hz, full_states: n })
}

/// Designs the compensator of `spec` on `plant` (the plant at the design speed).
///
/// # Errors
/// [`ControlError::Lqr`]: a kept unstable mode that no actuator moves (not stabilisable) or that no sensor
/// sees (not detectable), or a Riccati equation without a stabilising solution; [`ControlError::Eigen`].
pub fn design(
    plant: &Plant,
    sensors: &[Sensor],
    spec: &LqrSpec,
    design_speed_rad_s: f64,
) -> Result<(StateSpace, LqrDesign), ControlError> {
    let red = reduce(plant, sensors, spec.max_frequency_rad_s)?;
    let r = &red.ss;
    let n = r.states();
    let speed_rpm = crate::units::RPM.from_si(design_speed_rad_s);
    let fail = |reason: LqrFailure| ControlError::Lqr { speed_rpm, reason };
    if n == 0 {
        return Err(fail(LqrFailure::NoModes { max_frequency_hz: spec.max_frequency_rad_s / std::f64::consts::TAU }));
    }
    // unstable modes the actuators cannot move or the sensors cannot see
    let scale_b = r.b.norm().max(f64::MIN_POSITIVE);
    let scale_c = r.c.norm().max(f64::MIN_POSITIVE);
    let mut i = 0;
    while i < n {
        let m = if i + 1 < n && r.a[(i + 1, i)] != 0.0 { 2 } else { 1 };
        if r.a[(i, i)] >= 0.0 {
            let frequency_hz = r.a.view((i, i), (m, m)).norm() / std::f64::consts::TAU;
            if r.b.rows(i, m).norm() <= 1e-9 * scale_b {
                return Err(fail(LqrFailure::NotStabilisable { frequency_hz }));
            }
            if r.c.columns(i, m).norm() <= 1e-9 * scale_c {
                return Err(fail(LqrFailure::NotDetectable { frequency_hz }));
            }
        }
        i += m;
    }
    let q = r.c.transpose() * DMatrix::from_diagonal(&nalgebra::DVector::from_vec(spec.output_weight.clone())) * &r.c;
    let rr = DMatrix::from_diagonal(&nalgebra::DVector::from_vec(spec.input_weight.clone()));
    let riccati = |e: RiccatiError| fail(LqrFailure::Riccati { message: e.to_string() });
    let regulator = care(&r.a, &r.b, &q, &rr).map_err(riccati)?;
    let noise = DMatrix::identity(r.c.nrows(), r.c.nrows()) * spec.sensor_noise;
    let filter = care(&r.a.transpose(), &r.c.transpose(), &(&r.b * r.b.transpose()), &noise).map_err(riccati)?;
    let k = regulator.k;
    let l = filter.k.transpose();
    // the compensator: readings in SI in, volts out
    let to_units = DMatrix::from_diagonal(&nalgebra::DVector::from_iterator(
        sensors.len(),
        sensors.iter().map(|s| 1.0 / s.quantity.reading_unit()),
    ));
    let controller = StateSpace {
        a: &r.a - &r.b * &k - &l * &r.c,
        b: &l * to_units,
        c: k.clone(),
        d: DMatrix::zeros(k.nrows(), sensors.len()),
    };
    let pairs = |m: &DMatrix<f64>| -> Result<Vec<(f64, f64)>, ControlError> {
        let mut v: Vec<(f64, f64)> =
            super::state_space::eigenvalues(m)?.iter().filter(|z| z.im >= 0.0).map(|z| (z.re, z.im)).collect();
        v.sort_by(|a, b| a.1.total_cmp(&b.1));
        Ok(v)
    };
    let report = LqrDesign {
        design_speed_rad_s,
        reduced_states: n,
        full_states: red.full_states,
        kept_hz: red.kept_hz.clone(),
        regulator_poles: pairs(&(&r.a - &r.b * &k))?,
        observer_poles: pairs(&(&r.a - &l * &r.c))?,
    };
    Ok((controller, report))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::control::closed_loop::closed;
    use crate::control::state_space::eigenvalues;
    use crate::model::control::{Axis, Quantity, SensorAt};

    /// A Jeffcott rotor (m 10 kg, c 50 N·s/m, k 1 MN/m) with a flat force actuator (100 N/V), displacement
    /// and velocity sensors: kept whole (no truncation), the compensator closed on the plant has exactly the
    /// regulator's and the observer's poles (the separation principle), to 1e-9 relative.
    #[test]
    fn separation_principle_on_a_model_kept_whole() {
        let (m, c, k, g) = (10.0, 50.0, 1e6, 100.0);
        let plant = Plant {
            ss: StateSpace {
                a: DMatrix::from_row_slice(2, 2, &[0.0, 1.0, -k / m, -c / m]),
                b: DMatrix::from_row_slice(2, 1, &[0.0, g / m]),
                c: DMatrix::from_row_slice(2, 2, &[1.0, 0.0, 0.0, 1.0]),
                d: DMatrix::zeros(2, 1),
            },
            force: DMatrix::from_row_slice(2, 1, &[0.0, 1.0 / m]),
            coordinates: DMatrix::from_row_slice(1, 2, &[1.0, 0.0]),
            nozzle_pressure: vec![vec![]],
        };
        let sensor = |quantity| Sensor { at: SensorAt::Node(0), node: 0, direction: Axis::Y, quantity };
        let sensors = [sensor(Quantity::Displacement), sensor(Quantity::Velocity)];
        let spec = LqrSpec {
            design_speed_rad_s: None,
            output_weight: vec![1.0, 0.0],
            input_weight: vec![0.5],
            max_frequency_rad_s: 1e6,
            sensor_noise: 1e-2,
        };
        let (controller, report) = design(&plant, &sensors, &spec, 0.0).unwrap();
        assert_eq!(report.reduced_states, 2);
        let mut got: Vec<C64> = eigenvalues(&closed(&plant, &controller, 1.0)).unwrap();
        let mut want: Vec<C64> = report
            .regulator_poles
            .iter()
            .chain(&report.observer_poles)
            .flat_map(
                |&(re, im)| if im > 0.0 { vec![C64::new(re, im), C64::new(re, -im)] } else { vec![C64::new(re, im)] },
            )
            .collect();
        let key = |z: &C64| (z.im, z.re);
        got.sort_by(|a, b| key(a).partial_cmp(&key(b)).unwrap());
        want.sort_by(|a, b| key(a).partial_cmp(&key(b)).unwrap());
        assert_eq!(got.len(), want.len());
        for (a, b) in got.iter().zip(&want) {
            assert!((a - b).norm() < 1e-9 * b.norm(), "{a} vs {b}");
        }
        // the regulator damps the rotor's mode: ζ from ≈0.008 open to more than 0.1
        let (re, im) = report.regulator_poles[0];
        assert!(-re / re.hypot(im) > 0.1, "{re} {im}");
    }

    /// An unstable mode no actuator moves (the force on a node decoupled from it): a named error.
    #[test]
    fn unstabilisable_design_is_named() {
        let plant = Plant {
            ss: StateSpace {
                a: DMatrix::from_row_slice(2, 2, &[0.5, 0.0, 0.0, -1.0]),
                b: DMatrix::from_row_slice(2, 1, &[0.0, 1.0]),
                c: DMatrix::from_row_slice(1, 2, &[1.0, 1.0]),
                d: DMatrix::zeros(1, 1),
            },
            force: DMatrix::zeros(2, 1),
            coordinates: DMatrix::zeros(1, 2),
            nozzle_pressure: vec![vec![]],
        };
        let sensors = [Sensor { at: SensorAt::Node(0), node: 0, direction: Axis::Y, quantity: Quantity::Displacement }];
        let spec = LqrSpec {
            design_speed_rad_s: Some(100.0),
            output_weight: vec![1.0],
            input_weight: vec![1.0],
            max_frequency_rad_s: 1e3,
            sensor_noise: 1.0,
        };
        let e = design(&plant, &sensors, &spec, 100.0).unwrap_err();
        assert!(matches!(e, ControlError::Lqr { reason: LqrFailure::NotStabilisable { .. }, .. }), "{e}");
        assert!(e.to_string().contains("design_speed_rpm"), "{e}");
    }
}
