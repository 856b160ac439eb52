// GL's per-fragment operations before blending, in GL's order: unit 0's texture with GL's
// texture environment (GL 1.1 spec §3.8.9, tables 3.17 and 3.18; ADD from GL 1.3), the colour
// sum (GL 1.4 §3.9), fog (§3.9)
// and the alpha test (§4.1.3). Shared by the frame rasteriser (`raster.wgsl`) and the mesh
// rasteriser (`mesh_raster.wgsl`): each appends this source to its own and declares the
// bindings it reads, `tex_image`, `tex_image_3d`, `tex_sampler` and `env` (a `Fragment`).

struct Fragment {
    // 0 no texture, 1 MODULATE, 2 DECAL, 3 BLEND, 4 REPLACE, 5 ADD, 6 COMBINE.
    mode: u32,
    // The base internal format: 0 ALPHA, 1 LUMINANCE, 2 LUMINANCE_ALPHA, 3 RGB, 4 RGBA,
    // 5 INTENSITY.
    format: u32,
    // GL_CLAMP in s and t: 0 not, 1 with nearest filtering, 2 with linear filtering. The
    // coordinate is clamped to [0, 1] before filtering (GL 1.1 §3.8.6), so linear filtering at
    // the edge mixes in the border colour (`border_color`); the sampler clamps to the edge,
    // and the share of the filter that falls outside is replaced by the border here. GL 1.3's
    // GL_CLAMP_TO_BORDER: 3 with nearest, 4 with linear filtering (not clamped; outside is
    // the border).
    clamp_s: u32,
    clamp_t: u32,
    color: vec4<f32>,
    // 0 no fog, 1 LINEAR, 2 EXP, 3 EXP2.
    fog_mode: u32,
    // 0 no alpha test, else the GL comparison (GL_NEVER .. GL_ALWAYS) as 1 .. 8.
    alpha_func: u32,
    fog_density: f32,
    alpha_ref: f32,
    fog_start: f32,
    fog_end: f32,
    // 0 none, 1 a smooth point's coverage, 2 a smooth line's.
    coverage: u32,
    // 3 for a 3D texture, sampled at (s, t, r) from `tex_image_3d`; else 2.
    dims: u32,
    fog_color: vec4<f32>,
    // 1 with a polygon stipple (GL 1.1 §3.5.6): row y of the window (from the bottom, modulo
    // 32) keeps the fragments of column x where bit x is set.
    stipple: u32,
    // The target's height in pixels; 0 for a target drawn upside down (see `stipple_keeps`).
    height: u32,
    // GL_CLAMP in r, as clamp_s (a 3D texture).
    clamp_r: u32,
    pad3: u32,
    stipple_rows: array<vec4<u32>, 8>,
    // GL_TEXTURE_BORDER_COLOR, clamped to [0, 1].
    border_color: vec4<f32>,
    // GL 1.3's combiner (mode 6, GL_COMBINE), its RGB and alpha halves: x the function (1
    // REPLACE, 2 MODULATE, 3 ADD, 4 ADD_SIGNED, 5 INTERPOLATE, 6 SUBTRACT, 7 DOT3_RGB, 8
    // DOT3_RGBA), y the three sources four bits each (0 the texture, 1 the constant, 2 the
    // primary colour, 3 zero), z the three operands likewise (0 SRC_COLOR, 1
    // ONE_MINUS_SRC_COLOR, 2 SRC_ALPHA, 3 ONE_MINUS_SRC_ALPHA), w the scale.
    combine_rgb: vec4<u32>,
    combine_alpha: vec4<u32>,
};

// The fragment's colour after texturing, the colour sum and fog: `secondary` the secondary
// colour (zero where no sum is made), `tex` the interpolated (s, t, r, q), `fog` the eye
// distance. Samples even without a texture (a blank one is bound), so that the sample
// stays in uniform control flow.
fn fragment_ops(color_in: vec4<f32>, secondary: vec4<f32>, tex: vec4<f32>, fog: f32) -> vec4<f32> {
    // (s/q, t/q, r/q); GL's first image row is t = 0, uploaded as row 0, its first image r = 0.
    let q = select(1.0, tex.w, tex.w != 0.0);
    let str = tex.xyz / q;
    let clamp_modes = vec3<u32>(env.clamp_s, env.clamp_t, env.clamp_r);
    let clamped = (clamp_modes == vec3<u32>(1u)) | (clamp_modes == vec3<u32>(2u));
    let coord = select(str, clamp(str, vec3<f32>(0.0), vec3<f32>(1.0)), clamped);
    // One image is sampled: `env` is uniform, so the branch keeps the sample in uniform
    // control flow.
    let three_d = env.dims == 3u;
    var sampled: vec4<f32>;
    if three_d {
        sampled = textureSample(tex_image_3d, tex_sampler, coord);
    } else {
        sampled = textureSample(tex_image, tex_sampler, coord.xy);
    }
    let texel = mix(env.border_color, sampled, inside_border(coord, three_d));
    var color = color_in;
    if env.mode != 0u {
        color = apply_env(color, texel);
    }
    color = vec4<f32>(min(color.rgb + secondary.rgb, vec3<f32>(1.0)), color.a);
    if env.fog_mode != 0u {
        color = vec4<f32>(mix(env.fog_color.rgb, color.rgb, fog_factor(fog)), color.a);
    }
    return color;
}

