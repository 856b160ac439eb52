//! GL 1.3's compressed-image entry points (`Gl`'s `texture/compressed.rs`) and their ARB
//! names. No compressed format is one gleval keeps, so none of them reads or writes its image;
//! the pointers travel as empty slices.

use crate::context::with_gl;
use gleval::gl::types::*;
use std::ffi::c_void;

/// The same entry point under its core and ARB names.
macro_rules! both_names {
    ($core:ident, $arb:ident, $doc:literal, ($($a:ident: $t:ty),*), $data:ident: $dt:ty, |$gl:ident| $call:expr) => {
        entry! {
            #[doc = $doc]
            #[allow(clippy::too_many_arguments)]
            fn $core($($a: $t),*, $data: $dt) {
                let _ = $data;
                with_gl(|$gl| $call)
            }
        }
        entry! {
            #[doc = concat!("`", stringify!($arb), "`: `", stringify!($core), "`.")]
            #[allow(clippy::too_many_arguments)]
            fn $arb($($a: $t),*, $data: $dt) {
                $core($($a),*, $data)
            }
        }
    };
}

both_names!(glCompressedTexImage1D, glCompressedTexImage1DARB, "`glCompressedTexImage1D`: `Gl::compressed_tex_image_1d`.",
    (target: GLenum, level: GLint, internalformat: GLenum, width: GLsizei, border: GLint, size: GLsizei), data: *const c_void,
    |gl| gl.compressed_tex_image_1d(target, level, internalformat, width, border, size, &[]));
both_names!(glCompressedTexImage2D, glCompressedTexImage2DARB, "`glCompressedTexImage2D`: `Gl::compressed_tex_image_2d`.",
    (target: GLenum, level: GLint, internalformat: GLenum, width: GLsizei, height: GLsizei, border: GLint, size: GLsizei),
    data: *const c_void,
    |gl| gl.compressed_tex_image_2d(target, level, internalformat, width, height, border, size, &[]));
both_names!(glCompressedTexImage3D, glCompressedTexImage3DARB, "`glCompressedTexImage3D`: `Gl::compressed_tex_image_3d`.",
    (target: GLenum, level: GLint, internalformat: GLenum, width: GLsizei, height: GLsizei, depth: GLsizei, border: GLint,
     size: GLsizei), data: *const c_void,
    |gl| gl.compressed_tex_image_3d(target, level, internalformat, [width, height, depth], border, size, &[]));
both_names!(glCompressedTexSubImage1D, glCompressedTexSubImage1DARB,
    "`glCompressedTexSubImage1D`: `Gl::compressed_tex_sub_image_1d`.",
    (target: GLenum, level: GLint, xoffset: GLint, width: GLsizei, format: GLenum, size: GLsizei), data: *const c_void,
    |gl| gl.compressed_tex_sub_image_1d(target, level, xoffset, width, format, size, &[]));
both_names!(glCompressedTexSubImage2D, glCompressedTexSubImage2DARB,
    "`glCompressedTexSubImage2D`: `Gl::compressed_tex_sub_image_2d`.",
    (target: GLenum, level: GLint, xoffset: GLint, yoffset: GLint, width: GLsizei, height: GLsizei, format: GLenum,
     size: GLsizei), data: *const c_void,
    |gl| gl.compressed_tex_sub_image_2d(target, level, [xoffset, yoffset], [width, height], format, size, &[]));
both_names!(glCompressedTexSubImage3D, glCompressedTexSubImage3DARB,
    "`glCompressedTexSubImage3D`: `Gl::compressed_tex_sub_image_3d`.",
    (target: GLenum, level: GLint, xoffset: GLint, yoffset: GLint, zoffset: GLint, width: GLsizei, height: GLsizei,
     depth: GLsizei, format: GLenum, size: GLsizei), data: *const c_void,
    |gl| gl.compressed_tex_sub_image_3d(target, level, [xoffset, yoffset, zoffset], [width, height, depth], format, size, &[]));
both_names!(glGetCompressedTexImage, glGetCompressedTexImageARB,
    "`glGetCompressedTexImage`: `Gl::get_compressed_tex_image` (nothing is written).",
    (target: GLenum, level: GLint), img: *mut c_void,
    |gl| gl.get_compressed_tex_image(target, level, &mut []));
