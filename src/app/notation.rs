//! How the workbench writes a number in a field it can be edited in (drag values, sliders): values of
//! everyday size plainly, with the field's decimals; large and small ones in engineering notation, so a pivot
//! stiffness reads "20e6" (N/m) rather than "20000000". What a field shows reads back as typed, and typing
//! accepts plain digits as well ("20000000", "2e7" and "20e6" are the same value).
//!
//! [`apply`] makes [`field_text`] egui's number formatter for every field of the workbench.

use std::ops::RangeInclusive;

use crate::number::sig;

/// Magnitudes written plainly; others in engineering notation.
const PLAIN: std::ops::Range<f64> = 1e-3..1e5;
/// Significant digits of a value in engineering notation.
const DIGITS: usize = 6;

/// A field's text of `x`: plainly with `decimals` (egui's own rule) for 1e-3 ≤ |x| < 1e5 and 0; otherwise in
/// engineering notation, the exponent a multiple of three and up to six significant digits: 2e7 → "20e6",
/// 1.5e9 → "1.5e9", 4.2e-5 → "42e-6", 123456 → "123.456e3".
#[must_use]
pub fn field_text(x: f64, decimals: RangeInclusive<usize>) -> String {
    let a = x.abs();
    if !x.is_finite() || a == 0.0 || PLAIN.contains(&a) {
        return egui::emath::format_with_decimals_in_range(x, decimals);
    }
    #[allow(clippy::cast_possible_truncation)]
    let mut exponent = (a.log10().floor() as i32).div_euclid(3) * 3;
    // Rounded to its digits, a mantissa just under 1000 becomes 1000: the next power of a thousand.
    if sig(a / 10f64.powi(exponent), DIGITS).parse::<f64>().is_ok_and(|m| m >= 1000.0) {
        exponent += 3;
    }
    format!("{}e{exponent}", sig(x / 10f64.powi(exponent), DIGITS))
}

/// Makes [`field_text`] the number formatter of every field, in both themes.
pub fn apply(ctx: &egui::Context) {
    ctx.all_styles_mut(|s| s.number_formatter = egui::style::NumberFormatter::new(field_text));
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::schema::{Widget, KEYS};

    #[test]
    fn large_and_small_values_read_in_engineering_notation_and_read_back() {
        let cases = [
            (2e7, "20e6"),
            (3.5e7, "35e6"),
            (1.5e9, "1.5e9"),
            (1e10, "10e9"),
            (123_456.0, "123.456e3"),
            (100_000.0, "100e3"),
            (999_999_999.9, "1e9"),
            (4.2e-5, "42e-6"),
            (-2.5e-4, "-250e-6"),
            (1e14, "100e12"),
        ];
        for (x, text) in cases {
            assert_eq!(field_text(x, 0..=6), text, "{x}");
            let back: f64 = text.parse().unwrap();
            assert!((back - x).abs() <= 1e-6 * x.abs(), "{text} reads back as {back}, not {x}");
        }
        // Everyday values keep egui's plain form with the field's decimals.
        assert_eq!(field_text(1918.0, 0..=1), "1918");
        assert_eq!(field_text(0.028, 0..=4), "0.028");
        assert_eq!(field_text(0.0, 2..=4), "0.00");
        assert_eq!(field_text(99_999.0, 0..=0), "99999");
    }

    /// Every editor number at the ends of its typical range reads in at most 9 characters with at most five
    /// digits before its point (the pivot stiffness's 1e10 N/m was "10000000000"; a load of 50000 N stays).
    #[test]
    fn every_editor_number_reads_at_the_ends_of_its_typical_range() {
        let mut checked = 0;
        let mut unreadable = Vec::new();
        for row in KEYS {
            let Some(editor) = row.editor else { continue };
            let (Widget::Number(decimals) | Widget::Optional(decimals)) = editor.widget else { continue };
            let Some((lo, hi)) = row.typical else { continue };
            for x in [lo, hi] {
                let text = field_text(x, 0..=decimals);
                let whole = text.trim_start_matches('-').split(['.', 'e']).next().unwrap_or_default().len();
                if text.len() > 9 || whole > 5 {
                    unreadable.push(format!("{}: {x} shows as {text}", row.key));
                }
                checked += 1;
            }
        }
        assert!(unreadable.is_empty(), "{}", unreadable.join("\n"));
        assert!(checked > 100, "{checked}");
    }
}
