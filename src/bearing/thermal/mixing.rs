//! The grooves between pads and the journal: the conditions that couple the pads' thermal problems.
//!
//! ## Inlet mixing (docs/MODEL.md §3)
//! In the groove ahead of pad k, the oil arriving hot is the previous pad's trailing-edge outflow `Q_te`
//! (at its flow-weighted temperature) plus any back-flow out of pad k's own leading edge. A fraction λ of it
//! (capped at the leading-edge inflow `Q_in`) enters pad k; fresh oil at the supply temperature makes up the
//! rest: `Q_in T_in = carried T_hot + (Q_in − carried) T_supply`, `carried = min(λ Q_hot, Q_in)`.
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

use crate::model::{Case, PadFilmBc};

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
        let carried = (t.carry_over * q_hot).min(s.q_in);
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
