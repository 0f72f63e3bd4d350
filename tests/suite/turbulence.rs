//! Turbulent films (`physics.turbulence`, docs/MODEL.md §2.7) on a long plane slider, against closed forms.
//!
//! A plane slider (length B along the motion, width 20 B, half model) with the film falling linearly from
//! `h_in` to `h_out`, isoviscous oil. Along the mid-plane the flow is the infinitely wide slider's. With the
//! Ng–Pan coefficients the flow per unit width `q = −h³/(k_s µ) dp/dx + U h/2` is constant, so
//!
//! ```text
//! dp/dx = k_s µ (U h/2 − q)/h³,   p(0) = p(B) = 0  ⇒  q = (U/2) ∫ k_s/h² dx / ∫ k_s/h³ dx
//! ρ c_p q ΔT = ∫ [C_f µ U²/h + k_s µ (U h/2 − q)²/h³] dx          (adiabatic, conduction negligible)
//! ```
//!
//! with `k_s(Re)`, `C_f(Re)` at the local `Re = ρ U h/µ`: one-dimensional quadratures (laminar: k_s = 12,
//! C_f = 1, the classical slider). Checks: the mid-plane pressure and the adiabatic outlet temperature rise
//! against these, turbulent and laminar, on the same mesh; the laminar limit below the transition band
//! bit for bit; and the exact discrete identities the energy balance rests on (∫Φ = shear power, the
//! energy equation's flux field is the Reynolds solve's consistent flow).

use tiltpad::bearing::thermal::pad_system::{PadThermal, ThermalSetup};
use tiltpad::fem::supg::Stabilisation;
use tiltpad::mesh::grid::{graded_nodes, PadGrid};
use tiltpad::model::{Cavitation, Turbulence};
use tiltpad::physics::energy::{BalanceInputs, Exchange, Injection, Oil};
use tiltpad::physics::pad_conduction::PadMaterial;
use tiltpad::physics::reynolds::{FilmGeometry, FilmInputs, FilmShape, PadFilm, Viscosity};
use tiltpad::physics::turbulence::{ng_pan_cf, ng_pan_ks, TurbulenceLaw};

const R: f64 = 10.0; // large radius: the arc is a plane to the film
const B: f64 = 0.05;
const H_IN: f64 = 100e-6;
const H_OUT: f64 = 50e-6;
const RHO: f64 = 860.0;
const MU: f64 = 0.001;
/// Surface speed [m/s]: Re = ρUh/µ from 5160 (inlet) to 2580 (outlet), well into the turbulent regime.
const U: f64 = 60.0;

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

fn law(mode: Turbulence, band: [f64; 2]) -> TurbulenceLaw {
    TurbulenceLaw { mode, re_start: band[0], re_end: band[1], density: RHO }
}

fn film(u: f64, mu: f64, turbulence: TurbulenceLaw) -> (PadFilm, FilmInputs<'static>) {
    let grid = PadGrid {
        s: graded_nodes(0.0, B, 80, &[]),
        z: graded_nodes(0.0, 10.0 * B, 40, &[]),
        periodic: false,
        half: true,
    };
    let geom = FilmGeometry::new(grid, R, 0.0, &[], &Slider);
    let mut film = PadFilm::new(geom).unwrap();
    film.set_coordinates(&[]).unwrap();
    let inp = FilmInputs {
        surface_speed: u,
        viscosity: Viscosity::Uniform(mu),
        injection_pressure: 0.0,
        injection_viscosity: mu,
        cavitation: Cavitation::Reynolds,
        turbulence,
        inlet: tiltpad::physics::reynolds::Inlet::Flooded,
        leading_edge_pressure: 0.0,
    };
    film.solve(&inp, false).unwrap();
    assert_eq!(film.cavitated.iter().filter(|c| **c).count(), 0, "a converging slider runs full");
    (film, inp)
}

