//! The oil-film energy equation on one pad (docs/MODEL.md §3), stabilised with SUPG.
//!
//! ## Equation
//! Steady, temperature `T(s, z)` averaged across the film, with the film flow per unit width
//! `q_s = −h³/(12µ) ∂p/∂s + U h_oil/2`, `q_z = −h³/(12µ) ∂p/∂z`:
//!
//! ```text
//! ∇·(κ h θ ∇T) − ρ c_p q·∇T + Φ − S_loss
//!   + [ κ (T_inj − T)/l0 + ρ c_p v_inj⁺ (T_inj − T) + p v_inj + (4/3) µ v_inj²/h ]   (inside orifices) = 0
//! Φ = θ µ U²/h + h³/(12µ) |∇p|²                                                       (viscous dissipation)
//! turbulent film (physics::turbulence): h³/(12µ) → G_s h³/(12µ), G_z h³/(12µ) per direction in q and Φ,
//! θ µ U²/h → θ C_f µ U²/h, κ → F_plane κ in the film plane and F_across κ across it (pad/journal exchange)
//! v_inj = g (p_inj − p)/(4 µ_inj l0)                                                  (orifice.rs)
//! ```
//!
//! Choices, each stated because the equation leaves them open (docs/MODEL.md §3.1):
//! - **Conduction** in conservative form `∇·(κ h ∇T)` (the film-integrated conductive flux is `−κ h ∇T`);
//!   the thesis' `κ h ∇²T` differs by `κ ∇h·∇T`, negligible (and the conservative form keeps the balance).
//! - **Injection**: the enthalpy term uses `v_inj⁺ = max(v_inj, 0)` and the pipe conduction term acts only
//!   where oil is injected: where the film drains into the hole (`v_inj < 0`) the oil leaves at the film
//!   temperature, which the advective form already accounts for. `p v_inj` and `(4/3) µ v_inj²/h` are kept
//!   as the thesis writes them, for both signs. Note that `Φ` already dissipates the injected oil's pressure
//!   energy (`∫ h³/(12µ)|∇p|² dA = U ∫ (h/2) ∂p/∂s dA + ∫ p v_inj dA` exactly), so the explicit `p v_inj`
//!   counts that work a second time; it is kept because the thesis' equation has it, and reported separately.
//! - **Cavitated zones** (`cavitated_film = "striated"`): the oil flows as striations. Along each axial row,
//!   downstream of the rupture (thickness `h_r` there, the rupture placed between the last full-film node
//!   and the first cavitated one by the pressure's approach to zero, [`FilmEnergy::film_fraction`]), the
//!   fraction of the gap filled with oil is `θ = min(1, h_r/h)` (mass conservation of the Couette flow
//!   `U θ h/2` at ambient pressure), and every
//!   per-area term of the film (shear heating, conduction, the capacity flux through `h_oil = θ h`, the
//!   exchange with pad and journal) is scaled by θ. With `"full_film"` θ ≡ 1, as in the thesis.
//!
//! ## Heat exchange with pad and journal, `S_loss` (docs/MODEL.md §3; [`Exchange`])
//! - BC1: `S_loss = 0` (adiabatic film; the pad takes the film temperature).
//! - BC2: `S_loss = θ H (T − T_pad)`.
//! - BC3 (Knight & Barrett, corrected parabola): `T(y) = T_pad + 2(3T − T_j − 2T_pad) y/h + 3(T_j − 2T + T_pad)(y/h)²`
//!   gives `q_pad = (2κ/h)(3T − T_j − 2T_pad)` into the pad and `q_j = (2κ/h)(3T − 2T_j − T_pad)` into the
//!   journal, `S_loss = θ (q_pad + q_j) = θ (6κ/h)(2T − T_j − T_pad)` ([`knight_barrett`]).
//!
//! ## Weak form, term by term (test function `W_i = N_i + τ a·∇N_i`, `a = ρ c_p q`)
//! ```text
//!   ∫ κ h θ ∇T·∇N_i                           conduction in the film plane (Galerkin)
//! + ∫ (a·∇T) W_i                              heat carried by the flow (SUPG, fem::supg)
//! + ∫ c T W_i                                 linear sinks: exchange (θ H, θ 12κ/h), injection (ρ c_p v⁺ + κ/l0)
//! − ∫ g_pad T_pad W_i                         exchange with the pad surface (θ H, θ 6κ/h): coupling block
//! = ∫ (Φ + p v + (4/3)µv²/h) W_i              heat generated
//! + ∫ (ρ c_p v⁺ + κ/l0) T_inj W_i             injected oil
//! + ∫ θ (6κ/h) T_j W_i                        journal (BC3)
//! ```
//! plus, optionally, Codina's crosswind discontinuity capturing computed from the previous outer iterate
//! (`fem::supg::add_crosswind_point`). `T` is prescribed on the leading-edge nodes where oil flows in;
//! elsewhere the boundary is natural (zero conductive flux; the advected heat leaves with the oil).
//!
//! ## Conservation
//! Summed over all nodes the SUPG weights add up to the Galerkin ones (`Σ W_i = 1`), and the advective term
//! equals `ρ c_p Σ_j o_j T_j` with `o_j = ∫ q·∇N_j + ∫ v_inj N_j` the consistent nodal outflow of the same
//! flux field. In full film `o_j` is the Reynolds solver's own consistent flow (same quadrature), zero at
//! interior nodes; so the discrete energy balance (generation = heat carried by the oil through the edges +
//! heat conducted out) closes to round-off there. With the Reynolds and Gümbel conditions `o_j` is not zero at
//! the interior nodes of rupture and reformation (they do not conserve mass); the balance books that heat
//! apart (`cavitation_transport_w`). After a mass-conserving film solve the Galerkin flux alone leaves
//! `o_j = (D θ)_j / 12` there, the oil the film's upwinding `D` moves between neighbours
//! (physics::reynolds::jfo_exchange); the equation carries those exchanges too, upwind, as
//! `ρ c_p m (T_to − T_from)` in the receiving row, and adds them to `o_j`, which is then zero at every
//! interior node to round-off. [`FlowState::outflow`] exposes `o_j`.
//!
//! Units: SI, temperatures °C, heats in W (whole pad: symmetry factor applied where stated).

