//! The GPU tessellator's draw path: every deferred `glEvalMesh` grid of a frame
//! ([`MeshVertices::Deferred`]) is evaluated by one compute dispatch (`shaders/eval_mesh.wgsl`)
//! into a vertex buffer and an index buffer, which the render pass then draws with GL's vertex
//! stage in WGSL (`shaders/mesh_raster.wgsl`). Nothing comes back to the CPU.
//!
//! What is bound by what: the CPU packs each mesh's control points and normalised parameters
//! (a few hundred bytes per patch) and computes the prefix sums of vertex and index counts,
//! which are known from the grid sizes alone; the GPU does all per-point work.

use super::assemble::Topology;
use crate::gl::consts::*;
use crate::gl::types::GLenum;
use crate::gl::{DrawState, Frame, GridMesh, Light, MapSample, Material, MeshJob, MeshMode, MeshVertices, Slot};
use crate::math::BezierPatch;
use crate::tess::{Mesh, MeshError};
use glam::{Mat3, Mat4};
use std::collections::HashMap;
use wgpu::util::DeviceExt;

/// The compute shader source.
pub const EVAL_MESH_WGSL: &str = include_str!("../../shaders/eval_mesh.wgsl");
/// The mesh rasteriser's source.
pub const MESH_RASTER_WGSL: &str = include_str!("../../shaders/mesh_raster.wgsl");

const WORKGROUP: u32 = 64;
const MAX_GROUPS_X: u32 = 65_535;
/// Bytes per output vertex: position, normal, colour, texture coordinate.
pub const VERTEX_BYTES: u64 = 64;

/// One enabled map of a job, as the shader reads it (`struct MapDesc`).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct GpuMapDesc {
    /// [`crate::gl::Slot`] number.
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
    /// [`MeshMode`] number: points, curve lines, surface lines, fill.
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
pub struct GpuMeshMeta {
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
pub struct GpuLight {
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
pub struct GpuMaterial {
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
pub struct GpuDraw {
    /// Modelview matrix, column-major.
    pub modelview: [[f32; 4]; 4],
    /// Projection matrix.
    pub projection: [[f32; 4]; 4],
    /// Inverse transpose of the modelview's 3×3, in a 4×4.
    pub normal_matrix: [[f32; 4]; 4],
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
    /// Front and back materials.
    pub materials: [GpuMaterial; 2],
    /// The eight lights.
    pub lights: [GpuLight; 8],
}

/// The mode number a job carries (the shader's `MODE_*` constants).
#[must_use]
pub fn mode_number(mode: MeshMode) -> u32 {
    match mode {
        MeshMode::Points => 0,
        MeshMode::CurveLines => 1,
        MeshMode::SurfaceLines => 2,
        MeshMode::Fill => 3,
        // Scattered points: the CPU supplies the triangles.
        MeshMode::Triangles => 4,
    }
}

/// Indices the shader writes for a grid: 6 per cell when filled, 2 per segment for lines.
#[must_use]
pub fn index_count(mode: MeshMode, nu: usize, nv: usize) -> usize {
    let (cu, cv) = (nu.saturating_sub(1), nv.saturating_sub(1));
    match mode {
        MeshMode::Points | MeshMode::Triangles => 0,
        MeshMode::Fill => 6 * cu * cv,
        MeshMode::CurveLines | MeshMode::SurfaceLines => 2 * (nv * cu + nu * cv),
    }
}

/// Jobs, control points and parameters packed for one dispatch, with per-job ranges.
#[derive(Debug, Default)]
pub struct PackedJobs {
    /// The jobs.
    pub jobs: Vec<GpuMeshJob>,
    /// Control points and Bernstein tables of every job, in one array (one storage binding:
    /// downlevel devices allow only four per stage).
    pub data: Vec<f32>,
    /// Total grid points (vertices).
    pub vertices: u32,
    /// Total indices.
    pub indices: u32,
    /// Index-buffer ranges the CPU fills (first index, values): GLU's trimmed triangles.
    pub explicit: Vec<(u32, Vec<u32>)>,
    /// Whether the backend's flat shading takes a primitive's last vertex, as GL does; if not,
    /// every primitive is rotated to start at GL's provoking vertex.
    pub provoking_last: bool,
}

impl PackedJobs {
    /// No jobs yet, for a backend whose flat shading takes the last vertex or the first.
    pub fn new(provoking_last: bool) -> Self {
        Self { provoking_last, ..Self::default() }
    }

