//! The Control view: a shipped system with its loop closed through the controllable bearings' valves, chosen
//! in the view ([`System`]):
//!
//! - the active compressor rotor (`cases/rotors/compressor-rotor-active.toml`, PD loops) or the same rotor
//!   with the LQR tiltpad designs (`cases/rotors/compressor-rotor-lqr.toml`: its weights, the designed
//!   compensator's gains at the design speed's running frequency, its reduced model), its bearings on the
//!   **edited case** when it is a controllable bearing (it has `[hydraulics]`: a valve to close the loop
//!   through; at its fidelity, preview while a value is dragged), else on the shipped
//!   `compressor-bearing-active.toml` at preview fidelity — the view says which;
//! - the test rig closed by its shipped controller: X/F with control against without
//!   ([`super::control_rig`]).
//!
//! On a rotor, the sliders a designer turns — the loop gain and the PD gains of every loop — with, updated as
//! they move:
//!
//! - the **root locus** at one speed over the loop gain (the lightly damped poles, the open loop and the
//!   current gain marked), the gain and phase margins at each valve's input written on it;
//! - the **stability map**: the smallest logarithmic decrement against speed, loop open and closed, each
//!   onset marked;
//! - the **unbalance response** at one node through the critical speeds, open and closed, with the valve
//!   signal it needs against the valve's small-signal range.
//!
//! Two background jobs ([`crate::app::jobs::control`]): the sweep solves
//! the bearings once per speed and builds the plants ([`crate::control::analysis::ControlAnalysis`]); each
//! slider change closes the loop again on those plants ([`crate::control::tuning`]: an eigen-solution and a
//! complex solve per speed, no bearing solve). The onset on the map is interpolated between the sweep's
//! speeds (`tiltpad control` bisects it with new bearing solves).

use std::fmt::Write as _;
use std::sync::Arc;

use egui::{RichText, Ui};

use crate::app::jobs::control::{Build, Built, Tune, Tuned, Tuning, GAIN_RANGE, SPEEDS};
use super::control_plots::{locus_ui, stability_ui, unbalance_ui, LIMIT};
use super::control_rig::{rig_ui, RigPage};
use super::view::EditedBearing;
use super::{View, ViewContext};
use crate::app::jobs::{Event, Runner};
use crate::app::frame_probe::Job;
use crate::bearing::stages::StageId;
use crate::control::analysis::ControlParams;
use crate::control::tuning::onset_on_grid;
use crate::model::control::{Control, Law, LqrSpec, PlantInfo, Quantity, Rule, SensorAt};
use crate::model::load_case;
use crate::model::rotor::{parse_rotor_file, BearingSupport, Rotor};
use crate::units::{MM, RPM, UM};

/// The shipped active rotors (PD loops, LQR) and their bearing case.
const ROTOR_NAME: &str = "compressor-rotor-active.toml";
const ROTOR_TEXT: &str = include_str!("../../../cases/rotors/compressor-rotor-active.toml");
const LQR_NAME: &str = "compressor-rotor-lqr.toml";
const LQR_TEXT: &str = include_str!("../../../cases/rotors/compressor-rotor-lqr.toml");
const BEARING_NAME: &str = "compressor-bearing-active.toml";
const BEARING_TEXT: &str = include_str!("../../../cases/compressor-bearing-active.toml");

/// Speeds of the sweep [rpm]: from `FIRST_RPM` to `MAX_FACTOR` × the top of the operating range (the LQR
/// raises the onset far above it: its sweep goes to `LQR_MAX_FACTOR` ×).
const FIRST_RPM: f64 = 2000.0;
const MAX_FACTOR: f64 = 1.3;
const LQR_MAX_FACTOR: f64 = 2.0;
/// Width of a slider's track [points]: two sliders with their values and names fit a row of 450 points.
const SLIDER_WIDTH: f32 = 80.0;
/// Ranges of the PD sliders (every PD loop): kp [V/µm], kd [V per mm/s].
const KP_RANGE: [f64; 2] = [-0.2, 0.2];
const KD_RANGE: [f64; 2] = [-0.5, 0.5];


