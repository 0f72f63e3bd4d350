//! Scalar fields of a pad, unwrapped onto the (circumferential × axial) plane, ready to colour.
//!
//! A [`PadMap`] holds one nodal field of one pad on its tensor grid: `s` (arc length from the leading
//! edge, left to right in the direction of rotation) and `z` (axial, from −L/2 to L/2). A half model
//! (`PadField::half`, z ∈ [0, L/2] with a symmetry plane at z = 0) is mirrored to the full length, since
//! a user expects to see the whole pad. Values stay in SI; [`FieldKind`] carries the display unit.
//!
//! Temperature fields are just further [`FieldKind`]s: they appear as soon as the solution carries them
//! ([`FieldKind::nodal`] is the one place that maps a kind to the solver's nodal data).

use crate::bearing::solution::{PadField, Solution};
use crate::units::{MPA, UM};

use super::colormap::ColorMap;

/// Which scalar field of a pad.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
pub enum FieldKind {
    Pressure,
    FilmThickness,
    /// Mean (across the film) oil temperature, from the thermal model.
    FilmTemperature,
    /// Temperature of the pad's film-side surface, from the thermal model.
    PadTemperature,
    /// Local film Reynolds number ρ U h / µ: where the film is laminar, in transition or turbulent.
    Reynolds,
}

impl FieldKind {
    pub const ALL: [Self; 5] =
        [Self::Pressure, Self::FilmThickness, Self::FilmTemperature, Self::PadTemperature, Self::Reynolds];

    #[must_use]
    pub fn label(self) -> &'static str {
        match self {
            Self::Pressure => "Pressure",
            Self::FilmThickness => "Film thickness",
            Self::FilmTemperature => "Film temperature",
            Self::PadTemperature => "Pad surface temperature",
            Self::Reynolds => "Local Reynolds number",
        }
    }

    /// Display unit and the factor from SI to it.
    #[must_use]
    pub fn unit(self) -> (&'static str, f64) {
        match self {
            Self::Pressure => (MPA.symbol, MPA.from_si(1.0)),
            Self::FilmThickness => (UM.symbol, UM.from_si(1.0)),
            Self::FilmTemperature | Self::PadTemperature => ("°C", 1.0),
            Self::Reynolds => ("–", 1.0),
        }
    }

    #[must_use]
    pub fn colormap(self) -> ColorMap {
        match self {
            Self::Pressure | Self::FilmThickness | Self::Reynolds => ColorMap::Viridis,
            Self::FilmTemperature | Self::PadTemperature => ColorMap::Inferno,
        }
    }

    /// What the field means, for tooltips.
    #[must_use]
    pub fn meaning(self) -> &'static str {
        match self {
            Self::Pressure => "Film pressure above ambient, from the Reynolds equation. Zero in cavitated regions.",
            Self::FilmThickness => {
                "Oil film thickness h between journal and pad: thin where the pad converges on the journal (the \
                 wedge that builds pressure), thick near the leading edge."
            }
            Self::FilmTemperature => "Oil temperature averaged across the film thickness (energy equation).",
            Self::PadTemperature => "Temperature of the pad's babbitt surface facing the film (pad conduction).",
            Self::Reynolds => {
                "Local film Reynolds number ρUh/µ (U the journal surface speed, h and µ at each point): laminar below \
                 physics.transition_reynolds_start (default 1000), in the transition band up to \
                 physics.transition_reynolds_end, turbulent above. Highest where the film is thick and hot."
            }
        }
    }

    /// The solver's nodal values of this field, if the solution has them (temperatures need the thermal
    /// model; an isothermal solution has none).
    #[must_use]
    pub fn nodal(self, field: &PadField) -> Option<&[f64]> {
        match self {
            Self::Pressure => Some(&field.pressure_pa),
            Self::FilmThickness => Some(&field.film_thickness_m),
            Self::FilmTemperature => field.film_temperature_c.as_deref(),
            Self::PadTemperature => field.pad_surface_temperature_c.as_deref(),
            Self::Reynolds => (!field.reynolds.is_empty()).then_some(&field.reynolds[..]),
        }
    }

    /// Kinds the solution can show (every pad has the same fields).
    #[must_use]
    pub fn available(solution: &Solution) -> Vec<Self> {
        Self::ALL.into_iter().filter(|k| solution.pads.first().is_some_and(|p| k.nodal(&p.field).is_some())).collect()
    }
}

