//! Meshes: graded tensor-product grids on each pad's film surface, and the pad solids extruded from them.

pub mod grid;
pub mod pad3d;

pub use grid::{graded_nodes, PadGrid, Refinement};
pub use pad3d::PadMesh;
