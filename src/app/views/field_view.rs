//! Pad fields unwrapped onto (circumferential × axial): a colour map per pad with a legend, a hover
//! readout, the orifices, and optionally the flowlines of the mean film velocity.
//!
//! Each pad is drawn to scale (arc length horizontally, leading edge on the left, rotation to the right;
//! axial length vertically, +L/2 at the top). All pads share one colour range so they compare.

use std::collections::HashMap;
use std::sync::Arc;

use egui::{Align2, Color32, RichText, ColorImage, FontId, Pos2, Rect, Sense, Shape, Stroke, TextureHandle, TextureOptions, Ui, Vec2};

use crate::app::state::PadChoice;
use crate::bearing::Solution;
use crate::scene::colormap::ColorMap;
use crate::scene::field::{common_range, nice_ticks, FieldKind, PadMap};
use crate::scene::flowlines::{arrow_phase, arrowheads, orifice_sites, pad_flowlines, Flowline, FlowlineParams};
use crate::scene::summary::sig4;

/// Texture width and height of a rasterised pad.
const RASTER: (usize, usize) = (240, 160);

/// Derived drawables of the shown result, rebuilt when the result changes.
#[derive(Default)]
pub struct FieldCache {
    /// Identity of the solution the cache belongs to.
    solution: Option<Arc<Solution>>,
    maps: HashMap<FieldKind, (Vec<PadMap>, (f64, f64))>,
    /// Keyed by field, pad and whether the colour range is the pad's own (one pad shown) or common.
    textures: HashMap<(FieldKind, usize, bool), TextureHandle>,
    flowlines: HashMap<usize, Vec<Flowline>>,
}

impl FieldCache {
    fn sync(&mut self, solution: &Arc<Solution>) {
        if !self.solution.as_ref().is_some_and(|s| Arc::ptr_eq(s, solution)) {
            *self = Self { solution: Some(solution.clone()), ..Self::default() };
        }
    }

    fn maps(&mut self, solution: &Solution, kind: FieldKind) -> &(Vec<PadMap>, (f64, f64)) {
        self.maps.entry(kind).or_insert_with(|| {
            let maps = PadMap::all(solution, kind);
            let range = common_range(&maps);
            (maps, range)
        })
    }

    fn flowlines(&mut self, solution: &Solution, pad: usize) -> &[Flowline] {
        self.flowlines.entry(pad).or_insert_with(|| pad_flowlines(solution, pad, FlowlineParams::default()))
    }
}

/// What the hover readout says.
#[derive(Debug, Clone, PartialEq)]
pub struct Readout {
    pub pad: usize,
    pub theta_deg: f64,
    pub z_mm: f64,
    pub value: f64,
    pub cavitated: bool,
}

/// Maps a pad's (s, z) [m] into its screen rectangle (screen y down, +L/2 at the top).
struct ScreenFromPad {
    rect: Rect,
    s_len: f64,
    z0: f64,
    z_len: f64,
}

impl ScreenFromPad {
    #[allow(clippy::cast_possible_truncation)]
    fn map(&self, p: [f64; 2]) -> Pos2 {
        let fx = (p[0] / self.s_len) as f32;
        let fy = ((p[1] - self.z0) / self.z_len) as f32;
        Pos2::new(self.rect.left() + fx * self.rect.width(), self.rect.bottom() - fy * self.rect.height())
    }
    fn unmap(&self, q: Pos2) -> [f64; 2] {
        let fx = f64::from((q.x - self.rect.left()) / self.rect.width());
        let fy = f64::from((self.rect.bottom() - q.y) / self.rect.height());
        [fx * self.s_len, self.z0 + fy * self.z_len]
    }
}

