//! Film-thickness geometry of a pad and its generalised coordinates.
//!
//! For pad k (pivot angle θp, machined clearance Cp, assembled clearance Cb, pad bore radius Rp = R + Cp,
//! thickness t), the film thickness is linear in the generalised coordinates:
//!
//! ```text
//! h(θ) = Cp − (Cp − Cb) cos(θ − θp)          preload: h = Cb at the pivot with the journal centred
//!        − e_x cos θ − e_y sin θ                journal displacement (φ_ex = −cos θ, φ_ey = −sin θ)
//!        − (Rp + t) δ sin(θ − θp)               tilt δ: counter-clockwise rotation of the pad about its
//!                                               pivot; δ > 0 moves the trailing edge towards the journal
//!        + ξ cos(θ − θp)                        pivot radial displacement ξ, positive away from the journal
//! ```
//!
//! The generalised film force on coordinate q_k is `Q_k = ∫ p ∂h/∂q_k dA`; for the journal coordinates it
//! is the film force on the journal (x, y), for the tilt it is the film moment about the pivot
//! (counter-clockwise positive), for ξ the film force pushing the pad outwards along the pivot line.
//! A fixed sector has no pad coordinates (δ ≡ 0).

use crate::model::{Pad, PadKind};
use crate::physics::reynolds::FilmShape;

/// A pad degree of freedom beyond the journal's two.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum PadDof {
    /// Rotation about the pivot [rad].
    Tilt,
    /// Radial translation of the pivot [m] (finite pivot stiffness).
    PivotRadial,
}

impl PadDof {
    /// Unit of the coordinate, for display.
    #[must_use]
    pub fn unit(self) -> &'static str {
        match self {
            Self::Tilt => "rad",
            Self::PivotRadial => "m",
        }
    }
}

/// The pad's degrees of freedom, in order.
#[must_use]
pub fn pad_dofs(pad: &Pad) -> Vec<PadDof> {
    let mut d = Vec::new();
    if pad.kind == PadKind::Tilting {
        d.push(PadDof::Tilt);
        if pad.pivot_stiffness_n_per_m.is_some() {
            d.push(PadDof::PivotRadial);
        }
    }
    d
}

/// Thickness model of one pad: `h0` and the shapes `∂h/∂q` for q = (e_x, e_y, pad dofs…).
#[derive(Debug, Clone, PartialEq)]
pub struct PadShape {
    pub pad_clearance: f64,
    pub assembled_clearance: f64,
    pub pivot: f64,
    /// Distance from the pad's centre of curvature to the pivot, Rp + t.
    pub lever: f64,
    pub dofs: Vec<PadDof>,
}

impl PadShape {
    #[must_use]
    pub fn new(pad: &Pad, journal_radius: f64, assembled_clearance: f64) -> Self {
        Self {
            pad_clearance: pad.clearance_m,
            assembled_clearance,
            pivot: pad.pivot_rad,
            lever: pad.bore_radius_m(journal_radius) + pad.thickness_m,
            dofs: pad_dofs(pad),
        }
    }
}

impl FilmShape for PadShape {
    fn base(&self, theta: f64, _z: f64) -> f64 {
        self.pad_clearance - (self.pad_clearance - self.assembled_clearance) * (theta - self.pivot).cos()
    }
    fn n_dofs(&self) -> usize {
        2 + self.dofs.len()
    }
    fn dof(&self, k: usize, theta: f64, _z: f64) -> f64 {
        match k {
            0 => -theta.cos(),
            1 => -theta.sin(),
            _ => match self.dofs[k - 2] {
                PadDof::Tilt => -self.lever * (theta - self.pivot).sin(),
                PadDof::PivotRadial => (theta - self.pivot).cos(),
            },
        }
    }
}

