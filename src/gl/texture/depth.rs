//! GL 1.4's depth textures and shadow comparison (GL 1.4 spec §3.8.1, §3.8.4, §3.8.14;
//! `GL_ARB_depth_texture`, `GL_ARB_shadow`, GL 1.5's `GL_EXT_shadow_funcs`; Mesa
//! `main/teximage.c`, `main/texparam.c`, llvmpipe's `lp_bld_sample`).
//!
//! A depth level keeps each depth as llvmpipe stores it, in the texel's four bytes as an f32
//! (little-endian): `GL_DEPTH_COMPONENT` and `GL_DEPTH_COMPONENT24` as 24-bit unsigned
//! normalised values, `GL_DEPTH_COMPONENT16` as 16-bit ones, `GL_DEPTH_COMPONENT32` as floats
//! (measured: `GL_TEXTURE_DEPTH_SIZE` 24, 16 and 32, and `glGetTexImage` of 0.90001 exact for
//! the third only). An image's depths are truncated to the normalised value, d · (2ⁿ − 1), and
//! read back as z / (2ⁿ − 1) rounded to f32 (measured: 0.25 gives 0.249999955 in 24 bits, 0.5
//! gives 0.49999237 in 16); the depth buffer's, already of 24 bits, are copied as they are.

use crate::gl::consts::*;
use crate::gl::types::*;

/// A depth in [0, 1] of an image as a level of internal format `internal` keeps it.
#[must_use]
pub fn depth_texel(d: f32, internal: GLint) -> [u8; 4] {
    quantized(d, internal, f64::trunc).to_le_bytes()
}

/// A depth of the depth buffer as a level of internal format `internal` keeps it
/// (`glCopyTexImage`: the buffer's 24-bit value, to the nearest where the level has fewer bits;
/// measured: 0.5 reads back as 0.50000006, as the buffer holds it).
#[must_use]
pub fn copied_depth_texel(d: f32, internal: GLint) -> [u8; 4] {
    quantized(d, internal, f64::round).to_le_bytes()
}

/// `d`, clamped to [0, 1], as a depth of `internal`'s bits: `to_integer` makes the normalised
/// integer of it.
fn quantized(d: f32, internal: GLint, to_integer: fn(f64) -> f64) -> u32 {
    let d = d.clamp(0.0, 1.0);
    let bits = depth_bits(internal);
    if bits == 32 {
        return d.to_bits();
    }
    let max = f64::from((1u32 << bits) - 1);
    ((to_integer(f64::from(d) * max) / max) as f32).to_bits()
}

/// The depth a depth level's texel holds.
#[must_use]
pub fn texel_depth(texel: [u8; 4]) -> f32 {
    f32::from_bits(u32::from_le_bytes(texel))
}

/// `GL_TEXTURE_DEPTH_SIZE` of a level of `internal` format: the bits llvmpipe gives
/// `GL_DEPTH_COMPONENT16` and `32`, 24 for the unsized and 24-bit formats (measured).
pub(super) fn depth_bits(internal: GLint) -> u32 {
    match internal as GLenum {
        GL_DEPTH_COMPONENT16 => 16,
        // GL 3.0's float formats (GL_ARB_depth_buffer_float) keep floats, clamped to [0, 1]
        // (measured: 1.5 reads back as 1).
        GL_DEPTH_COMPONENT32 | GL_DEPTH_COMPONENT32F | GL_DEPTH32F_STENCIL8 => 32,
        _ => 24,
    }
}

/// A texture object's depth parameters (GL 1.4 table 6.17): `GL_DEPTH_TEXTURE_MODE`,
/// `GL_TEXTURE_COMPARE_MODE` and `GL_TEXTURE_COMPARE_FUNC`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct DepthParams {
    /// How a depth becomes a texel: `GL_LUMINANCE` (initially), `GL_INTENSITY`, `GL_ALPHA`, or
    /// `GL_RED` (which Mesa takes too).
    pub mode: GLenum,
    /// `GL_NONE` (initially) or `GL_COMPARE_R_TO_TEXTURE`.
    pub compare_mode: GLenum,
    /// The comparison: `GL_LEQUAL` (initially), `GL_GEQUAL`, and GL 1.5's other six.
    pub compare_func: GLenum,
}

impl Default for DepthParams {
    fn default() -> Self {
        Self { mode: GL_LUMINANCE, compare_mode: GL_NONE, compare_func: GL_LEQUAL }
    }
}

impl DepthParams {
    /// Whether `value` is one `pname`, a depth parameter, takes; `None` if `pname` is not one.
    pub(super) fn accepts(pname: GLenum, value: GLenum) -> Option<bool> {
        Some(match pname {
            GL_DEPTH_TEXTURE_MODE => matches!(value, GL_LUMINANCE | GL_INTENSITY | GL_ALPHA | GL_RED),
            GL_TEXTURE_COMPARE_MODE => matches!(value, GL_NONE | GL_COMPARE_R_TO_TEXTURE),
            GL_TEXTURE_COMPARE_FUNC => (GL_NEVER..=GL_ALWAYS).contains(&value),
            _ => return None,
        })
    }

