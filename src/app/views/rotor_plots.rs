//! The rotor view's plots of an analysis ([`super::rotor_view`]): the Campbell diagram (damped frequency of
//! the lowest forward and backward modes over speed, the 1× line and the critical speeds), the stability
//! map (log decrement, the onset marked), a mode shape (deflected shaft, largest deflection 1), the
//! unbalance response (orbit peak-to-peak and phase at named nodes, the API 617 limit drawn and said in
//! words) and the undamped critical-speed map (critical speed against support stiffness on a log axis,
//! the bearings' k_xx, k_yy over speed and their crossings).
//!
//! Every curve comes from [`crate::scene::rotor`]; these functions only lay out and paint, in rpm, Hz, µm
//! and degrees as the axes say. Forward whirl is drawn blue and solid, backward orange and dashed.

use egui::{Color32, RichText, Stroke, Ui};
use egui_plot::{HLine, Line, LineStyle, Plot, Points, VLine};

use super::plot_kit::{
    decade_label, legend_ui, phase_label, wrapped_phase, LabelledAxes, NamedPlot, PALETTE, PHASE_TICKS,
};
use crate::app::ink::{self, Ink};
use crate::model::rotor::Rotor;
use crate::rotor::analysis::AnalysisResult;
use crate::rotor::eigen::Whirl;
use crate::scene::rotor::{mode_curves, mode_shape, unbalance_bode, MapDrawing};
use crate::units::{MM, RPM};

/// Modes per whirl direction on the Campbell diagram, the stability map and the mode picker.
const RANKS: usize = 4;

/// Forward whirl, disks on the sketch.
pub(super) const FORWARD: Color32 = Color32::from_rgb(0, 114, 178);
/// Backward whirl, bearings on the sketch and the map.
pub(super) const BACKWARD: Ink = Ink { dark: Color32::from_rgb(230, 159, 0), light: Color32::from_rgb(165, 110, 0) };
/// Limits crossed, onsets, critical speeds, failures.
pub(super) const LIMIT: Ink = ink::EXCEEDED;

/// The colour of a whirl direction (`backward`: the theme's backward colour).
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
                .widget_info(|| egui::WidgetInfo::labeled(egui::Role::Image, true, format!("legend: {label}")));
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

/// The Campbell diagram (`campbell`) or the stability map of the analysis.
pub(super) fn curves_ui(ui: &mut Ui, r: &AnalysisResult, rotor: &Rotor, campbell: bool) {
    let (limit, backward) = (LIMIT.of(ui), BACKWARD.of(ui));
    let c = mode_curves(r, rotor, RANKS);
    let height = (ui.available_height() - 10.0).max(160.0);
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
        .labelled_x(70.0)
        .labelled_y(32.0)
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
                        VLine::new("operating range", x)
                            .color(Color32::from_gray(150))
                            .style(LineStyle::dotted_dense()),
                    );
                }
            }
            if campbell {
                p.line(
                    Line::new("1×", c.one_x.to_vec()).color(Color32::from_gray(120)).style(LineStyle::dashed_dense()),
                );
                p.points(Points::new("1× critical speeds", c.critical.clone()).radius(5.0).color(limit));
            } else {
                p.hline(HLine::new("δ = 0", 0.0).color(Color32::from_gray(120)));
                if let Some(x) = c.onset_rpm {
                    p.vline(VLine::new(format!("onset {x:.0} rpm"), x).color(limit).width(2.0));
                }
            }
        })
        .named(&format!("{y_label} against speed [rpm]"));
}

