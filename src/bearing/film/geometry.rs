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
//!        + η sin(θ − θp)                        pivot transverse displacement η, positive towards +θ
//! ```
//!
//! Each pad coordinate is a rigid motion of the pad (or an elastic mode); its shape follows from that
//! motion in [`crate::bearing::film::coordinates`].
//!
//! The generalised film force on coordinate q_k is `Q_k = ∫ p ∂h/∂q_k dA`; for the journal coordinates it
//! is the film force on the journal (x, y), for the tilt it is the film moment about the pivot
//! (counter-clockwise positive), for ξ the film force pushing the pad outwards along the pivot line.
//! A fixed sector has no pad coordinates (δ ≡ 0).

use crate::model::Pad;
use crate::physics::pad_modes::FilmField;
use crate::physics::reynolds::FilmShape;

use crate::bearing::film::coordinates::{PadDof, RigidMotion};

/// Thickness model of one pad: `h0` and the shapes `∂h/∂q` for q = (e_x, e_y, pad coordinates…).
#[derive(Debug, Clone, PartialEq)]
pub struct PadShape {
    pub pad_clearance: f64,
    pub assembled_clearance: f64,
    pub pivot: f64,
    /// Pad bore radius Rp = R + Cp.
    pub bore: f64,
    /// Distance from the pad's centre of curvature to the pivot, Rp + t.
    pub lever: f64,
    pub dofs: Vec<PadDof>,
    /// The rigid motion of each pad coordinate (`None`: an elastic mode, whose shape is sampled).
    motions: Vec<Option<RigidMotion>>,
    /// Film shapes of the elastic modes, `PadDof::Mode(i)` ↦ entry i (sampled at the film nodes).
    modes: Vec<FilmField>,
}

impl PadShape {
    #[must_use]
    pub fn new(pad: &Pad, journal_radius: f64, assembled_clearance: f64, dofs: &[PadDof]) -> Self {
        let bore = pad.bore_radius_m(journal_radius);
        let lever = bore + pad.thickness_m;
        Self {
            pad_clearance: pad.clearance_m,
            assembled_clearance,
            pivot: pad.pivot_rad,
            bore,
            lever,
            dofs: dofs.to_vec(),
            motions: dofs.iter().map(|d| d.rigid_motion(pad.pivot_rad, lever)).collect(),
            modes: Vec::new(),
        }
    }

    /// The film shapes of the pad's elastic modes (`PadDof::Mode(i)` takes entry i).
    #[must_use]
    pub fn with_modes(mut self, modes: Vec<FilmField>) -> Self {
        self.modes = modes;
        self
    }
}

impl FilmShape for PadShape {
    fn base(&self, theta: f64, _z: f64) -> f64 {
        self.pad_clearance - (self.pad_clearance - self.assembled_clearance) * (theta - self.pivot).cos()
    }
    fn n_dofs(&self) -> usize {
        2 + self.dofs.len()
    }
    fn dof(&self, k: usize, theta: f64, z: f64) -> f64 {
        match k {
            0 => -theta.cos(),
            1 => -theta.sin(),
            _ => match (self.motions[k - 2], self.dofs[k - 2]) {
                (Some(m), _) => m.film_shape(self.bore, theta),
                // Elastic modes: the sampled film-face radial displacement (pad flexibility).
                (None, PadDof::Mode(i)) => self.modes.get(usize::from(i)).map_or(0.0, |f| f.at(theta, z)),
                (None, _) => 0.0,
            },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bearing::film::coordinates::pad_dofs;
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
            pivot_transverse_stiffness_n_per_m: None,
            density_kg_per_m3: 7800.0,
            massless: false,
            pivot_contact: None,
            youngs_modulus_pa: 200e9,
            poisson_ratio: 0.3,
            orifices: vec![],
        }
    }

    #[test]
    fn tilt_towards_journal_at_trailing_edge_reduces_h_there() {
        let p = pad();
        let s = PadShape::new(&p, 0.05, 90e-6, &pad_dofs(&p));
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
}
