//! Rows of the title and of `[bearing]`: geometry, `[bearing.pads]` (also every `[[bearing.pad]]` override) and
//! `[[bearing.pads.orifice]]`.

use super::Group::{Geometry, Orifices, Pads, Title};
use super::Widget::{Choice, Custom, Number, Optional, Text};
use super::{Fallback, KeySpec, ANGLE};
use crate::model::error::Range;
use crate::model::file::{CaseFile, ContactKindFile};
use crate::units::{COUNT, DEG, GPA, KG_PER_M3, MM, N_PER_M, ONE, UM};

type Key = KeySpec;

/// `bearing.assembled_clearance_um` is at most this fraction of the journal radius (bearings are 1–3 ‰).
pub const MAX_CLEARANCE_RATIO: f64 = 0.05;

const GEOMETRY_CHOICE: Fallback = Fallback::Rule("give one of preload, clearance_um, bore_radius_mm");

fn preload_given(f: &CaseFile) -> bool {
    f.bearing.pads.clearance_um.is_none() && f.bearing.pads.bore_radius_mm.is_none()
}
fn clearance_given(f: &CaseFile) -> bool {
    f.bearing.pads.clearance_um.is_some()
}
fn bore_given(f: &CaseFile) -> bool {
    f.bearing.pads.clearance_um.is_none() && f.bearing.pads.bore_radius_mm.is_some()
}
fn has_mass(f: &CaseFile) -> bool {
    f.bearing.pads.massless != Some(true)
}
fn no_contact(f: &CaseFile) -> bool {
    f.bearing.pads.pivot_contact.is_none()
}
fn contact(f: &CaseFile) -> bool {
    f.bearing.pads.pivot_contact.is_some()
}
fn rocker(f: &CaseFile) -> bool {
    f.bearing.pads.pivot_contact == Some(ContactKindFile::Rocker)
}
fn bearing_length(f: &CaseFile) -> f64 {
    f.bearing.length_mm
}

