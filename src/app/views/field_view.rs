//! Pad fields unwrapped onto (circumferential × axial): a colour map per pad with a legend, a hover
//! readout, the orifices, and optionally the flowlines of the mean film velocity.
//!
//! Each pad is drawn to scale (arc length horizontally, leading edge on the left, rotation to the right;
//! axial length vertically, +L/2 at the top). All pads share one colour range so they compare.
//!
//! Compared with a pin ([`FieldOptions::pinned`]): the live and the pinned pads side by side under one
//! colour range, or one map per pad of live − pinned in a diverging map ([`crate::scene::field_compare`]).
//! The colour range of a field can be locked so it stays across edits.

use std::collections::HashMap;
use std::sync::Arc;

use egui::{
    Align2, Color32, ColorImage, FontId, Pos2, Rect, RichText, Sense, Shape, Stroke, TextureHandle, TextureOptions, Ui,
    Vec2,
};

use serde::{Deserialize, Serialize};

use crate::app::ink;
use super::{View, ViewContext};
use crate::bearing::stages::StageId;
use crate::bearing::Solution;
use crate::scene::colormap::ColorMap;
use crate::scene::field::{common_range, nice_ticks, FieldKind, PadMap};
use crate::scene::field_compare::{
    difference_maps, drawn_range, lock_for, set_lock, shared_range, FieldScaleLock, Mismatch,
};
use crate::scene::flowlines::{arrow_phase, arrowheads, orifice_sites, pad_flowlines, Flowline, FlowlineParams};
use crate::scene::summary::sig4;
use crate::units::MM;

/// The pad field view.
#[derive(Default)]
pub struct FieldView {
    pub settings: FieldSettings,
    cache: FieldCache,
}

/// What the pad field view keeps between sessions.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct FieldSettings {
    pub field: FieldKind,
    pub pads: PadChoice,
    pub flowlines: bool,
    /// How the view compares with a pin.
    pub compare: FieldCompare,
    /// Locked colour ranges (one per field kind).
    pub locks: Vec<FieldScaleLock>,
}

impl Default for FieldSettings {
    fn default() -> Self {
        Self {
            field: FieldKind::Pressure,
            pads: PadChoice::All,
            flowlines: true,
            compare: FieldCompare::SideBySide,
            locks: Vec::new(),
        }
    }
}

/// Which pads the field view shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
pub enum PadChoice {
    #[default]
    All,
    One(usize),
}

impl View for FieldView {
    fn id(&self) -> &'static str {
        "fields"
    }

    fn label(&self) -> &'static str {
        "Pad fields"
    }

    fn needs(&self) -> &'static [StageId] {
        &[StageId::Reduction]
    }

    fn ui(&mut self, ui: &mut Ui, cx: &mut ViewContext<'_>) {
        let Some(shown) = cx.shown else { return };
        let solution = shown.solution.clone();
        let settings = &mut self.settings;
        let available = FieldKind::available(&solution);
        let n_pads = solution.pads.len();
        // The chosen field when this result has it (a THD field after switching to isothermal: pressure);
        // the selector names what is drawn.
        let drawn = if available.contains(&settings.field) { settings.field } else { FieldKind::Pressure };
        // Wrapped: at 1280×720 with both side panels open the row is wider than the view.
        ui.horizontal_wrapped(|ui| {
            let label = ui.label("Field");
            egui::ComboBox::from_id_salt("field-kind")
                .selected_text(drawn.label())
                .show_ui(ui, |ui| {
                    for k in FieldKind::ALL {
                        let ok = available.contains(&k);
                        ui.add_enabled_ui(ok, |ui| ui.selectable_value(&mut settings.field, k, k.label()))
                            .response
                            .on_disabled_hover_text("Needs the thermal model: not part of this result.")
                            .on_hover_text(k.meaning());
                    }
                })
                .response
                .labelled_by(label.id);
            let label = ui.label("Pads");
            let text = match settings.pads {
                PadChoice::All => "all side by side".to_string(),
                PadChoice::One(k) => format!("pad {k}"),
            };
            egui::ComboBox::from_id_salt("field-pads")
                .selected_text(text)
                .show_ui(ui, |ui| {
                    ui.selectable_value(&mut settings.pads, PadChoice::All, "all side by side");
                    for k in 0..n_pads {
                        ui.selectable_value(&mut settings.pads, PadChoice::One(k), format!("pad {k}"));
                    }
                })
                .response
                .labelled_by(label.id);
            ui.checkbox(&mut settings.flowlines, "Flowlines")
                .on_hover_text("Streamlines of the mean film velocity: seeded on the leading edge and around each orifice (a source when injecting, a sink when not); they stop where the film cavitates.");
        });
        if let PadChoice::One(k) = settings.pads {
            if k >= n_pads {
                settings.pads = PadChoice::All;
            }
        }
        let kind = if available.contains(&settings.field) { settings.field } else { drawn };
        let compare = &mut settings.compare;
        let pinned = cx.compare_with_ui(ui, &[StageId::Reduction], |ui| {
            ui.selectable_value(compare, FieldCompare::SideBySide, "side by side");
            ui.selectable_value(compare, FieldCompare::Difference, "difference map");
        });
        let opts = FieldOptions {
            kind,
            pads: settings.pads,
            flowlines: settings.flowlines,
            locks: &mut settings.locks,
            pinned: pinned.as_ref().map(|(name, s)| (name.as_str(), &s.solution, settings.compare)),
        };
        field_view_ui(ui, &mut self.cache, &solution, opts);
    }

    fn settings(&mut self) -> Option<&mut dyn super::view::Settings> {
        Some(&mut self.settings)
    }
}

