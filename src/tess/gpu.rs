//! The WGSL compute back end of the grid evaluator (`shaders/eval_grid.wgsl`): many Bezier
//! patches over their grids in one dispatch, one invocation per grid point, writing positions
//! and unit normals to a storage buffer. It takes the same packed patches as the CPU path
//! (`tess::grid`), so the CPU (f64) evaluation is the oracle in the parity tests.

use super::grid::MapView;
use wgpu::util::DeviceExt;

/// The compute shader source.
pub const EVAL_GRID_WGSL: &str = include_str!("../../shaders/eval_grid.wgsl");

const WORKGROUP: u32 = 64;
const MAX_GROUPS_X: u32 = 65_535;

/// One patch's job, as the shader reads it (`struct Job`).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct GpuJob {
    /// Components per control point (1..=4).
    pub dim: u32,
    /// Order along u.
    pub uorder: u32,
    /// Order along v.
    pub vorder: u32,
    /// First float of the patch's control points.
    pub point_offset: u32,
    /// Grid points along u.
    pub nu: u32,
    /// Grid points along v.
    pub nv: u32,
    /// First float of the job's parameters (nu u values, then nv v values).
    pub param_offset: u32,
    /// First output grid point of the job (prefix sum of nu·nv).
    pub out_offset: u32,
}

/// The dispatch-wide constants (`struct Meta`).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct GpuMeta {
    /// Number of jobs.
    pub job_count: u32,
    /// Grid points over all jobs.
    pub total_points: u32,
    /// 1 to compute normals.
    pub want_normals: u32,
    /// Padding to 16 bytes.
    pub pad: u32,
}

/// A patch and the normalised parameters of its grid (u inner, v outer in the output).
#[derive(Clone, Copy, Debug)]
pub struct PatchGrid<'a> {
    /// The packed patch.
    pub map: MapView<'a, f32>,
    /// u parameters, normalised to the patch.
    pub us: &'a [f32],
    /// v parameters.
    pub vs: &'a [f32],
}

/// The GPU's output: per grid point a position (4 components) and a unit normal.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct GpuGrid {
    /// Positions, job after job, v outer and u inner.
    pub points: Vec<[f32; 4]>,
    /// Normals (zero when not asked for, or where du × dv vanishes).
    pub normals: Vec<[f32; 3]>,
}

/// A batch packed for the shader: jobs, control points, parameters, total grid points.
type Packed = (Vec<GpuJob>, Vec<f32>, Vec<f32>, u32);

