//! The band along the trim loops: the split of the retained region into grid cells wholly
//! inside it, taken as they are, and the band of cells the loops pass through or near; and the
//! band's constrained Delaunay triangulation (`spade`), the triangulation [`super::cells`] hands
//! over to.

use super::geometry::{orient, point, P};
use super::lattice::LatticeLines;
use super::loops::TrimError;
use super::mesh::{GridStrip, TrimBand};
use spade::handles::DirectedEdgeHandle;
use spade::{CdtEdge, ConstrainedDelaunayTriangulation, HasPosition, Point2, Triangulation};

/// A CDT vertex: a loop (or split) point, or a grid point with its index in the mesh.
#[derive(Clone, Copy, Debug)]
struct BandVertex {
    position: Point2<f64>,
    /// `LOOP_VERTEX` for a loop point, else the grid point's index in the mesh.
    mesh_index: u32,
}

const LOOP_VERTEX: u32 = u32::MAX;

impl HasPosition for BandVertex {
    type Scalar = f64;
    fn position(&self) -> Point2<f64> {
        self.position
    }
}

/// The split of the retained region into grid cells wholly inside it ("clean": four retained
/// corners, no loop in the closed cell) and the band along the loops, which alone needs a
/// constrained triangulation. The remedy for trimmed surfaces: the interior comes from
/// the grid, as GLU's monotone pieces meet its grid (`sampleMonoPoly.cc`).
pub(super) struct Band {
    /// Per cell (row-major, `grid.u.len() - 1` per row): wholly inside and away from the loops.
    pub(super) clean: Vec<bool>,
    /// Per grid point (row-major): its index in the mesh, or `u32::MAX` when not retained.
    pub(super) mesh_index: Vec<u32>,
    /// The retained grid points, row by row: the mesh's first points.
    pub(super) grid_points: Vec<P>,
    /// Each retained grid point's row-major index in the grid.
    pub(super) grid_index: Vec<u32>,
    /// The region starts inside (the domain's border is the outer loop, or there are no loops).
    pub(super) inside_domain: bool,
}

impl Band {
    pub(super) fn new(grid: &LatticeLines, kept: &[bool], touched: &[bool], inside_domain: bool) -> Self {
        let (nu, cu) = (grid.u.len(), grid.u.len().saturating_sub(1));
        let mut mesh_index = vec![u32::MAX; kept.len()];
        let retained = kept.iter().filter(|&&keep| keep).count();
        // Room for the loop points the mesh appends after the grid points (no copy of these).
        let (mut grid_points, mut grid_index) =
            (Vec::with_capacity(retained + retained / 16 + 1024), Vec::with_capacity(retained));
        for (j, ((row, slots), &v)) in
            kept.chunks_exact(nu).zip(mesh_index.chunks_exact_mut(nu)).zip(&grid.v).enumerate()
        {
            // Run by run of kept points (most rows are one or two runs): each a simple loop.
            let mut from = 0;
            while let Some(start) = row[from..].iter().position(|&keep| keep).map(|k| from + k) {
                let end = row[start..].iter().position(|&keep| !keep).map_or(nu, |k| start + k);
                let first = grid_points.len() as u32;
                for (k, slot) in slots[start..end].iter_mut().enumerate() {
                    *slot = first + k as u32;
                }
                grid_points.extend(grid.u[start..end].iter().map(|&u| [u, v]));
                let row_start = (j * nu) as u32;
                grid_index.extend((start as u32..end as u32).map(|i| row_start + i));
                from = end;
            }
        }
        // Row slices rather than index arithmetic per cell: this runs over every cell.
        let mut clean = vec![false; touched.len()];
        if cu > 0 {
            let rows: Vec<&[bool]> = kept.chunks_exact(nu).collect();
            for ((cells, touched), pair) in
                clean.chunks_exact_mut(cu).zip(touched.chunks_exact(cu)).zip(rows.windows(2))
            {
                let (below, above) = (pair[0], pair[1]);
                for (ci, (cell, &t)) in cells.iter_mut().zip(touched).enumerate() {
                    *cell = !t & below[ci] & below[ci + 1] & above[ci] & above[ci + 1];
                }
            }
        }
        Self { clean, mesh_index, grid_points, grid_index, inside_domain }
    }

