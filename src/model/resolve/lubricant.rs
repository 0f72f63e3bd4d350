//! The `[lubricant]` table resolved: the viscosity law `µ(T) = µ1 exp(−η (T − T1))` from a second
//! viscosity point (`η = ln(µ1/µ2)/(T2 − T1)`, in [0, 1] /K) or from the coefficient itself, and the oil's
//! density, specific heat and conductivity.

use super::super::case::{Lubricant, ViscosityLaw};
use super::super::error::{CaseError, Inconsistency};
use super::super::file::CaseFile;
use super::{inconsistent, missing};
use crate::key;

pub(super) fn resolve_lubricant(file: &CaseFile) -> Result<Lubricant, CaseError> {
    let l = &file.lubricant;
    let mu1 = key!("lubricant.viscosity_pa_s").value(Some(l.viscosity_pa_s))?;
    let t1 = key!("lubricant.viscosity_temperature_c").value(Some(l.viscosity_temperature_c))?;
    let coefficient = key!("lubricant.viscosity_coefficient_per_k");
    let eta = match (l.viscosity2_pa_s, l.viscosity2_temperature_c, l.viscosity_coefficient_per_k) {
        (Some(_), Some(_), Some(_)) => {
            return Err(inconsistent(coefficient.key, Inconsistency::ViscosityPointAndCoefficient));
        }
        (Some(mu2), Some(t2), None) => {
            let mu2 = key!("lubricant.viscosity2_pa_s").value(Some(mu2))?;
            let t2 = key!("lubricant.viscosity2_temperature_c").value(Some(t2))?;
            if (t2 - t1).abs() < 1.0 {
                return Err(inconsistent(
                    "lubricant.viscosity2_temperature_c",
                    Inconsistency::ViscosityPointsAtOneTemperature,
                ));
            }
            let eta = (mu1 / mu2).ln() / (t2 - t1);
            if !coefficient.allowed.range().is_some_and(|r| r.contains(eta)) {
                return Err(inconsistent(
                    "lubricant.viscosity2_pa_s",
                    Inconsistency::ViscosityRises { eta_per_k: eta },
                ));
            }
            eta
        }
        (None, None, Some(eta)) => coefficient.value(Some(eta))?,
        (Some(_), None, _) => {
            return Err(missing("lubricant.viscosity2_temperature_c", "temperature of the second viscosity point"))
        }
        (None, Some(_), _) => return Err(missing("lubricant.viscosity2_pa_s", "viscosity of the second point")),
        (None, None, None) => {
            return Err(missing(
                "lubricant.viscosity2_pa_s",
                "second viscosity point (viscosity2_pa_s, viscosity2_temperature_c) or viscosity_coefficient_per_k",
            ))
        }
    };
    Ok(Lubricant {
        name: l.name.clone().unwrap_or_default(),
        viscosity: ViscosityLaw { mu_ref_pa_s: mu1, t_ref_c: t1, eta_per_k: eta },
        density_kg_per_m3: key!("lubricant.density_kg_per_m3").value(Some(l.density_kg_per_m3))?,
        specific_heat_j_per_kg_k: key!("lubricant.specific_heat_j_per_kg_k").value(Some(l.specific_heat_j_per_kg_k))?,
        conductivity_w_per_m_k: key!("lubricant.conductivity_w_per_m_k").value(Some(l.conductivity_w_per_m_k))?,
    })
}
