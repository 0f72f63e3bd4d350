//! The thermal system of one pad: the film energy equation ([`crate::physics::energy`]) and, when needed,
//! the pad's heat conduction ([`crate::physics::pad_conduction`]) in one sparse system.
//!
//! For a fixed flow and viscosity field the system is linear in the temperatures, and the only unknowns
//! coupling it to the rest of the bearing are the pad's inlet temperature `T_in` (leading-edge Dirichlet
//! value, from the groove mixing balance) and the journal temperature `T_j` (BC3). So the system is
//! factorised once per outer iteration and solved for three right-hand sides:
//!
//! ```text
//! T = ψ₀ + T_in ψ_in + T_j ψ_j        (film and pad nodes)
//! ```
//!
//! and every quantity the mixing balance needs (inflow, trailing-edge outflow and its mean temperature,
//! back-flow at the leading edge, mean film temperature, heat flux into the journal) is an affine function
//! of (T_in, T_j) ([`Affine`]). The bearing loop then solves a small dense system for all pads' inlet
//! temperatures and the journal temperature at once: no inner mixing iteration.
//!
//! Systems per pad, each with its pattern and symbolic factorisation built once (on first use): film only
//! (BC1: film and pad decouple), film + pad (BC2/BC3, LU) and, for BC1 after convergence, the pad alone with
//! the film temperature on its face (symmetric positive definite: Cholesky, much cheaper than the LU whose
//! fill follows the structure of AᵀA).

use crate::fem::supg::Stabilisation;
use crate::fem::{GeneralPattern, LuSolver, SolverError};
use crate::mesh::grid::NodeSite;
use crate::physics::energy::{Exchange, FilmEnergy, FilmLayout, FlowState, Injection, Oil, RHS_COLUMNS};
use crate::physics::pad_conduction::{PadConduction, PadDirichletSolver, PadLayout, PadMaterial};
use crate::physics::reynolds::{FilmInputs, PadFilm};

/// `c0 + c_in T_in + c_j T_j`.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Affine {
    pub c0: f64,
    pub c_in: f64,
    pub c_j: f64,
}

impl Affine {
    #[must_use]
    pub fn at(&self, t_in: f64, t_j: f64) -> f64 {
        self.c0 + self.c_in * t_in + self.c_j * t_j
    }
    fn of(f: impl Fn(usize) -> f64) -> Self {
        Self { c0: f(0), c_in: f(1), c_j: f(2) }
    }
}

/// Everything one pad's thermal solve needs besides the film.
#[derive(Debug, Clone, Copy)]
pub struct ThermalSetup {
    pub oil: Oil,
    pub injection: Injection,
    pub exchange: Exchange,
    pub material: PadMaterial,
    pub stabilisation: Stabilisation,
    pub striated: bool,
}

#[derive(Debug, Clone)]
struct System {
    pattern: GeneralPattern,
    lu: LuSolver,
    values: Vec<f64>,
    rhs: Vec<f64>,
    film: FilmLayout,
    pad: Option<PadLayout>,
}

impl System {
    fn new(pattern: GeneralPattern, film: FilmLayout, pad: Option<PadLayout>) -> Result<Self, SolverError> {
        let lu = LuSolver::new(&pattern)?;
        let (nnz, n) = (pattern.nnz(), pattern.n);
        Ok(Self { lu, values: vec![0.0; nnz], rhs: vec![0.0; RHS_COLUMNS * n], pattern, film, pad })
    }
}

/// Geometry-lifetime thermal data of one pad, and the previous film temperature (crosswind term).
#[derive(Debug, Clone)]
pub struct PadThermal {
    pub energy: FilmEnergy,
    pub conduction: Option<PadConduction>,
    film_only: System,
    coupled: Option<System>,
    /// Film temperature of the previous outer iteration.
    pub t_prev: Option<Vec<f64>>,
    /// Factorisations done (for reports).
    pub factorizations: usize,
}

