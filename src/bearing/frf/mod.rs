//! The controllable bearing's frequency responses: the bearing linearised at its injection nozzles (the
//! influence fields of each nozzle's pressure on the films, [`injection`]), the coupled valve → line →
//! nozzle → film → pads and journal system at one frequency ([`dynamics`]), and the FRF model that keeps the
//! linearisation and evaluates the chain over a band ([`model`]).

pub mod dynamics;
pub mod injection;
pub mod model;
