//! The wgpu rasteriser: draws a [`DrawList`] into an RGBA8 target, headless (read back as an
//! [`Image`]) or into a window's surface.
//!
//! GL conventions kept in one place: viewports (origin bottom-left, allowed outside the
//! drawable) become a full-target transform of the clip coordinates plus a scissor rectangle,
//! which is what clipping to GL's view volume amounts to; depth was already mapped to [0, 1]
//! during assembly; the depth test and depth writes exist only while `GL_DEPTH_TEST` is on.

use super::assemble::{assemble_frame, Batch, DrawList, Op, RasterVertex, Topology};
use super::mesh_gpu::{gpu_mesh_indices, mesh_viewport, MeshPipelines, PreparedMeshes};
use crate::gl::consts::*;
use crate::gl::types::GLenum;
use crate::gl::Frame;
use std::collections::HashMap;
use std::sync::{Arc, Mutex};
use wgpu::util::DeviceExt;

/// The rasteriser's WGSL source (`shaders/raster.wgsl`).
pub const RASTER_WGSL: &str = include_str!("../../shaders/raster.wgsl");

const COLOR_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8Unorm;
pub(crate) const DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;

/// Why rendering failed.
#[derive(Clone, Debug, PartialEq)]
pub enum RenderError {
    /// No wgpu adapter: no Vulkan driver and no usable GL/EGL.
    NoAdapter(String),
    /// The adapter refused a device.
    Device(String),
    /// wgpu reported a validation or device error while drawing.
    Gpu(String),
}

impl std::fmt::Display for RenderError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::NoAdapter(why) => write!(
                f,
                "no GPU adapter found ({why}). On Debian/Ubuntu without a GPU install Mesa's software \
                 drivers: `apt-get install mesa-vulkan-drivers libvulkan1` (lavapipe, Vulkan) or \
                 `libegl1 libegl-mesa0 libgl1-mesa-dri` (llvmpipe, GL backend)"
            ),
            Self::Device(why) => write!(f, "could not create a wgpu device: {why}"),
            Self::Gpu(why) => write!(f, "wgpu error: {why}"),
        }
    }
}

impl std::error::Error for RenderError {}

/// An RGBA8 picture, rows top to bottom (PNG order).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Image {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// `width * height * 4` bytes.
    pub pixels: Vec<u8>,
}

/// The backends to try, in order: `WGPU_BACKEND` if set, else Vulkan (lavapipe on machines
/// without a GPU) and then GL.
pub(crate) fn backend_order() -> Vec<wgpu::Backends> {
    match wgpu::Backends::from_env() {
        Some(b) => vec![b],
        None => vec![wgpu::Backends::VULKAN, wgpu::Backends::GL],
    }
}

/// A wgpu device with the pipelines that draw assembled GL frames.
pub struct Renderer {
    /// The instance the adapter came from (a window surface must be made from it).
    pub instance: wgpu::Instance,
    /// The adapter in use.
    pub adapter: wgpu::Adapter,
    /// The device.
    pub device: wgpu::Device,
    /// Its queue.
    pub queue: wgpu::Queue,
    module: wgpu::ShaderModule,
    layout: wgpu::PipelineLayout,
    pipelines: HashMap<(Topology, Option<GLenum>, wgpu::TextureFormat), wgpu::RenderPipeline>,
    meshes: Option<MeshPipelines>,
    errors: Arc<Mutex<Option<String>>>,
}

impl Renderer {
    /// A headless renderer on the first adapter that works (see [`RenderError::NoAdapter`]).
    pub fn new() -> Result<Self, RenderError> {
        let mut tried = Vec::new();
        for backends in backend_order() {
            let desc = wgpu::InstanceDescriptor { backends, ..wgpu::InstanceDescriptor::new_without_display_handle() };
            let instance = wgpu::Instance::new(desc);
            let options = wgpu::RequestAdapterOptions::default();
            match pollster::block_on(instance.request_adapter(&options)) {
                Ok(adapter) => return Self::with_adapter(instance, adapter),
                Err(e) => tried.push(format!("{backends:?}: {e}")),
            }
        }
        Err(RenderError::NoAdapter(tried.join("; ")))
    }

