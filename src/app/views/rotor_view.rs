//! The rotor view (`View::Rotor`): a rotor analysed over a speed range in the background
//! ([`crate::app::jobs::rotor`]) — by default the shipped rotor on the **edited bearing** (every bearing
//! position that names a bearing case runs on the edited case, at its fidelity, at preview fidelity while a
//! value is dragged), or on the rotor file's own bearing cases (at preview fidelity; how an opened rotor file
//! starts) — shown as a sketch of the rotor and, by tab,
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
//!
//! The view says which bearings, fidelity and speeds its analysis used. An edit of the case re-runs the
//! analysis; until it is done the previous one stays on screen, said to be of an earlier design.

use std::sync::Arc;

use egui::{RichText, Ui};

use super::rotor_plots::{critical_map_ui, curves_ui, mode_shape_ui, unbalance_ui, LIMIT};
use super::rotor_sketch::sketch_ui;
use super::view::EditedBearing;
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

/// Which bearings the rotor runs on.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Bearings {
    /// The edited case at every bearing position that names a case.
    #[default]
    Edited,
    /// The bearing cases the rotor file names (at preview fidelity).
    RotorFile,
}

/// What an analysis was asked for: the rotor chosen and its edit, the coefficients, the bearings and — on
/// the edited bearing — the case text and whether at preview fidelity.
#[derive(Debug, Clone, PartialEq)]
struct Wanted {
    preset: usize,
    coefficients: CoefficientModel,
    generation: usize,
    edit_revision: usize,
    bearings: Bearings,
    case: Option<(String, bool)>,
}

/// What an analysis used, as the view states it.
#[derive(Debug, Clone, PartialEq)]
pub struct Uses {
    /// "the edited case compressor-bearing.toml (standard fidelity)" or "the rotor file's bearing cases …".
    pub bearings: String,
    pub nodes: Vec<usize>,
    pub speeds_rpm: (f64, f64, usize),
    /// The document's revision the analysis is of (the edited bearing's).
    pub revision: u64,
}

impl Uses {
    /// One line: the bearings, their nodes, the speeds.
    #[must_use]
    pub fn sentence(&self) -> String {
        let nodes: Vec<String> = self.nodes.iter().map(ToString::to_string).collect();
        let (a, b, n) = self.speeds_rpm;
        format!(
            "Bearings: {} at node{} {}; {n} speeds from {a:.0} to {b:.0} rpm.",
            self.bearings,
            if nodes.len() == 1 { "" } else { "s" },
            nodes.join(", ")
        )
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
    /// The bearings each rotor (the shipped ones, then the opened file) runs on.
    pub bearings: Vec<Bearings>,
    runner: Option<Runner<RotorJob>>,
    /// What was submitted, the rotor (or why it cannot be read) and what it uses.
    submitted: Option<Wanted>,
    rotor: Option<Result<Rotor, String>>,
    uses: Option<Uses>,
    /// The result shown (or why it failed), what it was asked for, its rotor and what it used.
    result: Option<Result<Arc<AnalysisResult>, String>>,
    result_for: Option<Wanted>,
    result_rotor: Option<Rotor>,
    result_uses: Option<Uses>,
    /// The edited case is invalid: the analysis on screen is of its last valid version.
    case_invalid: bool,
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
            bearings: (0..=ROTOR_PRESETS.len())
                .map(|i| if i < ROTOR_PRESETS.len() { Bearings::Edited } else { Bearings::RotorFile })
                .collect(),
            runner: None,
            submitted: None,
            rotor: None,
            uses: None,
            result: None,
            result_for: None,
            result_rotor: None,
            result_uses: None,
            case_invalid: false,
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

    /// No stage of the edited case's solve: the view runs its own analysis on the edited case.
    fn needs(&self) -> &'static [StageId] {
        &[]
    }

