//! The case being edited: the [`CaseFile`] (persisted, engineering units), its validation, where it
//! came from, whether it has unsaved changes, and undo/redo.
//!
//! The document keeps the text it was opened from: [`Document::text`] writes the edited values into that
//! text ([`CaseFile::to_toml_preserving`]), so a save keeps the user's comments, order and units and
//! changes only the values that were edited.
//!
//! Every change of the document — an edit, an undo or redo, another case opened — gives it a new
//! [`Document::revision`]. Results carry the revision they were computed from, so a view can tell a result
//! of the design on screen from one of an earlier design (and say so, or recompute), never mixing the two.
//!
//! Undo works on whole `CaseFile` snapshots (a case is a few hundred bytes). Continuous edits of one field
//! (dragging a value) form one undo step: an edit that continues the previous edit of the same key does
//! not push a new snapshot.

use crate::model::{Case, CaseError, CaseFile};

/// Most undo steps kept.
const MAX_UNDO: usize = 200;

/// The edited case.
pub struct Document {
    file: CaseFile,
    /// Display name: the file name, or the preset's name.
    pub name: String,
    /// Where it is saved on disk (native), if anywhere.
    pub path: Option<std::path::PathBuf>,
    /// The file as last saved or opened, to tell unsaved changes.
    saved: Option<CaseFile>,
    undo: Vec<CaseFile>,
    redo: Vec<CaseFile>,
    last_key: Option<String>,
    validation: Result<Case, CaseError>,
    /// The TOML text the case was opened from or last saved as.
    source: Option<String>,
    /// Counts changes (never repeats: an undo is a new revision too).
    revision: u64,
}

impl Document {
    /// A document from a case file; `saved` says whether it matches a file on disk (or a shipped preset).
    #[must_use]
    pub fn new(file: CaseFile, name: impl Into<String>, saved: bool) -> Self {
        let validation = file.resolve();
        Self {
            saved: saved.then(|| file.clone()),
            file,
            name: name.into(),
            path: None,
            undo: Vec::new(),
            redo: Vec::new(),
            last_key: None,
            validation,
            source: None,
            revision: 0,
        }
    }

    /// The revision of the edited design: a new one after every change.
    #[must_use]
    pub fn revision(&self) -> u64 {
        self.revision
    }

    /// The document with the text its case was read from (kept for comment-preserving saves).
    #[must_use]
    pub fn with_source(mut self, text: impl Into<String>) -> Self {
        self.source = Some(text.into());
        self
    }

    /// The case as TOML: the source text with the edited values written into it (comments, order and
    /// units kept), or a fresh file when there is no source.
    ///
    /// # Errors
    /// A value TOML cannot hold (non-finite numbers).
    pub fn text(&self) -> Result<String, CaseError> {
        match &self.source {
            Some(src) => self.file.to_toml_preserving(src).or_else(|_| self.file.to_toml()),
            None => self.file.to_toml(),
        }
    }

    #[must_use]
    pub fn file(&self) -> &CaseFile {
        &self.file
    }

    /// The validated SI case, or the first problem found.
    pub fn validation(&self) -> &Result<Case, CaseError> {
        &self.validation
    }

    /// The validation error, if it concerns `key` or one of its elements (`bearing.pads.pivot_deg[2]`
    /// concerns `bearing.pads.pivot_deg`).
    #[must_use]
    pub fn error_for(&self, key: &str) -> Option<&CaseError> {
        let e = self.validation.as_ref().err()?;
        let k = e.key()?;
        let concerns =
            k == key || k.strip_prefix(key).is_some_and(|rest| rest.starts_with('[') || rest.starts_with('.'));
        concerns.then_some(e)
    }

    /// Applies an edit of `key`. `continuing` marks a continuous gesture (a drag) on the same key: it joins
    /// the previous undo step instead of starting one.
    pub fn edit(&mut self, key: &str, continuing: bool, f: impl FnOnce(&mut CaseFile)) {
        let before = self.file.clone();
        f(&mut self.file);
        if self.file == before {
            return;
        }
        let joins = continuing && self.last_key.as_deref() == Some(key);
        if !joins {
            self.undo.push(before);
            if self.undo.len() > MAX_UNDO {
                self.undo.remove(0);
            }
        }
        self.last_key = Some(key.to_string());
        self.redo.clear();
        self.revalidate();
    }

    /// Replaces the whole case (opening a file or a preset): a fresh history.
    pub fn replace(&mut self, file: CaseFile, name: impl Into<String>, path: Option<std::path::PathBuf>, source: &str) {
        let revision = self.revision + 1;
        *self = Self { path, revision, ..Self::new(file, name, true).with_source(source) };
    }

    /// Ends a continuous gesture, so the next edit of the same key is a new undo step.
    pub fn end_gesture(&mut self) {
        self.last_key = None;
    }

