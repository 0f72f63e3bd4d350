//! "Open case…" and "Open rotor…" inside the workbench, for machines without a native file dialog (no
//! desktop portal on the session bus): the user types a path, or picks one of the TOML files listed in the
//! directory (listed first; its folders below them, to go into; `../` goes up). Contract: nothing is read
//! before the user asked for a file; a file that cannot be read (or is not UTF-8 text) keeps the dialog open
//! with the message naming it, and the case on screen is untouched until the read file goes through the
//! unsaved-changes guard like any other opened case. The twin of [`super::save_dialog`].

use std::path::{Path, PathBuf};

use egui::RichText;

use super::file_event::{display_name, FileEvent, OpenKind};
use super::path_fields::PathFields;
use crate::app::ink;

/// What the dialog did this frame.
pub enum OpenOutcome {
    Open,
    Cancelled,
    /// A file was read; the dialog is finished.
    Done(FileEvent),
}

/// At most this many files of the directory are listed (a large directory is typed into, not scrolled).
const MAX_LISTED: usize = 200;

/// The dialog's state.
#[derive(Debug)]
pub struct OpenDialog {
    pub kind: OpenKind,
    fields: PathFields,
    error: Option<String>,
    /// The `.toml` files of `listed_for`, sorted.
    listing: Vec<String>,
    /// The folders of `listed_for`, sorted (clicking one goes into it).
    folders: Vec<String>,
    listed_for: Option<String>,
}

impl OpenDialog {
    /// A dialog on the working directory with an empty name.
    #[must_use]
    pub fn new(kind: OpenKind) -> Self {
        Self {
            kind,
            fields: PathFields::new(),
            error: None,
            listing: Vec::new(),
            folders: Vec::new(),
            listed_for: None,
        }
    }

    /// The file the typed name reads: `None` until a name is typed. An absolute name is taken as it is.
    #[must_use]
    pub fn target(&self) -> Option<PathBuf> {
        self.fields.joined()
    }

    /// The `.toml` files of the directory (read again when the directory changes).
    fn refresh_listing(&mut self) {
        let dir = self.fields.directory.trim().to_string();
        if self.listed_for.as_deref() == Some(dir.as_str()) {
            return;
        }
        self.listing = toml_files(Path::new(&dir));
        self.folders = folders(Path::new(&dir));
        self.listed_for = Some(dir);
    }

    /// Shows the dialog as a modal window.
    pub fn ui(&mut self, ctx: &egui::Context) -> OpenOutcome {
        let mut outcome = OpenOutcome::Open;
        self.refresh_listing();
        let modal = egui::Modal::new(egui::Id::unique(("open-dialog", self.kind.title()))).show(ctx, |ui| {
            ui.heading(self.kind.title());
            ui.label("No system file dialog here: type the file's path or pick a file below.");
            let edited = self.fields.ui(ui, "open-grid", "case.toml");
            if edited {
                self.error = None;
            }
            ui.label(RichText::new(format!("TOML files in this directory ({}):", self.listing.len())).weak());
            let mut into = None;
            // The files first (what the dialog is for: a case folder's files show without scrolling), then
            // the folders to go into.
            egui::ScrollArea::vertical().max_height(180.0).auto_shrink([false, true]).show(ui, |ui| {
                for file in self.listing.iter().take(MAX_LISTED) {
                    if ui.selectable_label(self.fields.name == *file, file).clicked() {
                        self.fields.name.clone_from(file);
                        self.error = None;
                    }
                }
                if self.listing.len() > MAX_LISTED {
                    ui.label(
                        RichText::new(format!("… and {} more: type the name", self.listing.len() - MAX_LISTED)).weak(),
                    );
                }
                if self.fields.directory().parent().is_some() || !self.folders.is_empty() {
                    ui.label(RichText::new("Folders:").weak());
                }
                if self.fields.directory().parent().is_some() && ui.selectable_label(false, "../").clicked() {
                    into = Some("..".to_string());
                }
                for folder in &self.folders {
                    if ui.selectable_label(false, format!("{folder}/")).clicked() {
                        into = Some(folder.clone());
                    }
                }
            });
            if let Some(folder) = into {
                self.enter(&folder);
            }
            let target = self.target();
            if let Some(e) = &self.error {
                ui.label(RichText::new(e).color(ink::ERROR.of(ui)));
            }
            let enter = ui.input(|i| i.key_pressed(egui::Key::Enter));
            ui.separator();
            ui.horizontal(|ui| {
                let open = ui.add_enabled(target.is_some(), egui::Button::new("Open")).clicked()
                    || (enter && target.is_some());
                if let (true, Some(t)) = (open, &target) {
                    outcome = self.read(t);
                }
                if ui.button("Cancel").clicked() {
                    outcome = OpenOutcome::Cancelled;
                }
            });
        });
        if modal.should_close() && matches!(outcome, OpenOutcome::Open) {
            outcome = OpenOutcome::Cancelled;
        }
        outcome
    }

