//! `tiltpad.coefficients` and `tiltpad.frf`: reduced coefficients over running speed (the band sampler the
//! command line's `tiltpad coefficients` uses, `study::band`, with its refinement and warnings, so
//! `tiltpad.ross.bearing_element` and `--ross` give the same elements) or over excitation frequency, and the
//! controllable bearing's frequency responses (`tiltpad frf`).

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use std::sync::Arc;

use tiltpad::bearing::frf::model::{band as frequency_band, FrfModel, FrfSweep};
use tiltpad::bearing::{Request, SolveError, StageId};
use tiltpad::io::coefficients::{CoefficientTable, FrequencyMeaning};
use tiltpad::scene::frf::FrfCurves;
use tiltpad::study::band::{self, BandParams, BandWarning};
use tiltpad::study::PointError;

use crate::case::Case;
use crate::control::{CancelToken, Control};
use crate::convert::{stack, vector};
use crate::errors::{json_to_py, point_error};
use crate::solve::{run_stages, solve_detached};

/// Reduced 2×2 coefficients over frequency, with the warnings of their sampling.
///
/// `frequency_rad_s` is the running speed Ω of a speed band (each point condensed at ω = (ω/Ω)·Ω, the
/// case's excitation ratio) or the excitation frequency ω at the case's speed; `k_n_per_m` [N/m] and
/// `c_ns_per_m` [N·s/m] have shape (n, 2, 2), rows and columns x (horizontal), y (vertical up), as ROSS has
/// them.
#[pyclass(module = "tiltpad", frozen)]
pub struct Coefficients {
    pub table: CoefficientTable,
    pub warnings: Vec<BandWarning>,
    pub solves: usize,
}

#[pymethods]
impl Coefficients {
    /// Frequency of each row [rad/s]: the running speed (speed bands) or the excitation frequency.
    #[getter]
    fn frequency_rad_s<'py>(&self, py: Python<'py>) -> Bound<'py, PyAny> {
        vector(py, &self.table.frequency_rad_s).into_any()
    }
    /// Running speed of each row [rpm].
    #[getter]
    fn speed_rpm<'py>(&self, py: Python<'py>) -> Bound<'py, PyAny> {
        vector(py, &self.table.speed_rpm).into_any()
    }
    /// Excitation frequency of each row's reduction [rad/s].
    #[getter]
    fn excitation_rad_s<'py>(&self, py: Python<'py>) -> Bound<'py, PyAny> {
        vector(py, &self.table.excitation_rad_s).into_any()
    }
    /// Reduced stiffness [N/m], shape (n, 2, 2).
    #[getter]
    fn k_n_per_m<'py>(&self, py: Python<'py>) -> Bound<'py, PyAny> {
        stack(py, &self.table.k_n_per_m).into_any()
    }
    /// Reduced damping [N·s/m], shape (n, 2, 2).
    #[getter]
    fn c_ns_per_m<'py>(&self, py: Python<'py>) -> Bound<'py, PyAny> {
        stack(py, &self.table.c_ns_per_m).into_any()
    }
    /// `"running_speed"` (a speed band) or `"excitation"` (frequencies at one speed).
    #[getter]
    fn meaning(&self) -> &'static str {
        match self.table.meaning {
            FrequencyMeaning::RunningSpeed { .. } => "running_speed",
            FrequencyMeaning::Excitation => "excitation",
        }
    }
    /// The sampling's warnings as sentences (the band misses the analysis range, jumps between samples,
    /// speeds left out).
    #[getter]
    fn warnings(&self) -> Vec<String> {
        self.warnings.iter().map(ToString::to_string).collect()
    }
    /// The same warnings with their data (`kind`, speeds, term …).
    #[getter]
    fn warning_details<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        json_to_py(py, &serde_json::to_value(&self.warnings).unwrap_or_default())
    }
    /// Bearing solves made (refinement included).
    #[getter]
    fn solves(&self) -> usize {
        self.solves
    }
    /// The CSV `tiltpad coefficients --csv` writes.
    fn to_csv(&self) -> String {
        self.table.csv()
    }
    /// The ROSS bearing-element file `tiltpad coefficients --ross` writes: one element per `(node, tag)`.
    #[pyo3(signature = (elements, source = "tiltpad"))]
    fn to_ross_toml(&self, elements: Vec<(usize, String)>, source: &str) -> String {
        self.table.ross_toml_elements(&elements, source)
    }
    /// The columns of the CSV as NumPy arrays (keys with their units).
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        d.set_item("frequency_rad_s", self.frequency_rad_s(py))?;
        d.set_item("speed_rpm", self.speed_rpm(py))?;
        d.set_item("excitation_rad_s", self.excitation_rad_s(py))?;
        for (name, k, i, j) in band::TERMS {
            let v: Vec<f64> = if k {
                self.table.k_n_per_m.iter().map(|m| m[i][j]).collect()
            } else {
                self.table.c_ns_per_m.iter().map(|m| m[i][j]).collect()
            };
            d.set_item(format!("{name}_{}", if k { "n_per_m" } else { "ns_per_m" }), vector(py, &v))?;
        }
        Ok(d)
    }
    fn __len__(&self) -> usize {
        self.table.frequency_rad_s.len()
    }
    fn __repr__(&self) -> String {
        format!(
            "<tiltpad.Coefficients: {} rows over {}, {} warnings>",
            self.table.frequency_rad_s.len(),
            self.meaning(),
            self.warnings.len()
        )
    }
}

