//! Energy conservation on a plane inclined slider (the film energy equation alone).
//!
//! A long plane slider (length B along the motion, width L = 20 B, half model) with film thickness falling
//! linearly from `h_in` to `h_out`, isoviscous oil, no exchange with the surfaces (BC1). Along the
//! mid-plane the flow is the infinitely wide slider's: `q = U h*/2` with `h* = 2 h_in h_out/(h_in + h_out)`,
//! `dp/dx = 6 µ U (h − h*)/h³`, and with conduction negligible (Péclet ≫ 1) the adiabatic energy balance
//! `ρ c_p q dT/dx = µU²/h + h³/(12µ)(dp/dx)²` integrates in closed form:
//!
//! ```text
//! ρ c_p q ΔT = µ U² B/(h_in − h_out) · [ ln h + 3 (ln h + 2h*/h − h*²/(2h²)) ]_{h_out}^{h_in}
//! ```
//!
//! (the classical adiabatic slider, e.g. Hamrock, Schmid & Jacobson, *Fundamentals of Fluid Film
//! Lubrication*, ch. 8). Checks: the outlet temperature on the mid-plane against that closed form, and the
//! global balance `P = H + C` of the whole finite slider.

use tiltpad::bearing::thermal::pad_system::{PadThermal, ThermalSetup};
use tiltpad::fem::supg::Stabilisation;
use tiltpad::mesh::grid::{graded_nodes, PadGrid};
use tiltpad::model::Cavitation;
use tiltpad::physics::energy::{BalanceInputs, Exchange, Injection, Oil};
use tiltpad::physics::pad_conduction::PadMaterial;
use tiltpad::physics::reynolds::{FilmGeometry, FilmInputs, FilmShape, PadFilm, Viscosity};

const R: f64 = 10.0; // large radius: the arc is a plane to the film
const B: f64 = 0.05;
const H_IN: f64 = 100e-6;
const H_OUT: f64 = 50e-6;

struct Slider;
impl FilmShape for Slider {
    fn base(&self, theta: f64, _z: f64) -> f64 {
        let x = R * theta;
        H_IN + (H_OUT - H_IN) * x / B
    }
    fn n_dofs(&self) -> usize {
        0
    }
    fn dof(&self, _k: usize, _theta: f64, _z: f64) -> f64 {
        0.0
    }
}

fn closed_form_rise(mu: f64, u: f64, rc: f64) -> f64 {
    let hs = 2.0 * H_IN * H_OUT / (H_IN + H_OUT);
    let prim = |h: f64| h.ln() + 3.0 * (h.ln() + 2.0 * hs / h - hs * hs / (2.0 * h * h));
    let integral = mu * u * u * B / (H_IN - H_OUT) * (prim(H_IN) - prim(H_OUT));
    integral / (rc * u * hs / 2.0)
}

#[test]
fn adiabatic_slider_matches_the_closed_form_and_conserves_energy() {
    let (mu, rpm_u, t_in) = (0.03, 20.0, 40.0);
    let oil = Oil { density: 860.0, specific_heat: 2000.0, conductivity: 0.13 };
    let length = 20.0 * B;
    let grid = PadGrid {
        s: graded_nodes(0.0, B, 60, &[]),
        z: graded_nodes(0.0, 0.5 * length, 40, &[]),
        periodic: false,
        half: true,
    };
    let geom = FilmGeometry::new(grid, R, 0.0, &[], &Slider);
    let mut film = PadFilm::new(geom).unwrap();
    film.set_coordinates(&[]).unwrap();
    let inp = FilmInputs {
        surface_speed: rpm_u,
        viscosity: Viscosity::Uniform(mu),
        injection_pressure: 0.0,
        injection_viscosity: mu,
        cavitation: Cavitation::Reynolds,
        turbulence: tiltpad::physics::turbulence::TurbulenceLaw::LAMINAR,
        inlet: tiltpad::physics::reynolds::Inlet::Flooded,
        leading_edge_pressure: 0.0,
    };
    film.solve(&inp, false).unwrap();
    assert_eq!(film.cavitated.iter().filter(|c| **c).count(), 0, "a converging slider runs full");

    let mut thermal = PadThermal::new(&film, None).unwrap();
    let setup = ThermalSetup {
        oil,
        injection: Injection { pressure: 0.0, viscosity: mu, temperature_c: t_in },
        exchange: Exchange::Adiabatic,
        material: PadMaterial { conductivity: 45.0, convection: 0.0, ambient_c: t_in },
        stabilisation: Stabilisation::Supg,
        striated: true,
    };
    let sol = thermal.solve(&film, &inp, &setup).unwrap();
    let t = sol.film(t_in, t_in);
    // Mid-plane outlet (row 0 of the half model, last column).
    let g = &film.geom;
    let out = g.grid.node(g.grid.n_cols() - 1, 0);
    let rise = t[out] - t_in;
    let exact = closed_form_rise(mu, rpm_u, oil.capacity());
    println!("mid-plane outlet rise {rise:.4} K, closed form {exact:.4} K ({:+.2} %)", 100.0 * (rise / exact - 1.0));
    assert!((rise / exact - 1.0).abs() < 0.01, "outlet rise {rise} vs {exact}");
    // Temperature rises monotonically along the mid-plane (no wiggles).
    for i in 1..g.grid.n_cols() {
        assert!(t[g.grid.node(i, 0)] >= t[g.grid.node(i - 1, 0)] - 1e-9);
    }

    // Global balance of the finite slider: shear power = heat carried by the oil + conducted out.
    let bal = BalanceInputs {
        oil: &oil,
        exchange: Exchange::Adiabatic,
        t: &t,
        t_pad: None,
        t_journal: t_in,
        t_ref: t_in,
        dirichlet_reaction: sol.dirichlet_reaction(t_in, t_in),
    };
    let heat = thermal.energy.heat_balance(&film, &sol.flow, &bal);
    let (_, p_reynolds) = film.friction(&inp);
    println!(
        "shear power {:.4} W (Reynolds module {:.4} W), carried by oil {:.4} W, closure {:.2e}",
        heat.shear_power_w,
        p_reynolds,
        heat.carried_by_oil(),
        heat.closure()
    );
    assert!((heat.shear_power_w / p_reynolds - 1.0).abs() < 1e-12, "full film: both friction powers agree");
    // Exact identities, so round-off (measured 5e-15 and 3.5e-16 of the shear power).
    assert!((heat.dissipation_w / heat.shear_power_w - 1.0).abs() < 1e-12, "∫Φ = U ∫ (µU/h + h/2 ∂p/∂s) exactly");
    assert!(
        heat.cavitation_transport_w.abs() < 1e-12 * heat.shear_power_w,
        "a full film carries nothing into cavitation"
    );
    // Round-off (measured 1.9e-15, docs/THERMAL.md).
    assert!(heat.closure().abs() < 1e-12, "closure {:.2e}", heat.closure());
}
