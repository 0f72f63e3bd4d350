//! `tiltpad.Solution` and `tiltpad.Pad`: a solved bearing as Python attributes (SI, the unit in every name;
//! a few engineering-unit twins where the command line's columns use them) and NumPy arrays.
//!
//! The solution is kept as the library's `Solution` (moved out of the solve, not copied); each array is copied
//! once from it when first read, then kept (read-only, so the copy a caller holds is the one every later read
//! returns). `to_dict()` is the JSON `tiltpad solve --json` writes, through the same function.

use std::collections::HashMap;
use std::sync::{Arc, Mutex};

use numpy::ndarray::{Array2, Array3};
use numpy::PyArrayMethods;
use pyo3::prelude::*;

use tiltpad::bearing::solution::json::solution_json;
use tiltpad::bearing::solution::limits::exceeded;
use tiltpad::bearing::solution::{PadField, PadResult};
use tiltpad::bearing::Solution as Solved;
use tiltpad::units::{MPA, UM};

use crate::convert::{array, bools, matrix, two_by_two, vector};
use crate::errors::json_to_py;

/// Objects made once per result and handed out on every read.
#[derive(Default)]
struct Kept(Mutex<HashMap<&'static str, Py<PyAny>>>);

impl Kept {
    fn get<'py>(
        &self,
        py: Python<'py>,
        name: &'static str,
        make: impl FnOnce() -> PyResult<Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        if let Some(v) = self.0.lock().ok().and_then(|m| m.get(name).map(|v| v.clone_ref(py))) {
            return Ok(v.into_bound(py));
        }
        let v = make()?;
        if let Ok(mut m) = self.0.lock() {
            m.insert(name, v.clone().unbind());
        }
        Ok(v)
    }
}

/// A bearing solve's result. Scalars are attributes with their unit in the name (SI: `h_min_m`,
/// `p_max_pa`; engineering twins of the CLI columns: `h_min_um`, `p_max_mpa`, `speed_rpm`), one for each
/// Python name of the library's table of outputs, put on the class by [`crate::outputs`]; coefficients and
/// fields are read-only NumPy arrays. `str(solution)` is the summary `tiltpad solve` prints; `to_dict()` the
/// JSON of `tiltpad solve --json`.
#[pyclass(module = "tiltpad", frozen)]
pub struct Solution {
    pub sol: Arc<Solved>,
    kept: Kept,
}

impl Solution {
    pub fn new(sol: Arc<Solved>) -> Self {
        Self { sol, kept: Kept::default() }
    }
}

