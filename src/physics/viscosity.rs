//! Viscosity–temperature law `µ(T) = µ* exp(−η (T − T*))`, with `η = ln(µ1/µ2)/(T2 − T1)` from two catalogue
//! points. The law itself lives on [`crate::model::ViscosityLaw`] (it is case data); this module holds the
//! helpers the solver uses around it.

pub use crate::model::ViscosityLaw;

/// Temperature at which the law gives viscosity `mu` (inverse of [`ViscosityLaw::at`]); `None` if η = 0.
#[must_use]
pub fn temperature_for(law: &ViscosityLaw, mu: f64) -> Option<f64> {
    (law.eta_per_k > 0.0 && mu > 0.0).then(|| law.t_ref_c - (mu / law.mu_ref_pa_s).ln() / law.eta_per_k)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_point_law_passes_through_both_points() {
        // Compressor-bearing oil: 0.028 Pa·s at 40 °C, 0.007 Pa·s at 80 °C.
        let eta = (0.028_f64 / 0.007).ln() / 40.0;
        let law = ViscosityLaw { mu_ref_pa_s: 0.028, t_ref_c: 40.0, eta_per_k: eta };
        assert!((law.at(40.0) - 0.028).abs() < 1e-15);
        assert!((law.at(80.0) - 0.007).abs() < 1e-12);
        assert!((temperature_for(&law, 0.014).unwrap() - 60.0).abs() < 1e-9);
    }
}
