//! The point attribute group (GL 1.1 spec §3.3; table 6.8; Mesa `main/points.c`):
//! `glPointSize`, in one struct as `GL_POINT_BIT` saves it with `GL_POINT_SMOOTH`, its list
//! record, its `glGet` row. The pattern of `depth.rs`.

use super::consts::*;
use super::lists::ListCommand;
use super::state_var::{limit, row, Kind, StateVar};
use super::types::*;
use super::Gl;

/// `GL_POINT_BIT`'s state (its enable aside).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Point {
    /// `glPointSize`: the diameter, in pixels, of a rasterised point.
    pub size: f32,
}

impl Default for Point {
    fn default() -> Self {
        Self { size: 1.0 }
    }
}

/// A point call as a display list holds it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum PointCall {
    Size(GLfloat),
}

/// The enables GL files under the group (GL 1.1 table 6.8).
pub(crate) const POINT_ENABLES: &[GLenum] = &[GL_POINT_SMOOTH];

impl Gl {
    /// `glPointSize`: `size <= 0` (or NaN) → `GL_INVALID_VALUE`; inside `begin`/`end` →
    /// `GL_INVALID_OPERATION`. Compiled into display lists.
    pub fn point_size(&mut self, size: GLfloat) {
        if self.compiled_state_call(|| ListCommand::Point(PointCall::Size(size))) {
            return;
        }
        if size.is_nan() || size <= 0.0 {
            return self.set_error(GL_INVALID_VALUE);
        }
        self.server.point.size = size;
        self.touch_state();
    }

    /// Replays a listed point call.
    pub(crate) fn replay_point_call(&mut self, call: PointCall) {
        match call {
            PointCall::Size(size) => self.point_size(size),
        }
    }
}

/// The group's `glGet` row.
pub(crate) static GET_ROWS: &[StateVar] = &[
    row(GL_POINT_SIZE, 1, Kind::Float, |gl, o| o[0] = gl.server.point.size.into()),
    limit!(GL_POINT_SIZE_RANGE, 1, 255),
    limit!(GL_POINT_SIZE_GRANULARITY, 0.1f32),
    limit!(GL_ALIASED_POINT_SIZE_RANGE, 1, 255),
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_group_as_mesa_keeps_it() {
        let mut gl = Gl::new(4, 4);
        gl.point_size(0.0);
        gl.point_size(f32::NAN);
        assert_eq!((gl.get_error(), gl.server.point.size), (GL_INVALID_VALUE, 1.0));
        gl.push_attrib(GL_POINT_BIT);
        gl.point_size(5.0);
        gl.enable(GL_POINT_SMOOTH);
        let mut v = [0];
        gl.get_integerv(GL_POINT_SIZE, &mut v);
        assert_eq!(v, [5]);
        gl.pop_attrib();
        assert_eq!((gl.server.point, gl.is_enabled(GL_POINT_SMOOTH)), (Point::default(), GL_FALSE));
    }
}
