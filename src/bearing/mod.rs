//! # The bearing
//!
//! Everything that turns a validated [`crate::model::Case`] into a [`Solution`], in folders by role. Each
//! folder imports only the ones listed above it here, never one below:
//!
//! | folder            | owns                                                                                 |
//! |-------------------|--------------------------------------------------------------------------------------|
//! | [`report`]        | what every solve hands back besides its result: the [`SolveReport`], the typed errors ([`SolveError`]) and warnings, cancellation and suspension ([`Cancel`], [`Progress`]) |
//! | [`film`]          | the films of the pads: film-thickness geometry, the generalised coordinates and their layout ([`DofMap`]), the model built once per mesh ([`BearingModel`]) and the flexible pads' modes |
//! | [`equilibrium`]   | the static equilibrium of journal and pads (coupled Newton, its fallbacks, the Hertz pivots' load iteration) |
//! | [`thermal`]       | the thermal (THD) loop around the equilibrium: per-pad energy and conduction systems, groove mixing, Anderson acceleration, the thermal growth of pads, journal and housing (TEHD) |
//! | [`solution`]      | a converged state as a result: assembly, dynamic coefficients and their reduction, flow-regime and design-limit checks, the JSON form |
//! | [`frf`]           | the bearing linearised at its injection nozzles and the frequency responses of the controllable bearing |
//! | [`stages`]        | **the one entrance**: every caller (workbench, CLI, studies, rotor, bench) asks [`Stages`] for what it needs with a [`Request`]; one cache keyed on each stage's declared inputs serves them all |
//!
//! [`solve_case`] is the three-line form of a request for one solution.

pub mod equilibrium;
pub mod film;
pub mod frf;
pub mod report;
pub mod solution;
pub mod stages;
pub mod thermal;

pub use equilibrium::EquilibriumParams;
pub use film::coordinates::{Coord, DofMap, PadDof};
pub use film::model::{BearingModel, OperatingPoint};
pub use report::error::SolveError;
pub use report::progress::{Cancel, FrameBudget, NoCancel, NoSuspend, Progress};
pub use report::SolveReport;
pub use solution::coefficients::{FullCoefficients, ReducedCoefficients};
pub use solution::Solution;
pub use stages::{solve_case, Outcome, Request, StageId, Stages, Start, Step};
pub use thermal::{ThermalModel, ThermalParams, ThermalReport};
