//! The bearing: film geometry and coordinates ([`geometry`]), the model built once per mesh ([`model`]),
//! static equilibrium ([`equilibrium`]), the thermal (THD) loop around it ([`thermal`], with the per-pad
//! thermal systems in [`thermal_pad`] and the thermal growth of pads and journal in [`tehd`]), dynamic coefficients ([`coefficients`]), the flow-regime checks of
//! a solved film ([`regime`]), the design-limit checks of a solution ([`limits`]), the solve job ([`job`]) that turns a case into a [`Solution`], and the
//! cached, steppable [`stages`] the app asks for results through.

pub mod anderson;
pub mod coefficients;
pub mod coordinates;
pub mod equilibrium;
pub mod error;
pub mod flex;
pub mod frf;
pub mod frf_job;
pub mod geometry;
pub mod growth_solid;
pub mod injection;
pub mod job;
pub mod limits;
pub mod mixing;
pub mod model;
pub mod pivot_contact;
pub mod progress;
pub mod regime;
pub mod report;
pub mod solution;
pub mod stages;
pub mod tehd;
pub mod thermal;
pub mod thermal_pad;

pub use coefficients::{FullCoefficients, ReducedCoefficients};
pub use coordinates::{Coord, DofMap, PadDof};
pub use equilibrium::EquilibriumParams;
pub use error::SolveError;
pub use job::{solve_case, solve_operating_point, solve_point};
pub use model::{BearingModel, OperatingPoint};
pub use progress::{Cancel, FrameBudget, NoCancel, NoSuspend, Progress};
pub use report::SolveReport;
pub use solution::Solution;
pub use stages::{Outcome, Request, StageId, Stages, Step};
pub use thermal::{ThermalModel, ThermalParams, ThermalReport};
