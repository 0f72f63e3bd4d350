//! Tensor-product grids on a pad's film surface, graded towards injection orifices.
//!
//! Coordinates: `s` is arc length along the journal surface from the pad's leading edge, `s = R (θ − θ_le)`,
//! in `[0, R β]`; `z` is axial from the mid-plane, in `[−L/2, L/2]` (full model) or `[0, L/2]` (half model,
//! symmetry plane at `z = 0`). Nodes are numbered with `z` fastest: `node(i, j) = i · n_z + j`. A periodic
//! (360°) sector has no node column at `s = 2πR`: column `n_s` wraps to column 0.
//!
//! Grading: inside each refinement zone the spacing is `fine`; away from it the spacing grows
//! geometrically (ratio `GROWTH`) up to the base spacing. Nodes are placed by inverting the cumulative
//! integral of 1/spacing, so both ends are hit exactly and the spacing varies smoothly.

/// Largest ratio between neighbouring cell sizes in a graded grid.
pub const GROWTH: f64 = 1.25;

/// A zone `[centre − half_width, centre + half_width]` to mesh with spacing `fine`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Refinement {
    pub centre: f64,
    pub half_width: f64,
    pub fine: f64,
}

/// Half-width of the refinement zone around an orifice, as a fraction of its diameter.
pub const ORIFICE_ZONE_HALF_WIDTH: f64 = 0.6;

/// The refinement around an orifice of diameter `diameter` centred at `centre` (one direction): spacing
/// `diameter / elements_across` within [`ORIFICE_ZONE_HALF_WIDTH`] diameters of the centre.
#[must_use]
#[allow(clippy::cast_precision_loss)]
pub fn orifice_zone(centre: f64, diameter: f64, elements_across: usize) -> Refinement {
    Refinement {
        centre,
        half_width: ORIFICE_ZONE_HALF_WIDTH * diameter,
        fine: diameter / elements_across.max(1) as f64,
    }
}

/// The cumulative integral of 1/spacing over `[a, b]` on a fine uniform sampling, and the sample width.
#[allow(clippy::cast_precision_loss)]
fn cumulative_density(a: f64, b: f64, base_cells: usize, zones: &[Refinement]) -> (Vec<f64>, f64) {
    let len = b - a;
    let base = len / base_cells as f64;
    let spacing = |x: f64| -> f64 {
        let mut h = base;
        for zn in zones {
            let fine = zn.fine.min(base);
            let d = ((x - zn.centre).abs() - zn.half_width).max(0.0);
            // Geometric growth away from the zone: h(d) ≈ fine + (GROWTH − 1) d.
            h = h.min(fine + (GROWTH - 1.0) * d);
        }
        h
    };
    let samples = 4000.max(20 * base_cells);
    let dx = len / samples as f64;
    let mut cum = Vec::with_capacity(samples + 1);
    cum.push(0.0);
    for k in 0..samples {
        let xm = a + (k as f64 + 0.5) * dx;
        cum.push(cum[k] + dx / spacing(xm));
    }
    (cum, dx)
}

/// Number of cells [`graded_nodes`] makes on `[a, b]`, counted without placing the nodes (the sampling
/// it needs is `max(4000, 20 base_cells)` values, whatever the count).
#[must_use]
#[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
pub fn graded_cells(a: f64, b: f64, base_cells: usize, zones: &[Refinement]) -> usize {
    let (cum, _) = cumulative_density(a, b, base_cells, zones);
    (cum[cum.len() - 1].round() as usize).max(1)
}

/// Node positions on `[a, b]` with about `base_cells` cells, refined in the given zones.
///
/// # Panics
/// Never for valid input (`b > a`, `base_cells ≥ 1`, positive refinement sizes); callers validate.
#[must_use]
#[allow(clippy::cast_precision_loss, clippy::cast_possible_truncation, clippy::cast_sign_loss)]
pub fn graded_nodes(a: f64, b: f64, base_cells: usize, zones: &[Refinement]) -> Vec<f64> {
    let (cum, dx) = cumulative_density(a, b, base_cells, zones);
    let samples = cum.len() - 1;
    let total = cum[samples];
    let n = (total.round() as usize).max(1);
    let mut nodes = Vec::with_capacity(n + 1);
    nodes.push(a);
    let mut k = 0;
    for m in 1..n {
        let target = total * m as f64 / n as f64;
        while cum[k + 1] < target {
            k += 1;
        }
        let f = (target - cum[k]) / (cum[k + 1] - cum[k]);
        nodes.push(a + (k as f64 + f) * dx);
    }
    nodes.push(b);
    nodes
}

/// The grid of one pad.
#[derive(Debug, Clone, PartialEq)]
pub struct PadGrid {
    /// Circumferential node positions (arc length from the leading edge) [m]; for a periodic sector the
    /// last entry is `2πR` and is the same node as the first.
    pub s: Vec<f64>,
    /// Axial node positions [m].
    pub z: Vec<f64>,
    pub periodic: bool,
    /// Half model: `z` starts on the symmetry plane.
    pub half: bool,
}

