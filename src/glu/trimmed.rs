//! Trimmed NURBS surfaces: the trim loops become (u, v) polylines, the retained region is
//! triangulated with the surface's sampling grid inside ([`crate::tess::trim`]), and every
//! vertex is evaluated on the exact surface. Loop errors are GLU's numbers 28, 29, 31 and 18.

use super::callbacks::StripSink;
use super::consts::*;
use super::draw::{emit_attributes, piece_kernel, surface_normal, trim_polylines, vertex_row, PatchGrid, Surface};
use super::nurbs::{NurbsObject, TrimPiece};
use super::pieces::{locate, SurfacePatches};
use super::sampling::Sampler;
use crate::gl::consts::*;
use crate::gl::{Gl, MapSample, MapTarget, MeshJob, MeshMode, Slot, Tessellator, Vertex};
use crate::math::bezier::bernstein;
use crate::tess::trim::{join_curves, triangulate_with, GridStrip, Lattice, TrimLoop, TrimOptions, TrimPlan};
use crate::tess::{MapView, Row, RowKernel};
use std::collections::BTreeMap;

/// Grid lines of every patch at its sampling density, merged over the whole domain.
fn grid_lines(steps: &[PatchGrid]) -> (Vec<f64>, Vec<f64>) {
    let mut us: Vec<f64> = Vec::new();
    let mut vs: Vec<f64> = Vec::new();
    for &((u0, u1), (v0, v1), (nu, nv)) in steps {
        us.extend((0..=nu).map(|i| u0 + (u1 - u0) * i as f64 / nu as f64));
        vs.extend((0..=nv).map(|j| v0 + (v1 - v0) * j as f64 / nv as f64));
    }
    for lines in [&mut us, &mut vs] {
        lines.sort_by(f64::total_cmp);
        lines.dedup_by(|a, b| (*a - *b).abs() < 1e-9);
    }
    (us, vs)
}

/// The triangulation of trimmed surfaces in both modes: the band cell by cell, as GLU's slicer
/// cuts its grid.
const BY_CELLS: TrimOptions = TrimOptions::DEFAULT.with_clearance(0.0).with_by_cells(true);

/// Draws a trimmed surface.
pub(crate) fn draw_trimmed(
    gl: &mut Gl,
    obj: &mut NurbsObject,
    surface: &Surface,
    loops: &[Vec<TrimPiece>],
    sampler: &Sampler,
    tessellate: bool,
) {
    let steps = surface.patches(sampler);
    let (us, vs) = grid_lines(&steps);
    // Trim curves are sampled about as finely as the surface grid.
    let spacing = steps
        .iter()
        .map(|&((u0, u1), (v0, v1), (nu, nv))| ((u1 - u0) / nu as f64).min((v1 - v0) / nv as f64))
        .fold(f64::INFINITY, f64::min);
    let segments = |points: &[f64], dim: usize, _order: usize| {
        let length: f64 = points
            .chunks_exact(dim)
            .map(|p| if dim == 3 { [p[0] / p[2], p[1] / p[2]] } else { [p[0], p[1]] })
            .collect::<Vec<_>>()
            .windows(2)
            .map(|w| ((w[1][0] - w[0][0]).powi(2) + (w[1][1] - w[0][1]).powi(2)).sqrt())
            .sum();
        ((length / spacing).ceil() as usize).clamp(4, 4096)
    };
    let mut trim_loops = Vec::with_capacity(loops.len());
    for pieces in loops {
        match join_curves(&trim_polylines(pieces, segments)) {
            Ok(l) => trim_loops.push(l),
            Err(e) => return obj.nurbs_error(e.glu_number()),
        }
    }
    let domain = surface.domain();
    if tessellate {
        return tessellate_trimmed(obj, surface, &trim_loops, domain, (&us, &vs));
    }
    let mesh = match triangulate_with(&trim_loops, domain, &us, &vs, &BY_CELLS) {
        Ok(m) => m,
        Err(e) => return obj.nurbs_error(e.glu_number()),
    };
    if obj.props.display_mode == GLU_OUTLINE_PATCH {
        return outline_loops(gl, surface, &trim_loops);
    }
    let saved_mode = gl.raster.polygon_mode;
    if obj.props.display_mode == GLU_OUTLINE_POLYGON {
        gl.polygon_mode(GL_FRONT_AND_BACK, GL_LINE);
    } else {
        gl.polygon_mode(GL_FRONT_AND_BACK, GL_FILL);
    }
    if gl.tessellator() == Tessellator::Gpu && obj.props.display_mode == GLU_FILL && gl.gpu_draws(MeshMode::Triangles) {
        record_on_gpu(gl, surface, &mesh.points, mesh.triangles());
        return gl.restore_polygon_mode(saved_mode);
    }
    // Each point evaluated once; the triangles issue the shared vertices.
    let vertices: Vec<Option<Vertex>> = mesh.points.iter().map(|&[u, v]| trimmed_vertex(gl, surface, u, v)).collect();
    gl.begin(GL_TRIANGLES);
    for tri in mesh.triangles() {
        for i in tri {
            if let Some(vertex) = vertices[i as usize] {
                gl.emit_vertex(vertex);
            }
        }
    }
    gl.end();
    gl.restore_polygon_mode(saved_mode);
}

