//! Pieces the plots of several views share, so every plot reads the same way:
//!
//! - [`legend_ui`]: the legend as a row of coloured names above the plot, never over the curves or the
//!   controls (egui_plot's legend is drawn inside the plot frame);
//! - [`decade_label`]: tick labels of a log10 axis as the numbers they stand for (`0.01`, `1`, `1k`), on
//!   the grid of [`log_spacer`] (decades, and 2 and 5 within a decade when there is room);
//! - [`labelled_spacer`]: a linear grid whose labelled step is at least a given number of points apart, and
//!   [`LabelledAxes`]: plot axes on that grid, labelled with the digits their step needs;
//! - [`wrapped_phase`]: a phase curve folded into (−180°, 180°], cut where it wraps, with [`PHASE_TICKS`]
//!   (labelled every 90°) as the axis' grid;
//! - [`footer_height`]: the room the lines below a drawing take, measured before the drawing is laid out;
//! - [`text_within`]: a title painted into a drawing, cut with "…" at the width it has rather than over
//!   its neighbours;
//! - [`NamedPlot`]: a plot's name for screen readers and UI tests (`plot: <what it shows>`).

use egui::{Color32, RichText, Ui};

/// Curve colours readable on both the dark and the light theme: each keeps a contrast of at least 3:1
/// against both backgrounds (relative luminance between about 0.12 and 0.3; no yellow, no pale blue).
pub const PALETTE: [Color32; 8] = [
    Color32::from_rgb(0, 114, 178),
    Color32::from_rgb(213, 94, 0),
    Color32::from_rgb(0, 158, 115),
    Color32::from_rgb(190, 100, 150),
    Color32::from_rgb(160, 120, 0),
    Color32::from_rgb(120, 100, 220),
    Color32::from_rgb(0, 150, 170),
    Color32::from_rgb(128, 128, 128),
];

/// One legend entry: the curve's name and colour.
pub type LegendEntry = (String, Color32);

/// The legend of a plot as a row that wraps: per entry a short line in the curve's colour (an image
/// labelled `legend: <name>` for screen readers and tests) and the name.
pub fn legend_ui(ui: &mut Ui, entries: &[LegendEntry]) {
    const SAMPLE: egui::Vec2 = egui::vec2(16.0, 12.0);
    ui.horizontal_wrapped(|ui| {
        for (name, color) in entries {
            // Whole: an entry (sample and name) that does not fit the row moves to the next one, rather than
            // leaving its sample at the end of one row and its name on the next.
            let text = egui::WidgetText::from(RichText::new(name).color(*color));
            let galley = text.into_galley(ui, Some(egui::TextWrapMode::Extend), f32::INFINITY, egui::TextStyle::Body);
            let width = SAMPLE.x + ui.spacing().item_spacing.x + galley.size().x;
            let row_started = ui.cursor().min.x > ui.max_rect().min.x + 0.5;
            if row_started && width > ui.available_size_before_wrap().x {
                ui.end_row();
            }
            let (rect, sample) = ui.allocate_exact_size(SAMPLE, egui::Sense::hover());
            sample.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Image, true, format!("legend: {name}")));
            ui.painter().line_segment([rect.left_center(), rect.right_center()], egui::Stroke::new(2.5, *color));
            ui.add(egui::Label::new(galley));
            ui.add_space(6.0);
        }
    });
}

/// Names a shown plot: egui_plot leaves its area an unnamed node, which a screen reader announces as
/// nothing. The name says what the plot shows (`plot: X/F [µm/kN] against frequency [Hz]`).
pub trait NamedPlot {
    fn named(self, name: &str);
}

impl<R> NamedPlot for egui_plot::PlotResponse<R> {
    fn named(self, name: &str) {
        self.response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Image, true, format!("plot: {name}")));
    }
}

/// A decade tick of a log10 axis (`value` = log10 of the number) as the number it stands for, with an SI
/// prefix from 1000 on: −2 → "0.01", 0 → "1", 3 → "1k", 6 → "1M". Off-decade values (a zoomed axis) get
/// three significant digits.
#[must_use]
pub fn decade_label(value: f64) -> String {
    let v = 10f64.powf(value);
    let (scaled, prefix) = match v {
        v if v >= 1e9 => (v / 1e9, "G"),
        v if v >= 1e6 => (v / 1e6, "M"),
        v if v >= 1e3 => (v / 1e3, "k"),
        v => (v, ""),
    };
    format!("{}{prefix}", crate::number::sig(scaled, 3))
}

