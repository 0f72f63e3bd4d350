//! The pad-deformation view: one deforming pad's mid-plane cross-section, undeformed (grey) and deformed with
//! a chosen exaggeration, coloured by the radial displacement — mechanical (bending modes), thermal (the pad's
//! thermal growth, TEHD solves only) or total, selectable; the unwrapped film-face displacement; the film
//! with and without that displacement side by side or their difference map; and a gallery of the retained
//! mode shapes with their frequencies. Hover reads the value in µm.
//!
//! The drawables come from [`crate::scene::deformation`]; this file only lays them out and paints them.

use std::collections::HashMap;
use std::sync::Arc;

use egui::{
    TextStyle,
    Align2, Color32, ColorImage, FontId, Pos2, Rect, RichText, Sense, Shape, Stroke, TextureHandle, TextureOptions, Ui,
    Vec2,
};

use super::{View, ViewContext};
use crate::bearing::stages::StageId;
use crate::bearing::Solution;
use crate::scene::colormap::ColorMap;
use crate::scene::deformation::{deforms, Displacement, PadDeformation, Section};
use crate::scene::field::PadMap;
use crate::scene::summary::sig4;
use crate::number;
use crate::units::{MM, UM};

use super::field_paint::colour_bar;
use super::plot_kit::{footer_height, text_within};

/// Texture size of a rasterised map.
const RASTER: (usize, usize) = (200, 140);

/// Which film maps are shown.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum FilmMaps {
    /// The flexible and the rigid film thickness side by side.
    #[default]
    SideBySide,
    /// Their difference (the radial displacement of the film face).
    Difference,
}

/// The view's runtime state (not persisted).
#[derive(Default)]
pub struct DeformationView {
    /// The solution the cache belongs to.
    solution: Option<Arc<Solution>>,
    /// The chosen pad (`None`: the most loaded flexible pad).
    pad: Option<usize>,
    /// A fixed exaggeration (`None`: automatic).
    exaggeration: Option<f64>,
    films: FilmMaps,
    /// The displacement drawn (thermal and total need a TEHD solve).
    shown: Displacement,
    scene: Option<(usize, Option<f64>, PadDeformation)>,
    /// Keyed by pad and map name.
    textures: HashMap<(usize, &'static str), TextureHandle>,
}

impl DeformationView {
    fn sync(&mut self, solution: &Arc<Solution>) {
        if !self.solution.as_ref().is_some_and(|s| Arc::ptr_eq(s, solution)) {
            self.solution = Some(solution.clone());
            self.scene = None;
            self.textures.clear();
        }
    }

    fn scene(&mut self, solution: &Solution, pad: usize) -> Option<&PadDeformation> {
        let shown = self.shown;
        let thermal = solution.pads.get(pad).is_some_and(|p| p.thermal_growth.is_some());
        let same = |d: &PadDeformation| d.shown == shown || (!thermal && d.shown == Displacement::Mechanical);
        if !self.scene.as_ref().is_some_and(|(p, e, d)| *p == pad && *e == self.exaggeration && same(d)) {
            self.scene =
                PadDeformation::new(solution, pad, self.exaggeration, shown).map(|d| (pad, self.exaggeration, d));
            // The maps' textures hold the previous displacement.
            self.textures.clear();
        }
        self.scene.as_ref().map(|(_, _, d)| d)
    }
}

impl View for DeformationView {
    fn id(&self) -> &'static str {
        "pad_deformation"
    }

    fn label(&self) -> &'static str {
        "Pad deformation"
    }

    /// The solution carries each flexible pad's modes, amplitudes and displacement (the films stage computes
    /// the modes when `physics.pad_modes > 0`).
    fn needs(&self) -> &'static [StageId] {
        &[StageId::Reduction]
    }

    fn ui(&mut self, ui: &mut Ui, cx: &mut ViewContext<'_>) {
        let Some(shown) = cx.shown else { return };
        // The result on screen is of an earlier case whose pads do not deform, while the edited case's do:
        // its solve is under way (or failed) — never "rigid" for a case with flexible pads.
        if cx.stale && cx.case().is_some_and(pads_deform) && flexible_pads(&shown.solution).1.is_none() {
            ui.add_space(16.0);
            ui.label(RichText::new("The edited case's pads deform: waiting for its solution").heading());
            ui.label("The result on screen is of an earlier case, whose pads are rigid.");
            return;
        }
        deformation_view_ui(ui, self, &shown.solution);
    }

    fn snapshot_setup(&mut self) -> Option<&'static str> {
        Some(include_str!("../../../cases/compressor-bearing-flexible.toml"))
    }
}

