//! The names of the stages, in the order they run (a stage after every stage it reads). A stage's code is
//! in its own file and its registration in [`super::registry`]; this enum is what callers name them by
//! (a view's needs, [`super::Outcome::get`]).

use serde::{Deserialize, Serialize};

/// The stages, in the order they run.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub enum StageId {
    /// Meshes and films of every pad, the coordinate layout.
    Films,
    /// Isothermal equilibrium with the full linearisation.
    Equilibrium,
    /// The thermal (THD) loop: equilibrium and temperatures together.
    Thermal,
    /// Full stiffness, damping and inertia.
    Coefficients,
    /// Reduced coefficients at the case's ω/Ω: the solution shown.
    Reduction,
    /// Reduced coefficients over a range of ω/Ω.
    FrequencySweep,
    /// One solution per speed.
    SpeedSweep,
    /// The bearing linearised for its injection ports (the FRFs' operating point).
    Frf,
}

impl StageId {
    pub const ALL: &'static [StageId] = &[
        Self::Films,
        Self::Equilibrium,
        Self::Thermal,
        Self::Coefficients,
        Self::Reduction,
        Self::FrequencySweep,
        Self::SpeedSweep,
        Self::Frf,
    ];

    /// Position in [`Self::ALL`] (the slot of the stage).
    #[must_use]
    pub fn index(self) -> usize {
        self as usize
    }
}

#[cfg(test)]
mod tests {
    use super::StageId;

    #[test]
    fn all_lists_every_stage_at_its_index() {
        for (i, s) in StageId::ALL.iter().enumerate() {
            assert_eq!(s.index(), i);
        }
        assert_eq!(StageId::ALL.len(), StageId::Frf.index() + 1);
    }
}
