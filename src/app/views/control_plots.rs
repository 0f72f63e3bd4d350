//! The Control view's plots on a rotor: the root locus over the loop gain at one speed (margins written on
//! it), the stability map (smallest log decrement against speed, loop open and closed, onsets marked) and the
//! unbalance response at one node through the critical speeds with the API 617 line. Each takes the sweep's
//! plants ([`Built`]) and the loop closed at the sliders' gains ([`Tuned`]) and draws; nothing is computed
//! here but the curves' points.

use std::fmt::Write as _;

use egui::{Color32, RichText, Ui};
use egui_plot::{HLine, Line, LineStyle, Plot, PlotPoint, Points, Text, VLine};

use super::plot_kit::{legend_ui, LabelledAxes, NamedPlot, PALETTE};
use crate::app::jobs::control::{Built, Tuned, GAIN_RANGE};
use crate::units::{RPM, UM};

/// The root locus shows poles up to [`crate::app::jobs::control::LOCUS_MAX_HZ`] and this damping ratio.
const LOCUS_MAX_DAMPING: f64 = 0.25;
/// Loop open and closed, in every plot of the view.
pub const OPEN: Color32 = PALETTE[0];
pub const CLOSED: Color32 = PALETTE[1];
/// Warnings (saturation, a failed analysis).
pub const LIMIT: Color32 = Color32::from_rgb(213, 94, 0);
/// The API 617 line (dotted grey: the closed loop's colour is the warning's).
pub const API: Color32 = Color32::from_gray(150);

/// Room right of a plot's frame [points]: half the last x tick's label ("20000") is written past the frame.
const RIGHT_ROOM: f32 = 20.0;

pub fn plot(id: &str, ui: &Ui, height: f32) -> Plot<'static> {
    let width = (ui.available_width().min(ui.clip_rect().width()) - RIGHT_ROOM).max(100.0);
    Plot::new(id.to_string()).height(height).width(width).allow_scroll(false)
}

pub fn locus_ui(ui: &mut Ui, tuned: &Tuned, height: f32) {
    let l = &tuned.locus;
    let keep = |p: &[f64; 2]| {
        let mag = p[0].hypot(std::f64::consts::TAU * p[1]);
        -p[0] <= LOCUS_MAX_DAMPING * mag
    };
    let grey = Color32::from_gray(140);
    legend_ui(
        ui,
        &[
            (format!("locus, gain {:+} to {:+}", GAIN_RANGE[0], GAIN_RANGE[1]), grey),
            ("loop open".into(), OPEN),
            (format!("gain {:.2}", tuned.tuning.gain), CLOSED),
        ],
    );
    let gain_index = |g: f64| l.gains.iter().position(|x| (x - g).abs() < 1e-12);
    let locus: Vec<[f64; 2]> = l.poles.iter().flatten().filter(|p| keep(p)).copied().collect();
    let open: Vec<[f64; 2]> =
        gain_index(0.0).map(|i| l.poles[i].iter().filter(|p| keep(p)).copied().collect()).unwrap_or_default();
    let current: Vec<[f64; 2]> = tuned
        .speeds
        .get(tuned.tuning.locus_at.min(tuned.speeds.len().saturating_sub(1)))
        .map(|s| {
            s.poles
                .modes
                .iter()
                .map(|m| [m.real_per_s, m.frequency_hz()])
                .filter(|p| p[1] <= l.max_hz && keep(p))
                .collect()
        })
        .unwrap_or_default();
    let x_min = locus.iter().chain(&current).map(|p| p[0]).fold(-1.0, f64::min);
    let x_max = locus.iter().chain(&current).map(|p| p[0]).fold(1.0, f64::max);
    // Room above the poles for the margins written in the plot's top-left corner.
    let y_top = 1.6 * locus.iter().chain(&current).map(|p| p[1]).fold(10.0, f64::max);
    let mut margins = format!("{:.0} rpm, loop broken at each valve", RPM.from_si(l.speed_rad_s));
    for (a, (gm, pm, p)) in tuned.margins.iter().enumerate() {
        let gm = gm.map_or("—".to_string(), |g| format!("{g:.1} dB"));
        let pm = pm.map_or("—".to_string(), |p| format!("{p:.0}°"));
        let _ = write!(margins, "\nvalve {a}: GM {gm}, PM {pm}, P = {p}");
    }
    margins.push_str("\n(P: unstable poles of the broken loop)");
    // Above the plot: its legend, two rows when it wraps in a narrow column.
    let height = (height - 2.0 * ui.spacing().interact_size.y - 12.0).max(200.0);
    plot("control_root_locus", ui, height)
        .x_axis_label("real part [1/s]")
        .y_axis_label("damped frequency [Hz]")
        .labelled_x(60.0)
        .labelled_y(32.0)
        .include_x(x_min * 1.05)
        .include_x(x_max * 1.05)
        .include_y(0.0)
        .include_y(y_top)
        .show(ui, |p| {
            p.vline(VLine::new("stability boundary", 0.0).color(Color32::from_gray(120)));
            p.points(Points::new("locus", locus).radius(1.5).color(grey));
            p.points(Points::new("loop open", open).radius(4.0).shape(egui_plot::MarkerShape::Cross).color(OPEN));
            p.points(
                Points::new(format!("gain {:.2}", tuned.tuning.gain), current).radius(3.5).filled(true).color(CLOSED),
            );
            p.text(
                Text::new("margins", PlotPoint::new(x_min * 1.05, y_top), RichText::new(margins).small())
                    .anchor(egui::Align2::LEFT_TOP),
            );
        })
        .named("root locus, damped frequency [Hz] against real part [1/s]");
}