    /// A renderer on a given instance and adapter (a window's).
    pub fn with_adapter(instance: wgpu::Instance, adapter: wgpu::Adapter) -> Result<Self, RenderError> {
        // Large storage buffers let the GPU tessellator take big grids in one dispatch.
        let available = adapter.limits();
        let required_limits = wgpu::Limits {
            max_storage_buffer_binding_size: available.max_storage_buffer_binding_size,
            max_buffer_size: available.max_buffer_size,
            ..wgpu::Limits::downlevel_defaults().using_resolution(available)
        };
        let desc = wgpu::DeviceDescriptor { label: Some("gleval"), required_limits, ..Default::default() };
        let (device, queue) =
            pollster::block_on(adapter.request_device(&desc)).map_err(|e| RenderError::Device(e.to_string()))?;
        let errors = Arc::new(Mutex::new(None));
        let sink = Arc::clone(&errors);
        device.on_uncaptured_error(Arc::new(move |e: wgpu::Error| {
            if let Ok(mut slot) = sink.lock() {
                slot.get_or_insert_with(|| e.to_string());
            }
        }));
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("raster.wgsl"),
            source: wgpu::ShaderSource::Wgsl(RASTER_WGSL.into()),
        });
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("raster"),
            bind_group_layouts: &[],
            immediate_size: 0,
        });
        Ok(Self { instance, adapter, device, queue, module, layout, pipelines: HashMap::new(), meshes: None, errors })
    }

    /// Whether flat shading takes a primitive's last vertex (GL's convention, kept by wgpu's GL
    /// backend) rather than its first (Vulkan, Metal, DX12).
    pub fn provoking_vertex_is_last(&self) -> bool {
        self.adapter.get_info().backend == wgpu::Backend::Gl
    }

    /// A one-line description of the adapter (name and backend).
    #[must_use]
    pub fn adapter_name(&self) -> String {
        let info = self.adapter.get_info();
        format!("{} ({:?})", info.name, info.backend)
    }

    /// Renders a recorded frame headless and reads it back.
    pub fn render_frame(&mut self, frame: &Frame, width: u32, height: u32) -> Result<Image, RenderError> {
        let target = Target::new(&self.device, width.max(1), height.max(1), COLOR_FORMAT);
        let mut encoder = self.device.create_command_encoder(&Default::default());
        self.encode(
            frame,
            &mut encoder,
            &target.color_view,
            &target.depth_view,
            (target.width, target.height),
            COLOR_FORMAT,
        );
        let readback = target.copy_out(&self.device, &mut encoder);
        let submission = self.queue.submit([encoder.finish()]);
        // A validation error makes the submission fail; report the error itself.
        let pixels = readback.read(&self.device, submission);
        self.take_error()?;
        let pixels = pixels?;
        Ok(Image { width: target.width, height: target.height, pixels })
    }

    /// The first wgpu validation or device error since the last call, if any.
    pub fn take_error(&self) -> Result<(), RenderError> {
        match self.errors.lock().ok().and_then(|mut e| e.take()) {
            Some(e) => Err(RenderError::Gpu(e)),
            None => Ok(()),
        }
    }

    /// Records a frame into `encoder`, rendering to `color` (of `format`) and `depth`: meshes
    /// left to the GPU tessellator are evaluated by one compute dispatch first, then everything
    /// is drawn in program order.
    pub fn encode(
        &mut self,
        frame: &Frame,
        encoder: &mut wgpu::CommandEncoder,
        color: &wgpu::TextureView,
        depth: &wgpu::TextureView,
        size: (u32, u32),
        format: wgpu::TextureFormat,
    ) {
        let on_gpu = gpu_mesh_indices(&self.device, frame);
        let list = assemble_frame(frame, &on_gpu);
        let prepared = (!on_gpu.is_empty()).then(|| {
            let provoking_last = self.provoking_vertex_is_last();
            let meshes = self.meshes.get_or_insert_with(|| MeshPipelines::new(&self.device, provoking_last));
            let prepared = meshes.prepare(&self.device, &self.queue, encoder, frame, &on_gpu, size);
            meshes.ensure_pipelines(&self.device, frame, &prepared, format);
            prepared
        });
        self.encode_list(&list, frame, prepared.as_ref(), encoder, color, depth, size, format);
    }

    /// Records an assembled list (with its frame's GPU meshes already prepared).
    #[allow(clippy::too_many_arguments)]
    fn encode_list(
        &mut self,
        list: &DrawList,
        frame: &Frame,
        prepared: Option<&PreparedMeshes>,
        encoder: &mut wgpu::CommandEncoder,
        color: &wgpu::TextureView,
        depth: &wgpu::TextureView,
        size: (u32, u32),
        format: wgpu::TextureFormat,
    ) {
        let vertices = to_target_space(list, size);
        let buffer = (!vertices.is_empty()).then(|| {
            self.device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some("frame vertices"),
                contents: bytemuck::cast_slice(&vertices),
                usage: wgpu::BufferUsages::VERTEX,
            })
        });
        for pass in split_passes(&list.ops) {
            for item in &pass.draws {
                if let PassItem::Batch(batch) = item {
                    self.ensure_pipeline(batch.topology, batch.depth_test, format);
                }
            }
            let mut rp = begin_pass(encoder, color, depth, pass.clear_color, pass.clear_depth);
            for item in &pass.draws {
                match item {
                    PassItem::Batch(batch) => {
                        let Some(buffer) = &buffer else { continue };
                        let Some(scissor) = scissor_rect(batch.viewport, size) else { continue };
                        rp.set_scissor_rect(scissor[0], scissor[1], scissor[2], scissor[3]);
                        rp.set_pipeline(&self.pipelines[&(batch.topology, batch.depth_test, format)]);
                        rp.set_vertex_buffer(0, buffer.slice(..));
                        rp.draw(batch.first..batch.first + batch.count, 0..1);
                    }
                    PassItem::Mesh(index) => {
                        let (Some(prepared), Some(meshes)) = (prepared, &self.meshes) else { continue };
                        let Some(viewport) = mesh_viewport(frame, prepared, *index) else { continue };
                        let Some(scissor) = scissor_rect(viewport, size) else { continue };
                        rp.set_scissor_rect(scissor[0], scissor[1], scissor[2], scissor[3]);
                        meshes.draw(&mut rp, frame, prepared, *index, format);
                    }
                }
            }
        }
    }

    fn ensure_pipeline(&mut self, topology: Topology, depth: Option<GLenum>, format: wgpu::TextureFormat) {
        if self.pipelines.contains_key(&(topology, depth, format)) {
            return;
        }
        let pipeline = make_pipeline(&self.device, &self.module, &self.layout, topology, depth, format);
        self.pipelines.insert((topology, depth, format), pipeline);
    }
}

