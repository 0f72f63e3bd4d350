//! The "Compare" part of the results panel: pin the current result under a name (several pins, kept
//! across restarts with the persisted settings), and for each pin the live and pinned values of every
//! output column side by side with their change: in per cent for a magnitude, the difference for an angle or
//! a temperature, every value of a group (the stiffness matrix) in one unit prefix ([`crate::scene::compare`]).

use egui::{Grid, RichText, Ui};

use crate::bearing::solution::outputs::{Digits, OUTPUTS};
use crate::bearing::Solution;
use crate::scene::compare::{compare, pin_name, Pin};
use crate::scene::summary::{shared_prefix, sig4};

/// What the panel asks the app to do.
pub enum CompareAction {
    /// Export the pins and the live result as CSV.
    ExportCsv(String),
    /// The live result was pinned (the last pin).
    Pinned,
}

/// A scale and unit for values of a column's `unit` (the sweep view's plots): an SI unit that the table of
/// outputs shows with a prefix takes the prefix of the larger of `live` and `pinned` (3.0e7 N/m in MN/m);
/// units chosen for reading (µm, MPa, L/min, °C) and dimensionless ones stay as they are.
#[must_use]
pub fn row_unit(unit: &str, live: Option<f64>, pinned: Option<f64>) -> (f64, String) {
    let prefixed = OUTPUTS.iter().any(|o| o.digits == Digits::Prefixed && o.unit.symbol == unit);
    if !prefixed {
        return (1.0, unit.to_string());
    }
    shared_prefix([live, pinned].into_iter().flatten(), unit)
}

/// A cell: four significant digits of `v / scale`.
fn value(v: Option<f64>, scale: f64) -> String {
    v.map_or_else(|| "—".into(), |x| sig4(x / scale))
}

/// What the change column holds.
const CHANGE_MEANING: &str = "Live against pinned: the relative change in per cent for a magnitude; the difference, \
     in the quantity's unit, for an angle or a temperature (whose zero is a convention, so a ratio means nothing).";

/// The pinned cell of a column the pin does not hold.
const NOT_IN_PIN: &str = "n/a";
/// What [`NOT_IN_PIN`] means.
const NOT_IN_PIN_MEANING: &str = "Not in this pin: it was made before this output existed. The workbench adds it by \
     solving the pin's case again (its other values stay as pinned); this one stays empty if that case no longer solves.";

/// Width of the number columns [points]: four significant digits, a sign and a decimal point fit
/// (values of SI units carry a prefix, so they stay below 1000).
const NUMBER_WIDTH: f32 = 58.0;
/// Width of the change column [points]: its six characters ([`crate::scene::compare::CHANGE_CHARS`]: `+24.2%`,
/// `-10.9°`).
const CHANGE_WIDTH: f32 = 48.0;
/// Quantity column [points] below which Δ gives way; names longer than their column wrap onto a second
/// line (never cut: "eccentricity ratio" must read whole).
const QUANTITY_MIN: f32 = 120.0;
/// Narrowest quantity column [points], in a panel too narrow for the numbers and a full name.
const QUANTITY_LEAST: f32 = 80.0;
/// Widest quantity column [points]: the longest name with its unit.
const QUANTITY_MAX: f32 = 230.0;

/// The comparison table's column widths in a panel `room` points wide with `gap` between columns: the
/// quantity, live, pinned, Δ (only when it fits beside the others: it is in the export and the hover of
/// the change) and the change (in per cent for a magnitude, the difference for an angle or a temperature).
/// Fixed from the first frame, so a new pin's table never lays out over itself.
#[must_use]
pub fn column_widths(room: f32, gap: f32) -> Vec<f32> {
    let numbers = |n: usize| n as f32 * (NUMBER_WIDTH + gap) + CHANGE_WIDTH + gap;
    let with_delta = room - numbers(3) >= QUANTITY_MIN;
    let n = if with_delta { 3 } else { 2 };
    let quantity = (room - numbers(n)).clamp(QUANTITY_LEAST, QUANTITY_MAX);
    let mut widths = vec![quantity];
    widths.extend(std::iter::repeat_n(NUMBER_WIDTH, n));
    widths.push(CHANGE_WIDTH);
    widths
}

