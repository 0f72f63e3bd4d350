//! Generalised coordinates of the bearing: what each pad's coordinates are, and where every coordinate
//! lives in the global vector.
//!
//! ## Coordinates
//! The global vector is `u = [e_x, e_y, pad 0 coordinates…, pad 1 coordinates…, …]`. A pad may carry any
//! list of coordinates ([`PadDof`]); each has
//! - a film shape `φ(θ, z) = ∂h/∂q` (the film thickness is linear in the coordinates, see
//!   [`crate::bearing::film::geometry`]),
//! - a structural stiffness and an inertia ([`PadStructure`]),
//! - a unit and a residual scale for the equilibrium.
//!
//! The rigid coordinates are rigid motions of the pad body (section below); their film shapes and their
//! inertia both follow from that motion, so a new rigid coordinate is one arm of [`PadDof::rigid_motion`]
//! plus its stiffness in [`PadDof::stiffness`]. Elastic modes ([`PadDof::Mode`]) carry sampled shapes and
//! modal mass and stiffness from the pad's finite-element model.
//!
//! ## Rigid motions (pad frame, bearing centre O at the origin, pivot point P = (Rp + t) e_p)
//! ```text
//! Tilt δ            rotation about P, counter-clockwise      Δh = −(Rp + t) sin(θ − θp) δ
//! PivotRadial ξ     translation along e_p = (cos θp, sin θp)  Δh = cos(θ − θp) ξ
//! PivotTransverse η translation along e_t = (−sin θp, cos θp) Δh = sin(θ − θp) η
//! ```
//! (`Δh` = outward normal displacement of the pad's bore surface at angle θ; positive opens the film.)
//! Inertia of rigid motions with velocity fields `v_a(r)`: `M_ab = ∫ ρ v_a·v_b dV`, i.e. `m d_a·d_b` for two
//! translations, `m d·(ẑ × (r_G − P))` for a translation and the rotation, `I_P` for the rotation.
//!
//! ## The map
//! [`DofMap`] is the one place that knows the layout: slices, local↔global index maps, gather and
//! scatter. Nothing else computes `2 + d` or a pad offset by hand.

use std::ops::Range;

use nalgebra::DMatrix;
use serde::{Deserialize, Serialize};

use crate::model::{Pad, PadKind};

/// A pad coordinate kind.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum PadDof {
    /// Rotation about the pivot [rad] (counter-clockwise; > 0 closes the trailing edge).
    Tilt,
    /// Translation of the pivot along the pivot line [m], positive away from the journal.
    PivotRadial,
    /// Translation of the pivot across the pivot line [m], positive towards +θ.
    PivotTransverse,
    /// Elastic mode `i` of the pad (pseudo-modal coordinate, unit modal amplitude [m]).
    Mode(u8),
}

/// A rigid motion of the pad body, per unit coordinate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum RigidMotion {
    /// Counter-clockwise rotation about a point (bearing frame) [m].
    Rotation { about: [f64; 2] },
    /// Translation along a unit direction.
    Translation { direction: [f64; 2] },
}

impl RigidMotion {
    /// Velocity of the material point at `r` for a unit rate.
    #[must_use]
    pub fn velocity(&self, r: [f64; 2]) -> [f64; 2] {
        match *self {
            Self::Rotation { about } => [-(r[1] - about[1]), r[0] - about[0]],
            Self::Translation { direction } => direction,
        }
    }

    /// Outward normal displacement of the bore surface at angle θ (radius `bore`, centred at the origin):
    /// the film-thickness shape `∂h/∂q`.
    #[must_use]
    pub fn film_shape(&self, bore: f64, theta: f64) -> f64 {
        let n = [theta.cos(), theta.sin()];
        let v = self.velocity([bore * n[0], bore * n[1]]);
        n[0] * v[0] + n[1] * v[1]
    }
}

