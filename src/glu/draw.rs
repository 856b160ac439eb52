//! Drawing NURBS the way GLU does: Bezier pieces sampled per GLU's tolerance, then either
//! GL evaluator calls (`GLU_NURBS_RENDERER`: `glMap1f`/`glMapGrid1f`/`glEvalMesh1` per curve
//! span, `glMap2f` + `glMapGrid2f` with v reversed + `glEvalMesh2(GL_FILL)` per patch) or
//! callbacks (`GLU_NURBS_TESSELLATOR`). Trimmed surfaces are triangulated in (u, v) by
//! [`crate::tess::trim`] and each vertex evaluated on the exact surface.

use super::callbacks::StripSink;
use super::consts::*;
use super::nurbs::{CurveMap, NurbsObject, SurfaceDef, TrimPiece};
use super::pieces::{CurvePieces, SurfacePatches};
use super::sampling::Sampler;
use crate::gl::consts::*;
use crate::gl::types::GLenum;
use crate::gl::{Gl, MapTarget, Slot};
use crate::math::rational::{cross, normalize, rational_derivative};
use crate::math::{BezierPatches, Scalar};
use crate::tess::{MapView, Row, RowKernel};
use glam::Vec4;

fn slot_of(target: GLenum) -> Option<Slot> {
    MapTarget::from_enum(target).map(|t| t.slot)
}

fn is_position(target: GLenum) -> bool {
    matches!(slot_of(target), Some(Slot::Vertex3 | Slot::Vertex4))
}

/// The callback that receives a map's values in tessellator mode.
fn callback_kind(target: GLenum) -> Option<GLenum> {
    match slot_of(target)? {
        Slot::Color4 | Slot::Index => Some(GLU_NURBS_COLOR),
        Slot::Normal => Some(GLU_NURBS_NORMAL),
        Slot::TexCoord1 | Slot::TexCoord2 | Slot::TexCoord3 | Slot::TexCoord4 => Some(GLU_NURBS_TEXTURE_COORD),
        Slot::Vertex3 | Slot::Vertex4 => Some(GLU_NURBS_VERTEX),
    }
}

/// Callback order per vertex (GLU `inDoEvalCoord`): texture coordinate, colour, normal.
fn attribute_rank(target: GLenum) -> u8 {
    match callback_kind(target) {
        Some(GLU_NURBS_TEXTURE_COORD) => 0,
        Some(GLU_NURBS_COLOR) => 1,
        _ => 2,
    }
}

/// `GLU_CULLING`: true when every control point lies outside one clip plane.
fn culled(obj: &NurbsObject, points: &[f64], k: usize) -> bool {
    if !obj.props.culling {
        return false;
    }
    let m = obj.matrices.projection * obj.matrices.modelview;
    let mut inside_any = [false; 6];
    for p in points.chunks_exact(k) {
        let w = if k == 4 { p[3] } else { 1.0 };
        let c = m * Vec4::new(p[0] as f32, p[1] as f32, p.get(2).copied().unwrap_or(0.0) as f32, w as f32);
        let tests = [c.x >= -c.w, c.x <= c.w, c.y >= -c.w, c.y <= c.w, c.z >= -c.w, c.z <= c.w];
        for (seen, ok) in inside_any.iter_mut().zip(tests) {
            *seen |= ok;
        }
    }
    inside_any.iter().any(|seen| !seen)
}

/// Draws a curve (`gluEndCurve`).
pub(crate) fn draw_curve(gl: &mut Gl, obj: &mut NurbsObject, maps: &[CurveMap]) {
    let Some(position) = maps.iter().rev().find(|m| is_position(m.target)) else {
        return obj.nurbs_error(8);
    };
    if culled(obj, &position.points, position.k) {
        return;
    }
    let Some(pos) = CurvePieces::new(position) else { return obj.nurbs_error(8) };
    let mut all: Vec<CurvePieces> =
        maps.iter().filter(|m| !is_position(m.target)).filter_map(CurvePieces::new).collect();
    all.sort_by_key(|p| attribute_rank(p.target));
    let sampler = Sampler::new(obj.props, &obj.matrices);
    let tessellate = obj.props.nurbs_mode == GLU_NURBS_TESSELLATOR;
    let saved = gl.eval.attrib();
    for (index, &(a, b)) in pos.pieces.intervals.iter().enumerate() {
        let Some(points) = pos.pieces.piece(index) else { continue };
        for (t0, t1, nu) in sampler.curve_segments(points, pos.pieces.dim, pos.pieces.order, b - a) {
            let (r0, r1) = (a + t0 * (b - a), a + t1 * (b - a));
            if tessellate {
                tessellate_curve_span(obj, &all, &pos, (r0, r1), nu);
            } else {
                render_curve_span(gl, &all, &pos, (r0, r1), nu);
            }
        }
    }
    gl.eval.restore(saved);
}