    fn ui(&mut self, ui: &mut Ui, cx: &mut ViewContext<'_>) {
        if let Some(save) = rotor_ui(ui, self, &cx.edited_bearing()) {
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

    /// The rotor of the analysis shown, if any.
    #[must_use]
    pub fn analysed_rotor(&self) -> Option<&Rotor> {
        self.result_rotor.as_ref()
    }

    /// What the analysis shown used (bearings, nodes, speeds), if any.
    #[must_use]
    pub fn uses(&self) -> Option<&Uses> {
        self.result_uses.as_ref()
    }

    /// The analysis shown is the one last asked for (not of an earlier design or setting).
    #[must_use]
    pub fn result_is_current(&self) -> bool {
        self.result.is_some() && self.result_for == self.submitted
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
        // An opened rotor file runs on its own bearing cases until told otherwise.
        self.bearings[ROTOR_PRESETS.len()] = Bearings::RotorFile;
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

    /// The analysis the view wants now: the rotor (or why not) and what it uses; `None` while the edited
    /// case is invalid and the rotor runs on it (the analysis on screen stays).
    fn wanted(&mut self, edited: &EditedBearing) -> Option<(Wanted, Result<Rotor, String>, Option<Uses>)> {
        let (preset, coefficients, generation) = (self.preset, self.coefficients, self.generation);
        let choice = self.preset.min(ROTOR_PRESETS.len());
        let bearings = self.bearings[choice];
        let edit = match self.edit_mut() {
            Ok(e) => e,
            Err(e) => {
                let e = e.clone();
                let wanted = Wanted { preset, coefficients, generation, edit_revision: 0, bearings, case: None };
                return Some((wanted, Err(e), None));
            }
        };
        let on_edited = bearings == Bearings::Edited && edit.has_bearing_cases();
        let (rotor, case, what) = if on_edited {
            let text = edited.text.as_ref()?;
            let rotor = edit.on_case(text, edited.preview).map_err(|e| format!("on the edited case {}: {e}", edited.name));
            let fidelity = rotor.as_ref().ok().and_then(|r| first_case(r)).map(|c| c.mesh.fidelity);
            let fidelity =
                fidelity.map_or_else(String::new, |f| format!(" ({} fidelity)", format!("{f:?}").to_lowercase()));
            let while_dragged = if edited.preview { ", while the value is dragged" } else { "" };
            (rotor, Some((text.clone(), edited.preview)), format!("the edited case {}{fidelity}{while_dragged}", edited.name))
        } else if edit.has_bearing_cases() {
            (Ok(edit.rotor().clone()), None, "the rotor file's bearing cases (preview fidelity)".to_string())
        } else {
            (Ok(edit.rotor().clone()), None, "the rotor file's bearings (given by numbers)".to_string())
        };
        let wanted = Wanted { preset, coefficients, generation, edit_revision: edit.revision, bearings, case };
        let rotor = rotor.map(|mut r| {
            r.coefficients = coefficients;
            r
        });
        let uses = rotor.as_ref().ok().map(|r| {
            let s = speeds(r);
            Uses {
                bearings: what,
                nodes: if on_edited { edit.case_nodes() } else { r.bearings.iter().map(|b| b.node).collect() },
                speeds_rpm: (RPM.from_si(s[0]), RPM.from_si(s[s.len() - 1]), s.len()),
                revision: edited.revision,
            }
        });
        Some((wanted, rotor, uses))
    }

    /// Starts the analysis when what it is asked for changed (the rotor or an edit of it, the coefficient
    /// model, the bearings, the edited case); takes in the runner's events. While a value is dragged a running
    /// analysis finishes before the next value's starts, so results keep coming during the drag.
    fn drive(&mut self, ctx: &egui::Context, edited: &EditedBearing) {
        let wanted = self.wanted(edited);
        self.case_invalid = wanted.is_none();
        let busy = self.runner.as_ref().is_some_and(Runner::busy);
        if let Some((wanted, rotor, uses)) = wanted {
            if self.submitted.as_ref() != Some(&wanted) && !(edited.preview && busy) {
                self.submitted = Some(wanted);
                let runner = self.runner.get_or_insert_with(|| Runner::new(ctx));
                match &rotor {
                    Ok(r) => runner.submit(RotorJob::new(r.clone(), AnalysisParams::new(speeds(r)))),
                    Err(_) => runner.stop(),
                }
                (self.rotor, self.uses, self.progress) = (Some(rotor), uses, None);
            }
        }
        let Some(runner) = self.runner.as_mut() else { return };
        for e in runner.poll(crate::app::WEB_SOLVE_BUDGET_S) {
            let result = match e {
                Event::Progress(p) => {
                    self.progress = Some(progress_counts(&p));
                    continue;
                }
                Event::Partial(_) => continue,
                Event::Done(r) => Ok(r.0),
                Event::Failed(e) => Err(e),
            };
            (self.result, self.progress, self.map) = (Some(result), None, None);
            self.result_for.clone_from(&self.submitted);
            self.result_rotor = self.rotor.as_ref().and_then(|r| r.as_ref().ok()).cloned();
            self.result_uses.clone_from(&self.uses);
        }
    }
}

/// The bearing case of a rotor's first position that has one.
fn first_case(r: &Rotor) -> Option<&crate::model::Case> {
    r.bearings.iter().find_map(|b| match &b.support {
        crate::model::rotor::BearingSupport::Case { case, .. } => Some(case.as_ref()),
        crate::model::rotor::BearingSupport::Numbers(_) => None,
    })
}

/// A job's progress as whole units done and in all (speeds).
#[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
fn progress_counts(p: &crate::app::jobs::Progress) -> (usize, usize) {
    (p.done.round().max(0.0) as usize, p.of.round().max(0.0) as usize)
}

/// Draws the view; returns a save of the rotor file the user asked for.
pub fn rotor_ui(ui: &mut Ui, view: &mut RotorView, edited: &EditedBearing) -> Option<SaveRequest> {
    view.drive(ui.ctx(), edited);
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
        let choice = view.preset.min(ROTOR_PRESETS.len());
        if view.edit().is_some_and(RotorEdit::has_bearing_cases) {
            ui.separator();
            let bearings = &mut view.bearings[choice];
            ui.selectable_value(bearings, Bearings::Edited, format!("on {}", edited.name)).on_hover_text(
                "Every bearing position that names a bearing case runs on the edited case (its own overrides kept), \
                 at the case's fidelity (preview while a value is dragged).",
            );
            ui.selectable_value(bearings, Bearings::RotorFile, "on the rotor file's cases")
                .on_hover_text("The bearing cases the rotor file names, at preview fidelity.");
        }
    });
    match &view.rotor {
        Some(Ok(_)) => {}
        Some(Err(e)) => {
            ui.label(RichText::new(format!("Cannot read the rotor: {e}")).color(LIMIT.of(ui)));
            return None;
        }
        None if view.case_invalid => {
            ui.label(RichText::new("The edited case is invalid: fix it in the editor to analyse the rotor on it.").color(LIMIT.of(ui)));
            return None;
        }
        None => return None,
    }
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
    // What is being analysed, and whether what is shown is of it.
    let current = view.result_is_current();
    if !current {
        ui.horizontal_wrapped(|ui| {
            ui.spinner();
            let (done, of) = view.progress.unwrap_or((0, SPEEDS));
            let what = view.uses.as_ref().map_or_else(String::new, |u| format!(" on {}", u.bearings));
            ui.label(format!("Analysing{what}: speed {done} of {of} (bearings solved at each speed)…"));
        });
    }
    if view.case_invalid {
        ui.label(
            RichText::new("The edited case is invalid: the analysis shown is of its last valid version.").color(LIMIT.of(ui)),
        );
    }
    let (result, rotor) = match (&view.result, &view.result_rotor) {
        (Some(Ok(r)), Some(rotor)) => (r.clone(), rotor.clone()),
        (Some(Err(e)), _) => {
            ui.label(RichText::new(format!("Analysis failed: {e}")).color(LIMIT.of(ui)));
            return save;
        }
        _ => return save,
    };
    if let Some(uses) = &view.result_uses {
        let line = uses.sentence();
        if current {
            ui.label(line);
        } else {
            // Kept while the edited design is analysed, and said to be of the design it was computed for.
            ui.label(
                RichText::new(format!(
                    "Shown until the analysis above is done: the analysis of an earlier design (revision {}). {line}",
                    uses.revision
                ))
                .color(LIMIT.of(ui)),
            );
        }
    }
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
