//! Feedback mode (GL 1.1 spec §5.3; Mesa `main/feedback.c`): `glRenderMode(GL_FEEDBACK)` with
//! `glFeedbackBuffer`, how a program reads back the primitives it drew instead of pixels.
//!
//! In feedback mode nothing is drawn: when the program leaves it (`render_mode`), the
//! primitives recorded since it entered are taken out of the frame and written as GL's tokens
//! (`GL_POINT_TOKEN`, `GL_LINE_TOKEN`, `GL_POLYGON_TOKEN` with its vertex count), each vertex
//! as the buffer type asks: window coordinates (through the viewport and depth range the
//! primitive was drawn with), then the colour and the texture coordinate. Strips, loops, fans,
//! quads and polygons are broken into the lines and triangles GL's feedback reports, in Mesa's
//! order (checked against Mesa 22 in `tests/reference/calls/cases/feedback.calls`).
//!
//! Vertices are lit, clipped, culled and drawn in their polygon mode as Mesa's draw module
//! hands them to its feedback stage (`feedback_prims`); `glPassThrough` writes its token in
//! program order. Selection mode (`select.rs`) shares the render mode and the primitives.

use super::consts::*;
use super::feedback_prims::{self, FeedbackPrimitive, FeedbackVertex};
use super::frame::Command;
use super::state_var::{put_enum, row, Kind, StateVar};
use super::types::*;
use super::vertex::Vertex;
use super::Gl;

/// The feedback state of a context.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Feedback {
    /// `GL_RENDER` or `GL_FEEDBACK`.
    mode: GLenum,
    /// `glFeedbackBuffer`'s size (values) and type; size 0 until a buffer is given.
    size: usize,
    kind: GLenum,
    /// Frame commands recorded before feedback mode began (they are drawn).
    start: usize,
    /// What the last feedback pass wrote, at most `size` values.
    values: Vec<GLfloat>,
    /// Primitives drawn while a list compiles wait for the next pass after it ends.
    held: bool,
    /// The `GL_BITMAP_TOKEN`s and `GL_DRAW_PIXEL_TOKEN`s of this pass, each with the frame
    /// command it came before and the vertex it reports (window position, colour, texture
    /// coordinate of the raster position).
    raster_tokens: Vec<(usize, GLenum, [[GLfloat; 4]; 3])>,
}

impl Default for Feedback {
    fn default() -> Self {
        Self {
            mode: GL_RENDER,
            size: 0,
            kind: GL_2D,
            start: 0,
            values: Vec::new(),
            held: false,
            raster_tokens: Vec::new(),
        }
    }
}

/// Which parts a buffer type writes: (4D position, colour, texture coordinate); `None` for a
/// type GL does not know.
fn layout(kind: GLenum) -> Option<(bool, bool, bool)> {
    match kind {
        GL_2D | GL_3D => Some((false, false, false)),
        GL_3D_COLOR => Some((false, true, false)),
        GL_3D_COLOR_TEXTURE => Some((false, true, true)),
        GL_4D_COLOR_TEXTURE => Some((true, true, true)),
        _ => None,
    }
}

/// The vertex indices of the tokens GL reports for a primitive of `count` vertices:
/// (token, indices) in Mesa's order and winding, before clipping and culling (what the Mesa
/// call-script tests' own feedback emulation reads).
/// The render mode's and the feedback buffer's `glGet` rows.
pub(crate) static GET_ROWS: &[StateVar] = &[
    row(GL_RENDER_MODE, 1, Kind::Int, |gl, o| put_enum(o, gl.render_mode_value())),
    row(GL_FEEDBACK_BUFFER_SIZE, 1, Kind::Int, |gl, o| o[0] = gl.feedback_buffer_spec().0 as f64),
    row(GL_FEEDBACK_BUFFER_TYPE, 1, Kind::Int, |gl, o| put_enum(o, gl.feedback_buffer_spec().1)),
];

