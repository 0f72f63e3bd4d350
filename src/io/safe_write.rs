//! Safe writes: every file tiltpad writes (case saves, `--json`, `--csv`, exports) either appears whole or
//! leaves the old file as it was.
//!
//! Contract of [`SafeFile`]:
//! - The bytes go to a temporary file created exclusively (`O_EXCL`) with an unpredictable name
//!   (`.NAME.XXXXXXXX.partial`, 8 random characters, by the `tempfile` crate) in the target's directory, so a
//!   planted file cannot redirect the write. [`SafeFile::commit`] flushes and syncs it, gives it the old
//!   file's permission bits (a new file gets `0666` less the umask), renames it over the target and syncs
//!   the directory.
//! - Dropping a [`SafeFile`] without committing removes the temporary file (a failed write, a full disk):
//!   the old file stays intact and nothing is left behind. A process killed mid-way leaves its
//!   `.partial` file, which is how a long sweep keeps every row it finished.
//! - A symlink is never replaced: the write goes through it to the file it names (a dangling link is
//!   refused). A FIFO or a character device (`/dev/stdout`, a pipe from `>(…)`) is written through in
//!   place, since renaming over it would destroy it; a directory, block device or socket is refused.
//! - Every error names the path the user gave.
//!
//! Native only: on the web, files leave the app as downloads.

use std::fs::{File, OpenOptions, Permissions};
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};

use tempfile::NamedTempFile;
use thiserror::Error;

