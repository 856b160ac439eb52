//! GL 1.4's `GL_GENERATE_MIPMAP` (GL 1.4 spec §3.8.8, `GL_SGIS_generate_mipmap`): when the base
//! level of a texture that asks for it changes, the levels below it are made again, each from
//! the one above. GL leaves the filter to the implementation; llvmpipe's (Mesa's
//! `st_generate_mipmap` through `util_gen_mipmap`, a blit with a linear filter) samples the
//! level above at each new texel's centre, clamped to the edge, and weighs in 8-bit fixed point
//! axis by axis, rounding after each (measured: `tests/reference/calls/cases/generate_mipmap.calls`,
//! where 0, 1, 2, 2 make 2, not the mean's 1).

use super::{depth_texel, texel_depth, ImageTarget, TexLevel, TextureObject};
use crate::gl::consts::GL_DEPTH_COMPONENT;
use crate::gl::types::GLint;
use crate::gl::Gl;

/// `a` to `b` by `weight` (of 256), as llvmpipe's 8-bit lerp rounds.
fn lerp8(a: i32, b: i32, weight: i32) -> i32 {
    a + (((b - a) * weight + 128) >> 8)
}

/// Where new texel `i` of `to` samples an axis of `from` texels: the two texels and the second's
/// weight (of 256).
fn taps(i: usize, from: usize, to: usize) -> (usize, usize, i32) {
    let u = (i as f32 + 0.5) * from as f32 / to as f32 - 0.5;
    let first = u.floor();
    let weight = ((u - first) * 256.0) as i32;
    let clamp = |k: f32| (k.max(0.0) as usize).min(from - 1);
    (clamp(first), clamp(first + 1.0), weight)
}

/// The level below `level`: each side halved (at least 1), filtered as llvmpipe filters; a
/// depth level's depths (`depth`: its internal format) with the same taps and weights, in
/// floats (not measured against Mesa).
pub(super) fn next_level(level: &TexLevel, three_d: bool, depth: Option<GLint>) -> TexLevel {
    let (w, h, d) = (level.width as usize, level.height as usize, level.depth as usize);
    let (nw, nh, nd) = ((w / 2).max(1), (h / 2).max(1), if three_d { (d / 2).max(1) } else { d });
    // Each axis's taps, once per new column, row and image.
    let axis = |from: usize, to: usize| (0..to).map(|i| taps(i, from, to)).collect::<Vec<_>>();
    let (columns, rows) = (axis(w, nw), axis(h, nh));
    let images = if three_d { axis(d, nd) } else { (0..d).map(|k| (k, k, 0)).collect() };
    let mut texels = Vec::with_capacity(nw * nh * nd);
    for &(k0, k1, wr) in &images {
        for &(j0, j1, wt) in &rows {
            for &(i0, i1, ws) in &columns {
                let texel = if let Some(internal) = depth {
                    let lerp = |a: f32, b: f32, weight: i32| a + (b - a) * weight as f32 / 256.0;
                    let at = |i: usize, j: usize, k: usize| texel_depth(level.texel(i, j, k));
                    let row = |j: usize, k: usize| lerp(at(i0, j, k), at(i1, j, k), ws);
                    let image = |k: usize| lerp(row(j0, k), row(j1, k), wt);
                    depth_texel(lerp(image(k0), image(k1), wr), internal)
                } else {
                    std::array::from_fn(|c| {
                        let at = |i: usize, j: usize, k: usize| i32::from(level.texel(i, j, k)[c]);
                        let row = |j: usize, k: usize| lerp8(at(i0, j, k), at(i1, j, k), ws);
                        let image = |k: usize| lerp8(row(j0, k), row(j1, k), wt);
                        lerp8(image(k0), image(k1), wr) as u8
                    })
                };
                texels.push(texel);
            }
        }
    }
    TexLevel { width: nw as u32, height: nh as u32, depth: nd as u32, texels, stencil: Vec::new() }
}

impl TextureObject {
    /// Makes the levels below the base level again from it, down to 1 × 1 (× 1) or the maximum
    /// level, with the base's formats, when `GL_GENERATE_MIPMAP` is set and `level` is the
    /// base.
    pub(super) fn generate_below(&mut self, face: usize, level: usize, dims: u8) {
        let base = usize::try_from(self.params.base_level).unwrap_or(usize::MAX);
        if !self.params.generate_mipmap || level != base {
            return;
        }
        let images = self.face(face);
        let Some(top) = images.level(base) else { return };
        let depth = (images.formats[base] == GL_DEPTH_COMPONENT).then(|| images.level_format(base).0);
        let last = usize::try_from(self.params.max_level).unwrap_or(0);
        let mut below: Vec<TexLevel> = Vec::new();
        for _ in base..last {
            let above = below.last().unwrap_or(top);
            if above.width == 1 && above.height == 1 && (dims != 3 || above.depth == 1) {
                break;
            }
            below.push(next_level(above, dims == 3, depth));
        }
        let (format, (internal, _)) = (images.formats[base], images.level_format(base));
        for (k, image) in (base + 1..).zip(below) {
            self.define_level(face, k, Some(image), (format, internal), 0);
        }
    }
}

impl Gl {
    /// After level `level` of the image target `t` of the bound texture changed: its mipmaps
    /// made again if it asks for them and `level` is its base (a cube map's face by face).
    pub(in crate::gl) fn generate_if_base(&mut self, t: ImageTarget, level: usize) {
        let object = self.bound_object_mut(t.slot);
        if object.params.generate_mipmap {
            object.generate_below(t.face, level, t.dims());
            self.image_changed(t.slot);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn levels_are_filtered_as_llvmpipe_filters_them() {
        // Mesa's answers (generate_mipmap.calls): 2 × 2 of red 0, 1 / 2, 2 makes 2 (the rows'
        // lerps round to 1 and 2 before the column's); 5 × 1 of 0, 100, 200, 50, 250 makes 75,
        // 100 (the centres at 0.75 and 3.25).
        let two = TexLevel::flat(2, 2, vec![[0, 0, 1, 1], [1, 1, 0, 0], [2, 1, 2, 1], [2, 2, 1, 3]]);
        assert_eq!(next_level(&two, false, None).texels, [[2, 2, 2, 2]]);
        let five = TexLevel::flat(5, 1, [0u8, 100, 200, 50, 250].map(|v| [v; 4]).to_vec());
        let below = next_level(&five, false, None);
        assert_eq!((below.width, below.texels.clone()), (2, vec![[75; 4], [100; 4]]));
        let solid = TexLevel {
            width: 2,
            height: 1,
            depth: 2,
            texels: vec![[0; 4], [1; 4], [2; 4], [2; 4]],
            stencil: Vec::new(),
        };
        let below = next_level(&solid, true, None);
        assert_eq!((below.width, below.height, below.depth, below.texels), (1, 1, 1, vec![[2; 4]]));
    }

    #[test]
    fn depth_levels_are_filtered_as_depths() {
        // The bytes of a depth level are a float's: filtered as bytes, 0.25 and 0.75 would not
        // make their mean.
        let z32 = crate::gl::consts::GL_DEPTH_COMPONENT32 as GLint;
        let level = TexLevel::flat(2, 1, vec![depth_texel(0.25, z32), depth_texel(0.75, z32)]);
        let below = next_level(&level, false, Some(z32));
        assert_eq!(below.texels.iter().map(|&t| texel_depth(t)).collect::<Vec<_>>(), [0.5]);
    }
}
