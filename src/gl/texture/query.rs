//! The texture parameters GL 1.1 has besides filters and wraps (`GL_TEXTURE_BORDER_COLOR`,
//! `GL_TEXTURE_PRIORITY`), the vector forms `glTexParameterfv/iv`, and the texture queries:
//! `glGetTexParameter*`, `glGetTexLevelParameter*`, `glGetTexEnv*`, `glGetTexImage` (GL 1.1
//! spec §6.1.4; Mesa `main/texparam.c`, `texenv.c`, `texgetimage.c`), each with Mesa's checks
//! in Mesa's order and its conversions.

use super::super::consts::*;
use super::super::pixel_packed::Source;
use super::super::state_var::{c_int, float_to_int, iround};
use super::super::types::*;
use super::super::variants::GlComponent;
use super::super::Gl;
use super::TextureCall;
use super::{image_target, max_level, proxy_index, slot_dims, target_index, FaceImages};

/// A texture object's parameters beyond [`super::TexParams`], and each level's internal format
/// as the program gave it and its border (what `GL_TEXTURE_INTERNAL_FORMAT` and
/// `GL_TEXTURE_BORDER` report).
#[derive(Clone, Debug, PartialEq)]
pub(super) struct ObjectExtras {
    /// `GL_TEXTURE_BORDER_COLOR`, as given (reported clamped to [0, 1], as Mesa does for an
    /// 8-bit framebuffer).
    border_color: [f32; 4],
    /// `GL_TEXTURE_PRIORITY`, clamped to [0, 1]; `glPrioritizeTextures` sets it too.
    pub(crate) priority: f32,
}

impl Default for ObjectExtras {
    fn default() -> Self {
        Self { border_color: [0.0; 4], priority: 1.0 }
    }
}

impl ObjectExtras {
    /// The border colour and priority (`GL_TEXTURE_BIT` saves them).
    pub(super) fn sampling(&self) -> ([f32; 4], f32) {
        (self.border_color, self.priority)
    }

    /// Restores what [`ObjectExtras::sampling`] gave.
    pub(super) fn set_sampling(&mut self, (border_color, priority): ([f32; 4], f32)) {
        (self.border_color, self.priority) = (border_color, priority);
    }
}

/// A level given as a float, as Mesa's `_mesa_TexParameterf` converts it: rounded
/// half away from zero, saturated to `GLint` (`glTexParameterf(GL_TEXTURE_BASE_LEVEL, 3.75)` is
/// level 4, -0.5 is -1; measured on Mesa 22.3).
fn round_level(p: GLfloat) -> GLint {
    let p = f64::from(p);
    if p > 0.0 {
        if p > f64::from(GLint::MAX) {
            GLint::MAX
        } else {
            (p + 0.5) as GLint
        }
    } else if p < f64::from(GLint::MIN) {
        GLint::MIN
    } else {
        (p - 0.5) as GLint
    }
}

/// The bits llvmpipe gives each component of a level of base format `base`, in the order red,
/// green, blue, alpha, luminance, intensity (Mesa 22.3 through OSMesa: 8-bit formats, 0 for a
/// component the base format lacks).
fn component_sizes(base: GLenum) -> [GLint; 6] {
    match base {
        GL_RGBA => [8, 8, 8, 8, 0, 0],
        GL_RGB => [8, 8, 8, 0, 0, 0],
        GL_ALPHA => [0, 0, 0, 8, 0, 0],
        GL_LUMINANCE => [0, 0, 0, 0, 8, 0],
        GL_LUMINANCE_ALPHA => [0, 0, 0, 8, 8, 0],
        GL_INTENSITY => [0, 0, 0, 0, 0, 8],
        _ => [0; 6],
    }
}

/// A level texel (RGBA8 as stored) as the components `glGetTexImage` reads of base format
/// `base` (GL 1.1 §6.1.4, table 6.1): luminance is R, a missing colour 0, a missing alpha 1.
fn texel_rgba(base: GLenum, t: [u8; 4]) -> [f32; 4] {
    // Mesa multiplies by 1/255 in float (50 → 0x3E48C8CA, where 50/255 rounds to ...C9).
    let [r, g, b, a] = t.map(|c| f32::from(c) * (1.0 / 255.0));
    match base {
        // Intensity as Mesa 22.3 returns it (measured): I in R, alpha 1.
        GL_LUMINANCE | GL_INTENSITY => [r, 0.0, 0.0, 1.0],
        GL_LUMINANCE_ALPHA => [r, 0.0, 0.0, a],
        GL_ALPHA => [0.0, 0.0, 0.0, a],
        GL_RGB => [r, g, b, 1.0],
        _ => [r, g, b, a],
    }
}

