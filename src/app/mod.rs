//! The workbench: an eframe app that edits a case, solves it in the background and shows the result.
//!
//! Layout: a menu bar; the editor on the left; the results panel on the right; a status bar; the views
//! (bearing cross-section, pad fields with flowlines, coefficients, pad deformation, FRFs, rotor, sweep …:
//! the list in [`views`]) in the centre, one tab each.
//!
//! State is split by lifetime: [`state::Persisted`] (the case and view settings, saved by eframe between
//! sessions) and the runtime state in [`WorkbenchApp`] (worker, shown result, dialogs) and its views.
//!
//! Solving is declarative: every frame the app derives the [`Request`] the screen needs from the current
//! case and view; when it differs from the last one submitted, the worker gets it (cancelling the running
//! job). While a value is dragged, requests are solved at preview fidelity and coalesced (the running one
//! finishes, then the latest value is taken), so the picture follows the drag. The last valid result
//! stays on screen while the case is invalid, solving or failed.

mod actions;
mod compare_views;
pub mod document;
pub mod editor;
pub mod file_event;
pub mod files;
mod frame;
pub mod frame_probe;
pub mod ink;
pub mod jobs;
pub mod notation;
pub mod open_dialog;
pub mod path_fields;
pub mod pinned;
pub mod presets;
pub mod save_dialog;
pub mod state;
pub mod sweep_run;
pub mod views;
#[cfg(target_arch = "wasm32")]
pub mod web;

use std::sync::Arc;

use web_time::Instant;

use crate::bearing::stages::{Outcome, Request, SpeedPoint, StageId};
use crate::bearing::{ReducedCoefficients, Solution};
use crate::model::{parse_case_file, Case, Fidelity};
use document::Document;
use files::Files;
use jobs::solve::{stage_of, SolveJob};
use jobs::{Event, Runner};
use state::Persisted;
use views::View;

/// Per-frame time the web build may spend stepping a job where no web worker runs it [s].
pub const WEB_SOLVE_BUDGET_S: f64 = 0.012;
/// What the results panel shows: the solution at the operating point (asked for whatever view is open).
const RESULTS_PANEL_NEEDS: &[StageId] = &[StageId::Reduction];

/// The result on screen.
#[derive(Clone)]
pub struct Shown {
    pub solution: Arc<Solution>,
    pub frequency_sweep: Option<Arc<Vec<(f64, ReducedCoefficients)>>>,
    pub speed_sweep: Option<Arc<Vec<SpeedPoint>>>,
    /// The bearing linearised for its injection ports (FRF view open, case with `[hydraulics]`).
    pub frf: Option<Arc<crate::bearing::frf::model::FrfModel>>,
}

/// What the solver is doing.
#[derive(Debug, Clone, PartialEq)]
pub enum Status {
    Idle,
    Solving { stage: Option<StageId>, fraction: f64 },
    Failed(String),
}

/// An action that would discard unsaved changes, waiting for the user's answer.
#[derive(Debug, Clone)]
pub enum Pending {
    Preset(usize),
    Open,
    Replace { name: String, path: Option<std::path::PathBuf>, text: String },
    Close,
}

/// The eframe app.
pub struct WorkbenchApp {
    pub persisted: Persisted,
    pub doc: Document,
    /// The edited case's solve.
    solver: Runner<SolveJob>,
    files: Files,
    submitted: Option<Request>,
    pub shown: Option<Shown>,
    pub status: Status,
    /// A value is being dragged in the editor.
    dragging: bool,
    /// Every view ([`views::all`]); the open one is named by `persisted.view`.
    views: Vec<Box<dyn View>>,
    /// Results of the pins the views compare with (kept or re-solved, never persisted).
    pinned: pinned::PinnedResults,
    pending: Option<Pending>,
    save_dialog: Option<save_dialog::SaveDialog>,
    open_dialog: Option<open_dialog::OpenDialog>,
    allow_close: bool,
    /// Messages for the status bar (file saved, errors of dialogs), set by [`Self::say`].
    pub notice: Option<String>,
    /// The case as it was when the notice was given: an edit since makes the notice history, and the
    /// status bar drops it ("Opened <file>" no longer describes an edited case).
    notice_for: Option<crate::model::CaseFile>,
    /// Smoothed duration of building a frame [s].
    pub frame_time_s: f64,
    /// Where the last frame's time went [ms]: menu, status and editor; results panel; view; solver events.
    pub frame_parts_ms: [f64; 4],
    /// Durations of the last frames [s].
    pub recent_frames_s: std::collections::VecDeque<f64>,
    /// Replace wall-clock times by dashes (reproducible screenshots).
    pub hide_timings: bool,
    /// Screen rectangle of the central view (for the PNG export).
    view_rect: Option<egui::Rect>,
    screenshot: Option<std::sync::mpsc::Receiver<Arc<egui::ColorImage>>>,
    /// Frame-time probe (web build with `?probe`): repaints continuously and logs frame times.
    probe: Option<frame_probe::FrameProbe>,
}

