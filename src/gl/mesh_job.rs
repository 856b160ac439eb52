//! One `glEvalMesh` call as data: the enabled maps it reads (control points copied, parameters
//! already normalised to each map's domain) and the current attributes that fill the rest.
//!
//! The CPU back end evaluates a job at once ([`MeshJob::evaluate`]); the GPU back end keeps the
//! job in the frame and evaluates every job of the frame in one compute dispatch
//! (the crate's GPU evaluator, `src/gpu/evaluate.rs`). Both read the same numbers, so the CPU result is the GPU's oracle.

use super::eval::Slot;
use super::vertex::Vertex;
use crate::math::rational::normalize;
use crate::tess::{for_row_bands, MapView, Row, RowKernel};
use std::cell::RefCell;
use std::ops::Range;

/// Columns per tile of a long curve (`glEvalMesh1`): a degree-10 basis table of one tile is
/// 88 KiB of f32.
const CURVE_TILE: usize = 2048;

thread_local! {
    /// Row scratch of this thread, kept between meshes so that small meshes allocate nothing.
    static SCRATCH_ROWS: RefCell<Vec<Row<f32>>> = const { RefCell::new(Vec::new()) };
}

/// Writes the evaluated `slot` of a row into its vertices (as `Vertex::set_attribute` does, with the
/// choice of field made once per row rather than per vertex).
fn write_attribute(vertices: &mut [Vertex], slot: Slot, row: &Row<f32>) {
    let p = &row.point;
    match slot {
        Slot::Vertex3 => {
            for (v, ((x, y), z)) in vertices.iter_mut().zip(p[0].iter().zip(&p[1]).zip(&p[2])) {
                v.position = [*x, *y, *z, 1.0];
            }
        }
        Slot::Vertex4 => {
            for (v, (((x, y), z), w)) in vertices.iter_mut().zip(p[0].iter().zip(&p[1]).zip(&p[2]).zip(&p[3])) {
                v.position = [*x, *y, *z, *w];
            }
        }
        _ => {
            for (i, v) in vertices.iter_mut().enumerate() {
                v.set_attribute(slot, row.point_at(i, slot.components()));
            }
        }
    }
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
    /// (`RowKernel`), rows shared out between the cores, every vertex written once.
    #[must_use]
    pub fn evaluate(&self) -> Vec<Vertex> {
        let mut out = Vec::new();
        self.evaluate_into(&mut out);
        out
    }

    /// [`MeshJob::evaluate`] into `out`, reusing its memory (every vertex is overwritten).
    pub fn evaluate_into(&self, out: &mut Vec<Vertex>) {
        if self.scattered {
            *out = self.evaluate_scattered();
            return;
        }
        if out.capacity() >= self.len() {
            out.resize(self.len(), self.template);
        } else {
            // Fresh zeroed memory comes from calloc: its pages are faulted in by the threads
            // below rather than all by this one.
            *out = bytemuck::zeroed_vec(self.len());
        }
        if self.nv == 1 && self.nu > CURVE_TILE {
            // A long curve: tiles of columns, so that each tile's basis table stays in cache
            // and the tiles can be shared out between the cores.
            for_row_bands(out, CURVE_TILE, |first_tile, band| {
                with_scratch_rows(self.maps.len(), |rows| {
                    for (t, vertices) in band.chunks_mut(CURVE_TILE).enumerate() {
                        let start = (first_tile + t) * CURVE_TILE;
                        let kernels = self.kernels(start..start + vertices.len());
                        self.fill_row(&kernels, 0, rows, vertices);
                    }
                });
            });
            return;
        }
        let kernels = self.kernels(0..self.nu);
        for_row_bands(out, self.nu, |first_row, band| {
            with_scratch_rows(self.maps.len(), |rows| {
                for (r, vertices) in band.chunks_mut(self.nu).enumerate() {
                    self.fill_row(&kernels, first_row + r, rows, vertices);
                }
            });
        });
    }

    /// A row kernel per map over the grid columns `columns` (`None` for a malformed map).
    fn kernels(&self, columns: Range<usize>) -> Vec<(Slot, bool, Option<RowKernel<'_, f32>>)> {
        self.maps
            .iter()
            .map(|map| {
                let normals = self.auto_normal && matches!(map.slot, Slot::Vertex3 | Slot::Vertex4);
                let us = map.us.get(columns.clone()).unwrap_or_default();
                (map.slot, normals, RowKernel::new(map.view(), us, &map.vs, normals))
            })
            .collect()
    }

    /// Writes row `j` of every map into `vertices`: the template, then each map's attribute in
    /// Mesa's order (the vertex map last), and the normal where `GL_AUTO_NORMAL` asks for it.
    fn fill_row(
        &self,
        kernels: &[(Slot, bool, Option<RowKernel<'_, f32>>)],
        j: usize,
        rows: &mut [Row<f32>],
        vertices: &mut [Vertex],
    ) {
        for ((_, _, kernel), row) in kernels.iter().zip(rows.iter_mut()) {
            if let Some(kernel) = kernel {
                kernel.eval_row(j, row);
            }
        }
        vertices.fill(self.template);
        for ((slot, normals, kernel), row) in kernels.iter().zip(rows.iter()) {
            // A malformed map (never made by the façade) evaluates to zeros.
            let Some(_) = kernel else {
                vertices.iter_mut().for_each(|v| v.set_attribute(*slot, [0.0; 4]));
                if *normals {
                    vertices.iter_mut().for_each(|v| v.normal = [0.0; 3]);
                }
                continue;
            };
            write_attribute(vertices, *slot, row);
            if *normals {
                for (i, v) in vertices.iter_mut().enumerate() {
                    v.normal = normalize(row.cross_at(i));
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
                point.evaluate()[0]
            })
            .collect()
    }
}
