//! Texture objects, images, parameters and the environment.

use super::pixel_buffers::unpack_bytes;
use crate::context::with_gl;
use crate::memory::{array, array_mut, count};
use gleval::gl::consts::*;
use gleval::gl::types::*;
use std::ffi::c_void;

forward! {
    glBindTexture(target: GLenum, texture: GLuint) => bind_texture;
    glIsTexture(texture: GLuint) -> GLboolean => is_texture;
    glTexParameteri(target: GLenum, pname: GLenum, param: GLint) => tex_parameteri;
    glTexParameterf(target: GLenum, pname: GLenum, param: GLfloat) => tex_parameterf;
    glTexEnvi(target: GLenum, pname: GLenum, param: GLint) => tex_envi;
    glTexEnvf(target: GLenum, pname: GLenum, param: GLfloat) => tex_envf;
}

entry! {
    /// `glGenTextures`: writes `n` names.
    unsafe fn glGenTextures(n: GLsizei, textures: *mut GLuint) {
        let textures = unsafe { array_mut(textures, count(n).unwrap_or(0)) };
        with_gl(|gl| gl.gen_textures(n, textures))
    }
}

entry! {
    /// `glDeleteTextures`: reads `n` names.
    unsafe fn glDeleteTextures(n: GLsizei, textures: *const GLuint) {
        let textures = unsafe { array(textures, count(n)) };
        with_gl(|gl| gl.delete_textures(n, textures));
        draw_if_holding_textures();
    }
}

/// The texture memory a recorded frame may hold before it is drawn: 256 MiB.
const FRAME_TEXTURE_BYTES: usize = 256 << 20;

/// Draws the frame recorded so far onto the drawable (as `glFlush` does) when the texture
/// images it holds pass [`FRAME_TEXTURE_BYTES`]: the images of textures deleted or given new
/// ones since are let go then, as GL lets them go (`Gl::frame_texture_bytes`). Not inside
/// `glBegin`/`glEnd`, where a primitive is open.
fn draw_if_holding_textures() {
    let heavy: GLboolean =
        with_gl(|gl| (!gl.inside_begin_end() && gl.frame_texture_bytes() > FRAME_TEXTURE_BYTES).into());
    if heavy != 0 {
        crate::surface::flush_current();
    }
}

entry! {
    /// `glTexEnvfv`: the colour reads 4 values, the other names 1.
    unsafe fn glTexEnvfv(target: GLenum, pname: GLenum, params: *const GLfloat) {
        let n = if pname == GL_TEXTURE_ENV_COLOR { 4 } else { 1 };
        let params = unsafe { array(params, Some(n)) };
        with_gl(|gl| gl.tex_envfv(target, pname, params))
    }
}

entry! {
    /// `glTexImage2D`: reads the image under the unpack modes; NULL defines the level without
    /// texels, as in GL.
    #[allow(clippy::too_many_arguments)]
    unsafe fn glTexImage2D(
        target: GLenum, level: GLint, internalformat: GLint, width: GLsizei, height: GLsizei,
        border: GLint, format: GLenum, type_: GLenum, pixels: *const c_void,
    ) {
        with_gl(|gl| {
            let len = gl.unpacked_image_len(width, height, format, type_);
            let Some(pixels) = (unsafe { unpack_bytes(gl, pixels, len) }) else { return };
            gl.tex_image_2d(target, level, internalformat, width, height, border, format, type_, &pixels[..])
        });
        draw_if_holding_textures();
    }
}

entry! {
    /// `glTexImage1D`: as `glTexImage2D`, one row.
    #[allow(clippy::too_many_arguments)]
    unsafe fn glTexImage1D(
        target: GLenum, level: GLint, internalformat: GLint, width: GLsizei,
        border: GLint, format: GLenum, type_: GLenum, pixels: *const c_void,
    ) {
        with_gl(|gl| {
            let len = gl.unpacked_image_len(width, 1, format, type_);
            let Some(pixels) = (unsafe { unpack_bytes(gl, pixels, len) }) else { return };
            gl.tex_image_1d(target, level, internalformat, width, border, format, type_, &pixels[..])
        });
        draw_if_holding_textures();
    }
}

