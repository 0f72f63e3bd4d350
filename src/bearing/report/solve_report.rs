//! What a solve did ([`SolveReport`]): iterations, residuals, the method that converged, time and warnings.
//! Every equilibrium returns one; the thermal loop keeps its own ([`crate::bearing::ThermalReport`]) around the
//! equilibria it runs.

use serde::{Deserialize, Serialize};

use crate::bearing::report::warning::{Method, Warning};

/// What an equilibrium solve did.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct SolveReport {
    /// Outer (journal) Newton iterations, summed over methods and continuation steps (and for a THD
    /// solve over every equilibrium of the thermal loop: counts and `seconds` are the whole solve's).
    pub iterations: usize,
    /// Pad (inner) iterations.
    pub inner_iterations: usize,
    pub film_solves: usize,
    pub factorizations: usize,
    /// Of `factorizations`: those of the mass-conserving film that the factorisation without row exchanges
    /// refused (or solved inaccurately) and the pivoting sparse LU did again.
    #[serde(default)]
    pub pivoted_factorizations: usize,
    /// Final journal force residual |ΣF + W| relative to the force scale.
    pub residual: f64,
    /// Largest final pad residual relative to the pad's scale (floating pads excluded).
    pub pad_residual: f64,
    /// Residual after each outer iteration (THD: of the converged state's equilibrium).
    pub residual_history: Vec<f64>,
    /// The method that found the equilibrium.
    pub method: Method,
    /// Parts the solve was split into across frames (0: run in one go; the web build's frame budget).
    #[serde(default, skip_serializing_if = "is_zero")]
    pub resumed_parts: usize,
    /// Load iterations of the Hertz pivots around the equilibrium (`None` without pivot contacts).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pivot_load_iterations: Option<usize>,
    pub seconds: f64,
    /// Pads that float (no film pressure): their film contributes no stiffness or damping.
    pub floating_pads: Vec<usize>,
    pub warnings: Vec<Warning>,
}

#[allow(clippy::trivially_copy_pass_by_ref)]
fn is_zero(n: &usize) -> bool {
    *n == 0
}

impl SolveReport {
    /// How the equilibrium was found, in words (method, parts, pivot load iterations).
    #[must_use]
    pub fn method_text(&self) -> String {
        let mut t = self.method.to_string();
        if self.resumed_parts > 0 {
            t += &format!(" (resumed {} times, one part per frame)", self.resumed_parts);
        }
        if let Some(n) = self.pivot_load_iterations {
            t += &format!("; Hertz pivots: {n} load iteration(s)");
        }
        t
    }

    /// Adds a warning once.
    pub fn warn(&mut self, w: Warning) {
        if !self.warnings.contains(&w) {
            self.warnings.push(w);
        }
    }

    /// Adds the counts and time of other work that belongs to the same result (the isothermal start of a
    /// THD solve); residuals, method and warnings stay this report's.
    pub fn add_work(&mut self, other: &SolveReport) {
        self.iterations += other.iterations;
        self.inner_iterations += other.inner_iterations;
        self.film_solves += other.film_solves;
        self.factorizations += other.factorizations;
        self.pivoted_factorizations += other.pivoted_factorizations;
        self.seconds += other.seconds;
    }

    /// Adds the work of an earlier part of the same solve (a suspended part): counts and time add up, its
    /// residual history comes first, warnings are merged. The final residuals and the method stay this
    /// part's.
    pub fn add_earlier(&mut self, earlier: SolveReport) {
        self.iterations += earlier.iterations;
        self.inner_iterations += earlier.inner_iterations;
        self.film_solves += earlier.film_solves;
        self.factorizations += earlier.factorizations;
        self.pivoted_factorizations += earlier.pivoted_factorizations;
        self.seconds += earlier.seconds;
        let mut history = earlier.residual_history;
        history.append(&mut self.residual_history);
        self.residual_history = history;
        for w in earlier.warnings {
            self.warn(w);
        }
    }
}