/// One field of one pad on the full (mirrored) grid.
#[derive(Debug, Clone, PartialEq)]
pub struct PadMap {
    pub pad: usize,
    pub kind: FieldKind,
    /// Circumferential node positions from the leading edge [m], ascending.
    pub s_m: Vec<f64>,
    /// Axial node positions [m], ascending over [−L/2, L/2].
    pub z_m: Vec<f64>,
    /// Journal radius [m] (s = R (θ − θ_le)).
    pub radius_m: f64,
    /// Leading-edge angle [rad].
    pub theta_le_rad: f64,
    /// Values, `values[i * z_m.len() + j]` (z fastest), SI.
    pub values: Vec<f64>,
    /// Cavitated nodes, same layout.
    pub cavitated: Vec<bool>,
    pub min: f64,
    pub max: f64,
}

/// Full-length axial rows of a pad field: `(z, source row)` ascending; a half model is mirrored.
pub(crate) fn full_rows(field: &PadField) -> Vec<(f64, usize)> {
    let mut rows: Vec<(f64, usize)> = Vec::with_capacity(2 * field.z_m.len());
    if field.half {
        // z_m runs from the symmetry plane (0) to L/2: mirror rows 1.. to negative z.
        for j in (1..field.z_m.len()).rev() {
            rows.push((-field.z_m[j], j));
        }
    }
    rows.extend(field.z_m.iter().enumerate().map(|(j, &z)| (z, j)));
    rows
}

/// Re-lays nodal values of a pad field onto the full grid (same layout as [`PadMap::values`]).
pub(crate) fn full_values<T: Copy>(field: &PadField, rows: &[(f64, usize)], nodal: &[T]) -> Vec<T> {
    let mut out = Vec::with_capacity(field.s_m.len() * rows.len());
    for i in 0..field.s_m.len() {
        for &(_, j) in rows {
            out.push(nodal[field.index(i, j)]);
        }
    }
    out
}

impl PadMap {
    /// The map of `kind` on pad `pad` of a solution, `None` if the solution lacks that field.
    #[must_use]
    pub fn new(solution: &Solution, pad: usize, kind: FieldKind) -> Option<Self> {
        let result = solution.pads.get(pad)?;
        Self::from_field(&result.field, pad, kind, solution.inputs.bearing.journal_radius_m)
    }

    /// The map of `kind` from a pad's nodal fields (journal radius `radius_m`).
    #[must_use]
    pub fn from_field(field: &PadField, pad: usize, kind: FieldKind, radius_m: f64) -> Option<Self> {
        Self::from_nodal(field, pad, kind, radius_m, kind.nodal(field)?)
    }