/// A write that could not be done; the old file (if any) is unchanged.
#[derive(Debug, Error)]
pub enum WriteError {
    #[error("cannot write {path}: it is a directory")]
    IsDirectory { path: PathBuf },
    #[error("cannot write {path}: it is a {kind}, which tiltpad does not replace")]
    Special { path: PathBuf, kind: &'static str },
    #[error("cannot write {path}: it is a symlink to {target}, which does not exist")]
    DanglingLink { path: PathBuf, target: PathBuf },
    /// The operating system's error is part of the message, not a separate cause (printed once).
    #[error("cannot write {path}: {error}")]
    Io { path: PathBuf, error: io::Error },
}

impl WriteError {
    fn io(path: &Path, source: io::Error) -> Self {
        Self::Io { path: path.to_path_buf(), error: source }
    }
}

/// Where the bytes go.
enum Sink {
    /// A temporary file beside the regular-file target, renamed over it on commit.
    Temp { file: BufWriter<NamedTempFile>, target: PathBuf, mode: Option<Permissions> },
    /// A FIFO or character device, written in place.
    Stream(BufWriter<File>),
    /// Standard output (`-`).
    Stdout(io::Stdout),
}

/// A file being written safely (see the module documentation). Implements [`Write`].
pub struct SafeFile {
    sink: Sink,
    /// The path as the user gave it (for messages).
    path: PathBuf,
}

/// What is at a path, after following symlinks.
enum Target {
    /// A regular file or nothing yet: write atomically at this (resolved) path.
    Regular { resolved: PathBuf, mode: Option<Permissions> },
    /// A FIFO or character device.
    Stream(PathBuf),
}

#[cfg(unix)]
fn special_kind(ft: std::fs::FileType) -> Option<(&'static str, bool)> {
    use std::os::unix::fs::FileTypeExt;
    // (kind, written through in place)
    if ft.is_fifo() {
        Some(("FIFO", true))
    } else if ft.is_char_device() {
        Some(("character device", true))
    } else if ft.is_block_device() {
        Some(("block device", false))
    } else if ft.is_socket() {
        Some(("socket", false))
    } else {
        None
    }
}

#[cfg(not(unix))]
fn special_kind(_: std::fs::FileType) -> Option<(&'static str, bool)> {
    None
}

fn examine(path: &Path) -> Result<Target, WriteError> {
    let link = match std::fs::symlink_metadata(path) {
        Ok(m) => m,
        Err(e) if e.kind() == io::ErrorKind::NotFound => {
            return Ok(Target::Regular { resolved: path.to_path_buf(), mode: None })
        }
        Err(e) => return Err(WriteError::io(path, e)),
    };
    let resolved = if link.file_type().is_symlink() {
        match std::fs::canonicalize(path) {
            Ok(p) => p,
            Err(e) if e.kind() == io::ErrorKind::NotFound => {
                let target = std::fs::read_link(path).unwrap_or_default();
                return Err(WriteError::DanglingLink { path: path.to_path_buf(), target });
            }
            Err(e) => return Err(WriteError::io(path, e)),
        }
    } else {
        path.to_path_buf()
    };
    let meta = std::fs::metadata(&resolved).map_err(|e| WriteError::io(path, e))?;
    let ft = meta.file_type();
    if ft.is_dir() {
        return Err(WriteError::IsDirectory { path: path.to_path_buf() });
    }
    match special_kind(ft) {
        Some((_, true)) => Ok(Target::Stream(resolved)),
        Some((kind, false)) => Err(WriteError::Special { path: path.to_path_buf(), kind }),
        None => Ok(Target::Regular { resolved, mode: Some(meta.permissions()) }),
    }
}

/// Permission bits for a new file: `0666` less the umask (applied by `open`).
#[cfg(unix)]
fn new_file_permissions() -> Option<Permissions> {
    use std::os::unix::fs::PermissionsExt;
    Some(Permissions::from_mode(0o666))
}

#[cfg(not(unix))]
fn new_file_permissions() -> Option<Permissions> {
    None
}

impl SafeFile {
    /// Starts a safe write of `path`; `-` means standard output.
    ///
    /// # Errors
    /// The target is a directory, block device, socket or dangling symlink, or its directory does not
    /// accept a new file (missing, read-only, full).
    pub fn create(path: &Path) -> Result<Self, WriteError> {
        if path.as_os_str() == "-" {
            return Ok(Self { sink: Sink::Stdout(io::stdout()), path: path.to_path_buf() });
        }
        let sink = match examine(path)? {
            Target::Stream(resolved) => {
                let f = OpenOptions::new().write(true).open(&resolved).map_err(|e| WriteError::io(path, e))?;
                Sink::Stream(BufWriter::new(f))
            }
            Target::Regular { resolved, mode } => {
                let dir = resolved.parent().filter(|d| !d.as_os_str().is_empty()).unwrap_or_else(|| Path::new("."));
                let name = resolved.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
                let prefix = format!(".{name}.");
                let mut builder = tempfile::Builder::new();
                builder.prefix(&prefix).suffix(".partial").rand_bytes(8);
                if let Some(p) = new_file_permissions() {
                    builder.permissions(p);
                }
                let tmp = builder.tempfile_in(dir).map_err(|e| WriteError::io(path, e))?;
                Sink::Temp { file: BufWriter::new(tmp), target: resolved, mode }
            }
        };
        Ok(Self { sink, path: path.to_path_buf() })
    }

    /// The temporary file that holds the bytes until [`Self::commit`] (none for streams and stdout).
    #[must_use]
    pub fn partial_path(&self) -> Option<&Path> {
        match &self.sink {
            Sink::Temp { file, .. } => Some(file.get_ref().path()),
            _ => None,
        }
    }

    /// The path as given.
    #[must_use]
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// Wraps an I/O error of this write with its path.
    #[must_use]
    pub fn error(&self, source: io::Error) -> WriteError {
        WriteError::io(&self.path, source)
    }

    /// Writes all of `bytes`, naming the path on failure.
    ///
    /// # Errors
    /// The underlying write failed (e.g. the disk is full).
    pub fn put(&mut self, bytes: &[u8]) -> Result<(), WriteError> {
        self.write_all(bytes).map_err(|e| self.error(e))
    }

