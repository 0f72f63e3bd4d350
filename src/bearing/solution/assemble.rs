//! A converged state as a [`Solution`]: the films' fields, forces, flows and friction of every pad, the
//! bearing's flows and power loss, the full dynamic coefficients (with the Hertz pivots' tangent stiffness
//! where the pads have them) and their reduction, the journal's position, attitude and Sommerfeld number,
//! and the warnings the state calls for (static stability, directions without stiffness, flow regime);
//! for a THD state also the thermal fields and balances ([`assemble_thd_solution`]).
//!
//! Called by the stages that solve ([`crate::bearing::stages`]); it runs no solve of its own.

use std::f64::consts::TAU;

use crate::model::{Case, Cavitation, LoadSpec};

use crate::bearing::equilibrium::pivots::HertzPivots;
use crate::bearing::equilibrium::Equilibrium;
use crate::bearing::film::coordinates::PadDof;
use crate::bearing::film::model::{BearingModel, OperatingPoint};
use crate::bearing::report::warning::Warning;
use crate::bearing::solution::churning::churning;
use crate::bearing::solution::coefficients::{full_coefficients, reduce};
use crate::bearing::solution::result::{
    BearingFlows, Derived, PadField, PadFlex, PadResult, PadSolidField, PadThermalGrowth, PadThermalResult, Solution,
    ThermalResult,
};
use crate::bearing::thermal::growth;
use crate::bearing::thermal::ThdState;

/// Collects results of a converged THD state: the solution at its equilibrium (coefficients at the
/// converged viscosity field, temperatures frozen) plus the thermal fields.
#[must_use]
pub fn assemble_thd_solution(model: &mut BearingModel, case: &Case, state: &ThdState) -> Solution {
    // The films of the converged state hold its thermal growth (TEHD) while the solution is assembled.
    if let Some(g) = &state.growth {
        growth::install(model, g);
    }
    let mut sol = assemble_solution(model, case, &state.op, &state.equilibrium, state.pivots.as_ref());
    if state.growth.is_some() {
        growth::clear(model);
    }
    // The headline report is the whole loop's (every equilibrium of it, and its wall time), not the last
    // equilibrium's; residuals and method stay those of the converged state.
    let t = &state.report;
    sol.report.iterations = t.equilibrium_iterations;
    sol.report.inner_iterations = t.inner_iterations;
    sol.report.film_solves = t.film_solves;
    sol.report.factorizations = t.equilibrium_factorizations + t.thermal_factorizations;
    sol.report.seconds = t.seconds;
    let max = |v: &[f64]| v.iter().fold(f64::NEG_INFINITY, |m, &x| m.max(x));
    let (mut t_area, mut area) = (0.0, 0.0);
    for (k, (p, st)) in sol.pads.iter_mut().zip(&state.pads).enumerate() {
        let n_film = st.film_c.len();
        p.thermal_growth =
            state.growth.as_ref().filter(|g| g.pad_nodal_m.get(k).is_some_and(|u| !u.is_empty())).map(|g| {
                PadThermalGrowth {
                    film_radial_m: g.pad_film_m[k].clone(),
                    nodal_polar_m: g.pad_nodal_m[k].clone(),
                    radii_m: st.pad_radii_m.clone(),
                }
            });
        let surface = st.pad_c.as_ref().map(|t| t[..n_film].to_vec());
        p.field.film_temperature_c = Some(st.film_c.clone());
        p.field.pad_surface_temperature_c.clone_from(&surface);
        t_area += st.film_mean_c * st.oil_area_m2;
        area += st.oil_area_m2;
        p.thermal = Some(PadThermalResult {
            inlet_temperature_c: st.inlet_temperature_c,
            outlet_temperature_c: st.outlet_temperature_c,
            film_t_max_c: max(&st.film_c),
            film_t_mean_c: st.film_mean_c,
            pad_t_max_c: st.pad_c.as_deref().map(max),
            pad_surface_t_max_c: surface.as_deref().map(max),
            heat: st.heat,
            pad_to_surroundings_w: st.pad_to_surroundings_w,
            solid: st
                .pad_c
                .as_ref()
                .map(|t| PadSolidField { radii_m: st.pad_radii_m.clone(), temperature_c: t.clone() }),
        });
    }
    // The oil in the gap ahead of each pad is the mixed oil that pad's film takes in.
    let law = case.lubricant.viscosity;
    sol.churning = churning(case, state.op.speed_rad_s, |k| law.at(state.pads[k].inlet_temperature_c));
    let pad_max = state
        .pads
        .iter()
        .filter_map(|p| p.pad_c.as_deref().map(max))
        .fold(None, |m: Option<f64>, v| Some(m.map_or(v, |m| m.max(v))));
    sol.thermal = Some(ThermalResult {
        pad_film_bc: case.thermal.pad_film_bc,
        journal_temperature_c: state.journal_temperature_c,
        t_max_film_c: state.pads.iter().map(|p| max(&p.film_c)).fold(f64::NEG_INFINITY, f64::max),
        t_mean_film_c: if area > 0.0 { t_area / area } else { state.journal_temperature_c },
        t_max_pad_c: pad_max,
        inlet_temperatures_c: state.pads.iter().map(|p| p.inlet_temperature_c).collect(),
        heat: state.heat,
        heat_carried_by_oil_w: state.heat.carried_by_oil(),
        heat_conducted_w: state.heat.conducted_out(),
        heat_pads_to_surroundings_w: state.pads.iter().map(|p| p.pad_to_surroundings_w).sum(),
        energy_balance_closure: state.report.energy_balance_closure,
        report: state.report.clone(),
    });
    sol
}

