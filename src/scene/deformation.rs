//! Pad deformation, as plain drawables: the pad's cross-section (undeformed and deformed, exaggerated), the
//! unwrapped film-face displacement, the flexible and the rigid film thickness, and a gallery of the retained
//! mode shapes with their frequencies.
//!
//! Mechanical deformation of a flexible pad (model.md §5): the solid's displacement is
//! `v(x) = Σ_i q_i ψ_i(x)`, with `q_i` the solved amplitude of `PadDof::Mode(i)` and `ψ_i` the mode's nodal
//! displacement (polar components u_r, u_θ, u_z per pad node, per unit coordinate). Its radial component on the
//! film face is `u(s, z) = Σ_i q_i φ_i(s, z)` ([`crate::bearing::solution::PadResult::elastic_displacement_m`];
//! positive away from the journal, opening the film). The film thickness of the flexible pad is
//! `h = h_rigid(q_rigid) + u`, so the rigid pad at the same pivot, tilt and journal positions has the film
//! `h − u` and the difference map of the two is `u` itself. (Thermal growth of the pads is not modelled yet:
//! the displacement shown is the mechanical one, which is then also the total.)
//!
//! The cross-section is cut at the axial mid-plane (the row nearest z = 0) through every node layer of the pad
//! solid. It is drawn in the pad frame: origin at the bearing centre, y outwards through the pivot, x along
//! the direction of rotation (leading edge on the left), so
//! `x = r sin(θ − θ_p)`, `y = r cos(θ − θ_p)`; a displaced node moves by `a (u_r e_r + u_θ e_θ)` with the
//! exaggeration `a`. Lengths in metres; display units are the view's.

use crate::bearing::solution::{PadField, PadFlex, Solution};

use super::field::{FieldKind, PadMap};
use super::outline::round_factor;

/// Automatic exaggeration: the largest displacement drawn as this fraction of the pad thickness.
pub const AUTO_FRACTION: f64 = 0.15;

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
    pub exaggeration: f64,
    pub thickness_m: f64,
    pub section: Section,
    /// Film-face radial displacement u [m] (also the flexible − rigid film difference).
    pub displacement: PadMap,
    /// Film thickness of the flexible pad h and of the rigid pad at the same positions h − u [m].
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

impl PadDeformation {
    /// The drawables of pad `pad` of a solution; `None` for a rigid pad (no modes). `exaggeration`: `None`
    /// chooses one ([`auto_exaggeration`]).
    #[must_use]
    pub fn new(solution: &Solution, pad: usize, exaggeration: Option<f64>) -> Option<Self> {
        let result = solution.pads.get(pad)?;
        let flex = result.flex.as_ref()?;
        let field = &result.field;
        let r = solution.inputs.bearing.journal_radius_m;
        let pivot_rad = solution.inputs.bearing.pads.get(pad)?.pivot_rad;
        let thickness_m = flex.radii_m.last()? - flex.radii_m.first()?;
        let cut = SectionCut::new(field, flex, pivot_rad)?;
        let peak = cut.peak(&result.mode_amplitudes_m);
        let exaggeration = exaggeration.unwrap_or_else(|| auto_exaggeration(peak, thickness_m));
        let u = &result.elastic_displacement_m;
        let rigid_h: Vec<f64> = field.film_thickness_m.iter().zip(u).map(|(h, u)| h - u).collect();
        let map = |nodal: &[f64]| PadMap::from_nodal(field, pad, FieldKind::FilmThickness, r, nodal);
        let modes = flex
            .modes
            .modes
            .iter()
            .enumerate()
            .filter_map(|(i, m)| {
                let mut unit = vec![0.0; flex.modes.modes.len()];
                unit[i] = 1.0;
                // A shape per unit coordinate (1 m at its peak): drawn with its peak at AUTO_FRACTION of t.
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
            exaggeration,
            thickness_m,
            section: cut.section(&result.mode_amplitudes_m, exaggeration),
            displacement: map(u)?,
            film_flexible: map(&field.film_thickness_m)?,
            film_rigid: map(&rigid_h)?,
            modes,
        })
    }
}

/// The mid-plane cut through a pad solid: outline nodes and their undeformed positions.
struct SectionCut<'a> {
    flex: &'a PadFlex,
    /// Pad node, angle from the pivot [rad] and radius [m] of each outline vertex.
    vertices: Vec<(usize, f64, f64)>,
    film_face: usize,
    pivot: [f64; 2],
}

