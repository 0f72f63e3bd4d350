//! The pivot-load view: what each pad carries — the load it puts on its pivot, its share of the static load
//! and, for Hertz pivots, the contact's approach and tangent stiffness — as a table, and a sketch of the
//! bearing with the force on each pivot drawn to scale with the load.
//!
//! Conventions (bearing frame, x right, y up, angles from +x counter-clockwise):
//! - `F_k` is pad k's film force on the journal; the pads balance the static load, `Σ F_k = −W`, so pad k's
//!   share of the load is `−F_k · Ŵ / |W|` (the shares add up to 100 %; a pad pressing the journal along
//!   the load, an unloaded upper pad with preload, has a negative share);
//! - the pad puts `−F_k` on its pivot (a massless pad in equilibrium): its radial part, positive pressing
//!   the pivot outwards along the pivot line `ê_p = (cos θ_p, sin θ_p)`, is what a Hertz pivot carries; its
//!   tangential part (positive in the direction of rotation) vanishes for a tilting pad, whose film force
//!   has no moment about the pivot and so acts along the pivot line.

use egui::{Align2, Color32, FontId, Grid, Pos2, RichText, Sense, Shape, Stroke, Ui, Vec2};

use super::bearing_view::ScreenFromBearing;
use crate::app::ink;
use super::{View, ViewContext};
use crate::bearing::stages::StageId;
use crate::bearing::Solution;
use crate::model::case::PadKind;
use crate::physics::hertz::ContactState;
use crate::scene::summary::sig4;
use crate::units::{DEG, MN_PER_M, UM};

const PAD: Color32 = Color32::from_rgb(150, 135, 110);
const JOURNAL: Color32 = Color32::from_rgb(95, 105, 120);

/// What one pad carries [SI].
#[derive(Debug, Clone, PartialEq)]
pub struct PadLoad {
    pub pad: usize,
    /// The pad tilts on a pivot (else a fixed sector: no pivot load).
    pub tilting: bool,
    pub pivot_rad: f64,
    /// Film force on the journal `F_k` [N].
    pub force_n: [f64; 2],
    pub magnitude_n: f64,
    /// Share of the static load, `−F_k · Ŵ / |W|` (sums to 1 over the pads).
    pub share: f64,
    /// The pad's force on its pivot along the pivot line (> 0 pressing it outwards) and across it (> 0 in
    /// the direction of rotation) [N].
    pub radial_n: f64,
    pub tangential_n: f64,
    /// The Hertz contact at its load (Hertz pivots only).
    pub contact: Option<ContactState>,
}

/// What each pad of `s` carries.
#[must_use]
pub fn pad_loads(s: &Solution) -> Vec<PadLoad> {
    let w = s.load_magnitude_n;
    let load_dir = if w > 0.0 { [s.load_n[0] / w, s.load_n[1] / w] } else { [0.0, 0.0] };
    s.pads
        .iter()
        .map(|p| {
            let geometry = s.inputs.bearing.pads.get(p.index);
            let pivot_rad = geometry.map_or(0.0, |g| g.pivot_rad);
            let [fx, fy] = p.force_n;
            let (sin, cos) = pivot_rad.sin_cos();
            PadLoad {
                pad: p.index,
                tilting: geometry.is_some_and(|g| g.kind == PadKind::Tilting),
                pivot_rad,
                force_n: p.force_n,
                magnitude_n: fx.hypot(fy),
                share: if w > 0.0 { -(fx * load_dir[0] + fy * load_dir[1]) / w } else { 0.0 },
                radial_n: -(fx * cos + fy * sin),
                tangential_n: -(-fx * sin + fy * cos),
                contact: p.pivot_contact,
            }
        })
        .collect()
}

/// The pivot-load view (no state of its own).
#[derive(Debug, Default)]
pub struct PivotLoadView;

impl View for PivotLoadView {
    fn id(&self) -> &'static str {
        "pivot_loads"
    }

    fn label(&self) -> &'static str {
        "Pivot loads"
    }

    fn needs(&self) -> &'static [StageId] {
        &[StageId::Reduction]
    }

    fn ui(&mut self, ui: &mut Ui, cx: &mut ViewContext<'_>) {
        let Some(shown) = cx.shown else { return };
        let s = &shown.solution;
        let loads = pad_loads(s);
        ui.label(format!(
            "Static load W = {} at {}°, carried by {} pads (Σ share = {} %)",
            crate::number::eng(s.load_magnitude_n, "N"),
            sig4(DEG.from_si(s.load_angle_rad()).rem_euclid(360.0)),
            loads.len(),
            sig4(100.0 * loads.iter().map(|l| l.share).sum::<f64>())
        ));
        table_ui(ui, &loads);
        if !loads.iter().any(|l| l.contact.is_some()) {
            ui.label(
                RichText::new("No Hertz pivot contact in this case (compressor-bearing-rocker-pivot has rocker pivots).")
                    .weak(),
            );
        }
        sketch_ui(ui, s, &loads);
    }

    fn snapshot_setup(&mut self) -> Option<&'static str> {
        Some(include_str!("../../../cases/compressor-bearing-rocker-pivot.toml"))
    }
}

