//! The bearing cross-section, to scale with an exaggerated clearance.
//!
//! Frame: the bearing frame of the solver (x horizontal, y up, metres, origin at the bearing centre);
//! a view maps it to the screen with `screen_from_bearing` (screen y points down).
//!
//! Scale: every dimension is true to scale except the film and the journal displacement, which are
//! multiplied by the exaggeration factor `k` (a round number chosen so the largest pad clearance shows as
//! about a sixth of the journal radius). A point at angle θ that sits a small radial distance δ from the
//! journal's nominal surface (radius R) is drawn at radius `R + k δ`:
//!
//! ```text
//! journal surface  ρ_j(θ) = R + k (e_x cos θ + e_y sin θ)
//! pad film surface ρ_p(θ) = ρ_j(θ) + k h(θ)            so the drawn gap is exactly k h
//! pad back         ρ_b(θ) = ρ_p(θ) + t                 pad thickness t to scale
//! ```
//!
//! `h(θ)` comes from the solver's own film geometry ([`PadShape`]) at the solved coordinates (journal
//! position, pad tilt, pivot displacement); without a solution the journal is centred and the pads
//! untilted. The mid-plane pressure is drawn inside the journal, inward from its surface, scaled so the
//! largest pressure reaches a third of the radius.

use std::f64::consts::TAU;

use crate::bearing::film::coordinates::{pad_dofs, Coord};
use crate::bearing::film::geometry::PadShape;
use crate::bearing::solution::Solution;
use crate::model::{Case, LoadSpec};
use crate::physics::reynolds::FilmShape;

/// A point in the drawing (bearing frame, metres, clearances exaggerated).
pub type Point = [f64; 2];

/// One pad of the cross-section.
#[derive(Debug, Clone, PartialEq)]
pub struct PadOutline {
    pub index: usize,
    /// Film-side surface from leading to trailing edge.
    pub film_surface: Vec<Point>,
    /// Back of the pad from leading to trailing edge.
    pub back: Vec<Point>,
    /// Pivot: contact point on the pad back and the two base corners of its support triangle.
    pub pivot: [Point; 3],
    /// Orifice channels: the two walls of each, from the back to the film surface.
    pub orifices: Vec<[[Point; 2]; 2]>,
    /// Oil is injected through this pad's orifices.
    pub injecting: bool,
    /// Minimum film thickness: the journal point, the pad point and the value [m].
    pub h_min: Option<(Point, Point, f64)>,
    /// Mid-plane pressure: a closed polygon from the journal surface inwards; empty without a solution.
    pub pressure: Vec<Point>,
    /// Where to write the pad's number.
    pub label_at: Point,
    pub fixed: bool,
}

/// The whole cross-section.
#[derive(Debug, Clone, PartialEq)]
pub struct BearingOutline {
    /// Clearance and displacement exaggeration factor k.
    pub exaggeration: f64,
    pub journal_radius_m: f64,
    /// Drawn journal centre (k e).
    pub journal_centre: Point,
    /// Journal surface polygon (closed).
    pub journal: Vec<Point>,
    pub pads: Vec<PadOutline>,
    /// Load on the journal: from the centre along the load direction, and its magnitude [N].
    pub load: Option<(Point, Point, f64)>,
    /// Pressure scale: the pressure drawn at a third of the journal radius [Pa].
    pub pressure_scale_pa: f64,
    /// Some pressure band was cut at [`PRESSURE_BAND_MAX`] of the radius (a locked scale below this result's
    /// peak would otherwise draw it through the journal's centre and out of the housing).
    pub pressure_clipped: bool,
    /// Half-size of a square that holds the drawing [m].
    pub extent_m: f64,
}

/// The longest pressure band, as a fraction of the journal radius (twice the scale's R/3).
pub const PRESSURE_BAND_MAX: f64 = 2.0 / 3.0;

/// The scales of a drawing: the film exaggeration and the pressure drawn at a third of the radius. A view
/// that locks them passes them back ([`bearing_outline_with`]) so two pictures compare (otherwise the
/// lock the exaggeration is chosen per case, and the pressure scale per solution).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct OutlineScales {
    pub exaggeration: f64,
    pub pressure_scale_pa: f64,
}

