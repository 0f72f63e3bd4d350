//! Nested-dissection elimination order of a pad solid's nodes for the Cholesky factorisation.

use crate::physics::pad_elastic::Solid;

/// Nested dissection of a pad solid's nodes: the nodes on the middle grid surface of constant arc length or
/// axial position (whichever extent is longer; through all layers) separate the rest in two, which are ordered
/// first, recursively, and the separator after them. On the pad's thin, plate-like mesh this keeps the
/// Cholesky factor's fill near that of a 2-D grid, with the layers' unknowns of a column together.
pub(super) fn pad_dissection(solid: &Solid) -> Vec<usize> {
    // (arc length about the mean direction, z) of every node.
    let (sx, sy) = solid.nodes.iter().fold((0.0, 0.0), |(a, b), x| (a + x[0], b + x[1]));
    let mean = sy.atan2(sx);
    let r_mean = solid.nodes.iter().map(|x| x[0].hypot(x[1])).sum::<f64>() / (solid.n_nodes().max(1) as f64);
    let at: Vec<[f64; 2]> = solid
        .nodes
        .iter()
        .map(|x| {
            let (s, c) = mean.sin_cos();
            [r_mean * (x[1] * c - x[0] * s).atan2(x[0] * c + x[1] * s), x[2]]
        })
        .collect();
    let mut out = Vec::with_capacity(at.len());
    dissect((0..at.len()).collect(), &at, &mut out);
    out
}

/// Nodes at most this many are ordered as they come (a leaf of the dissection).
const DISSECTION_LEAF: usize = 48;

fn dissect(ids: Vec<usize>, at: &[[f64; 2]], out: &mut Vec<usize>) {
    if ids.len() <= DISSECTION_LEAF {
        out.extend(ids);
        return;
    }
    let extent = |d: usize| {
        let (lo, hi) =
            ids.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &i| (lo.min(at[i][d]), hi.max(at[i][d])));
        hi - lo
    };
    let dims = if extent(0) >= extent(1) { [0, 1] } else { [1, 0] };
    for d in dims {
        let tol = 1e-9 * extent(d).max(f64::MIN_POSITIVE);
        let mut lines: Vec<f64> = ids.iter().map(|&i| at[i][d]).collect();
        lines.sort_by(f64::total_cmp);
        lines.dedup_by(|a, b| (*a - *b).abs() <= tol);
        if lines.len() < 3 {
            continue;
        }
        let v = lines[lines.len() / 2];
        let (mut left, mut right, mut middle) = (Vec::new(), Vec::new(), Vec::new());
        for i in ids {
            let x = at[i][d];
            if x < v - tol {
                left.push(i);
            } else if x > v + tol {
                right.push(i);
            } else {
                middle.push(i);
            }
        }
        dissect(left, at, out);
        dissect(right, at, out);
        out.extend(middle);
        return;
    }
    out.extend(ids);
}