impl WorkbenchApp {
    /// The app as eframe creates it: the persisted state if any, else the default case.
    #[must_use]
    pub fn new(cc: &eframe::CreationContext<'_>) -> Self {
        let persisted: Option<Persisted> = cc.storage.and_then(|s| eframe::get_value(s, eframe::APP_KEY));
        Self::with_state(&cc.egui_ctx, persisted.unwrap_or_default())
    }

    /// The app with given persisted state (tests start from `Persisted::default()`).
    #[must_use]
    pub fn with_state(ctx: &egui::Context, persisted: Persisted) -> Self {
        let (name, text) = presets::default_preset();
        let restored = persisted.case_toml.as_deref().and_then(|t| parse_case_file(t, &[]).ok().map(|f| (f, t)));
        let doc = match restored {
            Some((file, source)) => {
                let mut doc =
                    Document::new(file, persisted.case_name.clone(), persisted.case_saved).with_source(source);
                doc.path.clone_from(&persisted.case_path);
                doc
            }
            // The shipped default is compiled in and checked by a unit test: not user input.
            #[allow(clippy::expect_used)]
            None => Document::new(parse_case_file(text, &[]).expect("the shipped default case parses"), name, true)
                .with_source(text),
        };
        ink::apply(ctx);
        notation::apply(ctx);
        let mut views = views::all();
        for v in &mut views {
            let id = v.id();
            if let (Some(json), Some(settings)) = (persisted.view_settings.get(id), v.settings()) {
                // Settings of an older layout leave the view's defaults.
                settings.read_json(json);
            }
        }
        Self {
            persisted,
            doc,
            solver: Runner::new(ctx),
            files: Files::new(ctx.clone()),
            submitted: None,
            shown: None,
            status: Status::Idle,
            dragging: false,
            views,
            pinned: pinned::PinnedResults::new(ctx.clone()),
            pending: None,
            save_dialog: None,
            open_dialog: None,
            allow_close: false,
            notice: None,
            notice_for: None,
            frame_time_s: 0.0,
            frame_parts_ms: [0.0; 4],
            recent_frames_s: std::collections::VecDeque::with_capacity(120),
            hide_timings: false,
            view_rect: None,
            screenshot: None,
            probe: None,
        }
    }

    /// Loads a case text as the document (after the unsaved-changes guard): every way of opening a case
    /// ends here. The views hear whether the new case has the same bearing ([`views::View::case_opened`]).
    pub fn load_text(&mut self, name: &str, path: Option<std::path::PathBuf>, text: &str) {
        match parse_case_file(text, &[]) {
            Ok(file) => {
                let before = self.doc.validation().as_ref().ok().map(|c| c.bearing.clone());
                self.doc.replace(file, name, path, text);
                let same_bearing = before.is_some_and(|b| self.doc.validation().as_ref().is_ok_and(|c| c.bearing == b));
                for view in &mut self.views {
                    view.case_opened(same_bearing);
                }
                self.say(format!("Opened {name}"));
            }
            Err(e) => self.say(format!("Cannot open {name}: {e}")),
        }
    }

    /// Shows `text` in the status bar until the case is edited.
    fn say(&mut self, text: String) {
        self.notice = Some(text);
        self.notice_for = Some(self.doc.file().clone());
    }

    /// Drops the notice once the case differs from the one it was given for.
    fn forget_stale_notice(&mut self) {
        if self.notice.is_some() && self.notice_for.as_ref() != Some(self.doc.file()) {
            self.notice = None;
            self.notice_for = None;
        }
    }

    /// Saves, exports and opens ask for a path in the workbench's own dialogs, as without a desktop portal.
    pub fn use_workbench_save_dialog(&mut self) {
        self.files.native_dialogs = false;
    }

    /// Screen rectangle of the central view in the last frame.
    #[must_use]
    pub fn view_rect(&self) -> Option<egui::Rect> {
        self.view_rect
    }

