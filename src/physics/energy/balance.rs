//! The energy balance of one pad's film (docs/MODEL.md §12: friction power = heat carried away by the oil + heat
//! conducted out).
//!
//! Every term is integrated independently of the assembled system:
//!
//! ```text
//! mechanical power in  P = U ∫ (θ µ U/h + (h/2) ∂p/∂s) dA     journal shear (film fraction θ)
//!                        + ∫ p v_inj dA                         pressure work of the injected oil
//!                        + ∫ (p v_inj + (4/3) µ v_inj²/h) dA    explicit injection terms of docs/MODEL.md §3
//!                        + p_le Q_le                            flow work of the oil entering at the ram pressure
//! heat to the oil      H = ρ c_p Σ_edge nodes o_j (T_j − T_ref)  (Reynolds-consistent nodal flows)
//!                        + ρ c_p Σ_interior o_j (T_j − T_ref)   (flows into/out of ruptured zones, FilmHeat doc)
//!                        − ρ c_p Σ_j [∫ v⁺ N_j (T_inj − T_ref) + ∫ v⁻ N_j (T_j − T_ref)]
//! conducted out        C = ∫ q_pad + ∫ q_j − Σ_j ∫ κ/l0 [v > 0] N_j (T_inj − T_j) − (conduction in across the inlet)
//! heat generated       G = ∫ Φ dA + ∫ (p v_inj + (4/3) µ v_inj²/h) dA     the energy equation's sources
//! closure              (G − H − C) / G                                    the energy equation's conservation
//! power identity       (P − G) / P                                        the film solve's
//! ```
//!
//! The two checks are kept apart because they test different things. The closure tests the energy
//! equation: everything it was given leaves with the oil or by conduction (round-off on every thermal solve).
//! The power identity tests the film: the power the journal's shear delivers equals the heat the film
//! dissipates, `∫ h³/(12µ) |∇p|² = U ∫ (h/2) ∂p/∂s + ∫ p v_inj (+ p_le Q_le)`, which the Reynolds and Gümbel
//! solves satisfy to round-off (their pressure is the discrete solution tested with itself). The
//! mass-conserving solve's Couette term carries the film fraction and its upwinding at the nodes next to
//! rupture and reformation, where the pressure gradient is small but not zero; there the identity holds
//! only as the mesh is refined (a discretisation error, measured in docs/VALIDATION.md).
//!
//! `T_ref` is the supply temperature (any value gives the same H when the nodal flows balance; the choice
//! only weights a residual mass imbalance). The inlet conduction is the reaction of the leading-edge
//! Dirichlet rows, computed by the caller from the unmodified rows.

use serde::{Deserialize, Serialize};

use crate::mesh::grid::NodeSite;
use crate::physics::energy::{Exchange, FilmEnergy, FlowState, Oil};
use crate::physics::reynolds::PadFilm;

/// Heat balance of one pad's film [W], whole pad.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct FilmHeat {
    /// Journal shear power with the film fraction.
    pub shear_power_w: f64,
    /// Pressure work of the injected oil (dissipated in the film).
    pub pumping_power_w: f64,
    /// The explicit injection work terms `p v + (4/3) µ v²/h`.
    pub injection_work_w: f64,
    /// ∫ Φ dA (equals shear + pumping power up to round-off).
    pub dissipation_w: f64,
    /// Flow work of the oil entering through a pressurised leading edge, `p_le Q_le` (the ram pressure,
    /// docs/MODEL.md §2.2; 0 with an ambient leading edge).
    #[serde(default)]
    pub inlet_pressure_work_w: f64,
    /// Enthalpy rise of the oil through the pad's edges and orifices, relative to the supply temperature.
    pub heat_to_oil_w: f64,
    /// Into the pad through the film-side surface (BC2/BC3; 0 for BC1, whose film is adiabatic).
    pub heat_to_pad_w: f64,
    /// Into the journal (BC3).
    pub heat_to_journal_w: f64,
    /// Conducted into the film from the injection pipes.
    pub orifice_conduction_in_w: f64,
    /// Conducted into the film across the leading edge (Dirichlet reaction).
    pub inlet_conduction_in_w: f64,
    /// Heat carried by the flow the cavitation model moves into (or out of) ruptured zones inside the pad:
    /// `ρ c_p Σ_interior o_j (T_j − T_ref)` over interior nodes outside the orifices. Swift–Stieber
    /// cavitation does not conserve mass at rupture and reformation (the isothermal mass balance books the
    /// same flows as `to_cavitation`); counted with the oil. Zero for a full film.
    pub cavitation_transport_w: f64,
}