    /// Appends every job of a deferred mesh; scattered meshes bring their triangles, renumbered
    /// to the packed vertices and, unless the backend's provoking vertex is the last (GL's),
    /// rotated so that GL's provoking vertex comes first (rotation keeps the winding).
    pub fn push_mesh(&mut self, mesh: &GridMesh) -> Option<()> {
        let MeshVertices::Deferred(jobs) = &mesh.vertices else { return None };
        let base = self.vertices;
        for job in jobs {
            self.push(job, mesh.mode)?;
        }
        if mesh.mode == MeshMode::Triangles {
            let count = u32::try_from(mesh.triangles.len()).ok()?;
            let total = self.vertices - base;
            if mesh.triangles.iter().any(|&i| i >= total) {
                return None;
            }
            let last = self.provoking_last;
            let rotated = mesh
                .triangles
                .chunks_exact(3)
                .flat_map(|t| if last { [t[0], t[1], t[2]] } else { [t[2], t[0], t[1]] })
                .map(|i| i + base)
                .collect();
            self.explicit.push((self.indices, rotated));
            self.indices = self.indices.checked_add(count)?;
        }
        Some(())
    }

    /// Appends a job (`mode` decides its indices); `None` if 32-bit offsets overflow or the job
    /// is malformed (more than four maps, or parameter lists of the wrong length).
    pub fn push(&mut self, job: &MeshJob, mode: MeshMode) -> Option<()> {
        let u32_of = |v: usize| u32::try_from(v).ok();
        if job.maps.len() > 4 || job.is_empty() || job.scattered != (mode == MeshMode::Triangles) {
            return None;
        }
        let mut gpu = GpuMeshJob {
            map_count: u32_of(job.maps.len())?,
            nu: u32_of(job.nu)?,
            nv: u32_of(job.nv)?,
            mode: mode_number(mode),
            out_offset: self.vertices,
            index_offset: self.indices,
            auto_normal: u32::from(job.auto_normal),
            pad: 0,
            normal: [job.template.normal[0], job.template.normal[1], job.template.normal[2], 0.0],
            color: job.template.color,
            tex: job.template.tex_coord,
            maps: Default::default(),
        };
        for (desc, map) in gpu.maps.iter_mut().zip(&job.maps) {
            let dim = map.slot.components();
            let ok = map.points.len() >= map.uorder * map.vorder * dim && map.us.len() == job.nu;
            let rows = if job.scattered { job.nu } else { job.nv };
            if !ok || map.vs.len() != rows || !(1..=30).contains(&map.uorder) || !(1..=30).contains(&map.vorder) {
                return None;
            }
            let point_offset = u32_of(self.data.len())?;
            self.data.extend_from_slice(&map.points[..map.uorder * map.vorder * dim]);
            // Room for the shader's four-wide reads of the last point.
            self.data.extend_from_slice(&[0.0; 3]);
            let u_offset = u32_of(self.data.len())?;
            push_basis_table(&mut self.data, map.uorder, &map.us);
            let v_offset = u32_of(self.data.len())?;
            push_basis_table(&mut self.data, map.vorder, &map.vs);
            *desc = GpuMapDesc {
                slot: map.slot as u32,
                dim: u32_of(dim)?,
                uorder: u32_of(map.uorder)?,
                vorder: u32_of(map.vorder)?,
                point_offset,
                u_offset,
                v_offset,
                pad: 0,
            };
        }
        self.vertices = self.vertices.checked_add(u32_of(job.len())?)?;
        self.indices = self.indices.checked_add(u32_of(index_count(mode, job.nu, job.nv))?)?;
        self.jobs.push(gpu);
        Some(())
    }
}

/// The Bernstein basis of `order` at `t` (de Casteljau's triangle, f64), into `out[..order]`.
fn bernstein(order: usize, t: f64, out: &mut [f64; 30]) {
    out[0] = 1.0;
    for level in 1..order {
        let mut saved = 0.0;
        for i in 0..level {
            let v = out[i];
            out[i] = saved + (1.0 - t) * v;
            saved = t * v;
        }
        out[level] = saved;
    }
}

/// Per parameter: the `order` Bernstein values and the `order − 1` of one degree less.
fn push_basis_table(data: &mut Vec<f32>, order: usize, params: &[f32]) {
    let mut b = [0.0; 30];
    data.reserve(params.len() * (2 * order - 1));
    for &t in params {
        let t = f64::from(t);
        bernstein(order, t, &mut b);
        data.extend(b[..order].iter().map(|&x| x as f32));
        if order > 1 {
            bernstein(order - 1, t, &mut b);
            data.extend(b[..order - 1].iter().map(|&x| x as f32));
        }
    }
}

fn storage(binding: u32, read_only: bool) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility: wgpu::ShaderStages::COMPUTE,
        ty: wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Storage { read_only },
            has_dynamic_offset: false,
            min_binding_size: None,
        },
        count: None,
    }
}