mod balance;
mod striated;

pub use balance::{BalanceInputs, FilmHeat};

use crate::fem::quad4::QuadPoint;
use crate::fem::supg::{
    add_crosswind_point, add_point, element_average, supg_tau, test_weights, Adr, Stabilisation, CROSSWIND_CONSTANT,
};
use crate::fem::GeneralPattern;
use crate::mesh::grid::NodeSite;
use crate::physics::reynolds::{FilmGeometry, FilmInputs, NodeExchange, OrificeOperator, PadFilm};
use crate::physics::turbulence::Factors;

/// Sub-cells per direction for elements cut by an orifice edge (the value the Reynolds solver uses, so the
/// injected flow is integrated identically; checked by a test).
const ORIFICE_SUBCELLS: usize = 6;

/// Oil properties.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Oil {
    /// ρ [kg/m³]
    pub density: f64,
    /// c_p [J/(kg K)]
    pub specific_heat: f64,
    /// κ [W/(m K)]
    pub conductivity: f64,
}

impl Oil {
    /// Volumetric heat capacity ρ c_p [J/(m³ K)].
    #[must_use]
    pub fn capacity(&self) -> f64 {
        self.density * self.specific_heat
    }
}

/// Film–pad exchange as it enters the film rows.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Exchange {
    /// BC1: adiabatic film.
    Adiabatic,
    /// BC2: `θ H (T − T_pad)`.
    Convective { h: f64 },
    /// BC3: Knight & Barrett parabola.
    Parabolic,
}

/// Linear exchange coefficients at a point for `S_loss = c T − g_pad T_pad − g_j T_j` and the pad influx
/// `q_pad = γ T − β T_pad − φ T_j` (both per unit film area, θ applied).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ExchangeCoefficients {
    pub c: f64,
    pub g_pad: f64,
    pub g_j: f64,
    pub gamma: f64,
    pub beta: f64,
    pub phi: f64,
}

