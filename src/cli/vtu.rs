//! File names of VTK exports: `out.vtu` (film) and `out-pads.vtu` (pad solids) for one solve; for a sweep
//! `out.pvd` with `out-0003.vtu`, `out-0003-pads.vtu` per solved point beside it.

use std::path::{Path, PathBuf};

use anyhow::Result;

use crate::bearing::Solution;
use crate::io::{vtk, write_file};

use super::rows::announce;

/// `dir/stem-suffix.vtu` for `dir/stem.ext`.
fn sibling(path: &Path, suffix: &str) -> PathBuf {
    let stem = path.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
    path.with_file_name(format!("{stem}{suffix}.vtu"))
}

/// Writes the film grid to `path` and, when the solve has pad solids, the pad grid beside it; returns the
/// files written.
///
/// # Errors
/// A file that cannot be written.
pub fn write_solution(path: &Path, solution: &Solution) -> Result<Vec<PathBuf>> {
    write_file(path, vtk::film_grid(solution).to_vtu().as_bytes())?;
    let mut written = vec![path.to_path_buf()];
    if let Some(pads) = vtk::pad_solid_grid(solution) {
        let p = sibling(path, "-pads");
        write_file(&p, pads.to_vtu().as_bytes())?;
        written.push(p);
    }
    Ok(written)
}

/// The `.vtu` files of a sweep and their `.pvd` collection.
pub struct VtuSeries {
    pvd: PathBuf,
    entries: Vec<(f64, usize, String)>,
}

impl VtuSeries {
    /// The collection at `pvd`; a symlink is followed, so that the `.vtu` files are written beside the file
    /// the collection really is (its references are relative to its own directory).
    #[must_use]
    pub fn new(pvd: &Path) -> Self {
        let resolved = match std::fs::symlink_metadata(pvd) {
            Ok(m) if m.file_type().is_symlink() => std::fs::canonicalize(pvd).unwrap_or_else(|_| pvd.to_path_buf()),
            _ => pvd.to_path_buf(),
        };
        Self { pvd: resolved, entries: Vec::new() }
    }

    /// Writes point `index`'s grids, listed at time step `step`.
    ///
    /// # Errors
    /// A file that cannot be written.
    pub fn add(&mut self, index: usize, step: f64, solution: &Solution) -> Result<()> {
        let film = sibling(&self.pvd, &format!("-{index:04}"));
        for (part, file) in write_solution(&film, solution)?.into_iter().enumerate() {
            let name = file.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
            self.entries.push((step, part, name));
        }
        Ok(())
    }

    /// Writes the collection.
    ///
    /// # Errors
    /// A file that cannot be written.
    pub fn finish(self) -> Result<()> {
        write_file(&self.pvd, vtk::pvd(&self.entries).as_bytes())?;
        announce(&self.pvd);
        Ok(())
    }
}
