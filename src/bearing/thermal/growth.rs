//! Thermal growth of the pads and the journal, fed back into the films inside the THD loop (TEHD,
//! docs/MODEL.md §5–§7).
//!
//! ## Equations
//! ```text
//! h = h_rigid(q) + u_p(s, z) − δ_j                 each film's extra thickness (PadFilm::set_extra_thickness)
//! δ_j = α_j R (T_j − T_ref)                        journal growth, uniform around the bearing
//! h += δ_h cos(θ − θ_p),  δ_h = α_h R_p (T_h − T_ref)   housing and pivot growth (a case option, given T_h):
//!                                                  the pivot (at R_p = R + Cb + t) moves out along its line;
//!                                                  a fixed sector's bore (R + Cp) grows uniformly instead
//! K u = f_th,  f_th = ∫ Bᵀ D α_p (T − T_ref) m dV   pad solid (physics::pad_elastic), m = [1 1 1 0 0 0]ᵀ,
//!                                                  supported statically determinately at its pivot line
//! u_p = u · e_r on the film face                   positive away from the journal (opens the film)
//! ```
//! `T` is the pad's 3-D temperature on the pad mesh (the thermal model's, same mesh as the elastic one).
//!
//! The pad solid, its supports and its layers: [`crate::bearing::thermal::growth_solid`].
//!
//! With all three expansion coefficients zero ([`Growth::is_off`]) nothing is built and the THD loop is the
//! rigid one. The housing's growth is given (its temperature is a case input), so it needs no solid: each
//! pivot moves out along its line, and it is in the films from the loop's first equilibrium
//! ([`housing_only`]).

use crate::bearing::report::error::ElasticWork;
use crate::fem::solid8::Elastic;
use crate::mesh::pad3d::PadMesh;
use crate::model::{Case, PadKind};
use crate::physics::reynolds::SampledField;

use crate::bearing::film::model::BearingModel;
use crate::bearing::report::error::SolveError;
use crate::bearing::thermal::growth_solid::{effective_step, growth_layer_step, GrowthSolver};

/// Convergence of the growth in the thermal loop: its largest change between outer iterations, relative to
/// the assembled clearance.
pub const GROWTH_TOL: f64 = 1e-4;

/// Expansion coefficients and reference temperature of the thermal growth.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Growth {
    /// Pad thermal expansion coefficient α_p [1/K].
    pub pad_per_k: f64,
    /// Journal thermal expansion coefficient α_j [1/K].
    pub journal_per_k: f64,
    /// Temperature at which the clearances are given [°C].
    pub reference_c: f64,
    /// Housing and pivot expansion coefficient α_h [1/K] and the housing temperature [°C].
    pub housing_per_k: f64,
    pub housing_c: f64,
}

impl Growth {
    /// The growth of a case (`thermal.pad_expansion_per_k`, `thermal.journal_expansion_per_k`,
    /// `thermal.reference_temperature_c`, default the supply temperature).
    #[must_use]
    pub fn of(case: &Case) -> Self {
        let t = &case.thermal;
        Self {
            pad_per_k: t.pad_expansion_per_k,
            journal_per_k: t.journal_expansion_per_k,
            reference_c: t.reference_temperature_c.unwrap_or(case.operating.supply_temperature_c),
            housing_per_k: t.housing_expansion_per_k,
            housing_c: t.housing_temperature_c.unwrap_or(case.operating.supply_temperature_c),
        }
    }

    #[must_use]
    pub fn is_off(&self) -> bool {
        self.pad_per_k == 0.0 && self.journal_per_k == 0.0 && self.housing_per_k == 0.0
    }

