//! The thermal model's data: its settings ([`ThermalParams`]) and report ([`ThermalReport`]), the per-pad
//! thermal systems and pad solids built once per mesh ([`ThermalModel`]), and the state of one outer
//! iteration ([`PadThermalState`], [`ThdState`]).

use crate::bearing::report::error::ThermalSystem;
use crate::bearing::report::error::Unsupported;
use crate::bearing::report::warning::Warning;
use serde::{Deserialize, Serialize};

use crate::fem::supg::Stabilisation;
use crate::fem::SolverError;
use crate::mesh::pad3d::PadMesh;
use crate::model::{Case, PadFilmBc};
use crate::physics::energy::FilmHeat;
use crate::physics::pad_conduction::{PadConduction, PadDirichletSolver, PadMaterial};

use crate::bearing::equilibrium::{Equilibrium, EquilibriumParams};
use crate::bearing::film::model::{BearingModel, OperatingPoint};
use crate::bearing::report::error::SolveError;
use crate::bearing::thermal::growth::GrowthField;
use crate::bearing::thermal::pad_system::PadThermal;

/// History depth of the Anderson acceleration of the thermal loop.
pub const ANDERSON_DEPTH: usize = 4;
/// Smallest damping of the temperature update the safeguard of the Anderson acceleration lowers ω to (each
/// outer iteration whose viscosity change grows halves it). Measured on Fillon A at five times its load
/// (S = 0.1, h_min 3.6 µm): damped fixed-point steps contract there at ω ≤ 0.3 (rate about 0.93 per step),
/// the undamped extrapolation does not.
pub const MIN_RELAXATION: f64 = 0.1;
/// Outer iterations of the plain Anderson loop (the former iteration budget) before the safeguard applies:
/// a loop that converged before converges as before (from the start, the safeguard made the compressor
/// bearing's 40 bar leading-edge injection, which the plain loop converges in 27 iterations through rises
/// of its change, spend 100 iterations).
pub const SAFEGUARD_AFTER: usize = 40;
/// Outer iterations of the safeguarded phase without the viscosity change falling below [`STALL_GAIN`]
/// times its best after which the loop gives up the Anderson extrapolation for plain damped steps
/// ([`PLAIN_RELAXATION`], still halved on growth and restored on falls). Where the extrapolation keeps
/// proposing fields whose images move away (Fillon A at S = 0.1, 40°: a change of 0.1–0.2 for 260
/// iterations), the damped steps contract (converged in 74 outer iterations).
pub const STALL_WINDOW: usize = 20;
/// See [`STALL_WINDOW`].
pub const STALL_GAIN: f64 = 0.5;
/// Damping of the plain steps a stalled loop falls back to ([`STALL_WINDOW`]).
pub const PLAIN_RELAXATION: f64 = 0.4;
/// Default iteration budget of the thermal loop. The safeguarded steps contract at about 0.93 per step where
/// they are needed ([`MIN_RELAXATION`]), so from a change of order 1e-1 at [`SAFEGUARD_AFTER`] the 1e-4
/// tolerance takes about 100 more: a budget of 100 stopped such loops short by construction (Fillon A at
/// S = 0.1: 20 of the convergence map's points converge in 102–224 iterations). A loop that converges
/// within 100 is unchanged.
pub const DEFAULT_MAX_ITERATIONS: usize = match crate::key!("thermal.max_iterations").default {
    crate::model::schema::Fallback::Count(n) => n,
    _ => panic!("thermal.max_iterations has a count for its default"),
};
/// Halvings of a temperature update whose viscosity field has no equilibrium.
pub const MAX_BACKTRACKS: usize = 6;
/// Load share below which a pad whose non-uniform viscosity leaves it without an equilibrium tilt is given
/// its mean film viscosity instead.
pub const LIGHT_PAD_SHARE: f64 = 0.1;

