//! Texture objects, images, parameters, and each texture unit's bindings and environment (GL
//! 1.1 spec §3.8, with GL 1.2's 3D textures and GL 1.3's units, §2.7 and §3.8.15; Mesa
//! `main/teximage.c`, `texobj.c`, `texparam.c`, `texenv.c`, `texstate.c`).
//!
//! Images are unpacked from client memory with the pixel store ([`super::pixels`]) into RGBA8
//! levels; the base internal format (`GL_RGB`, `GL_LUMINANCE`, ...) travels beside them, since
//! the texture environment's result depends on it (GL 1.1 tables 3.17 and 3.18). When a
//! primitive is recorded, the bound, complete texture of the enabled target is part of its
//! [`DrawState`](super::DrawState) ([`BoundTexture`]); the renderer uploads each texture once
//! per version and samples it with GL's filters and wrap modes.
//!
//! This file holds the objects, their binding and completeness, the attribute group and the
//! `glGet` rows; `texture/image.rs` the images, `texture/params.rs` the parameters and the
//! environment, `texture/query.rs` `glGetTex*`.

use super::consts::*;
use super::lists::ListCommand;
use super::pixel_unpack::format_components;
use super::pixels::PixelStore;
use super::state_var::{int_limit, limit, put_enum, row, Kind, StateVar};
use super::types::*;
pub use super::units::{MAX_COMBINED_TEXTURE_IMAGE_UNITS, MAX_TEXTURE_UNITS};
use super::Gl;
pub use combine::{texture_source, Combine, Combiner};
pub(crate) use compressed::{CompressedCall, GET_ROWS as COMPRESSION_GET_ROWS};
pub use depth::{copied_depth_texel, depth_texel, texel_depth, DepthParams, DepthSampling};
pub use gen::{TexGen, TexGenCoord, TexGenState};
use glam::Mat4;
use std::collections::HashMap;
use std::sync::Arc;

mod combine;
mod compressed;
mod depth;
mod gen;
mod generate;
mod image;
mod rectangle;
pub(in crate::gl) use image::depth_of_depth_stencil;
mod params;
mod query;

/// The largest texture side accepted (Mesa's `MAX_TEXTURE_SIZE` for llvmpipe is 16384; GL's
/// minimum is 64). Larger images are `GL_INVALID_VALUE`.
pub const MAX_TEXTURE_SIZE: i32 = 8192;

/// The largest 3D texture side: llvmpipe's (Mesa 22.3 answers 2048 for
/// `GL_MAX_3D_TEXTURE_SIZE`, so levels 0 to 11; measured in `texture_3d.calls`).
pub const MAX_3D_TEXTURE_SIZE: i32 = 2048;

/// The largest side of a texture of `dims` dimensions.
pub(in crate::gl) fn max_size(dims: u8) -> i32 {
    if dims == 3 {
        MAX_3D_TEXTURE_SIZE
    } else {
        MAX_TEXTURE_SIZE
    }
}

/// The last level a texture of `dims` dimensions may define (log2 of its largest side).
pub(in crate::gl) fn max_level(dims: u8) -> GLint {
    max_size(dims).ilog2() as GLint
}

/// One mipmap level: RGBA8 texels, row by row from the bottom (GL's first row is t = 0), and
/// for a 3D texture image by image from the front (r = 0).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TexLevel {
    /// Width in texels.
    pub width: u32,
    /// Height in texels (1 for a 1D texture).
    pub height: u32,
    /// Depth in texels: the images of a 3D texture (1 for a 1D or 2D texture).
    pub depth: u32,
    /// The texels as GL converted them to RGBA (before the base format picks components).
    pub texels: Vec<[u8; 4]>,
    /// A depth-and-stencil level's stencil indices, one a texel in the texels' order
    /// (`GL_EXT_packed_depth_stencil`: what `glGetTexImage(GL_DEPTH_STENCIL)` reads back; no
    /// GL 1.x sampler reads them); empty for every other level, and read as 0 where missing.
    pub stencil: Vec<u8>,
}

impl TexLevel {
    /// A level of one image (1D or 2D).
    #[must_use]
    pub fn flat(width: u32, height: u32, texels: Vec<[u8; 4]>) -> Self {
        Self { width, height, depth: 1, texels, stencil: Vec::new() }
    }

    /// A level of `size` (width, height, depth) holding `texels`, without stencil.
    #[must_use]
    pub fn sized([w, h, d]: [usize; 3], texels: Vec<[u8; 4]>) -> Self {
        Self { width: w as u32, height: h as u32, depth: d as u32, texels, stencil: Vec::new() }
    }

    /// The texel at column `i`, row `j`, image `k`.
    #[must_use]
    pub fn texel(&self, i: usize, j: usize, k: usize) -> [u8; 4] {
        self.texels[(k * self.height as usize + j) * self.width as usize + i]
    }
}

/// `glTexParameter` state of a texture object.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct TexParams {
    /// `GL_TEXTURE_MIN_FILTER` (initially `GL_NEAREST_MIPMAP_LINEAR`).
    pub min_filter: GLenum,
    /// `GL_TEXTURE_MAG_FILTER` (initially `GL_LINEAR`).
    pub mag_filter: GLenum,
    /// `GL_TEXTURE_WRAP_S` (initially `GL_REPEAT`).
    pub wrap_s: GLenum,
    /// `GL_TEXTURE_WRAP_T`.
    pub wrap_t: GLenum,
    /// `GL_TEXTURE_WRAP_R` (GL 1.2's third coordinate): kept and answered, as Mesa does for
    /// every target, and unused by 1D and 2D textures.
    pub wrap_r: GLenum,
    /// `GL_TEXTURE_BASE_LEVEL` (GL 1.2): the level a complete texture starts at.
    pub base_level: i32,
    /// `GL_TEXTURE_MAX_LEVEL` (GL 1.2): the last level a mipmap chain may use.
    pub max_level: i32,
    /// `GL_TEXTURE_MIN_LOD` and `GL_TEXTURE_MAX_LOD` (GL 1.2): the range λ is clamped to.
    pub lod: LodRange,
    /// `GL_GENERATE_MIPMAP` (GL 1.4): the levels below the base are made again whenever the
    /// base level's image changes.
    pub generate_mipmap: bool,
    /// GL 1.4's depth texture mode and shadow comparison.
    pub depth: DepthParams,
}

/// GL 1.2's LOD clamp (§3.8.7): `GL_TEXTURE_MIN_LOD` and `GL_TEXTURE_MAX_LOD`, and GL 1.4's
/// `GL_TEXTURE_LOD_BIAS` of the object, compared and hashed by their bits (the samplers are
/// cached by their parameters).
#[derive(Clone, Copy, Debug)]
pub struct LodRange {
    /// The least λ (initially −1000).
    pub min: f32,
    /// The greatest λ (initially 1000).
    pub max: f32,
    /// GL 1.4's `GL_TEXTURE_LOD_BIAS` of the object (initially 0): added to λ with the unit's
    /// bias before the clamp (GL 1.4 eq. 3.16, [`BoundTexture::lod_bias`]).
    pub bias: f32,
}

/// `GL_MAX_TEXTURE_LOD_BIAS`: llvmpipe's 16.
pub const MAX_TEXTURE_LOD_BIAS: f32 = 16.0;

impl LodRange {
    /// λ clamped to the range (GL 1.2 eq. 3.15; a NaN λ stays NaN).
    #[must_use]
    pub fn clamp(&self, lambda: f32) -> f32 {
        if lambda > self.max {
            self.max
        } else if lambda < self.min {
            self.min
        } else {
            lambda
        }
    }
}

impl PartialEq for LodRange {
    fn eq(&self, other: &Self) -> bool {
        let bits = |l: &Self| (l.min.to_bits(), l.max.to_bits(), l.bias.to_bits());
        bits(self) == bits(other)
    }
}

impl Eq for LodRange {}

impl std::hash::Hash for LodRange {
    fn hash<H: std::hash::Hasher>(&self, state: &mut H) {
        (self.min.to_bits(), self.max.to_bits(), self.bias.to_bits()).hash(state);
    }
}