/// Tessellator mode. The sampling lattice is evaluated on the pool while this thread checks the
/// loops and splits the region ([`TrimPlan`]); then, when only begin, vertex and end callbacks
/// are registered, the pool triangulates the band along the loops (cell by cell) while this
/// thread issues the grid cells wholly inside, a `GL_QUAD_STRIP` per run, as GLU issues its grid
/// blocks; the band follows as `GL_TRIANGLES`. Each point is evaluated once.
fn tessellate_trimmed(
    obj: &mut NurbsObject,
    surface: &Surface,
    loops: &[TrimLoop],
    domain: [f64; 4],
    (us, vs): (&[f64], &[f64]),
) {
    let lattice = Lattice::lines(domain, us, vs);
    let mut values = None;
    let plan = rayon::in_place_scope(|scope| {
        scope.spawn(|_| values = LatticeValues::evaluate(&surface.pos, surface.k, lattice));
        TrimPlan::new(loops, domain, us, vs, &BY_CELLS)
    });
    let plan = match plan {
        Ok(plan) => plan,
        Err(e) => return obj.nurbs_error(e.glu_number()),
    };
    let mut values = values.filter(|v| plan.lattice_lines() == (&v.lattice.u[..], &v.lattice.v[..]));
    let mut band = None;
    if let (Some(lattice), Some(mut sinks)) = (&values, obj.callbacks.sinks()) {
        rayon::in_place_scope(|scope| {
            scope.spawn(|_| band = Some(plan.triangulate_band()));
            let value = |i: u32| lattice.values[plan.grid_index()[i as usize] as usize].as_ref();
            match sinks.plain() {
                Some(mut plain) => issue_strips(&mut plain, plan.strips(), value),
                None => issue_strips(&mut sinks, plan.strips(), value),
            }
        });
        if let Some(Ok(band)) = &band {
            let data = PointValues::new(surface, plan.grid_points(), plan.grid_index(), &band.points, values.take());
            match sinks.plain() {
                Some(mut plain) => issue_band(&mut plain, &band.triangles, |i| data.get(i)),
                None => issue_band(&mut sinks, &band.triangles, |i| data.get(i)),
            }
            return;
        }
    }
    // A band that failed after the strips went out is reported as GLU reports a bad trim.
    let band = match band.unwrap_or_else(|| plan.triangulate_band()) {
        Ok(band) => band,
        Err(e) => return obj.nurbs_error(e.glu_number()),
    };
    let mesh = plan.into_mesh(band);
    let (grid_points, extra) = mesh.points.split_at(mesh.lattice.index.len());
    let data = PointValues::new(surface, grid_points, &mesh.lattice.index, extra, values);
    if let Some(mut sinks) = obj.callbacks.sinks() {
        issue_strips(&mut sinks, &mesh.strips, |i| data.get(i));
        return issue_band(&mut sinks, &mesh.band, |i| data.get(i));
    }
    // Other callbacks registered: attributes and normals per vertex, before the position.
    let per_vertex = !surface.attributes.is_empty() || obj.callbacks.wants_normals();
    let emit = |obj: &mut NurbsObject, i: u32| {
        let [u, v] = mesh.points[i as usize];
        if per_vertex {
            emit_attributes(obj, surface.view_ref(), u, v);
        }
        if let Some(d) = data.get(i) {
            obj.callbacks.attribute(GLU_NURBS_VERTEX, d);
        }
    };
    for strip in &mesh.strips {
        obj.callbacks.begin(GL_QUAD_STRIP);
        for (top, bottom) in strip_pairs(*strip) {
            emit(obj, top);
            emit(obj, bottom);
        }
        obj.callbacks.end();
    }
    if !mesh.band.is_empty() {
        obj.callbacks.begin(GL_TRIANGLES);
        mesh.band.iter().flatten().for_each(|&i| emit(obj, i));
        obj.callbacks.end();
    }
}