    /// The housing's growth under each pad of a case: the outward displacement of the pad's pivot (of a fixed
    /// sector's bore) [m], and its film's extra thickness at the film nodes of `model` [m]: `δ_h cos(θ − θ_p)`
    /// for a tilting pad (a translation along the pivot line), `δ_h` for a fixed sector (a uniformly
    /// grown bore). Empty when α_h = 0.
    #[must_use]
    pub fn housing(&self, case: &Case, model: &BearingModel) -> (Vec<f64>, Vec<Vec<f64>>) {
        if self.housing_per_k == 0.0 {
            return (Vec::new(), Vec::new());
        }
        let b = &case.bearing;
        let r = b.journal_radius_m;
        let rise = self.housing_c - self.reference_c;
        case.bearing
            .pads
            .iter()
            .zip(&model.pads)
            .map(|(pad, pm)| {
                let grid = &pm.film.geom.grid;
                if pad.kind == PadKind::Tilting {
                    let delta = self.housing_per_k * (r + b.assembled_clearance_m + pad.thickness_m) * rise;
                    let film = (0..grid.n_nodes())
                        .map(|n| delta * (pad.leading_edge_rad + grid.s[grid.col_row(n).0] / r - pad.pivot_rad).cos())
                        .collect();
                    (delta, film)
                } else {
                    let delta = self.housing_per_k * pad.bore_radius_m(r) * rise;
                    (delta, vec![delta; grid.n_nodes()])
                }
            })
            .unzip()
    }
}

/// The thermal growth model of a bearing: one factorised solid per distinct pad.
pub struct TehdModel {
    pub growth: Growth,
    journal_radius: f64,
    solvers: Vec<GrowthSolver>,
    /// The housing's growth under each pad ([`Growth::housing`]).
    housing: (Vec<f64>, Vec<Vec<f64>>),
    /// Which solver each pad uses (`None`: no pad solid, only the journal grows under it).
    solver_of: Vec<Option<usize>>,
}

/// One evaluation of the growth: each pad's film-face growth at its film nodes [m] (zeros without a pad
/// solid), each pad solid's nodal displacement (empty without one), and the journal growth [m].
#[derive(Debug, Clone, PartialEq, Default)]
pub struct GrowthField {
    pub pad_film_m: Vec<Vec<f64>>,
    /// (u_r, u_θ, u_z) at every node of pad k's solid [m] ([`PadGrowth::nodal_polar_m`]).
    pub pad_nodal_m: Vec<Vec<f64>>,
    pub journal_m: f64,
    /// The housing's growth ([`Growth::housing`]): each pad's pivot displacement [m] and the extra film
    /// thickness it makes at the film nodes [m] (both empty without housing growth).
    pub housing_m: Vec<f64>,
    pub housing_film_m: Vec<Vec<f64>>,
}

impl GrowthField {
    /// The extra film thickness of pad k at its nodes: `u_p − δ_j + δ_h cos(θ − θ_p)`.
    #[must_use]
    pub fn extra(&self, k: usize) -> Vec<f64> {
        let housing = self.housing_film_m.get(k);
        self.pad_film_m[k].iter().enumerate().map(|(n, u)| u - self.journal_m + housing.map_or(0.0, |h| h[n])).collect()
    }

    /// Largest extra film thickness (against no growth at all) [m].
    #[must_use]
    pub fn magnitude(&self) -> f64 {
        let largest = |v: &[Vec<f64>]| v.iter().flatten().fold(0.0_f64, |m, x| m.max(x.abs()));
        self.journal_m.abs() + largest(&self.pad_film_m) + largest(&self.housing_film_m)
    }

    /// Largest change of the extra film thickness against another evaluation [m] (the housing's growth is
    /// given, so it does not change).
    #[must_use]
    pub fn change(&self, other: &Self) -> f64 {
        let dj = (self.journal_m - other.journal_m).abs();
        let dp = self
            .pad_film_m
            .iter()
            .flatten()
            .zip(other.pad_film_m.iter().flatten())
            .fold(0.0_f64, |m, (a, b)| m.max((a - b).abs()));
        dj + dp
    }
}

impl TehdModel {
    /// The growth model of a case on its bearing model and pad meshes (`meshes[k]`: pad k's solid, shared
    /// with the thermal model); `None` when the growth is off.
    ///
    /// # Errors
    /// [`SolveError::PadElastic`] naming the pad if its elastic model fails.
    pub fn new(
        case: &Case,
        model: &BearingModel,
        meshes: &[Option<std::sync::Arc<PadMesh>>],
    ) -> Result<Option<Self>, SolveError> {
        Self::with_layer_step(case, model, meshes, None)
    }