/// The shipped systems the view closes a loop on.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum System {
    /// The active compressor rotor, each journal's displacement fed back to its valve (PD loops).
    #[default]
    RotorPd,
    /// The same rotor with the LQR tiltpad designs on its reduced model.
    RotorLqr,
    /// The test rig, its journal's vertical displacement fed back to its valve.
    Rig,
}

impl System {
    pub const ALL: [System; 3] = [System::RotorPd, System::RotorLqr, System::Rig];

    #[must_use]
    pub fn label(self) -> &'static str {
        match self {
            System::RotorPd => "Compressor rotor, PD loops",
            System::RotorLqr => "Compressor rotor, LQR",
            System::Rig => "Test rig, X/F with and without control",
        }
    }

    /// The rotor file's name and text (`None`: the rig).
    fn rotor(self) -> Option<(&'static str, &'static str)> {
        match self {
            System::RotorPd => Some((ROTOR_NAME, ROTOR_TEXT)),
            System::RotorLqr => Some((LQR_NAME, LQR_TEXT)),
            System::Rig => None,
        }
    }
}

/// The view's state (runtime; nothing persisted).
pub struct ControlView {
    /// The system shown (switching starts its analysis afresh).
    pub system: System,
    pub rig: RigPage,
    pub tuning: Tuning,
    /// Response node shown (index in the sweep's response nodes).
    pub node: usize,
    loaded: Option<Result<(Rotor, Control), String>>,
    /// The bearing `loaded` runs on (`None`: not loaded yet), and the same said in words.
    loaded_on: Option<BearingChoice>,
    pub bearing_said: String,
    /// `built` (and `tuned`) are of an earlier bearing than `loaded`, kept on screen until the new ones come.
    built_earlier: bool,
    build: Option<Runner<Build>>,
    built: Option<Result<Arc<Built>, String>>,
    progress: Option<(usize, usize)>,
    tune: Option<Runner<Tune>>,
    submitted: Option<Tuning>,
    tuned: Option<Result<Arc<Tuned>, String>>,
}

impl Default for ControlView {
    fn default() -> Self {
        Self {
            system: System::default(),
            rig: RigPage::default(),
            tuning: Tuning { gain: 1.0, kp_v_per_um: None, kd_v_per_mm_s: None, locus_at: 0 },
            node: 0,
            loaded: None,
            loaded_on: None,
            bearing_said: String::new(),
            built_earlier: false,
            build: None,
            built: None,
            progress: None,
            tune: None,
            submitted: None,
            tuned: None,
        }
    }
}

/// The bearing case the rotor runs on: the edited one (its text, at preview fidelity or not), or the shipped
/// controllable case at preview fidelity.
#[derive(Debug, Clone, PartialEq)]
struct BearingChoice {
    edited: Option<String>,
    preview: bool,
}

impl BearingChoice {
    /// What the view runs on for the edited case `edited` (`None`: keep what it runs on).
    fn of(edited: &EditedBearing, now: Option<&BearingChoice>) -> Option<Self> {
        match &edited.text {
            Some(t) if edited.controllable => Some(Self { edited: Some(t.clone()), preview: edited.preview }),
            Some(_) => Some(Self { edited: None, preview: true }),
            None => now.cloned().or(Some(Self { edited: None, preview: true })),
        }
    }

    /// In words, for the view.
    fn said(&self, edited: &EditedBearing, rotor: Option<&Rotor>) -> String {
        let nodes: Vec<String> = rotor
            .map(|r| {
                r.bearings
                    .iter()
                    .filter(|b| matches!(b.support, BearingSupport::Case { .. }))
                    .map(|b| b.node.to_string())
                    .collect()
            })
            .unwrap_or_default();
        let at = format!("at nodes {}", nodes.join(", "));
        match &self.edited {
            Some(_) => {
                let fidelity = rotor
                    .and_then(|r| {
                        r.bearings.iter().find_map(|b| match &b.support {
                            BearingSupport::Case { case, .. } => Some(format!("{:?}", case.mesh.fidelity).to_lowercase()),
                            BearingSupport::Numbers(_) => None,
                        })
                    })
                    .unwrap_or_default();
                format!("Bearings: the edited case {} ({fidelity} fidelity) {at}", edited.name)
            }
            None => format!("Bearings: the shipped {BEARING_NAME} (preview) {at}: the edited case has no [hydraulics]"),
        }
    }
}

