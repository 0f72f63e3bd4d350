//! The rotor view (`View::Rotor`): a shipped rotor (its bearing cases at preview fidelity) analysed over a
//! speed range in the background ([`crate::app::rotor_worker`]), shown as a sketch of the rotor and, by tab,
//! the Campbell diagram (1× line, critical speeds), the stability map (log dec, onset marked), the mode
//! shapes (deflected shaft, forward blue / backward orange, exaggerated), the unbalance Bode plot with
//! the API 617 line and the undamped critical-speed map (log stiffness axis, the bearings' k_xx, k_yy over
//! speed on it, crossings marked; computed once per result from the analysis' bearing stiffnesses). Full or
//! synchronously reduced bearing coefficients are selectable.
//!
//! Drawables come from [`crate::scene::rotor`]; nothing here computes physics. A click on the sketch
//! selects a section, disk, bearing or unbalance to edit ([`super::rotor_edit`]); each rotor keeps its edits
//! while another is shown. A rotor file opened from the File menu (native) joins the shipped ones.

use std::sync::Arc;

use egui::{Color32, RichText, Stroke, Ui};
use egui_plot::{HLine, Line, LineStyle, Plot, Points, VLine};

use super::plot_kit::{decade_label, labelled_spacer, legend_ui, phase_label, wrapped_phase, PALETTE, PHASE_TICKS};
use super::{View, ViewContext};
use crate::app::ink::{self, Ink};
use crate::app::frame_probe::Job;
use crate::app::rotor_worker::{RotorEvent, RotorRunner};
use crate::bearing::stages::StageId;
use crate::model::rotor::{CoefficientModel, Rotor};
use crate::rotor::analysis::{AnalysisParams, AnalysisResult};
use crate::rotor::critical_map::map_over_curves;
use crate::rotor::eigen::Whirl;
use crate::scene::rotor::{
    map_drawing, mode_curves, mode_shape, sketch, unbalance_bode, MapDrawing, RotorSketch, SketchItem,
};
use crate::units::{MM, RPM};

use super::rotor_edit::{edit_ui, RotorEdit, SaveRequest, Selected};

/// Shipped rotors: file name and text (bearing cases are the shipped presets named by file name).
pub const ROTOR_PRESETS: [(&str, &str); 1] =
    [("compressor-rotor.toml", include_str!("../../../cases/rotors/compressor-rotor.toml"))];

/// Speeds analysed [rpm]: from `FIRST_RPM` to `MAX_FACTOR` × the top of the operating range.
const FIRST_RPM: f64 = 1000.0;
const MAX_FACTOR: f64 = 1.3;
const SPEEDS: usize = 41;
/// Modes per whirl direction on the Campbell diagram and the stability map.
const RANKS: usize = 4;
/// Stiffnesses and modes of the critical-speed map.
const MAP_POINTS: usize = 61;
const MAP_MODES: usize = 4;

const FORWARD: Color32 = Color32::from_rgb(0, 114, 178);
const BACKWARD: Ink = Ink { dark: Color32::from_rgb(230, 159, 0), light: Color32::from_rgb(165, 110, 0) };
const LIMIT: Ink = ink::EXCEEDED;

/// The plot shown under the sketch.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum RotorTab {
    #[default]
    Campbell,
    Stability,
    ModeShape,
    Unbalance,
    CriticalMap,
}

impl RotorTab {
    const ALL: [Self; 5] = [Self::Campbell, Self::Stability, Self::ModeShape, Self::Unbalance, Self::CriticalMap];
    fn label(self) -> &'static str {
        match self {
            Self::Campbell => "Campbell diagram",
            Self::Stability => "Stability map",
            Self::ModeShape => "Mode shapes",
            Self::Unbalance => "Unbalance response",
            Self::CriticalMap => "Critical-speed map",
        }
    }
}

/// The view's runtime state (not persisted).
pub struct RotorView {
    /// The shipped rotor shown; `ROTOR_PRESETS.len()` is the rotor file opened ([`RotorView::open_file`]).
    pub preset: usize,
    /// Every rotor offered (the shipped ones, then the opened file) as edited, or why it cannot be read;
    /// built when first shown.
    edits: Vec<Option<Result<RotorEdit, String>>>,
    /// Counts opened files, so opening one again restarts the analysis.
    generation: usize,
    pub coefficients: CoefficientModel,
    pub tab: RotorTab,
    /// Speed point and mode (ascending frequency) of the mode-shape tab.
    pub speed_index: usize,
    pub mode_index: usize,
    runner: Option<RotorRunner>,
    /// What was submitted: (preset, coefficients, generation, edit revision), the rotor, and the result
    /// (or why it failed).
    submitted: Option<(usize, CoefficientModel, usize, usize)>,
    rotor: Option<Result<Rotor, String>>,
    result: Option<Result<Arc<AnalysisResult>, String>>,
    progress: Option<(usize, usize)>,
    /// The critical-speed map of the current result (computed when first shown).
    map: Option<Result<MapDrawing, String>>,
}