#[pymethods]
impl Solution {
    #[getter]
    fn title(&self) -> String {
        self.sol.title.clone()
    }
    /// Journal centre displacement (x horizontal, y vertical up) [m], shape (2,).
    #[getter]
    fn journal_position_m<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        self.kept.get(py, "journal_position_m", || Ok(vector(py, &self.sol.journal_position_m).into_any()))
    }
    /// Load carried by the film (x, y; equal and opposite to the pads' forces on the journal) [N], shape (2,).
    #[getter]
    fn load_n<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        self.kept.get(py, "load_n", || Ok(vector(py, &self.sol.load_n).into_any()))
    }
    /// Whole-bearing flows [m³/s]: `leading_edges_in`, `trailing_edges_out`, `sides_out`, `orifices_in`,
    /// `to_cavitation`, and the discrete `mass_balance_error` [–].
    #[getter]
    fn flows_m3_per_s<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        json_to_py(py, &serde_json::to_value(self.sol.flows_m3_per_s).unwrap_or_default())
    }
    /// Reduced stiffness at ω (rows, columns x, y) [N/m], shape (2, 2).
    #[getter]
    fn k_n_per_m<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        self.kept.get(py, "k_n_per_m", || Ok(two_by_two(py, &self.sol.reduced.k_n_per_m).into_any()))
    }
    /// Reduced damping at ω (rows, columns x, y) [N·s/m], shape (2, 2).
    #[getter]
    fn c_ns_per_m<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        self.kept.get(py, "c_ns_per_m", || Ok(two_by_two(py, &self.sol.reduced.c_ns_per_m).into_any()))
    }
    /// Full stiffness over journal and pad coordinates, shape (n, n); units by block: N/m, N/rad, N·m/m,
    /// N·m/rad (`full_coordinates` and `full_units` name the rows).
    #[getter]
    fn full_k<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        self.kept.get(py, "full_k", || Ok(matrix(py, &self.sol.full.k)?.into_any()))
    }
    /// Full damping, shape (n, n): N·s/m, N·s/rad, N·m·s/m, N·m·s/rad by block.
    #[getter]
    fn full_c<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        self.kept.get(py, "full_c", || Ok(matrix(py, &self.sol.full.c)?.into_any()))
    }
    /// Pad inertia, shape (n, n): kg, kg·m, kg·m² by block (zero on the journal block, which is the rotor's).
    #[getter]
    fn full_m<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        self.kept.get(py, "full_m", || Ok(matrix(py, &self.sol.full.m)?.into_any()))
    }
    /// The coordinate of each row of the full matrices: `"x"`, `"y"`, `"pad 0 tilt"`, …
    #[getter]
    fn full_coordinates(&self) -> Vec<String> {
        self.sol.full.coords.iter().map(|c| c.label()).collect()
    }
    /// The unit of each coordinate of the full matrices (`"m"`, `"rad"`).
    #[getter]
    fn full_units(&self) -> Vec<&'static str> {
        self.sol.full.coords.iter().map(|c| c.unit()).collect()
    }
    /// The pads, in order: a tuple made on the first read and returned on every later one (so each pad's
    /// arrays are copied once, however often they are read).
    #[getter]
    fn pads<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyAny>> {
        let (py, s) = (slf.py(), slf.get());
        s.kept.get(py, "pads", || {
            let pads = (0..s.sol.pads.len())
                .map(|i| Bound::new(py, Pad { sol: Arc::clone(&s.sol), index: i, kept: Kept::default() }))
                .collect::<PyResult<Vec<_>>>()?;
            Ok(pyo3::types::PyTuple::new(py, pads)?.into_any())
        })
    }
    /// The solve's report (iterations, residuals, method, floating pads, time, warnings), as in the JSON.
    #[getter]
    fn report<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let v = solution_json(&self.sol);
        json_to_py(py, &v["report"])
    }
    /// The solve's warnings, as sentences (the thermal loop's included).
    #[getter]
    fn warnings(&self) -> Vec<String> {
        let mut w: Vec<String> = self.sol.report.warnings.iter().map(ToString::to_string).collect();
        if let Some(t) = &self.sol.thermal {
            w.extend(t.report.warnings.iter().map(ToString::to_string));
        }
        w
    }
    /// The design limits and the check of each (value, limit, exceeded), as in the JSON.
    #[getter]
    fn design_limits<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let v = solution_json(&self.sol);
        json_to_py(py, &v["design_limits"])
    }
    /// Names of the design limits this solution exceeds (the `limits_exceeded` column of sweeps).
    #[getter]
    fn limits_exceeded(&self) -> Vec<&'static str> {
        exceeded(&self.sol.inputs.limits, &self.sol).iter().map(|c| c.kind.name()).collect()
    }
    /// Thermal results of a THD solve (temperatures, heat balance, the loop's report), or `None`.
    #[getter]
    fn thermal<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let v = solution_json(&self.sol);
        json_to_py(py, &v["thermal"])
    }
    /// The JSON `tiltpad solve --json` writes, as Python objects (SI, units in the key names).
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        json_to_py(py, &solution_json(&self.sol))
    }
    /// The JSON `tiltpad solve --json` writes, as text.
    fn to_json(&self) -> PyResult<String> {
        let mut text = serde_json::to_string_pretty(&solution_json(&self.sol))
            .map_err(|e| pyo3::exceptions::PyValueError::new_err(e.to_string()))?;
        text.push('\n');
        Ok(text)
    }
    /// The summary `tiltpad solve` prints.
    #[getter]
    fn summary(&self) -> String {
        tiltpad::scene::summary_text::summary_text(&self.sol)
    }
    fn __str__(&self) -> String {
        self.summary()
    }
    fn __repr__(&self) -> String {
        format!(
            "<tiltpad.Solution {:?}: ε = {:.4}, h_min = {:.2} µm, p_max = {:.3} MPa, {} pads>",
            self.sol.title,
            self.sol.eccentricity_ratio,
            UM.from_si(self.sol.h_min_m),
            MPA.from_si(self.sol.p_max_pa),
            self.sol.pads.len()
        )
    }
}

/// One pad of a solution: its scalars and its fields on the pad's grid. Field arrays have shape
/// `(len(s_m), len(z_m))`: circumferential node i (from the leading edge), axial node j.
#[pyclass(module = "tiltpad", frozen)]
pub struct Pad {
    sol: Arc<Solved>,
    index: usize,
    kept: Kept,
}