/// What the converged loop's last outer iteration changed, against the tolerances that stopped it.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct ThermalConvergence {
    /// Largest relative change of the nodal viscosity, and its tolerance.
    pub viscosity_change: f64,
    pub viscosity_tol: f64,
    /// With Hertz pivots: the largest relative change of their secant springs, and its tolerance.
    pub pivot_change: Option<[f64; 2]>,
}

impl std::fmt::Display for ThermalConvergence {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "viscosity change {:.1e} below {:.0e}", self.viscosity_change, self.viscosity_tol)?;
        if let Some([change, tol]) = self.pivot_change {
            write!(f, ", Hertz pivot springs changing by {change:.1e} (below {tol:.0e})")?;
        }
        Ok(())
    }
}

/// Settings of the thermal loop, with documented defaults.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ThermalParams {
    /// Largest nodal relative viscosity change at convergence (default 1e-4).
    pub viscosity_tol: f64,
    /// Iteration budget: outer iterations at most (default [`DEFAULT_MAX_ITERATIONS`]: [`SAFEGUARD_AFTER`] plain
    /// ones, then the safeguarded damped steps; the case key `thermal.max_iterations`). With the equilibrium's
    /// work budget per outer iteration it bounds the loop's work; no time limit decides its outcome.
    pub max_iterations: usize,
    /// The equilibrium's settings at full precision (its work budget: `physics.max_film_solves_per_pad`); the
    /// early outer iterations loosen its tolerances only.
    pub equilibrium: EquilibriumParams,
    /// Damping ω of the film temperature update (default 0.8).
    pub relaxation: f64,
    /// Stabilisation of the film energy equation (default plain SUPG: linear, so the loop's fixed point is
    /// smooth; [`Stabilisation::SupgCrosswind`] lags its capturing term by one outer iteration and can stall
    /// the loop in a ~1e-3 limit cycle).
    pub stabilisation: Stabilisation,
}

impl ThermalParams {
    /// The defaults, with the case's iteration budget (`thermal.max_iterations`).
    #[must_use]
    pub fn of(case: &Case) -> Self {
        Self {
            max_iterations: case.tuning.count(crate::key!("thermal.max_iterations")),
            viscosity_tol: case.tuning.value(crate::key!("thermal.viscosity_tolerance")),
            equilibrium: EquilibriumParams::of(case),
            ..Self::default()
        }
    }
}

impl Default for ThermalParams {
    fn default() -> Self {
        Self {
            viscosity_tol: 1e-4,
            max_iterations: DEFAULT_MAX_ITERATIONS,
            equilibrium: EquilibriumParams::default(),
            relaxation: 0.8,
            stabilisation: Stabilisation::Supg,
        }
    }
}

/// What the thermal loop did.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct ThermalReport {
    /// Outer (equilibrium + thermal) iterations.
    pub outer_iterations: usize,
    /// Largest nodal relative viscosity change after each outer iteration.
    pub viscosity_change: Vec<f64>,
    pub converged: bool,
    /// Why the loop stopped, when it converged.
    pub stop_reason: Option<ThermalConvergence>,
    /// Energy balance closure of the converged state (G − H − C)/G, whole bearing: heat generated in the
    /// films against the heat the oil carries away and the heat conducted (physics::energy::balance).
    pub energy_balance_closure: f64,
    /// The films' power identity (P − G)/P, whole bearing: the journal's shear power against the heat the
    /// films generate; round-off with the Reynolds and Gümbel conditions, a discretisation error with the
    /// mass-conserving film (physics::energy::balance).
    #[serde(default)]
    pub power_identity: f64,
    /// Worst closure over the pads.
    pub energy_balance_worst_pad: f64,
    pub equilibrium_iterations: usize,
    /// Pad (inner) iterations of those equilibria.
    pub inner_iterations: usize,
    pub film_solves: usize,
    /// Reynolds factorisations of those equilibria.
    pub equilibrium_factorizations: usize,
    pub thermal_factorizations: usize,
    pub seconds: f64,
    pub equilibrium_seconds: f64,
    /// Film energy, pad conduction and mixing (all iterations).
    pub thermal_seconds: f64,
    /// Of which the final BC1 pad conduction solves.
    pub pad_conduction_seconds: f64,
    /// TEHD: largest change of the films' thermal growth after each outer iteration [m] (empty without
    /// thermal growth; the loop also needs it below `GROWTH_TOL` × the assembled clearance).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub growth_change_m: Vec<f64>,
    /// TEHD: journal growth α_j R (T_j − T_ref) and the range of the pads' film-face growth in the converged
    /// films [m].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub journal_growth_m: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pad_growth_range_m: Option<[f64; 2]>,
    /// TEHD: outward displacement of each pad's pivot (of a fixed sector's bore) by the housing's growth
    /// α_h R_p (T_h − T_ref) [m] (empty without housing growth).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub housing_growth_m: Vec<f64>,
    /// TEHD, of `thermal_seconds`: building the growth model (pad solids assembled and factorised, thermal-load
    /// operators) and the growth steps of every outer iteration (pad conduction for BC1, thermal loads,
    /// solves) [s].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub growth_setup_seconds: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub growth_seconds: Option<f64>,
    pub warnings: Vec<Warning>,
}