/// An unmodified Dirichlet row: its entries `(column, value)` and its three right-hand sides.
type DirichletRow = (Vec<(usize, f64)>, [f64; 3]);

/// The superposed solution of one pad (module documentation).
#[derive(Debug, Clone)]
pub struct PadTemperatures {
    pub flow: FlowState,
    n_film: usize,
    /// Pad unknowns (0 without a pad solve).
    n_pad: usize,
    /// Columns ψ₀, ψ_in, ψ_j over all unknowns (film, then pad).
    cols: Vec<f64>,
    n: usize,
    /// Leading-edge Dirichlet rows before they were replaced by identity rows.
    dirichlet_rows: Vec<DirichletRow>,
    /// Oil flowing in through the leading edge [m³/s] (whole pad).
    pub q_in: f64,
    /// Out through the trailing edge [m³/s] (whole pad).
    pub q_te: f64,
    /// Flow-weighted trailing-edge temperature.
    pub t_te: Affine,
    /// Out through the leading edge (back-flow into the groove) [m³/s].
    pub q_back: f64,
    pub t_back: Affine,
    /// Film-fraction-weighted mean film temperature.
    pub mean_film: Affine,
    /// ∫ θ dA [m²] (whole pad): the weight of `mean_film`.
    pub area: f64,
    /// Heat flux into the journal [W] (whole pad; BC3 only, else 0).
    pub journal_flux: Affine,
    /// Nodes with a prescribed (inlet) temperature.
    pub inlet_nodes: Vec<usize>,
    /// No oil flowed in through the leading edge: its whole edge was held at the inlet temperature.
    pub no_inflow: bool,
}

impl PadTemperatures {
    fn column(&self, t_in: f64, t_j: f64, range: std::ops::Range<usize>) -> Vec<f64> {
        range.map(|i| self.cols[i] + t_in * self.cols[self.n + i] + t_j * self.cols[2 * self.n + i]).collect()
    }
    /// Film temperature at the nodes.
    #[must_use]
    pub fn film(&self, t_in: f64, t_j: f64) -> Vec<f64> {
        self.column(t_in, t_j, 0..self.n_film)
    }
    /// Pad temperatures (all pad nodes, layer-major), if the pad was solved.
    #[must_use]
    pub fn pad(&self, t_in: f64, t_j: f64) -> Option<Vec<f64>> {
        (self.n_pad > 0).then(|| self.column(t_in, t_j, self.n_film..self.n_film + self.n_pad))
    }
    /// Σ of the unmodified Dirichlet rows' residuals `(K T − F)_i` (modelled domain).
    #[must_use]
    pub fn dirichlet_reaction(&self, t_in: f64, t_j: f64) -> f64 {
        let all = self.column(t_in, t_j, 0..self.n);
        self.dirichlet_rows
            .iter()
            .map(|(row, f)| row.iter().map(|&(c, v)| v * all[c]).sum::<f64>() - (f[0] + t_in * f[1] + t_j * f[2]))
            .sum()
    }
}

impl PadThermal {
    /// Builds the systems of a pad (`conduction` = `None` for a sector without a pad solid).
    ///
    /// # Errors
    /// If a symbolic factorisation fails.
    pub fn new(film: &PadFilm, conduction: Option<PadConduction>) -> Result<Self, SolverError> {
        let g = &film.geom;
        let nf = g.n_nodes();
        let energy = FilmEnergy::new(g);
        let film_only = System::new(
            GeneralPattern::from_groups(nf, g.elements.iter().map(|e| &e[..])),
            FilmLayout { film_groups: 0, coupling_groups: None },
            None,
        )?;
        Ok(Self { energy, conduction, film_only, coupled: None, t_prev: None, factorizations: 0 })
    }

