//! One frame of the workbench: the menu bar, the panels, the status bar and the central view.

use egui::{Color32, RichText, Ui};

use super::editor::editor_ui;
use super::ink;
use super::presets::PRESETS;
use super::views::{compare_panel, limits_view, results_panel, ViewContext};
use super::{Pending, ShownFor, Status, WorkbenchApp};
use crate::scene::{export, summary};
use crate::units::MS;

#[cfg(not(target_arch = "wasm32"))]
const FRAME_TIME_MEANING: &str = "Time to build a frame on the UI thread; the solver runs on its own thread.";
#[cfg(target_arch = "wasm32")]
const FRAME_TIME_MEANING: &str = "Time to build a frame, including the solver steps run in it (the browser has no threads here): one solver stage may take longer than the per-frame budget.";

/// The largest share of the window's width the editor takes (its rows need about 440 points).
const EDITOR_MAX: f32 = 0.36;
/// The smallest and largest share of the window's width the results panel takes: its tables scroll
/// sideways inside it rather than widening it.
const RESULTS_RANGE: [f32; 2] = [0.25, 0.3];

/// The menu at the end of the tab row that holds the views whose tabs do not fit.
const MORE_TABS: &str = "More…";

/// The width a tab (a selectable label) of `label` takes in the row, with the spacing after it.
fn tab_width(ui: &Ui, label: &str) -> f32 {
    let text = ui.ctx().fonts_mut(|f| {
        f.layout_no_wrap(label.to_string(), egui::TextStyle::Button.resolve(ui.style()), Color32::WHITE).size().x
    });
    text + 2.0 * ui.spacing().button_padding.x + ui.spacing().item_spacing.x
}

/// The text of the "More" menu's button: its name, or the open view's label when that view is in the menu
/// (the button then reads as that view's tab, highlighted, and still opens the menu).
fn more_text(open_label: Option<&str>) -> String {
    open_label.map_or_else(|| MORE_TABS.to_string(), str::to_string)
}

/// The tabs shown in a row of `room` points, in list order: all when they fit; else as many from the first
/// as fit beside the "More" menu, whose button takes `more(hidden)` points for the tabs it then holds (at
/// its widest: it names the open view when that view is one of them). The row does not depend on which
/// view is open, so opening a view from the menu moves no tab.
#[must_use]
pub fn tabs_that_fit(widths: &[f32], room: f32, more: impl Fn(std::ops::Range<usize>) -> f32) -> Vec<usize> {
    if widths.iter().sum::<f32>() <= room {
        return (0..widths.len()).collect();
    }
    let n =
        (0..widths.len()).rev().find(|&n| widths[..n].iter().sum::<f32>() + more(n..widths.len()) <= room).unwrap_or(0);
    (0..n).collect()
}