fn uniform(binding: u32, visibility: wgpu::ShaderStages, dynamic: bool) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility,
        ty: wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Uniform,
            has_dynamic_offset: dynamic,
            min_binding_size: None,
        },
        count: None,
    }
}

/// The evaluated buffers of one dispatch.
pub struct EvaluatedMeshes {
    /// `vertices` × 64 bytes: position, normal, colour, texture coordinate (vec4 each).
    pub vertices: wgpu::Buffer,
    /// u32 indices (at least 16 bytes even when empty).
    pub indices: wgpu::Buffer,
}

/// Pipeline key: topology, depth function, target format, culling (front face, culled face),
/// flat shading.
type PipelineKey = (Topology, Option<GLenum>, wgpu::TextureFormat, (wgpu::FrontFace, Option<wgpu::Face>), bool);

/// The compute and render pipelines of the GPU tessellator.
pub struct MeshPipelines {
    compute: wgpu::ComputePipeline,
    compute_layout: wgpu::BindGroupLayout,
    raster_module: wgpu::ShaderModule,
    draw_layout: wgpu::BindGroupLayout,
    raster_layout: wgpu::PipelineLayout,
    pipelines: HashMap<PipelineKey, wgpu::RenderPipeline>,
    provoking_last: bool,
}

impl MeshPipelines {
    /// Compiles both shaders on `device`; `provoking_last` tells whether the backend's flat
    /// shading takes a primitive's last vertex ([`super::Renderer::provoking_vertex_is_last`]).
    #[must_use]
    pub fn new(device: &wgpu::Device, provoking_last: bool) -> Self {
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("eval_mesh.wgsl"),
            source: wgpu::ShaderSource::Wgsl(EVAL_MESH_WGSL.into()),
        });
        let compute_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("eval_mesh"),
            entries: &[
                storage(0, true),
                storage(1, true),
                storage(2, false),
                storage(3, false),
                uniform(4, wgpu::ShaderStages::COMPUTE, false),
            ],
        });
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("eval_mesh"),
            bind_group_layouts: &[Some(&compute_layout)],
            immediate_size: 0,
        });
        let compute = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some("eval_mesh"),
            layout: Some(&layout),
            module: &module,
            entry_point: Some("main"),
            compilation_options: Default::default(),
            cache: None,
        });
        let raster_module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("mesh_raster.wgsl"),
            source: wgpu::ShaderSource::Wgsl(MESH_RASTER_WGSL.into()),
        });
        let draw_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("mesh draw"),
            entries: &[uniform(0, wgpu::ShaderStages::VERTEX | wgpu::ShaderStages::FRAGMENT, true)],
        });
        let raster_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("mesh raster"),
            bind_group_layouts: &[Some(&draw_layout)],
            immediate_size: 0,
        });
        Self {
            compute,
            compute_layout,
            raster_module,
            draw_layout,
            raster_layout,
            pipelines: HashMap::new(),
            provoking_last,
        }
    }

    /// Records the evaluation of `packed` into `encoder` (one dispatch). The caller keeps the
    /// total within the device's storage-buffer limit (see [`MeshPipelines::fits`]).
    pub fn evaluate(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        encoder: &mut wgpu::CommandEncoder,
        packed: &PackedJobs,
    ) -> EvaluatedMeshes {
        let init = |label, contents: &[u8], usage| {
            device.create_buffer_init(&wgpu::util::BufferInitDescriptor { label: Some(label), contents, usage })
        };
        // wgpu rejects empty bindings: pad each input to at least 16 bytes.
        let padded = |v: &[f32]| {
            let mut v = v.to_vec();
            v.resize(v.len().max(4), 0.0);
            v
        };
        let jobs = if packed.jobs.is_empty() { vec![GpuMeshJob::default()] } else { packed.jobs.clone() };
        let jobs_buf = init("mesh jobs", bytemuck::cast_slice(&jobs), wgpu::BufferUsages::STORAGE);
        let data_buf = init("mesh data", bytemuck::cast_slice(&padded(&packed.data)), wgpu::BufferUsages::STORAGE);
        let meta = GpuMeshMeta {
            job_count: packed.jobs.len() as u32,
            total_points: packed.vertices,
            provoking_last: u32::from(packed.provoking_last),
            pad: 0,
        };
        let meta_buf = init("mesh meta", bytemuck::bytes_of(&meta), wgpu::BufferUsages::UNIFORM);
        let vertices = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("mesh vertices"),
            size: (u64::from(packed.vertices) * VERTEX_BYTES).max(VERTEX_BYTES),
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_SRC,
            mapped_at_creation: false,
        });
        let indices = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("mesh indices"),
            size: (u64::from(packed.indices) * 4).max(16),
            usage: wgpu::BufferUsages::STORAGE
                | wgpu::BufferUsages::INDEX
                | wgpu::BufferUsages::COPY_SRC
                | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        // Trimmed triangles come from the CPU triangulation; the shader writes the rest.
        for (first, values) in &packed.explicit {
            queue.write_buffer(&indices, u64::from(*first) * 4, bytemuck::cast_slice(values));
        }
        let bind = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("eval_mesh"),
            layout: &self.compute_layout,
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: jobs_buf.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 1, resource: data_buf.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 2, resource: vertices.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 3, resource: indices.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 4, resource: meta_buf.as_entire_binding() },
            ],
        });
        let groups = packed.vertices.div_ceil(WORKGROUP);
        if groups > 0 {
            let (x, y) = (groups.min(MAX_GROUPS_X), groups.div_ceil(MAX_GROUPS_X));
            let mut pass = encoder
                .begin_compute_pass(&wgpu::ComputePassDescriptor { label: Some("eval_mesh"), timestamp_writes: None });
            pass.set_pipeline(&self.compute);
            pass.set_bind_group(0, &bind, &[]);
            pass.dispatch_workgroups(x, y, 1);
        }
        EvaluatedMeshes { vertices, indices }
    }

    /// Whether `vertices` and `indices` fit one dispatch's storage bindings on `device`.
    #[must_use]
    pub fn fits(device: &wgpu::Device, vertices: u64, indices: u64) -> bool {
        let limit = device.limits().max_storage_buffer_binding_size;
        vertices * VERTEX_BYTES <= limit && indices * 4 <= limit
    }

    /// The render pipeline for a key, made on first use.
    fn pipeline(&mut self, device: &wgpu::Device, key: PipelineKey) -> &wgpu::RenderPipeline {
        let (module, layout) = (&self.raster_module, &self.raster_layout);
        self.pipelines.entry(key).or_insert_with(|| make_pipeline(device, module, layout, key))
    }
}

