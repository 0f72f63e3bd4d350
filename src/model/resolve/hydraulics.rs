//! `[hydraulics]` validated against the bearing and converted to SI ([`super::super::hydraulics`] holds both
//! forms): ranges, defaults and units from the rows of the key table; each port feeds pads the bearing has,
//! no pad twice, and the valve's ports are named once.

use super::super::error::{CaseError, Inconsistency};
use super::super::hydraulics::{Hydraulics, HydraulicsFile, Port, Rig, Valve, ValvePort};
use crate::key;
use crate::model::schema::KeySpec;

/// Validates `[hydraulics]` against a bearing of `n_pads` pads and converts it to SI (ranges, defaults and
/// units from the rows of [`crate::model::schema`]).
///
/// # Errors
/// The first value out of range or inconsistent (a pad fed twice or missing, ports named twice), by key.
pub(super) fn resolve_hydraulics(h: &HydraulicsFile, n_pads: usize) -> Result<Hydraulics, CaseError> {
    let supply = key!("hydraulics.supply_pressure_bar").value(Some(h.supply_pressure_bar))?;
    let ret = key!("hydraulics.return_pressure_bar").value(h.return_pressure_bar)?;
    if ret >= supply {
        return Err(CaseError::inconsistent("hydraulics.return_pressure_bar", Inconsistency::ReturnNotBelowSupply));
    }
    let v = &h.valve;
    let valve = Valve {
        natural_frequency_rad_s: key!("hydraulics.valve.natural_frequency_hz").value(Some(v.natural_frequency_hz))?,
        damping_ratio: key!("hydraulics.valve.damping_ratio").value(Some(v.damping_ratio))?,
        rated_flow_m3_s: key!("hydraulics.valve.rated_flow_l_per_min").value(Some(v.rated_flow_l_per_min))?,
        rated_drop_pa: key!("hydraulics.valve.rated_drop_bar").value(Some(v.rated_drop_bar))?,
        full_scale_v: key!("hydraulics.valve.full_scale_v").value(v.full_scale_v)?,
        flow_pressure_coefficient: key!("hydraulics.valve.flow_pressure_coefficient_l_per_min_bar")
            .value(v.flow_pressure_coefficient_l_per_min_bar)?,
        leakage_m3_s: key!("hydraulics.valve.leakage_l_per_min").value(v.leakage_l_per_min)?,
    };
    if h.port.is_empty() || h.port.len() > 2 {
        return Err(CaseError::inconsistent("hydraulics.port", Inconsistency::PortCount { ports: h.port.len() }));
    }
    let mut fed = vec![false; n_pads];
    let mut ports = Vec::with_capacity(h.port.len());
    for (i, p) in h.port.iter().enumerate() {
        let key = |name: &str| format!("hydraulics.port[{i}].{name}");
        let conflict = |name: &str, reason| Err(CaseError::inconsistent(key(name), reason));
        if h.port[..i].iter().any(|q| q.valve_port == p.valve_port) {
            let port = if p.valve_port == ValvePort::A { 'A' } else { 'B' };
            return conflict("valve_port", Inconsistency::PortTwice { port });
        }
        if p.pads.is_empty() {
            return conflict("pads", Inconsistency::PortFeedsNoPad);
        }
        for &k in &p.pads {
            match fed.get_mut(k) {
                None => return conflict("pads", Inconsistency::NoSuchPad { pad: k, last: n_pads.saturating_sub(1) }),
                Some(true) => return conflict("pads", Inconsistency::PadFedTwice { pad: k }),
                Some(f) => *f = true,
            }
        }
        let number = |row: &KeySpec, given: Option<f64>| {
            row.value_at(&key(row.key.rsplit('.').next().unwrap_or(row.key)), given)
        };
        ports.push(Port {
            sign: if p.valve_port == ValvePort::A { 1.0 } else { -1.0 },
            pads: p.pads.clone(),
            line_length_m: number(key!("hydraulics.port[].line_length_mm"), Some(p.line_length_mm))?,
            line_diameter_m: number(key!("hydraulics.port[].line_diameter_mm"), Some(p.line_diameter_mm))?,
            oil_bulk_modulus_pa: number(key!("hydraulics.port[].bulk_modulus_gpa"), p.bulk_modulus_gpa)?,
            air_fraction: number(key!("hydraulics.port[].air_fraction"), p.air_fraction)?,
            wall_compliance_per_pa: number(
                key!("hydraulics.port[].wall_compliance_per_gpa"),
                p.wall_compliance_per_gpa,
            )?,
            modes: key!("hydraulics.port[].modes").count_at(&key("modes"), p.modes)?,
        });
    }
    let rig = match &h.rig {
        None => None,
        Some(r) => Some(Rig {
            mass_kg: key!("hydraulics.rig.mass_kg").value(Some(r.mass_kg))?,
            support_stiffness_n_per_m: key!("hydraulics.rig.support_stiffness_n_per_m")
                .value(Some(r.support_stiffness_n_per_m))?,
            support_damping_ns_per_m: key!("hydraulics.rig.support_damping_ns_per_m")
                .value(r.support_damping_ns_per_m)?,
        }),
    };
    Ok(Hydraulics { supply_pressure_pa: supply, return_pressure_pa: ret, valve, ports, rig })
}

#[cfg(test)]
mod tests {
    use crate::model::{load_case, CaseError};

    const RIG: &str = include_str!("../../../cases/test-rig-pub5.toml");

    #[test]
    fn the_rig_case_resolves_to_si() {
        let (_, case) = load_case(RIG, &[]).unwrap();
        let h = case.hydraulics.unwrap();
        assert_eq!(h.ports.len(), 2);
        assert_eq!((h.ports[0].sign, h.ports[1].sign), (1.0, -1.0));
        assert!((h.ports[0].line_length_m - 0.7).abs() < 1e-15);
        assert!((h.supply_pressure_pa - 40e5).abs() < 1e-9);
    }

    #[test]
    fn inconsistent_ports_are_refused_by_key() {
        let cases = [
            ("hydraulics.port.1.pads=[0]", "hydraulics.port[1].pads"),
            ("hydraulics.port.1.pads=[7]", "hydraulics.port[1].pads"),
            ("hydraulics.port.1.valve_port=\"A\"", "hydraulics.port[1].valve_port"),
            ("hydraulics.port.0.modes=0", "hydraulics.port[0].modes"),
            ("hydraulics.return_pressure_bar=50", "hydraulics.return_pressure_bar"),
        ];
        for (set, key) in cases {
            let e = load_case(RIG, &[set.to_string()]).unwrap_err();
            assert_eq!(e.key(), Some(key), "{set}: {e}");
            assert!(matches!(e, CaseError::Inconsistent { .. } | CaseError::OutOfRange { .. }), "{e}");
        }
    }
}
