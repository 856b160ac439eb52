//! `GL_ARB_texture_rectangle` (GL 3.1 §3.8.1, §3.8.8; Mesa `main/texparam.c`,
//! `main/teximage.c`): `GL_TEXTURE_RECTANGLE` textures of one level of any size, addressed in
//! texels, s in [0, width] and t in [0, height], with no border, no mipmaps and no repeating
//! wrap. Measured on Mesa 22.3 (`capi/tests/texture_rectangle.c`): a level above 0 or a border
//! is `GL_INVALID_VALUE`; `GL_REPEAT`, `GL_MIRRORED_REPEAT` and a mipmap filter are
//! `GL_INVALID_ENUM`; a base level above 0 `GL_INVALID_OPERATION`; the initial wraps are
//! `GL_CLAMP_TO_EDGE` and the minification filter `GL_LINEAR`; an enabled rectangle comes before
//! `GL_TEXTURE_2D` and after `GL_TEXTURE_3D`.
//!
//! The CPU rasteriser samples such a texture in its texel coordinates as they come, as
//! llvmpipe does (no division by the size and multiplication back, which would move a
//! bilinear weight by a rounding: `render/soft/sampler.rs`); wgpu hands its frames to it.

use crate::gl::consts::*;
use crate::gl::types::*;

/// Whether a rectangle texture takes `value` for `pname` (the other names take what they take
/// for any target).
pub(super) fn takes(pname: GLenum, value: GLenum) -> bool {
    match pname {
        GL_TEXTURE_WRAP_S | GL_TEXTURE_WRAP_T | GL_TEXTURE_WRAP_R => !matches!(value, GL_REPEAT | GL_MIRRORED_REPEAT),
        GL_TEXTURE_MIN_FILTER => matches!(value, GL_NEAREST | GL_LINEAR),
        _ => true,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn no_repeat_and_no_mipmaps() {
        assert!(!takes(GL_TEXTURE_WRAP_S, GL_REPEAT));
        assert!(!takes(GL_TEXTURE_WRAP_T, GL_MIRRORED_REPEAT));
        assert!(takes(GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER));
        assert!(!takes(GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST));
        assert!(takes(GL_TEXTURE_MAG_FILTER, GL_LINEAR));
    }
}
