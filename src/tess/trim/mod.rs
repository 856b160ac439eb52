//! Trimmed parameter domains (GLU trimming, spec 2.7).
//!
//! A trimmed NURBS surface is drawn only over part of its (u, v) domain: the region that lies to
//! the **left** of every trim loop as it is traversed. Outer boundaries therefore run
//! counter-clockwise, holes clockwise, and loops nested inside holes alternate again:
//!
//! ```text
//!   v ^  +-------<-------+   outer loop, CCW (depth 0)
//!     |  |   +--->---+   |   hole, CW (depth 1): removed
//!     |  |   | +<-+  |   |   island, CCW (depth 2): kept again
//!     |  |   | +->+  |   |
//!     |  |   +---<---+   |
//!     |  +------->-------+
//!     +--------------------> u
//! ```
//!
//! This module checks the loops the way GLU does (curves joined head to tail within 1e-5, no
//! self-intersections, no crossings, orientation matching the nesting depth) and triangulates the
//! retained region. Grid cells wholly inside the region and clear of every loop are taken as
//! they are (two triangles each, listed as [`GridStrip`]s); only the band of cells along the
//! loops goes through a constrained Delaunay triangulation (`spade`) of the loop polylines (as
//! constraint edges), the grid points there and the outline of the grid cells, keeping the
//! triangles on the retained side of the loops. A loop running round the domain's border is the
//! domain itself: the grid reaches the border and makes no band there. The result is a mesh in
//! (u, v) at whose points the surface is then evaluated. Nothing here knows about GL.
//!
//! With [`TrimOptions::by_cells`] (what the GLU façade uses) the band is instead cut cell by cell
//! against the loops and each piece ear-clipped, handing over to the Delaunay triangulation only
//! where that cannot be done exactly.
//!
//! Files, each importing only those listed before it:
//!
//! | file | what it holds |
//! |---|---|
//! | `geometry.rs` | orientation, areas, segment tests and bounds in (u, v) |
//! | `lattice.rs` | the sampling lattice's lines and the loops traced through them |
//! | `loops.rs` | [`TrimLoop`], joining curves, GLU's loop rules, [`TrimError`] |
//! | `mesh.rs` | the results: [`TrimMesh`], [`Lattice`], [`GridStrip`], and a plan's triangulated band |
//! | `band.rs` | the split into clean cells and the band; the band's Delaunay triangulation |
//! | `cells.rs` | the band triangulated cell by cell |
//! | `plan.rs` | [`TrimOptions`], the plan, [`triangulate`] and [`triangulate_with`] |
//!
//! GLU itself (`subdivider.cc`, `slicer.cc`, `sampleMonoPoly.cc`) splits the region into monotone
//! pieces and stitches them to its uniform grid; the triangles differ, the covered region and
//! the grid points inside it are the same.

mod band;
mod cells;
mod geometry;
mod lattice;
mod loops;
mod mesh;
mod plan;
#[cfg(test)]
mod tests;

pub use loops::{join_curves, split_at_lines, TrimError, TrimLoop, JOIN_TOLERANCE};
pub use mesh::{GridStrip, Lattice, TrimMesh};
pub(crate) use plan::TrimPlan;
pub use plan::{triangulate, triangulate_with, TrimOptions};
