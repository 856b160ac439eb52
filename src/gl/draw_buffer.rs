//! `glDrawBuffer` and `glReadBuffer` (GL 1.1 spec §4.2.1, §4.3.2; Mesa `main/buffers.c`): which
//! colour buffers draws write and which one reads take.
//!
//! Measured on Mesa 22.3 (OSMesa, and freeglut on Xvfb, single- and double-buffered alike):
//! `GL_NONE`, `GL_FRONT`, `GL_BACK`, `GL_LEFT`, `GL_FRONT_LEFT`, `GL_BACK_LEFT` and
//! `GL_FRONT_AND_BACK` are taken by both calls; the right buffers, the auxiliary buffers and
//! the colour attachments are `GL_INVALID_OPERATION` (no such buffer); any other name
//! `GL_INVALID_ENUM`. A single-buffered context's back buffer is its one buffer (OSMesa draws
//! `GL_BACK` into the caller's buffer).

use super::color_buffer::ColorBufferCall;
use super::consts::*;
use super::fragments::{BACK_BUFFER, FRONT_BUFFER};
use super::frame::Command;
use super::lists::ListCommand;
use super::pixel_transfer::PixelTransferCall;
use super::types::*;
use super::Gl;

/// The buffers a name reaches (front, back), or the error GL raises for it.
fn buffers_named(mode: GLenum) -> Result<u8, GLenum> {
    match mode {
        GL_NONE => Ok(0),
        GL_FRONT | GL_FRONT_LEFT => Ok(FRONT_BUFFER),
        GL_BACK | GL_BACK_LEFT => Ok(BACK_BUFFER),
        GL_LEFT | GL_FRONT_AND_BACK => Ok(FRONT_BUFFER | BACK_BUFFER),
        GL_RIGHT | GL_FRONT_RIGHT | GL_BACK_RIGHT | GL_AUX0..=GL_AUX3 => Err(GL_INVALID_OPERATION),
        // GL_COLOR_ATTACHMENT0 .. 15: no such buffer in a window's framebuffer.
        0x8CE0..=0x8CEF => Err(GL_INVALID_OPERATION),
        _ => Err(GL_INVALID_ENUM),
    }
}

impl Gl {
    /// Records a buffer swap in a double-buffered context (`glutSwapBuffers`); nothing in a
    /// single-buffered one. Inside `begin`/`end` GL would end the primitive's frame: ignored.
    pub fn record_swap_buffers(&mut self) {
        if self.server.framebuffer.double && !self.inside_begin_end() {
            self.recorder.frame.commands.push(Command::SwapBuffers);
            self.recorder.swaps += 1;
        }
    }

    /// How many buffer swaps this context has recorded ([`Gl::record_swap_buffers`]): how a
    /// main loop sees a frame presented outside the display callback (an idle callback or a
    /// timer that draws and swaps without posting a redisplay).
    #[must_use]
    pub fn buffer_swaps(&self) -> u64 {
        self.recorder.swaps
    }

    /// `glDrawBuffer`: the colour buffers draws and clears write (see the module's table).
    pub fn draw_buffer(&mut self, mode: GLenum) {
        if self.compiled_color_buffer_call(ColorBufferCall::DrawBuffer(mode)) {
            return;
        }
        match buffers_named(mode) {
            Ok(_) => self.server.color_buffer.draw_buffer = mode,
            Err(e) => return self.set_error(e),
        }
        self.touch_state();
    }

    /// `glReadBuffer`: the colour buffer `glReadPixels`, `glCopyPixels` and `glAccum` read.
    pub fn read_buffer(&mut self, mode: GLenum) {
        if self.compiled_state_call(|| ListCommand::PixelTransfer(PixelTransferCall::ReadBuffer(mode))) {
            return;
        }
        match buffers_named(mode) {
            Ok(_) => self.server.pixel_state.mode.read_buffer = mode,
            Err(e) => self.set_error(e),
        }
    }

    /// The buffers (`FRONT_BUFFER`, `BACK_BUFFER` bits) `mode` reaches in this context: a
    /// single-buffered context has one buffer, the front, which `GL_BACK` reaches too.
    /// Whether the read buffer (`glReadBuffer`) is the back one: what a reader of the window
    /// hands `glReadPixels`, `glCopyPixels` and `glCopyTexImage` (a single-buffered context
    /// reads its front buffer whatever is named).
    #[must_use]
    pub fn reads_back_buffer(&self) -> bool {
        self.buffers_of(self.server.pixel_state.mode.read_buffer) & super::fragments::BACK_BUFFER != 0
    }

    pub(crate) fn buffers_of(&self, mode: GLenum) -> u8 {
        let bits = buffers_named(mode).unwrap_or(0);
        if self.server.framebuffer.double || bits == 0 {
            bits
        } else {
            FRONT_BUFFER
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mesa_s_table() {
        let mut gl = Gl::new(4, 4);
        for (mode, error) in [
            (GL_NONE, GL_NO_ERROR),
            (GL_BACK, GL_NO_ERROR),
            (GL_FRONT_AND_BACK, GL_NO_ERROR),
            (GL_RIGHT, GL_INVALID_OPERATION),
            (GL_AUX3, GL_INVALID_OPERATION),
            (0x8CE0, GL_INVALID_OPERATION),
            (GL_DEPTH, GL_INVALID_ENUM),
        ] {
            gl.draw_buffer(mode);
            assert_eq!(gl.get_error(), error, "glDrawBuffer({mode:#x})");
            gl.read_buffer(mode);
            assert_eq!(gl.get_error(), error, "glReadBuffer({mode:#x})");
        }
        let mut v = [0];
        gl.get_integerv(GL_DRAW_BUFFER, &mut v);
        assert_eq!(v, [GL_FRONT_AND_BACK as i32]);
    }
}
