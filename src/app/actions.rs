//! What the workbench does beyond drawing: actions that replace the case (behind the unsaved-changes
//! guard), saving, keyboard shortcuts, file events from dialogs and drops, and the PNG export of the view.

use egui::{Key, KeyboardShortcut, Modifiers};

use super::files::{encode_png, FileEvent};
use super::open_dialog::{OpenDialog, OpenOutcome};
use super::presets::PRESETS;
use super::save_dialog::{SaveDialog, SaveOutcome};
use super::views::rotor_view::RotorView;
use super::{Pending, WorkbenchApp};

const UNDO: KeyboardShortcut = KeyboardShortcut::new(Modifiers::COMMAND, Key::Z);
const REDO: KeyboardShortcut = KeyboardShortcut::new(Modifiers::COMMAND.plus(Modifiers::SHIFT), Key::Z);
const REDO_Y: KeyboardShortcut = KeyboardShortcut::new(Modifiers::COMMAND, Key::Y);
const SAVE: KeyboardShortcut = KeyboardShortcut::new(Modifiers::COMMAND, Key::S);
const OPEN: KeyboardShortcut = KeyboardShortcut::new(Modifiers::COMMAND, Key::O);

impl WorkbenchApp {
    pub(super) fn export_name(&self, what: &str, ext: &str) -> String {
        super::views::view::export_name(&self.doc.name, what, ext)
    }

    /// Runs an action that replaces the case, asking first when there are unsaved changes.
    pub(super) fn request(&mut self, action: Pending) {
        if self.doc.is_dirty() {
            self.pending = Some(action);
        } else {
            self.perform(action);
        }
    }

    pub(super) fn perform(&mut self, action: Pending) {
        match action {
            Pending::Preset(k) => {
                if let Some((name, text)) = PRESETS.get(k) {
                    self.load_text(name, None, text);
                }
            }
            Pending::Open => self.files.open_case(),
            Pending::Replace { name, path, text } => self.load_text(&name, path, &text),
            Pending::Close => self.allow_close = true,
        }
    }

    pub(super) fn guard_ui(&mut self, ctx: &egui::Context) {
        let Some(action) = self.pending.clone() else { return };
        let modal = egui::Modal::new(egui::Id::unique("unsaved")).show(ctx, |ui| {
            ui.heading("Unsaved changes");
            ui.label(format!("{} has changes that are not saved. Discard them?", self.doc.name));
            ui.horizontal(|ui| {
                if ui.button("Discard changes").clicked() {
                    self.pending = None;
                    let close = matches!(action, Pending::Close);
                    self.perform(action.clone());
                    if close {
                        ctx.send_viewport_cmd(egui::ViewportCommand::Close);
                    }
                }
                if ui.button("Cancel").clicked() {
                    self.pending = None;
                }
            });
        });
        if modal.should_close() {
            self.pending = None;
        }
    }

    pub(super) fn guard_close(&mut self, ctx: &egui::Context) {
        if ctx.input(|i| i.viewport().close_requested()) && self.doc.is_dirty() && !self.allow_close {
            ctx.send_viewport_cmd(egui::ViewportCommand::CancelClose);
            self.pending = Some(Pending::Close);
        }
    }

    pub(super) fn save_case(&mut self, ask: bool) {
        let path = if ask { None } else { self.doc.path.clone() };
        let name =
            if self.doc.name.ends_with(".toml") { self.doc.name.clone() } else { format!("{}.toml", self.doc.name) };
        self.files.save_case(self.doc.text(), self.doc.file(), &name, path.as_deref());
    }

    pub(super) fn take_shortcuts(&mut self, ctx: &egui::Context) {
        let (undo, redo, save, open) = ctx.input_mut(|i| {
            (
                i.consume_shortcut(&UNDO),
                i.consume_shortcut(&REDO) || i.consume_shortcut(&REDO_Y),
                i.consume_shortcut(&SAVE),
                i.consume_shortcut(&OPEN),
            )
        });
        if undo {
            self.doc.undo();
        }
        if redo {
            self.doc.redo();
        }
        if save {
            self.save_case(false);
        }
        if open {
            self.request(Pending::Open);
        }
    }