impl FilmHeat {
    /// Mechanical power delivered to the film.
    #[must_use]
    pub fn power_in(&self) -> f64 {
        self.shear_power_w + self.pumping_power_w + self.injection_work_w + self.inlet_pressure_work_w
    }
    /// Heat conducted out of the film (net).
    #[must_use]
    pub fn conducted_out(&self) -> f64 {
        self.heat_to_pad_w + self.heat_to_journal_w - self.orifice_conduction_in_w - self.inlet_conduction_in_w
    }
    /// Sums two pads' balances.
    #[must_use]
    pub fn add(&self, o: &Self) -> Self {
        Self {
            shear_power_w: self.shear_power_w + o.shear_power_w,
            pumping_power_w: self.pumping_power_w + o.pumping_power_w,
            injection_work_w: self.injection_work_w + o.injection_work_w,
            dissipation_w: self.dissipation_w + o.dissipation_w,
            inlet_pressure_work_w: self.inlet_pressure_work_w + o.inlet_pressure_work_w,
            heat_to_oil_w: self.heat_to_oil_w + o.heat_to_oil_w,
            heat_to_pad_w: self.heat_to_pad_w + o.heat_to_pad_w,
            heat_to_journal_w: self.heat_to_journal_w + o.heat_to_journal_w,
            orifice_conduction_in_w: self.orifice_conduction_in_w + o.orifice_conduction_in_w,
            inlet_conduction_in_w: self.inlet_conduction_in_w + o.inlet_conduction_in_w,
            cavitation_transport_w: self.cavitation_transport_w + o.cavitation_transport_w,
        }
    }
    /// Heat carried away by the oil: through the edges and orifices, and into ruptured zones.
    #[must_use]
    pub fn carried_by_oil(&self) -> f64 {
        self.heat_to_oil_w + self.cavitation_transport_w
    }
    /// The heat the energy equation generates: `∫ Φ dA` and the explicit injection work (module
    /// documentation, G).
    #[must_use]
    pub fn heat_generated(&self) -> f64 {
        self.dissipation_w + self.injection_work_w
    }
    /// (G − H − C)/G: the energy equation's conservation.
    #[must_use]
    pub fn closure(&self) -> f64 {
        let g = self.heat_generated();
        if g.abs() > 0.0 {
            (g - self.carried_by_oil() - self.conducted_out()) / g
        } else {
            0.0
        }
    }
    /// (P − G)/P: the film's power identity (module documentation).
    #[must_use]
    pub fn power_identity(&self) -> f64 {
        let p = self.power_in();
        if p.abs() > 0.0 {
            (p - self.heat_generated()) / p
        } else {
            0.0
        }
    }
}

/// Inputs of [`FilmEnergy::heat_balance`] besides the film and its flow.
#[derive(Debug, Clone, Copy)]
pub struct BalanceInputs<'a> {
    pub oil: &'a Oil,
    pub exchange: Exchange,
    /// Film temperature at the nodes.
    pub t: &'a [f64],
    /// Pad film-side surface temperature at the (film) nodes; `None` for BC1.
    pub t_pad: Option<&'a [f64]>,
    pub t_journal: f64,
    /// Reference temperature of the enthalpies (the supply temperature).
    pub t_ref: f64,
    /// Sum of the leading-edge Dirichlet reactions `Σ (K T − F)_i` (modelled domain).
    pub dirichlet_reaction: f64,
}

impl FilmEnergy {
    /// The energy balance of the film with temperature `inp.t` (module documentation).
    #[must_use]
    pub fn heat_balance(&self, film: &PadFilm, st: &FlowState, inp: &BalanceInputs<'_>) -> FilmHeat {
        let g = &film.geom;
        let rc = inp.oil.capacity();
        let t = inp.t;
        let mut out = FilmHeat {
            shear_power_w: st.shear_power,
            pumping_power_w: st.pumping_power,
            injection_work_w: st.injection_work,
            dissipation_w: st.dissipation,
            inlet_conduction_in_w: g.sym * inp.dirichlet_reaction,
            inlet_pressure_work_w: film.leading_edge_pressure_work(),
            ..FilmHeat::default()
        };
        let (mut edges, mut leak) = (0.0, 0.0);
        for (j, &o) in st.outflow.iter().enumerate() {
            let dh = rc * o * (t[j] - inp.t_ref);
            let interior = matches!(g.sites[j], NodeSite::Interior | NodeSite::Symmetry);
            if interior && !self.in_orifice[j] {
                leak += dh;
            } else {
                edges += dh;
            }
        }
        let (mut inj, mut pipe) = (0.0, 0.0);
        for j in 0..t.len() {
            inj += rc
                * (st.inj.inflow[j] * (st.injection_temperature_c - inp.t_ref) + st.inj.drain[j] * (t[j] - inp.t_ref));
            pipe += st.inj.pipe[j] * (st.injection_temperature_c - t[j]);
        }
        let (mut to_pad, mut to_journal) = (0.0, 0.0);
        if inp.exchange != Exchange::Adiabatic {
            for (e, nodes) in g.elements.iter().enumerate() {
                for (k, q) in g.qp[e].iter().enumerate() {
                    let ex = st.exchange_at(e, k, inp.exchange, inp.oil.conductivity);
                    let tq: f64 = (0..4).map(|a| q.n[a] * t[nodes[a]]).sum();
                    let tp: f64 = inp.t_pad.map_or(tq, |tp| (0..4).map(|a| q.n[a] * tp[nodes[a]]).sum());
                    let q_pad = ex.gamma * tq - ex.beta * tp - ex.phi * inp.t_journal;
                    let s_loss = ex.c * tq - ex.g_pad * tp - ex.g_j * inp.t_journal;
                    to_pad += q.w * q_pad;
                    to_journal += q.w * (s_loss - q_pad);
                }
            }
        }
        out.heat_to_oil_w = g.sym * (edges - inj);
        out.cavitation_transport_w = g.sym * leak;
        out.orifice_conduction_in_w = g.sym * pipe;
        out.heat_to_pad_w = g.sym * to_pad;
        out.heat_to_journal_w = g.sym * to_journal;
        out
    }
}
