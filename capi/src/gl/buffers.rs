//! GL 1.5's buffer objects (`GL_ARB_vertex_buffer_object`): `glGenBuffers` … `glUnmapBuffer`,
//! each under its ARB name too, one function for both.
//!
//! `glMapBuffer` hands out the address of gleval's data store ([`gleval::gl::BufferMap::as_ptr`]),
//! which C may read and write as the access allows until the mapping ends (the store does not
//! move before); `glGetBufferPointerv` answers the same address.

use crate::context::with_gl;
use crate::memory::{array, array_mut, bytes, count};
use gleval::gl::types::*;
use std::ffi::c_void;

with_arb! {
    /// `glGenBuffers`: writes `n` names.
    unsafe fn glGenBuffers / glGenBuffersARB(n: GLsizei, buffers: *mut GLuint) {
        let buffers = unsafe { array_mut(buffers, count(n).unwrap_or(0)) };
        with_gl(|gl| gl.gen_buffers(n, buffers))
    }
}

with_arb! {
    /// `glDeleteBuffers`: reads `n` names.
    unsafe fn glDeleteBuffers / glDeleteBuffersARB(n: GLsizei, buffers: *const GLuint) {
        let buffers = unsafe { array(buffers, count(n)) };
        with_gl(|gl| gl.delete_buffers(n, buffers))
    }
}

with_arb! {
    /// `glIsBuffer`: `Gl::is_buffer`.
    fn glIsBuffer / glIsBufferARB(buffer: GLuint) -> GLboolean {
        with_gl(|gl| gl.is_buffer(buffer))
    }
}

with_arb! {
    /// `glBindBuffer`: `Gl::bind_buffer`.
    fn glBindBuffer / glBindBufferARB(target: GLenum, buffer: GLuint) {
        with_gl(|gl| gl.bind_buffer(target, buffer))
    }
}

with_arb! {
    /// `glBufferData`: copies `size` bytes at `data` (NULL: none, the store is zeros).
    unsafe fn glBufferData / glBufferDataARB(target: GLenum, size: GLsizeiptr, data: *const c_void, usage: GLenum) {
        let data = (!data.is_null()).then(|| unsafe { bytes(data, usize::try_from(size).ok()) });
        with_gl(|gl| gl.buffer_data(target, size, data, usage))
    }
}

with_arb! {
    /// `glBufferSubData`: copies `size` bytes at `data`.
    unsafe fn glBufferSubData / glBufferSubDataARB(target: GLenum, offset: GLintptr, size: GLsizeiptr, data: *const c_void) {
        let data = unsafe { bytes(data, usize::try_from(size).ok()) };
        with_gl(|gl| gl.buffer_sub_data(target, offset, size, data))
    }
}

with_arb! {
    /// `glGetBufferSubData`: writes `size` bytes at `data`.
    unsafe fn glGetBufferSubData / glGetBufferSubDataARB(target: GLenum, offset: GLintptr, size: GLsizeiptr, data: *mut c_void) {
        let data = unsafe { array_mut(data.cast::<u8>(), usize::try_from(size).unwrap_or(0)) };
        with_gl(|gl| gl.get_buffer_sub_data(target, offset, size, data))
    }
}

with_arb! {
    /// `glMapBuffer`: the data store's address, NULL on an error.
    fn glMapBuffer / glMapBufferARB(target: GLenum, access: GLenum) -> *mut c_void {
        with_gl(|gl| gl.map_buffer(target, access).map_or(std::ptr::null_mut(), |m| m.as_ptr().cast()))
    }
}

with_arb! {
    /// `glUnmapBuffer`: `Gl::unmap_buffer`.
    fn glUnmapBuffer / glUnmapBufferARB(target: GLenum) -> GLboolean {
        with_gl(|gl| gl.unmap_buffer(target))
    }
}

with_arb! {
    /// `glGetBufferParameteriv`: writes one value.
    unsafe fn glGetBufferParameteriv / glGetBufferParameterivARB(target: GLenum, pname: GLenum, params: *mut GLint) {
        let params = unsafe { array_mut(params, 1) };
        with_gl(|gl| gl.get_buffer_parameteriv(target, pname, params))
    }
}

with_arb! {
    /// `glGetBufferPointerv`: writes the mapping's address (NULL when not mapped), nothing on
    /// an error.
    unsafe fn glGetBufferPointerv / glGetBufferPointervARB(target: GLenum, pname: GLenum, params: *mut *mut c_void) {
        with_gl(|gl| {
            let mut out = [None];
            let writes = gl.get_buffer_pointerv_error(target, pname).is_none();
            gl.get_buffer_pointerv(target, pname, &mut out);
            if writes && !params.is_null() {
                let address = out[0].as_ref().map_or(std::ptr::null_mut(), |m| m.as_ptr().cast());
                // SAFETY: glGetBufferPointerv's contract: `params` addresses one pointer.
                unsafe { params.write(address) };
            }
        })
    }
}
