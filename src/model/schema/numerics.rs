//! Rows of how the film is modelled and discretised: `[physics]` and `[mesh]`.

use super::super::error::Range;
use super::Group::{Fidelity, Physics};
use super::Widget::{Choice, Custom, Optional};
use super::{Fallback, KeySpec};
use crate::model::file::{CaseFile, OneOrMany};
use crate::units::{COUNT, DEG, NODES, ONE, UM};

/// Default of `mesh.max_nodes` (the node budget, [`crate::model::budget`]): about 1 GB. Measured peaks
/// (release build, `/usr/bin/time`): the isothermal compressor bearing with 16 k / 51 k / 114 k film nodes uses
/// 35 / 93 / 204 MB (≈ 1.8 kB per node), Fillon's THD bearing with 175 k nodes (165 k in pad solids) 358 MB
/// (≈ 2 kB per node); time grows as about N^1.2 (docs/PERFORMANCE.md, cost growth). The reference fidelity of
/// every shipped case needs less than a quarter of it (tests/suite/node_budget.rs).
pub const DEFAULT_MAX_NODES: usize = 500_000;

type Key = KeySpec;

/// Largest local film Reynolds number a transition band may name (far beyond any oil film; the Ng–Pan
/// coefficients are fitted up to 10⁵).
pub const MAX_TRANSITION_REYNOLDS: f64 = 1e5;

/// `physics.touchdown_film_um` is at most this fraction of the assembled clearance.
pub const MAX_TOUCHDOWN_RATIO: f64 = 0.5;
/// Default of `physics.touchdown_film_um`, as a fraction of the assembled clearance.
pub const TOUCHDOWN_RATIO: f64 = 0.01;

fn touchdown(f: &CaseFile) -> f64 {
    TOUCHDOWN_RATIO * f.bearing.assembled_clearance_um
}

/// The longest pad arc a file gives [rad] (per-pad arcs, else the common one): sets the level's count along
/// the arc.
fn longest_arc_rad(f: &CaseFile) -> f64 {
    let p = &f.bearing.pads;
    let listed = match &p.pivot_deg {
        Some(OneOrMany::Many(v)) => v.len(),
        _ => 0,
    };
    let pads = p.count.unwrap_or(f.bearing.pad.len().max(listed)).max(1);
    let arc = |i: usize| f.bearing.pad.get(i).and_then(|own| own.arc_deg).or(p.arc_deg).unwrap_or(0.0);
    DEG.to_si((0..pads).map(arc).fold(0.0, f64::max))
}

#[allow(clippy::cast_precision_loss)]
fn level_circumferential(f: &CaseFile) -> f64 {
    f.mesh.fidelity.unwrap_or_default().circumferential_elements(longest_arc_rad(f)) as f64
}
#[allow(clippy::cast_precision_loss)]
fn level_axial(f: &CaseFile) -> f64 {
    f.mesh.fidelity.unwrap_or_default().elements().1 as f64
}
#[allow(clippy::cast_precision_loss)]
fn level_orifice(f: &CaseFile) -> f64 {
    f.mesh.fidelity.unwrap_or_default().elements().2 as f64
}
#[allow(clippy::cast_precision_loss)]
fn level_pad_radial(f: &CaseFile) -> f64 {
    f.mesh.fidelity.unwrap_or_default().pad_radial_elements() as f64
}

const fn level(value: fn(&CaseFile) -> f64) -> Fallback {
    Fallback::Follows { text: "from the fidelity", value }
}

