//! One `glEvalMesh` call as data: the enabled maps it reads (control points copied, parameters
//! already normalised to each map's domain) and the current attributes that fill the rest.
//!
//! The CPU back end evaluates a job at once ([`MeshJob::evaluate`]); the GPU back end keeps the
//! job in the frame and evaluates every job of the frame in one compute dispatch
//! (`render::mesh_gpu`). Both read the same numbers, so the CPU result is the GPU's oracle.

use super::eval::{auto_normal, set_attribute, Slot};
use super::Vertex;
use crate::tess::{eval_grid1, eval_grid2, Grid2, MapView};

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

    /// The vertices of the grid on the CPU, v outer.
    #[must_use]
    pub fn evaluate(&self) -> Vec<Vertex> {
        if self.scattered {
            return self.evaluate_scattered();
        }
        let mut out = vec![self.template; self.len()];
        let mut grid = Grid2::default();
        let mut values = Vec::new();
        for map in &self.maps {
            let is_vertex = matches!(map.slot, Slot::Vertex3 | Slot::Vertex4);
            let normals = is_vertex && self.auto_normal;
            if map.vorder == 1 && self.nv == 1 && map.vs.len() == 1 && !normals {
                eval_grid1(&map.view(), &map.us, &mut values);
                for (v, p) in out.iter_mut().zip(&values) {
                    set_attribute(v, map.slot, *p);
                }
                continue;
            }
            eval_grid2(&map.view(), &map.us, &map.vs, normals, &mut grid);
            let k = map.slot.components();
            for (idx, v) in out.iter_mut().enumerate() {
                set_attribute(v, map.slot, grid.points[idx]);
                if normals {
                    v.normal = auto_normal(k, grid.points[idx], grid.du[idx], grid.dv[idx]);
                }
            }
        }
        out
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
