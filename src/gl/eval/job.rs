//! One `glEvalMesh` call as data: the enabled maps it reads (control points copied, parameters
//! already normalised to each map's domain) and the current attributes that fill the rest.
//!
//! The CPU back end evaluates a job at once ([`MeshJob::evaluate`]); the GPU back end keeps the
//! job in the frame and evaluates every job of the frame in one compute dispatch
//! (the crate's GPU evaluator, `src/gpu/evaluate.rs`). Both read the same numbers, so the CPU result is the GPU's oracle.

use super::super::vertex::Vertex;
use super::super::GridVertices;
use super::target::Slot;
use crate::math::bezier::{horner_many, Vec4};
use crate::math::rational::{normalize, normalize_many};
use crate::tess::{rows_per_band, run_bands, MapView, Row, RowBases, RowKernel};
use std::cell::RefCell;
use std::sync::Arc;

/// Points per tile of a curve (`glEvalMesh1`): the unit of work shared out between the cores.
const CURVE_TILE: usize = 2048;

/// Rows up to this many points are evaluated point by point (`RowKernel::eval_row_points`):
/// the row kernel's per-component passes cost more than they save on short rows.
const POINT_BY_POINT_ROW: usize = 64;

/// Basis tables kept by each thread for the meshes after (a frame of many small patches uses a
/// few grids and orders again and again).
const KEPT_BASES: usize = 4;

/// The basis tables for these orders over this grid: kept ones where they fit (the most
/// recently used first), else new ones, kept in place of the least recently used.
fn shared_bases(uorder: usize, vorder: usize, us: &[f32], vs: &[f32], normals: bool) -> Arc<RowBases<f32>> {
    BASES.with_borrow_mut(|kept| {
        if let Some(k) = kept.iter().position(|b| b.fits(uorder, vorder, us, vs, normals)) {
            let bases = kept.remove(k);
            kept.insert(0, Arc::clone(&bases));
            return bases;
        }
        let bases = Arc::new(RowBases::new(uorder, vorder, us, vs, normals));
        kept.truncate(KEPT_BASES - 1);
        kept.insert(0, Arc::clone(&bases));
        bases
    })
}

thread_local! {
    /// The basis tables of the latest meshes of this thread ([`shared_bases`]).
    static BASES: RefCell<Vec<Arc<RowBases<f32>>>> = const { RefCell::new(Vec::new()) };
    /// Row scratch of this thread, kept between meshes so that small meshes allocate nothing.
    static SCRATCH_ROWS: RefCell<Vec<Row<f32>>> = const { RefCell::new(Vec::new()) };
    /// A curve tile's values, likewise.
    static SCRATCH_VALUES: RefCell<Vec<Vec4<f32>>> = const { RefCell::new(Vec::new()) };
}

/// A band of a grid's attribute arrays (whole rows), to be filled by one thread. An array the
/// grid does not keep is empty here too.
struct Columns<'a> {
    positions: &'a mut [[f32; 4]],
    normals: &'a mut [[f32; 3]],
    colors: &'a mut [[f32; 4]],
    tex_coords: &'a mut [[f32; 4]],
}

impl<'a> Columns<'a> {
    fn of(grid: &'a mut GridVertices) -> Self {
        Self {
            positions: &mut grid.positions,
            normals: &mut grid.normals,
            colors: &mut grid.colors,
            tex_coords: &mut grid.tex_coords,
        }
    }

    fn len(&self) -> usize {
        self.positions.len()
    }

    /// The first `n` points and the rest.
    fn split_at(self, n: usize) -> (Self, Self) {
        fn cut<T>(column: &mut [T], n: usize) -> (&mut [T], &mut [T]) {
            let n = if column.is_empty() { 0 } else { n.min(column.len()) };
            column.split_at_mut(n)
        }
        let (p0, p1) = cut(self.positions, n);
        let (n0, n1) = cut(self.normals, n);
        let (c0, c1) = cut(self.colors, n);
        let (t0, t1) = cut(self.tex_coords, n);
        (
            Self { positions: p0, normals: n0, colors: c0, tex_coords: t0 },
            Self { positions: p1, normals: n1, colors: c1, tex_coords: t1 },
        )
    }

    /// Consecutive pieces of `n` points each (the last may be shorter).
    fn chunks(self, n: usize) -> Vec<Self> {
        let mut out = Vec::with_capacity(self.len().div_ceil(n.max(1)));
        let mut rest = self;
        while rest.len() > 0 {
            let (piece, tail) = rest.split_at(n.max(1));
            out.push(piece);
            rest = tail;
        }
        out
    }