fn make_pipeline(
    device: &wgpu::Device,
    module: &wgpu::ShaderModule,
    layout: &wgpu::PipelineLayout,
    (topology, depth, format, cull, flat): PipelineKey,
) -> wgpu::RenderPipeline {
    let attributes = wgpu::vertex_attr_array![0 => Float32x4, 1 => Float32x4, 2 => Float32x4];
    let vertex_layout = wgpu::VertexBufferLayout {
        array_stride: VERTEX_BYTES,
        step_mode: wgpu::VertexStepMode::Vertex,
        attributes: &attributes,
    };
    let topology = match topology {
        Topology::Triangles => wgpu::PrimitiveTopology::TriangleList,
        Topology::Lines => wgpu::PrimitiveTopology::LineList,
        Topology::Points => wgpu::PrimitiveTopology::PointList,
    };
    let primitive = wgpu::PrimitiveState { topology, front_face: cull.0, cull_mode: cull.1, ..Default::default() };
    let depth_stencil = wgpu::DepthStencilState {
        format: super::gpu::DEPTH_FORMAT,
        depth_write_enabled: Some(depth.is_some()),
        depth_compare: Some(depth.map_or(wgpu::CompareFunction::Always, super::gpu::compare)),
        stencil: wgpu::StencilState::default(),
        bias: wgpu::DepthBiasState::default(),
    };
    let (vs, fs) = if flat { ("vs_flat", "fs_flat") } else { ("vs_smooth", "fs_smooth") };
    device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some("gl mesh raster"),
        layout: Some(layout),
        vertex: wgpu::VertexState {
            module,
            entry_point: Some(vs),
            compilation_options: Default::default(),
            buffers: &[Some(vertex_layout)],
        },
        primitive,
        depth_stencil: Some(depth_stencil),
        multisample: wgpu::MultisampleState::default(),
        fragment: Some(wgpu::FragmentState {
            module,
            entry_point: Some(fs),
            compilation_options: Default::default(),
            targets: &[Some(wgpu::ColorTargetState { format, blend: None, write_mask: wgpu::ColorWrites::ALL })],
        }),
        multiview_mask: None,
        cache: None,
    })
}