/// The infinitely wide slider by quadrature (module documentation): (x, p(x)) at `n + 1` points, the flow
/// q, and the adiabatic temperature rise for volumetric heat capacity `rc`.
fn wide_slider(u: f64, mu: f64, turbulent: bool, rc: f64) -> (Vec<f64>, Vec<f64>, f64, f64) {
    let n = 20_000;
    let h = |x: f64| H_IN + (H_OUT - H_IN) * x / B;
    let coef = |x: f64| {
        let re = RHO * u * h(x) / mu;
        if turbulent {
            (ng_pan_ks(re).0, ng_pan_cf(re).0)
        } else {
            (12.0, 1.0)
        }
    };
    // Simpson on n intervals.
    let simpson = |f: &dyn Fn(f64) -> f64| {
        let d = B / f64::from(n);
        let mut s = f(0.0) + f(B);
        for i in 1..n {
            s += if i % 2 == 1 { 4.0 } else { 2.0 } * f(d * f64::from(i));
        }
        s * d / 3.0
    };
    let q = 0.5 * u * simpson(&|x| coef(x).0 / h(x).powi(2)) / simpson(&|x| coef(x).0 / h(x).powi(3));
    let dpdx = |x: f64| coef(x).0 * mu * (0.5 * u * h(x) - q) / h(x).powi(3);
    let (mut xs, mut ps) = (vec![0.0], vec![0.0]);
    let d = B / f64::from(n);
    for i in 0..n {
        let (a, b) = (d * f64::from(i), d * f64::from(i + 1));
        let p = ps[ps.len() - 1] + d / 6.0 * (dpdx(a) + 4.0 * dpdx(0.5 * (a + b)) + dpdx(b));
        xs.push(b);
        ps.push(p);
    }
    let heat = simpson(&|x| {
        let (k, cf) = coef(x);
        cf * mu * u * u / h(x) + k * mu * (0.5 * u * h(x) - q).powi(2) / h(x).powi(3)
    });
    (xs, ps, q, heat / (rc * q))
}

/// Largest mid-plane pressure error of the film against the wide slider, relative to its peak, and the
/// peak pressures (film, closed form).
fn midplane_error(film: &PadFilm, xs: &[f64], ps: &[f64]) -> (f64, f64, f64) {
    let g = &film.geom;
    let peak = ps.iter().copied().fold(0.0, f64::max);
    let (mut err, mut fe_peak) = (0.0_f64, 0.0_f64);
    for i in 0..g.grid.n_cols() {
        let k = g.grid.node(i, 0);
        let x = R * g.node_theta[k];
        let j = xs.partition_point(|&v| v < x - 1e-9 * B).min(xs.len() - 1);
        assert!((xs[j] - x).abs() < 1e-9 * B, "node on the quadrature grid");
        err = err.max((film.p[k] - ps[j]).abs() / peak);
        fe_peak = fe_peak.max(film.p[k]);
    }
    (err, fe_peak, peak)
}

/// The mid-plane pressure of the turbulent slider matches the wide-slider quadrature as closely as the
/// laminar one matches the classical solution on the same mesh (the element error), and the turbulent
/// film carries much more pressure (k_s/12 ≈ 2.7–3.7 along this film).
#[test]
fn turbulent_slider_pressure_matches_the_wide_slider_quadrature() {
    let (lam, _) = film(U, MU, TurbulenceLaw::LAMINAR);
    let (xs, ps, _, _) = wide_slider(U, MU, false, 1.0);
    let (e_lam, p_lam, exact_lam) = midplane_error(&lam, &xs, &ps);
    let (turb, _) = film(U, MU, law(Turbulence::On, [1000.0, 1500.0]));
    let (xs, ps, _, _) = wide_slider(U, MU, true, 1.0);
    let (e_turb, p_turb, exact_turb) = midplane_error(&turb, &xs, &ps);
    println!(
        "mid-plane peak: laminar {p_lam:.0} Pa (closed form {exact_lam:.0}, error {e_lam:.2e}), turbulent \
         {p_turb:.0} Pa (quadrature {exact_turb:.0}, error {e_turb:.2e})"
    );
    assert!(exact_turb / exact_lam > 2.5, "turbulence stiffens the film: {exact_turb} vs {exact_lam}");
    // Measured 8.9e-5 (laminar) and 6.3e-5 (turbulent) of the peak.
    assert!(e_lam < 2e-4, "laminar element error {e_lam:.2e}");
    assert!(e_turb < 2e-4, "turbulent mid-plane error {e_turb:.2e}");
}

