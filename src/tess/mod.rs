//! Tessellation: Bezier maps evaluated over grids into points, partial derivatives and normals.
//!
//! This is the CPU back end that `glEvalMesh` (and later GLU NURBS and the typed mesh API) draw
//! through. It knows nothing of GL state: it takes packed control points and parameter lists.

pub mod export;
pub mod grid;
pub mod mesh;
pub mod rows;
pub mod trim;

pub use grid::{eval_grid1, eval_grid2, BasisTable, Grid2, MapView};
pub use mesh::{Mesh, MeshError, MAX_MESH_VERTICES};
pub(crate) use rows::MIN_POINTS_PER_THREAD;
pub use rows::{for_row_bands, rows_per_band, run_bands, Row, RowKernel};
