//! `glEvalMesh1` / `glEvalMesh2` (Mesa `main/draw.c` `_mesa_EvalMesh1/2`): the same primitives
//! in the same order as Mesa, with every grid point evaluated once on the tessellation grid
//! path and the exact end parameter at i = n. A mesh is recorded as one grid
//! ([`crate::gl::GridMesh`]), evaluated now by the CPU tessellator or at draw time by the GPU's.

use super::job::PendingMeshes;
use super::EvalCall;
use super::Grid;
use crate::gl::consts::*;
use crate::gl::lists::ListCommand;
use crate::gl::types::*;
use crate::gl::{Command, Gl, GridMesh, MapSample, MeshJob, MeshMode, MeshVertices, Tessellator};

/// Largest number of vertices one `glEvalMesh` call may record; beyond it the call sets
/// `GL_OUT_OF_MEMORY` and draws nothing (instead of exhausting memory).
pub const MAX_MESH_VERTICES: usize = 1 << 27;

/// The grid parameters for lines `first..=last` through `normalise` (a map's normalisation),
/// in one pass; an empty list when `last < first`.
fn grid_params(grid: &Grid, first: i32, last: i32, normalise: impl Fn(f32) -> f32) -> Vec<f32> {
    (i64::from(first)..=i64::from(last)).map(|i| normalise(grid.param(i))).collect()
}

/// Number of lines in `first..=last` (0 when reversed).
fn line_count(first: i32, last: i32) -> usize {
    usize::try_from(i64::from(last) - i64::from(first) + 1).unwrap_or(0)
}

/// Pending grid points that make a batch: about a millisecond of work, so that handing it to
/// the pool costs little, and a few MiB of vertices.
const PENDING_BATCH_POINTS: usize = 1 << 15;

impl Gl {
    /// `glEvalMesh1(mode, i1, i2)`: `GL_POINT` → one `GL_POINTS`, `GL_LINE` → one
    /// `GL_LINE_STRIP` over grid lines i1..=i2. Another mode → `GL_INVALID_ENUM`; no vertex map
    /// enabled → nothing at all.
    pub fn eval_mesh1(&mut self, mode: GLenum, i1: GLint, i2: GLint) {
        if self.compiled(|| ListCommand::Eval(EvalCall::EvalMesh1(mode, i1, i2))) {
            return;
        }
        if self.reject_inside_begin_end() {
            return;
        }
        let mesh_mode = match mode {
            GL_POINT => MeshMode::Points,
            GL_LINE => MeshMode::CurveLines,
            _ => return self.set_error(GL_INVALID_ENUM),
        };
        let act = self.server.eval.active(1);
        if act.vertex.is_none() {
            return;
        }
        let n = line_count(i1, i2);
        if !self.reserve_vertices(n) {
            return;
        }
        let grid = self.server.eval.grid1;
        let maps = act
            .attributes()
            .chain(act.vertex)
            .map(|slot| {
                let m = self.server.eval.map(1, slot);
                let us = grid_params(&grid, i1, i2, |u| m.norm_u(u));
                MapSample { slot, uorder: m.uorder, vorder: 1, points: m.points.clone(), us, vs: vec![0.0] }
            })
            .collect();
        let template = self.current_vertex([0.0, 0.0, 0.0, 1.0]);
        let job = MeshJob { maps, auto_normal: false, template, nu: n, nv: 1, scattered: false };
        self.record_mesh(mesh_mode, job);
    }

