//! One `glEvalMesh` call as data: the enabled maps it reads (control points copied, parameters
//! already normalised to each map's domain) and the current attributes that fill the rest.
//!
//! The CPU back end evaluates a job at once ([`MeshJob::evaluate`]); the GPU back end keeps the
//! job in the frame and evaluates every job of the frame in one compute dispatch
//! (`render::mesh_gpu`). Both read the same numbers, so the CPU result is the GPU's oracle.

use super::eval::{set_attribute, Slot};
use super::Vertex;
use crate::math::rational::normalize;
use crate::tess::{for_row_bands, MapView, Row, RowKernel};

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
    /// ([`RowKernel`]), rows shared out between the cores, every vertex written once.
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
        let kernels: Vec<_> = self
            .maps
            .iter()
            .map(|map| {
                let normals = self.auto_normal && matches!(map.slot, Slot::Vertex3 | Slot::Vertex4);
                (map.slot, normals, RowKernel::new(map.view(), &map.us, &map.vs, normals))
            })
            .collect();
        if out.capacity() >= self.len() {
            out.resize(self.len(), self.template);
        } else {
            // Fresh zeroed memory comes from calloc: its pages are faulted in by the threads
            // below rather than all by this one.
            *out = bytemuck::zeroed_vec(self.len());
        }
        for_row_bands(out, self.nu, |first_row, band| {
            let mut rows = vec![Row::default(); kernels.len()];
            for (r, vertices) in band.chunks_mut(self.nu).enumerate() {
                for ((_, _, kernel), row) in kernels.iter().zip(&mut rows) {
                    if let Some(kernel) = kernel {
                        kernel.eval_row(first_row + r, row);
                    }
                }
                for (i, v) in vertices.iter_mut().enumerate() {
                    *v = self.template;
                    for ((slot, normals, kernel), row) in kernels.iter().zip(&rows) {
                        let k = slot.components();
                        // A malformed map (never made by the façade) evaluates to zeros.
                        let valid = kernel.is_some();
                        set_attribute(v, *slot, if valid { row.point_at(i, k) } else { [0.0; 4] });
                        if *normals {
                            v.normal = if valid { normalize(row.cross_at(i)) } else { [0.0; 3] };
                        }
                    }
                }
            }
        });
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