fn light_uniform(l: &Light) -> GpuLight {
    let spot = l.spot_cutoff != 180.0;
    GpuLight {
        ambient: l.ambient.to_array(),
        diffuse: l.diffuse.to_array(),
        specular: l.specular.to_array(),
        position: l.position.to_array(),
        spot_direction: l.spot_direction.extend(l.spot_exponent).to_array(),
        params: [f32::from(u8::from(l.enabled)), f32::from(u8::from(spot)), l.spot_cutoff.to_radians().cos(), 0.0],
        attenuation: l.attenuation.extend(0.0).to_array(),
    }
}

fn material_uniform(m: &Material) -> GpuMaterial {
    GpuMaterial {
        ambient: m.ambient.to_array(),
        diffuse: m.diffuse.to_array(),
        specular: m.specular.to_array(),
        emission: m.emission.to_array(),
        shininess: [m.shininess, 0.0, 0.0, 0.0],
    }
}

fn flag(b: bool) -> f32 {
    f32::from(u8::from(b))
}

/// The draw uniform of a mesh drawn with `state` into a `width` × `height` target.
#[must_use]
pub fn draw_uniform(state: &DrawState, polygon: bool, (width, height): (u32, u32)) -> GpuDraw {
    let normal_matrix = Mat4::from_mat3(Mat3::from_mat4(state.modelview).inverse().transpose());
    let [vx, vy, vw, vh] = state.viewport.map(|c| c as f32);
    let (fw, fh) = (width as f32, height as f32);
    let viewport = [vw / fw, (2.0 * vx + vw) / fw - 1.0, vh / fh, (2.0 * vy + vh) / fh - 1.0];
    let mut draw = GpuDraw {
        modelview: state.modelview.to_cols_array_2d(),
        projection: state.projection.to_cols_array_2d(),
        normal_matrix: normal_matrix.to_cols_array_2d(),
        viewport,
        depth_range: [state.depth_range[0], state.depth_range[1], 0.0, 0.0],
        primitive: [flag(polygon), 0.0, 0.0, 0.0],
        ..GpuDraw::default()
    };
    if let Some(l) = &state.lighting {
        draw.flags = [1.0, flag(l.two_side), flag(l.local_viewer), flag(state.normalize || state.rescale_normal)];
        let (face, mode) = l.color_material;
        let on = |f: GLenum| flag(state.color_material && (face == f || face == GL_FRONT_AND_BACK));
        let mode = match mode {
            GL_AMBIENT => 0.0,
            GL_DIFFUSE => 1.0,
            GL_SPECULAR => 2.0,
            GL_EMISSION => 3.0,
            _ => 4.0,
        };
        draw.color_material = [on(GL_FRONT), on(GL_BACK), mode, 0.0];
        draw.model_ambient = l.model_ambient.to_array();
        draw.materials = [material_uniform(&l.materials[0]), material_uniform(&l.materials[1])];
        draw.lights = std::array::from_fn(|i| light_uniform(&l.lights[i]));
    }
    draw
}

