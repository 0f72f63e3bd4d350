//! The thermal loop's temperature update ([`ThdRun`]): the next proposed field from the current one and its
//! image — Anderson-extrapolated, safeguarded, clamped — and what the loop does when an equilibrium fails
//! with a proposed field (backtracking, the lightly loaded pads' mean viscosity, the cautious restart).

use crate::bearing::report::error::{Budget, Iteration, SolveError};
use crate::bearing::report::warning::Warning;
use crate::bearing::thermal::anderson::{flatten, unflatten, Anderson};
use crate::bearing::thermal::growth::GrowthField;
use crate::bearing::thermal::model::{
    ThdState, ThermalModel, ANDERSON_DEPTH, LIGHT_PAD_SHARE, MAX_BACKTRACKS, MIN_RELAXATION, PLAIN_RELAXATION,
    SAFEGUARD_AFTER, STALL_GAIN, STALL_WINDOW,
};
use crate::bearing::thermal::run::ThdRun;
use crate::model::Case;

/// How far below the coldest oil or surroundings a proposed film temperature may lie [K]: the
/// discretisation's own undershoot in converged states is far smaller (0.08 K below the supply temperature,
/// compressor bearing with 40 bar leading-edge injection, standard mesh; a proposal clamped at the supply
/// temperature itself left that loop at a change of 2.9e-3 for good).
const UNDERSHOOT_ALLOWANCE_K: f64 = 10.0;

impl ThdRun {
    /// The next proposed temperature field from the current one (flattened), its image `t_new` and their
    /// viscosity change (see [`ThdRun`]'s robustness notes).
    pub(super) fn propose(&mut self, case: &Case, current: &[f64], t_new: &[Vec<f64>], change: f64) -> Vec<Vec<f64>> {
        let it = self.report.outer_iterations;
        let safeguarded = self.restarted_from.is_some() || it > SAFEGUARD_AFTER;
        if safeguarded && !self.plain {
            if change < STALL_GAIN * self.best_change.0 {
                self.best_change = (change, it);
            } else if it - self.best_change.1 >= STALL_WINDOW {
                self.plain = true;
                self.anderson = Anderson::safeguarded(0, PLAIN_RELAXATION, MIN_RELAXATION);
                self.report.warnings.push(Warning::TemperatureUpdateStalled {
                    best_change: self.best_change.0,
                    best_iteration: self.best_change.1,
                    from_iteration: it,
                });
            }
        }
        let mut next = if safeguarded {
            self.anderson.step_safeguarded(current, &flatten(t_new), change)
        } else {
            self.anderson.step(current, &flatten(t_new))
        };
        // The fixed point is one of the images, so it lies within their range: an extrapolation beyond the
        // range of this image is cut back to it (unclamped, Fillon A at S = 0.1, 55°, proposed film
        // temperatures of −880 and 840 °C), and to no more than UNDERSHOOT_ALLOWANCE_K below the coldest oil
        // or surroundings there are (the film is heated by shear): an image of a film near touchdown can
        // undershoot (−219 °C, Fillon A at S = 0.1, 35°), and its viscosity would run away.
        let th = &case.thermal;
        let coldest = [th.inlet_temperature_c, th.journal_temperature_c]
            .into_iter()
            .flatten()
            .fold(case.operating.supply_temperature_c.min(th.ambient_temperature_c), f64::min);
        let floor = coldest - UNDERSHOOT_ALLOWANCE_K;
        let (lo, hi) =
            t_new.iter().flatten().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| (a.min(v), b.max(v)));
        let (lo, hi) = (lo.max(floor), hi.max(floor));
        for v in &mut next {
            *v = v.clamp(lo, hi);
        }
        unflatten(&next, t_new)
    }

    /// An equilibrium failed with the proposed field: the lightly loaded pads get their mean viscosity, or the
    /// step is halved back towards the last field that worked, or — a touchdown that backtracking could not
    /// leave — the loop restarts cautiously once ([`ThdRun::restart_cautiously`]); else the error stands.
    pub(super) fn failed_equilibrium(
        &mut self,
        thermal: &mut ThermalModel,
        e: SolveError,
    ) -> Result<Option<ThdState>, SolveError> {
        let Some(tt) = &self.t_try else { return Err(e) };
        let light: Vec<usize> =
            (0..self.uniform.len()).filter(|&k| !self.uniform[k] && self.shares[k] < LIGHT_PAD_SHARE).collect();
        if !light.is_empty() {
            for &k in &light {
                self.uniform[k] = true;
                self.report.warnings.push(Warning::MeanViscosityAfterFailure {
                    pad: k,
                    load_percent: 100.0 * self.shares[k],
                    error: Box::new(e.clone()),
                });
            }
            return Ok(None);
        }
        let max_iterations = self.params.max_iterations;
        if self.report.outer_iterations >= max_iterations {
            return Err(self.budget_exceeded(Budget::Iterations(max_iterations)));
        }
        if self.backtracks >= MAX_BACKTRACKS {
            // a touchdown, or an equilibrium that spent its work budget, met at fields the loop proposed
            let proposed_field = matches!(
                e,
                SolveError::Touchdown { .. } | SolveError::BudgetExceeded { what: Iteration::Equilibrium, .. }
            );
            if proposed_field && self.restarted_from.is_none() {
                self.restart_cautiously(thermal, &e);
                return Ok(None);
            }
            return Err(e);
        }
        self.backtracks += 1;
        let base = self.t_ok.as_ref().unwrap_or(&self.t_iso);
        self.t_try = Some(midway(base, tt));
        // TEHD: the growth the failed step installed goes halfway back too (else a step whose growth moved
        // the films into touchdown is retried with the same growth six times: the compressor bearing with
        // growth at S = 0.1, 65°, whose first growth alone is 56 µm of its 102 µm clearance).
        if let Some(next) = &self.growth_next {
            self.growth_next = Some(halfway(self.growth_ok.as_ref(), next));
        }
        self.anderson.reset();
        self.report.warnings.push(Warning::StepHalved { error: Box::new(e.clone()) });
        Ok(None)
    }

    /// The loop walked into a touchdown (or an equilibrium that spent its work budget) that backtracking
    /// could not leave: start again, once, from the isothermal field, safeguarded from the first step (the
    /// iteration budget goes on). The
    /// unsafeguarded extrapolation of the first [`SAFEGUARD_AFTER`] steps can overshoot into a film hotter
    /// than the converged one (Fillon A at S = 0.1, 35°: 265 °C and h_min 0.79 µm at the fifth step, where
    /// the converged state has 192 °C and 1.8 µm); a touchdown of the cautious loop is the answer; a cautious
    /// loop that spends the iteration budget answers with the budget (the first touchdown was met at an
    /// intermediate viscosity field, not at a state of the bearing).
    fn restart_cautiously(&mut self, thermal: &mut ThermalModel, e: &SolveError) {
        self.report.warnings.push(Warning::ThermalRestart {
            outer_iteration: self.report.outer_iterations,
            error: Box::new(e.clone()),
        });
        self.restarted_from = Some(e.clone());
        self.t_ok = None;
        self.t_try = None;
        self.backtracks = 0;
        self.anderson = Anderson::safeguarded(ANDERSON_DEPTH, self.params.relaxation, MIN_RELAXATION);
        self.best_change = (f64::INFINITY, 0);
        self.plain = false;
        self.last_change = f64::INFINITY;
        self.growth_next.clone_from(&self.growth_at_start);
        self.growth_ok.clone_from(&self.growth_at_start);
        self.u.clone_from(&self.u_start);
        for pt in &mut thermal.pads {
            pt.t_prev = None;
        }
    }
}

