//! Colours that mean something (an error, a warning, the load arrow …), each in a dark-theme and a
//! light-theme shade, so a word or a mark reads on both backgrounds.
//!
//! Contract: every [`Ink`] used for text has a contrast of at least 4.5:1 (WCAG 2 AA for normal text)
//! against the panel fill of its theme, and every mark (arrows, outlines) at least 3:1 (WCAG's minimum for
//! graphics); the unit tests below check both. The shade is picked from `visuals.dark_mode` at the moment
//! of drawing, so switching the theme recolours everything on the next frame. [`apply`] gives egui's own
//! warning and error colours (used by its widgets) the same treatment.

use egui::{Color32, Visuals};

/// A colour with a meaning, as one shade per theme.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Ink {
    pub dark: Color32,
    pub light: Color32,
}

impl Ink {
    /// The shade for `visuals` (dark or light theme).
    #[must_use]
    pub fn on(self, visuals: &Visuals) -> Color32 {
        if visuals.dark_mode {
            self.dark
        } else {
            self.light
        }
    }

    /// The shade for the theme `ui` is drawn in.
    #[must_use]
    pub fn of(self, ui: &egui::Ui) -> Color32 {
        self.on(ui.visuals())
    }
}

/// A failure: a solve that failed, an invalid value, a write that did not happen.
pub const ERROR: Ink = Ink { dark: Color32::from_rgb(235, 95, 85), light: Color32::from_rgb(185, 30, 30) };
/// A warning or a caution (the last valid result is shown, a file will be replaced, a model's range).
pub const WARNING: Ink = Ink { dark: Color32::from_rgb(235, 155, 65), light: Color32::from_rgb(160, 75, 0) };
/// A design limit exceeded (the limits list, the sweep's points beyond a limit, API 617 in the rotor view).
pub const EXCEEDED: Ink = Ink { dark: Color32::from_rgb(240, 90, 75), light: Color32::from_rgb(180, 35, 25) };
/// All is well (solved, within the design limits).
pub const GOOD: Ink = Ink { dark: Color32::from_rgb(120, 200, 120), light: Color32::from_rgb(25, 115, 40) };
/// The static load (arrow and its label).
pub const LOAD: Ink = Ink { dark: Color32::from_rgb(240, 200, 40), light: Color32::from_rgb(130, 95, 0) };
/// The mid-plane pressure drawn inside the journal.
pub const PRESSURE: Ink = Ink { dark: Color32::from_rgb(255, 160, 60), light: Color32::from_rgb(170, 80, 0) };
/// The minimum film thickness of each pad.
pub const H_MIN: Ink = Ink { dark: Color32::from_rgb(235, 70, 70), light: Color32::from_rgb(190, 30, 30) };
/// An injecting orifice.
pub const INJECTION: Ink = Ink { dark: Color32::from_rgb(70, 160, 255), light: Color32::from_rgb(0, 85, 200) };
/// A pinned result drawn over the live one.
pub const PINNED: Ink = Ink { dark: Color32::from_rgb(90, 220, 240), light: Color32::from_rgb(0, 110, 140) };
/// The resultant load on each pivot.
pub const PIVOT_LOAD: Ink = Ink { dark: Color32::from_rgb(235, 125, 45), light: Color32::from_rgb(165, 70, 0) };
/// Reference marks in plots (this case, the operating range, zero lines).
pub const REFERENCE: Ink = Ink { dark: Color32::from_gray(150), light: Color32::from_gray(105) };

/// Every ink used for text.
pub const TEXT_INKS: [Ink; 10] = [ERROR, WARNING, EXCEEDED, GOOD, LOAD, PRESSURE, H_MIN, INJECTION, PINNED, PIVOT_LOAD];

/// Gives egui's warning and error colours (its widgets' own messages) shades that read on the light theme;
/// the dark theme keeps egui's.
pub fn apply(ctx: &egui::Context) {
    ctx.style_mut_of(egui::Theme::Light, |s| {
        s.visuals.warn_fg_color = WARNING.light;
        s.visuals.error_fg_color = ERROR.light;
    });
}

/// WCAG 2 relative luminance of an sRGB colour.
fn luminance(c: Color32) -> f64 {
    let lin = |v: u8| {
        let v = f64::from(v) / 255.0;
        if v <= 0.040_45 {
            v / 12.92
        } else {
            ((v + 0.055) / 1.055).powf(2.4)
        }
    };
    0.2126 * lin(c.r()) + 0.7152 * lin(c.g()) + 0.0722 * lin(c.b())
}

/// WCAG 2 contrast ratio of two colours (1 to 21): text needs 4.5, graphics and large text 3.
#[must_use]
pub fn contrast(a: Color32, b: Color32) -> f64 {
    let (la, lb) = (luminance(a), luminance(b));
    (la.max(lb) + 0.05) / (la.min(lb) + 0.05)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn contrast_ratio_of_black_on_white_is_21() {
        assert!((contrast(Color32::BLACK, Color32::WHITE) - 21.0).abs() < 1e-9);
        assert!((contrast(Color32::WHITE, Color32::WHITE) - 1.0).abs() < 1e-12);
    }

    /// Text inks: 4.5:1 on their theme's panel and window fills; the dark shade would fail on the light
    /// theme for most of them (which is why there are two shades).
    #[test]
    fn every_text_ink_reads_on_its_theme() {
        let (dark, light) = (Visuals::dark(), Visuals::light());
        for ink in TEXT_INKS {
            for bg in [dark.panel_fill, dark.window_fill, dark.extreme_bg_color] {
                assert!(contrast(ink.dark, bg) >= 4.5, "{ink:?} on {bg:?}: {:.2}", contrast(ink.dark, bg));
            }
            for bg in [light.panel_fill, light.window_fill, light.extreme_bg_color] {
                assert!(contrast(ink.light, bg) >= 4.5, "{ink:?} on {bg:?}: {:.2}", contrast(ink.light, bg));
            }
        }
        let fails_on_light = TEXT_INKS.iter().filter(|i| contrast(i.dark, light.panel_fill) < 4.5).count();
        assert!(fails_on_light >= 7, "{fails_on_light}");
    }

    #[test]
    fn reference_marks_read_as_graphics_on_both_themes() {
        assert!(contrast(REFERENCE.dark, Visuals::dark().panel_fill) >= 3.0);
        assert!(contrast(REFERENCE.light, Visuals::light().panel_fill) >= 3.0);
    }

    #[test]
    fn the_light_theme_gets_readable_warnings() {
        let ctx = egui::Context::default();
        apply(&ctx);
        let light = ctx.style_of(egui::Theme::Light);
        assert_eq!((light.visuals.warn_fg_color, light.visuals.error_fg_color), (WARNING.light, ERROR.light));
        assert_eq!(ctx.style_of(egui::Theme::Dark).visuals.warn_fg_color, Visuals::dark().warn_fg_color);
    }
}