/// GL's depth function as wgpu's comparison.
pub(crate) fn compare(func: GLenum) -> wgpu::CompareFunction {
    match func {
        GL_NEVER => wgpu::CompareFunction::Never,
        GL_EQUAL => wgpu::CompareFunction::Equal,
        GL_LEQUAL => wgpu::CompareFunction::LessEqual,
        GL_GREATER => wgpu::CompareFunction::Greater,
        GL_NOTEQUAL => wgpu::CompareFunction::NotEqual,
        GL_GEQUAL => wgpu::CompareFunction::GreaterEqual,
        GL_ALWAYS => wgpu::CompareFunction::Always,
        _ => wgpu::CompareFunction::Less,
    }
}

fn make_pipeline(
    device: &wgpu::Device,
    module: &wgpu::ShaderModule,
    layout: &wgpu::PipelineLayout,
    topology: Topology,
    depth: Option<GLenum>,
    format: wgpu::TextureFormat,
) -> wgpu::RenderPipeline {
    let attributes = wgpu::vertex_attr_array![0 => Float32x4, 1 => Float32x4];
    let vertex_layout = wgpu::VertexBufferLayout {
        array_stride: std::mem::size_of::<RasterVertex>() as wgpu::BufferAddress,
        step_mode: wgpu::VertexStepMode::Vertex,
        attributes: &attributes,
    };
    let topology = match topology {
        Topology::Triangles => wgpu::PrimitiveTopology::TriangleList,
        Topology::Lines => wgpu::PrimitiveTopology::LineList,
        Topology::Points => wgpu::PrimitiveTopology::PointList,
    };
    // Without GL_DEPTH_TEST, GL neither tests nor writes depth.
    let depth_stencil = wgpu::DepthStencilState {
        format: DEPTH_FORMAT,
        depth_write_enabled: Some(depth.is_some()),
        depth_compare: Some(depth.map_or(wgpu::CompareFunction::Always, compare)),
        stencil: wgpu::StencilState::default(),
        bias: wgpu::DepthBiasState::default(),
    };
    device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some("gl raster"),
        layout: Some(layout),
        vertex: wgpu::VertexState {
            module,
            entry_point: Some("vs_main"),
            compilation_options: Default::default(),
            buffers: &[Some(vertex_layout)],
        },
        primitive: wgpu::PrimitiveState { topology, ..Default::default() },
        depth_stencil: Some(depth_stencil),
        multisample: wgpu::MultisampleState::default(),
        fragment: Some(wgpu::FragmentState {
            module,
            entry_point: Some("fs_main"),
            compilation_options: Default::default(),
            targets: &[Some(wgpu::ColorTargetState { format, blend: None, write_mask: wgpu::ColorWrites::ALL })],
        }),
        multiview_mask: None,
        cache: None,
    })
}

/// What a render pass draws: a batch of assembled vertices or a GPU-tessellated mesh.
enum PassItem {
    Batch(Batch),
    Mesh(usize),
}