/// Draws the field view; returns the hover readout, if any.
#[allow(clippy::too_many_lines)]
pub fn field_view_ui(ui: &mut Ui, cache: &mut FieldCache, solution: &Arc<Solution>, kind: FieldKind, pads: PadChoice, flowlines: bool) -> Option<Readout> {
    cache.sync(solution);
    let (maps, (mut lo, mut hi)) = cache.maps(solution, kind).clone();
    if maps.is_empty() {
        ui.label(format!("{} is not part of this result. {}", kind.label(), kind.meaning()));
        return None;
    }
    let (unit, scale) = kind.unit();
    let shown: Vec<&PadMap> = match pads {
        PadChoice::All => maps.iter().collect(),
        PadChoice::One(k) => maps.iter().filter(|m| m.pad == k).collect(),
    };
    // One pad alone gets its own colour range (more contrast); side by side, pads share one.
    let own_range = shown.len() == 1;
    if let (true, Some(m)) = (own_range, shown.first()) {
        (lo, hi) = (m.min, m.max);
    }
    ui.label(RichText::new("Rotation: left to right (s along the arc from the leading edge; z axial, +L/2 at the top)").small());
    let full = ui.available_rect_before_wrap();
    // The painted area; the readout is a real label below it (readable by screen readers and tests).
    let avail = Rect::from_min_max(full.min, full.max - Vec2::new(0.0, 48.0));
    let legend_w = 100.0;
    let gap = 16.0;
    let area = Rect::from_min_max(avail.min + Vec2::new(8.0, 22.0), avail.max - Vec2::new(legend_w, 24.0));
    let rects = pack(area, &shown, gap);
    let response = ui.allocate_rect(avail, Sense::hover());
    let painter = ui.painter_at(avail);
    let text = ui.visuals().text_color();
    let small = FontId::proportional(11.0);

    let mut readout = None;
    let ppm = rects.first().map_or(1.0, |(r, m)| f64::from(r.width()) / m.arc_length_m());
    for &(rect, map) in &rects {
        let tex = cache.textures.entry((kind, map.pad, own_range)).or_insert_with(|| {
            let r = map.raster(RASTER.0, RASTER.1, lo, hi);
            let image = ColorImage::from_rgba_unmultiplied([r.width, r.height], &r.rgba);
            ui.ctx().load_texture(format!("pad{}-{kind:?}", map.pad), image, TextureOptions::LINEAR)
        });
        painter.image(tex.id(), rect, Rect::from_min_max(Pos2::ZERO, Pos2::new(1.0, 1.0)), Color32::WHITE);
        painter.rect_stroke(rect, 0.0, Stroke::new(1.0, Color32::from_gray(160)), egui::StrokeKind::Outside);
        let frame = ScreenFromPad { rect, s_len: map.arc_length_m(), z0: map.z_m[0], z_len: map.length_m() };
        for o in orifice_sites(solution, map.pad) {
            #[allow(clippy::cast_possible_truncation)]
            let r = (o.radius_m * ppm) as f32;
            let color = if o.flow_m3_per_s > 0.0 { Color32::from_rgb(70, 160, 255) } else { Color32::WHITE };
            painter.circle_stroke(frame.map([o.s_m, o.z_m]), r, Stroke::new(1.5, color));
        }
        if flowlines {
            for (k, line) in cache.flowlines(solution, map.pad).iter().enumerate() {
                draw_flowline(&painter, &frame, line, arrow_phase(k));
            }
        }
        painter.text(rect.center_top() - Vec2::new(0.0, 2.0), Align2::CENTER_BOTTOM, format!("Pad {}", map.pad), FontId::proportional(13.0), text);
        painter.text(rect.left_bottom() + Vec2::new(0.0, 3.0), Align2::LEFT_TOP, format!("{:.0}°", map.theta_deg(0.0).rem_euclid(360.0)), small.clone(), text);
        painter.text(rect.right_bottom() + Vec2::new(0.0, 3.0), Align2::RIGHT_TOP, format!("{:.0}°", map.theta_deg(map.arc_length_m()).rem_euclid(360.0)), small.clone(), text);
        if let Some(pos) = response.hover_pos().filter(|p| rect.contains(*p)) {
            let [s, z] = frame.unmap(pos);
            if let Some(v) = map.sample(s, z) {
                readout = Some(Readout { pad: map.pad, theta_deg: map.theta_deg(s).rem_euclid(360.0), z_mm: z * 1e3, value: v * scale, cavitated: map.cavitated_at(s, z) });
                painter.circle_stroke(pos, 4.0, Stroke::new(1.0, Color32::WHITE));
            }
        }
    }
    let bottom = rects.iter().map(|(r, _)| r.bottom()).fold(area.top() + 160.0, f32::max);
    legend(&painter, Rect::from_min_max(Pos2::new(avail.right() - legend_w + 12.0, area.top()), Pos2::new(avail.right() - legend_w + 30.0, bottom)), kind, lo, hi, text);
    let line = match &readout {
        Some(r) => format!(
            "Pad {}  θ = {:.1}°  z = {:+.1} mm   {} = {:.4} {unit}{}",
            r.pad,
            r.theta_deg,
            r.z_mm,
            kind.label().to_lowercase(),
            r.value,
            if r.cavitated { "  (cavitated)" } else { "" }
        ),
        None => "Hover over a pad to read the value under the cursor.".into(),
    };
    ui.label(line);
    ui.label(format!(
        "Colour scale: {} [{unit}] from {} to {} (perceptually uniform). Hatched: cavitated film (ruptured, p = 0).",
        kind.label(),
        sig4(lo * scale),
        sig4(hi * scale)
    ));
    readout
}