    /// [`Self::new`] with the growth solids' layer step given (`None`: [`growth_layer_step`] of each mesh).
    ///
    /// # Errors
    /// As [`Self::new`].
    pub fn with_layer_step(
        case: &Case,
        model: &BearingModel,
        meshes: &[Option<std::sync::Arc<PadMesh>>],
        step: Option<usize>,
    ) -> Result<Option<Self>, SolveError> {
        let growth = Growth::of(case);
        if growth.is_off() {
            return Ok(None);
        }
        let mut solvers: Vec<GrowthSolver> = Vec::new();
        let mut solver_of = Vec::with_capacity(model.pads.len());
        for (k, (pad, mesh)) in case.bearing.pads.iter().zip(meshes).enumerate() {
            let Some(mesh) = mesh.clone().filter(|_| growth.pad_per_k != 0.0) else {
                solver_of.push(None);
                continue;
            };
            let material = Elastic {
                youngs_modulus: pad.youngs_modulus_pa,
                poisson_ratio: pad.poisson_ratio,
                density: pad.density_kg_per_m3,
            };
            let pivot_from_le = pad.pivot_rad - pad.leading_edge_rad;
            let step =
                effective_step(&mesh, step.unwrap_or_else(|| growth_layer_step(case.mesh.fidelity, mesh.layers)));
            let same = |s: &GrowthSolver| {
                s.mesh.same_shape(&mesh)
                    && s.step == step
                    && (s.pivot_from_le - pivot_from_le).abs() < 1e-12
                    && s.material == material
            };
            let index = match solvers.iter().position(same) {
                Some(i) => i,
                None => {
                    let half = model.pads[k].film.geom.grid.half;
                    let s = GrowthSolver::new(mesh, step, pad.pivot_rad, pivot_from_le, material, half)
                        .map_err(|error| SolveError::PadElastic { pad: k, what: ElasticWork::ThermalGrowth, error })?;
                    solvers.push(s);
                    solvers.len() - 1
                }
            };
            solver_of.push(Some(index));
        }
        let housing = growth.housing(case, model);
        Ok(Some(Self { growth, journal_radius: case.bearing.journal_radius_m, solvers, housing, solver_of }))
    }

    /// Distinct factorised pad solids.
    #[must_use]
    pub fn distinct_solids(&self) -> usize {
        self.solvers.len()
    }

    /// The growth for the pads' temperatures (`pad_c[k]`: all pad nodes of pad k [°C], `None` without a
    /// solid) and the journal temperature `t_j` [°C]; `film_nodes[k]`: pad k's film node count. The solids
    /// are factorised already, so nothing here can fail.
    #[must_use]
    pub fn evaluate(&mut self, pad_c: &[Option<Vec<f64>>], t_j: f64, film_nodes: &[usize]) -> GrowthField {
        let g = self.growth;
        let mut pad_film_m: Vec<Vec<f64>> =
            (0..pad_c.len()).map(|k| vec![0.0; film_nodes.get(k).copied().unwrap_or(0)]).collect();
        let mut pad_nodal_m = vec![Vec::new(); pad_c.len()];
        // The pads of each distinct solid, solved together.
        for (i, solver) in self.solvers.iter_mut().enumerate() {
            let pads: Vec<(usize, &Vec<f64>)> = pad_c
                .iter()
                .enumerate()
                .filter_map(|(k, t)| {
                    t.as_ref().filter(|_| self.solver_of.get(k).copied().flatten() == Some(i)).map(|t| (k, t))
                })
                .collect();
            let loads: Vec<f64> = pads
                .iter()
                .flat_map(|(_, t)| {
                    let dt: Vec<f64> = t.iter().map(|x| x - g.reference_c).collect();
                    solver.reduced_load(g.pad_per_k, &dt)
                })
                .collect();
            for ((k, _), u) in pads.iter().zip(solver.displacements(loads)) {
                pad_film_m[*k] = u.film_m;
                pad_nodal_m[*k] = u.nodal_polar_m;
            }
        }
        GrowthField {
            pad_film_m,
            pad_nodal_m,
            journal_m: g.journal_per_k * self.journal_radius * (t_j - g.reference_c),
            housing_m: self.housing.0.clone(),
            housing_film_m: self.housing.1.clone(),
        }
    }
}

