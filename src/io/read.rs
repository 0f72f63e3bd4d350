//! Input files read from disk, shared by the command line and the Python package: text under a size cap
//! ([`read_text`]: a case path of `/dev/zero` is refused after [`MAX_INPUT_BYTES`], not read until memory
//! runs out), a rotor file with the bearing cases it names beside it ([`read_rotor`]), and a rotor file with
//! its controller ([`read_controlled`]).
//!
//! Every error names the file and what it was read as ([`ReadError`]); a rotor file's validation error keeps
//! its [`CaseError`] (the key, the value and the allowed range). Native only (the web workbench reads what
//! the page gives it).

use std::io::Read as _;
use std::path::{Path, PathBuf};

use crate::control::ControlError;
use crate::model::control::{Control, PlantInfo};
use crate::model::rotor::{parse_rotor_file, Rotor, RotorFile};
use crate::model::CaseError;

/// Largest input file read [bytes]: case, rotor and designs files are kilobytes; a designs table of a
/// hundred thousand rows is a few megabytes.
pub const MAX_INPUT_BYTES: u64 = 64 * 1024 * 1024;

/// An input file that cannot be used; `what` says what it was read as (`case file`, `rotor file`, …).
#[derive(Debug, thiserror::Error)]
pub enum ReadError {
    #[error("cannot read {what} {}: {error}", path.display())]
    Unreadable { what: &'static str, path: PathBuf, error: std::io::Error },
    #[error("cannot read {what} {}: it is a directory", path.display())]
    Directory { what: &'static str, path: PathBuf },
    #[error(
        "{what} {} is larger than {} MiB, the most tiltpad reads from an input file (a {what} is a few kilobytes); \
         is it the right file?",
        path.display(),
        MAX_INPUT_BYTES / (1024 * 1024)
    )]
    TooLarge { what: &'static str, path: PathBuf },
    #[error("{what} {} is not UTF-8 text (invalid byte at offset {offset})", path.display())]
    NotText { what: &'static str, path: PathBuf, offset: usize },
    /// The rotor file (or a bearing case it names, or its controller) is invalid.
    #[error("invalid rotor file {}: {error}", path.display())]
    InvalidRotor { path: PathBuf, error: CaseError },
    #[error("{}: {}", path.display(), ControlError::NoController)]
    NoController { path: PathBuf },
}

/// Reads a text input (`what`: "case file", "designs table", …) of at most [`MAX_INPUT_BYTES`].
///
/// # Errors
/// A missing or unreadable file, a directory, more than the cap, or text that is not UTF-8.
pub fn read_text(path: &Path, what: &'static str) -> Result<String, ReadError> {
    let unreadable = |error| ReadError::Unreadable { what, path: path.to_path_buf(), error };
    let file = std::fs::File::open(path).map_err(unreadable)?;
    if file.metadata().is_ok_and(|m| m.is_dir()) {
        return Err(ReadError::Directory { what, path: path.to_path_buf() });
    }
    let mut bytes = Vec::new();
    file.take(MAX_INPUT_BYTES + 1).read_to_end(&mut bytes).map_err(unreadable)?;
    if bytes.len() as u64 > MAX_INPUT_BYTES {
        return Err(ReadError::TooLarge { what, path: path.to_path_buf() });
    }
    String::from_utf8(bytes).map_err(|e| ReadError::NotText {
        what,
        path: path.to_path_buf(),
        offset: e.utf8_error().valid_up_to(),
    })
}

/// The rotor file parsed, and resolved with its bearing cases (read relative to it).
fn rotor_file(path: &Path) -> Result<(RotorFile, Rotor), ReadError> {
    let text = read_text(path, "rotor file")?;
    let invalid = |error| ReadError::InvalidRotor { path: path.to_path_buf(), error };
    let file = parse_rotor_file(&text).map_err(invalid)?;
    let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
    let read = |name: &str| read_text(&dir.join(name), "bearing case").map_err(|e| e.to_string());
    let rotor = file.resolve(&read).map_err(invalid)?;
    Ok((file, rotor))
}

/// Reads a rotor file and the bearing cases it names (relative to it).
///
/// # Errors
/// I/O and validation errors, naming the file and the key.
pub fn read_rotor(path: &Path) -> Result<Rotor, ReadError> {
    Ok(rotor_file(path)?.1)
}

/// Reads a rotor file, the bearing cases it names and its controller (`[control]`).
///
/// # Errors
/// I/O and validation errors naming the file and the key; a file without `[control]`.
pub fn read_controlled(path: &Path) -> Result<(Rotor, Control), ReadError> {
    let (file, rotor) = rotor_file(path)?;
    let Some(table) = file.control else { return Err(ReadError::NoController { path: path.to_path_buf() }) };
    let control = table
        .resolve(&PlantInfo::rotor(&rotor))
        .map_err(|error| ReadError::InvalidRotor { path: path.to_path_buf(), error })?;
    Ok((rotor, control))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::rotor::BearingSupport;

    #[test]
    fn inputs_are_read_under_a_size_cap() {
        #[cfg(unix)]
        {
            let e = read_text(Path::new("/dev/zero"), "case file").unwrap_err();
            assert!(matches!(e, ReadError::TooLarge { what: "case file", .. }), "{e:?}");
            assert!(e.to_string().contains("larger than 64 MiB"), "{e}");
        }
        let e = read_text(Path::new("/nonexistent/case.toml"), "case file").unwrap_err().to_string();
        assert!(e.starts_with("cannot read case file /nonexistent/case.toml: "), "{e}");
        let e = read_text(Path::new(env!("CARGO_MANIFEST_DIR")), "case file").unwrap_err().to_string();
        assert!(e.ends_with("it is a directory"), "{e}");
    }

    /// A rotor file names its bearing cases relative to itself; a bad key is the case error with its key, a
    /// rotor without a controller says so.
    #[test]
    fn a_rotor_file_reads_its_bearings_beside_it_and_errors_name_the_key() {
        let cases = Path::new(env!("CARGO_MANIFEST_DIR")).join("cases/rotors");
        let rotor = read_rotor(&cases.join("compressor-rotor.toml")).unwrap();
        // two journal bearings from `../compressor-bearing.toml`, and a seal given by its coefficients
        let from_cases = rotor
            .bearings
            .iter()
            .filter(|b| matches!(&b.support, BearingSupport::Case { case, .. } if case.bearing.pads.len() == 5))
            .count();
        assert_eq!((rotor.bearings.len(), from_cases), (3, 2));
        let e = read_controlled(&cases.join("compressor-rotor.toml")).unwrap_err();
        assert!(matches!(e, ReadError::NoController { .. }), "{e:?}");
        assert!(e.to_string().ends_with("the rotor file has no [control] section: nothing closes the loop"), "{e}");
        let (rotor, control) = read_controlled(&cases.join("compressor-rotor-active.toml")).unwrap();
        assert_eq!((rotor.bearings.len(), control.actuators.len()), (3, 2));
        let dir = tempfile::tempdir().unwrap();
        let bad = dir.path().join("bad.toml");
        std::fs::write(&bad, "[rotor]\n[[rotor.section]]\nlength_mm = -1\nouter_diameter_mm = 50\nelements = 4\n")
            .unwrap();
        match read_rotor(&bad).unwrap_err() {
            ReadError::InvalidRotor { error: CaseError::OutOfRange { key, .. }, .. } => {
                assert_eq!(key, "rotor.section[0].length_mm");
            }
            other => panic!("{other:?}"),
        }
    }
}
