//! Finite-element building blocks: bilinear rectangles with Gauss quadrature, the sparsity pattern and a
//! Cholesky solver whose symbolic factorisation is built once per pattern and reused.

pub mod quad4;
pub mod sparse;

pub use quad4::{RectElement, GAUSS_2X2};
pub use sparse::{Pattern, SpdSolver, SolverError};
