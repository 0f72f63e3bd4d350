//! What a user describes: bearing geometry, pads, orifices, lubricant, operating point, mesh and physics
//! options. Case files are TOML in engineering units ([`file`]); they are validated and converted to SI once
//! ([`resolve`]) into a [`Case`] that the solver reads; [`budget`] counts the mesh nodes a case would
//! allocate, so that an oversized one is refused before anything is built.

pub mod budget;
pub mod case;
pub mod error;
pub mod file;
pub mod load;
pub mod resolve;

pub use case::{
    Bearing, Case, CavitatedFilm, Cavitation, Fidelity, LoadSpec, Lubricant, MeshSpec, Operating, Orifice, Pad, PadFilmBc, PadKind, Physics,
    Thermal, ThermalModelKind, ViscosityLaw,
};
pub use error::CaseError;
pub use file::CaseFile;
pub use load::{load_case, parse_case_file};
