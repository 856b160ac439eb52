//! Texture images (GL 1.1 spec §3.8.1–3.8.2, GL 1.2's 3D images; Mesa `main/teximage.c`):
//! `glTexImage1D/2D/3D` and `glTexSubImage2D/3D` of the bound texture (proxies, borders, level
//! sizes), each image unpacked from client memory through the pixel store and the pixel
//! transfer into RGBA8.

use super::TextureCall;
use super::{base_format, fits_level, image_target_of, max_level, proxy_of, strip_border, texture_format};
use super::{ImageTarget, TexLevel};
use crate::gl::consts::*;
use crate::gl::lists::ListCommand;
use crate::gl::pixel_packed::depth_stencil_size;
use crate::gl::pixel_unpack::{format_and_type_error, image_stride, unpack_each};
use crate::gl::types::*;
use crate::gl::Gl;

/// The format and type a texture image of `format` and `type_` is read as: GL 3.0's
/// `GL_DEPTH_STENCIL` of `GL_UNSIGNED_INT_24_8`, which Mesa takes for a depth texture in every
/// context, as the 32-bit depths whose top 24 bits its depths are (the stencil's 8 bits weigh
/// in below 2⁻²⁴ of a depth; gleval keeps no stencil in textures); every other pair as it is.
pub(in crate::gl) fn depth_of_depth_stencil(format: GLenum, type_: GLenum) -> (GLenum, GLenum) {
    if (format, type_) == (GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8) {
        (GL_DEPTH_COMPONENT, GL_UNSIGNED_INT)
    } else {
        (format, type_)
    }
}

/// Whether a level of internal format `internal` keeps stencil indices beside its depths
/// (GL 3.0's `GL_DEPTH_STENCIL` and `GL_DEPTH24_STENCIL8`, `GL_EXT_packed_depth_stencil`'s, and
/// `GL_ARB_depth_buffer_float`'s `GL_DEPTH32F_STENCIL8`).
pub(in crate::gl) fn keeps_stencil(internal: GLint) -> bool {
    matches!(internal as GLenum, GL_DEPTH_STENCIL | GL_DEPTH24_STENCIL8 | GL_DEPTH32F_STENCIL8)
}

/// The most bytes a level's texels may take (4 a texel): llvmpipe's limit, about 1.75 GiB.
const MAX_LEVEL_BYTES: usize = 7 << 28;