impl Default for RotorView {
    fn default() -> Self {
        Self {
            preset: 0,
            edits: (0..=ROTOR_PRESETS.len()).map(|_| None).collect(),
            generation: 0,
            coefficients: CoefficientModel::Full,
            tab: RotorTab::Campbell,
            speed_index: 0,
            mode_index: 0,
            runner: None,
            submitted: None,
            rotor: None,
            result: None,
            progress: None,
            map: None,
        }
    }
}

/// The rotor of the view's snapshot: a shaft 1000 mm long, Ø 50 mm, in 10 elements; a 20 kg disk at mid-span;
/// bearings given by numbers at both ends (no bearing solve: the analysis is quick).
const SNAPSHOT_ROTOR: &str = "title = \"Two-bearing shaft (bearings by numbers)\"\n[rotor]\n\
    [[rotor.section]]\nlength_mm = 1000.0\nouter_diameter_mm = 50.0\nelements = 10\n\
    [[rotor.disk]]\nnode = 5\nmass_kg = 20.0\n\
    [[rotor.bearing]]\nnode = 0\nk_n_per_m = [[1e7, 0.0, 0.0, 1e7]]\nc_ns_per_m = [[1e3, 0.0, 0.0, 1e3]]\n\
    [[rotor.bearing]]\nnode = 10\nk_n_per_m = [[1e7, 0.0, 0.0, 1e7]]\nc_ns_per_m = [[1e3, 0.0, 0.0, 1e3]]\n";

impl View for RotorView {
    fn id(&self) -> &'static str {
        "rotor"
    }

    fn label(&self) -> &'static str {
        "Rotor"
    }

    /// Nothing of the edited case: the view analyses its rotor file in the background.
    fn needs(&self) -> &'static [StageId] {
        &[]
    }

    fn ui(&mut self, ui: &mut Ui, cx: &mut ViewContext<'_>) {
        if let Some(save) = rotor_ui(ui, self) {
            cx.export_as(save.name, "Rotor (TOML)", "toml", save.text.into_bytes());
        }
    }

    fn busy(&self) -> Option<Job> {
        (!self.is_idle()).then_some(Job::Rotor)
    }

    fn snapshot_setup(&mut self) -> Option<&'static str> {
        self.open_file("two-bearing-shaft.toml", None, SNAPSHOT_ROTOR);
        None
    }
}

/// The view's speeds [rad/s] for `rotor`.
fn speeds(rotor: &Rotor) -> Vec<f64> {
    let top_rpm = rotor.operating_range.map_or(12_000.0, |[_, b]| RPM.from_si(b)) * MAX_FACTOR;
    #[allow(clippy::cast_precision_loss)]
    (0..SPEEDS)
        .map(|i| RPM.to_si(FIRST_RPM + (top_rpm - FIRST_RPM) * i as f64 / (SPEEDS - 1) as f64))
        .collect()
}

impl RotorView {
    /// Nothing is being analysed.
    #[must_use]
    pub fn is_idle(&self) -> bool {
        self.runner.as_ref().is_none_or(|r| !r.busy())
    }

    /// The rotor of the analysis shown (as submitted), if it could be read.
    #[must_use]
    pub fn analysed_rotor(&self) -> Option<&Rotor> {
        self.rotor.as_ref().and_then(|r| r.as_ref().ok())
    }

    /// The finished analysis, if any.
    #[must_use]
    pub fn result(&self) -> Option<&AnalysisResult> {
        self.result.as_ref().and_then(|r| r.as_ref().ok()).map(AsRef::as_ref)
    }

    /// Shows the rotor file `name` read from `text` (bearing cases beside `path`); a file that cannot be read
    /// shows its error (the key, the value and the allowed range) in the view.
    pub fn open_file(&mut self, name: &str, path: Option<&std::path::Path>, text: &str) {
        self.edits[ROTOR_PRESETS.len()] = Some(RotorEdit::open(name, path, text));
        self.preset = ROTOR_PRESETS.len();
        self.generation += 1;
    }

