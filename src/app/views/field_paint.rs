//! Painting the pad fields of one picture ([`super::field_view`]): the drawables of one result kept between
//! frames ([`Layer`]: the pad maps of each field with their common range, the rasterised textures per
//! colour range, the flowlines per pad), the layout of the pads to a common scale, and one panel's pads
//! painted with their orifices (blue: injecting, white: draining), flowlines with arrowheads, edge angles and
//! the hover readout; and the vertical colour bar the pad and deformation views share.
//!
//! Pad frame: arc length s from the leading edge (screen x to the right, the direction of rotation) and
//! axial z (+L/2 at the top; screen y points down). Values are SI inside; the readout is in the field's
//! display unit ([`FieldKind::unit`]).

use std::collections::HashMap;
use std::sync::Arc;

use egui::{Align2, Color32, ColorImage, FontId, Pos2, Rect, Shape, Stroke, TextureHandle, TextureOptions, Vec2};

use crate::bearing::Solution;
use crate::scene::colormap::ColorMap;
use crate::scene::field::{common_range, nice_ticks, FieldKind, PadMap};
use crate::scene::flowlines::{arrow_phase, arrowheads, orifice_sites, pad_flowlines, Flowline, FlowlineParams};
use crate::units::MM;

/// Texture width and height of a rasterised pad.
const RASTER: (usize, usize) = (240, 160);

/// Derived drawables of one result, rebuilt when the result changes.
#[derive(Default)]
pub(super) struct Layer {
    /// Identity of the solution the layer belongs to.
    pub(super) solution: Option<Arc<Solution>>,
    pub(super) maps: HashMap<FieldKind, (Vec<PadMap>, (f64, f64))>,
    /// Keyed by field, pad and the colour range drawn (bits of lo and hi).
    textures: HashMap<(FieldKind, usize, [u64; 2]), TextureHandle>,
    flowlines: HashMap<usize, Vec<Flowline>>,
}

impl Layer {
    /// Resets the layer when `solution` is another result; says whether it did.
    pub(super) fn sync(&mut self, solution: &Arc<Solution>) -> bool {
        let changed = !self.solution.as_ref().is_some_and(|s| Arc::ptr_eq(s, solution));
        if changed {
            *self = Self { solution: Some(solution.clone()), ..Self::default() };
        }
        changed
    }

    pub(super) fn maps(&mut self, solution: &Solution, kind: FieldKind) -> &(Vec<PadMap>, (f64, f64)) {
        self.maps.entry(kind).or_insert_with(|| {
            let maps = PadMap::all(solution, kind);
            let range = common_range(&maps);
            (maps, range)
        })
    }

    pub(super) fn flowlines(&mut self, solution: &Solution, pad: usize) -> &[Flowline] {
        self.flowlines.entry(pad).or_insert_with(|| pad_flowlines(solution, pad, FlowlineParams::default()))
    }
}

/// Which result a panel of maps shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Source {
    Live,
    Pinned,
    Difference,
}

/// One group of pad maps drawn together (a whole picture, or half of a side-by-side one).
pub(super) struct Panel<'a> {
    pub(super) source: Source,
    pub(super) title: Option<String>,
    pub(super) maps: Vec<PadMap>,
    pub(super) solution: &'a Solution,
}

/// What the hover readout says.
#[derive(Debug, Clone, PartialEq)]
pub struct Readout {
    /// Whose value: "" (live), "pinned " or "live − pinned ".
    pub of: &'static str,
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

/// What every panel of one picture shares.
pub(super) struct PanelDraw<'p> {
    pub(super) painter: &'p egui::Painter,
    pub(super) hover: Option<Pos2>,
    pub(super) ctx: &'p egui::Context,
    pub(super) kind: FieldKind,
    pub(super) colormap: ColorMap,
    pub(super) range: (f64, f64),
    pub(super) flowlines: bool,
    pub(super) text: Color32,
}

