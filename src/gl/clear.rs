//! `glClear`, `glFlush` and `glFinish` (GL 1.1 spec §4.2.3, §5.5): the framebuffer calls that
//! belong to no attribute group.

use super::consts::*;
use super::frame::Command;
use super::lists::ListCommand;
use super::types::*;
use super::Gl;

impl Gl {
    /// `glClear`: bits other than colour, depth, stencil and accum → `GL_INVALID_VALUE`.
    /// Records a clear of the whole drawable (no scissor), as GL does.
    pub fn clear(&mut self, mask: GLbitfield) {
        if self.compiled(|| ListCommand::Clear(mask)) {
            return;
        }
        if self.reject_inside_begin_end() {
            return;
        }
        let known = GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | GL_ACCUM_BUFFER_BIT;
        if mask & !known != 0 {
            return self.set_error(GL_INVALID_VALUE);
        }
        let (color, depth) = (self.server.color_buffer.clear_color, self.server.depth.clear);
        let (stencil, accum, tests) = (self.server.stencil.clear, self.server.clear_accum, self.fragment_tests());
        self.recorder.frame.commands.push(Command::Clear { mask, color, depth, stencil, accum, tests });
    }

    /// `glFlush`: the recording is already complete; nothing to do.
    pub fn flush(&mut self) {
        self.reject_inside_begin_end();
    }

    /// `glFinish`: as [`Gl::flush`].
    pub fn finish(&mut self) {
        self.reject_inside_begin_end();
    }
}
