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
//! GLU itself (`subdivider.cc`, `slicer.cc`, `sampleMonoPoly.cc`) splits the region into monotone
//! pieces and stitches them to its uniform grid; the triangles differ, the covered region and
//! the grid points inside it are the same.

use spade::handles::DirectedEdgeHandle;
use spade::{CdtEdge, ConstrainedDelaunayTriangulation, HasPosition, Point2, Triangulation};

/// GLU's tolerance for joining trim curves (`arc.cc` ZERO): |Δu| and |Δv| both at most this.
pub const JOIN_TOLERANCE: f64 = 1e-5;

type P = [f64; 2];

/// A closed trim loop: a polyline in (u, v), the last point joined back to the first.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TrimLoop {
    /// The vertices. Repeating the first point at the end is allowed but not needed.
    pub points: Vec<[f64; 2]>,
}

impl TrimLoop {
    /// A loop through `points`.
    #[must_use]
    pub fn new(points: Vec<[f64; 2]>) -> Self {
        Self { points }
    }

    /// The signed area (shoelace formula): positive for a counter-clockwise loop.
    #[must_use]
    pub fn signed_area(&self) -> f64 {
        signed_area(&self.points)
    }
}

/// Why a set of trim loops is rejected, with GLU's error numbers.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TrimError {
    /// Consecutive curves of a loop do not meet within 1e-5 (GLU error 31).
    Unconnected,
    /// A loop crosses or touches itself, runs the wrong way for its nesting depth, has fewer than
    /// three distinct points or no area, has a point that is not finite or lies outside the
    /// domain; or the domain itself is empty or not finite (GLU error 28).
    Misoriented,
    /// Two loops cross or touch (GLU error 29).
    Intersecting,
    /// A loop without any point, or no curve at all (GLU error 18).
    Empty,
}

impl TrimError {
    /// The GLU NURBS error number (`GLU_NURBS_ERRORn`): 31, 28, 29 or 18.
    ///
    /// ```
    /// use gleval::tess::trim::{join_curves, TrimError};
    /// let err = join_curves(&[vec![[0.0, 0.0], [1.0, 0.0]], vec![[1.0, 0.5], [0.0, 0.0]]]);
    /// assert_eq!(err, Err(TrimError::Unconnected));
    /// assert_eq!(TrimError::Unconnected.glu_number(), 31);
    /// ```
    #[must_use]
    pub fn glu_number(self) -> u32 {
        match self {
            Self::Unconnected => 31,
            Self::Misoriented => 28,
            Self::Intersecting => 29,
            Self::Empty => 18,
        }
    }
}

impl std::fmt::Display for TrimError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        // GLU's own texts (`glue.c` __gluNurbsErrors).
        let text = match self {
            Self::Unconnected => "unconnected trim curves",
            Self::Misoriented => "intersecting or misoriented trim curves",
            Self::Intersecting => "intersecting trim curves",
            Self::Empty => "invalid or missing trim curve",
        };
        f.write_str(text)
    }
}

impl std::error::Error for TrimError {}

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
    /// The lattice [`triangulate`] starts from for `domain` ([umin, umax, vmin, vmax]) and the
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

/// How [`triangulate_with`] samples the retained region.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TrimOptions {
    /// Grid points closer to a loop than this fraction of the local grid spacing are left out,
    /// so that no sliver triangles form along the loops. Distances are measured in grid cells
    /// (u and v scaled by their local spacings); clamped to [0, 0.5].
    pub clearance: f64,
    /// Give loop edges a vertex wherever they cross a grid line, so that long trim edges are
    /// sampled as finely as the interior. GLU splits user trims only at knot lines and at its
    /// sampling subdivisions, so this is off by default; [`split_at_lines`] splits at chosen
    /// lines. The border loop made when there are no loops is always split (GLU tessellates
    /// its border arcs at the sampling step).
    pub split_at_grid_lines: bool,
    /// Budget for grid points plus split points. While it is exceeded, every other
    /// grid line is dropped (in u and in v), so absurd sampling cannot exhaust memory.
    pub max_points: usize,
    /// Triangulate the band cell by cell: every cell a loop passes through clipped against the
    /// loops and ear-clipped, as GLU's slicer meets its grid, instead of one constrained
    /// Delaunay triangulation of the whole band. Linear in the band's size; loop edges gain a
    /// vertex at every grid line they cross, and grid points are kept however close to a loop
    /// (use it with clearance 0). Where it cannot decide (a loop inside one grid cell), or its
    /// area does not check against the loops' shoelace area, the Delaunay triangulation runs.
    pub by_cells: bool,
}

impl TrimOptions {
    /// Clearance 0.25, no splitting, at most 4 million grid and split points.
    pub const DEFAULT: Self =
        Self { clearance: 0.25, split_at_grid_lines: false, max_points: 4_000_000, by_cells: false };

    /// With another clearance (a fraction of the grid spacing).
    #[must_use]
    pub const fn with_clearance(self, clearance: f64) -> Self {
        Self { clearance, ..self }
    }

    /// With or without the cell-by-cell triangulation of the band.
    #[must_use]
    pub const fn with_by_cells(self, by_cells: bool) -> Self {
        Self { by_cells, ..self }
    }

    /// With or without vertices where loop edges cross grid lines.
    #[must_use]
    pub const fn with_split_at_grid_lines(self, split_at_grid_lines: bool) -> Self {
        Self { split_at_grid_lines, ..self }
    }

