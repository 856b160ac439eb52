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
//! Files: this one has the loops, their checks and [`TrimPlan`]; `trim_grid.rs` the sampling
//! grid and the loops' passage through it; `trim_band.rs` the split into clean cells and band
//! and the band's Delaunay triangulation; `trim_cells.rs` the cell-by-cell triangulation.
//!
//! GLU itself (`subdivider.cc`, `slicer.cc`, `sampleMonoPoly.cc`) splits the region into monotone
//! pieces and stitches them to its uniform grid; the triangles differ, the covered region and
//! the grid points inside it are the same.

use spade::Point2;

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

#[path = "trim_band.rs"]
mod band;
use band::Band;

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

#[path = "trim_grid.rs"]
mod grid;
use grid::{count_at_most, count_below, grid_lines, sorted_lines, EdgeTrace, Grid};

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
