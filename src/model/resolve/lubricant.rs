//! The `[lubricant]` table resolved: the viscosity law `µ(T) = µ1 exp(−η (T − T1))` from a second
//! viscosity point (`η = ln(µ1/µ2)/(T2 − T1)`, in [0, 1] /K) or from the coefficient itself, and the oil's
//! density, specific heat and conductivity.

use super::super::case::{Lubricant, ViscosityLaw};
use super::super::error::{CaseError, Range};
use super::super::file::CaseFile;
use super::{inconsistent, missing};

pub(super) fn resolve_lubricant(file: &CaseFile) -> Result<Lubricant, CaseError> {
    let l = &file.lubricant;
    let t_range = Range::closed(-60.0, 400.0);
    let mu1 = Range::positive(100.0).check("lubricant.viscosity_pa_s", l.viscosity_pa_s)?;
    let t1 = t_range.check("lubricant.viscosity_temperature_c", l.viscosity_temperature_c)?;
    let eta = match (l.viscosity2_pa_s, l.viscosity2_temperature_c, l.viscosity_coefficient_per_k) {
        (Some(_), Some(_), Some(_)) => {
            return Err(inconsistent(
                "lubricant.viscosity_coefficient_per_k",
                "give either a second viscosity point or the coefficient, not both",
            ))
        }
        (Some(mu2), Some(t2), None) => {
            let mu2 = Range::positive(100.0).check("lubricant.viscosity2_pa_s", mu2)?;
            let t2 = t_range.check("lubricant.viscosity2_temperature_c", t2)?;
            if (t2 - t1).abs() < 1.0 {
                return Err(inconsistent(
                    "lubricant.viscosity2_temperature_c",
                    "the two viscosity points need different temperatures",
                ));
            }
            let eta = (mu1 / mu2).ln() / (t2 - t1);
            if !(0.0..=1.0).contains(&eta) {
                return Err(inconsistent(
                    "lubricant.viscosity2_pa_s",
                    format!(
                        "the two points give η = {eta:.4} /K; viscosity must fall with temperature (η in [0, 1] /K)"
                    ),
                ));
            }
            eta
        }
        (None, None, Some(eta)) => Range::closed(0.0, 1.0).check("lubricant.viscosity_coefficient_per_k", eta)?,
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
        density_kg_per_m3: Range::positive(2e4).check("lubricant.density_kg_per_m3", l.density_kg_per_m3)?,
        specific_heat_j_per_kg_k: Range::positive(1e5)
            .check("lubricant.specific_heat_j_per_kg_k", l.specific_heat_j_per_kg_k)?,
        conductivity_w_per_m_k: Range::positive(1e3)
            .check("lubricant.conductivity_w_per_m_k", l.conductivity_w_per_m_k)?,
    })
}