    /// The rotor of the current choice as edited (a shipped one read when first shown), or why it cannot
    /// be read.
    pub fn edit_mut(&mut self) -> &mut Result<RotorEdit, String> {
        let opened = self.edits[ROTOR_PRESETS.len()].is_some();
        if self.preset >= ROTOR_PRESETS.len() && !opened {
            self.preset = 0;
        }
        let i = self.preset.min(ROTOR_PRESETS.len());
        self.edits[i].get_or_insert_with(|| {
            let (name, text) = ROTOR_PRESETS[i];
            RotorEdit::open(name, None, text)
        })
    }

    /// The rotor of the current choice as edited.
    #[must_use]
    pub fn edit(&self) -> Option<&RotorEdit> {
        self.edits.get(self.preset)?.as_ref()?.as_ref().ok()
    }

    /// Starts the analysis when the rotor (or an edit of it) or the coefficient model changed; takes in the
    /// runner's events.
    fn drive(&mut self, ctx: &egui::Context) {
        let revision = self.edit_mut().as_ref().map_or(0, |e| e.revision);
        let wanted = (self.preset, self.coefficients, self.generation, revision);
        if self.submitted != Some(wanted) {
            self.submitted = Some(wanted);
            let coefficients = self.coefficients;
            let rotor = self
                .edit_mut()
                .as_ref()
                .map(|e| {
                    let mut r = e.rotor().clone();
                    r.coefficients = coefficients;
                    r
                })
                .map_err(Clone::clone);
            let runner = self.runner.get_or_insert_with(|| RotorRunner::new(ctx.clone()));
            if let Ok(r) = &rotor {
                runner.start(r, AnalysisParams::new(speeds(r)));
            }
            self.rotor = Some(rotor);
            (self.result, self.progress, self.map) = (None, None, None);
        }
        let Some(runner) = self.runner.as_mut() else { return };
        for e in runner.poll() {
            match e {
                RotorEvent::Progress { done, of } => self.progress = Some((done, of)),
                RotorEvent::Done(r) => (self.result, self.progress, self.map) = (Some(r), None, None),
            }
        }
    }
}

/// Draws the view; returns a save of the rotor file the user asked for.
pub fn rotor_ui(ui: &mut Ui, view: &mut RotorView) -> Option<SaveRequest> {
    view.drive(ui.ctx());
    // Wrapped rows throughout: a row wider than the central panel would widen the whole view under the side
    // panels and clip it.
    ui.horizontal_wrapped(|ui| {
        let label = ui.label("Rotor");
        let opened = view.edits[ROTOR_PRESETS.len()]
            .as_ref()
            .map(|e| e.as_ref().map_or_else(|_| "opened file".to_string(), |e| e.name.clone()));
        let shown =
            ROTOR_PRESETS.get(view.preset).map_or_else(|| opened.clone().unwrap_or_default(), |p| p.0.to_string());
        egui::ComboBox::from_id_salt("rotor-preset")
            .selected_text(shown)
            .show_ui(ui, |ui| {
                for (i, (name, _)) in ROTOR_PRESETS.iter().enumerate() {
                    ui.selectable_value(&mut view.preset, i, *name);
                }
                if let Some(name) = opened {
                    ui.selectable_value(&mut view.preset, ROTOR_PRESETS.len(), name);
                }
            })
            .response
            .labelled_by(label.id);
        ui.separator();
        ui.label("Bearings");
        ui.selectable_value(&mut view.coefficients, CoefficientModel::Full, "full coefficients")
            .on_hover_text("Journal and pad coordinates with the pads' inertia (no reduction).");
        ui.selectable_value(&mut view.coefficients, CoefficientModel::Reduced, "reduced 2×2")
            .on_hover_text("Synchronously reduced (ω = Ω): overestimates the stable range.");
    });
    let rotor = match &view.rotor {
        Some(Ok(r)) => r.clone(),
        Some(Err(e)) => {
            ui.label(RichText::new(format!("Cannot read the rotor: {e}")).color(LIMIT.of(ui)));
            return None;
        }
        None => return None,
    };
    let save = match view.edit_mut() {
        Ok(edit) => {
            let shown = edit.rotor();
            let title = if shown.representative {
                format!("{} — representative shaft, not the thesis' rotor", shown.title)
            } else {
                shown.title.clone()
            };
            ui.label(RichText::new(format!("{title} — {:.0} kg", shown.mass())).strong());
            if let Some(picked) = sketch_ui(ui, &sketch(shown), &edit.section_of_elements(), edit.selected) {
                edit.selected = Some(picked);
            }
            edit_ui(ui, edit)
        }
        Err(_) => None,
    };
    let result = match &view.result {
        Some(Ok(r)) => r.clone(),
        Some(Err(e)) => {
            ui.label(RichText::new(format!("Analysis failed: {e}")).color(LIMIT.of(ui)));
            return save;
        }
        None => {
            ui.horizontal(|ui| {
                ui.spinner();
                let (done, of) = view.progress.unwrap_or((0, SPEEDS));
                ui.label(format!("Analysing: speed {done} of {of} (bearings solved at each speed, preview fidelity)…"));
            });
            return save;
        }
    };
    // Wrapped: every tab stays readable in a narrow central panel.
    ui.horizontal_wrapped(|ui| {
        for t in RotorTab::ALL {
            ui.selectable_value(&mut view.tab, t, t.label());
        }
    });
    summary_ui(ui, &result, &rotor);
    match view.tab {
        RotorTab::Campbell | RotorTab::Stability => curves_ui(ui, &result, &rotor, view.tab),
        RotorTab::ModeShape => mode_shape_ui(ui, view, &result, &rotor),
        RotorTab::Unbalance => unbalance_ui(ui, &result, &rotor),
        RotorTab::CriticalMap => {
            let map = view.map.get_or_insert_with(|| {
                map_over_curves(&rotor, result.bearing_stiffness.clone(), MAP_POINTS, MAP_MODES)
                    .map(|m| map_drawing(&m, &rotor))
                    .map_err(|e| e.to_string())
            });
            match map {
                Ok(m) => critical_map_ui(ui, m),
                Err(e) => {
                    ui.label(RichText::new(format!("Critical-speed map failed: {e}")).color(LIMIT.of(ui)));
                }
            }
        }
    }
    save
}