/// The case's pads deform: bending modes, or thermal growth in a THD solve.
fn pads_deform(case: &crate::model::Case) -> bool {
    let thd = case.thermal.model == crate::model::ThermalModelKind::Thd;
    case.physics.pad_modes > 0 || (thd && case.thermal.pad_expansion_per_k != 0.0)
}

/// The deforming pads of a solution (bending modes or thermal growth), and the most loaded of them.
fn flexible_pads(solution: &Solution) -> (Vec<usize>, Option<usize>) {
    let pads: Vec<usize> = solution.pads.iter().filter(|p| deforms(p)).map(|p| p.index).collect();
    let load = |k: usize| solution.pads[k].force_n[0].hypot(solution.pads[k].force_n[1]);
    let loaded = pads.iter().copied().max_by(|&a, &b| load(a).total_cmp(&load(b)));
    (pads, loaded)
}

/// What is under the cursor.
struct Hover {
    what: String,
    value_m: f64,
}

/// Draws the view.
pub fn deformation_view_ui(ui: &mut Ui, view: &mut DeformationView, solution: &Arc<Solution>) {
    view.sync(solution);
    let (pads, loaded) = flexible_pads(solution);
    let Some(default_pad) = loaded else {
        ui.add_space(16.0);
        ui.label(RichText::new("The pads of this case are rigid").heading());
        ui.label(
            "Set physics.pad_modes to 1–3 (Physics in the editor) to give each tilting pad its lowest bending modes \
             on the pivot (a 3-D finite-element pad reduced to pseudo-modes, docs/MODEL.md §5), or a pad expansion \
             coefficient with the THD model for its thermal growth; this view then shows the deformed pads, the \
             film they make and the mode shapes. The shipped cases compressor-bearing-flexible and fillon-a-tehd \
             show it.",
        );
        return;
    };
    let pad = view.pad.filter(|p| pads.contains(p)).unwrap_or(default_pad);
    let thermal = solution.pads[pad].thermal_growth.is_some();
    controls_ui(ui, view, &pads, pad, thermal);
    let Some(scene) = view.scene(solution, pad).cloned() else {
        ui.label(format!("Pad {pad}: its deformation cannot be drawn (the mode shapes do not match the pad's grid)."));
        return;
    };
    let modes: Vec<String> = scene
        .modes
        .iter()
        .map(|m| format!("mode {} at {} Hz ({} µm)", m.mode + 1, sig4(m.frequency_hz), sig4(UM.from_si(m.amplitude_m))))
        .collect();
    let retained = if modes.is_empty() {
        "no bending modes (rigid pads)".to_string()
    } else {
        format!("retained {}", modes.join(", "))
    };
    ui.label(format!("Pad {pad}: mid-plane section drawn ×{}; {retained}", sig4(scene.exaggeration)));
    let full = ui.available_rect_before_wrap();
    let u = &scene.displacement;
    let range = symmetric(u.min, u.max);
    let kind = scene.shown.label().to_lowercase();
    // In µm, the unit of the colour bars beside the drawings.
    let scale_line =
        format!("Colour scale: {kind} u from {} to {} µm", sig4(UM.from_si(range.0)), sig4(UM.from_si(range.1)));
    let explanation = format!(
        "Radial displacement of the pad, positive away from the journal: mechanical (the solved bending-mode amplitudes), \
         thermal (the pad's growth from its temperature, TEHD; the journal's uniform growth is not the pad's) or their \
         total. Pad thickness {}. Film h − u: the film at the same pad positions without the shown displacement.",
        number::eng(scene.thickness_m, "m")
    );
    // The footer (scale, hover readout, explanation) is measured before the drawing takes the rest, so at
    // 1280×720 its last line stays inside the view.
    let footer = footer_height(
        ui,
        full.width(),
        &[(&scale_line, TextStyle::Body), ("Hover", TextStyle::Body), (&explanation, TextStyle::Small)],
    );
    let avail = Rect::from_min_max(full.min, full.max - Vec2::new(0.0, footer));
    let response = ui.allocate_rect(avail, Sense::hover());
    let painter = ui.painter_at(avail);
    let hover_pos = response.hover_pos();
    let top_h = avail.height() * 0.62;
    let section_rect = Rect::from_min_size(avail.min, Vec2::new(avail.width() * 0.42, top_h));
    let maps_rect = Rect::from_min_max(
        Pos2::new(section_rect.right() + 12.0, avail.top()),
        Pos2::new(avail.right(), avail.top() + top_h),
    );
    let gallery_rect = Rect::from_min_max(Pos2::new(avail.left(), avail.top() + top_h + 8.0), avail.max);

    // The line above names the pad and the exaggeration: the drawing's title says only what it shows.
    let title = format!("{} deformation", scene.shown.label());
    let mut hover =
        section_ui(&painter, section_rect, &scene.section, range, hover_pos, &title, ui.visuals().text_color());
    hover = hover.or(maps_ui(ui, view, &painter, maps_rect, &scene, range, hover_pos));
    hover = hover.or(gallery_ui(ui, view, &painter, gallery_rect, &scene, hover_pos));
    let line = match hover {
        Some(h) => format!("{}: {} µm", h.what, sig4(UM.from_si(h.value_m))),
        None => "Hover over the section, a map or a mode to read the value in µm.".into(),
    };
    ui.add(egui::Label::new(scale_line).wrap());
    ui.add(egui::Label::new(line).truncate());
    ui.add(egui::Label::new(RichText::new(explanation).small()).wrap());
}

