//! Line and polygon stipple, polygon offset and clip planes.

use crate::context::with_gl;
use crate::memory::{array, array_mut, bytes};
use gleval::gl::types::*;

forward! {
    glLineStipple(factor: GLint, pattern: GLushort) => line_stipple;
    glPolygonOffset(factor: GLfloat, units: GLfloat) => polygon_offset;
}

entry! {
    /// `glClipPlane`: reads the plane's 4 coefficients.
    unsafe fn glClipPlane(plane: GLenum, equation: *const GLdouble) {
        let equation = unsafe { array(equation, Some(4)) };
        with_gl(|gl| gl.clip_plane(plane, equation))
    }
}

entry! {
    /// `glGetClipPlane`: writes the plane's 4 coefficients.
    unsafe fn glGetClipPlane(plane: GLenum, equation: *mut GLdouble) {
        with_gl(|gl| gl.get_clip_plane(plane, unsafe { array_mut(equation, 4) }))
    }
}

entry! {
    /// `glPolygonStipple`: reads a 32 × 32 bitmap under the unpack modes.
    unsafe fn glPolygonStipple(mask: *const GLubyte) {
        with_gl(|gl| {
            let mask = unsafe { bytes(mask.cast(), gl.unpacked_bitmap_len(32, 32)) };
            gl.polygon_stipple(mask)
        })
    }
}
