//! The shaders' sources and the `#[repr(C)]` twins of the structs they read: what the CPU
//! writes into a buffer is, byte for byte, what WGSL's layout rules (WGSL spec §13.4, "Memory
//! Layout") make the shader read. The tests below check every member's offset against naga's
//! reflection of the shader, so a field added on one side only fails at `cargo test`, not as a
//! wrong picture.

/// GL's per-fragment operations (`shaders/fragment.wgsl`), appended to both rasterisers.
pub const FRAGMENT_WGSL: &str = include_str!("../../shaders/fragment.wgsl");
/// The frame rasteriser's source (`shaders/raster.wgsl`, then `shaders/fragment.wgsl`).
pub const RASTER_WGSL: &str =
    concat!(include_str!("../../shaders/raster.wgsl"), include_str!("../../shaders/fragment.wgsl"));
/// The evaluator's compute shader (`shaders/eval_mesh.wgsl`).
pub const EVAL_MESH_WGSL: &str = include_str!("../../shaders/eval_mesh.wgsl");
/// The mesh rasteriser's source (`shaders/mesh_raster.wgsl`, then `shaders/fragment.wgsl`).
pub const MESH_RASTER_WGSL: &str =
    concat!(include_str!("../../shaders/mesh_raster.wgsl"), include_str!("../../shaders/fragment.wgsl"));

/// Bytes per evaluated vertex (`struct Vertex`): position, normal, colour, texture coordinate.
pub const VERTEX_BYTES: u64 = 64;

/// One enabled map of a job, as the shader reads it (`struct MapDesc`).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct GpuMapDesc {
    /// [`Slot`](crate::gl::Slot) number.
    pub slot: u32,
    /// Components per control point.
    pub dim: u32,
    /// Order along u.
    pub uorder: u32,
    /// Order along v (1 for a curve).
    pub vorder: u32,
    /// First float of the control points.
    pub point_offset: u32,
    /// First value of the u Bernstein table (`nu` columns of `2·uorder − 1` values).
    pub u_offset: u32,
    /// First value of the v Bernstein table (`nv` rows of `2·vorder − 1` values).
    pub v_offset: u32,
    /// Padding.
    pub pad: u32,
}

/// One mesh, as the shader reads it (`struct Job`).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct GpuMeshJob {
    /// The enabled maps, attribute maps first and the vertex map last.
    pub maps: [GpuMapDesc; 4],
    /// How many of `maps` are used.
    pub map_count: u32,
    /// Grid points along u.
    pub nu: u32,
    /// Grid points along v.
    pub nv: u32,
    /// [`MeshMode`](crate::gl::MeshMode) number: points, curve lines, surface lines, fill.
    pub mode: u32,
    /// First output vertex (prefix sum of grid points).
    pub out_offset: u32,
    /// First output index (prefix sum of index counts).
    pub index_offset: u32,
    /// 1 when `GL_AUTO_NORMAL` applies.
    pub auto_normal: u32,
    /// Padding.
    pub pad: u32,
    /// The current normal (w unused).
    pub normal: [f32; 4],
    /// The current colour.
    pub color: [f32; 4],
    /// The current texture coordinate.
    pub tex: [f32; 4],
}

/// The dispatch's constants (`struct Meta`).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, bytemuck::Pod, bytemuck::Zeroable)]
pub(crate) struct GpuMeshMeta {
    /// Number of jobs.
    pub job_count: u32,
    /// Grid points over all jobs.
    pub total_points: u32,
    /// 1 where the backend's flat shading takes a primitive's last vertex (wgpu's GL backend),
    /// 0 where it takes the first (Vulkan, Metal, DX12).
    pub provoking_last: u32,
    /// Padding to 16 bytes.
    pub pad: u32,
}

/// One light in the draw uniform (`struct Light` of `mesh_raster.wgsl`).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub(crate) struct GpuLight {
    /// Ambient intensity.
    pub ambient: [f32; 4],
    /// Diffuse intensity.
    pub diffuse: [f32; 4],
    /// Specular intensity.
    pub specular: [f32; 4],
    /// Eye-space position.
    pub position: [f32; 4],
    /// Spot direction (xyz) and exponent (w).
    pub spot_direction: [f32; 4],
    /// Enabled, spot (cutoff ≠ 180), cos(cutoff).
    pub params: [f32; 4],
    /// Constant, linear, quadratic attenuation.
    pub attenuation: [f32; 4],
}