impl WorkbenchApp {
    pub(super) fn frame_ui(&mut self, ui: &mut Ui) {
        let ctx = ui.ctx().clone();
        self.take_file_events();
        self.take_dropped_files(&ctx);
        self.take_shortcuts(&ctx);
        self.guard_close(&ctx);
        self.take_screenshot(&ctx);

        let t0 = web_time::Instant::now();
        egui::Panel::top("menu").show(ui, |ui| self.menu_ui(ui));
        self.forget_stale_notice();
        egui::Panel::bottom("status").show(ui, |ui| self.status_ui(ui));
        // On windows narrower than ~1330 points the side panels start narrower, so the view keeps about half
        // the width; each can also be collapsed (menu bar) or dragged closed, and neither can be dragged (or
        // pushed by a wide table) past about a third of the window: the view keeps at least a third.
        let width = ctx.content_rect().width();
        let doc = &mut self.doc;
        let edit = egui::Panel::left("editor")
            .resizable(true)
            .max_size(EDITOR_MAX * width)
            .default_size(self.persisted.editor_width.min(0.27 * width))
            .show_collapsible(ui, &mut self.persisted.editor_open, |ui| {
                egui::ScrollArea::vertical().id_salt("editor-scroll").show(ui, |ui| editor_ui(ui, doc)).inner
            })
            .map(|r| r.inner);
        self.dragging = edit.is_some_and(|e| e.dragging);
        let t1 = web_time::Instant::now();
        let mut results_open = self.persisted.results_open;
        egui::Panel::right("results")
            .resizable(true)
            .size_range(RESULTS_RANGE[0] * width..=RESULTS_RANGE[1] * width)
            // Its widest by default: the comparison of a pin needs the room (the view keeps > 40 %).
            .default_size(RESULTS_RANGE[1] * width)
            .show_collapsible(ui, &mut results_open, |ui| self.results_ui(ui));
        self.persisted.results_open = results_open;
        let t2 = web_time::Instant::now();
        egui::CentralPanel::default_margins().show(ui, |ui| self.central_ui(ui));
        let t3 = web_time::Instant::now();
        self.guard_ui(&ctx);
        self.save_dialog_ui(&ctx);
        self.open_dialog_ui(&ctx);
        if ctx.input(|i| !i.raw.hovered_files.is_empty()) {
            let screen = ctx.content_rect();
            ctx.layer_painter(egui::LayerId::new(egui::Order::Foreground, egui::Id::unique("drop"))).text(
                screen.center(),
                egui::Align2::CENTER_CENTER,
                "Drop a case file (.toml) to open it",
                egui::FontId::proportional(24.0),
                Color32::WHITE,
            );
        }
        self.drive_solver();
        let t4 = web_time::Instant::now();
        let ms = |a: web_time::Instant, b: web_time::Instant| MS.from_si((b - a).as_secs_f64());
        self.frame_parts_ms = [ms(t0, t1), ms(t1, t2), ms(t2, t3), ms(t3, t4)];
        if !self.is_idle() {
            ctx.request_repaint_after(std::time::Duration::from_millis(100));
        }
    }

