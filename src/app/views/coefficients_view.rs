//! Reduced stiffness and damping against ω/Ω or speed (from a background sweep): direct and cross terms
//! on plots of their own scale, legends above the plots, the case's own point marked, a pinned result's
//! curves overlaid, and the full coefficient matrices as a table (folded away until opened).

use egui::{Color32, Grid, RichText, ScrollArea, Ui};
use egui_plot::{GridInput, GridMark, Line, LineStyle, MarkerShape, Plot, Points, VLine};
use serde::{Deserialize, Serialize};

use crate::app::ink;
use super::plot_kit::{legend_ui, NamedPlot, PALETTE};
use super::{View, ViewContext};
use crate::app::Shown;
use crate::bearing::stages::StageId;
use crate::number::tick;
use crate::scene::field::nice_ticks;
use crate::scene::plots::{self, CoefficientPlot, MatrixTable};

/// The coefficient view.
#[derive(Debug, Default)]
pub struct CoefficientsView {
    pub settings: CoefficientSettings,
}

/// What the coefficient view keeps between sessions.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct CoefficientSettings {
    pub axis: CoefficientAxis,
}

/// Abscissa of the coefficient plots.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
pub enum CoefficientAxis {
    #[default]
    FrequencyRatio,
    Speed,
}

impl CoefficientsView {
    fn axis_ui(&mut self, ui: &mut Ui) {
        let axis = &mut self.settings.axis;
        ui.horizontal(|ui| {
            ui.label("Against");
            ui.selectable_value(axis, CoefficientAxis::FrequencyRatio, "excitation frequency ratio ω/Ω");
            ui.selectable_value(axis, CoefficientAxis::Speed, "speed (background sweep)");
        });
    }

    /// The plot of `shown` against the chosen axis (`None`: its sweep is still running).
    fn plot(&self, shown: &Shown) -> Option<CoefficientPlot> {
        let sol = &shown.solution;
        match self.settings.axis {
            CoefficientAxis::FrequencyRatio => shown
                .frequency_sweep
                .as_ref()
                .map(|f| plots::frequency_plot(f, Some((sol.inputs.operating.excitation_ratio, sol.reduced)))),
            CoefficientAxis::Speed => {
                shown.speed_sweep.as_ref().map(|p| plots::speed_plot(p, Some((sol.derived.speed_rpm, sol.reduced))))
            }
        }
    }
}

impl View for CoefficientsView {
    fn id(&self) -> &'static str {
        "coefficients"
    }

    fn label(&self) -> &'static str {
        "Coefficients"
    }

    fn needs(&self) -> &'static [StageId] {
        match self.settings.axis {
            CoefficientAxis::FrequencyRatio => &[StageId::Reduction, StageId::FrequencySweep],
            CoefficientAxis::Speed => &[StageId::Reduction, StageId::SpeedSweep],
        }
    }

    fn ui(&mut self, ui: &mut Ui, cx: &mut ViewContext<'_>) {
        self.axis_ui(ui);
        let Some(shown) = cx.shown else { return };
        let pinned =
            cx.compare_with_ui(ui, self.needs(), |_| {}).and_then(|(name, p)| self.plot(&p).map(|plot| (name, plot)));
        match self.plot(shown) {
            Some(p) => coefficient_plots_ui(ui, &p, pinned.as_ref().map(|(n, p)| (n.as_str(), p))),
            None => {
                ui.horizontal(|ui| {
                    ui.spinner();
                    ui.label("Sweeping in the background…");
                });
            }
        }
        ui.separator();
        matrix_table_ui(ui, &plots::matrix_table(&shown.solution.full));
    }

    fn placeholder_ui(&mut self, ui: &mut Ui, _cx: &mut ViewContext<'_>) {
        self.axis_ui(ui);
        super::view::waiting_ui(ui);
    }

    fn settings(&mut self) -> Option<&mut dyn super::view::Settings> {
        Some(&mut self.settings)
    }
}

/// One colour per entry xx, xy, yx, yy (readable on both themes).
const COLORS: [Color32; 4] = [PALETTE[0], PALETTE[1], PALETTE[2], PALETTE[3]];

/// The direct (xx, yy) and the cross (xy, yx) entries, plotted on scales of their own: the direct terms
/// are often ten times the cross terms and would flatten them on one scale.
const DIRECT: [usize; 2] = [0, 3];
const CROSS: [usize; 2] = [1, 2];