    /// Writes `slot`'s values, one a point from the first, widened as GL widens
    /// (`Vertex::set_attribute`): missing components are 0, and w or q 1.
    fn write_values(&mut self, slot: Slot, values: &[Vec4<f32>]) {
        let k = slot.components();
        // Component c is the value's below k, else (0, 0, 0, 1)'s: a select per component, not
        // a copy of a run-time length.
        let widen = |p: &Vec4<f32>| {
            std::array::from_fn(|c| {
                if c < k {
                    p[c]
                } else if c == 3 {
                    1.0
                } else {
                    0.0
                }
            })
        };
        match slot {
            Slot::Vertex3 | Slot::Vertex4 => self.positions.iter_mut().zip(values).for_each(|(o, p)| *o = widen(p)),
            Slot::Normal => self.normals.iter_mut().zip(values).for_each(|(o, p)| *o = [p[0], p[1], p[2]]),
            Slot::Color4 => self.colors.iter_mut().zip(values).for_each(|(o, p)| *o = widen(p)),
            _ => self.tex_coords.iter_mut().zip(values).for_each(|(o, p)| *o = widen(p)),
        }
    }

    /// Writes `slot`'s value at each point of `row` (widened as GL widens), or `value` at every
    /// point when `row` is `None`.
    fn write(&mut self, slot: Slot, row: Option<&Row<f32>>, value: [f32; 4]) {
        let k = slot.components();
        let at = |i: usize| row.map_or(value, |r| r.point_at(i, k));
        match slot {
            Slot::Vertex3 if row.is_some() => {
                let p = &row.expect("checked").point;
                for (v, ((x, y), z)) in self.positions.iter_mut().zip(p[0].iter().zip(&p[1]).zip(&p[2])) {
                    *v = [*x, *y, *z, 1.0];
                }
            }
            Slot::Vertex3 | Slot::Vertex4 => self.positions.iter_mut().enumerate().for_each(|(i, v)| *v = at(i)),
            Slot::Normal => self.normals.iter_mut().enumerate().for_each(|(i, n)| {
                let p = at(i);
                *n = [p[0], p[1], p[2]];
            }),
            Slot::Color4 => self.colors.iter_mut().enumerate().for_each(|(i, c)| *c = at(i)),
            _ => self.tex_coords.iter_mut().enumerate().for_each(|(i, t)| *t = at(i)),
        }
    }
}

/// Makes `column` hold `len` values (to be overwritten), reusing its memory, or empties it when
/// the grid does not keep this attribute.
fn fit<T: bytemuck::Zeroable + Clone>(column: &mut Vec<T>, len: usize, kept: bool) {
    let len = if kept { len } else { 0 };
    if column.len() >= len {
        column.truncate(len);
    } else if column.capacity() >= len {
        column.resize(len, T::zeroed());
    } else {
        // Fresh zeroed memory comes from calloc: its pages are faulted in by the threads that
        // fill them rather than all by this one.
        *column = bytemuck::zeroed_vec(len);
    }
}

/// Runs `work(first_row, band)` over the rows of `grid` (`row_len` points each), split into
/// bands of whole rows, one band per core when the grid is large enough.
fn for_column_bands(grid: &mut GridVertices, row_len: usize, work: impl Fn(usize, Columns<'_>) + Sync) {
    let columns = Columns::of(grid);
    if row_len == 0 || columns.len() == 0 {
        return;
    }
    let band = rows_per_band(columns.len().div_ceil(row_len), row_len);
    run_bands(columns.chunks(band * row_len).into_iter(), |k, band_columns| work(k * band, band_columns));
}

/// Runs `f` with `n` scratch rows of this thread.
fn with_scratch_rows(n: usize, f: impl FnOnce(&mut [Row<f32>])) {
    SCRATCH_ROWS.with_borrow_mut(|rows| {
        if rows.len() < n {
            rows.resize_with(n, Row::default);
        }
        f(&mut rows[..n]);
    });
}

/// Small CPU meshes recorded but not yet evaluated: each job with its mesh's index in
/// `frame.meshes`, and their grid points in all (evaluated as one batch past a threshold, or
/// when the frame is looked at).
#[derive(Debug, Default)]
pub(crate) struct PendingMeshes {
    pub jobs: Vec<(usize, MeshJob)>,
    pub points: usize,
}

/// An enabled map sampled by a mesh.
#[derive(Clone, Debug, PartialEq)]
pub struct MapSample {
    /// The attribute it produces.
    pub slot: Slot,
    /// Order along u.
    pub uorder: usize,
    /// Order along v (1 for a `GL_MAP1_*` map).
    pub vorder: usize,
    /// `uorder · vorder · k` control values, point (i, j) at `(i · vorder + j) · k`.
    pub points: Vec<f32>,
    /// The grid's u parameters normalised to this map: `(u − u1) / (u2 − u1)`, as Mesa computes.
    pub us: Vec<f32>,
    /// The v parameters, normalised (a single 0 for a curve).
    pub vs: Vec<f32>,
}

impl MapSample {
    fn view(&self) -> MapView<'_, f32> {
        MapView { dim: self.slot.components(), uorder: self.uorder, vorder: self.vorder, points: &self.points }
    }
}