/// Texture width and height of a rasterised pad.
const RASTER: (usize, usize) = (240, 160);

/// Derived drawables of one result, rebuilt when the result changes.
#[derive(Default)]
struct Layer {
    /// Identity of the solution the layer belongs to.
    solution: Option<Arc<Solution>>,
    maps: HashMap<FieldKind, (Vec<PadMap>, (f64, f64))>,
    /// Keyed by field, pad and the colour range drawn (bits of lo and hi).
    textures: HashMap<(FieldKind, usize, [u64; 2]), TextureHandle>,
    flowlines: HashMap<usize, Vec<Flowline>>,
}

impl Layer {
    /// Resets the layer when `solution` is another result; says whether it did.
    fn sync(&mut self, solution: &Arc<Solution>) -> bool {
        let changed = !self.solution.as_ref().is_some_and(|s| Arc::ptr_eq(s, solution));
        if changed {
            *self = Self { solution: Some(solution.clone()), ..Self::default() };
        }
        changed
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

/// Drawables of the shown result, of the pinned result compared with it, and of their difference.
#[derive(Default)]
pub struct FieldCache {
    live: Layer,
    pinned: Layer,
    /// Live − pinned per field (the difference maps and their symmetric range, or why there are none).
    difference: Layer,
    mismatch: HashMap<FieldKind, Mismatch>,
}

impl FieldCache {
    fn sync(&mut self, live: &Arc<Solution>, pinned: Option<&Arc<Solution>>) {
        let mut changed = self.live.sync(live);
        if let Some(p) = pinned {
            changed |= self.pinned.sync(p);
        }
        if changed {
            self.difference = Layer::default();
            self.mismatch.clear();
        }
    }

    /// The difference maps of `kind` (computed once per pair of results).
    fn difference(
        &mut self,
        live: &Solution,
        pinned: &Solution,
        kind: FieldKind,
    ) -> Result<(Vec<PadMap>, (f64, f64)), Mismatch> {
        if let Some(m) = self.mismatch.get(&kind) {
            return Err(m.clone());
        }
        if let Some(d) = self.difference.maps.get(&kind) {
            return Ok(d.clone());
        }
        let a = self.live.maps(live, kind).0.clone();
        let b = self.pinned.maps(pinned, kind).0.clone();
        match difference_maps(&a, &b) {
            Ok(d) => {
                self.difference.maps.insert(kind, d.clone());
                Ok(d)
            }
            Err(m) => {
                self.mismatch.insert(kind, m.clone());
                Err(m)
            }
        }
    }
}

/// How the pad field view compares with a pinned result.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize, Default)]
pub enum FieldCompare {
    /// Live and pinned maps side by side, one colour scale.
    #[default]
    SideBySide,
    /// One map per pad of live − pinned.
    Difference,
}

/// What the field view draws.
pub struct FieldOptions<'a> {
    pub kind: FieldKind,
    pub pads: PadChoice,
    pub flowlines: bool,
    /// Locked colour ranges (one per field kind).
    pub locks: &'a mut Vec<FieldScaleLock>,
    /// A pinned result to compare with: its name, result and how.
    pub pinned: Option<(&'a str, &'a Arc<Solution>, FieldCompare)>,
}

/// Which result a panel of maps shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Source {
    Live,
    Pinned,
    Difference,
}