pub(super) const KEYS: &[Key] = &[
    Key::text("title").edit(Title, "Title", Text).meaning("Free text shown in the workbench and in result files."),
    // [bearing]
    Key::number("bearing.journal_radius_mm", MM, Range::positive(1e4))
        .typical(10.0, 500.0)
        .edit(Geometry, "Journal radius R", Number(3))
        .meaning("Radius of the shaft journal running in the bearing."),
    Key::number("bearing.length_mm", MM, Range::positive(1e4))
        .typical(10.0, 400.0)
        .edit(Geometry, "Pad length L", Number(3))
        .meaning("Axial length of the pads. With L/D below about 0.5 side leakage dominates and the load capacity falls quickly."),
    Key::rule("bearing.assembled_clearance_um", UM, "(0, 5 % of the journal radius]")
        .typical(20.0, 400.0)
        .edit(Geometry, "Assembled clearance Cb", Number(2))
        .meaning("Radial clearance of the assembled bearing: the gap between the journal and the pads at their pivots with the journal centred. Typically 1–2 ‰ of the radius."),
    // [bearing.pads]
    Key::integer("bearing.pads.count", COUNT, 1, 24)
        .default(Fallback::Rule("the number of [[bearing.pad]] entries or pivot angles"))
        .edit(Pads, "Number of pads", Custom)
        .meaning("How many pads share the circumference."),
    Key::choice("bearing.pads.kind", &["tilting", "fixed"])
        .default(Fallback::Word("tilting"))
        .edit(Pads, "Pad kind", Choice(&["tilting", "fixed sector"]))
        .meaning("Tilting pads rotate freely about their pivots (no cross-coupled stiffness from a symmetric bearing); fixed sectors do not tilt (lobed or plain bearings)."),
    Key::rule("bearing.pads.arc_deg", DEG, "(0, 360/count] (360 for one fixed sector)")
        .typical(20.0, 120.0)
        .edit(Pads, "Pad arc β", Number(2))
        .meaning("Angular extent of each pad."),
    Key::per_pad("bearing.pads.pivot_deg", DEG, ANGLE)
        .typical(0.0, 360.0)
        .edit(Pads, "Pivot angles", Custom)
        .meaning("Angle of each pad's pivot from +x (horizontal), counter-clockwise; the load usually acts at 270° (down). A pivot at 270° is load on pad, pivots at 225° and 315° load between pads. One angle: the first pad, the others evenly spaced."),
    Key::rule("bearing.pads.offset", ONE, "(0, 1) for tilting pads, [0, 1] for fixed sectors")
        .typical(0.4, 0.7)
        .default(Fallback::Sometimes { value: 0.5, text: "0.5 for fixed sectors" })
        .edit(Pads, "Pivot offset α", Number(3))
        .meaning("Pivot position as a fraction of the arc from the leading edge: 0.5 is centred (either rotation direction), 0.6 is the common offset that raises the film thickness and lowers the temperature."),
    Key::number("bearing.pads.preload", ONE, Range::open_hi(-1.0, 1.0))
        .typical(0.0, 0.7)
        .default(GEOMETRY_CHOICE)
        .edit(Pads, "Preload m", Number(3))
        .when(preload_given)
        .meaning("m = 1 − Cb/Cp: how much the pads' own curvature converges on the journal. Preload keeps unloaded pads working (a converging wedge) and raises stiffness."),
    Key::number("bearing.pads.clearance_um", UM, Range::positive(1e6))
        .typical(20.0, 600.0)
        .default(GEOMETRY_CHOICE)
        .edit(Pads, "Pad clearance Cp", Number(2))
        .when(clearance_given)
        .meaning("Machined radial clearance of the pads: pad bore radius minus journal radius."),
    Key::number_where("bearing.pads.bore_radius_mm", MM, Range::positive(1e4), "greater than the journal radius")
        .typical(10.0, 500.0)
        .default(GEOMETRY_CHOICE)
        .edit(Pads, "Pad bore radius Rp", Number(4))
        .when(bore_given)
        .meaning("Radius to which the pads are machined, Rp = R + Cp."),
    Key::number("bearing.pads.thickness_mm", MM, Range::positive(1e4))
        .typical(3.0, 150.0)
        .default(Fallback::Sometimes { value: 0.0, text: "0 for fixed sectors" })
        .edit(Pads, "Pad thickness t", Number(3))
        .meaning("Radial thickness of the pad; the pivot sits on its back, so t sets the lever of the tilt."),
    Key::flag("bearing.pads.massless")
        .default(Fallback::Flag(false))
        .edit(Pads, "Pad inertia", Custom)
        .meaning("Pads without inertia (zero mass and moment of inertia), as databook coefficients assume; the reduced coefficients then do not depend on the pad material. Give no density with it."),
    // Real pivots are 1e7–1e10 N/m; below 1e5 N/m a pad would float millimetres off its seat.
    Key::number("bearing.pads.pivot_stiffness_n_per_m", N_PER_M, Range::closed(1e5, 1e14))
        .typical(1e6, 1e10)
        .default(Fallback::Rule("rigid pivot"))
        .edit(Pads, "Pivot stiffness", Optional(0))
        .when(no_contact)
        .meaning("Radial stiffness of the pivot contact (a rocker-back Hertz contact, a spring). Absent: rigid pivot. A soft pivot lowers the bearing's effective stiffness."),
    Key::number("bearing.pads.pivot_transverse_stiffness_n_per_m", N_PER_M, Range::closed(1e5, 1e14))
        .typical(1e6, 1e10)
        .default(Fallback::Rule("rigid pivot"))
        .edit(Pads, "Pivot transverse stiffness", Optional(0))
        .meaning("Stiffness of the pivot across the pivot line (a rocker's tangential contact). Absent: the pivot does not move sideways. A finite value adds the sideways pivot motion as a pad coordinate."),
    Key::number("bearing.pads.density_kg_per_m3", KG_PER_M3, Range::positive(3e4))
        .typical(1000.0, 9000.0)
        .or(7800.0)
        .edit(Pads, "Pad density", Optional(0))
        .when(has_mass)
        .meaning("Pad material density: sets the pad inertia that enters the frequency-dependent reduced coefficients."),
    Key::number("bearing.pads.youngs_modulus_gpa", GPA, Range::positive(2000.0))
        .typical(70.0, 220.0)
        .or(200.0)
        .edit(Pads, "Young's modulus E", Optional(1))
        .meaning("Pad material stiffness, for the pad flexibility model (steel 200 GPa, brass about 100 GPa). Not used by rigid pads."),
    Key::number("bearing.pads.poisson_ratio", ONE, Range::open(-1.0, 0.5))
        .typical(0.25, 0.35)
        .or(0.3)
        .edit(Pads, "Poisson ratio ν", Optional(3))
        .meaning("Pad material Poisson ratio, for the pad flexibility model."),
    Key::choice("bearing.pads.pivot_contact", &["rocker", "ball"])
        .default(Fallback::Rule("none (pivot_stiffness_n_per_m, else rigid)"))
        .edit(Pads, "Pivot contact", Custom)
        .meaning("Pivot stiffness from a Hertz contact, nonlinear in the pad's load: a rocker (cylinder in a cylindrical seat, line contact) or a ball in a socket. The radial stiffness follows each pad's load in the equilibrium (isothermal model). Instead of pivot_stiffness_n_per_m."),
    Key::number("bearing.pads.pivot_radius_mm", MM, Range::positive(1e4))
        .typical(5.0, 200.0)
        .default(Fallback::Rule("required with pivot_contact"))
        .edit(Pads, "Pivot radius", Optional(3))
        .when(contact)
        .meaning("Radius of the pivot's convex surface (rocker back or ball), of the pad's material. Smaller radii make softer, more load-dependent pivots."),
    Key::number("bearing.pads.pivot_seat_radius_mm", MM, Range::positive(1e4))
        .typical(5.0, 250.0)
        .default(Fallback::Rule("required with pivot_contact"))
        .edit(Pads, "Pivot seat radius", Optional(3))
        .when(contact)
        .meaning("Radius of the housing's concave seat, larger than the pivot radius; the closer the two, the more conformal and stiffer the contact."),
    Key::number("bearing.pads.pivot_length_mm", MM, Range::positive(1e4))
        .typical(10.0, 300.0)
        .default(Fallback::Follows { text: "the bearing length", value: bearing_length })
        .edit(Pads, "Rocker contact length", Optional(3))
        .when(rocker)
        .meaning("Length of a rocker's line contact (not used by a ball)."),
    Key::number("bearing.pads.pivot_seat_youngs_modulus_gpa", GPA, Range::positive(2000.0))
        .typical(70.0, 220.0)
        .or(200.0)
        .edit(Pads, "Seat Young's modulus", Optional(1))
        .when(contact)
        .meaning("Young's modulus of the pivot seat (housing) material."),
    Key::number("bearing.pads.pivot_seat_poisson_ratio", ONE, Range::open(-1.0, 0.5))
        .typical(0.25, 0.35)
        .or(0.3)
        .edit(Pads, "Seat Poisson ratio", Optional(3))
        .when(contact)
        .meaning("Poisson ratio of the pivot seat (housing) material."),
    // [[bearing.pads.orifice]]
    Key::number_where("bearing.pads.orifice[].position_frac", ONE, Range::open(0.0, 1.0), "the hole inside the pad's arc")
        .typical(0.1, 0.9)
        .edit(Orifices, "Position along arc", Number(3))
        .meaning("Circumferential position of the orifice centre as a fraction of the arc from the leading edge. Injection near the leading edge lifts the pad's leading edge and cools the film."),
    Key::number_where("bearing.pads.orifice[].axial_frac", ONE, Range::open(0.0, 1.0), "the hole inside the pad's length")
        .typical(0.2, 0.8)
        .or(0.5)
        .edit(Orifices, "Axial position", Number(3))
        .meaning("Axial position as a fraction of the length; 0.5 is the mid-plane (the half model needs every orifice there)."),
    Key::number("bearing.pads.orifice[].diameter_mm", MM, Range::positive(1e3))
        .typical(1.0, 10.0)
        .edit(Orifices, "Diameter d0", Number(3))
        .meaning("Orifice diameter: the injected flow scales with d0⁴ (Hagen–Poiseuille)."),
    Key::number("bearing.pads.orifice[].length_mm", MM, Range::positive(1e4))
        .typical(1.0, 20.0)
        .edit(Orifices, "Capillary length l0", Number(3))
        .meaning("Length of the capillary through the pad: its hydraulic resistance, proportional to l0/d0⁴, throttles the injection."),
];