/// Below the transition band `auto` runs the laminar arithmetic: the same pressures and friction to the
/// last bit. Inside the band the film lies between laminar and turbulent.
#[test]
fn below_the_band_auto_is_laminar_bit_for_bit() {
    // Re = 860 · 2 · 100e-6 / 0.03 ≈ 5.7: far below the band.
    let (off, inp_off) = film(2.0, 0.03, TurbulenceLaw::LAMINAR);
    let (auto, inp_auto) = film(2.0, 0.03, law(Turbulence::Auto, [1000.0, 1500.0]));
    assert!(auto.turbulence_qp().is_none(), "no turbulence data below the band");
    assert_eq!(off.p, auto.p, "pressures");
    assert_eq!(off.friction(&inp_off), auto.friction(&inp_auto), "friction");
    assert_eq!(off.flows(&inp_off), auto.flows(&inp_auto), "flows");

    // The band across the film (Re 2580–5160): blended between the two.
    let (lam, _) = film(U, MU, TurbulenceLaw::LAMINAR);
    let (mid, _) = film(U, MU, law(Turbulence::Auto, [3000.0, 4500.0]));
    let (on, _) = film(U, MU, law(Turbulence::On, [3000.0, 4500.0]));
    let peak = |f: &PadFilm| f.p.iter().copied().fold(0.0, f64::max);
    println!("peaks: laminar {:.0}, auto (band 3000–4500) {:.0}, on {:.0}", peak(&lam), peak(&mid), peak(&on));
    assert!(peak(&lam) * 1.2 < peak(&mid) && peak(&mid) * 1.2 < peak(&on));
}

/// The adiabatic turbulent slider: mid-plane outlet temperature against the quadrature (the energy
/// equation with the turbulent flow, dissipation and eddy diffusivity), and the energy balance's exact
/// identities.
#[test]
fn turbulent_adiabatic_slider_heats_as_the_quadrature_and_conserves_energy() {
    let oil = Oil { density: RHO, specific_heat: 2000.0, conductivity: 0.13 };
    let t_in = 40.0;
    let mut rises = Vec::new();
    for turbulent in [false, true] {
        let turbulence = if turbulent { law(Turbulence::On, [1000.0, 1500.0]) } else { TurbulenceLaw::LAMINAR };
        let (film, inp) = film(U, MU, turbulence);
        let mut thermal = PadThermal::new(&film, None).unwrap();
        let setup = ThermalSetup {
            oil,
            injection: Injection { pressure: 0.0, viscosity: MU, temperature_c: t_in },
            exchange: Exchange::Adiabatic,
            material: PadMaterial { conductivity: 45.0, convection: 0.0, ambient_c: t_in },
            stabilisation: Stabilisation::Supg,
            striated: true,
        };
        let sol = thermal.solve(&film, &inp, &setup).unwrap();
        let t = sol.film(t_in, t_in);
        let g = &film.geom;
        let rise = t[g.grid.node(g.grid.n_cols() - 1, 0)] - t_in;
        let (_, _, _, exact) = wide_slider(U, MU, turbulent, oil.capacity());
        println!(
            "{}: mid-plane outlet rise {rise:.4} K, quadrature {exact:.4} K ({:+.3} %)",
            if turbulent { "turbulent" } else { "laminar" },
            100.0 * (rise / exact - 1.0)
        );
        // Measured −0.006 % both ways (the element error of the mesh).
        assert!((rise / exact - 1.0).abs() < 5e-4, "outlet rise {rise} vs {exact}");
        rises.push(rise);

        // The flux field is the Reynolds solve's consistent flow: nothing leaves at interior nodes.
        let through: f64 = sol.flow.outflow.iter().map(|o| o.abs()).sum();
        let interior: f64 = (0..g.n_nodes())
            .filter(|&k| {
                matches!(g.sites[k], tiltpad::mesh::grid::NodeSite::Interior | tiltpad::mesh::grid::NodeSite::Symmetry)
            })
            .map(|k| sol.flow.outflow[k].abs())
            .sum();
        assert!(interior < 1e-12 * through, "interior outflow {interior:.2e} of {through:.2e}");
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
        assert!((heat.shear_power_w / p_reynolds - 1.0).abs() < 1e-12, "both friction powers agree");
        assert!((heat.dissipation_w / heat.shear_power_w - 1.0).abs() < 1e-12, "∫Φ = shear power exactly");
        assert!(heat.closure().abs() < 1e-12, "closure {:.2e}", heat.closure());
    }
    assert!(rises[1] > 1.5 * rises[0], "turbulence heats more: {rises:?}");
}