impl PadDof {
    /// The rigid motion of a rigid coordinate (`None` for elastic modes).
    #[must_use]
    pub fn rigid_motion(self, pivot_rad: f64, lever: f64) -> Option<RigidMotion> {
        let (c, s) = (pivot_rad.cos(), pivot_rad.sin());
        match self {
            Self::Tilt => Some(RigidMotion::Rotation { about: [lever * c, lever * s] }),
            Self::PivotRadial => Some(RigidMotion::Translation { direction: [c, s] }),
            Self::PivotTransverse => Some(RigidMotion::Translation { direction: [-s, c] }),
            Self::Mode(_) => None,
        }
    }

    /// Structural stiffness on this coordinate [N/m, N·m/rad] (frictionless pivot: none on the tilt; a Hertz
    /// pivot's load-dependent stiffness is set by [`crate::bearing::equilibrium::pivots`], 0 here).
    #[must_use]
    pub fn stiffness(self, pad: &Pad) -> f64 {
        match self {
            Self::Tilt | Self::Mode(_) => 0.0,
            Self::PivotRadial => pad.pivot_stiffness_n_per_m.unwrap_or(0.0),
            Self::PivotTransverse => pad.pivot_transverse_stiffness_n_per_m.unwrap_or(0.0),
        }
    }

    /// Unit of the coordinate, for display.
    #[must_use]
    pub fn unit(self) -> &'static str {
        match self {
            Self::Tilt => "rad",
            Self::PivotRadial | Self::PivotTransverse | Self::Mode(_) => "m",
        }
    }

    /// Short name, for labels and file headers.
    #[must_use]
    pub fn name(self) -> String {
        match self {
            Self::Tilt => "tilt".into(),
            Self::PivotRadial => "pivot_radial".into(),
            Self::PivotTransverse => "pivot_transverse".into(),
            Self::Mode(i) => format!("mode{i}"),
        }
    }

    /// The coordinate is a rotation (its generalised force is a moment, scaled by a lever in residuals).
    #[must_use]
    pub fn is_rotation(self) -> bool {
        matches!(self, Self::Tilt)
    }
}

/// The pad's coordinates, in order: tilt for a tilting pad, then each pivot translation that has a finite
/// stiffness. A fixed sector has none.
#[must_use]
pub fn pad_dofs(pad: &Pad) -> Vec<PadDof> {
    let mut d = Vec::new();
    if pad.kind == PadKind::Tilting {
        d.push(PadDof::Tilt);
        if pad.pivot_stiffness_n_per_m.is_some() || pad.pivot_contact.is_some() {
            d.push(PadDof::PivotRadial);
        }
        if pad.pivot_transverse_stiffness_n_per_m.is_some() {
            d.push(PadDof::PivotTransverse);
        }
    }
    d
}

/// Structural stiffness and inertia of one pad over its coordinates.
#[derive(Debug, Clone, PartialEq)]
pub struct PadStructure {
    pub dofs: Vec<PadDof>,
    /// Structural stiffness `K_s` (pivot springs, modal stiffness).
    pub stiffness: DMatrix<f64>,
    /// Inertia `M_s` [kg, kg·m, kg·m²].
    pub mass: DMatrix<f64>,
}

/// Mass properties of a rigid pad: an annular sector of radii Rp, Rp + t, arc β, length L.
#[derive(Debug, Clone, Copy, PartialEq)]
struct SectorInertia {
    mass: f64,
    /// Centroid (bearing frame) [m].
    centroid: [f64; 2],
    /// Polar moment about the centre of curvature O [kg·m²].
    polar_o: f64,
}

