//! The stencil buffer attribute group (GL 1.1 spec §4.1.4 the test, §4.2.2 the write mask,
//! §4.2.3 the clear value; table 6.15; Mesa `main/stencil.c`): `glStencilFunc`, `glStencilOp`,
//! `glStencilMask`, `glClearStencil`, in one struct as `GL_STENCIL_BUFFER_BIT` saves it, with
//! the group's display-list record, its `glGet` rows and its enable. A recorded primitive's
//! [`FragmentTests`](super::FragmentTests) carries the test; the rasterisers test and update
//! the buffer.

use super::consts::*;
use super::fragments::Stencil;
use super::lists::ListCommand;
use super::state_var::{put_enum, row, Kind, StateVar};
use super::types::*;
use super::Gl;

/// Whether `op` is a stencil operation Mesa takes (GL 1.1's six and GL 1.4's wrapping two).
fn stencil_op_known(op: GLenum) -> bool {
    matches!(op, GL_KEEP | GL_ZERO | GL_REPLACE | GL_INCR | GL_DECR | GL_INVERT | GL_INCR_WRAP | GL_DECR_WRAP)
}

/// `GL_STENCIL_BUFFER_BIT`'s state (its enable aside).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct StencilBuffer {
    /// `glStencilFunc`, `glStencilOp` and `glStencilMask`.
    pub test: Stencil,
    /// `glClearStencil`, kept as given.
    pub clear: GLint,
}

/// A stencil call as a display list holds it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum StencilCall {
    Func(GLenum, GLint, GLuint),
    Op(GLenum, GLenum, GLenum),
    Mask(GLuint),
    Clear(GLint),
}

/// The enables GL files under the group (GL 1.1 table 6.15).
pub(crate) const STENCIL_ENABLES: &[GLenum] = &[GL_STENCIL_TEST];

impl Gl {
    /// Records a stencil call in the list being compiled, or refuses it inside `begin`/`end`;
    /// true when it must not run now.
    fn compiled_stencil_call(&mut self, call: StencilCall) -> bool {
        self.compiled_state_call(|| ListCommand::Stencil(call))
    }

    /// `glStencilFunc(func, ref, mask)`: the comparison (`GL_NEVER` .. `GL_ALWAYS`, else
    /// `GL_INVALID_ENUM`), the reference (kept as given; compared clamped to the buffer's
    /// range) and the mask ANDed with both sides.
    pub fn stencil_func(&mut self, func: GLenum, reference: GLint, mask: GLuint) {
        if self.compiled_stencil_call(StencilCall::Func(func, reference, mask)) {
            return;
        }
        if !(GL_NEVER..=GL_ALWAYS).contains(&func) {
            return self.set_error(GL_INVALID_ENUM);
        }
        let s = &mut self.server.stencil.test;
        (s.func, s.reference, s.value_mask) = (func, reference, mask);
        self.touch_state();
    }

    /// `glStencilOp(fail, zfail, zpass)`: what the stencil test's failure, the depth test's
    /// failure and both tests' passing do to the stencil value. An operation other than
    /// `GL_KEEP`, `GL_ZERO`, `GL_REPLACE`, `GL_INCR`, `GL_DECR`, `GL_INVERT`, `GL_INCR_WRAP`,
    /// `GL_DECR_WRAP` → `GL_INVALID_ENUM`.
    pub fn stencil_op(&mut self, fail: GLenum, zfail: GLenum, zpass: GLenum) {
        if self.compiled_stencil_call(StencilCall::Op(fail, zfail, zpass)) {
            return;
        }
        if ![fail, zfail, zpass].into_iter().all(stencil_op_known) {
            return self.set_error(GL_INVALID_ENUM);
        }
        self.server.stencil.test.ops = [fail, zfail, zpass];
        self.touch_state();
    }

    /// `glStencilMask`: the bits of the stencil buffer that draws and clears write.
    pub fn stencil_mask(&mut self, mask: GLuint) {
        if self.compiled_stencil_call(StencilCall::Mask(mask)) {
            return;
        }
        self.server.stencil.test.write_mask = mask;
        self.touch_state();
    }

    /// `glClearStencil`: the value `glClear(GL_STENCIL_BUFFER_BIT)` writes (kept as given,
    /// masked to the buffer's bits when clearing).
    pub fn clear_stencil(&mut self, s: GLint) {
        if self.compiled_stencil_call(StencilCall::Clear(s)) {
            return;
        }
        self.server.stencil.clear = s;
    }

    /// Replays a listed stencil call.
    pub(crate) fn replay_stencil_call(&mut self, call: StencilCall) {
        match call {
            StencilCall::Func(func, reference, mask) => self.stencil_func(func, reference, mask),
            StencilCall::Op(fail, zfail, zpass) => self.stencil_op(fail, zfail, zpass),
            StencilCall::Mask(mask) => self.stencil_mask(mask),
            StencilCall::Clear(s) => self.clear_stencil(s),
        }
    }
}

/// The group's `glGet` rows. The reference reads clamped to the buffer's range; the value mask
/// is unsigned, so one above 2³¹ − 1 reads as 2³¹ − 1 in `glGetIntegerv` (measured).
pub(crate) static GET_ROWS: &[StateVar] = &[
    row(GL_STENCIL_FUNC, 1, Kind::Int, |gl, o| put_enum(o, gl.server.stencil.test.func)),
    row(GL_STENCIL_VALUE_MASK, 1, Kind::Int, |gl, o| o[0] = f64::from(gl.server.stencil.test.value_mask)),
    row(GL_STENCIL_REF, 1, Kind::Int, |gl, o| {
        o[0] = f64::from(gl.server.stencil.test.reference.clamp(0, gl.stencil_max() as GLint))
    }),
    row(GL_STENCIL_FAIL, 1, Kind::Int, |gl, o| put_enum(o, gl.server.stencil.test.ops[0])),
    row(GL_STENCIL_PASS_DEPTH_FAIL, 1, Kind::Int, |gl, o| put_enum(o, gl.server.stencil.test.ops[1])),
    row(GL_STENCIL_PASS_DEPTH_PASS, 1, Kind::Int, |gl, o| put_enum(o, gl.server.stencil.test.ops[2])),
    row(GL_STENCIL_WRITEMASK, 1, Kind::Int, |gl, o| o[0] = f64::from(gl.server.stencil.test.write_mask)),
    row(GL_STENCIL_CLEAR_VALUE, 1, Kind::Int, |gl, o| o[0] = f64::from(gl.server.stencil.clear)),
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mesa_s_errors() {
        let mut gl = Gl::new(4, 4);
        gl.stencil_func(0x1234, 0, 0);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
        gl.stencil_op(GL_KEEP, GL_KEEP, 0x1234);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
        gl.stencil_op(GL_INCR_WRAP, GL_DECR_WRAP, GL_INVERT);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        gl.begin(GL_POINTS);
        gl.stencil_mask(3);
        gl.end();
        assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
        // Measured on Mesa 22.3: a reference of 300 reads back as 255 with 8 bits.
        gl.stencil_func(GL_LESS, 300, 0x0f);
        let mut v = [0];
        gl.get_integerv(GL_STENCIL_REF, &mut v);
        assert_eq!(v, [255]);
    }
}