impl TexParams {
    /// A new object's parameters for target slot `slot`: GL's initial ones, a rectangle's
    /// wraps `GL_CLAMP_TO_EDGE` and minification filter `GL_LINEAR` (`GL_ARB_texture_rectangle`;
    /// measured on Mesa, `capi/tests/texture_rectangle.c`).
    #[must_use]
    pub(super) fn initial(slot: usize) -> Self {
        if slot != RECT {
            return Self::default();
        }
        Self {
            min_filter: GL_LINEAR,
            wrap_s: GL_CLAMP_TO_EDGE,
            wrap_t: GL_CLAMP_TO_EDGE,
            wrap_r: GL_CLAMP_TO_EDGE,
            ..Self::default()
        }
    }
}

impl Default for TexParams {
    fn default() -> Self {
        Self {
            min_filter: GL_NEAREST_MIPMAP_LINEAR,
            mag_filter: GL_LINEAR,
            wrap_s: GL_REPEAT,
            wrap_t: GL_REPEAT,
            wrap_r: GL_REPEAT,
            base_level: 0,
            max_level: 1000,
            lod: LodRange { min: -1000.0, max: 1000.0, bias: 0.0 },
            generate_mipmap: false,
            depth: DepthParams::default(),
        }
    }
}

impl TexParams {
    /// Whether the minification filter reads mipmap levels.
    #[must_use]
    pub fn uses_mipmaps(&self) -> bool {
        self.min_filter != GL_NEAREST && self.min_filter != GL_LINEAR
    }
}

/// What `GL_TEXTURE_BIT` saves: the active unit and, for every unit of the fixed-function
/// pipeline, the bindings, the environment mode and colour, `glTexGen`, and the parameters
/// (filters, wraps, border colour, priority) of the bound objects; and of each target's default
/// object, which Mesa restores into those objects (measured on Mesa 22.3: a change to a default
/// texture made while another was bound is undone too, `texture_3d.calls`).
#[derive(Clone, Debug)]
pub(crate) struct TextureAttrib {
    active: GLenum,
    bound: [[GLuint; TARGETS]; MAX_TEXTURE_UNITS],
    env: [TexEnv; MAX_TEXTURE_UNITS],
    tex_gen: [TexGen; MAX_TEXTURE_UNITS],
    objects: [[ObjectSampling; TARGETS]; MAX_TEXTURE_UNITS],
    defaults: [ObjectSampling; TARGETS],
}

/// A unit's texture environment (GL 1.3 §3.8.13): `GL_TEXTURE_ENV_MODE`, `GL_TEXTURE_ENV_COLOR`
/// and the combiner.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct TexEnv {
    pub(crate) mode: GLenum,
    pub(crate) color: [f32; 4],
    pub(crate) combine: Combine,
    /// GL 1.4's `GL_TEXTURE_FILTER_CONTROL` `GL_TEXTURE_LOD_BIAS` of the unit (initially 0).
    pub(crate) lod_bias: f32,
}

impl Default for TexEnv {
    fn default() -> Self {
        Self { mode: GL_MODULATE, color: [0.0; 4], combine: Combine::default(), lod_bias: 0.0 }
    }
}

/// An object's parameters, border colour and priority.
type ObjectSampling = (TexParams, ([f32; 4], f32));

/// The texture a recorded primitive is drawn with: the complete mipmap chain of the enabled
/// target's bound object, its parameters, unit 0's environment and the texture matrix.
#[derive(Clone, Debug)]
pub struct BoundTexture {
    /// Identifies the chain: unique in the process, new whenever the chain is made again (an
    /// image, the levels or the filter changed), the renderers' upload cache key.
    pub key: u64,
    /// Level 0 and, when the minification filter uses them, every further level down to 1×1.
    pub levels: Arc<Vec<TexLevel>>,
    /// `GL_ALPHA`, `GL_LUMINANCE`, `GL_LUMINANCE_ALPHA`, `GL_INTENSITY`, `GL_RGB` or `GL_RGBA`.
    pub base_format: GLenum,
    /// Filters and wrap modes.
    pub params: TexParams,
    /// `GL_TEXTURE_ENV_MODE`: `GL_MODULATE`, `GL_DECAL`, `GL_BLEND`, `GL_REPLACE`, `GL_ADD` or
    /// `GL_COMBINE`.
    pub env_mode: GLenum,
    /// The combiner `GL_COMBINE` applies.
    pub combine: Combine,
    /// `GL_TEXTURE_ENV_COLOR`, for `GL_BLEND`.
    pub env_color: [f32; 4],
    /// `GL_TEXTURE_BORDER_COLOR`, clamped to [0, 1]: what a linear filter at a `GL_CLAMP` edge
    /// mixes in (GL 1.1 §3.8.6; the border texels are stripped, as in Mesa).
    pub border_color: [f32; 4],
    /// The top of the texture matrix stack.
    pub matrix: Mat4,
    /// GL 1.4's bias added to λ (eq. 3.16): the object's `GL_TEXTURE_LOD_BIAS` plus the unit's,
    /// clamped to ±`GL_MAX_TEXTURE_LOD_BIAS`.
    pub lod_bias: f32,
    /// 1, 2 or 3: a `GL_TEXTURE_1D` texture (t is not used), `GL_TEXTURE_2D` or
    /// `GL_TEXTURE_3D` (r is used); 2 for a cube map.
    pub dims: u8,
    /// A `GL_TEXTURE_CUBE_MAP` texture (GL 1.3 §3.8.6): each level holds the six faces as its
    /// images (depth 6: +X, −X, +Y, −Y, +Z, −Z), and (s, t, r) is a direction that picks the
    /// face and the 2D coordinates within it ([`cube_face`]).
    pub cube_map: bool,
    /// A `GL_TEXTURE_RECTANGLE` texture (`GL_ARB_texture_rectangle`): one level, its
    /// coordinates in texels (s in [0, width], t in [0, height]) rather than normalised.
    pub rectangle: bool,
    /// A depth texture's sampling (GL 1.4 §3.8.14): its levels hold depths ([`texel_depth`](crate::gl::texel_depth)),
    /// and `base_format` is its mode's ([`DepthParams::environment_format`](crate::gl::DepthParams::environment_format)).
    pub depth: Option<DepthSampling>,
    /// `glTexGen`: the coordinates generated per vertex, if any is enabled.
    pub generate: Option<TexGenState>,
}

impl BoundTexture {
    /// A 1×1 white texture under key 0 (no object has that key), for where none is bound.
    #[must_use]
    pub fn blank() -> Self {
        Self {
            key: 0,
            levels: Arc::new(vec![TexLevel::flat(1, 1, vec![[255; 4]])]),
            base_format: GL_RGBA,
            params: TexParams { min_filter: GL_NEAREST, ..TexParams::default() },
            env_mode: GL_REPLACE,
            combine: Combine::default(),
            env_color: [0.0; 4],
            border_color: [0.0; 4],
            matrix: Mat4::IDENTITY,
            lod_bias: 0.0,
            dims: 2,
            cube_map: false,
            rectangle: false,
            depth: None,
            generate: None,
        }
    }
}

impl PartialEq for BoundTexture {
    fn eq(&self, other: &Self) -> bool {
        self.key == other.key
            && self.base_format == other.base_format
            && self.params == other.params
            && self.env_mode == other.env_mode
            && self.combine == other.combine
            && self.env_color == other.env_color
            && self.border_color == other.border_color
            && self.matrix == other.matrix
            && self.lod_bias.to_bits() == other.lod_bias.to_bits()
            && self.dims == other.dims
            && self.cube_map == other.cube_map
            && self.rectangle == other.rectangle
            && self.depth == other.depth
            && self.generate == other.generate
    }
}

/// A key no other texture chain has had, in any context of the process: renderers cache their
/// uploads by it, and one renderer may draw several contexts' frames. 0 is the blank texture's.
fn fresh_key() -> u64 {
    static NEXT: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(1);
    NEXT.fetch_add(1, std::sync::atomic::Ordering::Relaxed)
}

/// A texture object.
#[derive(Clone, Debug, Default)]
pub(super) struct TextureObject {
    /// The target slot ([`target_index`]) the object was first bound to; `None` before.
    target: Option<usize>,
    /// The images: one face, or a cube map's six (`GL_TEXTURE_CUBE_MAP_POSITIVE_X`,
    /// `NEGATIVE_X`, `POSITIVE_Y`, `NEGATIVE_Y`, `POSITIVE_Z`, `NEGATIVE_Z`), made as defined.
    faces: Vec<FaceImages>,
    params: TexParams,
    /// The key of the chain last made (see [`BoundTexture::key`]).
    key: u64,
    /// The complete chain, made when first drawn with (dropped when an image changes).
    complete: Option<Option<Arc<Vec<TexLevel>>>>,
    /// Border colour and priority.
    extra: query::ObjectExtras,
}