/// How one deferred mesh is drawn from the evaluated buffers.
#[derive(Clone, Copy, Debug)]
pub(crate) struct MeshDraw {
    topology: Topology,
    first_vertex: u32,
    vertex_count: u32,
    first_index: u32,
    index_count: u32,
    uniform_offset: u32,
    state: usize,
}

/// A frame's deferred meshes, evaluated and ready to draw.
pub(crate) struct PreparedMeshes {
    buffers: EvaluatedMeshes,
    uniforms: wgpu::Buffer,
    bind: wgpu::BindGroup,
    draws: HashMap<usize, MeshDraw>,
}

fn topology_of(mode: MeshMode) -> Topology {
    match mode {
        MeshMode::Points => Topology::Points,
        MeshMode::CurveLines | MeshMode::SurfaceLines => Topology::Lines,
        MeshMode::Fill | MeshMode::Triangles => Topology::Triangles,
    }
}

/// The deferred meshes of `frame` the GPU path can take in one dispatch on `device`, in
/// program order; the others are left to the CPU assembler.
pub(crate) fn gpu_mesh_indices(device: &wgpu::Device, frame: &Frame) -> Vec<usize> {
    let (mut vertices, mut indices) = (0u64, 0u64);
    let mut out = Vec::new();
    for (i, mesh) in frame.meshes.iter().enumerate() {
        if !matches!(mesh.vertices, MeshVertices::Deferred(_)) {
            continue;
        }
        let n = index_count(mesh.mode, mesh.nu, mesh.nv) + mesh.triangles.len();
        let (v, n) = (mesh.nu as u64 * mesh.nv as u64, n as u64);
        if MeshPipelines::fits(device, vertices + v, indices + n) {
            vertices += v;
            indices += n;
            out.push(i);
        }
    }
    out
}