/// A plot against speed [rpm] from 0 up.
pub fn speed_plot(id: &str, y_label: &str, ui: &Ui, height: f32) -> Plot<'static> {
    plot(id, ui, height)
        .x_axis_label("speed [rpm]")
        .y_axis_label(y_label.to_string())
        .labelled_x(70.0)
        .labelled_y(28.0)
        .include_y(0.0)
}

/// The open loop dashed, the closed loop solid.
pub fn open_and_closed(p: &mut egui_plot::PlotUi<'_>, open: Vec<[f64; 2]>, closed: Vec<[f64; 2]>) {
    p.line(Line::new("loop open", open).color(OPEN).style(LineStyle::dashed_loose()).width(1.6));
    p.line(Line::new("loop closed", closed).color(CLOSED).width(2.0));
}

pub fn stability_ui(ui: &mut Ui, built: &Built, tuned: &Tuned, onset_open: Option<f64>, height: f32) {
    let rpm: Vec<f64> = built.sweep.speeds_rad_s.iter().map(|w| RPM.from_si(*w)).collect();
    let finite = |v: Vec<[f64; 2]>| v.into_iter().filter(|p| p[1].is_finite()).collect::<Vec<_>>();
    let open = finite(rpm.iter().zip(&built.open_log_dec).map(|(x, y)| [*x, *y]).collect());
    let closed = finite(rpm.iter().zip(&tuned.speeds).map(|(x, s)| [*x, s.poles.min_log_dec()]).collect());
    // The onsets are the vertical lines (their speeds are in the summary above).
    legend_ui(ui, &[("open (dashed)".to_string(), OPEN), (format!("gain {:.2}", tuned.tuning.gain), CLOSED)]);
    speed_plot("control_stability", "smallest log dec [–]", ui, height)
        .show(ui, |p| {
            p.hline(HLine::new("δ = 0", 0.0).color(Color32::from_gray(120)));
            open_and_closed(p, open, closed);
            if let Some(w) = onset_open {
                p.vline(VLine::new("onset open", RPM.from_si(w)).color(OPEN).style(LineStyle::dashed_loose()));
            }
            if let Some(w) = tuned.onset_rad_s {
                p.vline(VLine::new("onset closed", RPM.from_si(w)).color(CLOSED).width(2.0));
            }
        })
        .named("smallest log dec [–] against speed [rpm]");
}

pub fn unbalance_ui(ui: &mut Ui, built: &Built, tuned: &Tuned, nodes: &[usize], node: &mut usize, height: f32) {
    let rpm: Vec<f64> = built.sweep.speeds_rad_s.iter().map(|w| RPM.from_si(*w)).collect();
    let curve = |orbits: &mut dyn Iterator<Item = &Vec<crate::rotor::unbalance::Orbit>>| -> Vec<[f64; 2]> {
        rpm.iter().zip(orbits).filter_map(|(x, o)| o.get(*node).map(|o| [*x, UM.from_si(o.major_pp_m)])).collect()
    };
    let open = curve(&mut built.open_orbits.iter());
    let closed = curve(&mut tuned.speeds.iter().map(|s| &s.orbits));
    let api: Vec<[f64; 2]> =
        rpm.iter().zip(&built.api617_um).filter(|p| p.1.is_finite()).map(|(x, y)| [*x, *y]).collect();
    ui.horizontal(|ui| {
        let label = ui.label("Unbalance response at");
        egui::ComboBox::from_id_salt("control-node")
            .selected_text(format!("node {}", nodes.get(*node).copied().unwrap_or(0)))
            .show_ui(ui, |ui| {
                for (i, n) in nodes.iter().enumerate() {
                    ui.selectable_value(node, i, format!("node {n}"));
                }
            })
            .response
            .labelled_by(label.id);
    });
    legend_ui(ui, &[("open (dashed)".into(), OPEN), ("closed".into(), CLOSED), ("API 617 (dotted)".into(), API)]);
    speed_plot("control_unbalance", "orbit p-p [µm]", ui, height)
        .show(ui, |p| {
            open_and_closed(p, open, closed);
            p.line(Line::new("API 617 limit", api).color(API).style(LineStyle::dotted_dense()).width(1.5));
        })
        .named("unbalance response, orbit p-p [µm] against speed [rpm]");
}