/// The grid strips, a `GL_QUAD_STRIP` per run of cells, through the fast callbacks.
fn issue_strips<'v>(sinks: &mut impl StripSink, strips: &[GridStrip], value: impl Fn(u32) -> Option<&'v [f32; 5]>) {
    for strip in strips {
        sinks.begin(GL_QUAD_STRIP);
        for (top, bottom) in strip_pairs(*strip) {
            for d in [top, bottom].into_iter().filter_map(&value) {
                sinks.vertex(d);
            }
        }
        sinks.end();
    }
}

/// The band's triangles as `GL_TRIANGLES` through the fast callbacks.
fn issue_band<'v>(sinks: &mut impl StripSink, triangles: &[[u32; 3]], value: impl Fn(u32) -> Option<&'v [f32; 5]>) {
    if !triangles.is_empty() {
        sinks.begin(GL_TRIANGLES);
        triangles.iter().flatten().filter_map(|&i| value(i)).for_each(|d| sinks.vertex(d));
        sinks.end();
    }
}

/// A run's (top, bottom) point pairs by increasing u: as a `GL_QUAD_STRIP`, quads
/// top, bottom, next bottom, next top: counter-clockwise in (u, v).
fn strip_pairs(strip: GridStrip) -> impl Iterator<Item = (u32, u32)> {
    (0..=strip.cells).map(move |i| (strip.top + i, strip.bottom + i))
}

/// The vertex-callback data of every point of a [`Lattice`] (v outer), `None` outside the
/// surface.
struct LatticeValues {
    lattice: Lattice,
    values: Vec<Option<[f32; 5]>>,
}

impl LatticeValues {
    /// Evaluates every lattice point on the row path: one row kernel per Bezier piece (its
    /// basis tables computed once), rows shared out on the pool. `None` when the lattice is
    /// beyond the triangulation's point budget (it would be coarsened and not match).
    fn evaluate(pos: &SurfacePatches, k: usize, lattice: Lattice) -> Option<Self> {
        use rayon::prelude::*;
        if lattice.point_count() > TrimOptions::DEFAULT.max_points {
            return None;
        }
        let p = &pos.patches;
        let uruns = piece_runs(&p.uintervals, &lattice.u);
        let vruns = piece_runs(&p.vintervals, &lattice.v);
        let kernels: Vec<Vec<Option<RowKernel<f64>>>> = vruns
            .iter()
            .map(|(b, vrange)| {
                uruns
                    .iter()
                    .map(|(a, urange)| {
                        let (us, vs) = (&lattice.u[urange.clone()], &lattice.v[vrange.clone()]);
                        piece_kernel(p, (*a, *b), p.patch(*a, *b)?, us, vs)
                    })
                    .collect()
            })
            .collect();
        let nu = lattice.u.len();
        let mut values = vec![None; lattice.point_count()];
        // Per v line: its run in `vruns` (None: outside every piece, left None).
        let mut row_run = vec![None; lattice.v.len()];
        for (bi, (_, range)) in vruns.iter().enumerate() {
            range.clone().for_each(|j| row_run[j] = Some(bi));
        }
        values.par_chunks_mut(nu).zip(row_run.par_iter().enumerate()).for_each_init(
            Row::default,
            |row, (line, (j, run))| {
                let Some(bi) = *run else { return };
                let local_j = j - vruns[bi].1.start;
                for ((_, urange), kernel) in uruns.iter().zip(&kernels[bi]) {
                    let Some(kernel) = kernel else { continue };
                    kernel.eval_row(local_j, row);
                    vertex_row(row, k, &lattice.u[urange.clone()], lattice.v[j], &mut line[urange.clone()], Some);
                }
            },
        );
        Some(Self { lattice, values })
    }
}