impl SectorInertia {
    fn new(pad: &Pad, journal_radius: f64, length: f64) -> Self {
        let r1 = pad.bore_radius_m(journal_radius);
        let r2 = r1 + pad.thickness_m;
        let beta = pad.arc_rad;
        let rho = if pad.massless { 0.0 } else { pad.density_kg_per_m3 };
        let mass = 0.5 * rho * length * beta * (r2 * r2 - r1 * r1);
        let polar_o = 0.25 * rho * length * beta * (r2.powi(4) - r1.powi(4));
        let r_cm = (2.0 / 3.0) * (r2.powi(3) - r1.powi(3)) / (r2 * r2 - r1 * r1) * (0.5 * beta).sin() / (0.5 * beta);
        let theta_mid = pad.leading_edge_rad + 0.5 * beta;
        Self { mass, centroid: [r_cm * theta_mid.cos(), r_cm * theta_mid.sin()], polar_o }
    }

    /// `∫ ρ v_a·v_b dV` for two rigid motions.
    fn inner(&self, a: RigidMotion, b: RigidMotion) -> f64 {
        let cross = |p: [f64; 2]| [-(self.centroid[1] - p[1]), self.centroid[0] - p[0]];
        let dot = |x: [f64; 2], y: [f64; 2]| x[0] * y[0] + x[1] * y[1];
        match (a, b) {
            (RigidMotion::Translation { direction: d1 }, RigidMotion::Translation { direction: d2 }) => {
                self.mass * dot(d1, d2)
            }
            (RigidMotion::Translation { direction }, RigidMotion::Rotation { about })
            | (RigidMotion::Rotation { about }, RigidMotion::Translation { direction }) => {
                self.mass * dot(direction, cross(about))
            }
            (RigidMotion::Rotation { about: p }, RigidMotion::Rotation { about: q }) => {
                // ∫ρ (r − p)·(r − q) dV = I_O − m r_G·(p + q) + m p·q
                self.polar_o - self.mass * dot(self.centroid, [p[0] + q[0], p[1] + q[1]]) + self.mass * dot(p, q)
            }
        }
    }
}

/// What the structure needs of one elastic mode (from the pad's finite-element model).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ModalProperties {
    /// Modal mass [kg] and stiffness [N/m] (whole pad).
    pub mass: f64,
    pub stiffness: f64,
    /// `∫ ρ v dV` along the pivot line e_p and across it e_t [kg]: the mass coupling with the pivot's
    /// translations (the modes are M-orthogonal to the tilt).
    pub momentum_pt: [f64; 2],
}

impl PadStructure {
    /// Appends elastic modes `Mode(0..)`: modal mass and stiffness on the diagonal, mass coupling with the
    /// pivot translations.
    #[must_use]
    pub fn with_modes(self, modes: &[ModalProperties]) -> Self {
        let n0 = self.dofs.len();
        let n = n0 + modes.len();
        let mut dofs = self.dofs;
        dofs.extend((0..modes.len()).map(|i| PadDof::Mode(u8::try_from(i).unwrap_or(u8::MAX))));
        let mut mass = DMatrix::zeros(n, n);
        let mut stiffness = DMatrix::zeros(n, n);
        mass.view_mut((0, 0), (n0, n0)).copy_from(&self.mass);
        stiffness.view_mut((0, 0), (n0, n0)).copy_from(&self.stiffness);
        for (i, m) in modes.iter().enumerate() {
            let d = n0 + i;
            mass[(d, d)] = m.mass;
            stiffness[(d, d)] = m.stiffness;
            for (a, dof) in dofs[..n0].iter().enumerate() {
                let coupling = match dof {
                    PadDof::PivotRadial => m.momentum_pt[0],
                    PadDof::PivotTransverse => m.momentum_pt[1],
                    PadDof::Tilt | PadDof::Mode(_) => 0.0,
                };
                mass[(a, d)] = coupling;
                mass[(d, a)] = coupling;
            }
        }
        Self { dofs, stiffness, mass }
    }

