//! The rotor view (`View::Rotor`): a shipped rotor (its bearing cases at preview fidelity) analysed over a
//! speed range in the background ([`crate::app::rotor_worker`]), shown as a sketch of the rotor and, by tab,
//! the Campbell diagram (1× line, critical speeds), the stability map (log dec, onset marked), the mode
//! shapes (deflected shaft, forward blue / backward orange, exaggerated), the unbalance Bode plot with
//! the API 617 line and the undamped critical-speed map (log stiffness axis, the bearings' k_xx, k_yy over
//! speed on it, crossings marked; computed once per result from the analysis' bearing stiffnesses). Full or
//! synchronously reduced bearing coefficients are selectable.
//!
//! This file holds the view's state, its background analysis and its layout; the plots are in
//! [`super::rotor_plots`], the sketch in [`super::rotor_sketch`]. Drawables come from
//! [`crate::scene::rotor`]; nothing here computes physics. A click on the sketch
//! selects a section, disk, bearing or unbalance to edit ([`super::rotor_edit`]); each rotor keeps its edits
//! while another is shown. A rotor file opened from the File menu (native) joins the shipped ones.

use std::sync::Arc;

use egui::{RichText, Ui};

use super::rotor_plots::{critical_map_ui, curves_ui, mode_shape_ui, unbalance_ui, LIMIT};
use super::rotor_sketch::sketch_ui;
use super::{View, ViewContext};
use crate::app::frame_probe::Job;
use crate::app::jobs::rotor::RotorJob;
use crate::app::jobs::{Event, Runner};
use crate::bearing::stages::StageId;
use crate::model::rotor::{CoefficientModel, Rotor};
use crate::rotor::analysis::{AnalysisParams, AnalysisResult};
use crate::rotor::critical_map::map_over_curves;
use crate::scene::rotor::{map_drawing, sketch, MapDrawing};
use crate::units::RPM;

use super::rotor_edit::{edit_ui, RotorEdit, SaveRequest};

/// Shipped rotors: file name and text (bearing cases are the shipped presets named by file name).
pub const ROTOR_PRESETS: [(&str, &str); 1] =
    [("compressor-rotor.toml", include_str!("../../../cases/rotors/compressor-rotor.toml"))];

/// Speeds analysed [rpm]: from `FIRST_RPM` to `MAX_FACTOR` × the top of the operating range.
const FIRST_RPM: f64 = 1000.0;
const MAX_FACTOR: f64 = 1.3;
const SPEEDS: usize = 41;
/// Stiffnesses and modes of the critical-speed map.
const MAP_POINTS: usize = 61;
const MAP_MODES: usize = 4;


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
    runner: Option<Runner<RotorJob>>,
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
            let runner = self.runner.get_or_insert_with(|| Runner::new(ctx));
            match &rotor {
                Ok(r) => runner.submit(RotorJob::new(r.clone(), AnalysisParams::new(speeds(r)))),
                Err(_) => runner.stop(),
            }
            self.rotor = Some(rotor);
            (self.result, self.progress, self.map) = (None, None, None);
        }
        let Some(runner) = self.runner.as_mut() else { return };
        for e in runner.poll(crate::app::WEB_SOLVE_BUDGET_S) {
            match e {
                Event::Progress(p) => self.progress = Some(progress_counts(&p)),
                Event::Partial(_) => {}
                Event::Done(r) => (self.result, self.progress, self.map) = (Some(Ok(r.0)), None, None),
                Event::Failed(e) => (self.result, self.progress, self.map) = (Some(Err(e)), None, None),
            }
        }
    }
}

/// A job's progress as whole units done and in all (speeds).
#[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
fn progress_counts(p: &crate::app::jobs::Progress) -> (usize, usize) {
    (p.done.round().max(0.0) as usize, p.of.round().max(0.0) as usize)
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
            // In grams with the engineering prefix: 412.3 kg, 1.25 Mg (the prefixes do not apply to kg).
            let mass = crate::number::eng(crate::units::G.from_si(shown.mass()), "g");
            ui.label(RichText::new(format!("{title} — {mass}")).strong());
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
        RotorTab::Campbell | RotorTab::Stability => {
            curves_ui(ui, &result, &rotor, view.tab == RotorTab::Campbell);
        }
        RotorTab::ModeShape => mode_shape_ui(ui, (&mut view.speed_index, &mut view.mode_index), &result, &rotor),
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
