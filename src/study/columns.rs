//! The output columns of a study row: what a bearing engineer reads off a solve, the unit in each name.
//!
//! One table ([`COLUMNS`]): a column's name and how it is taken from a [`Solution`]. `None` is an empty
//! cell: temperatures of an isothermal solve, the Sommerfeld number of an unloaded journal. Flows are
//! whole-bearing flows (docs/MODEL.md §2: leading edges in, trailing edges and sides out, orifices in),
//! coefficients the reduced 2×2 ones at the case's excitation ratio (rows and columns x, y).

use crate::bearing::Solution;
use crate::units::{L_PER_MIN, MPA, UM};

/// One output column.
#[derive(Clone, Copy)]
pub struct Column {
    /// Name with its unit (`h_min_um`).
    pub name: &'static str,
    pub value: fn(&Solution) -> Option<f64>,
}

impl std::fmt::Debug for Column {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name)
    }
}

/// Every output column, in table order.
#[allow(clippy::cast_precision_loss)]
pub const COLUMNS: &[Column] = &[
    Column { name: "eccentricity_ratio", value: |s| Some(s.eccentricity_ratio) },
    Column { name: "attitude_angle_deg", value: |s| Some(s.attitude_angle_deg) },
    Column { name: "load_n", value: |s| Some(s.load_magnitude_n) },
    Column { name: "sommerfeld", value: |s| s.sommerfeld },
    Column { name: "h_min_um", value: |s| Some(UM.from_si(s.h_min_m)) },
    Column { name: "p_max_mpa", value: |s| Some(MPA.from_si(s.p_max_pa)) },
    Column { name: "t_max_film_c", value: |s| s.thermal.as_ref().map(|t| t.t_max_film_c) },
    Column { name: "t_max_pad_c", value: |s| s.thermal.as_ref().and_then(|t| t.t_max_pad_c) },
    Column { name: "t_journal_c", value: |s| s.thermal.as_ref().map(|t| t.journal_temperature_c) },
    Column { name: "friction_power_w", value: |s| Some(s.friction_power_w) },
    Column { name: "churning_power_w", value: |s| Some(s.churning_power_w()) },
    Column { name: "total_power_loss_w", value: |s| Some(s.total_power_loss_w()) },
    Column {
        name: "flow_leading_edges_in_l_per_min",
        value: |s| Some(L_PER_MIN.from_si(s.flows_m3_per_s.leading_edges_in)),
    },
    Column {
        name: "flow_trailing_edges_out_l_per_min",
        value: |s| Some(L_PER_MIN.from_si(s.flows_m3_per_s.trailing_edges_out)),
    },
    Column { name: "flow_sides_out_l_per_min", value: |s| Some(L_PER_MIN.from_si(s.flows_m3_per_s.sides_out)) },
    Column { name: "flow_orifices_in_l_per_min", value: |s| Some(L_PER_MIN.from_si(s.flows_m3_per_s.orifices_in)) },
    Column { name: "kxx_n_per_m", value: |s| Some(s.reduced.k_n_per_m[0][0]) },
    Column { name: "kxy_n_per_m", value: |s| Some(s.reduced.k_n_per_m[0][1]) },
    Column { name: "kyx_n_per_m", value: |s| Some(s.reduced.k_n_per_m[1][0]) },
    Column { name: "kyy_n_per_m", value: |s| Some(s.reduced.k_n_per_m[1][1]) },
    Column { name: "cxx_ns_per_m", value: |s| Some(s.reduced.c_ns_per_m[0][0]) },
    Column { name: "cxy_ns_per_m", value: |s| Some(s.reduced.c_ns_per_m[0][1]) },
    Column { name: "cyx_ns_per_m", value: |s| Some(s.reduced.c_ns_per_m[1][0]) },
    Column { name: "cyy_ns_per_m", value: |s| Some(s.reduced.c_ns_per_m[1][1]) },
    Column { name: "iterations", value: |s| Some(s.report.iterations as f64) },
];

/// The output cells of a solution, in [`COLUMNS`] order.
#[must_use]
pub fn outputs(solution: &Solution) -> Vec<Option<f64>> {
    COLUMNS.iter().map(|c| (c.value)(solution)).collect()
}

/// The column of a name.
#[must_use]
pub fn column(name: &str) -> Option<&'static Column> {
    COLUMNS.iter().find(|c| c.name == name)
}
