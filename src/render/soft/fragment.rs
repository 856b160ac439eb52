//! GL's per-fragment operations before the depth test, for the CPU rasteriser: each drawing
//! unit's texture with its texture environment in unit order (GL 1.1 spec §3.8.9, tables 3.17
//! and 3.18; `GL_ADD` from GL 1.3; GL 1.3 §3.8.15's units), fog (§3.9), the polygon stipple (§3.5.6), the coverage of smooth points and
//! lines (Mesa's, `render/smooth.rs`) and the alpha test (§4.1.3). The same operations in the
//! same order as `shaders/fragment.wgsl` and `shaders/raster.wgsl` on the GPU.

use super::framebuffer::compare;
use super::sampler::Sampler;
use super::units::UnitCoords;
use crate::gl::consts::*;
use crate::gl::{BoundTexture, Fog, MAX_TEXTURE_UNITS};
use crate::render::assemble::{FragmentState, Smooth};

/// A fragment's interpolated values (see [`crate::render::RasterVertex`]), with units 1 to 7's
/// coordinates where the batch draws with them (`()` where it does not).
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct Fragment<U = ()> {
    pub color: [f32; 4],
    pub secondary: [f32; 4],
    pub tex: [f32; 4],
    pub units: U,
    pub fog: f32,
    pub aa: [f32; 4],
}

/// How `tex` (and the units' coordinates) change one pixel right and one pixel down (for the
/// textures' level of detail).
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct TexSlope<U = ()> {
    pub dx: [f32; 4],
    pub dy: [f32; 4],
    pub units_dx: U,
    pub units_dy: U,
}

/// A batch's fragment state, ready to shade fragments.
pub(super) struct Program<'a> {
    state: &'a FragmentState,
    sampler: Option<Sampler<'a>>,
    /// One sampler for each of [`FragmentState::more_textures`].
    more_samplers: Vec<Sampler<'a>>,
}

impl<'a> Program<'a> {
    pub fn new(state: &'a FragmentState) -> Self {
        let more_samplers = state.more_textures.iter().map(|(_, t)| Sampler::new(t)).collect();
        Self { state, sampler: state.texture.as_ref().map(Sampler::new), more_samplers }
    }

    /// Whether fragments read a texture (and so need [`TexSlope`]).
    pub fn textured(&self) -> bool {
        self.sampler.is_some() || !self.more_samplers.is_empty()
    }

    /// Whether units beyond unit 0 draw (their coordinates are needed).
    pub fn multi_unit(&self) -> bool {
        !self.more_samplers.is_empty()
    }

    /// The fragment's colour before blending, or `None` where GL discards it; `(x, row)` is
    /// its window column and its GL row (counted from the bottom).
    pub fn shade<U: UnitCoords>(&self, f: &Fragment<U>, slope: &TexSlope<U>, (x, row): (u32, u32)) -> Option<[f32; 4]> {
        let mut color = f.color;
        if self.multi_unit() {
            color = self.units(f, slope);
        } else if let (Some(sampler), Some(texture)) = (&self.sampler, &self.state.texture) {
            color = apply_env(
                texture,
                color,
                texel(texture, sampler, f.tex, &TexSlope { dx: slope.dx, dy: slope.dy, ..TexSlope::default() }),
            );
        }
        color = color_sum(color, f.secondary);
        if let Some(fog) = &self.state.fog {
            let k = fog_factor(fog, f.fog);
            for c in 0..3 {
                color[c] = fog.color[c] + (color[c] - fog.color[c]) * k;
            }
        }
        if let Some(rows) = &self.state.polygon_stipple {
            if (rows[(row % 32) as usize] >> (x % 32)) & 1 == 0 {
                return None;
            }
        }
        color[3] *= coverage(self.state.smooth, f.aa)?;
        if let Some((func, reference)) = self.state.alpha_test {
            if !compare(func, color[3], reference) {
                return None;
            }
        }
        Some(color)
    }
}