/// Line style and marker per series, distinct so that coinciding curves are told apart.
const SERIES_STYLES: [(LineStyle, MarkerShape); 4] = [
    (LineStyle::Solid, MarkerShape::Circle),
    (LineStyle::Dashed { length: 8.0 }, MarkerShape::Square),
    (LineStyle::Dotted { spacing: 5.0 }, MarkerShape::Up),
    (LineStyle::Dashed { length: 3.0 }, MarkerShape::Cross),
];

/// What a plot shows: its id, title, unit and abscissa.
struct PlotSpec<'a> {
    id: &'a str,
    title: &'a str,
    unit: &'a str,
    x_label: &'a str,
}

/// The entries `which` (indices into xx, xy, yx, yy) of `series`; `pinned`: a pinned result's name and
/// series, drawn wide and faint in the same colours. The legend is a row above the plot.
#[allow(clippy::too_many_arguments)]
fn plot_ui(
    ui: &mut Ui,
    spec: &PlotSpec<'_>,
    which: [usize; 2],
    series: &[crate::scene::plots::Series],
    current: Option<(f64, [f64; 4])>,
    pinned: Option<(&str, &[crate::scene::plots::Series])>,
    height: f32,
) {
    let PlotSpec { id, title, unit, x_label } = *spec;
    ui.label(RichText::new(format!("{title} [{unit}]")).strong());
    let legend: Vec<(String, Color32)> =
        which.iter().filter_map(|&i| series.get(i).map(|s| (s.name.clone(), COLORS[i]))).collect();
    legend_ui(ui, &legend);
    let width = ui.available_width();
    Plot::new(id)
        .height(height)
        .width(width)
        .x_axis_label(x_label)
        .y_axis_label(unit)
        .allow_scroll(false)
        .x_grid_spacer(round_grid(70.0))
        .y_grid_spacer(round_grid(24.0))
        .x_axis_formatter(|mark, _| tick(mark.value, mark.step_size))
        .y_axis_formatter(|mark, _| tick(mark.value, mark.step_size))
        .show(ui, |p| {
            // Each series has its own dash and marker as well as its colour: coinciding curves (Kxx = Kyy
            // on a symmetric bearing) stay visible, the later one dashed over the earlier.
            for &i in &which {
                let Some(s) = series.get(i) else { continue };
                let (color, (style, marker)) = (COLORS[i], SERIES_STYLES[i]);
                p.line(Line::new(s.name.clone(), s.points.clone()).color(color).width(1.8).style(style));
                p.points(Points::new(s.name.clone(), s.points.clone()).color(color).shape(marker).radius(3.0));
            }
            if let Some((name, pinned)) = pinned {
                for &i in &which {
                    let Some(s) = pinned.get(i) else { continue };
                    p.line(
                        Line::new(format!("{} (pinned \"{name}\")", s.name), s.points.clone())
                            .color(COLORS[i].gamma_multiply(0.55))
                            .width(3.0)
                            .style(LineStyle::Dashed { length: 12.0 }),
                    );
                }
            }
            if let Some((x, values)) = current {
                p.vline(VLine::new("this case", x).color(Color32::from_gray(150)));
                for &i in &which {
                    p.points(
                        Points::new("this case", vec![[x, values[i]]])
                            .color(COLORS[i])
                            .shape(MarkerShape::Diamond)
                            .radius(6.0),
                    );
                }
            }
        }).named(&format!("{title} [{unit}] against {x_label}"));
}

/// Grid lines at round values (1, 2 or 5 × 10ⁿ apart, up to five labelled and at least `label_px` points
/// apart, so egui_plot labels them: it hides labels closer than about 60 points on x), with fainter lines
/// at a fifth of that step: the default decade grid leaves a 0–90 MN/m axis with a single label, and five
/// ticks on a 190-point x axis were all left unlabelled.
fn round_grid(label_px: f64) -> impl Fn(GridInput) -> Vec<GridMark> {
    move |input| round_marks(input, label_px)
}