/// Where a node sits on the pad boundary (for boundary conditions and edge flows).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum NodeSite {
    Interior,
    /// Leading edge (s = 0), including its corners.
    Leading,
    /// Trailing edge (s = Rβ), including its corners.
    Trailing,
    /// An axial end (z = ±L/2), corners excluded.
    Side,
    /// Symmetry plane of the half model (z = 0), corners excluded; natural (Neumann) condition.
    Symmetry,
}

impl PadGrid {
    /// Number of distinct node columns along s.
    #[must_use]
    pub fn n_cols(&self) -> usize {
        if self.periodic {
            self.s.len() - 1
        } else {
            self.s.len()
        }
    }
    #[must_use]
    pub fn n_rows(&self) -> usize {
        self.z.len()
    }
    #[must_use]
    pub fn n_nodes(&self) -> usize {
        self.n_cols() * self.n_rows()
    }
    #[must_use]
    pub fn n_elements(&self) -> usize {
        (self.s.len() - 1) * (self.z.len() - 1)
    }
    /// Node id of column `i` (wrapping for periodic grids) and row `j`.
    #[must_use]
    pub fn node(&self, i: usize, j: usize) -> usize {
        (i % self.n_cols()) * self.n_rows() + j
    }
    /// Column and row of a node.
    #[must_use]
    pub fn col_row(&self, node: usize) -> (usize, usize) {
        (node / self.n_rows(), node % self.n_rows())
    }
    /// The four nodes of element (i, j), counter-clockwise from (s_i, z_j).
    #[must_use]
    pub fn element_nodes(&self, i: usize, j: usize) -> [usize; 4] {
        [self.node(i, j), self.node(i + 1, j), self.node(i + 1, j + 1), self.node(i, j + 1)]
    }
    /// Where node (column, row) sits.
    #[must_use]
    pub fn site(&self, node: usize) -> NodeSite {
        let (i, j) = self.col_row(node);
        if !self.periodic && i == 0 {
            return NodeSite::Leading;
        }
        if !self.periodic && i == self.s.len() - 1 {
            return NodeSite::Trailing;
        }
        let last = self.z.len() - 1;
        if j == last || (!self.half && j == 0) {
            NodeSite::Side
        } else if self.half && j == 0 {
            NodeSite::Symmetry
        } else {
            NodeSite::Interior
        }
    }
    /// True where the pressure is prescribed (ambient): leading and trailing edges and axial ends.
    #[must_use]
    pub fn is_dirichlet(&self, node: usize) -> bool {
        matches!(self.site(node), NodeSite::Leading | NodeSite::Trailing | NodeSite::Side)
    }
    /// Elements as (i, j) pairs.
    pub fn elements(&self) -> impl Iterator<Item = (usize, usize)> + '_ {
        let nj = self.z.len() - 1;
        (0..self.s.len() - 1).flat_map(move |i| (0..nj).map(move |j| (i, j)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn uniform_without_zones() {
        let x = graded_nodes(0.0, 2.0, 10, &[]);
        assert_eq!(x.len(), 11);
        for (k, v) in x.iter().enumerate() {
            assert!((v - 0.2 * k as f64).abs() < 1e-9, "{k}: {v}");
        }
    }

    #[test]
    fn refined_zone_has_fine_cells_and_smooth_growth() {
        let zone = Refinement { centre: 0.3, half_width: 0.05, fine: 0.01 };
        let x = graded_nodes(0.0, 1.0, 10, &[zone]);
        assert_eq!(x[0], 0.0);
        assert_eq!(*x.last().unwrap(), 1.0);
        let h: Vec<f64> = x.windows(2).map(|w| w[1] - w[0]).collect();
        // Cells inside the zone are about `fine`.
        for w in x.windows(2) {
            let mid = 0.5 * (w[0] + w[1]);
            if (mid - 0.3).abs() < 0.04 {
                assert!((w[1] - w[0]) < 0.013, "cell {w:?} too coarse");
            }
        }
        // Neighbouring cells never differ by much more than the growth ratio.
        for w in h.windows(2) {
            let r = (w[1] / w[0]).max(w[0] / w[1]);
            assert!(r < GROWTH + 0.1, "ratio {r}");
        }
    }

    #[test]
    fn cell_count_without_placing_nodes() {
        let zones = [orifice_zone(0.3, 0.05, 12), orifice_zone(0.7, 0.01, 24)];
        for base in [4, 10, 37] {
            let x = graded_nodes(0.0, 1.0, base, &zones);
            assert_eq!(graded_cells(0.0, 1.0, base, &zones), x.len() - 1, "{base} base cells");
        }
    }

    #[test]
    fn periodic_wraps() {
        let g = PadGrid { s: vec![0.0, 1.0, 2.0, 3.0], z: vec![0.0, 0.5, 1.0], periodic: true, half: false };
        assert_eq!(g.n_cols(), 3);
        assert_eq!(g.element_nodes(2, 0), [g.node(2, 0), g.node(0, 0), g.node(0, 1), g.node(2, 1)]);
        assert_eq!(g.site(g.node(0, 1)), NodeSite::Interior);
    }
}