    /// With another budget of grid and split points.
    #[must_use]
    pub const fn with_max_points(self, max_points: usize) -> Self {
        Self { max_points, ..self }
    }
}

impl Default for TrimOptions {
    fn default() -> Self {
        Self::DEFAULT
    }
}

fn close(a: P, b: P) -> bool {
    (a[0] - b[0]).abs() <= JOIN_TOLERANCE && (a[1] - b[1]).abs() <= JOIN_TOLERANCE
}

fn midpoint(a: P, b: P) -> P {
    [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])]
}

/// Joins the curves (polylines) of one trim loop head to tail, as GLU does before tessellating.
///
/// Each curve's last point must meet the next curve's first point, and the last curve's end the
/// first curve's start, within [`JOIN_TOLERANCE`] in u and in v (`arc.cc` `isDisconnected`);
/// meeting points are snapped to their average. Consecutive points within the tolerance are
/// merged (`reader.cc` ELIMINATE_REDUNDANT_POINTS), as is a closing point equal to the first.
///
/// Errors: no curves or no points → [`TrimError::Empty`]; a gap → [`TrimError::Unconnected`];
/// a point that is not finite, or fewer than three distinct points → [`TrimError::Misoriented`].
///
/// ```
/// use gleval::tess::trim::join_curves;
/// let bottom = vec![[0.0, 0.0], [1.0, 0.0]];
/// let rest = vec![[1.0, 4e-6], [1.0, 1.0], [0.0, 1.0], [0.0, 0.0]];
/// let l = join_curves(&[bottom, rest]).unwrap();
/// assert_eq!(l.points, vec![[0.0, 0.0], [1.0, 2e-6], [1.0, 1.0], [0.0, 1.0]]);
/// ```
pub fn join_curves(pieces: &[Vec<[f64; 2]>]) -> Result<TrimLoop, TrimError> {
    let mut pieces: Vec<Vec<P>> = pieces.iter().filter(|p| !p.is_empty()).cloned().collect();
    if pieces.is_empty() {
        return Err(TrimError::Empty);
    }
    if pieces.iter().flatten().any(|p| !is_finite(*p)) {
        return Err(TrimError::Misoriented);
    }
    let n = pieces.len();
    for i in 0..n {
        let j = (i + 1) % n;
        let (Some(&end), Some(&start)) = (pieces[i].last(), pieces[j].first()) else { continue };
        if !close(end, start) {
            return Err(TrimError::Unconnected);
        }
        let m = midpoint(end, start);
        if let Some(last) = pieces[i].last_mut() {
            *last = m;
        }
        pieces[j][0] = m;
    }
    let mut points: Vec<P> = Vec::new();
    for p in pieces.iter().flatten() {
        if points.last().is_none_or(|q| !close(*q, *p)) {
            points.push(*p);
        }
    }
    while points.len() > 1 && points.last().is_some_and(|q| close(points[0], *q)) {
        points.pop();
    }
    if points.len() < 3 {
        return Err(TrimError::Misoriented);
    }
    Ok(TrimLoop { points })
}

/// The loop with a vertex added wherever an edge crosses one of the lines u = `us[i]` or
/// v = `vs[j]` (GLU's `splitInS`/`splitInT` at knot lines). The new vertices lie on the edges,
/// with the crossed coordinate exactly equal to the line's.
#[must_use]
pub fn split_at_lines(l: &TrimLoop, us: &[f64], vs: &[f64]) -> TrimLoop {
    let grid = Grid {
        u: sorted_lines(us, f64::NEG_INFINITY, f64::INFINITY),
        v: sorted_lines(vs, f64::NEG_INFINITY, f64::INFINITY),
    };
    let n = l.points.len();
    let mut points = Vec::with_capacity(n);
    for i in 0..n {
        let (a, b) = (l.points[i], l.points[(i + 1) % n]);
        points.push(a);
        if n > 1 && is_finite(a) && is_finite(b) {
            points.extend(grid.crossings(a, b).into_iter().map(|c| c.1));
        }
    }
    TrimLoop { points }
}

/// Triangulates the region the loops retain within `domain` = [umin, umax, vmin, vmax], with
/// [`TrimOptions::DEFAULT`]; see [`triangulate_with`].
///
/// ```
/// use gleval::tess::trim::{triangulate, TrimLoop};
/// // A square hole (clockwise) in the unit square.
/// let outer = TrimLoop::new(vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]);
/// let hole = TrimLoop::new(vec![[0.25, 0.25], [0.25, 0.75], [0.75, 0.75], [0.75, 0.25]]);
/// let grid = [0.0, 0.5, 1.0];
/// let mesh = triangulate(&[outer, hole], [0.0, 1.0, 0.0, 1.0], &grid, &grid).unwrap();
/// assert!((mesh.area() - 0.75).abs() < 1e-12);
/// ```
pub fn triangulate(loops: &[TrimLoop], domain: [f64; 4], us: &[f64], vs: &[f64]) -> Result<TrimMesh, TrimError> {
    triangulate_with(loops, domain, us, vs, &TrimOptions::DEFAULT)
}