    fn menu_ui(&mut self, ui: &mut Ui) {
        egui::MenuBar::new().ui(ui, |ui| {
            ui.menu_button("File", |ui| {
                if ui.button("Open case…").clicked() {
                    self.request(Pending::Open);
                }
                #[cfg(not(target_arch = "wasm32"))]
                if ui.button("Open rotor…").on_hover_text("A rotor file (TOML) with its bearing cases beside it; shown in the Rotor view.").clicked() {
                    self.files.open_rotor();
                }
                ui.menu_button("Open preset", |ui| {
                    for (k, (name, _)) in PRESETS.iter().enumerate() {
                        if ui.button(*name).clicked() {
                            self.request(Pending::Preset(k));
                        }
                    }
                });
                if ui.button("Save case").clicked() {
                    self.save_case(false);
                }
                if ui.button("Save case as…").clicked() {
                    self.save_case(true);
                }
                ui.separator();
                if ui.button("Export view as PNG…").clicked() {
                    ui.ctx().send_viewport_cmd(egui::ViewportCommand::Screenshot(self.screenshot_callback(ui.ctx())));
                }
                let solution = self.shown.as_ref().map(|s| s.solution.clone());
                if ui.add_enabled(solution.is_some(), egui::Button::new("Export fields as CSV…")).clicked() {
                    if let Some(s) = &solution {
                        self.files.export(&self.export_name("fields", "csv"), "CSV", "csv", export::fields_csv(s).into_bytes());
                    }
                }
                if ui.add_enabled(solution.is_some(), egui::Button::new("Export results as JSON…")).clicked() {
                    if let Some(s) = &solution {
                        self.files.export(&self.export_name("results", "json"), "JSON", "json", export::results_json(s, &self.persisted.pins).into_bytes());
                    }
                }
                if ui.add_enabled(solution.is_some(), egui::Button::new("Export results as CSV…")).on_hover_text("One row per result: the live one, then each pinned one, every output column.").clicked() {
                    if let Some(s) = &solution {
                        self.files.export(&self.export_name("results", "csv"), "CSV", "csv", export::results_csv(s, &self.persisted.pins).into_bytes());
                    }
                }
                if ui.add_enabled(solution.is_some(), egui::Button::new("Export film fields for ParaView (VTU)…")).on_hover_text("Pressure, film thickness, temperatures and the mean film velocity on the 3-D pad surfaces, as a VTK unstructured grid.").clicked() {
                    if let Some(s) = &solution {
                        self.files.export(&self.export_name("film", "vtu"), "VTK unstructured grid", "vtu", crate::io::vtk::film_grid(s).to_vtu().into_bytes());
                    }
                }
                let pads = solution.as_ref().and_then(|s| crate::io::vtk::pad_solid_grid(s));
                if ui.add_enabled(pads.is_some(), egui::Button::new("Export pad temperatures for ParaView (VTU)…")).on_hover_text("The pads' 3-D temperature field (thermal model), as a VTK unstructured grid.").clicked() {
                    if let Some(g) = &pads {
                        self.files.export(&self.export_name("pads", "vtu"), "VTK unstructured grid", "vtu", g.to_vtu().into_bytes());
                    }
                }
            });
            ui.menu_button("Edit", |ui| {
                if ui.add_enabled(self.doc.can_undo(), egui::Button::new("Undo")).clicked() {
                    self.doc.undo();
                }
                if ui.add_enabled(self.doc.can_redo(), egui::Button::new("Redo")).clicked() {
                    self.doc.redo();
                }
                ui.checkbox(&mut self.persisted.preview_while_dragging, "Preview fidelity while dragging")
                    .on_hover_text("Solve on the coarse preview mesh while a value is dragged, at the case's fidelity on release.");
                ui.separator();
                theme_ui(ui);
            });
            ui.separator();
            if ui.add_enabled(self.doc.can_undo(), egui::Button::new("Undo")).on_hover_text("Undo (Ctrl+Z)").clicked() {
                self.doc.undo();
            }
            if ui.add_enabled(self.doc.can_redo(), egui::Button::new("Redo")).on_hover_text("Redo (Ctrl+Shift+Z)").clicked() {
                self.doc.redo();
            }
            ui.separator();
            ui.toggle_value(&mut self.persisted.editor_open, "Show editor").on_hover_text("Show or hide the editor panel (the view gets its room).");
            ui.toggle_value(&mut self.persisted.results_open, "Show results").on_hover_text("Show or hide the results panel (the view gets its room).");
            ui.separator();
            let dirty = if self.doc.is_dirty() { " *" } else { "" };
            ui.label(RichText::new(format!("{}{dirty}", self.doc.name)).strong()).on_hover_text("Case file (* = unsaved changes)");
        });
    }