impl Gl {
    /// Values `glTexParameter*v` read and `glGetTexParameter*v` write for `pname`: 4 for
    /// `GL_TEXTURE_BORDER_COLOR`, else 1.
    #[must_use]
    pub fn tex_parameter_param_count(pname: GLenum) -> usize {
        if pname == GL_TEXTURE_BORDER_COLOR {
            4
        } else {
            1
        }
    }

    /// Values `glTexEnv*v` read and `glGetTexEnv*v` write for `pname`: 4 for
    /// `GL_TEXTURE_ENV_COLOR`, else 1.
    #[must_use]
    pub fn tex_env_param_count(pname: GLenum) -> usize {
        if pname == GL_TEXTURE_ENV_COLOR {
            4
        } else {
            1
        }
    }

    /// `glTexParameterfv`: as [`Gl::tex_parameteri`] for the filters and wraps (the value
    /// truncated to an enum), and `GL_TEXTURE_BORDER_COLOR` (4 values) and
    /// `GL_TEXTURE_PRIORITY` (clamped to [0, 1]). A short slice → `GL_INVALID_VALUE`.
    pub fn tex_parameterfv(&mut self, target: GLenum, pname: GLenum, params: &[GLfloat]) {
        match pname {
            GL_TEXTURE_BORDER_COLOR
            | GL_TEXTURE_PRIORITY
            | GL_TEXTURE_MIN_LOD
            | GL_TEXTURE_MAX_LOD
            | GL_TEXTURE_LOD_BIAS => self.tex_parameter_values(target, pname, params),
            _ => match params.first() {
                // Mesa truncates an enum given as a float (9729.75 is GL_LINEAR), and rounds a level.
                Some(&p) if matches!(pname, GL_TEXTURE_BASE_LEVEL | GL_TEXTURE_MAX_LEVEL) => {
                    self.tex_parameteri(target, pname, round_level(p))
                }
                Some(&p) => self.tex_parameteri(target, pname, p as GLint),
                None => self.set_error(GL_INVALID_VALUE),
            },
        }
    }

    /// `glTexParameteriv`: the border colour normalised, the priority and enums as they are.
    pub fn tex_parameteriv(&mut self, target: GLenum, pname: GLenum, params: &[GLint]) {
        match pname {
            GL_TEXTURE_BORDER_COLOR => {
                let v: Vec<f32> = params.iter().take(4).map(|p| p.normalized()).collect();
                self.tex_parameter_values(target, pname, &v);
            }
            GL_TEXTURE_PRIORITY | GL_TEXTURE_MIN_LOD | GL_TEXTURE_MAX_LOD | GL_TEXTURE_LOD_BIAS => {
                let v: Vec<f32> = params.iter().take(1).map(|&p| p as f32).collect();
                self.tex_parameter_values(target, pname, &v);
            }
            _ => match params.first() {
                Some(&p) => self.tex_parameteri(target, pname, p),
                None => self.set_error(GL_INVALID_VALUE),
            },
        }
    }

    /// The float-valued parameters, compiled into lists as GL does.
    fn tex_parameter_values(&mut self, target: GLenum, pname: GLenum, params: &[GLfloat]) {
        let command = || {
            super::super::lists::ListCommand::Texture(TextureCall::TexParameterValues(target, pname, params.to_vec()))
        };
        if self.compiled(command) || self.reject_inside_begin_end() {
            return;
        }
        let Some(t) = target_index(target) else { return self.set_error(GL_INVALID_ENUM) };
        let needed = Self::tex_parameter_param_count(pname);
        let Some(values) = params.get(..needed) else { return self.set_error(GL_INVALID_VALUE) };
        let extra = &mut self.bound_object_mut(t).extra;
        match pname {
            GL_TEXTURE_BORDER_COLOR => extra.border_color.copy_from_slice(values),
            GL_TEXTURE_PRIORITY => extra.priority = values[0].clamp(0.0, 1.0),
            _ => {
                let object = self.bound_object_mut(t);
                let lod = &mut object.params.lod;
                match pname {
                    GL_TEXTURE_MIN_LOD => lod.min = values[0],
                    GL_TEXTURE_MAX_LOD => lod.max = values[0],
                    _ => lod.bias = values[0],
                }
            }
        }
        self.touch_state();
    }