    /// Rigid-pad structure of a case pad (pivot springs; rigid-body inertia about the pivot).
    #[must_use]
    pub fn rigid(pad: &Pad, journal_radius: f64, length: f64) -> Self {
        let dofs = pad_dofs(pad);
        let n = dofs.len();
        let lever = pad.bore_radius_m(journal_radius) + pad.thickness_m;
        let sector = SectorInertia::new(pad, journal_radius, length);
        let motions: Vec<Option<RigidMotion>> = dofs.iter().map(|d| d.rigid_motion(pad.pivot_rad, lever)).collect();
        let mass = DMatrix::from_fn(n, n, |i, j| match (motions[i], motions[j]) {
            (Some(a), Some(b)) => sector.inner(a, b),
            _ => 0.0,
        });
        let stiffness = DMatrix::from_fn(n, n, |i, j| if i == j { dofs[i].stiffness(pad) } else { 0.0 });
        Self { dofs, stiffness, mass }
    }
}

/// A journal axis.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Axis {
    X,
    Y,
}

/// One coordinate of the bearing. In JSON: `{"journal": "x"}`, `{"pad": 3, "dof": "tilt"}`,
/// `{"pad": 3, "dof": {"mode": 1}}`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(untagged)]
pub enum Coord {
    /// Journal centre displacement [m].
    Journal { journal: Axis },
    /// A pad coordinate.
    Pad { pad: usize, dof: PadDof },
}

impl Coord {
    pub const X: Self = Self::Journal { journal: Axis::X };
    pub const Y: Self = Self::Journal { journal: Axis::Y };

    /// Unit of the coordinate, for display.
    #[must_use]
    pub fn unit(self) -> &'static str {
        match self {
            Self::Journal { .. } => "m",
            Self::Pad { dof, .. } => dof.unit(),
        }
    }

    /// Label for tables and file headers: `x`, `y`, `pad 3 tilt`.
    #[must_use]
    pub fn label(self) -> String {
        match self {
            Self::Journal { journal: Axis::X } => "x".into(),
            Self::Journal { journal: Axis::Y } => "y".into(),
            Self::Pad { pad, dof } => format!("pad {pad} {}", dof.name()),
        }
    }
}

impl std::fmt::Display for Coord {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.label())
    }
}

/// Number of journal coordinates at the head of the global vector (and of every pad's local vector).
pub const JOURNAL_DOFS: usize = 2;

/// The layout of the global coordinate vector.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct DofMap {
    pads: Vec<Vec<PadDof>>,
    offsets: Vec<usize>,
    n: usize,
}

impl DofMap {
    /// The layout for pads with these coordinates.
    #[must_use]
    pub fn new(pads: Vec<Vec<PadDof>>) -> Self {
        let mut offsets = Vec::with_capacity(pads.len());
        let mut n = JOURNAL_DOFS;
        for p in &pads {
            offsets.push(n);
            n += p.len();
        }
        Self { pads, offsets, n }
    }

    /// Length of the global vector.
    #[must_use]
    pub fn len(&self) -> usize {
        self.n
    }