/// The large five-pad bearing in transition (`cases/large-5pad-transition.toml`, isothermal, preview mesh):
/// below the band (1800 rpm, Re ≤ 939) `auto` is the laminar solution to the last bit; past it the friction
/// power rises faster than Ω² (the turbulent bearings' trend: the Couette shear factor grows as Re^0.94),
/// while the laminar model's rises more slowly than Ω² (the journal's eccentricity falls with speed).
#[test]
fn large_bearing_power_rises_faster_than_speed_squared_past_transition() {
    let solve = |mode: &str, rpm: f64| {
        crate::common::solve(
            "large-5pad-transition.toml",
            &[
                "mesh.fidelity=\"preview\"",
                "thermal.model=\"isothermal\"",
                &format!("physics.turbulence=\"{mode}\""),
                &format!("operating.speed_rpm={rpm}"),
            ],
        )
    };
    let (off, auto) = (solve("off", 1800.0), solve("auto", 1800.0));
    assert!(auto.regime.reynolds_max < 1000.0 && auto.regime.transitional_fraction == 0.0);
    assert_eq!(off.friction_power_w, auto.friction_power_w);
    assert_eq!(off.coordinates, auto.coordinates);
    assert_eq!(off.full, auto.full);
    let exponent = |mode: &str| {
        let (a, b) = (solve(mode, 3600.0), solve(mode, 6000.0));
        let n = (b.friction_power_w / a.friction_power_w).ln() / (6000.0_f64 / 3600.0).ln();
        println!(
            "{mode}: friction {:.1} kW at 3600 rpm, {:.1} kW at 6000 rpm: P ∝ Ω^{n:.2}; Re max {:.0}, {:.0} % of the \
             film past the band's start at 6000 rpm",
            a.friction_power_w / 1e3,
            b.friction_power_w / 1e3,
            b.regime.reynolds_max,
            100.0 * b.regime.transitional_fraction
        );
        n
    };
    let (n_off, n_auto) = (exponent("off"), exponent("auto"));
    // Measured 1.88 (laminar) and 2.62 (auto).
    assert!(n_off < 2.0 && n_auto > 2.4, "exponents: laminar {n_off:.2}, auto {n_auto:.2}");
    assert!(solve("auto", 3600.0).report.warnings.iter().all(|w| !w.to_string().starts_with("turbulent film")));
}