    /// The parameter `pname` names.
    pub(super) fn field(&mut self, pname: GLenum) -> &mut GLenum {
        match pname {
            GL_DEPTH_TEXTURE_MODE => &mut self.mode,
            GL_TEXTURE_COMPARE_MODE => &mut self.compare_mode,
            _ => &mut self.compare_func,
        }
    }

    /// The base format the texture environment sees (GL 1.4 §3.8.13, "the depth texture is
    /// treated as" the mode's format): `GL_RED`'s (d, 0, 0, 1) as an RGB texel.
    #[must_use]
    pub fn environment_format(&self) -> GLenum {
        if self.mode == GL_RED {
            GL_RGB
        } else {
            self.mode
        }
    }
}

/// How a bound depth texture is sampled: each texel's depth, or with a comparison the result
/// of comparing the reference r with it (GL 1.4 §3.8.14: 1 where the function passes, 0 where
/// not, each texel compared before filtering as llvmpipe does), made a texel by the mode.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct DepthSampling {
    /// The comparison function, if `GL_TEXTURE_COMPARE_MODE` is `GL_COMPARE_R_TO_TEXTURE`.
    pub compare: Option<GLenum>,
    /// `GL_DEPTH_TEXTURE_MODE`.
    pub mode: GLenum,
}

impl DepthSampling {
    /// The sampling a texture of `params` gets.
    #[must_use]
    pub fn new(params: &DepthParams) -> Self {
        let compare = (params.compare_mode == GL_COMPARE_R_TO_TEXTURE).then_some(params.compare_func);
        Self { compare, mode: params.mode }
    }

    /// One texel's value: its depth, or its comparison with `r` (clamped to [0, 1], as for a
    /// fixed-point depth format).
    #[must_use]
    pub fn value(&self, texel: [u8; 4], r: f32) -> f32 {
        let d = texel_depth(texel);
        let Some(func) = self.compare else { return d };
        let r = r.clamp(0.0, 1.0);
        let pass = match func {
            GL_NEVER => false,
            GL_LESS => r < d,
            GL_EQUAL => r == d,
            GL_LEQUAL => r <= d,
            GL_GREATER => r > d,
            GL_NOTEQUAL => r != d,
            GL_GEQUAL => r >= d,
            _ => true,
        };
        f32::from(u8::from(pass))
    }

    /// The filtered value as the texel the environment reads (its base format is
    /// [`DepthParams::environment_format`]).
    #[must_use]
    pub fn texel(&self, v: f32) -> [f32; 4] {
        match self.mode {
            GL_RED => [v, 0.0, 0.0, 1.0],
            _ => [v; 4],
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn depths_read_back_as_mesa_reads_them() {
        // Mesa 22.3's glGetTexImage(GL_DEPTH_COMPONENT, GL_FLOAT) of a texture given 0, 0.25,
        // 0.5 and 1.
        let z24 = GL_DEPTH_COMPONENT as GLint;
        // Mesa's bits, as depth_texture.calls prints them.
        let back = [0.0f32, 0.25, 0.5, 1.0].map(|d| texel_depth(depth_texel(d, z24)).to_bits());
        assert_eq!(back, [0, 0x3E7F_FFFD, 0x3EFF_FFFF, 0x3F80_0000]);
        assert_eq!(texel_depth(depth_texel(-3.0, z24)), 0.0);
        assert_eq!(texel_depth(depth_texel(0.5, GL_DEPTH_COMPONENT16 as GLint)).to_bits(), 0x3EFF_FF00);
        assert_eq!(texel_depth(depth_texel(0.90001, GL_DEPTH_COMPONENT32 as GLint)), 0.90001);
        assert_eq!(texel_depth(copied_depth_texel(0.5, z24)).to_bits(), 0x3F00_0001);
    }

    #[test]
    fn comparisons_pass_as_their_functions_say() {
        let texel = depth_texel(0.5, GL_DEPTH_COMPONENT as GLint);
        let d = texel_depth(texel);
        let compare = |func, r| DepthSampling { compare: Some(func), mode: GL_LUMINANCE }.value(texel, r);
        assert_eq!([GL_LEQUAL, GL_GEQUAL, GL_EQUAL, GL_NOTEQUAL].map(|f| compare(f, d)), [1.0, 1.0, 1.0, 0.0]);
        assert_eq!([GL_LESS, GL_GREATER, GL_NEVER, GL_ALWAYS].map(|f| compare(f, 0.75)), [0.0, 1.0, 0.0, 1.0]);
        assert_eq!(compare(GL_LEQUAL, -2.0), 1.0, "r is clamped to [0, 1]");
        assert_eq!(DepthSampling { compare: None, mode: GL_RED }.texel(0.5), [0.5, 0.0, 0.0, 1.0]);
    }
}