/// Reduced coefficients over running speed (`speeds_rpm`) or over excitation frequency at the case's speed
/// (`excitation_ratios`, ω/Ω), as `tiltpad coefficients` computes them.
///
/// - `refine`: check every interval of the speed band at its midpoint and halve it where a cubic through the
///   samples misses the coefficients (what ROSS's spline needs; `tiltpad.ross.bearing_element` refines).
/// - `analysis_speeds_rpm`: the speeds of the rotor analysis these coefficients serve: a warning when the
///   band does not cover them.
///
/// Speeds that fail are left out with a warning (`warnings`); every speed failing raises `SolveError`.
#[pyfunction]
#[pyo3(signature = (case, *, speeds_rpm = None, excitation_ratios = None, refine = false,
    analysis_speeds_rpm = None, fidelity = None, progress = None, cancel = None))]
#[allow(clippy::too_many_arguments)]
pub fn coefficients(
    py: Python<'_>,
    case: &Bound<'_, Case>,
    speeds_rpm: Option<Vec<f64>>,
    excitation_ratios: Option<Vec<f64>>,
    refine: bool,
    analysis_speeds_rpm: Option<Vec<f64>>,
    fidelity: Option<&str>,
    progress: Option<Bound<'_, PyAny>>,
    cancel: Option<&Bound<'_, CancelToken>>,
) -> PyResult<Coefficients> {
    let control = Control::new(progress, cancel);
    let (text, mut base, resolved) = {
        let c = case.borrow();
        (c.text.clone(), c.overrides.clone(), c.with(py, &Case::fidelity_override(fidelity))?)
    };
    base.extend(Case::fidelity_override(fidelity));
    match (speeds_rpm, excitation_ratios) {
        (Some(_), Some(_)) => Err(PyValueError::new_err(
            "give speeds_rpm (a speed band) or excitation_ratios (frequencies at the case's speed), not both",
        )),
        (None, Some(ratios)) => {
            let sol = solve_detached(py, resolved, &control).map_err(|e| control.error(py, &e))?;
            let t = CoefficientTable::of_excitation(&sol, &ratios);
            Ok(Coefficients { table: t, warnings: Vec::new(), solves: 1 })
        }
        (speeds, None) => {
            let speeds = speeds.unwrap_or_else(|| vec![resolved.operating.speed_rad_s * 60.0 / std::f64::consts::TAU]);
            let analysis = analysis_speeds_rpm.and_then(|a| {
                let lo = a.iter().copied().fold(f64::INFINITY, f64::min);
                let hi = a.iter().copied().fold(f64::NEG_INFINITY, f64::max);
                (lo <= hi).then_some([lo, hi])
            });
            let params = BandParams { refine, analysis_rpm: analysis, ..BandParams::default() };
            let ratio = resolved.operating.excitation_ratio;
            let result = py.detach(|| {
                let mut runner = band::cold_runner(text, base);
                let mut solves = 0usize;
                let band = band::sample(&speeds, &params, &mut |rpm| {
                    if control.stopped() {
                        return Err(PointError::Solve(SolveError::Cancelled));
                    }
                    let s = band::solve_point(&mut runner, rpm, &control);
                    solves += 1;
                    control.report(band_fraction(solves, speeds.len(), refine), &format!("{rpm:.1} rpm"));
                    s
                })?;
                control.report(1.0, &format!("{solves} speeds solved"));
                Ok(band)
            });
            let band = match result {
                Ok(b) => b,
                Err(PointError::Solve(SolveError::Cancelled)) => {
                    return Err(control.error(py, &SolveError::Cancelled));
                }
                Err(e) => return Err(point_error(py, &e)),
            };
            if band.samples.is_empty() {
                let why = band.warnings.iter().map(ToString::to_string).collect::<Vec<_>>().join("; ");
                return Err(crate::errors::no_point_solved(py, format!("no speed solved: {why}")));
            }
            Ok(Coefficients {
                table: CoefficientTable::of_band(&band, ratio),
                warnings: band.warnings,
                solves: band.solves,
            })
        }
    }
}