    /// The map of other nodal values on a pad field's grid (same layout as the field's), coloured and
    /// labelled as `kind` (e.g. a displacement shown as a length, like the film thickness).
    #[must_use]
    pub fn from_nodal(field: &PadField, pad: usize, kind: FieldKind, radius_m: f64, nodal: &[f64]) -> Option<Self> {
        if field.s_m.len() < 2 || field.z_m.len() < 2 || nodal.is_empty() || nodal.len() != field.pressure_pa.len() {
            return None;
        }
        let rows = full_rows(field);
        let values = full_values(field, &rows, nodal);
        let cavitated = full_values(field, &rows, &field.cavitated);
        let (min, max) = values.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &v| (lo.min(v), hi.max(v)));
        Some(Self {
            pad,
            kind,
            s_m: field.s_m.clone(),
            z_m: rows.iter().map(|r| r.0).collect(),
            radius_m,
            theta_le_rad: field.theta_rad.first().copied().unwrap_or(0.0),
            values,
            cavitated,
            min,
            max,
        })
    }

    /// Maps of every pad.
    #[must_use]
    pub fn all(solution: &Solution, kind: FieldKind) -> Vec<Self> {
        (0..solution.pads.len()).filter_map(|k| Self::new(solution, k, kind)).collect()
    }

    /// Arc length of the pad [m].
    #[must_use]
    pub fn arc_length_m(&self) -> f64 {
        self.s_m.last().copied().unwrap_or(0.0)
    }

    /// Full axial length [m].
    #[must_use]
    pub fn length_m(&self) -> f64 {
        self.z_m.last().copied().unwrap_or(0.0) - self.z_m.first().copied().unwrap_or(0.0)
    }

    /// Bilinear interpolation of the nodal values at (s, z) — exactly the finite-element interpolant on
    /// the bilinear elements of the solver; `None` outside the pad.
    #[must_use]
    pub fn sample(&self, s: f64, z: f64) -> Option<f64> {
        bilinear(&self.s_m, &self.z_m, |k| self.values[k], s, z)
    }

    /// Whether (s, z) lies in the cavitated (ruptured) film: the interpolated cavitation indicator is at
    /// least one half, so the boundary runs midway between full and cavitated nodes.
    #[must_use]
    pub fn cavitated_at(&self, s: f64, z: f64) -> bool {
        bilinear(&self.s_m, &self.z_m, |k| f64::from(u8::from(self.cavitated[k])), s, z).is_some_and(|c| c >= 0.5)
    }

    /// Angle of an arc-length position [deg].
    #[must_use]
    pub fn theta_deg(&self, s: f64) -> f64 {
        (self.theta_le_rad + s / self.radius_m).to_degrees()
    }

    /// Rasterises the map: `width × height` RGBA pixels, row 0 at z = +L/2 (top), column 0 at the leading
    /// edge (left); values coloured on `[lo, hi]`; the cavitated film hatched with thin light diagonals.
    #[must_use]
    #[allow(clippy::cast_precision_loss)]
    pub fn raster(&self, width: usize, height: usize, lo: f64, hi: f64) -> Raster {
        self.raster_with(self.kind.colormap(), width, height, lo, hi)
    }

    /// [`Self::raster`] in the colour map `map` (a difference map is drawn with the diverging one).
    #[must_use]
    #[allow(clippy::cast_precision_loss)]
    pub fn raster_with(&self, map: ColorMap, width: usize, height: usize, lo: f64, hi: f64) -> Raster {
        let (s_end, z0, len) = (self.arc_length_m(), self.z_m[0], self.length_m());
        let mut rgba = Vec::with_capacity(width * height * 4);
        for row in 0..height {
            let z = z0 + len * (1.0 - (row as f64 + 0.5) / height as f64);
            for col in 0..width {
                let s = s_end * (col as f64 + 0.5) / width as f64;
                let v = self.sample(s, z).unwrap_or(lo);
                let [r, g, b] = if (row + col) % HATCH_PERIOD == 0 && self.cavitated_at(s, z) {
                    HATCH
                } else {
                    map.rgb_in(v, lo, hi)
                };
                rgba.extend_from_slice(&[r, g, b, 255]);
            }
        }
        Raster { width, height, rgba }
    }
}

/// Pixels between the hatch lines of cavitated regions, and their colour.
pub const HATCH_PERIOD: usize = 6;
pub const HATCH: [u8; 3] = [200, 200, 200];

