//! What a solve tells besides its numbers: the method that found the equilibrium ([`Method`]) and the
//! warnings of a report ([`Warning`]), each with the data it is about, so a caller can match on them (a
//! study flags floating pads, a test asks which pad floats) and a reader gets a sentence ([`std::fmt::Display`]).
//!
//! Serialised with a `kind` tag (`{"kind": "pad_floats", "pad": 3, …}`); the JSON form of a solution adds
//! each warning's sentence as `message`.

use serde::{Deserialize, Serialize};

use crate::bearing::report::error::{SolveError, StallReason};
use crate::model::Cavitation;
use crate::physics::reynolds::FilmWarning;

/// How an equilibrium was found (in the order the solver tries them).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Method {
    /// Not solved (an empty report).
    #[default]
    None,
    /// The journal position is given: only the pads were solved.
    PrescribedPosition,
    /// Newton on every coordinate at once (the usual way).
    CoupledNewton,
    /// The fallbacks after the coupled Newton, as a whole.
    Fallbacks,
    /// Newton on the journal position with every pad solved inside (pad assembly).
    PadAssemblyNewton,
    /// The polar bracketing search on the journal position.
    PolarSearch,
    /// A scan along the load for the first stable crossing, then Newton.
    ScanAlongLoad,
    /// Load continuation from a centred journal.
    LoadContinuation,
}

impl std::fmt::Display for Method {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Self::None => "none",
            Self::PrescribedPosition => "prescribed journal position (pads solved)",
            Self::CoupledNewton => "coupled Newton",
            Self::Fallbacks => "the fallbacks",
            Self::PadAssemblyNewton => "Newton (pad assembly)",
            Self::PolarSearch => "polar bracketing search",
            Self::ScanAlongLoad => "scan along the load + Newton",
            Self::LoadContinuation => "load continuation",
        })
    }
}

/// A warning of a solve report.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Warning {
    /// A method stopped short of the tolerance; the next one is tried.
    MethodFailed { method: Method, reason: StallReason, next: Method },
    /// A film solve's own warning.
    Film { pad: usize, warning: FilmWarning },
    /// The pad carries (almost) no load: its film is treated as cavitated.
    PadFloats {
        pad: usize,
        /// Its load over the bearing's force scale.
        share: f64,
        /// It has coordinates of its own (its tilt is then weakly determined).
        tilting: bool,
    },
    /// A floating pad that also has a lightly loaded state nearby (a fold).
    PadNearFold { pad: usize },
    /// A pad's equilibrium residual above tolerance (relative).
    PadResidual { pad: usize, residual: f64 },
    /// The thinnest film is close to the touchdown film.
    NearTouchdown { pad: usize, h_min_m: f64, touchdown_film_m: f64 },
    /// A Hertz pivot carries less than the floor at which its stiffness is evaluated.
    PivotLoadBelowFloor { pad: usize, load_n: f64, floor_n: f64, floor_share: f64 },
    /// The Hertz pivots' load iteration stopped before converging.
    PivotLoadsNotConverged { iterations: usize, tolerance: f64 },
    /// The static stiffness has a negative principal value [N/m].
    StaticallyUnstable { principal_n_per_m: f64 },
    /// The static stiffness vanishes along an axis [° from +x].
    NoStaticStiffness { axis_deg: f64 },
    /// The film Reynolds number passes the laminar limit.
    Turbulent { reynolds: f64, pad: usize, limit: f64 },
    /// The Taylor number passes the critical value.
    TaylorVortices { taylor: f64, critical: f64 },
    /// The minimum film is of the order of the surface roughness [m].
    MixedLubrication { h_min_m: f64, roughness_m: f64 },
    /// The clearance ratio is outside the usual range.
    UnusualClearance { ratio: f64, usual: [f64; 2] },
    /// A pivot deflects by more than the assembled clearance.
    PivotDeflection { pad: usize, clearances: f64 },
    /// The thermal loop holds an unloaded pad's tilt.
    TiltHeld { pad: usize, outer_iteration: usize },
    /// A lightly loaded pad's Reynolds equation uses its mean film viscosity.
    MeanViscosity { pad: usize, load_percent: f64 },
    /// A lightly loaded pad had no tilt equilibrium with its non-uniform viscosity.
    MeanViscosityAfterFailure { pad: usize, load_percent: f64, error: Box<SolveError> },
    /// The accelerated temperature update stalled: damped steps from then on.
    TemperatureUpdateStalled { best_change: f64, best_iteration: usize, from_iteration: usize },
    /// An equilibrium failed with a proposed viscosity field: the step was halved.
    StepHalved { error: Box<SolveError> },
    /// The loop walked into a touchdown (or an equilibrium that spent its work budget) at a proposed field and
    /// restarted with safeguarded steps.
    ThermalRestart { outer_iteration: usize, error: Box<SolveError> },
    /// No oil flows in through a pad's leading edge.
    NoLeadingEdgeInflow { pad: usize },
    /// The energy balance of the converged state closes only to this fraction.
    EnergyBalance { closure: f64 },
    /// A cavitation condition that does not conserve mass counts gas as oil in cavitated zones: the oil it
    /// creates there [m³/s] and its share of the leading-edge inflow, with the pads where it does.
    CavitationCreatesOil { condition: Cavitation, pads: Vec<usize>, created_m3_s: f64, share_of_inflow: f64 },
}