/// A shipped active rotor (`text`) with its bearing positions on `bearing` (the edited case, or the shipped
/// controllable one), and its controller.
fn load(text: &str, bearing: &BearingChoice) -> Result<(Rotor, Control), String> {
    let file = parse_rotor_file(text).map_err(|e| e.to_string())?;
    let read = |name: &str| {
        if name.rsplit('/').next() == Some(BEARING_NAME) {
            Ok(BEARING_TEXT.to_string())
        } else {
            Err(format!("{name}: not shipped with the Control view"))
        }
    };
    let mut rotor = file.resolve(&read).map_err(|e| e.to_string())?;
    let case_text = bearing.edited.as_deref().unwrap_or(BEARING_TEXT);
    for (b, table) in rotor.bearings.iter_mut().zip(&file.rotor.bearing) {
        if let BearingSupport::Case { case, .. } = &mut b.support {
            let preview = bearing.preview.then(|| "mesh.fidelity=\"preview\"".to_string());
            let set: Vec<String> = preview.into_iter().chain(table.set.clone()).collect();
            **case = load_case(case_text, &set).map_err(|e| e.to_string())?.1;
        }
    }
    let table = file.control.ok_or_else(|| crate::control::ControlError::NoController.to_string())?;
    let control = table.resolve(&PlantInfo::rotor(&rotor)).map_err(|e| e.to_string())?;
    Ok((rotor, control))
}

/// The response node (index) the view opens on: the rotor's first unbalance (on the compressor rotor the
/// mid-span impeller, whose response passes the first critical speed), else the first node.
fn first_unbalance(b: &Built, rotor: &Rotor) -> usize {
    let nodes = b.sweep.response_nodes();
    rotor.unbalances.first().and_then(|u| nodes.iter().position(|n| *n == u.node)).unwrap_or(0)
}

/// The sweep's speeds [rad/s] (the LQR's sweep reaches further).
#[must_use]
pub fn speeds(rotor: &Rotor, control: &Control) -> Vec<f64> {
    let factor = if matches!(control.law, Law::Lqr(_)) { LQR_MAX_FACTOR } else { MAX_FACTOR };
    let top_rpm = rotor.operating_range.map_or(12_000.0, |[_, b]| RPM.from_si(b)) * factor;
    #[allow(clippy::cast_precision_loss)]
    (0..SPEEDS).map(|i| RPM.to_si(FIRST_RPM + (top_rpm - FIRST_RPM) * i as f64 / (SPEEDS - 1) as f64)).collect()
}

/// The PD gains shared by every loop [V/µm, V per mm/s] (`None` unless every loop is PD with the same gains).
fn shared_pd(control: &Control) -> Option<(f64, f64)> {
    let Law::Loops(loops) = &control.law else { return None };
    let mut gains = loops.iter().map(|l| match l.rule {
        Rule::Pd { kp, kd, .. } => Some((kp * UM.to_si(1.0), kd * MM.to_si(1.0))),
        Rule::TransferFunction { .. } => None,
    });
    let first = gains.next()??;
    gains.all(|g| g == Some(first)).then_some(first)
}

/// `control` with the sliders' PD gains in every loop.
fn tuned_control(control: &Control, t: &Tuning) -> Control {
    let mut c = control.clone();
    if let (Law::Loops(loops), Some(kp), Some(kd)) = (&mut c.law, t.kp_v_per_um, t.kd_v_per_mm_s) {
        for l in loops {
            if let Rule::Pd { kp: p, kd: d, .. } = &mut l.rule {
                *p = kp / UM.to_si(1.0);
                *d = kd / MM.to_si(1.0);
            }
        }
    }
    c.gain = t.gain;
    c
}