/// The lowest damped natural frequency [Hz] at the analysed speed [rpm] nearest the top of the operating
/// range (the sweep's last speed without one): modes there are lightly damped, so a heavier rotor lowers it
/// as `√(k/m)` says (a heavily damped mode at low speed may not).
#[must_use]
pub fn first_mode_at_top_speed(r: &AnalysisResult, rotor: &Rotor) -> Option<(f64, f64)> {
    let s = match rotor.operating_range {
        Some([_, top]) => r
            .speeds
            .iter()
            .min_by(|a, b| (a.point.speed_rad_s - top).abs().total_cmp(&(b.point.speed_rad_s - top).abs()))?,
        // (Measured from an infinite top, every speed would tie and the first be taken.)
        None => r.speeds.last()?,
    };
    s.point.modes.modes.first().map(|m| (RPM.from_si(s.point.speed_rad_s), m.frequency_hz()))
}

fn summary_ui(ui: &mut Ui, r: &AnalysisResult, rotor: &Rotor) {
    let rpm = |w: f64| RPM.from_si(w);
    let onset =
        r.onset.as_ref().map_or_else(|| "none in the sweep".to_string(), |o| format!("{:.0} rpm", rpm(o.speed_rad_s)));
    let critical: Vec<String> = r.critical_speeds.iter().map(|c| format!("{:.0}", rpm(c.speed_rad_s))).collect();
    let lowest = first_mode_at_top_speed(r, rotor)
        .map(|(n, f)| format!(" Lowest natural frequency at {n:.0} rpm: {f:.3} Hz."))
        .unwrap_or_default();
    ui.label(format!(
        "Onset of instability: {onset}. 1× critical speeds: {} rpm.{lowest} {} bearing solves, {} eigen-solutions, {} DOFs.",
        if critical.is_empty() { "none".to_string() } else { critical.join(", ") },
        r.report.bearing_solves,
        r.report.eigen_solutions,
        r.report.system_dofs
    ));
    for w in &r.report.warnings {
        ui.label(RichText::new(w.to_string()).color(LIMIT.of(ui)));
    }
}

fn whirl_color(w: Whirl, backward: Color32) -> Color32 {
    match w {
        Whirl::Forward => FORWARD,
        Whirl::Backward => backward,
    }
}

fn plot_without_legend(id: &str, ui: &Ui, height: f32) -> Plot<'static> {
    let width = ui.available_width().min(ui.clip_rect().width());
    Plot::new(id.to_string()).height(height).width(width).allow_scroll(false)
}

/// How a legend entry's sample is drawn.
#[derive(Clone, Copy)]
enum Sample {
    Solid,
    Dashed,
    Dotted,
    Dot,
}

