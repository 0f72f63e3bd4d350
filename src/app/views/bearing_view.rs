//! The bearing cross-section: journal, pads with their tilt, pivots, orifices, load, minimum film
//! thickness, and the mid-plane pressure around each pad — drawn from [`BearingOutline`]; a pinned result's
//! outline dashed over it; the scales can be locked across edits. Before the first result: the case's
//! outline, unsolved.

use egui::{Align2, Color32, FontId, Mesh, Pos2, Rect, RichText, Sense, Shape, Stroke, Ui, Vec2};
use serde::{Deserialize, Serialize};

use super::{View, ViewContext};
use crate::app::ink;
use crate::number::{eng, sig};
use crate::bearing::solution::limits::{Check, LimitKind};
use crate::bearing::stages::StageId;
use crate::scene::outline::{self, BearingOutline, OutlineScales, Point};
use crate::scene::summary::{self, PadRow};
use crate::units::{MPA, UM};

const PAD_FILL: Color32 = Color32::from_rgb(150, 135, 110);
const JOURNAL_FILL: Color32 = Color32::from_rgb(95, 105, 120);
const PRESSURE_FILL: Color32 = Color32::from_rgba_premultiplied(200, 110, 20, 170);
const INJECTION: Color32 = Color32::from_rgb(70, 160, 255);
const LOAD: Color32 = Color32::from_rgb(240, 200, 40);

/// The bearing view.
#[derive(Debug, Default)]
pub struct BearingView {
    pub settings: BearingSettings,
}

/// What the bearing view keeps between sessions.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct BearingSettings {
    /// Locked film exaggeration and pressure scale (`None`: chosen per picture).
    pub outline_lock: Option<OutlineScales>,
    /// The user unlocked the scales. Until then they lock on the first result, so that a class comparing
    /// pictures before and after an edit sees the field change, not the scale.
    pub unlocked: bool,
}

impl View for BearingView {
    fn id(&self) -> &'static str {
        "bearing"
    }

    fn label(&self) -> &'static str {
        "Bearing"
    }

    fn needs(&self) -> &'static [StageId] {
        &[StageId::Reduction]
    }

    fn ui(&mut self, ui: &mut Ui, cx: &mut ViewContext<'_>) {
        let case = cx.shown.map(|s| s.solution.inputs.clone()).or_else(|| cx.case().cloned());
        let Some(case) = case else { return };
        let pinned = cx.compare_with_ui(ui, self.needs(), |_| {});
        let solution = cx.shown.map(|s| s.solution.as_ref());
        let lock = &mut self.settings.outline_lock;
        // Locked on the first result of the edited case (not on an earlier case's, still drawn while the
        // newly opened one solves).
        if lock.is_none() && !self.settings.unlocked && solution.is_some() && !cx.stale {
            *lock = Some(outline::bearing_outline_with(&case, solution, None).scales());
        }
        let o = outline::bearing_outline_with(&case, solution, *lock);
        let free = outline::bearing_outline_with(&case, solution, None).scales();
        if lock_ui(ui, lock, o.scales()) {
            self.settings.unlocked = lock.is_none();
        }
        scale_note_ui(ui, *lock, free, solution.map(|s| s.p_max_pa));
        let pads = solution.map(|s| summary::summary(s).pads).unwrap_or_default();
        let checks = solution.map(|s| crate::bearing::solution::limits::check(&s.inputs.limits, s)).unwrap_or_default();
        let Some((name, p)) = pinned else {
            bearing_view_ui(ui, &o, &pads, &checks, cx.stale, None);
            return;
        };
        match geometry_difference(&case.bearing, &p.solution.inputs.bearing) {
            // The pinned outline at the live picture's scales, so the two overlay.
            None => {
                let over = outline::bearing_outline_with(&p.solution.inputs, Some(&p.solution), Some(o.scales()));
                bearing_view_ui(ui, &o, &pads, &checks, cx.stale, Some((name.as_str(), &over)));
            }
            // Another geometry is never drawn over this journal: beside it, each at its own scales.
            Some(why) => {
                ui.colored_label(
                    ink::PINNED.of(ui),
                    format!(
                        "Pinned \"{name}\" is another bearing ({why}): drawn beside this one at its own scales, not \
                         over it; the results panel compares the numbers."
                    ),
                );
                let pin_outline = outline::bearing_outline_with(&p.solution.inputs, Some(&p.solution), None);
                let pin_pads = summary::summary(&p.solution).pads;
                let pin_checks = crate::bearing::solution::limits::check(&p.solution.inputs.limits, &p.solution);
                ui.columns(2, |cols| {
                    let [live, pin] = cols else { return };
                    live.label(RichText::new("Live").strong());
                    bearing_view_ui(live, &o, &pads, &checks, cx.stale, None);
                    pin.label(RichText::new(format!("Pinned \"{name}\"")).strong().color(ink::PINNED.of(pin)));
                    bearing_view_ui(pin, &pin_outline, &pin_pads, &pin_checks, false, None);
                });
            }
        }
    }

    /// The case's outline, unsolved.
    fn placeholder_ui(&mut self, ui: &mut Ui, cx: &mut ViewContext<'_>) {
        self.ui(ui, cx);
    }

    fn settings(&mut self) -> Option<&mut dyn super::view::Settings> {
        Some(&mut self.settings)
    }

    /// Another bearing's scales would draw this one's film and pressure out of proportion: the lock is
    /// dropped, and taken again on the new case's first result (unless the user unlocked the scales). A
    /// variant of the same bearing keeps it, as an edit does, so the two pictures compare.
    fn case_opened(&mut self, same_bearing: bool) {
        if !same_bearing {
            self.settings.outline_lock = None;
        }
    }
}