fn controls_ui(ui: &mut Ui, view: &mut DeformationView, pads: &[usize], pad: usize, thermal: bool) {
    ui.horizontal_wrapped(|ui| {
        let label = ui.label("Pad");
        let mut chosen = pad;
        egui::ComboBox::from_id_salt("deformation-pad")
            .selected_text(format!("pad {pad}"))
            .show_ui(ui, |ui| {
                for &k in pads {
                    ui.selectable_value(&mut chosen, k, format!("pad {k}"));
                }
            })
            .response
            .labelled_by(label.id);
        if chosen != pad {
            view.pad = Some(chosen);
        }
        let mut auto = view.exaggeration.is_none();
        if ui.checkbox(&mut auto, "Automatic exaggeration").changed() {
            view.exaggeration = if auto { None } else { view.scene.as_ref().map(|(_, _, d)| d.exaggeration) };
        }
        if let Some(e) = view.exaggeration.as_mut() {
            let label = ui.label("Exaggeration");
            ui.add(egui::DragValue::new(e).range(1.0..=1e6).speed(10.0).prefix("×")).labelled_by(label.id);
        }
        ui.separator();
        ui.label("Colour by");
        for d in Displacement::ALL {
            let enabled = thermal || d == Displacement::Mechanical;
            let selected = view.shown == d || (!thermal && d == Displacement::Mechanical);
            let response = ui
                .add_enabled(enabled, egui::Button::selectable(selected, d.label()))
                .on_disabled_hover_text("Thermal growth needs a TEHD solve: the THD model with a pad expansion coefficient (thermal.pad_expansion_ppm_per_k).");
            if response.clicked() {
                view.shown = d;
            }
        }
        ui.separator();
        ui.selectable_value(&mut view.films, FilmMaps::SideBySide, "Film with and without u");
        ui.selectable_value(&mut view.films, FilmMaps::Difference, "Difference map");
    });
}

/// A range symmetric about zero that holds `lo..hi` (so zero displacement has the middle colour).
fn symmetric(lo: f64, hi: f64) -> (f64, f64) {
    let m = lo.abs().max(hi.abs()).max(1e-12);
    (-m, m)
}

fn colour(v: f64, (lo, hi): (f64, f64)) -> Color32 {
    let [r, g, b] = ColorMap::Viridis.rgb_in(v, lo, hi);
    Color32::from_rgb(r, g, b)
}

