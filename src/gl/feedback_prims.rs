//! The primitives feedback and selection report (GL 1.1 §5.2–5.3): what reaches the
//! rasteriser after the vertex stage, as Mesa 22.3's draw module hands it to its feedback and
//! selection stages (`draw_pipe_clip.c`, `draw_pipe_cull.c`, `draw_pipe_unfilled.c`,
//! `draw_pt_decompose.h`; measured in `tests/reference/calls/cases/feedback_full.calls`):
//!
//! - vertices are lit (the lit, clamped colour of the polygon's face) and transformed;
//! - points outside the view volume or a clip plane are dropped; lines and polygons are
//!   clipped, attributes interpolated in clip space;
//! - polygons are split into triangles (strips and fans as the filled feedback reports them,
//!   a quad as (v0, v1, v3), (v1, v2, v3), a polygon as (vᵢ₊₁, vᵢ₊₂, v0)), culled by their
//!   window-space orientation, and drawn in their face's polygon mode: filled as polygon
//!   tokens, outlined as line tokens (each triangle's visible edges from its last vertex:
//!   v2 → v0, v0 → v1, v1 → v2, the first line of a primitive a `GL_LINE_RESET_TOKEN`), or as
//!   point tokens at the vertices that start visible edges. A vertex's false edge flag hides
//!   the edge it starts (in every polygon primitive, as Mesa); the diagonals a split adds are
//!   never shown;
//! - a clipped triangle becomes the fan (Lᵢ₋₁, Lᵢ, L0) of its clipped outline L, whose new
//!   edges along the view volume are hidden and along a user clip plane shown, as Mesa does.

use super::clip::{segment_by, Mix};
use super::consts::*;
use super::frame::DrawState;
use super::shade::{ShadedVertex, Shader};
use super::types::*;
use super::vertex::Vertex;
use glam::Vec4;

/// A vertex as feedback reports it: window x, y, z and clip w, colour, texture coordinate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct FeedbackVertex {
    pub window: [f32; 4],
    pub color: [f32; 4],
    pub tex: [f32; 4],
}

/// One token's primitive.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum FeedbackPrimitive {
    Point(FeedbackVertex),
    /// A line; `reset`: the first of a polygon outline (`GL_LINE_RESET_TOKEN`).
    Line(FeedbackVertex, FeedbackVertex, bool),
    Polygon(Vec<FeedbackVertex>),
}

/// A triangle of the split: vertex indices, which edges (vᵢ → vᵢ₊₁) are the primitive's own,
/// and whether it starts a new outline.
struct Triangle {
    v: [usize; 3],
    edges: [bool; 3],
    reset: bool,
}

/// How a primitive of `count` vertices is split into triangles, in Mesa's order.
fn triangles(mode: GLenum, n: usize) -> Vec<Triangle> {
    let all = [true; 3];
    let tri = |v: [usize; 3], edges: [bool; 3], reset: bool| Triangle { v, edges, reset };
    match mode {
        GL_TRIANGLES => (0..n / 3).map(|i| tri([3 * i, 3 * i + 1, 3 * i + 2], all, true)).collect(),
        GL_TRIANGLE_STRIP => (2..n)
            .map(|i| {
                let v = if i % 2 == 0 { [i - 2, i - 1, i] } else { [i - 1, i - 2, i] };
                tri(v, all, i == 2)
            })
            .collect(),
        GL_TRIANGLE_FAN => (2..n).map(|i| tri([0, i - 1, i], all, i == 2)).collect(),
        GL_QUADS => (0..n / 4)
            .flat_map(|q| {
                let b = 4 * q;
                [
                    tri([b, b + 1, b + 3], [true, false, true], true),
                    tri([b + 1, b + 2, b + 3], [true, true, false], false),
                ]
            })
            .collect(),
        GL_QUAD_STRIP => (1..n / 2)
            .flat_map(|q| {
                let b = 2 * (q - 1);
                let first = q == 1;
                [tri([b + 2, b, b + 3], [true, false, true], first), tri([b, b + 1, b + 3], [true, true, false], false)]
            })
            .collect(),
        GL_POLYGON if n >= 3 => {
            (0..n - 2).map(|i| tri([i + 1, i + 2, 0], [true, i == n - 3, i == 0], i == 0)).collect()
        }
        _ => Vec::new(),
    }
}

