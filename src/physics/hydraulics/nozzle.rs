//! The nozzles at the lines' far ends: the flow into the film, linearised about the static state.
//!
//! ## Equation
//! The flow through the orifices `o` of port `k`'s pads (docs/MODEL.md §2, §8; thesis eq. 2.31) is
//! `q_k = Σ_o ∫_S0 (p_k − p) g dS / (4 µ_inj l0)`, with the film pressure `p` depending on the port
//! pressures, the bearing's coordinates `u` (journal and pads) and their velocities (squeeze). Linearised:
//!
//! ```text
//! δq_k = Σ_j Y_kj δp_j + Σ_c (D_kc + s E_kc) δu_c
//! Y_kj = ∂q_k/∂p_j     nozzle admittance seen by the line (the film's resistance behind the hole included)
//! D_kc = ∂q_k/∂u_c     flow pushed through the nozzle by a displacement
//! E_kc = ∂q_k/∂u̇_c     by a velocity (squeeze); by the symmetry of the Reynolds operator E = Bᵀ, with
//! B_ck = ∂Q_c/∂p_k     the generalised film force per unit port pressure
//! ```
//!
//! The line's end condition therefore depends on the film: on eccentricity and speed, as the thesis
//! measured (its §6.2.2). This module holds the coefficients and evaluates the law; the film's influence
//! fields that give them are computed by [`crate::physics::reynolds::PadFilm::injection_response`] and
//! assembled over pads by [`crate::bearing::frf::injection`].

use nalgebra::{Complex, DMatrix, DVector};
use serde::{Deserialize, Serialize};

/// π d⁴/(128 µ l): flow per unit pressure drop of a capillary of diameter `d`, length `l` (Hagen–Poiseuille),
/// the admittance of a nozzle discharging into a film at uniform pressure [m³/(s·Pa)].
#[must_use]
pub fn capillary_conductance(diameter: f64, length: f64, viscosity: f64) -> f64 {
    std::f64::consts::PI * diameter.powi(4) / (128.0 * viscosity * length)
}

/// Linearised nozzle–film coupling: over a pad's local coordinates and its orifices
/// ([`crate::physics::reynolds::InjectionResponse`]), or over the bearing's global coordinates and the valve
/// ports ([`crate::bearing::frf::injection::injection_coupling`]).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct NozzleCoupling {
    /// Y [m³/(s·Pa)], ports × ports.
    pub admittance: DMatrix<f64>,
    /// D [m³/(s·m)] or per rad, ports × coordinates.
    pub displacement: DMatrix<f64>,
    /// E [m³/m] or per rad, ports × coordinates.
    pub velocity: DMatrix<f64>,
    /// B [N/Pa, N·m/Pa, …], coordinates × ports.
    pub force: DMatrix<f64>,
    /// Static flow of each port (orifice) into the film [m³/s].
    pub static_flow: Vec<f64>,
}

impl NozzleCoupling {
    /// Number of ports.
    #[must_use]
    pub fn ports(&self) -> usize {
        self.admittance.nrows()
    }

    /// The nozzle flows `δq = Y δp + (D + s E) δu` at `s`.
    #[must_use]
    pub fn flow(
        &self,
        s: Complex<f64>,
        dp: &DVector<Complex<f64>>,
        du: &DVector<Complex<f64>>,
    ) -> DVector<Complex<f64>> {
        let y = self.admittance.map(Complex::from);
        let m = DMatrix::from_fn(self.displacement.nrows(), self.displacement.ncols(), |i, j| {
            Complex::from(self.displacement[(i, j)]) + s * self.velocity[(i, j)]
        });
        y * dp + m * du
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn capillary_conductance_is_hagen_poiseuille() {
        // 6 mm × 10 mm nozzle, VG22 at 40 °C.
        let g = capillary_conductance(6e-3, 10e-3, 0.01892);
        let expected = std::f64::consts::PI * 1.296e-9 / (128.0 * 0.01892 * 0.01);
        assert!((g / expected - 1.0).abs() < 1e-14, "{g}");
    }
}
