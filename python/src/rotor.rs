//! `tiltpad.rotor`: the rotor–bearing analysis of `tiltpad rotor` (a rotor file and the bearing cases it
//! names, solved through the stages at each speed), stepped one speed at a time with the GIL released.

use std::path::PathBuf;

use numpy::ndarray::{Array1, Array2};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

use tiltpad::model::rotor::{CoefficientModel, Rotor};
use tiltpad::rotor::analysis::{Analysis, AnalysisParams, AnalysisResult, Step};
use tiltpad::rotor::eigen::Whirl;
use tiltpad::rotor::RotorError;
use tiltpad::units::RPM;

use crate::control::{CancelToken, Control};
use crate::convert::{array, vector};
use crate::errors::{json_to_py, rotor_error};

/// A rotor analysis over speed: damped natural frequencies, logarithmic decrements and whirl per speed (the
/// lowest `modes` oscillatory modes; NaN where a speed has fewer), the instability onset, the 1× critical
/// speeds and the unbalance response. `str(result)` is the summary `tiltpad rotor` prints; `to_dict()` its
/// JSON; `to_csv()` its CSV.
#[pyclass(module = "tiltpad", frozen)]
pub struct RotorResult {
    rotor: Rotor,
    result: AnalysisResult,
    modes: usize,
}

impl RotorResult {
    fn per_mode(&self, f: impl Fn(&tiltpad::rotor::eigen::Mode) -> f64) -> Array2<f64> {
        let s = &self.result.speeds;
        Array2::from_shape_fn((s.len(), self.modes), |(i, m)| s[i].point.modes.modes.get(m).map_or(f64::NAN, &f))
    }
}

#[pymethods]
impl RotorResult {
    #[getter]
    fn title(&self) -> String {
        self.result.title.clone()
    }
    /// Spin speeds of the sweep [rpm], shape (n,).
    #[getter]
    fn speeds_rpm<'py>(&self, py: Python<'py>) -> Bound<'py, PyAny> {
        let v: Vec<f64> = self.result.speeds.iter().map(|p| RPM.from_si(p.point.speed_rad_s)).collect();
        vector(py, &v).into_any()
    }
    /// Damped natural frequencies [Hz], shape (n, modes), ascending at each speed.
    #[getter]
    fn frequencies_hz<'py>(&self, py: Python<'py>) -> Bound<'py, PyAny> {
        array(py, self.per_mode(tiltpad::rotor::eigen::Mode::frequency_hz)).into_any()
    }
    /// Damped natural frequencies [rad/s], shape (n, modes).
    #[getter]
    fn frequencies_rad_s<'py>(&self, py: Python<'py>) -> Bound<'py, PyAny> {
        array(py, self.per_mode(|m| m.imag_rad_s)).into_any()
    }
    /// Logarithmic decrements [–] (negative: unstable), shape (n, modes).
    #[getter]
    fn log_decrements<'py>(&self, py: Python<'py>) -> Bound<'py, PyAny> {
        array(py, self.per_mode(|m| m.log_dec)).into_any()
    }
    /// Whirl of each mode, `"F"` forward or `"B"` backward (`""` where a speed has fewer modes).
    #[getter]
    fn whirl(&self) -> Vec<Vec<&'static str>> {
        self.result
            .speeds
            .iter()
            .map(|p| {
                (0..self.modes)
                    .map(|m| match p.point.modes.modes.get(m).map(|x| x.whirl) {
                        Some(Whirl::Forward) => "F",
                        Some(Whirl::Backward) => "B",
                        None => "",
                    })
                    .collect()
            })
            .collect()
    }
    /// Smallest logarithmic decrement at each speed, shape (n,).
    #[getter]
    fn min_log_dec<'py>(&self, py: Python<'py>) -> Bound<'py, PyAny> {
        let v: Vec<f64> = self.result.speeds.iter().map(|p| p.point.min_log_dec()).collect();
        vector(py, &v).into_any()
    }
    /// Instability onset [rpm], or `None` when the sweep has none.
    #[getter]
    fn onset_rpm(&self) -> Option<f64> {
        self.result.onset.map(|o| RPM.from_si(o.speed_rad_s))
    }
    /// 1× critical speeds: `[{"rank", "whirl", "speed_rpm", "log_dec"}, …]`.
    #[getter]
    fn critical_speeds<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let v: Vec<serde_json::Value> = self
            .result
            .critical_speeds
            .iter()
            .map(|c| {
                serde_json::json!({
                    "rank": c.rank, "whirl": c.whirl, "order": c.order,
                    "speed_rpm": RPM.from_si(c.speed_rad_s), "log_dec": c.log_dec,
                })
            })
            .collect();
        json_to_py(py, &serde_json::Value::Array(v))
    }
    /// Nodes where the unbalance response is computed (bearing and unbalance nodes).
    #[getter]
    fn response_nodes(&self) -> Vec<usize> {
        self.result.response_nodes.clone()
    }
    /// Peak-to-peak major axis of the unbalance orbit at each response node [µm], shape (n, nodes) (NaN at
    /// zero speed or without unbalance).
    #[getter]
    fn response_pp_um<'py>(&self, py: Python<'py>) -> Bound<'py, PyAny> {
        let nodes = &self.result.response_nodes;
        let s = &self.result.speeds;
        let a = Array2::from_shape_fn((s.len(), nodes.len()), |(i, k)| {
            s[i].orbits.iter().find(|o| o.node == nodes[k]).map_or(f64::NAN, |o| o.major_pp_m * 1e6)
        });
        array(py, a).into_any()
    }
    /// API 617 vibration limit at each speed [µm peak-to-peak], shape (n,) (inf at zero speed).
    #[getter]
    fn api617_limit_um<'py>(&self, py: Python<'py>) -> Bound<'py, PyAny> {
        array(py, Array1::from_iter(self.result.speeds.iter().map(|p| p.api617_limit_um))).into_any()
    }
    /// The analysis's warnings, as sentences.
    #[getter]
    fn warnings(&self) -> Vec<String> {
        self.result.report.warnings.iter().map(|w| format!("{w:?}")).collect()
    }
    /// The JSON `tiltpad rotor --json` writes, as Python objects.
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        json_to_py(py, &serde_json::to_value(&self.result).map_err(|e| PyValueError::new_err(e.to_string()))?)
    }
    /// The CSV `tiltpad rotor --csv` writes.
    fn to_csv(&self) -> PyResult<String> {
        tiltpad::io::rotor_text::csv_text(&self.result).map_err(|e| PyValueError::new_err(e.to_string()))
    }
    /// The summary `tiltpad rotor` prints.
    #[getter]
    fn summary(&self) -> String {
        tiltpad::io::rotor_text::summary(&self.rotor, &self.result)
    }
    fn __str__(&self) -> String {
        self.summary()
    }
    fn __repr__(&self) -> String {
        format!(
            "<tiltpad.RotorResult {:?}: {} speeds, onset {}>",
            self.result.title,
            self.result.speeds.len(),
            self.onset_rpm().map_or_else(|| "none".to_string(), |o| format!("{o:.0} rpm"))
        )
    }
}

