//! FRF curves for the Bode view, the CLI and the exports: magnitude and unwrapped phase of every transfer
//! function of an [`FrfSweep`] against frequency, the line modes to mark, and the notes the view states.
//!
//! Curves (names as in the CSV header): `G1` [V/V]; per port `G2_A` [bar/V]; per port and axis `G3_A_y`
//! [N/bar]; per axis `G_y` [N/V]; with a rig `C` [N/V], `H_pseudo` [µm/V], `H_chain` and `H_direct`
//! [µm/N] (configuration 2: rotor free). Phases in degrees, unwrapped along the band.

use nalgebra::Complex;
use serde::Serialize;

use crate::bearing::frf::model::FrfSweep;
use crate::model::Case;
use crate::units::{BAR, UM};

type C64 = Complex<f64>;

/// The model limitation the thesis measured (its §6.3), stated wherever FRFs are shown.
pub const PHASE_LAG_NOTE: &str = "The thesis measured an extra phase lag between the nozzle pressure and the active force (its §6.3). \
    This model does not contain it: the Reynolds film is quasi-static, so the force follows the injection pressure without delay.";

/// One transfer function over the band.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Curve {
    /// `G1`, `G2_A`, `G3_A_y`, `G_y`, `C`, `H_pseudo`, `H_chain`, `H_direct`.
    pub name: String,
    /// Unit of the magnitude.
    pub unit: &'static str,
    /// Which group the view toggles it with: `G1`, `G2`, `G3`, `G`, `rig`.
    pub group: &'static str,
    pub magnitude: Vec<f64>,
    pub phase_deg: Vec<f64>,
}

/// Everything a Bode plot of one sweep needs.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FrfCurves {
    pub frequency_hz: Vec<f64>,
    pub curves: Vec<Curve>,
    /// Acoustic mode frequencies of each port's line [Hz], to mark.
    pub line_modes_hz: Vec<Vec<f64>>,
    /// The operating point, for titles.
    pub title: String,
    pub notes: Vec<String>,
}

/// Phase in degrees, unwrapped along the sequence (jumps of more than 180° folded back).
#[must_use]
pub fn unwrapped_phase_deg(values: &[C64]) -> Vec<f64> {
    let mut out: Vec<f64> = Vec::with_capacity(values.len());
    for v in values {
        let mut p = v.arg().to_degrees();
        if let Some(&prev) = out.last() {
            p += 360.0 * ((prev - p) / 360.0).round();
        }
        out.push(p);
    }
    out
}

/// A curve of `values` (SI) shown in `unit`, `scale` times the SI magnitude (from [`crate::units`]).
fn curve(name: String, unit: &'static str, group: &'static str, scale: f64, values: &[C64]) -> Curve {
    Curve {
        name,
        unit,
        group,
        magnitude: values.iter().map(|v| v.norm() * scale).collect(),
        phase_deg: unwrapped_phase_deg(values),
    }
}

const PORTS: [&str; 2] = ["A", "B"];

/// Port names of a case in its order: the servovalve port each nozzle line is fed from (`A` or `B`); none
/// without `[hydraulics]`.
#[must_use]
pub fn port_names(case: &Case) -> Vec<&'static str> {
    case.hydraulics
        .as_ref()
        .map_or_else(Vec::new, |h| h.ports.iter().map(|p| if p.sign > 0.0 { PORTS[0] } else { PORTS[1] }).collect())
}
const AXES: [&str; 2] = ["x", "y"];

impl FrfCurves {
    /// The curves of a sweep; `port_names` name the ports (`A`, `B`) in the sweep's order.
    #[must_use]
    pub fn new(sweep: &FrfSweep, port_names: &[&str], title: String) -> Self {
        let pts = &sweep.points;
        let get = |f: &dyn Fn(&crate::bearing::frf::dynamics::FrfPoint) -> C64| pts.iter().map(f).collect::<Vec<_>>();
        let mut curves = vec![curve("G1".into(), "V/V", "G1", 1.0, &get(&|p| p.g1))];
        let np = pts.first().map_or(0, |p| p.g2.len());
        let name = |k: usize| port_names.get(k).copied().unwrap_or(PORTS[k.min(1)]);
        for k in 0..np {
            curves.push(curve(format!("G2_{}", name(k)), "bar/V", "G2", BAR.from_si(1.0), &get(&|p| p.g2[k])));
        }
        for k in 0..np {
            for (a, ax) in AXES.iter().enumerate() {
                curves.push(curve(
                    format!("G3_{}_{ax}", name(k)),
                    "N/bar",
                    "G3",
                    BAR.to_si(1.0),
                    &get(&|p| p.g3[k][a]),
                ));
            }
        }
        for (a, ax) in AXES.iter().enumerate() {
            curves.push(curve(format!("G_{ax}"), "N/V", "G", 1.0, &get(&|p| p.g[a])));
        }
        if let Some(sh) = &sweep.shaker {
            let col =
                |f: &dyn Fn(&crate::bearing::frf::dynamics::ShakerPoint) -> C64| sh.iter().map(f).collect::<Vec<_>>();
            curves.push(curve("C".into(), "N/V", "rig", 1.0, &col(&|p| p.calibration)));
            curves.push(curve("H_pseudo".into(), "µm/V", "rig", UM.from_si(1.0), &col(&|p| p.pseudo)));
            curves.push(curve("H_chain".into(), "µm/N", "rig", UM.from_si(1.0), &col(&|p| p.chain)));
            curves.push(curve("H_direct".into(), "µm/N", "rig", UM.from_si(1.0), &col(&|p| p.direct)));
        }
        Self {
            frequency_hz: pts.iter().map(|p| p.frequency_hz).collect(),
            curves,
            line_modes_hz: sweep.line_modes_hz.clone(),
            title,
            notes: vec![PHASE_LAG_NOTE.to_string()],
        }
    }

    /// Adds the small-signal warning when a control amplitude exceeds the valve model's range.
    pub fn check_signal(&mut self, amplitude_v: f64, limit_v: f64) {
        if amplitude_v > limit_v {
            self.notes.push(format!(
                "Control amplitude {amplitude_v} V exceeds the small-signal range of the linear valve model ({limit_v} V, 10 % of full scale): the valve's response is no longer linear."
            ));
        }
    }

    /// CSV: `frequency_hz`, then `<name>_mag_<unit>` and `<name>_phase_deg` per curve.
    #[must_use]
    pub fn csv(&self) -> String {
        let mut s = String::from("frequency_hz");
        for c in &self.curves {
            s.push_str(&format!(",{}_mag_{},{}_phase_deg", c.name, c.unit.replace('/', "_per_"), c.name));
        }
        s.push('\n');
        for (i, f) in self.frequency_hz.iter().enumerate() {
            s.push_str(&crate::number::csv(*f));
            for c in &self.curves {
                s.push_str(&format!(",{:e},{:.6}", c.magnitude[i], c.phase_deg[i]));
            }
            s.push('\n');
        }
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn phase_is_unwrapped_across_the_branch_cut() {
        // A delay e^{-iωτ} over three turns: the unwrapped phase falls linearly, the wrapped one would jump.
        let v: Vec<C64> = (0..100).map(|i| C64::from_polar(1.0, -0.2 * f64::from(i))).collect();
        let p = unwrapped_phase_deg(&v);
        for (i, x) in p.iter().enumerate() {
            let expect = (-0.2 * f64::from(u32::try_from(i).unwrap())).to_degrees();
            assert!((x - expect).abs() < 1e-9, "{i}: {x} vs {expect}");
        }
    }
}