impl MeshPipelines {
    /// Evaluates the meshes `which` of `frame` (one dispatch) and prepares their draw uniforms.
    pub(crate) fn prepare(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        encoder: &mut wgpu::CommandEncoder,
        frame: &Frame,
        which: &[usize],
        size: (u32, u32),
    ) -> PreparedMeshes {
        let align = device.limits().min_uniform_buffer_offset_alignment.max(1);
        let stride = (std::mem::size_of::<GpuDraw>() as u32).div_ceil(align) * align;
        let mut packed = PackedJobs::new(self.provoking_last);
        let mut uniforms: Vec<u8> = Vec::new();
        let mut draws = HashMap::new();
        for &i in which {
            let mesh: &GridMesh = &frame.meshes[i];
            let Some(state) = frame.states.get(mesh.state) else { continue };
            let (first_vertex, first_index) = (packed.vertices, packed.indices);
            if packed.push_mesh(mesh).is_none() {
                continue;
            }
            let uniform_offset = uniforms.len() as u32;
            let draw = draw_uniform(state, matches!(mesh.mode, MeshMode::Fill | MeshMode::Triangles), size);
            uniforms.extend_from_slice(bytemuck::bytes_of(&draw));
            uniforms.resize((uniform_offset + stride) as usize, 0);
            draws.insert(
                i,
                MeshDraw {
                    topology: topology_of(mesh.mode),
                    first_vertex,
                    vertex_count: packed.vertices - first_vertex,
                    first_index,
                    index_count: packed.indices - first_index,
                    uniform_offset,
                    state: mesh.state,
                },
            );
        }
        uniforms.resize(uniforms.len().max(stride as usize), 0);
        let buffers = self.evaluate(device, queue, encoder, &packed);
        let uniforms = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("mesh draws"),
            contents: &uniforms,
            usage: wgpu::BufferUsages::UNIFORM,
        });
        let bind = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("mesh draw"),
            layout: &self.draw_layout,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                    buffer: &uniforms,
                    offset: 0,
                    size: wgpu::BufferSize::new(std::mem::size_of::<GpuDraw>() as u64),
                }),
            }],
        });
        PreparedMeshes { buffers, uniforms, bind, draws }
    }

    /// Makes sure the pipelines the prepared meshes need exist (before the render pass borrows).
    pub(crate) fn ensure_pipelines(
        &mut self,
        device: &wgpu::Device,
        frame: &Frame,
        prepared: &PreparedMeshes,
        format: wgpu::TextureFormat,
    ) {
        for draw in prepared.draws.values() {
            if let Some(key) = pipeline_key(draw, &frame.states[draw.state], format) {
                self.pipeline(device, key);
            }
        }
    }

    /// Draws mesh `index` of the frame inside a render pass.
    pub(crate) fn draw(
        &self,
        rp: &mut wgpu::RenderPass<'_>,
        frame: &Frame,
        prepared: &PreparedMeshes,
        index: usize,
        format: wgpu::TextureFormat,
    ) {
        let Some(draw) = prepared.draws.get(&index) else { return };
        let state = &frame.states[draw.state];
        let Some(key) = pipeline_key(draw, state, format) else { return };
        let Some(pipeline) = self.pipelines.get(&key) else { return };
        rp.set_pipeline(pipeline);
        rp.set_bind_group(0, &prepared.bind, &[draw.uniform_offset]);
        rp.set_vertex_buffer(0, prepared.buffers.vertices.slice(..));
        if draw.topology == Topology::Points {
            rp.draw(draw.first_vertex..draw.first_vertex + draw.vertex_count, 0..1);
        } else {
            rp.set_index_buffer(prepared.buffers.indices.slice(..), wgpu::IndexFormat::Uint32);
            rp.draw_indexed(draw.first_index..draw.first_index + draw.index_count, 0, 0..1);
        }
        let _ = &prepared.uniforms;
    }
}

/// The pipeline a mesh draws with, or `None` when GL draws nothing (both faces culled). The
/// front face is always GL's: two-sided lighting reads the facing even without culling.
fn pipeline_key(draw: &MeshDraw, state: &DrawState, format: wgpu::TextureFormat) -> Option<PipelineKey> {
    let front = if state.front_face == GL_CW { wgpu::FrontFace::Cw } else { wgpu::FrontFace::Ccw };
    let cull = match (draw.topology, state.cull_face) {
        (Topology::Triangles, Some(GL_FRONT_AND_BACK)) => return None,
        (Topology::Triangles, Some(GL_FRONT)) => Some(wgpu::Face::Front),
        (Topology::Triangles, Some(_)) => Some(wgpu::Face::Back),
        _ => None,
    };
    Some((draw.topology, state.depth_test, format, (front, cull), state.shade_model == GL_FLAT))
}

/// The scissor viewport of a prepared mesh.
pub(crate) fn mesh_viewport(frame: &Frame, prepared: &PreparedMeshes, index: usize) -> Option<[i32; 4]> {
    prepared.draws.get(&index).map(|d| frame.states[d.state].viewport)
}

/// The evaluated vertices of `jobs` read back from the GPU (the parity tests' entry point):
/// per vertex position, normal (w 0), colour and texture coordinate.
pub fn evaluate_jobs(
    renderer: &super::Renderer,
    jobs: &[(MeshJob, MeshMode)],
) -> Result<Vec<[[f32; 4]; 4]>, super::RenderError> {
    let mut packed = PackedJobs::new(renderer.provoking_vertex_is_last());
    for (job, mode) in jobs {
        packed.push(job, *mode).ok_or_else(|| super::RenderError::Gpu("malformed mesh job".into()))?;
    }
    let device = &renderer.device;
    if !MeshPipelines::fits(device, packed.vertices.into(), packed.indices.into()) {
        return Err(super::RenderError::Gpu("batch exceeds the storage buffer limit".into()));
    }
    let pipelines = MeshPipelines::new(device, renderer.provoking_vertex_is_last());
    let mut encoder = device.create_command_encoder(&Default::default());
    let out = pipelines.evaluate(device, &renderer.queue, &mut encoder, &packed);
    let bytes = u64::from(packed.vertices) * VERTEX_BYTES;
    let data = super::gpu::read_buffer(renderer, encoder, &out.vertices, bytes)?;
    Ok(bytemuck::cast_slice::<u8, [[f32; 4]; 4]>(&data).to_vec())
}