    /// Nothing is being solved (the edited case, a pin the views compare with, the open view's own work)
    /// and no result is pending.
    #[must_use]
    pub fn is_idle(&self) -> bool {
        !self.solver.busy() && !self.pinned.busy() && self.open_view().busy().is_none()
    }

    /// The open view.
    #[must_use]
    pub fn open_view(&self) -> &dyn View {
        self.views[self.open_index()].as_ref()
    }

    /// Where the open view is in the list (`persisted.view` not listed: the first).
    fn open_index(&self) -> usize {
        self.views.iter().position(|v| state::names_view(&self.persisted.view, v.id())).unwrap_or(0)
    }

    /// Opens the view of type `V`.
    pub fn open<V: View>(&mut self) {
        if let Some(v) = self.views.iter().find(|v| v.as_ref().as_any().is::<V>()) {
            self.persisted.view = v.id().to_string();
        }
    }

    /// The view of type `V` (`None`: not in the list).
    #[must_use]
    pub fn view<V: View>(&self) -> Option<&V> {
        self.views.iter().find_map(|v| v.as_ref().as_any().downcast_ref::<V>())
    }

    /// The view of type `V`, to change (`None`: not in the list).
    pub fn view_mut<V: View>(&mut self) -> Option<&mut V> {
        self.views.iter_mut().find_map(|v| v.as_mut().as_any_mut().downcast_mut::<V>())
    }

    /// Opens the view `id` as the UI test that walks the list snapshots it: the view sets itself up
    /// ([`View::snapshot_setup`]) and the case it names replaces the document. `false`: no such view.
    pub fn open_for_snapshot(&mut self, id: &str) -> bool {
        let Some(view) = self.views.iter_mut().find(|v| v.id() == id) else { return false };
        self.persisted.view = id.to_string();
        if let Some(text) = view.snapshot_setup() {
            self.load_text("snapshot case", None, text);
            self.notice = None;
        }
        true
    }

    /// What the frame probe files this frame under: the open view's own work first (a sweep, a rotor
    /// analysis), then the edited case's solve, a pin's, another view's work.
    fn probe_job(&self) -> frame_probe::Job {
        use frame_probe::Job;
        if let Some(job) = self.open_view().busy() {
            job
        } else if self.solver.busy() {
            let thd =
                self.submitted.as_ref().is_some_and(|r| r.case.thermal.model == crate::model::ThermalModelKind::Thd);
            Job::Solve {
                thd,
                stage: match self.status {
                    Status::Solving { stage, .. } => stage,
                    _ => None,
                },
            }
        } else if self.pinned.busy() {
            Job::Pin
        } else {
            self.views.iter().find_map(|v| v.busy()).unwrap_or(Job::Idle)
        }
    }

    /// The request the open view needs now ([`crate::scene::request`]), if the case is valid.
    fn wanted_request(&self) -> Option<Request> {
        let case = self.doc.validation().as_ref().ok()?;
        let case = if self.dragging && self.persisted.preview_while_dragging { preview(case) } else { case.clone() };
        Some(crate::scene::request::request(case, [RESULTS_PANEL_NEEDS, self.open_view().needs()]))
    }

    /// Submits the wanted request when it changed, and takes in the worker's events.
    fn drive_solver(&mut self) {
        self.submit_wanted();
        for event in self.solver.poll(WEB_SOLVE_BUDGET_S) {
            match event {
                Event::Progress(p) => self.status = Status::Solving { stage: stage_of(&p), fraction: p.fraction() },
                Event::Partial(outcome) => self.accept(outcome),
                Event::Done(outcome) => {
                    self.accept(outcome);
                    self.status = Status::Idle;
                }
                Event::Failed(error) => self.status = Status::Failed(error),
            }
        }
        // A dragged value that waited for the running solve goes now, in the frame that solve came back:
        // no frame shows the older value's result as solved.
        self.submit_wanted();
        // A pin's re-solve runs when the edited case is solved (on the web: in the frames it leaves free).
        if !self.solver.busy() {
            self.pinned.poll(WEB_SOLVE_BUDGET_S);
            self.pinned.complete(&mut self.persisted.pins);
        }
        self.pinned.retain(&self.persisted.pins);
    }

    /// Submits the request the screen needs when it differs from the last one submitted. While a value is
    /// dragged, the running (preview) solve finishes first and then the latest value is taken, so results
    /// keep coming during the drag; otherwise a newer request cancels the running one at once.
    fn submit_wanted(&mut self) {
        let Some(req) = self.wanted_request() else { return };
        let hold = self.dragging && self.solver.busy();
        if self.submitted.as_ref() != Some(&req) && !hold {
            self.solver.submit(SolveJob::new(req.clone()));
            self.submitted = Some(req);
            self.status = Status::Solving { stage: None, fraction: 0.0 };
        }
    }