    /// The film + pad system (built on first use).
    fn coupled_system(&mut self, film: &PadFilm) -> Result<&mut System, SolverError> {
        if self.coupled.is_none() {
            let c = self.conduction.as_ref().ok_or_else(|| SolverError::Singular("no pad solid".into()))?;
            let g = &film.geom;
            let (nf, ne) = (g.n_nodes(), g.elements.len());
            let n = nf + c.mesh.n_nodes();
            let mut groups: Vec<Vec<usize>> = g.elements.iter().map(|e| e.to_vec()).collect();
            groups.extend(
                g.elements.iter().map(|e| vec![e[0], e[1], e[2], e[3], e[0] + nf, e[1] + nf, e[2] + nf, e[3] + nf]),
            );
            groups.extend(c.hex_groups(nf).map(|h| h.to_vec()));
            let pattern = GeneralPattern::from_groups(n, groups.iter().map(Vec::as_slice));
            let pad = PadLayout { offset: nf, hex_groups: 2 * ne, coupling_groups: ne };
            self.coupled =
                Some(System::new(pattern, FilmLayout { film_groups: 0, coupling_groups: Some(ne) }, Some(pad))?);
        }
        self.coupled.as_mut().ok_or_else(|| SolverError::Singular("no pad system".into()))
    }

    /// BC1, after convergence: the pad's temperatures with the film temperature `film_t` on its face, using
    /// `solver` (shared by identical pads). `None` for a sector without a pad solid.
    ///
    /// # Errors
    /// A failed factorisation.
    pub fn solve_pad_bc1(
        &self,
        solver: &mut PadDirichletSolver,
        film_t: &[f64],
        material: &PadMaterial,
    ) -> Result<Option<Vec<f64>>, SolverError> {
        let Some(c) = &self.conduction else { return Ok(None) };
        c.solve_dirichlet(solver, material, film_t).map(Some)
    }

    /// True if the pad has a solid to conduct heat.
    #[must_use]
    pub fn has_pad(&self) -> bool {
        self.conduction.is_some()
    }