/// The legend of the Campbell diagram and the stability map, as a row above the plot: inside it, the
/// entries (eight modes, the 1× line, the critical speeds, the operating range) covered much of the curves
/// at 1280×720. Short labels keep it to one row there; each curve keeps its name (F1, B2, …: whirl and rank)
/// for the plot's hover label.
fn curves_legend_ui(ui: &mut Ui, campbell: bool, operating: bool, onset: Option<f64>) {
    let (limit, backward) = (LIMIT.of(ui), BACKWARD.of(ui));
    let grey = Color32::from_gray(150);
    let mut entries =
        vec![("forward".to_string(), FORWARD, Sample::Solid), ("backward".to_string(), backward, Sample::Dashed)];
    if campbell {
        entries.push(("1×".into(), grey, Sample::Dashed));
        entries.push(("1× critical".into(), limit, Sample::Dot));
    } else {
        entries.push(("δ = 0".into(), grey, Sample::Solid));
        if let Some(x) = onset {
            entries.push((format!("onset {x:.0} rpm"), limit, Sample::Solid));
        }
    }
    if operating {
        entries.push(("operating range".into(), grey, Sample::Dotted));
    }
    ui.horizontal_wrapped(|ui| {
        for (label, color, sample) in entries {
            let (rect, sample_response) = ui.allocate_exact_size(egui::vec2(18.0, 12.0), egui::Sense::hover());
            sample_response
                .widget_info(|| egui::WidgetInfo::labeled(egui::Role::Image, true, format!("legend sample: {label}")));
            let (a, b) = (rect.left_center(), rect.right_center());
            let stroke = Stroke::new(1.6, color);
            let painter = ui.painter();
            match sample {
                Sample::Solid => {
                    painter.line_segment([a, b], stroke);
                }
                Sample::Dashed => {
                    painter.extend(egui::Shape::dashed_line(&[a, b], stroke, 5.0, 3.0));
                }
                Sample::Dotted => {
                    painter.extend(egui::Shape::dotted_line(&[a, b], color, 4.0, 1.0));
                }
                Sample::Dot => {
                    painter.circle_filled(rect.center(), 4.0, color);
                }
            }
            ui.label(RichText::new(label).small());
        }
    });
}

fn curves_ui(ui: &mut Ui, r: &AnalysisResult, rotor: &Rotor, tab: RotorTab) {
    let (limit, backward) = (LIMIT.of(ui), BACKWARD.of(ui));
    let c = mode_curves(r, rotor, RANKS);
    let height = (ui.available_height() - 10.0).max(160.0);
    let campbell = tab == RotorTab::Campbell;
    let (id, y_label, curves) = if campbell {
        ("rotor_campbell", "damped frequency [Hz]", &c.frequency_hz)
    } else {
        ("rotor_stability", "log decrement [–]", &c.log_dec)
    };
    curves_legend_ui(ui, campbell, c.operating_rpm.is_some(), c.onset_rpm);
    let height = (height - ui.spacing().interact_size.y - ui.spacing().item_spacing.y).max(160.0);
    plot_without_legend(id, ui, height)
        .x_axis_label("speed [rpm]")
        .y_axis_label(y_label)
        .x_grid_spacer(labelled_spacer(70.0))
        .y_grid_spacer(labelled_spacer(32.0))
        .show(ui, |p| {
        for curve in curves {
            let style = if curve.whirl == Whirl::Forward { LineStyle::Solid } else { LineStyle::dashed_loose() };
            p.line(
                Line::new(curve.name.clone(), curve.points.clone())
                    .color(whirl_color(curve.whirl, backward))
                    .style(style)
                    .width(1.6),
            );
        }
        if let Some([a, b]) = c.operating_rpm {
            for x in [a, b] {
                p.vline(
                    VLine::new("operating range", x).color(Color32::from_gray(150)).style(LineStyle::dotted_dense()),
                );
            }
        }
        if campbell {
            p.line(Line::new("1×", c.one_x.to_vec()).color(Color32::from_gray(120)).style(LineStyle::dashed_dense()));
            p.points(Points::new("1× critical speeds", c.critical.clone()).radius(5.0).color(limit));
        } else {
            p.hline(HLine::new("δ = 0", 0.0).color(Color32::from_gray(120)));
            if let Some(x) = c.onset_rpm {
                p.vline(VLine::new(format!("onset {x:.0} rpm"), x).color(limit).width(2.0));
            }
        }
    });
}

