//! Campbell diagram: damped natural frequencies against spin speed, and the critical speeds where a
//! forward mode crosses an n× excitation line (`ω_d(Ω) = n Ω`), located by linear interpolation between the
//! sweep's speeds. Modes are followed by their rank in frequency within their whirl direction (forward modes
//! 1, 2, … and backward modes 1, 2, …), which is how the curves are drawn.

use serde::Serialize;

use super::eigen::Whirl;
use super::stability::SpeedPoint;

/// A crossing of a mode with an n× line.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct CriticalSpeed {
    /// Excitation order n.
    pub order: f64,
    pub whirl: Whirl,
    /// Rank of the mode within its whirl direction (0 = lowest).
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

/// Critical speeds of the first `ranks` forward modes on the n× line `order`.
#[must_use]
pub fn critical_speeds(sweep: &[SpeedPoint], order: f64, ranks: usize) -> Vec<CriticalSpeed> {
    let mut out = Vec::new();
    for rank in 0..ranks {
        for w in sweep.windows(2) {
            let (Some((f0, d0)), Some((f1, d1))) = (nth_mode(&w[0], Whirl::Forward, rank), nth_mode(&w[1], Whirl::Forward, rank)) else {
                continue;
            };
            let (g0, g1) = (f0 - order * w[0].speed_rad_s, f1 - order * w[1].speed_rad_s);
            if g0 > 0.0 && g1 <= 0.0 {
                let t = g0 / (g0 - g1);
                out.push(CriticalSpeed {
                    order,
                    whirl: Whirl::Forward,
                    rank,
                    speed_rad_s: w[0].speed_rad_s + t * (w[1].speed_rad_s - w[0].speed_rad_s),
                    log_dec: d0 + t * (d1 - d0),
                });
            }
        }
    }
    out.sort_by(|a, b| a.speed_rad_s.total_cmp(&b.speed_rad_s));
    out
}
