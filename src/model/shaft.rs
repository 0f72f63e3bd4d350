//! A shaft element's section and material [SI], and the beam theory the rotor's elements use: the data a
//! rotor file resolves into ([`super::rotor::Rotor`]). The element matrices built on them are in
//! `rotor::element`.

/// Which beam theory the shaft elements use.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum BeamTheory {
    /// Shear deformation and rotary inertia (Nelson & McVaugh).
    #[default]
    Timoshenko,
    /// Neither shear deformation nor transverse rotary inertia.
    EulerBernoulli,
}

/// Section and material of one element [SI].
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct BeamSection {
    pub length_m: f64,
    pub outer_diameter_m: f64,
    pub inner_diameter_m: f64,
    pub density_kg_per_m3: f64,
    pub youngs_modulus_pa: f64,
    pub poisson_ratio: f64,
}

impl BeamSection {
    /// Cross-section area [m²].
    #[must_use]
    pub fn area(&self) -> f64 {
        std::f64::consts::PI / 4.0 * (self.outer_diameter_m.powi(2) - self.inner_diameter_m.powi(2))
    }

    /// Second moment of area about a diameter [m⁴].
    #[must_use]
    pub fn second_moment(&self) -> f64 {
        std::f64::consts::PI / 64.0 * (self.outer_diameter_m.powi(4) - self.inner_diameter_m.powi(4))
    }

    /// Mass [kg].
    #[must_use]
    pub fn mass(&self) -> f64 {
        self.density_kg_per_m3 * self.area() * self.length_m
    }
}
