//! The line attribute group (GL 1.1 spec §3.4; table 6.8; Mesa `main/lines.c`):
//! `glLineWidth` and `glLineStipple` (which fragments of a line are drawn: a 16-bit pattern
//! read one bit per `factor` fragments; the renderer cuts stippled lines into their drawn
//! pieces, `render::stipple`), in one struct as `GL_LINE_BIT` saves it with its enables, the
//! calls' list records and the `glGet` rows. The pattern of `depth.rs`.

use super::consts::*;
use super::lists::ListCommand;
use super::state_var::{limit, row, Kind, StateVar};
use super::types::*;
use super::Gl;

/// GL clamps the repeat factor to [1, 256] (§3.4.2; Mesa `_mesa_LineStipple`).
const MAX_STIPPLE_FACTOR: GLint = 256;

/// `GL_LINE_BIT`'s state (its enables aside).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Line {
    /// `glLineWidth`.
    pub width: f32,
    /// `glLineStipple`: the repeat factor (clamped to 1..=256) and the pattern.
    pub stipple: (i32, u16),
}

impl Default for Line {
    fn default() -> Self {
        Self { width: 1.0, stipple: (1, 0xFFFF) }
    }
}

/// A line call as a display list holds it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum LineCall {
    Width(GLfloat),
    Stipple(GLint, GLushort),
}

/// The enables GL files under the group (GL 1.1 table 6.8).
pub(crate) const LINE_ENABLES: &[GLenum] = &[GL_LINE_SMOOTH, GL_LINE_STIPPLE];

impl Gl {
    /// `glLineWidth`: `width <= 0` (or NaN) → `GL_INVALID_VALUE`.
    pub fn line_width(&mut self, width: GLfloat) {
        if self.compiled_state_call(|| ListCommand::Line(LineCall::Width(width))) {
            return;
        }
        if width.is_nan() || width <= 0.0 {
            return self.set_error(GL_INVALID_VALUE);
        }
        self.server.line.width = width;
        self.touch_state();
    }

    /// `glLineStipple(factor, pattern)`: no argument is an error, the factor is clamped to
    /// 1..=256.
    pub fn line_stipple(&mut self, factor: GLint, pattern: GLushort) {
        if self.compiled_state_call(|| ListCommand::Line(LineCall::Stipple(factor, pattern))) {
            return;
        }
        self.server.line.stipple = (factor.clamp(1, MAX_STIPPLE_FACTOR), pattern);
        self.touch_state();
    }

    /// The stipple while `GL_LINE_STIPPLE` is on: (factor, pattern).
    pub(crate) fn enabled_line_stipple(&self) -> Option<(i32, u16)> {
        self.capability(GL_LINE_STIPPLE).then_some(self.server.line.stipple)
    }

    /// Replays a listed line call.
    pub(crate) fn replay_line_call(&mut self, call: LineCall) {
        match call {
            LineCall::Width(width) => self.line_width(width),
            LineCall::Stipple(factor, pattern) => self.line_stipple(factor, pattern),
        }
    }
}

/// The group's `glGet` rows.
pub(crate) static GET_ROWS: &[StateVar] = &[
    row(GL_LINE_WIDTH, 1, Kind::Float, |gl, o| o[0] = gl.server.line.width.into()),
    row(GL_LINE_STIPPLE_PATTERN, 1, Kind::Int, |gl, o| o[0] = gl.server.line.stipple.1.into()),
    row(GL_LINE_STIPPLE_REPEAT, 1, Kind::Int, |gl, o| o[0] = gl.server.line.stipple.0.into()),
    limit!(GL_LINE_WIDTH_RANGE, 1, 255),
    limit!(GL_LINE_WIDTH_GRANULARITY, 0.1f32),
    limit!(GL_ALIASED_LINE_WIDTH_RANGE, 1, 255),
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_factor_is_clamped_and_nothing_is_an_error() {
        let mut gl = Gl::new(4, 4);
        gl.line_stipple(0, 0x00FF);
        assert_eq!(gl.server.line.stipple, (1, 0x00FF));
        gl.line_stipple(1000, 1);
        assert_eq!(gl.server.line.stipple, (256, 1));
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        assert_eq!(gl.enabled_line_stipple(), None);
        gl.enable(GL_LINE_STIPPLE);
        assert_eq!(gl.enabled_line_stipple(), Some((256, 1)));
    }

    #[test]
    fn the_group_is_saved_whole_and_compiled() {
        let mut gl = Gl::new(4, 4);
        gl.push_attrib(GL_LINE_BIT);
        gl.line_width(3.0);
        gl.line_stipple(2, 0xF0F0);
        gl.enable(GL_LINE_STIPPLE);
        gl.line_width(-1.0);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
        let mut v = [0.0; 1];
        gl.get_floatv(GL_LINE_WIDTH, &mut v);
        assert_eq!(v, [3.0]);
        gl.pop_attrib();
        assert_eq!((gl.server.line, gl.is_enabled(GL_LINE_STIPPLE)), (Line::default(), GL_FALSE));
        gl.new_list(1, GL_COMPILE);
        gl.line_width(2.0);
        gl.end_list();
        assert_eq!(gl.server.line.width, 1.0);
        gl.call_list(1);
        assert_eq!(gl.server.line.width, 2.0);
    }
}