    fn accept(&mut self, outcome: Outcome) {
        let Some(solution) = outcome.solution() else { return };
        // A speed sweep of the same case survives a first-phase result (the sweep follows in phase two).
        let keep_speed = self
            .shown
            .as_ref()
            .filter(|s| outcome.speed_sweep().is_none() && s.solution.inputs == solution.inputs)
            .and_then(|s| s.speed_sweep.clone());
        self.shown = Some(Shown {
            solution,
            frequency_sweep: outcome.frequency_sweep(),
            speed_sweep: outcome.speed_sweep().or(keep_speed),
            frf: outcome.get(StageId::Frf),
        });
    }

    /// Which case the shown result is of, against the edited one.
    #[must_use]
    pub fn shown_for(&self) -> ShownFor {
        match (&self.shown, self.doc.validation()) {
            (None, _) => ShownFor::Nothing,
            (Some(s), Ok(case)) if s.solution.inputs == *case => ShownFor::Edited,
            (Some(s), Ok(case)) if s.solution.inputs == preview(case) => ShownFor::EditedPreview,
            (Some(_), _) => ShownFor::Previous,
        }
    }

    /// The shown result is of an earlier case than the edited one (invalid, solving or failed); a preview
    /// solve of the edited case is not stale.
    #[must_use]
    pub fn result_is_stale(&self) -> bool {
        self.shown_for() == ShownFor::Previous
    }
}

/// Which case the result on screen is of ([`WorkbenchApp::shown_for`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ShownFor {
    /// No result yet.
    Nothing,
    /// The edited case.
    Edited,
    /// The edited case on the preview mesh (solved while a value is dragged).
    EditedPreview,
    /// An earlier case: before the last edit, or the last valid one of an invalid case.
    Previous,
}

/// The case at preview fidelity (explicit element counts dropped), for fast solves while dragging.
fn preview(case: &Case) -> Case {
    let mut c = case.clone();
    let (_, nz, no) = Fidelity::Preview.elements();
    let nx = Fidelity::Preview.circumferential_elements(c.bearing.longest_arc_rad());
    c.mesh.fidelity = Fidelity::Preview;
    c.mesh.circumferential_elements = nx;
    c.mesh.axial_elements = nz;
    c.mesh.orifice_elements = no;
    c
}

impl eframe::App for WorkbenchApp {
    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        let start = Instant::now();
        self.frame_ui(ui);
        let dt = start.elapsed().as_secs_f64();
        // The web build solves inside frames: say so in the browser console when one runs long.
        #[cfg(target_arch = "wasm32")]
        if dt > 0.033 {
            let [edit, results, view, solver] = self.frame_parts_ms;
            log::info!(
                "slow frame: {:.1} ms ({}): menu and editor {edit:.1}, results {results:.1}, view {view:.1}, solver events {solver:.1} ms",
                crate::units::MS.from_si(dt),
                if self.solver.busy() { "solving" } else { "idle" }
            );
        }
        self.frame_time_s = if self.frame_time_s == 0.0 { dt } else { 0.9 * self.frame_time_s + 0.1 * dt };
        if self.recent_frames_s.len() == 120 {
            self.recent_frames_s.pop_front();
        }
        self.recent_frames_s.push_back(dt);
        let job = self.probe_job();
        if let Some(probe) = self.probe.as_mut() {
            if let Some(summary) = probe.frame(start, dt, job) {
                log::info!("{summary}");
            }
            #[cfg(target_arch = "wasm32")]
            if let Some(page_ms) = web_sys::window().and_then(|w| w.performance()).map(|p| p.now()) {
                for line in probe.milestones(page_ms, dt, self.shown.is_some()) {
                    log::info!("{line}");
                }
            }
            ui.ctx().request_repaint();
        }
    }

    fn save(&mut self, storage: &mut dyn eframe::Storage) {
        self.persisted.case_toml = self.doc.text().ok();
        self.persisted.case_name.clone_from(&self.doc.name);
        self.persisted.case_path.clone_from(&self.doc.path);
        self.persisted.case_saved = !self.doc.is_dirty();
        for v in &mut self.views {
            let id = v.id();
            if let Some(json) = v.settings().and_then(|s| s.to_json()) {
                self.persisted.view_settings.insert(id.to_string(), json);
            }
        }
        eframe::set_value(storage, eframe::APP_KEY, &self.persisted);
    }
}