/// One row per pad: its pivot, the load on the pivot, its share of the static load and, when the case has
/// Hertz pivots, the contact's approach and tangent stiffness. (The film force of a tilting pad acts along
/// its pivot line: its magnitude is the pivot load, and a Hertz contact carries it.)
fn table_ui(ui: &mut Ui, loads: &[PadLoad]) {
    let hertz = loads.iter().any(|l| l.contact.is_some());
    let number = |ui: &mut Ui, text: String| ui.label(RichText::new(text).monospace());
    Grid::new("pivot-loads").striped(true).min_col_width(40.0).show(ui, |ui| {
        let mut headers = vec![
            ("pad".to_string(), "Pad number, from +x counter-clockwise."),
            (format!("pivot\n[{}]", DEG.symbol), "Pivot angle θ_p from +x, counter-clockwise."),
            (
                "pivot load\n[N]".to_string(),
                "The pad's force on its pivot along the pivot line (its film force on the journal, reversed); a fixed sector has no pivot (its film force is given).",
            ),
            (
                "share of W\n[%]".to_string(),
                "The pad's film force along −W over |W|: the shares add up to 100 %; negative: the pad pushes the journal along the load (a preloaded, unloaded pad).",
            ),
        ];
        if hertz {
            headers.push((format!("contact δ\n[{}]", UM.symbol), "Hertz approach of the pivot contact at its load."));
            headers.push((
                format!("contact k\n[{}]", MN_PER_M.symbol),
                "Tangent stiffness dF/dδ of the pivot contact at its load (what the dynamic coefficients use).",
            ));
        }
        for (h, meaning) in headers {
            ui.label(RichText::new(h).strong()).on_hover_text(meaning);
        }
        ui.end_row();
        for l in loads {
            ui.label(if l.tilting { l.pad.to_string() } else { format!("{} (fixed)", l.pad) });
            number(ui, format!("{:.0}", DEG.from_si(l.pivot_rad).rem_euclid(360.0)));
            number(ui, sig4(if l.tilting { l.radial_n } else { l.magnitude_n }));
            number(ui, format!("{:.1}", 100.0 * l.share));
            if hertz {
                match &l.contact {
                    Some(c) => {
                        number(ui, format!("{:.2}", UM.from_si(c.approach_m)));
                        number(ui, sig4(MN_PER_M.from_si(c.tangent_n_per_m)));
                    }
                    None => {
                        ui.label("—");
                        ui.label("—");
                    }
                }
            }
            ui.end_row();
        }
    });
}