/// The mipmap levels of one face of a texture (GL 1.3 §3.8.1: each face of a cube map has its
/// own images, defined one face at a time).
#[derive(Clone, Debug, Default)]
pub(super) struct FaceImages {
    pub(super) levels: Vec<Option<TexLevel>>,
    /// The base format of each level.
    pub(super) formats: Vec<GLenum>,
    /// Each level's internal format and border: the border 0 but for a proxy given one (a
    /// texture's border is stripped, [`strip_border`]).
    level_formats: Vec<(GLint, GLint)>,
}

/// The face of a texture no image has been given.
static NO_IMAGES: FaceImages = FaceImages { levels: Vec::new(), formats: Vec::new(), level_formats: Vec::new() };

impl FaceImages {
    /// The internal format and border level `level` was defined with (`(1, 0)`, GL's initial
    /// internal format, if never).
    pub(super) fn level_format(&self, level: usize) -> (GLint, GLint) {
        self.level_formats.get(level).copied().unwrap_or((1, 0))
    }

    /// Level `level`, if defined.
    pub(super) fn level(&self, level: usize) -> Option<&TexLevel> {
        self.levels.get(level)?.as_ref()
    }
}

impl TextureObject {
    /// The images of face `face` (0 but for a cube map).
    pub(super) fn face(&self, face: usize) -> &FaceImages {
        self.faces.get(face).unwrap_or(&NO_IMAGES)
    }

    pub(super) fn face_mut(&mut self, face: usize) -> &mut FaceImages {
        if self.faces.len() <= face {
            self.faces.resize(face + 1, FaceImages::default());
        }
        &mut self.faces[face]
    }

    /// Sets level `level` of face `face` (`None`: undefined, as a proxy too large for its
    /// level is), with its base and internal formats and the border it keeps (0 but for a
    /// proxy).
    pub(super) fn define_level(
        &mut self,
        face: usize,
        level: usize,
        image: Option<TexLevel>,
        (base, internal): (GLenum, GLint),
        border: GLint,
    ) {
        let images = self.face_mut(face);
        if images.levels.len() <= level {
            images.levels.resize(level + 1, None);
            images.formats.resize(level + 1, 0);
            images.level_formats.resize(level + 1, (1, 0));
        }
        images.levels[level] = image;
        images.formats[level] = base;
        // A generic compressed format is kept, and reported, as its base format (Mesa's
        // answer for the generic formats it keeps uncompressed).
        let internal = compressed::generic_base(internal as GLenum).map_or(internal, |b| b as GLint);
        images.level_formats[level] = (internal, border);
    }

    /// New parameters. The complete chain, and with it the key a renderer caches its upload by,
    /// is made again only when what the chain depends on changed: whether the minification
    /// filter reads mipmaps, and the level range. A wrap, a filter or an LOD clamp set every
    /// frame, or a `glPopAttrib(GL_TEXTURE_BIT)`, uploads nothing again.
    pub(super) fn set_params(&mut self, params: TexParams) {
        let chain = |p: &TexParams| (p.uses_mipmaps(), p.base_level, p.max_level);
        if chain(&params) != chain(&self.params) {
            self.complete = None;
        }
        self.params = params;
    }

    /// `glPrioritizeTextures`: `GL_TEXTURE_PRIORITY`, clamped to [0, 1].
    pub(super) fn set_priority(&mut self, priority: f32) {
        self.extra.priority = priority.clamp(0.0, 1.0);
    }
}

/// The texture objects and each unit's bindings and environment.
#[derive(Debug)]
pub(crate) struct Textures {
    pub(super) objects: HashMap<GLuint, TextureObject>,
    /// The default objects (name 0) of `GL_TEXTURE_1D`, `GL_TEXTURE_2D`, `GL_TEXTURE_3D` and
    /// `GL_TEXTURE_CUBE_MAP`.
    defaults: [TextureObject; TARGETS],
    /// `GL_PROXY_TEXTURE_1D`, `_2D`, `_3D` and `_CUBE_MAP`: levels of sizes and formats only
    /// (GL 1.1 §3.8.1), never bound or drawn.
    proxies: [TextureObject; TARGETS],
    /// Each unit's bindings, by target slot ([`target_index`]).
    bound: Box<[[GLuint; TARGETS]; MAX_COMBINED_TEXTURE_IMAGE_UNITS]>,
    /// Each fixed-function unit's environment.
    pub(super) env: [TexEnv; MAX_TEXTURE_UNITS],
    max_name: GLuint,
}

impl Default for Textures {
    fn default() -> Self {
        let default =
            |t, key| TextureObject { target: Some(t), key, params: TexParams::initial(t), ..TextureObject::default() };
        Self {
            objects: HashMap::new(),
            defaults: std::array::from_fn(|t| default(t, fresh_key())),
            proxies: std::array::from_fn(|t| default(t, 0)),
            bound: Box::new([[0; TARGETS]; MAX_COMBINED_TEXTURE_IMAGE_UNITS]),
            env: [TexEnv::default(); MAX_TEXTURE_UNITS],
            max_name: 0,
        }
    }
}

/// The texture targets an object is bound to: `GL_TEXTURE_1D`, `_2D`, `_3D`, GL 1.3's
/// `GL_TEXTURE_CUBE_MAP` and `GL_ARB_texture_rectangle`'s `GL_TEXTURE_RECTANGLE`.
pub(super) const TARGETS: usize = 5;

/// The slot of `GL_TEXTURE_CUBE_MAP` ([`target_index`]).
pub(super) const CUBE: usize = 3;

/// The slot of `GL_TEXTURE_RECTANGLE` ([`target_index`]): one 2D level, addressed in texels
/// (`texture/rectangle.rs`).
pub(super) const RECT: usize = 4;

/// A target's slot: 0 for `GL_TEXTURE_1D`, 1 for `GL_TEXTURE_2D`, 2 for `GL_TEXTURE_3D`, 3
/// ([`CUBE`]) for `GL_TEXTURE_CUBE_MAP`, 4 ([`RECT`]) for `GL_TEXTURE_RECTANGLE`.
pub(super) fn target_index(target: GLenum) -> Option<usize> {
    match target {
        GL_TEXTURE_1D => Some(0),
        GL_TEXTURE_2D => Some(1),
        GL_TEXTURE_3D => Some(2),
        GL_TEXTURE_CUBE_MAP => Some(CUBE),
        GL_TEXTURE_RECTANGLE => Some(RECT),
        _ => None,
    }
}

/// The slot of a proxy target: 0 for `GL_PROXY_TEXTURE_1D`, 1 for `_2D`, 2 for `_3D`, 3 for
/// `_CUBE_MAP`, 4 for `_RECTANGLE`.
pub(super) fn proxy_index(target: GLenum) -> Option<usize> {
    match target {
        GL_PROXY_TEXTURE_1D => Some(0),
        GL_PROXY_TEXTURE_2D => Some(1),
        GL_PROXY_TEXTURE_3D => Some(2),
        GL_PROXY_TEXTURE_CUBE_MAP => Some(CUBE),
        GL_PROXY_TEXTURE_RECTANGLE => Some(RECT),
        _ => None,
    }
}

/// The dimensions of the images of the target in `slot`: a cube map's faces and a
/// rectangle's one image are 2D.
pub(super) fn slot_dims(slot: usize) -> u8 {
    [1, 2, 3, 2, 2][slot]
}

/// Where an image call's target puts its image (GL 1.3 §3.8.1): the bound object's slot, and
/// the face of a cube map (0 for every other target).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct ImageTarget {
    pub(super) slot: usize,
    pub(super) face: usize,
}

impl ImageTarget {
    /// The dimensions of the images it holds.
    pub(super) fn dims(self) -> u8 {
        slot_dims(self.slot)
    }
}

/// The image target `target` names: `GL_TEXTURE_1D`, `_2D`, `_3D` or one of a cube map's six
/// faces (`GL_TEXTURE_CUBE_MAP` itself holds no image).
pub(super) fn image_target(target: GLenum) -> Option<ImageTarget> {
    let slot = match target {
        GL_TEXTURE_CUBE_MAP_POSITIVE_X..=GL_TEXTURE_CUBE_MAP_NEGATIVE_Z => {
            return Some(ImageTarget { slot: CUBE, face: (target - GL_TEXTURE_CUBE_MAP_POSITIVE_X) as usize })
        }
        GL_TEXTURE_CUBE_MAP => return None,
        _ => target_index(target)?,
    };
    Some(ImageTarget { slot, face: 0 })
}

