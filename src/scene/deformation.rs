//! Pad deformation, as plain drawables: the pad's cross-section (undeformed and deformed, exaggerated), the
//! unwrapped film-face displacement, the flexible and the rigid film thickness, and a gallery of the retained
//! mode shapes with their frequencies.
//!
//! Mechanical deformation of a flexible pad (docs/MODEL.md §5): the solid's displacement is
//! `v(x) = Σ_i q_i ψ_i(x)`, with `q_i` the solved amplitude of `PadDof::Mode(i)` and `ψ_i` the mode's nodal
//! displacement (polar components u_r, u_θ, u_z per pad node, per unit coordinate). Its radial component on the
//! film face is `u_m(s, z) = Σ_i q_i φ_i(s, z)` ([`crate::bearing::solution::PadResult::elastic_displacement_m`];
//! positive away from the journal, opening the film).
//!
//! Thermal growth of the pad (TEHD, [`crate::bearing::thermal::growth`]): the solid's displacement `v_t(x)` from the
//! converged pad temperature, its film-face radial component `u_t`
//! ([`crate::bearing::solution::PadThermalGrowth`]). The journal's uniform growth δ_j is not the pad's and
//! is not drawn here (the film carries it: `h = h_rigid + u_m + u_t − δ_j`).
//!
//! [`Displacement`] selects which is drawn and mapped: mechanical `u_m`, thermal `u_t` or the total
//! `u = u_m + u_t`. The film thickness of the pad is `h`; the film at the same pivot, tilt and journal
//! positions without the selected displacement is `h − u`, so the difference map of the two is `u` itself.
//!
//! The cross-section is cut at the axial mid-plane (the row nearest z = 0) through every node layer of the pad
//! solid. It is drawn in the pad frame: origin at the bearing centre, y outwards through the pivot, x along
//! the direction of rotation (leading edge on the left), so
//! `x = r sin(θ − θ_p)`, `y = r cos(θ − θ_p)`; a displaced node moves by `a (u_r e_r + u_θ e_θ)` with the
//! exaggeration `a`. Lengths in metres; display units are the view's.

use crate::bearing::solution::{PadField, PadResult, Solution};

use super::field::{FieldKind, PadMap};
use super::outline::round_factor;

/// Automatic exaggeration: the largest displacement drawn as this fraction of the pad thickness.
pub const AUTO_FRACTION: f64 = 0.15;

/// Which radial displacement of the pad is drawn and mapped.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Displacement {
    /// The elastic bending modes at their solved amplitudes.
    #[default]
    Mechanical,
    /// The pad's thermal growth (TEHD only).
    Thermal,
    /// Their sum.
    Total,
}

impl Displacement {
    pub const ALL: [Self; 3] = [Self::Mechanical, Self::Thermal, Self::Total];

    #[must_use]
    pub fn label(self) -> &'static str {
        match self {
            Self::Mechanical => "Mechanical",
            Self::Thermal => "Thermal",
            Self::Total => "Total",
        }
    }

    /// Weights of the mechanical and the thermal part.
    fn weights(self) -> [f64; 2] {
        match self {
            Self::Mechanical => [1.0, 0.0],
            Self::Thermal => [0.0, 1.0],
            Self::Total => [1.0, 1.0],
        }
    }
}

/// The pad's mid-plane cross-section.
#[derive(Debug, Clone, PartialEq)]
pub struct Section {
    /// Closed outline in the pad frame [m]: film face leading → trailing edge, trailing side outwards, back
    /// trailing → leading edge, leading side inwards.
    pub rigid: Vec<[f64; 2]>,
    /// The same vertices displaced by the exaggerated deformation [m].
    pub deformed: Vec<[f64; 2]>,
    /// Radial displacement at each vertex (not exaggerated) [m].
    pub radial_m: Vec<f64>,
    /// Vertices on the film face (the first ones of the outline).
    pub film_face: usize,
    /// The pivot in the pad frame [m].
    pub pivot: [f64; 2],
}

