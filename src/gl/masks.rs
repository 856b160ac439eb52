//! The colour write mask, the scissor box and the logic op (GL 1.1 spec §4.1.2, §4.1.7,
//! §4.2.2; Mesa `main/blend.c`, `main/scissor.c`, `main/logicop.c`): `glColorMask`,
//! `glScissor`, `glLogicOp`. (`glDepthMask` is the depth group's, `depth.rs`.)

use super::consts::*;
use super::fragments::FragmentCall;
use super::types::*;
use super::Gl;

impl Gl {
    /// `glColorMask`: which of red, green, blue and alpha draws and clears write.
    pub fn color_mask(&mut self, red: GLboolean, green: GLboolean, blue: GLboolean, alpha: GLboolean) {
        if self.compiled_fragment(FragmentCall::ColorMask([red, green, blue, alpha])) {
            return;
        }
        self.server.fragments.color_write = [red, green, blue, alpha].map(|c| c != GL_FALSE);
        self.touch_state();
    }

    /// `glScissor`: the box (origin bottom-left) outside which `GL_SCISSOR_TEST` discards
    /// fragments and clears write nothing. A negative width or height → `GL_INVALID_VALUE`.
    pub fn scissor(&mut self, x: GLint, y: GLint, width: GLsizei, height: GLsizei) {
        if self.compiled_fragment(FragmentCall::Scissor([x, y, width, height])) {
            return;
        }
        if width < 0 || height < 0 {
            return self.set_error(GL_INVALID_VALUE);
        }
        self.server.fragments.scissor = [x, y, width, height];
        self.touch_state();
    }

    /// `glLogicOp`: the operation (`GL_CLEAR` .. `GL_SET`, else `GL_INVALID_ENUM`) between the
    /// fragment's colour and the buffer's while `GL_COLOR_LOGIC_OP` is on.
    pub fn logic_op(&mut self, opcode: GLenum) {
        if self.compiled_fragment(FragmentCall::LogicOp(opcode)) {
            return;
        }
        if !(GL_CLEAR..=GL_SET).contains(&opcode) {
            return self.set_error(GL_INVALID_ENUM);
        }
        self.server.fragments.logic_op = opcode;
        self.touch_state();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mesa_s_errors() {
        let mut gl = Gl::new(4, 4);
        gl.scissor(0, 0, -1, 1);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
        gl.logic_op(0x1234);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
        gl.logic_op(GL_XOR);
        gl.color_mask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
        let mut v = [0; 4];
        gl.get_integerv(GL_COLOR_WRITEMASK, &mut v);
        assert_eq!(v, [1, 0, 1, 0]);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
    }
}