impl PanelDraw<'_> {
    /// Draws one panel's pads into `area`; returns the hover readout and the bottom of the lowest pad.
    pub(super) fn panel(&self, layer: &mut Layer, area: Rect, panel: &Panel<'_>) -> (Option<Readout>, f32) {
        let (kind, (lo, hi), painter) = (self.kind, self.range, self.painter);
        let text = self.text;
        let small = FontId::proportional(11.0);
        let shown: Vec<&PadMap> = panel.maps.iter().collect();
        let rects = pack(area, &shown, 16.0);
        let of = match panel.source {
            Source::Live => "",
            Source::Pinned => "pinned ",
            Source::Difference => "live − pinned ",
        };
        let mut readout = None;
        let ppm = rects.first().map_or(1.0, |(r, m)| f64::from(r.width()) / m.arc_length_m());
        for &(rect, map) in &rects {
            let tex = layer.textures.entry((kind, map.pad, [lo.to_bits(), hi.to_bits()])).or_insert_with(|| {
                let r = map.raster_with(self.colormap, RASTER.0, RASTER.1, lo, hi);
                let image = ColorImage::from_rgba_unmultiplied([r.width, r.height], &r.rgba);
                self.ctx.load_texture(format!("pad{}-{kind:?}-{of}", map.pad), image, TextureOptions::LINEAR)
            });
            painter.image(tex.id(), rect, Rect::from_min_max(Pos2::ZERO, Pos2::new(1.0, 1.0)), Color32::WHITE);
            painter.rect_stroke(rect, 0.0, Stroke::new(1.0, Color32::from_gray(160)), egui::StrokeKind::Outside);
            let frame = ScreenFromPad { rect, s_len: map.arc_length_m(), z0: map.z_m[0], z_len: map.length_m() };
            for o in orifice_sites(panel.solution, map.pad) {
                #[allow(clippy::cast_possible_truncation)]
                let r = (o.radius_m * ppm) as f32;
                let color = if o.flow_m3_per_s > 0.0 { Color32::from_rgb(70, 160, 255) } else { Color32::WHITE };
                painter.circle_stroke(frame.map([o.s_m, o.z_m]), r, Stroke::new(1.5, color));
            }
            if self.flowlines {
                for (k, line) in layer.flowlines(panel.solution, map.pad).iter().enumerate() {
                    draw_flowline(painter, &frame, line, arrow_phase(k));
                }
            }
            painter.text(
                rect.center_top() - Vec2::new(0.0, 2.0),
                Align2::CENTER_BOTTOM,
                format!("Pad {}", map.pad),
                FontId::proportional(13.0),
                text,
            );
            painter.text(
                rect.left_bottom() + Vec2::new(0.0, 3.0),
                Align2::LEFT_TOP,
                format!("{:.0}°", map.theta_deg(0.0).rem_euclid(360.0)),
                small.clone(),
                text,
            );
            painter.text(
                rect.right_bottom() + Vec2::new(0.0, 3.0),
                Align2::RIGHT_TOP,
                format!("{:.0}°", map.theta_deg(map.arc_length_m()).rem_euclid(360.0)),
                small.clone(),
                text,
            );
            if let Some(pos) = self.hover.filter(|p| rect.contains(*p)) {
                let [s, z] = frame.unmap(pos);
                if let Some(v) = map.sample(s, z) {
                    let theta_deg = map.theta_deg(s).rem_euclid(360.0);
                    readout = Some(Readout {
                        of,
                        pad: map.pad,
                        theta_deg,
                        z_mm: MM.from_si(z),
                        value: v * kind.unit().1,
                        cavitated: map.cavitated_at(s, z),
                    });
                    painter.circle_stroke(pos, 4.0, Stroke::new(1.0, Color32::WHITE));
                }
            }
        }
        (readout, rects.iter().map(|(r, _)| r.bottom()).fold(area.top(), f32::max))
    }
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
        painter.add(Shape::convex_polygon(
            vec![tip, tip - d * 6.0 + n * 3.0, tip - d * 6.0 - n * 3.0],
            stroke.color,
            Stroke::NONE,
        ));
    }
}

/// A vertical colour bar of `map` over the SI range `(lo, hi)`, ticks in display units (SI × `scale`),
/// titled `title`.
#[allow(clippy::cast_possible_truncation)]
pub(super) fn colour_bar(
    painter: &egui::Painter,
    rect: Rect,
    map: ColorMap,
    title: &str,
    scale: f64,
    (lo, hi): (f64, f64),
    text_color: Color32,
) {
    let steps = 64;
    for i in 0..steps {
        let t0 = i as f32 / steps as f32;
        let t1 = (i + 1) as f32 / steps as f32;
        let [r, g, b] = map.rgb(f64::from(0.5 * (t0 + t1)));
        let band = Rect::from_min_max(
            Pos2::new(rect.left(), rect.bottom() - t1 * rect.height()),
            Pos2::new(rect.right(), rect.bottom() - t0 * rect.height() + 0.5),
        );
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
    painter.text(
        rect.center_top() - Vec2::new(0.0, 6.0),
        Align2::CENTER_BOTTOM,
        title,
        FontId::proportional(11.0),
        color,
    );
}
