//! The Control view's test-rig page: the shipped rig (`cases/test-rig-pub5.toml`, configuration 2: the journal
//! free vertically on the rig's support, the calibrated shaker pushing on it) with its loop closed by the
//! shipped controller (`cases/controllers/test-rig-pub5-control.toml`), and the receptance X/F with control
//! against without — magnitude and phase over the band `tiltpad frf --control` documents (10–200 Hz, 1 Hz
//! apart), the same numbers ([`crate::control::rig::RigLoop::sweep`], called by both).
//!
//! The work runs off the UI thread ([`crate::app::jobs::rig`]): the FRF stage (one bearing solve and its
//! linearisation), then the loop closed over the band.

use egui::{Color32, RichText, Ui};
use egui_plot::{Line, LineStyle, Plot};

use super::plot_kit::{legend_ui, phase_label, wrapped_phase, LabelledAxes, NamedPlot, PALETTE, PHASE_TICKS};
use crate::app::jobs::rig::{RigJob, RigShown, CASE_NAME};
use crate::app::jobs::{Event, Runner};
use crate::units::{KN, UM};

const OPEN: Color32 = PALETTE[0];
const CLOSED: Color32 = PALETTE[1];
const LIMIT: Color32 = Color32::from_rgb(213, 94, 0);

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
                    let mut runner = Runner::new(ctx);
                    runner.submit(job);
                    self.runner = Some(runner);
                }
                Err(e) => self.shown = Some(Err(e)),
            }
        }
        if let Some(runner) = self.runner.as_mut() {
            for e in runner.poll(crate::app::WEB_SOLVE_BUDGET_S) {
                match e {
                    Event::Done(r) => self.shown = Some(Ok(r)),
                    Event::Failed(e) => self.shown = Some(Err(e)),
                    Event::Progress(_) | Event::Partial(_) => {}
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
