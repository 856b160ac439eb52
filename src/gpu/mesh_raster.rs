//! The mesh rasteriser: every deferred `glEvalMesh` grid of a frame
//! ([`MeshVertices::Deferred`]) is evaluated by one dispatch of the evaluator into a vertex and
//! an index buffer, which the render pass draws with GL's vertex stage in WGSL
//! (`shaders/mesh_raster.wgsl`). Nothing comes back to the CPU.
//!
//! What is bound by what: the CPU packs each mesh's control points and normalised parameters
//! (a few hundred bytes per patch) and computes the prefix sums of vertex and index counts,
//! which are known from the grid sizes alone; the GPU does all per-point work.

use super::device::{shader_module, uniform};
use super::draw_uniform::draw_uniform;
use super::evaluate::{EvaluatedMeshes, Evaluator};
use super::layout::{GpuDraw, MESH_RASTER_WGSL, VERTEX_BYTES};
use super::pack::{index_count, PackedJobs};
use super::raster::{PipelineTests, RasterPipeline};
use crate::gl::consts::*;
use crate::gl::types::GLenum;
use crate::gl::{DrawState, Frame, MeshMode, MeshVertices};
use crate::render::assemble::Topology;
use std::collections::HashMap;
use wgpu::util::DeviceExt;

/// Pipeline key: topology, depth function, target format, culling (front face, culled face),
/// flat shading, blend factors.
type PipelineKey = (
    Topology,
    Option<GLenum>,
    wgpu::TextureFormat,
    (wgpu::FrontFace, Option<wgpu::Face>),
    bool,
    Option<wgpu::BlendState>,
    PipelineTests,
);

/// The evaluator and the render pipelines that draw what it writes.
pub(crate) struct MeshRaster {
    evaluator: Evaluator,
    module: wgpu::ShaderModule,
    draw_layout: wgpu::BindGroupLayout,
    layout: wgpu::PipelineLayout,
    pipelines: HashMap<PipelineKey, wgpu::RenderPipeline>,
    provoking_last: bool,
}

/// How one deferred mesh is drawn from the evaluated buffers.
#[derive(Clone, Copy, Debug)]
struct MeshDraw {
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
    /// Kept alive while the bind group refers to it.
    _uniforms: wgpu::Buffer,
    bind: wgpu::BindGroup,
    draws: HashMap<usize, MeshDraw>,
    /// Drawn upside down (the renderer's headless frames): windings swap.
    flip: bool,
}

impl PreparedMeshes {
    /// The draw state of mesh `index` (the renderer scissors to its viewport and scissor box).
    pub(crate) fn state<'f>(&self, frame: &'f Frame, index: usize) -> Option<&'f DrawState> {
        self.draws.get(&index).and_then(|d| frame.states.get(d.state))
    }
}

/// The packed jobs of a frame's meshes, their draw uniforms (one `stride` apart) and draws.
struct Packed {
    jobs: PackedJobs,
    uniforms: Vec<u8>,
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
        if Evaluator::fits(device, vertices + v, indices + n) {
            vertices += v;
            indices += n;
            out.push(i);
        }
    }
    out
}

