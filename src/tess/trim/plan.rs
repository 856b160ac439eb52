//! The triangulation of a trimmed domain in two steps: [`TrimPlan::new`] checks the loops, traces
//! them through the sampling lattice and splits the region into clean grid strips and the band
//! along the loops; [`TrimPlan::triangulate_band`] triangulates the band.

use super::band::Band;
use super::cells::triangulate_cells;
use super::geometry::P;
use super::lattice::{EdgeTrace, LatticeLines};
use super::loops::{clean_loop, is_domain_border, validate, TrimError, TrimLoop};
use super::mesh::{GridStrip, Lattice, TrimBand, TrimMesh};

/// How [`triangulate_with`] samples the retained region.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TrimOptions {
    /// Grid points closer to a loop than this fraction of the local grid spacing are left out,
    /// so that no sliver triangles form along the loops. Distances are measured in grid cells
    /// (u and v scaled by their local spacings); clamped to [0, 0.5].
    pub clearance: f64,
    /// Give loop edges a vertex wherever they cross a grid line, so that long trim edges are
    /// sampled as finely as the interior. GLU splits user trims only at knot lines and at its
    /// sampling subdivisions, so this is off by default; [`split_at_lines`](super::split_at_lines) splits at chosen
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
    let band = plan.triangulate_band()?;
    Ok(plan.into_mesh(band))
}

/// A trimmed region half triangulated: the loops checked, the grid points kept and the grid
/// cells wholly inside taken as strips, the band along the loops still to triangulate
/// ([`TrimPlan::triangulate_band`]). [`triangulate_with`] is [`TrimPlan::new`], [`TrimPlan::triangulate_band`] and
/// [`TrimPlan::into_mesh`]; a caller may use the strips while the band is being triangulated
/// (GLU's tessellator mode issues them meanwhile).
pub struct TrimPlan {
    grid: LatticeLines,
    loops: Vec<Vec<P>>,
    kept: Vec<bool>,
    band: Band,
    /// The Delaunay triangulation's vertices and constraint edges.
    loop_points: Vec<P>,
    edges: Vec<[usize; 2]>,
    by_cells: bool,
    strips: Vec<GridStrip>,
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
        let mut grid = LatticeLines { u, v };
        let splits = split || options.by_cells;
        let budget =
            |g: &LatticeLines| g.point_count().saturating_add(if splits { g.count_crossings(&loops) } else { 0 });
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
    pub fn triangulate_band(&self) -> Result<TrimBand, TrimError> {
        if self.by_cells {
            if let Some(band) = self.triangulate_band_by_cells() {
                return Ok(band);
            }
        }
        self.band.triangulate(&self.grid, &self.loop_points, self.edges.clone())
    }

    /// The band cut cell by cell against the loops, or `None` where that cannot be done exactly
    /// (the case [`TrimPlan::triangulate_band`] hands over to the Delaunay triangulation).
    pub(super) fn triangulate_band_by_cells(&self) -> Option<TrimBand> {
        let (points, triangles) = triangulate_cells(&self.band, &self.grid, &self.loops, &self.kept, &self.strips)?;
        Some(TrimBand { points, triangles })
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
