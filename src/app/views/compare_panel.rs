//! The "Compare" part of the results panel: pin the current result under a name (several pins, kept
//! across restarts with the persisted settings), and for each pin the live and pinned values of every
//! output column side by side with their differences ([`crate::scene::compare`]).

use egui::{Grid, RichText, Ui};

use crate::bearing::Solution;
use crate::scene::compare::{compare, pin_name, Pin};
use crate::scene::summary::sig4;

/// What the panel asks the app to do.
pub enum CompareAction {
    /// Export the pins and the live result as CSV.
    ExportCsv(String),
    /// The live result was pinned (the last pin).
    Pinned,
}

/// Units shown with an engineering prefix (`N/m` → `MN/m`): the SI units of the columns. Units already
/// chosen for reading (µm, MPa, l/min, °C) and dimensionless ones stay as they are.
const PREFIXED_UNITS: [&str; 5] = ["N", "N/m", "N·s/m", "W", "N·m"];

/// A row's scale and unit as shown: `kxx` of 3.0e7 N/m in MN/m. The prefix is chosen by the larger of the
/// live and pinned values, so the row's three numbers share it.
#[must_use]
pub fn row_unit(unit: &str, live: Option<f64>, pinned: Option<f64>) -> (f64, String) {
    if !PREFIXED_UNITS.contains(&unit) {
        return (1.0, unit.to_string());
    }
    let largest = live.unwrap_or(0.0).abs().max(pinned.unwrap_or(0.0).abs());
    let (scale, prefix) = crate::number::eng_prefix(largest);
    (scale, format!("{prefix}{unit}"))
}

/// A cell: four significant digits of `v / scale`; a difference below 1e-9 of the values compared
/// (round-off of the same load given twice) shows as 0.
fn value(v: Option<f64>, scale: f64) -> String {
    v.map_or_else(|| "—".into(), |x| sig4(x / scale))
}

/// Width of the number columns [points]: four significant digits, a sign and an exponent fit.
const NUMBER_WIDTH: f32 = 64.0;

/// Draws the panel; `case_toml` is the edited case's text (stored with a new pin).
pub fn compare_ui(ui: &mut Ui, pins: &mut Vec<Pin>, live: &Solution, case_toml: Option<&str>) -> Option<CompareAction> {
    let mut action = None;
    egui::CollapsingHeader::new(RichText::new("Compare with pinned results").strong()).default_open(true).show(ui, |ui| {
        let id = ui.make_persistent_id("pin-name");
        let error_id = ui.make_persistent_id("pin-name-error");
        let mut name = ui.data_mut(|d| d.get_temp::<String>(id)).unwrap_or_default();
        let mut error = ui.data_mut(|d| d.get_temp::<String>(error_id));
        // Wrapped: the button stays inside a narrow results panel (which scrolls sideways).
        ui.horizontal_wrapped(|ui| {
            let label = ui.label("Pin name");
            let hint = pin_name("", pins).unwrap_or_default();
            if ui.add(egui::TextEdit::singleline(&mut name).desired_width(100.0).hint_text(hint)).labelled_by(label.id).changed() {
                error = None;
            }
            if ui.button("Pin current result").on_hover_text("Keep this result as a named reference; the panel then shows live and pinned values with their differences.").clicked() {
                // Names pick pins in the views and name the rows of the export: refuse an ambiguous one.
                match pin_name(&name, pins) {
                    Ok(n) => {
                        pins.push(Pin::new(&n, case_toml.unwrap_or_default(), live));
                        action = Some(CompareAction::Pinned);
                        // The new table's columns are measured in this frame: lay it out again at once
                        // rather than overlapping until the next input.
                        ui.ctx().request_discard("a pin was added");
                        (name, error) = (String::new(), None);
                    }
                    Err(e) => error = Some(e.to_string()),
                }
            }
        });
        if let Some(e) = &error {
            ui.colored_label(ui.visuals().error_fg_color, e);
        }
        ui.data_mut(|d| {
            d.insert_temp(id, name);
            match error {
                Some(e) => {
                    d.insert_temp(error_id, e);
                }
                None => d.remove::<String>(error_id),
            }
        });
        if pins.is_empty() {
            return;
        }
        if ui.button("Export pins and live result as CSV").clicked() {
            action = Some(CompareAction::ExportCsv(crate::scene::compare::pins_csv(pins, Some(live))));
        }
        let mut remove = None;
        for (k, pin) in pins.iter().enumerate() {
            ui.separator();
            ui.horizontal(|ui| {
                ui.label(RichText::new(format!("Live vs \"{}\"", pin.name)).strong());
                if ui.small_button(format!("Remove \"{}\"", pin.name)).clicked() {
                    remove = Some(k);
                }
            });
            Grid::new(("compare", k)).num_columns(5).min_col_width(NUMBER_WIDTH).striped(true).show(ui, |ui| {
                for h in ["quantity", "live", "pinned", "Δ", "Δ %"] {
                    ui.label(RichText::new(h).small());
                }
                ui.end_row();
                for r in compare(live, pin) {
                    let (scale, unit) = row_unit(r.unit, r.live, r.pinned);
                    ui.label(if unit.is_empty() { r.label.clone() } else { format!("{} [{unit}]", r.label) });
                    ui.label(RichText::new(value(r.live, scale)).monospace());
                    ui.label(RichText::new(value(r.pinned, scale)).monospace());
                    // Round-off (the same value given twice) is no difference.
                    let size = r.live.unwrap_or(0.0).abs().max(r.pinned.unwrap_or(0.0).abs());
                    let difference = r.difference.map(|d| if d.abs() <= 1e-9 * size { 0.0 } else { d });
                    let relative = r.relative.map(|x| if difference == Some(0.0) { 0.0 } else { x });
                    let changed = difference.is_some_and(|d| d != 0.0);
                    let color = if changed { ui.visuals().warn_fg_color } else { ui.visuals().weak_text_color() };
                    ui.label(RichText::new(value(difference, scale)).monospace().color(color));
                    ui.label(RichText::new(relative.map_or_else(|| "—".into(), |x| format!("{:+.1}", 100.0 * x))).monospace().color(color));
                    ui.end_row();
                }
            });
        }
        if let Some(k) = remove {
            pins.remove(k);
        }
    });
    action
}

#[cfg(test)]
mod tests {
    use super::row_unit;

    /// The compressor's kxx live 30.17 MN/m against 43.42 MN/m pinned reads in MN/m; units chosen for
    /// reading stay as they are.
    #[test]
    fn rows_of_si_units_take_an_engineering_prefix() {
        assert_eq!(row_unit("N/m", Some(3.017e7), Some(4.342e7)), (1e6, "MN/m".to_string()));
        assert_eq!(row_unit("N·s/m", Some(65_972.0), None), (1e3, "kN·s/m".to_string()));
        assert_eq!(row_unit("W", Some(2516.0), Some(5449.0)), (1e3, "kW".to_string()));
        assert_eq!(row_unit("N", Some(1918.0), Some(1918.0)), (1e3, "kN".to_string()));
        assert_eq!(row_unit("µm", Some(47.06), Some(53.95)), (1.0, "µm".to_string()));
        assert_eq!(row_unit("–", Some(0.4179), None), (1.0, "–".to_string()));
        assert_eq!(row_unit("N/m", None, None), (1.0, "N/m".to_string()));
    }
}