/// `glMap1f` for every map, `glMapGrid1f(nu, r0, r1)`, `glEvalMesh1(GL_LINE, 0, nu)`.
fn render_curve_span(gl: &mut Gl, attributes: &[CurvePieces], pos: &CurvePieces, (r0, r1): (f64, f64), nu: usize) {
    for map in attributes.iter().chain([pos]) {
        let Some(points) = map.on(r0, r1) else { continue };
        let points: Vec<f32> = points.iter().map(|&v| v as f32).collect();
        let (k, order) = (map.pieces.dim as i32, map.pieces.order as i32);
        gl.map1f(map.target, r0 as f32, r1 as f32, k, order, &points);
        gl.enable(map.target);
    }
    gl.map_grid1f(nu as i32, r0 as f32, r1 as f32);
    gl.eval_mesh1(GL_LINE, 0, nu as i32);
}

/// One `GL_LINE_STRIP` of nu + 1 vertices through the callbacks; the vertex is the raw
/// k-vector (not divided by w, as GLU does for curves).
fn tessellate_curve_span(
    obj: &mut NurbsObject,
    attributes: &[CurvePieces],
    pos: &CurvePieces,
    (r0, r1): (f64, f64),
    nu: usize,
) {
    obj.callbacks.begin(GL_LINE_STRIP);
    for i in 0..=nu {
        let u = if i == nu { r1 } else { r0 + i as f64 * (r1 - r0) / nu as f64 };
        for map in attributes.iter().chain([pos]) {
            let (Some(value), Some(kind)) = (map.eval(u), callback_kind(map.target)) else { continue };
            let v: Vec<f32> = value[..map.pieces.dim].iter().map(|&c| c as f32).collect();
            obj.callbacks.attribute(kind, &v);
        }
    }
    obj.callbacks.end();
}

/// A patch's parameter ranges ((u0, u1), (v0, v1)) and its grid (nu, nv) segments.
pub(crate) type PatchGrid = ((f64, f64), (f64, f64), (usize, usize));

/// Everything needed to draw a surface: the position map's patches and the other maps'.
pub(crate) struct Surface {
    pub pos: SurfacePatches,
    pub attributes: Vec<SurfacePatches>,
    pub k: usize,
}

impl Surface {
    fn new(obj: &mut NurbsObject, def: &SurfaceDef) -> Option<Self> {
        let Some(position) = def.maps.iter().rev().find(|m| is_position(m.target)) else {
            obj.nurbs_error(8);
            return None;
        };
        let pos = SurfacePatches::new(position)?;
        let mut attributes: Vec<SurfacePatches> =
            def.maps.iter().filter(|m| !is_position(m.target)).filter_map(SurfacePatches::new).collect();
        attributes.sort_by_key(|p| attribute_rank(p.target));
        Some(Self { pos, attributes, k: position.k })
    }

    pub fn domain(&self) -> [f64; 4] {
        let p = &self.pos.patches;
        let (u, v) = (&p.uintervals, &p.vintervals);
        [u[0].0, u[u.len() - 1].1, v[0].0, v[v.len() - 1].1]
    }

    /// Every patch: ((u0, u1), (v0, v1), (nu, nv)).
    pub fn patches(&self, sampler: &Sampler) -> Vec<PatchGrid> {
        let p = &self.pos.patches;
        let mut out = Vec::new();
        for (a, &(u0, u1)) in p.uintervals.iter().enumerate() {
            for (b, &(v0, v1)) in p.vintervals.iter().enumerate() {
                let Some(points) = p.patch(a, b) else { continue };
                let n = sampler.patch_segments(points, self.k, (p.uorder, p.vorder), (u1 - u0, v1 - v0));
                out.push(((u0, u1), (v0, v1), n));
            }
        }
        out
    }
}