    fn status_ui(&mut self, ui: &mut Ui) {
        let timing = (!self.hide_timings).then(|| {
            let peak = self.recent_frames_s.iter().copied().fold(0.0, f64::max);
            RichText::new(format!(
                "UI {:.1} ms/frame (slowest of the last 120: {:.1} ms)",
                MS.from_si(self.frame_time_s),
                MS.from_si(peak)
            ))
            .weak()
        });
        // The frame time keeps its room at the right: a long message (a failed solve names its cause) is
        // cut with "…" (whole on hover) rather than written under it.
        let timing_width = timing.as_ref().map_or(0.0, |t| {
            egui::WidgetText::from(t.clone())
                .into_galley(ui, Some(egui::TextWrapMode::Extend), f32::INFINITY, egui::TextStyle::Body)
                .size()
                .x
                + 2.0 * ui.spacing().item_spacing.x
        });
        let cut = |ui: &mut Ui, text: RichText| {
            let full = text.text().to_string();
            let room = (ui.max_rect().right() - timing_width - ui.cursor().min.x).max(40.0);
            ui.scope(|ui| {
                ui.set_max_width(room);
                ui.add(egui::Label::new(text).truncate()).on_hover_text(full);
            });
        };
        ui.horizontal(|ui| {
            // One state at a time, and what the drawing shows: an invalid case is not solved, whatever result
            // is still on screen; "Solved" only over a result of the edited case.
            let invalid = self.doc.validation().is_err();
            let shown_for = self.shown_for();
            let drawn = match shown_for {
                ShownFor::Previous => " (showing the previous result)",
                ShownFor::EditedPreview => " (showing the preview-mesh result)",
                ShownFor::Edited | ShownFor::Nothing => "",
            };
            match &self.status {
                Status::Idle if invalid => {
                    ui.label(RichText::new("Not solved").color(ui.visuals().warn_fg_color))
                        .on_hover_text("The edited case is invalid; the views show the last valid result.");
                }
                Status::Idle if shown_for == ShownFor::Edited => {
                    ui.label(RichText::new("Solved").color(ink::GOOD.of(ui)));
                }
                Status::Idle if shown_for == ShownFor::EditedPreview => {
                    ui.label(RichText::new("Solved on the preview mesh").color(ink::GOOD.of(ui)))
                        .on_hover_text("Solved on the coarse preview mesh while the value is dragged; the case's own mesh follows on release.");
                }
                // The result of an older value, its successor not yet submitted (a drag's next value).
                Status::Idle => {
                    ui.spinner();
                    ui.label(format!("Solving: starting…{drawn}"));
                }
                Status::Solving { stage, fraction } => {
                    ui.spinner();
                    // The stage worked on last, and how far it got.
                    let now = match stage {
                        None => "starting".to_string(),
                        Some(s) if *fraction < 1.0 => format!("{} {:.0} %", s.label(), 100.0 * fraction),
                        Some(s) => format!("{} done", s.label()),
                    };
                    ui.label(format!("Solving: {now}…{drawn}"));
                }
                Status::Failed(e) => cut(ui, RichText::new(format!("Solve failed: {e}")).color(ink::ERROR.of(ui))),
            }
            if let Err(e) = self.doc.validation() {
                ui.separator();
                cut(ui, RichText::new(format!("Invalid case: {e}")).color(ink::ERROR.of(ui)));
            }
            if let Some(n) = &self.notice {
                ui.separator();
                cut(ui, RichText::new(n));
            }
            ui.with_layout(egui::Layout::right_to_left(egui::Align::Center), |ui| {
                if let Some(t) = timing {
                    ui.label(t).on_hover_text(FRAME_TIME_MEANING);
                }
            });
        });
    }

    fn results_ui(&mut self, ui: &mut Ui) {
        ui.heading("Results");
        let Some(shown) = &self.shown else {
            ui.label("No result yet.");
            return;
        };
        if self.result_is_stale() {
            ui.label(
                RichText::new("Showing the last valid result: it does not match the edited case.")
                    .color(ink::WARNING.of(ui)),
            );
        }
        let fidelity = format!("{:?}", shown.solution.inputs.mesh.fidelity).to_lowercase();
        ui.label(RichText::new(format!("{} — {fidelity} mesh", shown.solution.title)).small());
        let s = summary::summary(&shown.solution);
        limits_view::limits_ui(
            ui,
            &crate::bearing::solution::limits::check(&shown.solution.inputs.limits, &shown.solution),
        );
        let (solution, text) = (shown.solution.clone(), self.doc.text().ok());
        let pins = &mut self.persisted.pins;
        // Both ways: a wide comparison table scrolls inside the panel rather than widening it.
        let action = egui::ScrollArea::both()
            .id_salt("results-scroll")
            .show(ui, |ui| {
                let action = compare_panel::compare_ui(ui, pins, &solution, text.as_deref());
                results_panel::results_panel_ui(ui, &s, self.hide_timings);
                action
            })
            .inner;
        match action {
            Some(compare_panel::CompareAction::ExportCsv(csv)) => {
                self.files.export(&self.export_name("pins", "csv"), "CSV", "csv", csv.into_bytes())
            }
            Some(compare_panel::CompareAction::Pinned) => self.pinned_now(),
            None => {}
        }
    }