pub(super) const KEYS: &[Key] = &[
    // [physics]
    Key::choice("physics.cavitation", &["reynolds", "gumbel", "jfo"])
        .default(Fallback::Word("reynolds"))
        .edit(
            Physics,
            "Cavitation",
            Choice(&["Reynolds (Swift–Stieber)", "Gümbel (half-Sommerfeld)", "JFO (mass-conserving)"]),
        )
        .meaning("Where the film diverges the pressure would fall below ambient; oil cannot sustain that and the film ruptures. Reynolds (Swift–Stieber): p ≥ 0 with zero flux gradient at the rupture boundary, solved exactly. Gümbel: solve, then clip negative pressures (simpler, violates mass conservation). JFO (Jakobsson–Floberg–Olsson, mass-conserving): pressure and film fraction complementary; the ruptured film carries its oil on as striations and reforms where it meets a pressurised film or an orifice fills it; flows balance to round-off; the only option that can starve a pad (operating.supply_flow_l_per_min)."),
    Key::choice("physics.turbulence", &["off", "auto", "on"])
        .default(Fallback::Word("off"))
        .edit(Physics, "Film turbulence", Choice(&["off (laminar)", "auto (above the transition band)", "on (turbulent everywhere)"]))
        .meaning("Flow regime of the film. off: the laminar Reynolds and energy equations at every Reynolds number (the report warns where the local Reynolds number passes the transition band's start). auto: Ng–Pan turbulent coefficients where the local film Reynolds number ρUh/µ exceeds the transition band, laminar below it, blended inside it; the energy equation gets the matching eddy diffusivity. on: the turbulent coefficients everywhere."),
    Key::number("physics.transition_reynolds_start", ONE, Range::closed(1.0, MAX_TRANSITION_REYNOLDS))
        .typical(500.0, 2000.0)
        .or(1000.0)
        .edit(Physics, "Transition starts at Re", Optional(0))
        .meaning("Local film Reynolds number ρUh/µ where the laminar–turbulent transition band starts (with turbulence = \"auto\"): the film is laminar below it. Journal bearings leave the laminar regime at about 1000–1500; the Taylor-vortex onset 41.3·√(R/h) is another common choice."),
    Key::rule("physics.transition_reynolds_end", ONE, "(transition_reynolds_start, 100000]")
        .typical(1000.0, 3000.0)
        .or(1500.0)
        .edit(Physics, "Transition ends at Re", Optional(0))
        .meaning("Local film Reynolds number where the transition band ends (with turbulence = \"auto\"): fully turbulent (Ng–Pan) above it; inside the band the coefficients are blended with a smooth intermittency. Must lie above the start."),
    Key::rule("physics.touchdown_film_um", UM, "(0, half the assembled clearance]")
        .typical(0.1, 10.0)
        .default(Fallback::Follows { text: "1 % of the assembled clearance", value: touchdown })
        .edit(Physics, "Touchdown film", Optional(2))
        .meaning("Smallest film thickness accepted at equilibrium; below it the solve reports touchdown (contact through the surface roughness)."),
    Key::integer("physics.pad_modes", COUNT, 0, 3)
        .typical(0.0, 3.0)
        .default(Fallback::Count(0))
        .edit(Physics, "Pad bending modes", Optional(0))
        .meaning("Bending modes per tilting pad beyond the rigid tilt (pad flexibility by pseudo-modal reduction of the pad's finite-element model, with E, ν and density of the pads); 0: rigid pads. Each mode adds a coordinate to the equilibrium and a row/column to the full coefficient matrices. The first bending mode carries almost all of the effect."),
    Key::integer("physics.max_film_solves_per_pad", COUNT, 100, 1_000_000)
        .typical(1000.0, 30000.0)
        .default(Fallback::Count(3000))
        .edit(Physics, "Equilibrium work budget", Optional(0))
        .meaning("Film solves per pad the static equilibrium may spend over all its methods and fallbacks before it stops and says it did not converge (a count of work, so the same case gives the same answer on an idle or a busy machine). Shipped cases converge in a few dozen; a search through folds or near touchdown can take a few thousand. A solve stopped by this budget names it in its error: raise it there."),
    // [mesh]
    Key::choice("mesh.fidelity", &["preview", "standard", "reference"])
        .default(Fallback::Word("standard"))
        .edit(Fidelity, "Mesh fidelity", Choice(&["preview", "standard", "reference"]))
        .meaning("Element counts per pad: preview 16×8 (fast, a few % error), standard 36×16, reference 96×48 (for convergence checks); pads longer than 80° get proportionally more along the arc (a 360° bore: 4.5×). Each orifice is refined further."),
    Key::flag("mesh.half_model")
        .default(Fallback::Rule("true when every orifice is on the mid-plane"))
        .edit(Fidelity, "Half model", Custom)
        .meaning("Model half the pad length with a symmetry plane (half the cost). Automatic: used when every orifice is on the mid-plane, the only case where the film is symmetric."),
    Key::integer("mesh.circumferential_elements", COUNT, 4, 2000)
        .typical(2.0, 200.0)
        .default(level(level_circumferential))
        .edit(Fidelity, "Circumferential elements", Optional(0))
        .meaning("Explicit element count along each pad's arc (before orifice refinement), overriding the fidelity level."),
    Key::integer("mesh.axial_elements", COUNT, 2, 1000)
        .typical(2.0, 200.0)
        .default(level(level_axial))
        .edit(Fidelity, "Axial elements", Optional(0))
        .meaning("Explicit element count across the full axial length (even with the half model), overriding the fidelity level."),
    Key::integer("mesh.orifice_elements", COUNT, 2, 64)
        .typical(2.0, 200.0)
        .default(level(level_orifice))
        .edit(Fidelity, "Elements across an orifice", Optional(0))
        .meaning("Explicit element count across each orifice diameter (local refinement), overriding the fidelity level."),
    Key::integer("mesh.pad_radial_elements", COUNT, 1, 200)
        .typical(2.0, 200.0)
        .default(level(level_pad_radial))
        .edit(Fidelity, "Pad layers (thermal)", Optional(0))
        .meaning("Explicit element layers through the pad thickness (pad conduction), overriding the fidelity level."),
    Key::integer("mesh.max_nodes", NODES, 1_000, 50_000_000)
        .typical(1e4, 1e7)
        .default(Fallback::Count(DEFAULT_MAX_NODES))
        .edit(Fidelity, "Node budget", Optional(0))
        .meaning("Node budget: the most mesh nodes a solve may allocate (film nodes over all pads plus, with the thermal model, the pad solids' nodes). A case whose meshes would need more is refused before anything is built; memory grows about 2 kB per node and time faster than the node count."),
];
