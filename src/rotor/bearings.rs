//! Bearing coefficients per speed for every bearing position: bearing cases solved at each speed (each
//! distinct case once per speed, warm-started from the nearest speed solved before, results cached by speed)
//! or coefficients given by numbers (interpolated in their speed table).
//!
//! The case's own operating point is kept except the speed, which is the rotor's spin speed. With
//! [`CoefficientModel::Reduced`] a case's full coefficients are reduced synchronously (at ω = Ω); with
//! [`CoefficientModel::Full`] they enter whole ([`super::coupling`]). Numbers are always 2×2.

use std::collections::BTreeMap;

use super::coupling::BearingCoefficients;
use super::error::RotorError;
use crate::bearing::film::model::BearingModel;
use crate::bearing::solution::assemble::solve_point;
use crate::bearing::solution::coefficients::FullCoefficients;
use crate::bearing::thermal::ThermalModel;
use crate::bearing::NoCancel;
use crate::model::rotor::{BearingSupport, CoefficientModel, CoefficientTable, Rotor};
use crate::model::Case;

/// One distinct bearing case and what was solved for it.
struct CaseEntry {
    name: String,
    case: Case,
    model: Option<BearingModel>,
    thermal: Option<ThermalModel>,
    /// Speed [rad/s] bits → (full coefficients, equilibrium coordinates).
    cache: BTreeMap<u64, (FullCoefficients, Vec<f64>)>,
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
                            model: None,
                            thermal: None,
                            cache: BTreeMap::new(),
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

    /// Full coefficients of distinct case `i` at `omega` [rad/s] (solved, or from the cache).
    fn full(&mut self, i: usize, omega: f64) -> Result<FullCoefficients, RotorError> {
        let e = &mut self.entries[i];
        if let Some((f, _)) = e.cache.get(&omega.to_bits()) {
            return Ok(f.clone());
        }
        let speed_rpm = omega * 30.0 / std::f64::consts::PI;
        let err = |source| RotorError::Bearing { bearing: e.name.clone(), speed_rpm, source };
        let mut case = e.case.clone();
        case.operating.speed_rad_s = omega;
        if e.model.is_none() {
            e.model = Some(BearingModel::new(&case).map_err(err)?);
        }
        let start = nearest(&e.cache, omega).map(|(_, x)| x.clone());
        let model = e.model.as_mut().ok_or_else(|| RotorError::Speeds("no bearing model".into()))?;
        let sol = solve_point(model, &mut e.thermal, &case, start.as_deref(), &NoCancel)
            .map_err(|source| RotorError::Bearing { bearing: e.name.clone(), speed_rpm, source })?;
        e.cache.insert(omega.to_bits(), (sol.full.clone(), sol.coordinates.clone()));
        self.solves += 1;
        Ok(sol.full)
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

fn nearest(cache: &BTreeMap<u64, (FullCoefficients, Vec<f64>)>, omega: f64) -> Option<&(FullCoefficients, Vec<f64>)> {
    cache
        .iter()
        .min_by(|a, b| (f64::from_bits(*a.0) - omega).abs().total_cmp(&(f64::from_bits(*b.0) - omega).abs()))
        .map(|(_, v)| v)
}
