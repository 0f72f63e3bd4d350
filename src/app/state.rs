//! What the workbench remembers between sessions (eframe storage: a file on native, local storage on
//! the web) — the case being edited, the open view, the pins and each view's own settings. Runtime state
//! (the worker, results, textures, dialogs) lives in [`super::WorkbenchApp`] and the views, never persisted.
//!
//! Storage written by an older workbench loads: keys it no longer has are ignored, keys it lacks take their
//! defaults, an open view that is no longer listed opens the first, and a view whose stored settings no
//! longer read starts from its defaults.

use std::collections::BTreeMap;

use serde::{Deserialize, Deserializer, Serialize};

/// Persisted settings and the edited case.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Persisted {
    /// The case as TOML (what the user was editing), and its display name.
    pub case_toml: Option<String>,
    pub case_name: String,
    /// Where the case was last opened from or saved to (native), and whether it was unchanged since.
    pub case_path: Option<std::path::PathBuf>,
    pub case_saved: bool,
    /// The open view, by its id ([`super::views::View::id`]; empty or no longer listed: the first view).
    #[serde(deserialize_with = "stored_view")]
    pub view: String,
    /// Solve at preview fidelity while a value is dragged, at the case's fidelity on release.
    pub preview_while_dragging: bool,
    pub editor_width: f32,
    /// Pinned reference results (Compare in the results panel).
    pub pins: Vec<crate::scene::compare::Pin>,
    /// The pin the views overlay or show beside the live result (by name; `None`: live only).
    pub compare_with: Option<String>,
    /// Each view's settings as JSON, by view id ([`super::views::View::settings`]; written on save).
    pub view_settings: BTreeMap<String, String>,
    /// The editor and results side panels are shown (each can be collapsed to give the view room).
    pub editor_open: bool,
    pub results_open: bool,
}

impl Default for Persisted {
    fn default() -> Self {
        Self {
            case_toml: None,
            case_name: String::new(),
            case_path: None,
            case_saved: false,
            view: String::new(),
            preview_while_dragging: true,
            editor_width: 360.0,
            pins: Vec::new(),
            compare_with: None,
            view_settings: BTreeMap::new(),
            editor_open: true,
            results_open: true,
        }
    }
}

/// Whether the stored view name `stored` names the view `id`. Older storage wrote the names of an enum
/// (`PadDeformation` for `pad_deformation`): case and underscores are ignored.
#[must_use]
pub fn names_view(stored: &str, id: &str) -> bool {
    let plain = |s: &str| s.chars().filter(|c| *c != '_').flat_map(char::to_lowercase).collect::<String>();
    plain(stored) == plain(id)
}

/// The open view as stored: a name, as a string or (older storage) an enum variant; anything else is no view
/// (the first opens) rather than an error that would lose the whole stored state.
fn stored_view<'de, D: Deserializer<'de>>(d: D) -> Result<String, D::Error> {
    #[derive(Deserialize)]
    #[serde(untagged)]
    enum Stored {
        Name(String),
        Other(serde::de::IgnoredAny),
    }
    Ok(match Stored::deserialize(d)? {
        Stored::Name(n) => n,
        Stored::Other(_) => String::new(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// eframe's storage, in memory, holding one RON text under the app key.
    struct Stored(String);

    impl eframe::Storage for Stored {
        fn get_string(&self, key: &str) -> Option<String> {
            (key == eframe::APP_KEY).then(|| self.0.clone())
        }
        fn set_string(&mut self, _: &str, value: String) {
            self.0 = value;
        }
        fn remove_string(&mut self, _: &str) {}
        fn flush(&mut self) {}
    }

    fn load(ron: &str) -> Option<Persisted> {
        eframe::get_value(&Stored(ron.into()), eframe::APP_KEY)
    }

    #[test]
    fn storage_of_the_enum_era_loads_with_its_case_and_view() {
        // As the workbench wrote it when the open view was an enum and the view settings sat at the top.
        let old = r#"(case_toml: Some("title = \"x\""), case_name: "x.toml", case_path: None, case_saved: true,
            view: PadDeformation, field: FilmThickness, pads: One(3), flowlines: false, axis: Speed,
            preview_while_dragging: false, editor_width: 300.0, outline_lock: None, pins: [], compare_with: None,
            field_compare: Difference, field_locks: [], sweep: (key: "operating.load_n", from: 1.0, to: 2.0,
            count: 3, outputs: [], against_sommerfeld: false, preview: true), editor_open: true, results_open: false)"#;
        let p = load(old).expect("old storage loads");
        assert_eq!(p.case_toml.as_deref(), Some("title = \"x\""));
        assert!(names_view(&p.view, "pad_deformation"), "{}", p.view);
        assert!(!p.preview_while_dragging && !p.results_open);
        assert_eq!(p.editor_width, 300.0);
    }

    #[test]
    fn an_open_view_that_does_not_read_falls_back_and_keeps_the_rest() {
        let p = load(r#"(case_name: "kept.toml", view: Gone((1, 2)))"#).expect("loads");
        assert_eq!((p.view.as_str(), p.case_name.as_str()), ("", "kept.toml"));
        // Written and read back as a string.
        let mut s = Stored(String::new());
        let p = Persisted { view: "rotor".into(), ..Persisted::default() };
        eframe::set_value(&mut s, eframe::APP_KEY, &p);
        assert_eq!(load(&s.0), Some(p));
    }
}