/// Maps pad-frame points [m] into a rectangle to one scale (y up), fitted to the points it was built from.
struct ScreenFromSection {
    centre: [f64; 2],
    scale: f64,
    origin: Pos2,
}

impl ScreenFromSection {
    fn fit(rect: Rect, points: &[[f64; 2]]) -> Self {
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for p in points {
            for c in 0..2 {
                lo[c] = lo[c].min(p[c]);
                hi[c] = hi[c].max(p[c]);
            }
        }
        let w = (hi[0] - lo[0]).max(1e-9);
        let h = (hi[1] - lo[1]).max(1e-9);
        let scale = (f64::from(rect.width()) / w).min(f64::from(rect.height()) / h);
        Self { centre: [0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1])], scale, origin: rect.center() }
    }

    #[allow(clippy::cast_possible_truncation)]
    fn map(&self, p: [f64; 2]) -> Pos2 {
        self.origin
            + Vec2::new(((p[0] - self.centre[0]) * self.scale) as f32, (-(p[1] - self.centre[1]) * self.scale) as f32)
    }
}

/// Height of the pivot's wedge on a section [points].
const WEDGE: f32 = 12.0;

/// Paints a section (grey undeformed outline, deformed outline coloured by u_r); the hover under `hover_pos`.
fn section_ui(
    painter: &egui::Painter,
    rect: Rect,
    section: &Section,
    range: (f64, f64),
    hover_pos: Option<Pos2>,
    title: &str,
    text: Color32,
) -> Option<Hover> {
    text_within(painter, rect.center_top(), Align2::CENTER_TOP, title, FontId::proportional(12.0), text, rect.width());
    // Below the title (14 points) the pivot's wedge stands 12 points above the pad's back: the drawing
    // starts under both. Below it, the LE and TE labels.
    let inner = Rect::from_min_max(rect.min + Vec2::new(10.0, 14.0 + WEDGE + 6.0), rect.max - Vec2::new(10.0, 22.0));
    let all: Vec<[f64; 2]> = section.rigid.iter().chain(&section.deformed).copied().collect();
    let frame = ScreenFromSection::fit(inner, &all);
    let rigid: Vec<Pos2> = section.rigid.iter().map(|&p| frame.map(p)).collect();
    painter.add(Shape::closed_line(rigid, Stroke::new(1.0, Color32::from_gray(150))));
    let deformed: Vec<Pos2> = section.deformed.iter().map(|&p| frame.map(p)).collect();
    let n = deformed.len();
    for k in 0..n {
        let next = (k + 1) % n;
        let v = 0.5 * (section.radial_m[k] + section.radial_m[next]);
        painter.line_segment([deformed[k], deformed[next]], Stroke::new(2.5, colour(v, range)));
    }
    // The pivot: a wedge on the back of the pad.
    let pivot = frame.map(section.pivot);
    painter.add(Shape::convex_polygon(
        vec![pivot, pivot + Vec2::new(7.0, -WEDGE), pivot + Vec2::new(-7.0, -WEDGE)],
        Color32::from_gray(120),
        Stroke::NONE,
    ));
    if let (Some(first), Some(last)) = (deformed.first(), deformed.get(section.film_face.saturating_sub(1))) {
        let small = FontId::proportional(11.0);
        painter.text(*first + Vec2::new(-4.0, 4.0), Align2::RIGHT_TOP, "LE", small.clone(), text);
        painter.text(*last + Vec2::new(4.0, 4.0), Align2::LEFT_TOP, "TE", small, text);
    }
    let pos = hover_pos.filter(|p| inner.expand(8.0).contains(*p))?;
    let (k, d) = deformed.iter().enumerate().map(|(k, q)| (k, q.distance(pos))).min_by(|a, b| a.1.total_cmp(&b.1))?;
    (d < 12.0).then(|| {
        painter.circle_stroke(deformed[k], 4.0, Stroke::new(1.0, text));
        let place = if k < section.film_face { "film face" } else { "pad body" };
        Hover { what: format!("{title}, {place}: radial displacement"), value_m: section.radial_m[k] }
    })
}