    pub(super) fn take_file_events(&mut self) {
        for e in self.files.poll() {
            self.file_event(e);
        }
    }

    fn file_event(&mut self, e: FileEvent) {
        match e {
            FileEvent::Opened { name, path, text } => self.request(Pending::Replace { name, path, text }),
            FileEvent::OpenedRotor { name, path, text } => {
                if let Some(rotor) = self.view_mut::<RotorView>() {
                    rotor.open_file(&name, Some(&path), &text);
                }
                self.open::<RotorView>();
                self.say(format!("Opened rotor {}", path.display()));
            }
            FileEvent::SavedCase { name, path, saved, text } => {
                self.say(format!("Saved {}", path.as_ref().map_or(name.clone(), |p| p.display().to_string())));
                if *saved == *self.doc.file() {
                    self.doc.mark_saved(name, path, text);
                }
            }
            FileEvent::Exported { name, path } => {
                self.say(format!("Exported {}", path.map_or(name, |p| p.display().to_string())));
            }
            FileEvent::NameNeeded(pending) => self.save_dialog = Some(SaveDialog::new(*pending)),
            FileEvent::PathNeeded(kind) => self.open_dialog = Some(OpenDialog::new(kind)),
            FileEvent::Error(e) => self.say(e),
        }
    }

    /// The workbench's own "Save as" dialog, while one is open.
    pub(super) fn save_dialog_ui(&mut self, ctx: &egui::Context) {
        let Some(dialog) = &mut self.save_dialog else { return };
        match dialog.ui(ctx) {
            SaveOutcome::Open => {}
            SaveOutcome::Cancelled => {
                self.save_dialog = None;
                self.say("Not saved".into());
            }
            SaveOutcome::Done(event) => {
                self.save_dialog = None;
                self.file_event(event);
            }
        }
    }

    /// The workbench's own "Open" dialog, while one is open.
    pub(super) fn open_dialog_ui(&mut self, ctx: &egui::Context) {
        let Some(dialog) = &mut self.open_dialog else { return };
        match dialog.ui(ctx) {
            OpenOutcome::Open => {}
            OpenOutcome::Cancelled => self.open_dialog = None,
            OpenOutcome::Done(event) => {
                self.open_dialog = None;
                self.file_event(event);
            }
        }
    }

    pub(super) fn take_dropped_files(&mut self, ctx: &egui::Context) {
        let dropped = ctx.input(|i| i.raw.dropped_files.clone());
        if let Some(f) = dropped.into_iter().next() {
            self.files.read_dropped(f);
        }
    }

    pub(super) fn screenshot_callback(&mut self, ctx: &egui::Context) -> egui::ScreenshotCallback {
        let (tx, rx) = std::sync::mpsc::channel();
        self.screenshot = Some(rx);
        let ctx = ctx.clone();
        egui::ScreenshotCallback::new(move |image| {
            let _ = tx.send(image);
            ctx.request_repaint();
        })
    }

    pub(super) fn take_screenshot(&mut self, ctx: &egui::Context) {
        let Some(image) = self.screenshot.as_ref().and_then(|rx| rx.try_recv().ok()) else { return };
        self.screenshot = None;
        let ppp = ctx.pixels_per_point();
        #[allow(clippy::cast_precision_loss)]
        let whole =
            egui::Rect::from_min_size(egui::Pos2::ZERO, egui::vec2(image.width() as f32, image.height() as f32) / ppp);
        let region = self.view_rect.map_or(whole, |r| r.intersect(whole));
        let cropped = if region.is_positive() { image.region(&region, Some(ppp)) } else { (*image).clone() };
        let rgba: Vec<u8> = cropped.pixels.iter().flat_map(|c| c.to_array()).collect();
        match encode_png(cropped.width(), cropped.height(), &rgba) {
            Ok(bytes) => {
                let name = self.export_name(&self.open_view().label().to_lowercase().replace(' ', "-"), "png");
                self.files.export(&name, "PNG image", "png", bytes);
            }
            Err(e) => self.say(format!("PNG export failed: {e}")),
        }
    }
}