impl Exchange {
    /// Coefficients for film thickness `h`, film fraction `theta`, oil conductivity `kappa`.
    #[must_use]
    pub fn coefficients(self, h: f64, theta: f64, kappa: f64) -> ExchangeCoefficients {
        match self {
            Self::Adiabatic => ExchangeCoefficients::default(),
            Self::Convective { h: hc } => {
                let k = theta * hc;
                ExchangeCoefficients { c: k, g_pad: k, g_j: 0.0, gamma: k, beta: k, phi: 0.0 }
            }
            Self::Parabolic => {
                let k = theta * kappa / h;
                ExchangeCoefficients {
                    c: 12.0 * k,
                    g_pad: 6.0 * k,
                    g_j: 6.0 * k,
                    gamma: 6.0 * k,
                    beta: 4.0 * k,
                    phi: 2.0 * k,
                }
            }
        }
    }
}

/// The Knight & Barrett profile across the film (docs/MODEL.md §3, corrected): temperature at `y/h = eta` for
/// mean film temperature `t`, pad surface `t_pad` (y = 0) and journal `t_j` (y = h).
#[must_use]
pub fn knight_barrett(t: f64, t_pad: f64, t_j: f64, eta: f64) -> f64 {
    t_pad + 2.0 * (3.0 * t - t_j - 2.0 * t_pad) * eta + 3.0 * (t_j - 2.0 * t + t_pad) * eta * eta
}

/// Injection conditions of the pad's orifices.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Injection {
    pub pressure: f64,
    pub viscosity: f64,
    pub temperature_c: f64,
}

#[derive(Debug, Clone)]
struct OrificePoint {
    q: QuadPoint,
    /// The paraboloid weight g [m²].
    g: f64,
    /// Orifice (capillary) length l0 [m].
    length: f64,
}

/// Orifice sub-cell quadrature of one element.
#[derive(Debug, Clone)]
struct OrificeCell {
    element: usize,
    points: Vec<OrificePoint>,
}

/// Geometry-lifetime data of a pad's energy equation.
#[derive(Debug, Clone)]
pub struct FilmEnergy {
    cells: Vec<OrificeCell>,
    /// Element diameters (crosswind term).
    pub diameters: Vec<f64>,
    /// Nodes of the elements an orifice touches (where a film opened to the hole can drain into it).
    pub in_orifice: Vec<bool>,
    n_nodes: usize,
}

/// Nodal (lumped) injection data of the current flow, modelled domain.
#[derive(Debug, Clone, Default)]
struct NodalInjection {
    /// `∫ v⁺ N_j dA` [m³/s]: oil injected at node j.
    inflow: Vec<f64>,
    /// `∫ v⁻ N_j dA` [m³/s] (≤ 0): oil drained into the hole at node j.
    drain: Vec<f64>,
    /// `∫ κ/l0 [v > 0] N_j dA` [W/K]: conductance to the injection pipe.
    pipe: Vec<f64>,
    /// `∫ (p v + (4/3) µ v²/h) N_j dA` [W].
    work: Vec<f64>,
    /// Per orifice element: (element, reaction density, source density) averaged over the element, for τ
    /// and the crosswind residual.
    elements: Vec<(usize, f64, f64)>,
}

/// The film quantities of one outer iteration (flow, dissipation, injection), at quadrature points.
#[derive(Debug, Clone)]
pub struct FlowState {
    /// Film fraction θ at the nodes.
    pub theta: Vec<f64>,
    theta_qp: Vec<[f64; 4]>,
    h_qp: Vec<[f64; 4]>,
    /// ρ c_p q at the quadrature points.
    a: Vec<[[f64; 2]; 4]>,
    /// Dissipation Φ [W/m²].
    phi: Vec<[f64; 4]>,
    /// Eddy-diffusivity factors (in-plane, across the film) at the quadrature points; empty where the film is
    /// laminar everywhere (physics::turbulence).
    eddy: Vec<[[f64; 2]; 4]>,
    inj: NodalInjection,
    /// Consistent nodal outflow `o_j` of the flux field [m³/s] (modelled domain, no symmetry factor), the
    /// mass-conserving film's exchanges included.
    pub outflow: Vec<f64>,
    /// After a mass-conserving film solve: the oil its upwinding moves between neighbouring nodes
    /// ([`NodeExchange`]), carried as heat by the energy equation too (module documentation, Conservation).
    exchanges: Vec<NodeExchange>,
    /// Journal shear power with the film fraction, `U ∫ (θ µ U/h + (h/2) ∂p/∂s) dA` [W] (whole pad).
    pub shear_power: f64,
    /// `∫ p v_inj dA`: pressure work of the injected oil dissipated in the film [W] (whole pad).
    pub pumping_power: f64,
    /// `∫ (p v_inj + (4/3) µ v_inj²/h) dA`: the explicit injection work terms [W] (whole pad).
    pub injection_work: f64,
    /// `∫ Φ dA` [W] (whole pad).
    pub dissipation: f64,
    injection_temperature_c: f64,
}