/// The smallest of 1, 2, 5 × 10ⁿ at least `x` (> 0).
#[must_use]
pub fn nice_up(x: f64) -> f64 {
    if !(x.is_finite() && x > 0.0) {
        return 1.0;
    }
    let decade = 10f64.powf(x.log10().floor());
    [1.0, 2.0, 5.0, 10.0].into_iter().map(|m| m * decade).find(|&s| s >= x * (1.0 - 1e-12)).unwrap_or(10.0 * decade)
}

/// A linear axis grid on 1-2-5 steps whose largest step is at least `label_px` points apart, so that
/// egui_plot labels it (it labels a step only when its marks stand 60 points apart on x, 20 on y): a
/// 1000–13 000 rpm axis 500 points wide gets labels every 2000 rpm rather than one label at 10 000.
pub fn labelled_spacer(label_px: f64) -> impl Fn(egui_plot::GridInput) -> Vec<egui_plot::GridMark> {
    egui_plot::uniform_grid_spacer(move |input| {
        // `base_step_size` is the value spanned by the plot's minimum grid spacing (8 points).
        let per_px = input.base_step_size / 8.0;
        nested_steps(per_px, label_px)
    })
}

/// The three grid steps of [`labelled_spacer`] for an axis of `per_px` value per point: the labelled step
/// (at least `label_px` points), a middle step that divides it, and the finest (at least 8 points). egui_plot
/// labels every step that stands far enough apart, so a middle step that did not divide the labelled one
/// (2 beside 5) wrote its numbers between the labelled ones: "4000 5000 6000" 35 points apart on a speed
/// axis, "0.6 0.5 0.4" on top of each other on a short plot. After 5 × 10ⁿ the middle step is 10ⁿ.
#[must_use]
pub fn nested_steps(per_px: f64, label_px: f64) -> [f64; 3] {
    let label = nice_up(per_px * label_px);
    let mantissa = label / 10f64.powf(label.log10().floor());
    let middle = if (mantissa - 5.0).abs() < 1e-9 { label / 5.0 } else { nice_up(0.25 * label).min(label) };
    [nice_up(per_px * 8.0).min(middle), middle, label]
}

/// Linear axes labelled on [`labelled_spacer`]'s grid with the digits their step needs
/// ([`crate::number::tick`]: steps of 0.05 read 0.45, not 0.5 twice), as plot builder methods.
pub trait LabelledAxes: Sized {
    /// The x axis: labelled steps at least `label_px` points apart.
    #[must_use]
    fn labelled_x(self, label_px: f64) -> Self;
    /// The y axis: labelled steps at least `label_px` points apart.
    #[must_use]
    fn labelled_y(self, label_px: f64) -> Self;
}

impl LabelledAxes for egui_plot::Plot<'_> {
    fn labelled_x(self, label_px: f64) -> Self {
        self.x_grid_spacer(labelled_spacer(label_px)).x_axis_formatter(|m, _| crate::number::tick(m.value, m.step_size))
    }

    fn labelled_y(self, label_px: f64) -> Self {
        self.y_grid_spacer(labelled_spacer(label_px)).y_axis_formatter(|m, _| crate::number::tick(m.value, m.step_size))
    }
}

/// The grid of a log10 axis (plotted values are log10 of the numbers): lines at 1 … 9 × 10ⁿ, labels at
/// the decades and, where a decade spans enough points (less than about two decades shown), at 2 and 5 ×
/// 10ⁿ too, so a chart over one decade of S reads "0.5, 1, 2" rather than a lone "1". egui_plot labels a
/// mark by its `step_size` against the room it needs; 2 and 5 are given the step log10(5/2) (they stand
/// that far from each other), the other lines 0.1.
pub fn log_spacer(input: egui_plot::GridInput) -> Vec<egui_plot::GridMark> {
    let (lo, hi) = input.bounds;
    if !(lo.is_finite() && hi.is_finite()) || hi - lo > 60.0 {
        return Vec::new();
    }
    let mut marks = Vec::new();
    // Decades of a plotted range (checked finite and under 60 wide above): small integers.
    #[allow(clippy::cast_possible_truncation, clippy::cast_precision_loss)]
    for decade in ((lo.floor() as i64)..=(hi.ceil() as i64)).map(|n| n as f64) {
        for m in 1..=9_u32 {
            let value = decade + f64::from(m).log10();
            if value < lo || value > hi {
                continue;
            }
            let step_size = match m {
                1 => 1.0,
                2 | 5 => 2.5_f64.log10(),
                _ => 0.1,
            };
            marks.push(egui_plot::GridMark { value, step_size });
        }
    }
    marks
}