/// A grid of vertices to evaluate: `nu` × `nv` points, v outer and u inner.
#[derive(Clone, Debug, PartialEq)]
pub struct MeshJob {
    /// Attribute maps in Mesa's order (colour, texture, normal), then the vertex map last.
    pub maps: Vec<MapSample>,
    /// `GL_AUTO_NORMAL` was on (and the job is a surface): the vertex map's normal wins.
    pub auto_normal: bool,
    /// The current colour, normal and texture coordinate, for attributes with no map.
    pub template: Vertex,
    /// Grid points along u.
    pub nu: usize,
    /// Grid points along v (1 for `glEvalMesh1` and for scattered points).
    pub nv: usize,
    /// Scattered points: point k is (`us[k]`, `vs[k]`) of each map, not a grid (`nv` = 1).
    pub scattered: bool,
}

impl MeshJob {
    /// Number of grid points.
    #[must_use]
    pub fn len(&self) -> usize {
        self.nu * self.nv
    }

    /// True when the grid has no point.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The vertices of the grid on the CPU, v outer: each map evaluated a row at a time
    /// (`RowKernel`), rows shared out between the cores, every value written once.
    #[must_use]
    pub fn evaluate(&self) -> GridVertices {
        let mut out = GridVertices::default();
        self.evaluate_into(&mut out);
        out
    }

    /// [`MeshJob::evaluate`] into `out`, reusing its memory (every value is overwritten).
    pub fn evaluate_into(&self, out: &mut GridVertices) {
        if self.scattered {
            *out = GridVertices::from_vertices(&self.evaluate_scattered());
            return;
        }
        out.template = self.template;
        let has = |wanted: &[Slot]| self.maps.iter().any(|m| wanted.contains(&m.slot));
        let vertex_map = has(&[Slot::Vertex3, Slot::Vertex4]);
        let len = self.len();
        fit(&mut out.positions, len, true);
        fit(&mut out.normals, len, has(&[Slot::Normal]) || (self.auto_normal && vertex_map));
        fit(&mut out.colors, len, has(&[Slot::Color4]));
        fit(&mut out.tex_coords, len, has(&[Slot::TexCoord1, Slot::TexCoord2, Slot::TexCoord3, Slot::TexCoord4]));
        if !vertex_map {
            out.positions.fill(self.template.position);
        }
        if self.is_curve() {
            // Tiles of points, shared out between the cores.
            for_column_bands(out, CURVE_TILE, |first_tile, band| {
                SCRATCH_VALUES.with_borrow_mut(|values| {
                    for (t, tile) in band.chunks(CURVE_TILE).into_iter().enumerate() {
                        self.fill_curve((first_tile + t) * CURVE_TILE, tile, values);
                    }
                });
            });
            return;
        }
        let kernels = self.kernels();
        for_column_bands(out, self.nu, |first_row, band| {
            with_scratch_rows(self.maps.len(), |rows| {
                for (r, row) in band.chunks(self.nu).into_iter().enumerate() {
                    self.fill_row(&kernels, first_row + r, rows, row);
                }
            });
        });
    }

    /// A `glEvalMesh1` job: one row of `GL_MAP1_*` maps (order 1 along v, at v = 0), no normals.
    fn is_curve(&self) -> bool {
        self.nv == 1 && !self.auto_normal && self.maps.iter().all(|m| m.vorder == 1 && m.vs.len() == 1)
    }