/// How the bearing `b` differs in geometry from `a` (the journal, the clearance, the pads' arcs, angles,
/// offsets, clearances and thickness), said in words; `None`: the same geometry, so one may be drawn over the
/// other. Everything else (the operating point, the physics, the pivots' stiffness) may differ.
#[must_use]
pub fn geometry_difference(a: &crate::model::case::Bearing, b: &crate::model::case::Bearing) -> Option<String> {
    use crate::units::MM;
    let mut why = Vec::new();
    if a.journal_radius_m != b.journal_radius_m {
        why.push(format!("its R {} mm, this one's {} mm", sig(MM.from_si(b.journal_radius_m), 5), sig(MM.from_si(a.journal_radius_m), 5)));
    }
    if a.length_m != b.length_m {
        why.push(format!("its L {} mm, this one's {} mm", sig(MM.from_si(b.length_m), 5), sig(MM.from_si(a.length_m), 5)));
    }
    if a.assembled_clearance_m != b.assembled_clearance_m {
        why.push(format!("its Cb {} µm, this one's {} µm", sig(UM.from_si(b.assembled_clearance_m), 5), sig(UM.from_si(a.assembled_clearance_m), 5)));
    }
    if a.pads.len() != b.pads.len() {
        why.push(format!("its {} pads, this one's {}", b.pads.len(), a.pads.len()));
    } else if a.pads.iter().zip(&b.pads).any(|(p, q)| {
        (p.kind, p.leading_edge_rad, p.arc_rad, p.pivot_rad, p.offset, p.clearance_m, p.thickness_m)
            != (q.kind, q.leading_edge_rad, q.arc_rad, q.pivot_rad, q.offset, q.clearance_m, q.thickness_m)
    }) {
        why.push("its pads differ".into());
    }
    (!why.is_empty()).then(|| why.join(", "))
}

/// Maps the bearing frame (metres, y up) to the screen (points, y down).
#[derive(Debug, Clone, Copy)]
pub struct ScreenFromBearing {
    centre: Pos2,
    points_per_m: f32,
}

impl ScreenFromBearing {
    #[must_use]
    pub fn fit(rect: Rect, extent_m: f64) -> Self {
        #[allow(clippy::cast_possible_truncation)]
        let points_per_m = (0.5 * rect.width().min(rect.height()) / extent_m as f32).max(1e-3);
        Self { centre: rect.center(), points_per_m }
    }

    #[must_use]
    #[allow(clippy::cast_possible_truncation)]
    pub fn map(&self, p: Point) -> Pos2 {
        Pos2::new(self.centre.x + self.points_per_m * p[0] as f32, self.centre.y - self.points_per_m * p[1] as f32)
    }
}