impl Pad {
    fn pad(&self) -> &PadResult {
        &self.sol.pads[self.index]
    }
    fn field(&self) -> &PadField {
        &self.pad().field
    }
    /// A nodal field as (circumferential, axial) nodes (a periodic pad's closing column repeats column 0).
    fn grid<'py>(&self, py: Python<'py>, name: &'static str, values: &[f64]) -> PyResult<Bound<'py, PyAny>> {
        self.kept.get(py, name, || {
            let f = self.field();
            let (ns, nz) = (f.s_m.len(), f.z_m.len());
            let a = Array2::from_shape_fn((ns, nz), |(i, j)| values.get(f.index(i, j)).copied().unwrap_or(0.0));
            Ok(array(py, a).into_any())
        })
    }
    fn optional_grid<'py>(
        &self,
        py: Python<'py>,
        name: &'static str,
        values: Option<&[f64]>,
    ) -> PyResult<Bound<'py, PyAny>> {
        match values {
            Some(v) => self.grid(py, name, v),
            None => Ok(py.None().into_bound(py)),
        }
    }
}

#[pymethods]
impl Pad {
    #[getter]
    fn index(&self) -> usize {
        self.pad().index
    }
    /// Tilt about the pivot [rad] (> 0 closes the trailing edge); `None` for a fixed sector.
    #[getter]
    fn tilt_rad(&self) -> Option<f64> {
        self.pad().tilt_rad
    }
    /// Radial pivot displacement [m] (finite pivot stiffness), or `None`.
    #[getter]
    fn pivot_displacement_m(&self) -> Option<f64> {
        self.pad().pivot_displacement_m
    }
    #[getter]
    fn h_min_m(&self) -> f64 {
        self.pad().h_min_m
    }
    /// Where the film is thinnest [deg].
    #[getter]
    fn h_min_angle_deg(&self) -> f64 {
        self.pad().h_min_angle_deg
    }
    #[getter]
    fn p_max_pa(&self) -> f64 {
        self.pad().p_max_pa
    }
    /// Film force of this pad on the journal (x, y) [N], shape (2,).
    #[getter]
    fn force_n<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        self.kept.get(py, "force_n", || Ok(vector(py, &self.pad().force_n).into_any()))
    }
    /// Film moment about the pivot [N·m] (zero at equilibrium for a tilting pad).
    #[getter]
    fn moment_nm(&self) -> f64 {
        self.pad().moment_nm
    }
    #[getter]
    fn friction_power_w(&self) -> f64 {
        self.pad().friction_power_w
    }
    /// Fraction of the film's nodes that are cavitated [–].
    #[getter]
    fn cavitated_fraction(&self) -> f64 {
        self.pad().cavitated_fraction
    }
    /// The pad floats (carries almost no load).
    #[getter]
    fn unloaded(&self) -> bool {
        self.pad().unloaded
    }
    /// The pad's flows [m³/s]: `leading_edge_in`, `trailing_edge_out`, `sides_out`, `orifice_in`, `to_cavitation`.
    #[getter]
    fn flows_m3_per_s<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        json_to_py(py, &serde_json::to_value(self.pad().flows_m3_per_s).unwrap_or_default())
    }
    /// Flow into the film through each orifice [m³/s], shape (orifices,).
    #[getter]
    fn orifice_flows_m3_per_s<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        self.kept.get(py, "orifice_flows", || Ok(vector(py, &self.pad().orifice_flows_m3_per_s).into_any()))
    }
    /// Amplitude of each retained bending mode (flexible pads) [m], shape (modes,).
    #[getter]
    fn mode_amplitudes_m<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        self.kept.get(py, "mode_amplitudes", || Ok(vector(py, &self.pad().mode_amplitudes_m).into_any()))
    }
    /// Circumferential node positions: arc length from the leading edge [m], shape (ns,).
    #[getter]
    fn s_m<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        self.kept.get(py, "s_m", || Ok(vector(py, &self.field().s_m).into_any()))
    }
    /// Node angles in the bearing frame (from +x, counter-clockwise) [rad], shape (ns,).
    #[getter]
    fn theta_rad<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        self.kept.get(py, "theta_rad", || Ok(vector(py, &self.field().theta_rad).into_any()))
    }
    /// Axial node positions [m], shape (nz,) (from the mid-plane z = 0 when `half`).
    #[getter]
    fn z_m<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        self.kept.get(py, "z_m", || Ok(vector(py, &self.field().z_m).into_any()))
    }
    /// The grid covers half the pad (symmetry plane at z = 0).
    #[getter]
    fn half(&self) -> bool {
        self.field().half
    }
    /// A full ring (fixed-geometry bearing): the last column repeats the first.
    #[getter]
    fn periodic(&self) -> bool {
        self.field().periodic
    }
    /// Film pressure [Pa], shape (ns, nz).
    #[getter]
    fn pressure_pa<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        self.grid(py, "pressure_pa", &self.field().pressure_pa)
    }
    /// Film thickness [m], shape (ns, nz).
    #[getter]
    fn film_thickness_m<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        self.grid(py, "film_thickness_m", &self.field().film_thickness_m)
    }
    /// Viscosity at the nodes [Pa·s], shape (ns, nz).
    #[getter]
    fn viscosity_pa_s<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        self.grid(py, "viscosity_pa_s", &self.field().viscosity_pa_s)
    }
    /// Cavitated nodes, shape (ns, nz) (bool).
    #[getter]
    fn cavitated<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        self.kept.get(py, "cavitated", || {
            let f = self.field();
            let (ns, nz) = (f.s_m.len(), f.z_m.len());
            let flat: Vec<bool> =
                (0..ns * nz).map(|k| f.cavitated.get(f.index(k / nz, k % nz)).copied().unwrap_or(false)).collect();
            Ok(bools(py, &flat).reshape([ns, nz])?.into_any())
        })
    }
    /// Film temperature, mean across the film [°C], shape (ns, nz); `None` for an isothermal solve.
    #[getter]
    fn film_temperature_c<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        self.optional_grid(py, "film_temperature_c", self.field().film_temperature_c.as_deref())
    }
    /// Temperature of the pad's film-side surface [°C], shape (ns, nz); `None` without a pad solid.
    #[getter]
    fn pad_surface_temperature_c<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        self.optional_grid(py, "pad_surface_temperature_c", self.field().pad_surface_temperature_c.as_deref())
    }
    /// Elastic radial displacement of the film face Σ q_i φ_i [m], shape (ns, nz); `None` for rigid pads.
    #[getter]
    fn elastic_displacement_m<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let v = &self.pad().elastic_displacement_m;
        self.optional_grid(py, "elastic_displacement_m", (!v.is_empty()).then_some(v.as_slice()))
    }
    /// Thermal growth of the film face, radial, positive away from the journal [m], shape (ns, nz); `None`
    /// without pad growth (TEHD).
    #[getter]
    fn thermal_growth_m<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let v = self.pad().thermal_growth.as_ref().map(|g| g.film_radial_m.as_slice());
        self.optional_grid(py, "thermal_growth_m", v)
    }
    /// Radii of the pad solid's node layers, film face first [m], shape (layers,); `None` without a pad solid.
    #[getter]
    fn pad_radii_m<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        match self.pad().thermal.as_ref().and_then(|t| t.solid.as_ref()) {
            Some(s) => self.kept.get(py, "pad_radii_m", || Ok(vector(py, &s.radii_m).into_any())),
            None => Ok(py.None().into_bound(py)),
        }
    }
    /// The pad solid's temperature [°C], shape (layers, ns, nz) (layer 0 the film face); `None` without one.
    #[getter]
    fn pad_temperature_c<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let Some(s) = self.pad().thermal.as_ref().and_then(|t| t.solid.as_ref()) else {
            return Ok(py.None().into_bound(py));
        };
        self.kept.get(py, "pad_temperature_c", || {
            let f = self.field();
            let (ns, nz, layers) = (f.s_m.len(), f.z_m.len(), s.radii_m.len());
            let n_film = s.temperature_c.len() / layers.max(1);
            let a = Array3::from_shape_fn((layers, ns, nz), |(l, i, j)| {
                s.temperature_c.get(l * n_film + f.index(i, j)).copied().unwrap_or(0.0)
            });
            Ok(array(py, a).into_any())
        })
    }
    /// The pad's thermal results (inlet and outlet oil temperatures, T_max, heat), or `None`.
    #[getter]
    fn thermal<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        json_to_py(py, &serde_json::to_value(&self.pad().thermal).unwrap_or_default())
    }
    fn __repr__(&self) -> String {
        let p = self.pad();
        format!(
            "<tiltpad.Pad {}: h_min = {:.2} µm, p_max = {:.3} MPa{}>",
            p.index,
            UM.from_si(p.h_min_m),
            MPA.from_si(p.p_max_pa),
            if p.unloaded { ", floating" } else { "" }
        )
    }
}