/// One retained mode of the gallery.
#[derive(Debug, Clone, PartialEq)]
pub struct ModeTile {
    pub mode: usize,
    pub frequency_hz: f64,
    /// Solved amplitude (largest film-face radial displacement of the mode) [m].
    pub amplitude_m: f64,
    /// The mode shape (per unit coordinate) drawn with its own scale: its largest in-plane displacement at
    /// [`AUTO_FRACTION`] of the pad thickness.
    pub section: Section,
    pub exaggeration: f64,
    /// Film-face radial displacement per unit coordinate [m/m].
    pub shape: PadMap,
}

/// Everything the deformation view draws for one pad.
#[derive(Debug, Clone, PartialEq)]
pub struct PadDeformation {
    pub pad: usize,
    /// The displacement drawn (thermal or total only when the pad has a thermal growth).
    pub shown: Displacement,
    /// The pad has a thermal growth (a TEHD solve).
    pub thermal: bool,
    pub exaggeration: f64,
    pub thickness_m: f64,
    pub section: Section,
    /// Film-face radial displacement u of the shown kind [m] (also the film difference).
    pub displacement: PadMap,
    /// Film thickness of the pad h and the film without the shown displacement h − u [m].
    pub film_flexible: PadMap,
    pub film_rigid: PadMap,
    pub modes: Vec<ModeTile>,
}

/// The exaggeration that draws a peak displacement `peak_m` as [`AUTO_FRACTION`] of the thickness, rounded
/// to 1, 2 or 5 × 10ⁿ (1 when there is no displacement).
#[must_use]
pub fn auto_exaggeration(peak_m: f64, thickness_m: f64) -> f64 {
    if peak_m > 0.0 && thickness_m > 0.0 {
        round_factor(AUTO_FRACTION * thickness_m / peak_m)
    } else {
        1.0
    }
}

/// A pad deforms if it has bending modes or a thermal growth.
#[must_use]
pub fn deforms(pad: &PadResult) -> bool {
    pad.flex.is_some() || pad.thermal_growth.is_some()
}

/// Weighted nodal fields (u_r, u_θ, u_z per pad node) whose sum is a displacement.
type Parts<'a> = Vec<(&'a [f64], f64)>;

/// The film-face radial displacement of the `shown` kind at the film nodes [m].
fn film_face(result: &PadResult, shown: Displacement, n_film: usize) -> Vec<f64> {
    let [wm, wt] = shown.weights();
    let thermal = result.thermal_growth.as_ref().map(|g| g.film_radial_m.as_slice());
    (0..n_film)
        .map(|i| {
            let m = result.elastic_displacement_m.get(i).copied().unwrap_or(0.0);
            let t = thermal.and_then(|t| t.get(i)).copied().unwrap_or(0.0);
            wm * m + wt * t
        })
        .collect()
}

