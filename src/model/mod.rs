//! What a user describes: bearing geometry, pads, orifices, lubricant, operating point, mesh and physics
//! options. Case files are TOML in engineering units ([`file`]); they are validated and converted to SI once
//! ([`resolve`]) into a [`Case`] that the solver reads; [`budget`] counts the mesh nodes a case would
//! allocate, so that an oversized one is refused before anything is built. [`schema`] is the table of every
//! key — unit, allowed values, default, meaning and editor row, one row per key — that validation, `tiltpad
//! schema` and the workbench's editor read (its opening comment says how to add a key); [`limits`] holds
//! the design limits results are checked against; [`edit`] writes an edited case back into the user's own
//! file, keeping its comments; [`rotor`] is the rotor file (its keys: [`rotor_schema`]) with its
//! controller ([`control`], keys: [`control_schema`]), [`shaft`] its
//! elements' data, and [`rotor_sections`] adds and removes a rotor file's shaft sections, renumbering what
//! sits on its nodes. Nothing here imports the solver: the layers above read these types.

pub mod budget;
pub mod case;
pub mod control;
mod control_resolve;
pub mod control_schema;
pub mod edit;
pub mod error;
pub mod file;
pub mod hydraulics;
pub mod limits;
pub mod load;
pub mod resolve;
pub mod rotor;
mod rotor_resolve;
pub mod rotor_schema;
pub mod rotor_sections;
pub mod schema;
pub mod shaft;
pub mod tuning;

pub use case::{
    Bearing, Case, CavitatedFilm, Cavitation, Feeding, Fidelity, LoadSpec, Lubricant, MeshSpec, Operating, Orifice,
    Pad, PadFilmBc, PadKind, Physics, Thermal, ThermalModelKind, Turbulence, ViscosityLaw,
};
pub use error::CaseError;
pub use file::CaseFile;
pub use load::{load_case, parse_case_file, replaced_keys, Replaced, PAD_GEOMETRY_KEYS};

/// Name and text of every shipped case (`cases/*.toml`), for tests that must cover them all.
#[cfg(test)]
pub(crate) fn shipped_cases() -> Vec<(String, String)> {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("cases");
    let mut out: Vec<(String, String)> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .map(|p| (p.file_name().unwrap().to_string_lossy().into_owned(), std::fs::read_to_string(&p).unwrap()))
        .collect();
    out.sort();
    assert!(out.len() >= 7, "shipped cases missing from {}", dir.display());
    out
}
