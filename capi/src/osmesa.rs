//! A stand-in for OSMesa's context calls (`GL/osmesa.h`), so that programs written for
//! off-screen Mesa (the scripted-call interpreter `tests/reference/calls/interp.c`) run on
//! gleval unchanged: a context is a `Gl`, made current on this thread. gleval renders through
//! wgpu, not into the caller's buffer: the buffer is left untouched, and a program reads back
//! what it drew with feedback mode.

use crate::context::{make_current, release_if_current};
use gleval::gl::types::*;
use gleval::gl::Gl;
use std::ffi::c_void;

/// What an `OSMesaContext` points at.
pub struct OSMesaContext(Gl);

entry! {
    /// `OSMesaCreateContextExt`: a context in GL's initial state (format and buffer depths
    /// are not used: gleval's frames always have colour and depth).
    fn OSMesaCreateContextExt(
        _format: GLenum, _depth_bits: GLint, _stencil_bits: GLint, _accum_bits: GLint, _sharelist: *mut OSMesaContext,
    ) -> *mut OSMesaContext {
        Box::into_raw(Box::new(OSMesaContext(Gl::new(1, 1))))
    }
}

entry! {
    /// `OSMesaCreateContext`.
    fn OSMesaCreateContext(format: GLenum, sharelist: *mut OSMesaContext) -> *mut OSMesaContext {
        OSMesaCreateContextExt(format, 16, 0, 0, sharelist)
    }
}

entry! {
    /// `OSMesaMakeCurrent`: makes `ctx` current for a `width` × `height` buffer; the first time,
    /// the viewport becomes the whole buffer, as GL sets it. Returns `GL_TRUE`, or `GL_FALSE`
    /// for a NULL context or a size that is not positive.
    unsafe fn OSMesaMakeCurrent(
        ctx: *mut OSMesaContext, _buffer: *mut c_void, _type: GLenum, width: GLsizei, height: GLsizei,
    ) -> GLboolean {
        // SAFETY: made by OSMesaCreateContext and not destroyed (the caller's promise).
        let Some(ctx) = (unsafe { ctx.as_mut() }) else { return 0 };
        if width <= 0 || height <= 0 {
            return 0;
        }
        let first = ctx.0.width() == 1 && ctx.0.height() == 1;
        ctx.0.set_window_size(width, height);
        if first {
            ctx.0.viewport(0, 0, width, height);
        }
        make_current(&mut ctx.0);
        1
    }
}

entry! {
    /// `OSMesaDestroyContext`: frees the context (no longer current if it was).
    unsafe fn OSMesaDestroyContext(ctx: *mut OSMesaContext) {
        if !ctx.is_null() {
            // SAFETY: made by OSMesaCreateContext (the caller's promise).
            let mut owned = unsafe { Box::from_raw(ctx) };
            release_if_current(&mut owned.0);
        }
    }
}
