//! The film energy equation on a mass-conserving (JFO) film (physics::energy, physics::reynolds::jfo_exchange):
//! the oil the energy equation carries heat with is the oil the film's own mass balance moves, so no heat
//! appears or vanishes at nodes inside the pad, and the energy balance closes to round-off; the film's power
//! identity (journal shear power = heat generated) holds to round-off with the Reynolds condition and
//! converges with the mesh with the mass-conserving film.

use crate::common;
use tiltpad::bearing::Solution;

const JFO_STARVED: &str = "compressor-bearing-starved.toml";
const THD: &str = "thermal.model=\"thd\"";

fn thermal(s: &Solution) -> &tiltpad::bearing::solution::ThermalResult {
    s.thermal.as_ref().expect("thermal result")
}

/// The starved compressor bearing (25 l/min, JFO, THD): ruptured zones, striations and a starved inlet on every
/// pad. Before the upwinding's exchanges were carried by the energy equation, its flux field lost or gained
/// oil at the nodes next to rupture and reformation, and the balance booked 84.7 W of 3888 W (2.2 %) at preview
/// and 23.7 W (0.6 %) at standard as heat carried "into cavitation" inside the pads.
#[test]
fn the_energy_equation_carries_the_oil_the_mass_conserving_film_moves() {
    let s = common::solve(JFO_STARVED, &[THD, "mesh.fidelity=\"preview\""]);
    let t = thermal(&s);
    for (k, pad) in s.pads.iter().enumerate() {
        let h = &pad.thermal.as_ref().expect("pad thermal").heat;
        let leak = h.cavitation_transport_w / h.power_in();
        eprintln!("pad {k}: heat into cavitation {:.3e} of the power, closure {:.1e}", leak, h.closure());
        assert!(leak.abs() < 1e-12, "pad {k}: {} W inside the pad", h.cavitation_transport_w);
        assert!(h.closure().abs() < 1e-12, "pad {k}: closure {}", h.closure());
    }
    assert!(t.energy_balance_closure.abs() < 1e-12, "closure {}", t.energy_balance_closure);
}

/// The power identity `(P − G)/P` (physics::energy::balance): round-off with the Reynolds condition; with the
/// mass-conserving film a discretisation error of the nodes next to rupture and reformation that falls with the
/// mesh, at first order (the film's upwinding `D` is first order). Measured on the starved bearing: preview 2.92e-5
/// (1620 film nodes), standard 1.69e-5 (4940 nodes), reference 6.6e-6: order 0.98, then 0.90 in the element size
/// (release build). Before the capillary term was lumped the spurious ring under the holes' rims put it at
/// 2.2e-4 and 6.6e-5, an apparent order 2.2 that was that ring resolving.
#[test]
fn the_films_power_identity_converges_with_the_mesh() {
    let r = common::solve("compressor-bearing.toml", &[THD, "mesh.fidelity=\"preview\""]);
    let ir = thermal(&r).report.power_identity;
    eprintln!("Reynolds condition: power identity {ir:.1e}");
    assert!(ir.abs() < 1e-12, "Reynolds: {ir}");
    let level = |f: &str| {
        let s = common::solve(JFO_STARVED, &[THD, &format!("mesh.fidelity=\"{f}\"")]);
        let nodes = s.derived.film_nodes;
        (thermal(&s).report.power_identity, nodes)
    };
    let (a, na) = level("preview");
    let (b, nb) = level("standard");
    let order = (a / b).ln() / (0.5 * (nb as f64 / na as f64).ln());
    eprintln!("JFO: power identity {a:.2e} ({na} nodes) → {b:.2e} ({nb} nodes): order {order:.2}");
    assert!(a > 0.0 && b > 0.0, "{a} {b}");
    assert!(order > 0.85, "order {order}");
}
