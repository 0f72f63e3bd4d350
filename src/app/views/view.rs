//! What a view is: the [`View`] trait every tab of the central area implements, the [`ViewContext`] it draws
//! from, and the [`Settings`] it may persist.
//!
//! A view declares what it needs and draws; the app does the rest: it joins the open view's
//! [`View::needs`] with the results panel's into the solver request ([`crate::scene::request`]), calls
//! [`View::ui`] once the result is on screen (or [`View::placeholder_ui`] before), writes the files the view
//! asks for ([`ViewContext::export`]) and saves its [`View::settings`] with eframe's storage.

use std::any::Any;

use egui::Ui;

use crate::app::document::Document;
use crate::app::frame_probe::Job;
use crate::app::pinned::PinnedResults;
use crate::app::Shown;
use crate::bearing::stages::StageId;
use crate::model::Case;
use crate::scene::compare::Pin;

/// A tab of the central area.
pub trait View: AsAny {
    /// The view's stable name: stored as the open view between sessions, and the name of its snapshot
    /// (`tests/snapshots/view_<id>.png`). Never change it once shipped.
    fn id(&self) -> &'static str;

    /// The tab's text.
    fn label(&self) -> &'static str;

    /// The solver stages whose results the view draws ([`crate::bearing::stages::StageId`]); they run, with
    /// every stage they read, while the view is open. Empty: the view draws no solver result (the results
    /// panel's solution is still solved).
    fn needs(&self) -> &'static [StageId];

    /// Draws the view. Called when the result it needs is on screen (`cx.shown` is `Some` unless
    /// [`View::needs`] is empty), otherwise [`View::placeholder_ui`] is.
    fn ui(&mut self, ui: &mut Ui, cx: &mut ViewContext<'_>);

    /// Drawn instead of [`View::ui`] while the result is missing (before the first solve).
    fn placeholder_ui(&mut self, ui: &mut Ui, _cx: &mut ViewContext<'_>) {
        waiting_ui(ui);
    }

    /// The settings the view keeps between sessions (saved as JSON under its id; an entry that no longer
    /// reads leaves the defaults). `None`: it keeps none.
    fn settings(&mut self) -> Option<&mut dyn Settings> {
        None
    }

    /// Another case was opened (a file, a dropped file, a preset, the web page's `?case=`). `same_bearing`:
    /// it has the bearing of the case before (geometry, pads, pivots, orifices), as a variant of one bearing
    /// at another load or with another physics has. Default: nothing changes.
    fn case_opened(&mut self, _same_bearing: bool) {}

    /// Work of the view's own running in the background (a sweep, a rotor analysis), if any.
    fn busy(&self) -> Option<Job> {
        None
    }

    /// Prepares the view for the UI test that snapshots every view of the list at 1280×720, and returns the
    /// case text it is shown on (`None`: the default case). Default: the view as it opens, on that case.
    fn snapshot_setup(&mut self) -> Option<&'static str> {
        None
    }
}

/// "Waiting for the first result…": the default placeholder.
pub fn waiting_ui(ui: &mut Ui) {
    ui.label("Waiting for the first result…");
}

/// Downcasting a `dyn View` to its type (the app's typed access: [`crate::app::WorkbenchApp::view_mut`]).
pub trait AsAny: Any {
    fn as_any(&self) -> &dyn Any;
    fn as_any_mut(&mut self) -> &mut dyn Any;
}

impl<T: Any> AsAny for T {
    fn as_any(&self) -> &dyn Any {
        self
    }
    fn as_any_mut(&mut self) -> &mut dyn Any {
        self
    }
}

/// A view's persisted settings: any serde type is one (stored as JSON).
pub trait Settings {
    /// The settings as JSON.
    fn to_json(&self) -> Option<String>;
    /// Reads settings written by [`Settings::to_json`]; text that does not read (an older or newer layout)
    /// leaves the settings as they are and returns `false`.
    fn read_json(&mut self, json: &str) -> bool;
}

impl<T: serde::Serialize + serde::de::DeserializeOwned> Settings for T {
    fn to_json(&self) -> Option<String> {
        serde_json::to_string(self).ok()
    }

    fn read_json(&mut self, json: &str) -> bool {
        match serde_json::from_str(json) {
            Ok(v) => {
                *self = v;
                true
            }
            Err(_) => false,
        }
    }
}

/// A file a view asks the app to write (through the save dialog or the browser's download).
#[derive(Debug, Clone, PartialEq)]
pub struct Export {
    pub name: String,
    /// What the file holds, for the dialog's filter ("CSV", "Rotor (TOML)").
    pub description: &'static str,
    pub extension: &'static str,
    pub bytes: Vec<u8>,
}

/// The name of an export of `what` from the case `doc_name`: `<case>-<what>.<ext>`.
#[must_use]
pub fn export_name(doc_name: &str, what: &str, extension: &str) -> String {
    let stem = doc_name.trim_end_matches(".toml");
    format!("{stem}-{what}.{extension}")
}

/// The edited case as a view's own analysis runs on it (the rotor and Control views put it in their machine).
#[derive(Debug, Clone)]
pub struct EditedBearing {
    /// The case as TOML (`None`: it is invalid).
    pub text: Option<String>,
    pub name: String,
    /// A value is being dragged: preview fidelity, and a running analysis finishes before the next starts.
    pub preview: bool,
    /// The document's revision.
    pub revision: u64,
    /// The case has `[hydraulics]` (a valve to close a control loop through).
    pub controllable: bool,
}

/// What a view draws from, built by the app every frame.
pub struct ViewContext<'a> {
    /// The result on screen (`None` before the first solve).
    pub shown: Option<&'a Shown>,
    /// The edited case (its text, its validation).
    pub doc: &'a Document,
    /// The shown result does not match the edited case (invalid, solving or failed).
    pub stale: bool,
    /// A value is being dragged and solves run at preview fidelity meanwhile (a view's own background work
    /// on the edited case follows suit).
    pub preview: bool,
    /// The pins, the one the views compare with, and their results ([`ViewContext::compare_with_ui`]).
    pub(crate) pins: &'a [Pin],
    pub(crate) compare_with: &'a mut Option<String>,
    pub(crate) pinned: &'a mut PinnedResults,
    pub(crate) exports: Vec<Export>,
}

impl ViewContext<'_> {
    /// The edited case, when it is valid.
    #[must_use]
    pub fn case(&self) -> Option<&Case> {
        self.doc.validation().as_ref().ok()
    }

    /// The edited case as text, when it is valid (what a sweep starts from).
    #[must_use]
    pub fn case_text(&self) -> Option<String> {
        self.doc.validation().is_ok().then(|| self.doc.text().ok()).flatten()
    }

    /// The edited case, for a view that runs its own analysis on it.
    #[must_use]
    pub fn edited_bearing(&self) -> EditedBearing {
        EditedBearing {
            text: self.case_text(),
            name: self.doc.name.clone(),
            preview: self.preview,
            revision: self.doc.revision(),
            controllable: self.case().is_some_and(|c| c.hydraulics.is_some()),
        }
    }

    /// Asks the app to write `bytes` as `<case>-<what>.<extension>`.
    pub fn export(&mut self, what: &str, description: &'static str, extension: &'static str, bytes: Vec<u8>) {
        let name = export_name(&self.doc.name, what, extension);
        self.export_as(name, description, extension, bytes);
    }

    /// Asks the app to write `bytes` under `name`.
    pub fn export_as(&mut self, name: String, description: &'static str, extension: &'static str, bytes: Vec<u8>) {
        self.exports.push(Export { name, description, extension, bytes });
    }
}
