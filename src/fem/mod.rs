//! Finite-element building blocks: bilinear rectangles with Gauss quadrature, general (isoparametric)
//! quadrilaterals, trilinear hexahedra in cylindrical coordinates (conduction) and Cartesian hexahedra with
//! incompatible modes (elasticity), sparse patterns with a Cholesky solver (SPD
//! systems) and an LU solver (non-symmetric systems), whose symbolic factorisations are built once per
//! pattern and reused, the SUPG-stabilised advection–diffusion kernel, and
//! shift-inverted subspace iteration for the lowest eigenpairs of sparse symmetric pencils.

pub mod eigen;
pub mod hex8;
pub mod ldu;
pub mod lu;
pub mod quad4;
pub mod quad_iso;
pub mod solid8;
pub mod sparse;
pub mod supg;

pub use ldu::StaticLdu;
pub use lu::{GeneralPattern, LuSolver};
pub use quad4::{RectElement, GAUSS_2X2};
pub use sparse::{Pattern, SolverError, SpdSolver};
