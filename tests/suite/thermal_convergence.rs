//! Mesh convergence of the thermal model (docs/MODEL.md §11), on Fillon bearing A (docs/REFERENCES.md §3).
//!
//! - Pad conduction through the thickness (BC3, where the pad and film are coupled): the maximum pad
//!   temperature against the number of graded element layers, measured order.
//! - Film mesh: the maximum film temperature at the three fidelity levels, measured order against the
//!   reference mesh.

use crate::common;

fn pad_max(set: &[&str]) -> f64 {
    let s = common::solve("fillon-a.toml", set);
    s.thermal.as_ref().and_then(|t| t.t_max_pad_c).unwrap()
}

#[test]
fn pad_layers_converge_at_second_order() {
    let bc3 = "thermal.pad_film_bc=\"bc3\"";
    let at = |n: usize| pad_max(&[bc3, "mesh.fidelity=\"preview\"", &format!("mesh.pad_radial_elements={n}")]);
    let fine = at(24);
    let e: Vec<f64> = [2, 4, 8].iter().map(|&n| (at(n) - fine).abs()).collect();
    let order = [(e[0] / e[1]).log2(), (e[1] / e[2]).log2()];
    println!(
        "pad max error vs 24 layers: 2 → {:.4} K, 4 → {:.4} K, 8 → {:.4} K; orders {:.2}, {:.2}",
        e[0], e[1], e[2], order[0], order[1]
    );
    assert!(order[0] > 1.5 && order[1] > 1.5, "orders {order:?}");
    assert!(e[1] < 0.02, "4 layers (the standard fidelity) within 0.02 K: {:.4}", e[1]);
}

#[test]
fn film_mesh_converges() {
    let t = ["preview", "standard", "reference"].map(|f| {
        let s = common::solve("fillon-a.toml", &[&format!("mesh.fidelity=\"{f}\"")]);
        s.thermal.as_ref().unwrap().t_max_film_c
    });
    let (e0, e1) = ((t[0] - t[2]).abs(), (t[1] - t[2]).abs());
    // Circumferential elements 16 → 36 → 96: refinement ratio 2.25 between preview and standard.
    let order = (e0 / e1).ln() / 2.25_f64.ln();
    println!("film max: preview {:.3}, standard {:.3}, reference {:.3} °C; order {order:.2}", t[0], t[1], t[2]);
    assert!(order > 1.0, "order {order:.2}");
    assert!(e1 < 0.01 * (t[2] - 40.0), "standard within 1 % of the temperature rise: {e1:.3} K");
}