/// The lines grouped by the Bezier piece they lie on: (piece, range of line indices), lines
/// outside every piece left out.
fn piece_runs(intervals: &[(f64, f64)], lines: &[f64]) -> Vec<(usize, std::ops::Range<usize>)> {
    let mut runs: Vec<(usize, std::ops::Range<usize>)> = Vec::new();
    for (i, &x) in lines.iter().enumerate() {
        let Some(piece) = locate(intervals, x) else { continue };
        match runs.last_mut() {
            Some((last, range)) if *last == piece && range.end == i => range.end = i + 1,
            _ => runs.push((piece, i..i + 1)),
        }
    }
    runs
}

/// The vertex-callback data of a trimmed mesh's points: the grid points from the lattice's
/// values when there are some, the rest (the band's points, or all) evaluated here.
struct PointValues<'a> {
    /// Each grid point's index in the lattice (the plan's, not copied).
    grid_index: &'a [u32],
    lattice: Option<LatticeValues>,
    rest: Vec<Option<[f32; 5]>>,
    first_rest: usize,
}

impl<'a> PointValues<'a> {
    /// The data of `grid_points` (lattice indices `grid_index`) then of `extra`.
    fn new(
        surface: &Surface,
        grid_points: &[[f64; 2]],
        grid_index: &'a [u32],
        extra: &[[f64; 2]],
        lattice: Option<LatticeValues>,
    ) -> Self {
        let (pos, k) = (&surface.pos, surface.k);
        match lattice {
            Some(l) => Self {
                grid_index,
                lattice: Some(l),
                rest: evaluate_positions(pos, k, extra),
                first_rest: grid_points.len(),
            },
            None => {
                let all: Vec<[f64; 2]> = grid_points.iter().chain(extra).copied().collect();
                Self { grid_index, lattice: None, rest: evaluate_positions(pos, k, &all), first_rest: 0 }
            }
        }
    }

    fn get(&self, i: u32) -> Option<&[f32; 5]> {
        let i = i as usize;
        match &self.lattice {
            Some(l) if i < self.first_rest => l.values[self.grid_index[i] as usize].as_ref(),
            _ => self.rest[i - self.first_rest].as_ref(),
        }
    }
}

/// Points evaluated per parallel task in [`evaluate_positions`].
const POINTS_PER_TASK: usize = 4096;

/// Runs of at least this many points with one v on one piece go through the row kernel.
const MIN_KERNEL_RUN: usize = 8;

/// The vertex-callback data ((x, y, z) divided by w, then u, v) of every point, `None` outside
/// the surface. The triangulation lists its grid points row by row: a run of points sharing a
/// v and a Bezier piece is evaluated by the row kernel (basis tables, vectorised sums); the
/// loop points one by one.
fn evaluate_positions(pos: &SurfacePatches, k: usize, points: &[[f64; 2]]) -> Vec<Option<[f32; 5]>> {
    use rayon::prelude::*;
    let mut out = vec![None; points.len()];
    out.par_chunks_mut(POINTS_PER_TASK).zip(points.par_chunks(POINTS_PER_TASK)).for_each(|(out, points)| {
        let mut single = RowCache::default();
        let mut row = Row::default();
        let mut start = 0;
        while start < points.len() {
            let piece =
                |p: &[f64; 2]| Some((locate(&pos.patches.uintervals, p[0])?, locate(&pos.patches.vintervals, p[1])?));
            let key = (points[start][1].to_bits(), piece(&points[start]));
            let len = points[start..].iter().take_while(|p| (p[1].to_bits(), piece(p)) == key).count().max(1);
            let run = &points[start..start + len];
            let done = match key.1 {
                Some((a, b)) if len >= MIN_KERNEL_RUN => {
                    eval_run(pos, k, (a, b), run, &mut row, &mut out[start..start + len])
                }
                _ => false,
            };
            if !done {
                for (o, &[u, v]) in out[start..start + len].iter_mut().zip(run) {
                    *o = single.eval(pos, k, u, v);
                }
            }
            start += len;
        }
    });
    out
}