impl MeshRaster {
    /// Compiles the evaluator and the mesh rasteriser on `device`; `provoking_last` tells
    /// whether the backend's flat shading takes a primitive's last vertex.
    /// `texture_layout` is the frame rasteriser's: meshes are textured with its bind groups.
    pub(crate) fn new(device: &wgpu::Device, texture_layout: &wgpu::BindGroupLayout, provoking_last: bool) -> Self {
        let evaluator = Evaluator::new(device);
        let module = shader_module(device, "mesh_raster.wgsl", MESH_RASTER_WGSL);
        let draw_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("mesh draw"),
            entries: &[uniform(0, wgpu::ShaderStages::VERTEX | wgpu::ShaderStages::FRAGMENT, true)],
        });
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("mesh raster"),
            bind_group_layouts: &[Some(&draw_layout), Some(texture_layout)],
            immediate_size: 0,
        });
        Self { evaluator, module, draw_layout, layout, pipelines: HashMap::new(), provoking_last }
    }

    /// Evaluates the meshes `which` of `frame` (one dispatch) and prepares their draw uniforms.
    pub(crate) fn prepare(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        encoder: &mut wgpu::CommandEncoder,
        frame: &Frame,
        which: &[usize],
        (size, flip): ((u32, u32), bool),
    ) -> PreparedMeshes {
        let align = device.limits().min_uniform_buffer_offset_alignment.max(1);
        let stride = (std::mem::size_of::<GpuDraw>() as u32).div_ceil(align) * align;
        let mut packed = self.pack(frame, which, (size, flip), stride);
        packed.uniforms.resize(packed.uniforms.len().max(stride as usize), 0);
        let buffers = self.evaluator.evaluate(device, queue, encoder, &packed.jobs);
        let uniforms = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("mesh draws"),
            contents: &packed.uniforms,
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
        PreparedMeshes { buffers, _uniforms: uniforms, bind, draws: packed.draws, flip }
    }

    /// Packs the meshes `which` of `frame` and their draw uniforms; a mesh whose state is
    /// missing or whose jobs do not pack is left out.
    fn pack(&self, frame: &Frame, which: &[usize], (size, flip): ((u32, u32), bool), stride: u32) -> Packed {
        let mut out =
            Packed { jobs: PackedJobs::new(self.provoking_last), uniforms: Vec::new(), draws: HashMap::new() };
        for &i in which {
            let mesh = &frame.meshes[i];
            let Some(state) = frame.states.get(mesh.state) else { continue };
            let (first_vertex, first_index) = (out.jobs.vertices, out.jobs.indices);
            if out.jobs.push_mesh(mesh).is_none() {
                continue;
            }
            let uniform_offset = out.uniforms.len() as u32;
            let polygon = matches!(mesh.mode, MeshMode::Fill | MeshMode::Triangles);
            let draw = draw_uniform(state, (polygon, &mesh.template()), size, flip);
            out.uniforms.extend_from_slice(bytemuck::bytes_of(&draw));
            out.uniforms.resize((uniform_offset + stride) as usize, 0);
            let draw = MeshDraw {
                topology: topology_of(mesh.mode),
                first_vertex,
                vertex_count: out.jobs.vertices - first_vertex,
                first_index,
                index_count: out.jobs.indices - first_index,
                uniform_offset,
                state: mesh.state,
            };
            out.draws.insert(i, draw);
        }
        out
    }

    /// Makes sure the pipelines the prepared meshes need exist (before the render pass borrows).
    pub(crate) fn ensure_pipelines(
        &mut self,
        device: &wgpu::Device,
        frame: &Frame,
        prepared: &PreparedMeshes,
        format: wgpu::TextureFormat,
    ) {
        let keys = prepared
            .draws
            .values()
            .filter_map(|draw| pipeline_key(draw, &frame.states[draw.state], format, prepared.flip));
        let (module, layout) = (&self.module, &self.layout);
        super::raster::make_missing(&mut self.pipelines, keys, |key| make_pipeline(device, module, layout, key));
    }

    /// Draws mesh `index` of the frame inside a render pass, with the bind group of its
    /// texture, fog and alpha test.
    pub(crate) fn draw(
        &self,
        rp: &mut wgpu::RenderPass<'_>,
        frame: &Frame,
        prepared: &PreparedMeshes,
        (index, fragment): (usize, &wgpu::BindGroup),
        format: wgpu::TextureFormat,
    ) {
        let Some(draw) = prepared.draws.get(&index) else { return };
        let state = &frame.states[draw.state];
        let Some(key) = pipeline_key(draw, state, format, prepared.flip) else { return };
        let Some(pipeline) = self.pipelines.get(&key) else { return };
        rp.set_pipeline(pipeline);
        rp.set_bind_group(0, &prepared.bind, &[draw.uniform_offset]);
        rp.set_bind_group(1, fragment, &[]);
        rp.set_vertex_buffer(0, prepared.buffers.vertices.slice(..));
        if draw.topology == Topology::Points {
            rp.draw(draw.first_vertex..draw.first_vertex + draw.vertex_count, 0..1);
        } else {
            rp.set_index_buffer(prepared.buffers.indices.slice(..), wgpu::IndexFormat::Uint32);
            rp.draw_indexed(draw.first_index..draw.first_index + draw.index_count, 0, 0..1);
        }
    }
}

/// The pipeline a mesh draws with, or `None` when GL draws nothing (both faces culled). The
/// front face is always GL's (the other winding in a target drawn upside down): two-sided
/// lighting reads the facing even without culling.
fn pipeline_key(draw: &MeshDraw, state: &DrawState, format: wgpu::TextureFormat, flip: bool) -> Option<PipelineKey> {
    let front = if (state.front_face == GL_CW) != flip { wgpu::FrontFace::Cw } else { wgpu::FrontFace::Ccw };
    let cull = match (draw.topology, state.cull_face) {
        (Topology::Triangles, Some(GL_FRONT_AND_BACK)) => return None,
        (Topology::Triangles, Some(GL_FRONT)) => Some(wgpu::Face::Front),
        (Topology::Triangles, Some(_)) => Some(wgpu::Face::Back),
        _ => None,
    };
    let tests = PipelineTests::of(&state.fragment_tests);
    let blend = state.blend.as_ref().and_then(super::blend::wgpu_blend).map(|(state, _)| state);
    Some((draw.topology, state.depth_test, format, (front, cull), state.shade_model == GL_FLAT, blend, tests))
}

fn make_pipeline(
    device: &wgpu::Device,
    module: &wgpu::ShaderModule,
    layout: &wgpu::PipelineLayout,
    (topology, depth, format, faces, flat, blend, tests): PipelineKey,
) -> wgpu::RenderPipeline {
    let attributes = wgpu::vertex_attr_array![0 => Float32x4, 1 => Float32x4, 2 => Float32x4, 3 => Float32x4];
    let vertex = wgpu::VertexBufferLayout {
        array_stride: VERTEX_BYTES,
        step_mode: wgpu::VertexStepMode::Vertex,
        attributes: &attributes,
    };
    let entry_points = if flat { ("vs_flat", "fs_flat") } else { ("vs_smooth", "fs_smooth") };
    RasterPipeline {
        label: "gl mesh raster",
        module,
        entry_points,
        layout,
        vertex,
        topology,
        depth,
        faces,
        format,
        blend,
        tests,
    }
    .build(device)
}
