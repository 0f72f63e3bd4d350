//! Meshes: graded tensor-product grids on each pad's film surface.

pub mod grid;

pub use grid::{graded_nodes, PadGrid, Refinement};