    /// `glEvalMesh2(mode, i1, i2, j1, j2)`: `GL_POINT` → one `GL_POINTS` (j outer, i inner);
    /// `GL_LINE` → a `GL_LINE_STRIP` per row j, then one per column i; `GL_FILL` → one
    /// `GL_TRIANGLE_STRIP` per row j in j1..j2, alternating (i, j) and (i, j+1): clockwise in
    /// (u, v) when both increase, exactly as Mesa. Every grid point is evaluated once.
    pub fn eval_mesh2(&mut self, mode: GLenum, i1: GLint, i2: GLint, j1: GLint, j2: GLint) {
        if self.compiled(|| ListCommand::Eval(EvalCall::EvalMesh2(mode, i1, i2, j1, j2))) {
            return;
        }
        if self.reject_inside_begin_end() {
            return;
        }
        let mesh_mode = match mode {
            GL_POINT => MeshMode::Points,
            GL_LINE => MeshMode::SurfaceLines,
            GL_FILL => MeshMode::Fill,
            _ => return self.set_error(GL_INVALID_ENUM),
        };
        let act = self.server.eval.active(2);
        if act.vertex.is_none() {
            return;
        }
        let (nu, nv) = (line_count(i1, i2), line_count(j1, j2));
        // GL's primitives repeat interior points (strips twice): the limit counts what GL issues.
        let issued =
            if mesh_mode == MeshMode::Points { nu.saturating_mul(nv) } else { nu.saturating_mul(nv).saturating_mul(2) };
        if !self.reserve_vertices(issued) {
            return;
        }
        if nu == 0 || nv == 0 {
            // GL issues only empty strips (j2 < j1 with a huge i range, say): nothing is drawn,
            // and a mesh of 2³⁰ empty columns would cost gigabytes to assemble.
            return;
        }
        let (gu, gv) = self.server.eval.grid2;
        let maps = act
            .attributes()
            .chain(act.vertex)
            .map(|slot| {
                let m = self.server.eval.map(2, slot);
                MapSample {
                    slot,
                    uorder: m.uorder,
                    vorder: m.vorder,
                    points: m.points.clone(),
                    us: grid_params(&gu, i1, i2, |u| m.norm_u(u)),
                    vs: grid_params(&gv, j1, j2, |v| m.norm_v(v)),
                }
            })
            .collect();
        let template = self.current_vertex([0.0, 0.0, 0.0, 1.0]);
        let job = MeshJob { maps, auto_normal: self.server.eval.auto_normal, template, nu, nv, scattered: false };
        self.record_mesh(mesh_mode, job);
    }

    /// Checks the size limit; false (with `GL_OUT_OF_MEMORY`) if too large.
    fn reserve_vertices(&mut self, n: usize) -> bool {
        if n > MAX_MESH_VERTICES || self.recorder.frame.meshes.try_reserve(1).is_err() {
            self.set_error(GL_OUT_OF_MEMORY);
            return false;
        }
        true
    }

    /// Records a mesh, evaluated now on the CPU tessellator or left for the GPU.
    ///
    /// A small grid (one the row path would evaluate on a single core) is left pending with its own copy of the maps
    /// and the state, and evaluated with the other pending ones, many at once across the cores,
    /// when they add up to [`PENDING_BATCH_POINTS`] or when the frame is looked at
    /// ([`Gl::frame`], [`Gl::take_frame`]): a program drawing many small patches (the teapot,
    /// B-spline surfaces patch by patch) would otherwise use one core.
    fn record_mesh(&mut self, mode: MeshMode, job: MeshJob) {
        let (nu, nv) = (job.nu, job.nv);
        let mut pending = None;
        let vertices = if self.recorder.tessellator == Tessellator::Gpu && self.gpu_draws(mode) {
            MeshVertices::Deferred(vec![job])
        } else if job.len() < crate::tess::MIN_POINTS_PER_THREAD && !job.scattered {
            pending = Some(job);
            MeshVertices::Evaluated(self.pooled_vertices())
        } else {
            let mut vertices = self.pooled_vertices();
            job.evaluate_into(&mut vertices);
            MeshVertices::Evaluated(vertices)
        };
        let state = self.current_state_index();
        let unit_tex_coords = self.server.current.unit_tex_coords;
        let mesh = GridMesh { mode, nu, nv, state, vertices, triangles: Vec::new(), unit_tex_coords };
        self.recorder.frame.meshes.push(mesh);
        let index = self.recorder.frame.meshes.len() - 1;
        self.recorder.frame.commands.push(Command::Mesh(index));
        if let Some(job) = pending {
            let PendingMeshes { jobs, points } = &mut self.recorder.pending_meshes;
            *points += job.len();
            jobs.push((index, job));
            if *points >= PENDING_BATCH_POINTS {
                self.evaluate_pending_meshes();
            }
        }
    }