/// Thermal model of the bearing: per-pad systems built once per geometry and mesh.
#[derive(Debug, Clone)]
pub struct ThermalModel {
    pub pads: Vec<PadThermal>,
    /// `upstream[k]`: the pad whose trailing edge feeds the groove ahead of pad k.
    pub upstream: Vec<usize>,
    /// BC1 pad conduction solvers, one per distinct pad mesh (built on first use), and which one each pad
    /// uses.
    pad_solvers: Vec<PadDirichletSolver>,
    pad_solver_of: Vec<Option<usize>>,
}

impl ThermalModel {
    /// Builds the pad meshes and the thermal systems of a bearing model.
    ///
    /// # Errors
    /// A 360° sector (no inlet), or a failed symbolic factorisation.
    pub fn new(case: &Case, model: &BearingModel) -> Result<Self, SolveError> {
        let b = &case.bearing;
        let mut pads = Vec::with_capacity(model.pads.len());
        for (k, (pm, pad)) in model.pads.iter().zip(&b.pads).enumerate() {
            let film = &pm.film;
            if film.geom.grid.periodic {
                return Err(SolveError::Unsupported(Unsupported::ThermalWithoutInlet { pad: k }));
            }
            let conduction = (pad.thickness_m > 0.0).then(|| {
                let mesh = pm.solid.clone().unwrap_or_else(|| {
                    std::sync::Arc::new(PadMesh::extrude(
                        &film.geom.grid,
                        b.journal_radius_m,
                        pad.leading_edge_rad,
                        pad.bore_radius_m(b.journal_radius_m),
                        pad.thickness_m,
                        case.mesh.pad_radial_elements,
                    ))
                });
                PadConduction::new(mesh)
            });
            if conduction.is_none() && !matches!(case.thermal.pad_film_bc, PadFilmBc::Bc1) {
                return Err(SolveError::Unsupported(Unsupported::NoPadSolid { pad: k }));
            }
            pads.push(PadThermal::new(film, conduction).map_err(|error| SolveError::PadThermal {
                pad: k,
                system: ThermalSystem::Assembly,
                error,
            })?);
        }
        // Upstream pad: the one whose leading edge comes last before pad k's, going against the rotation.
        let n = b.pads.len();
        let le: Vec<f64> = b.pads.iter().map(|p| p.leading_edge_rad.rem_euclid(std::f64::consts::TAU)).collect();
        let upstream = (0..n)
            .map(|k| {
                (0..n)
                    .filter(|&j| j != k || n == 1)
                    .min_by(|&a, &c| {
                        let da = (le[k] - le[a]).rem_euclid(std::f64::consts::TAU);
                        let dc = (le[k] - le[c]).rem_euclid(std::f64::consts::TAU);
                        let da = if da == 0.0 { std::f64::consts::TAU } else { da };
                        let dc = if dc == 0.0 { std::f64::consts::TAU } else { dc };
                        da.total_cmp(&dc)
                    })
                    .unwrap_or(k)
            })
            .collect();
        let n_pads = pads.len();
        Ok(Self { pads, upstream, pad_solvers: Vec::new(), pad_solver_of: vec![None; n_pads] })
    }