    /// Per grid point (row-major): whether a band cell is among the cells round it.
    fn next_to_band(&self, grid: &LatticeLines) -> Vec<bool> {
        let (nu, cu) = (grid.u.len(), grid.u.len().saturating_sub(1));
        let mut near = vec![false; self.mesh_index.len()];
        for (cj, cells) in self.clean.chunks_exact(cu.max(1)).enumerate() {
            for (ci, _) in cells.iter().enumerate().filter(|(_, &clean)| !clean) {
                for k in [cj * nu + ci, (cj + 1) * nu + ci] {
                    near[k] = true;
                    near[k + 1] = true;
                }
            }
        }
        near
    }

    /// Whether cell (ci, cj) exists and is clean.
    fn is_clean(&self, grid: &LatticeLines, ci: usize, cj: usize) -> bool {
        ci < grid.u.len() - 1 && cj < grid.v.len() - 1 && self.clean[cj * (grid.u.len() - 1) + ci]
    }

    /// Triangulates the band (the loops' points and edges, the retained grid points next to a
    /// band cell, the clean region's outline as constraints) and appends the clean cells.
    pub(super) fn triangulate(
        &self,
        grid: &LatticeLines,
        loop_points: &[P],
        mut edges: Vec<[usize; 2]>,
    ) -> Result<TrimBand, TrimError> {
        let mut vertices: Vec<BandVertex> =
            loop_points.iter().map(|&p| BandVertex { position: point(p), mesh_index: LOOP_VERTEX }).collect();
        // Grid points with a band cell among their cells; their CDT index per grid point.
        let mut cdt_index = vec![u32::MAX; self.mesh_index.len()];
        for ((slot, &m), _) in cdt_index
            .iter_mut()
            .zip(&self.mesh_index)
            .zip(self.next_to_band(grid))
            .filter(|((_, &m), near)| *near && m != u32::MAX)
        {
            *slot = vertices.len() as u32;
            vertices.push(BandVertex { position: point(self.grid_points[m as usize]), mesh_index: m });
        }
        self.outline_edges(grid, &cdt_index, &mut edges);
        let mut band = TrimBand { points: Vec::new(), triangles: Vec::with_capacity(vertices.len() * 2) };
        if !vertices.is_empty() {
            let mut conflict = false;
            let cdt =
                ConstrainedDelaunayTriangulation::<BandVertex>::try_bulk_load_cdt(vertices, edges, |_| conflict = true)
                    .map_err(|_| TrimError::Misoriented)?;
            if conflict {
                return Err(TrimError::Intersecting);
            }
            self.band_triangles(grid, &cdt, &mut band);
        }
        Ok(band)
    }

    /// The clean region's outline as constraint edges (CDT indices): the cell sides between a
    /// clean cell and a band cell.
    fn outline_edges(&self, grid: &LatticeLines, cdt_index: &[u32], edges: &mut Vec<[usize; 2]>) {
        let (nu, cu, cv) = (grid.u.len(), grid.u.len().saturating_sub(1), grid.v.len().saturating_sub(1));
        let at = |i: usize, j: usize| cdt_index[j * nu + i] as usize;
        for cj in 0..cv {
            let row = &self.clean[cj * cu..(cj + 1) * cu];
            for ci in (0..cu).filter(|&ci| row[ci]) {
                let k = cj * cu + ci;
                if cj > 0 && !self.clean[k - cu] {
                    edges.push([at(ci, cj), at(ci + 1, cj)]);
                }
                if cj + 1 < cv && !self.clean[k + cu] {
                    edges.push([at(ci, cj + 1), at(ci + 1, cj + 1)]);
                }
                if ci > 0 && !row[ci - 1] {
                    edges.push([at(ci, cj), at(ci, cj + 1)]);
                }
                if ci + 1 < cu && !row[ci + 1] {
                    edges.push([at(ci + 1, cj), at(ci + 1, cj + 1)]);
                }
            }
        }
    }

