//! What a trimmed domain's triangulation yields: the retained points, the band's triangles, the
//! grid strips, and the lattice the grid points lie on.

use super::geometry::orient;
use super::lattice::grid_lines;

/// A triangulated region of the parameter domain.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TrimMesh {
    /// Vertices in (u, v): the retained grid points row by row (v outer, u inner), then the loop
    /// points (and any split points). Grid points on the domain's border are among them when
    /// the border is the outer loop (or there are no loops). Every vertex is used by a triangle.
    pub points: Vec<[f64; 2]>,
    /// The band along the loops as counter-clockwise triangles (u to the right, v up), indices
    /// into `points`. [`TrimMesh::triangles`] adds the strips' cells.
    pub band: Vec<[u32; 3]>,
    /// The grid cells that lie wholly inside the region, away from every loop, as runs of
    /// cells along a grid row (two triangles per cell, or a quad strip per run).
    pub strips: Vec<GridStrip>,
    /// The lattice the grid points lie on, and where each of them is in it.
    pub lattice: Lattice,
}

/// The lattice of sampling lines a [`TrimMesh`]'s grid points lie on. A caller that evaluates
/// the surface on the whole lattice (say while the triangulation runs, from
/// [`Lattice::lines`]) finds each grid point's value through `index`.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Lattice {
    /// The u lines, increasing: the domain's bounds and the finite sampling lines strictly
    /// between them (every other line dropped while the point budget was exceeded).
    pub u: Vec<f64>,
    /// The v lines, likewise.
    pub v: Vec<f64>,
    /// For each of the mesh's first `index.len()` points (its grid points), the point's index
    /// `j * u.len() + i` in the lattice (v outer).
    pub index: Vec<u32>,
}

impl Lattice {
    /// The lattice [`triangulate`](super::triangulate) starts from for `domain` ([umin, umax, vmin, vmax]) and the
    /// sampling lines `us`, `vs` (before any coarsening; `index` empty).
    #[must_use]
    pub fn lines(domain: [f64; 4], us: &[f64], vs: &[f64]) -> Self {
        let [u0, u1, v0, v1] = domain;
        Self { u: grid_lines(us, u0, u1), v: grid_lines(vs, v0, v1), index: Vec::new() }
    }

    /// The lattice's point count.
    #[must_use]
    pub fn point_count(&self) -> usize {
        self.u.len().saturating_mul(self.v.len())
    }

    /// Whether both have the same lines (the indices aside).
    #[must_use]
    pub fn same_lines(&self, other: &Self) -> bool {
        self.u == other.u && self.v == other.v
    }
}

/// A run of `cells` grid cells along one row of the sampling grid. The run's bottom points are
/// `points[bottom..=bottom + cells]` and its top points `points[top..=top + cells]`, by
/// increasing u; the top row has the larger v.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct GridStrip {
    /// Index of the run's first bottom point.
    pub bottom: u32,
    /// Index of the run's first top point.
    pub top: u32,
    /// Number of cells.
    pub cells: u32,
}

impl GridStrip {
    /// The run's cells as counter-clockwise triangles, two per cell.
    pub fn triangles(self) -> impl Iterator<Item = [u32; 3]> {
        (0..self.cells).flat_map(move |i| {
            let (a, b, c, d) = (self.bottom + i, self.bottom + i + 1, self.top + i + 1, self.top + i);
            [[a, b, c], [a, c, d]]
        })
    }
}

impl TrimMesh {
    /// Every triangle, counter-clockwise: the band's, then two per cell of the strips, run by
    /// run.
    pub fn triangles(&self) -> impl Iterator<Item = [u32; 3]> + '_ {
        self.band.iter().copied().chain(self.strips.iter().flat_map(|s| s.triangles()))
    }

    /// The number of triangles [`TrimMesh::triangles`] yields.
    #[must_use]
    pub fn triangle_count(&self) -> usize {
        self.band.len() + self.strips.iter().map(|s| 2 * s.cells as usize).sum::<usize>()
    }

    /// The total area of the triangles in (u, v).
    #[must_use]
    pub fn area(&self) -> f64 {
        let at = |i: u32| self.points.get(i as usize).copied().unwrap_or([0.0; 2]);
        self.triangles().map(|t| 0.5 * orient(at(t[0]), at(t[1]), at(t[2]))).sum()
    }
}

/// The band of a `TrimPlan`: its triangles, over the plan's grid points (ids below
/// `TrimPlan::grid_points().len()`) and the band's own `points` after them.
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct TrimBand {
    /// The points the band adds after the grid points: loop points, crossings.
    pub points: Vec<[f64; 2]>,
    /// Counter-clockwise triangles.
    pub triangles: Vec<[u32; 3]>,
}