fn mode_shape_ui(ui: &mut Ui, view: &mut RotorView, r: &AnalysisResult, rotor: &Rotor) {
    let last = r.speeds.len().saturating_sub(1);
    view.speed_index = view.speed_index.min(last);
    let index_rpm: Vec<f64> =
        (0..r.speeds.len()).map(|i| RPM.from_si(r.speeds[i].point.speed_rad_s)).collect();
    ui.horizontal(|ui| {
        ui.add(
            egui::Slider::new(&mut view.speed_index, 0..=last)
                .custom_formatter(|v, _| format!("{:.0} rpm", index_rpm.get(nearest_index(v)).copied().unwrap_or(0.0)))
                .text("speed"),
        );
        let modes = &r.speeds[view.speed_index].point.modes.modes;
        view.mode_index = view.mode_index.min(modes.len().saturating_sub(1));
        let describe = |i: usize| {
            modes.get(i).map_or_else(String::new, |m| {
                format!(
                    "{} {:.1} Hz, δ {:.3}",
                    if m.whirl == Whirl::Forward { "forward" } else { "backward" },
                    m.frequency_hz(),
                    m.log_dec
                )
            })
        };
        let label = ui.label("Mode");
        egui::ComboBox::from_id_salt("rotor-mode")
            .selected_text(describe(view.mode_index))
            .show_ui(ui, |ui| {
                for i in 0..modes.len().min(2 * RANKS) {
                    ui.selectable_value(&mut view.mode_index, i, describe(i));
                }
            })
            .response
            .labelled_by(label.id);
    });
    let Some(s) = mode_shape(r, rotor, view.speed_index, view.mode_index) else {
        ui.label("No mode at this speed.");
        return;
    };
    let z_mm: Vec<f64> = s.z_m.iter().map(|z| MM.from_si(*z)).collect();
    let color = whirl_color(s.whirl, BACKWARD.of(ui));
    let bearings: Vec<f64> = rotor.bearings.iter().map(|b| z_mm[b.node]).collect();
    let whirl = if s.whirl == Whirl::Forward { "forward" } else { "backward" };
    legend_ui(
        ui,
        &[
            (format!("x ({whirl} whirl)"), color),
            ("y (dashed)".into(), color),
            ("bearings (dotted)".into(), Color32::from_gray(150)),
        ],
    );
    plot_without_legend("rotor_mode_shape", ui, (ui.available_height() - 10.0).max(160.0))
        .x_axis_label("axial position [mm]")
        .x_grid_spacer(labelled_spacer(70.0))
        .y_axis_label("deflection (largest = 1)")
        .show(ui, |p| {
            p.hline(HLine::new("undeflected axis", 0.0).color(Color32::from_gray(120)));
            p.line(
                Line::new("x", z_mm.iter().zip(&s.x).map(|(z, v)| [*z, *v]).collect::<Vec<_>>())
                    .color(color)
                    .width(2.5),
            );
            p.line(
                Line::new("y", z_mm.iter().zip(&s.y).map(|(z, v)| [*z, *v]).collect::<Vec<_>>())
                    .color(color)
                    .style(LineStyle::dashed_loose())
                    .width(1.5),
            );
            for z in &bearings {
                p.vline(VLine::new("bearings", *z).color(Color32::from_gray(150)).style(LineStyle::dotted_dense()));
            }
        });
}

fn unbalance_ui(ui: &mut Ui, r: &AnalysisResult, rotor: &Rotor) {
    let limit = LIMIT.of(ui);
    let b = unbalance_bode(r, rotor);
    let over = !b.exceedances().is_empty();
    let sentence = b.api617_sentence();
    ui.label(if over { RichText::new(sentence).color(limit).strong() } else { RichText::new(sentence) });
    let colors: Vec<Color32> = PALETTE.iter().copied().cycle().take(b.nodes.len()).collect();
    let mut legend: Vec<(String, Color32)> = b.nodes.iter().zip(&colors).map(|(n, c)| (n.name.clone(), *c)).collect();
    legend.push(("API 617 limit 25.4 sqrt(12000/N) µm (dashed)".into(), limit));
    legend_ui(ui, &legend);
    let height = ((ui.available_height() - 20.0) / 2.0).max(120.0);
    let link = ui.scope_id().with("rotor_bode");
    plot_without_legend("rotor_unbalance_amplitude", ui, height)
        .x_axis_label("speed [rpm]")
        .y_axis_label("orbit p-p [µm]")
        .x_grid_spacer(labelled_spacer(70.0))
        .y_grid_spacer(labelled_spacer(32.0))
        .include_y(0.0)
        .link_axis(link, [true, false])
        .show(ui, |p| {
            for (n, color) in b.nodes.iter().zip(&colors) {
                p.line(Line::new(n.name.clone(), n.amplitude_um.clone()).color(*color).width(1.6));
            }
            p.line(
                Line::new("API 617 limit", b.api617_um.clone()).color(limit).style(LineStyle::dashed_dense()).width(2.0),
            );
        });
    plot_without_legend("rotor_unbalance_phase", ui, height)
        .x_axis_label("speed [rpm]")
        .y_axis_label("phase of x [°]")
        .x_grid_spacer(labelled_spacer(70.0))
        .y_grid_spacer(egui_plot::uniform_grid_spacer(|_| PHASE_TICKS))
        .y_axis_formatter(|m, _| phase_label(m.value))
        .include_y(-180.0)
        .include_y(180.0)
        .link_axis(link, [true, false])
        .show(ui, |p| {
            for (n, color) in b.nodes.iter().zip(&colors) {
                let x: Vec<f64> = n.phase_deg.iter().map(|q| q[0]).collect();
                let y: Vec<f64> = n.phase_deg.iter().map(|q| q[1]).collect();
                for piece in wrapped_phase(&x, &y) {
                    p.line(Line::new(n.name.clone(), piece).color(*color).width(1.6));
                }
            }
        });
}