/// Grid steps of a phase axis in degrees: lines every 30°, labels every 90° and 180°.
pub const PHASE_TICKS: [f64; 3] = [30.0, 90.0, 180.0];

/// Phase in (−180°, 180°].
#[must_use]
pub fn wrap_deg(phase: f64) -> f64 {
    let p = phase.rem_euclid(360.0);
    if p > 180.0 {
        p - 360.0
    } else {
        p
    }
}

/// The points `(x, phase)` with the phase folded into (−180°, 180°], as pieces cut where the folded phase
/// jumps by more than 180° (a wrap, not a change of the response), so no line crosses the plot at a wrap.
#[must_use]
pub fn wrapped_phase(x: &[f64], phase_deg: &[f64]) -> Vec<Vec<[f64; 2]>> {
    let mut pieces: Vec<Vec<[f64; 2]>> = Vec::new();
    let mut last: Option<f64> = None;
    for (&x, &p) in x.iter().zip(phase_deg) {
        let w = wrap_deg(p);
        match (last, pieces.last_mut()) {
            (Some(prev), Some(piece)) if (w - prev).abs() <= 180.0 => piece.push([x, w]),
            _ => pieces.push(vec![[x, w]]),
        }
        last = Some(w);
    }
    pieces
}

/// The tick label of a phase axis: whole degrees with the degree sign.
#[must_use]
pub fn phase_label(value: f64) -> String {
    format!("{value:.0}°")
}

/// Height [points] of the lines a view writes below its drawing: each `(text, style)` wrapped at `width`,
/// with the item spacing between them (and a little slack), so the drawing can leave exactly that room and
/// the last line stays inside the view at 1280×720.
#[must_use]
pub fn footer_height(ui: &Ui, width: f32, lines: &[(&str, egui::TextStyle)]) -> f32 {
    let color = ui.visuals().text_color();
    let gap = ui.spacing().item_spacing.y;
    lines
        .iter()
        .map(|(text, style)| {
            let font = style.resolve(ui.style());
            ui.painter().layout((*text).to_string(), font, color, width).size().y + gap
        })
        .sum::<f32>()
        + 2.0 * gap
}