/// Draws between two clears share one render pass.
struct Pass {
    clear_color: Option<[f32; 4]>,
    clear_depth: Option<f32>,
    draws: Vec<PassItem>,
}

/// Splits the ops at every clear. The first pass clears to transparent black and depth 1 (the
/// state of a new OSMesa buffer) unless the program clears first.
fn split_passes(ops: &[Op]) -> Vec<Pass> {
    let mut passes = vec![Pass { clear_color: Some([0.0; 4]), clear_depth: Some(1.0), draws: Vec::new() }];
    for op in ops {
        match *op {
            Op::Clear { color, depth } => {
                let last = passes.last_mut().expect("at least one pass");
                if last.draws.is_empty() {
                    last.clear_color = color.or(last.clear_color);
                    last.clear_depth = depth.or(last.clear_depth);
                } else {
                    passes.push(Pass { clear_color: color, clear_depth: depth, draws: Vec::new() });
                }
            }
            Op::Draw(batch) => passes.last_mut().expect("at least one pass").draws.push(PassItem::Batch(batch)),
            Op::GpuMesh(index) => passes.last_mut().expect("at least one pass").draws.push(PassItem::Mesh(index)),
        }
    }
    passes
}

fn begin_pass<'e>(
    encoder: &'e mut wgpu::CommandEncoder,
    color: &wgpu::TextureView,
    depth: &wgpu::TextureView,
    clear_color: Option<[f32; 4]>,
    clear_depth: Option<f32>,
) -> wgpu::RenderPass<'e> {
    let color_load = match clear_color {
        Some([r, g, b, a]) => wgpu::LoadOp::Clear(wgpu::Color { r: r.into(), g: g.into(), b: b.into(), a: a.into() }),
        None => wgpu::LoadOp::Load,
    };
    let depth_load = clear_depth.map_or(wgpu::LoadOp::Load, wgpu::LoadOp::Clear);
    encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
        label: Some("gl frame"),
        color_attachments: &[Some(wgpu::RenderPassColorAttachment {
            view: color,
            depth_slice: None,
            resolve_target: None,
            ops: wgpu::Operations { load: color_load, store: wgpu::StoreOp::Store },
        })],
        depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
            view: depth,
            depth_ops: Some(wgpu::Operations { load: depth_load, store: wgpu::StoreOp::Store }),
            stencil_ops: None,
        }),
        timestamp_writes: None,
        occlusion_query_set: None,
        multiview_mask: None,
    })
}

/// Moves each batch's vertices from its GL viewport's clip space into the whole target's:
/// x' = x·(vw/W) + w·((2·vx + vw)/W − 1), likewise y. wgpu needs viewports inside the target;
/// GL allows them anywhere, so the viewport transform is applied here instead.
fn to_target_space(list: &DrawList, (width, height): (u32, u32)) -> Vec<RasterVertex> {
    let mut out = list.vertices.clone();
    let (fw, fh) = (width as f32, height as f32);
    for op in &list.ops {
        let Op::Draw(b) = op else { continue };
        let [vx, vy, vw, vh] = b.viewport.map(|c| c as f32);
        let (sx, ox) = (vw / fw, (2.0 * vx + vw) / fw - 1.0);
        let (sy, oy) = (vh / fh, (2.0 * vy + vh) / fh - 1.0);
        for v in &mut out[b.first as usize..(b.first + b.count) as usize] {
            let w = v.clip[3];
            v.clip[0] = v.clip[0] * sx + w * ox;
            v.clip[1] = v.clip[1] * sy + w * oy;
        }
    }
    out
}

/// The GL viewport (origin bottom-left) intersected with the target, in wgpu's top-left
/// coordinates; `None` when empty.
fn scissor_rect([x, y, w, h]: [i32; 4], (width, height): (u32, u32)) -> Option<[u32; 4]> {
    let (fw, fh) = (i64::from(width), i64::from(height));
    let x0 = i64::from(x).clamp(0, fw);
    let x1 = (i64::from(x) + i64::from(w)).clamp(0, fw);
    let top = (fh - i64::from(y) - i64::from(h)).clamp(0, fh);
    let bottom = (fh - i64::from(y)).clamp(0, fh);
    (x1 > x0 && bottom > top).then(|| [x0 as u32, top as u32, (x1 - x0) as u32, (bottom - top) as u32])
}

/// A colour and depth texture to render into.
struct Target {
    width: u32,
    height: u32,
    color: wgpu::Texture,
    color_view: wgpu::TextureView,
    depth_view: wgpu::TextureView,
}

