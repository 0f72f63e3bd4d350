//! Cases and files: a preset over unsaved changes, a dropped file, a restart, and saving and opening
//! without a desktop portal.

use egui::accesskit::Role;
use egui_kittest::kittest::{NodeT, Queryable};
use egui_kittest::Harness;
use tiltpad::app::state::Persisted;
use tiltpad::app::views::field_view::{FieldView, PadChoice};
use tiltpad::app::WorkbenchApp;

use super::harness::{open_fields, open_preset, rotor, solved_app, spin_button, wait_for_solve};

#[test]
fn opening_a_preset_over_unsaved_changes_asks_first() {
    let mut h = solved_app(None, |_| {});
    spin_button(&h, "Load W").set_value_accesskit(2500.0);
    h.run_steps(2);
    assert!(h.state().doc.is_dirty());
    open_preset(&mut h, "test-rig.toml");
    // The guard holds the preset back until the user decides.
    h.get_by_label_contains("has changes that are not saved");
    assert_eq!(h.state().doc.name, "compressor-bearing.toml");
    h.get_by_label("Cancel").click();
    h.run_steps(2);
    assert!(h.query_by_label_contains("has changes that are not saved").is_none());
    assert_eq!(h.state().doc.file().operating.load_n, Some(2500.0));
    // Again, and discard this time.
    open_preset(&mut h, "test-rig.toml");
    h.get_by_label("Discard changes").click();
    h.run_steps(2);
    assert_eq!(h.state().doc.name, "test-rig.toml");
    assert!(!h.state().doc.is_dirty() && !h.state().doc.can_undo());
    wait_for_solve(&mut h);
    assert_eq!(h.state().shown.clone().unwrap().solution.pads.len(), 2);
}

/// A file dropped on the window, as the native integration hands it over.
#[derive(Debug)]
struct Dropped(std::path::PathBuf);

impl egui::DroppedFile for Dropped {
    fn path(&self) -> &std::path::Path {
        &self.0
    }
    fn bytes(&self) -> Result<Vec<u8>, String> {
        std::fs::read(&self.0).map_err(|e| e.to_string())
    }
}

#[test]
fn a_dropped_case_file_is_opened_and_solved() {
    let mut h = solved_app(None, |_| {});
    let path = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("cases/fillon-a.toml");
    h.input_mut().dropped_files.push(std::sync::Arc::new(Dropped(path)));
    h.run_steps(3);
    assert_eq!(h.state().doc.name, "fillon-a.toml");
    wait_for_solve(&mut h);
    let s = h.state().shown.clone().unwrap().solution;
    assert_eq!(s.pads.len(), 4);
    assert!((s.load_magnitude_n - 10_000.0).abs() < 1e-3 * 10_000.0);
}

/// eframe's storage, in memory.
#[derive(Default)]
struct MemoryStorage(std::collections::HashMap<String, String>);

impl eframe::Storage for MemoryStorage {
    fn get_string(&self, key: &str) -> Option<String> {
        self.0.get(key).cloned()
    }
    fn set_string(&mut self, key: &str, value: String) {
        self.0.insert(key.to_string(), value);
    }
    fn remove_string(&mut self, key: &str) {
        self.0.remove(key);
    }
    fn flush(&mut self) {}
}

#[test]
fn the_edited_case_and_the_view_survive_a_restart() {
    let mut h = solved_app(None, |app| open_fields(app, |f| f.pads = PadChoice::One(2)));
    spin_button(&h, "Speed").set_value_accesskit(7500.0);
    h.run_steps(2);
    let mut storage = MemoryStorage::default();
    eframe::App::save(h.state_mut(), &mut storage);
    let restored: Persisted = eframe::get_value(&storage, eframe::APP_KEY).expect("persisted state");
    assert_eq!(restored.view, "fields");
    let ctx = egui::Context::default();
    let app = WorkbenchApp::with_state(&ctx, restored);
    assert_eq!(app.open_view().label(), "Pad fields");
    assert_eq!(app.view::<FieldView>().unwrap().settings.pads, PadChoice::One(2), "the view's own settings");
    assert_eq!(app.doc.file().operating.speed_rpm, 7500.0);
    assert_eq!(app.doc.name, "compressor-bearing.toml");
    assert!(app.doc.is_dirty(), "the restored edit is still unsaved");
}

