// The rasteriser for gleval's assembled frames: GL's fixed-function vertex work (transform,
// lighting, primitive assembly, wide lines and points) is already done, so a vertex carries its
// clip-space position and final colour, and the fragment stage writes the interpolated colour.

struct VertexOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) color: vec4<f32>,
};

@vertex
fn vs_main(@location(0) clip: vec4<f32>, @location(1) color: vec4<f32>) -> VertexOut {
    var out: VertexOut;
    out.clip = clip;
    out.color = color;
    return out;
}

@fragment
fn fs_main(in: VertexOut) -> @location(0) vec4<f32> {
    return in.color;
}