#[allow(clippy::cast_possible_truncation, clippy::cast_precision_loss, clippy::cast_sign_loss, clippy::needless_pass_by_value)]
fn round_marks(input: GridInput, label_px: f64) -> Vec<GridMark> {
    let (lo, hi) = input.bounds;
    // `base_step_size` is the value spanned by the plot's minimum grid spacing (8 points).
    let points = (hi - lo).abs() / (input.base_step_size / 8.0).max(f64::MIN_POSITIVE);
    let count = ((points / label_px).floor() as usize).clamp(2, 5);
    let ticks = nice_ticks(lo, hi, count);
    let step = match ticks.as_slice() {
        [a, b, ..] => b - a,
        _ => return ticks.into_iter().map(|value| GridMark { value, step_size: (hi - lo).abs().max(1e-12) }).collect(),
    };
    let minor = step / 5.0;
    let (first, last) = ((lo / minor).ceil() as i64, (hi / minor).floor() as i64);
    let minors = (first..=last).map(|k| k as f64 * minor).filter(|v| ((v / step) - (v / step).round()).abs() > 1e-6);
    ticks
        .iter()
        .map(|&value| GridMark { value, step_size: step })
        .chain(minors.map(|value| GridMark { value, step_size: minor }))
        .collect()
}

/// Four plots in two columns: stiffness (left) and damping (right), direct terms above, cross terms
/// below, each on its own scale. `pinned`: a pinned result's name and plot, overlaid.
pub fn coefficient_plots_ui(ui: &mut Ui, plot: &CoefficientPlot, pinned: Option<(&str, &CoefficientPlot)>) {
    // Two rows of plots share what the view leaves after the matrices' header and the notes below.
    let h = ((ui.available_height() - 170.0) / 2.0).max(110.0);
    let spec = |id, title, unit| PlotSpec { id, title, unit, x_label: plot.x_label };
    let stiffness = pinned.map(|(n, p)| (n, p.stiffness.as_slice()));
    let damping = pinned.map(|(n, p)| (n, p.damping.as_slice()));
    let (k_now, c_now) = (plot.current.map(|c| (c.0, c.1)), plot.current.map(|c| (c.0, c.2)));
    ui.columns(2, |cols| {
        let [left, right] = cols else { return };
        plot_ui(left, &spec("stiffness", "Direct stiffness", "MN/m"), DIRECT, &plot.stiffness, k_now, stiffness, h);
        plot_ui(left, &spec("stiffness_cross", "Cross stiffness", "MN/m"), CROSS, &plot.stiffness, k_now, stiffness, h);
        plot_ui(right, &spec("damping", "Direct damping", "kN·s/m"), DIRECT, &plot.damping, c_now, damping, h);
        plot_ui(right, &spec("damping_cross", "Cross damping", "kN·s/m"), CROSS, &plot.damping, c_now, damping, h);
    });
    ui.label(
        RichText::new("Diamonds and the grey line: this case's point.")
            .small()
            .weak(),
    );
    if let Some((name, _)) = pinned {
        ui.label(RichText::new(format!("Wide faint dashed curves: pinned \"{name}\".")).small());
    }
    for (x, why) in &plot.failures {
        ui.label(RichText::new(format!("No solution at {x:.0}: {why}")).color(ink::WARNING.of(ui)));
    }
}

/// The full matrices.
pub fn matrix_table_ui(ui: &mut Ui, table: &MatrixTable) {
    egui::CollapsingHeader::new(RichText::new("Full coefficient matrices over journal and pad coordinates").strong())
        .id_salt("full-matrices")
        .show(ui, |ui| matrices_ui(ui, table));
}

fn matrices_ui(ui: &mut Ui, table: &MatrixTable) {
    ui.label("SI: force or moment per unit of the column coordinate.");
    ScrollArea::both().id_salt("matrices").show(ui, |ui| {
        for (name, m) in [("K (stiffness)", &table.k), ("C (damping)", &table.c), ("M (pad inertia)", &table.m)] {
            ui.label(name);
            Grid::new(name).striped(true).show(ui, |ui| {
                ui.label("");
                for h in &table.headers {
                    ui.label(h);
                }
                ui.end_row();
                for (h, row) in table.headers.iter().zip(m) {
                    ui.label(h);
                    for v in row {
                        ui.label(RichText::new(format!("{v:.3e}")).monospace());
                    }
                    ui.end_row();
                }
            });
            ui.add_space(6.0);
        }
    });
}