/// Without a desktop portal, an export asks for a name in the workbench's own dialog: nothing is written
/// before a name is typed, and an existing file is replaced only after the user confirms.
#[test]
fn exports_without_a_portal_ask_for_a_name_and_never_overwrite_silently() {
    let mut h = solved_app(None, |_| {});
    h.state_mut().use_workbench_save_dialog();
    let dir = std::env::temp_dir().join(format!("tiltpad-save-as-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let written = |dir: &std::path::Path| -> Vec<String> {
        let mut names: Vec<String> =
            std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
        names.sort();
        names
    };
    let export = |h: &mut Harness<'_, WorkbenchApp>| {
        h.get_by_label("File").click();
        h.run_steps(2);
        h.get_by_label("Export results as JSON…").click();
        h.run_steps(3);
        // Point the dialog at the test's directory (it opens on the working directory).
        h.get_by_role_and_label(Role::TextInput, "Directory").focus();
        h.run_steps(1);
        h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
        h.get_by_role_and_label(Role::TextInput, "Directory").type_text(&dir.display().to_string());
        h.run_steps(2);
    };
    export(&mut h);
    h.get_by_label_contains("Nothing is written until you do");
    // No name typed: Save is disabled (clicking it does nothing), and nothing is written.
    let save = h.get_by_role_and_label(Role::Button, "Save");
    assert!(save.accesskit_node().is_disabled());
    save.click();
    h.run_steps(2);
    assert!(written(&dir).is_empty());
    h.get_by_role_and_label(Role::TextInput, "File name").focus();
    h.run_steps(1);
    h.get_by_role_and_label(Role::TextInput, "File name").type_text("run1");
    h.run_steps(2);
    h.get_by_label_contains(&format!("Writes {}", dir.join("run1.json").display()));
    h.get_by_role_and_label(Role::Button, "Save").click();
    h.run_steps(3);
    assert_eq!(written(&dir), ["run1.json"]);
    let first = std::fs::read_to_string(dir.join("run1.json")).unwrap();
    assert!(first.contains("eccentricity"), "{first}");
    h.get_by_label_contains("Exported");
    // The same name again: the dialog asks; "Keep it" leaves the file as it was.
    std::fs::write(dir.join("run1.json"), "kept").unwrap();
    export(&mut h);
    h.get_by_role_and_label(Role::TextInput, "File name").focus();
    h.run_steps(1);
    h.get_by_role_and_label(Role::TextInput, "File name").type_text("run1.json");
    h.run_steps(2);
    h.get_by_role_and_label(Role::Button, "Save").click();
    h.run_steps(2);
    h.get_by_label_contains("run1.json exists. Replace it?");
    h.get_by_label("Keep it").click();
    h.run_steps(2);
    assert_eq!(std::fs::read_to_string(dir.join("run1.json")).unwrap(), "kept");
    // Save again, and replace this time.
    h.get_by_role_and_label(Role::Button, "Save").click();
    h.run_steps(2);
    h.get_by_label("Replace").click();
    h.run_steps(3);
    assert_eq!(std::fs::read_to_string(dir.join("run1.json")).unwrap(), first);
    assert_eq!(written(&dir), ["run1.json"], "no temporary file left");
    assert!(h.query_by_label("Save as").is_none(), "the dialog closed");
    std::fs::remove_dir_all(&dir).ok();
}

/// Without a desktop portal, "Open case…" and "Open rotor…" ask for the path in the workbench's own dialog
/// (as the save does): the directory's TOML files are listed to pick from; a file that cannot be read keeps
/// the dialog open with its name and leaves the case on screen; a read case replaces the edited one and a
/// read rotor opens in the Rotor view.
#[test]
fn opening_without_a_portal_asks_for_the_path_in_the_workbench() {
    let mut h = solved_app(None, |_| {});
    h.state_mut().use_workbench_save_dialog();
    let dir = std::env::temp_dir().join(format!("tiltpad-open-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("rig.toml"), include_str!("../../../cases/test-rig.toml")).unwrap();
    std::fs::write(dir.join("notes.txt"), "not listed").unwrap();
    let open = |h: &mut Harness<'_, WorkbenchApp>, item: &str| {
        h.get_by_label("File").click();
        h.run_steps(2);
        h.get_by_label(item).click();
        h.run_steps(3);
        h.get_by_role_and_label(Role::TextInput, "Directory").focus();
        h.run_steps(1);
        h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
        h.get_by_role_and_label(Role::TextInput, "Directory").type_text(&dir.display().to_string());
        h.run_steps(2);
    };
    open(&mut h, "Open case…");
    h.get_by_label("Open a case");
    h.get_by_label("TOML files in this directory (1):");
    assert!(h.query_by_label("notes.txt").is_none());
    // Nothing typed: Open is disabled.
    assert!(h.get_by_role_and_label(Role::Button, "Open").accesskit_node().is_disabled());
    // A missing file: the dialog stays with the message; the case on screen is the same.
    h.get_by_role_and_label(Role::TextInput, "File name").focus();
    h.run_steps(1);
    h.get_by_role_and_label(Role::TextInput, "File name").type_text("missing.toml");
    h.run_steps(2);
    h.get_by_role_and_label(Role::Button, "Open").click();
    h.run_steps(2);
    h.get_by_label_contains(&format!("cannot read {}", dir.join("missing.toml").display()));
    assert_eq!(h.state().doc.name, "compressor-bearing.toml");
    // Pick the listed file and open it.
    h.get_by_label("rig.toml").click();
    h.run_steps(2);
    h.get_by_role_and_label(Role::Button, "Open").click();
    h.run_steps(3);
    assert!(h.query_by_label("Open a case").is_none(), "the dialog closed");
    assert_eq!(h.state().doc.name, "rig.toml");
    assert_eq!(h.state().doc.path.as_deref(), Some(std::fs::canonicalize(dir.join("rig.toml")).unwrap().as_path()));
    // A rotor: typed as a full path (the directory field is ignored for an absolute name).
    let rotor_path = std::fs::canonicalize("cases/rotors/compressor-rotor.toml").unwrap();
    open(&mut h, "Open rotor…");
    h.get_by_label("Open a rotor");
    h.get_by_role_and_label(Role::TextInput, "File name").focus();
    h.run_steps(1);
    h.get_by_role_and_label(Role::TextInput, "File name").type_text(&rotor_path.display().to_string());
    h.run_steps(2);
    h.key_press(egui::Key::Enter);
    h.run_steps(3);
    assert_eq!(h.state().open_view().id(), "rotor");
    assert_eq!(h.state().notice.as_deref(), Some(format!("Opened rotor {}", rotor_path.display()).as_str()));
    assert_eq!(rotor(&h).preset, tiltpad::app::views::rotor_view::ROTOR_PRESETS.len());
    std::fs::remove_dir_all(&dir).ok();
}