/// Analyses a rotor file (and the bearing cases it names, read beside it) at `speeds_rpm` (ascending), as
/// `tiltpad rotor` does: damped modes per speed, the instability onset, the 1× critical speeds and the
/// unbalance response.
///
/// - `coefficients`: `"full"` or `"reduced"` overrides the rotor file's bearing model;
/// - `shaft_modes`: fixed-interface shaft modes per plane (0: the full shaft), overriding the file;
/// - `progress(fraction, message)` after each speed; `cancel`: a `CancelToken` (checked between speeds).
#[pyfunction]
#[pyo3(signature = (path, *, speeds_rpm, coefficients = None, shaft_modes = None, modes = 6, progress = None,
    cancel = None))]
#[allow(clippy::too_many_arguments)]
pub fn rotor(
    py: Python<'_>,
    path: PathBuf,
    speeds_rpm: Vec<f64>,
    coefficients: Option<&str>,
    shaft_modes: Option<usize>,
    modes: usize,
    progress: Option<Bound<'_, PyAny>>,
    cancel: Option<&Bound<'_, CancelToken>>,
) -> PyResult<RotorResult> {
    let mut rotor = tiltpad::io::read::read_rotor(&path).map_err(|e| match &e {
        tiltpad::io::read::ReadError::InvalidRotor { error, .. } => crate::errors::case_error(py, error, None),
        _ => crate::errors::os_error(e.to_string()),
    })?;
    match coefficients {
        None => {}
        Some("full") => rotor.coefficients = CoefficientModel::Full,
        Some("reduced") => rotor.coefficients = CoefficientModel::Reduced,
        Some(other) => {
            return Err(PyValueError::new_err(format!("coefficients={other:?}: \"full\" or \"reduced\"")));
        }
    }
    if let Some(m) = shaft_modes {
        rotor.shaft_modes = m;
    }
    let speeds: Vec<f64> = speeds_rpm.iter().map(|&n| RPM.to_si(n)).collect();
    let control = Control::new(progress, cancel);
    let result = py.detach(|| -> Result<Option<AnalysisResult>, RotorError> {
        let mut a = Analysis::new(&rotor, AnalysisParams::new(speeds.clone()))?;
        loop {
            if control.stopped() {
                return Ok(None);
            }
            match a.step()? {
                Step::Finished => break,
                Step::More { done, of } => {
                    #[allow(clippy::cast_precision_loss)]
                    control.report(done as f64 / (of + 1) as f64, &format!("{done} of {of} speeds"));
                }
            }
        }
        let result = a.finish()?;
        control.report(1.0, "onset and critical speeds");
        Ok(Some(result))
    });
    match result {
        Ok(Some(result)) => Ok(RotorResult { rotor, result, modes }),
        Ok(None) => Err(control.take_error().unwrap_or_else(|| control.cancelled(py))),
        Err(e) => Err(rotor_error(py, &e)),
    }
}