impl PadDeformation {
    /// The drawables of pad `pad` of a solution showing the `shown` displacement (mechanical when the pad
    /// has no thermal growth); `None` for a pad that does not deform. `exaggeration`: `None` chooses one
    /// ([`auto_exaggeration`]).
    #[must_use]
    pub fn new(solution: &Solution, pad: usize, exaggeration: Option<f64>, shown: Displacement) -> Option<Self> {
        let result = solution.pads.get(pad)?;
        let growth = result.thermal_growth.as_ref();
        let shown = if growth.is_some() { shown } else { Displacement::Mechanical };
        let radii = result.flex.as_ref().map(|f| &f.radii_m).or(growth.map(|g| &g.radii_m))?;
        let field = &result.field;
        let r = solution.inputs.bearing.journal_radius_m;
        let pivot_rad = solution.inputs.bearing.pads.get(pad)?.pivot_rad;
        let thickness_m = radii.last()? - radii.first()?;
        let cut = SectionCut::new(field, radii, pivot_rad)?;
        let [wm, wt] = shown.weights();
        let modes = result.flex.as_ref().map_or(&[][..], |f| f.modes.modes.as_slice());
        let mut parts: Parts<'_> =
            modes.iter().zip(&result.mode_amplitudes_m).map(|(m, &q)| (m.nodal.as_slice(), wm * q)).collect();
        parts.extend(growth.map(|g| (g.nodal_polar_m.as_slice(), wt)));
        if parts.iter().any(|(nodal, _)| nodal.len() != 3 * cut.n_nodes) {
            return None;
        }
        let exaggeration = exaggeration.unwrap_or_else(|| auto_exaggeration(cut.peak(&parts), thickness_m));
        let u = film_face(result, shown, field.pressure_pa.len());
        let rigid_h: Vec<f64> = field.film_thickness_m.iter().zip(&u).map(|(h, u)| h - u).collect();
        let map = |nodal: &[f64]| PadMap::from_nodal(field, pad, FieldKind::FilmThickness, r, nodal);
        let tiles = modes
            .iter()
            .enumerate()
            .filter_map(|(i, m)| {
                // A shape per unit coordinate (1 m at its peak): drawn with its peak at AUTO_FRACTION of t.
                let unit = vec![(m.nodal.as_slice(), 1.0)];
                let peak = cut.peak(&unit);
                let a = if peak > 0.0 { AUTO_FRACTION * thickness_m / peak } else { 1.0 };
                Some(ModeTile {
                    mode: i,
                    frequency_hz: m.frequency_hz,
                    amplitude_m: result.mode_amplitudes_m.get(i).copied().unwrap_or(0.0),
                    section: cut.section(&unit, a),
                    exaggeration: a,
                    shape: map(&m.film_shape)?,
                })
            })
            .collect();
        Some(Self {
            pad,
            shown,
            thermal: growth.is_some(),
            exaggeration,
            thickness_m,
            section: cut.section(&parts, exaggeration),
            displacement: map(&u)?,
            film_flexible: map(&field.film_thickness_m)?,
            film_rigid: map(&rigid_h)?,
            modes: tiles,
        })
    }
}

/// The mid-plane cut through a pad solid: outline nodes and their undeformed positions.
struct SectionCut {
    /// Pad node, angle from the pivot [rad] and radius [m] of each outline vertex.
    vertices: Vec<(usize, f64, f64)>,
    film_face: usize,
    pivot: [f64; 2],
    /// Nodes of the pad solid.
    n_nodes: usize,
}

impl SectionCut {
    fn new(field: &PadField, radii: &[f64], pivot_rad: f64) -> Option<Self> {
        let n_film = field.pressure_pa.len();
        let layers = radii.len().checked_sub(1)?;
        let cols = field.s_m.len();
        if cols < 2 || layers == 0 {
            return None;
        }
        // The row nearest the axial mid-plane.
        let row = (0..field.z_m.len()).min_by(|&a, &b| field.z_m[a].abs().total_cmp(&field.z_m[b].abs()))?;
        let vertex = |layer: usize, col: usize| {
            (layer * n_film + field.index(col, row), field.theta_rad[col] - pivot_rad, radii[layer])
        };
        let mut vertices: Vec<_> = (0..cols).map(|i| vertex(0, i)).collect();
        vertices.extend((1..=layers).map(|l| vertex(l, cols - 1)));
        vertices.extend((0..cols - 1).rev().map(|i| vertex(layers, i)));
        vertices.extend((1..layers).rev().map(|l| vertex(l, 0)));
        Some(Self { vertices, film_face: cols, pivot: [0.0, radii[layers]], n_nodes: n_film * (layers + 1) })
    }

    /// Polar displacement (u_r, u_θ) of pad node `node` for the weighted nodal fields `parts`.
    fn displacement(parts: &Parts<'_>, node: usize) -> [f64; 2] {
        parts.iter().fold([0.0, 0.0], |[ur, ut], (nodal, a)| [ur + a * nodal[3 * node], ut + a * nodal[3 * node + 1]])
    }