    /// Writes the curve points `start..start + out.len()` of every map: Horner's rule as
    /// `glEvalCoord1` evaluates it (GL 1.1 §5.1 defines `glEvalMesh1` as that loop over the grid,
    /// and Mesa runs it so), many points side by side: the same bits as `Gl::eval_coord1f`.
    fn fill_curve(&self, start: usize, mut out: Columns<'_>, values: &mut Vec<Vec4<f32>>) {
        let len = out.len();
        values.resize(len, [0.0; 4]);
        for map in &self.maps {
            let us = map.us.get(start..start + len).unwrap_or_default();
            horner_many(&map.points, map.slot.components(), map.uorder, us, values);
            out.write_values(map.slot, &values[..us.len()]);
        }
    }

    /// A row kernel per map over the whole grid (`None` for a malformed map), its basis tables
    /// shared with the meshes before it of the same orders over the same grid.
    fn kernels(&self) -> Vec<(Slot, bool, Option<RowKernel<'_, f32>>)> {
        self.maps
            .iter()
            .map(|map| {
                let normals = self.auto_normal && matches!(map.slot, Slot::Vertex3 | Slot::Vertex4);
                let view = map.view();
                let kernel = view.is_valid().then(|| {
                    let bases = shared_bases(map.uorder, map.vorder, &map.us, &map.vs, normals);
                    RowKernel::with_bases(view, bases)
                });
                (map.slot, normals, kernel.flatten())
            })
            .collect()
    }

    /// Writes row `j` of every map into `out`: each map's attribute in Mesa's order (the
    /// vertex map last), and the normal where `GL_AUTO_NORMAL` asks for it.
    fn fill_row(
        &self,
        kernels: &[(Slot, bool, Option<RowKernel<'_, f32>>)],
        j: usize,
        rows: &mut [Row<f32>],
        mut out: Columns<'_>,
    ) {
        for ((slot, normals, kernel), row) in kernels.iter().zip(rows.iter_mut()) {
            // A malformed map (never made by the façade) evaluates to zeros (widened as GL does).
            let Some(kernel) = kernel else {
                let mut zero = [0.0, 0.0, 0.0, 1.0];
                zero[..slot.components().min(4)].fill(0.0);
                out.write(*slot, None, zero);
                if *normals {
                    out.normals.fill([0.0; 3]);
                }
                continue;
            };
            if *slot == Slot::Vertex3 && out.len() <= POINT_BY_POINT_ROW {
                let (positions, normal_out) = (&mut *out.positions, &mut *out.normals);
                let by_points = kernel.eval_row_points(j, row, |i, p, n| {
                    positions[i] = [p[0], p[1], p[2], 1.0];
                    if *normals {
                        normal_out[i] = n;
                    }
                });
                if by_points {
                    if *normals {
                        normalize_many(normal_out);
                    }
                    continue;
                }
            }
            kernel.eval_row(j, row);
            out.write(*slot, Some(row), [0.0; 4]);
            if *normals {
                for (i, n) in out.normals.iter_mut().enumerate() {
                    *n = normalize(row.cross_at(i));
                }
            }
        }
    }

    /// Scattered points, each evaluated alone (the CPU oracle of GLU's trimmed surfaces).
    fn evaluate_scattered(&self) -> Vec<Vertex> {
        (0..self.nu)
            .map(|k| {
                let point = MeshJob {
                    maps: self
                        .maps
                        .iter()
                        .map(|m| MapSample { us: vec![m.us[k]], vs: vec![m.vs[k]], ..m.clone() })
                        .collect(),
                    nu: 1,
                    nv: 1,
                    scattered: false,
                    ..self.clone()
                };
                point.evaluate().vertex(0)
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The bands cover every point of every kept array once, in row order, and leave the
    /// arrays the grid does not keep empty.
    #[test]
    fn bands_cover_every_row_once() {
        for (len, row_len) in [(0, 3), (7, 7), (100_000, 10), (100_001, 1000), (1 << 17, 3)] {
            let mut grid = GridVertices {
                positions: vec![[f32::NAN; 4]; len],
                colors: vec![[f32::NAN; 4]; len],
                ..GridVertices::default()
            };
            for_column_bands(&mut grid, row_len, |first, band| {
                assert!(band.normals.is_empty() && band.tex_coords.is_empty());
                assert_eq!(band.positions.len(), band.colors.len());
                for (k, (p, c)) in band.positions.iter_mut().zip(band.colors.iter_mut()).enumerate() {
                    let index = (first * row_len + k) as f32;
                    (*p, *c) = ([index; 4], [-index; 4]);
                }
            });
            let covered = |k: usize| grid.positions[k][0] == k as f32 && grid.colors[k][0] == -(k as f32);
            assert!((0..len).all(covered), "{len} {row_len}");
        }
    }
}