/// One group of pad maps drawn together (a whole picture, or half of a side-by-side one).
struct Panel<'a> {
    source: Source,
    title: Option<String>,
    maps: Vec<PadMap>,
    solution: &'a Solution,
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

/// The panels to draw, the colour map and its automatic range, and a note when the comparison asked for
/// cannot be drawn.
fn panels<'a>(
    cache: &mut FieldCache,
    solution: &'a Solution,
    opts: &FieldOptions<'a>,
) -> (Vec<Panel<'a>>, ColorMap, (f64, f64), Option<String>) {
    let kind = opts.kind;
    let select = |maps: &[PadMap]| -> Vec<PadMap> {
        match opts.pads {
            PadChoice::All => maps.to_vec(),
            PadChoice::One(k) => maps.iter().filter(|m| m.pad == k).cloned().collect(),
        }
    };
    // One pad alone gets its own colour range (more contrast); side by side, pads share one.
    let own = |maps: &[PadMap], all: (f64, f64)| if maps.len() == 1 { (maps[0].min, maps[0].max) } else { all };
    let (live, live_range) = cache.live.maps(solution, kind).clone();
    let live = select(&live);
    let alone = |note: Option<String>, live: Vec<PadMap>| {
        let range = own(&live, live_range);
        (vec![Panel { source: Source::Live, title: None, maps: live, solution }], kind.colormap(), range, note)
    };
    match opts.pinned {
        None => alone(None, live),
        Some((name, pin, FieldCompare::SideBySide)) => {
            let (pinned, pinned_range) = cache.pinned.maps(pin, kind).clone();
            let pinned = select(&pinned);
            if pinned.is_empty() {
                return alone(
                    Some(format!("The pinned result \"{name}\" has no {}.", kind.label().to_lowercase())),
                    live,
                );
            }
            let range = shared_range(own(&live, live_range), own(&pinned, pinned_range));
            let panels = vec![
                Panel { source: Source::Live, title: Some("Live".into()), maps: live, solution },
                Panel {
                    source: Source::Pinned,
                    title: Some(format!("Pinned \"{name}\"")),
                    maps: pinned,
                    solution: pin,
                },
            ];
            (panels, kind.colormap(), range, None)
        }
        Some((name, pin, FieldCompare::Difference)) => match cache.difference(solution, pin, kind) {
            Ok((d, range)) => {
                let d = select(&d);
                let range = if d.len() == 1 {
                    (-d[0].min.abs().max(d[0].max.abs()), d[0].min.abs().max(d[0].max.abs()))
                } else {
                    range
                };
                let title = Some(format!("Live − pinned \"{name}\""));
                (vec![Panel { source: Source::Difference, title, maps: d, solution }], ColorMap::Diverging, range, None)
            }
            Err(e) => alone(Some(format!("No difference map: {e}. The live result is shown.")), live),
        },
    }
}

/// The "Lock colour scale" toggle of the drawn field: locked, the colour range stays the one on screen
/// when it was locked, so pictures before and after an edit compare.
fn lock_ui(ui: &mut Ui, locks: &mut Vec<FieldScaleLock>, kind: FieldKind, range: (f64, f64)) {
    let (unit, scale) = kind.unit();
    let lock = lock_for(locks, kind);
    let mut locked = lock.is_some();
    let text = match lock {
        Some(l) => format!("Lock colour scale ({} to {} {unit})", sig4(l.lo * scale), sig4(l.hi * scale)),
        None => "Lock colour scale".to_string(),
    };
    if ui.checkbox(&mut locked, text).on_hover_text("Keep this field's colour range fixed across edits, so two pictures compare (values outside it take the end colours).").changed() {
        set_lock(locks, kind, locked.then_some(range));
    }
}

