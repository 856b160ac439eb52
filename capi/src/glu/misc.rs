//! GLU's projections, `gluBuild2DMipmaps`, `gluErrorString`, `gluGetString` and
//! `gluCheckExtension`.

use crate::context::with_gl;
use crate::memory::{array_mut, bytes};
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

entry! {
    /// `gluScaleImage`: reads the image under the unpack modes, writes the scaled one under
    /// the pack modes; returns 0 or a GLU error.
    #[allow(clippy::too_many_arguments)]
    unsafe fn gluScaleImage(
        format: GLenum, widthin: GLint, heightin: GLint, typein: GLenum, datain: *const c_void, widthout: GLint,
        heightout: GLint, typeout: GLenum, dataout: *mut c_void,
    ) -> GLint {
        with_gl(|gl| {
            let input = unsafe { bytes(datain, gl.glu_image_len(widthin, heightin, format, typein, false)) };
            let out_len = gl.glu_image_len(widthout, heightout, format, typeout, true).unwrap_or(0);
            let output = unsafe { array_mut(dataout.cast::<u8>(), out_len) };
            gl.glu_scale_image(format, widthin, heightin, typein, input, widthout, heightout, typeout, output)
        })
    }
}

entry! {
    /// `gluBuild1DMipmaps`.
    unsafe fn gluBuild1DMipmaps(
        target: GLenum, internal_format: GLint, width: GLsizei, format: GLenum, type_: GLenum, data: *const c_void,
    ) -> GLint {
        with_gl(|gl| {
            let data = unsafe { bytes(data, gl.glu_image_len(width, 1, format, type_, false)) };
            gl.glu_build_1d_mipmaps(target, internal_format, width, format, type_, data)
        })
    }
}

entry! {
    /// `gluBuild1DMipmapLevels`.
    #[allow(clippy::too_many_arguments)]
    unsafe fn gluBuild1DMipmapLevels(
        target: GLenum, internal_format: GLint, width: GLsizei, format: GLenum, type_: GLenum, user_level: GLint,
        base_level: GLint, max_level: GLint, data: *const c_void,
    ) -> GLint {
        with_gl(|gl| {
            let data = unsafe { bytes(data, gl.glu_image_len(width, 1, format, type_, false)) };
            gl.glu_build_1d_mipmap_levels(target, internal_format, width, format, type_, user_level, base_level, max_level, data)
        })
    }
}

entry! {
    /// `gluBuild2DMipmapLevels`.
    #[allow(clippy::too_many_arguments)]
    unsafe fn gluBuild2DMipmapLevels(
        target: GLenum, internal_format: GLint, width: GLsizei, height: GLsizei, format: GLenum, type_: GLenum,
        user_level: GLint, base_level: GLint, max_level: GLint, data: *const c_void,
    ) -> GLint {
        with_gl(|gl| {
            let data = unsafe { bytes(data, gl.unpacked_image_len(width, height, format, type_)) };
            gl.glu_build_2d_mipmap_levels(
                target, internal_format, width, height, format, type_, user_level, base_level, max_level, data,
            )
        })
    }
}

entry! {
    /// `gluBuild3DMipmaps`: reads the image under the unpack modes (image height and skipped
    /// images included); returns 0 or a GLU error.
    #[allow(clippy::too_many_arguments)]
    unsafe fn gluBuild3DMipmaps(
        target: GLenum, internal_format: GLint, width: GLsizei, height: GLsizei, depth: GLsizei, format: GLenum,
        type_: GLenum, data: *const c_void,
    ) -> GLint {
        with_gl(|gl| {
            let data = unsafe { bytes(data, gl.glu_image_len_3d((width, height, depth), format, type_, false)) };
            gl.glu_build_3d_mipmaps(target, internal_format, width, height, depth, format, type_, data)
        })
    }
}

entry! {
    /// `gluBuild3DMipmapLevels`: as `gluBuild3DMipmaps`.
    #[allow(clippy::too_many_arguments)]
    unsafe fn gluBuild3DMipmapLevels(
        target: GLenum, internal_format: GLint, width: GLsizei, height: GLsizei, depth: GLsizei, format: GLenum,
        type_: GLenum, user_level: GLint, base_level: GLint, max_level: GLint, data: *const c_void,
    ) -> GLint {
        with_gl(|gl| {
            let data = unsafe { bytes(data, gl.glu_image_len_3d((width, height, depth), format, type_, true)) };
            gl.glu_build_3d_mipmap_levels(
                target, internal_format, width, height, depth, format, type_, user_level, base_level, max_level, data,
            )
        })
    }
}
