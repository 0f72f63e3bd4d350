//! A converged state as a result: the [`Solution`] types ([`result`]), their assembly from the converged
//! films and thermal fields ([`assemble`]), the dynamic coefficients and their reduction to the journal
//! ([`coefficients`]), the churning loss of a flooded housing ([`churning`]), the flow-regime checks ([`regime`]) and design-limit checks ([`limits`]) of a
//! solution, the one table of its scalar outputs ([`outputs`]) and its JSON form ([`json`]). Nothing here solves: the stages call the assembly on states the
//! equilibrium and the thermal loop converged.

pub mod assemble;
pub mod churning;
pub mod coefficients;
pub mod json;
pub mod limits;
pub mod outputs;
pub mod regime;
pub mod result;

pub use result::{
    BearingFlows, Derived, PadField, PadFlex, PadResult, PadSolidField, PadThermalGrowth, PadThermalResult, Solution,
    ThermalResult,
};
