//! Texture sampling for the CPU rasteriser: GL's filters, wrap modes and mipmap selection
//! (GL 1.1 spec §3.8.5–3.8.8, with GL 1.2's LOD clamp and 3D textures; the levels from the base level on are
//! the bound texture's) as the wgpu sampler of `gpu/textures.rs` does them, so both
//! rasterisers read the same texels. `GL_CLAMP` clamps to the edge here; the fragment stage
//! clamps the coordinate and weighs in the border (`fragment.rs`), as `fragment.wgsl` does.

use crate::gl::consts::*;
use crate::gl::types::GLenum;
use crate::gl::{BoundTexture, TexLevel};

/// Samples a bound texture.
pub(super) struct Sampler<'a> {
    texture: &'a BoundTexture,
}

impl<'a> Sampler<'a> {
    pub fn new(texture: &'a BoundTexture) -> Self {
        Self { texture }
    }

    /// The filtered texel at `str` (normalised, or in texels for a rectangle texture; r is read
    /// for a 3D texture only), given the
    /// change of the coordinates one pixel right (`dx`) and one pixel down (`dy`), which choose
    /// between magnification and minification and the mipmap level (the scale factor ρ of
    /// §3.8.5, GL 1.2 eq. 3.13 with r for a 3D texture).
    pub fn sample(&self, str: [f32; 3], dx: [f32; 3], dy: [f32; 3]) -> [f32; 4] {
        self.sample_image(0, str, dx, dy)
    }

    /// As [`Sampler::sample`] within image `image` of each level of a 1D or 2D texture: a cube
    /// map's face (GL 1.3 §3.8.6: once the face is chosen, it is sampled as a 2D texture).
    pub fn sample_image(&self, image: usize, str: [f32; 3], dx: [f32; 3], dy: [f32; 3]) -> [f32; 4] {
        let filtered = self.filtered(image, str, dx, dy);
        // A depth texture's filtered depth, or share of texels passing the comparison, as the
        // texel its mode makes.
        self.texture.depth.map_or(filtered, |depth| depth.texel(filtered[0]))
    }

    /// The texel filtered from the levels (for a depth texture, its depth or comparison in
    /// every component).
    fn filtered(&self, image: usize, str: [f32; 3], dx: [f32; 3], dy: [f32; 3]) -> [f32; 4] {
        let params = &self.texture.params;
        let levels = &self.texture.levels;
        let base = &levels[0];
        // A depth factor of 0 below 3D: hypot(x, 0) is |x| exactly, so 1D and 2D are as before.
        let d = if self.texture.dims == 3 { base.depth as f32 } else { 0.0 };
        // A rectangle texture's coordinates are in texels already (GL_ARB_texture_rectangle).
        let (w, h) = if self.texture.rectangle { (1.0, 1.0) } else { (base.width as f32, base.height as f32) };
        let scale = |v: [f32; 3]| (v[0] * w).hypot(v[1] * h).hypot(v[2] * d);
        let rho = scale(dx).max(scale(dy));
        // GL 1.4's bias, then GL 1.2's LOD clamp, decide between magnification and
        // minification too (eqs. 3.15 and 3.16).
        let lambda = params.lod.clamp(rho.log2() + self.texture.lod_bias);
        // Magnification, also where ρ is 0 or not a number (λ is −∞ or NaN).
        if lambda.is_nan() || lambda <= 0.0 {
            return self.filter(base, params.mag_filter, str, image);
        }
        let last = (levels.len() - 1) as f32;
        let lambda = lambda.min(last);
        match params.min_filter {
            GL_NEAREST | GL_LINEAR => self.filter(base, params.min_filter, str, image),
            GL_NEAREST_MIPMAP_NEAREST | GL_LINEAR_MIPMAP_NEAREST => {
                // The nearest level, halves rounding down (Vulkan's ⌈λ + ½⌉ − 1).
                let d = ((lambda + 0.5).ceil() - 1.0).max(0.0) as usize;
                self.filter(&levels[d], level_filter(params.min_filter), str, image)
            }
            _ => {
                let d = lambda.floor();
                let lower = d as usize;
                let upper = (lower + 1).min(levels.len() - 1);
                let f = lambda - d;
                let filter = level_filter(params.min_filter);
                let (a, b) =
                    (self.filter(&levels[lower], filter, str, image), self.filter(&levels[upper], filter, str, image));
                std::array::from_fn(|k| a[k] + (b[k] - a[k]) * f)
            }
        }
    }

