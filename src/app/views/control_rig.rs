//! The Control view's test-rig page: the shipped rig (`cases/test-rig-pub5.toml`, configuration 2: the journal
//! free vertically on the rig's support, the calibrated shaker pushing on it) with its loop closed by the
//! shipped controller (`cases/controllers/test-rig-pub5-control.toml`), and the receptance X/F with control
//! against without — magnitude and phase over the band `tiltpad frf --control` documents (10–200 Hz, 1 Hz
//! apart), the same numbers ([`crate::control::rig::RigLoop::sweep`], called by both).
//!
//! The work runs off the UI thread ([`crate::app::job_runner`]; stepped per frame on the web): the FRF
//! stage (one bearing solve and its linearisation), then the loop closed over the band.

use egui::{Color32, RichText, Ui};
use egui_plot::{Line, LineStyle, Plot};

use super::plot_kit::{legend_ui, phase_label, wrapped_phase, LabelledAxes, NamedPlot, PALETTE, PHASE_TICKS};
use crate::app::job_runner::{Event, Runner, Work};
use crate::bearing::frf::model::{band, FrfModel};
use crate::bearing::{NoCancel, Stages};
use crate::control::rig::{RigLoop, RigSweep};
use crate::model::control::parse_control_file;
use crate::model::control::PlantInfo;
use crate::model::{load_case, Case};
use crate::units::{KN, UM};

pub const CASE_NAME: &str = "test-rig-pub5.toml";
const CASE_TEXT: &str = include_str!("../../../cases/test-rig-pub5.toml");
pub const CONTROLLER_NAME: &str = "controllers/test-rig-pub5-control.toml";
const CONTROLLER_TEXT: &str = include_str!("../../../cases/controllers/test-rig-pub5-control.toml");
/// The band [Hz] and its points (1 Hz apart), as in the controller file's header.
pub const BAND_HZ: [f64; 2] = [10.0, 200.0];
pub const BAND_POINTS: usize = 191;

const OPEN: Color32 = PALETTE[0];
const CLOSED: Color32 = PALETTE[1];
const LIMIT: Color32 = Color32::from_rgb(213, 94, 0);

/// The rig's loop as computed for the page.
pub struct RigShown {
    pub title: String,
    pub sweep: RigSweep,
}

/// The job: the FRF stage, then the loop over the band.
pub struct RigJob {
    case: Option<Case>,
    frf: Option<std::sync::Arc<FrfModel>>,
}

impl RigJob {
    /// The shipped rig and controller.
    ///
    /// # Errors
    /// The shipped case does not parse (a broken build).
    pub fn shipped() -> Result<Self, String> {
        let case = load_case(CASE_TEXT, &[]).map_err(|e| format!("{CASE_NAME}: {e}"))?.1;
        Ok(Self { case: Some(case), frf: None })
    }
}

impl Work for RigJob {
    type Output = RigShown;

    fn step(&mut self) -> Result<Option<RigShown>, String> {
        let case = self.case.as_ref().ok_or("the rig job already finished")?;
        let Some(frf) = &self.frf else {
            self.frf = Some(Stages::new().frf(case, &NoCancel).map_err(|e| format!("{CASE_NAME}: {e}"))?);
            return Ok(None);
        };
        let file = parse_control_file(CONTROLLER_TEXT).map_err(|e| format!("{CONTROLLER_NAME}: {e}"))?;
        let control = file.control.resolve(&PlantInfo::rig(case)).map_err(|e| format!("{CONTROLLER_NAME}: {e}"))?;
        let sweep = RigLoop::new(case, frf, &control)
            .and_then(|l| l.sweep(&band(BAND_HZ[0], BAND_HZ[1], BAND_POINTS)))
            .map_err(|e| format!("closing the rig's loop: {e}"))?;
        let title = format!("{} — {CASE_NAME} closed by {CONTROLLER_NAME}", case.title);
        self.case = None;
        Ok(Some(RigShown { title, sweep }))
    }

    fn progress(&self) -> (usize, usize) {
        (usize::from(self.frf.is_some()), 2)
    }
}

/// The page's state.
#[derive(Default)]
pub struct RigPage {
    runner: Option<Runner<RigJob>>,
    shown: Option<Result<RigShown, String>>,
}

impl RigPage {
    /// The loop over the band, once computed.
    #[must_use]
    pub fn shown(&self) -> Option<&RigShown> {
        self.shown.as_ref().and_then(|s| s.as_ref().ok())
    }

    #[must_use]
    pub fn is_idle(&self) -> bool {
        self.runner.as_ref().is_none_or(|r| !r.busy())
    }