/// Lays the pads out to a common scale in the grid (columns × rows) that makes them largest.
#[allow(clippy::cast_precision_loss, clippy::cast_possible_truncation)]
fn pack<'m>(area: Rect, maps: &[&'m PadMap], gap: f32) -> Vec<(Rect, &'m PadMap)> {
    let n = maps.len().max(1);
    let arc = maps.iter().map(|m| m.arc_length_m()).fold(0.0, f64::max) as f32;
    let len = maps.iter().map(|m| m.length_m()).fold(0.0, f64::max) as f32;
    if arc <= 0.0 || len <= 0.0 {
        return Vec::new();
    }
    let label_h = 34.0;
    let (cols, ppm) = (1..=n)
        .map(|cols| {
            let rows = n.div_ceil(cols);
            let w = (area.width() - gap * (cols - 1) as f32) / (cols as f32 * arc);
            let h = (area.height() - (label_h + gap) * (rows - 1) as f32) / (rows as f32 * len);
            (cols, w.min(h))
        })
        .fold((1, 0.0_f32), |best, c| if c.1 > best.1 { c } else { best });
    maps.iter()
        .enumerate()
        .map(|(k, m)| {
            let (col, row) = ((k % cols) as f32, (k / cols) as f32);
            let min = area.min + Vec2::new(col * (arc * ppm + gap), row * (len * ppm + label_h + gap));
            (Rect::from_min_size(min, Vec2::new(ppm * m.arc_length_m() as f32, ppm * m.length_m() as f32)), *m)
        })
        .collect()
}

/// A flowline with arrowheads every 70 points of length, starting at `phase` of that ([`arrowheads`]).
#[allow(clippy::cast_possible_truncation)]
fn draw_flowline(painter: &egui::Painter, frame: &ScreenFromPad, line: &Flowline, phase: f64) {
    let pts: Vec<Pos2> = line.points.iter().map(|&p| frame.map(p)).collect();
    let stroke = Stroke::new(1.2, Color32::from_rgba_unmultiplied(255, 255, 255, 200));
    let screen: Vec<[f64; 2]> = pts.iter().map(|p| [f64::from(p.x), f64::from(p.y)]).collect();
    painter.add(Shape::line(pts, stroke));
    for (tip, d) in arrowheads(&screen, 70.0, phase) {
        let (tip, d) = (Pos2::new(tip[0] as f32, tip[1] as f32), Vec2::new(d[0] as f32, d[1] as f32));
        let n = Vec2::new(-d.y, d.x);
        painter.add(Shape::convex_polygon(vec![tip, tip - d * 6.0 + n * 3.0, tip - d * 6.0 - n * 3.0], stroke.color, Stroke::NONE));
    }
}

/// A vertical colour bar with ticks in display units.
fn legend(painter: &egui::Painter, rect: Rect, kind: FieldKind, lo: f64, hi: f64, text_color: Color32) {
    let (unit, scale) = kind.unit();
    colour_bar(painter, rect, kind.colormap(), &format!("{} [{unit}]", kind.label()), scale, (lo, hi), text_color);
}

/// A vertical colour bar of `map` over the SI range `(lo, hi)`, ticks in display units (SI × `scale`),
/// titled `title`.
#[allow(clippy::cast_possible_truncation)]
pub(crate) fn colour_bar(painter: &egui::Painter, rect: Rect, map: ColorMap, title: &str, scale: f64, (lo, hi): (f64, f64), text_color: Color32) {
    let steps = 64;
    for i in 0..steps {
        let t0 = i as f32 / steps as f32;
        let t1 = (i + 1) as f32 / steps as f32;
        let [r, g, b] = map.rgb(f64::from(0.5 * (t0 + t1)));
        let band = Rect::from_min_max(Pos2::new(rect.left(), rect.bottom() - t1 * rect.height()), Pos2::new(rect.right(), rect.bottom() - t0 * rect.height() + 0.5));
        painter.rect_filled(band, 0.0, Color32::from_rgb(r, g, b));
    }
    painter.rect_stroke(rect, 0.0, Stroke::new(1.0, Color32::from_gray(160)), egui::StrokeKind::Outside);
    let color = text_color;
    let (lo_d, hi_d) = (lo * scale, hi * scale);
    let values = nice_ticks(lo_d, hi_d, 5);
    for (&v, label) in values.iter().zip(crate::number::ticks(&values)) {
        let t = if hi_d > lo_d { ((v - lo_d) / (hi_d - lo_d)) as f32 } else { 0.5 };
        let y = rect.bottom() - t * rect.height();
        painter.line_segment([Pos2::new(rect.right(), y), Pos2::new(rect.right() + 4.0, y)], Stroke::new(1.0, color));
        painter.text(Pos2::new(rect.right() + 6.0, y), Align2::LEFT_CENTER, label, FontId::proportional(11.0), color);
    }
    painter.text(rect.center_top() - Vec2::new(0.0, 6.0), Align2::CENTER_BOTTOM, title, FontId::proportional(11.0), color);
}