#[cfg(test)]
fn tokens(mode: GLenum, count: usize) -> Vec<(GLenum, Vec<usize>)> {
    let n = count;
    let tri = |a: usize, b: usize, c: usize| (GL_POLYGON_TOKEN, vec![a, b, c]);
    match mode {
        GL_POINTS => (0..n).map(|i| (GL_POINT_TOKEN, vec![i])).collect(),
        GL_LINES => (0..n / 2).map(|i| (GL_LINE_TOKEN, vec![2 * i, 2 * i + 1])).collect(),
        GL_LINE_STRIP => (1..n).map(|i| (GL_LINE_TOKEN, vec![i - 1, i])).collect(),
        GL_LINE_LOOP if n >= 2 => {
            let mut lines: Vec<_> = (1..n).map(|i| (GL_LINE_TOKEN, vec![i - 1, i])).collect();
            lines.push((GL_LINE_TOKEN, vec![n - 1, 0]));
            lines
        }
        GL_TRIANGLES => (0..n / 3).map(|i| tri(3 * i, 3 * i + 1, 3 * i + 2)).collect(),
        GL_TRIANGLE_STRIP => {
            (2..n).map(|i| if i % 2 == 0 { tri(i - 2, i - 1, i) } else { tri(i - 1, i - 2, i) }).collect()
        }
        GL_TRIANGLE_FAN => (2..n).map(|i| tri(0, i - 1, i)).collect(),
        GL_POLYGON => (2..n).map(|i| tri(i - 1, i, 0)).collect(),
        GL_QUADS => {
            (0..n / 4).flat_map(|q| [tri(4 * q, 4 * q + 1, 4 * q + 3), tri(4 * q + 1, 4 * q + 2, 4 * q + 3)]).collect()
        }
        // Mesa splits each quad of a strip as (v2, v0, v3), (v0, v1, v3).
        GL_QUAD_STRIP => (1..n / 2)
            .flat_map(|q| {
                let b = 2 * (q - 1);
                [tri(b + 2, b, b + 3), tri(b, b + 1, b + 3)]
            })
            .collect(),
        _ => Vec::new(),
    }
}

impl Gl {
    /// `glFeedbackBuffer(size, type, buffer)`: feedback mode writes up to `size` values of
    /// vertices laid out as `type_` says (`GL_2D` .. `GL_4D_COLOR_TEXTURE`); read them with
    /// [`Gl::feedback_values`] after `render_mode` leaves feedback mode. Errors, in Mesa's
    /// order: inside `begin`/`end` or in feedback mode (`GL_INVALID_OPERATION`), a negative size
    /// (`GL_INVALID_VALUE`), an unknown type (`GL_INVALID_ENUM`). Not compiled into lists.
    pub fn feedback_buffer(&mut self, size: GLsizei, type_: GLenum) {
        if let Some(error) = self.feedback_buffer_error(size, type_) {
            return self.set_error(error);
        }
        (self.client.feedback.size, self.client.feedback.kind) = (size as usize, type_);
    }

    /// The error `glFeedbackBuffer(size, type)` raises now, in Mesa's order (inside
    /// `begin`/`end`, feedback mode, a negative size, an unknown type), `None` when it takes
    /// the buffer: what a binding that keeps the caller's buffer asks before it does.
    #[must_use]
    pub fn feedback_buffer_error(&self, size: GLsizei, type_: GLenum) -> Option<GLenum> {
        if self.inside_begin_end() || self.client.feedback.mode == GL_FEEDBACK {
            Some(GL_INVALID_OPERATION)
        } else if size < 0 {
            Some(GL_INVALID_VALUE)
        } else if layout(type_).is_none() {
            Some(GL_INVALID_ENUM)
        } else {
            None
        }
    }

    /// `glRenderMode(mode)`: `GL_RENDER` or `GL_FEEDBACK`. Leaving feedback mode returns the
    /// number of values written, or −1 if the buffer was too small; leaving render mode returns
    /// 0. Entering feedback mode without a buffer is `GL_INVALID_OPERATION` (the mode changes
    /// anyway, as in Mesa); another mode is `GL_INVALID_ENUM`, as inside `begin`/`end` is
    /// `GL_INVALID_OPERATION`. Not compiled into lists.
    pub fn render_mode(&mut self, mode: GLenum) -> GLint {
        if self.reject_inside_begin_end() {
            return 0;
        }
        // Mesa buffers what a GL_COMPILE_AND_EXECUTE list draws and runs it when the list
        // ends: its primitives reach the feedback buffer after glEndList, so they are held.
        let compiling = self.compiling_list();
        let result = match self.client.feedback.mode {
            GL_SELECT => self.finish_select(),
            GL_FEEDBACK if compiling => {
                self.client.feedback.held = true;
                self.client.feedback.values.clear();
                0
            }
            GL_FEEDBACK => {
                self.client.feedback.held = false;
                self.finish_feedback()
            }
            _ => 0,
        };
        match mode {
            GL_RENDER => {}
            GL_SELECT => self.start_select(),
            GL_FEEDBACK => {
                if self.client.feedback.size == 0 {
                    self.set_error(GL_INVALID_OPERATION);
                }
                if !self.client.feedback.held {
                    self.evaluate_pending_meshes();
                    self.client.feedback.start = self.recorder.frame.commands.len();
                    self.client.feedback.raster_tokens.clear();
                }
            }
            _ => {
                self.set_error(GL_INVALID_ENUM);
                return 0;
            }
        }
        self.client.feedback.mode = mode;
        result
    }