/// A warning when the static (ω = 0) journal stiffness vanishes along an axis: the journal's position along
/// it is set by the force balance alone (pads floating there, or no pad on that axis).
fn zero_stiffness_warning(k: &[[f64; 2]; 2]) -> Option<Warning> {
    let m = nalgebra::Matrix2::new(k[0][0], k[0][1], k[1][0], k[1][1]);
    let svd = m.svd(false, true);
    let v_t = svd.v_t?;
    let (smax, smin) = (svd.singular_values.max(), svd.singular_values.min());
    let i = if svd.singular_values[0] < svd.singular_values[1] { 0 } else { 1 };
    (smax > 0.0 && smin < 1e-7 * smax).then(|| {
        let axis = v_t[(i, 1)].atan2(v_t[(i, 0)]).to_degrees().rem_euclid(180.0).round() % 180.0 + 0.0;
        Warning::NoStaticStiffness { axis_deg: axis }
    })
}

/// A warning when the static (ω = 0) journal stiffness has a negative principal value: the equilibrium
/// exists but is statically unstable (the journal would move away from it).
fn static_stability_warning(k: &[[f64; 2]; 2]) -> Option<Warning> {
    let (a, b, d) = (k[0][0], 0.5 * (k[0][1] + k[1][0]), k[1][1]);
    let mean = 0.5 * (a + d);
    let rad = (0.25 * (a - d) * (a - d) + b * b).sqrt();
    let (lo, hi) = (mean - rad, mean + rad);
    let scale = hi.abs().max(lo.abs());
    (lo < -1e-6 * scale).then_some(Warning::StaticallyUnstable { principal_n_per_m: lo })
}

fn wrap_deg(a: f64) -> f64 {
    let x = a.rem_euclid(360.0);
    if x > 180.0 {
        x - 360.0
    } else {
        x
    }
}