/// Progress of a speed band after `solves` solves of `requested` speeds: the requested speeds take the whole
/// way without refinement; with it they take 80 % and the midpoints (their number is not known beforehand)
/// the rest, approaching it as `r / (r + requested)` after `r` of them. Below 1 until the caller says done.
fn band_fraction(solves: usize, requested: usize, refine: bool) -> f64 {
    #[allow(clippy::cast_precision_loss)]
    let (s, n) = (solves as f64, requested.max(1) as f64);
    let first = if refine { 0.8 } else { 0.999 };
    if s <= n {
        first * s / n
    } else {
        let r = s - n;
        first + (0.999 - first) * r / (r + n)
    }
}

/// The controllable bearing's frequency responses over a band, as `tiltpad frf` computes them: the valve
/// G1 = x_V/u_V [V/V], the line G2 = p_inj/x_V per port [bar/V], the film G3 = F/p_inj per port and axis
/// [N/bar], G = G1·G2·G3 per axis [N/V], and with `[hydraulics.rig]` the shaker chain (C [N/V], Ĥ [µm/V],
/// H [µm/N]).
///
/// Returns `{"frequency_hz": array, "curves": {name: {"unit", "group", "magnitude": array, "phase_deg":
/// array}}, "line_modes_hz": [[…] per port], "title": str, "notes": [str], "eccentricity_ratio": float}`.
/// Frequencies are log-spaced from `from_hz` (> 0) to `to_hz`, linear when `from_hz` is 0.
///
/// `progress(fraction, message)` after each solver stage (the equilibrium and the linearisation: up to 0.9)
/// and after each twentieth of the band (the rest); returning `False` cancels. `cancel`: a `CancelToken`.
#[pyfunction]
#[pyo3(signature = (case, *, from_hz = 1.0, to_hz = 1000.0, points = 400, amplitude_v = None, fidelity = None,
    progress = None, cancel = None))]
