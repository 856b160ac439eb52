//! The polygon attribute group (GL 1.1 spec §3.5; table 6.8; Mesa `main/polygon.c`):
//! `glPolygonMode`, `glFrontFace`, `glCullFace` and `glPolygonOffset`, in one struct as
//! `GL_POLYGON_BIT` saves it with its enables, the calls' list records and the `glGet` rows.
//! The pattern of `depth.rs`. (The stipple is its own group, `stipple.rs`; how an offset is
//! applied, `offset.rs`.)

use super::consts::*;
use super::lists::ListCommand;
use super::state_var::{put, put_enum, row, Kind, StateVar};
use super::types::*;
use super::Gl;

/// `GL_POLYGON_BIT`'s state (its enables aside).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Polygon {
    /// `glPolygonMode`: the front and back faces' modes (`GL_POINT`, `GL_LINE`, `GL_FILL`).
    pub mode: [GLenum; 2],
    /// `glFrontFace`: `GL_CCW` or `GL_CW`.
    pub front_face: GLenum,
    /// `glCullFace`: the faces `GL_CULL_FACE` drops.
    pub cull_face: GLenum,
    /// `glPolygonOffset`: factor and units.
    pub offset: (f32, f32),
}

impl Default for Polygon {
    fn default() -> Self {
        Self { mode: [GL_FILL, GL_FILL], front_face: GL_CCW, cull_face: GL_BACK, offset: (0.0, 0.0) }
    }
}

/// A polygon call as a display list holds it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum PolygonCall {
    Mode(GLenum, GLenum),
    FrontFace(GLenum),
    CullFace(GLenum),
    Offset(GLfloat, GLfloat),
}

/// The enables GL files under the group (GL 1.1 table 6.8).
pub(crate) const POLYGON_ENABLES: &[GLenum] = &[
    GL_CULL_FACE,
    GL_POLYGON_SMOOTH,
    GL_POLYGON_OFFSET_POINT,
    GL_POLYGON_OFFSET_LINE,
    GL_POLYGON_OFFSET_FILL,
    GL_POLYGON_STIPPLE,
];

impl Gl {
    /// `glPolygonMode(face, mode)`: a mode other than `GL_POINT`, `GL_LINE`, `GL_FILL`, then a
    /// face other than `GL_FRONT`, `GL_BACK`, `GL_FRONT_AND_BACK` → `GL_INVALID_ENUM`.
    pub fn polygon_mode(&mut self, face: GLenum, mode: GLenum) {
        if self.compiled_state_call(|| ListCommand::Polygon(PolygonCall::Mode(face, mode))) {
            return;
        }
        if !matches!(mode, GL_POINT | GL_LINE | GL_FILL) {
            return self.set_error(GL_INVALID_ENUM);
        }
        let modes = &mut self.server.polygon.mode;
        match face {
            GL_FRONT => modes[0] = mode,
            GL_BACK => modes[1] = mode,
            GL_FRONT_AND_BACK => *modes = [mode, mode],
            _ => return self.set_error(GL_INVALID_ENUM),
        }
        self.touch_state();
    }

    /// `glGetIntegerv(GL_POLYGON_MODE)` for GLU: the front and back modes, which GLU saves
    /// around a surface and puts back with `glPolygonMode` (`glsurfeval.cc`).
    pub(crate) fn polygon_modes(&self) -> [GLenum; 2] {
        self.server.polygon.mode
    }

    /// `glFrontFace`: `GL_CW` or `GL_CCW`, else `GL_INVALID_ENUM`.
    pub fn front_face(&mut self, mode: GLenum) {
        if self.compiled_state_call(|| ListCommand::Polygon(PolygonCall::FrontFace(mode))) {
            return;
        }
        if mode != GL_CW && mode != GL_CCW {
            return self.set_error(GL_INVALID_ENUM);
        }
        self.server.polygon.front_face = mode;
        self.touch_state();
    }

    /// `glCullFace`: `GL_FRONT`, `GL_BACK` or `GL_FRONT_AND_BACK`, else `GL_INVALID_ENUM`.
    pub fn cull_face(&mut self, mode: GLenum) {
        if self.compiled_state_call(|| ListCommand::Polygon(PolygonCall::CullFace(mode))) {
            return;
        }
        if !matches!(mode, GL_FRONT | GL_BACK | GL_FRONT_AND_BACK) {
            return self.set_error(GL_INVALID_ENUM);
        }
        self.server.polygon.cull_face = mode;
        self.touch_state();
    }

    /// `glPolygonOffset(factor, units)`: no value is an error (Mesa stores any float).
    pub fn polygon_offset(&mut self, factor: GLfloat, units: GLfloat) {
        if self.compiled_state_call(|| ListCommand::Polygon(PolygonCall::Offset(factor, units))) {
            return;
        }
        self.server.polygon.offset = (factor, units);
        self.touch_state();
    }

    /// Replays a listed polygon call.
    pub(crate) fn replay_polygon_call(&mut self, call: PolygonCall) {
        match call {
            PolygonCall::Mode(face, mode) => self.polygon_mode(face, mode),
            PolygonCall::FrontFace(mode) => self.front_face(mode),
            PolygonCall::CullFace(mode) => self.cull_face(mode),
            PolygonCall::Offset(factor, units) => self.polygon_offset(factor, units),
        }
    }
}

/// The group's `glGet` rows.
pub(crate) static GET_ROWS: &[StateVar] = &[
    row(GL_CULL_FACE_MODE, 1, Kind::Int, |gl, o| put_enum(o, gl.server.polygon.cull_face)),
    row(GL_FRONT_FACE, 1, Kind::Int, |gl, o| put_enum(o, gl.server.polygon.front_face)),
    row(GL_POLYGON_MODE, 2, Kind::Int, |gl, o| put(o, &gl.server.polygon.mode)),
    row(GL_POLYGON_OFFSET_FACTOR, 1, Kind::Float, |gl, o| o[0] = gl.server.polygon.offset.0.into()),
    row(GL_POLYGON_OFFSET_UNITS, 1, Kind::Float, |gl, o| o[0] = gl.server.polygon.offset.1.into()),
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_group_is_saved_whole_and_its_errors_are_mesas() {
        let mut gl = Gl::new(4, 4);
        gl.polygon_mode(0x1234, 0x1234);
        gl.front_face(GL_FRONT);
        gl.cull_face(GL_CW);
        assert_eq!((gl.get_error(), gl.server.polygon), (GL_INVALID_ENUM, Polygon::default()));
        gl.push_attrib(GL_POLYGON_BIT);
        gl.polygon_mode(GL_BACK, GL_LINE);
        gl.front_face(GL_CW);
        gl.cull_face(GL_FRONT_AND_BACK);
        gl.polygon_offset(1.5, -2.0);
        gl.enable(GL_CULL_FACE);
        let mut v = [0; 2];
        gl.get_integerv(GL_POLYGON_MODE, &mut v);
        assert_eq!(v.map(|m| m as GLenum), [GL_FILL, GL_LINE]);
        gl.pop_attrib();
        assert_eq!((gl.server.polygon, gl.is_enabled(GL_CULL_FACE)), (Polygon::default(), GL_FALSE));
        gl.new_list(1, GL_COMPILE);
        gl.polygon_offset(1.0, 1.0);
        gl.end_list();
        gl.call_list(1);
        assert_eq!(gl.server.polygon.offset, (1.0, 1.0));
    }
}
