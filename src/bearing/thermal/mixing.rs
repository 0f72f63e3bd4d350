//! The grooves between pads and the journal: the conditions that couple the pads' thermal problems.
//!
//! ## Inlet mixing (docs/MODEL.md §3.4)
//! In the groove ahead of pad k, the oil arriving hot is the previous pad's trailing-edge outflow `Q_te`
//! (at its flow-weighted temperature) plus any back-flow out of pad k's own leading edge, `Q_hot`. A fraction
//! λ of it reaches pad k's leading edge (λ of the feeding kind, [`Feeding::carry_over`]). Of the leading-edge
//! inflow `Q_in`, `carried` is hot oil and the rest fresh oil at the supply temperature:
//!
//! ```text
//! Q_in T_in = carried T_hot + (Q_in − carried) T_supply
//! flooded housing, leading-edge groove (hot oil first):  carried = min(λ Q_hot, Q_in)
//! spray bar (full mixing with the sprayed flow Q_s):     carried = Q_in · λ Q_hot / (λ Q_hot + Q_s)
//! ```
//!
//! `Q_s` is the pad's share of the supply flow when one is given, else the film's own inflow.
//!
//! ## Offered flow of a starved pad
//! With a supply flow (mass-conserving cavitation), the oil offered at pad k's leading edge is its supply
//! share plus the carried hot oil, `Q_offer = Q_supply/n + λ Q_hot`: the film takes all of it when starved
//! (so the fresh oil it takes is exactly its share), or what a full inlet drags in. [`offered_inlets`] gives
//! these inlets from the last thermal solve; the THD loop iterates them with the temperatures.
//!
//! ## Journal temperature
//! Given, or: BC3 — zero net heat flux into the journal, `Σ ∫ q_j dA = 0`; BC1/BC2 (the film exchanges no
//! heat with the journal) — the film-fraction-weighted mean film temperature (the thesis' rule; it then
//! affects nothing but the report).
//!
//! Each pad's film temperature is affine in its inlet temperature and the journal temperature
//! ([`crate::bearing::thermal::pad_system::Affine`]), so all the balances together are one small dense linear system in
//! (T_in per pad, T_j), solved exactly.

use crate::bearing::report::error::SingularSystem;
use nalgebra::{DMatrix, DVector};

use crate::bearing::film::model::pad_inlets;
use crate::model::{Case, Feeding, PadFilmBc};
use crate::physics::reynolds::Inlet;

use crate::bearing::report::error::SolveError;
use crate::bearing::thermal::pad_system::PadTemperatures;

/// Solves the groove mixing balances and the journal condition for all inlet temperatures and the journal
/// temperature at once (module documentation). Returns (T_in per pad, T_j).
pub fn inlet_and_journal(
    case: &Case,
    sols: &[PadTemperatures],
    upstream: &[usize],
) -> Result<(Vec<f64>, f64), SolveError> {
    let n = sols.len();
    let t = &case.thermal;
    let ts = case.operating.supply_temperature_c;
    let supply = supply_shares(case);
    let mut a = DMatrix::<f64>::zeros(n + 1, n + 1);
    let mut b = DVector::<f64>::zeros(n + 1);
    for k in 0..n {
        let s = &sols[k];
        if let Some(ti) = t.inlet_temperature_c {
            a[(k, k)] = 1.0;
            b[k] = ti;
            continue;
        }
        if s.q_in <= 0.0 {
            a[(k, k)] = 1.0;
            b[k] = ts;
            continue;
        }
        let p = upstream[k];
        let q_hot = sols[p].q_te + s.q_back;
        let carried = carried_flow(t.feeding, q_hot, s.q_in, supply[k]);
        let alpha = if q_hot > 0.0 { carried / q_hot } else { 0.0 };
        // Q_in T_in − α (Q_te,p T_te,p + Q_back,k T_back,k) = (Q_in − carried) T_supply
        a[(k, k)] += s.q_in;
        let (te, bk) = (&sols[p].t_te, &s.t_back);
        a[(k, p)] -= alpha * sols[p].q_te * te.c_in;
        a[(k, n)] -= alpha * sols[p].q_te * te.c_j;
        a[(k, k)] -= alpha * s.q_back * bk.c_in;
        a[(k, n)] -= alpha * s.q_back * bk.c_j;
        b[k] = (s.q_in - carried) * ts + alpha * (sols[p].q_te * te.c0 + s.q_back * bk.c0);
    }
    let journal_flux_slope: f64 = sols.iter().map(|s| s.journal_flux.c_j).sum();
    if let Some(tj) = t.journal_temperature_c {
        a[(n, n)] = 1.0;
        b[n] = tj;
    } else if matches!(t.pad_film_bc, PadFilmBc::Bc3) && journal_flux_slope.abs() > 0.0 {
        // Σ_k J_k(T_in,k, T_j) = 0
        for (k, s) in sols.iter().enumerate() {
            a[(n, k)] += s.journal_flux.c_in;
            b[n] -= s.journal_flux.c0;
        }
        a[(n, n)] = journal_flux_slope;
    } else {
        // T_j − Σ A_k mean_k / Σ A_k = 0
        let total: f64 = sols.iter().map(|s| s.area).sum::<f64>().max(f64::MIN_POSITIVE);
        a[(n, n)] = 1.0;
        for (k, s) in sols.iter().enumerate() {
            let w = s.area / total;
            a[(n, k)] -= w * s.mean_film.c_in;
            a[(n, n)] -= w * s.mean_film.c_j;
            b[n] += w * s.mean_film.c0;
        }
    }
    let x = a
        .lu()
        .solve(&b)
        .filter(|x| x.iter().all(|v| v.is_finite()))
        .ok_or(SolveError::Singular(SingularSystem::InletMixing))?;
    Ok(((0..n).map(|k| x[k]).collect(), x[n]))
}