impl FlowState {
    /// Film fraction at quadrature point k of element e.
    #[must_use]
    pub fn theta_at(&self, e: usize, k: usize) -> f64 {
        self.theta_qp[e][k]
    }
    /// Exchange coefficients at quadrature point k of element e (a turbulent film conducts across its
    /// thickness as if its conductivity were `F_across κ`).
    #[must_use]
    pub fn exchange_at(&self, e: usize, k: usize, exchange: Exchange, kappa: f64) -> ExchangeCoefficients {
        exchange.coefficients(self.h_qp[e][k], self.theta_qp[e][k], kappa * self.eddy_at(e, k)[1])
    }
    /// Eddy-diffusivity factors `[F_plane, F_across]` at quadrature point k of element e (1 laminar).
    #[must_use]
    pub fn eddy_at(&self, e: usize, k: usize) -> [f64; 2] {
        self.eddy.get(e).map_or([1.0, 1.0], |x| x[k])
    }
}

impl FilmEnergy {
    /// Builds the orifice quadrature of a film geometry.
    #[must_use]
    pub fn new(geom: &FilmGeometry) -> Self {
        let mut cells = Vec::new();
        for (e, r) in geom.rects.iter().enumerate() {
            let mut points = Vec::new();
            for op in &geom.orifices {
                let o = op.orifice;
                if !o.touches(r.s0, r.s0 + r.ds, r.z0, r.z0 + r.dz) {
                    continue;
                }
                for q in r.subcell_points(ORIFICE_SUBCELLS) {
                    let g = o.g(q.s, q.z);
                    if g > 0.0 {
                        points.push(OrificePoint { q, g, length: o.length });
                    }
                }
            }
            if !points.is_empty() {
                cells.push(OrificeCell { element: e, points });
            }
        }
        let diameters = geom.rects.iter().map(|r| r.ds.hypot(r.dz)).collect();
        let mut in_orifice = vec![false; geom.n_nodes()];
        for cell in &cells {
            for &k in &geom.elements[cell.element] {
                in_orifice[k] = true;
            }
        }
        Self { cells, diameters, in_orifice, n_nodes: geom.n_nodes() }
    }