    /// Assembles, factorises and solves the pad's thermal system for the film's last solve: the film alone
    /// for BC1, film and pad together for BC2/BC3.
    ///
    /// # Errors
    /// A singular system (never NaN temperatures).
    pub fn solve(
        &mut self,
        film: &PadFilm,
        inp: &FilmInputs<'_>,
        setup: &ThermalSetup,
    ) -> Result<PadTemperatures, SolverError> {
        let flow = self.energy.flow_state(film, inp, &setup.injection, &setup.oil, setup.striated);
        let coupled = self.conduction.is_some() && setup.exchange != Exchange::Adiabatic;
        let t_prev = self.t_prev.take();
        if coupled {
            self.coupled_system(film)?;
        }
        let Self { energy, conduction, film_only, coupled: coupled_sys, .. } = self;
        let sys = match coupled_sys {
            Some(c) if coupled => c,
            _ => film_only,
        };
        let n = sys.pattern.n;
        sys.values.fill(0.0);
        sys.rhs.fill(0.0);
        energy.assemble(
            film,
            &flow,
            &setup.oil,
            setup.exchange,
            setup.stabilisation,
            t_prev.as_deref(),
            &sys.pattern,
            sys.film,
            &mut sys.values,
            &mut sys.rhs,
        );
        let g = &film.geom;
        if let (Some(pl), Some(cond)) = (sys.pad.filter(|_| coupled), conduction.as_ref()) {
            cond.assemble_body(&setup.material, &sys.pattern, pl, &mut sys.values, &mut sys.rhs);
            let coef = |e: usize, k: usize| {
                let c = flow.exchange_at(e, k, setup.exchange, setup.oil.conductivity);
                (c.gamma, c.beta, c.phi)
            };
            cond.film_face_exchange(g, &coef, &sys.pattern, pl, &mut sys.values, &mut sys.rhs);
        }
        // Inlet: prescribed temperature where oil flows in through the leading edge.
        let mut inlet_nodes = FilmEnergy::inflow_nodes(film, &flow);
        let no_inflow = inlet_nodes.is_empty();
        if no_inflow {
            inlet_nodes = (0..g.n_nodes()).filter(|&k| g.sites[k] == NodeSite::Leading).collect();
        }
        let mut dirichlet_rows = Vec::with_capacity(inlet_nodes.len());
        for &k in &inlet_nodes {
            dirichlet_rows
                .push((sys.pattern.row_entries(&sys.values, k), [sys.rhs[k], sys.rhs[n + k], sys.rhs[2 * n + k]]));
            sys.pattern.set_identity_row(&mut sys.values, k);
            sys.rhs[k] = 0.0;
            sys.rhs[n + k] = 1.0;
            sys.rhs[2 * n + k] = 0.0;
        }
        sys.lu.factor(&sys.pattern, &sys.values)?;
        let mut cols = sys.rhs.clone();
        sys.lu.solve_in_place(&mut cols, n)?;
        self.factorizations += 1;
        self.t_prev = t_prev;
        let nf = g.n_nodes();
        let n_pad = if coupled { n - nf } else { 0 };
        let sym = g.sym;
        let col = |c: usize, i: usize| cols[c * n + i];
        // Flows and flow-weighted temperatures.
        let weighted = |nodes: &[usize]| -> (f64, Affine) {
            let q: f64 = nodes.iter().map(|&k| flow.outflow[k]).sum();
            let t = if q.abs() > 0.0 {
                Affine::of(|c| nodes.iter().map(|&k| flow.outflow[k] * col(c, k)).sum::<f64>() / q)
            } else {
                Affine::default()
            };
            (sym * q, t)
        };
        let te: Vec<usize> = (0..nf).filter(|&k| g.sites[k] == NodeSite::Trailing && flow.outflow[k] > 0.0).collect();
        let back: Vec<usize> = (0..nf)
            .filter(|&k| g.sites[k] == NodeSite::Leading && flow.outflow[k] > 0.0 && !inlet_nodes.contains(&k))
            .collect();
        let (q_te, t_te) = weighted(&te);
        let (q_back, t_back) = weighted(&back);
        let q_in = -sym * inlet_nodes.iter().map(|&k| flow.outflow[k].min(0.0)).sum::<f64>();
        // Area means and the journal flux, by nodal weights.
        let (mut w_mean, mut w_t, mut w_p, mut k_j) = (vec![0.0; nf], vec![0.0; nf], vec![0.0; nf], 0.0);
        for (e, nodes) in g.elements.iter().enumerate() {
            for (k, q) in g.qp[e].iter().enumerate() {
                let th = flow.theta_at(e, k);
                let c = flow.exchange_at(e, k, setup.exchange, setup.oil.conductivity);
                k_j += q.w * (c.g_j - c.phi);
                for a in 0..4 {
                    w_mean[nodes[a]] += q.w * th * q.n[a];
                    w_t[nodes[a]] += q.w * (c.c - c.gamma) * q.n[a];
                    w_p[nodes[a]] += q.w * (c.g_pad - c.beta) * q.n[a];
                }
            }
        }
        let area: f64 = w_mean.iter().sum::<f64>().max(f64::MIN_POSITIVE);
        let mean_film = Affine::of(|c| (0..nf).map(|i| w_mean[i] * col(c, i)).sum::<f64>() / area);
        let journal_flux = if setup.exchange == Exchange::Parabolic {
            let mut j = Affine::of(|c| {
                (0..nf)
                    .map(|i| w_t[i] * col(c, i) - w_p[i] * if coupled { col(c, nf + i) } else { col(c, i) })
                    .sum::<f64>()
            });
            j.c_j -= k_j;
            Affine { c0: sym * j.c0, c_in: sym * j.c_in, c_j: sym * j.c_j }
        } else {
            Affine::default()
        };
        Ok(PadTemperatures {
            flow,
            n_film: nf,
            n_pad,
            cols,
            n,
            dirichlet_rows,
            q_in,
            q_te,
            t_te,
            q_back,
            t_back,
            mean_film,
            area: sym * area,
            journal_flux,
            inlet_nodes,
            no_inflow,
        })
    }
}