/// Triangulates the region the loops retain within `domain` = [umin, umax, vmin, vmax].
///
/// `us` and `vs` are the sampling grid lines (any order; duplicates, lines outside the open
/// domain and non-finite values are ignored). The grid points strictly inside the retained region
/// and not within `options.clearance` grid cells of a loop are used. Cells with four such
/// corners and no loop in them become two triangles each ([`TrimMesh::strips`]); the rest, the
/// band along the loops, is a constrained Delaunay triangulation with the loop edges and the
/// cells' outline as constraint edges, of which the triangles to the left of the loops are
/// kept. All triangles are counter-clockwise.
///
/// No loops means the whole domain (GLU's `makeBorderTrim`): a counter-clockwise border with a
/// vertex on every grid line. So does a loop running once counter-clockwise round the domain's
/// border (every point on it): the grid points on the border lines are then used.
///
/// Errors (GLU's rules; the checks run in this order):
/// - the domain is not finite or empty (umin ≥ umax or vmin ≥ vmax) → [`TrimError::Misoriented`];
/// - a loop without points → [`TrimError::Empty`];
/// - a loop with a non-finite point, a point outside the domain (GLU requires trims inside it),
///   fewer than three distinct points, zero area, an edge doubling back on the previous one,
///   or an edge touching a non-adjacent edge of the same loop → [`TrimError::Misoriented`];
/// - an edge of one loop touching or crossing an edge of another → [`TrimError::Intersecting`];
/// - a loop whose orientation contradicts its nesting depth (counter-clockwise inside an even
///   number of other loops, clockwise inside an odd number) → [`TrimError::Misoriented`].
///
/// Coordinates beyond spade's range (about 3e60) are [`TrimError::Misoriented`]; coordinates
/// smaller than about 1.8e-43 in magnitude are flushed to zero.
pub fn triangulate_with(
    loops: &[TrimLoop],
    domain: [f64; 4],
    us: &[f64],
    vs: &[f64],
    options: &TrimOptions,
) -> Result<TrimMesh, TrimError> {
    let plan = TrimPlan::new(loops, domain, us, vs, options)?;
    let band = plan.band()?;
    Ok(plan.into_mesh(band))
}

/// A trimmed region half triangulated: the loops checked, the grid points kept and the grid
/// cells wholly inside taken as strips, the band along the loops still to triangulate
/// ([`TrimPlan::band`]). [`triangulate_with`] is [`TrimPlan::new`], [`TrimPlan::band`] and
/// [`TrimPlan::into_mesh`]; a caller may use the strips while the band is being triangulated
/// (GLU's tessellator mode issues them meanwhile).
pub struct TrimPlan {
    grid: Grid,
    loops: Vec<Vec<P>>,
    kept: Vec<bool>,
    band: Band,
    /// The Delaunay triangulation's vertices and constraint edges.
    loop_points: Vec<P>,
    edges: Vec<[usize; 2]>,
    by_cells: bool,
    strips: Vec<GridStrip>,
}

/// The band of a [`TrimPlan`]: its triangles, over the plan's grid points (ids below
/// `TrimPlan::grid_points().len()`) and the band's own `points` after them.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TrimBand {
    /// The points the band adds after the grid points: loop points, crossings.
    pub points: Vec<[f64; 2]>,
    /// Counter-clockwise triangles.
    pub triangles: Vec<[u32; 3]>,
}

impl TrimPlan {
    /// Checks the loops and splits the region into grid strips and the band; see
    /// [`triangulate_with`] for the errors.
    pub fn new(
        loops: &[TrimLoop],
        domain: [f64; 4],
        us: &[f64],
        vs: &[f64],
        options: &TrimOptions,
    ) -> Result<Self, TrimError> {
        let [u0, u1, v0, v1] = domain;
        if !domain.iter().all(|c| c.is_finite() && c.abs() <= spade::MAX_ALLOWED_VALUE) || u0 >= u1 || v0 >= v1 {
            return Err(TrimError::Misoriented);
        }
        let split = options.split_at_grid_lines;
        let mut loops: Vec<Vec<P>> = loops.iter().map(clean_loop).collect::<Result<_, _>>()?;
        if !loops.is_empty() {
            validate(&loops, domain)?;
        }
        // No loops, or one running round the domain's border (GLU's `makeBorderTrim`, and what most
        // programs pass as their outer loop): the grid's border lines carry grid points and the
        // region starts inside; only the other loops make a band.
        let inside_domain = loops.is_empty() || {
            let before = loops.len();
            loops.retain(|l| !is_domain_border(l, domain));
            loops.len() < before
        };
        let Lattice { u, v, .. } = Lattice::lines(domain, us, vs);
        let mut grid = Grid { u, v };
        let splits = split || options.by_cells;
        let budget = |g: &Grid| g.point_count().saturating_add(if splits { g.count_crossings(&loops) } else { 0 });
        while budget(&grid) > options.max_points && grid.coarsen() {}
        let clearance = if options.clearance.is_nan() { 0.0 } else { options.clearance.clamp(0.0, 0.5) };
        let (mut vertices, mut edges) = (Vec::new(), Vec::new());
        let mut blocked = vec![false; grid.point_count()];
        let mut touched = vec![false; grid.cell_count()];
        let mut trace = EdgeTrace::default();
        for l in &loops {
            let first = vertices.len();
            for (i, &a) in l.iter().enumerate() {
                let b = l[(i + 1) % l.len()];
                vertices.push(a);
                grid.trace(a, b, &mut trace);
                grid.block_near(&trace.coords, clearance, &mut blocked);
                grid.touch(&trace.coords, &mut touched);
                if split {
                    vertices.extend(grid.thin(a, b, &trace.cuts));
                }
            }
            let last = vertices.len();
            edges.extend((first..last).map(|i| [i, if i + 1 == last { first } else { i + 1 }]));
        }
        let kept = grid.retained_mask(&loops, &blocked, inside_domain);
        let band = Band::new(&grid, &kept, &touched, inside_domain);
        let strips = band.strips(&grid);
        Ok(Self { grid, loops, kept, band, loop_points: vertices, edges, by_cells: options.by_cells, strips })
    }