    /// Flushes, syncs and puts the file in place.
    ///
    /// # Errors
    /// Flushing, syncing or renaming failed; the temporary file is then removed and the old file kept.
    pub fn commit(self) -> Result<(), WriteError> {
        let path = self.path;
        match self.sink {
            Sink::Stdout(mut out) => out.flush().map_err(|e| WriteError::io(&path, e)),
            Sink::Stream(mut f) => f.flush().map_err(|e| WriteError::io(&path, e)),
            Sink::Temp { file, target, mode } => {
                let tmp = file.into_inner().map_err(|e| WriteError::io(&path, e.into_error()))?;
                if let Some(m) = mode {
                    std::fs::set_permissions(tmp.path(), m).map_err(|e| WriteError::io(&path, e))?;
                }
                tmp.as_file().sync_all().map_err(|e| WriteError::io(&path, e))?;
                tmp.persist(&target).map_err(|e| WriteError::io(&path, e.error))?;
                sync_dir(&target).map_err(|e| WriteError::io(&path, e))
            }
        }
    }
}

/// Makes the rename durable.
#[cfg(unix)]
fn sync_dir(target: &Path) -> io::Result<()> {
    let dir = target.parent().filter(|d| !d.as_os_str().is_empty()).unwrap_or_else(|| Path::new("."));
    File::open(dir)?.sync_all()
}

#[cfg(not(unix))]
fn sync_dir(_: &Path) -> io::Result<()> {
    Ok(())
}

impl Write for SafeFile {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        match &mut self.sink {
            Sink::Temp { file, .. } => file.write(buf),
            Sink::Stream(f) => f.write(buf),
            Sink::Stdout(out) => out.write(buf),
        }
    }

    fn flush(&mut self) -> io::Result<()> {
        match &mut self.sink {
            Sink::Temp { file, .. } => file.flush(),
            Sink::Stream(f) => f.flush(),
            Sink::Stdout(out) => out.flush(),
        }
    }
}

/// Writes `bytes` to `path` safely (`-`: standard output).
///
/// # Errors
/// See [`SafeFile::create`] and [`SafeFile::commit`].
pub fn write_file(path: &Path, bytes: &[u8]) -> Result<(), WriteError> {
    write_with(path, |w| w.write_all(bytes))
}