    /// The render mode: `GL_RENDER`, `GL_FEEDBACK` or `GL_SELECT` (what
    /// `glGetIntegerv(GL_RENDER_MODE)` answers, without its begin/end check).
    #[must_use]
    pub fn render_mode_value(&self) -> GLenum {
        self.client.feedback.mode
    }

    /// `glPassThrough(token)`: in feedback mode, a `GL_PASS_THROUGH_TOKEN` and `token` among
    /// the primitives, where the call was made; nothing in the other modes. Compiled into
    /// lists; inside `begin`/`end` → `GL_INVALID_OPERATION`.
    pub fn pass_through(&mut self, token: GLfloat) {
        if self.compiled_state_call(|| super::lists::ListCommand::PassThrough(token)) {
            return;
        }
        if self.client.feedback.mode == GL_FEEDBACK {
            self.evaluate_pending_meshes();
            let value = [[token, 0.0, 0.0, 0.0]; 3];
            self.client.feedback.raster_tokens.push((self.recorder.frame.commands.len(), GL_PASS_THROUGH_TOKEN, value));
        }
    }

    /// The size and type the last successful `feedback_buffer` set (0 and `GL_2D` initially):
    /// a binding that keeps the caller's buffer knows from it whether the call took.
    #[must_use]
    pub fn feedback_buffer_spec(&self) -> (usize, GLenum) {
        (self.client.feedback.size, self.client.feedback.kind)
    }

    /// The values the last feedback pass wrote (at most the buffer's size).
    #[must_use]
    pub fn feedback_values(&self) -> &[GLfloat] {
        &self.client.feedback.values
    }

    /// Takes what was drawn in feedback mode out of the frame and writes its tokens; the count
    /// `glRenderMode` returns.
    fn finish_feedback(&mut self) -> GLint {
        self.evaluate_pending_meshes();
        let start = self.client.feedback.start.min(self.recorder.frame.commands.len());
        let commands: Vec<Command> = self.recorder.frame.commands.drain(start..).collect();
        let mut tokens = std::mem::take(&mut self.client.feedback.raster_tokens).into_iter().peekable();
        let mut values = Vec::new();
        for (k, command) in commands.into_iter().enumerate() {
            while let Some((_, token, vertex)) = tokens.next_if(|t| t.0 <= start + k) {
                self.feedback_raster(&mut values, token, vertex);
            }
            for prim in self.command_primitives(&command) {
                self.feedback_primitive(&mut values, &prim);
            }
        }
        for (_, token, vertex) in tokens {
            self.feedback_raster(&mut values, token, vertex);
        }
        let overflow = values.len() > self.client.feedback.size;
        values.truncate(self.client.feedback.size);
        let count = values.len();
        self.client.feedback.values = values;
        if overflow {
            -1
        } else {
            GLint::try_from(count).unwrap_or(GLint::MAX)
        }
    }

    /// In feedback mode a `glBitmap` or `glDrawPixels` at a valid raster position writes
    /// `token` and the raster position as a vertex instead of drawing (GL 1.1 §5.3); true
    /// when it did.
    pub(crate) fn feedback_raster_token(&mut self, token: GLenum) -> bool {
        if self.client.feedback.mode != GL_FEEDBACK {
            return false;
        }
        let r = &self.server.raster_pos;
        let vertex = [r.window, r.color.map(|c| c.clamp(0.0, 1.0)), r.tex_coord];
        self.client.feedback.raster_tokens.push((self.recorder.frame.commands.len(), token, vertex));
        true
    }

    /// A raster token and its vertex, laid out as the buffer type says.
    fn feedback_raster(&self, out: &mut Vec<GLfloat>, token: GLenum, [window, color, tex]: [[GLfloat; 4]; 3]) {
        out.push(token as GLfloat);
        if token == GL_PASS_THROUGH_TOKEN {
            return out.push(window[0]);
        }
        let (four, with_color, with_texture) = layout(self.client.feedback.kind).unwrap_or_default();
        let position = match self.client.feedback.kind {
            GL_2D => 2,
            _ if four => 4,
            _ => 3,
        };
        out.extend_from_slice(&window[..position]);
        if with_color {
            out.extend_from_slice(&color);
        }
        if with_texture {
            out.extend_from_slice(&tex);
        }
    }