// The share of the filter at `coord` that lies on the texture rather than on the border of
// GL_CLAMP or GL_CLAMP_TO_BORDER (1 away from the edges): a linear filter's weight on texels
// inside (the sampler duplicated the edge texel), a nearest one's 1 or 0.
fn inside_border(coord: vec3<f32>, three_d: bool) -> f32 {
    let flat = vec3<f32>(vec2<f32>(textureDimensions(tex_image, 0)), 1.0);
    let size = select(flat, vec3<f32>(textureDimensions(tex_image_3d, 0)), three_d);
    let u = coord * size - 0.5;
    let linear = clamp(min(u + 1.0, size - u), vec3<f32>(0.0), vec3<f32>(1.0));
    // GL_CLAMP_TO_BORDER's nearest texel: on the texture or not.
    let texel = floor(coord * size);
    let nearest = select(vec3<f32>(0.0), vec3<f32>(1.0), (texel >= vec3<f32>(0.0)) & (texel < size));
    let s = axis_share(env.clamp_s, linear.x, nearest.x);
    let t = axis_share(env.clamp_t, linear.y, nearest.y);
    let r = select(1.0, axis_share(env.clamp_r, linear.z, nearest.z), three_d);
    return s * t * r;
}

// The share along one axis by its clamp mode (see `Fragment.clamp_s`).
fn axis_share(mode: u32, linear: f32, nearest: f32) -> f32 {
    switch mode {
        case 2u, 4u: { return linear; }
        case 3u: { return nearest; }
        default: { return 1.0; }
    }
}

// Whether the polygon stipple keeps the fragment at framebuffer position `p` (y down, pixel
// centres at +0.5): GL's window row is height − 1 − ⌊y⌋, or ⌊y⌋ itself in a target drawn upside
// down (a height of 0: the renderer's headless frames, rows in GL's order).
fn stipple_keeps(p: vec2<f32>) -> bool {
    let x = u32(p.x) % 32u;
    let down = env.height - 1u - min(u32(p.y), max(env.height, 1u) - 1u);
    let y = select(down, u32(p.y), env.height == 0u) % 32u;
    let row = env.stipple_rows[y / 4u][y % 4u];
    return ((row >> x) & 1u) != 0u;
}

// GL's fog factor f (the fragment's share), clamped to [0, 1]: C = f·Cf + (1 − f)·Cfog.
fn fog_factor(z: f32) -> f32 {
    var f: f32;
    switch env.fog_mode {
        case 1u: { f = (env.fog_end - z) / (env.fog_end - env.fog_start); }
        case 2u: { f = exp(-env.fog_density * z); }
        default: { let dz = env.fog_density * z; f = exp(-dz * dz); }
    }
    return clamp(f, 0.0, 1.0);
}

// The alpha test: NEVER, LESS, EQUAL, LEQUAL, GREATER, NOTEQUAL, GEQUAL, ALWAYS as 1 .. 8.
fn alpha_passes(a: f32) -> bool {
    let r = env.alpha_ref;
    switch env.alpha_func {
        case 1u: { return false; }
        case 2u: { return a < r; }
        case 3u: { return a == r; }
        case 4u: { return a <= r; }
        case 5u: { return a > r; }
        case 6u: { return a != r; }
        case 7u: { return a >= r; }
        default: { return true; }
    }
}