impl<'a> SectionCut<'a> {
    fn new(field: &PadField, flex: &'a PadFlex, pivot_rad: f64) -> Option<Self> {
        let n_film = field.pressure_pa.len();
        let layers = flex.radii_m.len().checked_sub(1)?;
        let cols = field.s_m.len();
        let n_nodes = n_film * (layers + 1);
        if cols < 2 || layers == 0 || flex.modes.modes.iter().any(|m| m.nodal.len() != 3 * n_nodes) {
            return None;
        }
        // The row nearest the axial mid-plane.
        let row = (0..field.z_m.len()).min_by(|&a, &b| field.z_m[a].abs().total_cmp(&field.z_m[b].abs()))?;
        let vertex = |layer: usize, col: usize| (layer * n_film + field.index(col, row), field.theta_rad[col] - pivot_rad, flex.radii_m[layer]);
        let mut vertices: Vec<_> = (0..cols).map(|i| vertex(0, i)).collect();
        vertices.extend((1..=layers).map(|l| vertex(l, cols - 1)));
        vertices.extend((0..cols - 1).rev().map(|i| vertex(layers, i)));
        vertices.extend((1..layers).rev().map(|l| vertex(l, 0)));
        Some(Self { flex, vertices, film_face: cols, pivot: [0.0, flex.radii_m[layers]] })
    }

    /// Polar displacement (u_r, u_θ) of pad node `node` for the mode amplitudes `q`.
    fn displacement(&self, q: &[f64], node: usize) -> [f64; 2] {
        self.flex.modes.modes.iter().zip(q).fold([0.0, 0.0], |[ur, ut], (m, a)| [ur + a * m.nodal[3 * node], ut + a * m.nodal[3 * node + 1]])
    }

    /// Largest in-plane displacement on the outline for the amplitudes `q` [m].
    fn peak(&self, q: &[f64]) -> f64 {
        self.vertices.iter().map(|&(n, _, _)| self.displacement(q, n)).fold(0.0_f64, |p, [ur, ut]| p.max(ur.hypot(ut)))
    }

    fn section(&self, q: &[f64], exaggeration: f64) -> Section {
        let mut section = Section {
            rigid: Vec::with_capacity(self.vertices.len()),
            deformed: Vec::with_capacity(self.vertices.len()),
            radial_m: Vec::with_capacity(self.vertices.len()),
            film_face: self.film_face,
            pivot: self.pivot,
        };
        for &(node, phi, r) in &self.vertices {
            let (s, c) = phi.sin_cos();
            let [ur, ut] = self.displacement(q, node);
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
        let all: Vec<String> = std::iter::once("mesh.fidelity=preview").chain(sets.iter().copied()).map(str::to_string).collect();
        let case = load_case(include_str!("../../cases/compressor-bearing-flexible.toml"), &all).unwrap().1;
        solve_case(&case).unwrap()
    }

    #[test]
    fn the_deformed_section_and_the_maps_agree_with_the_solved_modes() {
        let s = flexible(&["physics.pad_modes=2"]);
        let loaded = 3;
        let d = PadDeformation::new(&s, loaded, None).unwrap();
        let p = &s.pads[loaded];
        // The film face of the section carries the film-face field of the solve (nodal and film shapes are
        // the same field), at the mid-plane row.
        let field = &p.field;
        let row = (0..field.z_m.len()).min_by(|&a, &b| field.z_m[a].abs().total_cmp(&field.z_m[b].abs())).unwrap();
        let scale = p.elastic_displacement_m.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        assert!(scale > 1e-8, "the loaded pad bends: {scale}");
        for i in 0..d.section.film_face {
            let expected = p.elastic_displacement_m[field.index(i, row)];
            assert!((d.section.radial_m[i] - expected).abs() <= 1e-9 * scale, "column {i}: {} vs {expected}", d.section.radial_m[i]);
        }
        // Flexible − rigid film = displacement, everywhere.
        for ((hf, hr), u) in d.film_flexible.values.iter().zip(&d.film_rigid.values).zip(&d.displacement.values) {
            assert!((hf - hr - u).abs() <= 1e-15, "{hf} {hr} {u}");
        }
        // The deformation is drawn to the chosen exaggeration: doubling it doubles every vertex's offset.
        let twice = PadDeformation::new(&s, loaded, Some(2.0 * d.exaggeration)).unwrap();
        for ((a, b), r) in d.section.deformed.iter().zip(&twice.section.deformed).zip(&d.section.rigid) {
            for c in 0..2 {
                let (da, db) = (a[c] - r[c], b[c] - r[c]);
                assert!((db - 2.0 * da).abs() <= 1e-12 * d.thickness_m, "{da} {db}");
            }
        }
        // Auto exaggeration: the largest drawn offset is between AUTO_FRACTION/2 and 2·AUTO_FRACTION of t.
        let drawn = d.section.deformed.iter().zip(&d.section.rigid).fold(0.0_f64, |m, (a, r)| m.max((a[0] - r[0]).hypot(a[1] - r[1])));
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

    #[test]
    fn rigid_pads_have_no_deformation() {
        let s = flexible(&["physics.pad_modes=0"]);
        assert!(PadDeformation::new(&s, 3, None).is_none());
    }
}
