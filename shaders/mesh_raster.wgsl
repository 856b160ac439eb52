// Draws the GPU tessellator's vertices (shaders/eval_mesh.wgsl) with GL 1.x's fixed-function
// vertex stage: modelview/projection transform, per-vertex lighting (GL 1.1 spec §2.13.1, the
// same formulas as src/render/shade.rs), the texture matrix, the fog coordinate, glDepthRange,
// and the GL viewport applied as a clip transform (wgpu needs viewports inside the target; GL
// allows them anywhere). Two-sided lighting picks the back colour by the rasteriser's facing;
// flat shading takes the first vertex, which the index buffer makes GL's provoking vertex. The
// fragment stage is GL's texturing, fog and alpha test (`shaders/fragment.wgsl`, appended to this
// source when the module is made), with the frame rasteriser's bind group as group 1.

struct Light {
    ambient: vec4<f32>,
    diffuse: vec4<f32>,
    specular: vec4<f32>,
    position: vec4<f32>,        // eye space; w = 0: directional
    spot_direction: vec4<f32>,  // xyz, w = spot exponent
    params: vec4<f32>,          // x: 1 enabled, y: 1 spot, z: cos(cutoff)
    attenuation: vec4<f32>,     // constant, linear, quadratic
};

struct Material {
    ambient: vec4<f32>,
    diffuse: vec4<f32>,
    specular: vec4<f32>,
    emission: vec4<f32>,
    shininess: vec4<f32>,       // x
};

struct Draw {
    modelview: mat4x4<f32>,
    projection: mat4x4<f32>,
    normal_matrix: mat4x4<f32>, // inverse transpose of the modelview's 3x3
    texture_matrix: mat4x4<f32>,
    viewport: vec4<f32>,        // x' = x·sx + w·ox, y' = y·sy + w·oy
    depth_range: vec4<f32>,     // near, far
    flags: vec4<f32>,           // lighting, two-sided, local viewer, normalize
    color_material: vec4<f32>,  // front, back, mode (0 ambient 1 diffuse 2 specular 3 emission 4 both)
    model_ambient: vec4<f32>,
    primitive: vec4<f32>,       // x: 1 for polygons (two-sided lighting applies); y: 1 for fog from
                                // glFogCoord (GL_FOG_COORD_SRC GL_FOG_COORD); z: |glFogCoord|
    color_sum: vec4<f32>,       // rgb: an unlit mesh's secondary colour; w: 1 separate specular
    materials: array<Material, 2>,
    lights: array<Light, 8>,
};

@group(0) @binding(0) var<uniform> draw: Draw;
@group(1) @binding(0) var tex_image: texture_2d<f32>;
@group(1) @binding(1) var tex_sampler: sampler;
@group(1) @binding(2) var<uniform> env: Fragment;
@group(1) @binding(3) var tex_image_3d: texture_3d<f32>;

struct Smooth {
    @builtin(position) clip: vec4<f32>,
    @location(0) front: vec4<f32>,
    @location(1) back: vec4<f32>,
    @location(2) tex: vec4<f32>,
    @location(3) fog: f32,
    @location(4) front_secondary: vec4<f32>,
    @location(5) back_secondary: vec4<f32>,
};

struct Flat {
    @builtin(position) clip: vec4<f32>,
    @location(0) @interpolate(flat) front: vec4<f32>,
    @location(1) @interpolate(flat) back: vec4<f32>,
    @location(2) tex: vec4<f32>,
    @location(3) fog: f32,
    @location(4) @interpolate(flat) front_secondary: vec4<f32>,
    @location(5) @interpolate(flat) back_secondary: vec4<f32>,
};

// A face's primary colour and the secondary colour the colour sum adds (GL 1.4 §3.9).
struct FaceColours {
    primary: vec4<f32>,
    secondary: vec4<f32>,
};

