//! What a bearing point's equilibrium has to find, counted from the case's pads before anything is built:
//! the work estimate ([`super::estimate::point_cost`]) scales the film solves of the reference point by it.
//!
//! The equilibrium is a Newton iteration over the journal and every pad coordinate, one film solve per pad
//! per iteration, after each pad has been placed on its own ([`crate::bearing::equilibrium`]). Two things
//! add film solves in proportion to the pads they concern:
//! ```text
//! coordinates = (1/n) Σ_pads max(1, pad coordinates)     tilt, the pivot translations a finite pivot
//!                                                         stiffness or a contact law gives, elastic modes
//! floating    = (pads that float at the cold start) / n   placed by a search of their own before Newton
//! ```
//! Each coordinate of a pad beyond its tilt is a direction of its own solve (the other coordinates are found
//! by Newton with the tilt condensed, each in its bracket), and a pad that floats at the cold start is placed
//! by a search along its tilt range before the bearing's Newton can use it. A pad floats there when nothing
//! presses it onto the film: every pad of a starved bearing (a supply flow below what the films draw: the
//! journal starts centred with every inlet short of oil), and a zero-preload tilting pad whose pivot lies
//! more than 90° from the load (its converging wedge opens away from the journal). The point's time is
//! `t_film · (f_thermal · coordinates + floating)`: the placement happens once, in the first (isothermal)
//! equilibrium, where an outer thermal loop repeats the Newton from a warm start. Both are counts, no
//! constant is fitted: the reference point (the compressor bearing, preloaded tilting pads on rigid pivots)
//! has `coordinates = 1`, `floating = 0`.

use crate::bearing::film::coordinates::pad_dofs;
use crate::model::{Case, LoadSpec, Pad, PadKind};

/// See the module.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EquilibriumWork {
    /// Mean over the pads of their coordinates, each pad at least 1.
    pub coordinates: f64,
    /// Share of the pads that float at the cold start.
    pub floating: f64,
}

/// The [`EquilibriumWork`] of `case`; `flexible`: its tilting pads carry `physics.pad_modes` elastic modes.
#[must_use]
pub fn equilibrium_work(case: &Case, flexible: bool) -> EquilibriumWork {
    let pads = &case.bearing.pads;
    if pads.is_empty() {
        return EquilibriumWork { coordinates: 1.0, floating: 0.0 };
    }
    let modes = if flexible { case.physics.pad_modes } else { 0 };
    let tilting = |p: &Pad| p.kind == PadKind::Tilting;
    let coordinates: usize = pads.iter().map(|p| (pad_dofs(p).len() + if tilting(p) { modes } else { 0 }).max(1)).sum();
    let floating = pads.iter().filter(|p| tilting(p) && floats_at_cold_start(case, p)).count();
    #[allow(clippy::cast_precision_loss)]
    let n = pads.len() as f64;
    #[allow(clippy::cast_precision_loss)]
    EquilibriumWork { coordinates: coordinates as f64 / n, floating: floating as f64 / n }
}

/// Whether a tilting pad floats at the cold start (see the module).
fn floats_at_cold_start(case: &Case, pad: &Pad) -> bool {
    if case.operating.supply_flow_m3_s.is_some() {
        return true;
    }
    let LoadSpec::Force { magnitude_n, angle_rad } = case.operating.load else { return false };
    let away = (pad.pivot_rad - angle_rad).rem_euclid(std::f64::consts::TAU);
    let from_load = away.min(std::f64::consts::TAU - away);
    pad.preload <= 0.0 && magnitude_n > 0.0 && from_load > std::f64::consts::FRAC_PI_2
}

#[cfg(test)]
mod tests {
    use super::*;

    fn case(name: &str, set: &[&str]) -> Case {
        let text = std::fs::read_to_string(format!("{}/cases/{name}", env!("CARGO_MANIFEST_DIR"))).unwrap();
        let set: Vec<String> = set.iter().map(|s| (*s).to_string()).collect();
        crate::model::load_case(&text, &set).unwrap().1
    }

    #[test]
    fn pads_count_their_coordinates_and_the_pads_that_float_at_the_cold_start() {
        // the reference: preloaded tilting pads on rigid pivots
        let w = equilibrium_work(&case("compressor-bearing.toml", &[]), false);
        assert_eq!((w.coordinates, w.floating), (1.0, 0.0));
        // a pivot stiffness (the test rig) or a contact law (rocker) adds the pivot's radial coordinate
        for name in ["test-rig.toml", "test-rig-pub5.toml", "compressor-bearing-rocker-pivot.toml"] {
            assert_eq!(equilibrium_work(&case(name, &[]), false).coordinates, 2.0, "{name}");
        }
        // one elastic mode on each tilting pad
        assert_eq!(equilibrium_work(&case("compressor-bearing-flexible.toml", &[]), true).coordinates, 2.0);
        // starved: every pad floats at the cold start
        assert_eq!(equilibrium_work(&case("compressor-bearing-starved.toml", &[]), false).floating, 1.0);
        // Someya's zero-preload pads, load between pads at 270°: the two pads at 45° and 135° face away from it
        let w = equilibrium_work(&case("someya-4pad-lbp.toml", &[]), false);
        assert_eq!((w.coordinates, w.floating), (1.0, 0.5));
        // with preload they are pressed onto their films
        assert_eq!(equilibrium_work(&case("someya-4pad-lbp.toml", &["bearing.pads.preload=0.3"]), false).floating, 0.0);
        // fixed sectors have no coordinate and never float
        let w = equilibrium_work(&case("plain-2groove-ld05.toml", &[]), false);
        assert_eq!((w.coordinates, w.floating), (1.0, 0.0));
    }
}