/// The field halfway from `from` to `to`, node by node (a backtracked step's temperatures and growth).
fn midway(from: &[Vec<f64>], to: &[Vec<f64>]) -> Vec<Vec<f64>> {
    from.iter().zip(to).map(|(a, b)| a.iter().zip(b).map(|(x, y)| x + 0.5 * (y - x)).collect()).collect()
}

/// The growth halfway from `ok` (the last field with an equilibrium; `None`: no growth yet) to `next` (the
/// one that had none); the housing's growth is given and the same in both.
fn halfway(ok: Option<&GrowthField>, next: &GrowthField) -> GrowthField {
    let none = GrowthField::default();
    let ok = ok.unwrap_or(&none);
    let same_shape =
        |a: &[Vec<f64>], b: &[Vec<f64>]| a.len() == b.len() && a.iter().zip(b).all(|(x, y)| x.len() == y.len());
    // the housing-only start has no pad growth yet: halfway from zero
    let zero = |b: &[Vec<f64>]| -> Vec<Vec<f64>> { b.iter().map(|v| vec![0.0; v.len()]).collect() };
    let from = |a: &[Vec<f64>], b: &[Vec<f64>]| if same_shape(a, b) { a.to_vec() } else { zero(b) };
    GrowthField {
        pad_film_m: midway(&from(&ok.pad_film_m, &next.pad_film_m), &next.pad_film_m),
        pad_nodal_m: midway(&from(&ok.pad_nodal_m, &next.pad_nodal_m), &next.pad_nodal_m),
        journal_m: ok.journal_m + 0.5 * (next.journal_m - ok.journal_m),
        housing_m: next.housing_m.clone(),
        housing_film_m: next.housing_film_m.clone(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn field(pad: f64, journal: f64) -> GrowthField {
        GrowthField {
            pad_film_m: vec![vec![pad; 3], vec![2.0 * pad; 2]],
            pad_nodal_m: vec![vec![pad; 6], vec![pad; 4]],
            journal_m: journal,
            housing_m: vec![1e-6, 2e-6],
            housing_film_m: vec![vec![1e-6; 3], vec![2e-6; 2]],
        }
    }

    #[test]
    fn a_backtracked_step_takes_the_growth_halfway_back() {
        let close = |a: &[Vec<f64>], b: &[Vec<f64>]| {
            a.len() == b.len()
                && a.iter()
                    .zip(b)
                    .all(|(x, y)| x.len() == y.len() && x.iter().zip(y).all(|(p, q)| (p - q).abs() < 1e-18))
        };
        let next = field(40e-6, 20e-6);
        let mid = halfway(Some(&field(10e-6, 4e-6)), &next);
        assert!(close(&mid.pad_film_m, &[vec![25e-6; 3], vec![50e-6; 2]]), "{:?}", mid.pad_film_m);
        assert!(close(&mid.pad_nodal_m, &[vec![25e-6; 6], vec![25e-6; 4]]), "{:?}", mid.pad_nodal_m);
        assert!((mid.journal_m - 12e-6).abs() < 1e-18);
        // the housing's growth is given: unchanged
        assert_eq!((mid.housing_m.clone(), mid.housing_film_m.clone()), (next.housing_m.clone(), next.housing_film_m));
        // from the housing-only start (no pad growth yet) or no growth at all: halfway from zero
        let mut housing_only = field(0.0, 0.0);
        housing_only.pad_nodal_m = vec![Vec::new(); 2];
        for ok in [Some(&housing_only), None] {
            let mid = halfway(ok, &field(40e-6, 20e-6));
            assert!(close(&mid.pad_nodal_m, &[vec![20e-6; 6], vec![20e-6; 4]]), "{:?}", mid.pad_nodal_m);
            assert!((mid.journal_m - 10e-6).abs() < 1e-18);
        }
    }
}