/// A filled band between two polylines of equal length (pads, pressure), as a triangle mesh
/// (the bands are not convex, so a polygon fill would be wrong).
fn band(a: &[Pos2], b: &[Pos2], color: Color32) -> Shape {
    let mut mesh = Mesh::default();
    for (p, q) in a.iter().zip(b) {
        mesh.colored_vertex(*p, color);
        mesh.colored_vertex(*q, color);
    }
    #[allow(clippy::cast_possible_truncation)]
    for i in 0..a.len().min(b.len()).saturating_sub(1) as u32 {
        let k = 2 * i;
        mesh.add_triangle(k, k + 1, k + 2);
        mesh.add_triangle(k + 1, k + 3, k + 2);
    }
    Shape::mesh(mesh)
}

fn arrow(painter: &egui::Painter, from: Pos2, to: Pos2, stroke: Stroke) {
    painter.line_segment([from, to], stroke);
    let dir = (to - from).normalized();
    let n = Vec2::new(-dir.y, dir.x);
    let head = 10.0;
    painter.add(Shape::convex_polygon(
        vec![to, to - dir * head + n * head * 0.45, to - dir * head - n * head * 0.45],
        stroke.color,
        Stroke::NONE,
    ));
}

/// The "Lock scales" toggle: locked, the film exaggeration and the pressure scale stay those of the
/// picture on screen when it was locked, so pictures before and after an edit compare.
/// Returns whether the user toggled it.
pub fn lock_ui(ui: &mut Ui, lock: &mut Option<OutlineScales>, current: OutlineScales) -> bool {
    let mut locked = lock.is_some();
    let text = match lock {
        Some(l) => format!("Lock scales (film × {}, pressure {})", l.exaggeration, eng(l.pressure_scale_pa, "Pa")),
        None => "Lock scales".to_string(),
    };
    if ui
        .checkbox(&mut locked, text)
        .on_hover_text("Keep the film exaggeration and the pressure scale fixed across edits, so two pictures compare.")
        .changed()
    {
        *lock = locked.then_some(current);
        return true;
    }
    false
}

/// What the picture's scales mean for this result, said beside it: locked, whether the result's peak
/// pressure goes past the locked pressure scale (its band is drawn longer than R/3); unlocked, when the
/// scales changed from the previous picture (a class would otherwise read a new scale as a new field).
fn scale_note_ui(ui: &mut Ui, lock: Option<OutlineScales>, free: OutlineScales, p_max_pa: Option<f64>) {
    let warn = ui.visuals().warn_fg_color;
    match (lock, p_max_pa) {
        (Some(l), Some(p)) if p > l.pressure_scale_pa * (1.0 + 1e-9) => {
            // Past twice the scale the band would cross the journal's centre: it is cut at 2R/3.
            let reach = if p > 2.0 * l.pressure_scale_pa {
                "its band is cut at 2R/3 (unlock the scales to see it whole)"
            } else {
                "its band reaches further"
            };
            ui.colored_label(
                warn,
                format!(
                    "Peak pressure {} is above the locked scale ({} at R/3): {reach}.",
                    eng(p, "Pa"),
                    eng(l.pressure_scale_pa, "Pa")
                ),
            );
        }
        (None, Some(_)) => {
            let id = ui.make_persistent_id("bearing-free-scales");
            let (before, now): (Option<OutlineScales>, Option<OutlineScales>) =
                ui.data(|d| d.get_temp(id)).unwrap_or((None, None));
            let (before, now) = if now == Some(free) { (before, now) } else { (now, Some(free)) };
            ui.data_mut(|d| d.insert_temp(id, (before, now)));
            // Said only when the change shows in the numbers printed (a scale a rounding apart is the same).
            let printed = |s: &OutlineScales| (eng(s.pressure_scale_pa, "Pa"), s.exaggeration.to_string());
            if let Some(b) = before.filter(|b| printed(b) != printed(&free)) {
                ui.colored_label(
                    warn,
                    format!(
                        "Scales changed with this result: pressure {} to {} at R/3, film × {} to × {}.",
                        eng(b.pressure_scale_pa, "Pa"),
                        eng(free.pressure_scale_pa, "Pa"),
                        b.exaggeration,
                        free.exaggeration
                    ),
                );
            }
        }
        _ => {}
    }
}