fn material(face: u32, color: vec4<f32>) -> Material {
    var m = draw.materials[face];
    let applies = select(draw.color_material.y, draw.color_material.x, face == 0u);
    if (applies != 0.0) {
        let mode = u32(draw.color_material.z);
        if (mode == 0u || mode == 4u) {
            m.ambient = color;
        }
        if (mode == 1u || mode == 4u) {
            m.diffuse = color;
        }
        if (mode == 2u) {
            m.specular = color;
        }
        if (mode == 3u) {
            m.emission = color;
        }
    }
    return m;
}

fn safe_normalize(v: vec3<f32>) -> vec3<f32> {
    let len2 = dot(v, v);
    if (len2 > 0.0) {
        return v * inverseSqrt(len2);
    }
    return vec3<f32>(0.0);
}

// x^y with C's powf at the edges WGSL leaves undefined: x^0 = 1, 0^y = 0.
fn power(x: f32, y: f32) -> f32 {
    if (y == 0.0) {
        return 1.0;
    }
    if (x <= 0.0) {
        return 0.0;
    }
    return pow(x, y);
}

// The primary and secondary colours of one face: the specular terms go to the secondary colour
// with GL_SEPARATE_SPECULAR_COLOR (GL 1.2 §2.13.1), else to the primary one.
fn light_face(face: u32, n: vec3<f32>, position: vec3<f32>, color: vec4<f32>) -> FaceColours {
    let m = material(face, color);
    var sum = m.emission.xyz + m.ambient.xyz * draw.model_ambient.xyz;
    var specular_sum = vec3<f32>(0.0);
    for (var i = 0u; i < 8u; i++) {
        let light = draw.lights[i];
        if (light.params.x == 0.0) {
            continue;
        }
        var vp: vec3<f32>;
        var attenuation = 1.0;
        if (light.position.w == 0.0) {
            vp = safe_normalize(light.position.xyz);
        } else {
            let d = light.position.xyz / light.position.w - position;
            let dist = length(d);
            let k = light.attenuation;
            vp = safe_normalize(d);
            attenuation = 1.0 / (k.x + k.y * dist + k.z * dist * dist);
        }
        var spot = 1.0;
        if (light.params.y != 0.0) {
            let cos_angle = dot(-vp, safe_normalize(light.spot_direction.xyz));
            spot = select(power(max(cos_angle, 0.0), light.spot_direction.w), 0.0, cos_angle < light.params.z);
        }
        let n_dot_vp = dot(n, vp);
        var c = m.ambient.xyz * light.ambient.xyz;
        var specular = vec3<f32>(0.0);
        if (n_dot_vp > 0.0) {
            c += n_dot_vp * m.diffuse.xyz * light.diffuse.xyz;
            var eye_dir = vec3<f32>(0.0, 0.0, 1.0);
            if (draw.flags.z != 0.0) {
                eye_dir = -safe_normalize(position);
            }
            let h = safe_normalize(vp + eye_dir);
            let n_dot_h = max(dot(n, h), 0.0);
            specular = power(n_dot_h, m.shininess.x) * m.specular.xyz * light.specular.xyz;
        }
        sum += attenuation * spot * c;
        specular_sum += attenuation * spot * specular;
    }
    var out: FaceColours;
    if (draw.color_sum.w != 0.0) {
        out.primary = vec4<f32>(sum, m.diffuse.w);
        out.secondary = vec4<f32>(clamp(specular_sum, vec3<f32>(0.0), vec3<f32>(1.0)), 0.0);
    } else {
        out.primary = vec4<f32>(sum + specular_sum, m.diffuse.w);
        out.secondary = vec4<f32>(0.0);
    }
    out.primary = clamp(out.primary, vec4<f32>(0.0), vec4<f32>(1.0));
    return out;
}

struct Lit {
    clip: vec4<f32>,
    front: vec4<f32>,
    back: vec4<f32>,
    tex: vec4<f32>,
    fog: f32,
    front_secondary: vec4<f32>,
    back_secondary: vec4<f32>,
};