/// The indices of `jobs` read back (to check the primitive order against GL's).
pub fn evaluate_job_indices(
    renderer: &super::Renderer,
    jobs: &[(MeshJob, MeshMode)],
) -> Result<Vec<u32>, super::RenderError> {
    let mut packed = PackedJobs::new(renderer.provoking_vertex_is_last());
    for (job, mode) in jobs {
        packed.push(job, *mode).ok_or_else(|| super::RenderError::Gpu("malformed mesh job".into()))?;
    }
    let device = &renderer.device;
    let pipelines = MeshPipelines::new(device, renderer.provoking_vertex_is_last());
    let mut encoder = device.create_command_encoder(&Default::default());
    let out = pipelines.evaluate(device, &renderer.queue, &mut encoder, &packed);
    let data = super::gpu::read_buffer(renderer, encoder, &out.indices, u64::from(packed.indices) * 4)?;
    Ok(bytemuck::cast_slice::<u8, u32>(&data).to_vec())
}

/// The typed API on the GPU tessellator: each patch over a uniform `segments_u` × `segments_v`
/// grid of its unit domain, all patches in one dispatch, read back as one [`Mesh`] with the
/// layout of [`BezierPatch::tessellate`] (the CPU back end): positions divided by w, unit
/// normals (zero where degenerate), (u, v) texture coordinates, counter-clockwise triangles.
pub fn tessellate_patches(
    renderer: &super::Renderer,
    patches: &[BezierPatch<f64>],
    segments_u: usize,
    segments_v: usize,
) -> Result<Mesh, super::RenderError> {
    let bad = |why: String| super::RenderError::Gpu(why);
    if segments_u == 0 || segments_v == 0 {
        return Err(bad(MeshError::EmptyGrid.to_string()));
    }
    let (nu, nv) = (segments_u + 1, segments_v + 1);
    let us: Vec<f32> = (0..nu).map(|i| (i as f64 / segments_u as f64) as f32).collect();
    let vs: Vec<f32> = (0..nv).map(|j| (j as f64 / segments_v as f64) as f32).collect();
    let mut jobs = Vec::with_capacity(patches.len());
    for patch in patches {
        let slot = match patch.dim {
            3 => Slot::Vertex3,
            4 => Slot::Vertex4,
            d => return Err(bad(format!("a surface needs 3 or 4 components per point, not {d}"))),
        };
        let map = MapSample {
            slot,
            uorder: patch.uorder,
            vorder: patch.vorder,
            points: patch.points.iter().map(|&c| c as f32).collect(),
            us: us.clone(),
            vs: vs.clone(),
        };
        let job = MeshJob {
            maps: vec![map],
            auto_normal: true,
            template: crate::gl::Vertex::default(),
            nu,
            nv,
            scattered: false,
        };
        jobs.push((job, MeshMode::Fill));
    }
    let vertices = evaluate_jobs(renderer, &jobs)?;
    let indices = evaluate_job_indices(renderer, &jobs)?;
    let mut mesh = Mesh {
        positions: Vec::with_capacity(vertices.len()),
        normals: Vec::with_capacity(vertices.len()),
        tex_coords: Vec::with_capacity(vertices.len()),
        indices: Vec::with_capacity(indices.len()),
    };
    for (k, [p, n, _, _]) in vertices.iter().enumerate() {
        let local = k % (nu * nv);
        mesh.positions.push([p[0] / p[3], p[1] / p[3], p[2] / p[3]]);
        mesh.normals.push([n[0], n[1], n[2]]);
        mesh.tex_coords.push([us[local % nu], vs[local / nu]]);
    }
    // GL's strips run clockwise in (u, v) (their faces point against du × dv): reverse them.
    mesh.indices.extend(indices.chunks_exact(3).flat_map(|t| [t[0], t[2], t[1]]));
    Ok(mesh)
}