    pub fn undo(&mut self) -> bool {
        let Some(prev) = self.undo.pop() else { return false };
        self.redo.push(std::mem::replace(&mut self.file, prev));
        self.last_key = None;
        self.revalidate();
        true
    }

    pub fn redo(&mut self) -> bool {
        let Some(next) = self.redo.pop() else { return false };
        self.undo.push(std::mem::replace(&mut self.file, next));
        self.last_key = None;
        self.revalidate();
        true
    }

    #[must_use]
    pub fn can_undo(&self) -> bool {
        !self.undo.is_empty()
    }

    #[must_use]
    pub fn can_redo(&self) -> bool {
        !self.redo.is_empty()
    }

    /// Unsaved changes: differs from the file last opened or saved.
    #[must_use]
    pub fn is_dirty(&self) -> bool {
        self.saved.as_ref() != Some(&self.file)
    }

    /// Records that the current case was saved as `text`.
    pub fn mark_saved(&mut self, name: impl Into<String>, path: Option<std::path::PathBuf>, text: String) {
        self.saved = Some(self.file.clone());
        self.source = Some(text);
        self.name = name.into();
        if path.is_some() {
            self.path = path;
        }
    }

    fn revalidate(&mut self) {
        self.revision += 1;
        self.validation = self.file.resolve();
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::parse_case_file;

    fn doc() -> Document {
        let file = parse_case_file(include_str!("../../cases/compressor-bearing.toml"), &[]).unwrap();
        Document::new(file, "compressor", true).with_source(include_str!("../../cases/compressor-bearing.toml"))
    }

    #[test]
    fn the_saved_text_keeps_the_source_comments() {
        let mut d = doc();
        d.edit("operating.speed_rpm", false, |f| f.operating.speed_rpm = 8000.0);
        let text = d.text().unwrap();
        assert!(text.starts_with("# Industrial gas-compressor bearing"), "{text}");
        assert!(text.contains("speed_rpm = 8000.0\n"), "{text}");
        // Without a source the case is written fresh.
        let fresh = Document::new(d.file().clone(), "x", false).text().unwrap();
        assert!(!fresh.contains('#') && fresh.contains("speed_rpm = 8000.0"));
    }

    #[test]
    fn edits_undo_redo_and_dirty_state() {
        let mut d = doc();
        assert!(!d.is_dirty() && !d.can_undo());
        let r0 = d.revision();
        d.edit("operating.speed_rpm", false, |f| f.operating.speed_rpm = 8000.0);
        // An edit that changes nothing is no new revision; every change is.
        let r1 = d.revision();
        d.edit("operating.speed_rpm", true, |f| f.operating.speed_rpm = 8000.0);
        assert!(r1 > r0 && d.revision() == r1);
        // A drag on the same key joins the step; a new key starts one.
        d.edit("operating.speed_rpm", true, |f| f.operating.speed_rpm = 8100.0);
        d.edit("operating.load_n", false, |f| f.operating.load_n = Some(2500.0));
        assert!(d.is_dirty());
        assert!(d.undo());
        assert_eq!(d.file().operating.load_n, Some(1918.0));
        assert_eq!(d.file().operating.speed_rpm, 8100.0);
        assert!(d.undo());
        assert_eq!(d.file().operating.speed_rpm, 9000.0);
        assert!(!d.is_dirty() && !d.undo());
        let before_redo = d.revision();
        assert!(d.redo() && d.redo() && !d.redo());
        assert_eq!(d.file().operating.load_n, Some(2500.0));
        assert_eq!(d.revision(), before_redo + 2, "an undo or a redo is a new revision");
        let before_open = d.revision();
        d.replace(d.file().clone(), "again", None, "");
        assert!(d.revision() > before_open, "opening a case is a new revision");
        d.mark_saved("x.toml", None, String::new());
        assert!(!d.is_dirty());
    }

    #[test]
    fn invalid_values_are_flagged_on_their_key() {
        let mut d = doc();
        d.edit("bearing.length_mm", false, |f| f.bearing.length_mm = -3.0);
        assert!(d.validation().is_err());
        assert!(d.error_for("bearing.length_mm").is_some());
        assert!(d.error_for("bearing.length").is_none());
        assert!(d.error_for("operating.speed_rpm").is_none());
        d.edit("bearing.pads.pivot_deg", false, |f| {
            f.bearing.length_mm = 44.45;
            f.bearing.pads.pivot_deg =
                Some(crate::model::file::OneOrMany::Many(vec![60.0, 132.0, 204.0, 276.0, f64::NAN]));
        });
        assert!(d.error_for("bearing.pads.pivot_deg").is_some(), "{:?}", d.validation());
    }
}
