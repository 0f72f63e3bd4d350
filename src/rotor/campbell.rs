//! Campbell diagram: damped natural frequencies against spin speed, and the critical speeds where a
//! forward mode crosses an n× excitation line (`ω_d(Ω) = n Ω`), located by linear interpolation between the
//! sweep's speeds.
//!
//! Modes are followed from speed to speed by eigenvector continuity, not by their rank in frequency, so a
//! line does not jump to another mode where two modes cross. Between neighbouring speeds the modal assurance
//! criterion of the shaft's complex (x, y) mode shapes
//! ```text
//! MAC(a, b) = |φ_aᴴ φ_b|² / ((φ_aᴴ φ_a)(φ_bᴴ φ_b))      (1: the same shape, 0: orthogonal)
//! ```
//! pairs each followed mode with the mode of the next speed it resembles most (greedy, largest MAC first,
//! each mode taken once). Forward and backward whirl of one shape are orthogonal under this product
//! (`(1, −i)` against `(1, i)`), so whirl directions are kept apart too. A track takes the whirl most of its
//! points have and is numbered within that whirl by its frequency at the first speed.

use nalgebra::Complex;
use serde::{Deserialize, Serialize};

use super::eigen::{Mode, Whirl};
use super::stability::SpeedPoint;

/// A crossing of a mode with an n× line.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct CriticalSpeed {
    /// Excitation order n.
    pub order: f64,
    pub whirl: Whirl,
    /// Number of the followed mode within its whirl direction (0 = lowest at the sweep's first speed).
    pub rank: usize,
    pub speed_rad_s: f64,
    /// Logarithmic decrement at the crossing (interpolated).
    pub log_dec: f64,
}

/// Frequencies [rad/s] and decrements of the rank-th mode of a whirl direction at a speed point.
#[must_use]
pub fn nth_mode(p: &SpeedPoint, whirl: Whirl, rank: usize) -> Option<(f64, f64)> {
    p.modes.modes.iter().filter(|m| m.whirl == whirl).nth(rank).map(|m| (m.imag_rad_s, m.log_dec))
}

/// A mode followed over a sweep.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Track {
    /// The whirl most of its points have.
    pub whirl: Whirl,
    /// Number within that whirl (0 = lowest at the first speed).
    pub rank: usize,
    /// Index of the followed mode in each speed point's modes (`None` where the point has too few modes).
    pub index: Vec<Option<usize>>,
}

impl Track {
    /// The followed mode at speed point `i`.
    #[must_use]
    pub fn mode<'a>(&self, sweep: &[&'a SpeedPoint], i: usize) -> Option<&'a Mode> {
        self.index.get(i).copied().flatten().and_then(|k| sweep[i].modes.modes.get(k))
    }
}

/// Modal assurance criterion of two complex shapes over the shaft nodes.
#[must_use]
pub fn mac(a: &[[Complex<f64>; 2]], b: &[[Complex<f64>; 2]]) -> f64 {
    let (mut ab, mut aa, mut bb) = (Complex::new(0.0, 0.0), 0.0, 0.0);
    for (p, q) in a.iter().zip(b) {
        for d in 0..2 {
            ab += p[d].conj() * q[d];
            aa += p[d].norm_sqr();
            bb += q[d].norm_sqr();
        }
    }
    if aa > 0.0 && bb > 0.0 {
        ab.norm_sqr() / (aa * bb)
    } else {
        0.0
    }
}

/// Follows the `count` lowest modes of the sweep's first point through the sweep.
#[must_use]
pub fn track_modes(sweep: &[&SpeedPoint], count: usize) -> Vec<Track> {
    let Some(first) = sweep.first() else { return Vec::new() };
    let n = count.min(first.modes.modes.len());
    let mut index: Vec<Vec<Option<usize>>> = (0..n).map(|k| vec![Some(k)]).collect();
    // the shape each track had where it was last found
    let mut last: Vec<&[[Complex<f64>; 2]]> = (0..n).map(|k| first.modes.modes[k].shape.as_slice()).collect();
    for p in &sweep[1..] {
        let modes = &p.modes.modes;
        let mut pairs: Vec<(f64, usize, usize)> = Vec::with_capacity(n * modes.len());
        for (t, shape) in last.iter().enumerate() {
            for (j, m) in modes.iter().enumerate() {
                pairs.push((mac(shape, &m.shape), t, j));
            }
        }
        pairs.sort_by(|a, b| b.0.total_cmp(&a.0));
        let (mut taken_t, mut taken_j) = (vec![false; n], vec![false; modes.len()]);
        let mut pick = vec![None; n];
        for (_, t, j) in pairs {
            if !taken_t[t] && !taken_j[j] {
                (taken_t[t], taken_j[j]) = (true, true);
                pick[t] = Some(j);
            }
        }
        for t in 0..n {
            index[t].push(pick[t]);
            if let Some(j) = pick[t] {
                last[t] = modes[j].shape.as_slice();
            }
        }
    }
    let mut tracks: Vec<Track> = index
        .into_iter()
        .map(|index| {
            let forward = index
                .iter()
                .zip(sweep)
                .filter(|(k, p)| k.and_then(|k| p.modes.modes.get(k)).is_some_and(|m| m.whirl == Whirl::Forward))
                .count();
            let found = index.iter().filter(|k| k.is_some()).count();
            Track { whirl: if 2 * forward >= found { Whirl::Forward } else { Whirl::Backward }, rank: 0, index }
        })
        .collect();
    // tracks start in ascending frequency: number them in that order within their whirl
    for whirl in [Whirl::Forward, Whirl::Backward] {
        for (r, t) in tracks.iter_mut().filter(|t| t.whirl == whirl).enumerate() {
            t.rank = r;
        }
    }
    tracks
}

