//! Perceptually uniform colour maps as small tables.
//!
//! A map is a list of evenly spaced sRGB control colours on `[0, 1]`, interpolated linearly in sRGB. The
//! tables are the published 11-point (viridis) and 10-point (inferno) samples of the matplotlib maps by
//! van der Walt and Smith; between the samples the lightness stays monotonic, which is what matters for
//! reading a field: equal steps in value look like equal steps in colour, and the map survives greyscale
//! printing and the common colour-vision deficiencies.
//!
//! Viridis is used for pressure and film thickness, inferno (black → yellow, "hot") for temperatures.
//! Differences (live − pinned) use a diverging map, blue through light grey to red, with grey at zero:
//! five samples of Moreland's cool–warm map ("Diverging Color Maps for Scientific Visualization", 2009),
//! whose two halves have matching lightness so equal positive and negative differences look equally strong.

/// A colour map.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ColorMap {
    Viridis,
    Inferno,
    /// Cool–warm diverging map for signed differences (grey at the middle of the range).
    Diverging,
}

const VIRIDIS: [[u8; 3]; 11] = [
    [68, 1, 84],
    [72, 36, 117],
    [65, 68, 135],
    [53, 95, 141],
    [42, 120, 142],
    [33, 145, 140],
    [34, 168, 132],
    [68, 191, 112],
    [122, 209, 81],
    [189, 223, 38],
    [253, 231, 37],
];

const INFERNO: [[u8; 3]; 10] = [
    [0, 0, 4],
    [27, 12, 65],
    [74, 12, 107],
    [120, 28, 109],
    [165, 44, 96],
    [207, 68, 70],
    [237, 105, 37],
    [251, 155, 6],
    [247, 209, 61],
    [252, 255, 164],
];

const COOL_WARM: [[u8; 3]; 5] = [[59, 76, 192], [141, 176, 254], [221, 221, 221], [244, 154, 123], [180, 4, 38]];

impl ColorMap {
    fn table(self) -> &'static [[u8; 3]] {
        match self {
            Self::Viridis => &VIRIDIS,
            Self::Inferno => &INFERNO,
            Self::Diverging => &COOL_WARM,
        }
    }

    /// sRGB colour at `t` in `[0, 1]` (clamped; NaN maps to the low end).
    #[must_use]
    #[allow(clippy::cast_precision_loss, clippy::cast_possible_truncation, clippy::cast_sign_loss)]
    pub fn rgb(self, t: f64) -> [u8; 3] {
        let table = self.table();
        let t = if t.is_nan() { 0.0 } else { t.clamp(0.0, 1.0) };
        let x = t * (table.len() - 1) as f64;
        let i = (x.floor() as usize).min(table.len() - 2);
        let f = x - i as f64;
        let (a, b) = (table[i], table[i + 1]);
        let mix = |k: usize| (f64::from(a[k]) + f * (f64::from(b[k]) - f64::from(a[k]))).round() as u8;
        [mix(0), mix(1), mix(2)]
    }

    /// Colour of `value` on the range `[lo, hi]` (a degenerate range maps everything to the middle).
    #[must_use]
    pub fn rgb_in(self, value: f64, lo: f64, hi: f64) -> [u8; 3] {
        let span = hi - lo;
        let t = if span > 0.0 && span.is_finite() { (value - lo) / span } else { 0.5 };
        self.rgb(t)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Relative luminance (Rec. 709 weights on linearised sRGB).
    fn luminance(c: [u8; 3]) -> f64 {
        let lin = |v: u8| {
            let v = f64::from(v) / 255.0;
            if v <= 0.04045 {
                v / 12.92
            } else {
                ((v + 0.055) / 1.055).powf(2.4)
            }
        };
        0.2126 * lin(c[0]) + 0.7152 * lin(c[1]) + 0.0722 * lin(c[2])
    }

    #[test]
    fn ends_and_midpoint_are_the_table_entries() {
        assert_eq!(ColorMap::Viridis.rgb(0.0), [68, 1, 84]);
        assert_eq!(ColorMap::Viridis.rgb(1.0), [253, 231, 37]);
        assert_eq!(ColorMap::Viridis.rgb(0.5), [33, 145, 140]);
        assert_eq!(ColorMap::Inferno.rgb(1.0), [252, 255, 164]);
        // Clamped outside [0, 1], NaN at the low end.
        assert_eq!(ColorMap::Viridis.rgb(-3.0), ColorMap::Viridis.rgb(0.0));
        assert_eq!(ColorMap::Viridis.rgb(f64::NAN), ColorMap::Viridis.rgb(0.0));
        assert_eq!(ColorMap::Inferno.rgb_in(5.0, 5.0, 5.0), ColorMap::Inferno.rgb(0.5));
    }

    #[test]
    fn lightness_increases_monotonically() {
        for map in [ColorMap::Viridis, ColorMap::Inferno] {
            let mut last = -1.0;
            for k in 0..=200 {
                let l = luminance(map.rgb(f64::from(k) / 200.0));
                assert!(l >= last - 1e-3, "{map:?} at {k}: {l} after {last}");
                last = l;
            }
        }
    }

    /// The diverging map is grey at zero difference and its two halves are equally light at equal
    /// distances from the middle (within 0.03 in relative luminance on the five samples and between them).
    #[test]
    fn the_diverging_map_is_symmetric_in_lightness() {
        assert_eq!(ColorMap::Diverging.rgb_in(0.0, -2.0, 2.0), [221, 221, 221]);
        for k in 0..=50 {
            let t = f64::from(k) / 100.0;
            let (cool, warm) = (luminance(ColorMap::Diverging.rgb(t)), luminance(ColorMap::Diverging.rgb(1.0 - t)));
            assert!((cool - warm).abs() < 0.03, "t = {t}: {cool} vs {warm}");
        }
    }
}
