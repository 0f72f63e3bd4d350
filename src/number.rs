//! Numbers as text, at the edges (workbench, CSV, messages): one place decides how many digits a value
//! shows, so that arithmetic round-off (`0.1 + 0.5 = 0.6000000000000001`) never reaches a user.
//!
//! - [`sig`]: `n` significant digits, trailing zeros trimmed; plain notation for 1e-4 ≤ |x| < 1e6, else
//!   `2.5e7` (what the workbench shows).
//! - [`csv`]: 12 significant digits, trimmed; plain for 1e-5 ≤ |x| < 1e15: for values made by arithmetic
//!   on what the user typed (sweep values, speeds, frequencies, range bounds), which read back within 5e-12
//!   relative without the round-off digits. Solver outputs in data files keep Rust's shortest round-trip
//!   text (`{:?}`), so a CSV cell and the JSON of the same result are the same number.
//! - [`eng`], [`eng_values`]: values of an SI unit in engineering notation with the prefixed unit
//!   (`1.95 GN/m`, `2.259 kN`): how the workbench shows forces, stiffnesses, damping, powers and torques,
//!   in the results, the pads table and the comparison of pins alike.
//! - [`ticks`]: labels of evenly spaced ticks, all with the decimals their step needs (`0`, `0.5`, `1`,
//!   `1.5` → "0.0", "0.5", "1.0", "1.5").
//!
//! Non-finite values are written as Rust writes them (`NaN`, `inf`), so a bad value is never hidden.

/// `n` (≥ 1) significant digits, trailing zeros trimmed: `sig(1918.0, 4)` = "1918",
/// `sig(0.012345, 4)` = "0.01235", `sig(1.4000000000000001, 6)` = "1.4", `sig(2.5e7, 4)` = "2.5e7".
#[must_use]
pub fn sig(x: f64, n: usize) -> String {
    with_digits(x, n, -4..6)
}

/// CSV cell: 12 significant digits, trimmed (`0.6000000000000001` → "0.6").
#[must_use]
pub fn csv(x: f64) -> String {
    with_digits(x, 12, -5..15)
}

/// Tick labels with the decimals of the step between the first two ticks (one tick: 4 significant digits).
#[must_use]
pub fn ticks(values: &[f64]) -> Vec<String> {
    match values {
        [a, b, ..] => values.iter().map(|&v| tick(v, (b - a).abs())).collect(),
        _ => values.iter().map(|&v| sig(v, 4)).collect(),
    }
}

/// One tick label on a grid of spacing `step`: the decimals the step needs (`tick(0.5, 0.5)` = "0.5",
/// `tick(1.0, 0.5)` = "1.0"); 3 significant digits for large values or tiny steps.
#[must_use]
pub fn tick(value: f64, step: f64) -> String {
    if !(step.is_finite() && step > 0.0) || value.abs() >= 1e6 || step < 1e-4 {
        return sig(value, 3);
    }
    #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
    let decimals = (-(step * (1.0 + 1e-9)).log10().floor()).max(0.0) as usize;
    // Round-off below the last shown digit must not print as "-0".
    let v = if value.abs() < 0.5 * step { 0.0 } else { value };
    format!("{v:.decimals$}")
}

/// `n` significant digits; plain notation when the decimal exponent is in `plain`.
fn with_digits(x: f64, n: usize, plain: std::ops::Range<i32>) -> String {
    if !x.is_finite() {
        return format!("{x}");
    }
    if x == 0.0 {
        return "0".into();
    }
    let n = n.max(1);
    // Rounded to n digits first: the exponent is the rounded value's (9.9996 → 1.000e1).
    let e_form = format!("{:.*e}", n - 1, x);
    let (mantissa, exponent) = e_form.split_once('e').unwrap_or((e_form.as_str(), "0"));
    let exponent: i32 = exponent.parse().unwrap_or(0);
    if plain.contains(&exponent) {
        #[allow(clippy::cast_sign_loss, clippy::cast_possible_wrap, clippy::cast_possible_truncation)]
        let decimals = (n as i32 - 1 - exponent).max(0) as usize;
        trim(&format!("{x:.decimals$}"))
    } else {
        format!("{}e{exponent}", trim(mantissa))
    }
}

/// Engineering notation for values of an SI unit: the power of 1000 and its prefix that bring `max_abs`
/// (the largest magnitude to be shown in that unit) into [1, 1000): `eng_prefix(3.0e7)` = (1e6, "M"),
/// so 3.017e7 N/m reads "30.17 MN/m"; 0 and values in [1, 1000) keep the unit (1, ""). Prefixes from n to G.
#[must_use]
pub fn eng_prefix(max_abs: f64) -> (f64, &'static str) {
    const PREFIXES: [(f64, &str); 7] =
        [(1e9, "G"), (1e6, "M"), (1e3, "k"), (1.0, ""), (1e-3, "m"), (1e-6, "µ"), (1e-9, "n")];
    if !(max_abs.is_finite() && max_abs > 0.0) {
        return (1.0, "");
    }
    // Rounded to 4 digits first, so 999.96 shows as "1 k" rather than "1000".
    let rounded: f64 = format!("{max_abs:.3e}").parse().unwrap_or(max_abs);
    PREFIXES.into_iter().find(|(f, _)| rounded >= *f).unwrap_or(PREFIXES[6])
}

