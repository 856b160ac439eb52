//! The accumulation buffer attribute group (GL 1.1 spec §4.2.4; table 6.16; Mesa
//! `main/accum.c`): `glAccum` and `glClearAccum`, the clear value `GL_ACCUM_BUFFER_BIT` saves,
//! the group's display-list record and its `glGet` row. `glAccum` is recorded in the frame as a [`Command::Accum`], carried out
//! by the rasterisers on Mesa's buffer: signed 16-bit integers a channel (`RGBA_SNORM16`), with
//! Mesa's truncations and wrapping (`render::accum`).

use super::consts::*;
use super::frame::{Accumulation, Command};
use super::lists::ListCommand;
use super::state_var::{put, row, Kind, StateVar};
use super::types::*;
use super::Gl;

/// An accumulation call as a display list holds it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum AccumCall {
    Accum(GLenum, GLfloat),
    Clear([GLfloat; 4]),
}

impl Gl {
    /// `glAccum(op, value)`: `GL_ACCUM`, `GL_LOAD`, `GL_ADD`, `GL_MULT` or `GL_RETURN` (another
    /// → `GL_INVALID_ENUM`), within the scissor box when the scissor test is on. Without an
    /// accumulation buffer → `GL_INVALID_OPERATION` (Mesa's order: the operation first).
    pub fn accum(&mut self, op: GLenum, value: GLfloat) {
        if self.compiled_state_call(|| ListCommand::Accum(AccumCall::Accum(op, value))) {
            return;
        }
        if !matches!(op, GL_ACCUM | GL_LOAD | GL_ADD | GL_MULT | GL_RETURN) {
            return self.set_error(GL_INVALID_ENUM);
        }
        if self.server.framebuffer.accum_bits == 0 {
            return self.set_error(GL_INVALID_OPERATION);
        }
        let tests = self.fragment_tests();
        let read = self.buffers_of(self.server.pixel_state.mode.read_buffer);
        self.recorder.frame.commands.push(Command::Accum(Accumulation { op, value, tests, read }));
    }

    /// `glClearAccum`: the value `glClear(GL_ACCUM_BUFFER_BIT)` writes, each component clamped
    /// to [−1, 1].
    pub fn clear_accum(&mut self, red: GLfloat, green: GLfloat, blue: GLfloat, alpha: GLfloat) {
        if self.compiled_state_call(|| ListCommand::Accum(AccumCall::Clear([red, green, blue, alpha]))) {
            return;
        }
        self.server.clear_accum = [red, green, blue, alpha].map(|c| c.clamp(-1.0, 1.0));
    }

    /// Replays a listed accumulation call.
    pub(crate) fn replay_accum_call(&mut self, call: AccumCall) {
        match call {
            AccumCall::Accum(op, value) => self.accum(op, value),
            AccumCall::Clear([r, g, b, a]) => self.clear_accum(r, g, b, a),
        }
    }
}

/// The group's `glGet` row.
pub(crate) static GET_ROWS: &[StateVar] =
    &[row(GL_ACCUM_CLEAR_VALUE, 4, Kind::Normalized, |gl, o| put(o, &gl.server.clear_accum))];

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gl::fragments::BufferConfig;

    #[test]
    fn mesa_s_errors_and_order() {
        let mut gl = Gl::new(4, 4);
        gl.accum(0x1234, 1.0);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
        gl.set_buffer_config(BufferConfig { accum_bits: 0, ..BufferConfig::default() });
        gl.accum(0x1234, 1.0);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
        gl.accum(GL_LOAD, 1.0);
        assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
        gl.clear_accum(-2.0, 0.5, 2.0, 0.25);
        let mut v = [0.0; 4];
        gl.get_floatv(GL_ACCUM_CLEAR_VALUE, &mut v);
        assert_eq!(v, [-1.0, 0.5, 1.0, 0.25]);
    }
}
