//! The Nyquist criterion at one actuator's input, and the loop's gain and phase margins.
//!
//! With the loop broken at the input of actuator `a` ([`super::closed_loop::broken`]), the loop transfer
//! `L(s) = z/w` closes as `w = −z`: the closed loop's poles are the zeros of `1 + L(s)`. Nyquist: with `P`
//! poles of the open (broken) loop in the right half-plane and `N` counter-clockwise encirclements of −1 by
//! `L(iω)`, ω from −∞ to ∞, the closed loop has `Z = P − N` poles there.
//!
//! `L` is evaluated in the open loop's modal form, `L(s) = Σ_i (C v_i)(w_iᵀ B)/(s − λ_i)` (one eigen-solution
//! of the open loop, then any number of frequencies for the price of a sum). The winding of `1 + L(iω)` is the
//! phase it gathers over ω ≥ 0, doubled (conjugate symmetry), tracked on a grid that refines wherever the phase
//! moves more than 0.2 rad between neighbours. This path never forms the closed loop's matrix: it checks the
//! eigenvalues of [`super::closed_loop::poles`] (a test holds the two to agree at every speed of a sweep).
//!
//! Margins (read on the same curve): the gain margin is the factor `1/|L|` at the phase crossings of the
//! negative real axis nearest to −1, the phase margin `180° + ∠L` at the gain crossings `|L| = 1` nearest to
//! −1 (smallest in magnitude).

use nalgebra::{DMatrix, DVector};
use serde::{Deserialize, Serialize};

use super::error::ControlError;
use super::state_space::{eigen, StateSpace, C64};

/// The loop transfer in modal form.
pub struct ModalLoop {
    pub poles: Vec<C64>,
    residues: Vec<C64>,
    direct: f64,
}

impl ModalLoop {
    /// The modal form of SISO `l`.
    ///
    /// # Errors
    /// [`ControlError::Eigen`] when the open loop's eigen-solution fails or its eigenvectors are singular.
    pub fn new(l: &StateSpace) -> Result<Self, ControlError> {
        let n = l.states();
        let (poles, v) = eigen(&l.a)?;
        let b = DVector::from_fn(n, |i, _| C64::from(l.b[(i, 0)]));
        let beta = v.clone().lu().solve(&b).ok_or(ControlError::Eigen { size: n })?;
        let c = DMatrix::from_fn(1, n, |_, j| C64::from(l.c[(0, j)]));
        let gamma = c * &v;
        let residues = (0..n).map(|i| gamma[(0, i)] * beta[i]).collect();
        Ok(Self { poles, residues, direct: l.d[(0, 0)] })
    }

    /// `L(iω)`.
    #[must_use]
    pub fn at(&self, omega: f64) -> C64 {
        let s = C64::new(0.0, omega);
        self.poles.iter().zip(&self.residues).fold(C64::from(self.direct), |acc, (p, r)| acc + r / (s - p))
    }

    /// Open-loop poles with Re > 0.
    #[must_use]
    pub fn unstable_poles(&self) -> usize {
        self.poles.iter().filter(|p| p.re > 0.0).count()
    }
}

/// What the Nyquist plot of one loop says.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Nyquist {
    /// Open-loop poles in the right half-plane.
    pub open_unstable: usize,
    /// Counter-clockwise encirclements of −1.
    pub encirclements: i64,
    /// Closed-loop poles in the right half-plane, `P − N`.
    pub closed_unstable: i64,
    /// Gain margin (factor; `None`: no crossing of the negative real axis) and its frequency [Hz].
    pub gain_margin: Option<f64>,
    pub gain_margin_hz: Option<f64>,
    /// Phase margin [deg] (`None`: |L| never crosses 1) and its frequency [Hz].
    pub phase_margin_deg: Option<f64>,
    pub phase_margin_hz: Option<f64>,
    /// The curve `(f [Hz], Re L, Im L)`, thinned for plotting.
    pub curve: Vec<[f64; 3]>,
}

impl Nyquist {
    /// Stable by the Nyquist criterion.
    #[must_use]
    pub fn stable(&self) -> bool {
        self.closed_unstable == 0
    }
}

/// Largest phase step between neighbouring samples before the grid is refined [rad].
const STEP: f64 = 0.2;
/// Refinement depth (halvings of a base interval).
const DEPTH: usize = 40;

