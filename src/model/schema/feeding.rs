//! Rows of `[feeding]`: how oil reaches the pads' leading edges, and so which oil enters each film and at what
//! temperature (docs/MODEL.md §3.4). The film itself sees the feeding only through its inlet (flooded, or a
//! supply flow with the mass-conserving cavitation option); the kinds differ in the groove mixing of the
//! thermal model.

use super::Group::Thermal;
use super::Widget::{Choice, Optional};
use super::{Fallback, KeySpec};
use crate::model::error::Range;
use crate::model::file::{CaseFile, FeedingKind, ThermalModelKind};
use crate::units::ONE;

type Key = KeySpec;

fn thd(f: &CaseFile) -> bool {
    f.thermal.model == Some(ThermalModelKind::Thd)
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
];