impl Target {
    fn new(device: &wgpu::Device, width: u32, height: u32, format: wgpu::TextureFormat) -> Self {
        let size = wgpu::Extent3d { width, height, depth_or_array_layers: 1 };
        let texture = |format, usage| {
            device.create_texture(&wgpu::TextureDescriptor {
                label: Some("gleval target"),
                size,
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format,
                usage,
                view_formats: &[],
            })
        };
        let color = texture(format, wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC);
        let depth = texture(DEPTH_FORMAT, wgpu::TextureUsages::RENDER_ATTACHMENT);
        let color_view = color.create_view(&Default::default());
        let depth_view = depth.create_view(&Default::default());
        Self { width, height, color, color_view, depth_view }
    }

    /// Records a copy of the colour texture into a mappable buffer.
    fn copy_out(&self, device: &wgpu::Device, encoder: &mut wgpu::CommandEncoder) -> Readback {
        let align = wgpu::COPY_BYTES_PER_ROW_ALIGNMENT;
        let padded_row = (self.width * 4).div_ceil(align) * align;
        let buffer = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("gleval readback"),
            size: u64::from(padded_row) * u64::from(self.height),
            usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        encoder.copy_texture_to_buffer(
            wgpu::TexelCopyTextureInfo {
                texture: &self.color,
                mip_level: 0,
                origin: wgpu::Origin3d::ZERO,
                aspect: wgpu::TextureAspect::All,
            },
            wgpu::TexelCopyBufferInfo {
                buffer: &buffer,
                layout: wgpu::TexelCopyBufferLayout {
                    offset: 0,
                    bytes_per_row: Some(padded_row),
                    rows_per_image: Some(self.height),
                },
            },
            wgpu::Extent3d { width: self.width, height: self.height, depth_or_array_layers: 1 },
        );
        Readback { buffer, padded_row, width: self.width }
    }
}

/// A buffer the target was copied into.
struct Readback {
    buffer: wgpu::Buffer,
    padded_row: u32,
    width: u32,
}

impl Readback {
    /// Waits for the submission and returns the pixels without row padding.
    fn read(self, device: &wgpu::Device, submission: wgpu::SubmissionIndex) -> Result<Vec<u8>, RenderError> {
        let slice = self.buffer.slice(..);
        let (tx, rx) = std::sync::mpsc::channel();
        slice.map_async(wgpu::MapMode::Read, move |r| {
            let _ = tx.send(r);
        });
        device
            .poll(wgpu::PollType::Wait { submission_index: Some(submission), timeout: None })
            .map_err(|e| RenderError::Gpu(e.to_string()))?;
        match rx.recv() {
            Ok(Ok(())) => {}
            Ok(Err(e)) => return Err(RenderError::Gpu(e.to_string())),
            Err(e) => return Err(RenderError::Gpu(e.to_string())),
        }
        let row = self.width as usize * 4;
        let pixels = {
            let view = slice.get_mapped_range().map_err(|e| RenderError::Gpu(e.to_string()))?;
            view.chunks_exact(self.padded_row as usize).flat_map(|r| r[..row].iter().copied()).collect()
        };
        self.buffer.unmap();
        Ok(pixels)
    }
}

/// Submits `encoder` after copying `bytes` of `buffer` out, and returns them.
pub(crate) fn read_buffer(
    renderer: &Renderer,
    mut encoder: wgpu::CommandEncoder,
    buffer: &wgpu::Buffer,
    bytes: u64,
) -> Result<Vec<u8>, RenderError> {
    let size = bytes.max(4).div_ceil(4) * 4;
    let staging = renderer.device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("gleval buffer readback"),
        size,
        usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
    encoder.copy_buffer_to_buffer(buffer, 0, &staging, 0, size.min(buffer.size()));
    let submission = renderer.queue.submit([encoder.finish()]);
    let slice = staging.slice(..);
    let (tx, rx) = std::sync::mpsc::channel();
    slice.map_async(wgpu::MapMode::Read, move |r| {
        let _ = tx.send(r);
    });
    renderer
        .device
        .poll(wgpu::PollType::Wait { submission_index: Some(submission), timeout: None })
        .map_err(|e| RenderError::Gpu(e.to_string()))?;
    match rx.recv() {
        Ok(Ok(())) => {}
        Ok(Err(e)) => return Err(RenderError::Gpu(e.to_string())),
        Err(e) => return Err(RenderError::Gpu(e.to_string())),
    }
    let data = slice.get_mapped_range().map_err(|e| RenderError::Gpu(e.to_string()))?[..bytes as usize].to_vec();
    staging.unmap();
    renderer.take_error()?;
    Ok(data)
}