/// Bilinear interpolation of nodal values `f(i · z.len() + j)` on the tensor grid `s × z` at (x, y);
/// `None` outside.
pub(crate) fn bilinear(s: &[f64], z: &[f64], f: impl Fn(usize) -> f64, x: f64, y: f64) -> Option<f64> {
    let (i, fs) = locate(s, x)?;
    let (j, fz) = locate(z, y)?;
    let n = z.len();
    let v = |a: usize, b: usize| f(a * n + b);
    Some(
        (1.0 - fs) * ((1.0 - fz) * v(i, j) + fz * v(i, j + 1)) + fs * ((1.0 - fz) * v(i + 1, j) + fz * v(i + 1, j + 1)),
    )
}

/// Cell index and fraction of `x` on ascending nodes (the last cell includes its right end).
pub(crate) fn locate(nodes: &[f64], x: f64) -> Option<(usize, f64)> {
    let (first, last) = (*nodes.first()?, *nodes.last()?);
    if nodes.len() < 2 || !(first..=last).contains(&x) {
        return None;
    }
    let i = nodes.partition_point(|&v| v <= x).saturating_sub(1).min(nodes.len() - 2);
    let w = nodes[i + 1] - nodes[i];
    Some((i, if w > 0.0 { (x - nodes[i]) / w } else { 0.0 }))
}

/// An RGBA image, row-major, 4 bytes a pixel.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Raster {
    pub width: usize,
    pub height: usize,
    pub rgba: Vec<u8>,
}

/// The common colour range of several maps (so pads side by side compare), `(lo, hi)`.
#[must_use]
pub fn common_range(maps: &[PadMap]) -> (f64, f64) {
    let lo = maps.iter().map(|m| m.min).fold(f64::INFINITY, f64::min);
    let hi = maps.iter().map(|m| m.max).fold(f64::NEG_INFINITY, f64::max);
    if lo.is_finite() && hi.is_finite() {
        (lo, hi)
    } else {
        (0.0, 1.0)
    }
}