/// Rasterises `map` on `range` once per pad and name.
fn texture(
    ui: &Ui,
    view: &mut DeformationView,
    name: &'static str,
    map: &PadMap,
    range: (f64, f64),
) -> egui::TextureId {
    view.textures
        .entry((map.pad, name))
        .or_insert_with(|| {
            let r = map.raster(RASTER.0, RASTER.1, range.0, range.1);
            let image = ColorImage::from_rgba_unmultiplied([r.width, r.height], &r.rgba);
            ui.ctx().load_texture(format!("deformation-{}-{name}", map.pad), image, TextureOptions::LINEAR)
        })
        .id()
}

/// One unwrapped map to draw: the map, its texture name, its title and its colour range.
struct MapSpec<'a> {
    map: &'a PadMap,
    name: &'static str,
    title: &'a str,
    range: (f64, f64),
}

/// Paints an unwrapped map into `rect` (to scale, centred) with its title; the value under the cursor.
#[allow(clippy::cast_possible_truncation)]
fn map_ui(
    ui: &Ui,
    view: &mut DeformationView,
    painter: &egui::Painter,
    rect: Rect,
    spec: &MapSpec<'_>,
    hover_pos: Option<Pos2>,
) -> Option<Hover> {
    let MapSpec { map, name, title, range } = *spec;
    let text = ui.visuals().text_color();
    text_within(painter, rect.center_top(), Align2::CENTER_TOP, title, FontId::proportional(12.0), text, rect.width());
    let inner = rect.shrink2(Vec2::new(4.0, 18.0));
    let (arc, len) = (map.arc_length_m(), map.length_m());
    if arc <= 0.0 || len <= 0.0 {
        return None;
    }
    let ppm = (f64::from(inner.width()) / arc).min(f64::from(inner.height()) / len);
    let r = Rect::from_center_size(inner.center(), Vec2::new((arc * ppm) as f32, (len * ppm) as f32));
    let id = texture(ui, view, name, map, range);
    painter.image(id, r, Rect::from_min_max(Pos2::ZERO, Pos2::new(1.0, 1.0)), Color32::WHITE);
    painter.rect_stroke(r, 0.0, Stroke::new(1.0, Color32::from_gray(160)), egui::StrokeKind::Outside);
    let pos = hover_pos.filter(|p| r.contains(*p))?;
    let s = f64::from((pos.x - r.left()) / r.width()) * arc;
    let z = map.z_m[0] + f64::from((r.bottom() - pos.y) / r.height()) * len;
    map.sample(s, z).map(|v| Hover {
        what: format!("{title} at θ = {:.1}°, z = {} mm", map.theta_deg(s).rem_euclid(360.0), sig4(MM.from_si(z))),
        value_m: v,
    })
}

