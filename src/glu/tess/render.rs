//! Handing the result to the callbacks (GLU's `libtess/render.c`): the triangulated mesh as
//! triangle fans, strips and a final list of lone triangles; the boundary as line loops; and
//! the quick path for a single contour that is a fan from its first vertex.
//!
//! The grouping is libtess's greedy one: for each inside face not yet drawn, in the mesh's
//! face order, try the three fans and three strips through it and draw the largest; ties go
//! to the first tried. With edge flags wanted, every triangle is drawn alone, with the flag
//! set before the first vertex of each run of boundary or interior edges.

use super::callbacks::TessData;
use super::mesh::{Mesh, F_HEAD, NIL};
use crate::gl::consts::*;
use crate::gl::types::GLenum;
use crate::glu::consts::*;

/// Where primitives go: the begin, edge-flag, vertex and end callbacks.
pub(crate) trait Sink {
    fn begin(&mut self, prim: GLenum);
    fn edge_flag(&mut self, boundary: bool);
    fn vertex(&mut self, data: Option<&TessData>);
    fn end(&mut self);
}

/// The primitive chosen for a face group (`FaceCount`).
#[derive(Clone, Copy)]
enum Group {
    Triangle,
    Fan,
    Strip,
}

/// A candidate primitive: triangles it covers, the edge it starts from, its kind.
#[derive(Clone, Copy)]
struct Candidate {
    size: usize,
    start: usize,
    kind: Group,
}

/// The faces marked while measuring a candidate, to unmark afterwards (libtess's trail).
struct Trail<'m> {
    m: &'m mut Mesh,
    faces: Vec<usize>,
}

impl Trail<'_> {
    /// Drawn already, or not part of the polygon (`Marked`).
    fn marked(&self, f: usize) -> bool {
        f == NIL || !self.m.f[f].inside || self.m.f[f].marked
    }

    fn add(&mut self, f: usize) {
        self.m.f[f].marked = true;
        self.faces.push(f);
    }
}

impl Drop for Trail<'_> {
    fn drop(&mut self) {
        for &f in &self.faces {
            self.m.f[f].marked = false;
        }
    }
}

fn marked(m: &Mesh, f: usize) -> bool {
    f == NIL || !m.f[f].inside || m.f[f].marked
}

/// A way of measuring a candidate primitive from an edge.
type Measure = fn(&mut Mesh, usize) -> Candidate;

/// The largest fan around `e_orig.org` through `e_orig`'s face (`MaximumFan`).
fn maximum_fan(m: &mut Mesh, e_orig: usize) -> Candidate {
    let mut t = Trail { m, faces: Vec::new() };
    let mut size = 0;
    let mut e = e_orig;
    while !t.marked(t.m.lface(e)) {
        t.add(t.m.lface(e));
        size += 1;
        e = t.m.onext(e);
    }
    e = e_orig;
    while !t.marked(t.m.rface(e)) {
        t.add(t.m.rface(e));
        size += 1;
        e = t.m.oprev(e);
    }
    Candidate { size, start: e, kind: Group::Fan }
}

/// The largest strip through `e_orig`'s face starting with its edge; a strip needs an even
/// count on the side it starts from, so one side may be shortened (`MaximumStrip`).
fn maximum_strip(m: &mut Mesh, e_orig: usize) -> Candidate {
    let mut t = Trail { m, faces: Vec::new() };
    let (mut tail, mut head) = (0usize, 0usize);
    let mut e = e_orig;
    while !t.marked(t.m.lface(e)) {
        t.add(t.m.lface(e));
        tail += 1;
        e = t.m.dprev(e);
        if t.marked(t.m.lface(e)) {
            break;
        }
        t.add(t.m.lface(e));
        tail += 1;
        e = t.m.onext(e);
    }
    let e_tail = e;
    e = e_orig;
    while !t.marked(t.m.rface(e)) {
        t.add(t.m.rface(e));
        head += 1;
        e = t.m.oprev(e);
        if t.marked(t.m.rface(e)) {
            break;
        }
        t.add(t.m.rface(e));
        head += 1;
        e = t.m.dnext(e);
    }
    let e_head = e;
    let mut size = tail + head;
    let start = if tail % 2 == 0 {
        e_tail ^ 1
    } else if head % 2 == 0 {
        e_head
    } else {
        size -= 1;
        t.m.onext(e_head)
    };
    Candidate { size, start, kind: Group::Strip }
}

/// Draws the mesh's inside faces as fans, strips and lone triangles (`__gl_renderMesh`).
pub(crate) fn render_mesh(m: &mut Mesh, flag_boundary: bool, sink: &mut dyn Sink) {
    let mut lonely = Vec::new();
    let mut f = m.f[F_HEAD].next;
    while f != F_HEAD {
        m.f[f].marked = false;
        f = m.f[f].next;
    }
    f = m.f[F_HEAD].next;
    while f != F_HEAD {
        if m.f[f].inside && !m.f[f].marked {
            render_maximum_face_group(m, f, flag_boundary, &mut lonely, sink);
        }
        f = m.f[f].next;
    }
    if !lonely.is_empty() {
        render_lonely_triangles(m, &lonely, flag_boundary, sink);
    }
}