    /// `glGetTexParameterfv`: the filters and wraps (enums), `GL_TEXTURE_BORDER_COLOR` (4),
    /// `GL_TEXTURE_PRIORITY`, `GL_TEXTURE_RESIDENT` (always true: gleval keeps every texture
    /// resident, as llvmpipe answers). Another target or name → `GL_INVALID_ENUM`.
    pub fn get_tex_parameterfv(&mut self, target: GLenum, pname: GLenum, params: &mut [GLfloat]) {
        if let Some(v) = self.tex_parameter_answer(target, pname, params.len()) {
            params[..v.len()].copy_from_slice(&v);
        }
    }

    /// `glGetTexParameteriv`: the border colour scaled as `glGetIntegerv` scales colours, the
    /// priority too (Mesa), the rest as they are.
    pub fn get_tex_parameteriv(&mut self, target: GLenum, pname: GLenum, params: &mut [GLint]) {
        if let Some(v) = self.tex_parameter_answer(target, pname, params.len()) {
            for (out, x) in params.iter_mut().zip(v) {
                *out = match pname {
                    GL_TEXTURE_BORDER_COLOR | GL_TEXTURE_PRIORITY => float_to_int(x.into()),
                    // Mesa's IROUND of the float LOD limits and bias.
                    GL_TEXTURE_MIN_LOD | GL_TEXTURE_MAX_LOD | GL_TEXTURE_LOD_BIAS => iround(x.into()),
                    _ => c_int(x),
                };
            }
        }
    }

    fn tex_parameter_answer(&mut self, target: GLenum, pname: GLenum, room: usize) -> Option<Vec<f32>> {
        if self.reject_inside_begin_end() {
            return None;
        }
        let Some(t) = target_index(target) else {
            self.set_error(GL_INVALID_ENUM);
            return None;
        };
        let object = self.bound_object(t);
        let p = object.params;
        let values = match pname {
            GL_TEXTURE_MIN_FILTER => vec![p.min_filter as f32],
            GL_TEXTURE_MAG_FILTER => vec![p.mag_filter as f32],
            GL_TEXTURE_WRAP_S => vec![p.wrap_s as f32],
            GL_TEXTURE_WRAP_T => vec![p.wrap_t as f32],
            GL_TEXTURE_WRAP_R => vec![p.wrap_r as f32],
            GL_GENERATE_MIPMAP => vec![f32::from(u8::from(p.generate_mipmap))],
            GL_TEXTURE_BASE_LEVEL => vec![p.base_level as f32],
            GL_DEPTH_TEXTURE_MODE => vec![p.depth.mode as f32],
            GL_TEXTURE_COMPARE_MODE => vec![p.depth.compare_mode as f32],
            GL_TEXTURE_COMPARE_FUNC => vec![p.depth.compare_func as f32],
            GL_TEXTURE_MAX_LEVEL => vec![p.max_level as f32],
            GL_TEXTURE_MIN_LOD => vec![p.lod.min],
            GL_TEXTURE_MAX_LOD => vec![p.lod.max],
            GL_TEXTURE_LOD_BIAS => vec![p.lod.bias],
            GL_TEXTURE_BORDER_COLOR => object.extra.border_color.map(|c| c.clamp(0.0, 1.0)).to_vec(),
            GL_TEXTURE_PRIORITY => vec![object.extra.priority],
            GL_TEXTURE_RESIDENT => vec![1.0],
            _ => {
                self.set_error(GL_INVALID_ENUM);
                return None;
            }
        };
        self.room_for(values, room)
    }

    /// `glGetTexLevelParameterfv`: `GL_TEXTURE_WIDTH`, `_HEIGHT`, `_DEPTH` (GL 1.2),
    /// `_BORDER`, `_INTERNAL_FORMAT` (`GL_TEXTURE_COMPONENTS`), and the component sizes of
    /// `level` of the bound 1D, 2D or 3D texture, or of a proxy (`GL_PROXY_TEXTURE_1D`, `_2D`,
    /// `_3D`); a level never defined answers 0 (its internal format `GL_RGBA`, as Mesa).
    /// Errors in Mesa's order: target (`GL_INVALID_ENUM`), level outside 0..=log2 of the
    /// largest size (`GL_INVALID_VALUE`), name (`GL_INVALID_ENUM`).
    pub fn get_tex_level_parameterfv(&mut self, target: GLenum, level: GLint, pname: GLenum, params: &mut [GLfloat]) {
        if let Some(v) = self.tex_level_answer(target, level, pname, params.len()) {
            params[0] = v as GLfloat;
        }
    }