/// Writes `path` safely with what `fill` writes; if `fill` fails, nothing changes and the error names
/// the path.
///
/// # Errors
/// `fill`'s error, and those of [`SafeFile::create`] and [`SafeFile::commit`].
pub fn write_with(path: &Path, fill: impl FnOnce(&mut dyn Write) -> io::Result<()>) -> Result<(), WriteError> {
    let mut f = SafeFile::create(path)?;
    fill(&mut f).map_err(|e| f.error(e))?;
    f.commit()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("tiltpad-safe-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    fn names(dir: &Path) -> Vec<String> {
        let mut v: Vec<String> =
            std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
        v.sort();
        v
    }

    #[test]
    fn replaces_a_file_whole_and_keeps_its_mode() {
        use std::os::unix::fs::PermissionsExt;
        let dir = scratch("mode");
        let p = dir.join("out.json");
        std::fs::write(&p, "old").unwrap();
        std::fs::set_permissions(&p, Permissions::from_mode(0o640)).unwrap();
        write_file(&p, b"new contents").unwrap();
        assert_eq!(std::fs::read_to_string(&p).unwrap(), "new contents");
        assert_eq!(std::fs::metadata(&p).unwrap().permissions().mode() & 0o777, 0o640);
        assert_eq!(names(&dir), vec!["out.json"]);
        std::fs::remove_dir_all(&dir).ok();
    }

    #[test]
    fn a_failing_writer_leaves_the_old_file_and_no_temporary() {
        // A mock of a full disk: the writer fails after part of the data.
        let dir = scratch("full");
        let p = dir.join("out.csv");
        std::fs::write(&p, "old rows\n").unwrap();
        let err = write_with(&p, |w| {
            w.write_all(b"half a row")?;
            Err(io::Error::new(io::ErrorKind::StorageFull, "No space left on device"))
        })
        .unwrap_err();
        let msg = err.to_string();
        assert!(msg.contains(&p.display().to_string()) && msg.contains("No space left"), "{msg}");
        assert_eq!(std::fs::read_to_string(&p).unwrap(), "old rows\n");
        assert_eq!(names(&dir), vec!["out.csv"]);
        std::fs::remove_dir_all(&dir).ok();
    }

    #[test]
    fn writes_through_a_symlink_and_keeps_the_link() {
        let dir = scratch("link");
        let real = dir.join("real.json");
        let link = dir.join("link.json");
        std::fs::write(&real, "old").unwrap();
        std::os::unix::fs::symlink(&real, &link).unwrap();
        write_file(&link, b"through").unwrap();
        assert!(std::fs::symlink_metadata(&link).unwrap().file_type().is_symlink(), "the link was replaced");
        assert_eq!(std::fs::read_link(&link).unwrap(), real);
        assert_eq!(std::fs::read_to_string(&real).unwrap(), "through");
        assert_eq!(names(&dir), vec!["link.json", "real.json"]);
        // A dangling link is refused, naming the path, and stays as it was.
        let dangling = dir.join("dangling.json");
        std::os::unix::fs::symlink(dir.join("missing.json"), &dangling).unwrap();
        let err = write_file(&dangling, b"x").unwrap_err().to_string();
        assert!(err.contains("dangling.json") && err.contains("missing.json"), "{err}");
        assert!(std::fs::symlink_metadata(&dangling).unwrap().file_type().is_symlink());
        assert_eq!(names(&dir), vec!["dangling.json", "link.json", "real.json"]);
        std::fs::remove_dir_all(&dir).ok();
    }

    #[test]
    fn a_directory_is_refused_and_left_alone() {
        let dir = scratch("dir");
        let target = dir.join("results");
        std::fs::create_dir(&target).unwrap();
        std::fs::write(target.join("keep.txt"), "x").unwrap();
        let err = write_file(&target, b"data").unwrap_err().to_string();
        assert!(err.contains(&target.display().to_string()) && err.contains("directory"), "{err}");
        assert_eq!(names(&target), vec!["keep.txt"]);
        assert_eq!(names(&dir), vec!["results"]);
        std::fs::remove_dir_all(&dir).ok();
    }

    #[test]
    fn a_planted_predictable_temporary_does_not_redirect_the_write() {
        // The old scheme wrote `.NAME.tmp<pid>`; a symlink planted under that name must stay untouched.
        let dir = scratch("plant");
        let victim = dir.join("victim.txt");
        std::fs::write(&victim, "precious").unwrap();
        let p = dir.join("out.json");
        std::os::unix::fs::symlink(&victim, dir.join(format!(".out.json.tmp{}", std::process::id()))).unwrap();
        write_file(&p, b"result").unwrap();
        assert_eq!(std::fs::read_to_string(&victim).unwrap(), "precious");
        assert_eq!(std::fs::read_to_string(&p).unwrap(), "result");
        std::fs::remove_dir_all(&dir).ok();
    }

    #[test]
    fn a_fifo_is_written_in_place() {
        let dir = scratch("fifo");
        let fifo = dir.join("pipe");
        assert!(std::process::Command::new("mkfifo").arg(&fifo).status().unwrap().success());
        let reader = {
            let fifo = fifo.clone();
            std::thread::spawn(move || std::fs::read_to_string(fifo).unwrap())
        };
        write_file(&fifo, b"streamed").unwrap();
        assert_eq!(reader.join().unwrap(), "streamed");
        assert!(std::os::unix::fs::FileTypeExt::is_fifo(&std::fs::symlink_metadata(&fifo).unwrap().file_type()));
        assert_eq!(names(&dir), vec!["pipe"]);
        std::fs::remove_dir_all(&dir).ok();
    }

    #[test]
    fn the_partial_file_holds_rows_until_commit() {
        let dir = scratch("partial");
        let p = dir.join("sweep.csv");
        let mut f = SafeFile::create(&p).unwrap();
        f.put(b"a,b\n1,2\n").unwrap();
        f.flush().unwrap();
        let partial = f.partial_path().unwrap().to_path_buf();
        let name = partial.file_name().unwrap().to_string_lossy().into_owned();
        assert!(
            name.starts_with(".sweep.csv.")
                && name.ends_with(".partial")
                && name.len() == ".sweep.csv.".len() + 8 + ".partial".len(),
            "{name}"
        );
        assert_eq!(std::fs::read_to_string(&partial).unwrap(), "a,b\n1,2\n");
        assert!(!p.exists());
        f.commit().unwrap();
        assert_eq!(std::fs::read_to_string(&p).unwrap(), "a,b\n1,2\n");
        assert_eq!(names(&dir), vec!["sweep.csv"]);
        std::fs::remove_dir_all(&dir).ok();
    }
}