/// A box of texels in a level: its first texel (x, y, z) and its size (width, height, depth);
/// z is 0 and the depth 1 below 3D, y 0 and the height 1 in 1D.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(in crate::gl) struct TexelBox {
    pub origin: [usize; 3],
    pub size: [usize; 3],
}

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
        self.tex_image(2, target, level, internalformat, [width, height, 1], border, (format, type_), bytes);
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
        self.tex_image(1, target, level, internalformat, [width, 1, 1], border, (format, type_), bytes);
    }

    /// `glTexImage3D` (GL 1.2 §3.8.1): as [`Gl::tex_image_2d`] for the bound 3D texture (or
    /// `GL_PROXY_TEXTURE_3D`), `depth` images read one after the other, each as a 2D image is,
    /// `GL_UNPACK_IMAGE_HEIGHT` rows apart, after `GL_UNPACK_SKIP_IMAGES` images. Sides up to
    /// [`crate::gl::MAX_3D_TEXTURE_SIZE`]; Mesa's errors in Mesa's order
    /// (`tests/reference/calls/cases/texture_3d.calls`).
    #[allow(clippy::too_many_arguments)]
    pub fn tex_image_3d<P: bytemuck::Pod>(
        &mut self,
        target: GLenum,
        level: GLint,
        internalformat: GLint,
        width: GLsizei,
        height: GLsizei,
        depth: GLsizei,
        border: GLint,
        format: GLenum,
        type_: GLenum,
        pixels: &[P],
    ) {
        let bytes: &[u8] = bytemuck::cast_slice(pixels);
        self.tex_image(3, target, level, internalformat, [width, height, depth], border, (format, type_), bytes);
    }

    #[allow(clippy::too_many_arguments)]
    pub(in crate::gl) fn tex_image(
        &mut self,
        dims: u8,
        target: GLenum,
        level: GLint,
        internalformat: GLint,
        size: [GLsizei; 3],
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
                size,
                border,
                format: (format, type_),
                image: (store, bytes.to_vec()),
            })
        }) || self.reject_inside_begin_end()
        {
            return;
        }
        let packed = format == GL_DEPTH_STENCIL && depth_stencil_size(type_).is_some();
        let given_type = type_;
        let (format, type_) = depth_of_depth_stencil(format, type_);
        let (image_target, proxy_slot) = (image_target_of(dims, target), proxy_of(dims, target));
        let proxy = proxy_slot.is_some();
        if image_target.is_none() && !proxy {
            return self.set_error(GL_INVALID_ENUM);
        }
        if !(0..=max_level(dims)).contains(&level) || size.iter().any(|&s| s < 0) || !(0..=1).contains(&border) {
            return self.set_error(GL_INVALID_VALUE);
        }
        // A rectangle has one level and no border (GL_ARB_texture_rectangle).
        let rectangle = image_target.map_or(proxy_slot, |t| Some(t.slot)) == Some(super::RECT);
        if rectangle && (level != 0 || border != 0) {
            return self.set_error(GL_INVALID_VALUE);
        }
        if let Some(error) = format_and_type_error(format, type_) {
            return self.set_error(error);
        }
        let Some(base) = base_format(internalformat) else { return self.set_error(GL_INVALID_VALUE) };
        // Depth data for a depth texture only, and no 3D depth texture (Mesa's
        // `_mesa_legal_texture_base_format_for_target`).
        if !texture_format(format, base) || (base == GL_DEPTH_COMPONENT && dims == 3) {
            return self.set_error(GL_INVALID_OPERATION);
        }
        // Too large for its level (or too small for its border): an error, or for a proxy, a
        // proxy level of nothing (GL 1.1 §3.8.1: "no error is generated"), as Mesa's
        // `teximage` answers after the checks above.
        // A cube map's faces are square (Mesa's `_mesa_legal_texture_dimensions`).
        let cube = image_target.map_or(proxy_slot, |t| Some(t.slot)) == Some(super::CUBE);
        let fits = fits_level(dims, level, size, border) && (!cube || size[0] == size[1]);
        if !fits && !proxy {
            return self.set_error(GL_INVALID_VALUE);
        }
        let [w, h, d] = size.map(|s| s as usize);
        // Too large for memory: a proxy of nothing, or GL_OUT_OF_MEMORY, as llvmpipe answers
        // (`llvmpipe_can_create_resource`; measured: 2048³ RGBA does not fit, 1024² × 447
        // does, about 1.75 GiB).
        let fits = fits && (w * h * d).checked_mul(4).is_some_and(|bytes| bytes <= MAX_LEVEL_BYTES);
        if !fits && !proxy {
            return self.set_error(GL_OUT_OF_MEMORY);
        }
        if proxy {
            // A proxy keeps the sizes and border as given (Mesa strips real images only).
            let image = fits.then(|| TexLevel::sized([w, h, d], Vec::new()));
            let object = &mut self.server.textures.proxies[proxy_slot.expect("a proxy")];
            return object.define_level(
                0,
                level as usize,
                image,
                (base, internalformat),
                if fits { border } else { 0 },
            );
        }
        let texels = if bytes.is_empty() {
            let mut texels = Vec::new();
            if texels.try_reserve_exact(w * h * d).is_err() {
                return self.set_error(GL_OUT_OF_MEMORY);
            }
            texels.resize(w * h * d, [0; 4]);
            texels
        } else {
            match self.unpack_texels(dims, (format, type_), [w, h, d], bytes, internalformat) {
                Some(texels) => texels,
                None => return self.set_error(GL_INVALID_VALUE),
            }
        };
        let (texels, stencil) = if !keeps_stencil(internalformat) {
            (texels, Vec::new())
        } else if packed && !bytes.is_empty() {
            let Some((texels, stencil)) = self.unpack_depth_stencil([w, h, d], (bytes, given_type), internalformat)
            else {
                return self.set_error(GL_INVALID_VALUE);
            };
            let stencil = stencil.into_iter().map(|s| [s, 0, 0, 0]).collect();
            let (stencil, _) = strip_border(dims, stencil, [w, h, d], border as usize);
            (texels, stencil.into_iter().map(|t| t[0]).collect())
        } else {
            let zeros = vec![0; texels.len()];
            (texels, zeros)
        };
        let (texels, [w, h, d]) = strip_border(dims, texels, [w, h, d], border as usize);
        let image = TexLevel { stencil, ..TexLevel::sized([w, h, d], texels) };
        let t = image_target.expect("not a proxy");
        self.bound_object_mut(t.slot).define_level(t.face, level as usize, Some(image), (base, internalformat), 0);
        self.image_changed(t.slot);
        self.generate_if_base(t, level as usize);
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
        let region = ([xoffset, yoffset, 0], [width, height, 1]);
        self.tex_sub_image_call(2, target, level, region, (format, type_), bytemuck::cast_slice(pixels));
    }

    /// `glTexSubImage1D`: as [`Gl::tex_sub_image_2d`] for the bound 1D texture (one row at
    /// `xoffset`).
    #[allow(clippy::too_many_arguments)]
    pub fn tex_sub_image_1d<P: bytemuck::Pod>(
        &mut self,
        target: GLenum,
        level: GLint,
        xoffset: GLint,
        width: GLsizei,
        format: GLenum,
        type_: GLenum,
        pixels: &[P],
    ) {
        let region = ([xoffset, 0, 0], [width, 1, 1]);
        self.tex_sub_image_call(1, target, level, region, (format, type_), bytemuck::cast_slice(pixels));
    }

    /// `glTexSubImage3D` (GL 1.2 §3.8.2): as [`Gl::tex_sub_image_2d`] for a box of the bound 3D
    /// texture's level, the images read as [`Gl::tex_image_3d`] reads them.
    #[allow(clippy::too_many_arguments)]
    pub fn tex_sub_image_3d<P: bytemuck::Pod>(
        &mut self,
        target: GLenum,
        level: GLint,
        xoffset: GLint,
        yoffset: GLint,
        zoffset: GLint,
        width: GLsizei,
        height: GLsizei,
        depth: GLsizei,
        format: GLenum,
        type_: GLenum,
        pixels: &[P],
    ) {
        let region = ([xoffset, yoffset, zoffset], [width, height, depth]);
        self.tex_sub_image_call(3, target, level, region, (format, type_), bytemuck::cast_slice(pixels));
    }

    /// `glTexSubImage1D/2D/3D` as called: compiled into a display list, or run.
    pub(in crate::gl) fn tex_sub_image_call(
        &mut self,
        dims: u8,
        target: GLenum,
        level: GLint,
        (offset, size): ([GLint; 3], [GLsizei; 3]),
        format: (GLenum, GLenum),
        bytes: &[u8],
    ) {
        let store = self.unpack_store();
        if self.compiled(|| {
            ListCommand::Texture(TextureCall::TexSubImage {
                dims,
                target,
                level,
                offset,
                size,
                format,
                image: (store, bytes.to_vec()),
            })
        }) || self.reject_inside_begin_end()
        {
            return;
        }
        self.tex_sub_image(dims, target, level, (offset, size), format, bytes);
    }

    /// `glTexSubImage1D/2D/3D` once compiled: `offset` and `size` the box in the level (y 0
    /// and height 1 for a 1D texture, z 0 and depth 1 below 3D).
    pub(in crate::gl) fn tex_sub_image(
        &mut self,
        dims: u8,
        target: GLenum,
        level: GLint,
        (offset, size): ([GLint; 3], [GLsizei; 3]),
        (format, type_): (GLenum, GLenum),
        bytes: &[u8],
    ) {
        let Some(t) = image_target_of(dims, target) else { return self.set_error(GL_INVALID_ENUM) };
        let packed = format == GL_DEPTH_STENCIL && depth_stencil_size(type_).is_some();
        let given_type = type_;
        let (format, type_) = depth_of_depth_stencil(format, type_);
        let Some(region) = self.sub_image_box(t, level, offset, size) else { return };
        let base = self.bound_object(t.slot).face(t.face).formats[level as usize];
        if !self.check_image_format(format, type_, base) {
            return;
        }
        let internal = self.bound_object(t.slot).face(t.face).level_format(level as usize).0;
        let Some(texels) = self.unpack_texels(dims, (format, type_), region.size, bytes, internal) else {
            return self.set_error(GL_INVALID_VALUE);
        };
        // Depths alone leave a depth-and-stencil level's stencil as it was (Mesa's
        // `_mesa_texstore_z24_s8` keeps it).
        if packed && keeps_stencil(internal) {
            let Some((texels, stencil)) = self.unpack_depth_stencil(region.size, (bytes, given_type), internal) else {
                return self.set_error(GL_INVALID_VALUE);
            };
            self.replace_stencil(t, level as usize, region, &stencil);
            return self.replace_texels(t, level as usize, region, &texels);
        }
        self.replace_texels(t, level as usize, region, &texels);
    }

    /// A `GL_DEPTH_STENCIL` image of `GL_UNSIGNED_INT_24_8` for a depth-and-stencil level of
    /// `internal` format: each element's 24-bit depth kept exactly (as Mesa's Z24_S8 store
    /// copies it; measured, `capi/tests/depth_stencil.c`) and its stencil index, read with the
    /// unpack modes; `None` if `bytes` is short. Depth-and-stencil textures are 1D, 2D or cube
    /// maps: `d` is 1.
    fn unpack_depth_stencil(
        &self,
        [w, h, d]: [usize; 3],
        (bytes, type_): (&[u8], GLenum),
        internal: GLint,
    ) -> Option<(Vec<[u8; 4]>, Vec<u8>)> {
        let (mut texels, mut stencil) = (Vec::with_capacity(w * h * d), Vec::with_capacity(w * h * d));
        let size = (w as GLsizei, (h * d) as GLsizei);
        // A 24-bit depth is stored as it is; a float one as a float image's depth (measured:
        // 0.125 in a GL_DEPTH24_STENCIL8 level reads back as 0x1FFFFF).
        let texel = if type_ == GL_UNSIGNED_INT_24_8 { super::depth::copied_depth_texel } else { super::depth_texel };
        unpack_each(self.unpack_store(), size, GL_DEPTH_STENCIL, type_, bytes, |c| {
            texels.push(texel(c[0], internal));
            stencil.push(c[1] as u8);
        })?;
        Some((texels, stencil))
    }

    /// Writes the box's stencil indices into level `level` of the bound object (a
    /// depth-and-stencil level).
    fn replace_stencil(&mut self, t: ImageTarget, level: usize, region: TexelBox, stencil: &[u8]) {
        let Some(Some(target)) = self.bound_object_mut(t.slot).face_mut(t.face).levels.get_mut(level) else { return };
        let ([x, y, _], [w, _, _]) = (region.origin, region.size);
        let (width, count) = (target.width as usize, target.texels.len());
        target.stencil.resize(count, 0);
        for (j, row) in stencil.chunks_exact(w.max(1)).enumerate() {
            let start = (y + j) * width + x;
            target.stencil[start..start + w].copy_from_slice(row);
        }
    }

    /// Checks a sub-image box against the bound object's level `level`: a level outside
    /// 0..=log2(max size) → `GL_INVALID_VALUE`; a level not defined → `GL_INVALID_OPERATION`;
    /// negative sizes or a box outside the level → `GL_INVALID_VALUE`. The box when it fits.
    pub(in crate::gl) fn sub_image_box(
        &mut self,
        t: ImageTarget,
        level: GLint,
        offset: [GLint; 3],
        size: [GLsizei; 3],
    ) -> Option<TexelBox> {
        // Mesa checks the level's range before whether it is defined (measured).
        if !(0..=max_level(t.dims())).contains(&level) {
            self.set_error(GL_INVALID_VALUE);
            return None;
        }
        let defined = usize::try_from(level)
            .ok()
            .and_then(|l| self.bound_object(t.slot).face(t.face).level(l))
            .map(|l| [l.width, l.height, l.depth].map(i64::from));
        let Some(extent) = defined else {
            self.set_error(GL_INVALID_OPERATION);
            return None;
        };
        let fits = (0..3).all(|k| {
            let (o, s) = (i64::from(offset[k]), i64::from(size[k]));
            o >= 0 && s >= 0 && o + s <= extent[k]
        });
        if !fits {
            self.set_error(GL_INVALID_VALUE);
            return None;
        }
        Some(TexelBox { origin: offset.map(|o| o as usize), size: size.map(|s| s as usize) })
    }

    /// Writes the box's texels (rows of its width, images of its height) into level `level` of
    /// the bound object.
    pub(in crate::gl) fn replace_texels(&mut self, t: ImageTarget, level: usize, region: TexelBox, texels: &[[u8; 4]]) {
        let Some(Some(target)) = self.bound_object_mut(t.slot).face_mut(t.face).levels.get_mut(level) else { return };
        let ([x, y, z], [w, h, _]) = (region.origin, region.size);
        let (width, height) = (target.width as usize, target.height as usize);
        for (row, source) in texels.chunks_exact(w.max(1)).enumerate() {
            let (j, k) = (row % h.max(1), row / h.max(1));
            let start = ((z + k) * height + y + j) * width + x;
            target.texels[start..start + w].copy_from_slice(source);
        }
        self.image_changed(t.slot);
        self.generate_if_base(t, level);
    }

    /// Checks `format` and `type_` as Mesa does for a level of base format `base`: the image's
    /// errors ([`super::pixel_unpack::format_and_type_error`]), then data that does not agree
    /// with the level (depths for a colour level, colours for a depth level, stencil indices)
    /// → `GL_INVALID_OPERATION`. False after an error.
    fn check_image_format(&mut self, format: GLenum, type_: GLenum, base: GLenum) -> bool {
        let error =
            format_and_type_error(format, type_).or((!texture_format(format, base)).then_some(GL_INVALID_OPERATION));
        if let Some(error) = error {
            self.set_error(error);
        }
        error.is_none()
    }

    /// Unpacks a texture image of `size` (width, height, depth) from client memory to RGBA8 as
    /// GL 1.1 §3.8.1 says: as `glDrawPixels` reads it ([`super::pixel_unpack`]), through the
    /// pixel transfer (colour indices through the index-to-RGBA maps, colours through scale,
    /// bias and, with `GL_MAP_COLOR`, the colour maps), clamped to [0, 1]. A 3D image's images
    /// lie [`image_stride`] bytes apart after the skipped ones (GL 1.2; below 3D the image
    /// modes do nothing). Depths go through the depth scale and bias into the texels a depth
    /// level of internal format `internal` keeps. `None` if `bytes` is short.
    fn unpack_texels(
        &self,
        dims: u8,
        (format, type_): (GLenum, GLenum),
        [w, h, d]: [usize; 3],
        bytes: &[u8],
        internal: GLint,
    ) -> Option<Vec<[u8; 4]>> {
        let transfer = self.color_transfer();
        let depth = matches!(format, GL_DEPTH_COMPONENT | GL_DEPTH_STENCIL).then(|| self.depth_transfer());
        // Halfway products round to even, as Mesa's float-to-unorm8 texel store does (measured:
        // 2.5/255 stores 2, 3.5/255 stores 4; `unpack_widening.calls`).
        let byte = |x: f32| (x.clamp(0.0, 1.0) * 255.0).round_ties_even() as u8;
        let store = self.unpack_store();
        let (stride, skipped) = if dims == 3 {
            (image_stride(store, (w, h), format, type_).unwrap_or(0), store.skip_images)
        } else {
            (0, 0)
        };
        let mut texels = Vec::with_capacity(w * h * d);
        // RGBA bytes without a transfer are the texels as they are (c/255 converted back is c):
        // copied row by row, the common case of large images.
        let as_they_are = format == GL_RGBA && type_ == GL_UNSIGNED_BYTE && transfer.is_none();
        for k in 0..d {
            let image = bytes.get((skipped + k) * stride..)?;
            if as_they_are {
                copy_rgba8(store, (w, h), image, &mut texels)?;
                continue;
            }
            unpack_each(store, (w as GLsizei, h as GLsizei), format, type_, image, |c| {
                // A depth travels in the red slot (`to_rgba`).
                if let Some(depth) = depth {
                    return texels.push(super::depth_texel(depth.apply(c[0]), internal));
                }
                let c = match format {
                    GL_COLOR_INDEX => self.index_to_rgba(c[0]),
                    _ => transfer.as_ref().map_or(c, |t| t.apply(c)),
                };
                texels.push(c.map(byte));
            })?;
        }
        Some(texels)
    }
}

/// Appends a `w` × `h` image of RGBA bytes as [`unpack_each`] reads it under `store` (rows
/// padded to the alignment, rows and pixels skipped); `None` if `image` is short.
fn copy_rgba8(
    store: crate::gl::pixels::PixelStore,
    (w, h): (usize, usize),
    image: &[u8],
    texels: &mut Vec<[u8; 4]>,
) -> Option<()> {
    if w == 0 || h == 0 {
        return Some(());
    }
    let stride = store.row_stride(w, 4, 1);
    let first = store.first_byte(stride, 4);
    if image.len() < first + (h - 1) * stride + 4 * w {
        return None;
    }
    for row in 0..h {
        let bytes = &image[first + row * stride..][..4 * w];
        texels.extend(bytes.chunks_exact(4).map(|p| [p[0], p[1], p[2], p[3]]));
    }
    Some(())
}