/// Draws the largest fan or strip through `f`, or queues `f` as a lone triangle
/// (`RenderMaximumFaceGroup`).
fn render_maximum_face_group(
    m: &mut Mesh,
    f: usize,
    flag_boundary: bool,
    lonely: &mut Vec<usize>,
    sink: &mut dyn Sink,
) {
    let e = m.f[f].an_edge;
    let mut best = Candidate { size: 1, start: e, kind: Group::Triangle };
    if !flag_boundary {
        let (lnext, lprev) = (m.lnext(e), m.lprev(e));
        let tries: [(Measure, usize); 6] = [
            (maximum_fan, e),
            (maximum_fan, lnext),
            (maximum_fan, lprev),
            (maximum_strip, e),
            (maximum_strip, lnext),
            (maximum_strip, lprev),
        ];
        for (measure, start) in tries {
            let c = measure(m, start);
            if c.size > best.size {
                best = c;
            }
        }
    }
    match best.kind {
        Group::Triangle => {
            let face = m.lface(best.start);
            m.f[face].marked = true;
            lonely.push(face);
        }
        Group::Fan => render_fan(m, best.start, sink),
        Group::Strip => render_strip(m, best.start, sink),
    }
}

/// All lone triangles in one `GL_TRIANGLES`, newest first as libtess's list is a stack
/// (`RenderLonelyTriangles`).
fn render_lonely_triangles(m: &Mesh, lonely: &[usize], flag_boundary: bool, sink: &mut dyn Sink) {
    let mut edge_state: Option<bool> = None;
    sink.begin(GL_TRIANGLES);
    for &f in lonely.iter().rev() {
        let start = m.f[f].an_edge;
        let mut e = start;
        loop {
            if flag_boundary {
                let boundary = !m.inside(m.rface(e));
                if edge_state != Some(boundary) {
                    edge_state = Some(boundary);
                    sink.edge_flag(boundary);
                }
            }
            sink.vertex(m.v[m.org(e)].data.as_ref());
            e = m.lnext(e);
            if e == start {
                break;
            }
        }
    }
    sink.end();
}

/// A fan from edge `e` (`RenderFan`).
fn render_fan(m: &mut Mesh, mut e: usize, sink: &mut dyn Sink) {
    sink.begin(GL_TRIANGLE_FAN);
    sink.vertex(m.v[m.org(e)].data.as_ref());
    sink.vertex(m.v[m.dst(e)].data.as_ref());
    while !marked(m, m.lface(e)) {
        let f = m.lface(e);
        m.f[f].marked = true;
        e = m.onext(e);
        sink.vertex(m.v[m.dst(e)].data.as_ref());
    }
    sink.end();
}

/// A strip from edge `e` (`RenderStrip`).
fn render_strip(m: &mut Mesh, mut e: usize, sink: &mut dyn Sink) {
    sink.begin(GL_TRIANGLE_STRIP);
    sink.vertex(m.v[m.org(e)].data.as_ref());
    sink.vertex(m.v[m.dst(e)].data.as_ref());
    while !marked(m, m.lface(e)) {
        let f = m.lface(e);
        m.f[f].marked = true;
        e = m.dprev(e);
        sink.vertex(m.v[m.org(e)].data.as_ref());
        if marked(m, m.lface(e)) {
            break;
        }
        let f = m.lface(e);
        m.f[f].marked = true;
        e = m.onext(e);
        sink.vertex(m.v[m.dst(e)].data.as_ref());
    }
    sink.end();
}

/// One line loop per inside face (`__gl_renderBoundary`).
pub(crate) fn render_boundary(m: &Mesh, sink: &mut dyn Sink) {
    let mut f = m.f[F_HEAD].next;
    while f != F_HEAD {
        if m.f[f].inside {
            sink.begin(GL_LINE_LOOP);
            let start = m.f[f].an_edge;
            let mut e = start;
            loop {
                sink.vertex(m.v[m.org(e)].data.as_ref());
                e = m.lnext(e);
                if e == start {
                    break;
                }
            }
            sink.end();
        }
        f = m.f[f].next;
    }
}

/// A vertex of a single contour kept for the quick path (`CachedVertex`).
#[derive(Clone)]
pub(crate) struct CachedVertex {
    pub coords: [f64; 3],
    pub data: Option<TessData>,
}

/// The fan triangles' orientations disagree (`SIGN_INCONSISTENT`).
const INCONSISTENT: i32 = 2;

