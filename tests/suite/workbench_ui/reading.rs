//! Reading what a frame shows: tick labels of plots, the field view's colour scale, and the layout checks
//! (strings over strings, widgets over widgets, strings cut at their area's edge or pushed below the view).

use egui::accesskit::Role;
use egui_kittest::kittest::Queryable;
use egui_kittest::Harness;
use tiltpad::app::WorkbenchApp;
use tiltpad::scene::field::{FieldKind, PadMap};
use tiltpad::units::MPA;

use crate::common::painted_text;

use super::harness::text_of;

/// The numbers a plot shows on its axes, found from its x-axis title `axis` (each plot with that title,
/// below `below` points, so a control of the same text above the plots is not taken for one): per plot,
/// (the numeric labels just above the title: x ticks; the numeric labels left of its middle between the
/// title and the nearest words above, its legend: y ticks). Tick labels read as numbers after a prefix
/// (k, M) or a degree sign is dropped.
pub(crate) fn tick_labels(h: &Harness<'_, WorkbenchApp>, axis: &str, below: f32) -> Vec<(Vec<String>, Vec<String>)> {
    let texts = painted_text::painted_texts(&h.output().shapes);
    let view = h.state().view_rect().expect("a view on screen");
    let numeric = |t: &str| t.trim_end_matches(['k', 'M', 'G', '°']).replace('−', "-").parse::<f64>().is_ok();
    texts
        .iter()
        .filter(|t| t.text == axis && t.shown.top() > below)
        .map(|a| {
            let (mid, top) = (a.shown.center().x, a.shown.top());
            let column = |t: &&painted_text::PaintedText| {
                view.contains_rect(t.shown) && (t.shown.center().x - mid).abs() < 200.0
            };
            let x: Vec<String> = texts
                .iter()
                .filter(|t| numeric(&t.text) && (t.shown.center().x - mid).abs() < 130.0)
                .filter(|t| t.shown.center().y < top && t.shown.center().y > top - 24.0)
                .map(|t| t.text.clone())
                .collect();
            let legend = texts
                .iter()
                .filter(column)
                // Words written across (a rotated y-axis title spans the plot's height).
                .filter(|t| !numeric(&t.text) && t.shown.width() > t.shown.height() && t.shown.bottom() < top - 24.0)
                .map(|t| t.shown.bottom())
                .fold(f32::MIN, f32::max);
            let y: Vec<String> = texts
                .iter()
                .filter(column)
                .filter(|t| numeric(&t.text) && t.shown.center().x < mid - 40.0)
                .filter(|t| t.shown.center().y < top - 24.0 && t.shown.center().y > legend)
                .map(|t| t.text.clone())
                .collect();
            (x, y)
        })
        .collect()
}

/// Strings that cover one another in the last frame, anywhere in the window, as "a" / "b" at their rects.
pub(crate) fn overlapping_texts(h: &Harness<'_, WorkbenchApp>) -> Vec<String> {
    let texts = painted_text::painted_texts(&h.output().shapes);
    let screen = h.ctx.content_rect();
    painted_text::overlapping(&texts, screen, 2.0)
        .into_iter()
        .map(|(a, b)| format!("{:?} at {:?} / {:?} at {:?}", a.text, a.shown, b.text, b.shown))
        .collect()
}

/// Widgets (labels, buttons, fields, boxes, sliders) that cover one another in the last frame: in the
/// editor, the view and the results panel, each widget whole inside its area (a widget scrolled partly
/// out of its panel is laid out where it would be, not where it shows).
pub(crate) fn overlapping_widgets(h: &Harness<'_, WorkbenchApp>) -> Vec<String> {
    let Some(view) = h.state().view_rect() else { return Vec::new() };
    let (screen, top) = (h.ctx.content_rect(), h.get_by_label("File").rect().bottom());
    let areas = [
        egui::Rect::from_min_max(egui::pos2(screen.left(), top), egui::pos2(view.left() - 1.0, view.bottom())),
        view,
        egui::Rect::from_min_max(egui::pos2(view.right() + 1.0, top), egui::pos2(screen.right(), view.bottom())),
    ];
    let roles =
        [Role::Label, Role::Button, Role::CheckBox, Role::ComboBox, Role::SpinButton, Role::TextInput, Role::Slider];
    let nodes: Vec<(String, egui::Rect)> = roles
        .iter()
        .flat_map(|&role| h.query_all_by_role(role).map(move |n| (format!("{role:?} {:?}", text_of(&n)), n.rect())))
        .collect();
    let mut found = Vec::new();
    for area in areas {
        let inside: Vec<&(String, egui::Rect)> = nodes.iter().filter(|(_, r)| area.contains_rect(*r)).collect();
        for (i, a) in inside.iter().enumerate() {
            // Two labels: a label wrapped beside another spans both lines; their glyphs are checked by
            // `overlapping_texts`.
            for b in inside[i + 1..].iter().filter(|b| !(a.0.starts_with("Label") && b.0.starts_with("Label"))) {
                let common = a.1.intersect(b.1);
                if common.width() > 1.0 && common.height() > 1.0 {
                    found.push(format!("{} at {:?} / {} at {:?}", a.0, a.1, b.0, b.1));
                }
            }
        }
    }
    found
}

/// Strings of the open view cut by their clip rectangle (drawn past the edge of what holds them): those
/// shown inside the view, and those that begin in it and run past its edge (a slider's name past the
/// results panel's edge shows partly outside the view).
pub(crate) fn cut_texts_in_view(h: &Harness<'_, WorkbenchApp>) -> Vec<String> {
    let Some(view) = h.state().view_rect() else { return Vec::new() };
    painted_text::painted_texts(&h.output().shapes)
        .into_iter()
        .filter(|t| view.contains_rect(t.shown) || view.contains(t.full.left_top()))
        .filter(|t| t.shown.width() + 1.0 < t.full.width())
        .map(|t| format!("{:?} shown {:?} of {:?}", t.text, t.shown, t.full))
        .collect()
}

/// Strings inside the open view laid out past its bottom edge (a footer line pushed out of the window).
pub(crate) fn texts_below_view(h: &Harness<'_, WorkbenchApp>) -> Vec<String> {
    let Some(view) = h.state().view_rect() else { return Vec::new() };
    painted_text::painted_texts(&h.output().shapes)
        .into_iter()
        .filter(|t| t.full.left() >= view.left() && t.full.right() <= view.right() + 1.0)
        .filter(|t| t.full.top() < view.bottom() && t.full.bottom() > view.bottom() + 1.0)
        .map(|t| format!("{:?} at {:?} past the view's bottom {}", t.text, t.full, view.bottom()))
        .collect()
}

/// The colour-scale label of the field view: "… from LO to HI (…)" as two numbers.
pub(crate) fn colour_scale(h: &Harness<'_, WorkbenchApp>) -> (String, String) {
    let t = text_of(&h.get_by_label_contains("Colour scale: "));
    let range = t.split(" from ").nth(1).unwrap().split(" (").next().unwrap().to_string();
    let (lo, hi) = range.split_once(" to ").unwrap();
    (lo.to_string(), hi.to_string())
}

/// The largest pressure of a result, as the field view's colour range reaches it [MPa].
pub(crate) fn p_max_mpa(s: &tiltpad::bearing::Solution) -> f64 {
    MPA.from_si(PadMap::all(s, FieldKind::Pressure).iter().map(|m| m.max).fold(0.0, f64::max))
}