impl BearingOutline {
    /// The scales this drawing used.
    #[must_use]
    pub fn scales(&self) -> OutlineScales {
        OutlineScales { exaggeration: self.exaggeration, pressure_scale_pa: self.pressure_scale_pa }
    }
}

/// A round exaggeration factor (1, 2 or 5 × 10ⁿ) near `raw`.
#[must_use]
pub fn round_factor(raw: f64) -> f64 {
    if !(raw.is_finite() && raw > 1.0) {
        return 1.0;
    }
    let decade = 10f64.powf(raw.log10().floor());
    let m = raw / decade;
    let nice = if m < 1.5 {
        1.0
    } else if m < 3.5 {
        2.0
    } else if m < 7.5 {
        5.0
    } else {
        10.0
    };
    nice * decade
}

fn polar(r: f64, theta: f64) -> Point {
    [r * theta.cos(), r * theta.sin()]
}

/// Builds the cross-section of a case, at the solution's equilibrium when one is given.
#[must_use]
pub fn bearing_outline(case: &Case, solution: Option<&Solution>) -> BearingOutline {
    bearing_outline_with(case, solution, None)
}

/// [`bearing_outline`] with locked scales: `Some` keeps the given exaggeration and pressure scale
/// (pressures above the locked scale are drawn past a third of the radius), `None` chooses them.
#[must_use]
#[allow(clippy::cast_precision_loss, clippy::too_many_lines)]
pub fn bearing_outline_with(case: &Case, solution: Option<&Solution>, lock: Option<OutlineScales>) -> BearingOutline {
    let b = &case.bearing;
    let r = b.journal_radius_m;
    let cp_max = b.pads.iter().map(|p| p.clearance_m).fold(b.assembled_clearance_m, f64::max);
    let k = lock.map_or_else(|| round_factor(r / 6.0 / cp_max), |l| l.exaggeration);
    let e = solution.map_or([0.0, 0.0], |s| s.journal_position_m);
    let rho_j = |theta: f64| r + k * (e[0] * theta.cos() + e[1] * theta.sin());
    let journal: Vec<Point> = (0..=180).map(|i| f64::from(i) * TAU / 180.0).map(|t| polar(rho_j(t), t)).collect();

    let p_max = match (lock, solution) {
        (Some(l), Some(_)) if l.pressure_scale_pa > 0.0 => l.pressure_scale_pa,
        (_, s) => s.map_or(0.0, |s| s.p_max_pa),
    };
    let p_len = r / 3.0;
    let mut clipped = false;
    let mut pads = Vec::with_capacity(b.pads.len());
    let mut extent = r;
    for (idx, pad) in b.pads.iter().enumerate() {
        let result = solution.and_then(|s| s.pads.get(idx));
        let dofs = pad_dofs(pad);
        let shape = PadShape::new(pad, r, b.assembled_clearance_m, &dofs);
        // Local coordinates [e_x, e_y, pad coordinates…], looked up by their typed ids in the solution.
        let mut q = vec![e[0], e[1]];
        q.extend(dofs.iter().map(|&dof| {
            solution
                .and_then(|s| s.full.index(Coord::Pad { pad: idx, dof }).and_then(|i| s.coordinates.get(i)).copied())
                .unwrap_or(0.0)
        }));
        let h =
            |theta: f64| shape.base(theta, 0.0) + (0..q.len()).map(|d| q[d] * shape.dof(d, theta, 0.0)).sum::<f64>();
        let rho_p = |theta: f64| rho_j(theta) + k * h(theta);
        let n = 48;
        let thetas: Vec<f64> =
            (0..=n).map(|i| pad.leading_edge_rad + pad.arc_rad * f64::from(i) / f64::from(n)).collect();
        let film_surface: Vec<Point> = thetas.iter().map(|&t| polar(rho_p(t), t)).collect();
        let back: Vec<Point> = thetas.iter().map(|&t| polar(rho_p(t) + pad.thickness_m, t)).collect();
        let tp = pad.pivot_rad;
        let contact = rho_p(tp) + pad.thickness_m;
        let base = 0.1 * r;
        let half_angle = 0.6 * base / (contact + base);
        let pivot =
            [polar(contact, tp), polar(contact + base, tp - half_angle), polar(contact + base, tp + half_angle)];
        extent = extent.max(contact + base);
        let orifices = pad
            .orifices
            .iter()
            .map(|o| {
                let half = 0.5 * o.diameter_m / r;
                let wall = |t: f64| [polar(rho_p(t) + pad.thickness_m, t), polar(rho_p(t), t)];
                [wall(o.angle_rad - half), wall(o.angle_rad + half)]
            })
            .collect();
        let injecting =
            !pad.orifices.is_empty() && case.operating.injection_pressure_pa.get(idx).is_some_and(|&p| p > 0.0);
        let h_min = result.map(|p| {
            let t = p.h_min_angle_deg.to_radians();
            (polar(rho_j(t), t), polar(rho_p(t), t), p.h_min_m)
        });
        let pressure = match (result, p_max > 0.0) {
            (Some(res), true) => {
                let f = &res.field;
                // Mid-plane row: z = 0 (first row of a half model, else the row nearest 0).
                let row = (0..f.z_m.len()).min_by(|&a, &b| f.z_m[a].abs().total_cmp(&f.z_m[b].abs())).unwrap_or(0);
                let outer: Vec<Point> = f.theta_rad.iter().map(|&t| polar(rho_j(t), t)).collect();
                let inner: Vec<Point> = f
                    .theta_rad
                    .iter()
                    .enumerate()
                    .map(|(i, &t)| {
                        let band = p_len * f.pressure_pa[f.index(i, row)].max(0.0) / p_max;
                        clipped |= band > PRESSURE_BAND_MAX * r;
                        polar(rho_j(t) - band.min(PRESSURE_BAND_MAX * r), t)
                    })
                    .collect();
                outer.into_iter().chain(inner.into_iter().rev()).collect()
            }
            _ => Vec::new(),
        };
        let mid = pad.leading_edge_rad + 0.5 * pad.arc_rad;
        pads.push(PadOutline {
            index: idx,
            film_surface,
            back,
            pivot,
            orifices,
            injecting,
            h_min,
            pressure,
            label_at: polar(rho_p(mid) + 0.5 * pad.thickness_m, mid),
            fixed: pad.kind == crate::model::PadKind::Fixed,
        });
    }
    let load = match (solution, case.operating.load) {
        (Some(s), _) if s.load_magnitude_n > 0.0 => {
            let a = s.load_angle_rad();
            Some((e.map(|c| c * k), [k * e[0] + 0.55 * r * a.cos(), k * e[1] + 0.55 * r * a.sin()], s.load_magnitude_n))
        }
        (None, LoadSpec::Force { magnitude_n, angle_rad }) if magnitude_n > 0.0 => {
            Some(([0.0, 0.0], [0.55 * r * angle_rad.cos(), 0.55 * r * angle_rad.sin()], magnitude_n))
        }
        _ => None,
    };
    BearingOutline {
        exaggeration: k,
        journal_radius_m: r,
        journal_centre: [k * e[0], k * e[1]],
        journal,
        pads,
        load,
        pressure_scale_pa: p_max,
        pressure_clipped: clipped,
        extent_m: extent * 1.05,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::load_case;

    fn compressor() -> Case {
        load_case(include_str!("../../cases/compressor-bearing.toml"), &[]).unwrap().1
    }

    /// A scale locked at a third of this result's peak would draw the band three times R/3, through the
    /// journal's centre: it is cut at 2R/3 and said to be; at the peak's own scale nothing is cut.
    #[test]
    fn a_pressure_band_past_twice_the_locked_scale_is_cut_inside_the_journal() {
        let mut case = compressor();
        case.mesh.fidelity = crate::model::Fidelity::Preview;
        let (_, nz, no) = crate::model::Fidelity::Preview.elements();
        case.mesh.circumferential_elements = crate::model::Fidelity::Preview.circumferential_elements(1.0);
        (case.mesh.axial_elements, case.mesh.orifice_elements) = (nz, no);
        let s = crate::bearing::solve_case(&case).unwrap();
        let r = case.bearing.journal_radius_m;
        let deepest = |o: &BearingOutline| {
            let c = o.journal_centre;
            o.pads.iter().flat_map(|p| &p.pressure).map(|q| (q[0] - c[0]).hypot(q[1] - c[1])).fold(f64::MAX, f64::min)
        };
        let own = bearing_outline_with(&case, Some(&s), None);
        assert!(!own.pressure_clipped);
        // At its own scale the peak is drawn R/3 deep (the journal's eccentricity drawn aside).
        let free_depth = r - deepest(&own);
        assert!((free_depth / (r / 3.0) - 1.0).abs() < 0.05, "{free_depth}");
        let lock = OutlineScales { exaggeration: own.exaggeration, pressure_scale_pa: s.p_max_pa / 3.0 };
        let locked = bearing_outline_with(&case, Some(&s), Some(lock));
        assert!(locked.pressure_clipped);
        let depth = r - deepest(&locked);
        assert!((depth / (PRESSURE_BAND_MAX * r) - 1.0).abs() < 0.05, "{depth} of {r}");
    }

    #[test]
    fn exaggeration_is_a_round_number() {
        assert_eq!(round_factor(83.0), 100.0);
        assert_eq!(round_factor(0.3), 1.0);
        assert_eq!(round_factor(420.0), 500.0);
        assert_eq!(round_factor(170.0), 200.0);
    }

    #[test]
    fn centred_journal_shows_the_preload_to_scale() {
        let case = compressor();
        let o = bearing_outline(&case, None);
        let k = o.exaggeration;
        // R 50.8 mm, Cp 121 µm: 50.8/6/0.121 ≈ 70 → 50.
        assert_eq!(k, 50.0);
        assert_eq!(o.pads.len(), 5);
        let pad = &case.bearing.pads[3];
        let r = case.bearing.journal_radius_m;
        // At the pivot of a centred journal h = Cb: the drawn gap is k Cb.
        let outline = &o.pads[3];
        let mid = outline.film_surface.len() / 2;
        let drawn = outline.film_surface[mid][0].hypot(outline.film_surface[mid][1]);
        let theta = (outline.film_surface[mid][1]).atan2(outline.film_surface[mid][0]);
        let h_expected =
            pad.clearance_m - (pad.clearance_m - case.bearing.assembled_clearance_m) * (theta - pad.pivot_rad).cos();
        assert!((drawn - (r + k * h_expected)).abs() < 1e-12);
        // Leading-edge gap is larger than at the pivot (preload).
        let le = outline.film_surface[0][0].hypot(outline.film_surface[0][1]);
        assert!(le > drawn);
        // The load arrow points down (270°), pads carry one orifice each, not injecting.
        let (from, to, w) = o.load.unwrap();
        assert!((to[1] - from[1]) < 0.0 && (to[0] - from[0]).abs() < 1e-12 && (w - 1918.0).abs() < 1e-9);
        assert!(o.pads.iter().all(|p| p.orifices.len() == 1 && !p.injecting && p.pressure.is_empty()));
    }

    /// Locked scales survive edits: a case whose clearance would choose another exaggeration keeps the
    /// locked one (and its pressure scale), and unlocked it chooses its own again.
    #[test]
    fn locked_scales_stay_across_edits() {
        let case = compressor();
        let lock = bearing_outline(&case, None).scales();
        assert_eq!(lock.exaggeration, 50.0);
        // Half the clearances: 50.8/6/0.0605 ≈ 140 → 100 when free.
        let tight = load_case(
            include_str!("../../cases/compressor-bearing.toml"),
            &["bearing.assembled_clearance_um=51".into(), "bearing.pads.bore_radius_mm=50.8605".into()],
        )
        .unwrap()
        .1;
        assert_eq!(bearing_outline(&tight, None).exaggeration, 100.0);
        let locked = bearing_outline_with(&tight, None, Some(lock));
        assert_eq!(locked.scales(), lock);
        assert!((locked.journal_centre[0]).abs() < 1e-15);
    }
}