/// Points of one v on Bezier piece (a, b) through the row kernel; false if it has none.
fn eval_run(
    pos: &SurfacePatches,
    k: usize,
    (a, b): (usize, usize),
    run: &[[f64; 2]],
    row: &mut Row<f64>,
    out: &mut [Option<[f32; 5]>],
) -> bool {
    let p = &pos.patches;
    let ((ua, ub), (va, vb)) = (p.uintervals[a], p.vintervals[b]);
    let Some(points) = p.patch(a, b) else { return false };
    let su: Vec<f64> = run.iter().map(|q| (q[0] - ua) / (ub - ua)).collect();
    let sv = [(run[0][1] - va) / (vb - va)];
    let view = MapView { dim: p.dim, uorder: p.uorder, vorder: p.vorder, points };
    let Some(kernel) = RowKernel::new(view, &su, &sv, false) else { return false };
    kernel.eval_row(0, row);
    let [x, y, z, w] = &row.point;
    for (i, (o, q)) in out.iter_mut().zip(run).enumerate() {
        let w = if k == 4 { w[i] } else { 1.0 };
        *o = Some([(x[i] / w) as f32, (y[i] / w) as f32, (z[i] / w) as f32, q[0] as f32, q[1] as f32]);
    }
    true
}

/// The net of one Bezier piece reduced along v at one v, reused while consecutive points share
/// the piece and the v.
#[derive(Default)]
struct RowCache {
    key: Option<(usize, usize, u64)>,
    reduced: Vec<[f64; 4]>,
    basis: Vec<f64>,
}

impl RowCache {
    fn eval(&mut self, pos: &SurfacePatches, k: usize, u: f64, v: f64) -> Option<[f32; 5]> {
        let p = &pos.patches;
        let (a, b) = (locate(&p.uintervals, u)?, locate(&p.vintervals, v)?);
        let ((ua, ub), (va, vb)) = (p.uintervals[a], p.vintervals[b]);
        if self.key != Some((a, b, v.to_bits())) {
            let net = p.patch(a, b)?;
            self.basis.resize(p.vorder, 0.0);
            bernstein(p.vorder, (v - va) / (vb - va), &mut self.basis);
            self.reduced.clear();
            for column in net.chunks_exact(p.vorder * p.dim) {
                let mut r = [0.0; 4];
                for (bj, point) in self.basis.iter().zip(column.chunks_exact(p.dim)) {
                    for (rc, &c) in r.iter_mut().zip(point) {
                        *rc += bj * c;
                    }
                }
                self.reduced.push(r);
            }
            self.key = Some((a, b, v.to_bits()));
        }
        self.basis.resize(p.uorder, 0.0);
        bernstein(p.uorder, (u - ua) / (ub - ua), &mut self.basis);
        let mut q = [0.0; 4];
        for (bi, r) in self.basis.iter().zip(&self.reduced) {
            for (qc, &c) in q.iter_mut().zip(r) {
                *qc += bi * c;
            }
        }
        let w = if k == 4 { q[3] } else { 1.0 };
        Some([(q[0] / w) as f32, (q[1] / w) as f32, (q[2] / w) as f32, u as f32, v as f32])
    }
}

