//! Tessellation on the CPU: Bezier maps evaluated over grids into points, partial derivatives
//! and normals ([`Mesh`]), trimmed parameter domains triangulated ([`trim`]), and meshes
//! exported ([`export`]).
//!
//! `glEvalMesh`, GLU's NURBS and the typed `BezierPatch::tessellate` all draw through it. It
//! knows nothing of GL state: it takes packed control points and parameter lists.

pub mod export;
pub(crate) mod grid;
mod mesh;
mod rows;
pub mod trim;

pub(crate) use grid::MapView;
pub use mesh::{Mesh, MeshError, MAX_MESH_VERTICES};
pub(crate) use rows::{rows_per_band, run_bands, Row, RowBases, RowKernel, MIN_POINTS_PER_THREAD};