    /// Nearest or linear filtering within one level: bilinear within an image, and for a 3D
    /// texture linear between the two nearest images too (GL 1.2 eq. 3.17); below 3D, within
    /// image `image`.
    fn filter(&self, level: &TexLevel, filter: GLenum, [s, t, r]: [f32; 3], image: usize) -> [f32; 4] {
        let (w, h, d) = (level.width as i64, level.height as i64, level.depth as i64);
        let params = &self.texture.params;
        let wrap_t = if self.texture.dims == 1 { GL_REPEAT } else { params.wrap_t };
        let (wrap_s, wrap_r) = (params.wrap_s, params.wrap_r);
        let solid = self.texture.dims == 3;
        let depth = self.texture.depth;
        let texel = |i: i64, j: i64, k: i64| {
            let (i, j) = (wrap(i, w, wrap_s), wrap(j, h, wrap_t));
            let k = if solid { wrap(k, d, wrap_r) } else { image as i64 };
            let texel = level.texels[((k * h + j) * w + i) as usize];
            match depth {
                // GL 1.4 §3.8.14: the reference is r, each texel compared before filtering.
                Some(depth) => [depth.value(texel, r); 4],
                None => texel.map(|c| f32::from(c) / 255.0),
            }
        };
        let (u, v, x) =
            if self.texture.rectangle { (s, t, r * d as f32) } else { (s * w as f32, t * h as f32, r * d as f32) };
        if filter == GL_NEAREST {
            return texel(floor(u), floor(v), floor(x));
        }
        let (u, v) = (u - 0.5, v - 0.5);
        let (i, j) = (floor(u), floor(v));
        let (a, b) = (u - u.floor(), v - v.floor());
        let bilinear = |k: i64| -> [f32; 4] {
            let (t00, t10, t01, t11) = (texel(i, j, k), texel(i + 1, j, k), texel(i, j + 1, k), texel(i + 1, j + 1, k));
            std::array::from_fn(|c| {
                let top = t00[c] + (t10[c] - t00[c]) * a;
                let bottom = t01[c] + (t11[c] - t01[c]) * a;
                top + (bottom - top) * b
            })
        };
        if !solid {
            return bilinear(0);
        }
        let x = x - 0.5;
        let (k, c) = (floor(x), x - x.floor());
        let (front, back) = (bilinear(k), bilinear(k + 1));
        std::array::from_fn(|n| front[n] + (back[n] - front[n]) * c)
    }
}

/// The filter within a level of a mipmapping minification filter.
fn level_filter(min_filter: GLenum) -> GLenum {
    match min_filter {
        GL_NEAREST_MIPMAP_NEAREST | GL_NEAREST_MIPMAP_LINEAR => GL_NEAREST,
        _ => GL_LINEAR,
    }
}

/// ⌊x⌋ as an integer, saturating far outside any texture (NaN gives 0).
fn floor(x: f32) -> i64 {
    x.floor().clamp(-1e15, 1e15) as i64
}

/// A texel index wrapped into `0..size`: `GL_REPEAT` repeats, `GL_MIRRORED_REPEAT` repeats
/// the texture and its mirror image (GL 1.4 §3.8.7), every other mode clamps to the edge (the
/// fragment stage weighs in the border for `GL_CLAMP` and `GL_CLAMP_TO_BORDER`).
fn wrap(i: i64, size: i64, mode: GLenum) -> i64 {
    match mode {
        GL_REPEAT => i.rem_euclid(size),
        GL_MIRRORED_REPEAT => {
            let m = i.rem_euclid(2 * size);
            if m < size {
                m
            } else {
                2 * size - 1 - m
            }
        }
        _ => i.clamp(0, size - 1),
    }
}