    /// Goes into the folder `name` of the directory (`..`: up one level).
    fn enter(&mut self, name: &str) {
        let dir = self.fields.directory();
        let next = if name == ".." { dir.parent().map(Path::to_path_buf) } else { Some(dir.join(name)) };
        if let Some(next) = next {
            self.fields.directory = next.display().to_string();
            self.error = None;
        }
    }

    /// Reads `path`: the event for a read file, or the dialog stays open with the message.
    fn read(&mut self, path: &Path) -> OpenOutcome {
        match read_text(path) {
            Ok(text) => {
                let name = display_name(path);
                let path = std::fs::canonicalize(path).unwrap_or_else(|_| path.to_path_buf());
                OpenOutcome::Done(match self.kind {
                    OpenKind::Case => FileEvent::Opened { name, path: Some(path), text },
                    OpenKind::Rotor => FileEvent::OpenedRotor { name, path, text },
                })
            }
            Err(e) => {
                self.error = Some(e);
                OpenOutcome::Open
            }
        }
    }
}

/// The names of the `.toml` files in `dir`, sorted (none when it cannot be read).
fn toml_files(dir: &Path) -> Vec<String> {
    let Ok(entries) = std::fs::read_dir(dir) else { return Vec::new() };
    let mut names: Vec<String> = entries
        .filter_map(Result::ok)
        .filter(|e| e.path().is_file() && e.path().extension().is_some_and(|x| x.eq_ignore_ascii_case("toml")))
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

/// The names of the folders in `dir` that are not hidden, sorted.
fn folders(dir: &Path) -> Vec<String> {
    let Ok(entries) = std::fs::read_dir(dir) else { return Vec::new() };
    let mut names: Vec<String> = entries
        .filter_map(Result::ok)
        .filter(|e| e.path().is_dir())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| !n.starts_with('.'))
        .collect();
    names.sort();
    names
}

#[cfg(not(target_arch = "wasm32"))]
fn read_text(path: &Path) -> Result<String, String> {
    let bytes = std::fs::read(path).map_err(|e| format!("cannot read {}: {e}", path.display()))?;
    String::from_utf8(bytes).map_err(|_| format!("{} is not UTF-8 text", path.display()))
}

/// The browser has its own dialog; this dialog is never opened there.
#[cfg(target_arch = "wasm32")]
fn read_text(path: &Path) -> Result<String, String> {
    Err(format!("cannot read {} in the browser", path.display()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_typed_name_is_joined_to_the_directory_and_an_absolute_one_kept() {
        let mut d = OpenDialog::new(OpenKind::Case);
        assert_eq!(d.target(), None);
        d.fields.directory = "/some/dir".into();
        d.fields.name = " case.toml ".into();
        assert_eq!(d.target(), Some(PathBuf::from("/some/dir/case.toml")));
        d.fields.name = "/elsewhere/rotor.toml".into();
        assert_eq!(d.target(), Some(PathBuf::from("/elsewhere/rotor.toml")));
    }

    #[test]
    fn the_listing_holds_the_toml_files_sorted() {
        let dir = std::env::temp_dir().join(format!("tiltpad-open-list-{}", std::process::id()));
        std::fs::create_dir_all(dir.join("sub.toml")).unwrap();
        for f in ["b.toml", "a.TOML", "notes.txt"] {
            std::fs::write(dir.join(f), "").unwrap();
        }
        assert_eq!(toml_files(&dir), ["a.TOML", "b.toml"]);
        std::fs::create_dir_all(dir.join(".hidden")).unwrap();
        assert_eq!(folders(&dir), ["sub.toml"]);
        let mut d = OpenDialog::new(OpenKind::Case);
        d.fields.directory = dir.display().to_string();
        d.enter("sub.toml");
        assert_eq!(Path::new(&d.fields.directory), dir.join("sub.toml"));
        d.enter("..");
        assert_eq!(Path::new(&d.fields.directory), dir);
        assert!(toml_files(&dir.join("missing")).is_empty());
        std::fs::remove_dir_all(&dir).ok();
    }

    #[test]
    fn a_file_that_cannot_be_read_keeps_the_dialog_open_with_its_name() {
        let dir = std::env::temp_dir().join(format!("tiltpad-open-bad-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(dir.join("binary.toml"), [0xff, 0xfe, 0x00]).unwrap();
        let mut d = OpenDialog::new(OpenKind::Rotor);
        for (file, says) in [("missing.toml", "cannot read"), ("binary.toml", "not UTF-8")] {
            assert!(matches!(d.read(&dir.join(file)), OpenOutcome::Open));
            let e = d.error.clone().unwrap();
            assert!(e.contains(file) && e.contains(says), "{e}");
        }
        std::fs::write(dir.join("rotor.toml"), "x = 1").unwrap();
        match d.read(&dir.join("rotor.toml")) {
            OpenOutcome::Done(FileEvent::OpenedRotor { name, text, .. }) => {
                assert_eq!((name.as_str(), text.as_str()), ("rotor.toml", "x = 1"))
            }
            _ => panic!("the rotor file is read"),
        }
        std::fs::remove_dir_all(&dir).ok();
    }
}