fn vertex_stage(position: vec4<f32>, normal: vec4<f32>, color: vec4<f32>, tex: vec4<f32>) -> Lit {
    let eye = draw.modelview * position;
    let clip = draw.projection * eye;
    var out: Lit;
    out.tex = draw.texture_matrix * tex;
    // The fog coordinate: the eye-space distance |z| (Mesa's default, as src/gl/shade.rs), or
    // GL 1.4's glFogCoord under GL_FOG_COORD_SRC GL_FOG_COORD (primitive.y), the mesh's one.
    if (draw.primitive.y != 0.0) {
        out.fog = draw.primitive.z;
    } else {
        out.fog = abs(eye.z);
    }
    // glDepthRange into wgpu's [0, w], then the GL viewport as a clip transform.
    let near = draw.depth_range.x;
    let far = draw.depth_range.y;
    let z = (clip.z + clip.w) * 0.5 * (far - near) + near * clip.w;
    out.clip = vec4<f32>(
        clip.x * draw.viewport.x + clip.w * draw.viewport.y,
        clip.y * draw.viewport.z + clip.w * draw.viewport.w,
        z,
        clip.w,
    );
    if (draw.flags.x == 0.0) {
        let c = clamp(color, vec4<f32>(0.0), vec4<f32>(1.0));
        out.front = c;
        out.back = c;
        out.front_secondary = vec4<f32>(draw.color_sum.rgb, 0.0);
        out.back_secondary = out.front_secondary;
        return out;
    }
    var n = (draw.normal_matrix * vec4<f32>(normal.xyz, 0.0)).xyz;
    if (draw.flags.w != 0.0) {
        n = safe_normalize(n);
    }
    var p = eye.xyz;
    if (eye.w != 0.0) {
        p = eye.xyz / eye.w;
    }
    let front = light_face(0u, n, p, color);
    var back = front;
    if (draw.flags.y != 0.0) {
        back = light_face(1u, -n, p, color);
    }
    out.front = front.primary;
    out.back = back.primary;
    out.front_secondary = front.secondary;
    out.back_secondary = back.secondary;
    return out;
}

@vertex
fn vs_smooth(
    @location(0) position: vec4<f32>,
    @location(1) normal: vec4<f32>,
    @location(2) color: vec4<f32>,
    @location(3) tex: vec4<f32>,
) -> Smooth {
    let lit = vertex_stage(position, normal, color, tex);
    return Smooth(lit.clip, lit.front, lit.back, lit.tex, lit.fog, lit.front_secondary, lit.back_secondary);
}

@vertex
fn vs_flat(
    @location(0) position: vec4<f32>,
    @location(1) normal: vec4<f32>,
    @location(2) color: vec4<f32>,
    @location(3) tex: vec4<f32>,
) -> Flat {
    let lit = vertex_stage(position, normal, color, tex);
    return Flat(lit.clip, lit.front, lit.back, lit.tex, lit.fog, lit.front_secondary, lit.back_secondary);
}

fn face_colour(front: vec4<f32>, back: vec4<f32>, facing: bool) -> vec4<f32> {
    if (draw.primitive.x != 0.0 && !facing) {
        return back;
    }
    return front;
}

// The face's colour through texturing, the colour sum, fog and the alpha test (a failing
// fragment is discarded here: WGSL allows it in a function the fragment stage calls).
fn shade(front: vec4<f32>, back: vec4<f32>, secondary: vec4<f32>, facing: bool, tex: vec4<f32>, fog: f32) -> vec4<f32> {
    let color = fragment_ops(face_colour(front, back, facing), secondary, tex, fog);
    if env.alpha_func != 0u && !alpha_passes(color.a) {
        discard;
    }
    return color;
}

@fragment
fn fs_smooth(in: Smooth, @builtin(front_facing) facing: bool) -> @location(0) vec4<f32> {
    let secondary = face_colour(in.front_secondary, in.back_secondary, facing);
    return shade(in.front, in.back, secondary, facing, in.tex, in.fog);
}

@fragment
fn fs_flat(in: Flat, @builtin(front_facing) facing: bool) -> @location(0) vec4<f32> {
    let secondary = face_colour(in.front_secondary, in.back_secondary, facing);
    return shade(in.front, in.back, secondary, facing, in.tex, in.fog);
}