/// The jobs and packed buffers for a batch of patches.
fn pack(grids: &[PatchGrid<'_>]) -> Result<Packed, String> {
    let (mut jobs, mut points, mut params, mut total) = (Vec::new(), Vec::new(), Vec::new(), 0u64);
    for g in grids {
        let m = &g.map;
        let size = m.uorder * m.vorder * m.dim;
        let ok = (1..=4).contains(&m.dim) && (1..=30).contains(&m.uorder) && (1..=30).contains(&m.vorder);
        if !ok || m.points.len() < size || g.us.is_empty() || g.vs.is_empty() {
            return Err(format!("invalid patch job: dim {} orders {}x{}", m.dim, m.uorder, m.vorder));
        }
        let u32_of = |v: usize| u32::try_from(v).map_err(|_| "batch too large for 32-bit offsets".to_owned());
        jobs.push(GpuJob {
            dim: u32_of(m.dim)?,
            uorder: u32_of(m.uorder)?,
            vorder: u32_of(m.vorder)?,
            point_offset: u32_of(points.len())?,
            nu: u32_of(g.us.len())?,
            nv: u32_of(g.vs.len())?,
            param_offset: u32_of(params.len())?,
            out_offset: u32::try_from(total).map_err(|_| "too many grid points".to_owned())?,
        });
        points.extend_from_slice(&m.points[..size]);
        params.extend_from_slice(g.us);
        params.extend_from_slice(g.vs);
        total += (g.us.len() * g.vs.len()) as u64;
    }
    let total = u32::try_from(total).map_err(|_| "too many grid points".to_owned())?;
    Ok((jobs, points, params, total))
}

/// The compute pipeline that evaluates patch grids.
pub struct GpuTessellator {
    pipeline: wgpu::ComputePipeline,
    layout: wgpu::BindGroupLayout,
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

impl GpuTessellator {
    /// Compiles the shader on `device`.
    #[must_use]
    pub fn new(device: &wgpu::Device) -> Self {
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("eval_grid.wgsl"),
            source: wgpu::ShaderSource::Wgsl(EVAL_GRID_WGSL.into()),
        });
        let uniform = wgpu::BindGroupLayoutEntry {
            binding: 4,
            visibility: wgpu::ShaderStages::COMPUTE,
            ty: wgpu::BindingType::Buffer {
                ty: wgpu::BufferBindingType::Uniform,
                has_dynamic_offset: false,
                min_binding_size: None,
            },
            count: None,
        };
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("eval_grid"),
            entries: &[storage(0, true), storage(1, true), storage(2, true), storage(3, false), uniform],
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("eval_grid"),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some("eval_grid"),
            layout: Some(&pipeline_layout),
            module: &module,
            entry_point: Some("main"),
            compilation_options: Default::default(),
            cache: None,
        });
        Self { pipeline, layout }
    }

    /// Records the evaluation of `grids` into `encoder`, returning the output buffer
    /// (`2 · points` vec4s: position, normal) and the number of grid points. The buffer can be
    /// bound as a vertex buffer (`VERTEX` usage) or copied out.
    pub fn encode(
        &self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        grids: &[PatchGrid<'_>],
        normals: bool,
    ) -> Result<(wgpu::Buffer, u32), String> {
        let (jobs, points, params, total) = pack(grids)?;
        let bytes = u64::from(total) * 32;
        if bytes > device.limits().max_storage_buffer_binding_size {
            return Err(format!("{total} grid points exceed the device's storage buffer limit; split the batch"));
        }
        let init = |label, contents: &[u8], usage| {
            device.create_buffer_init(&wgpu::util::BufferInitDescriptor { label: Some(label), contents, usage })
        };
        // wgpu rejects empty bindings: pad each input to at least 16 bytes.
        let padded = |v: &[f32]| {
            let mut v = v.to_vec();
            v.resize(v.len().max(4), 0.0);
            v
        };
        let storage_usage = wgpu::BufferUsages::STORAGE;
        let jobs_buf = init("jobs", bytemuck::cast_slice(&jobs), storage_usage);
        let points_buf = init("points", bytemuck::cast_slice(&padded(&points)), storage_usage);
        let params_buf = init("params", bytemuck::cast_slice(&padded(&params)), storage_usage);
        let meta =
            GpuMeta { job_count: jobs.len() as u32, total_points: total, want_normals: u32::from(normals), pad: 0 };
        let meta_buf = init("meta", bytemuck::bytes_of(&meta), wgpu::BufferUsages::UNIFORM);
        let out = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("grid output"),
            size: bytes.max(32),
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_SRC,
            mapped_at_creation: false,
        });
        let bind = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("eval_grid"),
            layout: &self.layout,
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: jobs_buf.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 1, resource: points_buf.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 2, resource: params_buf.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 3, resource: out.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 4, resource: meta_buf.as_entire_binding() },
            ],
        });
        let groups = total.div_ceil(WORKGROUP);
        let (gx, gy) = (groups.clamp(1, MAX_GROUPS_X), groups.div_ceil(MAX_GROUPS_X).max(1));
        let mut pass = encoder
            .begin_compute_pass(&wgpu::ComputePassDescriptor { label: Some("eval_grid"), timestamp_writes: None });
        pass.set_pipeline(&self.pipeline);
        pass.set_bind_group(0, &bind, &[]);
        pass.dispatch_workgroups(gx, gy, 1);
        drop(pass);
        Ok((out, total))
    }

    /// Evaluates `grids` and reads the result back (for tests and the typed API).
    pub fn evaluate(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        grids: &[PatchGrid<'_>],
        normals: bool,
    ) -> Result<GpuGrid, String> {
        let mut encoder = device.create_command_encoder(&Default::default());
        let (out, total) = self.encode(device, &mut encoder, grids, normals)?;
        let size = u64::from(total) * 32;
        let staging = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("grid readback"),
            size: size.max(32),
            usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        encoder.copy_buffer_to_buffer(&out, 0, &staging, 0, size.max(32));
        let submission = queue.submit([encoder.finish()]);
        let slice = staging.slice(..);
        let (tx, rx) = std::sync::mpsc::channel();
        slice.map_async(wgpu::MapMode::Read, move |r| {
            let _ = tx.send(r);
        });
        device
            .poll(wgpu::PollType::Wait { submission_index: Some(submission), timeout: None })
            .map_err(|e| e.to_string())?;
        rx.recv().map_err(|e| e.to_string())?.map_err(|e| e.to_string())?;
        let values: Vec<[f32; 4]> = {
            let view = slice.get_mapped_range().map_err(|e| e.to_string())?;
            bytemuck::cast_slice::<u8, [f32; 4]>(&view).to_vec()
        };
        staging.unmap();
        let n = total as usize;
        Ok(GpuGrid {
            points: values.iter().step_by(2).take(n).copied().collect(),
            normals: values.iter().skip(1).step_by(2).take(n).map(|v| [v[0], v[1], v[2]]).collect(),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn job_layout_matches_the_shader_struct() {
        // struct Job: eight u32 = 32 bytes; struct Meta: four u32 = 16 bytes (WGSL layout).
        assert_eq!(std::mem::size_of::<GpuJob>(), 32);
        assert_eq!(std::mem::align_of::<GpuJob>(), 4);
        assert_eq!(std::mem::size_of::<GpuMeta>(), 16);
        let j = GpuJob { out_offset: 7, ..GpuJob::default() };
        assert_eq!(bytemuck::cast::<GpuJob, [u32; 8]>(j)[7], 7, "out_offset is the last field");
    }

    #[test]
    fn packing_computes_prefix_sums_and_rejects_bad_jobs() {
        let pts = [0.0f32; 48];
        let map = MapView { dim: 3, uorder: 4, vorder: 4, points: &pts };
        let g = [PatchGrid { map, us: &[0.0, 1.0], vs: &[0.0, 0.5, 1.0] }, PatchGrid { map, us: &[0.5], vs: &[0.5] }];
        let (jobs, points, params, total) = pack(&g).unwrap();
        assert_eq!((jobs[1].out_offset, total), (6, 7));
        assert_eq!((jobs[1].point_offset, jobs[1].param_offset), (48, 5));
        assert_eq!((points.len(), params.len()), (96, 7));
        let bad = MapView { dim: 5, ..map };
        assert!(pack(&[PatchGrid { map: bad, us: &[0.0], vs: &[0.0] }]).is_err());
    }
}
