//! What the file dialogs and the workbench tell each other: the outcome of a dialog ([`FileEvent`]), what
//! the workbench's own dialogs open ([`OpenKind`]) and a save waiting for a name ([`PendingSave`]). Shared
//! by the dialog runner ([`super::files`]) and the workbench's own dialogs ([`super::open_dialog`],
//! [`super::save_dialog`]), which otherwise do not know each other.

use std::path::PathBuf;

/// What came back from a dialog.
#[derive(Debug)]
pub enum FileEvent {
    /// A case file was read: display name, path (native), text.
    Opened {
        name: String,
        path: Option<std::path::PathBuf>,
        text: String,
    },
    /// A rotor file was read (native): display name, path (its bearing cases are beside it), text.
    OpenedRotor {
        name: String,
        path: std::path::PathBuf,
        text: String,
    },
    /// The case was saved under this name (and path, on native) as `text`.
    SavedCase {
        name: String,
        path: Option<std::path::PathBuf>,
        saved: Box<crate::model::CaseFile>,
        text: String,
    },
    /// An export was written (to `path`, when known).
    Exported {
        name: String,
        path: Option<std::path::PathBuf>,
    },
    /// No native dialog: the workbench asks for a name itself ([`super::save_dialog`]).
    NameNeeded(Box<PendingSave>),
    /// No native dialog: the workbench asks for the path of a file to open ([`super::open_dialog`]).
    PathNeeded(OpenKind),
    Error(String),
}

/// What to report once a save was written: display name and path → event.
pub type SaveDone = Box<dyn FnOnce(String, Option<PathBuf>) -> FileEvent + Send>;

/// A save waiting for a name.
pub struct PendingSave {
    /// The name the dialog proposes (shown as a hint, never used unless typed).
    pub suggested: String,
    /// Added to a typed name without an extension.
    pub extension: String,
    pub bytes: Vec<u8>,
    pub done: SaveDone,
}

impl std::fmt::Debug for PendingSave {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("PendingSave")
            .field("suggested", &self.suggested)
            .field("bytes", &self.bytes.len())
            .finish_non_exhaustive()
    }
}

/// What the dialog opens.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OpenKind {
    /// A case file: it replaces the edited case (after the unsaved-changes guard).
    Case,
    /// A rotor file: shown in the Rotor view, its bearing cases read from beside it.
    Rotor,
}

impl OpenKind {
    pub(crate) fn title(self) -> &'static str {
        match self {
            Self::Case => "Open a case",
            Self::Rotor => "Open a rotor",
        }
    }
}

/// File name for display.
#[must_use]
pub fn display_name(path: &std::path::Path) -> String {
    path.file_name().map_or_else(|| path.display().to_string(), |n| n.to_string_lossy().into_owned())
}
