//! "Save as" inside the workbench, for machines without a native file dialog (no desktop portal on the
//! session bus): the user types a file name (the directory is shown and may be edited). Contract: nothing
//! is written before the user typed a name, and an existing file is replaced only after the user said so
//! in a second step. A failed write keeps the dialog open with the message, so the bytes are not lost.

use std::path::{Path, PathBuf};

use egui::RichText;

use super::file_event::{display_name, FileEvent, PendingSave};
use super::path_fields::PathFields;

/// What the dialog did this frame.
pub enum SaveOutcome {
    Open,
    Cancelled,
    /// Written (or a message to show); the dialog is finished.
    Done(FileEvent),
}

/// The dialog's state.
#[derive(Debug)]
pub struct SaveDialog {
    pending: PendingSave,
    fields: PathFields,
    /// The typed target exists: the user is asked whether to replace it.
    confirm: Option<PathBuf>,
    error: Option<String>,
}

impl SaveDialog {
    /// A dialog in the working directory with an empty name.
    #[must_use]
    pub fn new(pending: PendingSave) -> Self {
        Self { pending, fields: PathFields::new(), confirm: None, error: None }
    }

    /// Where the typed name writes: `None` until a name is typed. A name without an extension gets the
    /// export's one.
    #[must_use]
    pub fn target(&self) -> Option<PathBuf> {
        let mut path = self.fields.joined()?;
        if path.extension().is_none() {
            path.set_extension(&self.pending.extension);
        }
        Some(path)
    }

    /// Shows the dialog as a modal window.
    pub fn ui(&mut self, ctx: &egui::Context) -> SaveOutcome {
        let mut outcome = SaveOutcome::Open;
        let modal = egui::Modal::new(egui::Id::unique("save-as")).show(ctx, |ui| {
            ui.heading("Save as");
            ui.label("No system file dialog here: type a file name. Nothing is written until you do.");
            let edited = self.fields.ui(ui, "save-as-grid", &self.pending.suggested);
            if edited {
                self.confirm = None;
                self.error = None;
            }
            let target = self.target();
            match &target {
                Some(t) => ui.label(format!("Writes {}", t.display())),
                None => {
                    ui.label(RichText::new(format!("Type a name (for example {}).", self.pending.suggested)).weak())
                }
            };
            if let Some(e) = &self.error {
                ui.label(RichText::new(e).color(crate::app::ink::ERROR.of(ui)));
            }
            let enter = ui.input(|i| i.key_pressed(egui::Key::Enter));
            ui.separator();
            if let Some(existing) = self.confirm.clone() {
                ui.label(
                    RichText::new(format!("{} exists. Replace it?", display_name(&existing)))
                        .color(crate::app::ink::WARNING.of(ui)),
                );
                ui.horizontal(|ui| {
                    if ui.button("Replace").clicked() {
                        outcome = self.write(&existing);
                    }
                    if ui.button("Keep it").clicked() {
                        self.confirm = None;
                    }
                });
            } else {
                ui.horizontal(|ui| {
                    let save = ui.add_enabled(target.is_some(), egui::Button::new("Save")).clicked()
                        || (enter && target.is_some());
                    if let (true, Some(t)) = (save, &target) {
                        if t.exists() {
                            self.confirm = Some(t.clone());
                        } else {
                            outcome = self.write(t);
                        }
                    }
                    if ui.button("Cancel").clicked() {
                        outcome = SaveOutcome::Cancelled;
                    }
                });
            }
        });
        if modal.should_close() && matches!(outcome, SaveOutcome::Open) {
            outcome = SaveOutcome::Cancelled;
        }
        outcome
    }

    /// Writes the bytes to `path` (safely: a failed write leaves what was there).
    fn write(&mut self, path: &Path) -> SaveOutcome {
        match write_bytes(path, &self.pending.bytes) {
            Ok(()) => {
                let done = std::mem::replace(&mut self.pending.done, Box::new(|_, _| FileEvent::Error(String::new())));
                let shown = std::fs::canonicalize(path).unwrap_or_else(|_| path.to_path_buf());
                SaveOutcome::Done(done(display_name(path), Some(shown)))
            }
            Err(e) => {
                self.confirm = None;
                self.error = Some(e);
                SaveOutcome::Open
            }
        }
    }
}

#[cfg(not(target_arch = "wasm32"))]
fn write_bytes(path: &Path, bytes: &[u8]) -> Result<(), String> {
    crate::io::write_file(path, bytes).map_err(|e| e.to_string())
}

/// The browser has its own dialog (a download); this dialog is never opened there.
#[cfg(target_arch = "wasm32")]
fn write_bytes(path: &Path, _: &[u8]) -> Result<(), String> {
    Err(format!("cannot write {} in the browser", path.display()))
}