/// Draws a surface (`gluEndSurface`).
pub(crate) fn draw_surface(gl: &mut Gl, obj: &mut NurbsObject, def: &SurfaceDef) {
    if def.maps.is_empty() {
        return; // GLU ends an empty surface silently.
    }
    let Some(position) = def.maps.iter().rev().find(|m| is_position(m.target)) else {
        return obj.nurbs_error(8);
    };
    if culled(obj, &position.points, position.k) {
        return;
    }
    let Some(surface) = Surface::new(obj, def) else { return };
    let sampler = Sampler::new(obj.props, &obj.matrices);
    let tessellate = obj.props.nurbs_mode == GLU_NURBS_TESSELLATOR;
    if !def.loops.is_empty() {
        return super::trimmed::draw_trimmed(gl, obj, &surface, &def.loops, &sampler, tessellate);
    }
    let mut patches = surface.patches(&sampler);
    // A patch sampled beyond the façade's mesh limit (a weight near zero under path-length
    // sampling asks for 2^14 segments a side) would fail in glEvalMesh2 with a GL error, or
    // allocate gigabytes in tessellator mode: GLU's own convention is to report
    // GLU_OUT_OF_MEMORY through the error callback. The other patches are drawn.
    let before = patches.len();
    patches.retain(|patch| grid_size(patch) <= crate::tess::MAX_MESH_VERTICES);
    if patches.len() < before {
        obj.callbacks.error(GLU_OUT_OF_MEMORY);
    }
    if tessellate {
        if obj.callbacks.sinks().is_some() {
            return tessellate_patches_in_parallel(obj, &surface, &patches);
        }
        for (u, v, n) in patches {
            tessellate_patch(obj, &surface, u, v, n);
        }
        return;
    }
    let (saved_eval, saved_mode) = (gl.eval.attrib(), gl.raster.polygon_mode);
    gl.polygon_mode(GL_FRONT_AND_BACK, GL_FILL);
    for (u, v, n) in patches {
        match obj.props.display_mode {
            GLU_OUTLINE_PATCH => outline_patch(gl, &surface, u, v, n),
            // GLU draws grid blocks as quad outlines ("wireframequads"): the mesh's lines.
            GLU_OUTLINE_POLYGON => render_patch(gl, &surface, u, v, n, GL_LINE),
            _ => render_patch(gl, &surface, u, v, n, GL_FILL),
        }
    }
    gl.eval.restore(saved_eval);
    gl.restore_polygon_mode(saved_mode);
}

fn load_patch(gl: &mut Gl, surface: &Surface, u: (f64, f64), v: (f64, f64)) {
    for map in surface.attributes.iter().chain([&surface.pos]) {
        let Some(points) = map.on(u, v) else { continue };
        let points: Vec<f32> = points.iter().map(|&c| c as f32).collect();
        let p = &map.patches;
        let (k, uo, vo) = (p.dim as i32, p.uorder as i32, p.vorder as i32);
        gl.map2f(map.target, u.0 as f32, u.1 as f32, vo * k, uo, v.0 as f32, v.1 as f32, k, vo, &points);
        gl.enable(map.target);
    }
}

/// `glMap2f` per map, then `glMapGrid2f(nu, u0, u1, nv, v1, v0)` — v reversed so that
/// `glEvalMesh2`'s clockwise strips come out counter-clockwise (GLU `slicer.cc`) — and
/// `glEvalMesh2(mode)`: `GL_FILL`, or `GL_LINE` for `GLU_OUTLINE_POLYGON`.
fn render_patch(gl: &mut Gl, surface: &Surface, u: (f64, f64), v: (f64, f64), (nu, nv): (usize, usize), mode: GLenum) {
    load_patch(gl, surface, u, v);
    gl.map_grid2f(nu as i32, u.0 as f32, u.1 as f32, nv as i32, v.1 as f32, v.0 as f32);
    gl.eval_mesh2(mode, 0, nu as i32, 0, nv as i32);
}