    /// Evaluates the pending small meshes into their vertex buffers, meshes shared out between
    /// the cores (each mesh on one).
    pub(crate) fn evaluate_pending_meshes(&mut self) {
        use rayon::prelude::*;
        let PendingMeshes { jobs, points } = &mut self.recorder.pending_meshes;
        let Some(&(first, _)) = jobs.first() else { return };
        *points = 0;
        // Each job with its mesh's buffer: jobs are in the order of their (increasing) indices.
        let mut work = Vec::with_capacity(jobs.len());
        let mut next = jobs.iter().peekable();
        for (index, mesh) in self.recorder.frame.meshes.iter_mut().enumerate().skip(first) {
            let Some((wanted, job)) = next.peek() else { break };
            if *wanted == index {
                if let MeshVertices::Evaluated(vertices) = &mut mesh.vertices {
                    work.push((job, vertices));
                }
                next.next();
            }
        }
        work.into_par_iter().for_each(|(job, vertices)| job.evaluate_into(vertices));
        jobs.clear();
    }

    /// Records triangles over points evaluated by `jobs` (scattered (u, v) points, one job per
    /// Bezier piece, outputs concatenated): GLU's trimmed surfaces on the GPU tessellator.
    /// `triangles` index the concatenated points, GL_TRIANGLES order.
    pub(crate) fn record_scattered_mesh(&mut self, jobs: Vec<MeshJob>, triangles: Vec<u32>) {
        if self.compiled(|| ListCommand::ScatteredMesh(jobs.clone(), triangles.clone())) {
            return;
        }
        let nu = jobs.iter().map(MeshJob::len).sum();
        let state = self.current_state_index();
        let vertices = MeshVertices::Deferred(jobs);
        let unit_tex_coords = self.server.current.unit_tex_coords;
        let mesh = GridMesh { mode: MeshMode::Triangles, nu, nv: 1, state, vertices, triangles, unit_tex_coords };
        self.recorder.frame.meshes.push(mesh);
        let index = self.recorder.frame.meshes.len() - 1;
        self.recorder.frame.commands.push(Command::Mesh(index));
    }

    /// Whether the GPU mesh pipeline draws `mode` in the current state exactly as GL does:
    /// filled polygons (both faces `GL_FILL`), one-pixel lines and one-pixel points. GL's wide
    /// lines, large points and polygon-mode edges are built on the CPU, so such meshes are too.
    pub(crate) fn gpu_draws(&self, mode: MeshMode) -> bool {
        // Generated texture coordinates are computed with the CPU's vertex stage.
        let texturing = self.capability(GL_TEXTURE_2D) || self.capability(GL_TEXTURE_1D);
        let generating = [GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R, GL_TEXTURE_GEN_Q];
        if texturing && generating.iter().any(|&cap| self.capability(cap)) {
            return false;
        }
        // So are clip planes, polygon offset, stipple and smoothing, done by the CPU assembler.
        let (state, smooth) =
            (self.raster_modes_on(), self.capability(GL_POINT_SMOOTH) || self.capability(GL_LINE_SMOOTH));
        if state || smooth {
            return false;
        }
        let s = &self.server;
        match mode {
            MeshMode::Fill | MeshMode::Triangles => s.polygon.mode == [GL_FILL, GL_FILL],
            MeshMode::CurveLines | MeshMode::SurfaceLines => s.line.width.round() <= 1.0,
            MeshMode::Points => s.point.size.round() <= 1.0,
        }
    }
}