    /// The primitives a recorded draw or mesh reports (clipped, lit, culled, in polygon mode).
    pub(crate) fn command_primitives(&self, command: &Command) -> Vec<FeedbackPrimitive> {
        let mut out = Vec::new();
        match *command {
            Command::Draw(i) => {
                let p = self.recorder.frame.primitives[i];
                let Some(state) = self.recorder.frame.states.get(p.state) else { return out };
                let hidden = self.recorder.frame.hidden_edges_of(&p);
                out = feedback_prims::report(p.mode, state, self.recorder.frame.vertices_of(&p), &hidden);
            }
            Command::Mesh(i) => {
                let mesh = &self.recorder.frame.meshes[i];
                let Some(state) = self.recorder.frame.states.get(mesh.state) else { return out };
                let grid = mesh.evaluated();
                for (mode, indices) in mesh.primitives() {
                    let vertices: Vec<Vertex> = indices.iter().map(|&k| grid.vertex(k)).collect();
                    out.extend(feedback_prims::report(mode, state, &vertices, &[]));
                }
            }
            // GL clears and copies only in render mode (a copy gives its token instead).
            Command::Clear { .. }
            | Command::CopyPixels(_)
            | Command::Accum(_)
            | Command::SwapBuffers
            | Command::Query { .. } => {}
        }
        out
    }

    fn feedback_primitive(&self, out: &mut Vec<GLfloat>, prim: &FeedbackPrimitive) {
        match prim {
            FeedbackPrimitive::Point(v) => {
                out.push(GL_POINT_TOKEN as GLfloat);
                self.feedback_vertex(out, v);
            }
            FeedbackPrimitive::Line(a, b, reset) => {
                out.push(if *reset { GL_LINE_RESET_TOKEN } else { GL_LINE_TOKEN } as GLfloat);
                self.feedback_vertex(out, a);
                self.feedback_vertex(out, b);
            }
            FeedbackPrimitive::Polygon(vs) => {
                out.push(GL_POLYGON_TOKEN as GLfloat);
                out.push(vs.len() as GLfloat);
                vs.iter().for_each(|v| self.feedback_vertex(out, v));
            }
        }
    }

    /// One vertex as the buffer type lays it out: window x, y (z, w), colour, texcoord.
    fn feedback_vertex(&self, out: &mut Vec<GLfloat>, v: &FeedbackVertex) {
        let FeedbackVertex { window, .. } = *v;
        let (four, color, texture) = layout(self.client.feedback.kind).unwrap_or_default();
        let position = match self.client.feedback.kind {
            GL_2D => 2,
            _ if four => 4,
            _ => 3,
        };
        out.extend_from_slice(&window[..position]);
        if color {
            out.extend_from_slice(&v.color);
        }
        if texture {
            out.extend_from_slice(&v.tex);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn strips_break_into_mesas_triangles() {
        let t = tokens(GL_TRIANGLE_STRIP, 4);
        assert_eq!(t, vec![(GL_POLYGON_TOKEN, vec![0, 1, 2]), (GL_POLYGON_TOKEN, vec![2, 1, 3])]);
        assert_eq!(tokens(GL_LINE_STRIP, 3).len(), 2);
        assert!(tokens(GL_LINES, 1).is_empty());
    }

    #[test]
    fn feedback_reports_points_in_window_coordinates() {
        let mut gl = Gl::new(4, 4);
        gl.viewport(0, 0, 2, 2);
        gl.feedback_buffer(100, GL_3D);
        assert_eq!(gl.render_mode(GL_FEEDBACK), 0);
        gl.begin(GL_POINTS);
        gl.vertex3f(0.5, -0.5, 0.0);
        gl.end();
        assert_eq!(gl.render_mode(GL_RENDER), 4);
        assert_eq!(gl.feedback_values(), &[GL_POINT_TOKEN as f32, 1.5, 0.5, 0.5]);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        assert!(gl.frame().commands.is_empty(), "feedback draws nothing");
    }

    #[test]
    fn errors_follow_mesa() {
        let mut gl = Gl::new(4, 4);
        gl.render_mode(GL_FEEDBACK);
        assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
        gl.feedback_buffer(10, GL_2D);
        assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
        gl.render_mode(GL_RENDER);
        gl.feedback_buffer(-1, GL_2D);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
        gl.feedback_buffer(1, 0x1234);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
        assert_eq!(gl.render_mode(0x1234), 0);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    }
}