/// The image target of a `glTexImage{dims}D`-shaped call.
pub(super) fn image_target_of(dims: u8, target: GLenum) -> Option<ImageTarget> {
    image_target(target).filter(|t| t.dims() == dims)
}

/// The proxy slot of a `glTexImage{dims}D`-shaped call.
pub(super) fn proxy_of(dims: u8, target: GLenum) -> Option<usize> {
    proxy_index(target).filter(|&p| slot_dims(p) == dims)
}

/// Whether an image of `size` (width, height, depth) with `border` fits `level` (Mesa's
/// `_mesa_legal_texture_dimensions`: each side holds its two border texels, and its inside is
/// at most the largest texture's side at that level; a 1D image has no border above or below,
/// a 1D or 2D one none before or behind).
pub(super) fn fits_level(dims: u8, level: GLint, size: [GLsizei; 3], border: GLint) -> bool {
    let largest = i64::from(max_size(dims) >> level);
    let inside = |side: GLsizei, border: GLint| (0..=largest).contains(&(i64::from(side) - 2 * i64::from(border)));
    let bordered = |axis: u8| if dims > axis { border } else { 0 };
    inside(size[0], border) && inside(size[1], bordered(1)) && inside(size[2], bordered(2))
}

/// An image's texels without its border (GL 1.1 §3.8.1): Mesa's gallium drivers keep the
/// inside only (`strip_texture_border`, measured on llvmpipe: a 6 × 6 image with border 1 is a
/// 4 × 4 level whose `GL_TEXTURE_BORDER` is 0, and the border is never sampled; a 3D image
/// loses its first and last images too). The texels and the inside's size.
pub(super) fn strip_border(
    dims: u8,
    texels: Vec<[u8; 4]>,
    [w, h, d]: [usize; 3],
    border: usize,
) -> (Vec<[u8; 4]>, [usize; 3]) {
    if border == 0 {
        return (texels, [w, h, d]);
    }
    let rows = if dims == 1 { 0..h } else { border..h - border };
    let images = if dims == 3 { border..d - border } else { 0..d };
    let (inner_w, inner_h, inner_d) = (w - 2 * border, rows.len(), images.len());
    let inside = images
        .flat_map(|k| rows.clone().map(move |row| (k * h + row) * w + border))
        .flat_map(|start| texels[start..][..inner_w].to_vec())
        .collect();
    (inside, [inner_w, inner_h, inner_d])
}

/// The base internal format of an `internalformat` argument (GL 1.1 table 3.15, with GL 1.0's
/// component counts 1..4), `None` for one GL rejects.
pub(super) fn base_format(internal: GLint) -> Option<GLenum> {
    // GL 1.1 table 3.15's sized formats name their base format; gleval keeps each channel in
    // 8 bits whatever size is asked (GL allows more or fewer, §3.8.1), and says so through
    // `glGetTexLevelParameter`. An intensity level keeps I in its red component (Mesa: from
    // an RGBA image, I is R).
    match internal as GLenum {
        1 | GL_LUMINANCE | GL_LUMINANCE4 | GL_LUMINANCE8 | GL_LUMINANCE12 | GL_LUMINANCE16 => Some(GL_LUMINANCE),
        2
        | GL_LUMINANCE_ALPHA
        | GL_LUMINANCE4_ALPHA4
        | GL_LUMINANCE6_ALPHA2
        | GL_LUMINANCE8_ALPHA8
        | GL_LUMINANCE12_ALPHA4
        | GL_LUMINANCE12_ALPHA12
        | GL_LUMINANCE16_ALPHA16 => Some(GL_LUMINANCE_ALPHA),
        3 | GL_RGB | GL_R3_G3_B2 | GL_RGB4 | GL_RGB5 | GL_RGB8 | GL_RGB10 | GL_RGB12 | GL_RGB16 => Some(GL_RGB),
        4 | GL_RGBA | GL_RGBA2 | GL_RGBA4 | GL_RGB5_A1 | GL_RGBA8 | GL_RGB10_A2 | GL_RGBA12 | GL_RGBA16 => {
            Some(GL_RGBA)
        }
        GL_ALPHA | GL_ALPHA4 | GL_ALPHA8 | GL_ALPHA12 | GL_ALPHA16 => Some(GL_ALPHA),
        GL_INTENSITY | GL_INTENSITY4 | GL_INTENSITY8 | GL_INTENSITY12 | GL_INTENSITY16 => Some(GL_INTENSITY),
        // GL 1.4's depth textures (`texture/depth.rs`).
        GL_DEPTH_COMPONENT
        | GL_DEPTH_COMPONENT16
        | GL_DEPTH_COMPONENT24
        | GL_DEPTH_COMPONENT32
        | GL_DEPTH_COMPONENT32F => Some(GL_DEPTH_COMPONENT),
        // GL 3.0's depth and stencil formats, as Mesa takes them in a compatibility context:
        // gleval keeps their depths only (no stencil texturing before GL 4.3).
        GL_DEPTH_STENCIL | GL_DEPTH24_STENCIL8 | GL_DEPTH32F_STENCIL8 => Some(GL_DEPTH_COMPONENT),
        // GL 1.3's generic compressed formats, kept uncompressed (`texture/compressed.rs`).
        other => compressed::generic_base(other),
    }
}

/// Whether `glTexImage` and `glTexSubImage` take `format` for a level of base format `base`
/// (GL 1.4 §3.8.1): depths for a depth texture, colours (and colour indices; `GL_BGR` and
/// `GL_BGRA` as Mesa takes them) for any other, never stencil indices (Mesa's
/// `texture_formats_agree`).
fn texture_format(format: GLenum, base: GLenum) -> bool {
    let depth = matches!(format, GL_DEPTH_COMPONENT | GL_DEPTH_STENCIL);
    format_components(format).is_some() && format != GL_STENCIL_INDEX && depth == (base == GL_DEPTH_COMPONENT)
}

/// The texture group's calls as a display list holds them.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum TextureCall {
    ActiveTexture(GLenum),
    BindTexture(GLenum, GLuint),
    /// `glTexImage1D/2D/3D`: the client's bytes with the pixel store of compile time, as GL
    /// unpacks them then (GL 1.1 §5.4).
    TexImage {
        dims: u8,
        target: GLenum,
        level: GLint,
        internalformat: GLint,
        size: [GLsizei; 3],
        border: GLint,
        format: (GLenum, GLenum),
        image: (PixelStore, Vec<u8>),
    },
    /// `glTexSubImage1D/2D/3D`.
    TexSubImage {
        dims: u8,
        target: GLenum,
        level: GLint,
        offset: [GLint; 3],
        size: [GLsizei; 3],
        format: (GLenum, GLenum),
        image: (PixelStore, Vec<u8>),
    },
    TexParameter(GLenum, GLenum, GLint),
    /// `glTexParameterfv` of `GL_TEXTURE_BORDER_COLOR` or `GL_TEXTURE_PRIORITY`.
    TexParameterValues(GLenum, GLenum, Vec<GLfloat>),
    TexEnv(GLenum, GLenum, Vec<f32>),
    /// `glTexGen*`: coordinate, name and values (the eye plane is transformed when called).
    TexGen(GLenum, GLenum, Vec<f32>),
}

impl Gl {
    /// The bytes of texture levels the frame recorded so far holds (each level set once,
    /// however many primitives draw with it). A texture deleted or given new images lives on
    /// in the frame until it is drawn: a program that streams textures through one frame
    /// (piglit's `streaming-texture-leak`: 5,000 textures of 4 MiB) would otherwise keep them
    /// all; the C ABI draws the frame so far when this grows large.
    #[must_use]
    pub fn frame_texture_bytes(&self) -> usize {
        let mut seen = std::collections::HashSet::new();
        let textures = self
            .recorder
            .frame
            .states
            .iter()
            .flat_map(|s| s.texture.iter().chain(s.more_textures.iter().map(|(_, t)| t)));
        textures
            .filter(|t| seen.insert(Arc::as_ptr(&t.levels)))
            .map(|t| t.levels.iter().map(|l| l.texels.len() * 4 + l.stencil.len()).sum::<usize>())
            .sum()
    }
}

