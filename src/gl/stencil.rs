//! The stencil test's calls (GL 1.1 spec §4.1.4, §4.2.2, §4.2.3; Mesa `main/stencil.c`):
//! `glStencilFunc`, `glStencilOp`, `glStencilMask`, `glClearStencil`. The state is in
//! [`PerFragment`](super::fragments::PerFragment); the rasterisers test and update the buffer.

use super::consts::*;
use super::fragments::FragmentCall;
use super::lists::ListCommand;
use super::types::*;
use super::Gl;

/// GL 1.4's wrapping operations (`GL/glext.h`), which Mesa takes in every context.
pub(crate) const GL_INCR_WRAP: GLenum = 0x8507;
/// See [`GL_INCR_WRAP`].
pub(crate) const GL_DECR_WRAP: GLenum = 0x8508;

/// Whether `op` is a stencil operation Mesa takes (GL 1.1's six and GL 1.4's wrapping two).
fn stencil_op_known(op: GLenum) -> bool {
    matches!(op, GL_KEEP | GL_ZERO | GL_REPLACE | GL_INCR | GL_DECR | GL_INVERT | GL_INCR_WRAP | GL_DECR_WRAP)
}

impl Gl {
    /// Records a fragment call in the list being compiled; true when it must not run now.
    pub(crate) fn compiled_fragment(&mut self, call: FragmentCall) -> bool {
        self.compiled_state_call(|| ListCommand::Fragment(call))
    }

    /// `glStencilFunc(func, ref, mask)`: the comparison (`GL_NEVER` .. `GL_ALWAYS`, else
    /// `GL_INVALID_ENUM`), the reference (kept as given; compared clamped to the buffer's
    /// range) and the mask ANDed with both sides.
    pub fn stencil_func(&mut self, func: GLenum, reference: GLint, mask: GLuint) {
        if self.compiled_fragment(FragmentCall::StencilFunc(func, reference, mask)) {
            return;
        }
        if !(GL_NEVER..=GL_ALWAYS).contains(&func) {
            return self.set_error(GL_INVALID_ENUM);
        }
        let s = &mut self.server.fragments.stencil;
        (s.func, s.reference, s.value_mask) = (func, reference, mask);
        self.touch_state();
    }

    /// `glStencilOp(fail, zfail, zpass)`: what the stencil test's failure, the depth test's
    /// failure and both tests' passing do to the stencil value. An operation other than
    /// `GL_KEEP`, `GL_ZERO`, `GL_REPLACE`, `GL_INCR`, `GL_DECR`, `GL_INVERT`, `GL_INCR_WRAP`,
    /// `GL_DECR_WRAP` → `GL_INVALID_ENUM`.
    pub fn stencil_op(&mut self, fail: GLenum, zfail: GLenum, zpass: GLenum) {
        if self.compiled_fragment(FragmentCall::StencilOp(fail, zfail, zpass)) {
            return;
        }
        if ![fail, zfail, zpass].into_iter().all(stencil_op_known) {
            return self.set_error(GL_INVALID_ENUM);
        }
        self.server.fragments.stencil.ops = [fail, zfail, zpass];
        self.touch_state();
    }

    /// `glStencilMask`: the bits of the stencil buffer that draws and clears write.
    pub fn stencil_mask(&mut self, mask: GLuint) {
        if self.compiled_fragment(FragmentCall::StencilMask(mask)) {
            return;
        }
        self.server.fragments.stencil.write_mask = mask;
        self.touch_state();
    }

    /// `glClearStencil`: the value `glClear(GL_STENCIL_BUFFER_BIT)` writes (kept as given,
    /// masked to the buffer's bits when clearing).
    pub fn clear_stencil(&mut self, s: GLint) {
        if self.compiled_fragment(FragmentCall::ClearStencil(s)) {
            return;
        }
        self.server.fragments.clear_stencil = s;
    }
}

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