impl std::fmt::Display for Warning {
    #[allow(clippy::too_many_lines)]
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::MethodFailed { method, reason, next } => {
                write!(f, "{method} failed ({reason}); trying {next}")
            }
            Self::Film { pad, warning } => write!(f, "pad {pad}: {warning}"),
            Self::PadFloats { pad, share, tilting } => {
                let what =
                    if *tilting { "; its tilt is weakly determined (set where film pressure begins)" } else { "" };
                write!(
                    f,
                    "pad {pad} floats: it carries {share:.1e} of the load scale, its film is treated as cavitated and \
                     contributes no stiffness or damping{what}"
                )
            }
            Self::PadNearFold { pad } => write!(
                f,
                "pad {pad} also has a lightly loaded state near this operating point (found during the search; no \
                 equilibrium with it loaded was reached): a pad near a fold, so results here may differ between \
                 meshes and with the starting point"
            ),
            Self::PadResidual { pad, residual } => {
                write!(f, "pad {pad} equilibrium residual {residual:.1e} (relative) above tolerance")
            }
            Self::NearTouchdown { pad, h_min_m, touchdown_film_m } => write!(
                f,
                "minimum film thickness {:.2} µm on pad {pad} is close to touchdown ({:.2} µm)",
                crate::units::UM.from_si(*h_min_m),
                crate::units::UM.from_si(*touchdown_film_m)
            ),
            Self::PivotLoadBelowFloor { pad, load_n, floor_n, floor_share } => write!(
                f,
                "pad {pad}: pivot load {load_n:.4e} N below {floor_share} of the static load; its contact stiffness is \
                 taken at {floor_n:.4e} N"
            ),
            Self::PivotLoadsNotConverged { iterations, tolerance } => write!(
                f,
                "Hertz pivot loads not converged in {iterations} iterations (relative stiffness change above \
                 {tolerance})"
            ),
            Self::StaticallyUnstable { principal_n_per_m } => write!(
                f,
                "the equilibrium is statically unstable: the static stiffness has a negative principal value \
                 ({principal_n_per_m:.3e} N/m); the journal would move away from this position"
            ),
            Self::NoStaticStiffness { axis_deg } => write!(
                f,
                "the bearing has no static stiffness along the {axis_deg:.0}° axis at this equilibrium: the journal's \
                 position along it is set by the force balance alone (pads floating at the onset of pressure, or no \
                 pad on that axis: then it is held at its start position, as for a guided rotor)"
            ),
            Self::Turbulent { reynolds, pad, limit } => write!(
                f,
                "turbulent film: the film Reynolds number ρUh/µ reaches {reynolds:.0} (pad {pad}), past the \
                 transition band's start {limit:.0}; the laminar Reynolds equation used here (physics.turbulence = \
                 \"off\") underestimates friction loss, temperature rise and stiffness (\"auto\" models it)"
            ),
            Self::TaylorVortices { taylor, critical } => write!(
                f,
                "Taylor vortices: the Taylor number Re·√(h/R) reaches {taylor:.1}, above the critical {critical}; the \
                 laminar Couette flow the model assumes becomes cellular and the friction loss rises"
            ),
            Self::MixedLubrication { h_min_m, roughness_m } => write!(
                f,
                "the minimum film thickness {:.3} µm is below about {:.0} µm, the order of the combined surface \
                 roughness of journal and pad: mixed lubrication (asperity contact), which the smooth-film model \
                 does not describe",
                crate::units::UM.from_si(*h_min_m),
                crate::units::UM.from_si(*roughness_m)
            ),
            Self::UnusualClearance { ratio, usual } => write!(
                f,
                "clearance ratio Cb/R = {ratio:.2e} is outside {:.0e}–{:.0e} (built bearings: about 0.5–3 ‰)",
                usual[0], usual[1]
            ),
            Self::PivotDeflection { pad, clearances } => write!(
                f,
                "pad {pad}'s pivot deflects by {clearances:.1} times the assembled clearance, and the journal moves as \
                 far: no built bearing allows that (its linear pivot spring, its seat in the housing and the film's \
                 small-displacement kinematics are far outside their range); check the pivot stiffness against the \
                 load"
            ),
            Self::TiltHeld { pad, outer_iteration } => {
                write!(f, "pad {pad} is unloaded: its tilt is held from outer iteration {outer_iteration}")
            }
            Self::MeanViscosity { pad, load_percent } => write!(
                f,
                "pad {pad} carries {load_percent:.1} % of the load: its Reynolds equation uses its mean film viscosity \
                 (the film and pad temperatures are computed in full)"
            ),
            Self::MeanViscosityAfterFailure { pad, load_percent, error } => write!(
                f,
                "pad {pad} carries {load_percent:.1} % of the load and had no equilibrium tilt with its non-uniform \
                 viscosity ({error}): it is given its mean film viscosity"
            ),
            Self::TemperatureUpdateStalled { best_change, best_iteration, from_iteration } => write!(
                f,
                "the accelerated temperature update stalled (viscosity change {best_change:.1e} at best, outer \
                 iteration {best_iteration}): damped fixed-point steps from outer iteration {from_iteration}"
            ),
            Self::StepHalved { error } => {
                write!(f, "equilibrium failed with the updated viscosity field ({error}); step halved")
            }
            Self::ThermalRestart { outer_iteration, error } => write!(
                f,
                "the thermal loop's equilibrium failed at outer iteration {outer_iteration} ({error}): restarted from \
                 the isothermal field with safeguarded steps"
            ),
            Self::NoLeadingEdgeInflow { pad } => write!(
                f,
                "pad {pad}: no oil flows in through the leading edge: its whole edge is held at the inlet temperature"
            ),
            Self::EnergyBalance { closure } => {
                write!(f, "energy balance closes to {:.2} % only", 100.0 * closure)
            }
            Self::CavitationCreatesOil { condition, pads, created_m3_s, share_of_inflow } => {
                let name = match condition {
                    Cavitation::Gumbel => "Gümbel",
                    _ => "Reynolds",
                };
                let list: Vec<String> = pads.iter().map(ToString::to_string).collect();
                write!(
                    f,
                    "the {name} cavitation condition counts the gas in the cavitated zones of pad{} {} as oil: it \
                     creates {:.3} L/min there ({:.1} % of the leading-edge inflow), so the flows through those zones \
                     (edges, orifices, into cavitation) are not the oil's and do not converge with the mesh; \
                     physics.cavitation = \"jfo\" conserves the oil",
                    if pads.len() == 1 { "" } else { "s" },
                    list.join(", "),
                    crate::units::L_PER_MIN.from_si(*created_m3_s),
                    100.0 * share_of_inflow
                )
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_warning_reads_as_a_sentence_and_round_trips_with_its_kind() {
        let w = Warning::PadFloats { pad: 3, share: 2e-5, tilting: true };
        assert!(w.to_string().starts_with("pad 3 floats: it carries 2.0e-5 of the load scale"), "{w}");
        let json = serde_json::to_value(&w).unwrap();
        assert_eq!(json["kind"], "pad_floats");
        assert_eq!(json["pad"], 3);
        assert_eq!(serde_json::from_value::<Warning>(json).unwrap(), w);
        let failed = Warning::MethodFailed {
            method: Method::CoupledNewton,
            reason: StallReason::NoDecrease,
            next: Method::Fallbacks,
        };
        assert_eq!(failed.to_string(), "coupled Newton failed (line search found no decrease); trying the fallbacks");
    }
}
