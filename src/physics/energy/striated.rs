//! The striated film's fraction θ (module documentation of [`super`]): downstream of a rupture the oil
//! fills `θ = min(1, h_r/h)` of the gap, `h_r` the thickness at the rupture, which is placed between nodes by
//! the pressure's Swift–Stieber approach to zero ([`rupture_thickness`]), so the oil a pad hands to the next
//! one moves continuously with the film.

use crate::model::Cavitation;
use crate::physics::energy::FilmEnergy;
use crate::physics::reynolds::PadFilm;

impl FilmEnergy {
    /// Film fraction at the nodes (module documentation): per axial row, θ = min(1, h_r/h) in the cavitated
    /// nodes downstream of a rupture, `h_r` the thickness at the rupture, which lies between the last
    /// full-film node and the first cavitated one ([`rupture_thickness`]); 1 elsewhere, or everywhere when
    /// `striated` is false. After a mass-conserving (JFO) film solve: that solve's film fraction.
    /// Ambient-pressure boundary nodes carry no information of their own: a trailing-edge node continues its
    /// row (ruptured if the node before it is), and the axial-end rows copy the fraction of their
    /// neighbouring row, so the flux field does not jump at the boundary.
    #[must_use]
    pub fn film_fraction(film: &PadFilm, striated: bool) -> Vec<f64> {
        let g = &film.geom;
        let mut theta = vec![1.0; g.n_nodes()];
        if !striated {
            return theta;
        }
        // The mass-conserving film solve computes the fraction itself (rupture, striations, reformation and
        // a starved inlet): the energy equation transports that one.
        if film.solved_with() == Some(Cavitation::Jfo) {
            return film.theta.clone();
        }
        let grid = &g.grid;
        let (nc, nr) = (grid.n_cols(), grid.n_rows());
        let side_row = |j: usize| j == nr - 1 || (!grid.half && j == 0);
        for j in (0..nr).filter(|&j| !side_row(j)) {
            let mut h_ref: Option<f64> = None;
            let mut ruptured = false;
            for i in 0..nc {
                let k = grid.node(i, j);
                let h = film.h.node[k];
                let trailing_after_rupture = i == nc - 1 && ruptured;
                if film.cavitated[k] || trailing_after_rupture {
                    if !ruptured && h_ref.is_some() {
                        h_ref = Some(rupture_thickness(film, i, j));
                    }
                    if let Some(hr) = h_ref {
                        theta[k] = (hr / h).min(1.0);
                    }
                    ruptured = true;
                } else {
                    h_ref = Some(h);
                    ruptured = false;
                }
            }
        }
        for j in (0..nr).filter(|&j| side_row(j)) {
            let inner = if j == 0 { 1.min(nr - 1) } else { j - 1 };
            if inner == j || side_row(inner) {
                continue;
            }
            for i in 0..nc {
                theta[grid.node(i, j)] = theta[grid.node(i, inner)];
            }
        }
        theta
    }
}