#[allow(clippy::too_many_arguments)]
pub fn frf<'py>(
    py: Python<'py>,
    case: &Bound<'py, Case>,
    from_hz: f64,
    to_hz: f64,
    points: usize,
    amplitude_v: Option<f64>,
    fidelity: Option<&str>,
    progress: Option<Bound<'py, PyAny>>,
    cancel: Option<&Bound<'py, CancelToken>>,
) -> PyResult<Bound<'py, PyDict>> {
    if !(from_hz >= 0.0 && to_hz > from_hz && to_hz.is_finite()) {
        return Err(PyValueError::new_err(format!("from_hz {from_hz}, to_hz {to_hz}: need 0 ≤ from_hz < to_hz")));
    }
    if !(2..=100_000).contains(&points) {
        return Err(PyValueError::new_err(format!("points {points}: allowed 2 to 100000")));
    }
    let resolved = case.borrow().with(py, &Case::fidelity_override(fidelity))?;
    if resolved.hydraulics.is_none() {
        return Err(crate::errors::solve_error(py, &SolveError::NoHydraulics));
    }
    let control = Control::new(progress, cancel);
    let freqs = frequency_band(from_hz, to_hz, points);
    let computed = py.detach(|| frf_detached(&resolved, &freqs, &control));
    let (model, sweep) = computed.map_err(|e| control.error(py, &e))?;
    let Some(h) = resolved.hydraulics.as_ref() else {
        return Err(crate::errors::solve_error(py, &SolveError::NoHydraulics));
    };
    let title = format!(
        "{} — {:.0} rpm, ε = {:.3}, supply {:.0} bar",
        resolved.title,
        tiltpad::units::RPM.from_si(resolved.operating.speed_rad_s),
        model.eccentricity_ratio,
        tiltpad::units::BAR.from_si(h.supply_pressure_pa)
    );
    let mut curves = FrfCurves::new(&sweep, &tiltpad::scene::frf::port_names(&resolved), title);
    if let Some(a) = amplitude_v {
        curves.check_signal(a, 0.1 * h.valve.full_scale_v);
    }
    let out = PyDict::new(py);
    out.set_item("frequency_hz", vector(py, &curves.frequency_hz))?;
    let named = PyDict::new(py);
    for c in &curves.curves {
        let d = PyDict::new(py);
        d.set_item("unit", c.unit)?;
        d.set_item("group", c.group)?;
        d.set_item("magnitude", vector(py, &c.magnitude))?;
        d.set_item("phase_deg", vector(py, &c.phase_deg))?;
        named.set_item(&c.name, d)?;
    }
    out.set_item("curves", named)?;
    out.set_item("line_modes_hz", curves.line_modes_hz.clone())?;
    out.set_item("title", &curves.title)?;
    out.set_item("notes", curves.notes.clone())?;
    out.set_item("eccentricity_ratio", model.eccentricity_ratio)?;
    Ok(out)
}

/// Share of the progress the stages (equilibrium, linearisation) take in `frf`, the band the rest: the
/// equilibrium costs far more than the band (`tiltpad frf` on the Publication 5 rig: 0.1 s against under
/// 1 ms for 400 frequencies).
const FRF_STAGES_SHARE: f64 = 0.9;
/// Parts of the band between two progress reports (and cancellation checks).
const FRF_BAND_PARTS: usize = 20;

/// The FRF stages, then the band in parts (each frequency is independent, so the parts join into the sweep
/// one call over the whole band gives); without the GIL.
fn frf_detached(
    case: &tiltpad::model::Case,
    freqs: &[f64],
    control: &Control,
) -> Result<(Arc<FrfModel>, FrfSweep), SolveError> {
    let outcome = run_stages(&Request::frf(case.clone()), StageId::Frf, FRF_STAGES_SHARE, control)?;
    let model = outcome.frf().ok_or(SolveError::Cancelled)?;
    let part = freqs.len().div_ceil(FRF_BAND_PARTS).max(1);
    let mut sweep: Option<FrfSweep> = None;
    let mut done = 0usize;
    for chunk in freqs.chunks(part) {
        if control.stopped() {
            return Err(SolveError::Cancelled);
        }
        let s = model.sweep(case, chunk)?;
        done += chunk.len();
        sweep = Some(match sweep {
            None => s,
            Some(mut all) => {
                all.points.extend(s.points);
                if let (Some(a), Some(b)) = (all.shaker.as_mut(), s.shaker) {
                    a.extend(b);
                }
                all.seconds += s.seconds;
                all
            }
        });
        #[allow(clippy::cast_precision_loss)]
        let fraction = FRF_STAGES_SHARE + (1.0 - FRF_STAGES_SHARE) * done as f64 / freqs.len() as f64;
        control.report(fraction, &format!("{done} of {} frequencies", freqs.len()));
    }
    let sweep = sweep.ok_or(SolveError::Cancelled)?;
    Ok((model, sweep))
}
