//! SUPG benchmarks (docs/REFERENCES.md §4; docs/MODEL.md §11).
//!
//! - Skew advection on the unit square: Hughes, Mallet & Mizukami, "A new finite element formulation for
//!   computational fluid dynamics: II. Beyond SUPG", CMAME 54 (1986), after Brooks & Hughes, CMAME 32 (1982).
//!   `−ε Δu + b·∇u = 0`, `b = (cos(−π/3), sin(−π/3))`, `u = 1` on the top and on the left above y = 0.7, `u = 0`
//!   elsewhere on the boundary. The exact solution lies in [0, 1] (maximum principle); a scheme's over- and
//!   undershoot are the measure. Run on an irregular (distorted) quadrilateral mesh so the velocity is skewed
//!   to the elements and the elements are not rectangles.
//! - 1-D: `Pe u′ − u″ = 0` on (0, 1), `u(0) = 0`, `u(1) = 1`, exact `u = (e^{Pe x} − 1)/(e^{Pe} − 1)`; with
//!   linear elements and `τ = h/(2|b|)(coth Pe_h − 1/Pe_h)` SUPG is nodally exact.

use tiltpad::fem::quad4::QuadPoint;
use tiltpad::fem::quad_iso::iso_gauss_2x2;
use tiltpad::fem::supg::{solve_picard, Adr, AdrMesh, BoundaryEdge, PicardParams, PicardSolution, Stabilisation};
use tiltpad::fem::{GeneralPattern, LuSolver};

/// A structured n × n mesh of [0, a] × [0, 1] with interior nodes displaced by up to `distortion` of the
/// spacing (a deterministic pseudo-random pattern), the elements and their quadrature points.
struct Mesh {
    xy: Vec<[f64; 2]>,
    elements: Vec<[usize; 4]>,
    qp: Vec<[QuadPoint; 4]>,
    nx: usize,
    ny: usize,
}

fn mesh(nx: usize, ny: usize, width: f64, distortion: f64) -> Mesh {
    let node = |i: usize, j: usize| i * (ny + 1) + j;
    let mut xy = Vec::new();
    let (hx, hy) = (width / nx as f64, 1.0 / ny as f64);
    for i in 0..=nx {
        for j in 0..=ny {
            let (mut x, mut y) = (i as f64 * hx, j as f64 * hy);
            if i > 0 && i < nx && j > 0 && j < ny {
                // Deterministic "random" in [−1, 1] (a hash of the indices).
                let r = |k: usize| (((i * 7919 + j * 104_729 + k * 31) % 1000) as f64 / 500.0) - 1.0;
                x += distortion * hx * r(1);
                y += distortion * hy * r(2);
            }
            xy.push([x, y]);
        }
    }
    let mut elements = Vec::new();
    let mut qp = Vec::new();
    for i in 0..nx {
        for j in 0..ny {
            let e = [node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)];
            let corners = e.map(|k| xy[k]);
            qp.push(iso_gauss_2x2(&corners).expect("valid element"));
            elements.push(e);
        }
    }
    Mesh { xy, elements, qp, nx, ny }
}

/// Dirichlet edges of the unit-square mesh (all four sides) with outward normals.
fn boundary_edges(m: &Mesh) -> Vec<BoundaryEdge> {
    let mut out = Vec::new();
    for (e, nodes) in m.elements.iter().enumerate() {
        let (i, j) = (e / m.ny, e % m.ny);
        // Local edges (a, b) counter-clockwise: the outward normal is (dy, −dx)/len.
        let mut edges = Vec::new();
        if j == 0 {
            edges.push((0, 1));
        }
        if i == m.nx - 1 {
            edges.push((1, 2));
        }
        if j == m.ny - 1 {
            edges.push((2, 3));
        }
        if i == 0 {
            edges.push((3, 0));
        }
        for (a, b) in edges {
            let (pa, pb) = (m.xy[nodes[a]], m.xy[nodes[b]]);
            let (dx, dy) = (pb[0] - pa[0], pb[1] - pa[1]);
            let length = dx.hypot(dy);
            out.push(BoundaryEdge { element: e, normal: [dy / length, -dx / length], length });
        }
    }
    out
}

/// Solves `−ε Δu + b·∇u = 0` with Dirichlet values `bc(k, x, y)` (where `Some`).
fn solve(
    m: &Mesh,
    eps: f64,
    b: [f64; 2],
    stab: Stabilisation,
    bc: &dyn Fn(usize, f64, f64) -> Option<f64>,
) -> PicardSolution {
    let n = m.xy.len();
    let pattern = GeneralPattern::from_groups(n, m.elements.iter().map(|e| &e[..]));
    let diameters: Vec<f64> = m
        .elements
        .iter()
        .map(|e| {
            let d = |a: usize, b: usize| (m.xy[e[a]][0] - m.xy[e[b]][0]).hypot(m.xy[e[a]][1] - m.xy[e[b]][1]);
            d(0, 2).max(d(1, 3))
        })
        .collect();
    let edges = boundary_edges(m);
    let mesh = AdrMesh { elements: &m.elements, qp: &m.qp, diameters: &diameters, dirichlet_edges: &edges };
    let dirichlet: Vec<Option<f64>> = m.xy.iter().enumerate().map(|(k, p)| bc(k, p[0], p[1])).collect();
    let coef = |_: usize, _: usize| Adr { d: eps, a: b, c: 0.0, f: 0.0 };
    let mut lu = LuSolver::new(&pattern).unwrap();
    solve_picard(&pattern, &mut lu, &mesh, &coef, &dirichlet, stab, PicardParams::default()).unwrap()
}

