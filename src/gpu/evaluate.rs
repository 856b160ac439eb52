//! The GPU evaluator: every packed job of a dispatch ([`PackedJobs`]) evaluated by one compute
//! dispatch of `shaders/eval_mesh.wgsl`, one invocation per grid point, into a vertex buffer
//! (position, normal, colour, texture coordinate) and an index buffer of GL's primitives. The
//! renderer draws those buffers where they are; the read-backs below serve the typed API
//! ([`tessellate_patches`]) and the parity tests, whose oracle is the f64 CPU evaluation.

use super::device::{shader_module, storage, uniform, Gpu, RenderError};
use super::layout::{GpuMeshJob, GpuMeshMeta, EVAL_MESH_WGSL, VERTEX_BYTES};
use super::pack::PackedJobs;
use crate::gl::{MapSample, MeshJob, MeshMode, Slot, Vertex};
use crate::math::BezierPatch;
use crate::tess::{Mesh, MeshError};
use wgpu::util::DeviceExt;

/// Invocations per workgroup (`@workgroup_size` of `eval_mesh.wgsl`).
const WORKGROUP: u32 = 64;
/// wgpu's default `max_compute_workgroups_per_dimension`: larger dispatches spill into y.
const MAX_GROUPS_X: u32 = 65_535;

/// The evaluated buffers of one dispatch.
pub struct EvaluatedMeshes {
    /// `vertices` × 64 bytes: position, normal, colour, texture coordinate (vec4 each).
    pub(crate) vertices: wgpu::Buffer,
    /// u32 indices (at least 16 bytes even when empty).
    pub(crate) indices: wgpu::Buffer,
}

/// The evaluator's compute pipeline.
pub struct Evaluator {
    compute: wgpu::ComputePipeline,
    compute_layout: wgpu::BindGroupLayout,
}

impl Evaluator {
    /// Compiles `shaders/eval_mesh.wgsl` on `device`.
    #[must_use]
    pub fn new(device: &wgpu::Device) -> Self {
        let module = shader_module(device, "eval_mesh.wgsl", EVAL_MESH_WGSL);
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
        Self { compute, compute_layout }
    }

    /// Whether `vertices` and `indices` fit one dispatch's storage bindings on `device`.
    #[must_use]
    pub fn fits(device: &wgpu::Device, vertices: u64, indices: u64) -> bool {
        let limit = device.limits().max_storage_buffer_binding_size;
        vertices * VERTEX_BYTES <= limit && indices * 4 <= limit
    }

    /// Records the evaluation of `packed` into `encoder` (one dispatch). The caller keeps the
    /// total within the device's storage-buffer limit (see [`Evaluator::fits`]).
    pub fn evaluate(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        encoder: &mut wgpu::CommandEncoder,
        packed: &PackedJobs,
    ) -> EvaluatedMeshes {
        self.evaluate_timed(device, queue, encoder, packed, None)
    }

    /// [`Evaluator::evaluate`] with the compute pass's timestamps written where `timestamps`
    /// says (see [`super::PassTimer`]).
    pub fn evaluate_timed(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        encoder: &mut wgpu::CommandEncoder,
        packed: &PackedJobs,
        timestamps: Option<wgpu::ComputePassTimestampWrites<'_>>,
    ) -> EvaluatedMeshes {
        let [jobs, data, meta] = input_buffers(device, packed);
        let out = output_buffers(device, queue, packed);
        let bind = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("eval_mesh"),
            layout: &self.compute_layout,
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: jobs.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 1, resource: data.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 2, resource: out.vertices.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 3, resource: out.indices.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 4, resource: meta.as_entire_binding() },
            ],
        });
        let groups = packed.vertices.div_ceil(WORKGROUP);
        if groups > 0 {
            let (x, y) = (groups.min(MAX_GROUPS_X), groups.div_ceil(MAX_GROUPS_X));
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                label: Some("eval_mesh"),
                timestamp_writes: timestamps,
            });
            pass.set_pipeline(&self.compute);
            pass.set_bind_group(0, &bind, &[]);
            pass.dispatch_workgroups(x, y, 1);
        }
        out
    }
}

/// The shader's inputs: jobs, control points and tables, dispatch constants.
fn input_buffers(device: &wgpu::Device, packed: &PackedJobs) -> [wgpu::Buffer; 3] {
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
    [jobs_buf, data_buf, meta_buf]
}

/// The vertex and index buffers the shader writes, with the CPU's explicit indices in place.
fn output_buffers(device: &wgpu::Device, queue: &wgpu::Queue, packed: &PackedJobs) -> EvaluatedMeshes {
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
    EvaluatedMeshes { vertices, indices }
}

