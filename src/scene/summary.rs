//! The results panel as rows of text in display units, with what each quantity means.
//!
//! Conversion to engineering units happens here, once, and every row says its unit. Quantities the
//! solution does not have (the maximum temperature of an isothermal solve) say so instead of showing a
//! number.

use crate::bearing::solution::Solution;
use crate::units::{L_PER_MIN, MPA, MPA_S, MRAD, MS, UM};

/// One labelled value.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    pub label: &'static str,
    pub value: String,
    /// The unit as shown: an SI unit with its engineering prefix (`kN`) or a unit chosen for reading (µm).
    pub unit: String,
    /// Physical meaning, for a tooltip.
    pub meaning: &'static str,
}

/// A titled group of rows.
#[derive(Debug, Clone, PartialEq)]
pub struct Group {
    pub title: &'static str,
    pub rows: Vec<Row>,
}

/// Per-pad results in display units.
#[derive(Debug, Clone, PartialEq)]
pub struct PadRow {
    pub index: usize,
    pub tilt_mrad: Option<f64>,
    pub h_min_um: f64,
    pub p_max_mpa: f64,
    pub load_n: f64,
    /// Net orifice flow into the film [l/min]; negative = oil leaves through the hole.
    pub orifice_flow_l_min: Option<f64>,
    pub cavitated_percent: f64,
    pub unloaded: bool,
}

/// Everything the results panel shows.
#[derive(Debug, Clone, PartialEq)]
pub struct Summary {
    pub groups: Vec<Group>,
    pub pads: Vec<PadRow>,
    pub warnings: Vec<String>,
}

fn row(label: &'static str, value: String, unit: &'static str, meaning: &'static str) -> Row {
    Row { label, value, unit: unit.to_string(), meaning }
}

/// A row of values of one SI unit in engineering notation ([`crate::number::eng_values`]): the values
/// share the prefix of the largest (`Kxx, Kxy` = "46.36, -1.839" MN/m).
fn eng_row(label: &'static str, values_si: &[f64], unit_si: &str, meaning: &'static str) -> Row {
    let (values, unit) = crate::number::eng_values(values_si, unit_si);
    Row { label, value: values.join(", "), unit, meaning }
}

/// A relative residual or balance: round-off (below 1e-12) is shown as such, not as its noise digits.
#[must_use]
pub fn small(x: f64) -> String {
    if x.abs() < 1e-12 {
        "< 1e-12".into()
    } else {
        format!("{x:.1e}")
    }
}

/// Four significant figures ([`crate::number::sig`]).
#[must_use]
pub fn sig4(x: f64) -> String {
    crate::number::sig(x, 4)
}

