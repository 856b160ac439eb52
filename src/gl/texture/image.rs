//! Texture images (GL 1.1 spec §3.8.1–3.8.2; Mesa `main/teximage.c`): `glTexImage1D/2D` and
//! `glTexSubImage1D/2D` of the bound texture (proxies, borders, level sizes), each image
//! unpacked from client memory through the pixel store and the pixel transfer into RGBA8.

use super::TextureCall;
use super::{
    base_format, fits_level, proxy_index, strip_border, target_index, texture_format, TexLevel, MAX_TEXTURE_SIZE,
};
use crate::gl::consts::*;
use crate::gl::lists::ListCommand;
use crate::gl::pixel_unpack::{format_and_type_error, unpack_each};
use crate::gl::types::*;
use crate::gl::Gl;

impl Gl {
    /// `glTexImage2D`: defines level `level` of the bound 2D texture from `pixels` (any plain
    /// data: bytes for `GL_UNSIGNED_BYTE`, floats for `GL_FLOAT`), unpacked with the pixel
    /// store. An empty slice is C's NULL: the level gets undefined (zero) texels. Errors, in
    /// Mesa's order (checked against Mesa 22 in `tests/reference/calls/cases/textures.calls`):
    /// target (`GL_INVALID_ENUM`), level, sizes, border (`GL_INVALID_VALUE`), format and type
    /// (`GL_INVALID_ENUM`), internal format (`GL_INVALID_VALUE`), a slice shorter than the
    /// image (`GL_INVALID_VALUE`). A border (0 or 1) is stripped, as
    /// Mesa's gallium drivers strip it: the level is the inside, its border 0; a proxy keeps it.
    #[allow(clippy::too_many_arguments)]
    pub fn tex_image_2d<P: bytemuck::Pod>(
        &mut self,
        target: GLenum,
        level: GLint,
        internalformat: GLint,
        width: GLsizei,
        height: GLsizei,
        border: GLint,
        format: GLenum,
        type_: GLenum,
        pixels: &[P],
    ) {
        let bytes: &[u8] = bytemuck::cast_slice(pixels);
        self.tex_image(2, target, level, internalformat, (width, height), border, (format, type_), bytes);
    }

    /// `glTexImage1D`: as [`Gl::tex_image_2d`] for the bound 1D texture (height 1).
    #[allow(clippy::too_many_arguments)]
    pub fn tex_image_1d<P: bytemuck::Pod>(
        &mut self,
        target: GLenum,
        level: GLint,
        internalformat: GLint,
        width: GLsizei,
        border: GLint,
        format: GLenum,
        type_: GLenum,
        pixels: &[P],
    ) {
        let bytes: &[u8] = bytemuck::cast_slice(pixels);
        self.tex_image(1, target, level, internalformat, (width, 1), border, (format, type_), bytes);
    }

    #[allow(clippy::too_many_arguments)]
    fn tex_image(
        &mut self,
        dims: u8,
        target: GLenum,
        level: GLint,
        internalformat: GLint,
        (width, height): (GLsizei, GLsizei),
        border: GLint,
        (format, type_): (GLenum, GLenum),
        bytes: &[u8],
    ) {
        let store = self.unpack_store();
        if self.compiled(|| {
            ListCommand::Texture(TextureCall::TexImage {
                dims,
                target,
                level,
                internalformat,
                size: (width, height),
                border,
                format: (format, type_),
                image: (store, bytes.to_vec()),
            })
        }) || self.reject_inside_begin_end()
        {
            return;
        }
        let wanted = if dims == 1 { GL_TEXTURE_1D } else { GL_TEXTURE_2D };
        let proxy = proxy_index(target) == Some(usize::from(dims - 1));
        if target != wanted && !proxy {
            return self.set_error(GL_INVALID_ENUM);
        }
        let max_level = MAX_TEXTURE_SIZE.ilog2() as GLint;
        if !(0..=max_level).contains(&level) || width < 0 || height < 0 || !(0..=1).contains(&border) {
            return self.set_error(GL_INVALID_VALUE);
        }
        if !self.check_image_format(format, type_) {
            return;
        }
        let Some(base) = base_format(internalformat) else { return self.set_error(GL_INVALID_VALUE) };
        // Too large for its level (or too small for its border): an error, or for a proxy, a
        // proxy level of nothing (GL 1.1 §3.8.1: "no error is generated"), as Mesa's
        // `teximage` answers after the checks above.
        let fits = fits_level(dims, level, (width, height), border);
        if !fits && !proxy {
            return self.set_error(GL_INVALID_VALUE);
        }
        if proxy {
            // A proxy keeps the sizes and border as given (Mesa strips real images only).
            let image = fits.then(|| TexLevel { width: width as u32, height: height as u32, texels: Vec::new() });
            let object = &mut self.server.textures.proxies[usize::from(dims - 1)];
            return object.define_level(level as usize, image, (base, internalformat), if fits { border } else { 0 });
        }
        let (w, h) = (width as usize, height as usize);
        let texels = if bytes.is_empty() {
            vec![[0; 4]; w * h]
        } else {
            match self.unpack_texels((format, type_), w, h, bytes) {
                Some(texels) => texels,
                None => return self.set_error(GL_INVALID_VALUE),
            }
        };
        let (texels, w, h) = strip_border(dims, texels, (w, h), border as usize);
        let image = TexLevel { width: w as u32, height: h as u32, texels };
        self.bound_object_mut(dims).define_level(level as usize, Some(image), (base, internalformat), 0);
        self.image_changed(dims);
    }