/// `jobs` packed for `gpu`'s backend, or why they cannot be.
fn pack(gpu: Gpu<'_>, jobs: &[(MeshJob, MeshMode)]) -> Result<PackedJobs, RenderError> {
    let mut packed = PackedJobs::new(gpu.provoking_last);
    for (job, mode) in jobs {
        packed.push(job, *mode).ok_or_else(|| RenderError::Gpu("malformed mesh job".into()))?;
    }
    Ok(packed)
}

/// An encoder holding the evaluation of `packed`, and the buffers it writes.
fn dispatch(gpu: Gpu<'_>, packed: &PackedJobs) -> (wgpu::CommandEncoder, EvaluatedMeshes) {
    let evaluator = Evaluator::new(gpu.device);
    let mut encoder = gpu.device.create_command_encoder(&Default::default());
    let out = evaluator.evaluate(gpu.device, gpu.queue, &mut encoder, packed);
    (encoder, out)
}

/// The evaluated vertices of `jobs` read back from the GPU (the parity tests' entry point):
/// per vertex position, normal (w 0), colour and texture coordinate.
pub fn evaluate_jobs(gpu: Gpu<'_>, jobs: &[(MeshJob, MeshMode)]) -> Result<Vec<[[f32; 4]; 4]>, RenderError> {
    let packed = pack(gpu, jobs)?;
    if !Evaluator::fits(gpu.device, packed.vertices.into(), packed.indices.into()) {
        return Err(RenderError::Gpu("batch exceeds the storage buffer limit".into()));
    }
    let (encoder, out) = dispatch(gpu, &packed);
    let data = gpu.read_buffer(encoder, &out.vertices, u64::from(packed.vertices) * VERTEX_BYTES)?;
    Ok(bytemuck::cast_slice::<u8, [[f32; 4]; 4]>(&data).to_vec())
}

/// The indices of `jobs` read back (to check the primitive order against GL's).
pub fn evaluate_job_indices(gpu: Gpu<'_>, jobs: &[(MeshJob, MeshMode)]) -> Result<Vec<u32>, RenderError> {
    let packed = pack(gpu, jobs)?;
    let (encoder, out) = dispatch(gpu, &packed);
    let data = gpu.read_buffer(encoder, &out.indices, u64::from(packed.indices) * 4)?;
    Ok(bytemuck::cast_slice::<u8, u32>(&data).to_vec())
}

/// The typed API on the GPU evaluator: each patch over a uniform `segments_u` × `segments_v`
/// grid of its unit domain, all patches in one dispatch, read back as one [`Mesh`] with the
/// layout of [`BezierPatch::tessellate`] (the CPU back end): positions divided by w, unit
/// normals (zero where degenerate), (u, v) texture coordinates, counter-clockwise triangles.
pub(crate) fn tessellate_patches(
    gpu: Gpu<'_>,
    patches: &[BezierPatch<f64>],
    segments_u: usize,
    segments_v: usize,
) -> Result<Mesh, RenderError> {
    if segments_u == 0 || segments_v == 0 {
        return Err(RenderError::Gpu(MeshError::EmptyGrid.to_string()));
    }
    let us: Vec<f32> = (0..=segments_u).map(|i| (i as f64 / segments_u as f64) as f32).collect();
    let vs: Vec<f32> = (0..=segments_v).map(|j| (j as f64 / segments_v as f64) as f32).collect();
    let jobs = patches.iter().map(|patch| patch_job(patch, &us, &vs)).collect::<Result<Vec<_>, _>>()?;
    let vertices = evaluate_jobs(gpu, &jobs)?;
    let indices = evaluate_job_indices(gpu, &jobs)?;
    Ok(to_mesh(&vertices, &indices, &us, &vs))
}

/// A patch as a `glEvalMesh2(GL_FILL)` job over the grid `us` × `vs`, with `GL_AUTO_NORMAL`.
fn patch_job(patch: &BezierPatch<f64>, us: &[f32], vs: &[f32]) -> Result<(MeshJob, MeshMode), RenderError> {
    let slot = match patch.dim {
        3 => Slot::Vertex3,
        4 => Slot::Vertex4,
        d => return Err(RenderError::Gpu(format!("a surface needs 3 or 4 components per point, not {d}"))),
    };
    let map = MapSample {
        slot,
        uorder: patch.uorder,
        vorder: patch.vorder,
        points: patch.points.iter().map(|&c| c as f32).collect(),
        us: us.to_vec(),
        vs: vs.to_vec(),
    };
    let (nu, nv) = (us.len(), vs.len());
    let job = MeshJob { maps: vec![map], auto_normal: true, template: Vertex::default(), nu, nv, scattered: false };
    Ok((job, MeshMode::Fill))
}

/// The evaluated vertices and GL's triangles as a [`Mesh`] like the CPU back end's.
fn to_mesh(vertices: &[[[f32; 4]; 4]], indices: &[u32], us: &[f32], vs: &[f32]) -> Mesh {
    let (nu, nv) = (us.len(), vs.len());
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
    mesh
}