    /// The tabs of the views, and the open one.
    fn central_ui(&mut self, ui: &mut Ui) {
        let open = self.open_index();
        // One row whatever the number of views and the panel's width: the tabs that fit, the open view's
        // always among them, and the others under "More" at the row's end.
        let labels: Vec<&'static str> = self.views.iter().map(|v| v.label()).collect();
        let widths: Vec<f32> = labels.iter().map(|l| tab_width(ui, l)).collect();
        let more = |hidden: std::ops::Range<usize>| {
            hidden.map(|i| tab_width(ui, &more_text(Some(labels[i])))).fold(tab_width(ui, MORE_TABS), f32::max)
        };
        let shown = tabs_that_fit(&widths, ui.available_width(), more);
        ui.horizontal(|ui| {
            for &i in &shown {
                if ui.selectable_label(i == open, labels[i]).clicked() {
                    self.persisted.view = self.views[i].id().to_string();
                }
            }
            if shown.len() < labels.len() {
                // The open view in the menu: its button names it, highlighted like an open tab.
                let in_menu = !shown.contains(&open);
                let button = egui::Button::selectable(in_menu, more_text(in_menu.then(|| labels[open])));
                let (response, _) = egui::containers::menu::MenuButton::from_button(button).ui(ui, |ui| {
                    for (i, label) in labels.iter().enumerate().filter(|(i, _)| !shown.contains(i)) {
                        if ui.selectable_label(i == open, *label).clicked() {
                            self.persisted.view = self.views[i].id().to_string();
                            ui.close();
                        }
                    }
                });
                response.on_hover_text("The views whose tabs do not fit");
            }
        });
        ui.separator();
        self.view_rect = Some(ui.available_rect_before_wrap());
        let open = self.open_index();
        let mut cx = ViewContext {
            shown: self.shown.as_ref(),
            doc: &self.doc,
            stale: self.result_is_stale(),
            preview: self.dragging && self.persisted.preview_while_dragging,
            pins: &self.persisted.pins,
            compare_with: &mut self.persisted.compare_with,
            pinned: &mut self.pinned,
            exports: Vec::new(),
        };
        let view = &mut self.views[open];
        if cx.shown.is_none() && !view.needs().is_empty() {
            view.placeholder_ui(ui, &mut cx);
        } else {
            view.ui(ui, &mut cx);
        }
        for e in cx.exports {
            self.files.export(&e.name, e.description, e.extension, e.bytes);
        }
    }

    /// The live result was just pinned: keep it for the views, and compare with it if no pin was chosen.
    fn pinned_now(&mut self) {
        if let (Some(pin), Some(shown)) = (self.persisted.pins.last(), &self.shown) {
            self.pinned.remember(pin, shown);
            if self.persisted.compare_with.is_none() {
                self.persisted.compare_with = Some(pin.name.clone());
            }
        }
    }
}

/// The theme (in the Edit menu): follow the system, dark or light. Kept by egui between sessions.
fn theme_ui(ui: &mut Ui) {
    use egui::ThemePreference;
    ui.label("Theme");
    let mut preference = ui.options(|o| o.theme_preference);
    let before = preference;
    ui.radio_value(&mut preference, ThemePreference::System, "Follow the system");
    ui.radio_value(&mut preference, ThemePreference::Dark, "Dark");
    ui.radio_value(&mut preference, ThemePreference::Light, "Light");
    if preference != before {
        ui.ctx().set_theme(preference);
    }
}

#[cfg(test)]
mod tests {
    use super::tabs_that_fit;

    #[test]
    fn the_tab_row_keeps_to_one_row_whichever_view_is_open() {
        let w = [60.0, 80.0, 90.0, 100.0, 40.0, 50.0];
        // All fit: 420 points.
        assert_eq!(tabs_that_fit(&w, 420.0, |_| 50.0), [0, 1, 2, 3, 4, 5]);
        // 300 points: 250 beside a 50-point menu hold the first three (230).
        assert_eq!(tabs_that_fit(&w, 300.0, |_| 50.0), [0, 1, 2]);
        // The menu's button as wide as the widest label it holds (+10): with the fourth (100) in it,
        // 300 − 110 = 190 holds the first two.
        assert_eq!(tabs_that_fit(&w, 300.0, |h| h.map(|i| w[i] + 10.0).fold(50.0, f32::max)), [0, 1]);
        // No room at all: every tab in the menu.
        assert_eq!(tabs_that_fit(&w, 10.0, |_| 50.0), Vec::<usize>::new());
    }
}