entry! {
    /// `glTexSubImage2D`: reads the rectangle under the unpack modes.
    #[allow(clippy::too_many_arguments)]
    unsafe fn glTexSubImage2D(
        target: GLenum, level: GLint, xoffset: GLint, yoffset: GLint, width: GLsizei, height: GLsizei,
        format: GLenum, type_: GLenum, pixels: *const c_void,
    ) {
        with_gl(|gl| {
            let len = gl.unpacked_image_len(width, height, format, type_);
            let Some(pixels) = (unsafe { unpack_bytes(gl, pixels, len) }) else { return };
            gl.tex_sub_image_2d(target, level, xoffset, yoffset, width, height, format, type_, &pixels[..])
        })
    }
}

entry! {
    /// `glTexImage3D` (GL 1.2): reads the images under the unpack modes (image height and
    /// skipped images included); NULL defines the level without texels.
    #[allow(clippy::too_many_arguments)]
    unsafe fn glTexImage3D(
        target: GLenum, level: GLint, internalformat: GLint, width: GLsizei, height: GLsizei, depth: GLsizei,
        border: GLint, format: GLenum, type_: GLenum, pixels: *const c_void,
    ) {
        with_gl(|gl| {
            let len = gl.unpacked_image_3d_len((width, height, depth), format, type_);
            let Some(pixels) = (unsafe { unpack_bytes(gl, pixels, len) }) else { return };
            gl.tex_image_3d(target, level, internalformat, width, height, depth, border, format, type_, &pixels[..])
        });
        draw_if_holding_textures();
    }
}

entry! {
    /// `glTexImage3DEXT` (`GL_EXT_texture3D`): `glTexImage3D`, its internal format an enum.
    #[allow(clippy::too_many_arguments)]
    unsafe fn glTexImage3DEXT(
        target: GLenum, level: GLint, internalformat: GLenum, width: GLsizei, height: GLsizei, depth: GLsizei,
        border: GLint, format: GLenum, type_: GLenum, pixels: *const c_void,
    ) {
        unsafe {
            glTexImage3D(target, level, internalformat as GLint, width, height, depth, border, format, type_, pixels)
        }
    }
}

entry! {
    /// `glTexSubImage3D` (GL 1.2): reads the box's images under the unpack modes.
    #[allow(clippy::too_many_arguments)]
    unsafe fn glTexSubImage3D(
        target: GLenum, level: GLint, xoffset: GLint, yoffset: GLint, zoffset: GLint, width: GLsizei,
        height: GLsizei, depth: GLsizei, format: GLenum, type_: GLenum, pixels: *const c_void,
    ) {
        with_gl(|gl| {
            let len = gl.unpacked_image_3d_len((width, height, depth), format, type_);
            let Some(pixels) = (unsafe { unpack_bytes(gl, pixels, len) }) else { return };
            gl.tex_sub_image_3d(target, level, xoffset, yoffset, zoffset, width, height, depth, format, type_, &pixels[..])
        })
    }
}

entry! {
    /// `glTexSubImage3DEXT` (`GL_EXT_texture3D`): `glTexSubImage3D`.
    #[allow(clippy::too_many_arguments)]
    unsafe fn glTexSubImage3DEXT(
        target: GLenum, level: GLint, xoffset: GLint, yoffset: GLint, zoffset: GLint, width: GLsizei,
        height: GLsizei, depth: GLsizei, format: GLenum, type_: GLenum, pixels: *const c_void,
    ) {
        unsafe {
            glTexSubImage3D(target, level, xoffset, yoffset, zoffset, width, height, depth, format, type_, pixels)
        }
    }
}