    /// The retained grid points, row by row: the mesh's first points.
    #[must_use]
    pub fn grid_points(&self) -> &[[f64; 2]] {
        &self.band.grid_points
    }

    /// The grid cells wholly inside the region, as runs along grid rows.
    #[must_use]
    pub fn strips(&self) -> &[GridStrip] {
        &self.strips
    }

    /// The lattice's u and v lines (see [`Lattice`]).
    #[must_use]
    pub fn lattice_lines(&self) -> (&[f64], &[f64]) {
        (&self.grid.u, &self.grid.v)
    }

    /// Each grid point's index in the lattice (see [`Lattice::index`]).
    #[must_use]
    pub fn grid_index(&self) -> &[u32] {
        &self.band.grid_index
    }

    /// Triangulates the band: cell by cell with [`TrimOptions::by_cells`] (the Delaunay
    /// triangulation where that hands over), else by the constrained Delaunay triangulation.
    pub fn band(&self) -> Result<TrimBand, TrimError> {
        if self.by_cells {
            if let Some((points, triangles)) =
                cells::triangulate_cells(&self.band, &self.grid, &self.loops, &self.kept, &self.strips)
            {
                return Ok(TrimBand { points, triangles });
            }
            #[cfg(test)]
            CELL_FALLBACKS.with(|c| c.set(c.get() + 1));
        }
        self.band.triangulate(&self.grid, &self.loop_points, self.edges.clone())
    }

    /// The whole mesh: grid points then the band's points, the band's triangles, the strips.
    #[must_use]
    pub fn into_mesh(mut self, band: TrimBand) -> TrimMesh {
        let mut points = std::mem::take(&mut self.band.grid_points);
        points.extend(band.points);
        let index = std::mem::take(&mut self.band.grid_index);
        TrimMesh {
            points,
            band: band.triangles,
            strips: self.strips,
            lattice: Lattice { u: self.grid.u, v: self.grid.v, index },
        }
    }
}

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
/// constrained triangulation. The issue's remedy for trimmed surfaces: the interior comes from
/// the grid, as GLU's monotone pieces meet its grid (`sampleMonoPoly.cc`).
struct Band {
    /// Per cell (row-major, `grid.u.len() - 1` per row): wholly inside and away from the loops.
    clean: Vec<bool>,
    /// Per grid point (row-major): its index in the mesh, or `u32::MAX` when not retained.
    mesh_index: Vec<u32>,
    /// The retained grid points, row by row: the mesh's first points.
    grid_points: Vec<P>,
    /// Each retained grid point's row-major index in the grid.
    grid_index: Vec<u32>,
    /// The region starts inside (the domain's border is the outer loop, or there are no loops).
    inside_domain: bool,
}