impl Gl {
    /// Replays a listed call of the group.
    pub(crate) fn replay_texture_call(&mut self, call: &TextureCall) {
        use TextureCall as C;
        match call {
            C::ActiveTexture(unit) => self.active_texture(*unit),
            C::BindTexture(target, texture) => self.bind_texture(*target, *texture),
            C::TexImage { dims, target, level, internalformat, size, border, format, image } => {
                self.with_unpack_store(image.0, |gl| {
                    gl.tex_image(*dims, *target, *level, *internalformat, *size, *border, *format, &image.1);
                });
            }
            C::TexSubImage { dims, target, level, offset, size, format, image } => {
                self.with_unpack_store(image.0, |gl| {
                    gl.tex_sub_image_call(*dims, *target, *level, (*offset, *size), *format, &image.1);
                });
            }
            C::TexParameter(target, pname, param) => self.tex_parameteri(*target, *pname, *param),
            C::TexParameterValues(target, pname, params) => self.tex_parameterfv(*target, *pname, params),
            C::TexEnv(target, pname, params) => self.tex_envfv(*target, *pname, params),
            C::TexGen(coord, pname, params) => self.tex_genfv(*coord, *pname, params),
        }
    }
}

impl Gl {
    /// `glActiveTexture` (GL 1.3 §2.7): selects the unit the texture calls, the texture
    /// enables and `glMatrixMode(GL_TEXTURE)` act on (the evaluators only work on unit 0). A
    /// unit at or beyond [`MAX_COMBINED_TEXTURE_IMAGE_UNITS`] → `GL_INVALID_ENUM`.
    pub fn active_texture(&mut self, texture: GLenum) {
        if self.compiled_state_call(|| ListCommand::Texture(TextureCall::ActiveTexture(texture))) {
            return;
        }
        let units = GL_TEXTURE0..GL_TEXTURE0 + MAX_COMBINED_TEXTURE_IMAGE_UNITS as GLenum;
        if !units.contains(&texture) {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        self.server.active_texture = texture;
        self.server.matrices.set_unit(self.active_unit());
    }

    /// The active unit's index (`GL_ACTIVE_TEXTURE` − `GL_TEXTURE0`).
    pub(crate) fn active_unit(&self) -> usize {
        (self.server.active_texture - GL_TEXTURE0) as usize
    }

    /// The active unit's environment; `None` for a unit beyond the fixed-function ones.
    pub(super) fn active_env(&self) -> Option<&TexEnv> {
        self.server.textures.env.get(self.active_unit())
    }

    /// The active unit's environment to change (`None`: a unit beyond the fixed-function ones,
    /// whose environment Mesa ignores without an error, measured).
    pub(super) fn active_env_mut(&mut self) -> Option<&mut TexEnv> {
        let unit = self.active_unit();
        self.server.textures.env.get_mut(unit)
    }

    /// `glGenTextures`: `n` unused names into `textures` (short of room → `GL_INVALID_VALUE`,
    /// as is `n` < 0).
    pub fn gen_textures(&mut self, n: GLsizei, textures: &mut [GLuint]) {
        if self.reject_inside_begin_end() {
            return;
        }
        let Ok(count) = usize::try_from(n) else { return self.set_error(GL_INVALID_VALUE) };
        if textures.len() < count {
            return self.set_error(GL_INVALID_VALUE);
        }
        for name in &mut textures[..count] {
            self.server.textures.max_name += 1;
            *name = self.server.textures.max_name;
            self.server.textures.objects.insert(*name, TextureObject::default());
        }
    }

    /// `glBindTexture`: binds `texture` (0: the target's default) to `GL_TEXTURE_1D`, `_2D`,
    /// `_3D` or `_CUBE_MAP`, creating it on first use. Another target → `GL_INVALID_ENUM`; an
    /// object made for the other target → `GL_INVALID_OPERATION`.
    pub fn bind_texture(&mut self, target: GLenum, texture: GLuint) {
        if self.compiled_state_call(|| ListCommand::Texture(TextureCall::BindTexture(target, texture))) {
            return;
        }
        let Some(t) = target_index(target) else { return self.set_error(GL_INVALID_ENUM) };
        if texture != 0 {
            let object = self.server.textures.objects.entry(texture).or_default();
            match object.target {
                None => {
                    object.target = Some(t);
                    object.key = fresh_key();
                    object.params = TexParams::initial(t);
                }
                Some(first) if first != t => return self.set_error(GL_INVALID_OPERATION),
                Some(_) => {}
            }
            self.server.textures.max_name = self.server.textures.max_name.max(texture);
        }
        let unit = self.active_unit();
        self.server.textures.bound[unit][t] = texture;
        self.touch_state();
    }

    /// `glDeleteTextures`: deletes the named objects (0 and unused names are ignored); a bound
    /// one is replaced by its target's default. `n` < 0 or a short slice → `GL_INVALID_VALUE`.
    pub fn delete_textures(&mut self, n: GLsizei, textures: &[GLuint]) {
        if self.reject_inside_begin_end() {
            return;
        }
        let Ok(count) = usize::try_from(n) else { return self.set_error(GL_INVALID_VALUE) };
        let Some(names) = textures.get(..count) else { return self.set_error(GL_INVALID_VALUE) };
        for &name in names.iter().filter(|&&name| name != 0) {
            if self.server.textures.objects.remove(&name).is_some() {
                for bound in self.server.textures.bound.iter_mut().flatten() {
                    if *bound == name {
                        *bound = 0;
                    }
                }
            }
        }
        self.touch_state();
    }

    /// `glIsTexture`: whether `texture` names an object that has been bound (a name only
    /// generated is not yet a texture, as in Mesa).
    pub fn is_texture(&mut self, texture: GLuint) -> GLboolean {
        if self.reject_inside_begin_end() {
            return GL_FALSE;
        }
        let bound = self.server.textures.objects.get(&texture).is_some_and(|o| o.target.is_some());
        if bound {
            GL_TRUE
        } else {
            GL_FALSE
        }
    }

    /// The texture unit 0 draws the next primitive with (see [`Gl::bound_texture_of`]).
    pub(crate) fn bound_texture(&mut self) -> Option<BoundTexture> {
        self.bound_texture_of(0)
    }

    /// Units 1 to 7's textures that draw the next primitive, with their units (see
    /// [`DrawState::more_textures`](super::DrawState::more_textures)).
    pub(crate) fn more_textures(&mut self) -> Vec<(usize, BoundTexture)> {
        (1..MAX_TEXTURE_UNITS).filter_map(|unit| Some((unit, self.bound_texture_of(unit)?))).collect()
    }

    /// The texture unit `unit` draws the next primitive with: the bound object of its enabled
    /// target of the highest priority (`GL_TEXTURE_CUBE_MAP`, `GL_TEXTURE_3D`,
    /// `GL_TEXTURE_RECTANGLE`, `GL_TEXTURE_2D`, `GL_TEXTURE_1D`, GL 3.1 §3.8.18) whose mipmap chain is complete (§3.8.10), with the
    /// unit's environment, texture matrix and coordinate generation. Mesa's
    /// `update_ff_texture_state` passes over an incomplete target to the next enabled one, and
    /// a unit with none complete is disabled.
    pub(crate) fn bound_texture_of(&mut self, unit: usize) -> Option<BoundTexture> {
        const PRIORITY: [(GLenum, usize); TARGETS] = [
            (GL_TEXTURE_CUBE_MAP, CUBE),
            (GL_TEXTURE_3D, 2),
            (GL_TEXTURE_RECTANGLE, RECT),
            (GL_TEXTURE_2D, 1),
            (GL_TEXTURE_1D, 0),
        ];
        let caps = &self.server.caps;
        let enabled = PRIORITY.map(|(cap, t)| caps.is_on(super::units::unit_cap(cap, unit)).then_some(t));
        let (t, levels) = enabled.into_iter().flatten().find_map(|t| {
            let object = self.unit_object_mut(unit, t);
            if object.complete.is_none() {
                // A new chain (an image, the levels or the filter changed): a new key, so
                // that a renderer uploads it again.
                object.complete = Some(complete_object_chain(object));
                object.key = fresh_key();
            }
            Some((t, object.complete.clone().flatten()?))
        })?;
        let matrix = self.server.matrices.texture_of(unit);
        let generate = self.tex_gen_state_of(unit);
        let env = self.server.textures.env[unit];
        let object = self.unit_object(unit, t);
        let base_format = object.face(0).formats[object.params.base_level as usize];
        let depth = (base_format == GL_DEPTH_COMPONENT).then(|| DepthSampling::new(&object.params.depth));
        Some(BoundTexture {
            key: object.key,
            levels,
            base_format: if depth.is_some() { object.params.depth.environment_format() } else { base_format },
            params: object.params,
            env_mode: env.mode,
            combine: env.combine,
            env_color: env.color,
            border_color: object.extra.sampling().0.map(|c| c.clamp(0.0, 1.0)),
            matrix,
            // Constant bounds: `clamp` cannot panic (a NaN sum stays NaN, and λ with it).
            lod_bias: (object.params.lod.bias + env.lod_bias).clamp(-MAX_TEXTURE_LOD_BIAS, MAX_TEXTURE_LOD_BIAS),
            dims: slot_dims(t),
            cube_map: t == CUBE,
            rectangle: t == RECT,
            depth,
            generate,
        })
    }

    /// What `GL_TEXTURE_BIT` saves of the units: the active unit, the bindings, the environment
    /// and the coordinate generation of each (their enables are saved with the bit's other
    /// enables).
    pub(crate) fn texture_attrib(&self) -> TextureAttrib {
        let sampling = |object: &TextureObject| (object.params, object.extra.sampling());
        let textures = &self.server.textures;
        TextureAttrib {
            active: self.server.active_texture,
            bound: std::array::from_fn(|unit| textures.bound[unit]),
            env: textures.env,
            tex_gen: self.server.tex_gen,
            objects: std::array::from_fn(|unit| std::array::from_fn(|t| sampling(self.unit_object(unit, t)))),
            defaults: textures.defaults.each_ref().map(sampling),
        }
    }

    /// Restores what [`Gl::texture_attrib`] saved (a binding whose object was deleted since
    /// falls back to the default texture).
    pub(crate) fn restore_texture_attrib(&mut self, saved: TextureAttrib) {
        let restore = |object: &mut TextureObject, (params, sampling): ObjectSampling| {
            object.set_params(params);
            object.extra.set_sampling(sampling);
        };
        self.server.tex_gen = saved.tex_gen;
        for (object, sampling) in self.server.textures.defaults.iter_mut().zip(saved.defaults) {
            restore(object, sampling);
        }
        for (unit, (bound, objects)) in saved.bound.into_iter().zip(saved.objects).enumerate() {
            let exists = |name: GLuint| name == 0 || self.server.textures.objects.contains_key(&name);
            self.server.textures.bound[unit] = bound.map(|name| if exists(name) { name } else { 0 });
            for (t, sampling) in objects.into_iter().enumerate() {
                restore(self.unit_object_mut(unit, t), sampling);
            }
        }
        self.server.textures.env = saved.env;
        // Mesa 22.3's glPopAttrib(GL_TEXTURE_BIT) leaves every unit's GL_TEXTURE_LOD_BIAS of
        // GL_TEXTURE_FILTER_CONTROL 0, whatever was pushed (measured with OSMesa: 1.5 pushed,
        // 0 after the pop), though GL files the bias under the group; gleval does the same.
        for env in &mut self.server.textures.env {
            env.lod_bias = 0.0;
        }
        self.server.active_texture = saved.active;
        self.server.matrices.set_unit(self.active_unit());
        self.touch_state();
    }

    /// The object bound to the active unit's target in slot `t` ([`target_index`]).
    pub(super) fn bound_object(&self, t: usize) -> &TextureObject {
        self.unit_object(self.active_unit(), t)
    }

    /// The object bound to `unit`'s target in slot `t`.
    fn unit_object(&self, unit: usize, t: usize) -> &TextureObject {
        match self.server.textures.bound[unit][t] {
            0 => &self.server.textures.defaults[t],
            name => &self.server.textures.objects[&name],
        }
    }

    fn unit_object_mut(&mut self, unit: usize, t: usize) -> &mut TextureObject {
        match self.server.textures.bound[unit][t] {
            0 => &mut self.server.textures.defaults[t],
            name => self.server.textures.objects.get_mut(&name).expect("a bound texture exists"),
        }
    }

    /// The levels loaded into the bound 1D (`dims` 1), 2D or 3D texture, complete or not (tests of
    /// `gluBuild*Mipmap*` read them as `glGetTexImage` would).
    #[cfg(test)]
    pub(crate) fn bound_levels(&mut self, dims: u8) -> Vec<Option<TexLevel>> {
        self.bound_object(usize::from(dims - 1)).face(0).levels.clone()
    }

    pub(super) fn bound_object_mut(&mut self, t: usize) -> &mut TextureObject {
        self.unit_object_mut(self.active_unit(), t)
    }

    /// A level of the object bound in slot `t` changed: a new chain, under a new key (the
    /// renderer uploads again).
    pub(super) fn image_changed(&mut self, t: usize) {
        let object = self.bound_object_mut(t);
        object.complete = None;
        self.touch_state();
    }
}

/// The complete chain of an object, from its base level (GL 1.3 §3.8.10): one face's, or a
/// cube map's when it is "cube complete" (six faces of the same square size and base format,
/// each complete), its six faces made the images of each level.
fn complete_object_chain(object: &TextureObject) -> Option<Arc<Vec<TexLevel>>> {
    if object.target != Some(CUBE) {
        let face = object.face(0);
        return complete_chain(&face.levels, &face.formats, &object.params);
    }
    let faces: Vec<Arc<Vec<TexLevel>>> = (0..6)
        .map(|f| complete_chain(&object.face(f).levels, &object.face(f).formats, &object.params))
        .collect::<Option<_>>()?;
    let base = usize::try_from(object.params.base_level).ok()?;
    let format = object.face(0).formats[base];
    let same = |f: usize| {
        faces[f].len() == faces[0].len()
            && faces[f][0].width == faces[0][0].width
            && faces[f][0].height == faces[0][0].height
            && object.face(f).formats[base] == format
    };
    if faces[0][0].width != faces[0][0].height || !(1..6).all(same) {
        return None;
    }
    let levels = (0..faces[0].len()).map(|k| {
        let (width, height) = (faces[0][k].width, faces[0][k].height);
        let texels = faces.iter().flat_map(|face| face[k].texels.iter().copied()).collect();
        TexLevel { width, height, depth: 6, texels, stencil: Vec::new() }
    });
    Some(Arc::new(levels.collect()))
}

/// Level 0 and, when the filter uses mipmaps, every level down to 1×1(×1) with the sizes and
/// base format GL requires (GL 1.1 §3.8.9); `None` when that chain is incomplete.
fn complete_chain(levels: &[Option<TexLevel>], formats: &[GLenum], params: &TexParams) -> Option<Arc<Vec<TexLevel>>> {
    let first = usize::try_from(params.base_level).ok()?;
    let base = levels.get(first)?.as_ref()?;
    if base.width == 0 || base.height == 0 || base.depth == 0 {
        return None;
    }
    if !params.uses_mipmaps() {
        return Some(Arc::new(vec![base.clone()]));
    }
    // GL 1.2 §3.8.10: levels base..=min(p, max level), p = base + log2 of the largest side; a
    // maximum below the base leaves the texture incomplete.
    let largest = base.width.max(base.height).max(base.depth);
    let last = (first + largest.ilog2() as usize).min(usize::try_from(params.max_level).ok()?);
    if last < first {
        return None;
    }
    let mut chain = Vec::with_capacity(last - first + 1);
    for (i, k) in (first..=last).enumerate() {
        let level = levels.get(k)?.as_ref()?;
        let size = [base.width, base.height, base.depth].map(|side| (side >> i).max(1));
        if [level.width, level.height, level.depth] != size || formats[k] != formats[first] {
            return None;
        }
        chain.push(level.clone());
    }
    Some(Arc::new(chain))
}

/// The face a direction (s, t, r) selects in a cube map (GL 1.3 §3.8.6, table 3.19): the
/// axis of the largest magnitude, ties going to x before y before z as llvmpipe breaks them;
/// and the 2D coordinates there ([`cube_face_coords`]).
#[must_use]
pub fn cube_face(r: [f32; 3]) -> (usize, [f32; 2]) {
    let [ax, ay, az] = r.map(f32::abs);
    let axis = if ax >= ay && ax >= az {
        0
    } else if ay >= az {
        1
    } else {
        2
    };
    let face = 2 * axis + usize::from(r[axis] < 0.0);
    (face, cube_face_coords(face, r))
}

/// The coordinates of direction `r` on cube face `face` (table 3.19's sc, tc and ma):
/// ((sc / |ma| + 1) / 2, (tc / |ma| + 1) / 2).
#[must_use]
pub fn cube_face_coords(face: usize, [rx, ry, rz]: [f32; 3]) -> [f32; 2] {
    let (sc, tc, ma) = match face {
        0 => (-rz, -ry, rx),
        1 => (rz, -ry, rx),
        2 => (rx, rz, ry),
        3 => (rx, -rz, ry),
        4 => (rx, -ry, rz),
        _ => (-rx, -ry, rz),
    };
    let ma = ma.abs();
    [(sc / ma + 1.0) * 0.5, (tc / ma + 1.0) * 0.5]
}

/// The texture bindings' `glGet` rows (GL 1.1 table 6.9, GL 1.2's 3D binding) and the size
/// limits.
pub(crate) static GET_ROWS: &[StateVar] = &[
    row(GL_TEXTURE_BINDING_1D, 1, Kind::Int, |gl, o| put_enum(o, gl.server.textures.bound[gl.active_unit()][0])),
    row(GL_TEXTURE_BINDING_2D, 1, Kind::Int, |gl, o| put_enum(o, gl.server.textures.bound[gl.active_unit()][1])),
    row(GL_TEXTURE_BINDING_3D, 1, Kind::Int, |gl, o| put_enum(o, gl.server.textures.bound[gl.active_unit()][2])),
    row(GL_TEXTURE_BINDING_CUBE_MAP, 1, Kind::Int, |gl, o| {
        put_enum(o, gl.server.textures.bound[gl.active_unit()][CUBE]);
    }),
    row(GL_TEXTURE_BINDING_RECTANGLE, 1, Kind::Int, |gl, o| {
        put_enum(o, gl.server.textures.bound[gl.active_unit()][RECT]);
    }),
    int_limit!(GL_MAX_RECTANGLE_TEXTURE_SIZE, MAX_TEXTURE_SIZE),
    int_limit!(GL_MAX_TEXTURE_SIZE, MAX_TEXTURE_SIZE),
    int_limit!(GL_MAX_CUBE_MAP_TEXTURE_SIZE, MAX_TEXTURE_SIZE),
    int_limit!(GL_MAX_3D_TEXTURE_SIZE, MAX_3D_TEXTURE_SIZE),
    limit!(GL_MAX_TEXTURE_LOD_BIAS, MAX_TEXTURE_LOD_BIAS),
    row(GL_ACTIVE_TEXTURE, 1, Kind::Int, |gl, o| put_enum(o, gl.server.active_texture)),
    int_limit!(GL_MAX_TEXTURE_UNITS, MAX_TEXTURE_UNITS),
];

#[cfg(test)]
mod tests {
    use super::*;