/// Draws the cross-section into the available space.
/// `checks`: the solution's design-limit checks (exceeded ones are listed, h_min below its limit marked).
/// `pinned`: a pinned result's name and outline (at the same scales), drawn dashed over the live one.
#[allow(clippy::too_many_lines)]
pub fn bearing_view_ui(
    ui: &mut Ui,
    outline: &BearingOutline,
    pads: &[PadRow],
    checks: &[Check],
    stale: bool,
    pinned: Option<(&str, &BearingOutline)>,
) {
    // Scale and colour notes, as text a screen reader finds.
    ui.label(format!("To scale, except film thickness and journal displacement × {}", outline.exaggeration));
    ui.horizontal_wrapped(|ui| {
        if outline.pressure_scale_pa > 0.0 {
            ui.colored_label(
                ink::PRESSURE.of(ui),
                format!(
                    "Mid-plane pressure inside the journal ({} drawn at R/3)",
                    eng(outline.pressure_scale_pa, "Pa")
                ),
            );
        }
        ui.colored_label(ink::H_MIN.of(ui), "Minimum film thickness of each pad");
        ui.colored_label(ink::LOAD.of(ui), "Static load W");
        if outline.pads.iter().any(|p| p.injecting) {
            ui.colored_label(ink::INJECTION.of(ui), "Injecting orifice");
        }
        if stale {
            ui.colored_label(ink::WARNING.of(ui), "Showing the last valid result");
        }
        if let Some((name, _)) = pinned {
            ui.colored_label(ink::PINNED.of(ui), format!("Pinned \"{name}\" (dashed: journal, pad film surfaces, pressure)"));
        }
    });
    for c in checks.iter().filter(|c| c.exceeded) {
        ui.colored_label(
            ink::EXCEEDED.of(ui),
            format!("Exceeds design limit: {}", crate::scene::limits::text(c)),
        );
    }
    let film_limit = checks.iter().find(|c| c.kind == LimitKind::MinFilmThickness).map_or(0.0, |c| c.limit);
    let size = ui.available_size();
    let (response, painter) = ui.allocate_painter(size, Sense::hover());
    let rect = response.rect;
    let to_screen = ScreenFromBearing::fit(rect.shrink(24.0), outline.extent_m);
    let map = |pts: &[Point]| -> Vec<Pos2> { pts.iter().map(|&p| to_screen.map(p)).collect() };
    let font = FontId::proportional(13.0);

    // Bearing centre.
    let c0 = to_screen.map([0.0, 0.0]);
    painter.line_segment([c0 - Vec2::X * 8.0, c0 + Vec2::X * 8.0], Stroke::new(1.0, Color32::GRAY));
    painter.line_segment([c0 - Vec2::Y * 8.0, c0 + Vec2::Y * 8.0], Stroke::new(1.0, Color32::GRAY));

    // Journal.
    let journal = map(&outline.journal);
    painter.add(Shape::convex_polygon(journal.clone(), JOURNAL_FILL, Stroke::new(1.0, Color32::from_gray(200))));
    let jc = to_screen.map(outline.journal_centre);
    painter.circle_filled(jc, 3.0, Color32::WHITE);
    // Direction of rotation: counter-clockwise, an arc with an arrowhead.
    // Screen points: f32 precision is what the painter draws with.
    #[allow(clippy::cast_possible_truncation)]
    let r_rot = 0.22 * to_screen.points_per_m * outline.journal_radius_m as f32;
    let arc: Vec<Pos2> = (0..=24)
        .map(|i| {
            let a = 0.35 + 1.1 * std::f32::consts::PI * i as f32 / 24.0;
            jc + Vec2::new(a.cos(), -a.sin()) * r_rot
        })
        .collect();
    painter.add(Shape::line(arc.clone(), Stroke::new(1.5, Color32::from_gray(220))));
    if let [.., a, b] = arc.as_slice() {
        arrow(&painter, *a, *b + (*b - *a) * 0.01, Stroke::new(1.5, Color32::from_gray(220)));
    }
    painter.text(jc + Vec2::new(0.0, -r_rot - 4.0), Align2::CENTER_BOTTOM, "Ω", font.clone(), Color32::from_gray(230));

    // Every pad's outline and pivot, which the h_min labels keep clear of.
    let mut obstacles: Vec<Vec<Pos2>> = Vec::new();
    for pad in &outline.pads {
        let mut edge = map(&pad.film_surface);
        edge.extend(map(&pad.back).into_iter().rev());
        if let Some(&first) = edge.first() {
            edge.push(first);
        }
        obstacles.push(edge);
        if !pad.fixed {
            let mut tri = map(&pad.pivot);
            if let Some(&first) = tri.first() {
                tri.push(first);
            }
            obstacles.push(tri);
        }
    }
    for pad in &outline.pads {
        // Pressure inside the journal, from its surface inwards.
        if !pad.pressure.is_empty() {
            let n = pad.pressure.len() / 2;
            let outer = map(&pad.pressure[..n]);
            let inner: Vec<Pos2> = map(&pad.pressure[n..]).into_iter().rev().collect();
            painter.add(band(&outer, &inner, PRESSURE_FILL));
            painter.add(Shape::line(inner, Stroke::new(1.0, Color32::from_rgb(255, 160, 60))));
        }
        let film = map(&pad.film_surface);
        let back = map(&pad.back);
        painter.add(band(&film, &back, if pad.fixed { Color32::from_gray(120) } else { PAD_FILL }));
        let mut edge = film.clone();
        edge.extend(back.iter().rev());
        edge.push(film[0]);
        painter.add(Shape::line(edge, Stroke::new(1.0, Color32::from_gray(40))));
        for [a, b] in &pad.orifices {
            let color = if pad.injecting { INJECTION } else { Color32::from_rgb(60, 55, 50) };
            let (a, b) = ([to_screen.map(a[0]), to_screen.map(a[1])], [to_screen.map(b[0]), to_screen.map(b[1])]);
            painter.add(Shape::convex_polygon(vec![a[0], a[1], b[1], b[0]], color, Stroke::NONE));
        }
        if !pad.fixed {
            let tri = map(&pad.pivot);
            painter.add(Shape::convex_polygon(tri, Color32::from_gray(70), Stroke::new(1.0, Color32::from_gray(20))));
        }
        painter.text(
            to_screen.map(pad.label_at),
            Align2::CENTER_CENTER,
            pad.index.to_string(),
            font.clone(),
            Color32::BLACK,
        );
        if let Some((j, p, h)) = pad.h_min {
            let (a, b) = (to_screen.map(j), to_screen.map(p));
            let h_min_ink = ink::H_MIN.on(&ui.style().visuals);
            painter.line_segment([a, b], Stroke::new(2.5, h_min_ink));
            painter.circle_filled(a, 2.5, h_min_ink);
            let below = if h < film_limit { " < limit" } else { "" };
            let galley = painter.layout_no_wrap(format!("{}{below}", eng(h, "m")), FontId::proportional(11.0), h_min_ink);
            let at = clear_label_rect(jc, b, galley.size(), &obstacles);
            obstacles.push(vec![at.left_top(), at.right_top(), at.right_bottom(), at.left_bottom(), at.left_top()]);
            painter.galley(at.min, galley, h_min_ink);
        }
    }
    if let Some((_, p)) = pinned {
        overlay(&painter, &to_screen, p, ink::PINNED.of(ui));
    }
    // Hovering a pad shows its results.
    if let Some(pos) = response.hover_pos() {
        let near = outline
            .pads
            .iter()
            .map(|p| (p.index, to_screen.map(p.label_at).distance(pos)))
            .min_by(|a, b| a.1.total_cmp(&b.1));
        if let Some((k, _)) = near.filter(|n| n.1 < 40.0) {
            if let Some(row) = pads.iter().find(|r| r.index == k) {
                let tilt = row.tilt_mrad.map_or("fixed sector".into(), |t| format!("tilt {}", eng(t * 1e-3, "rad")));
                let text = format!(
                    "Pad {k}{}\n{tilt}\nh_min {}, p_max {}\nfilm force {}, cavitated {} %",
                    if row.unloaded { " (unloaded)" } else { "" },
                    eng(UM.to_si(row.h_min_um), "m"),
                    eng(MPA.to_si(row.p_max_mpa), "Pa"),
                    eng(row.load_n, "N"),
                    sig(row.cavitated_percent, 3)
                );
                response.clone().on_hover_text_at_pointer(text);
            }
        }
    }
    if let Some((from, to, w)) = outline.load {
        let (a, b) = (to_screen.map(from), to_screen.map(to));
        arrow(&painter, a, b, Stroke::new(3.0, LOAD));
        load_label(&painter, (a, b), &format!("W = {}", eng(w, "N")), font.clone());
    }
}

