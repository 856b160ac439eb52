//! Immediate mode: `glBegin`/`glEnd`, `glVertex*`, and the current colour, normal and
//! texture coordinate (GL 1.1 spec §2.6–2.7).

use super::consts::*;
use super::frame::{Call, MaterialChange, Primitive};
use super::lists::ListCommand;
use super::types::*;
use super::vertex::Vertex;
use super::Gl;

impl Gl {
    /// `glBegin`: starts a primitive. Nested begin → `GL_INVALID_OPERATION`; a mode outside
    /// `GL_POINTS..=GL_POLYGON` → `GL_INVALID_ENUM` (checked in that order, as Mesa does).
    pub fn begin(&mut self, mode: GLenum) {
        if self.compiled(|| ListCommand::Immediate(Call::Begin(mode))) {
            return;
        }
        if self.reject_inside_begin_end() {
            return;
        }
        if mode > GL_POLYGON {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        self.recorder.frame.calls.push(Call::Begin(mode));
        self.open_primitive_raw(mode);
    }

    /// `glEnd`: closes the primitive; outside `begin` → `GL_INVALID_OPERATION`.
    pub fn end(&mut self) {
        if self.compiled(|| ListCommand::Immediate(Call::End)) {
            return;
        }
        if !self.inside_begin_end() {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        self.recorder.frame.calls.push(Call::End);
        self.recorder.open_primitive = None;
        self.color_material_end();
    }

    /// Begins a primitive on behalf of the evaluators (not logged as a user call).
    pub(crate) fn open_primitive_raw(&mut self, mode: GLenum) {
        self.color_material_begin();
        let first = self.recorder.frame.vertices.len();
        let state = self.current_state_index();
        self.recorder.multi_unit = !self.recorder.frame.states[state].more_textures.is_empty();
        let listed_or_indexed = self.recorder.indexed_draw || self.lists_executing();
        self.recorder.frame.primitives.push(Primitive { mode, first, count: 0, state, listed_or_indexed });
        let index = self.recorder.frame.primitives.len() - 1;
        self.recorder.frame.commands.push(super::frame::Command::Draw(index));
        self.recorder.open_primitive = Some(index);
    }

    /// Adds a finished vertex to the open primitive; outside `begin`/`end` a vertex only
    /// moves the current position, so nothing is recorded.
    pub(crate) fn emit_vertex(&mut self, v: Vertex) {
        if let Some(p) = self.recorder.open_primitive {
            if !self.edge_flag_value() {
                self.recorder.frame.hidden_edges.push(self.recorder.frame.vertices.len());
            }
            if self.recorder.multi_unit {
                let index = self.recorder.frame.vertices.len();
                self.recorder.frame.unit_tex_coords.push((index, self.server.current.unit_tex_coords));
            }
            self.recorder.frame.vertices.push(v);
            self.recorder.frame.primitives[p].count += 1;
        }
    }

    /// Inside `begin`/`end`, a material change applies from the primitive's next vertex on
    /// (GL 1.1 §2.13.2: each vertex is lit with the material current when it is issued):
    /// recorded as a [`MaterialChange`] naming the state the following vertices are lit with.
    pub(crate) fn note_material_change(&mut self) {
        let Some(p) = self.recorder.open_primitive else { return };
        let state = self.current_state_index();
        let vertex = self.recorder.frame.primitives[p].count;
        let change = MaterialChange { primitive: p, vertex, state };
        match self.recorder.frame.material_changes.last_mut() {
            Some(last) if last.primitive == p && last.vertex == vertex => *last = change,
            _ => self.recorder.frame.material_changes.push(change),
        }
    }

    /// The vertex that `glVertex4f(x, y, z, w)` issues now, with the current attributes.
    pub(crate) fn current_vertex(&self, position: [f32; 4]) -> Vertex {
        Vertex {
            position,
            color: self.server.current.color,
            normal: self.server.current.normal,
            tex_coord: self.server.current.tex_coord,
            secondary_color: self.server.current.secondary_color,
            fog_coord: self.server.current.fog_coord,
        }
    }

    fn vertex(&mut self, position: [f32; 4]) {
        if self.compiled(|| ListCommand::Immediate(Call::Vertex(position))) {
            return;
        }
        self.recorder.frame.calls.push(Call::Vertex(position));
        let v = self.current_vertex(position);
        self.emit_vertex(v);
    }

    /// `glVertex2f` (z = 0, w = 1).
    pub fn vertex2f(&mut self, x: GLfloat, y: GLfloat) {
        self.vertex([x, y, 0.0, 1.0]);
    }

    /// `glVertex2d` (cast to float, as Mesa stores vertices).
    pub fn vertex2d(&mut self, x: GLdouble, y: GLdouble) {
        self.vertex([x as f32, y as f32, 0.0, 1.0]);
    }

    /// `glVertex3f` (w = 1).
    pub fn vertex3f(&mut self, x: GLfloat, y: GLfloat, z: GLfloat) {
        self.vertex([x, y, z, 1.0]);
    }

    /// `glVertex3d`.
    pub fn vertex3d(&mut self, x: GLdouble, y: GLdouble, z: GLdouble) {
        self.vertex([x as f32, y as f32, z as f32, 1.0]);
    }

    /// `glVertex4f`.
    pub fn vertex4f(&mut self, x: GLfloat, y: GLfloat, z: GLfloat, w: GLfloat) {
        self.vertex([x, y, z, w]);
    }

    /// `glVertex2fv`: `v` needs 2 values.
    pub fn vertex2fv(&mut self, v: &[GLfloat]) {
        if let Some(v) = self.needs::<2>(v) {
            self.vertex2f(v[0], v[1]);
        }
    }

    /// `glVertex3fv`: `v` needs 3 values.
    pub fn vertex3fv(&mut self, v: &[GLfloat]) {
        if let Some(v) = self.needs::<3>(v) {
            self.vertex3f(v[0], v[1], v[2]);
        }
    }

    /// `glVertex4fv`: `v` needs 4 values.
    pub fn vertex4fv(&mut self, v: &[GLfloat]) {
        if let Some(v) = self.needs::<4>(v) {
            self.vertex4f(v[0], v[1], v[2], v[3]);
        }
    }

    /// `glColor3f` (alpha = 1).
    pub fn color3f(&mut self, r: GLfloat, g: GLfloat, b: GLfloat) {
        self.color4f(r, g, b, 1.0);
    }

    /// `glColor4f`.
    pub fn color4f(&mut self, r: GLfloat, g: GLfloat, b: GLfloat, a: GLfloat) {
        if self.compiled(|| ListCommand::Immediate(Call::Color([r, g, b, a]))) {
            return;
        }
        let old = std::mem::replace(&mut self.server.current.color, [r, g, b, a]);
        self.recorder.frame.calls.push(Call::Color(self.server.current.color));
        self.color_set(old);
    }

    /// `glColor3fv`: `v` needs 3 values.
    pub fn color3fv(&mut self, v: &[GLfloat]) {
        if let Some(v) = self.needs::<3>(v) {
            self.color3f(v[0], v[1], v[2]);
        }
    }

    /// `glColor4fv`: `v` needs 4 values.
    pub fn color4fv(&mut self, v: &[GLfloat]) {
        if let Some(v) = self.needs::<4>(v) {
            self.color4f(v[0], v[1], v[2], v[3]);
        }
    }

    /// `glColor3ub`: bytes map to [0, 1] as GL converts unsigned bytes (c / 255).
    pub fn color3ub(&mut self, r: u8, g: u8, b: u8) {
        let f = |c: u8| f32::from(c) / 255.0;
        self.color4f(f(r), f(g), f(b), 1.0);
    }

    /// `glSecondaryColor3f` (GL 1.4 §2.7, `GL_EXT_secondary_color`): the colour the colour sum
    /// adds after texturing when `GL_COLOR_SUM` is enabled and lighting is not (§3.9); alpha 1.
    /// Allowed between begin and end, compiled into lists.
    pub fn secondary_color3f(&mut self, r: GLfloat, g: GLfloat, b: GLfloat) {
        self.secondary_color([r, g, b, 1.0]);
    }

    /// The secondary colour with an alpha: what a size-4 secondary colour array sets.
    pub(crate) fn secondary_color(&mut self, rgba: [f32; 4]) {
        if self.compiled(|| ListCommand::Immediate(Call::SecondaryColor(rgba))) {
            return;
        }
        self.server.current.secondary_color = rgba;
        self.recorder.frame.calls.push(Call::SecondaryColor(rgba));
    }

    /// `glSecondaryColor3fv`: `v` needs 3 values.
    pub fn secondary_color3fv(&mut self, v: &[GLfloat]) {
        if let Some(v) = self.needs::<3>(v) {
            self.secondary_color3f(v[0], v[1], v[2]);
        }
    }

    /// `glFogCoordf` (GL 1.4 §2.7, `GL_EXT_fog_coord`): the coordinate fog is computed from
    /// while `GL_FOG_COORD_SRC` is `GL_FOG_COORD` (§3.10). Allowed between begin and end,
    /// compiled into lists.
    pub fn fog_coordf(&mut self, coord: GLfloat) {
        if self.compiled(|| ListCommand::Immediate(Call::FogCoord(coord))) {
            return;
        }
        self.server.current.fog_coord = coord;
        self.recorder.frame.calls.push(Call::FogCoord(coord));
    }

    /// `glFogCoordd`: the coordinate as a float, as Mesa keeps it.
    pub fn fog_coordd(&mut self, coord: GLdouble) {
        self.fog_coordf(coord as f32);
    }

    /// `glFogCoordfv`: `v` needs 1 value.
    pub fn fog_coordfv(&mut self, v: &[GLfloat]) {
        if let Some(v) = self.needs::<1>(v) {
            self.fog_coordf(v[0]);
        }
    }

    /// `glFogCoorddv`: `v` needs 1 value.
    pub fn fog_coorddv(&mut self, v: &[GLdouble]) {
        if let Some(v) = self.first::<1, GLdouble>(v) {
            self.fog_coordd(v[0]);
        }
    }

    /// `glNormal3f`.
    pub fn normal3f(&mut self, x: GLfloat, y: GLfloat, z: GLfloat) {
        if self.compiled(|| ListCommand::Immediate(Call::Normal([x, y, z]))) {
            return;
        }
        self.server.current.normal = [x, y, z];
        self.recorder.frame.calls.push(Call::Normal(self.server.current.normal));
    }

    /// `glNormal3fv`: `v` needs 3 values.
    pub fn normal3fv(&mut self, v: &[GLfloat]) {
        if let Some(v) = self.needs::<3>(v) {
            self.normal3f(v[0], v[1], v[2]);
        }
    }

    /// `glTexCoord1f` (t = r = 0, q = 1).
    pub fn tex_coord1f(&mut self, s: GLfloat) {
        self.tex_coord4f(s, 0.0, 0.0, 1.0);
    }

    /// `glTexCoord2f`.
    pub fn tex_coord2f(&mut self, s: GLfloat, t: GLfloat) {
        self.tex_coord4f(s, t, 0.0, 1.0);
    }

    /// `glTexCoord3f`.
    pub fn tex_coord3f(&mut self, s: GLfloat, t: GLfloat, r: GLfloat) {
        self.tex_coord4f(s, t, r, 1.0);
    }

    /// `glTexCoord4f`.
    pub fn tex_coord4f(&mut self, s: GLfloat, t: GLfloat, r: GLfloat, q: GLfloat) {
        if self.compiled(|| ListCommand::Immediate(Call::TexCoord([s, t, r, q]))) {
            return;
        }
        self.server.current.tex_coord = [s, t, r, q];
        self.recorder.frame.calls.push(Call::TexCoord(self.server.current.tex_coord));
    }

    /// `glTexCoord2fv`: `v` needs 2 values.
    pub fn tex_coord2fv(&mut self, v: &[GLfloat]) {
        if let Some(v) = self.needs::<2>(v) {
            self.tex_coord2f(v[0], v[1]);
        }
    }

    /// `glRectf`: exactly `glBegin(GL_POLYGON)`, the four corners (x1, y1), (x2, y1), (x2, y2),
    /// (x1, y2) with z = 0, `glEnd()` (GL 1.1 spec §2.9).
    pub fn rectf(&mut self, x1: GLfloat, y1: GLfloat, x2: GLfloat, y2: GLfloat) {
        // One command, as Mesa's `OPCODE_RECTF`: inside `begin`/`end` (directly or from a list
        // called there) it is `GL_INVALID_OPERATION` and draws nothing (GL 1.1 §2.9).
        if self.compiled_state_call(|| super::lists::ListCommand::Rect([x1, y1, x2, y2])) {
            return;
        }
        // In GL_COMPILE_AND_EXECUTE the rectangle is recorded once, not also as its vertices.
        self.uncompiled(|gl| {
            gl.begin(GL_POLYGON);
            gl.vertex2f(x1, y1);
            gl.vertex2f(x2, y1);
            gl.vertex2f(x2, y2);
            gl.vertex2f(x1, y2);
            gl.end();
        });
    }

    /// `glRectd` (cast to float).
    pub fn rectd(&mut self, x1: GLdouble, y1: GLdouble, x2: GLdouble, y2: GLdouble) {
        self.rectf(x1 as f32, y1 as f32, x2 as f32, y2 as f32);
    }

    /// `glRecti`.
    pub fn recti(&mut self, x1: GLint, y1: GLint, x2: GLint, y2: GLint) {
        self.rectf(x1 as f32, y1 as f32, x2 as f32, y2 as f32);
    }

    /// The first `N` values of a `*v` argument, or `GL_INVALID_VALUE` if the slice is shorter.
    pub(crate) fn needs<const N: usize>(&mut self, v: &[GLfloat]) -> Option<[GLfloat; N]> {
        self.first::<N, GLfloat>(v)
    }

    /// The first `N` values of a `*v` argument of any type, or `GL_INVALID_VALUE` if the slice
    /// is shorter.
    pub(crate) fn first<const N: usize, T: Copy>(&mut self, v: &[T]) -> Option<[T; N]> {
        let head = v.get(..N).and_then(|h| <[T; N]>::try_from(h).ok());
        if head.is_none() {
            self.set_error(GL_INVALID_VALUE);
        }
        head
    }
}