    fn drive(&mut self, ctx: &egui::Context) {
        if self.shown.is_none() && self.runner.is_none() {
            match RigJob::shipped() {
                Ok(job) => {
                    let mut runner = Runner::new(ctx.clone());
                    runner.start(job);
                    self.runner = Some(runner);
                }
                Err(e) => self.shown = Some(Err(e)),
            }
        }
        if let Some(runner) = self.runner.as_mut() {
            for e in runner.poll() {
                if let Event::Done(r) = e {
                    self.shown = Some(r);
                }
            }
        }
    }
}

/// µm/kN from m/N.
fn um_per_kn(x: f64) -> f64 {
    UM.from_si(x * KN.to_si(1.0))
}

/// Draws the page.
pub fn rig_ui(ui: &mut Ui, page: &mut RigPage) {
    page.drive(ui.ctx());
    let s = match &page.shown {
        Some(Ok(s)) => s,
        Some(Err(e)) => {
            ui.label(RichText::new(format!("The rig's loop failed: {e}")).color(LIMIT));
            return;
        }
        None => {
            ui.horizontal(|ui| {
                ui.spinner();
                ui.label(format!("Solving {CASE_NAME} and closing its loop…"));
            });
            return;
        }
    };
    let sw = &s.sweep;
    ui.label(RichText::new(&s.title).strong());
    let ((open, fo), (closed, fc)) = (sw.peak(false), sw.peak(true));
    let at_open_peak = sw.points.iter().find(|p| p.frequency_hz == fo).map_or(0.0, |p| p.closed_m_per_n);
    let signal = sw.signal_v_per_n();
    let stability = if sw.stable {
        RichText::new(format!("Loop gain {}: stable, smallest log dec {:.3}.", sw.gain, sw.min_log_dec))
    } else {
        RichText::new(format!("Loop gain {}: UNSTABLE, smallest log dec {:.3}.", sw.gain, sw.min_log_dec)).color(LIMIT)
    };
    ui.label(stability);
    ui.label(format!(
        "X/F peak: without control {:.1} µm/kN at {fo:.0} Hz, with control {:.1} µm/kN at {fc:.0} Hz ({:+.0} %); \
         at {fo:.0} Hz with control {:.1} µm/kN.",
        um_per_kn(open),
        um_per_kn(closed),
        100.0 * (closed - open) / open,
        um_per_kn(at_open_peak)
    ));
    ui.label(format!(
        "Valve signal up to {:.2} V per kN of shaker force: the small-signal range ({:.2} V) holds to {:.0} N.",
        signal * KN.to_si(1.0),
        sw.limit_v,
        if signal > 0.0 { sw.limit_v / signal } else { f64::INFINITY }
    ));
    legend_ui(ui, &[("without control (dashed)".to_string(), OPEN), ("with control".to_string(), CLOSED)]);
    let f: Vec<f64> = sw.points.iter().map(|p| p.frequency_hz).collect();
    let height = ((ui.available_height() - 12.0) / 2.0).max(120.0);
    let width = ui.available_width().min(ui.clip_rect().width());
    let magnitude = |closed: bool| -> Vec<[f64; 2]> {
        sw.points
            .iter()
            .map(|p| [p.frequency_hz, um_per_kn(if closed { p.closed_m_per_n } else { p.open_m_per_n })])
            .collect()
    };
    Plot::new("control_rig_magnitude")
        .height(height)
        .width(width)
        .allow_scroll(false)
        .x_axis_label("frequency [Hz]")
        .y_axis_label("X/F [µm/kN]")
        .labelled_x(60.0)
        .labelled_y(80.0)
        .include_y(0.0)
        .show(ui, |p| {
            p.line(
                Line::new("without control", magnitude(false)).color(OPEN).style(LineStyle::dashed_loose()).width(1.6),
            );
            p.line(Line::new("with control", magnitude(true)).color(CLOSED).width(2.0));
        })
        .named("X/F [µm/kN] against frequency [Hz]");
    let phase = |closed: bool| -> Vec<f64> {
        sw.points.iter().map(|p| if closed { p.closed_phase_deg } else { p.open_phase_deg }).collect()
    };
    Plot::new("control_rig_phase")
        .height(height)
        .width(width)
        .allow_scroll(false)
        .x_axis_label("frequency [Hz]")
        .y_axis_label("phase [deg]")
        .labelled_x(60.0)
        .y_grid_spacer(egui_plot::uniform_grid_spacer(|_| PHASE_TICKS))
        .y_axis_formatter(|m, _| phase_label(m.value))
        .include_y(-180.0)
        .include_y(180.0)
        .show(ui, |p| {
            for piece in wrapped_phase(&f, &phase(false)) {
                p.line(Line::new("without control", piece).color(OPEN).style(LineStyle::dashed_loose()).width(1.6));
            }
            for piece in wrapped_phase(&f, &phase(true)) {
                p.line(Line::new("with control", piece).color(CLOSED).width(2.0));
            }
        })
        .named("phase of X/F [°] against frequency [Hz]");
}