/// Each pad's share of the supply flow [m³/s], `None` for a flooded film.
fn supply_shares(case: &Case) -> Vec<Option<f64>> {
    pad_inlets(case)
        .into_iter()
        .map(|i| match i {
            Inlet::Flooded => None,
            Inlet::Supply { flow_m3_s } => Some(flow_m3_s),
        })
        .collect()
}

/// The hot oil among a pad's leading-edge inflow `q_in` [m³/s] (module documentation): `q_hot` leaves the pad
/// upstream (and the pad's own leading edge), `supply` is the pad's share of the supply flow, if given.
#[must_use]
pub fn carried_flow(feeding: Feeding, q_hot: f64, q_in: f64, supply: Option<f64>) -> f64 {
    let hot = feeding.carry_over() * q_hot.max(0.0);
    match feeding {
        Feeding::Flooded { .. } | Feeding::LeadingEdgeGroove { .. } => hot.min(q_in),
        Feeding::SprayBar { .. } => {
            let sprayed = supply.unwrap_or(q_in).max(0.0);
            if hot + sprayed > 0.0 {
                q_in * hot / (hot + sprayed)
            } else {
                0.0
            }
        }
    }
}

/// The inlets of the next films of a starved bearing (module documentation): each pad offered its supply
/// share plus the hot oil carried to its leading edge. `None` for a flooded film (no supply flow) or a given
/// inlet temperature (no mixing balance).
#[must_use]
pub fn offered_inlets(case: &Case, sols: &[PadTemperatures], upstream: &[usize]) -> Option<Vec<Inlet>> {
    if case.thermal.inlet_temperature_c.is_some() {
        return None;
    }
    let lambda = case.thermal.feeding.carry_over();
    let shares = supply_shares(case);
    (0..sols.len())
        .map(|k| {
            let q_hot = (sols[upstream[k]].q_te + sols[k].q_back).max(0.0);
            shares[k].map(|q| Inlet::Supply { flow_m3_s: q + lambda * q_hot })
        })
        .collect()
}

/// Largest relative change between two sets of inlets (0 when both are flooded).
#[must_use]
pub fn inlet_change(a: &[Inlet], b: &[Inlet]) -> f64 {
    a.iter().zip(b).fold(0.0_f64, |m, pair| match pair {
        (Inlet::Supply { flow_m3_s: x }, Inlet::Supply { flow_m3_s: y }) => {
            m.max((x - y).abs() / x.abs().max(y.abs()).max(f64::MIN_POSITIVE))
        }
        (Inlet::Flooded, Inlet::Flooded) => m,
        _ => f64::INFINITY,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    const Q_HOT: f64 = 2e-4;
    const Q_IN: f64 = 3e-4;

    #[test]
    fn flooded_and_groove_take_the_carried_hot_oil_first() {
        let flooded = Feeding::Flooded { carry_over: 0.8, churning_factor: 1.0 };
        assert!((carried_flow(flooded, Q_HOT, Q_IN, None) - 1.6e-4).abs() < 1e-18);
        // More hot oil than the film takes: the film is all hot oil.
        assert!((carried_flow(flooded, 1e-3, Q_IN, None) - Q_IN).abs() < 1e-18);
        let groove = Feeding::LeadingEdgeGroove { carry_over: 0.2 };
        assert!((carried_flow(groove, Q_HOT, Q_IN, None) - 4e-5).abs() < 1e-18);
    }

    #[test]
    fn a_spray_bar_mixes_the_carried_oil_with_the_sprayed_oil() {
        let spray = Feeding::SprayBar { carry_over: 0.8 };
        // Sprayed 1.6e-4 and carried 1.6e-4: half of the inflow is hot.
        assert!((carried_flow(spray, Q_HOT, Q_IN, Some(1.6e-4)) - 0.5 * Q_IN).abs() < 1e-18);
        // Without a supply flow the spray matches the film's intake: 1.6/(1.6 + 3) of it is hot.
        assert!((carried_flow(spray, Q_HOT, Q_IN, None) - Q_IN * 1.6 / 4.6).abs() < 1e-18);
    }

    #[test]
    fn inlet_change_is_relative_and_a_flooded_film_does_not_change() {
        let a = [Inlet::Supply { flow_m3_s: 1.0 }, Inlet::Supply { flow_m3_s: 2.0 }];
        let b = [Inlet::Supply { flow_m3_s: 1.0 }, Inlet::Supply { flow_m3_s: 2.2 }];
        assert!((inlet_change(&a, &b) - 0.2 / 2.2).abs() < 1e-15);
        assert!(inlet_change(&[Inlet::Flooded], &[Inlet::Flooded]) == 0.0);
    }
}