fn critical_map_ui(ui: &mut Ui, m: &MapDrawing) {
    let (limit, backward) = (LIMIT.of(ui), BACKWARD.of(ui));
    let colors = PALETTE;
    let mut legend: Vec<(String, Color32)> =
        (0..m.modes.len()).map(|i| (format!("mode {}", i + 1), colors[i % colors.len()])).collect();
    legend.push(("bearings k_xx (dashed), k_yy (dotted)".into(), backward));
    legend.push(("dots: crossings, critical speeds on the bearings".into(), limit));
    legend_ui(ui, &legend);
    plot_without_legend("rotor_critical_map", ui, (ui.available_height() - 10.0).max(160.0))
        .x_axis_label("support stiffness at the bearings [N/m]")
        .y_axis_label("undamped critical speed [rpm]")
        .x_grid_spacer(egui_plot::log_grid_spacer(10))
        .x_axis_formatter(|mark, _| decade_label(mark.value))
        .y_grid_spacer(labelled_spacer(32.0))
        .show(ui, |p| {
            for (i, (line, color)) in m.modes.iter().zip(colors.iter().cycle()).enumerate() {
                p.line(Line::new(format!("mode {}", i + 1), line.clone()).color(*color).width(1.8));
            }
            for (name, points) in &m.bearings {
                let style = if name.ends_with("k_xx") { LineStyle::dashed_dense() } else { LineStyle::dotted_dense() };
                p.line(Line::new(name.clone(), points.clone()).color(backward).style(style).width(1.6));
            }
            p.points(
                Points::new("crossings: critical speeds on the bearings", m.crossings.clone()).radius(5.0).color(limit),
            );
        });
}

/// A slider value (an index held as `f64`) as an index.
#[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)] // rounded and clamped at 0
fn nearest_index(v: f64) -> usize {
    v.round().max(0.0) as usize
}

/// Where the sketch draws an item of `kind` at axial screen position `px`, about the shaft axis `mid`.
fn item_rect(kind: SketchItem, px: f32, mid: f32) -> egui::Rect {
    match kind {
        SketchItem::Disk => egui::Rect::from_center_size(egui::pos2(px, mid), egui::vec2(6.0, 60.0)),
        SketchItem::Bearing => {
            egui::Rect::from_min_max(egui::pos2(px - 7.0, mid + 17.0), egui::pos2(px + 7.0, mid + 29.0))
        }
        SketchItem::Numbers | SketchItem::Support => {
            egui::Rect::from_center_size(egui::pos2(px, mid + 24.0), egui::vec2(10.0, 10.0))
        }
        SketchItem::Unbalance => egui::Rect::from_center_size(egui::pos2(px, mid - 38.0), egui::vec2(8.0, 8.0)),
    }
}

/// The selection an item of the sketch stands for: its `rank`-th entry among the items of its table.
fn item_selection(kind: SketchItem, rank: usize) -> Option<Selected> {
    match kind {
        SketchItem::Disk => Some(Selected::Disk(rank)),
        SketchItem::Bearing | SketchItem::Numbers => Some(Selected::Bearing(rank)),
        SketchItem::Unbalance => Some(Selected::Unbalance(rank)),
        SketchItem::Support => None,
    }
}

