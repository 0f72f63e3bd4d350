//! The two typed fields of the workbench's own file dialogs ([`super::open_dialog`], [`super::save_dialog`]):
//! a directory (the working directory at first, editable) and a file name, in a two-column grid, the name
//! field taking the keyboard focus when the dialog opens. Contract: the fields only hold text; the path they
//! name is [`PathFields::joined`] (`None` until a name is typed; an absolute name is taken as it is), and
//! what is read or written there is the dialog's business.

use std::path::{Path, PathBuf};

/// The directory and file-name fields of a dialog.
#[derive(Debug)]
pub struct PathFields {
    /// The directory, as typed.
    pub directory: String,
    /// The file name, as typed.
    pub name: String,
    /// The name field got the keyboard focus when the dialog opened.
    focused: bool,
}

impl PathFields {
    /// The working directory and an empty name.
    #[must_use]
    pub fn new() -> Self {
        let directory = std::env::current_dir().map(|d| d.display().to_string()).unwrap_or_default();
        Self { directory, name: String::new(), focused: false }
    }

    /// The typed directory, trimmed.
    #[must_use]
    pub fn directory(&self) -> &Path {
        Path::new(self.directory.trim())
    }

    /// The directory joined with the typed name: `None` until a name is typed.
    #[must_use]
    pub fn joined(&self) -> Option<PathBuf> {
        let name = self.name.trim();
        (!name.is_empty()).then(|| self.directory().join(name))
    }

    /// Draws the two fields in a grid `id`, `hint` greyed in the empty name; returns whether either was
    /// edited this frame.
    pub fn ui(&mut self, ui: &mut egui::Ui, id: &str, hint: &str) -> bool {
        let mut edited = false;
        egui::Grid::new(id).num_columns(2).show(ui, |ui| {
            let label = ui.label("Directory");
            edited |= ui
                .add(egui::TextEdit::singleline(&mut self.directory).desired_width(360.0))
                .labelled_by(label.id)
                .changed();
            ui.end_row();
            let label = ui.label("File name");
            let field = ui
                .add(egui::TextEdit::singleline(&mut self.name).hint_text(hint).desired_width(360.0))
                .labelled_by(label.id);
            edited |= field.changed();
            if !self.focused {
                field.request_focus();
                self.focused = true;
            }
            ui.end_row();
        });
        edited
    }
}

impl Default for PathFields {
    fn default() -> Self {
        Self::new()
    }
}

#[cfg(test)]
mod tests {
    use super::PathFields;

    #[test]
    fn the_path_is_the_directory_and_the_typed_name() {
        let mut f = PathFields { directory: " /data/cases ".into(), name: String::new(), focused: false };
        assert_eq!(f.joined(), None);
        f.name = " rig.toml ".into();
        assert_eq!(f.joined(), Some("/data/cases/rig.toml".into()));
        f.name = "/elsewhere/a.toml".into();
        assert_eq!(f.joined(), Some("/elsewhere/a.toml".into()));
    }
}