/// Draws the field view; returns the hover readout, if any.
pub fn field_view_ui(
    ui: &mut Ui,
    cache: &mut FieldCache,
    solution: &Arc<Solution>,
    opts: FieldOptions<'_>,
) -> Option<Readout> {
    cache.sync(solution, opts.pinned.map(|p| p.1));
    let kind = opts.kind;
    let (panels, colormap, auto, note) = panels(cache, solution, &opts);
    if panels.iter().all(|p| p.maps.is_empty()) {
        ui.label(format!("{} is not part of this result. {}", kind.label(), kind.meaning()));
        return None;
    }
    let difference = panels.iter().any(|p| p.source == Source::Difference);
    let range = if difference {
        auto
    } else {
        let range = drawn_range(opts.locks, kind, auto);
        lock_ui(ui, opts.locks, kind, range);
        range
    };
    if let Some(n) = note {
        ui.colored_label(ink::WARNING.of(ui), n);
    }
    let (unit, scale) = kind.unit();
    ui.label(
        RichText::new("Rotation: left to right (s along the arc from the leading edge; z axial, +L/2 at the top)")
            .small(),
    );
    let full = ui.available_rect_before_wrap();
    // The painted area; the readout is a real label below it (readable by screen readers and tests).
    let avail = Rect::from_min_max(full.min, full.max - Vec2::new(0.0, 48.0));
    let legend_w = 100.0;
    // Room on the right for the colour bar and its title (which is wider than the bar).
    let area = Rect::from_min_max(avail.min + Vec2::new(8.0, 22.0), avail.max - Vec2::new(legend_w + 24.0, 24.0));
    let response = ui.allocate_rect(avail, Sense::hover());
    let painter = ui.painter_at(avail);
    let text = ui.visuals().text_color();
    #[allow(clippy::cast_precision_loss)]
    let n = panels.len() as f32;
    // A panel's title sits above its pads' labels.
    let (gap, title_h) = (28.0, if panels.iter().any(|p| p.title.is_some()) { 40.0 } else { 0.0 });
    let width = (area.width() - gap * (n - 1.0)) / n;
    let mut readout = None;
    let mut bottom = area.top() + 160.0;
    for (k, panel) in panels.iter().enumerate() {
        #[allow(clippy::cast_precision_loss)]
        let left = area.left() + k as f32 * (width + gap);
        let rect = Rect::from_min_max(Pos2::new(left, area.top() + title_h), Pos2::new(left + width, area.bottom()));
        if let Some(t) = &panel.title {
            painter.text(
                Pos2::new(rect.center().x, area.top() - 4.0),
                Align2::CENTER_TOP,
                t,
                FontId::proportional(14.0),
                text,
            );
        }
        let layer = match panel.source {
            Source::Live => &mut cache.live,
            Source::Pinned => &mut cache.pinned,
            Source::Difference => &mut cache.difference,
        };
        let drawn = PanelDraw {
            painter: &painter,
            hover: response.hover_pos(),
            ctx: ui.ctx(),
            kind,
            colormap,
            range,
            flowlines: opts.flowlines && !difference,
            text,
        };
        let (r, b) = drawn.panel(layer, rect, panel);
        readout = readout.or(r);
        bottom = bottom.max(b);
    }
    let title = if difference { format!("Δ {} [{unit}]", kind.label()) } else { format!("{} [{unit}]", kind.label()) };
    colour_bar(
        &painter,
        Rect::from_min_max(
            Pos2::new(avail.right() - legend_w + 12.0, area.top() + title_h),
            Pos2::new(avail.right() - legend_w + 30.0, bottom),
        ),
        colormap,
        &title,
        scale,
        range,
        text,
    );
    let line = match &readout {
        Some(r) => format!(
            "{}Pad {}  θ = {:.1}°  z = {:+.1} mm   {} = {:.4} {unit}{}",
            r.of,
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
    let meaning = if difference { "live − pinned, grey = unchanged" } else { "perceptually uniform" };
    ui.label(format!(
        "Colour scale: {title} from {} to {} ({meaning}). Hatched: cavitated film (ruptured, p = 0).",
        sig4(range.0 * scale),
        sig4(range.1 * scale)
    ));
    readout
}

/// What every panel of one picture shares.
struct PanelDraw<'p> {
    painter: &'p egui::Painter,
    hover: Option<Pos2>,
    ctx: &'p egui::Context,
    kind: FieldKind,
    colormap: ColorMap,
    range: (f64, f64),
    flowlines: bool,
    text: Color32,
}

impl PanelDraw<'_> {
    /// Draws one panel's pads into `area`; returns the hover readout and the bottom of the lowest pad.
    fn panel(&self, layer: &mut Layer, area: Rect, panel: &Panel<'_>) -> (Option<Readout>, f32) {
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
pub(crate) fn colour_bar(
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
