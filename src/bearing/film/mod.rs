//! The films of the pads, built once per geometry and mesh: the film-thickness geometry of a pad and its
//! generalised coordinates ([`geometry`]), which coordinates each pad carries and where they sit in the
//! global vector ([`coordinates`]), the bearing model that holds every pad's film, mesh and factorisation
//! pattern ([`model`]), and the bending modes of flexible pads as extra coordinates ([`flex`]).

pub mod coordinates;
pub mod flex;
pub mod geometry;
pub mod model;
