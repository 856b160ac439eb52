//! The windowed mode of [`App`]: a winit 0.30 window with a wgpu surface, redrawn like a GLUT
//! window (reshape on resize, display on every redraw). The [`Gl`] context lives as long as the
//! window, so GL state set in `init` or in earlier frames persists.

use crate::app::App;
use crate::gl::Gl;
use crate::render::{assemble, Renderer};
use std::error::Error;
use std::sync::Arc;
use winit::application::ApplicationHandler;
use winit::dpi::PhysicalSize;
use winit::event::{ElementState, KeyEvent, WindowEvent};
use winit::event_loop::{ActiveEventLoop, EventLoop};
use winit::keyboard::{Key, NamedKey};
use winit::window::{Window, WindowId};

/// Opens the window and runs until it is closed (or Escape is pressed).
pub(crate) fn run(app: App) -> Result<(), Box<dyn Error>> {
    let has_display = ["DISPLAY", "WAYLAND_DISPLAY"].iter().any(|v| std::env::var_os(v).is_some_and(|s| !s.is_empty()));
    if !has_display {
        return Err("no display to open a window on (neither DISPLAY nor WAYLAND_DISPLAY is set); \
                    run with --png PATH to render one frame to a file instead"
            .into());
    }
    let event_loop = EventLoop::new()?;
    let mut state = WindowState { app, gl: None, gpu: None, error: None };
    event_loop.run_app(&mut state)?;
    match state.error {
        Some(e) => Err(e.into()),
        None => Ok(()),
    }
}

struct Gpu {
    window: Arc<Window>,
    surface: wgpu::Surface<'static>,
    config: wgpu::SurfaceConfiguration,
    renderer: Renderer,
    depth: wgpu::TextureView,
}

struct WindowState {
    app: App,
    gl: Option<Gl>,
    gpu: Option<Gpu>,
    error: Option<String>,
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
            format: crate::render::DEPTH_FORMAT,
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
            view_formats: &[],
        })
        .create_view(&Default::default())
}

impl Gpu {
    /// The window, a surface on it and a renderer on an adapter that can present to it:
    /// Vulkan first, then GL (or what `WGPU_BACKEND` says).
    fn new(event_loop: &ActiveEventLoop, app: &App) -> Result<Self, String> {
        let (w, h) = app.size();
        let attributes =
            Window::default_attributes().with_title(app.title()).with_inner_size(PhysicalSize::new(w as u32, h as u32));
        let window = Arc::new(event_loop.create_window(attributes).map_err(|e| e.to_string())?);
        let mut tried = Vec::new();
        for backends in crate::render::backend_order() {
            let desc = wgpu::InstanceDescriptor { backends, ..wgpu::InstanceDescriptor::new_without_display_handle() };
            let instance = wgpu::Instance::new(desc);
            let Ok(surface) = instance.create_surface(Arc::clone(&window)) else {
                tried.push(format!("{backends:?}: no surface"));
                continue;
            };
            let options = wgpu::RequestAdapterOptions { compatible_surface: Some(&surface), ..Default::default() };
            match pollster::block_on(instance.request_adapter(&options)) {
                Ok(adapter) => return Self::configure(window, surface, instance, adapter),
                Err(e) => tried.push(format!("{backends:?}: {e}")),
            }
        }
        Err(crate::render::RenderError::NoAdapter(tried.join("; ")).to_string())
    }

    fn configure(
        window: Arc<Window>,
        surface: wgpu::Surface<'static>,
        instance: wgpu::Instance,
        adapter: wgpu::Adapter,
    ) -> Result<Self, String> {
        let size = window.inner_size();
        let caps = surface.get_capabilities(&adapter);
        // GL writes byte values as they are: prefer a format without sRGB encoding.
        let format = caps
            .formats
            .iter()
            .copied()
            .find(|f| !f.is_srgb())
            .or(caps.formats.first().copied())
            .ok_or("surface has no formats")?;
        let mut config = surface
            .get_default_config(&adapter, size.width.max(1), size.height.max(1))
            .ok_or("the adapter cannot present to this window")?;
        config.format = format;
        config.present_mode = wgpu::PresentMode::Fifo;
        let renderer = Renderer::with_adapter(instance, adapter).map_err(|e| e.to_string())?;
        surface.configure(&renderer.device, &config);
        let depth = depth_view(&renderer.device, config.width, config.height);
        Ok(Self { window, surface, config, renderer, depth })
    }