/// `GLU_OUTLINE_PATCH`: the patch boundary as line strips along its four edges.
fn outline_patch(gl: &mut Gl, surface: &Surface, u: (f64, f64), v: (f64, f64), (nu, nv): (usize, usize)) {
    load_patch(gl, surface, u, v);
    let lerp = |r: (f64, f64), i: usize, n: usize| if i == n { r.1 } else { r.0 + (r.1 - r.0) * i as f64 / n as f64 };
    let edges: [Vec<(f64, f64)>; 4] = [
        (0..=nu).map(|i| (lerp(u, i, nu), v.0)).collect(),
        (0..=nv).map(|j| (u.1, lerp(v, j, nv))).collect(),
        (0..=nu).map(|i| (lerp((u.1, u.0), i, nu), v.1)).collect(),
        (0..=nv).map(|j| (u.0, lerp((v.1, v.0), j, nv))).collect(),
    ];
    for edge in edges {
        gl.begin(GL_LINE_STRIP);
        for (s, t) in edge {
            gl.eval_coord2f(s as f32, t as f32);
        }
        gl.end();
    }
}

/// The grid lines of a patch: nu + 1 values across u, nv + 1 across v, the last exactly the end.
fn patch_lines(u: (f64, f64), v: (f64, f64), (nu, nv): (usize, usize)) -> (Vec<f64>, Vec<f64>) {
    let at = |r: (f64, f64), i: usize, n: usize| if i == n { r.1 } else { r.0 + (r.1 - r.0) * i as f64 / n as f64 };
    ((0..=nu).map(|i| at(u, i, nu)).collect(), (0..=nv).map(|j| at(v, j, nv)).collect())
}

/// Grid points per batch of patches: small enough that evaluating the next batch overlaps
/// issuing this one's callbacks, large enough to amortise the hand-over.
const BATCH_POINTS: usize = 1 << 16;

fn grid_size(&(_, _, (nu, nv)): &PatchGrid) -> usize {
    (nu + 1).saturating_mul(nv + 1)
}

/// Consecutive runs of patches of at most [`BATCH_POINTS`] grid points (at least one patch each).
fn batches(patches: &[PatchGrid]) -> Vec<&[PatchGrid]> {
    let mut out = Vec::new();
    let mut rest = patches;
    while !rest.is_empty() {
        let mut take = 1;
        let mut points = grid_size(&rest[0]);
        while take < rest.len() && points.saturating_add(grid_size(&rest[take])) <= BATCH_POINTS {
            points += grid_size(&rest[take]);
            take += 1;
        }
        let (batch, tail) = rest.split_at(take);
        out.push(batch);
        rest = tail;
    }
    out
}

/// Evaluates a batch's grids into `out` (resized), in parallel; whether each succeeded.
fn evaluate_batch(surface: &Surface, batch: &[PatchGrid], out: &mut Vec<[f32; 5]>) -> Vec<bool> {
    use rayon::prelude::*;
    // Every entry is overwritten (a patch that fails is redone point by point): no zeroing.
    let size = batch.iter().map(grid_size).sum();
    if out.len() < size {
        out.resize(size, [0.0; 5]);
    }
    out.truncate(size);
    let mut chunks = Vec::with_capacity(batch.len());
    let mut free = out.as_mut_slice();
    for patch in batch {
        let (chunk, after) = free.split_at_mut(grid_size(patch));
        chunks.push((patch, chunk));
        free = after;
    }
    chunks
        .into_par_iter()
        .map(|(&(u, v, n), chunk)| {
            let (us, vs) = patch_lines(u, v, n);
            grid_vertices_into(&surface.pos, surface.k, &us, &vs, chunk).is_some()
        })
        .collect()
}

