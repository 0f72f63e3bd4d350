//! The results panel: the scalar results in display units with their meaning, per-pad results, and the
//! solver report with its warnings — shown plainly, including when the result is stale or failed.

use crate::app::ink;
use egui::{Grid, RichText, Ui};

use crate::scene::summary::Summary;

/// What the mark of an unloaded pad means.
const UNLOADED: &str = "unloaded: the film carries (almost) no load on this pad.";

/// Widest column of a result group [points]: about 28 monospace characters.
const VALUE_WIDTH: f32 = 220.0;

/// Draws the summary; `hide_timings` replaces wall-clock times (for reproducible screenshots).
pub fn results_panel_ui(ui: &mut Ui, summary: &Summary, hide_timings: bool) {
    for group in &summary.groups {
        egui::CollapsingHeader::new(RichText::new(group.title).strong()).default_open(true).show(ui, |ui| {
            let value_width = value_width(ui, group);
            Grid::new(group.title).num_columns(3).striped(true).show(ui, |ui| {
                for row in &group.rows {
                    ui.label(&row.label).on_hover_text(&row.meaning);
                    let value = if hide_timings && row.unit == "ms" { "—".to_string() } else { row.value.clone() };
                    // A long value (the method of a Hertz-pivot solve) wraps instead of widening the panel.
                    ui.scope(|ui| {
                        ui.set_max_width(value_width);
                        ui.add(egui::Label::new(RichText::new(value).monospace()).wrap()).on_hover_text(&row.meaning);
                    });
                    ui.label(&row.unit);
                    ui.end_row();
                }
            });
        });
    }
    egui::CollapsingHeader::new(RichText::new("Pads").strong()).default_open(true).show(ui, |ui| {
        // The loads share the engineering prefix of the largest (kN for the compressor).
        let loads: Vec<f64> = summary.pads.iter().map(|p| p.load_n).collect();
        let (loads, load_unit) = shared_decimals(&loads, "N");
        // Names above their units: seven columns fit the panel at 1280 points.
        let load_header = format!("load\n[{load_unit}]");
        Grid::new("pads").striped(true).spacing([6.0, 4.0]).min_col_width(0.0).show(ui, |ui| {
            let headers = [
                ("pad", "Pad number, from the first pad in the direction of rotation."),
                ("tilt\n[mrad]", "Tilt angle of the pad about its pivot."),
                ("h_min\n[µm]", "Smallest film thickness on the pad."),
                ("p_max\n[MPa]", "Largest film pressure on the pad."),
                (load_header.as_str(), "Magnitude of the film force on the pad."),
                (
                    "orifice\n[l/min]",
                    "Net flow through the pad's orifices into the film (negative: out through the hole).",
                ),
                ("cav.\n[%]", "Share of the pad's film area that is cavitated (ruptured, p = 0)."),
            ];
            for (h, meaning) in headers {
                ui.label(RichText::new(h).small()).on_hover_text(meaning);
            }
            ui.end_row();
            for (p, load) in summary.pads.iter().zip(&loads) {
                if p.unloaded {
                    ui.label(format!("{} *", p.index)).on_hover_text(UNLOADED);
                } else {
                    ui.label(p.index.to_string());
                }
                ui.label(p.tilt_mrad.map_or("fixed".into(), |t| format!("{t:.4}")));
                ui.label(format!("{:.2}", p.h_min_um));
                ui.label(format!("{:.3}", p.p_max_mpa));
                ui.label(load);
                ui.label(p.orifice_flow_l_min.map_or("–".into(), |q| format!("{q:.3}")));
                ui.label(format!("{:.0}", p.cavitated_percent));
                ui.end_row();
            }
        });
        if summary.pads.iter().any(|p| p.unloaded) {
            ui.label(RichText::new(format!("* {UNLOADED}")).small());
        }
    });
    if summary.warnings.is_empty() {
        ui.label(RichText::new("No solver warnings").weak());
    } else {
        // Wrapped inside the visible panel: the scroll area's content may be wider (a pinned comparison),
        // and a long warning must not run under the window's edge.
        let width = (ui.clip_rect().right() - ui.cursor().left() - 8.0).max(120.0);
        for w in &summary.warnings {
            ui.scope(|ui| {
                ui.set_max_width(width);
                ui.add(egui::Label::new(RichText::new(format!("Warning: {w}")).color(ink::WARNING.of(ui))).wrap());
            });
        }
    }
}

/// The width of a group's value column: at most [`VALUE_WIDTH`], and no wider than the room the panel shows
/// beside the widest label and the widest unit, so a long value wraps and its unit stays in view.
fn value_width(ui: &Ui, group: &crate::scene::summary::Group) -> f32 {
    let width = |text: &str, mono: bool| {
        let font = if mono { egui::TextStyle::Monospace } else { egui::TextStyle::Body }.resolve(ui.style());
        ui.painter().layout_no_wrap(text.to_string(), font, egui::Color32::WHITE).size().x
    };
    let widest = |texts: &mut dyn Iterator<Item = &String>| texts.map(|t| width(t, false)).fold(0.0_f32, f32::max);
    let label = widest(&mut group.rows.iter().map(|r| &r.label));
    let unit = widest(&mut group.rows.iter().map(|r| &r.unit));
    let gaps = 2.0 * ui.spacing().item_spacing.x + ui.spacing().scroll.bar_width + 4.0;
    let room = ui.clip_rect().right() - ui.cursor().left() - label - unit - gaps;
    room.clamp(width("0.000", true), VALUE_WIDTH)
}

/// Values of one SI unit in one column: the engineering prefix of the largest and the decimals that give it
/// four significant digits, the same for every value, so a column reads aligned and an unloaded pad's
/// round-off force (7.5e-8 N beside 2.5 kN) reads 0.000 kN rather than "7.485e-11".
#[must_use]
pub fn shared_decimals(values_si: &[f64], unit_si: &str) -> (Vec<String>, String) {
    let largest = values_si.iter().filter(|v| v.is_finite()).fold(0.0_f64, |m, v| m.max(v.abs()));
    let (scale, prefix) = crate::number::eng_prefix(largest);
    // The prefix brings the largest into [1, 1000): 1 to 3 digits before the point.
    #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
    let decimals = (3.0 - (largest / scale).max(1.0).log10().floor()).clamp(0.0, 3.0) as usize;
    let text = |v: f64| {
        let t = format!("{:.decimals$}", v / scale);
        // "-0.000" is a zero.
        if t.trim_start_matches('-').chars().all(|c| c == '0' || c == '.') {
            t.trim_start_matches('-').to_string()
        } else {
            t
        }
    };
    (values_si.iter().map(|&v| text(v)).collect(), format!("{prefix}{unit_si}"))
}

#[cfg(test)]
mod tests {
    use super::shared_decimals;

    #[test]
    fn a_column_shares_its_prefix_and_decimals() {
        let (v, unit) = shared_decimals(&[7.485e-8, 189.0, 1005.0, 2499.0, -2.0e-9], "N");
        assert_eq!(
            (v, unit.as_str()),
            (vec!["0.000".into(), "0.189".into(), "1.005".into(), "2.499".into(), "0.000".into()], "kN")
        );
        let (v, unit) = shared_decimals(&[25_400.0, 312_000.0], "N");
        assert_eq!((v, unit.as_str()), (vec!["25.4".into(), "312.0".into()], "kN"));
    }
}
