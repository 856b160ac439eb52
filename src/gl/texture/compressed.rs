//! GL 1.3's texture compression (§3.8.3, `GL_ARB_texture_compression`) with no specific
//! compressed format: the generic formats (`GL_COMPRESSED_RGB`, ...) are taken by
//! `glTexImage` and `glCopyTexImage` and kept uncompressed, and `glCompressedTexImage`,
//! `glCompressedTexSubImage` and `glGetCompressedTexImage` answer as GL does when no image is
//! compressed.
//!
//! GL lets an implementation list no compressed format (`GL_NUM_COMPRESSED_TEXTURE_FORMATS`
//! 0) and keep a generic one uncompressed (§3.8.1). Mesa's llvmpipe lists 12 (S3TC, FXT1, ETC2,
//! ...) and compresses `GL_COMPRESSED_RGB` as DXT1 with its own encoder; drawing Mesa's
//! picture from such a texture would need that encoder bit for bit, so gleval leaves the
//! specific formats out. What Mesa does with the generic formats it cannot compress (alpha and
//! intensity, and every 1D image: measured on Mesa 22.3) is what gleval does with all of them:
//! the level keeps the base format, which `GL_TEXTURE_INTERNAL_FORMAT` reports, and
//! `GL_TEXTURE_COMPRESSED` is false.

use super::super::consts::*;
use super::super::lists::ListCommand;
use super::super::state_var::{int_limit, row, Kind, StateVar};
use super::super::types::*;
use super::super::Gl;
use super::{image_target, image_target_of, max_level, proxy_index};

/// The base format a generic compressed internal format is kept in (GL 1.3 table 3.17), `None`
/// for any other.
pub(in crate::gl) fn generic_base(internal: GLenum) -> Option<GLenum> {
    match internal {
        GL_COMPRESSED_ALPHA => Some(GL_ALPHA),
        GL_COMPRESSED_LUMINANCE => Some(GL_LUMINANCE),
        GL_COMPRESSED_LUMINANCE_ALPHA => Some(GL_LUMINANCE_ALPHA),
        GL_COMPRESSED_INTENSITY => Some(GL_INTENSITY),
        GL_COMPRESSED_RGB => Some(GL_RGB),
        GL_COMPRESSED_RGBA => Some(GL_RGBA),
        _ => None,
    }
}

/// A compressed-image call as a display list holds it: only what its checks read, since
/// every one is refused when it runs (see the module).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum CompressedCall {
    /// `glCompressedTexImage1D/2D/3D`.
    Image,
    /// `glCompressedTexSubImage1D/2D/3D`: its dimensions, target and format.
    SubImage(u8, GLenum, GLenum),
}

impl Gl {
    /// `glCompressedTexImage1D`: `GL_INVALID_ENUM`, since no format is one gleval compresses
    /// (see the module); inside `begin`/`end` `GL_INVALID_OPERATION`. `data` is not read.
    #[allow(clippy::too_many_arguments)]
    pub fn compressed_tex_image_1d(
        &mut self,
        target: GLenum,
        level: GLint,
        internalformat: GLenum,
        width: GLsizei,
        border: GLint,
        image_size: GLsizei,
        data: &[u8],
    ) {
        let _ = (level, internalformat, width, border, image_size, data);
        self.compressed_tex_image(target);
    }

    /// `glCompressedTexImage2D`: as [`Gl::compressed_tex_image_1d`].
    #[allow(clippy::too_many_arguments)]
    pub fn compressed_tex_image_2d(
        &mut self,
        target: GLenum,
        level: GLint,
        internalformat: GLenum,
        width: GLsizei,
        height: GLsizei,
        border: GLint,
        image_size: GLsizei,
        data: &[u8],
    ) {
        let _ = (level, internalformat, width, height, border, image_size, data);
        self.compressed_tex_image(target);
    }

    /// `glCompressedTexImage3D`: as [`Gl::compressed_tex_image_1d`].
    #[allow(clippy::too_many_arguments)]
    pub fn compressed_tex_image_3d(
        &mut self,
        target: GLenum,
        level: GLint,
        internalformat: GLenum,
        size: [GLsizei; 3],
        border: GLint,
        image_size: GLsizei,
        data: &[u8],
    ) {
        let _ = (level, internalformat, size, border, image_size, data);
        self.compressed_tex_image(target);
    }

    /// `glCompressedTexSubImage1D`: `GL_INVALID_ENUM` (no 1D image is ever compressed: Mesa's
    /// answer whatever the arguments); inside `begin`/`end` `GL_INVALID_OPERATION`.
    #[allow(clippy::too_many_arguments)]
    pub fn compressed_tex_sub_image_1d(
        &mut self,
        target: GLenum,
        level: GLint,
        xoffset: GLint,
        width: GLsizei,
        format: GLenum,
        image_size: GLsizei,
        data: &[u8],
    ) {
        let _ = (level, xoffset, width, image_size, data);
        self.compressed_tex_sub_image(1, target, format);
    }

