//! Pad fields unwrapped onto (circumferential × axial): a colour map per pad with a legend, a hover
//! readout, the orifices, and optionally the flowlines of the mean film velocity.
//!
//! Each pad is drawn to scale (arc length horizontally, leading edge on the left, rotation to the right;
//! axial length vertically, +L/2 at the top). All pads share one colour range so they compare.
//!
//! Compared with a pin ([`FieldOptions::pinned`]): the live and the pinned pads side by side under one
//! colour range, or one map per pad of live − pinned in a diverging map ([`crate::scene::field_compare`]).
//! The colour range of a field can be locked so it stays across edits.
//!
//! This file holds the view's settings, its caches and its layout; the painting of the pads and the
//! colour bar are in [`super::field_paint`].

use std::collections::HashMap;
use std::sync::Arc;

use egui::{Align2, FontId, Pos2, Rect, RichText, Sense, TextStyle, Ui, Vec2};

use serde::{Deserialize, Serialize};

use crate::app::ink;
use super::{View, ViewContext};
use crate::bearing::stages::StageId;
use crate::bearing::Solution;
use crate::scene::colormap::ColorMap;
use super::plot_kit::footer_height;
use super::field_paint::{colour_bar, Layer, Panel, PanelDraw, Readout, Source};
use crate::scene::field::{FieldKind, PadMap};
use crate::scene::field_compare::{
    difference_maps, drawn_range, lock_for, set_lock, shared_range, FieldScaleLock, Mismatch,
};
use crate::scene::summary::sig4;

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

    /// Colour ranges locked on another bearing do not describe this one (a 2 MPa range over a 4.5 MPa
    /// field): they are dropped. A variant of the same bearing keeps them, as an edit does.
    fn case_opened(&mut self, same_bearing: bool) {
        if !same_bearing {
            self.settings.locks.clear();
        }
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
    let title = if difference { format!("Δ {} [{unit}]", kind.label()) } else { format!("{} [{unit}]", kind.label()) };
    let meaning = if difference { "live − pinned, grey = unchanged" } else { "perceptually uniform" };
    let scale_line = format!(
        "Colour scale: {title} from {} to {} ({meaning}). Hatched: cavitated film (ruptured, p = 0).",
        sig4(range.0 * scale),
        sig4(range.1 * scale)
    );
    // The painted area; the readout and the scale are real labels below it (readable by screen readers
    // and tests), measured first so that the scale's last line stays inside the view.
    let footer = footer_height(ui, full.width(), &[("Hover", TextStyle::Body), (&scale_line, TextStyle::Body)]);
    let avail = Rect::from_min_max(full.min, full.max - Vec2::new(0.0, footer));
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
    ui.add(egui::Label::new(line).truncate());
    ui.add(egui::Label::new(scale_line).wrap());
    readout
}