/// The displacement map and the film maps with their colour bars.
fn maps_ui(
    ui: &Ui,
    view: &mut DeformationView,
    painter: &egui::Painter,
    rect: Rect,
    scene: &PadDeformation,
    range: (f64, f64),
    hover_pos: Option<Pos2>,
) -> Option<Hover> {
    let text = ui.visuals().text_color();
    let bar_w = 70.0;
    let body = Rect::from_min_max(rect.min, rect.max - Vec2::new(bar_w, 0.0));
    let half = body.height() * 0.5;
    let upper = Rect::from_min_size(body.min, Vec2::new(body.width(), half));
    let lower = Rect::from_min_max(Pos2::new(body.left(), body.top() + half), body.max);
    let bar = |r: Rect| {
        Rect::from_min_max(
            Pos2::new(rect.right() - bar_w + 8.0, r.top() + 24.0),
            Pos2::new(rect.right() - bar_w + 22.0, r.bottom() - 10.0),
        )
    };
    let u_title = format!("Film-face u ({})", scene.shown.label().to_lowercase());
    let u = MapSpec { map: &scene.displacement, name: "u", title: &u_title, range };
    let mut hover = map_ui(ui, view, painter, upper, &u, hover_pos);
    colour_bar(painter, bar(upper), ColorMap::Viridis, "u [µm]", UM.from_si(1.0), range, text);
    match view.films {
        FilmMaps::SideBySide => {
            let h =
                (scene.film_flexible.min.min(scene.film_rigid.min), scene.film_flexible.max.max(scene.film_rigid.max));
            let w = lower.width() * 0.5;
            let left = Rect::from_min_size(lower.min, Vec2::new(w, lower.height()));
            let right = Rect::from_min_max(Pos2::new(lower.left() + w, lower.top()), lower.max);
            let flexible = MapSpec { map: &scene.film_flexible, name: "h", title: "Film h", range: h };
            let rigid = MapSpec { map: &scene.film_rigid, name: "h-rigid", title: "Film h − u", range: h };
            hover = hover.or(map_ui(ui, view, painter, left, &flexible, hover_pos));
            hover = hover.or(map_ui(ui, view, painter, right, &rigid, hover_pos));
            colour_bar(painter, bar(lower), ColorMap::Viridis, "h [µm]", UM.from_si(1.0), h, text);
        }
        FilmMaps::Difference => {
            let difference = MapSpec { map: &scene.displacement, name: "u", title: "Film h − (h − u)", range };
            hover = hover.or(map_ui(ui, view, painter, lower, &difference, hover_pos));
            colour_bar(painter, bar(lower), ColorMap::Viridis, "Δh [µm]", UM.from_si(1.0), range, text);
        }
    }
    hover
}

/// Texture names of the gallery's shape maps.
const MODE_NAMES: [&str; 6] = ["mode-1", "mode-2", "mode-3", "mode-4", "mode-5", "mode-6"];

/// One tile per retained mode: its section (own exaggeration), frequency and film-face shape.
#[allow(clippy::cast_precision_loss)]
fn gallery_ui(
    ui: &Ui,
    view: &mut DeformationView,
    painter: &egui::Painter,
    rect: Rect,
    scene: &PadDeformation,
    hover_pos: Option<Pos2>,
) -> Option<Hover> {
    let text = ui.visuals().text_color();
    text_within(
        painter,
        rect.left_top(),
        Align2::LEFT_TOP,
        "Retained bending modes (on the pivot; each peak drawn at 15 % of the thickness)",
        FontId::proportional(12.0),
        text,
        rect.width(),
    );
    let body = Rect::from_min_max(rect.min + Vec2::new(0.0, 18.0), rect.max);
    let w = body.width() / scene.modes.len().max(1) as f32;
    let mut hover = None;
    for (k, tile) in scene.modes.iter().enumerate() {
        let r = Rect::from_min_size(body.min + Vec2::new(w * k as f32, 0.0), Vec2::new(w - 8.0, body.height()));
        painter.rect_stroke(r, 4.0, Stroke::new(1.0, Color32::from_gray(90)), egui::StrokeKind::Inside);
        let title = format!(
            "Mode {}: {} Hz, amplitude {} µm",
            tile.mode + 1,
            sig4(tile.frequency_hz),
            sig4(UM.from_si(tile.amplitude_m))
        );
        let range = symmetric(tile.shape.min, tile.shape.max);
        let upper = Rect::from_min_max(r.min, Pos2::new(r.right(), r.top() + r.height() * 0.6));
        let lower = Rect::from_min_max(Pos2::new(r.left(), upper.bottom()), r.max);
        // Shapes are per unit amplitude: hover reads the mode's part of the deformation at its solved amplitude.
        let at_amplitude = |h: Hover| Hover {
            what: format!("{} (mode {} at its solved amplitude)", h.what, tile.mode + 1),
            value_m: h.value_m * tile.amplitude_m,
        };
        hover =
            hover
                .or(section_ui(painter, upper.shrink(4.0), &tile.section, range, hover_pos, &title, text)
                    .map(at_amplitude));
        let shape_title = format!("Mode {} film-face shape", tile.mode + 1);
        let name = MODE_NAMES.get(tile.mode).copied().unwrap_or("mode-n");
        let spec = MapSpec { map: &tile.shape, name, title: &shape_title, range };
        hover = hover.or(map_ui(ui, view, painter, lower.shrink(4.0), &spec, hover_pos).map(at_amplitude));
    }
    hover
}