    /// `glCompressedTexSubImage2D`: a target other than `GL_TEXTURE_2D` or a generic format →
    /// `GL_INVALID_ENUM`; any other format → `GL_INVALID_OPERATION`, since it cannot be the
    /// format of the (uncompressed) image, which Mesa checks before the level, offsets and
    /// sizes; inside `begin`/`end` `GL_INVALID_OPERATION`. `data` is not read.
    #[allow(clippy::too_many_arguments)]
    pub fn compressed_tex_sub_image_2d(
        &mut self,
        target: GLenum,
        level: GLint,
        offset: [GLint; 2],
        size: [GLsizei; 2],
        format: GLenum,
        image_size: GLsizei,
        data: &[u8],
    ) {
        let _ = (level, offset, size, image_size, data);
        self.compressed_tex_sub_image(2, target, format);
    }

    /// `glCompressedTexSubImage3D`: as [`Gl::compressed_tex_sub_image_2d`] for
    /// `GL_TEXTURE_3D`.
    #[allow(clippy::too_many_arguments)]
    pub fn compressed_tex_sub_image_3d(
        &mut self,
        target: GLenum,
        level: GLint,
        offset: [GLint; 3],
        size: [GLsizei; 3],
        format: GLenum,
        image_size: GLsizei,
        data: &[u8],
    ) {
        let _ = (level, offset, size, image_size, data);
        self.compressed_tex_sub_image(3, target, format);
    }

    /// `glGetCompressedTexImage`: in Mesa's order, inside `begin`/`end`
    /// `GL_INVALID_OPERATION`; a target other than `GL_TEXTURE_1D`, `_2D`, `_3D`
    /// `GL_INVALID_ENUM`; a level outside the target's range or not defined
    /// `GL_INVALID_VALUE`; else `GL_INVALID_OPERATION`, the image not being compressed.
    /// Nothing is written to `img`.
    pub fn get_compressed_tex_image(&mut self, target: GLenum, level: GLint, img: &mut [u8]) {
        let _ = img;
        if self.reject_inside_begin_end() {
            return;
        }
        let Some(t) = image_target(target) else { return self.set_error(GL_INVALID_ENUM) };
        let dims = t.dims();
        let defined = usize::try_from(level)
            .ok()
            .filter(|_| level <= max_level(dims))
            .is_some_and(|l| self.bound_object(t.slot).face(t.face).level(l).is_some());
        self.set_error(if defined { GL_INVALID_OPERATION } else { GL_INVALID_VALUE });
    }

    /// Every form of `glCompressedTexImage`: compiled into a list but for a proxy target,
    /// which Mesa runs at once (`save_CompressedTexImage2D`).
    fn compressed_tex_image(&mut self, target: GLenum) {
        if proxy_index(target).is_none() && self.compiled(|| ListCommand::Compressed(CompressedCall::Image)) {
            return;
        }
        self.replay_compressed_call(CompressedCall::Image);
    }

    fn compressed_tex_sub_image(&mut self, dims: u8, target: GLenum, format: GLenum) {
        let call = CompressedCall::SubImage(dims, target, format);
        if self.compiled(|| ListCommand::Compressed(call)) {
            return;
        }
        self.replay_compressed_call(call);
    }

    /// Runs a compressed-image call (see the module for why each is refused).
    pub(crate) fn replay_compressed_call(&mut self, call: CompressedCall) {
        if self.reject_inside_begin_end() {
            return;
        }
        let error = match call {
            CompressedCall::Image => GL_INVALID_ENUM,
            CompressedCall::SubImage(dims, target, format) => {
                let target_fits = dims > 1 && image_target_of(dims, target).is_some();
                if !target_fits || generic_base(format).is_some() {
                    GL_INVALID_ENUM
                } else {
                    GL_INVALID_OPERATION
                }
            }
        };
        self.set_error(error);
    }
}

/// The compressed formats' `glGet` rows: none is listed (see the module).
pub(crate) static GET_ROWS: &[StateVar] =
    &[int_limit!(GL_NUM_COMPRESSED_TEXTURE_FORMATS, 0), row(GL_COMPRESSED_TEXTURE_FORMATS, 0, Kind::Int, |_, _| {})];

#[cfg(test)]
mod tests {
    use super::*;

    /// No compressed format is listed: the count is 0 and the list writes nothing.
    #[test]
    fn no_format_is_listed() {
        let mut gl = Gl::new(4, 4);
        let mut count = [7];
        gl.get_integerv(GL_NUM_COMPRESSED_TEXTURE_FORMATS, &mut count);
        let mut formats = [-1; 4];
        gl.get_integerv(GL_COMPRESSED_TEXTURE_FORMATS, &mut formats);
        assert_eq!((count, formats, gl.get_error()), ([0], [-1; 4], GL_NO_ERROR));
    }
}