/// Round tick values (1, 2 or 5 × 10ⁿ apart) inside `[lo, hi]`, about `target` of them.
#[must_use]
#[allow(clippy::cast_possible_truncation)]
pub fn nice_ticks(lo: f64, hi: f64, target: usize) -> Vec<f64> {
    let span = hi - lo;
    if !(span.is_finite() && span > 0.0) || target == 0 {
        return if lo.is_finite() { vec![lo] } else { Vec::new() };
    }
    let raw = span / target as f64;
    let decade = 10f64.powf(raw.log10().floor());
    let step = [1.0, 2.0, 5.0, 10.0].iter().map(|m| m * decade).find(|&st| st >= 0.75 * raw).unwrap_or(10.0 * decade);
    let first = (lo / step).ceil() as i64;
    let last = (hi / step).floor() as i64;
    (first..=last).map(|k| k as f64 * step).collect()
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    /// A small half-model pad field with p = s · (1 + z) and h = 1e-4 + s.
    pub fn half_field() -> PadField {
        let s_m = vec![0.0, 0.01, 0.03];
        let z_m = vec![0.0, 0.01, 0.02];
        let mut p = Vec::new();
        let mut h = Vec::new();
        for &s in &s_m {
            for &z in &z_m {
                p.push(s * (1.0 + z));
                h.push(1e-4 + s);
            }
        }
        let n = p.len();
        PadField {
            theta_rad: s_m.iter().map(|s| s / 0.05).collect(),
            s_m,
            z_m,
            half: true,
            periodic: false,
            pressure_pa: p,
            film_thickness_m: h,
            cavitated: vec![false; n],
            viscosity_pa_s: vec![0.02; n],
            ..PadField::default()
        }
    }

    #[test]
    fn half_model_is_mirrored_to_the_full_length() {
        let f = half_field();
        let rows = full_rows(&f);
        let z: Vec<f64> = rows.iter().map(|r| r.0).collect();
        assert_eq!(z, vec![-0.02, -0.01, 0.0, 0.01, 0.02]);
        let v = full_values(&f, &rows, &f.pressure_pa);
        // Column 2 (s = 0.03): symmetric about z = 0, the source field evaluated at |z|.
        let col: Vec<f64> = v[10..15].to_vec();
        assert!((col[0] - 0.03 * 1.02).abs() < 1e-15 && (col[4] - col[0]).abs() < 1e-15);
        assert!((col[2] - 0.03).abs() < 1e-15);
    }

    #[test]
    fn sampling_reproduces_a_bilinear_field_and_the_raster_covers_the_pad() {
        let m = PadMap::from_field(&half_field(), 0, FieldKind::Pressure, 0.05).unwrap();
        // Exactly bilinear inside a cell on one side of the mirror plane.
        assert!((m.sample(0.02, 0.015).unwrap() - 0.02 * 1.015).abs() < 1e-15);
        assert!((m.sample(0.02, -0.015).unwrap() - 0.02 * 1.015).abs() < 1e-15);
        assert_eq!(m.sample(0.031, 0.0), None);
        assert_eq!((m.min, m.max), (0.0, 0.03 * 1.02));
        let r = m.raster(8, 4, m.min, m.max);
        assert_eq!(r.rgba.len(), 8 * 4 * 4);
        // Each pixel is the colour of the value at its centre: top-left (s = 0.03/16, z near +L/2) and
        // top-right (s = 0.03·15/16).
        let expect = |s: f64, z: f64| ColorMap::Viridis.rgb_in(m.sample(s, z).unwrap(), m.min, m.max);
        assert_eq!(&r.rgba[0..3], &expect(0.03 / 16.0, 0.02 - 0.04 / 8.0));
        let last = (8 - 1) * 4;
        assert_eq!(&r.rgba[last..last + 3], &expect(0.03 * 15.0 / 16.0, 0.02 - 0.04 / 8.0));
        assert!(r.rgba[last + 1] > 180, "high end is yellow-green: {:?}", &r.rgba[last..last + 3]);
    }

    #[test]
    fn the_cavitated_film_is_hatched() {
        let mut f = half_field();
        // The trailing-edge column cavitated: its half-cell is hatched, the leading edge is not.
        for j in 0..3 {
            f.cavitated[2 * 3 + j] = true;
        }
        let m = PadMap::from_field(&f, 0, FieldKind::Pressure, 0.05).unwrap();
        assert!(m.cavitated_at(0.029, 0.0) && !m.cavitated_at(0.015, 0.0));
        let r = m.raster(30, 12, m.min, m.max);
        let px = |row: usize, col: usize| {
            [r.rgba[4 * (row * 30 + col)], r.rgba[4 * (row * 30 + col) + 1], r.rgba[4 * (row * 30 + col) + 2]]
        };
        let hatched = |c0: usize, c1: usize| {
            (0..12)
                .flat_map(|row| (c0..c1).map(move |col| (row, col)))
                .filter(|&(row, col)| px(row, col) == HATCH)
                .count()
        };
        assert!(hatched(27, 30) > 0, "the cavitated strip has hatch lines");
        assert_eq!(hatched(0, 15), 0, "the full film has none");
    }

    #[test]
    fn ticks_are_round_and_inside() {
        assert_eq!(nice_ticks(0.0, 1.98, 4), vec![0.0, 0.5, 1.0, 1.5]);
        let t = nice_ticks(53.87, 181.2, 5);
        assert_eq!(t, vec![60.0, 80.0, 100.0, 120.0, 140.0, 160.0, 180.0]);
        assert_eq!(nice_ticks(2.0, 2.0, 4), vec![2.0]);
    }

    #[test]
    fn locate_finds_cells_and_rejects_outside() {
        let x = [0.0, 1.0, 3.0];
        assert_eq!(locate(&x, 0.0), Some((0, 0.0)));
        assert_eq!(locate(&x, 2.0), Some((1, 0.5)));
        assert_eq!(locate(&x, 3.0), Some((1, 1.0)));
        assert_eq!(locate(&x, 3.1), None);
        assert_eq!(locate(&x, -0.1), None);
    }
}