    /// The retained band triangles of the CDT: a flood fill from the outer face, toggling parity
    /// at every loop edge (not at the clean outline); odd parity is inside an odd number of
    /// loops. Triangles inside clean cells are left to [`Band::append_strips`].
    fn band_triangles(
        &self,
        grid: &LatticeLines,
        cdt: &ConstrainedDelaunayTriangulation<BandVertex>,
        band: &mut TrimBand,
    ) {
        let is_loop_edge = |e: DirectedEdgeHandle<'_, BandVertex, (), CdtEdge<()>, ()>| {
            e.is_constraint_edge()
                && e.from().data().mesh_index == LOOP_VERTEX
                && e.to().data().mesh_index == LOOP_VERTEX
        };
        let mut parity: Vec<Option<bool>> = vec![None; cdt.num_all_faces()];
        let mut stack = Vec::new();
        for e in cdt.convex_hull() {
            // Whichever side of a hull edge is not the outer face.
            if let Some(f) = e.face().as_inner().or_else(|| e.rev().face().as_inner()) {
                if parity[f.fix().index()].is_none() {
                    parity[f.fix().index()] = Some(self.inside_domain ^ is_loop_edge(e));
                    stack.push(f);
                }
            }
        }
        while let Some(f) = stack.pop() {
            let p = parity[f.fix().index()].unwrap_or(false);
            for e in f.adjacent_edges() {
                if let Some(g) = e.rev().face().as_inner() {
                    if parity[g.fix().index()].is_none() {
                        parity[g.fix().index()] = Some(p ^ is_loop_edge(e));
                        stack.push(g);
                    }
                }
            }
        }
        let mut loop_index = vec![u32::MAX; cdt.num_vertices()];
        for f in cdt.inner_faces().filter(|f| parity[f.fix().index()] == Some(true)) {
            let [a, b, c] = f.positions();
            // Grid points in a row can make the hull, and the bulk-loaded triangulation then
            // has faces of no area along it: nothing to draw.
            if orient([a.x, a.y], [b.x, b.y], [c.x, c.y]) <= 0.0 {
                continue;
            }
            let centroid = grid.cell_coords([(a.x + b.x + c.x) / 3.0, (a.y + b.y + c.y) / 3.0]);
            let (ci, cj) = (centroid[0].floor() as usize, centroid[1].floor() as usize);
            if ci < grid.u.len() - 1 && cj < grid.v.len() - 1 && self.is_clean(grid, ci, cj) {
                continue;
            }
            let tri = f.vertices().map(|v| {
                let data = v.data();
                if data.mesh_index != LOOP_VERTEX {
                    return data.mesh_index;
                }
                let slot = &mut loop_index[v.fix().index()];
                if *slot == u32::MAX {
                    *slot = (self.grid_points.len() + band.points.len()) as u32;
                    band.points.push([data.position.x, data.position.y]);
                }
                *slot
            });
            band.triangles.push(tri);
        }
    }

    /// The clean cells as runs along grid rows.
    pub(super) fn strips(&self, grid: &LatticeLines) -> Vec<GridStrip> {
        let (nu, cu) = (grid.u.len(), grid.u.len().saturating_sub(1));
        let mut strips = Vec::new();
        for (cj, row) in self.clean.chunks_exact(cu.max(1)).enumerate() {
            let mut ci = 0;
            while ci < row.len() {
                let start = ci;
                ci += row[ci..].iter().take_while(|&&clean| clean).count();
                if ci > start {
                    let (bottom, top) = (self.mesh_index[cj * nu + start], self.mesh_index[(cj + 1) * nu + start]);
                    strips.push(GridStrip { bottom, top, cells: (ci - start) as u32 });
                }
                ci += 1;
            }
        }
        strips
    }
}