impl ControlView {
    /// Nothing is being computed.
    #[must_use]
    pub fn is_idle(&self) -> bool {
        self.build.as_ref().is_none_or(|r| !r.busy())
            && self.tune.as_ref().is_none_or(|r| !r.busy())
            && self.rig.is_idle()
    }

    /// Shows `system`: its analysis starts afresh (a running one is cancelled).
    pub fn show(&mut self, system: System) {
        if system != self.system {
            *self = Self { system, ..Self::default() };
        }
    }

    /// What the LQR design produced, once the sweep is done (`None` for another law).
    #[must_use]
    pub fn lqr(&self) -> Option<&crate::control::lqr::LqrDesign> {
        self.built.as_ref()?.as_ref().ok()?.lqr.as_ref()
    }

    /// The loop closed at the sliders, once computed.
    #[must_use]
    pub fn tuned(&self) -> Option<&Tuned> {
        self.tuned.as_ref().and_then(|t| t.as_ref().ok()).map(AsRef::as_ref)
    }

    /// The onset with the loop open [rad/s] (interpolated on the sweep), once the sweep is done.
    #[must_use]
    pub fn onset_open_rad_s(&self) -> Option<f64> {
        let b = self.built.as_ref()?.as_ref().ok()?;
        onset_on_grid(&b.sweep.speeds_rad_s, &b.open_log_dec)
    }

    /// The results shown are of an earlier bearing than the one the view now runs on (a new sweep is under
    /// way).
    #[must_use]
    pub fn shows_earlier_design(&self) -> bool {
        self.built_earlier
    }

    /// Loads the rotor on the bearing it runs on (again when the edited case changed), starts the sweep, and
    /// closes the loop again when a slider moved.
    fn drive(&mut self, ctx: &egui::Context, edited: &EditedBearing) {
        let Some((_, text)) = self.system.rotor() else { return };
        let busy = self.build.as_ref().is_some_and(Runner::busy);
        let choice = BearingChoice::of(edited, self.loaded_on.as_ref());
        if choice != self.loaded_on && !(edited.preview && busy && self.loaded.is_some()) {
            // Another bearing: a new sweep; what is on screen stays, said to be of an earlier design.
            self.built_earlier = self.built.is_some();
            (self.loaded, self.loaded_on, self.submitted) = (None, choice, None);
        }
        if self.loaded.is_none() {
            let Some(choice) = self.loaded_on.clone() else { return };
            let loaded = load(text, &choice);
            self.bearing_said = choice.said(edited, loaded.as_ref().ok().map(|(r, _)| r));
            if let Ok((rotor, control)) = &loaded {
                if let Some((kp, kd)) = shared_pd(control) {
                    (self.tuning.kp_v_per_um, self.tuning.kd_v_per_mm_s) = (Some(kp), Some(kd));
                }
                self.tuning.gain = control.gain;
                self.tuning.locus_at = SPEEDS * 2 / 3;
                let mut params = ControlParams::new(speeds(rotor, control));
                params.nyquist = false;
                self.build.get_or_insert_with(|| Runner::new(ctx)).submit(Build::new(
                    rotor.clone(),
                    control.clone(),
                    params,
                ));
            }
            self.loaded = Some(loaded);
        }
        if let Some(runner) = self.build.as_mut() {
            for e in runner.poll(crate::app::WEB_SOLVE_BUDGET_S) {
                match e {
                    #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
                    Event::Progress(p) => self.progress = Some((p.done as usize, p.of as usize)),
                    Event::Partial(_) => {}
                    Event::Done(b) => {
                        if let Some(Ok((rotor, _))) = &self.loaded {
                            self.node = first_unbalance(&b, rotor);
                        }
                        (self.built, self.progress, self.built_earlier, self.submitted) = (Some(Ok(b)), None, false, None);
                    }
                    Event::Failed(e) => {
                        (self.built, self.progress, self.built_earlier) = (Some(Err(e)), None, false);
                    }
                }
            }
        }
        let (Some(Ok(built)), Some(Ok((_, control)))) = (&self.built, &self.loaded) else { return };
        if self.submitted != Some(self.tuning) && !self.built_earlier {
            self.submitted = Some(self.tuning);
            let work = Tune::new(built.clone(), tuned_control(control, &self.tuning), self.tuning);
            self.tune.get_or_insert_with(|| Runner::new(ctx)).submit(work);
        }
        if let Some(runner) = self.tune.as_mut() {
            for e in runner.poll(crate::app::WEB_SOLVE_BUDGET_S) {
                match e {
                    Event::Done(t) => self.tuned = Some(Ok(t)),
                    Event::Failed(e) => self.tuned = Some(Err(e)),
                    Event::Progress(_) | Event::Partial(_) => {}
                }
            }
        }
    }
}