/// Collects results from the converged films; with Hertz pivots, their tangent stiffness enters the
/// coefficients (installed in the model, which keeps it) and each contact pad's state its result.
#[must_use]
pub fn assemble_solution(
    model: &mut BearingModel,
    case: &Case,
    op: &OperatingPoint,
    eq: &Equilibrium,
    pivots: Option<&HertzPivots>,
) -> Solution {
    if let Some(p) = pivots {
        p.install_tangents(model);
    }
    let cb = model.assembled_clearance;
    let r = model.journal_radius;
    let e = [eq.u[0], eq.u[1]];
    let load = [-eq.film_force[0], -eq.film_force[1]];
    let wmag = load[0].hypot(load[1]);
    let mut pads = Vec::with_capacity(model.pads.len());
    let mut flows = BearingFlows::default();
    let mut power = 0.0;
    let mut torque = 0.0;
    let mut created = Vec::with_capacity(model.pads.len());
    for (k, (pm, st)) in model.pads.iter().zip(&eq.pads).enumerate() {
        let inp = op.film_inputs(k);
        let film = &pm.film;
        let f = film.flows(&inp);
        let (drag, pw) = film.friction(&inp);
        let (hmin, inode) = film.h_min();
        let coordinate = |dof: PadDof| pm.dofs().iter().position(|d| *d == dof).map(|i| st.q[i]);
        let grid = &film.geom.grid;
        let viscosity: Vec<f64> = match &op.nodal_viscosity[k] {
            Some(v) => v.clone(),
            None => vec![op.viscosity; film.p.len()],
        };
        let rho_u = case.lubricant.density_kg_per_m3 * op.surface_speed;
        let field = PadField {
            s_m: grid.s.clone(),
            theta_rad: grid.s.iter().map(|s| film.geom.theta_le + s / r).collect(),
            z_m: grid.z.clone(),
            half: grid.half,
            periodic: grid.periodic,
            pressure_pa: film.p.clone(),
            film_thickness_m: film.h.node.clone(),
            cavitated: film.cavitated.clone(),
            reynolds: film.h.node.iter().zip(&viscosity).map(|(h, mu)| rho_u * h / mu).collect(),
            viscosity_pa_s: viscosity,
            film_temperature_c: None,
            pad_surface_temperature_c: None,
        };
        flows.leading_edges_in += f.leading_edge_in;
        flows.trailing_edges_out += f.trailing_edge_out;
        flows.sides_out += f.sides_out;
        flows.orifices_in += f.orifice_in;
        flows.to_cavitation += f.to_cavitation;
        created.push(film.created_at_cavity());
        power += pw;
        torque += drag * r;
        #[allow(clippy::cast_precision_loss)]
        let cav_frac = film.cavitated.iter().filter(|&&c| c).count() as f64 / film.p.len() as f64;
        pads.push(PadResult {
            index: k,
            tilt_rad: coordinate(PadDof::Tilt),
            pivot_displacement_m: coordinate(PadDof::PivotRadial),
            pivot_transverse_displacement_m: coordinate(PadDof::PivotTransverse),
            h_min_m: hmin,
            h_min_angle_deg: film.geom.node_theta[inode].to_degrees(),
            p_max_pa: film.p_max(),
            force_n: [st.forces[0], st.forces[1]],
            moment_nm: pm.dofs().iter().position(|d| *d == PadDof::Tilt).map_or(0.0, |i| st.pad_force(i)),
            flows_m3_per_s: f,
            orifice_flows_m3_per_s: (0..film.geom.orifices.len()).map(|o| film.orifice_flow(o, &inp)).collect(),
            friction_power_w: pw,
            cavitated_fraction: cav_frac,
            unloaded: st.unloaded,
            mode_amplitudes_m: mode_amplitudes(pm, &st.q),
            elastic_displacement_m: elastic_displacement(pm, &st.q),
            thermal_growth: None,
            flex: pm
                .modes
                .as_ref()
                .zip(pm.solid.as_ref())
                .map(|(modes, solid)| PadFlex { modes: modes.clone(), radii_m: solid.radii.clone() }),
            field,
            thermal: None,
            pivot_contact: None,
        });
    }
    let inflow = flows.leading_edges_in + flows.orifices_in;
    let outflow = flows.trailing_edges_out + flows.sides_out + flows.to_cavitation;
    // Relative to the throughput (a 360° bore has no edges: its in- and outflow are both ~0 net).
    let scale = flows.leading_edges_in.abs()
        + flows.orifices_in.abs()
        + flows.trailing_edges_out.abs()
        + flows.sides_out.abs()
        + flows.to_cavitation.abs();
    flows.mass_balance_error = if scale > 0.0 { (inflow - outflow) / scale } else { 0.0 };

    let full = full_coefficients(model, eq);
    let omega = case.operating.excitation_ratio * op.speed_rad_s;
    let reduced = reduce(&full, omega);
    let mut report = eq.report.clone();
    let k_static = reduce(&full, 0.0).k_n_per_m;
    report.warnings.extend(static_stability_warning(&k_static).into_iter().chain(zero_stiffness_warning(&k_static)));
    report.warnings.extend(created_oil_warning(case.physics.cavitation, &created, flows.leading_edges_in));
    let load_angle = match op.load {
        LoadSpec::Force { angle_rad, magnitude_n } if magnitude_n > 0.0 => angle_rad,
        _ => load[1].atan2(load[0]),
    };
    let ecc = e[0].hypot(e[1]) / cb;
    let attitude = if ecc > 1e-12 { wrap_deg((e[1].atan2(e[0]) - load_angle).to_degrees()) } else { 0.0 };
    let n_rev = op.speed_rad_s / TAU;
    let sommerfeld = (wmag > 1e-9).then(|| op.viscosity * n_rev * model.length * 2.0 * r / wmag * (r / cb).powi(2));
    let regime = crate::bearing::solution::regime::Regime::of(case, op.surface_speed, &pads);
    report.warnings.extend(regime.warnings());
    let mut sol = Solution {
        title: case.title.clone(),
        eccentricity_ratio: ecc,
        attitude_angle_deg: attitude,
        journal_position_m: e,
        load_n: load,
        load_magnitude_n: wmag,
        sommerfeld,
        h_min_m: pads.iter().fold(f64::INFINITY, |m, p| m.min(p.h_min_m)),
        p_max_pa: pads.iter().fold(0.0, |m, p| m.max(p.p_max_pa)),
        pads,
        friction_power_w: power,
        friction_torque_nm: torque,
        churning: churning(case, op.speed_rad_s, |_| op.viscosity),
        flows_m3_per_s: flows,
        full,
        reduced,
        coordinates: eq.u.clone(),
        report,
        regime,
        derived: Derived {
            assembled_clearance_m: cb,
            pad_clearances_m: case.bearing.pads.iter().map(|p| p.clearance_m).collect(),
            preloads: case.bearing.pads.iter().map(|p| p.preload).collect(),
            speed_rad_s: op.speed_rad_s,
            speed_rpm: crate::units::RPM.from_si(op.speed_rad_s),
            film_viscosity_pa_s: op.viscosity,
            film_nodes: model.film_nodes(),
        },
        inputs: case.clone(),
        thermal: None,
    };
    if let Some(p) = pivots {
        annotate_pivots(&mut sol, p);
    }
    sol
}