/// The growth before any temperature is known: the housing's alone (it is given, not computed), so that the
/// loop's first equilibrium — which decides the lightly loaded pads — sees the bearing the housing makes.
/// `None` without housing growth.
#[must_use]
pub fn housing_only(case: &Case, model: &BearingModel) -> Option<GrowthField> {
    let (housing_m, housing_film_m) = Growth::of(case).housing(case, model);
    (!housing_m.is_empty()).then(|| GrowthField {
        pad_film_m: model.pads.iter().map(|p| vec![0.0; p.film.geom.n_nodes()]).collect(),
        pad_nodal_m: vec![Vec::new(); model.pads.len()],
        journal_m: 0.0,
        housing_m,
        housing_film_m,
    })
}

/// Installs a growth field as each film's extra thickness (nodal values, interpolated bilinearly to the
/// quadrature points: the trace of the pad's trilinear displacement).
pub fn install(model: &mut BearingModel, field: &GrowthField) {
    for (k, pm) in model.pads.iter_mut().enumerate() {
        let node = field.extra(k);
        let g = &pm.film.geom;
        let qp = g
            .elements
            .iter()
            .zip(&g.qp)
            .map(|(nodes, q)| q.each_ref().map(|p| (0..4).map(|a| p.n[a] * node[nodes[a]]).sum::<f64>()))
            .collect();
        pm.film.set_extra_thickness(Some(SampledField { qp, node }));
    }
}