/// The mode shape of the chosen mode (`indices`: speed and mode, clamped to the analysis) with their pickers.
pub(super) fn mode_shape_ui(
    ui: &mut Ui,
    (speed_index, mode_index): (&mut usize, &mut usize),
    r: &AnalysisResult,
    rotor: &Rotor,
) {
    let last = r.speeds.len().saturating_sub(1);
    *speed_index = (*speed_index).min(last);
    let index_rpm: Vec<f64> = (0..r.speeds.len()).map(|i| RPM.from_si(r.speeds[i].point.speed_rad_s)).collect();
    ui.horizontal(|ui| {
        ui.add(
            egui::Slider::new(speed_index, 0..=last)
                .custom_formatter(|v, _| format!("{:.0} rpm", index_rpm.get(nearest_index(v)).copied().unwrap_or(0.0)))
                .text("speed"),
        );
        let modes = &r.speeds[*speed_index].point.modes.modes;
        *mode_index = (*mode_index).min(modes.len().saturating_sub(1));
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
            .selected_text(describe(*mode_index))
            .show_ui(ui, |ui| {
                for i in 0..modes.len().min(2 * RANKS) {
                    ui.selectable_value(mode_index, i, describe(i));
                }
            })
            .response
            .labelled_by(label.id);
    });
    let Some(s) = mode_shape(r, rotor, *speed_index, *mode_index) else {
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
        .labelled_x(70.0)
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
        })
        .named("mode shape, deflection against axial position [mm]");
}

/// The unbalance response (orbit amplitude and phase) with the API 617 limit said in words.
pub(super) fn unbalance_ui(ui: &mut Ui, r: &AnalysisResult, rotor: &Rotor) {
    let limit = LIMIT.of(ui);
    let b = unbalance_bode(r, rotor);
    let over = !b.exceedances().is_empty();
    let sentence = b.api617_sentence();
    ui.label(if over { RichText::new(sentence).color(limit).strong() } else { RichText::new(sentence) });
    let colors: Vec<Color32> = PALETTE.iter().copied().cycle().take(b.nodes.len()).collect();
    let mut legend: Vec<(String, Color32)> = b.nodes.iter().zip(&colors).map(|(n, c)| (n.name.clone(), *c)).collect();
    legend.push(("API 617 limit 25.4 sqrt(12000/N) µm (dashed)".into(), limit));
    legend_ui(ui, &legend);
    let link = ui.scope_id().with("rotor_bode");
    let amplitude = |ui: &mut Ui, height: f32| {
        plot_without_legend("rotor_unbalance_amplitude", ui, height)
            .x_axis_label("speed [rpm]")
            .y_axis_label("orbit p-p [µm]")
            .labelled_x(70.0)
            .labelled_y(32.0)
            .include_y(0.0)
            .link_axis(link, [true, false])
            .show(ui, |p| {
                for (n, color) in b.nodes.iter().zip(&colors) {
                    p.line(Line::new(n.name.clone(), n.amplitude_um.clone()).color(*color).width(1.6));
                }
                p.line(
                    Line::new("API 617 limit", b.api617_um.clone())
                        .color(limit)
                        .style(LineStyle::dashed_dense())
                        .width(2.0),
                );
            })
            .named("unbalance response, orbit p-p [µm] against speed [rpm]");
    };
    let phase = |ui: &mut Ui, height: f32| {
        plot_without_legend("rotor_unbalance_phase", ui, height)
            .x_axis_label("speed [rpm]")
            .y_axis_label("phase of x [°]")
            .labelled_x(70.0)
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
            })
            .named("unbalance response, phase of x [°] against speed [rpm]");
    };
    // Amplitude over phase, each at least 120 points high; where the view is shorter than that, side by
    // side at its full height: at 1280×720 the rotor view leaves about 220 points under the legend, and
    // stacked, the phase plot's lower half (its −180° and its speed axis) ran past the view's bottom.
    let room = ui.available_height();
    if room - 20.0 >= 2.0 * 120.0 || ui.available_width() < 400.0 {
        let height = ((room - 20.0) / 2.0).max(120.0);
        amplitude(ui, height);
        phase(ui, height);
    } else {
        ui.columns(2, |c| {
            amplitude(&mut c[0], room - 10.0);
            phase(&mut c[1], room - 10.0);
        });
    }
}

/// The undamped critical-speed map with the bearings' stiffness over speed.
pub(super) fn critical_map_ui(ui: &mut Ui, m: &MapDrawing) {
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
        .labelled_y(32.0)
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
        })
        .named("undamped critical speed [rpm] against support stiffness [N/m]");
}

/// A slider value (an index held as `f64`) as an index.
#[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)] // rounded and clamped at 0
fn nearest_index(v: f64) -> usize {
    v.round().max(0.0) as usize
}
