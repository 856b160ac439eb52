//! GLU's projections, `gluBuild2DMipmaps`, `gluErrorString`, `gluGetString` and
//! `gluCheckExtension`.

use crate::context::with_gl;
use crate::memory::bytes;
use crate::strings::static_c_string;
use gleval::gl::types::*;
use std::ffi::{c_void, CStr};

forward! {
    gluOrtho2D(left: GLdouble, right: GLdouble, bottom: GLdouble, top: GLdouble) => glu_ortho_2d;
    gluPerspective(fovy: GLdouble, aspect: GLdouble, near: GLdouble, far: GLdouble) => glu_perspective;
}

entry! {
    /// `gluLookAt`: `Gl::glu_look_at`.
    #[allow(clippy::too_many_arguments)]
    fn gluLookAt(
        eye_x: GLdouble, eye_y: GLdouble, eye_z: GLdouble, center_x: GLdouble, center_y: GLdouble,
        center_z: GLdouble, up_x: GLdouble, up_y: GLdouble, up_z: GLdouble,
    ) {
        with_gl(|gl| gl.glu_look_at(eye_x, eye_y, eye_z, center_x, center_y, center_z, up_x, up_y, up_z))
    }
}

entry! {
    /// `gluBuild2DMipmaps`: reads the image under the unpack modes; returns 0 or a GLU error.
    #[allow(clippy::too_many_arguments)]
    unsafe fn gluBuild2DMipmaps(
        target: GLenum, internal_format: GLint, width: GLsizei, height: GLsizei, format: GLenum,
        type_: GLenum, data: *const c_void,
    ) -> GLint {
        with_gl(|gl| {
            let data = unsafe { bytes(data, gl.unpacked_image_len(width, height, format, type_)) };
            gl.glu_build_2d_mipmaps(target, internal_format, width, height, format, type_, data)
        })
    }
}

entry! {
    /// `gluErrorString`: GLU's message for a GLU or GL error code, NULL for another number.
    fn gluErrorString(code: GLenum) -> *const GLubyte {
        gleval::glu::glu_error_string(code).map_or(std::ptr::null(), |s| static_c_string(s).cast())
    }
}

entry! {
    /// `gluGetString`: GLU's version or extension string (no context needed), NULL for another
    /// name.
    fn gluGetString(name: GLenum) -> *const GLubyte {
        gleval::glu::glu_get_string(name).map_or(std::ptr::null(), |s| static_c_string(s).cast())
    }
}

entry! {
    /// `gluCheckExtension`: whether `ext_name` is a word of `ext_string`; NULL is no match.
    unsafe fn gluCheckExtension(ext_name: *const GLubyte, ext_string: *const GLubyte) -> GLboolean {
        if ext_name.is_null() || ext_string.is_null() {
            return 0;
        }
        // SAFETY: GLU's contract: both are NUL-terminated strings.
        let (name, string) = unsafe { (CStr::from_ptr(ext_name.cast()), CStr::from_ptr(ext_string.cast())) };
        gleval::glu::glu_check_extension(name.to_bytes(), string.to_bytes())
    }
}