impl Program<'_> {
    /// Every drawing unit in order, each applying its environment to the previous one's result
    /// (GL 1.3 §3.8.15; the first to the fragment's colour); `GL_COMBINE`'s `GL_TEXTUREn`
    /// reads unit n's texel (GL 1.4's crossbar), zero for a unit that does not draw.
    fn units<U: UnitCoords>(&self, f: &Fragment<U>, slope: &TexSlope<U>) -> [f32; 4] {
        let mut texels = [[0.0; 4]; MAX_TEXTURE_UNITS];
        let mut drawing: Vec<(usize, &BoundTexture)> = Vec::with_capacity(MAX_TEXTURE_UNITS);
        if let (Some(sampler), Some(texture)) = (&self.sampler, &self.state.texture) {
            let unit_slope = TexSlope { dx: slope.dx, dy: slope.dy, ..TexSlope::default() };
            texels[0] = texel(texture, sampler, f.tex, &unit_slope);
            drawing.push((0, texture));
        }
        for ((unit, texture), sampler) in self.state.more_textures.iter().zip(&self.more_samplers) {
            let k = unit - 1;
            let unit_slope = TexSlope { dx: slope.units_dx.unit(k), dy: slope.units_dy.unit(k), ..TexSlope::default() };
            texels[*unit] = texel(texture, sampler, f.units.unit(k), &unit_slope);
            drawing.push((*unit, texture));
        }
        let drawn = |unit: usize| drawing.iter().any(|(u, _)| *u == unit);
        let source = |unit: usize| match drawing.iter().find(|(u, _)| *u == unit) {
            Some((_, t)) if drawn(unit) => crate::gl::texture_source(t.base_format, texels[unit]),
            _ => [0.0; 4],
        };
        let mut color = f.color;
        for (unit, texture) in &drawing {
            color = if texture.env_mode == GL_COMBINE {
                let own = crate::gl::texture_source(texture.base_format, texels[*unit]);
                texture.combine.apply_on_unit(own, [color, f.color], texture.env_color, &source)
            } else {
                apply_env(texture, color, texels[*unit])
            };
        }
        color
    }
}

/// The texel for (s, t, r, q): s/q, t/q (and r/q for a 3D texture), clamped to [0, 1] under
/// `GL_CLAMP`, filtered, and with a linear filter at a `GL_CLAMP` edge, or anywhere outside
/// under GL 1.3's `GL_CLAMP_TO_BORDER`, the share falling on the border given the border
/// colour, as `inside_border` does in `fragment.wgsl`.
fn texel(texture: &BoundTexture, sampler: &Sampler<'_>, tex: [f32; 4], slope: &TexSlope) -> [f32; 4] {
    if texture.cube_map {
        return cube_texel(sampler, tex, slope);
    }
    let project = |t: [f32; 4]| {
        let q = if t[3] != 0.0 { t[3] } else { 1.0 };
        [t[0] / q, t[1] / q, t[2] / q]
    };
    let str = project(tex);
    let at = |d: [f32; 4]| {
        let moved = project(std::array::from_fn(|k| tex[k] + d[k]));
        std::array::from_fn(|k| moved[k] - str[k])
    };
    let (dx, dy) = (at(slope.dx), at(slope.dy));
    let params = &texture.params;
    let wraps = [params.wrap_s, params.wrap_t, params.wrap_r];
    // The coordinates a texture of these dimensions reads: s, t below 1D's, r in 3D only.
    let used = |k: usize| k < usize::from(texture.dims);
    let clamped: [bool; 3] = std::array::from_fn(|k| used(k) && wraps[k] == GL_CLAMP);
    let bordered: [bool; 3] = std::array::from_fn(|k| used(k) && wraps[k] == GL_CLAMP_TO_BORDER);
    let base = &texture.levels[0];
    let sizes = [base.width, base.height, base.depth];
    // Texels a coordinate of 1 spans: the level's size, or 1 for a rectangle texture, whose
    // coordinates are in texels (GL_ARB_texture_rectangle), as the sampler takes them.
    let per_unit = |k: usize| if texture.rectangle { 1.0 } else { sizes[k] as f32 };
    let top = |k: usize| sizes[k] as f32 / per_unit(k);
    let coord: [f32; 3] = std::array::from_fn(|k| if clamped[k] { str[k].clamp(0.0, top(k)) } else { str[k] });
    let sample = sampler.sample(coord, dx, dy);
    let linear = params.mag_filter == GL_LINEAR
        && matches!(params.min_filter, GL_LINEAR | GL_LINEAR_MIPMAP_NEAREST | GL_LINEAR_MIPMAP_LINEAR);
    let weighs_border = bordered.contains(&true) || (clamped.contains(&true) && linear);
    if !weighs_border {
        return sample;
    }
    // The share of the filter on the texture along one axis: a linear filter's weight on
    // texels inside (the sampler clamped to the edge, so the edge texel stands in for the
    // border's); for GL_CLAMP_TO_BORDER's nearest filter, whether the texel is inside.
    let inside = |c: f32, size: u32, k: usize| {
        let (size, texels) = (size as f32, c * per_unit(k));
        if linear && (clamped[k] || bordered[k]) {
            let u = texels - 0.5;
            (u + 1.0).min(size - u).clamp(0.0, 1.0)
        } else if bordered[k] {
            let i = texels.floor();
            if (0.0..size).contains(&i) {
                1.0
            } else {
                0.0
            }
        } else {
            1.0
        }
    };
    let share = [base.width, base.height, base.depth]
        .into_iter()
        .enumerate()
        .map(|(k, size)| inside(coord[k], size, k))
        .product::<f32>();
    std::array::from_fn(|k| texture.border_color[k] + (sample[k] - texture.border_color[k]) * share)
}

