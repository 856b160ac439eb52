//! `glEvalMesh1` / `glEvalMesh2` (Mesa `main/draw.c` `_mesa_EvalMesh1/2`): the same primitives
//! in the same order as Mesa, with every grid point evaluated once on the tessellation grid
//! path and the exact end parameter at i = n.

use super::coord::{auto_normal, set_attribute};
use super::target::Slot;
use super::{ActiveMaps, Grid};
use crate::gl::consts::*;
use crate::gl::types::*;
use crate::gl::{Gl, Vertex};
use crate::tess::{eval_grid1, eval_grid2, Grid2, MapView};

/// Largest number of vertices one `glEvalMesh` call may record; beyond it the call sets
/// `GL_OUT_OF_MEMORY` and draws nothing (instead of exhausting memory).
pub const MAX_MESH_VERTICES: usize = 1 << 27;

/// The grid parameters for lines `first..=last`, or an empty list when `last < first`.
fn grid_params(grid: &Grid, first: i32, last: i32) -> Vec<f32> {
    (i64::from(first)..=i64::from(last)).map(|i| grid.param(i)).collect()
}

/// Number of lines in `first..=last` (0 when reversed).
fn line_count(first: i32, last: i32) -> usize {
    usize::try_from(i64::from(last) - i64::from(first) + 1).unwrap_or(0)
}

impl Gl {
    /// `glEvalMesh1(mode, i1, i2)`: `GL_POINT` → one `GL_POINTS`, `GL_LINE` → one
    /// `GL_LINE_STRIP` over grid lines i1..=i2. Another mode → `GL_INVALID_ENUM`; no vertex map
    /// enabled → nothing at all.
    pub fn eval_mesh1(&mut self, mode: GLenum, i1: GLint, i2: GLint) {
        if self.reject_inside_begin_end() {
            return;
        }
        let prim = match mode {
            GL_POINT => GL_POINTS,
            GL_LINE => GL_LINE_STRIP,
            _ => return self.set_error(GL_INVALID_ENUM),
        };
        let act = self.eval.active(1);
        if act.vertex.is_none() {
            return;
        }
        let n = line_count(i1, i2);
        if !self.reserve_vertices(n) {
            return;
        }
        let us = grid_params(&self.eval.grid1, i1, i2);
        let vertices = self.curve_vertices(&act, &us);
        self.open_primitive_raw(prim);
        for v in vertices {
            self.emit_vertex(v);
        }
        self.open_primitive = None;
    }

    /// `glEvalMesh2(mode, i1, i2, j1, j2)`: `GL_POINT` → one `GL_POINTS` (j outer, i inner);
    /// `GL_LINE` → a `GL_LINE_STRIP` per row j, then one per column i; `GL_FILL` → one
    /// `GL_TRIANGLE_STRIP` per row j in j1..j2, alternating (i, j) and (i, j+1): clockwise in
    /// (u, v) when both increase, exactly as Mesa.
    pub fn eval_mesh2(&mut self, mode: GLenum, i1: GLint, i2: GLint, j1: GLint, j2: GLint) {
        if self.reject_inside_begin_end() {
            return;
        }
        if !matches!(mode, GL_POINT | GL_LINE | GL_FILL) {
            return self.set_error(GL_INVALID_ENUM);
        }
        let act = self.eval.active(2);
        if act.vertex.is_none() {
            return;
        }
        let (nu, nv) = (line_count(i1, i2), line_count(j1, j2));
        let total = nu.saturating_mul(nv).saturating_mul(2);
        if !self.reserve_vertices(total) {
            return;
        }
        let (gu, gv) = self.eval.grid2;
        let us = grid_params(&gu, i1, i2);
        let vs = grid_params(&gv, j1, j2);
        let grid = self.surface_vertices(&act, &us, &vs);
        match mode {
            GL_POINT => self.emit_mesh_points(&grid),
            GL_LINE => self.emit_mesh_lines(&grid, nu, nv),
            _ => self.emit_mesh_fill(&grid, nu, nv),
        }
    }

