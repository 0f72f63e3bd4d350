//! The output columns of a study row: the rows of the table of outputs
//! ([`crate::bearing::solution::outputs::OUTPUTS`]) that have a CSV column, in the table's order, each in
//! the unit its name ends with (`h_min_um`).
//!
//! `None` is an empty cell: temperatures of an isothermal solve, the Sommerfeld number of an unloaded
//! journal. Flows are whole-bearing flows (docs/MODEL.md §2: leading edges in, trailing edges and sides
//! out, orifices in), coefficients the reduced 2×2 ones at the case's excitation ratio (rows and columns
//! x, y). A column is added by giving its row in the table a `csv` name; nothing here changes.

use crate::bearing::solution::outputs::{Output, OUTPUTS};
use crate::bearing::Solution;

/// One output column.
#[derive(Clone, Copy)]
pub struct Column {
    /// Name with its unit (`h_min_um`).
    pub name: &'static str,
    /// Its row of the table of outputs.
    pub output: &'static Output,
}

impl Column {
    /// The cell of a solution, in the column's unit.
    #[must_use]
    pub fn value(&self, s: &Solution) -> Option<f64> {
        self.output.shown(s)
    }
}

impl std::fmt::Debug for Column {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name)
    }
}

/// How many rows of the table have a CSV column.
const fn column_count(rows: &[Output]) -> usize {
    let (mut n, mut k) = (0, 0);
    while k < rows.len() {
        if rows[k].csv.is_some() {
            n += 1;
        }
        k += 1;
    }
    n
}

const N: usize = column_count(OUTPUTS);

/// The rows with a CSV column, in table order.
const fn columns_of(rows: &'static [Output]) -> [Column; N] {
    let mut out = [Column { name: "", output: &rows[0] }; N];
    let (mut n, mut k) = (0, 0);
    while k < rows.len() {
        if let Some(name) = rows[k].csv {
            out[n] = Column { name, output: &rows[k] };
            n += 1;
        }
        k += 1;
    }
    out
}

const ALL: [Column; N] = columns_of(OUTPUTS);

/// Every output column, in table order.
pub const COLUMNS: &[Column] = &ALL;

/// The output cells of a solution, in [`COLUMNS`] order.
#[must_use]
pub fn outputs(solution: &Solution) -> Vec<Option<f64>> {
    COLUMNS.iter().map(|c| c.value(solution)).collect()
}

/// The column of a name.
#[must_use]
pub fn column(name: &str) -> Option<&'static Column> {
    COLUMNS.iter().find(|c| c.name == name)
}
