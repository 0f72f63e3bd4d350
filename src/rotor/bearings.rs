//! Bearing coefficients per speed for every bearing position: bearing cases asked of the stages at each
//! speed (each distinct case has its own [`Stages`], which builds its films once, warm-starts each speed from
//! the last one solved and keeps the outputs of the speeds it has solved), or coefficients given by numbers
//! (interpolated in their speed table).
//!
//! The case's own operating point is kept except the speed, which is the rotor's spin speed. With
//! [`CoefficientModel::Reduced`] a case's full coefficients are reduced synchronously (at ω = Ω); with
//! [`CoefficientModel::Full`] they enter whole ([`super::coupling`]). Numbers are always 2×2.

use super::coupling::BearingCoefficients;
use super::error::RotorError;
use crate::bearing::frf::model::FrfModel;
use crate::bearing::solution::coefficients::FullCoefficients;
use crate::bearing::{NoCancel, Request, StageId, Stages};
use crate::model::rotor::{BearingSupport, CoefficientModel, CoefficientTable, Rotor};
use crate::model::Case;

/// Outputs each bearing case's stages keep: enough for the speeds an onset bisection returns to.
const KEPT_SPEEDS: usize = 16;

/// One distinct bearing case and the stages that solve it.
struct CaseEntry {
    name: String,
    case: Case,
    stages: Stages,
}

enum Source {
    Case(usize),
    Numbers(CoefficientTable),
}

/// The bearings of a rotor, ready to give coefficients at any speed.
pub struct BearingSet {
    entries: Vec<CaseEntry>,
    sources: Vec<Source>,
    /// Node of each bearing position.
    pub nodes: Vec<usize>,
    pub model: CoefficientModel,
    /// Bearing solves done so far.
    pub solves: usize,
}

impl BearingSet {
    /// Collects the rotor's bearings (identical case names share one model and one solve per speed).
    #[must_use]
    pub fn new(rotor: &Rotor) -> Self {
        let mut entries: Vec<CaseEntry> = Vec::new();
        let mut sources = Vec::new();
        for b in &rotor.bearings {
            sources.push(match &b.support {
                BearingSupport::Numbers(t) => Source::Numbers(t.clone()),
                BearingSupport::Case { name, case } => {
                    let i = entries.iter().position(|e| e.name == *name).unwrap_or_else(|| {
                        entries.push(CaseEntry {
                            name: name.clone(),
                            case: (**case).clone(),
                            stages: Stages::keeping(KEPT_SPEEDS),
                        });
                        entries.len() - 1
                    });
                    Source::Case(i)
                }
            });
        }
        Self {
            entries,
            sources,
            nodes: rotor.bearings.iter().map(|b| b.node).collect(),
            model: rotor.coefficients,
            solves: 0,
        }
    }

    /// Full coefficients of distinct case `i` at `omega` [rad/s] (solved, or kept from before).
    fn full(&mut self, i: usize, omega: f64) -> Result<FullCoefficients, RotorError> {
        let e = &mut self.entries[i];
        let mut case = e.case.clone();
        case.operating.speed_rad_s = omega;
        let before = e.stages.runs(StageId::Coefficients);
        let solution = e.stages.coefficients(&Request::coefficients(case), &NoCancel).map_err(|error| {
            RotorError::Bearing { bearing: e.name.clone(), speed_rpm: crate::units::RPM.from_si(omega), error }
        })?;
        self.solves += e.stages.runs(StageId::Coefficients) - before;
        Ok(solution.full.clone())
    }

    /// Coefficients of every position at spin speed `omega` [rad/s].
    ///
    /// # Errors
    /// A bearing solve that fails.
    pub fn at(&mut self, omega: f64) -> Result<Vec<BearingCoefficients>, RotorError> {
        let mut out = Vec::with_capacity(self.sources.len());
        for s in 0..self.sources.len() {
            let c = match &self.sources[s] {
                Source::Numbers(t) => {
                    let (k, c) = t.at(omega);
                    BearingCoefficients::Reduced { k, c }
                }
                Source::Case(i) => {
                    let i = *i;
                    let full = BearingCoefficients::Full(self.full(i, omega)?);
                    match self.model {
                        CoefficientModel::Full => full,
                        CoefficientModel::Reduced => full.reduced(omega),
                    }
                }
            };
            out.push(c);
        }
        Ok(out)
    }

    /// The case at bearing position `p` linearised for its injection ports at `omega` (the FRF stage: the
    /// nozzle–film influence fields), if it is a case; its stages share the equilibrium with the coefficients.
    ///
    /// # Errors
    /// A bearing solve that fails, or a case without `[hydraulics]`.
    pub fn frf_at(&mut self, p: usize, omega: f64) -> Result<Option<std::sync::Arc<FrfModel>>, RotorError> {
        let Source::Case(i) = self.sources[p] else { return Ok(None) };
        let e = &mut self.entries[i];
        let mut case = e.case.clone();
        case.operating.speed_rad_s = omega;
        let model = e.stages.frf(&case, &NoCancel).map_err(|error| RotorError::Bearing {
            bearing: e.name.clone(),
            speed_rpm: crate::units::RPM.from_si(omega),
            error,
        })?;
        Ok(Some(model))
    }

    /// Full coefficients of the case at bearing position `p` at `omega`, if it is a case.
    ///
    /// # Errors
    /// A bearing solve that fails.
    pub fn full_at(&mut self, p: usize, omega: f64) -> Result<Option<FullCoefficients>, RotorError> {
        match self.sources[p] {
            Source::Case(i) => Ok(Some(self.full(i, omega)?)),
            Source::Numbers(_) => Ok(None),
        }
    }
}