/// Rigid-body inertia of a pad (an annular sector of radii Rp, Rp + t, arc β, length L) in its own
/// coordinates (tilt about the pivot, pivot radial translation).
#[must_use]
pub fn pad_mass_matrix(pad: &Pad, journal_radius: f64, length: f64) -> Vec<Vec<f64>> {
    let dofs = pad_dofs(pad);
    let r1 = pad.bore_radius_m(journal_radius);
    let r2 = r1 + pad.thickness_m;
    let beta = pad.arc_rad;
    let rho = pad.density_kg_per_m3;
    let mass = 0.5 * rho * length * beta * (r2 * r2 - r1 * r1);
    // Polar moment about the centre of curvature O.
    let i_o = 0.25 * rho * length * beta * (r2.powi(4) - r1.powi(4));
    // Centroid distance from O, along the arc's mid-line.
    let r_cm = if mass > 0.0 { (2.0 / 3.0) * (r2.powi(3) - r1.powi(3)) / (r2 * r2 - r1 * r1) * (0.5 * beta).sin() / (0.5 * beta) } else { 0.0 };
    let theta_mid = pad.leading_edge_rad + 0.5 * beta;
    let lever = r2; // pivot on the back of the pad
    let i_p = i_o - 2.0 * mass * lever * r_cm * (theta_mid - pad.pivot_rad).cos() + mass * lever * lever;
    let m_tr = mass * r_cm * (pad.pivot_rad - theta_mid).sin();
    dofs.iter()
        .map(|a| {
            dofs.iter()
                .map(|b| match (a, b) {
                    (PadDof::Tilt, PadDof::Tilt) => i_p,
                    (PadDof::PivotRadial, PadDof::PivotRadial) => mass,
                    _ => m_tr,
                })
                .collect()
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::PadKind;

    fn pad() -> Pad {
        Pad {
            kind: PadKind::Tilting,
            leading_edge_rad: (90.0_f64 - 30.0).to_radians(),
            arc_rad: 60_f64.to_radians(),
            pivot_rad: 90_f64.to_radians(),
            offset: 0.5,
            clearance_m: 120e-6,
            preload: 0.25,
            thickness_m: 10e-3,
            pivot_stiffness_n_per_m: Some(1e8),
            density_kg_per_m3: 7800.0,
            youngs_modulus_pa: 200e9,
            poisson_ratio: 0.3,
            orifices: vec![],
        }
    }

    #[test]
    fn tilt_towards_journal_at_trailing_edge_reduces_h_there() {
        let p = pad();
        let s = PadShape::new(&p, 0.05, 90e-6);
        let te = p.trailing_edge_rad();
        let le = p.leading_edge_rad;
        // δ > 0: trailing edge closer, leading edge further.
        assert!(s.dof(2, te, 0.0) < 0.0);
        assert!(s.dof(2, le, 0.0) > 0.0);
        // h = Cb at the pivot with the journal centred; Cp − (Cp − Cb) cos(β/2) at the edges.
        assert!((s.base(p.pivot_rad, 0.0) - 90e-6).abs() < 1e-15);
        // A journal displacement towards the pad (here +y, pad on top) closes the film at the pivot.
        assert!((s.dof(1, p.pivot_rad, 0.0) + 1.0).abs() < 1e-15);
        // Pivot moving away opens the film.
        assert!(s.dof(3, p.pivot_rad, 0.0) > 0.0);
    }

    #[test]
    fn centred_pivot_pad_inertia_matches_closed_form() {
        let p = pad();
        let (r, l) = (0.05, 0.04);
        let m = pad_mass_matrix(&p, r, l);
        let (r1, r2) = (r + p.clearance_m, r + p.clearance_m + p.thickness_m);
        let mass = 0.5 * 7800.0 * l * p.arc_rad * (r2 * r2 - r1 * r1);
        assert!((m[1][1] - mass).abs() < 1e-12 * mass);
        // Centred pivot: no coupling between tilt and radial translation.
        assert!(m[0][1].abs() < 1e-12);
        // Parallel-axis sanity: I_P between the moment about the centroid and about O + m·lever².
        assert!(m[0][0] > 0.0 && m[0][0] < 0.25 * 7800.0 * l * p.arc_rad * (r2.powi(4) - r1.powi(4)) + mass * r2 * r2);
    }
}