/// A cube map's texel: (s, t, r) a direction, its face and the coordinates there (GL 1.3
/// §3.8.6; q scales the direction only, which changes neither), the coordinates' change one
/// pixel right and down measured on the same face, and the face sampled as a 2D texture.
fn cube_texel(sampler: &Sampler<'_>, tex: [f32; 4], slope: &TexSlope) -> [f32; 4] {
    let direction = |d: [f32; 4]| [tex[0] + d[0], tex[1] + d[1], tex[2] + d[2]];
    let (face, [s, t]) = crate::gl::cube_face(direction([0.0; 4]));
    let change = |d: [f32; 4]| {
        let [s1, t1] = crate::gl::cube_face_coords(face, direction(d));
        [s1 - s, t1 - t, 0.0]
    };
    sampler.sample_image(face, [s, t, 0.0], change(slope.dx), change(slope.dy))
}

/// GL's texture functions: `cf` the fragment's colour, `texel` the texture's, by base format;
/// GL 1.3's combiner for `GL_COMBINE`.
fn apply_env(texture: &BoundTexture, cf: [f32; 4], texel: [f32; 4]) -> [f32; 4] {
    if texture.env_mode == GL_COMBINE {
        let source = crate::gl::texture_source(texture.base_format, texel);
        return texture.combine.apply(source, cf, texture.env_color);
    }
    let format = texture.base_format;
    let has_rgb = format != GL_ALPHA;
    let intensity = format == GL_INTENSITY;
    let has_alpha = matches!(format, GL_ALPHA | GL_LUMINANCE_ALPHA | GL_RGBA | GL_INTENSITY);
    let luminance = matches!(format, GL_LUMINANCE | GL_LUMINANCE_ALPHA | GL_INTENSITY);
    let ct = if luminance { [texel[0]; 3] } else { [texel[0], texel[1], texel[2]] };
    // An intensity texel is I in all four components (GL 1.1 table 3.15).
    let at = if intensity { texel[0] } else { texel[3] };
    let mut c = [cf[0], cf[1], cf[2]];
    let mut a = cf[3];
    let env = texture.env_color;
    match texture.env_mode {
        GL_MODULATE => {
            if has_rgb {
                c = std::array::from_fn(|k| cf[k] * ct[k]);
            }
            if has_alpha {
                a = cf[3] * at;
            }
        }
        GL_DECAL => {
            if format == GL_RGB {
                c = ct;
            }
            if format == GL_RGBA {
                c = std::array::from_fn(|k| cf[k] + (ct[k] - cf[k]) * at);
            }
        }
        GL_BLEND => {
            if has_rgb {
                c = std::array::from_fn(|k| cf[k] + (env[k] - cf[k]) * ct[k]);
            }
            if has_alpha {
                // Intensity blends its alpha as its colour (GL 1.1 table 3.18).
                a = if intensity { cf[3] + (env[3] - cf[3]) * at } else { cf[3] * at };
            }
        }
        GL_REPLACE => {
            if has_rgb {
                c = ct;
            }
            if has_alpha {
                a = at;
            }
        }
        _ => {
            if has_rgb {
                c = std::array::from_fn(|k| (cf[k] + ct[k]).min(1.0));
            }
            if has_alpha {
                a = if intensity { (cf[3] + at).min(1.0) } else { cf[3] * at };
            }
        }
    }
    [c[0], c[1], c[2], a]
}

/// The colour sum (GL 1.4 §3.9): the secondary colour's RGB added, clamped; the vertex stage
/// made the secondary colour zero where GL makes no sum.
pub(super) fn color_sum([r, g, b, a]: [f32; 4], secondary: [f32; 4]) -> [f32; 4] {
    [(r + secondary[0]).min(1.0), (g + secondary[1]).min(1.0), (b + secondary[2]).min(1.0), a]
}

/// GL's fog factor f (the fragment's share), clamped to [0, 1]: C = f·Cf + (1 − f)·Cfog.
fn fog_factor(fog: &Fog, z: f32) -> f32 {
    let f = match fog.mode {
        GL_LINEAR => (fog.end - z) / (fog.end - fog.start),
        GL_EXP => (-fog.density * z).exp(),
        _ => {
            let dz = fog.density * z;
            (-dz * dz).exp()
        }
    };
    f.clamp(0.0, 1.0)
}

/// A smooth point's or line's coverage (the factor on alpha), or `None` outside a smooth
/// point's disc. A point's k = (1 − 1/r)²: Mesa 22.3 takes (1 − d)/(1 − k) where k ≥ d.
fn coverage(smooth: Smooth, aa: [f32; 4]) -> Option<f32> {
    match smooth {
        Smooth::None => Some(1.0),
        Smooth::Point => {
            let d = aa[0] * aa[0] + aa[1] * aa[1];
            if d > aa[3] {
                return None;
            }
            Some(if aa[2] >= d { (1.0 - d) / (1.0 - aa[2]).max(1e-6) } else { 1.0 })
        }
        Smooth::Line => {
            let saturate = |x: f32| x.clamp(0.0, 1.0);
            Some(saturate(aa[1] - aa[0].abs()) * saturate(aa[3] - aa[2].abs()))
        }
    }
}
