// The rasteriser for gleval's assembled frames: GL's fixed-function vertex work (transform,
// lighting, primitive assembly, wide lines and points) is already done, so a vertex carries its
// clip-space position, final colour, secondary colour (what the colour sum adds, zero without
// one), texture coordinates and fog coordinate. The fragment stage
// is GL's per-fragment work, shared with the mesh rasteriser (`shaders/fragment.wgsl`, appended
// to this source when the module is made), plus what only this rasteriser draws: the polygon
// stipple, and smooth points and lines, whose coverage multiplies the alpha before the alpha
// test, as Mesa's llvmpipe does (src/render/smooth.rs). Blending is the pipeline's blend state.

@group(0) @binding(0) var tex_image: texture_2d<f32>;
@group(0) @binding(1) var tex_sampler: sampler;
@group(0) @binding(2) var<uniform> env: Fragment;
@group(0) @binding(3) var tex_image_3d: texture_3d<f32>;

struct VertexOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) color: vec4<f32>,
    @location(1) secondary: vec4<f32>,
    @location(2) tex: vec4<f32>,
    @location(3) fog: f32,
    @location(4) aa: vec4<f32>,
};

@vertex
fn vs_main(
    @location(0) clip: vec4<f32>,
    @location(1) color: vec4<f32>,
    @location(2) secondary: vec4<f32>,
    @location(3) tex: vec4<f32>,
    @location(4) fog: f32,
    @location(5) aa: vec4<f32>,
) -> VertexOut {
    var out: VertexOut;
    out.clip = clip;
    out.color = color;
    out.secondary = secondary;
    out.tex = tex;
    out.fog = fog;
    out.aa = aa;
    return out;
}

@fragment
fn fs_main(in: VertexOut) -> @location(0) vec4<f32> {
    var color = fragment_ops(in.color, in.secondary, in.tex, in.fog);
    if env.stipple != 0u && !stipple_keeps(in.clip.xy) {
        discard;
    }
    if env.coverage == 1u {
        let d = dot(in.aa.xy, in.aa.xy);
        if d > in.aa.w {
            discard;
        }
        color.a *= point_coverage(d, in.aa.z);
    } else if env.coverage == 2u {
        color.a *= saturate(in.aa.y - abs(in.aa.x)) * saturate(in.aa.w - abs(in.aa.z));
    }
    if env.alpha_func != 0u && !alpha_passes(color.a) {
        discard;
    }
    return color;
}

// A smooth point's coverage at d = u² + v² with k = (1 − 1/r)²: Mesa 22.3's NIR pass takes
// (1 − d)/(1 − k) where k ≥ d and 1 elsewhere (k < 1 for every radius).
fn point_coverage(d: f32, k: f32) -> f32 {
    return select(1.0, (1.0 - d) / max(1.0 - k, 1e-6), k >= d);
}