/// The rotor to scale along its axis, diameters exaggerated to fit the strip; the `selected` item framed.
/// A click selects the item under the pointer (within a few points), else the shaft section there
/// (`section_of_element`: the section of each element).
#[allow(clippy::cast_possible_truncation)] // millimetres to screen points
fn sketch_ui(
    ui: &mut Ui,
    s: &RotorSketch,
    section_of_element: &[usize],
    selected: Option<Selected>,
) -> Option<Selected> {
    let width = ui.available_width().min(ui.clip_rect().width());
    let (rect, response) = ui.allocate_exact_size(egui::vec2(width, 124.0), egui::Sense::click());
    response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Image, true, "rotor sketch"));
    let painter = ui.painter_at(rect);
    let (limit, backward) = (LIMIT.of(ui), BACKWARD.of(ui));
    let margin = 12.0;
    let sx = (rect.width() - 2.0 * margin) / s.length_mm.max(1e-9) as f32;
    let sy = 30.0 / s.max_diameter_mm.max(1e-9) as f32;
    let x = |z: f64| rect.left() + margin + z as f32 * sx;
    let mid = rect.top() + 50.0;
    let fill = Color32::from_gray(170);
    let mark = Stroke::new(2.0, ui.visuals().strong_text_color());
    // Items with their rank in their rotor table (disks; bearings and numbers; supports; unbalances).
    let mut counts = [0_usize; 4];
    let items: Vec<(f64, SketchItem, usize)> = s
        .items
        .iter()
        .map(|&(z, kind, _)| {
            let table = match kind {
                SketchItem::Disk => 0,
                SketchItem::Bearing | SketchItem::Numbers => 1,
                SketchItem::Support => 2,
                SketchItem::Unbalance => 3,
            };
            counts[table] += 1;
            (z, kind, counts[table] - 1)
        })
        .collect();
    for (e, [z0, z1, d, di]) in s.sections.iter().enumerate() {
        let (h, hi) = (*d as f32 * sy / 2.0, *di as f32 * sy / 2.0);
        let r = egui::Rect::from_min_max(egui::pos2(x(*z0), mid - h), egui::pos2(x(*z1), mid + h));
        painter.rect_filled(r, 0.0, fill);
        if hi > 0.0 {
            painter.rect_filled(
                egui::Rect::from_min_max(egui::pos2(x(*z0), mid - hi), egui::pos2(x(*z1), mid + hi)),
                0.0,
                ui.visuals().extreme_bg_color,
            );
        }
        if let (Some(Selected::Section(i)), Some(&sec)) = (selected, section_of_element.get(e)) {
            if i == sec {
                painter.rect_stroke(r, 0.0, mark, egui::StrokeKind::Outside);
            }
        }
    }
    for &(z, kind, rank) in &items {
        let r = item_rect(kind, x(z), mid);
        match kind {
            SketchItem::Disk => {
                painter.rect_filled(r, 1.0, FORWARD);
            }
            SketchItem::Bearing => {
                painter.add(egui::Shape::convex_polygon(
                    vec![r.center_top(), r.left_bottom(), r.right_bottom()],
                    backward,
                    Stroke::NONE,
                ));
            }
            SketchItem::Numbers | SketchItem::Support => {
                painter.line_segment([r.left_top(), r.right_bottom()], Stroke::new(2.0, limit));
                painter.line_segment([r.left_bottom(), r.right_top()], Stroke::new(2.0, limit));
            }
            SketchItem::Unbalance => {
                painter.circle_filled(r.center(), 4.0, limit);
                painter
                    .line_segment([r.center_bottom(), egui::pos2(r.center().x, mid - 30.0)], Stroke::new(1.0, limit));
            }
        }
        if selected.is_some() && item_selection(kind, rank) == selected {
            painter.rect_stroke(r.expand(3.0), 2.0, mark, egui::StrokeKind::Outside);
        }
    }
    let text = ui.visuals().weak_text_color();
    // Two lines under the shaft: the scale, then the legend (side by side they overlap in a narrow panel).
    painter.text(
        egui::pos2(rect.left() + margin, rect.bottom() - 16.0),
        egui::Align2::LEFT_BOTTOM,
        format!("0 — {:.0} mm (diameters ×{:.0})", s.length_mm, sy / sx),
        egui::FontId::proportional(11.0),
        text,
    );
    painter.text(
        egui::pos2(rect.left() + margin, rect.bottom() - 2.0),
        egui::Align2::LEFT_BOTTOM,
        "blue: disks, orange: bearings, red ×: coefficients by numbers, red dots: unbalances",
        egui::FontId::proportional(11.0),
        text,
    );
    let click = response.interact_pointer_pos().filter(|_| response.clicked())?;
    // The nearest item whose drawing (grown by a few points) holds the click, else the section at its z.
    let hit = items
        .iter()
        .filter(|&&(z, kind, _)| item_rect(kind, x(z), mid).expand(4.0).contains(click))
        .min_by(|a, b| (x(a.0) - click.x).abs().total_cmp(&(x(b.0) - click.x).abs()))
        .and_then(|&(_, kind, rank)| item_selection(kind, rank));
    hit.or_else(|| {
        let z = f64::from((click.x - rect.left() - margin) / sx);
        let e = s.sections.iter().position(|sec| z >= sec[0] && z <= sec[1])?;
        section_of_element.get(e).map(|&i| Selected::Section(i))
    })
}