/// Film thickness at the rupture of row `j`, whose first cavitated node is column `i` (> 0; the last
/// full-film node is `i − 1`). The rupture lies between the two nodes: with the Reynolds (Swift–Stieber)
/// condition the pressure meets zero with zero slope, `p ≈ c (s* − s)²`, so `√p` is linear in s and the two
/// full-film nodes before the rupture place it, `s* = s₀ + (s₀ − s₋) √p₀ / (√p₋ − √p₀)`, clamped to
/// `[s₀, s₁]`; the thickness there is interpolated linearly. The striated film downstream then carries the
/// flow `U h(s*)/2` of the rupture itself, which moves continuously with the film instead of jumping by a
/// node's `U Δh/2` when the last full-film node changes (that jump, in the oil a pad hands to the next
/// one's inlet, kept the THD loop of Fillon A with thermal growth cycling between two or three states).
/// Falls back to the last full-film node's thickness where the pressure does not
/// fall towards the rupture (fewer than two full-film nodes before it, or no decrease).
fn rupture_thickness(film: &PadFilm, i: usize, j: usize) -> f64 {
    let grid = &film.geom.grid;
    let (k0, k1) = (grid.node(i - 1, j), grid.node(i, j));
    let h0 = film.h.node[k0];
    if i < 2 {
        return h0;
    }
    let km = grid.node(i - 2, j);
    let (pm, p0) = (film.p[km].max(0.0), film.p[k0].max(0.0));
    if film.cavitated[km] || pm <= p0 {
        return h0;
    }
    let (sm, s0, s1) = (grid.s[i - 2], grid.s[i - 1], grid.s[i]);
    let (rm, r0) = (pm.sqrt(), p0.sqrt());
    let frac = ((s0 - sm) * r0 / (rm - r0) / (s1 - s0)).clamp(0.0, 1.0);
    h0 + frac * (film.h.node[k1] - h0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::grid::PadGrid;
    use crate::physics::reynolds::{FilmGeometry, FilmShape};

    struct Flat;
    impl FilmShape for Flat {
        fn base(&self, _theta: f64, _z: f64) -> f64 {
            50e-6
        }
        fn n_dofs(&self) -> usize {
            0
        }
        fn dof(&self, _k: usize, _theta: f64, _z: f64) -> f64 {
            0.0
        }
    }

    /// The striated film downstream of a rupture carries `U h(s*)/2`, the flow at the rupture itself: with a
    /// Swift–Stieber pressure `p = c (s* − s)²` (zero with zero slope at s*) on a diverging film, the
    /// film fraction at the trailing edge times the thickness there is `h(s*)` for every rupture position,
    /// between nodes too, so the oil (and the heat) a pad hands to the next one changes continuously as the
    /// rupture moves. Taking the last full-film node's thickness instead is off by up to a cell's Δh (a
    /// step of `U Δh/2` each time the rupture passes a node).
    #[test]
    fn striated_flow_follows_the_rupture_between_nodes() {
        let (nc, r) = (11, 0.05);
        let ds = 0.004;
        let s: Vec<f64> = (0..nc).map(|i| ds * f64::from(u32::try_from(i).unwrap_or(0))).collect();
        let grid = PadGrid { s: s.clone(), z: vec![-0.01, 0.0, 0.01], periodic: false, half: false };
        let mut film = PadFilm::new(FilmGeometry::new(grid, r, 0.0, &[], &Flat)).unwrap();
        let h = |x: f64| 20e-6 + 5e-3 * x;
        let g = film.geom.grid.clone();
        let te = g.node(nc - 1, 1);
        let mut worst = 0.0_f64;
        let mut last: Option<f64> = None;
        let mut largest_step = 0.0_f64;
        // Rupture swept from inside cell 3 to inside cell 7 in 400 steps (crossing four nodes).
        for step in 0..=400 {
            let rupture = s[3] + 0.3 * ds + (s[7] - s[3]) * f64::from(step) / 400.0;
            for i in 0..nc {
                for j in 0..3 {
                    let k = g.node(i, j);
                    film.h.node[k] = h(s[i]);
                    film.p[k] = if s[i] < rupture { 1e12 * (rupture - s[i]).powi(2) } else { 0.0 };
                    film.cavitated[k] = s[i] >= rupture;
                }
            }
            let theta = FilmEnergy::film_fraction(&film, true);
            let carried = theta[te] * film.h.node[te];
            worst = worst.max((carried - h(rupture)).abs() / h(rupture));
            if let Some(prev) = last {
                largest_step = largest_step.max((carried - prev).abs());
            }
            last = Some(carried);
        }
        // A step of the sweep moves the rupture by 1/100 of a cell, h(s*) by 2e-7 m; the last full node's
        // thickness jumps by a cell's Δh = 2e-5 m where the rupture passes a node.
        let dh_step = h(s[7] - s[3]) - h(0.0);
        let dh_step = dh_step / 400.0;
        assert!(worst < 1e-12, "θ h at the trailing edge differs from h(s*) by {worst:.2e} (relative)");
        assert!(largest_step < 1.000_001 * dh_step, "θ h at the trailing edge jumps by {largest_step:.3e} m in one step (the rupture moves h by {dh_step:.3e} m)");
    }
}
