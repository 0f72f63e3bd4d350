//! The rotor sketch of the rotor view ([`super::rotor_view`]): the shaft to scale along its axis with its
//! diameters exaggerated to fit a 124-point strip, the disks (blue), the bearings (orange triangles), the
//! bearings given by numbers and the supports (red ×) and the unbalances (red dots); the selected item
//! framed. A click returns what it hit: the nearest item within a few points, else the shaft section at
//! that axial position, as a [`Selected`] for the rotor editor.
//!
//! Screen x grows with the axial position z (from the rotor's left end); screen y points down.

use egui::{Color32, Stroke, Ui};

use super::rotor_edit::Selected;
use super::rotor_plots::{BACKWARD, FORWARD, LIMIT};
use crate::scene::rotor::{RotorSketch, SketchItem};

/// Where the sketch draws an item of `kind` at axial screen position `px`, about the shaft axis `mid`.
fn item_rect(kind: SketchItem, px: f32, mid: f32) -> egui::Rect {
    match kind {
        SketchItem::Disk => egui::Rect::from_center_size(egui::pos2(px, mid), egui::vec2(6.0, 60.0)),
        SketchItem::Bearing => {
            egui::Rect::from_min_max(egui::pos2(px - 7.0, mid + 17.0), egui::pos2(px + 7.0, mid + 29.0))
        }
        SketchItem::Numbers | SketchItem::Support => {
            egui::Rect::from_center_size(egui::pos2(px, mid + 24.0), egui::vec2(10.0, 10.0))
        }
        SketchItem::Unbalance => egui::Rect::from_center_size(egui::pos2(px, mid - 38.0), egui::vec2(8.0, 8.0)),
    }
}

/// The selection an item of the sketch stands for: its `rank`-th entry among the items of its table.
fn item_selection(kind: SketchItem, rank: usize) -> Option<Selected> {
    match kind {
        SketchItem::Disk => Some(Selected::Disk(rank)),
        SketchItem::Bearing | SketchItem::Numbers => Some(Selected::Bearing(rank)),
        SketchItem::Unbalance => Some(Selected::Unbalance(rank)),
        SketchItem::Support => None,
    }
}

/// The rotor to scale along its axis, diameters exaggerated to fit the strip; the `selected` item framed.
/// A click selects the item under the pointer (within a few points), else the shaft section there
/// (`section_of_element`: the section of each element).
#[allow(clippy::cast_possible_truncation)] // millimetres to screen points
pub(super) fn sketch_ui(
    ui: &mut Ui,
    s: &RotorSketch,
    section_of_element: &[usize],
    selected: Option<Selected>,
) -> Option<Selected> {
    let width = ui.available_width().min(ui.clip_rect().width());
    let (rect, response) = ui.allocate_exact_size(egui::vec2(width, 124.0), egui::Sense::click());
    response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Image, true, "rotor sketch"));
    let painter = ui.painter_at(rect);
    let (limit, backward) = (LIMIT.of(ui), BACKWARD.of(ui));
    let margin = 12.0;
    let sx = (rect.width() - 2.0 * margin) / s.length_mm.max(1e-9) as f32;
    let sy = 30.0 / s.max_diameter_mm.max(1e-9) as f32;
    let x = |z: f64| rect.left() + margin + z as f32 * sx;
    let mid = rect.top() + 50.0;
    let fill = Color32::from_gray(170);
    let mark = Stroke::new(2.0, ui.visuals().strong_text_color());
    // Items with their rank in their rotor table (disks; bearings and numbers; supports; unbalances).
    let mut counts = [0_usize; 4];
    let items: Vec<(f64, SketchItem, usize)> = s
        .items
        .iter()
        .map(|&(z, kind, _)| {
            let table = match kind {
                SketchItem::Disk => 0,
                SketchItem::Bearing | SketchItem::Numbers => 1,
                SketchItem::Support => 2,
                SketchItem::Unbalance => 3,
            };
            counts[table] += 1;
            (z, kind, counts[table] - 1)
        })
        .collect();
    for (e, [z0, z1, d, di]) in s.sections.iter().enumerate() {
        let (h, hi) = (*d as f32 * sy / 2.0, *di as f32 * sy / 2.0);
        let r = egui::Rect::from_min_max(egui::pos2(x(*z0), mid - h), egui::pos2(x(*z1), mid + h));
        painter.rect_filled(r, 0.0, fill);
        if hi > 0.0 {
            painter.rect_filled(
                egui::Rect::from_min_max(egui::pos2(x(*z0), mid - hi), egui::pos2(x(*z1), mid + hi)),
                0.0,
                ui.visuals().extreme_bg_color,
            );
        }
        if let (Some(Selected::Section(i)), Some(&sec)) = (selected, section_of_element.get(e)) {
            if i == sec {
                painter.rect_stroke(r, 0.0, mark, egui::StrokeKind::Outside);
            }
        }
    }
    for &(z, kind, rank) in &items {
        let r = item_rect(kind, x(z), mid);
        match kind {
            SketchItem::Disk => {
                painter.rect_filled(r, 1.0, FORWARD);
            }
            SketchItem::Bearing => {
                painter.add(egui::Shape::convex_polygon(
                    vec![r.center_top(), r.left_bottom(), r.right_bottom()],
                    backward,
                    Stroke::NONE,
                ));
            }
            SketchItem::Numbers | SketchItem::Support => {
                painter.line_segment([r.left_top(), r.right_bottom()], Stroke::new(2.0, limit));
                painter.line_segment([r.left_bottom(), r.right_top()], Stroke::new(2.0, limit));
            }
            SketchItem::Unbalance => {
                painter.circle_filled(r.center(), 4.0, limit);
                painter
                    .line_segment([r.center_bottom(), egui::pos2(r.center().x, mid - 30.0)], Stroke::new(1.0, limit));
            }
        }
        if selected.is_some() && item_selection(kind, rank) == selected {
            painter.rect_stroke(r.expand(3.0), 2.0, mark, egui::StrokeKind::Outside);
        }
    }
    let text = ui.visuals().weak_text_color();
    // Two lines under the shaft: the scale, then the legend (side by side they overlap in a narrow panel).
    painter.text(
        egui::pos2(rect.left() + margin, rect.bottom() - 16.0),
        egui::Align2::LEFT_BOTTOM,
        format!("0 — {:.0} mm (diameters ×{:.0})", s.length_mm, sy / sx),
        egui::FontId::proportional(11.0),
        text,
    );
    painter.text(
        egui::pos2(rect.left() + margin, rect.bottom() - 2.0),
        egui::Align2::LEFT_BOTTOM,
        "blue: disks, orange: bearings, red ×: coefficients by numbers, red dots: unbalances",
        egui::FontId::proportional(11.0),
        text,
    );
    let click = response.interact_pointer_pos().filter(|_| response.clicked())?;
    // The nearest item whose drawing (grown by a few points) holds the click, else the section at its z.
    let hit = items
        .iter()
        .filter(|&&(z, kind, _)| item_rect(kind, x(z), mid).expand(4.0).contains(click))
        .min_by(|a, b| (x(a.0) - click.x).abs().total_cmp(&(x(b.0) - click.x).abs()))
        .and_then(|&(_, kind, rank)| item_selection(kind, rank));
    hit.or_else(|| {
        let z = f64::from((click.x - rect.left() - margin) / sx);
        let e = s.sections.iter().position(|sec| z >= sec[0] && z <= sec[1])?;
        section_of_element.get(e).map(|&i| Selected::Section(i))
    })
}