impl View for ControlView {
    fn id(&self) -> &'static str {
        "control"
    }

    fn label(&self) -> &'static str {
        "Control"
    }

    /// Nothing of the edited case: the view analyses its shipped rotor in the background.
    fn needs(&self) -> &'static [StageId] {
        &[]
    }

    fn ui(&mut self, ui: &mut Ui, cx: &mut ViewContext<'_>) {
        control_ui(ui, self, &cx.edited_bearing());
    }

    fn busy(&self) -> Option<Job> {
        (!self.is_idle()).then_some(Job::Control)
    }
}

/// Draws the view.
pub fn control_ui(ui: &mut Ui, view: &mut ControlView, edited: &EditedBearing) {
    let mut system = view.system;
    ui.horizontal(|ui| {
        let label = ui.label("System");
        egui::ComboBox::from_id_salt("control-system")
            .selected_text(system.label())
            .show_ui(ui, |ui| {
                for s in System::ALL {
                    ui.selectable_value(&mut system, s, s.label());
                }
            })
            .response
            .labelled_by(label.id);
    });
    view.show(system);
    let Some((name, _)) = view.system.rotor() else {
        rig_ui(ui, &mut view.rig);
        return;
    };
    view.drive(ui.ctx(), edited);
    let (title, control) = match &view.loaded {
        Some(Ok(l)) => (l.0.title.clone(), l.1.clone()),
        Some(Err(e)) => {
            ui.label(RichText::new(format!("Cannot read {name}: {e}")).color(LIMIT));
            return;
        }
        None => return,
    };
    // The rotor's title on hover: one line, so the plots keep their height at 1280×720.
    ui.label(RichText::new(format!("{name} — {SPEEDS} speeds")).strong()).on_hover_text(title);
    ui.label(&view.bearing_said).on_hover_text(
        "The loop closes through the bearings' servovalves: a case without [hydraulics] has none, and the shipped \
         controllable compressor bearing is used instead. Open it (File → Open preset) to edit the bearing the loop \
         runs on.",
    );
    let solving = view.build.as_ref().is_some_and(Runner::busy);
    if solving {
        ui.horizontal(|ui| {
            ui.spinner();
            let (done, of) = view.progress.unwrap_or((0, SPEEDS));
            ui.label(format!("Solving the bearings and building the loop: speed {done} of {of}…"));
        });
    }
    if view.built_earlier {
        ui.label(RichText::new("Shown until the new sweep is done: the results of an earlier design.").color(LIMIT));
    }
    let built = match &view.built {
        Some(Ok(b)) => b.clone(),
        Some(Err(e)) => {
            ui.label(RichText::new(format!("Analysis failed: {e}")).color(LIMIT));
            return;
        }
        None => return,
    };
    sliders_ui(ui, view, &built);
    let tuned = match &view.tuned {
        Some(Ok(t)) => t,
        Some(Err(e)) => {
            ui.label(RichText::new(format!("Closing the loop failed: {e}")).color(LIMIT));
            return;
        }
        None => {
            ui.spinner();
            return;
        }
    };
    let nodes = built.sweep.response_nodes();
    let onset_open = view.onset_open_rad_s();
    let mut node = view.node.min(nodes.len().saturating_sub(1));
    summary_ui(ui, &built, tuned, onset_open, node, control.actuators.len());
    if let (Law::Lqr(spec), Some(design)) = (&control.law, &built.lqr) {
        lqr_ui(ui, spec, design, &built.controller, &control);
    }
    let height = (ui.available_height() - 8.0).max(240.0);
    ui.columns(2, |cols| {
        locus_ui(&mut cols[0], tuned, height);
        // Above the two plots: the stability legend, the node selector and the unbalance legend (which wraps
        // to two lines in a narrow column): four rows of widgets and their spacing.
        let half = (height - 4.0 * cols[1].spacing().interact_size.y - 24.0) / 2.0;
        stability_ui(&mut cols[1], &built, tuned, onset_open, half.max(100.0));
        unbalance_ui(&mut cols[1], &built, tuned, &nodes, &mut node, half.max(100.0));
    });
    view.node = node;
}