    /// Evaluates the flow, dissipation and injection of the film's last solve.
    #[must_use]
    pub fn flow_state(
        &self,
        film: &PadFilm,
        inp: &FilmInputs<'_>,
        inj: &Injection,
        oil: &Oil,
        striated: bool,
    ) -> FlowState {
        let g = &film.geom;
        let u = inp.surface_speed;
        let rc = oil.capacity();
        let mu_qp = film.viscosity_qp();
        let theta = Self::film_fraction(film, striated);
        let ne = g.elements.len();
        let mut st = FlowState {
            theta_qp: vec![[1.0; 4]; ne],
            h_qp: film.h.qp.clone(),
            a: vec![[[0.0; 2]; 4]; ne],
            phi: vec![[0.0; 4]; ne],
            eddy: Vec::new(),
            inj: NodalInjection {
                inflow: vec![0.0; self.n_nodes],
                drain: vec![0.0; self.n_nodes],
                pipe: vec![0.0; self.n_nodes],
                work: vec![0.0; self.n_nodes],
                elements: Vec::with_capacity(self.cells.len()),
            },
            outflow: vec![0.0; self.n_nodes],
            exchanges: if striated { film.upwinding_exchanges(u) } else { Vec::new() },
            shear_power: 0.0,
            pumping_power: 0.0,
            injection_work: 0.0,
            dissipation: 0.0,
            injection_temperature_c: inj.temperature_c,
            theta,
        };
        // Turbulent film: the Reynolds solve's own Poiseuille and Couette multipliers (so the flux field stays
        // its consistent flow), and the eddy diffusivity of heat at the same local Reynolds number.
        let turb = film.turbulence_qp();
        if let Some(t) = turb {
            let law = &inp.turbulence;
            st.eddy = t
                .iter()
                .zip(film.h.qp.iter().zip(mu_qp))
                .map(|(f, (h, mu))| {
                    std::array::from_fn(|k| {
                        if f[k].gamma == 0.0 {
                            return [1.0, 1.0];
                        }
                        let re = law.reynolds(u, h[k], mu[k]);
                        let (plane, across) = law.thermal_factors(re, mu[k] * oil.specific_heat / oil.conductivity);
                        [plane, across]
                    })
                })
                .collect();
        }
        for (e, nodes) in g.elements.iter().enumerate() {
            for (k, q) in g.qp[e].iter().enumerate() {
                let h = film.h.qp[e][k];
                let mu = mu_qp[e][k];
                let th: f64 = (0..4).map(|a| q.n[a] * st.theta[nodes[a]]).sum();
                let (mut ps, mut pz) = (0.0, 0.0);
                for a in 0..4 {
                    ps += q.dn_ds[a] * film.p[nodes[a]];
                    pz += q.dn_dz[a] * film.p[nodes[a]];
                }
                let cp = h * h * h / (12.0 * mu);
                let f = turb.map_or(Factors::LAMINAR, |t| t[e][k]);
                let (cs, cz) = (cp * f.gs, cp * f.gz);
                let qs = -cs * ps + 0.5 * u * th * h;
                let qz = -cz * pz;
                st.theta_qp[e][k] = th;
                st.a[e][k] = [rc * qs, rc * qz];
                // (the laminar film keeps the laminar arithmetic, bit for bit)
                let poiseuille = if turb.is_some() { cs * ps * ps + cz * pz * pz } else { cp * (ps * ps + pz * pz) };
                st.phi[e][k] = th * f.cf * mu * u * u / h + poiseuille;
                st.dissipation += g.sym * q.w * st.phi[e][k];
                st.shear_power += g.sym * q.w * u * (th * f.cf * mu * u / h + 0.5 * h * ps);
                for a in 0..4 {
                    st.outflow[nodes[a]] += q.w * (qs * q.dn_ds[a] + qz * q.dn_dz[a]);
                }
            }
        }
        for x in &st.exchanges {
            st.outflow[x.to] += x.m;
            st.outflow[x.from] -= x.m;
        }
        // The pumping power in the film's form of the capillary term, so that it meets the film's power
        // identity to round-off: lumped (each node's own pressure) for a hole open to ambient, consistent (the
        // interpolated pressure) for an injecting one (physics::reynolds::geometry).
        let lumped = OrificeOperator::lumped_at(inj.pressure);
        for cell in &self.cells {
            let nodes = g.elements[cell.element];
            let area: f64 = g.qp[cell.element].iter().map(|q| q.w).sum();
            let (mut c_avg, mut f_avg) = (0.0, 0.0);
            for op in &cell.points {
                let q = &op.q;
                let p: f64 = (0..4).map(|a| q.n[a] * film.p[nodes[a]]).sum();
                let h: f64 = (0..4).map(|a| q.n[a] * film.h.node[nodes[a]]).sum();
                let mu: f64 = (0..4).map(|a| q.n[a] * mu_qp[cell.element][a]).sum::<f64>().max(f64::MIN_POSITIVE);
                let v = op.g * (inj.pressure - p) / (4.0 * inj.viscosity * op.length);
                let work = p * v + 4.0 / 3.0 * mu * v * v / h;
                let pipe = if v > 0.0 { oil.conductivity / op.length } else { 0.0 };
                for a in 0..4 {
                    let wn = q.w * q.n[a];
                    st.outflow[nodes[a]] += wn * v;
                    st.inj.inflow[nodes[a]] += wn * v.max(0.0);
                    st.inj.drain[nodes[a]] += wn * v.min(0.0);
                    st.inj.pipe[nodes[a]] += wn * pipe;
                    st.inj.work[nodes[a]] += wn * work;
                    if lumped {
                        let pa = film.p[nodes[a]];
                        st.pumping_power +=
                            g.sym * wn * pa * op.g * (inj.pressure - pa) / (4.0 * inj.viscosity * op.length);
                    }
                }
                if !lumped {
                    st.pumping_power += g.sym * q.w * p * v;
                }
                let reaction = rc * v.max(0.0) + pipe;
                c_avg += q.w * reaction / area;
                f_avg += q.w * (reaction * inj.temperature_c + work) / area;
                st.injection_work += g.sym * q.w * work;
            }
            st.inj.elements.push((cell.element, c_avg, f_avg));
        }
        st
    }
}