/// (overshoot above 1, undershoot below 0, Picard iterations) of the skew-advection solution.
fn skew(n: usize, distortion: f64, eps: f64, stab: Stabilisation) -> (f64, f64, usize) {
    let m = mesh(n, n, 1.0, distortion);
    let b = [(-std::f64::consts::FRAC_PI_3).cos(), (-std::f64::consts::FRAC_PI_3).sin()];
    let ny = m.ny;
    let bc = |k: usize, _x: f64, y: f64| -> Option<f64> {
        let (i, j) = (k / (ny + 1), k % (ny + 1));
        let boundary = i == 0 || i == n || j == 0 || j == ny;
        boundary.then_some(if j == ny || (i == 0 && y > 0.7) { 1.0 } else { 0.0 })
    };
    let sol = solve(&m, eps, b, stab, &bc);
    assert!(sol.converged, "Picard iteration did not converge: change {:.2e}", sol.change);
    let over = sol.u.iter().fold(0.0_f64, |a, &v| a.max(v - 1.0));
    let under = sol.u.iter().fold(0.0_f64, |a, &v| a.max(-v));
    (over, under, sol.iterations)
}

#[test]
fn skew_advection_supg_with_crosswind_capturing_has_no_wiggles() {
    // Interior nodes displaced at random by up to 15 % of the spacing.
    for &eps in &[1e-8, 1e-4] {
        for &n in &[16, 32, 64] {
            let (over, under, it) = skew(n, 0.15, eps, Stabilisation::SupgCrosswind);
            println!(
                "SUPG+crosswind ε = {eps:.0e}, {n}×{n}: overshoot {:.3} %, undershoot {:.3} % ({it} iterations)",
                100.0 * over,
                100.0 * under
            );
            assert!(over < 0.01 && under < 0.01, "ε = {eps}, n = {n}: over {over:.4}, under {under:.4}");
        }
    }
}

#[test]
fn skew_advection_strongly_distorted_mesh_reported() {
    // Displacements up to 25 % and 30 % of the spacing: reported in docs/THERMAL.md; asserted only to stay
    // within a few per cent (the 1 % bound above holds for the moderately distorted mesh).
    for &d in &[0.25, 0.3] {
        for &n in &[16, 32, 64] {
            let (over, under, it) = skew(n, d, 1e-8, Stabilisation::SupgCrosswind);
            println!(
                "SUPG+crosswind distortion {d}, {n}×{n}: overshoot {:.2} %, undershoot {:.2} % ({it} iterations)",
                100.0 * over,
                100.0 * under
            );
            assert!(over < 0.03 && under < 0.03);
        }
    }
}

#[test]
fn skew_advection_plain_supg_and_galerkin_wiggle() {
    // The test can fail: plain Galerkin oscillates wildly; plain SUPG (linear, no crosswind term) overshoots
    // in the outflow layers and undershoots across the internal layer by several per cent.
    for &eps in &[1e-8, 1e-4] {
        let (over, under, _) = skew(32, 0.15, eps, Stabilisation::Galerkin);
        println!(
            "Galerkin       ε = {eps:.0e}, 32×32: overshoot {:.1} %, undershoot {:.1} %",
            100.0 * over,
            100.0 * under
        );
        assert!(over.max(under) > 0.5, "Galerkin ε = {eps}: over {over:.4}, under {under:.4}");
        let (over, under, _) = skew(32, 0.15, eps, Stabilisation::Supg);
        println!(
            "plain SUPG     ε = {eps:.0e}, 32×32: overshoot {:.1} %, undershoot {:.1} %",
            100.0 * over,
            100.0 * under
        );
        assert!(over.max(under) > 0.03, "plain SUPG ε = {eps}: over {over:.4}, under {under:.4}");
    }
}

#[test]
fn one_dimensional_supg_is_nodally_exact() {
    // A strip of Q4 elements one element high, natural conditions on the long sides: the 1-D problem.
    for stab in [Stabilisation::Supg, Stabilisation::SupgCrosswind] {
        for &pe in &[1.0, 10.0, 100.0, 1e4] {
            let n = 10;
            let m = mesh(n, 1, 1.0, 0.0);
            let sol = solve(&m, 1.0, [pe, 0.0], stab, &|k, x, _| {
                let i = k / 2;
                (i == 0 || i == n).then_some(x)
            });
            // (e^{Pe x} − 1)/(e^{Pe} − 1), written without overflow.
            let exact = |x: f64| (pe * (x - 1.0)).exp() * (-(-pe * x).exp_m1()) / (-(-pe).exp_m1());
            for (k, p) in m.xy.iter().enumerate() {
                assert!(
                    (sol.u[k] - exact(p[0])).abs() < 1e-10,
                    "{stab:?} Pe = {pe}, x = {}: {} vs {}",
                    p[0],
                    sol.u[k],
                    exact(p[0])
                );
            }
        }
    }
}
