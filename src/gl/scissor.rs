//! The scissor attribute group (GL 1.1 spec §4.1.2; table 6.14; Mesa `main/scissor.c`):
//! `glScissor` and its box, which `GL_SCISSOR_BIT` saves, with the group's `glGet` row and its
//! enable. A recorded primitive's [`FragmentTests`](super::FragmentTests) carries the box while
//! `GL_SCISSOR_TEST` is on. A display list holds the call as `ListCommand::Scissor`.

use super::consts::*;
use super::lists::ListCommand;
use super::state_var::{put, row, Kind, StateVar};
use super::types::*;
use super::Gl;

/// The enables GL files under the group (GL 1.1 table 6.14).
pub(crate) const SCISSOR_ENABLES: &[GLenum] = &[GL_SCISSOR_TEST];

impl Gl {
    /// `glScissor`: the box (origin bottom-left) outside which `GL_SCISSOR_TEST` discards
    /// fragments and clears write nothing. A negative width or height → `GL_INVALID_VALUE`.
    pub fn scissor(&mut self, x: GLint, y: GLint, width: GLsizei, height: GLsizei) {
        if self.compiled_state_call(|| ListCommand::Scissor([x, y, width, height])) {
            return;
        }
        if width < 0 || height < 0 {
            return self.set_error(GL_INVALID_VALUE);
        }
        self.server.scissor = [x, y, width, height];
        self.touch_state();
    }
}

/// The group's `glGet` row.
pub(crate) static GET_ROWS: &[StateVar] = &[row(GL_SCISSOR_BOX, 4, Kind::Int, |gl, o| put(o, &gl.server.scissor))];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_group_as_mesa_keeps_it() {
        let mut gl = Gl::new(4, 6);
        gl.scissor(0, 0, -1, 1);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
        gl.push_attrib(GL_SCISSOR_BIT);
        gl.scissor(1, 2, 3, 4);
        gl.enable(GL_SCISSOR_TEST);
        let mut v = [0; 4];
        gl.get_integerv(GL_SCISSOR_BOX, &mut v);
        assert_eq!(v, [1, 2, 3, 4]);
        gl.pop_attrib();
        gl.get_integerv(GL_SCISSOR_BOX, &mut v);
        assert_eq!((v, gl.is_enabled(GL_SCISSOR_TEST)), ([0, 0, 4, 6], GL_FALSE));
    }
}