fn sliders_ui(ui: &mut Ui, view: &mut ControlView, built: &Built) {
    let t = &mut view.tuning;
    let rpm: Vec<f64> = built.sweep.speeds_rad_s.iter().map(|w| RPM.from_si(*w)).collect();
    let last = rpm.len().saturating_sub(1);
    // Two sliders a row: the central panel between the editor and the results is about 490 points wide at
    // 1280×720, and a row wider than it would widen the whole view under the side panels (cutting the
    // second slider's text); the row wraps rather than widen a narrower view.
    ui.spacing_mut().slider_width = SLIDER_WIDTH;
    ui.horizontal_wrapped(|ui| {
        ui.add(egui::Slider::new(&mut t.gain, GAIN_RANGE[0]..=GAIN_RANGE[1]).step_by(0.05).text("loop gain"))
            .on_hover_text("Multiplies the whole controller: 0 opens the loop, −1 flips its sign.");
        ui.add(
            egui::Slider::new(&mut t.locus_at, 0..=last)
                .custom_formatter(|v, _| {
                    #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
                    let i = (v.round().max(0.0) as usize).min(last);
                    format!("{:.0} rpm", rpm.get(i).copied().unwrap_or(0.0))
                })
                .text("root locus at"),
        );
    });
    if t.kp_v_per_um.is_some() || t.kd_v_per_mm_s.is_some() {
        ui.horizontal_wrapped(|ui| {
            if let Some(kp) = t.kp_v_per_um.as_mut() {
                ui.add(egui::Slider::new(kp, KP_RANGE[0]..=KP_RANGE[1]).step_by(0.005).text("kp [V/µm]"))
                    .on_hover_text("Displacement gain of every loop.");
            }
            if let Some(kd) = t.kd_v_per_mm_s.as_mut() {
                ui.add(egui::Slider::new(kd, KD_RANGE[0]..=KD_RANGE[1]).step_by(0.01).text("kd [V/(mm/s)]"))
                    .on_hover_text("Velocity gain of every loop.");
            }
        });
    }
}

fn rpm_text(w: Option<f64>) -> String {
    w.map_or_else(|| "none in the sweep".to_string(), |w| format!("{:.0} rpm", RPM.from_si(w)))
}

fn summary_ui(ui: &mut Ui, built: &Built, tuned: &Tuned, onset_open: Option<f64>, node: usize, actuators: usize) {
    let peak = |orbits: &mut dyn Iterator<Item = &Vec<crate::rotor::unbalance::Orbit>>| {
        orbits.filter_map(|o| o.get(node)).map(|o| o.major_pp_m).fold(0.0, f64::max)
    };
    let open_peak = peak(&mut built.open_orbits.iter());
    let closed_peak = peak(&mut tuned.speeds.iter().map(|s| &s.orbits));
    let change = match (tuned.onset_rad_s, onset_open) {
        (Some(c), Some(o)) => format!(" ({:+.1} %)", 100.0 * (c - o) / o),
        _ => String::new(),
    };
    ui.label(format!(
        "Onset of instability: loop open {}, closed {}{change}. Unbalance peak at the node shown: open {:.1} µm pp, closed {:.1} µm pp.",
        rpm_text(onset_open),
        rpm_text(tuned.onset_rad_s),
        UM.from_si(open_peak),
        UM.from_si(closed_peak)
    ));
    let mut saturates = Vec::new();
    let mut text = String::from("Largest valve signal in that response:");
    for a in 0..actuators {
        let most = tuned.speeds.iter().filter_map(|s| s.signal_v.get(a)).copied().fold(0.0, f64::max);
        let limit = built.sweep.limits_v.get(a).copied().unwrap_or(f64::INFINITY);
        let _ = write!(text, " actuator {a} {most:.3} V of {limit:.2} V;");
        if most > limit {
            saturates.push(a);
        }
    }
    if saturates.is_empty() {
        ui.label(format!("{} inside the small-signal range.", text.trim_end_matches(';')));
    } else {
        ui.label(RichText::new(format!("{} saturates: actuators {saturates:?}.", text.trim_end_matches(';'))).color(LIMIT));
    }
}