    fn checker(gl: &mut Gl) -> GLuint {
        let mut name = [0];
        gl.gen_textures(1, &mut name);
        gl.bind_texture(GL_TEXTURE_2D, name[0]);
        let texels: [u8; 12] = [255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255];
        gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
        gl.tex_image_2d(GL_TEXTURE_2D, 0, GL_RGB as i32, 2, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, &texels);
        name[0]
    }

    #[test]
    fn the_frame_holds_each_drawn_texture_once_deleted_or_not() {
        let mut gl = Gl::new(4, 4);
        let name = checker(&mut gl);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
        assert_eq!(gl.frame_texture_bytes(), 0, "nothing drawn yet");
        gl.enable(GL_TEXTURE_2D);
        for _ in 0..2 {
            gl.begin(GL_POINTS);
            gl.vertex2f(0.0, 0.0);
            gl.end();
        }
        assert_eq!(gl.frame_texture_bytes(), 16, "one 2 x 2 level, however often drawn");
        gl.delete_textures(1, &[name]);
        assert_eq!(gl.frame_texture_bytes(), 16, "still held by the frame");
        let _ = gl.take_frame();
        assert_eq!(gl.frame_texture_bytes(), 0);
    }

    #[test]
    fn a_new_key_only_with_a_new_chain() {
        let mut gl = Gl::new(4, 4);
        checker(&mut gl);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
        gl.enable(GL_TEXTURE_2D);
        let key = |gl: &mut Gl| gl.bound_texture().map(|t| t.key);
        let first = key(&mut gl);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP as i32);
        gl.tex_parameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, 2.0);
        gl.push_attrib(GL_TEXTURE_BIT);
        gl.pop_attrib();
        assert_eq!(key(&mut gl), first, "the same chain, the same upload");
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
        assert_eq!(key(&mut gl), first);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
        let second = key(&mut gl);
        assert!(second.is_some() && second != first, "a new level range is a new chain");
    }

    #[test]
    fn an_incomplete_mipmap_chain_disables_texturing() {
        let mut gl = Gl::new(4, 4);
        checker(&mut gl);
        gl.enable(GL_TEXTURE_2D);
        // The initial minification filter reads mipmaps, and only level 0 exists.
        assert!(gl.bound_texture().is_none());
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR as i32);
        let bound = gl.bound_texture().expect("complete");
        assert_eq!(bound.levels[0].texels[1], [0, 255, 0, 255]);
        assert_eq!(bound.base_format, GL_RGB);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
    }

    #[test]
    fn rows_are_unpacked_with_the_alignment() {
        let mut gl = Gl::new(4, 4);
        let mut name = [0];
        gl.gen_textures(1, &mut name);
        gl.bind_texture(GL_TEXTURE_2D, name[0]);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
        // 1×2 luminance with the default alignment 4: the second row starts at byte 4.
        gl.tex_image_2d(GL_TEXTURE_2D, 0, 1, 1, 2, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, &[10u8, 0, 0, 0, 20]);
        gl.enable(GL_TEXTURE_2D);
        let bound = gl.bound_texture().expect("complete");
        assert_eq!(bound.levels[0].texels, vec![[10, 10, 10, 255], [20, 20, 20, 255]]);
        // Too short for the aligned layout.
        gl.tex_image_2d(GL_TEXTURE_2D, 0, 1, 1, 2, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, &[10u8, 20]);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
    }

    #[test]
    fn proxies_take_sizes_and_say_when_an_image_does_not_fit() {
        // GL 1.1 §3.8.1 and piglit's proxy-texture: errors leave the proxy as it was; an image
        // too large is no error and a proxy level of width and height 0.
        let mut gl = Gl::new(4, 4);
        let width = |gl: &mut Gl| {
            let mut w = [-1];
            gl.get_tex_level_parameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &mut w);
            w[0]
        };
        gl.tex_image_2d::<u8>(GL_PROXY_TEXTURE_2D, 0, GL_RGBA as GLint, 8, 8, 0, GL_RGBA, GL_FLOAT, &[]);
        assert_eq!((gl.get_error(), width(&mut gl)), (GL_NO_ERROR, 8));
        gl.tex_image_2d::<u8>(GL_PROXY_TEXTURE_2D, 0, GL_RGBA as GLint, 8, 8, 2, GL_RGBA, GL_FLOAT, &[]);
        assert_eq!((gl.get_error(), width(&mut gl)), (GL_INVALID_VALUE, 8));
        gl.tex_image_2d::<u8>(
            GL_PROXY_TEXTURE_2D,
            0,
            GL_RGBA as GLint,
            8,
            8,
            0,
            GL_DEPTH_COMPONENT,
            GL_UNSIGNED_INT_8_8_8_8,
            &[],
        );
        assert_eq!((gl.get_error(), width(&mut gl)), (GL_INVALID_OPERATION, 8));
        let big = 2 * MAX_TEXTURE_SIZE;
        gl.tex_image_2d::<u8>(GL_PROXY_TEXTURE_2D, 0, GL_RGBA as GLint, big, big, 0, GL_RGBA, GL_FLOAT, &[]);
        assert_eq!((gl.get_error(), width(&mut gl)), (GL_NO_ERROR, 0));
        assert!(gl.bound_levels(2).is_empty(), "the bound texture is untouched");
        // piglit's max-texture-size-level: a level's sides are at most the largest >> level.
        let define = |gl: &mut Gl, level: GLint, w: GLsizei, h: GLsizei| {
            gl.tex_image_2d::<u8>(GL_TEXTURE_2D, level, GL_RGBA as GLint, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, &[]);
            gl.get_error()
        };
        assert_eq!(define(&mut gl, 0, MAX_TEXTURE_SIZE, 1), GL_NO_ERROR);
        assert_eq!(define(&mut gl, 1, MAX_TEXTURE_SIZE, 1), GL_INVALID_VALUE);
        assert_eq!(define(&mut gl, 2, 1, MAX_TEXTURE_SIZE / 2), GL_INVALID_VALUE);
        let mut depth = [-1];
        gl.get_tex_level_parameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_SIZE, &mut depth);
        assert_eq!((gl.get_error(), depth[0]), (GL_NO_ERROR, 0));
    }

    #[test]
    fn borders_are_stripped_as_mesa_strips_them() {
        // Measured on Mesa 22.3 (llvmpipe, OSMesa): a 6 × 6 RGBA image with border 1 whose
        // inside texel (x, y) is (40x, 40y, 100) and whose border is red.
        let image: Vec<u8> = (0..36)
            .flat_map(|i| {
                let (x, y) = (i % 6, i / 6);
                let border = x == 0 || y == 0 || x == 5 || y == 5;
                if border {
                    [255, 0, 0, 255]
                } else {
                    [40 * x as u8, 40 * y as u8, 100, 255]
                }
            })
            .collect();
        let mut gl = Gl::new(4, 4);
        gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
        let level = |gl: &mut Gl, target: GLenum, pname: GLenum| {
            let mut v = [-1];
            gl.get_tex_level_parameteriv(target, 0, pname, &mut v);
            v[0]
        };
        let rgba = GL_RGBA as GLint;
        gl.tex_image_2d(GL_TEXTURE_2D, 0, rgba, 6, 6, 1, GL_RGBA, GL_UNSIGNED_BYTE, &image);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        let sizes = |gl: &mut Gl, target| {
            [GL_TEXTURE_WIDTH, GL_TEXTURE_HEIGHT, GL_TEXTURE_BORDER].map(|p| level(gl, target, p))
        };
        assert_eq!(sizes(&mut gl, GL_TEXTURE_2D), [4, 4, 0]);
        let texels = gl.bound_levels(2)[0].as_ref().unwrap().texels.clone();
        assert_eq!((texels[0], texels[15]), ([40, 40, 100, 255], [160, 160, 100, 255]));
        for (w, h, border, error) in
            [(5, 5, 1, GL_NO_ERROR), (1, 1, 1, GL_INVALID_VALUE), (2, 2, 1, GL_NO_ERROR), (0, 0, 1, GL_INVALID_VALUE)]
        {
            gl.tex_image_2d(GL_TEXTURE_2D, 0, rgba, w, h, border, GL_RGBA, GL_UNSIGNED_BYTE, &image);
            assert_eq!(gl.get_error(), error, "{w} × {h}");
        }
        assert_eq!(level(&mut gl, GL_TEXTURE_2D, GL_TEXTURE_WIDTH), 0, "2 × 2 with border 1 is empty");
        gl.tex_image_2d(GL_TEXTURE_2D, 0, rgba, 4, 4, 2, GL_RGBA, GL_UNSIGNED_BYTE, &image);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
        gl.tex_image_1d(GL_TEXTURE_1D, 0, rgba, 6, 1, GL_RGBA, GL_UNSIGNED_BYTE, &image);
        assert_eq!((gl.get_error(), sizes(&mut gl, GL_TEXTURE_1D)), (GL_NO_ERROR, [4, 1, 0]));
        gl.tex_image_2d::<u8>(GL_PROXY_TEXTURE_2D, 0, rgba, 6, 6, 1, GL_RGBA, GL_UNSIGNED_BYTE, &[]);
        assert_eq!(sizes(&mut gl, GL_PROXY_TEXTURE_2D), [6, 6, 1], "a proxy keeps its border");
        gl.copy_tex_image_2d(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 4, 4, 1);
        assert_eq!((gl.get_error(), sizes(&mut gl, GL_TEXTURE_2D)), (GL_NO_ERROR, [2, 2, 0]));
    }

    #[test]
    fn images_go_through_the_pixel_transfer() {
        // piglit's teximage-scale-bias: (0.5, 0.25, 0.1, 0.5) scaled by (2, 3, 1, 1) and biased
        // by (-0.25, 0, 0.4, 0) is (0.75, 0.75, 0.5, 0.5).
        let mut gl = Gl::new(4, 4);
        for (pname, v) in [(GL_RED_SCALE, 2.0), (GL_RED_BIAS, -0.25), (GL_GREEN_SCALE, 3.0), (GL_BLUE_BIAS, 0.4)] {
            gl.pixel_transferf(pname, v);
        }
        gl.tex_image_2d(GL_TEXTURE_2D, 0, GL_RGBA as GLint, 1, 1, 0, GL_RGBA, GL_FLOAT, &[0.5f32, 0.25, 0.1, 0.5]);
        let texel = gl.bound_levels(2)[0].as_ref().unwrap().texels[0];
        assert_eq!(texel, [191, 191, 128, 128]);
        // A colour-index bitmap through the I_TO_* maps (piglit's
        // read-pixels-after-display-list): bits 1 and 0 become the maps' entries 1 and 0.
        let mut gl = Gl::new(4, 4);
        gl.pixel_mapfv(GL_PIXEL_MAP_I_TO_R, 2, &[0.0, 1.0]);
        gl.pixel_mapfv(GL_PIXEL_MAP_I_TO_B, 2, &[1.0, 0.0]);
        gl.pixel_mapfv(GL_PIXEL_MAP_I_TO_A, 2, &[1.0, 1.0]);
        gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
        gl.tex_image_2d(GL_TEXTURE_2D, 0, GL_RGBA as GLint, 2, 1, 0, GL_COLOR_INDEX, GL_BITMAP, &[0x80u8]);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        let texels = gl.bound_levels(2)[0].as_ref().unwrap().texels.clone();
        assert_eq!(texels, [[255, 0, 0, 255], [0, 0, 255, 255]]);
        gl.tex_image_2d(GL_TEXTURE_2D, 0, GL_RGBA as GLint, 2, 1, 0, GL_RGB, GL_BITMAP, &[0x80u8]);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    }

    #[test]
    fn texture_errors() {
        let mut gl = Gl::new(4, 4);
        gl.bind_texture(0x1234, 1);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
        gl.bind_texture(GL_TEXTURE_1D, 7);
        gl.bind_texture(GL_TEXTURE_2D, 7);
        assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
        gl.tex_image_2d(GL_TEXTURE_2D, 0, 5, 1, 1, 0, GL_RGB, GL_UNSIGNED_BYTE, &[0u8; 4]);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
        gl.tex_image_2d(GL_TEXTURE_2D, 0, 3, 1, 1, 0, 0x1234, GL_UNSIGNED_BYTE, &[0u8; 4]);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
        gl.tex_image_2d(GL_TEXTURE_2D, -1, 3, 1, 1, 0, GL_RGB, GL_UNSIGNED_BYTE, &[0u8; 4]);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR_MIPMAP_LINEAR as i32);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
        gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_LINEAR as i32);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
        gl.tex_sub_image_2d(GL_TEXTURE_2D, 3, 0, 0, 1, 1, GL_RGB, GL_UNSIGNED_BYTE, &[0u8; 4]);
        assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
        let mut names = [0; 2];
        gl.gen_textures(-1, &mut names);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
        gl.gen_textures(2, &mut names);
        assert_eq!(gl.is_texture(names[0]), GL_FALSE);
        gl.bind_texture(GL_TEXTURE_2D, names[0]);
        assert_eq!(gl.is_texture(names[0]), GL_TRUE);
        gl.delete_textures(2, &names);
        assert_eq!(gl.is_texture(names[0]), GL_FALSE);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
    }

    #[test]
    fn sub_images_replace_a_rectangle() {
        let mut gl = Gl::new(4, 4);
        checker(&mut gl);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
        gl.tex_sub_image_2d(GL_TEXTURE_2D, 0, 1, 1, 1, 1, GL_RGBA, GL_FLOAT, &[0.5f32, 0.5, 0.5, 1.0]);
        gl.enable(GL_TEXTURE_2D);
        let bound = gl.bound_texture().expect("complete");
        assert_eq!(bound.levels[0].texels[3], [128, 128, 128, 255]);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
    }
}