/// Critical speeds of the followed modes (the `2 ranks` lowest at the first speed) where a forward-whirling
/// mode crosses the n× line `order`.
#[must_use]
pub fn critical_speeds(sweep: &[SpeedPoint], order: f64, ranks: usize) -> Vec<CriticalSpeed> {
    let refs: Vec<&SpeedPoint> = sweep.iter().collect();
    let mut out = Vec::new();
    for track in track_modes(&refs, 2 * ranks) {
        for i in 1..refs.len() {
            let (Some(a), Some(b)) = (track.mode(&refs, i - 1), track.mode(&refs, i)) else { continue };
            if a.whirl != Whirl::Forward || b.whirl != Whirl::Forward {
                continue;
            }
            let (s0, s1) = (refs[i - 1].speed_rad_s, refs[i].speed_rad_s);
            let (g0, g1) = (a.imag_rad_s - order * s0, b.imag_rad_s - order * s1);
            if g0 > 0.0 && g1 <= 0.0 {
                let t = g0 / (g0 - g1);
                out.push(CriticalSpeed {
                    order,
                    whirl: Whirl::Forward,
                    rank: track.rank,
                    speed_rad_s: s0 + t * (s1 - s0),
                    log_dec: a.log_dec + t * (b.log_dec - a.log_dec),
                });
            }
        }
    }
    out.sort_by(|a, b| a.speed_rad_s.total_cmp(&b.speed_rad_s));
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::rotor::Disk;
    use crate::rotor::assembly::ShaftModel;
    use crate::rotor::closed_form::uniform;
    use crate::rotor::coupling::BearingCoefficients;
    use crate::rotor::element::BeamTheory;
    use crate::rotor::stability::modes_at;

    /// A shaft symmetric about its middle: a disk at mid-span whose transverse inertia puts the pitching mode
    /// below the bouncing one at rest, and whose polar inertia (2 I_d) drives the forward pitching mode up
    /// through the bouncing modes as the speed rises. By symmetry the bouncing shapes are even about the
    /// middle and the pitching ones odd, exactly, so the followed mode's parity tells whether a line swapped.
    #[test]
    fn a_followed_mode_keeps_its_shape_through_a_crossing() {
        let n = 6;
        let mut rotor = uniform(0.6, 0.05, n, 7800.0, 2e11, BeamTheory::Timoshenko);
        rotor.disks.push(Disk { node: n / 2, mass: 20.0, polar: 8.0, transverse: 4.0 });
        let shaft = ShaftModel::new(&rotor).unwrap();
        let b = BearingCoefficients::Reduced { k: [[1e6, 0.0], [0.0, 1e6]], c: [[100.0, 0.0], [0.0, 100.0]] };
        let mut provider = |_w: f64| Ok(vec![b.clone(), b.clone()]);
        let sweep: Vec<SpeedPoint> =
            (1..=30).map(|i| modes_at(&shaft, &[0, n], &mut provider, 20.0 * f64::from(i)).unwrap()).collect();
        let refs: Vec<&SpeedPoint> = sweep.iter().collect();
        // parity of a shape: x at the two ends, relative to the larger
        let odd = |m: &Mode| {
            let (a, b) = (m.shape[0][0], m.shape[n][0]);
            (a + b).norm() / a.norm().max(b.norm())
        };
        let tracks = track_modes(&refs, 4);
        let pitch = tracks.iter().find(|t| t.whirl == Whirl::Forward && t.rank == 0).unwrap();
        let bounce_hz = sweep[0].modes.modes.iter().find(|m| odd(m) > 1.0).unwrap().imag_rad_s;
        let mut previous = 0.0;
        for i in 0..refs.len() {
            let m = pitch.mode(&refs, i).unwrap();
            assert!(odd(m) < 1e-6, "speed {i}: the followed pitching mode lost its parity ({})", odd(m));
            assert!(m.imag_rad_s > previous, "speed {i}: forward pitching rises with speed");
            previous = m.imag_rad_s;
        }
        eprintln!(
            "pitching {:.1} → {previous:.1} rad/s, bouncing {bounce_hz:.1} rad/s",
            pitch.mode(&refs, 0).unwrap().imag_rad_s
        );
        assert!(pitch.mode(&refs, 0).unwrap().imag_rad_s < bounce_hz && previous > 1.2 * bounce_hz, "the modes cross");
        // ranked by frequency, the lowest forward mode at the last speed is a bouncing one: a rank line swaps
        let last = refs.last().unwrap();
        let lowest_forward = last.modes.modes.iter().find(|m| m.whirl == Whirl::Forward).unwrap();
        assert!(odd(lowest_forward) > 1.0, "{}", odd(lowest_forward));
    }

    #[test]
    fn mac_is_one_for_a_scaled_shape_and_zero_between_forward_and_backward_whirl() {
        let c = |re, im| Complex::new(re, im);
        let fwd = [[c(1.0, 0.0), c(0.0, -1.0)], [c(0.5, 0.0), c(0.0, -0.5)]];
        let scaled: Vec<[Complex<f64>; 2]> = fwd.iter().map(|p| [p[0] * c(0.3, 2.0), p[1] * c(0.3, 2.0)]).collect();
        let bwd = [[c(1.0, 0.0), c(0.0, 1.0)], [c(0.5, 0.0), c(0.0, 0.5)]];
        assert!((mac(&fwd, &scaled) - 1.0).abs() < 1e-15);
        assert!(mac(&fwd, &bwd).abs() < 1e-15);
    }
}
