//! Rasterisation modes: line and polygon stipple, clip planes, polygon offset.

use crate::context::with_gl;
use crate::memory::{array, array_mut};
use gleval::gl::types::*;

forward! {
    glLineStipple(factor: GLint, pattern: GLushort) => line_stipple;
    glPolygonOffset(factor: GLfloat, units: GLfloat) => polygon_offset;
}

entry! {
    /// `glPolygonStipple`: a 32 × 32 bit mask, read with the unpack modes.
    unsafe fn glPolygonStipple(mask: *const GLubyte) {
        with_gl(|gl| {
            let len = gl.unpacked_bitmap_len(32, 32).unwrap_or(0);
            let Some(mask) = (unsafe { super::pixel_buffers::unpack_source(gl, mask, Some(len)) }) else { return };
            gl.polygon_stipple(&mask)
        })
    }
}

entry! {
    /// `glClipPlane`: 4 doubles.
    unsafe fn glClipPlane(plane: GLenum, equation: *const GLdouble) {
        let equation = unsafe { array(equation, Some(4)) };
        with_gl(|gl| gl.clip_plane(plane, equation))
    }
}

entry! {
    /// `glGetClipPlane`: writes 4 doubles.
    unsafe fn glGetClipPlane(plane: GLenum, equation: *mut GLdouble) {
        let equation = unsafe { array_mut(equation, 4) };
        with_gl(|gl| gl.get_clip_plane(plane, equation))
    }
}