    fn resize(&mut self, size: PhysicalSize<u32>) {
        if size.width == 0 || size.height == 0 {
            return;
        }
        self.config.width = size.width;
        self.config.height = size.height;
        self.surface.configure(&self.renderer.device, &self.config);
        self.depth = depth_view(&self.renderer.device, size.width, size.height);
    }
}

impl WindowState {
    fn fail(&mut self, event_loop: &ActiveEventLoop, error: String) {
        self.error = Some(error);
        event_loop.exit();
    }

    /// GLUT's redraw: reshape to the current size, display, then draw what was recorded.
    fn redraw(&mut self, event_loop: &ActiveEventLoop) {
        let (Some(gpu), Some(gl)) = (self.gpu.as_mut(), self.gl.as_mut()) else { return };
        let size = gpu.window.inner_size();
        if size.width == 0 || size.height == 0 {
            return; // minimised
        }
        self.app.draw_into(gl, size.width as i32, size.height as i32);
        let list = assemble(&gl.take_frame());
        let frame = match gpu.surface.get_current_texture() {
            wgpu::CurrentSurfaceTexture::Success(f) | wgpu::CurrentSurfaceTexture::Suboptimal(f) => f,
            wgpu::CurrentSurfaceTexture::Timeout | wgpu::CurrentSurfaceTexture::Occluded => return,
            wgpu::CurrentSurfaceTexture::Outdated | wgpu::CurrentSurfaceTexture::Lost => {
                gpu.resize(size);
                gpu.window.request_redraw();
                return;
            }
            other => return self.fail(event_loop, format!("the window surface failed: {other:?}")),
        };
        let view = frame.texture.create_view(&Default::default());
        let mut encoder = gpu.renderer.device.create_command_encoder(&Default::default());
        let format = gpu.config.format;
        gpu.renderer.encode(&list, &mut encoder, &view, &gpu.depth, (size.width, size.height), format);
        gpu.renderer.queue.submit([encoder.finish()]);
        gpu.renderer.queue.present(frame);
    }
}

impl ApplicationHandler for WindowState {
    fn resumed(&mut self, event_loop: &ActiveEventLoop) {
        if self.gpu.is_some() {
            return;
        }
        match Gpu::new(event_loop, &self.app) {
            Ok(gpu) => {
                let size = gpu.window.inner_size();
                let mut gl = Gl::new(size.width as i32, size.height as i32);
                self.app.run_init(&mut gl);
                self.gl = Some(gl);
                gpu.window.request_redraw();
                self.gpu = Some(gpu);
            }
            Err(e) => self.fail(event_loop, e),
        }
    }

    fn window_event(&mut self, event_loop: &ActiveEventLoop, _id: WindowId, event: WindowEvent) {
        match event {
            WindowEvent::CloseRequested => event_loop.exit(),
            WindowEvent::Resized(size) => {
                if let Some(gpu) = self.gpu.as_mut() {
                    gpu.resize(size);
                    gpu.window.request_redraw();
                }
            }
            WindowEvent::RedrawRequested => self.redraw(event_loop),
            WindowEvent::KeyboardInput {
                event: KeyEvent { logical_key, state: ElementState::Pressed, .. }, ..
            } => {
                if logical_key == Key::Named(NamedKey::Escape) {
                    return event_loop.exit();
                }
                if let (Key::Character(text), Some(gl)) = (&logical_key, self.gl.as_mut()) {
                    if let Some(c) = text.chars().next() {
                        self.app.run_keyboard(gl, c);
                    }
                }
                if let Some(gpu) = &self.gpu {
                    gpu.window.request_redraw();
                }
            }
            _ => {}
        }
    }
}
