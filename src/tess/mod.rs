//! Tessellation: Bezier maps evaluated over grids into points, partial derivatives and normals.
//!
//! This is the CPU back end that `glEvalMesh` (and later GLU NURBS and the typed mesh API) draw
//! through. It knows nothing of GL state: it takes packed control points and parameter lists.

pub mod export;
#[cfg(feature = "gpu")]
pub mod gpu;
pub(crate) mod grid;
mod mesh;
mod rows;
pub mod trim;

pub(crate) use grid::MapView;
pub use mesh::{Mesh, MeshError, MAX_MESH_VERTICES};
pub(crate) use rows::{for_row_bands, Row, RowKernel, MIN_POINTS_PER_THREAD};