/// Where the film rows go in a (possibly coupled) sparse system.
#[derive(Debug, Clone, Copy)]
pub struct FilmLayout {
    /// Group index of film element 0 (groups `first + e` are the film elements, 4 nodes each).
    pub film_groups: usize,
    /// Group index of the coupling group of element 0 (`[film nodes…, pad face nodes…]`), if coupled.
    pub coupling_groups: Option<usize>,
}

/// Right-hand sides by superposition: column 0 holds the sources and the injected-oil terms; column 1 the
/// response to a unit inlet temperature; column 2 the response to a unit journal temperature.
pub const RHS_COLUMNS: usize = 3;

impl FilmEnergy {
    /// Adds the film rows (module documentation) to `values` and the three right-hand-side columns `rhs`
    /// (column-major, `RHS_COLUMNS × n`). Dirichlet rows are imposed by the caller.
    /// `t_prev`: previous film temperature for the crosswind term ([`Stabilisation::SupgCrosswind`]).
    #[allow(clippy::too_many_arguments)]
    pub fn assemble(
        &self,
        film: &PadFilm,
        st: &FlowState,
        oil: &Oil,
        exchange: Exchange,
        stab: Stabilisation,
        t_prev: Option<&[f64]>,
        pattern: &GeneralPattern,
        layout: FilmLayout,
        values: &mut [f64],
        rhs: &mut [f64],
    ) {
        let g = &film.geom;
        let n = pattern.n;
        let mut inj_of = vec![(0.0, 0.0); g.elements.len()];
        for &(e, c, f) in &st.inj.elements {
            inj_of[e] = (c, f);
        }
        for (e, nodes) in g.elements.iter().enumerate() {
            let qp = &g.qp[e];
            let mut coef = [Adr::default(); 4];
            let mut ex = [ExchangeCoefficients::default(); 4];
            for k in 0..4 {
                let (h, th) = (st.h_qp[e][k], st.theta_qp[e][k]);
                let [plane, across] = st.eddy_at(e, k);
                ex[k] = exchange.coefficients(h, th, oil.conductivity * across);
                coef[k] = Adr { d: oil.conductivity * plane * h * th, a: st.a[e][k], c: ex[k].c, f: st.phi[e][k] };
            }
            // Injection reaction and source averaged over the element, for τ and the crosswind residual.
            let (c_inj, f_inj) = inj_of[e];
            let (mut avg, grad) = element_average(qp, &coef);
            avg.c += c_inj;
            let tau = if stab == Stabilisation::Galerkin { 0.0 } else { supg_tau(&avg, &grad) };
            let mut ke = [[0.0; 4]; 4];
            let mut fe = [0.0; 4];
            let mut fj = [0.0; 4];
            let mut kc = [[0.0; 4]; 4];
            let prev = match (stab, t_prev) {
                (Stabilisation::SupgCrosswind, Some(t)) => Some(nodes.map(|k| t[k])),
                _ => None,
            };
            for (k, q) in qp.iter().enumerate() {
                add_point(q, &coef[k], tau, &mut ke, &mut fe);
                if let Some(tp) = &prev {
                    let full = Adr { c: coef[k].c + c_inj, f: coef[k].f + f_inj, ..coef[k] };
                    add_crosswind_point(q, &full, tp, self.diameters[e], CROSSWIND_CONSTANT, &mut ke);
                }
                if ex[k].g_pad != 0.0 || ex[k].g_j != 0.0 {
                    let w = test_weights(q, coef[k].a, tau);
                    for a in 0..4 {
                        fj[a] += q.w * ex[k].g_j * w[a];
                        for b in 0..4 {
                            kc[a][b] -= q.w * ex[k].g_pad * w[a] * q.n[b];
                        }
                    }
                }
            }
            let pos = pattern.group_positions(layout.film_groups + e);
            for a in 0..4 {
                rhs[nodes[a]] += fe[a];
                rhs[2 * n + nodes[a]] += fj[a];
                for b in 0..4 {
                    values[pos[4 * a + b]] += ke[a][b];
                }
            }
            if let Some(cg) = layout.coupling_groups {
                let pos = pattern.group_positions(cg + e);
                for a in 0..4 {
                    for b in 0..4 {
                        values[pos[8 * a + 4 + b]] += kc[a][b];
                    }
                }
            }
        }
        // The mass-conserving film's exchanges between neighbours, upwind: the oil arriving at `to` brings
        // the temperature of `from` (advective form, like the flux field's term).
        let rc = oil.capacity();
        for x in &st.exchanges {
            let c = rc * x.m;
            // The exchanges come from the film's own element pattern, so (to, from) is always an entry here.
            let off = pattern.position(x.to, x.from);
            debug_assert!(off.is_some(), "nodes {} and {} share no element", x.to, x.from);
            if let Some(k) = off {
                values[pattern.diag[x.to]] += c;
                values[k] -= c;
            }
        }
        // Injection, lumped on the nodes.
        for j in 0..g.n_nodes() {
            let r = rc * st.inj.inflow[j] + st.inj.pipe[j];
            if r != 0.0 || st.inj.work[j] != 0.0 {
                values[pattern.diag[j]] += r;
                rhs[j] += r * st.injection_temperature_c + st.inj.work[j];
            }
        }
    }