/// [`tessellate_patch`] for every patch when only begin, vertex and end callbacks are set. The
/// grids are evaluated a batch ahead on rayon's workers while this thread issues the previous
/// batch's strips, in patch order as GLU issues them (the callbacks need not be `Send`). The two
/// buffers are kept in the object and reused.
fn tessellate_patches_in_parallel(obj: &mut NurbsObject, surface: &Surface, patches: &[PatchGrid]) {
    let mut current = std::mem::take(&mut obj.vertex_scratch[0]);
    let mut next = std::mem::take(&mut obj.vertex_scratch[1]);
    let batches = batches(patches);
    let mut ok = match batches.first() {
        Some(first) => evaluate_batch(surface, first, &mut current),
        None => Vec::new(),
    };
    for (k, batch) in batches.iter().enumerate() {
        let mut next_ok = Vec::new();
        rayon::in_place_scope(|scope| {
            if let Some(following) = batches.get(k + 1) {
                let (next, next_ok) = (&mut next, &mut next_ok);
                scope.spawn(move |_| *next_ok = evaluate_batch(surface, following, next));
            }
            let mut start = 0;
            for (patch, &done) in batch.iter().zip(&ok) {
                let &(u, v, (nu, nv)) = patch;
                let grid = &current[start..start + grid_size(patch)];
                start += grid_size(patch);
                match obj.callbacks.sinks() {
                    Some(mut sinks) if done => {
                        if let Some(mut plain) = sinks.plain() {
                            quad_strips(&mut plain, grid, nu, nv);
                        } else {
                            quad_strips(&mut sinks, grid, nu, nv);
                        }
                    }
                    _ => tessellate_patch(obj, surface, u, v, (nu, nv)),
                }
            }
        });
        std::mem::swap(&mut current, &mut next);
        ok = next_ok;
    }
    obj.vertex_scratch = [current, next];
}

/// The grid blocks of one patch as `GL_QUAD_STRIP`s through the callbacks (GLU `mapmesh2f`).
/// Positions come from one grid evaluation of the patch's Bezier piece (each point once, though
/// the strips issue interior points twice); other maps and normals are evaluated per vertex.
fn tessellate_patch(obj: &mut NurbsObject, surface: &Surface, u: (f64, f64), v: (f64, f64), (nu, nv): (usize, usize)) {
    let (us, vs) = patch_lines(u, v, (nu, nv));
    let grid = grid_vertices(&surface.pos, surface.k, &us, &vs);
    let per_vertex = !surface.attributes.is_empty() || obj.callbacks.wants_normals();
    let emit = |obj: &mut NurbsObject, i: usize, j: usize| {
        if per_vertex {
            emit_attributes(obj, surface.view_ref(), us[i], vs[j]);
        }
        match &grid {
            Some(g) => obj.callbacks.attribute(GLU_NURBS_VERTEX, &g[j * (nu + 1) + i]),
            None => emit_position(obj, &surface.pos, surface.k, us[i], vs[j]),
        }
    };
    if nu >= nv {
        for i in 0..nu {
            obj.callbacks.begin(GL_QUAD_STRIP);
            for j in (0..=nv).rev() {
                emit(obj, i, j);
                emit(obj, i + 1, j);
            }
            obj.callbacks.end();
        }
    } else {
        for j in 0..nv {
            obj.callbacks.begin(GL_QUAD_STRIP);
            for i in (0..=nu).rev() {
                emit(obj, i, j + 1);
                emit(obj, i, j);
            }
            obj.callbacks.end();
        }
    }
}

/// [`tessellate_patch`]'s strips when only begin, vertex and end callbacks are registered:
/// the same primitives, one indirect call per vertex.
fn quad_strips(sinks: &mut impl StripSink, g: &[[f32; 5]], nu: usize, nv: usize) {
    let at = |i: usize, j: usize| &g[j * (nu + 1) + i];
    if nu >= nv {
        for i in 0..nu {
            sinks.begin(GL_QUAD_STRIP);
            for j in (0..=nv).rev() {
                sinks.vertex(at(i, j));
                sinks.vertex(at(i + 1, j));
            }
            sinks.end();
        }
    } else {
        for j in 0..nv {
            sinks.begin(GL_QUAD_STRIP);
            for i in (0..=nu).rev() {
                sinks.vertex(at(i, j + 1));
                sinks.vertex(at(i, j));
            }
            sinks.end();
        }
    }
}

/// The vertex-callback data (x, y, z divided by w, then u, v) of every point of the grid
/// `us` × `vs` (v outer), all inside one Bezier piece of `pos`, evaluated on the grid path.
fn grid_vertices(pos: &SurfacePatches, k: usize, us: &[f64], vs: &[f64]) -> Option<Vec<[f32; 5]>> {
    let mut out = vec![[0.0; 5]; us.len() * vs.len()];
    grid_vertices_into(pos, k, us, vs, &mut out)?;
    Some(out)
}