/// Where a label of `size` goes on the ray from the journal centre `jc` through `b` (a pad's film surface at
/// its minimum film thickness): the first place outwards from `b` where it keeps [`LABEL_GAP`] points from
/// every polyline of `obstacles` (pad outlines, pivots, labels placed before), at most 200 points out.
fn clear_label_rect(jc: Pos2, b: Pos2, size: Vec2, obstacles: &[Vec<Pos2>]) -> Rect {
    let away = (b - jc).normalized();
    // From the centre to the rectangle's edge along `away`.
    let half = 0.5 * (size.x * away.x.abs() + size.y * away.y.abs());
    let at = |d: f32| Rect::from_center_size(b + away * (half + d), size);
    // Neither crossing an outline nor inside one (a thick pad holds a whole label between its outlines).
    (0..100_u8)
        .map(|k| at(LABEL_GAP + 2.0 * f32::from(k)))
        .find(|r| !obstacles.iter().any(|line| touches(r.expand(LABEL_GAP), line) || encloses(line, r.center())))
        .unwrap_or_else(|| at(LABEL_GAP))
}

/// The closed polyline `ring` (first point repeated last) encloses `p` (even-odd rule).
#[must_use]
pub fn encloses(ring: &[Pos2], p: Pos2) -> bool {
    let mut inside = false;
    for s in ring.windows(2) {
        let (a, b) = (s[0], s[1]);
        if (a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x) {
            inside = !inside;
        }
    }
    inside
}