/// One cell of `width` points: `text` aligned by `align`; a left-aligned (name) cell wraps when longer, a
/// number cell is cut with "…" (full text on hover; four digits and a prefix fit its width).
fn cell(ui: &mut Ui, width: f32, text: RichText, align: egui::Align) -> egui::Response {
    let layout = match align {
        egui::Align::Max => egui::Layout::right_to_left(egui::Align::Center),
        _ => egui::Layout::left_to_right(egui::Align::Center),
    };
    // A name's cell is as high as its wrapped lines: the grid centres a cell in its row by the height asked
    // for, so a name of three lines in a cell asked one line high ran into the next row.
    let lines = |ui: &Ui| {
        egui::WidgetText::from(text.clone())
            .into_galley(ui, Some(egui::TextWrapMode::Wrap), width, egui::TextStyle::Body)
            .size()
            .y
    };
    let one_line = ui.spacing().interact_size.y;
    let height = if align == egui::Align::Min { lines(ui).max(one_line) } else { one_line };
    ui.allocate_ui_with_layout(egui::vec2(width, height), layout, |ui| {
        ui.set_min_width(width);
        ui.set_max_width(width);
        let label = egui::Label::new(text);
        ui.add(if align == egui::Align::Min { label.wrap() } else { label.truncate() })
    })
    .inner
}

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
            // The room that shows (the panel scrolls both ways, so its available width is not what shows),
            // less the width of the floating scroll bar.
            let room = ui.clip_rect().right() - ui.cursor().left() - ui.spacing().scroll.bar_width;
            let widths = column_widths(room, ui.spacing().item_spacing.x);
            let with_delta = widths.len() == 5;
            let (right, left) = (egui::Align::Max, egui::Align::Min);
            Grid::new(("compare", k)).num_columns(widths.len()).striped(true).show(ui, |ui| {
                let headers: &[&str] = if with_delta { &["quantity", "live", "pinned", "Δ", "change"] } else { &["quantity", "live", "pinned", "change"] };
                for (h, w) in headers.iter().zip(&widths) {
                    let c = cell(ui, *w, RichText::new(*h).small(), if *h == "quantity" { left } else { right });
                    if *h == "change" {
                        c.on_hover_text(CHANGE_MEANING);
                    }
                }
                ui.end_row();
                for r in compare(live, pin) {
                    let name = if r.unit.is_empty() { r.label.to_string() } else { format!("{} [{}]", r.label, r.unit) };
                    cell(ui, widths[0], RichText::new(name), left);
                    cell(ui, NUMBER_WIDTH, RichText::new(value(r.live, r.scale)).monospace(), right);
                    if r.not_in_pin {
                        cell(ui, NUMBER_WIDTH, RichText::new(NOT_IN_PIN).monospace().weak(), right)
                            .on_hover_text(NOT_IN_PIN_MEANING);
                    } else {
                        cell(ui, NUMBER_WIDTH, RichText::new(value(r.pinned, r.scale)).monospace(), right);
                    }
                    let changed = r.change().is_some_and(|d| d != 0.0);
                    let color = if changed { ui.visuals().warn_fg_color } else { ui.visuals().weak_text_color() };
                    let delta = value(r.change(), r.scale);
                    if with_delta {
                        cell(ui, NUMBER_WIDTH, RichText::new(delta.clone()).monospace().color(color), right);
                    }
                    cell(ui, CHANGE_WIDTH, RichText::new(r.change_text()).monospace().color(color), right)
                        .on_hover_text(format!("Δ = {delta} {}", r.unit));
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
    use super::{column_widths, row_unit};

    /// The sweep view's kxx of 30.17 MN/m reads in MN/m; units chosen for reading stay as they are.
    #[test]
    fn columns_of_si_units_take_an_engineering_prefix() {
        assert_eq!(row_unit("N/m", Some(3.017e7), Some(4.342e7)), (1e6, "MN/m".to_string()));
        assert_eq!(row_unit("N·s/m", Some(65_972.0), None), (1e3, "kN·s/m".to_string()));
        assert_eq!(row_unit("W", Some(2516.0), Some(5449.0)), (1e3, "kW".to_string()));
        assert_eq!(row_unit("N", Some(1918.0), Some(1918.0)), (1e3, "kN".to_string()));
        assert_eq!(row_unit("µm", Some(47.06), Some(53.95)), (1.0, "µm".to_string()));
        assert_eq!(row_unit("–", Some(0.4179), None), (1.0, "–".to_string()));
        assert_eq!(row_unit("N/m", None, None), (1.0, "N/m".to_string()));
    }

    /// The results panel at 1280 points (384 wide, about 340 inside) has no room for Δ beside the change; at
    /// 1920 (576) it has; the quantity column never falls below its least width nor grows past its most.
    #[test]
    fn the_delta_column_shows_only_where_it_fits() {
        assert_eq!(column_widths(340.0, 8.0), vec![152.0, 58.0, 58.0, 48.0]);
        assert_eq!(column_widths(380.0, 8.0), vec![126.0, 58.0, 58.0, 58.0, 48.0]);
        assert_eq!(column_widths(540.0, 8.0), vec![230.0, 58.0, 58.0, 58.0, 48.0]);
        assert_eq!(column_widths(250.0, 8.0), vec![80.0, 58.0, 58.0, 48.0]);
    }
}