/// Paints `text` at `pos` (anchored by `align`) on one line of at most `width` points, cut with "…" when
/// longer; returns where it was painted.
pub fn text_within(
    painter: &egui::Painter,
    pos: egui::Pos2,
    align: egui::Align2,
    text: &str,
    font: egui::FontId,
    color: Color32,
    width: f32,
) -> egui::Rect {
    let mut job = egui::text::LayoutJob::simple_singleline(text.to_string(), font, color);
    job.wrap = egui::text::TextWrapping::truncate_at_width(width.max(0.0));
    let galley = painter.layout_job(job);
    let rect = align.anchor_size(pos, galley.size());
    painter.galley(rect.min, galley, color);
    rect
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every labelled-looking step divides the labelled one: a 0–13 000 rpm axis 450 points wide labels
    /// 5000 and 10 000 with lines every 1000 (it labelled 2000 steps too: 4000 beside 5000); a 60-point
    /// ε plot over 0.1–0.6 labels 0.5 steps (it wrote 0.4, 0.5 and 0.6 onto each other); 1 and 2 keep
    /// their quarter steps.
    #[test]
    fn grid_steps_nest_so_no_label_falls_between_labelled_ones() {
        let close = |a: [f64; 3], b: [f64; 3]| a.iter().zip(b).all(|(x, y)| (x - y).abs() <= 1e-12 * y);
        let speed = nested_steps(13_000.0 / 450.0, 70.0);
        assert!(close(speed, [500.0, 1000.0, 5000.0]), "{speed:?}");
        let eps = nested_steps(0.52 / 60.0, 24.0);
        assert!(close(eps, [0.1, 0.1, 0.5]), "{eps:?}");
        let one = nested_steps(0.8 / 24.0, 24.0);
        assert!(close(one, [0.5, 0.5, 1.0]), "{one:?}");
        for per_px in [1e-4, 3.3e-3, 0.07, 1.9, 28.9, 640.0] {
            for label_px in [24.0, 32.0, 60.0, 70.0, 80.0] {
                let [fine, middle, label] = nested_steps(per_px, label_px);
                let divides = |a: f64, b: f64| ((b / a) - (b / a).round()).abs() < 1e-9;
                assert!(divides(middle, label) && fine <= middle, "{per_px} {label_px}: {fine} {middle} {label}");
                assert!(label / per_px >= label_px * (1.0 - 1e-9), "{per_px} {label_px}");
            }
        }
    }

    use crate::app::ink::contrast;

    /// Every curve colour against egui's dark and light panel fills, at least 3:1 (WCAG's minimum for
    /// graphics and large text).
    #[test]
    fn the_palette_reads_on_both_themes() {
        let backgrounds = [egui::Visuals::dark().panel_fill, egui::Visuals::light().panel_fill];
        for c in PALETTE {
            for bg in backgrounds {
                assert!(contrast(c, bg) >= 3.0, "{c:?} on {bg:?}: {:.2}", contrast(c, bg));
            }
        }
    }

    #[test]
    fn nice_steps_are_one_two_five() {
        let steps: Vec<f64> = [0.7, 1.0, 1.3, 2.5, 4.0, 7.0, 1440.0].map(nice_up).to_vec();
        assert_eq!(steps, [1.0, 1.0, 2.0, 5.0, 5.0, 10.0, 2000.0]);
    }

    /// The unbalance plot's speed axis, 1000–13 221 rpm over 500 points: egui_plot labels steps whose marks
    /// stand 60 points apart or more; the spacer gives labels every 2000 rpm (82 points apart, six of them), where the default
    /// decade grid labelled only 10 000.
    #[test]
    fn a_speed_axis_gets_several_labelled_ticks() {
        let (lo, hi, px) = (1000.0, 13_221.0, 500.0);
        let input = egui_plot::GridInput { bounds: (lo, hi), base_step_size: (hi - lo) / px * 8.0 };
        let marks = labelled_spacer(70.0)(input);
        let labelled: Vec<f64> =
            marks.iter().filter(|m| m.step_size * px / (hi - lo) >= 60.0).map(|m| m.value).collect();
        assert_eq!(labelled, [2000.0, 4000.0, 6000.0, 8000.0, 10_000.0, 12_000.0]);
        // An amplitude axis of 0–65 µm over 150 points, labels 20 points apart or more: every 20 µm.
        let input = egui_plot::GridInput { bounds: (0.0, 65.0), base_step_size: 65.0 / 150.0 * 8.0 };
        let labelled: Vec<f64> = labelled_spacer(32.0)(input)
            .iter()
            .filter(|m| m.step_size * 150.0 / 65.0 >= 20.0)
            .map(|m| m.value)
            .collect();
        assert_eq!(labelled, [0.0, 20.0, 40.0, 60.0]);
    }

    #[test]
    fn decades_read_as_numbers() {
        let labels: Vec<String> = [-2.0, -1.0, 0.0, 1.0, 2.0, 3.0, 4.0, 6.0].map(decade_label).to_vec();
        assert_eq!(labels, ["0.01", "0.1", "1", "10", "100", "1k", "10k", "1M"]);
        assert_eq!(decade_label(0.5), "3.16");
    }

    #[test]
    fn phase_is_folded_and_cut_at_each_wrap() {
        assert_eq!([wrap_deg(-190.0), wrap_deg(180.0), wrap_deg(-180.0), wrap_deg(725.0)], [170.0, 180.0, 180.0, 5.0]);
        // A lag growing from 0 to −540°: folded, it wraps at −180° twice, so three pieces.
        let x: Vec<f64> = (0..=54).map(f64::from).collect();
        let p: Vec<f64> = x.iter().map(|k| -10.0 * k).collect();
        let pieces = wrapped_phase(&x, &p);
        assert_eq!(pieces.len(), 3, "{pieces:?}");
        assert!(pieces.iter().flatten().all(|q| q[1] > -180.0 && q[1] <= 180.0));
        assert_eq!(pieces.iter().map(Vec::len).sum::<usize>(), x.len());
        // Each piece is continuous.
        assert!(pieces.iter().all(|s| s.windows(2).all(|w| (w[1][1] - w[0][1]).abs() <= 10.0 + 1e-9)));
    }
}
