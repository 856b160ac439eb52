// The rasteriser for gleval's assembled frames: GL's fixed-function vertex work (transform,
// lighting, primitive assembly, wide lines and points) is already done, so a vertex carries its
// clip-space position, final colour, texture coordinates and fog coordinate. The fragment stage
// is GL's per-fragment work, shared with the mesh rasteriser (`shaders/fragment.wgsl`, appended
// to this source when the module is made); blending is the pipeline's blend state.

@group(0) @binding(0) var tex_image: texture_2d<f32>;
@group(0) @binding(1) var tex_sampler: sampler;
@group(0) @binding(2) var<uniform> env: Fragment;

struct VertexOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) color: vec4<f32>,
    @location(1) tex: vec4<f32>,
    @location(2) fog: f32,
};

@vertex
fn vs_main(
    @location(0) clip: vec4<f32>,
    @location(1) color: vec4<f32>,
    @location(2) tex: vec4<f32>,
    @location(3) fog: f32,
) -> VertexOut {
    var out: VertexOut;
    out.clip = clip;
    out.color = color;
    out.tex = tex;
    out.fog = fog;
    return out;
}

@fragment
fn fs_main(in: VertexOut) -> @location(0) vec4<f32> {
    let color = fragment_ops(in.color, in.tex, in.fog);
    if env.alpha_func != 0u && !alpha_passes(color.a) {
        discard;
    }
    return color;
}
