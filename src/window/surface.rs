//! A top-level window's surface: the winit window, a wgpu surface on it, the renderer on an
//! adapter that can present to it (Vulkan first, then GL) and the depth buffer of its size,
//! configured anew when the window resizes or the surface is lost.

use crate::glut::windows::WindowFacts;
use crate::render::{RenderError, Renderer};
use std::sync::{Arc, Mutex};
use winit::dpi::{PhysicalPosition, PhysicalSize};
use winit::event_loop::ActiveEventLoop;
use winit::window::Window;

/// The window and what draws into it.
pub(super) struct Gpu {
    pub(super) window: Arc<Window>,
    pub(super) surface: wgpu::Surface<'static>,
    pub(super) config: wgpu::SurfaceConfiguration,
    pub(super) renderer: Renderer,
    pub(super) depth: wgpu::TextureView,
    /// Set by wgpu when the device is lost.
    pub(super) lost: Arc<Mutex<Option<String>>>,
}

/// A depth buffer of the surface's size.
fn depth_view(device: &wgpu::Device, width: u32, height: u32) -> wgpu::TextureView {
    device
        .create_texture(&wgpu::TextureDescriptor {
            label: Some("window depth"),
            size: wgpu::Extent3d { width, height, depth_or_array_layers: 1 },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: crate::gpu::DEPTH_FORMAT,
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
            view_formats: &[],
        })
        .create_view(&Default::default())
}

impl Gpu {
    /// The window, a surface on it and a renderer on an adapter that can present to it:
    /// Vulkan first, then GL (or what `WGPU_BACKEND` says).
    pub(super) fn new(
        event_loop: &ActiveEventLoop,
        title: &str,
        facts: &WindowFacts,
        placed: Option<(i32, i32)>,
    ) -> Result<Self, String> {
        let (w, h) = (facts.width, facts.height);
        let mut attributes = Window::default_attributes()
            .with_title(title)
            .with_inner_size(PhysicalSize::new(w.max(1) as u32, h.max(1) as u32));
        if let Some((x, y)) = placed {
            attributes = attributes.with_position(PhysicalPosition::new(x, y));
        }
        let window =
            Arc::new(event_loop.create_window(attributes).map_err(|e| format!("could not open a window: {e}"))?);
        let mut tried = Vec::new();
        for backends in crate::gpu::backend_order() {
            // EGL (the GL backend) must know the display at instance creation to present to it.
            let desc = wgpu::InstanceDescriptor { backends, ..wgpu::InstanceDescriptor::new_without_display_handle() }
                .with_display_handle(Box::new(Arc::clone(&window)));
            let instance = wgpu::Instance::new(desc);
            let surface = match instance.create_surface(Arc::clone(&window)) {
                Ok(surface) => surface,
                Err(e) => {
                    tried.push(format!("{backends:?}: no surface ({e})"));
                    continue;
                }
            };
            let options = wgpu::RequestAdapterOptions { compatible_surface: Some(&surface), ..Default::default() };
            let adapter = match pollster::block_on(instance.request_adapter(&options)) {
                Ok(adapter) => adapter,
                Err(e) => {
                    tried.push(format!("{backends:?}: {e}"));
                    continue;
                }
            };
            match Self::configure(Arc::clone(&window), surface, instance, adapter) {
                Ok(gpu) => return Ok(gpu),
                Err(e) => tried.push(format!("{backends:?}: {e}")),
            }
        }
        Err(RenderError::NoAdapter(format!("none can present to the window: {}", tried.join("; "))).to_string())
    }

    pub(super) fn configure(
        window: Arc<Window>,
        surface: wgpu::Surface<'static>,
        instance: wgpu::Instance,
        adapter: wgpu::Adapter,
    ) -> Result<Self, String> {
        let size = window.inner_size();
        let caps = surface.get_capabilities(&adapter);
        // GL writes byte values as they are: prefer 8-bit formats without sRGB encoding.
        let preferred = [wgpu::TextureFormat::Bgra8Unorm, wgpu::TextureFormat::Rgba8Unorm];
        let format = preferred
            .into_iter()
            .find(|f| caps.formats.contains(f))
            .or_else(|| caps.formats.iter().copied().find(|f| !f.is_srgb()))
            .or_else(|| caps.formats.first().copied())
            .ok_or("the surface offers no formats")?;
        let mut config = surface
            .get_default_config(&adapter, size.width.max(1), size.height.max(1))
            .ok_or("the adapter cannot present to this window")?;
        config.format = format;
        // Subwindows are copied into the surface (see `WindowState::compose`).
        if caps.usages.contains(wgpu::TextureUsages::COPY_DST) {
            config.usage |= wgpu::TextureUsages::COPY_DST;
        }
        config.present_mode = wgpu::PresentMode::Fifo;
        let renderer = Renderer::with_adapter(instance, adapter).map_err(|e| e.to_string())?;
        let lost = Arc::new(Mutex::new(None));
        let sink = Arc::clone(&lost);
        renderer.device.set_device_lost_callback(move |reason, message| {
            if let Ok(mut slot) = sink.lock() {
                slot.get_or_insert(format!("the GPU device was lost ({reason:?}): {message}"));
            }
        });
        surface.configure(&renderer.device, &config);
        let depth = depth_view(&renderer.device, config.width, config.height);
        Ok(Self { window, surface, config, renderer, depth, lost })
    }

    /// Reconfigures the surface and depth buffer for a new size (not while minimised).
    pub(super) fn resize(&mut self, size: PhysicalSize<u32>) {
        if size.width == 0 || size.height == 0 {
            return;
        }
        if (size.width, size.height) != (self.config.width, self.config.height) {
            self.depth = depth_view(&self.renderer.device, size.width, size.height);
        }
        self.config.width = size.width;
        self.config.height = size.height;
        self.surface.configure(&self.renderer.device, &self.config);
    }

    /// Makes a new surface on the window after the old one was lost.
    pub(super) fn recreate_surface(&mut self) -> Result<(), String> {
        self.surface = self
            .renderer
            .instance
            .create_surface(Arc::clone(&self.window))
            .map_err(|e| format!("could not recreate the lost window surface: {e}"))?;
        self.surface.configure(&self.renderer.device, &self.config);
        Ok(())
    }

    pub(super) fn lost(&self) -> Option<String> {
        self.lost.lock().ok().and_then(|slot| slot.clone())
    }
}
