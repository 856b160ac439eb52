//! Pixel storage, the raster position, bitmaps and `glDrawPixels`.

use super::pixel_buffers::unpack_bytes;
use crate::context::with_gl;
use gleval::gl::types::*;
use std::ffi::c_void;

forward! {
    glPixelStorei(pname: GLenum, param: GLint) => pixel_storei;
    glPixelStoref(pname: GLenum, param: GLfloat) => pixel_storef;
    glPushClientAttrib(mask: GLbitfield) => push_client_attrib;
    glPopClientAttrib() => pop_client_attrib;
    glRasterPos2f(x: GLfloat, y: GLfloat) => raster_pos2f;
    glRasterPos2i(x: GLint, y: GLint) => raster_pos2i;
    glRasterPos2d(x: GLdouble, y: GLdouble) => raster_pos2d;
    glRasterPos3f(x: GLfloat, y: GLfloat, z: GLfloat) => raster_pos3f;
    glRasterPos3i(x: GLint, y: GLint, z: GLint) => raster_pos3i;
    glRasterPos3d(x: GLdouble, y: GLdouble, z: GLdouble) => raster_pos3d;
    glRasterPos4f(x: GLfloat, y: GLfloat, z: GLfloat, w: GLfloat) => raster_pos4f;
    glRasterPos4d(x: GLdouble, y: GLdouble, z: GLdouble, w: GLdouble) => raster_pos4d;
}

// GL_ARB_window_pos (core in GL 1.4), by both names.
forward! {
    glWindowPos2f(x: GLfloat, y: GLfloat) => window_pos2f;
    glWindowPos2d(x: GLdouble, y: GLdouble) => window_pos2d;
    glWindowPos2i(x: GLint, y: GLint) => window_pos2i;
    glWindowPos2s(x: GLshort, y: GLshort) => window_pos2s;
    glWindowPos3f(x: GLfloat, y: GLfloat, z: GLfloat) => window_pos3f;
    glWindowPos3d(x: GLdouble, y: GLdouble, z: GLdouble) => window_pos3d;
    glWindowPos3i(x: GLint, y: GLint, z: GLint) => window_pos3i;
    glWindowPos3s(x: GLshort, y: GLshort, z: GLshort) => window_pos3s;
    glWindowPos2fARB(x: GLfloat, y: GLfloat) => window_pos2f;
    glWindowPos2dARB(x: GLdouble, y: GLdouble) => window_pos2d;
    glWindowPos2iARB(x: GLint, y: GLint) => window_pos2i;
    glWindowPos2sARB(x: GLshort, y: GLshort) => window_pos2s;
    glWindowPos3fARB(x: GLfloat, y: GLfloat, z: GLfloat) => window_pos3f;
    glWindowPos3dARB(x: GLdouble, y: GLdouble, z: GLdouble) => window_pos3d;
    glWindowPos3iARB(x: GLint, y: GLint, z: GLint) => window_pos3i;
    glWindowPos3sARB(x: GLshort, y: GLshort, z: GLshort) => window_pos3s;
}

vector! {
    glWindowPos2fv(GLfloat; 2) => window_pos2fv;
    glWindowPos2dv(GLdouble; 2) => window_pos2dv;
    glWindowPos2iv(GLint; 2) => window_pos2iv;
    glWindowPos2sv(GLshort; 2) => window_pos2sv;
    glWindowPos3fv(GLfloat; 3) => window_pos3fv;
    glWindowPos3dv(GLdouble; 3) => window_pos3dv;
    glWindowPos3iv(GLint; 3) => window_pos3iv;
    glWindowPos3sv(GLshort; 3) => window_pos3sv;
    glWindowPos2fvARB(GLfloat; 2) => window_pos2fv;
    glWindowPos2dvARB(GLdouble; 2) => window_pos2dv;
    glWindowPos2ivARB(GLint; 2) => window_pos2iv;
    glWindowPos2svARB(GLshort; 2) => window_pos2sv;
    glWindowPos3fvARB(GLfloat; 3) => window_pos3fv;
    glWindowPos3dvARB(GLdouble; 3) => window_pos3dv;
    glWindowPos3ivARB(GLint; 3) => window_pos3iv;
    glWindowPos3svARB(GLshort; 3) => window_pos3sv;
}

vector! {
    glRasterPos2fv(GLfloat; 2) => raster_pos2fv;
    glRasterPos3fv(GLfloat; 3) => raster_pos3fv;
    glRasterPos4fv(GLfloat; 4) => raster_pos4fv;
    glRasterPos2iv(GLint; 2) => raster_pos2iv;
    glRasterPos2dv(GLdouble; 2) => raster_pos2dv;
    glRasterPos3dv(GLdouble; 3) => raster_pos3dv;
}

entry! {
    /// `glBitmap`: reads `height` rows of `width` bits under the unpack modes.
    #[allow(clippy::too_many_arguments)]
    unsafe fn glBitmap(
        width: GLsizei, height: GLsizei, xorig: GLfloat, yorig: GLfloat, xmove: GLfloat, ymove: GLfloat,
        bitmap: *const GLubyte,
    ) {
        with_gl(|gl| {
            let len = gl.unpacked_bitmap_len(width, height);
            let Some(bits) = (unsafe { unpack_bytes(gl, bitmap.cast(), len) }) else { return };
            gl.bitmap(width, height, xorig, yorig, xmove, ymove, &bits)
        })
    }
}

entry! {
    /// `glDrawPixels`: reads the image under the unpack modes.
    unsafe fn glDrawPixels(width: GLsizei, height: GLsizei, format: GLenum, type_: GLenum, pixels: *const c_void) {
        with_gl(|gl| {
            let len = gl.unpacked_image_len(width, height, format, type_);
            let Some(pixels) = (unsafe { unpack_bytes(gl, pixels, len) }) else { return };
            gl.draw_pixels(width, height, format, type_, &pixels[..])
        })
    }
}
