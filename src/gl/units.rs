//! GL 1.3's texture units as numbers (GL 1.3 §2.7): how many there are, and where each unit's
//! own enables are kept. A leaf, so that the areas with per-unit state (textures, enables,
//! matrices, current values, arrays) name the limits without importing each other.

use super::consts::*;
use super::types::*;

/// `GL_MAX_TEXTURE_UNITS`: the units of the fixed-function pipeline, each with its enables,
/// environment, coordinate generation, texture matrix and current coordinates (GL 1.3 §2.7,
/// §3.8.15; llvmpipe answers 8, as `GL_MAX_TEXTURE_COORDS`, measured on Mesa 22.3).
pub const MAX_TEXTURE_UNITS: usize = 8;

/// The units `glActiveTexture` selects. Without shaders these are the fixed-function units
/// (ARB_multitexture; GL 1.5 has no `GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS`), and a unit at
/// [`MAX_TEXTURE_UNITS`] is `GL_INVALID_ENUM`, as piglit's `texunits` checks of an
/// implementation that claims neither `GL_ARB_vertex_shader` nor `GL_ARB_fragment_program`.
/// llvmpipe takes any unit below its 192 shader image units (measured on Mesa 22.3): that is a
/// deviation of the call scripts (`tests/it/mesa_calls.rs`).
pub const MAX_COMBINED_TEXTURE_IMAGE_UNITS: usize = MAX_TEXTURE_UNITS;

/// The enables each texture unit has of its own (GL 1.3 §2.7, §3.8.15): its targets and its
/// coordinate generation.
pub(crate) const UNIT_ENABLES: &[GLenum] = &[
    GL_TEXTURE_1D,
    GL_TEXTURE_2D,
    GL_TEXTURE_3D,
    GL_TEXTURE_CUBE_MAP,
    GL_TEXTURE_RECTANGLE,
    GL_TEXTURE_GEN_S,
    GL_TEXTURE_GEN_T,
    GL_TEXTURE_GEN_R,
    GL_TEXTURE_GEN_Q,
];

/// Where unit `unit`'s enable `cap` (one of [`UNIT_ENABLES`]) is kept among the capabilities:
/// unit 0's under its own name, so that everything that draws with one unit reads it as before;
/// another unit's above every GL enum.
pub(crate) fn unit_cap(cap: GLenum, unit: usize) -> GLenum {
    cap | (unit as GLenum) << 20
}