/// The GPU tessellator's trimmed surface: the triangulation's (u, v) points grouped by the
/// Bezier piece they lie on, one scattered job per piece (its control points and the points'
/// parameters normalised to it), drawn as GL_TRIANGLES over the triangulation.
fn record_on_gpu(gl: &mut Gl, surface: &Surface, points: &[[f64; 2]], triangles: impl Iterator<Item = [u32; 3]>) {
    let p = &surface.pos.patches;
    let mut pieces: BTreeMap<(usize, usize), Vec<usize>> = BTreeMap::new();
    for (k, &[u, v]) in points.iter().enumerate() {
        let (Some(a), Some(b)) = (locate(&p.uintervals, u), locate(&p.vintervals, v)) else { return };
        pieces.entry((a, b)).or_default().push(k);
    }
    let template = gl.current_vertex([0.0, 0.0, 0.0, 1.0]);
    let mut renumbered = vec![0u32; points.len()];
    let mut jobs = Vec::with_capacity(pieces.len());
    for ((a, b), members) in pieces {
        let (u, v) = (p.uintervals[a], p.vintervals[b]);
        let mut maps = Vec::new();
        for map in surface.attributes.iter().chain([&surface.pos]) {
            let (Some(target), Some(control)) = (MapTarget::from_enum(map.target), map.on(u, v)) else { continue };
            let slot = target.slot;
            let norm = |x: f64, (x0, x1): (f64, f64)| ((x - x0) / (x1 - x0)) as f32;
            maps.push(MapSample {
                slot,
                uorder: map.patches.uorder,
                vorder: map.patches.vorder,
                points: control.iter().map(|&c| c as f32).collect(),
                us: members.iter().map(|&k| norm(points[k][0], u)).collect(),
                vs: members.iter().map(|&k| norm(points[k][1], v)).collect(),
            });
        }
        let first: usize = jobs.iter().map(MeshJob::len).sum();
        for (n, &k) in members.iter().enumerate() {
            renumbered[k] = (first + n) as u32;
        }
        let nu = members.len();
        jobs.push(MeshJob { maps, auto_normal: gl.eval.auto_normal, template, nu, nv: 1, scattered: true });
    }
    let triangles = triangles.flat_map(|t| t.map(|i| renumbered[i as usize])).collect();
    gl.record_scattered_mesh(jobs, triangles);
}

/// `GLU_OUTLINE_PATCH` of a trimmed surface: the trim loops drawn on the surface.
fn outline_loops(gl: &mut Gl, surface: &Surface, loops: &[TrimLoop]) {
    for l in loops {
        gl.begin(GL_LINE_LOOP);
        for &[u, v] in &l.points {
            if let Some(vertex) = trimmed_vertex(gl, surface, u, v) {
                gl.emit_vertex(vertex);
            }
        }
        gl.end();
    }
}

/// One vertex as GL's evaluators would produce it for GLU's `glEvalCoord2f`: evaluated
/// attributes over the current ones and, with `GL_AUTO_NORMAL`, the unit normal. Evaluated
/// values never become current.
fn trimmed_vertex(gl: &Gl, surface: &Surface, u: f64, v: f64) -> Option<Vertex> {
    let (pos, attributes, k) = surface.view_ref();
    let mut vertex = gl.current_vertex([0.0, 0.0, 0.0, 1.0]);
    for map in attributes {
        let (Some(s), Some(slot)) = (map.eval(u, v), crate::gl::MapTarget::from_enum(map.target).map(|t| t.slot))
        else {
            continue;
        };
        let p = [s.point[0] as f32, s.point[1] as f32, s.point[2] as f32, s.point[3] as f32];
        crate::gl::eval_set_attribute(&mut vertex, slot, p);
    }
    let s = pos.eval(u, v)?;
    if gl.eval.auto_normal {
        vertex.normal = surface_normal(pos, k, u, v, surface.domain());
    }
    let p = [s.point[0] as f32, s.point[1] as f32, s.point[2] as f32, s.point[3] as f32];
    crate::gl::eval_set_attribute(&mut vertex, if k == 4 { Slot::Vertex4 } else { Slot::Vertex3 }, p);
    Some(vertex)
}