/// A sensor's place and direction, as the table names it ("journal 0 x", "node 26 y").
fn sensor_name(s: &crate::model::control::Sensor) -> String {
    let dir = match s.direction {
        crate::model::control::Axis::X => "x",
        crate::model::control::Axis::Y => "y",
    };
    match s.at {
        SensorAt::Journal(b) => format!("journal {b} {dir}"),
        SensorAt::Node(n) => format!("node {n} {dir}"),
    }
}

/// The LQR's weights and what the design made of them: per sensor its weight and the compensator's gain to
/// each valve at the design speed's running frequency (magnitude and phase; the compensator is dynamic, its
/// gain depends on the frequency), the valves' weights, the reduced model.
fn lqr_ui(
    ui: &mut Ui,
    spec: &LqrSpec,
    design: &crate::control::lqr::LqrDesign,
    controller: &crate::control::state_space::StateSpace,
    control: &Control,
) {
    let hz = design.design_speed_rad_s / std::f64::consts::TAU;
    // Closed at first: open, the table leaves the plots below it too short at 1280×720.
    let title = format!(
        "LQR design at {:.0} rpm: weights and the compensator's gains",
        RPM.from_si(design.design_speed_rad_s)
    );
    egui::CollapsingHeader::new(title).id_salt("control-lqr-design").default_open(false).show(ui, |ui| {
        lqr_table_ui(ui, spec, design, controller, control, hz);
    });
}

/// The LQR design's table (in [`lqr_ui`]'s collapsing section).
fn lqr_table_ui(
    ui: &mut Ui,
    spec: &LqrSpec,
    design: &crate::control::lqr::LqrDesign,
    controller: &crate::control::state_space::StateSpace,
    control: &Control,
    hz: f64,
) {
    ui.label(format!(
        "On {} of the plant's {} states (modes below {:.0} Hz), observer noise {}; the compensator's gains at \
         the running frequency:",
        design.reduced_states,
        design.full_states,
        spec.max_frequency_rad_s / std::f64::consts::TAU,
        spec.sensor_noise
    ));
    let k = controller.response(crate::control::state_space::C64::new(0.0, design.design_speed_rad_s));
    let valves = control.actuators.len();
    egui::Grid::new("control-lqr-gains").striped(true).spacing([10.0, 0.0]).show(ui, |ui| {
        ui.label("sensor");
        ui.label("weight q");
        for a in 0..valves {
            ui.label(format!("valve {a} at {hz:.0} Hz"));
        }
        ui.end_row();
        for (i, sensor) in control.sensors.iter().enumerate() {
            let (unit, gain_unit) = match sensor.quantity {
                Quantity::Displacement => ("1/µm²", "V/µm"),
                Quantity::Velocity => ("1/(mm/s)²", "V/(mm/s)"),
            };
            ui.label(sensor_name(sensor));
            ui.label(format!("{} {unit}", spec.output_weight.get(i).copied().unwrap_or(0.0)));
            for a in 0..valves {
                let g = k.as_ref().map(|k| k[(a, i)] * sensor.quantity.reading_unit());
                ui.label(g.map_or("—".to_string(), |g| {
                    format!("{:.4} {gain_unit}, {:+.0}°", g.norm(), g.arg().to_degrees())
                }));
            }
            ui.end_row();
        }
        ui.label("valve weight r");
        ui.label("");
        for a in 0..valves {
            ui.label(format!("{} 1/V²", spec.input_weight.get(a).copied().unwrap_or(0.0)));
        }
        ui.end_row();
    });
}