/// [`grid_vertices`] into `out` (`us.len() * vs.len()` entries, v outer).
///
/// Evaluated in f32, as GLU's own evaluator does (libnurbs `REAL` is `float`) and as the
/// callbacks receive it: four points per SSE register instead of two. The vertices stay within
/// an f32 ulp of the f64 evaluation (`tessellator_vertices_lie_on_the_surface...` in the tests:
/// worst 4.4e-7 on a net ten units across), and the untrimmed case runs about 10% faster, its
/// evaluation sharing two cores with the callbacks.
fn grid_vertices_into(pos: &SurfacePatches, k: usize, us: &[f64], vs: &[f64], out: &mut [[f32; 5]]) -> Option<()> {
    let p = &pos.patches;
    let mid = |r: &[f64]| 0.5 * (r[0] + r[r.len() - 1]);
    let a = super::pieces::locate(&p.uintervals, mid(us))?;
    let b = super::pieces::locate(&p.vintervals, mid(vs))?;
    let net: Vec<f32> = p.patch(a, b)?.iter().map(|&c| c as f32).collect();
    let kernel = piece_kernel(p, (a, b), &net, us, vs)?;
    let mut row = Row::default();
    let n = us.len();
    if out.len() != n * vs.len() {
        return None;
    }
    for ((j, &v), line) in vs.iter().enumerate().zip(out.chunks_exact_mut(n)) {
        kernel.eval_row(j, &mut row);
        vertex_row(&row, k, us, v, line, |data| data);
    }
    Some(())
}

/// The row kernel of Bezier piece (a, b) of `p` (its control points `net`, in the kernel's
/// precision) over the lines `us` × `vs`, given in the surface's parameters.
pub(super) fn piece_kernel<'a, S: Scalar>(
    p: &BezierPatches<f64>,
    (a, b): (usize, usize),
    net: &'a [S],
    us: &[f64],
    vs: &[f64],
) -> Option<RowKernel<'a, S>> {
    let normalised = |lines: &[f64], (lo, hi): (f64, f64)| -> Vec<S> {
        lines.iter().map(|&x| S::from_f64((x - lo) / (hi - lo))).collect()
    };
    let (su, sv) = (normalised(us, p.uintervals[a]), normalised(vs, p.vintervals[b]));
    let view = MapView { dim: p.dim, uorder: p.uorder, vorder: p.vorder, points: net };
    RowKernel::new(view, &su, &sv, false)
}

/// A row of points as vertex-callback data, `wrap`ped into `out`: x, y, z (divided by w when
/// `k` is 4: only then, as a division per coordinate costs more than the rest of the point's
/// work), then the point's u (from `us`) and `v`.
pub(super) fn vertex_row<S: Scalar, T>(
    row: &Row<S>,
    k: usize,
    us: &[f64],
    v: f64,
    out: &mut [T],
    wrap: impl Fn([f32; 5]) -> T,
) {
    let [x, y, z, w] = &row.point;
    let xyz = x.iter().zip(y).zip(z).map(|((x, y), z)| [*x, *y, *z]);
    let out = out.iter_mut().zip(us);
    let (f, v) = (|c: S| c.to_f64() as f32, v as f32);
    if k == 4 {
        for ((o, &u), ([x, y, z], &w)) in out.zip(xyz.zip(w)) {
            *o = wrap([f(x / w), f(y / w), f(z / w), u as f32, v]);
        }
    } else {
        for ((o, &u), [x, y, z]) in out.zip(xyz) {
            *o = wrap([f(x), f(y), f(z), u as f32, v]);
        }
    }
}

impl Surface {
    pub fn view_ref(&self) -> (&SurfacePatches, &[SurfacePatches], usize) {
        (&self.pos, &self.attributes, self.k)
    }
}