/// Share of the leading-edge inflow above which the oil a non-conserving cavitation condition creates is
/// reported ([`Warning::CavitationCreatesOil`]), and a pad's share above which the warning names it.
const CREATED_OIL_SHARE: f64 = 0.01;
const CREATED_OIL_PAD_SHARE: f64 = 0.001;

/// [`Warning::CavitationCreatesOil`] when the pads' cavitated zones create more than
/// [`CREATED_OIL_SHARE`] of the leading-edge inflow (never with the mass-conserving option, whose
/// cavitated nodes balance their flows).
fn created_oil_warning(condition: Cavitation, created: &[f64], inflow: f64) -> Option<Warning> {
    let total: f64 = created.iter().sum();
    if condition == Cavitation::Jfo || inflow <= 0.0 || total <= CREATED_OIL_SHARE * inflow {
        return None;
    }
    let pads =
        created.iter().enumerate().filter(|(_, c)| **c > CREATED_OIL_PAD_SHARE * inflow).map(|(k, _)| k).collect();
    Some(Warning::CavitationCreatesOil { condition, pads, created_m3_s: total, share_of_inflow: total / inflow })
}

/// The pad's modal coordinates `PadDof::Mode(i)`, in mode order.
fn mode_amplitudes(pm: &crate::bearing::film::model::PadModel, q: &[f64]) -> Vec<f64> {
    pm.dofs().iter().zip(q).filter(|(d, _)| matches!(d, PadDof::Mode(_))).map(|(_, v)| *v).collect()
}

/// Σ q_i φ_i at the film nodes (empty for a rigid pad).
fn elastic_displacement(pm: &crate::bearing::film::model::PadModel, q: &[f64]) -> Vec<f64> {
    let Some(modes) = &pm.modes else { return Vec::new() };
    let amps = mode_amplitudes(pm, q);
    let mut u = vec![0.0; pm.film.geom.n_nodes()];
    for (m, a) in modes.modes.iter().zip(&amps) {
        for (ui, phi) in u.iter_mut().zip(&m.film_shape) {
            *ui += a * phi;
        }
    }
    u
}

/// Each contact pad's state in the solution (`PadResult::pivot_contact`), the load iteration in the report's
/// method, and the iteration's warnings (a load under the floor; loads not converged).
fn annotate_pivots(sol: &mut Solution, pivots: &HertzPivots) {
    for (pad, s) in pivots.states() {
        if let Some(p) = sol.pads.get_mut(pad) {
            p.pivot_contact = Some(s);
        }
    }
    let r = &mut sol.report;
    r.pivot_load_iterations = Some(pivots.iterations());
    for w in pivots.warnings() {
        r.warn(w);
    }
}