    /// `glGetTexLevelParameteriv`: as [`Gl::get_tex_level_parameterfv`].
    pub fn get_tex_level_parameteriv(&mut self, target: GLenum, level: GLint, pname: GLenum, params: &mut [GLint]) {
        if let Some(v) = self.tex_level_answer(target, level, pname, params.len()) {
            params[0] = v;
        }
    }

    fn tex_level_answer(&mut self, target: GLenum, level: GLint, pname: GLenum, room: usize) -> Option<GLint> {
        if self.reject_inside_begin_end() {
            return None;
        }
        let (images, dims): (&FaceImages, u8) = match (image_target(target), proxy_index(target)) {
            (Some(t), _) => (self.bound_object(t.slot).face(t.face), t.dims()),
            (_, Some(p)) => (self.server.textures.proxies[p].face(0), slot_dims(p)),
            _ => {
                self.set_error(GL_INVALID_ENUM);
                return None;
            }
        };
        if !(0..=max_level(dims)).contains(&level) {
            self.set_error(GL_INVALID_VALUE);
            return None;
        }
        let l = level as usize;
        let defined = images.level(l);
        let (internal, border) = match defined {
            Some(_) => images.level_format(l),
            None => (GL_RGBA as GLint, 0),
        };
        let sizes = defined.map_or([0; 6], |_| component_sizes(images.formats[l]));
        let value = match pname {
            GL_TEXTURE_WIDTH => defined.map_or(0, |d| d.width as GLint),
            GL_TEXTURE_HEIGHT => defined.map_or(0, |d| d.height as GLint),
            GL_TEXTURE_DEPTH => defined.map_or(0, |d| d.depth as GLint),
            GL_TEXTURE_BORDER => border,
            GL_TEXTURE_INTERNAL_FORMAT => internal,
            GL_TEXTURE_RED_SIZE => sizes[0],
            GL_TEXTURE_GREEN_SIZE => sizes[1],
            GL_TEXTURE_BLUE_SIZE => sizes[2],
            GL_TEXTURE_ALPHA_SIZE => sizes[3],
            GL_TEXTURE_LUMINANCE_SIZE => sizes[4],
            GL_TEXTURE_INTENSITY_SIZE => sizes[5],
            GL_TEXTURE_DEPTH_SIZE if defined.is_some() && images.formats[l] == GL_DEPTH_COMPONENT => {
                super::depth::depth_bits(internal) as GLint
            }
            // GL 3.0's depth-and-stencil formats have llvmpipe's 8 stencil bits (piglit's
            // sized-texture-format-channels); gleval keeps the depths only, since nothing of
            // GL 1.5 reads a texture's stencil back.
            GL_TEXTURE_STENCIL_SIZE if defined.is_some() && super::image::keeps_stencil(internal) => 8,
            // Colour textures have neither; Mesa answers both names (ARB_depth_texture, and
            // GL 3.0's stencil size, unguarded in `get_tex_level_parameter_image`).
            GL_TEXTURE_DEPTH_SIZE | GL_TEXTURE_STENCIL_SIZE => 0,
            // GL 1.3: no image is kept compressed (`compressed.rs`), so none has a compressed
            // size to report (Mesa's `GL_INVALID_OPERATION` for an uncompressed image).
            GL_TEXTURE_COMPRESSED => 0,
            GL_TEXTURE_COMPRESSED_IMAGE_SIZE => {
                self.set_error(GL_INVALID_OPERATION);
                return None;
            }
            _ => {
                self.set_error(GL_INVALID_ENUM);
                return None;
            }
        };
        self.room_for(vec![value], room).map(|v| v[0])
    }

    /// `glGetTexEnvfv`: `GL_TEXTURE_ENV_MODE` (an enum) or `GL_TEXTURE_ENV_COLOR` (4 values) of
    /// `GL_TEXTURE_ENV`; another target or name → `GL_INVALID_ENUM`.
    pub fn get_tex_envfv(&mut self, target: GLenum, pname: GLenum, params: &mut [GLfloat]) {
        if let Some(v) = self.tex_env_answer(target, pname, params.len()) {
            params[..v.len()].copy_from_slice(&v);
        }
    }