    /// Largest in-plane displacement on the outline for `parts` [m].
    fn peak(&self, parts: &Parts<'_>) -> f64 {
        self.vertices
            .iter()
            .map(|&(n, _, _)| Self::displacement(parts, n))
            .fold(0.0_f64, |p, [ur, ut]| p.max(ur.hypot(ut)))
    }

    fn section(&self, parts: &Parts<'_>, exaggeration: f64) -> Section {
        let mut section = Section {
            rigid: Vec::with_capacity(self.vertices.len()),
            deformed: Vec::with_capacity(self.vertices.len()),
            radial_m: Vec::with_capacity(self.vertices.len()),
            film_face: self.film_face,
            pivot: self.pivot,
        };
        for &(node, phi, r) in &self.vertices {
            let (s, c) = phi.sin_cos();
            let [ur, ut] = Self::displacement(parts, node);
            // e_r = (sin φ, cos φ), e_θ = (cos φ, −sin φ) in the pad frame.
            section.rigid.push([r * s, r * c]);
            section.deformed.push([r * s + exaggeration * (ur * s + ut * c), r * c + exaggeration * (ur * c - ut * s)]);
            section.radial_m.push(ur);
        }
        section
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bearing::solve_case;
    use crate::model::load_case;

    fn flexible(sets: &[&str]) -> Solution {
        let all: Vec<String> =
            std::iter::once("mesh.fidelity=preview").chain(sets.iter().copied()).map(str::to_string).collect();
        let case = load_case(include_str!("../../cases/compressor-bearing-flexible.toml"), &all).unwrap().1;
        solve_case(&case).unwrap()
    }

    #[test]
    fn the_deformed_section_and_the_maps_agree_with_the_solved_modes() {
        let s = flexible(&["physics.pad_modes=2"]);
        let loaded = 3;
        let d = PadDeformation::new(&s, loaded, None, Displacement::Mechanical).unwrap();
        let p = &s.pads[loaded];
        // The film face of the section carries the film-face field of the solve (nodal and film shapes are
        // the same field), at the mid-plane row.
        let field = &p.field;
        let row = (0..field.z_m.len()).min_by(|&a, &b| field.z_m[a].abs().total_cmp(&field.z_m[b].abs())).unwrap();
        let scale = p.elastic_displacement_m.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        assert!(scale > 1e-8, "the loaded pad bends: {scale}");
        for i in 0..d.section.film_face {
            let expected = p.elastic_displacement_m[field.index(i, row)];
            assert!(
                (d.section.radial_m[i] - expected).abs() <= 1e-9 * scale,
                "column {i}: {} vs {expected}",
                d.section.radial_m[i]
            );
        }
        // Flexible − rigid film = displacement, everywhere.
        for ((hf, hr), u) in d.film_flexible.values.iter().zip(&d.film_rigid.values).zip(&d.displacement.values) {
            assert!((hf - hr - u).abs() <= 1e-15, "{hf} {hr} {u}");
        }
        // The deformation is drawn to the chosen exaggeration: doubling it doubles every vertex's offset.
        // (An isothermal pad has no thermal growth: any selection shows the mechanical displacement.)
        let twice = PadDeformation::new(&s, loaded, Some(2.0 * d.exaggeration), Displacement::Total).unwrap();
        assert!(!twice.thermal && twice.shown == Displacement::Mechanical);
        for ((a, b), r) in d.section.deformed.iter().zip(&twice.section.deformed).zip(&d.section.rigid) {
            for c in 0..2 {
                let (da, db) = (a[c] - r[c], b[c] - r[c]);
                assert!((db - 2.0 * da).abs() <= 1e-12 * d.thickness_m, "{da} {db}");
            }
        }
        // Auto exaggeration: the largest drawn offset is between AUTO_FRACTION/2 and 2·AUTO_FRACTION of t.
        let drawn = d
            .section
            .deformed
            .iter()
            .zip(&d.section.rigid)
            .fold(0.0_f64, |m, (a, r)| m.max((a[0] - r[0]).hypot(a[1] - r[1])));
        let f = drawn / d.thickness_m;
        assert!((0.5 * AUTO_FRACTION..=2.0 * AUTO_FRACTION).contains(&f), "{f}");
        // Gallery: the retained modes in ascending frequency, each with the solved amplitude.
        assert_eq!(d.modes.len(), 2);
        assert!(d.modes[0].frequency_hz < d.modes[1].frequency_hz);
        assert_eq!(d.modes[1].amplitude_m, p.mode_amplitudes_m[1]);
        // Outline: film face and back (one vertex a column each) and the inner layers on both sides.
        let layers = p.flex.as_ref().unwrap().radii_m.len() - 1;
        assert_eq!(d.section.rigid.len(), 2 * d.section.film_face + 2 * (layers - 1));
    }

    /// TEHD (flexible pads with thermal growth): the thermal selection maps and draws the pad's thermal
    /// growth from the result, the total is the sum of the two parts, and h − u removes the shown part.
    #[test]
    fn thermal_and_total_displacements_are_the_growth_and_the_sum() {
        let s = flexible(&[
            "physics.pad_modes=1",
            "thermal.model=thd",
            "thermal.pad_expansion_ppm_per_k=12",
            "thermal.journal_expansion_ppm_per_k=11",
            "thermal.reference_temperature_c=20",
        ]);
        let loaded = 3;
        let p = &s.pads[loaded];
        let growth = p.thermal_growth.as_ref().expect("TEHD pads carry their growth");
        let scale = growth.film_radial_m.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        eprintln!(
            "thermal film-face growth of pad {loaded}: peak {:.3} µm; mechanical peak {:.3} µm",
            crate::units::UM.from_si(scale),
            crate::units::UM.from_si(p.elastic_displacement_m.iter().fold(0.0_f64, |m, v| m.max(v.abs())))
        );
        assert!(scale > 1e-7, "the heated pad grows: {scale}");
        let [m, t, total] = Displacement::ALL.map(|d| PadDeformation::new(&s, loaded, None, d).unwrap());
        assert!(m.thermal && t.shown == Displacement::Thermal && total.shown == Displacement::Total);
        let field = &p.field;
        let row = (0..field.z_m.len()).min_by(|&a, &b| field.z_m[a].abs().total_cmp(&field.z_m[b].abs())).unwrap();
        for i in 0..t.section.film_face {
            let n = field.index(i, row);
            assert!((t.section.radial_m[i] - growth.film_radial_m[n]).abs() <= 1e-12 * scale, "column {i}");
            let sum = m.section.radial_m[i] + t.section.radial_m[i];
            assert!((total.section.radial_m[i] - sum).abs() <= 1e-12 * scale, "column {i}");
        }
        // The thermal map's range is the growth's, and the maps of the parts add up to the total's.
        let (lo, hi) =
            growth.film_radial_m.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &v| (lo.min(v), hi.max(v)));
        assert!(
            (t.displacement.min - lo).abs() <= 1e-12 * scale && (t.displacement.max - hi).abs() <= 1e-12 * scale,
            "{} {} vs {lo} {hi}",
            t.displacement.min,
            t.displacement.max
        );
        for ((a, b), c) in m.displacement.values.iter().zip(&t.displacement.values).zip(&total.displacement.values) {
            assert!((a + b - c).abs() <= 1e-12 * scale, "{a} + {b} vs {c}");
        }
        for d in [&m, &t, &total] {
            for ((hf, hr), u) in d.film_flexible.values.iter().zip(&d.film_rigid.values).zip(&d.displacement.values) {
                assert!((hf - hr - u).abs() <= 1e-15, "{hf} {hr} {u}");
            }
        }
    }

    #[test]
    fn rigid_pads_have_no_deformation() {
        let s = flexible(&["physics.pad_modes=0"]);
        assert!(PadDeformation::new(&s, 3, None, Displacement::Total).is_none());
    }
}