/// Builds the summary of a solution.
#[must_use]
#[allow(clippy::too_many_lines)]
pub fn summary(s: &Solution) -> Summary {
    let f = &s.flows_m3_per_s;
    let r = &s.report;
    let mut operating = Group {
        title: "Operating point",
        rows: vec![
            row("Speed", sig4(s.derived.speed_rpm), "rpm", "Journal speed Ω."),
            eng_row("Load", &[s.load_magnitude_n], "N", "Static load carried by the film, equal and opposite to the film force."),
            row("Eccentricity ε", format!("{:.4}", s.eccentricity_ratio), "–", "Journal displacement from the bearing centre divided by the assembled clearance Cb."),
            row(
                "Attitude angle",
                format!("{:.2}", s.attitude_angle_deg),
                "°",
                "Angle from the load direction to the journal displacement, positive in the direction of rotation. Zero for a symmetric load-on-pad tilting-pad bearing.",
            ),
            row("Journal x, y", format!("{:.2}, {:.2}", UM.from_si(s.journal_position_m[0]), UM.from_si(s.journal_position_m[1])), "µm", "Journal centre displacement in the bearing frame (y up)."),
            row("h_min", format!("{:.2}", UM.from_si(s.h_min_m)), "µm", "Smallest film thickness on any pad: the margin against metal contact."),
            row("p_max", format!("{:.3}", MPA.from_si(s.p_max_pa)), "MPa", "Largest film pressure on any pad (babbitt fatigue limit is typically a few MPa)."),
            match &s.thermal {
                // Film and pad on rows of their own: one value per row keeps the unit column in view.
                Some(t) => row(
                    "T_max film",
                    format!("{:.1}", t.t_max_film_c),
                    "°C",
                    "Largest film temperature from the thermal model.",
                ),
                None => row(
                    "T_max",
                    "— (isothermal)".into(),
                    "°C",
                    "Largest film or pad temperature. The isothermal model uses one film temperature; switch the physics to THD to compute temperatures.",
                ),
            },
            eng_row("Film friction", &[s.friction_power_w], "W", "Viscous shear power dissipated in the films (friction loss)."),
            eng_row("Churning", &[s.churning_power_w()], "W", "Power the journal loses stirring the oil of a flooded housing in the gaps between the pads (feeding.churning_factor; 0 with directed feeding)."),
            eng_row("Total power loss", &[s.total_power_loss_w()], "W", "Film friction and churning: the power the bearing takes from the shaft."),
            eng_row("Friction torque", &[s.friction_torque_nm], "N·m", "Drag torque of the films on the journal."),
            row(
                "Sommerfeld S",
                s.sommerfeld.map_or_else(|| "— (no load)".into(), sig4),
                "–",
                "S = µ N L D / W (R/Cb)², with the film viscosity and the assembled clearance: the bearing's duty in one number (large S = lightly loaded).",
            ),
            row("Film viscosity", sig4(MPA_S.from_si(s.derived.film_viscosity_pa_s)), "mPa·s", "Viscosity of the isothermal film, from the lubricant's law at the film temperature."),
        ],
    };
    if let Some(tp) = s.thermal.as_ref().and_then(|t| t.t_max_pad_c) {
        let at = operating.rows.iter().position(|r| r.label == "T_max film").map_or(operating.rows.len(), |i| i + 1);
        let meaning = "Largest pad temperature (surface or body) from the thermal model.";
        operating.rows.insert(at, row("T_max pad", format!("{tp:.1}"), "°C", meaning));
    }
    let flows = Group {
        title: "Flows",
        rows: vec![
            row("Leading edges in", format!("{:.3}", L_PER_MIN.from_si(f.leading_edges_in)), "l/min", "Oil drawn into the films at the pads' leading edges."),
            row(
                "Orifices in",
                // A bearing without orifices has no orifice flow to show (not a measured 0.000).
                if s.pads.iter().all(|p| p.orifice_flows_m3_per_s.is_empty()) {
                    "— (no orifices)".into()
                } else {
                    format!("{:.3}", L_PER_MIN.from_si(f.orifices_in))
                },
                "l/min",
                "Net flow injected through the orifices (negative: oil leaves through the holes).",
            ),
            row("Trailing edges out", format!("{:.3}", L_PER_MIN.from_si(f.trailing_edges_out)), "l/min", "Oil carried out at the trailing edges (partly carried over to the next pad)."),
            row("Sides out", format!("{:.3}", L_PER_MIN.from_si(f.sides_out)), "l/min", "Side leakage at the axial ends: this is the flow the supply must replace."),
            row("Into cavitation", format!("{:.3}", L_PER_MIN.from_si(f.to_cavitation)), "l/min", "Net flow from the full film into cavitated (ruptured) regions; negative where more oil re-enters the full film at reformation than leaves it at rupture."),
            row("Mass balance", small(f.mass_balance_error), "–", "(in − out) / throughput of the discrete solution: should be round-off small."),
        ],
    };
    let k = s.reduced.k_n_per_m;
    let c = s.reduced.c_ns_per_m;
    let coeffs = Group {
        title: "Reduced coefficients",
        rows: vec![
            row(
                "ω/Ω",
                sig4(s.inputs.operating.excitation_ratio),
                "–",
                "Excitation frequency ratio used for the reduction of the pad coordinates.",
            ),
            eng_row("Kxx, Kxy", &k[0], "N/m", "Stiffness: force in x per displacement in x, y."),
            eng_row("Kyx, Kyy", &k[1], "N/m", "Stiffness: force in y per displacement in x, y."),
            eng_row("Cxx, Cxy", &c[0], "N·s/m", "Damping: force in x per velocity in x, y."),
            eng_row("Cyx, Cyy", &c[1], "N·s/m", "Damping: force in y per velocity in x, y."),
        ],
    };
    let solver = Group {
        title: "Solver report",
        rows: vec![
            row("Method", r.method_text(), "", "How equilibrium was found: coupled Newton on journal and pad coordinates; pad assembly (nested Newton), a scan along the load and load continuation as fallbacks."),
            row("Iterations", format!("{} outer, {} pad", r.iterations, r.inner_iterations), "", "Journal Newton iterations and pad (inner) iterations, over the whole solve (THD: every equilibrium of the thermal loop and its isothermal start)."),
            row("Film solves", format!("{} ({} factorisations)", r.film_solves, r.factorizations), "", "Reynolds solves and sparse numeric factorisations (THD: with the film-energy and pad-conduction factorisations)."),
            row("Residual", format!("{} (pads {})", small(r.residual), small(r.pad_residual)), "–", "Final force residual relative to the force scale, and the largest pad residual."),
            row("Solve time", format!("{:.0}", MS.from_si(r.seconds)), "ms", "Wall time of the whole solve (THD: the isothermal start and the thermal loop)."),
            row("Film nodes", s.derived.film_nodes.to_string(), "", "Finite-element nodes over all pads (mesh fidelity)."),
        ],
    };
    let pads = s
        .pads
        .iter()
        .map(|p| PadRow {
            index: p.index,
            tilt_mrad: p.tilt_rad.map(|t| MRAD.from_si(t)),
            h_min_um: UM.from_si(p.h_min_m),
            p_max_mpa: MPA.from_si(p.p_max_pa),
            load_n: p.force_n[0].hypot(p.force_n[1]),
            orifice_flow_l_min: (!p.orifice_flows_m3_per_s.is_empty())
                .then(|| L_PER_MIN.from_si(p.orifice_flows_m3_per_s.iter().sum::<f64>())),
            cavitated_percent: 100.0 * p.cavitated_fraction,
            unloaded: p.unloaded,
        })
        .collect();
    let mut groups = vec![operating, flows];
    let mut warnings: Vec<String> = r.warnings.iter().map(ToString::to_string).collect();
    if let Some(t) = &s.thermal {
        groups.push(thermal_group(t));
        warnings.extend(t.report.warnings.iter().map(ToString::to_string));
    }
    groups.extend([coeffs, solver]);
    Summary { groups, pads, warnings }
}

