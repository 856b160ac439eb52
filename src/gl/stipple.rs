//! `glLineStipple` (GL 1.1 spec §3.4.2): which fragments of a line are drawn, by a 16-bit
//! pattern read one bit per `factor` fragments. The state lives in the raster state; the
//! renderer cuts stippled lines into their drawn pieces (`render::stipple`).

use super::consts::*;
use super::lists::ListCommand;
use super::types::*;
use super::Gl;

/// GL clamps the repeat factor to [1, 256] (§3.4.2; Mesa `_mesa_LineStipple`).
const MAX_STIPPLE_FACTOR: GLint = 256;

impl Gl {
    /// `glLineStipple(factor, pattern)`: no argument is an error, the factor is clamped to
    /// 1..=256; inside `begin`/`end` → `GL_INVALID_OPERATION`.
    pub fn line_stipple(&mut self, factor: GLint, pattern: GLushort) {
        if self.compiled(|| ListCommand::LineStipple(factor, pattern)) || self.reject_inside_begin_end() {
            return;
        }
        self.raster.line_stipple = (factor.clamp(1, MAX_STIPPLE_FACTOR), pattern);
        self.touch_state();
    }

    /// The stipple while `GL_LINE_STIPPLE` is on: (factor, pattern).
    pub(crate) fn enabled_line_stipple(&self) -> Option<(i32, u16)> {
        self.capability(GL_LINE_STIPPLE).then_some(self.raster.line_stipple)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_factor_is_clamped_and_nothing_is_an_error() {
        let mut gl = Gl::new(4, 4);
        gl.line_stipple(0, 0x00FF);
        assert_eq!(gl.raster.line_stipple, (1, 0x00FF));
        gl.line_stipple(1000, 1);
        assert_eq!(gl.raster.line_stipple, (256, 1));
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        assert_eq!(gl.enabled_line_stipple(), None);
        gl.enable(GL_LINE_STIPPLE);
        assert_eq!(gl.enabled_line_stipple(), Some((256, 1)));
    }
}