/// Removes any growth from the films.
pub fn clear(model: &mut BearingModel) {
    for pm in &mut model.pads {
        pm.film.set_extra_thickness(None);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bearing::film::model::pad_grid;
    use crate::model::load_case;
    use crate::physics::pad_elastic::Solid;

    fn fillon(sets: &[&str]) -> Case {
        let set: Vec<String> =
            std::iter::once("mesh.fidelity=preview").chain(sets.iter().copied()).map(str::to_string).collect();
        load_case(include_str!("../../../cases/fillon-a.toml"), &set).unwrap().1
    }

    fn meshes(case: &Case, model: &BearingModel) -> Vec<Option<std::sync::Arc<PadMesh>>> {
        case.bearing
            .pads
            .iter()
            .enumerate()
            .map(|(k, p)| {
                let grid = pad_grid(case, k);
                let r = case.bearing.journal_radius_m;
                debug_assert_eq!(grid.n_nodes(), model.pads[k].film.geom.n_nodes());
                Some(std::sync::Arc::new(PadMesh::extrude(
                    &grid,
                    r,
                    p.leading_edge_rad,
                    p.bore_radius_m(r),
                    p.thickness_m,
                    case.mesh.pad_radial_elements,
                )))
            })
            .collect()
    }

    /// A uniform temperature rise ΔT is stress-free: the pad grows as a similarity about its clamped pivot
    /// point P, u = α ΔT (x − P), so the film face at angle φ from the pivot moves radially by
    /// α ΔT (R_b − (R_b + t) cos φ) (−α t ΔT at the pivot: towards the journal). Clamping the patch restrains
    /// only the patch's own growth, a local effect at the back.
    #[test]
    fn uniform_heating_is_a_similarity_about_the_pivot_and_identical_pads_share_a_solid() {
        uniform_heating_similarity("mesh.pad_radial_elements=2", None);
    }

    /// The same with four layers and a growth solid of every second one: the skipped node layers'
    /// displacement, interpolated in r, is the similarity's too (linear in r).
    #[test]
    fn uniform_heating_on_every_second_layer_is_the_similarity_on_every_node() {
        uniform_heating_similarity("mesh.pad_radial_elements=4", Some(2));
    }

    const STEEL: [&str; 3] = [
        "thermal.pad_expansion_ppm_per_k=12",
        "thermal.journal_expansion_ppm_per_k=11",
        "thermal.reference_temperature_c=20",
    ];

    fn uniform_heating_similarity(layers: &str, step: Option<usize>) {
        let case = fillon(&[STEEL[0], STEEL[1], STEEL[2], layers]);
        let model = BearingModel::new(&case).unwrap();
        let meshes = meshes(&case, &model);
        let mut tehd = TehdModel::with_layer_step(&case, &model, &meshes, step).unwrap().unwrap();
        assert_eq!(tehd.distinct_solids(), 1, "four identical pads");
        assert_eq!(tehd.solvers[0].step, step.unwrap_or(1));
        let dt = 30.0;
        let pad_c: Vec<Option<Vec<f64>>> =
            meshes.iter().map(|m| m.as_ref().map(|m| vec![20.0 + dt; m.n_nodes()])).collect();
        let nodes: Vec<usize> = model.pads.iter().map(|p| p.film.geom.n_nodes()).collect();
        let g = tehd.evaluate(&pad_c, 50.0, &nodes);
        // Journal: α_j R ΔT_j.
        assert!((g.journal_m - 1.1e-5 * 0.05 * 30.0).abs() < 1e-18, "{}", g.journal_m);
        for k in 1..4 {
            assert_eq!(g.pad_film_m[k], g.pad_film_m[0]);
        }
        let pad = &case.bearing.pads[0];
        let (rb, t) = (pad.bore_radius_m(case.bearing.journal_radius_m), pad.thickness_m);
        let geom = &model.pads[0].film.geom;
        let scale = 1.2e-5 * dt * t;
        let worst = (0..geom.n_nodes()).fold(0.0_f64, |m, n| {
            let exact = 1.2e-5 * dt * (rb - (rb + t) * (geom.node_theta[n] - pad.pivot_rad).cos());
            m.max((g.pad_film_m[0][n] - exact).abs() / scale)
        });
        eprintln!("uniform heating: largest deviation from the similarity {worst:.2e} of α t ΔT");
        assert!(worst < 1e-9, "{worst}");
        // The whole solid, in polar components: u_r = α ΔT (r − (R_b + t) cos φ), u_θ = α ΔT (R_b + t) sin φ,
        // u_z = α ΔT z (the similarity about the pivot line, which lies at z from −L/2 to L/2).
        let solid = Solid::from_pad(meshes[0].as_ref().unwrap());
        let u = &g.pad_nodal_m[0];
        assert_eq!(u.len(), 3 * solid.n_nodes());
        assert_eq!(&u[..3 * geom.n_nodes()].iter().step_by(3).copied().collect::<Vec<_>>(), &g.pad_film_m[0]);
        let worst = solid.nodes.iter().enumerate().fold(0.0_f64, |m, (n, x)| {
            let (r, phi) = (x[0].hypot(x[1]), x[1].atan2(x[0]) - pad.pivot_rad);
            let exact = [r - (rb + t) * phi.cos(), (rb + t) * phi.sin(), x[2]].map(|v| 1.2e-5 * dt * v);
            (0..3).fold(m, |m, c| m.max((u[3 * n + c] - exact[c]).abs() / scale))
        });
        eprintln!("uniform heating, whole solid: largest deviation {worst:.2e} of α t ΔT");
        assert!(worst < 1e-9, "{worst}");
        // Off without coefficients.
        assert!(TehdModel::new(&fillon(&[]), &model, &meshes).unwrap().is_none());
    }

    /// The growth solid of every second layer against the solid of all four layers, on two temperature fields
    /// (the bounds are the differences measured, a regression check, not a claim of accuracy: see the module
    /// documentation for both against eight layers)
    /// (film face rising 20 K along the arc, 5 K towards the mid-plane):
    /// - conducted: the face's variation decays into the pad as a harmonic (source-free) field does,
    ///   exp(−π d / ℓ) with d the depth and ℓ the arc length;
    /// - steep: the face's rise falls off within 0.3 of the thickness (heat that has not yet conducted in);
    ///   the first merged layer holds 37 % of the thickness, so its sampled temperatures miss much of it.
    #[test]
    fn every_second_layer_against_all_layers() {
        let case = fillon(&[STEEL[0], STEEL[1], STEEL[2], "mesh.pad_radial_elements=4"]);
        let model = BearingModel::new(&case).unwrap();
        let meshes = meshes(&case, &model);
        let pad = &case.bearing.pads[0];
        let (rb, t) = (pad.bore_radius_m(case.bearing.journal_radius_m), pad.thickness_m);
        let nodes: Vec<usize> = model.pads.iter().map(|p| p.film.geom.n_nodes()).collect();
        let mut all = TehdModel::with_layer_step(&case, &model, &meshes, Some(1)).unwrap().unwrap();
        let mut every_second = TehdModel::with_layer_step(&case, &model, &meshes, Some(2)).unwrap().unwrap();
        assert_eq!(every_second.solvers[0].step, 2);
        let (n_all, n_second) = (all.solvers[0].unknowns(), every_second.solvers[0].unknowns());
        eprintln!("unknowns: {n_all} on all layers, {n_second} on every second");
        // 3 of 5 node layers, less the supports (measured: 703 of 1179).
        assert!(5 * n_second <= 3 * n_all && 2 * n_second > n_all, "{n_second} of {n_all}");
        let field = |decay: &dyn Fn(f64) -> f64| -> Vec<Option<Vec<f64>>> {
            meshes
                .iter()
                .zip(&case.bearing.pads)
                .map(|(m, p)| {
                    let solid = Solid::from_pad(m.as_ref().unwrap());
                    Some(
                        solid
                            .nodes
                            .iter()
                            .map(|x| {
                                let arc = (x[1].atan2(x[0]) - p.leading_edge_rad).rem_euclid(std::f64::consts::TAU)
                                    / p.arc_rad;
                                let depth = x[0].hypot(x[1]) - rb;
                                50.0 + (20.0 * arc + 5.0 * (1.0 - 2.0 * x[2] / case.bearing.length_m)) * decay(depth)
                            })
                            .collect(),
                    )
                })
                .collect()
        };
        let conducted = field(&|d| (-std::f64::consts::PI * d / (rb * pad.arc_rad)).exp());
        let steep = field(&|d| (-d / (0.3 * t)).exp());
        for (name, pad_c, film_bound, nodal_bound) in
            [("conducted", conducted, 0.075, 0.065), ("steep", steep, 0.052, 0.029)]
        {
            let (a, b) = (all.evaluate(&pad_c, 60.0, &nodes), every_second.evaluate(&pad_c, 60.0, &nodes));
            let scale = a.pad_film_m[0].iter().fold(0.0_f64, |m, v| m.max(v.abs()));
            let film = a
                .pad_film_m
                .iter()
                .flatten()
                .zip(b.pad_film_m.iter().flatten())
                .fold(0.0_f64, |m, (x, y)| m.max((x - y).abs()))
                / scale;
            let nodal_scale = a.pad_nodal_m[0].iter().fold(0.0_f64, |m, v| m.max(v.abs()));
            let nodal = a
                .pad_nodal_m
                .iter()
                .flatten()
                .zip(b.pad_nodal_m.iter().flatten())
                .fold(0.0_f64, |m, (x, y)| m.max((x - y).abs()))
                / nodal_scale;
            eprintln!("{name}: every second layer moves the film-face growth by {film:.2e}, the nodal displacement by {nodal:.2e} of the largest (film {scale:.3e} m)");
            assert_eq!(b.pad_nodal_m[0].len(), a.pad_nodal_m[0].len());
            assert!(film < film_bound, "{name}: {film}");
            assert!(nodal < nodal_bound, "{name}: {nodal}");
        }
    }
}