/// The thermal results (THD solves only).
fn thermal_group(t: &crate::bearing::solution::ThermalResult) -> Group {
    let inlets: Vec<String> = t.inlet_temperatures_c.iter().map(|v| format!("{v:.1}")).collect();
    let rep = &t.report;
    Group {
        title: "Thermal (THD)",
        rows: vec![
            row("Film-pad condition", format!("{:?}", t.pad_film_bc), "", "How heat passes between film and pad: BC1 adiabatic film, BC2 exchange coefficient, BC3 Knight & Barrett parabola."),
            row("Film T max, mean", format!("{:.1}, {:.1}", t.t_max_film_c, t.t_mean_film_c), "°C", "Hottest and mean film temperature (averaged across the film thickness)."),
            row("Pad T max", t.t_max_pad_c.map_or_else(|| "—".into(), |v| format!("{v:.1}")), "°C", "Hottest point of the pads (the babbitt limit is ~120–130 °C)."),
            row("Journal T", format!("{:.1}", t.journal_temperature_c), "°C", "Journal surface temperature: given, or from zero net heat flux into the journal."),
            row("Inlet T per pad", inlets.join(", "), "°C", "Leading-edge oil temperature of each pad from the groove mixing of hot carried-over oil with fresh supply."),
            eng_row("Heat to oil, conducted", &[t.heat_carried_by_oil_w, t.heat_conducted_w], "W", "Friction power leaves as enthalpy of the oil and by conduction into pads and journal."),
            row("Energy balance", small(t.energy_balance_closure), "–", "(heat generated − heat to oil − heat conducted) / heat generated: the discrete energy balance, should be at round-off."),
            row("Thermal loop", rep.outer_iterations.to_string(), "iterations", "Outer iterations of equilibrium + temperatures until the viscosity field converged."),
            row("Thermal loop time", format!("{:.0}", MS.from_si(rep.seconds)), "ms", "Wall time of the thermal loop (equilibria, film energy, pad conduction, mixing)."),
            row("Viscosity change", rep.viscosity_change.last().map_or_else(|| "—".into(), |v| format!("{v:.1e}")), "–", "Largest nodal relative viscosity change of the last outer iteration (converged below 1e-4)."),
        ],
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_off_is_shown_as_such() {
        assert_eq!(small(-7.9e-17), "< 1e-12");
        assert_eq!(small(4.4e-6), "4.4e-6");
    }

    #[test]
    fn four_significant_figures() {
        assert_eq!(sig4(1918.0), "1918");
        assert_eq!(sig4(9000.0), "9000");
        assert_eq!(sig4(0.012345), "0.01235");
        assert_eq!(sig4(123.456), "123.5");
        assert_eq!(sig4(2.5e7), "2.5e7");
        assert_eq!(sig4(0.0), "0");
    }
}