/// The normal of the fan from the first vertex, back-facing triangles reversed so that a
/// self-intersecting contour still gets a sensible one (`ComputeNormal` of `render.c`).
fn fan_normal(cache: &[CachedVertex]) -> [f64; 3] {
    let mut norm = [0.0; 3];
    fan_walk(cache, |n| {
        let dot = n[0] * norm[0] + n[1] * norm[1] + n[2] * norm[2];
        let s = if dot >= 0.0 { 1.0 } else { -1.0 };
        for k in 0..3 {
            norm[k] += s * n[k];
        }
        true
    });
    norm
}

/// Whether every fan triangle faces the same way about `norm`: 1 all front, −1 all back,
/// 0 all degenerate, [`INCONSISTENT`] otherwise.
fn fan_sign(cache: &[CachedVertex], norm: [f64; 3]) -> i32 {
    let mut sign = 0;
    let consistent = fan_walk(cache, |n| {
        let dot = n[0] * norm[0] + n[1] * norm[1] + n[2] * norm[2];
        if dot > 0.0 {
            if sign < 0 {
                return false;
            }
            sign = 1;
        } else if dot < 0.0 {
            if sign > 0 {
                return false;
            }
            sign = -1;
        }
        true
    });
    if consistent {
        sign
    } else {
        INCONSISTENT
    }
}

/// Calls `f` with each fan triangle's cross product `(vp − v0) × (vc − v0)`, stopping when
/// it returns false; whether it ran to the end.
fn fan_walk(cache: &[CachedVertex], mut f: impl FnMut([f64; 3]) -> bool) -> bool {
    let v0 = cache[0].coords;
    let d = |c: [f64; 3]| [c[0] - v0[0], c[1] - v0[1], c[2] - v0[2]];
    let mut c = d(cache[1].coords);
    for v in &cache[2..] {
        let p = c;
        c = d(v.coords);
        let n = [p[1] * c[2] - p[2] * c[1], p[2] * c[0] - p[0] * c[2], p[0] * c[1] - p[1] * c[0]];
        if !f(n) {
            return false;
        }
    }
    true
}

/// Whether the fan's triangles, all facing one way, turn less than once around the first
/// vertex (and the contour does not come back to it). GLU does not ask: a contour that winds twice around its first vertex (a
/// pentagram seen from a tip, say) comes out of GLU's quick path as overlapping triangles,
/// covering the twice-wound region twice under every rule (or not at all with
/// `GLU_TESS_WINDING_ABS_GEQ_TWO`). gleval sends such a contour through the sweep instead,
/// the one place it departs from GLU's output on purpose.
fn fan_winds_once(cache: &[CachedVertex]) -> bool {
    let v0 = cache[0].coords;
    let d = |c: [f64; 3]| [c[0] - v0[0], c[1] - v0[1], c[2] - v0[2]];
    // A contour that comes back to its first vertex is two loops around it, whose sectors
    // may overlap however small their sum: the sweep decides.
    let last = cache.len() - 1;
    if cache[2..last].iter().any(|v| v.coords == v0) {
        return false;
    }
    let mut total = 0.0;
    for w in cache[1..].windows(2) {
        let (p, c) = (d(w[0].coords), d(w[1].coords));
        let n = [p[1] * c[2] - p[2] * c[1], p[2] * c[0] - p[0] * c[2], p[0] * c[1] - p[1] * c[0]];
        let sin = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
        total += sin.atan2(p[0] * c[0] + p[1] * c[1] + p[2] * c[2]);
    }
    // NaN (a NaN coordinate) compares false: such a contour keeps GLU's path.
    total.is_nan() || total < std::f64::consts::TAU * (1.0 - 1e-9)
}

/// Draws a single contour as one fan (or triangle, or line loop) from its first vertex when
/// every fan triangle faces the same way; false when it cannot (`__gl_renderCache`).
pub(crate) fn render_cache(
    cache: &[CachedVertex],
    normal: [f64; 3],
    rule: GLenum,
    boundary_only: bool,
    sink: &mut dyn Sink,
) -> bool {
    if cache.len() < 3 {
        return true;
    }
    let norm = if normal == [0.0; 3] { fan_normal(cache) } else { normal };
    let sign = fan_sign(cache, norm);
    if sign == INCONSISTENT {
        return false;
    }
    if sign == 0 {
        return true;
    }
    if !fan_winds_once(cache) {
        return false;
    }
    match rule {
        GLU_TESS_WINDING_POSITIVE if sign < 0 => return true,
        GLU_TESS_WINDING_NEGATIVE if sign > 0 => return true,
        GLU_TESS_WINDING_ABS_GEQ_TWO => return true,
        _ => {}
    }
    let prim = if boundary_only {
        GL_LINE_LOOP
    } else if cache.len() > 3 {
        GL_TRIANGLE_FAN
    } else {
        GL_TRIANGLES
    };
    sink.begin(prim);
    sink.vertex(cache[0].data.as_ref());
    if sign > 0 {
        cache[1..].iter().for_each(|v| sink.vertex(v.data.as_ref()));
    } else {
        cache[1..].iter().rev().for_each(|v| sink.vertex(v.data.as_ref()));
    }
    sink.end();
    true
}