/// Values of one SI unit sharing one engineering prefix, chosen by the largest magnitude, each with 4
/// significant digits: `eng_values(&[2.5e8, -1.2e7], "N/m")` = (["250", "-12"], "MN/m"). A row of
/// several values (Kxx, Kxy) so reads in one unit.
#[must_use]
pub fn eng_values(values: &[f64], unit: &str) -> (Vec<String>, String) {
    let largest = values.iter().filter(|v| v.is_finite()).fold(0.0_f64, |m, v| m.max(v.abs()));
    let (scale, prefix) = eng_prefix(largest);
    (values.iter().map(|&v| sig(v / scale, 4)).collect(), format!("{prefix}{unit}"))
}

/// One value of an SI unit in engineering notation with its prefixed unit, 4 significant digits:
/// `eng(1_950_103_829.0, "N/m")` = "1.95 GN/m", `eng(2259.1, "N")` = "2.259 kN".
#[must_use]
pub fn eng(x: f64, unit: &str) -> String {
    let (values, unit) = eng_values(&[x], unit);
    format!("{} {unit}", values[0])
}

/// Drops trailing zeros after a decimal point, and the point itself when nothing follows it.
fn trim(s: &str) -> String {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s.to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn significant_digits_without_noise() {
        assert_eq!(sig(1918.0, 4), "1918");
        assert_eq!(sig(9000.0, 4), "9000");
        assert_eq!(sig(0.012345, 4), "0.01235");
        assert_eq!(sig(123.456, 4), "123.5");
        assert_eq!(sig(2.5e7, 4), "2.5e7");
        assert_eq!(sig(-3.25e-6, 3), "-3.25e-6");
        assert_eq!(sig(0.0, 4), "0");
        assert_eq!(sig(1.4000000000000001, 6), "1.4");
        assert_eq!(sig(0.1 + 0.2, 6), "0.3");
        // Rounding that carries into the next decade.
        assert_eq!(sig(9.99996, 4), "10");
        assert_eq!(sig(999_999.7, 4), "1e6");
        assert_eq!(sig(f64::NAN, 4), "NaN");
        assert_eq!(sig(f64::INFINITY, 4), "inf");
    }

    #[test]
    fn engineering_prefixes_bring_values_into_one_to_a_thousand() {
        assert_eq!(eng_prefix(3.017e7), (1e6, "M"));
        assert_eq!(eng_prefix(65_972.0), (1e3, "k"));
        assert_eq!(eng_prefix(2516.0), (1e3, "k"));
        assert_eq!(eng_prefix(999.96), (1e3, "k"));
        assert_eq!(eng_prefix(1918.0), (1e3, "k"));
        assert_eq!(eng_prefix(5.0), (1.0, ""));
        assert_eq!(eng_prefix(0.0021), (1e-3, "m"));
        assert_eq!(eng_prefix(0.0), (1.0, ""));
        assert_eq!(eng_prefix(f64::NAN), (1.0, ""));
        assert_eq!(eng_prefix(4e12), (1e9, "G"));
    }

    /// The numbers that overflowed the results panel read with a prefix; a row shares the prefix of its
    /// largest value.
    #[test]
    fn engineering_notation_carries_the_prefix_into_the_unit() {
        assert_eq!(eng(1_950_103_829.0, "N/m"), "1.95 GN/m");
        assert_eq!(eng(2259.1, "N"), "2.259 kN");
        assert_eq!(eng(-65_972.0, "N·s/m"), "-65.97 kN·s/m");
        assert_eq!(eng(5.745, "N·m"), "5.745 N·m");
        assert_eq!(eng(0.0, "W"), "0 W");
        assert_eq!(eng(f64::NAN, "W"), "NaN W");
        let (v, unit) = eng_values(&[4.636e7, -1.839e6], "N/m");
        assert_eq!((v, unit.as_str()), (vec!["46.36".to_string(), "-1.839".to_string()], "MN/m"));
        let (v, unit) = eng_values(&[2.5e8, -1.2e7], "N/m");
        assert_eq!((v, unit.as_str()), (vec!["250".to_string(), "-12".to_string()], "MN/m"));
    }

    #[test]
    fn csv_cells_are_short_and_read_back_closely() {
        assert_eq!(csv(0.1 + 0.5), "0.6");
        assert_eq!(csv(3.0 * 0.1), "0.3");
        assert_eq!(csv(1918.0), "1918");
        assert_eq!(csv(2.5e-8), "2.5e-8");
        assert_eq!(csv(-1.25e16), "-1.25e16");
        // Twelve digits kept: the value reads back within 5e-12 relative.
        for x in [std::f64::consts::PI, 1.0 / 3.0, 6.02214076e23, -9.81e-7, 0.123_456_789_012_345] {
            let back: f64 = csv(x).parse().unwrap();
            assert!(((back - x) / x).abs() <= 5e-12, "{x} → {} → {back}", csv(x));
        }
    }

    #[test]
    fn tick_labels_share_the_step_decimals() {
        assert_eq!(ticks(&[0.0, 0.5, 1.0, 1.5]), ["0.0", "0.5", "1.0", "1.5"]);
        assert_eq!(ticks(&[60.0, 80.0, 100.0, 120.0]), ["60", "80", "100", "120"]);
        assert_eq!(ticks(&[0.30000000000000004, 0.6000000000000001, 0.9]), ["0.3", "0.6", "0.9"]);
        assert_eq!(ticks(&[0.02, 0.04]), ["0.02", "0.04"]);
        assert_eq!(ticks(&[-0.0, 5.0]), ["0", "5"]);
        assert_eq!(ticks(&[2.0]), ["2"]);
        assert_eq!(ticks(&[2e6, 4e6]), ["2e6", "4e6"]);
        assert_eq!(tick(-1e-17, 0.2), "0.0");
        assert_eq!(tick(250.0, 50.0), "250");
    }
}