    /// Leading-edge nodes where oil flows in (the Dirichlet set of the film).
    #[must_use]
    pub fn inflow_nodes(film: &PadFilm, st: &FlowState) -> Vec<usize> {
        let g = &film.geom;
        (0..g.n_nodes()).filter(|&k| g.sites[k] == NodeSite::Leading && st.outflow[k] < 0.0).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn knight_barrett_parabola_meets_its_three_conditions() {
        let (t, tp, tj) = (72.0, 65.0, 55.0);
        assert!((knight_barrett(t, tp, tj, 0.0) - tp).abs() < 1e-12, "T(0) = T_pad");
        assert!((knight_barrett(t, tp, tj, 1.0) - tj).abs() < 1e-12, "T(h) = T_j");
        // Mean over the film by 3-point Gauss (exact for a parabola).
        let g = 0.5 * (3.0_f64 / 5.0).sqrt();
        let mean = 5.0 / 18.0 * knight_barrett(t, tp, tj, 0.5 - g)
            + 8.0 / 18.0 * knight_barrett(t, tp, tj, 0.5)
            + 5.0 / 18.0 * knight_barrett(t, tp, tj, 0.5 + g);
        assert!((mean - t).abs() < 1e-12, "mean {mean} = T");
        // The thesis' printed form gives −T_j at y = h (the misprint docs/MODEL.md §3.5 corrects).
        let printed =
            |eta: f64| tp + 2.0 * (3.0 * t - 2.0 * tj - 2.0 * tp) * eta + 3.0 * (tj - 2.0 * t + tp) * eta * eta;
        assert!((printed(1.0) - tj).abs() > 1.0);
        // Fluxes: κ dT/dy at the pad (y = 0), −κ dT/dy at the journal (y = h), by central differences, which
        // are exact for a parabola (the polynomial extends past the film), so only round-off remains.
        let (kappa, h) = (0.13, 40e-6);
        let d = 1e-2;
        let slope =
            |eta: f64| (knight_barrett(t, tp, tj, eta + d) - knight_barrett(t, tp, tj, eta - d)) / (2.0 * d * h);
        let ex = Exchange::Parabolic.coefficients(h, 1.0, kappa);
        let q_pad = ex.gamma * t - ex.beta * tp - ex.phi * tj;
        assert!((q_pad - kappa * slope(0.0)).abs() < 1e-12 * q_pad.abs(), "q_pad {q_pad} vs {}", kappa * slope(0.0));
        let q_j = -kappa * slope(1.0);
        // S_loss = q_pad + q_j.
        let s_loss = ex.c * t - ex.g_pad * tp - ex.g_j * tj;
        assert!((s_loss - (q_pad + q_j)).abs() < 1e-12 * s_loss.abs(), "S_loss {s_loss} vs {}", q_pad + q_j);
    }
}