impl Band {
    fn new(grid: &Grid, kept: &[bool], touched: &[bool], inside_domain: bool) -> Self {
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
    fn next_to_band(&self, grid: &Grid) -> Vec<bool> {
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
    fn is_clean(&self, grid: &Grid, ci: usize, cj: usize) -> bool {
        ci < grid.u.len() - 1 && cj < grid.v.len() - 1 && self.clean[cj * (grid.u.len() - 1) + ci]
    }

    /// Triangulates the band (the loops' points and edges, the retained grid points next to a
    /// band cell, the clean region's outline as constraints) and appends the clean cells.
    fn triangulate(&self, grid: &Grid, loop_points: &[P], mut edges: Vec<[usize; 2]>) -> Result<TrimBand, TrimError> {
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
    fn outline_edges(&self, grid: &Grid, cdt_index: &[u32], edges: &mut Vec<[usize; 2]>) {
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
    fn band_triangles(&self, grid: &Grid, cdt: &ConstrainedDelaunayTriangulation<BandVertex>, band: &mut TrimBand) {
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
    fn strips(&self, grid: &Grid) -> Vec<GridStrip> {
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

/// Whether the loop runs once counter-clockwise round the domain's border: every point on the
/// border and the loop's area the domain's.
fn is_domain_border(l: &[P], [u0, u1, v0, v1]: [f64; 4]) -> bool {
    let on_border = |p: &P| {
        (p[0] == u0 || p[0] == u1) && p[1] >= v0 && p[1] <= v1 || (p[1] == v0 || p[1] == v1) && p[0] >= u0 && p[0] <= u1
    };
    let area = (u1 - u0) * (v1 - v0);
    l.iter().all(on_border) && (signed_area(l) - area).abs() <= 1e-12 * area
}

fn is_finite(p: P) -> bool {
    p[0].is_finite() && p[1].is_finite()
}

/// Spade rejects non-zero coordinates below its minimum; such values are zero for any domain.
fn flush(x: f64) -> f64 {
    if x.abs() < spade::MIN_ALLOWED_VALUE {
        0.0
    } else {
        x
    }
}

fn point(p: P) -> Point2<f64> {
    Point2::new(p[0], p[1])
}

/// The loop's points with exact consecutive duplicates (and a closing repeat) removed.
fn clean_loop(l: &TrimLoop) -> Result<Vec<P>, TrimError> {
    if l.points.is_empty() {
        return Err(TrimError::Empty);
    }
    let mut points: Vec<P> = Vec::with_capacity(l.points.len());
    for &p in &l.points {
        if !is_finite(p) {
            return Err(TrimError::Misoriented);
        }
        let p = [flush(p[0]), flush(p[1])];
        if points.last() != Some(&p) {
            points.push(p);
        }
    }
    while points.len() > 1 && points.last() == Some(&points[0]) {
        points.pop();
    }
    if points.len() < 3 {
        return Err(TrimError::Misoriented);
    }
    Ok(points)
}

/// The signed area (positive counter-clockwise), relative to the first point for precision.
fn signed_area(points: &[P]) -> f64 {
    let Some(&o) = points.first() else { return 0.0 };
    let n = points.len();
    let twice: f64 = (0..n)
        .map(|i| {
            let (a, b) = (points[i], points[(i + 1) % n]);
            (a[0] - o[0]) * (b[1] - o[1]) - (b[0] - o[0]) * (a[1] - o[1])
        })
        .sum();
    0.5 * twice
}

/// Twice the signed area of triangle abc.
fn orient(a: P, b: P, c: P) -> f64 {
    (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
}

/// Whether the closed segments ab and cd share a point (touching counts).
fn segments_meet(a: P, b: P, c: P, d: P) -> bool {
    let (d1, d2, d3, d4) = (orient(c, d, a), orient(c, d, b), orient(a, b, c), orient(a, b, d));
    let opposite = |x: f64, y: f64| (x > 0.0 && y < 0.0) || (x < 0.0 && y > 0.0);
    if opposite(d1, d2) && opposite(d3, d4) {
        return true;
    }
    let on = |p: P, q: P, r: P, o: f64| {
        o == 0.0 && r[0] >= p[0].min(q[0]) && r[0] <= p[0].max(q[0]) && r[1] >= p[1].min(q[1]) && r[1] <= p[1].max(q[1])
    };
    on(c, d, a, d1) || on(c, d, b, d2) || on(a, b, c, d3) || on(a, b, d, d4)
}

/// Whether edge b→c doubles back along edge a→b.
fn doubles_back(a: P, b: P, c: P) -> bool {
    orient(a, b, c) == 0.0 && (a[0] - b[0]) * (c[0] - b[0]) + (a[1] - b[1]) * (c[1] - b[1]) > 0.0
}

/// Even-odd point-in-polygon test (ray towards +u).
fn inside(points: &[P], p: P) -> bool {
    let mut result = false;
    let n = points.len();
    for i in 0..n {
        let (a, b) = (points[i], points[(i + 1) % n]);
        if (a[1] > p[1]) != (b[1] > p[1]) && p[0] < a[0] + (p[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0]) {
            result = !result;
        }
    }
    result
}

fn bbox(points: &[P]) -> [f64; 4] {
    points.iter().fold([f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY], |b, p| {
        [b[0].min(p[0]), b[1].max(p[0]), b[2].min(p[1]), b[3].max(p[1])]
    })
}

/// GLU's loop rules; see [`triangulate_with`] for the order of the checks.
fn validate(loops: &[Vec<P>], [u0, u1, v0, v1]: [f64; 4]) -> Result<(), TrimError> {
    let slack = 1e-12 * ((u1 - u0) + (v1 - v0));
    let in_domain = |p: &P| p[0] >= u0 - slack && p[0] <= u1 + slack && p[1] >= v0 - slack && p[1] <= v1 + slack;
    for l in loops {
        let n = l.len();
        let spike = (0..n).any(|i| doubles_back(l[i], l[(i + 1) % n], l[(i + 2) % n]));
        if !l.iter().all(in_domain) || signed_area(l) == 0.0 || spike {
            return Err(TrimError::Misoriented);
        }
    }
    if let Some(e) = find_touching_edges(loops) {
        return Err(e);
    }
    let boxes: Vec<[f64; 4]> = loops.iter().map(|l| bbox(l)).collect();
    for (i, l) in loops.iter().enumerate() {
        let p = l[0];
        let depth = (0..loops.len())
            .filter(|&j| {
                let b = boxes[j];
                j != i && p[0] >= b[0] && p[0] <= b[1] && p[1] >= b[2] && p[1] <= b[3] && inside(&loops[j], p)
            })
            .count();
        if (signed_area(l) > 0.0) != (depth % 2 == 0) {
            return Err(TrimError::Misoriented);
        }
    }
    Ok(())
}

/// Looks for touching edges with a uniform bucket grid over all loops: non-adjacent edges of one
/// loop → `Misoriented` (reported first), edges of two loops → `Intersecting`.
fn find_touching_edges(loops: &[Vec<P>]) -> Option<TrimError> {
    let segs: Vec<(usize, usize)> =
        loops.iter().enumerate().flat_map(|(k, l)| (0..l.len()).map(move |i| (k, i))).collect();
    let ends = |(k, i): (usize, usize)| (loops[k][i], loops[k][(i + 1) % loops[k].len()]);
    let all = bbox(&loops.iter().flatten().copied().collect::<Vec<_>>());
    let cells = ((segs.len() as f64).sqrt().ceil() as usize).clamp(1, 2048);
    let cell_of = |x: f64, lo: f64, hi: f64| {
        let w = hi - lo;
        if w > 0.0 {
            (((x - lo) / w * cells as f64).max(0.0) as usize).min(cells - 1)
        } else {
            0
        }
    };
    let ranges = |s: (usize, usize)| {
        let (a, b) = ends(s);
        let b4 = bbox(&[a, b]);
        let (i0, i1) = (cell_of(b4[0], all[0], all[1]), cell_of(b4[1], all[0], all[1]));
        let (j0, j1) = (cell_of(b4[2], all[2], all[3]), cell_of(b4[3], all[2], all[3]));
        (j0..=j1).flat_map(move |j| (i0..=i1).map(move |i| j * cells + i))
    };
    // Compressed buckets: counts, prefix sums, fill.
    let mut start = vec![0usize; cells * cells + 1];
    for &s in &segs {
        ranges(s).for_each(|c| start[c + 1] += 1);
    }
    for c in 0..cells * cells {
        start[c + 1] += start[c];
    }
    let mut fill = start.clone();
    let mut bucket = vec![0u32; start[cells * cells]];
    for (id, &s) in segs.iter().enumerate() {
        for c in ranges(s) {
            bucket[fill[c]] = id as u32;
            fill[c] += 1;
        }
    }
    let mut crossing = false;
    for c in 0..cells * cells {
        let ids = &bucket[start[c]..start[c + 1]];
        for (x, &p) in ids.iter().enumerate() {
            for &q in &ids[x + 1..] {
                let (s, t) = (segs[p as usize], segs[q as usize]);
                let n = loops[s.0].len();
                let adjacent = s.0 == t.0 && (s.1.abs_diff(t.1) == 1 || s.1.abs_diff(t.1) == n - 1);
                if adjacent || (crossing && s.0 != t.0) {
                    continue;
                }
                let ((a, b), (d, e)) = (ends(s), ends(t));
                if segments_meet(a, b, d, e) {
                    if s.0 == t.0 {
                        return Some(TrimError::Misoriented);
                    }
                    crossing = true;
                }
            }
        }
    }
    crossing.then_some(TrimError::Intersecting)
}

/// Sorted, deduplicated finite values strictly between `lo` and `hi`.
fn sorted_lines(values: &[f64], lo: f64, hi: f64) -> Vec<f64> {
    let mut v: Vec<f64> = values.iter().copied().map(flush).filter(|x| x.is_finite() && *x > lo && *x < hi).collect();
    v.sort_by(f64::total_cmp);
    v.dedup();
    v
}

/// The domain bounds with the interior grid lines between them.
fn grid_lines(values: &[f64], lo: f64, hi: f64) -> Vec<f64> {
    let mut v = vec![lo];
    v.extend(sorted_lines(values, lo, hi));
    v.push(hi);
    v
}

/// How many of the sorted `lines` are at most x (`lines.partition_point(|l| *l <= x)`).
/// The answer is guessed as if the lines were evenly spaced (as GLU's sampling lines are within
/// a piece), checked against the lines and stepped; a binary search only when the guess is far.
/// Trimming asks this for every loop point and crossing, where a binary search's mispredicted
/// branches cost more than the rest of the work.
fn count_at_most(lines: &[f64], x: f64) -> usize {
    count_where(lines, x, |l| l <= x)
}

/// How many of the sorted `lines` are below x (`lines.partition_point(|l| *l < x)`).
fn count_below(lines: &[f64], x: f64) -> usize {
    count_where(lines, x, |l| l < x)
}

/// The partition point of `before` (true on a prefix of `lines`), starting from the evenly
/// spaced guess for x.
fn count_where(lines: &[f64], x: f64, before: impl Fn(f64) -> bool) -> usize {
    let n = lines.len();
    if n < 2 {
        return lines.partition_point(|&l| before(l));
    }
    let (first, last) = (lines[0], lines[n - 1]);
    let guess = (x - first) / (last - first) * (n - 1) as f64;
    if !guess.is_finite() {
        return lines.partition_point(|&l| before(l));
    }
    // Truncation is the floor here (clamped at 0 first): no call to libm's floor.
    let mut k = (guess.clamp(0.0, (n - 1) as f64) as usize) + 1;
    for _ in 0..3 {
        if k < n && before(lines[k]) {
            k += 1;
        } else if k > 0 && !before(lines[k - 1]) {
            k -= 1;
        } else {
            return k;
        }
    }
    lines.partition_point(|&l| before(l))
}

/// Grid lines in u and v, sorted. For the triangulation the first and last are the domain bounds
/// and only the lines between them carry grid points.
struct Grid {
    u: Vec<f64>,
    v: Vec<f64>,
}

/// A crossing of an edge with grid lines: edge parameter t and the point.
type Cut = (f64, P);

/// Grid points within this many cells of a loop count as on it and are always left out (a CDT
/// vertex on a loop edge would split it), whatever the clearance.
const ON_LOOP: f64 = 1e-9;

/// Split points closer than this (in grid cells) to a neighbour on the edge are not inserted.
const MIN_SPLIT: f64 = 0.01;

impl Grid {
    fn point_count(&self) -> usize {
        self.u.len().saturating_mul(self.v.len())
    }

    /// Drops every other interior line in both directions; false when there is nothing to drop.
    fn coarsen(&mut self) -> bool {
        let halve = |lines: &mut Vec<f64>| {
            if lines.len() > 2 {
                let last = lines[lines.len() - 1];
                let keep: Vec<f64> = lines[..lines.len() - 1].iter().step_by(2).copied().chain([last]).collect();
                *lines = keep;
            }
        };
        let before = self.u.len() + self.v.len();
        halve(&mut self.u);
        halve(&mut self.v);
        self.u.len() + self.v.len() < before
    }

    /// Lines strictly between a and b.
    fn between(lines: &[f64], a: f64, b: f64) -> &[f64] {
        let (lo, hi) = (a.min(b), a.max(b));
        let i = count_at_most(lines, lo);
        let j = count_below(lines, hi).max(i);
        &lines[i..j]
    }

    fn count_crossings(&self, loops: &[Vec<P>]) -> usize {
        loops
            .iter()
            .flat_map(|l| (0..l.len()).map(move |i| (l[i], l[(i + 1) % l.len()])))
            .map(|(a, b)| Self::between(&self.u, a[0], b[0]).len() + Self::between(&self.v, a[1], b[1]).len())
            .fold(0usize, usize::saturating_add)
    }

    /// Where edge a→b crosses the grid lines, by increasing t in (0, 1); a crossing of a u line
    /// and a v line at the same t is one point with both coordinates exact.
    fn crossings(&self, a: P, b: P) -> Vec<Cut> {
        let mut trace = EdgeTrace::default();
        self.crossings_into(a, b, &mut trace);
        trace.cuts
    }

    /// [`Grid::crossings`] into `trace.cuts` (its buffers reused: this runs for every loop edge).
    fn crossings_into(&self, a: P, b: P, trace: &mut EdgeTrace) {
        let (du, dv) = (b[0] - a[0], b[1] - a[1]);
        let raw = &mut trace.raw;
        raw.clear();
        raw.extend(Self::between(&self.u, a[0], b[0]).iter().map(|&u| ((u - a[0]) / du, Some(u), None)));
        raw.extend(Self::between(&self.v, a[1], b[1]).iter().map(|&v| ((v - a[1]) / dv, None, Some(v))));
        raw.retain(|c| c.0 > 0.0 && c.0 < 1.0);
        raw.sort_by(|x, y| x.0.total_cmp(&y.0));
        trace.merged.clear();
        for &c in raw.iter() {
            match trace.merged.last_mut() {
                Some(last) if c.0 - last.0 <= 1e-12 => {
                    last.1 = last.1.or(c.1);
                    last.2 = last.2.or(c.2);
                }
                _ => trace.merged.push(c),
            }
        }
        trace.cuts.clear();
        trace.cuts.extend(
            trace.merged.iter().map(|&(t, u, v)| (t, [u.unwrap_or(a[0] + t * du), v.unwrap_or(a[1] + t * dv)])),
        );
    }

    /// Edge a→b's crossings and, in cell coordinates, a, every crossing and b.
    fn trace(&self, a: P, b: P, trace: &mut EdgeTrace) {
        self.crossings_into(a, b, trace);
        trace.coords.clear();
        let points = std::iter::once(a).chain(trace.cuts.iter().map(|c| c.1)).chain([b]);
        trace.coords.extend(points.map(|p| self.cell_coords(p)));
    }

    /// Fractional line index of x: i + (x - lines[i]) / (lines[i+1] - lines[i]).
    fn index(lines: &[f64], x: f64) -> f64 {
        if lines.len() < 2 {
            return 0.0;
        }
        let i = count_at_most(lines, x).clamp(1, lines.len() - 1) - 1;
        let (lo, hi) = (lines[i], lines[i + 1]);
        i as f64 + ((x - lo) / (hi - lo)).clamp(0.0, 1.0)
    }

    /// A point in grid-index space, where grid points are the integer lattice.
    fn cell_coords(&self, p: P) -> P {
        [Self::index(&self.u, p[0]), Self::index(&self.v, p[1])]
    }

    /// The split points worth inserting: not within [`MIN_SPLIT`] cells of the previous vertex
    /// or of b.
    fn thin<'a>(&'a self, a: P, b: P, cuts: &'a [Cut]) -> impl Iterator<Item = P> + 'a {
        let far = |p: P, q: P| {
            let (x, y) = (self.cell_coords(p), self.cell_coords(q));
            (x[0] - y[0]).abs().max((x[1] - y[1]).abs()) >= MIN_SPLIT
        };
        let mut prev = a;
        cuts.iter().filter_map(move |&(_, p)| {
            let keep = far(prev, p) && far(p, b);
            if keep {
                prev = p;
            }
            keep.then_some(p)
        })
    }

    /// Marks the grid points within `clearance` cells of an edge, given as its points in cell
    /// coordinates ([`Grid::trace`]). Between consecutive cuts the edge lies in one grid cell,
    /// where the map to cell coordinates is affine; only that cell's corners can be closer than
    /// one cell.
    fn block_near(&self, coords: &[P], clearance: f64, blocked: &mut [bool]) {
        let (nu, nv) = (self.u.len(), self.v.len());
        if nu < 2 || nv < 2 {
            return;
        }
        let limit = clearance.max(ON_LOOP);
        for piece in coords.windows(2) {
            let (prev, next) = (piece[0], piece[1]);
            let mid = midpoint(prev, next);
            // `as usize` truncates and saturates at 0: the floor of these non-negative values.
            let ci = (mid[0].max(0.0) as usize).min(nu - 2);
            let cj = (mid[1].max(0.0) as usize).min(nv - 2);
            for (i, j) in [(ci, cj), (ci + 1, cj), (ci, cj + 1), (ci + 1, cj + 1)] {
                if distance_squared_to_segment([i as f64, j as f64], prev, next) < limit * limit {
                    blocked[j * nu + i] = true;
                }
            }
        }
    }

    /// Per grid point (row-major, `u.len()` per row): inside the retained region (even-odd over
    /// all loops, row by row with sorted crossings, starting inside when `inside_domain`) and
    /// not blocked. The points on the domain's border are kept exactly when `inside_domain`.
    fn retained_mask(&self, loops: &[Vec<P>], blocked: &[bool], inside_domain: bool) -> Vec<bool> {
        let (nu, nv) = (self.u.len(), self.v.len());
        let mut hits: Vec<(usize, f64)> = Vec::new();
        for l in loops {
            for i in 0..l.len() {
                let (a, b) = (l[i], l[(i + 1) % l.len()]);
                // Rows with min(a.v, b.v) <= v < max(a.v, b.v): the half-open rule of `inside`.
                let (lo, hi) = (a[1].min(b[1]), a[1].max(b[1]));
                let (j0, j1) = (count_below(&self.v, lo), count_below(&self.v, hi));
                for (j, &v) in self.v.iter().enumerate().take(j1).skip(j0) {
                    hits.push((j, a[0] + (v - a[1]) / (b[1] - a[1]) * (b[0] - a[0])));
                }
            }
        }
        hits.sort_by(|x, y| x.0.cmp(&y.0).then(x.1.total_cmp(&y.1)));
        let mut out = vec![false; blocked.len()];
        let mut k = 0;
        for (j, (row, blocked)) in out.chunks_exact_mut(nu).zip(blocked.chunks_exact(nu)).enumerate() {
            let row_start = k;
            while k < hits.len() && hits[k].0 == j {
                k += 1;
            }
            // The domain's border, when it is the outer loop, keeps every grid point: the other
            // loops lie strictly inside it (validated), and the border must be whole.
            if j == 0 || j == nv - 1 {
                row.fill(inside_domain);
                continue;
            }
            // Between consecutive crossings (a point on one counts as past it) the parity of
            // the crossings to the right is constant: runs filled at once, not point by point.
            let xs = &hits[row_start..k];
            let mut from = 0;
            for crossed in 0..=xs.len() {
                let to = xs.get(crossed).map_or(nu, |&(_, x)| count_below(&self.u, x));
                let odd = (xs.len() - crossed) % 2 == 1;
                row[from..to.max(from)].fill(odd != inside_domain);
                from = from.max(to);
            }
            for (keep, &b) in row.iter_mut().zip(blocked) {
                *keep &= !b;
            }
            row[0] = inside_domain;
            row[nu - 1] = inside_domain;
        }
        out
    }

    /// Number of grid cells (between consecutive lines, domain bounds included).
    fn cell_count(&self) -> usize {
        self.u.len().saturating_sub(1).saturating_mul(self.v.len().saturating_sub(1))
    }

    /// Marks the cells an edge (its points in cell coordinates, [`Grid::trace`]) passes through
    /// or touches: between consecutive cuts the edge
    /// lies in one closed cell, and a piece's ends and middle mark every cell whose closed box
    /// holds them (a point on a grid line marks both sides), so no loop point lies in an
    /// unmarked closed cell.
    fn touch(&self, coords: &[P], touched: &mut [bool]) {
        const EPS: f64 = 1e-9;
        let (cu, cv) = (self.u.len().saturating_sub(1), self.v.len().saturating_sub(1));
        if cu == 0 || cv == 0 {
            return;
        }
        let mut mark = |p: P| {
            let span = |x: f64, n: usize| {
                // Truncation of a value clamped at 0 is its floor (without a libm call).
                let lo = ((x - EPS).max(0.0) as usize).min(n - 1);
                let hi = ((x + EPS).max(0.0) as usize).min(n - 1);
                lo..=hi
            };
            for j in span(p[1], cv) {
                for i in span(p[0], cu) {
                    touched[j * cu + i] = true;
                }
            }
        };
        let Some(&first) = coords.first() else { return };
        mark(first);
        for piece in coords.windows(2) {
            mark(midpoint(piece[0], piece[1]));
            mark(piece[1]);
        }
    }
}

/// Scratch buffers of [`Grid::trace`], reused from edge to edge.
#[derive(Default)]
struct EdgeTrace {
    /// Line crossings before merging: (t, u line, v line).
    raw: Vec<(f64, Option<f64>, Option<f64>)>,
    merged: Vec<(f64, Option<f64>, Option<f64>)>,
    /// The crossings by increasing t.
    cuts: Vec<Cut>,
    /// The edge's start, its crossings and its end, in cell coordinates.
    coords: Vec<P>,
}

/// The squared distance from p to segment a–b (no square root: compared with a squared limit).
fn distance_squared_to_segment(p: P, a: P, b: P) -> f64 {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let len2 = dx * dx + dy * dy;
    let t = if len2 > 0.0 { (((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2).clamp(0.0, 1.0) } else { 0.0 };
    let (x, y) = (p[0] - a[0] - t * dx, p[1] - a[1] - t * dy);
    x * x + y * y
}

#[path = "trim_cells.rs"]
mod cells;

// How often the cell-by-cell triangulation handed over to the Delaunay one, on this thread.
#[cfg(test)]
thread_local! {
    static CELL_FALLBACKS: std::cell::Cell<usize> = const { std::cell::Cell::new(0) };
}

#[cfg(test)]
#[path = "trim_tests.rs"]
mod tests;