    /// `glTexSubImage2D`: replaces a rectangle of an existing level. Errors: target
    /// (`GL_INVALID_ENUM`), a level not defined (`GL_INVALID_OPERATION`), a rectangle outside
    /// it or negative sizes (`GL_INVALID_VALUE`), format and type (`GL_INVALID_ENUM`).
    #[allow(clippy::too_many_arguments)]
    pub fn tex_sub_image_2d<P: bytemuck::Pod>(
        &mut self,
        target: GLenum,
        level: GLint,
        xoffset: GLint,
        yoffset: GLint,
        width: GLsizei,
        height: GLsizei,
        format: GLenum,
        type_: GLenum,
        pixels: &[P],
    ) {
        let bytes: &[u8] = bytemuck::cast_slice(pixels);
        let store = self.unpack_store();
        if self.compiled(|| {
            ListCommand::Texture(TextureCall::TexSubImage {
                target,
                level,
                offset: (xoffset, yoffset),
                size: (width, height),
                format: (format, type_),
                image: (store, bytes.to_vec()),
            })
        }) || self.reject_inside_begin_end()
        {
            return;
        }
        self.tex_sub_image(2, target, level, [xoffset, yoffset, width, height], (format, type_), bytes);
    }

    /// `glTexSubImage1D` and `glTexSubImage2D` once compiled: `rect` is x, y, width, height in
    /// the level (y 0 and height 1 for a 1D texture).
    pub(in crate::gl) fn tex_sub_image(
        &mut self,
        dims: u8,
        target: GLenum,
        level: GLint,
        rect: [GLint; 4],
        (format, type_): (GLenum, GLenum),
        bytes: &[u8],
    ) {
        if target_index(target) != Some(usize::from(dims - 1)) {
            return self.set_error(GL_INVALID_ENUM);
        }
        let Some((x, y, w, h)) = self.sub_image_rect(dims, level, rect) else { return };
        if !self.check_image_format(format, type_) {
            return;
        }
        let Some(texels) = self.unpack_texels((format, type_), w, h, bytes) else {
            return self.set_error(GL_INVALID_VALUE);
        };
        self.replace_texels(dims, level as usize, (x, y, w), &texels);
    }

    /// Checks a sub-image rectangle against the bound object's level `level`: a level outside
    /// 0..=log2(max size) → `GL_INVALID_VALUE`; a level not defined → `GL_INVALID_OPERATION`;
    /// negative sizes or a rectangle outside the level →
    /// `GL_INVALID_VALUE`. The rectangle as (x, y, width, height) when it fits.
    pub(in crate::gl) fn sub_image_rect(
        &mut self,
        dims: u8,
        level: GLint,
        rect: [GLint; 4],
    ) -> Option<(usize, usize, usize, usize)> {
        // Mesa checks the level's range before whether it is defined (measured).
        if !(0..=MAX_TEXTURE_SIZE.ilog2() as GLint).contains(&level) {
            self.set_error(GL_INVALID_VALUE);
            return None;
        }
        let defined = usize::try_from(level)
            .ok()
            .and_then(|l| self.bound_object(dims).levels.get(l).cloned().flatten())
            .map(|l| (i64::from(l.width), i64::from(l.height)));
        let Some((lw, lh)) = defined else {
            self.set_error(GL_INVALID_OPERATION);
            return None;
        };
        let [x, y, w, h] = rect.map(i64::from);
        if w < 0 || h < 0 || x < 0 || y < 0 || x + w > lw || y + h > lh {
            self.set_error(GL_INVALID_VALUE);
            return None;
        }
        Some((x as usize, y as usize, w as usize, h as usize))
    }

    /// Writes rows of `w` texels into level `level` of the bound object from (`x`, `y`) on.
    pub(in crate::gl) fn replace_texels(
        &mut self,
        dims: u8,
        level: usize,
        (x, y, w): (usize, usize, usize),
        texels: &[[u8; 4]],
    ) {
        let Some(Some(target)) = self.bound_object_mut(dims).levels.get_mut(level) else { return };
        for (row, source) in texels.chunks_exact(w.max(1)).enumerate() {
            let start = (y + row) * target.width as usize + x;
            target.texels[start..start + w].copy_from_slice(source);
        }
        self.image_changed(dims);
    }

    /// Checks `format` and `type_` as Mesa does for a colour texture: the image's errors
    /// ([`super::pixel_unpack::format_and_type_error`]), then a depth or stencil image →
    /// `GL_INVALID_OPERATION`. False after an error.
    fn check_image_format(&mut self, format: GLenum, type_: GLenum) -> bool {
        let error = format_and_type_error(format, type_).or((!texture_format(format)).then_some(GL_INVALID_OPERATION));
        if let Some(error) = error {
            self.set_error(error);
        }
        error.is_none()
    }

    /// Unpacks a `w`×`h` texture image from client memory to RGBA8 as GL 1.1 §3.8.1 says:
    /// as `glDrawPixels` reads it ([`super::pixel_unpack`]), through the pixel transfer (colour
    /// indices through the index-to-RGBA maps, colours through scale, bias and, with
    /// `GL_MAP_COLOR`, the colour maps), clamped to [0, 1]. `None` if `bytes` is short.
    fn unpack_texels(
        &self,
        (format, type_): (GLenum, GLenum),
        w: usize,
        h: usize,
        bytes: &[u8],
    ) -> Option<Vec<[u8; 4]>> {
        let transfer = self.color_transfer();
        let byte = |x: f32| (x.clamp(0.0, 1.0) * 255.0).round() as u8;
        let mut texels = Vec::with_capacity(w * h);
        unpack_each(self.unpack_store(), (w as GLsizei, h as GLsizei), format, type_, bytes, |c| {
            let c = match format {
                GL_COLOR_INDEX => self.index_to_rgba(c[0]),
                _ => transfer.as_ref().map_or(c, |t| t.apply(c)),
            };
            texels.push(c.map(byte));
        })?;
        Some(texels)
    }
}