    /// Never true (the journal's coordinates are always there); for clippy's `len_without_is_empty`.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.n == 0
    }

    #[must_use]
    pub fn n_pads(&self) -> usize {
        self.pads.len()
    }

    /// Coordinates of pad k.
    #[must_use]
    pub fn pad_dofs(&self, k: usize) -> &[PadDof] {
        &self.pads[k]
    }

    /// Where pad k's coordinates are in the global vector.
    #[must_use]
    pub fn pad_slice(&self, k: usize) -> Range<usize> {
        self.offsets[k]..self.offsets[k] + self.pads[k].len()
    }

    /// Global index of a coordinate.
    #[must_use]
    pub fn index(&self, c: Coord) -> Option<usize> {
        match c {
            Coord::Journal { journal: Axis::X } => Some(0),
            Coord::Journal { journal: Axis::Y } => Some(1),
            Coord::Pad { pad, dof } => {
                let d = self.pads.get(pad)?.iter().position(|x| *x == dof)?;
                Some(self.offsets[pad] + d)
            }
        }
    }

    /// Every coordinate, in global order.
    #[must_use]
    pub fn coords(&self) -> Vec<Coord> {
        let mut v = vec![Coord::X, Coord::Y];
        for (pad, dofs) in self.pads.iter().enumerate() {
            v.extend(dofs.iter().map(|&dof| Coord::Pad { pad, dof }));
        }
        v
    }

    /// Global index of each entry of pad k's local vector `[e_x, e_y, pad coordinates…]`.
    #[must_use]
    pub fn local_to_global(&self, k: usize) -> Vec<usize> {
        (0..JOURNAL_DOFS).chain(self.pad_slice(k)).collect()
    }

    /// Pad k's local vector `[e_x, e_y, pad coordinates…]` from the global vector.
    #[must_use]
    pub fn gather(&self, k: usize, u: &[f64]) -> Vec<f64> {
        self.local_to_global(k).into_iter().map(|i| u[i]).collect()
    }

    /// The journal part of a global vector.
    #[must_use]
    pub fn journal(u: &[f64]) -> [f64; 2] {
        [u[0], u[1]]
    }

    /// Adds a pad's local matrix (over `[e_x, e_y, pad coordinates…]`) into the global one.
    pub fn scatter_add(&self, k: usize, local: &DMatrix<f64>, global: &mut DMatrix<f64>) {
        let idx = self.local_to_global(k);
        debug_assert_eq!(local.nrows(), idx.len());
        for (a, &ga) in idx.iter().enumerate() {
            for (b, &gb) in idx.iter().enumerate() {
                global[(ga, gb)] += local[(a, b)];
            }
        }
    }

    /// Adds a pad's own block (over its coordinates only) into the global matrix.
    pub fn scatter_add_pad_block(&self, k: usize, block: &DMatrix<f64>, global: &mut DMatrix<f64>) {
        let r = self.pad_slice(k);
        for (a, ga) in r.clone().enumerate() {
            for (b, gb) in r.clone().enumerate() {
                global[(ga, gb)] += block[(a, b)];
            }
        }
    }

    /// A global vector with the journal at `journal` and each pad's coordinates from `pads`.
    #[must_use]
    pub fn assemble(&self, journal: [f64; 2], pads: &[&[f64]]) -> Vec<f64> {
        let mut u = vec![0.0; self.n];
        u[..JOURNAL_DOFS].copy_from_slice(&journal);
        for (k, q) in pads.iter().enumerate() {
            u[self.pad_slice(k)].copy_from_slice(q);
        }
        u
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
            pivot_transverse_stiffness_n_per_m: Some(5e8),
            density_kg_per_m3: 7800.0,
            massless: false,
            pivot_contact: None,
            youngs_modulus_pa: 200e9,
            poisson_ratio: 0.3,
            orifices: vec![],
        }
    }

    #[test]
    fn rigid_motions_give_the_documented_film_shapes() {
        let p = pad();
        let lever = 0.05 + p.clearance_m + p.thickness_m;
        let bore = 0.05 + p.clearance_m;
        for theta in [1.1_f64, 1.5, 1.9] {
            let s = theta - p.pivot_rad;
            let tilt = PadDof::Tilt.rigid_motion(p.pivot_rad, lever).unwrap().film_shape(bore, theta);
            assert!((tilt + lever * s.sin()).abs() < 1e-15, "{tilt}");
            let rad = PadDof::PivotRadial.rigid_motion(p.pivot_rad, lever).unwrap().film_shape(bore, theta);
            assert!((rad - s.cos()).abs() < 1e-15);
            let tr = PadDof::PivotTransverse.rigid_motion(p.pivot_rad, lever).unwrap().film_shape(bore, theta);
            assert!((tr - s.sin()).abs() < 1e-15);
        }
    }

    #[test]
    fn centred_pivot_inertia_matches_the_closed_form() {
        let p = pad();
        let (r, l) = (0.05, 0.04);
        let s = PadStructure::rigid(&p, r, l);
        assert_eq!(s.dofs, vec![PadDof::Tilt, PadDof::PivotRadial, PadDof::PivotTransverse]);
        let (r1, r2) = (r + p.clearance_m, r + p.clearance_m + p.thickness_m);
        let mass = 0.5 * 7800.0 * l * p.arc_rad * (r2 * r2 - r1 * r1);
        assert!((s.mass[(1, 1)] - mass).abs() < 1e-12 * mass);
        assert!((s.mass[(2, 2)] - mass).abs() < 1e-12 * mass);
        // Centred pivot: the centroid lies on the pivot line, so tilt and radial translation decouple …
        assert!(s.mass[(0, 1)].abs() < 1e-12 * mass);
        // … while a transverse translation couples with the tilt through the lever to the centroid:
        // m d_t·(ẑ × (r_G − P)) = −m (|P| − r_G).
        let r_g =
            (2.0 / 3.0) * (r2.powi(3) - r1.powi(3)) / (r2 * r2 - r1 * r1) * (0.5 * p.arc_rad).sin() / (0.5 * p.arc_rad);
        assert!((s.mass[(0, 2)] + mass * (r2 - r_g)).abs() < 1e-12 * mass * r2, "{}", s.mass[(0, 2)]);
        // I_P = I_O − 2 m r_G |P| + m |P|² (parallel axes through O and P on the same line).
        let i_o = 0.25 * 7800.0 * l * p.arc_rad * (r2.powi(4) - r1.powi(4));
        let i_p = i_o - 2.0 * mass * r2 * r_g + mass * r2 * r2;
        assert!((s.mass[(0, 0)] - i_p).abs() < 1e-12 * i_p);
        assert!(s.mass.clone().symmetric_eigenvalues().iter().all(|&v| v > 0.0), "positive definite");
        assert_eq!((s.stiffness[(0, 0)], s.stiffness[(1, 1)], s.stiffness[(2, 2)]), (0.0, 1e8, 5e8));
    }

    #[test]
    fn the_map_places_every_coordinate_once() {
        let m = DofMap::new(vec![vec![PadDof::Tilt], vec![], vec![PadDof::Tilt, PadDof::PivotRadial]]);
        assert_eq!(m.len(), 5);
        assert_eq!(m.pad_slice(2), 3..5);
        assert_eq!(m.index(Coord::Pad { pad: 2, dof: PadDof::PivotRadial }), Some(4));
        assert_eq!(m.index(Coord::Pad { pad: 1, dof: PadDof::Tilt }), None);
        let coords = m.coords();
        for (i, c) in coords.iter().enumerate() {
            assert_eq!(m.index(*c), Some(i));
        }
        assert_eq!(m.local_to_global(2), vec![0, 1, 3, 4]);
        let u = m.assemble([1.0, 2.0], &[&[3.0], &[], &[4.0, 5.0]]);
        assert_eq!(u, vec![1.0, 2.0, 3.0, 4.0, 5.0]);
        assert_eq!(m.gather(2, &u), vec![1.0, 2.0, 4.0, 5.0]);
        let mut g = DMatrix::zeros(5, 5);
        m.scatter_add(2, &DMatrix::from_element(4, 4, 1.0), &mut g);
        assert_eq!(g[(0, 4)], 1.0);
        assert_eq!(g[(2, 2)], 0.0);
        // Typed ids serialise as data, not as names to parse.
        let json = serde_json::to_string(&coords[4]).unwrap();
        assert_eq!(json, r#"{"pad":2,"dof":"pivot_radial"}"#);
        assert_eq!(serde_json::to_string(&coords[0]).unwrap(), r#"{"journal":"x"}"#);
        let mode = Coord::Pad { pad: 1, dof: PadDof::Mode(2) };
        assert_eq!(serde_json::from_str::<Coord>(&serde_json::to_string(&mode).unwrap()).unwrap(), mode);
    }
}