    /// `glGetTexEnviv`: the colour scaled as `glGetIntegerv` scales colours.
    pub fn get_tex_enviv(&mut self, target: GLenum, pname: GLenum, params: &mut [GLint]) {
        if let Some(v) = self.tex_env_answer(target, pname, params.len()) {
            for (out, x) in params.iter_mut().zip(v) {
                *out = if pname == GL_TEXTURE_ENV_COLOR { float_to_int(x.into()) } else { x as GLint };
            }
        }
    }

    fn tex_env_answer(&mut self, target: GLenum, pname: GLenum, room: usize) -> Option<Vec<f32>> {
        if self.reject_inside_begin_end() {
            return None;
        }
        // A unit beyond the fixed-function ones answers zeros, as Mesa (measured).
        let env = self.active_env().copied();
        let zeros = |n: usize| vec![0.0; n];
        let values = match (target, pname) {
            (GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE) => env.map_or(zeros(1), |e| vec![e.mode as f32]),
            (GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR) => env.map_or(zeros(4), |e| e.color.to_vec()),
            (GL_TEXTURE_ENV, p) if super::combine::is_combine_name(p) => {
                env.map_or(zeros(1), |e| vec![e.combine.get(p)])
            }
            (GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS) => env.map_or(zeros(1), |e| vec![e.lod_bias]),
            (GL_POINT_SPRITE, GL_COORD_REPLACE) => vec![f32::from(u8::from(self.coord_replace()))],
            _ => {
                self.set_error(GL_INVALID_ENUM);
                return None;
            }
        };
        self.room_for(values, room)
    }

    /// Bytes `glGetTexImage` writes for `level` of `target` in `format` and `type_` under the
    /// pack modes (a 3D level's images one after the other, GL 1.2 §6.1.4, after the skipped
    /// ones); `None` where it writes nothing (a bad argument, an undefined level).
    #[must_use]
    pub fn tex_image_len(&self, target: GLenum, level: GLint, format: GLenum, type_: GLenum) -> Option<usize> {
        let t = image_target(target)?;
        let l = self.bound_object(t.slot).face(t.face).level(usize::try_from(level).ok()?)?;
        let image = self.packed_image_len(l.width as GLsizei, l.height as GLsizei, format, type_)?;
        if t.dims() < 3 || image == 0 {
            return Some(image);
        }
        let (stride, skipped) = self.packed_image_stride((l.width as usize, l.height as usize), format, type_)?;
        Some((skipped + l.depth as usize - 1) * stride + image)
    }

    /// `glGetTexImage` of `GL_DEPTH_STENCIL` (`GL_EXT_packed_depth_stencil`): each texel's
    /// depth as 24 bits over its stencil index. A type other than `GL_UNSIGNED_INT_24_8` →
    /// `GL_INVALID_ENUM`; a level without stencil (any but `GL_DEPTH_STENCIL` and
    /// `GL_DEPTH24_STENCIL8`) → `GL_INVALID_OPERATION` (Mesa's `getteximage_error_check`).
    fn get_depth_stencil_image(
        &mut self,
        (target, t): (GLenum, super::ImageTarget),
        level: usize,
        type_: GLenum,
        pixels: &mut [u8],
    ) {
        let Some(size) = crate::gl::pixel_packed::depth_stencil_size(type_) else {
            return self.set_error(GL_INVALID_ENUM);
        };
        let images = self.bound_object(t.slot).face(t.face);
        let internal = images.level_format(level).0;
        if !super::image::keeps_stencil(internal) {
            return self.set_error(GL_INVALID_OPERATION);
        }
        let Some(needed) = self.tex_image_len(target, level as GLint, GL_DEPTH_STENCIL, type_) else { return };
        if pixels.is_empty() || needed == 0 {
            return;
        }
        if pixels.len() < needed {
            return self.set_error(GL_INVALID_VALUE);
        }
        let images = self.bound_object(t.slot).face(t.face);
        let Some(l) = images.level(level) else { return };
        let store = self.client.pixel_stores.pack;
        let w = l.width as usize;
        let stride = store.row_stride(w, 1, size);
        let first = store.first_byte(stride, size);
        // A 24-bit level's depth is k / (2²⁴ − 1) exactly (`depth.rs`): k again, rounded; a
        // float level's is truncated to 24 bits (measured: 0.5 reads as 0x7FFFFF).
        let to_integer = if super::depth::depth_bits(internal) == 32 { f64::trunc } else { f64::round };
        for (i, &texel) in l.texels.iter().enumerate() {
            let depth = super::texel_depth(texel);
            let stencil = u32::from(l.stencil.get(i).copied().unwrap_or(0));
            let words = if size == 8 {
                [depth.to_bits(), stencil]
            } else {
                [(to_integer(f64::from(depth) * 16_777_215.0) as u32) << 8 | stencil, 0]
            };
            let at = first + (i / w.max(1)) * stride + (i % w.max(1)) * size;
            for (k, word) in words.iter().take(size / 4).enumerate() {
                let mut bytes = word.to_ne_bytes();
                if store.swap_bytes {
                    bytes.reverse();
                }
                pixels[at + 4 * k..at + 4 * k + 4].copy_from_slice(&bytes);
            }
        }
    }