/// The film's analytic linearisation with turbulent coefficients (the thickness derivative of `h³ G/µ`
/// through `Re ∝ h`) equals central differences of the generalised forces, on every pad of the large
/// bearing (turbulent everywhere with `on`; partly in the band with `auto`, whose smooth intermittency the
/// derivative follows too).
#[test]
fn turbulent_linearisation_matches_finite_differences() {
    use tiltpad::bearing::equilibrium::{solve_equilibrium, EquilibriumParams};
    use tiltpad::bearing::{BearingModel, NoCancel, OperatingPoint};
    for mode in ["on", "auto"] {
        let case = crate::common::case(
            "large-5pad-transition.toml",
            &["mesh.fidelity=\"preview\"", "thermal.model=\"isothermal\"", &format!("physics.turbulence=\"{mode}\"")],
        );
        let mut model = BearingModel::new(&case).unwrap();
        let op = OperatingPoint::isothermal(&case);
        let eq = solve_equilibrium(&mut model, &op, EquilibriumParams::default(), None, &NoCancel).unwrap();
        let mut worst = 0.0_f64;
        for k in 0..model.pads.len() {
            let inp = op.film_inputs(k);
            let q0 = model.local(k, &eq.u);
            let pm = &mut model.pads[k];
            pm.film.set_coordinates(&q0).unwrap();
            pm.film.solve(&inp, true).unwrap();
            assert!(mode != "on" || pm.film.turbulence_qp().is_some(), "pad {k} has turbulent points");
            let lin = pm.film.linearize(&inp);
            let step = |j: usize| if j == 2 { 1e-7 } else { 1e-4 * case.bearing.assembled_clearance_m };
            for j in 0..q0.len() {
                let mut f = [vec![], vec![]];
                for (side, sign) in [1.0, -1.0].iter().enumerate() {
                    let mut q = q0.clone();
                    q[j] += sign * step(j);
                    pm.film.set_coordinates(&q).unwrap();
                    pm.film.solve(&inp, true).unwrap();
                    f[side] = pm.film.generalized_forces();
                }
                for (i, (fp, fm)) in f[0].iter().zip(&f[1]).enumerate() {
                    let fd = -(fp - fm) / (2.0 * step(j));
                    let scale = lin.stiffness[(i, i)].abs().max(lin.stiffness[(j, j)].abs());
                    let err = (fd - lin.stiffness[(i, j)]).abs() / scale;
                    worst = worst.max(err);
                    assert!(
                        err < 1e-4,
                        "{mode} pad {k} K[{i}][{j}]: analytic {:.6e} vs FD {fd:.6e}",
                        lin.stiffness[(i, j)]
                    );
                }
            }
        }
        println!("{mode}: worst |K − K_FD| {worst:.2e} of the diagonal");
    }
}

/// The local Reynolds field the field view draws (`FieldKind::Reynolds`): at every node `ρ U h / µ` of the
/// solution's own thickness and viscosity; its largest value is the report's `Re max`, and the share of
/// nodes past the band's start is the report's transitional fraction (the large bearing at 3600 rpm, THD
/// off, preview: about half the film past 1000).
#[test]
fn the_reynolds_field_is_the_reports_local_reynolds_number() {
    use tiltpad::scene::field::{FieldKind, PadMap};
    let s = crate::common::solve(
        "large-5pad-transition.toml",
        &["mesh.fidelity=\"preview\"", "thermal.model=\"isothermal\""],
    );
    let (rho, u) = (860.0, s.derived.speed_rad_s * 0.2);
    let (mut nodes, mut past, mut max) = (0_usize, 0_usize, 0.0_f64);
    for p in &s.pads {
        let f = &p.field;
        assert_eq!(f.reynolds.len(), f.film_thickness_m.len());
        for ((re, h), mu) in f.reynolds.iter().zip(&f.film_thickness_m).zip(&f.viscosity_pa_s) {
            assert!((re / (rho * u * h / mu) - 1.0).abs() < 1e-12);
            nodes += 1;
            past += usize::from(*re > 1000.0);
            max = max.max(*re);
        }
    }
    #[allow(clippy::cast_precision_loss)]
    let fraction = past as f64 / nodes as f64;
    println!("Re max {max:.0}, {:.1} % of the nodes past 1000", 100.0 * fraction);
    assert!((max / s.regime.reynolds_max - 1.0).abs() < 1e-12);
    assert!((fraction - s.regime.transitional_fraction).abs() < 1e-12);
    assert!(fraction > 0.2 && fraction < 0.8);
    let maps = PadMap::all(&s, FieldKind::Reynolds);
    assert_eq!(maps.len(), s.pads.len());
    assert!((maps.iter().map(|m| m.max).fold(0.0, f64::max) / max - 1.0).abs() < 1e-12);
    assert!(FieldKind::available(&s).contains(&FieldKind::Reynolds));
}