/// The clear space between an h_min label and the outlines [points].
const LABEL_GAP: f32 = 3.0;

/// Some segment of the polyline `line` crosses or lies in `rect`.
#[must_use]
pub fn touches(rect: Rect, line: &[Pos2]) -> bool {
    line.windows(2).any(|s| segment_meets_rect(s[0], s[1], rect))
}

/// The segment `a`–`b` meets `rect` (Liang–Barsky clipping: the part of the segment inside is not empty).
fn segment_meets_rect(a: Pos2, b: Pos2, rect: Rect) -> bool {
    let d = b - a;
    let (mut t0, mut t1) = (0.0_f32, 1.0_f32);
    for (p, q) in [
        (-d.x, a.x - rect.left()),
        (d.x, rect.right() - a.x),
        (-d.y, a.y - rect.top()),
        (d.y, rect.bottom() - a.y),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return false;
            }
        } else {
            let t = q / p;
            if p < 0.0 {
                t0 = t0.max(t);
            } else {
                t1 = t1.min(t);
            }
            if t0 > t1 {
                return false;
            }
        }
    }
    true
}

/// The load's label beside the middle of its arrow `a → b` (at the tip it lay on the pressure fill), on a
/// backing so that it reads over the journal and the pressure.
fn load_label(painter: &egui::Painter, (a, b): (Pos2, Pos2), text: &str, font: egui::FontId) {
    let galley = painter.layout_no_wrap(text.to_string(), font, LOAD);
    let d = (b - a).normalized();
    // The side of the arrow to the right of the screen (or above it for a horizontal arrow).
    let side = if d.y.abs() > 1e-3 { Vec2::new(-d.y, d.x) * (-d.y).signum() } else { Vec2::new(0.0, -1.0) };
    let anchor = if side.x.abs() >= side.y.abs() { Align2::LEFT_CENTER } else { Align2::CENTER_BOTTOM };
    let rect = anchor.anchor_size(a + 0.5 * (b - a) + side * 8.0, galley.size());
    painter.rect_filled(rect.expand(2.0), 3.0, Color32::from_black_alpha(170));
    painter.galley(rect.min, galley, LOAD);
}

/// A pinned outline over the live one: the journal, each pad's film surface and the pressure, dashed.
fn overlay(painter: &egui::Painter, to_screen: &ScreenFromBearing, pinned: &BearingOutline, color: Color32) {
    let map = |pts: &[Point]| -> Vec<Pos2> { pts.iter().map(|&p| to_screen.map(p)).collect() };
    let stroke = Stroke::new(1.6, color);
    let dashed = |pts: &[Pos2]| painter.extend(Shape::dashed_line(pts, stroke, 6.0, 4.0));
    let mut journal = map(&pinned.journal);
    if let Some(&first) = journal.first() {
        journal.push(first);
    }
    dashed(&journal);
    painter.circle_stroke(to_screen.map(pinned.journal_centre), 4.0, stroke);
    for pad in &pinned.pads {
        dashed(&map(&pad.film_surface));
        if !pad.pressure.is_empty() {
            let n = pad.pressure.len() / 2;
            dashed(&map(&pad.pressure[n..]));
        }
        if let Some((j, q, _)) = pad.h_min {
            painter.line_segment([to_screen.map(j), to_screen.map(q)], Stroke::new(1.0, color));
        }
    }
}
