//! The pixel path: transfer, maps and zoom, copies, the texture calls that read the window, and
//! the colour-index calls of an RGBA context.

use super::pixel_buffers::{pack_with, unpack_bytes, unpack_source};
use crate::context::with_gl;
use crate::memory::{array, count};
use gleval::gl::types::*;
use gleval::gl::Gl;
use std::ffi::c_void;

forward! {
    glPixelZoom(xfactor: GLfloat, yfactor: GLfloat) => pixel_zoom;
    glPixelTransferf(pname: GLenum, param: GLfloat) => pixel_transferf;
    glPixelTransferi(pname: GLenum, param: GLint) => pixel_transferi;
    glCopyPixels(x: GLint, y: GLint, width: GLsizei, height: GLsizei, type_: GLenum) => copy_pixels;
    glCopyTexSubImage1D(target: GLenum, level: GLint, xoffset: GLint, x: GLint, y: GLint, width: GLsizei)
        => copy_tex_sub_image_1d;
    glCopyTexImage1D(
        target: GLenum, level: GLint, internalformat: GLenum, x: GLint, y: GLint, width: GLsizei, border: GLint,
    ) => copy_tex_image_1d;
    glCopyTexImage2D(
        target: GLenum, level: GLint, internalformat: GLenum, x: GLint, y: GLint, width: GLsizei, height: GLsizei,
        border: GLint,
    ) => copy_tex_image_2d;
    glCopyTexSubImage2D(
        target: GLenum, level: GLint, xoffset: GLint, yoffset: GLint, x: GLint, y: GLint, width: GLsizei,
        height: GLsizei,
    ) => copy_tex_sub_image_2d;
    glCopyTexSubImage3D(
        target: GLenum, level: GLint, xoffset: GLint, yoffset: GLint, zoffset: GLint, x: GLint, y: GLint,
        width: GLsizei, height: GLsizei,
    ) => copy_tex_sub_image_3d;
    glCopyTexSubImage3DEXT(
        target: GLenum, level: GLint, xoffset: GLint, yoffset: GLint, zoffset: GLint, x: GLint, y: GLint,
        width: GLsizei, height: GLsizei,
    ) => copy_tex_sub_image_3d;
    glIndexf(c: GLfloat) => indexf;
    glIndexd(c: GLdouble) => indexd;
    glIndexi(c: GLint) => indexi;
    glIndexs(c: GLshort) => indexs;
    glIndexub(c: GLubyte) => indexub;
    glClearIndex(c: GLfloat) => clear_index;
    glIndexMask(mask: GLuint) => index_mask;
}

vector! {
    glIndexfv(GLfloat; 1) => indexfv;
    glIndexdv(GLdouble; 1) => indexdv;
    glIndexiv(GLint; 1) => indexiv;
    glIndexsv(GLshort; 1) => indexsv;
    glIndexubv(GLubyte; 1) => indexubv;
}

entry! {
    /// `glTexSubImage1D`: reads the row under the unpack modes.
    #[allow(clippy::too_many_arguments)]
    unsafe fn glTexSubImage1D(
        target: GLenum, level: GLint, xoffset: GLint, width: GLsizei, format: GLenum, type_: GLenum,
        pixels: *const c_void,
    ) {
        with_gl(|gl| {
            let len = gl.unpacked_image_len(width, 1, format, type_);
            let Some(pixels) = (unsafe { unpack_bytes(gl, pixels, len) }) else { return };
            gl.tex_sub_image_1d(target, level, xoffset, width, format, type_, &pixels[..])
        })
    }
}

entry! {
    /// `glPixelMapfv`: reads `mapsize` floats.
    unsafe fn glPixelMapfv(map: GLenum, mapsize: GLsizei, values: *const GLfloat) {
        with_gl(|gl| {
            let Some(values) = (unsafe { unpack_source(gl, values, Gl::pixel_map_len(mapsize)) }) else { return };
            gl.pixel_mapfv(map, mapsize, &values)
        })
    }
}

entry! {
    /// `glPixelMapuiv`: reads `mapsize` unsigned integers.
    unsafe fn glPixelMapuiv(map: GLenum, mapsize: GLsizei, values: *const GLuint) {
        with_gl(|gl| {
            let Some(values) = (unsafe { unpack_source(gl, values, Gl::pixel_map_len(mapsize)) }) else { return };
            gl.pixel_mapuiv(map, mapsize, &values)
        })
    }
}

entry! {
    /// `glPixelMapusv`: reads `mapsize` unsigned shorts.
    unsafe fn glPixelMapusv(map: GLenum, mapsize: GLsizei, values: *const GLushort) {
        with_gl(|gl| {
            let Some(values) = (unsafe { unpack_source(gl, values, Gl::pixel_map_len(mapsize)) }) else { return };
            gl.pixel_mapusv(map, mapsize, &values)
        })
    }
}

entry! {
    /// `glGetPixelMapfv`: writes the map's size of floats.
    unsafe fn glGetPixelMapfv(map: GLenum, values: *mut GLfloat) {
        unsafe { pack_with(values, |gl| gl.pixel_map_size(map), |gl, out| gl.get_pixel_mapfv(map, out)) }
    }
}

entry! {
    /// `glGetPixelMapuiv`: writes the map's size of unsigned integers.
    unsafe fn glGetPixelMapuiv(map: GLenum, values: *mut GLuint) {
        unsafe { pack_with(values, |gl| gl.pixel_map_size(map), |gl, out| gl.get_pixel_mapuiv(map, out)) }
    }
}

entry! {
    /// `glGetPixelMapusv`: writes the map's size of unsigned shorts.
    unsafe fn glGetPixelMapusv(map: GLenum, values: *mut GLushort) {
        unsafe { pack_with(values, |gl| gl.pixel_map_size(map), |gl, out| gl.get_pixel_mapusv(map, out)) }
    }
}

entry! {
    /// `glAreTexturesResident`: reads `n` names; `residences` is never written (every texture
    /// is resident), as in Mesa. NULL arrays answer `GL_FALSE` without an error, as Mesa does.
    unsafe fn glAreTexturesResident(n: GLsizei, textures: *const GLuint, residences: *mut GLboolean) -> GLboolean {
        with_gl(|gl| {
            if n >= 0 && (textures.is_null() || residences.is_null()) {
                return 0;
            }
            let names = unsafe { array(textures, count(n)) };
            gl.are_textures_resident(n, names, &mut [])
        })
    }
}

entry! {
    /// `glPrioritizeTextures`: reads `n` names and priorities; a NULL priority array does
    /// nothing, as in Mesa.
    unsafe fn glPrioritizeTextures(n: GLsizei, textures: *const GLuint, priorities: *const GLclampf) {
        with_gl(|gl| {
            if n >= 0 && priorities.is_null() {
                return;
            }
            let names = unsafe { array(textures, count(n)) };
            let values = unsafe { array(priorities, count(n)) };
            gl.prioritize_textures(n, names, values)
        })
    }
}
