//! The bottom of the GPU module: finding an adapter, asking it for a device, catching the
//! device's uncaptured errors, and the one read-back (GPU memory to a `Vec<u8>`) that both the
//! headless picture and the evaluator's buffers go through. Nothing here knows GL.

use std::sync::{Arc, Mutex};

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

/// The backends to try, in order: `WGPU_BACKEND` if set, else Vulkan (lavapipe on machines
/// without a GPU) and then GL.
pub(crate) fn backend_order() -> Vec<wgpu::Backends> {
    match wgpu::Backends::from_env() {
        Some(b) => vec![b],
        None => vec![wgpu::Backends::VULKAN, wgpu::Backends::GL],
    }
}

/// A headless instance and the first adapter that works, or every backend's refusal.
pub(crate) fn first_adapter() -> Result<(wgpu::Instance, wgpu::Adapter), RenderError> {
    let mut tried = Vec::new();
    for backends in backend_order() {
        let desc = wgpu::InstanceDescriptor { backends, ..wgpu::InstanceDescriptor::new_without_display_handle() };
        let instance = wgpu::Instance::new(desc);
        let options = wgpu::RequestAdapterOptions::default();
        match pollster::block_on(instance.request_adapter(&options)) {
            Ok(adapter) => return Ok((instance, adapter)),
            Err(e) => tried.push(format!("{backends:?}: {e}")),
        }
    }
    Err(RenderError::NoAdapter(tried.join("; ")))
}

/// A device and its queue on `adapter`, with the largest storage buffers it offers: they let
/// the evaluator take big grids in one dispatch.
pub(crate) fn request_device(adapter: &wgpu::Adapter) -> Result<(wgpu::Device, wgpu::Queue), RenderError> {
    let available = adapter.limits();
    let required_limits = wgpu::Limits {
        max_storage_buffer_binding_size: available.max_storage_buffer_binding_size,
        max_buffer_size: available.max_buffer_size,
        ..wgpu::Limits::downlevel_defaults().using_resolution(available)
    };
    // Timestamp queries where the adapter has them: benchmarks time compute passes on the GPU.
    // The stencil buffer's format (`raster::DEPTH_FORMAT`); Mesa's drivers all have it.
    let required_features =
        adapter.features() & (wgpu::Features::TIMESTAMP_QUERY | wgpu::Features::DEPTH32FLOAT_STENCIL8);
    let desc =
        wgpu::DeviceDescriptor { label: Some("gleval"), required_limits, required_features, ..Default::default() };
    pollster::block_on(adapter.request_device(&desc)).map_err(|e| RenderError::Device(e.to_string()))
}

/// Where a device's uncaptured errors land (the first one since the last [`ErrorSlot::take`]):
/// wgpu reports validation errors through a callback, not through the call that caused them.
#[derive(Clone, Debug, Default)]
pub(crate) struct ErrorSlot(Arc<Mutex<Option<String>>>);

impl ErrorSlot {
    /// A slot that catches `device`'s uncaptured errors.
    pub(crate) fn catching(device: &wgpu::Device) -> Self {
        let slot = Self::default();
        let sink = Arc::clone(&slot.0);
        device.on_uncaptured_error(Arc::new(move |e: wgpu::Error| {
            if let Ok(mut slot) = sink.lock() {
                slot.get_or_insert_with(|| e.to_string());
            }
        }));
        slot
    }

    /// The first error since the last call, if any.
    pub(crate) fn take(&self) -> Result<(), RenderError> {
        match self.0.lock().ok().and_then(|mut e| e.take()) {
            Some(e) => Err(RenderError::Gpu(e)),
            None => Ok(()),
        }
    }
}

/// What compute work and its read-back need of a renderer (`Renderer::gpu` lends one): the
/// device, its queue, where its errors land, and whether the backend's flat shading takes a
/// primitive's last vertex. Borrowed, so that the evaluator needs no renderer.
#[derive(Clone, Copy, Debug)]
pub struct Gpu<'a> {
    pub(crate) device: &'a wgpu::Device,
    pub(crate) queue: &'a wgpu::Queue,
    pub(crate) errors: &'a ErrorSlot,
    /// GL's provoking-vertex convention (wgpu's GL backend) rather than Vulkan's first vertex.
    pub(crate) provoking_last: bool,
}

impl Gpu<'_> {
    /// Submits `encoder` after copying the first `bytes` of `buffer` out, and returns them; a
    /// wgpu error raised meanwhile is the result instead.
    pub(crate) fn read_buffer(
        &self,
        encoder: wgpu::CommandEncoder,
        buffer: &wgpu::Buffer,
        bytes: u64,
    ) -> Result<Vec<u8>, RenderError> {
        // Copies move whole 4-byte words.
        let size = bytes.max(4).div_ceil(4) * 4;
        let copy = |encoder: &mut wgpu::CommandEncoder, staging: &wgpu::Buffer| {
            encoder.copy_buffer_to_buffer(buffer, 0, staging, 0, size.min(buffer.size()));
        };
        let mut data = read_back(self.device, self.queue, encoder, size, copy)?;
        data.truncate(bytes as usize);
        self.errors.take()?;
        Ok(data)
    }
}

/// The one read-back: `copy` records a copy into a fresh mappable buffer of `size` bytes at the
/// end of `encoder`, which is then submitted; waits for it and returns the buffer's bytes.
pub(crate) fn read_back(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    mut encoder: wgpu::CommandEncoder,
    size: u64,
    copy: impl FnOnce(&mut wgpu::CommandEncoder, &wgpu::Buffer),
) -> Result<Vec<u8>, RenderError> {
    let staging = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("gleval readback"),
        size,
        usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
    copy(&mut encoder, &staging);
    let submission = queue.submit([encoder.finish()]);
    let slice = staging.slice(..);
    let (tx, rx) = std::sync::mpsc::channel();
    slice.map_async(wgpu::MapMode::Read, move |r| {
        let _ = tx.send(r);
    });
    let gpu = |e: &dyn std::fmt::Display| RenderError::Gpu(e.to_string());
    device.poll(wgpu::PollType::Wait { submission_index: Some(submission), timeout: None }).map_err(|e| gpu(&e))?;
    rx.recv().map_err(|e| gpu(&e))?.map_err(|e| gpu(&e))?;
    let data = slice.get_mapped_range().map_err(|e| gpu(&e))?.to_vec();
    staging.unmap();
    Ok(data)
}

/// Compiles a WGSL source on `device`.
pub(crate) fn shader_module(device: &wgpu::Device, label: &str, source: &'static str) -> wgpu::ShaderModule {
    device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some(label),
        source: wgpu::ShaderSource::Wgsl(source.into()),
    })
}

/// A storage buffer binding of a compute shader.
pub(crate) fn storage(binding: u32, read_only: bool) -> wgpu::BindGroupLayoutEntry {
    buffer_entry(binding, wgpu::ShaderStages::COMPUTE, wgpu::BufferBindingType::Storage { read_only }, false)
}

/// A uniform buffer binding, at a dynamic offset or not.
pub(crate) fn uniform(binding: u32, visibility: wgpu::ShaderStages, dynamic: bool) -> wgpu::BindGroupLayoutEntry {
    buffer_entry(binding, visibility, wgpu::BufferBindingType::Uniform, dynamic)
}

fn buffer_entry(
    binding: u32,
    visibility: wgpu::ShaderStages,
    ty: wgpu::BufferBindingType,
    has_dynamic_offset: bool,
) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility,
        ty: wgpu::BindingType::Buffer { ty, has_dynamic_offset, min_binding_size: None },
        count: None,
    }
}