    /// `glGetTexImage(target, level, format, type, pixels)`: the level's texels converted to
    /// `format` and `type_` and packed with the pack modes, as `glReadPixels` packs (GL 1.1
    /// §6.1.4). Errors in Mesa's order: target (`GL_INVALID_ENUM`), level (`GL_INVALID_VALUE`),
    /// format and type (`GL_INVALID_ENUM`; a packed type the format does not go with, and
    /// depth, stencil and colour-index formats `GL_INVALID_OPERATION`), a non-empty `pixels` shorter than [`Gl::tex_image_len`]
    /// (`GL_INVALID_VALUE`). An undefined level, or an empty `pixels` (C's NULL), writes
    /// nothing.
    pub fn get_tex_image(&mut self, target: GLenum, level: GLint, format: GLenum, type_: GLenum, pixels: &mut [u8]) {
        if self.reject_inside_begin_end() {
            return;
        }
        let Some(t) = image_target(target) else { return self.set_error(GL_INVALID_ENUM) };
        if !(0..=max_level(t.dims())).contains(&level) {
            return self.set_error(GL_INVALID_VALUE);
        }
        let depth_level = usize::try_from(level)
            .ok()
            .and_then(|l| self.bound_object(t.slot).face(t.face).formats.get(l))
            .is_some_and(|&base| base == GL_DEPTH_COMPONENT);
        if format == GL_DEPTH_STENCIL {
            return self.get_depth_stencil_image((target, t), level as usize, type_, pixels);
        }
        if let Some(error) = super::super::pixel_pack::texture_read_error(format, type_, depth_level) {
            return self.set_error(error);
        }
        let Some(needed) = self.tex_image_len(target, level, format, type_) else { return };
        if pixels.is_empty() || needed == 0 {
            return;
        }
        if pixels.len() < needed {
            return self.set_error(GL_INVALID_VALUE);
        }
        let images = self.bound_object(t.slot).face(t.face);
        let l = images.level(level as usize).expect("tex_image_len checked it");
        let base = images.formats[level as usize];
        // Unlike glReadPixels, luminance is R alone (GL 1.1 §6.1.4; measured on Mesa).
        let luminance = matches!(format, GL_LUMINANCE | GL_LUMINANCE_ALPHA);
        let rgba: Vec<[f32; 4]> = l
            .texels
            .iter()
            .map(|&t| if depth_level { [super::texel_depth(t), 0.0, 0.0, 1.0] } else { texel_rgba(base, t) })
            .map(|[r, g, b, a]| if luminance { [r, 0.0, 0.0, a] } else { [r, g, b, a] })
            .collect();
        let (w, h) = (l.width as usize, l.height as usize);
        // Below 3D the image modes do nothing. The texels are bytes and glGetTexImage has no
        // pixel transfer (measured: a red scale of 0.5 leaves them as they are), so Mesa
        // converts them as integers.
        let images = if t.dims() == 3 { self.packed_image_stride((w, h), format, type_) } else { None };
        let (stride, skipped) = images.unwrap_or((0, 0));
        for (k, image) in rgba.chunks_exact((w * h).max(1)).enumerate() {
            let out = &mut pixels[(skipped + k) * stride..];
            let source = if depth_level { Source::TextureDepth } else { Source::Unorm8 };
            self.pack_rgba(image, (w, h), (format, type_, source), out);
        }
    }
}