/// A material in the draw uniform.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub(crate) struct GpuMaterial {
    /// Ambient reflectance.
    pub ambient: [f32; 4],
    /// Diffuse reflectance.
    pub diffuse: [f32; 4],
    /// Specular reflectance.
    pub specular: [f32; 4],
    /// Emission.
    pub emission: [f32; 4],
    /// Shininess in x.
    pub shininess: [f32; 4],
}

/// A mesh's GL state for the vertex and fragment stages (`struct Draw`).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub(crate) struct GpuDraw {
    /// Modelview matrix, column-major.
    pub modelview: [[f32; 4]; 4],
    /// Projection matrix.
    pub projection: [[f32; 4]; 4],
    /// Inverse transpose of the modelview's 3×3, in a 4×4.
    pub normal_matrix: [[f32; 4]; 4],
    /// The top of the texture matrix stack (identity without a texture).
    pub texture_matrix: [[f32; 4]; 4],
    /// Viewport as a clip transform: sx, ox, sy, oy.
    pub viewport: [f32; 4],
    /// Depth range near, far.
    pub depth_range: [f32; 4],
    /// Lighting, two-sided, local viewer, normalize (1 or 0).
    pub flags: [f32; 4],
    /// Colour material on the front, on the back, mode number.
    pub color_material: [f32; 4],
    /// Light model ambient.
    pub model_ambient: [f32; 4],
    /// x: 1 for polygons.
    pub primitive: [f32; 4],
    /// The colour sum (GL 1.4 §3.9): rgb the secondary colour of an unlit mesh (zero without
    /// `GL_COLOR_SUM`); w 1 with `GL_SEPARATE_SPECULAR_COLOR` (lit: the specular terms are the
    /// secondary colour).
    pub color_sum: [f32; 4],
    /// Front and back materials.
    pub materials: [GpuMaterial; 2],
    /// The eight lights.
    pub lights: [GpuLight; 8],
}