/// The unit normal of the position map at (u, v): du × dv with the rational correction, zero
/// left zero. A vanishing partial is re-evaluated slightly inside the domain (GLU's
/// `AVOID_ZERO_NORMAL`).
pub(crate) fn surface_normal(pos: &SurfacePatches, k: usize, u: f64, v: f64, domain: [f64; 4]) -> [f32; 3] {
    let partials = |u: f64, v: f64| pos.eval(u, v);
    let Some(mut s) = partials(u, v) else { return [0.0; 3] };
    let tiny = |d: [f64; 4]| d.iter().all(|c| c.abs() <= 1e-6);
    if tiny(s.du) || tiny(s.dv) {
        let nudge =
            |x: f64, lo: f64, hi: f64| if x - lo < hi - x { x + 0.001 * (hi - lo) } else { x - 0.001 * (hi - lo) };
        if let Some(n) = partials(nudge(u, domain[0], domain[1]), nudge(v, domain[2], domain[3])) {
            if tiny(s.du) {
                s.du = n.du;
            }
            if tiny(s.dv) {
                s.dv = n.dv;
            }
        }
    }
    let (a, b) = if k == 4 {
        (rational_derivative(s.point, s.du), rational_derivative(s.point, s.dv))
    } else {
        ([s.du[0], s.du[1], s.du[2]], [s.dv[0], s.dv[1], s.dv[2]])
    };
    normalize(cross(a, b)).map(|c| c as f32)
}

/// The attribute maps' values and the normal (if wanted) of the vertex at (u, v).
pub(crate) fn emit_attributes(
    obj: &mut NurbsObject,
    (pos, attributes, k): (&SurfacePatches, &[SurfacePatches], usize),
    u: f64,
    v: f64,
) {
    let mut has_normal_map = false;
    for map in attributes {
        let (Some(s), Some(kind)) = (map.eval(u, v), callback_kind(map.target)) else { continue };
        has_normal_map |= kind == GLU_NURBS_NORMAL;
        let values: Vec<f32> = s.point[..map.patches.dim].iter().map(|&c| c as f32).collect();
        obj.callbacks.attribute(kind, &values);
    }
    if !has_normal_map && obj.callbacks.wants_normals() {
        let p = &pos.patches;
        let domain = [
            p.uintervals[0].0,
            p.uintervals[p.uintervals.len() - 1].1,
            p.vintervals[0].0,
            p.vintervals[p.vintervals.len() - 1].1,
        ];
        obj.callbacks.attribute(GLU_NURBS_NORMAL, &surface_normal(pos, k, u, v, domain));
    }
}

/// The vertex callback at (u, v): (x, y, z) divided by w, then u, v.
fn emit_position(obj: &mut NurbsObject, pos: &SurfacePatches, k: usize, u: f64, v: f64) {
    let Some(s) = pos.eval(u, v) else { return };
    let w = if k == 4 { s.point[3] } else { 1.0 };
    let vertex = [(s.point[0] / w) as f32, (s.point[1] / w) as f32, (s.point[2] / w) as f32, u as f32, v as f32];
    obj.callbacks.attribute(GLU_NURBS_VERTEX, &vertex);
}

/// Loops of trim pieces as (u, v) polylines; NURBS trim curves are sampled on their Bezier
/// pieces at `per_piece` + 1 points each (TRIM_3 divided by w).
pub(crate) fn trim_polylines(
    pieces: &[TrimPiece],
    segments: impl Fn(&[f64], usize, usize) -> usize,
) -> Vec<Vec<[f64; 2]>> {
    pieces
        .iter()
        .map(|piece| match piece {
            TrimPiece::Pwl(points) => points.clone(),
            TrimPiece::Curve(map) => {
                let Some(c) = CurvePieces::new(map) else { return Vec::new() };
                let mut out: Vec<[f64; 2]> = Vec::new();
                for (index, &(a, b)) in c.pieces.intervals.iter().enumerate() {
                    let Some(points) = c.pieces.piece(index) else { continue };
                    let n = segments(points, c.pieces.dim, c.pieces.order).max(1);
                    let start = usize::from(!out.is_empty());
                    for i in start..=n {
                        let u = if i == n { b } else { a + (b - a) * i as f64 / n as f64 };
                        if let Some(p) = c.eval(u) {
                            out.push(if map.k == 3 { [p[0] / p[2], p[1] / p[2]] } else { [p[0], p[1]] });
                        }
                    }
                }
                out
            }
        })
        .collect()
}
