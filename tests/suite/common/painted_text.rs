//! The text a frame painted, read from its output shapes: what each string reads and where it shows
//! (its glyphs' bounds cut by its clip rectangle), to check that no two strings cover one another.
#![cfg(feature = "gui")]

use egui::epaint::{ClippedShape, Shape};
use egui::Rect;

/// A painted line of text and the part of it that shows.
#[derive(Debug, Clone)]
pub struct PaintedText {
    pub text: String,
    /// The glyphs' bounds cut by the clip rectangle.
    pub shown: Rect,
    /// The glyphs' bounds.
    pub full: Rect,
}

fn push(text: String, full: Rect, clip: Rect, out: &mut Vec<PaintedText>) {
    let shown = full.intersect(clip);
    if !text.is_empty() && shown.is_positive() {
        out.push(PaintedText { text, shown, full });
    }
}

fn collect(shape: &Shape, clip: Rect, out: &mut Vec<PaintedText>) {
    match shape {
        Shape::Vec(shapes) => shapes.iter().for_each(|s| collect(s, clip, out)),
        // Line by line: a label wrapped over two lines leaves room beside each for its neighbours.
        Shape::Text(t) if t.angle == 0.0 => {
            for placed in &t.galley.rows {
                let full = placed.row.visuals.mesh_bounds.translate(t.pos.to_vec2() + placed.pos.to_vec2());
                push(placed.row.text().trim().to_string(), full, clip, out);
            }
        }
        Shape::Text(t) => push(t.galley.text().trim().to_string(), shape.visual_bounding_rect(), clip, out),
        _ => {}
    }
}

/// The strings of `shapes` that show, in paint order.
#[must_use]
pub fn painted_texts(shapes: &[ClippedShape]) -> Vec<PaintedText> {
    let mut out = Vec::new();
    for c in shapes {
        collect(&c.shape, c.clip_rect, &mut out);
    }
    out
}

/// Pairs of shown strings inside `within` that cover one another by more than `slack` points both ways
/// (glyph bounds of neighbouring lines may touch by a pixel or two).
#[must_use]
pub fn overlapping(texts: &[PaintedText], within: Rect, slack: f32) -> Vec<(PaintedText, PaintedText)> {
    let inside: Vec<&PaintedText> = texts.iter().filter(|t| within.intersects(t.shown)).collect();
    let mut pairs = Vec::new();
    for (i, a) in inside.iter().enumerate() {
        for b in &inside[i + 1..] {
            let common = a.shown.intersect(b.shown);
            if common.width() > slack && common.height() > slack {
                pairs.push(((*a).clone(), (*b).clone()));
            }
        }
    }
    pairs
}