/// The Nyquist analysis of `l` (SISO).
///
/// # Errors
/// As [`ModalLoop::new`].
pub fn nyquist(l: &StateSpace) -> Result<Nyquist, ControlError> {
    let m = ModalLoop::new(l)?;
    let top = m.poles.iter().map(|p| p.norm()).fold(1.0, f64::max) * 100.0;
    // base grid: 0, then logarithmic from top·1e-8 to top, plus every pole's frequency and its half-power band
    let mut grid = vec![0.0];
    let n_log = 400;
    for i in 0..=n_log {
        #[allow(clippy::cast_precision_loss)]
        grid.push(top * 10f64.powf(-8.0 + 8.0 * i as f64 / f64::from(n_log)));
    }
    for p in &m.poles {
        if p.im > 0.0 {
            for k in [-2.0, -1.0, -0.5, 0.0, 0.5, 1.0, 2.0] {
                let w = p.im + k * p.re.abs();
                if w > 0.0 {
                    grid.push(w);
                }
            }
        }
    }
    grid.sort_by(f64::total_cmp);
    grid.dedup();
    let one = |w: f64| C64::from(1.0) + m.at(w);
    let mut samples: Vec<(f64, C64)> = Vec::with_capacity(grid.len() * 2);
    let mut phase = 0.0;
    let mut prev = (grid[0], one(grid[0]));
    samples.push((prev.0, m.at(prev.0)));
    for &w in &grid[1..] {
        let next = (w, one(w));
        refine(&one, prev, next, 0, &mut phase, &mut samples);
        prev = next;
    }
    // the tail from the top of the grid to ∞ (L → D, and the phase of 1 + L settles)
    let end = one(top * 1e6);
    phase += wrap((end / prev.1).arg());
    #[allow(clippy::cast_possible_truncation)]
    let encirclements = (2.0 * phase / std::f64::consts::TAU).round() as i64;
    let open_unstable = m.unstable_poles();
    let (gain_margin, gain_margin_hz, phase_margin_deg, phase_margin_hz) = margins(&samples, &m);
    let stride = (samples.len() / 2000).max(1);
    let hz = |w: f64| w / std::f64::consts::TAU;
    let curve = samples.iter().step_by(stride).map(|(w, z)| [hz(*w), z.re, z.im]).collect();
    #[allow(clippy::cast_possible_wrap)]
    Ok(Nyquist {
        open_unstable,
        encirclements,
        closed_unstable: open_unstable as i64 - encirclements,
        gain_margin,
        gain_margin_hz,
        phase_margin_deg,
        phase_margin_hz,
        curve,
    })
}

fn wrap(a: f64) -> f64 {
    let t = std::f64::consts::TAU;
    a - t * (a / t).round()
}

/// Adds the samples in `(a, b]` (refined where the phase of `1 + L` jumps) and their phase steps.
fn refine(
    one: &dyn Fn(f64) -> C64,
    a: (f64, C64),
    b: (f64, C64),
    depth: usize,
    phase: &mut f64,
    samples: &mut Vec<(f64, C64)>,
) {
    let step = wrap((b.1 / a.1).arg());
    if step.abs() > STEP && depth < DEPTH {
        let mid = 0.5 * (a.0 + b.0);
        let c = (mid, one(mid));
        refine(one, a, c, depth + 1, phase, samples);
        refine(one, c, b, depth + 1, phase, samples);
    } else {
        *phase += step;
        samples.push((b.0, b.1 - C64::from(1.0)));
    }
}

type Margins = (Option<f64>, Option<f64>, Option<f64>, Option<f64>);

/// The root of `g` in `[a, b]` (a sign change) by bisection, to round-off.
fn bisect(g: &dyn Fn(f64) -> f64, mut a: f64, mut b: f64) -> f64 {
    let ga = g(a);
    for _ in 0..80 {
        let mid = 0.5 * (a + b);
        if mid <= a || mid >= b {
            break;
        }
        if g(mid).signum() == ga.signum() {
            a = mid;
        } else {
            b = mid;
        }
    }
    0.5 * (a + b)
}

/// Gain and phase margins: the crossings bracketed by the samples of `L(iω)`, each refined by bisection on
/// the modal form.
fn margins(samples: &[(f64, C64)], m: &ModalLoop) -> Margins {
    let hz = |w: f64| w / std::f64::consts::TAU;
    let mut gm: Option<(f64, f64)> = None;
    let mut pm: Option<(f64, f64)> = None;
    for w in samples.windows(2) {
        let ((w0, a), (w1, b)) = (w[0], w[1]);
        // phase crossing of the negative real axis
        if a.im.signum() != b.im.signum() && a.im != 0.0 && (a.re < 0.0 || b.re < 0.0) {
            let w = bisect(&|x| m.at(x).im, w0, w1);
            let re = m.at(w).re;
            if re < 0.0 {
                let factor = -1.0 / re;
                if gm.is_none_or(|(g, _)| factor.ln().abs() < g.ln().abs()) {
                    gm = Some((factor, hz(w)));
                }
            }
        }
        // gain crossing
        let (ma, mb) = (a.norm() - 1.0, b.norm() - 1.0);
        if ma.signum() != mb.signum() && ma != 0.0 {
            let w = bisect(&|x| m.at(x).norm() - 1.0, w0, w1);
            let margin = wrap(m.at(w).arg() + std::f64::consts::PI).to_degrees();
            if pm.is_none_or(|(p, _)| margin.abs() < p.abs()) {
                pm = Some((margin, hz(w)));
            }
        }
    }
    (gm.map(|g| g.0), gm.map(|g| g.1), pm.map(|p| p.0), pm.map(|p| p.1))
}