// GL's texture functions: Cf, Af the fragment's colour; Ct, At the texture's by base format;
// GL 1.3's combiner for COMBINE.
fn apply_env(cf: vec4<f32>, texel: vec4<f32>) -> vec4<f32> {
    if env.mode == 6u {
        return combine(cf, texture_source(texel));
    }
    let has_rgb = env.format != 0u;
    let intensity = env.format == 5u;
    let has_alpha = env.format == 0u || env.format == 2u || env.format == 4u || intensity;
    let luminance = env.format == 1u || env.format == 2u || intensity;
    let ct = select(texel.rgb, vec3<f32>(texel.r), luminance);
    // An intensity texel is I in all four components (GL 1.1 table 3.15).
    let at = select(texel.a, texel.r, intensity);
    var c = cf.rgb;
    var a = cf.a;
    switch env.mode {
        case 1u: {
            if has_rgb { c = cf.rgb * ct; }
            if has_alpha { a = cf.a * at; }
        }
        case 2u: {
            if env.format == 3u { c = ct; }
            if env.format == 4u { c = mix(cf.rgb, ct, at); }
        }
        case 3u: {
            if has_rgb { c = mix(cf.rgb, env.color.rgb, ct); }
            if has_alpha { a = select(cf.a * at, mix(cf.a, env.color.a, at), intensity); }
        }
        case 4u: {
            if has_rgb { c = ct; }
            if has_alpha { a = at; }
        }
        default: {
            if has_rgb { c = min(cf.rgb + ct, vec3<f32>(1.0)); }
            if has_alpha { a = select(cf.a * at, min(cf.a + at, 1.0), intensity); }
        }
    }
    return vec4<f32>(c, a);
}

// The texel as a combiner source by base format (GL 1.3 table 3.15), as `texture_source` in
// gl/texture/combine.rs.
fn texture_source(t: vec4<f32>) -> vec4<f32> {
    switch env.format {
        case 0u: { return vec4<f32>(vec3<f32>(0.0), t.a); }
        case 1u: { return vec4<f32>(vec3<f32>(t.r), 1.0); }
        case 2u: { return vec4<f32>(vec3<f32>(t.r), t.a); }
        case 3u: { return vec4<f32>(t.rgb, 1.0); }
        case 5u: { return vec4<f32>(t.r); }
        default: { return t; }
    }
}

// Combiner argument k of a half: its source through its operand.
fn combine_argument(half: vec4<u32>, k: u32, cf: vec4<f32>, texel: vec4<f32>) -> vec4<f32> {
    var c: vec4<f32>;
    switch (half.y >> (4u * k)) & 15u {
        case 0u: { c = texel; }
        case 1u: { c = env.color; }
        case 2u: { c = cf; }
        default: { c = vec4<f32>(0.0); }
    }
    switch (half.z >> (4u * k)) & 15u {
        case 0u: { return c; }
        case 1u: { return 1.0 - c; }
        case 2u: { return vec4<f32>(c.a); }
        default: { return vec4<f32>(1.0 - c.a); }
    }
}

// A combiner function (GL 1.3 table 3.19) of three arguments, componentwise.
fn combine_function(f: u32, a0: vec4<f32>, a1: vec4<f32>, a2: vec4<f32>) -> vec4<f32> {
    switch f {
        case 1u: { return a0; }
        case 2u: { return a0 * a1; }
        case 3u: { return a0 + a1; }
        case 4u: { return a0 + a1 - 0.5; }
        case 5u: { return a0 * a2 + a1 * (1.0 - a2); }
        default: { return a0 - a1; }
    }
}

// GL 1.3's combiner (§3.8.13), as `Combine::apply`: PREVIOUS is the primary colour on unit 0.
fn combine(cf: vec4<f32>, texel: vec4<f32>) -> vec4<f32> {
    let rgb = env.combine_rgb;
    let alpha = env.combine_alpha;
    let r0 = combine_argument(rgb, 0u, cf, texel);
    let r1 = combine_argument(rgb, 1u, cf, texel);
    let r2 = combine_argument(rgb, 2u, cf, texel);
    let a0 = combine_argument(alpha, 0u, cf, texel).a;
    let a1 = combine_argument(alpha, 1u, cf, texel).a;
    let a2 = combine_argument(alpha, 2u, cf, texel).a;
    let a = clamp(combine_function(alpha.x, vec4<f32>(a0), vec4<f32>(a1), vec4<f32>(a2)).a * f32(alpha.w), 0.0, 1.0);
    if rgb.x >= 7u {
        // DOT3_RGBA's alpha is the dot product under the alpha scale, as Mesa's.
        let d = 4.0 * dot(r0.rgb - 0.5, r1.rgb - 0.5);
        let dot_alpha = clamp(d * f32(alpha.w), 0.0, 1.0);
        return vec4<f32>(vec3<f32>(clamp(d * f32(rgb.w), 0.0, 1.0)), select(a, dot_alpha, rgb.x == 8u));
    }
    let c = clamp(combine_function(rgb.x, r0, r1, r2).rgb * f32(rgb.w), vec3<f32>(0.0), vec3<f32>(1.0));
    return vec4<f32>(c, a);
}