/// A batch's fragment operations as the fragment shader reads them (`Fragment` in
/// `raster.wgsl`): the texture environment, fog and the alpha test.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub(crate) struct GpuFragment {
    /// 0 none, 1 `GL_MODULATE`, 2 `GL_DECAL`, 3 `GL_BLEND`, 4 `GL_REPLACE`, 5 `GL_ADD`.
    pub mode: u32,
    /// 0 `GL_ALPHA`, 1 `GL_LUMINANCE`, 2 `GL_LUMINANCE_ALPHA`, 3 `GL_RGB`, 4 `GL_RGBA`,
    /// 5 `GL_INTENSITY`.
    pub format: u32,
    /// `GL_CLAMP` in s: 0 not, 1 with nearest, 2 with linear filtering (the shader clamps the
    /// coordinate to [0, 1] and mixes in the border colour); `GL_CLAMP_TO_BORDER`: 3 with
    /// nearest, 4 with linear (the border replaces what lies outside).
    pub clamp_s: u32,
    /// `GL_CLAMP` in t, likewise.
    pub clamp_t: u32,
    /// `GL_TEXTURE_ENV_COLOR`.
    pub color: [f32; 4],
    /// 0 none, 1 `GL_LINEAR`, 2 `GL_EXP`, 3 `GL_EXP2`.
    pub fog_mode: u32,
    /// 0 none, else the GL comparison minus `GL_NEVER` plus 1.
    pub alpha_func: u32,
    pub fog_density: f32,
    pub alpha_ref: f32,
    pub fog_start: f32,
    pub fog_end: f32,
    /// 0 none, 1 a smooth point's coverage, 2 a smooth line's.
    pub coverage: u32,
    /// 3 for a 3D texture (sampled at (s, t, r) from the 3D binding), else 2.
    pub dims: u32,
    pub fog_color: [f32; 4],
    /// 1 with a polygon stipple.
    pub stipple: u32,
    /// The target's height in pixels (the stipple counts rows from the bottom).
    pub height: u32,
    /// `GL_CLAMP` in r (a 3D texture), as `clamp_s`.
    pub clamp_r: u32,
    pub pad3: u32,
    /// The stipple's 32 rows, four to a vector.
    pub stipple_rows: [[u32; 4]; 8],
    /// `GL_TEXTURE_BORDER_COLOR`, which a linear filter at a `GL_CLAMP` edge mixes in.
    pub border_color: [f32; 4],
    /// GL 1.3's combiner, RGB half: function, sources, operands, scale (see `fragment.wgsl`).
    pub combine_rgb: [u32; 4],
    /// The combiner's alpha half.
    pub combine_alpha: [u32; 4],
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::mem::{offset_of, size_of};

    /// Member offsets and the size of a WGSL struct, as naga lays it out for the GPU.
    fn wgsl_layout(source: &str, name: &str) -> (Vec<(String, u32)>, u32) {
        let module = naga::front::wgsl::parse_str(source).expect("parses");
        for (_, ty) in module.types.iter() {
            if ty.name.as_deref() == Some(name) {
                if let naga::TypeInner::Struct { members, span } = &ty.inner {
                    let offsets = members.iter().map(|m| (m.name.clone().unwrap_or_default(), m.offset)).collect();
                    return (offsets, *span);
                }
            }
        }
        panic!("no struct {name}");
    }

    /// A Rust twin has the WGSL struct's layout: the same size, and every member at the same
    /// offset, so bytemuck casts are what the shader reads.
    fn check(source: &str, name: &str, size: usize, rust: &[(&str, usize)]) {
        let (members, span) = wgsl_layout(source, name);
        assert_eq!(span as usize, size, "{name}: WGSL size {span}, Rust size {size}");
        assert_eq!(members.len(), rust.len(), "{name}: member count");
        for ((wname, woff), (rname, roff)) in members.iter().zip(rust) {
            assert_eq!(*woff as usize, *roff, "{name}.{wname} (Rust {rname}): WGSL offset {woff}, Rust {roff}");
        }
    }

    /// `check` of a twin named field by field (WGSL names the padding `_pad`).
    macro_rules! check_twin {
        ($source:expr, $wgsl:literal, $rust:ident { $($field:ident),* $(,)? }) => {
            check($source, $wgsl, size_of::<$rust>(), &[$((stringify!($field), offset_of!($rust, $field))),*])
        };
    }

    /// The evaluator's buffers: jobs, their maps, the dispatch constants and the vertices.
    #[test]
    fn evaluator_layouts_match_eval_mesh_wgsl() {
        check_twin!(
            EVAL_MESH_WGSL,
            "MapDesc",
            GpuMapDesc { slot, dim, uorder, vorder, point_offset, u_offset, v_offset, pad }
        );
        check_twin!(
            EVAL_MESH_WGSL,
            "Job",
            GpuMeshJob {
                maps,
                map_count,
                nu,
                nv,
                mode,
                out_offset,
                index_offset,
                auto_normal,
                pad,
                normal,
                color,
                tex
            }
        );
        check(
            EVAL_MESH_WGSL,
            "Meta",
            size_of::<GpuMeshMeta>(),
            &[("job_count", 0), ("total_points", 4), ("provoking_last", 8), ("_pad", 12)],
        );
        let (_, vertex) = wgsl_layout(EVAL_MESH_WGSL, "Vertex");
        assert_eq!(u64::from(vertex), VERTEX_BYTES);
    }

    /// The frame rasteriser's per-batch fragment operations.
    #[test]
    fn fragment_uniform_layout_matches_raster_wgsl() {
        check_twin!(
            RASTER_WGSL,
            "Fragment",
            GpuFragment {
                mode,
                format,
                clamp_s,
                clamp_t,
                color,
                fog_mode,
                alpha_func,
                fog_density,
                alpha_ref,
                fog_start,
                fog_end,
                coverage,
                dims,
                fog_color,
                stipple,
                height,
                clamp_r,
                pad3,
                stipple_rows,
                border_color,
                combine_rgb,
                combine_alpha
            }
        );
    }

    /// The mesh rasteriser's draw uniform: GL's state, materials and lights.
    #[test]
    fn draw_uniform_layouts_match_mesh_raster_wgsl() {
        check_twin!(
            MESH_RASTER_WGSL,
            "Light",
            GpuLight { ambient, diffuse, specular, position, spot_direction, params, attenuation }
        );
        check_twin!(MESH_RASTER_WGSL, "Material", GpuMaterial { ambient, diffuse, specular, emission, shininess });
        check_twin!(
            MESH_RASTER_WGSL,
            "Draw",
            GpuDraw {
                modelview,
                projection,
                normal_matrix,
                texture_matrix,
                viewport,
                depth_range,
                flags,
                color_material,
                model_ambient,
                primitive,
                color_sum,
                materials,
                lights
            }
        );
    }
}
