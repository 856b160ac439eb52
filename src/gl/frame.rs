//! What a [`Gl`](super::Gl) context records: the primitives it assembled between `begin` and
//! `end` (from immediate mode or from the evaluators), and a log of the immediate-mode calls.
//! Tests read it; the renderer draws it.

use super::types::GLenum;

/// One vertex as GL hands it to the rest of the pipeline: object-space position (w not divided),
/// and the current (or evaluated) colour, normal and texture coordinate of unit 0.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Vertex {
    /// (x, y, z, w); `vertex3f` gives w = 1; `GL_MAP*_VERTEX_4` passes w through.
    pub position: [f32; 4],
    /// RGBA, not clamped here (GL clamps after lighting).
    pub color: [f32; 4],
    /// The normal (unit length only when it came from `GL_AUTO_NORMAL`).
    pub normal: [f32; 3],
    /// (s, t, r, q).
    pub tex_coord: [f32; 4],
}

/// A `begin`/`end` pair: its mode and its vertices `first..first + count` of [`Frame::vertices`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Primitive {
    /// `GL_POINTS` ... `GL_POLYGON`.
    pub mode: GLenum,
    /// Index of the first vertex.
    pub first: usize,
    /// Number of vertices (may be too few to draw anything, as in GL).
    pub count: usize,
}

/// An immediate-mode call, in the order the program made it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Call {
    /// `glBegin(mode)`.
    Begin(GLenum),
    /// `glEnd()`.
    End,
    /// `glVertex*` (x, y, z, w).
    Vertex([f32; 4]),
    /// `glColor*` (r, g, b, a).
    Color([f32; 4]),
    /// `glNormal*`.
    Normal([f32; 3]),
    /// `glTexCoord*` (s, t, r, q).
    TexCoord([f32; 4]),
}

/// Everything drawn since the context was made or the frame last taken.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Frame {
    /// All vertices, primitive after primitive.
    pub vertices: Vec<Vertex>,
    /// The primitives, in drawing order.
    pub primitives: Vec<Primitive>,
    /// The immediate-mode calls the program made (evaluator output is not logged here,
    /// only in `primitives`).
    pub calls: Vec<Call>,
}

impl Frame {
    /// The vertices of primitive `index`.
    #[must_use]
    pub fn vertices_of(&self, primitive: &Primitive) -> &[Vertex] {
        &self.vertices[primitive.first..primitive.first + primitive.count]
    }

    /// Iterates over (primitive, its vertices).
    pub fn iter(&self) -> impl Iterator<Item = (&Primitive, &[Vertex])> {
        self.primitives.iter().map(move |p| (p, self.vertices_of(p)))
    }

    /// Removes everything recorded.
    pub fn clear(&mut self) {
        self.vertices.clear();
        self.primitives.clear();
        self.calls.clear();
    }
}
