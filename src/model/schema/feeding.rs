//! Rows of `[feeding]`: how oil reaches the pads' leading edges, and so which oil enters each film and at what
//! temperature (docs/MODEL.md §3.4). The film itself sees the feeding only through its inlet (flooded, or a
//! supply flow with the mass-conserving cavitation option) and its pressure (the ram pressure, §2.2); the
//! kinds differ in the groove mixing of the thermal model.

use super::Group::{Physics, Thermal};
use super::Widget::{Choice, Optional};
use super::{Fallback, KeySpec};
use crate::model::error::Range;
use crate::model::file::{CaseFile, FeedingKind, ThermalModelKind};
use crate::units::{DEG, ONE};

type Key = KeySpec;

fn thd(f: &CaseFile) -> bool {
    f.thermal.model == Some(ThermalModelKind::Thd)
}
fn flooded(f: &CaseFile) -> bool {
    matches!(f.feeding.kind, None | Some(FeedingKind::Flooded))
}
fn groove(f: &CaseFile) -> bool {
    thd(f) && f.feeding.kind == Some(FeedingKind::LeadingEdgeGroove)
}

/// Default hot-oil carry-over past a leading-edge groove (chosen, not published: the literature reports the
/// groove's fresh oil displacing most of the hot film, docs/MODEL.md §3.4).
pub const GROOVE_CARRY_OVER: f64 = 0.2;

pub(super) const KEYS: &[Key] = &[
    Key::choice("feeding.kind", &["flooded", "leading_edge_groove", "spray_bar"])
        .default(Fallback::Word("flooded"))
        .edit(
            Thermal,
            "Oil feeding",
            Choice(&["Flooded housing", "Leading-edge groove", "Spray bar between pads"]),
        )
        .when(thd)
        .meaning("How supply oil reaches the pads, and so the inlet temperature of each pad. Flooded: the pads run in an oil bath; the hot oil the journal carries from the pad upstream (thermal.carry_over of it) enters the film first and supply oil makes up the rest. Leading-edge groove: supply oil is fed at each pad's leading edge and displaces most of the hot oil; only feeding.groove_carry_over of it enters. Spray bar: supply oil is sprayed into the gap between pads and mixes fully with the carried hot oil before the film takes its share. With operating.supply_flow_l_per_min (starved pads) the oil offered at each leading edge is the pad's supply share plus the carried hot oil."),
    Key::number("feeding.groove_carry_over", ONE, Range::closed(0.0, 1.0))
        .typical(0.0, 0.4)
        .or(GROOVE_CARRY_OVER)
        .edit(Thermal, "Groove carry-over λg", Optional(2))
        .when(groove)
        .meaning("Leading-edge groove only: fraction of the hot oil leaving the pad upstream that passes the groove on the journal and enters the next film (the flooded bearing's thermal.carry_over is typically 0.7–0.9; a groove leaves much less). The default 0.2 is chosen, not fitted to a test."),
    Key::number_where("feeding.groove_width_deg", DEG, Range::open_lo(0.0, 90.0), "at most the gap between pads")
        .typical(3.0, 10.0)
        .edit(Thermal, "Groove width", Optional(1))
        .when(groove)
        .meaning("Leading-edge groove only: the groove's angular width on the bore. It must fit in the gap between the pads (the gap ahead of each pad follows from the pads' leading edges and arcs; with n equal, evenly spaced pads 360°/n − arc); a wider groove is refused naming the gap. The mixing model does not read the width: what passes the groove is set by feeding.groove_carry_over alone. Absent: not checked."),
    Key::number("feeding.churning_factor", ONE, Range::closed(0.0, 10.0))
        .typical(0.0, 2.0)
        .or(1.0)
        .edit(Thermal, "Churning factor", Optional(2))
        .when(flooded)
        .meaning("Flooded housing only: scale on the churning loss, the drag of the journal over the oil-filled cavities between the pads (docs/MODEL.md §3.8: each cavity taken as a turbulent Couette layer as deep as the pad, by the law of the wall of the film's turbulence model). It is reported apart from the film's friction and added to it in the total power loss; it does not heat the films (the housing oil takes it away). 1: the model's estimate (the default); 0: no churning. Directed feeding (leading-edge groove, spray bar) drains the housing: no churning, and this key is refused."),
    Key::number("feeding.ram_pressure_coefficient", ONE, Range::closed(0.0, 1.0))
        .typical(0.0, 0.5)
        .or(0.0)
        .edit(Physics, "Ram pressure k_ram", Optional(2))
        .meaning("Leading-edge (ram) pressure of the oil entering each film: p_le = k_ram · ρU²/2 on the pad's mid-plane, with U the journal surface speed, imposed along every pad's leading edge as p_le cos(π z/L), ambient at the axial ends where the oil escapes sideways. 0: ambient leading edges (the default and the thesis' condition); 1: the oil brought to rest from the full journal speed (Bernoulli's bound). Measured inlet pressures are a fraction of ρU²/2; the coefficient is the model's handle, not fitted to a test. Reynolds and Gümbel cavitation only (a starved, mass-conserving inlet has no pressure)."),
];