/// The bearing (journal, pads, pivots) with each pad's force on its pivot as an arrow from the pivot and the
/// static load at the centre, all to one force scale.
fn sketch_ui(ui: &mut Ui, s: &Solution, loads: &[PadLoad]) {
    ui.label(
        RichText::new("Arrows: each pad's force on its pivot (orange) and the static load W (yellow), to one scale")
            .small(),
    );
    let size = Vec2::new(ui.available_width().min(ui.clip_rect().width()), ui.available_height().max(160.0));
    let (response, painter) = ui.allocate_painter(size, Sense::hover());
    response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Image, true, "pivot load sketch"));
    let r = s.inputs.bearing.journal_radius_m;
    let (pad_in, pad_out, reach) = (1.1 * r, 1.28 * r, 0.7 * r);
    let to_screen = ScreenFromBearing::fit(response.rect.shrink(16.0), pad_out + reach);
    let polar = |radius: f64, angle: f64| to_screen.map([radius * angle.cos(), radius * angle.sin()]);
    let largest = loads.iter().map(|l| l.magnitude_n).fold(s.load_magnitude_n, f64::max).max(1e-12);
    let font = FontId::proportional(12.0);
    // The load and its label lie on the journal, which has one fill in both themes: the dark theme's shade.
    let (pivot_ink, load_ink) = (ink::PIVOT_LOAD.of(ui), ink::LOAD.dark);
    let circle: Vec<Pos2> = (0..72).map(|i| polar(r, f64::from(i) * 5.0_f64.to_radians())).collect();
    painter.add(Shape::convex_polygon(circle, JOURNAL, Stroke::NONE));
    for (l, g) in loads.iter().zip(&s.inputs.bearing.pads) {
        let arc = |radius: f64| -> Vec<Pos2> {
            (0..=24).map(|i| polar(radius, g.leading_edge_rad + g.arc_rad * f64::from(i) / 24.0)).collect()
        };
        let mut outline = arc(pad_in);
        outline.extend(arc(pad_out).into_iter().rev());
        outline.push(outline[0]);
        painter.add(Shape::line(outline, Stroke::new(2.0, PAD)));
        let mid = g.leading_edge_rad + 0.5 * g.arc_rad;
        painter.text(polar(0.5 * (pad_in + pad_out), mid), Align2::CENTER_CENTER, l.pad.to_string(), font.clone(), PAD);
        if !l.tilting {
            continue;
        }
        // The pad's force on the pivot, −F_k, from the pivot outwards.
        let from = [pad_out * l.pivot_rad.cos(), pad_out * l.pivot_rad.sin()];
        let k = reach / largest;
        let to = [from[0] - k * l.force_n[0], from[1] - k * l.force_n[1]];
        painter.circle_filled(to_screen.map(from), 3.5, Color32::WHITE);
        arrow(&painter, to_screen.map(from), to_screen.map(to), pivot_ink);
        let anchor = to_screen.map(to);
        let outwards = (anchor - to_screen.map([0.0, 0.0])).normalized();
        let align = if outwards.x >= 0.0 { Align2::LEFT_CENTER } else { Align2::RIGHT_CENTER };
        painter.text(anchor + outwards * 6.0, align, crate::number::eng(l.magnitude_n, "N"), font.clone(), pivot_ink);
    }
    let k = reach / largest;
    let tip = [k * s.load_n[0], k * s.load_n[1]];
    arrow(&painter, to_screen.map([0.0, 0.0]), to_screen.map(tip), load_ink);
    painter.text(
        to_screen.map([0.0, 0.0]) + Vec2::new(6.0, -6.0),
        Align2::LEFT_BOTTOM,
        format!("W = {}", crate::number::eng(s.load_magnitude_n, "N")),
        font,
        load_ink,
    );
}

fn arrow(painter: &egui::Painter, from: Pos2, to: Pos2, color: Color32) {
    let d = to - from;
    if d.length() < 1.0 {
        return;
    }
    painter.line_segment([from, to], Stroke::new(2.5, color));
    let dir = d.normalized();
    let n = Vec2::new(-dir.y, dir.x);
    painter.add(Shape::convex_polygon(vec![to, to - dir * 9.0 + n * 4.0, to - dir * 9.0 - n * 4.0], color, Stroke::NONE));
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bearing::solve_case;
    use crate::model::load_case;

    fn solved(text: &str) -> Solution {
        solve_case(&load_case(text, &[]).unwrap().1).unwrap()
    }

    /// The compressor bearing, load on pad 3 (pivot 276°, load 270°): the pads' shares add up to the load,
    /// pad 3 carries most of it, and every film force passes its pad's load to the pivot unchanged.
    #[test]
    fn the_shares_add_up_to_the_load_and_the_loaded_pad_carries_most() {
        let s = solved(include_str!("../../../cases/compressor-bearing.toml"));
        let loads = pad_loads(&s);
        let total: f64 = loads.iter().map(|l| l.share).sum();
        assert!((total - 1.0).abs() < 1e-6, "Σ share = {total}");
        let most = loads.iter().max_by(|a, b| a.share.total_cmp(&b.share)).unwrap();
        assert_eq!(most.pad, 3);
        assert!(most.share > 0.5 && most.share < 1.0, "{}", most.share);
        for l in &loads {
            assert!((l.radial_n.hypot(l.tangential_n) - l.magnitude_n).abs() < 1e-9 * s.load_magnitude_n);
            assert!(l.tilting && l.contact.is_none());
            // A tilting pad's film force acts along its pivot line (no moment about the pivot) and presses it.
            assert!(l.tangential_n.abs() < 1e-6 * s.load_magnitude_n && l.radial_n > 0.0, "{l:?}");
        }
    }

    /// Rocker pivots: each Hertz contact carries its pad's load along the pivot line.
    #[test]
    fn a_hertz_contact_carries_the_radial_pivot_load() {
        let s = solved(include_str!("../../../cases/compressor-bearing-rocker-pivot.toml"));
        for l in pad_loads(&s) {
            let c = l.contact.expect("every pad on a rocker");
            assert!((c.load_n - l.radial_n).abs() < 1e-4 * s.load_magnitude_n, "pad {}: {c:?} vs {l:?}", l.pad);
            assert!(c.approach_m > 0.0 && c.tangent_n_per_m > 0.0);
        }
    }
}