/// The primitives one `begin`/`end` of `mode` reports, in order; `hidden[i]`: vertex `i`'s
/// edge flag is false (empty: all true).
pub(crate) fn report(mode: GLenum, state: &DrawState, vertices: &[Vertex], hidden: &[bool]) -> Vec<FeedbackPrimitive> {
    let shader = Shader::new(state);
    let v: Vec<ShadedVertex> = vertices
        .iter()
        .map(|v| {
            let s = shader.shade(v);
            // Without a texture feedback reports the coordinate as given (the vertex stage's is
            // zero then: no rasteriser reads it).
            let tex = if state.texture.is_some() { s.tex } else { Vec4::from_array(v.tex_coord) };
            ShadedVertex { tex, ..s }
        })
        .collect();
    let out = Reporter { state, out: Vec::new() };
    out.primitive(mode, &v, hidden)
}

struct Reporter<'a> {
    state: &'a DrawState,
    out: Vec<FeedbackPrimitive>,
}

impl Reporter<'_> {
    fn primitive(mut self, mode: GLenum, v: &[ShadedVertex], hidden: &[bool]) -> Vec<FeedbackPrimitive> {
        let n = v.len();
        match mode {
            GL_POINTS => (0..n).for_each(|i| self.point(v[i], true)),
            GL_LINES => (0..n / 2).for_each(|i| self.line(v[2 * i], v[2 * i + 1], true, false)),
            GL_LINE_STRIP => (1..n).for_each(|i| self.line(v[i - 1], v[i], true, false)),
            GL_LINE_LOOP if n >= 2 => {
                (1..n).for_each(|i| self.line(v[i - 1], v[i], true, false));
                self.line(v[n - 1], v[0], true, false);
            }
            _ => {
                // Mesa applies the flags to every polygon primitive, strips and fans too
                // (GL 1.1 §2.6.2 names only independent triangles, quads and polygons).
                let flag = |i: usize| !hidden.get(i).copied().unwrap_or(false);
                for t in triangles(mode, n) {
                    let edges = [0, 1, 2].map(|k| t.edges[k] && flag(t.v[k]));
                    self.triangle(t.v.map(|i| v[i]), edges, t.reset);
                }
            }
        }
        self.out
    }

    /// Window coordinates of a vertex through the viewport and depth range, and its colour.
    fn vertex(&self, s: &ShadedVertex, front: bool) -> FeedbackVertex {
        let [vx, vy, vw, vh] = self.state.viewport.map(|c| c as f32);
        let [near, far] = self.state.depth_range;
        let ndc = s.clip / s.clip.w;
        let window = [
            vx + (ndc.x + 1.0) * vw / 2.0,
            vy + (ndc.y + 1.0) * vh / 2.0,
            near + (far - near) * (ndc.z + 1.0) / 2.0,
            s.clip.w,
        ];
        let color = if front { s.front } else { s.back };
        FeedbackVertex { window, color: color.to_array(), tex: s.tex.to_array() }
    }

    /// The signed distances of a vertex to every plane it is clipped by ([`plane_distance`]).
    fn distances(&self, s: &ShadedVertex) -> Vec<f32> {
        (0..self.planes()).map(|k| plane_distance(self.state, s, k)).collect()
    }

    /// How many planes clip: the view volume's six and the enabled clip planes.
    fn planes(&self) -> usize {
        6 + self.state.clip_planes.len()
    }

    fn point(&mut self, s: ShadedVertex, front: bool) {
        if self.distances(&s).iter().all(|d| *d >= 0.0) {
            let v = self.vertex(&s, front);
            self.out.push(FeedbackPrimitive::Point(v));
        }
    }

    /// A line clipped plane by plane (Liang–Barsky on the distances, `clip::segment_by`).
    fn line(&mut self, a: ShadedVertex, b: ShadedVertex, front: bool, reset: bool) {
        let state = self.state;
        let planes = (0..self.planes()).map(|k| move |s: &ShadedVertex| plane_distance(state, s, k));
        let Some((a2, b2)) = segment_by(a, b, planes) else { return };
        let (va, vb) = (self.vertex(&a2, front), self.vertex(&b2, front));
        self.out.push(FeedbackPrimitive::Line(va, vb, reset));
    }

    /// Twice the window-space signed area (counter-clockwise positive); from the homogeneous
    /// determinant when a vertex is behind the eye.
    fn area(t: &[ShadedVertex; 3]) -> f32 {
        if t.iter().all(|s| s.clip.w > 0.0) {
            let p: Vec<(f32, f32)> = t.iter().map(|s| (s.clip.x / s.clip.w, s.clip.y / s.clip.w)).collect();
            (p[1].0 - p[0].0) * (p[2].1 - p[0].1) - (p[2].0 - p[0].0) * (p[1].1 - p[0].1)
        } else {
            let [a, b, c] = t.map(|s| glam::Vec3::new(s.clip.x, s.clip.y, s.clip.w));
            a.dot(b.cross(c))
        }
    }

    fn triangle(&mut self, t: [ShadedVertex; 3], edges: [bool; 3], reset: bool) {
        let front = (Self::area(&t) > 0.0) == (self.state.front_face == GL_CCW);
        if let Some(cull) = self.state.cull_face {
            if cull == GL_FRONT_AND_BACK || (cull == GL_FRONT) == front {
                return;
            }
        }
        let mode = self.state.polygon_mode[usize::from(!front)];
        let inside = t.iter().all(|s| self.distances(s).iter().all(|d| *d >= 0.0));
        if inside {
            return self.face(mode, &t, edges, reset, front);
        }
        let (outline, outline_edges) = self.clip_polygon(t.to_vec(), edges.to_vec());
        let n = outline.len();
        let mut reset = reset;
        for i in 2..n {
            let fan = [outline[i - 1], outline[i], outline[0]];
            let fan_edges = [outline_edges[i - 1], i == n - 1 && outline_edges[n - 1], i == 2 && outline_edges[0]];
            self.face(mode, &fan, fan_edges, reset, front);
            reset = false;
        }
    }

    /// A triangle in its face's polygon mode.
    fn face(&mut self, mode: GLenum, t: &[ShadedVertex; 3], edges: [bool; 3], reset: bool, front: bool) {
        match mode {
            GL_POINT => {
                for k in 0..3 {
                    if edges[k] {
                        self.point(t[k], front);
                    }
                }
            }
            GL_LINE => {
                let mut reset = reset;
                for k in [2, 0, 1] {
                    if edges[k] {
                        self.line(t[k], t[(k + 1) % 3], front, reset);
                        reset = false;
                    }
                }
            }
            _ => {
                let v = t.iter().map(|s| self.vertex(s, front)).collect();
                self.out.push(FeedbackPrimitive::Polygon(v));
            }
        }
    }

    /// Sutherland–Hodgman against each plane a vertex is outside of, keeping the first vertex
    /// first and each vertex's outgoing edge flag, as Mesa's `do_clip_tri` does.
    fn clip_polygon(&self, mut list: Vec<ShadedVertex>, mut edges: Vec<bool>) -> (Vec<ShadedVertex>, Vec<bool>) {
        let planes = self.planes();
        for plane in 0..planes {
            if list.len() < 3 {
                break;
            }
            let d: Vec<f32> = list.iter().map(|s| plane_distance(self.state, s, plane)).collect();
            if d.iter().all(|x| *x >= 0.0) {
                continue;
            }
            let user = plane >= 6;
            let (mut out, mut out_edges) = (Vec::new(), Vec::new());
            let n = list.len();
            for i in 0..n {
                let j = (i + 1) % n;
                let (prev, dp_prev, dp) = (list[i], d[i], d[j]);
                if dp_prev >= 0.0 {
                    out.push(prev);
                    out_edges.push(edges[i]);
                }
                if (dp < 0.0) != (dp_prev < 0.0) {
                    if dp < 0.0 {
                        // Going out: the new edge runs along the plane.
                        out.push(list[j].mix(prev, dp / (dp - dp_prev)));
                        out_edges.push(user);
                    } else {
                        out.push(prev.mix(list[j], dp_prev / (dp_prev - dp)));
                        out_edges.push(edges[i]);
                    }
                }
            }
            (list, edges) = (out, out_edges);
        }
        (list, edges)
    }
}

/// The signed distance of a vertex to plane `k`: the view volume's six first (Mesa's order:
/// x, −x, y, −y, z, −z as w ∓ …), then the enabled clip planes.
fn plane_distance(state: &DrawState, s: &ShadedVertex, k: usize) -> f32 {
    let c = s.clip;
    match k {
        0 => c.w - c.x,
        1 => c.w + c.x,
        2 => c.w - c.y,
        3 => c.w + c.y,
        4 => c.w + c.z,
        5 => c.w - c.z,
        _ => Vec4::from_array(state.clip_planes[k - 6]).dot(s.eye),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quads_and_polygons_split_as_mesa_does() {
        let q = triangles(GL_QUADS, 4);
        assert_eq!((q[0].v, q[1].v), ([0, 1, 3], [1, 2, 3]));
        let p = triangles(GL_POLYGON, 5);
        assert_eq!(p.iter().map(|t| t.v).collect::<Vec<_>>(), vec![[1, 2, 0], [2, 3, 0], [3, 4, 0]]);
        assert_eq!(p[0].edges, [true, false, true]);
        assert_eq!(p[2].edges, [true, true, false]);
    }
}