    /// BC1 pad conduction of pad k with the film temperature `film_t` on its face (`None` without a pad
    /// solid). Identical pads share one solver and its factorisation.
    ///
    /// # Errors
    /// A failed factorisation.
    pub fn pad_bc1(
        &mut self,
        k: usize,
        film_t: &[f64],
        material: &PadMaterial,
    ) -> Result<Option<Vec<f64>>, SolverError> {
        let Some(mesh) = self.pads[k].conduction.as_ref().map(|c| &c.mesh) else { return Ok(None) };
        if self.pad_solver_of[k].is_none() {
            let shared = (0..self.pads.len()).find(|&j| {
                self.pad_solver_of[j].is_some()
                    && self.pads[j].conduction.as_ref().is_some_and(|c| c.mesh.same_shape(mesh))
            });
            self.pad_solver_of[k] = Some(match shared {
                Some(j) => self.pad_solver_of[j].unwrap_or_default(),
                None => {
                    self.pad_solvers.push(PadDirichletSolver::new(mesh)?);
                    self.pad_solvers.len() - 1
                }
            });
        }
        let i = self.pad_solver_of[k].unwrap_or_default();
        self.pads[k].solve_pad_bc1(&mut self.pad_solvers[i], film_t, material)
    }

    /// Numeric factorisations of the BC1 pad solvers so far.
    #[must_use]
    pub fn pad_factorizations(&self) -> usize {
        self.pad_solvers.iter().map(|s| s.factorizations).sum()
    }
}

/// Thermal state of one pad at convergence.
#[derive(Debug, Clone, PartialEq)]
pub struct PadThermalState {
    pub inlet_temperature_c: f64,
    /// Flow-weighted trailing-edge temperature.
    pub outlet_temperature_c: f64,
    /// Film temperature at the film nodes.
    pub film_c: Vec<f64>,
    /// Pad temperature at every pad node (layer-major, layer 0 = film face); `None` without a pad solid.
    pub pad_c: Option<Vec<f64>>,
    /// Layer radii of the pad mesh [m].
    pub pad_radii_m: Vec<f64>,
    pub heat: FilmHeat,
    /// Heat the pad gives to its surroundings [W] (whole pad).
    pub pad_to_surroundings_w: f64,
    /// Oil in through the leading edge / out through the trailing edge [m³/s].
    pub inflow_m3_per_s: f64,
    pub outflow_m3_per_s: f64,
    /// Film fraction θ at the film nodes.
    pub film_fraction: Vec<f64>,
    /// Oil-filled (θ-weighted) area mean of the film temperature.
    pub film_mean_c: f64,
    /// ∫ θ dA [m²] (whole pad), the weight of `film_mean_c`.
    pub oil_area_m2: f64,
}

/// Converged THD state.
#[derive(Debug, Clone, PartialEq)]
pub struct ThdState {
    pub equilibrium: Equilibrium,
    /// The operating point with the converged nodal viscosities.
    pub op: OperatingPoint,
    pub pads: Vec<PadThermalState>,
    pub journal_temperature_c: f64,
    pub heat: FilmHeat,
    pub report: ThermalReport,
    /// The thermal growth in the films of the converged state (TEHD), installed to assemble the solution.
    pub growth: Option<GrowthField>,
    /// The Hertz pivots' load iteration at the converged state (their tangent stiffnesses linearise it).
    pub pivots: Option<crate::bearing::equilibrium::pivots::HertzPivots>,
}