    /// Checks the size limit and reserves room; false (with `GL_OUT_OF_MEMORY`) if too large.
    fn reserve_vertices(&mut self, n: usize) -> bool {
        if n > MAX_MESH_VERTICES || self.frame.vertices.try_reserve(n).is_err() {
            self.set_error(GL_OUT_OF_MEMORY);
            return false;
        }
        true
    }

    fn emit_primitive(&mut self, mode: GLenum, vertices: impl Iterator<Item = Vertex>) {
        self.open_primitive_raw(mode);
        for v in vertices {
            self.emit_vertex(v);
        }
        self.open_primitive = None;
    }

    fn emit_mesh_points(&mut self, grid: &[Vertex]) {
        self.emit_primitive(GL_POINTS, grid.iter().copied());
    }

    fn emit_mesh_lines(&mut self, grid: &[Vertex], nu: usize, nv: usize) {
        for j in 0..nv {
            self.emit_primitive(GL_LINE_STRIP, (0..nu).map(|i| grid[j * nu + i]));
        }
        for i in 0..nu {
            self.emit_primitive(GL_LINE_STRIP, (0..nv).map(|j| grid[j * nu + i]));
        }
    }

    fn emit_mesh_fill(&mut self, grid: &[Vertex], nu: usize, nv: usize) {
        for j in 0..nv.saturating_sub(1) {
            let strip = (0..nu).flat_map(|i| [grid[j * nu + i], grid[(j + 1) * nu + i]]);
            self.emit_primitive(GL_TRIANGLE_STRIP, strip);
        }
    }

    /// The vertices of the active MAP1 maps at grid parameters `us`.
    fn curve_vertices(&self, act: &ActiveMaps, us: &[f32]) -> Vec<Vertex> {
        let template = self.current_vertex([0.0, 0.0, 0.0, 1.0]);
        let mut out = vec![template; us.len()];
        let mut values = Vec::new();
        for slot in act.attributes().chain(act.vertex) {
            let m = self.eval.map(1, slot);
            let view = MapView { dim: slot.components(), uorder: m.uorder, vorder: 1, points: &m.points };
            let normalised: Vec<f32> = us.iter().map(|&u| m.norm_u(u)).collect();
            eval_grid1(&view, &normalised, &mut values);
            for (v, p) in out.iter_mut().zip(&values) {
                set_attribute(v, slot, *p);
            }
        }
        out
    }

    /// The vertices of the active MAP2 maps on the grid `us` × `vs`, v outer.
    fn surface_vertices(&self, act: &ActiveMaps, us: &[f32], vs: &[f32]) -> Vec<Vertex> {
        let template = self.current_vertex([0.0, 0.0, 0.0, 1.0]);
        let mut out = vec![template; us.len() * vs.len()];
        let mut grid = Grid2::default();
        for slot in act.attributes() {
            self.eval_map2_grid(slot, us, vs, false, &mut grid);
            for (v, p) in out.iter_mut().zip(&grid.points) {
                set_attribute(v, slot, *p);
            }
        }
        if let Some(slot) = act.vertex {
            let normals = self.eval.auto_normal;
            self.eval_map2_grid(slot, us, vs, normals, &mut grid);
            let k = slot.components();
            for (idx, v) in out.iter_mut().enumerate() {
                set_attribute(v, slot, grid.points[idx]);
                if normals {
                    v.normal = auto_normal(k, grid.points[idx], grid.du[idx], grid.dv[idx]);
                }
            }
        }
        out
    }

    fn eval_map2_grid(&self, slot: Slot, us: &[f32], vs: &[f32], partials: bool, out: &mut Grid2<f32>) {
        let m = self.eval.map(2, slot);
        let view = MapView { dim: slot.components(), uorder: m.uorder, vorder: m.vorder, points: &m.points };
        let nu: Vec<f32> = us.iter().map(|&u| m.norm_u(u)).collect();
        let nv: Vec<f32> = vs.iter().map(|&v| m.norm_v(v)).collect();
        eval_grid2(&view, &nu, &nv, partials, out);
    }
}
