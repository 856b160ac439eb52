//! The windowed mode of [`App`]: a winit 0.30 window with a wgpu surface, redrawn like a GLUT
//! window (reshape when the size changes, display on every redraw). The [`Gl`] context lives as
//! long as the window, so GL state set in `init` or in earlier frames persists; only what a
//! frame draws is taken from it each time.

use crate::app::{App, Redraw};
use crate::gl::{Frame, Gl};
use crate::glut::consts::*;
use crate::glut::Schedule;
use crate::render::{RenderError, Renderer};
use std::error::Error;
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};
use winit::application::ApplicationHandler;
use winit::dpi::PhysicalSize;
use winit::event::{ElementState, KeyEvent, Modifiers, MouseButton, WindowEvent};
use winit::event_loop::{ActiveEventLoop, ControlFlow, EventLoop};
use winit::keyboard::{Key, NamedKey};
use winit::window::{Fullscreen, Window, WindowId};

/// Opens the window and runs until it is closed (or Escape is pressed).
pub(crate) fn run(app: App) -> Result<(), Box<dyn Error>> {
    const USE_PNG: &str = "run the program with --png PATH to render one frame to a PNG file instead";
    let has_display = ["DISPLAY", "WAYLAND_DISPLAY"].iter().any(|v| std::env::var_os(v).is_some_and(|s| !s.is_empty()));
    if !has_display {
        return Err(
            format!("no display to open a window on (neither DISPLAY nor WAYLAND_DISPLAY is set); {USE_PNG}").into()
        );
    }
    let event_loop = EventLoop::new().map_err(|e| format!("could not connect to the display ({e}); {USE_PNG}"))?;
    let mut state = WindowState {
        app,
        gl: None,
        gpu: None,
        size: None,
        cursor: (0, 0),
        buttons_down: 0,
        modifiers: 0,
        schedule: Schedule::default(),
        start: Instant::now(),
        frames_drawn: 0,
        last_frame: None,
        program_changed: true,
        error: None,
    };
    event_loop.run_app(&mut state)?;
    match state.error {
        Some(e) => Err(e.into()),
        None => Ok(()),
    }
}

/// The window and what draws into it.
struct Gpu {
    window: Arc<Window>,
    surface: wgpu::Surface<'static>,
    config: wgpu::SurfaceConfiguration,
    renderer: Renderer,
    depth: wgpu::TextureView,
    /// Set by wgpu when the device is lost.
    lost: Arc<Mutex<Option<String>>>,
}

struct WindowState {
    app: App,
    gl: Option<Gl>,
    gpu: Option<Gpu>,
    /// The size the reshape callback last saw.
    size: Option<(u32, u32)>,
    /// The mouse position in window pixels (origin top left, as GLUT reports it).
    cursor: (i32, i32),
    /// Mouse buttons held (motion callbacks run only then, as GLUT's).
    buttons_down: u32,
    /// `GLUT_ACTIVE_*` bits of the modifier keys held.
    modifiers: i32,
    /// The idle callback and timers.
    schedule: Schedule,
    /// When the main loop started: `GLUT_ELAPSED_TIME` and the timers count from here.
    start: Instant,
    /// Frames presented (`--frames N` closes the window after N).
    frames_drawn: usize,
    /// What the display callback drew last: shown again under a menu that changed.
    last_frame: Option<Frame>,
    /// The display callback must draw again at the next redraw (false when only the open
    /// menu changed).
    program_changed: bool,
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
            format: crate::gpu::DEPTH_FORMAT,
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
        let attributes = Window::default_attributes()
            .with_title(app.title())
            .with_inner_size(PhysicalSize::new(w.max(1) as u32, h.max(1) as u32));
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

    fn configure(
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
    fn resize(&mut self, size: PhysicalSize<u32>) {
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
    fn recreate_surface(&mut self) -> Result<(), String> {
        self.surface = self
            .renderer
            .instance
            .create_surface(Arc::clone(&self.window))
            .map_err(|e| format!("could not recreate the lost window surface: {e}"))?;
        self.surface.configure(&self.renderer.device, &self.config);
        Ok(())
    }

    fn lost(&self) -> Option<String> {
        self.lost.lock().ok().and_then(|slot| slot.clone())
    }
}

impl WindowState {
    fn fail(&mut self, event_loop: &ActiveEventLoop, error: String) {
        self.error = Some(error);
        event_loop.exit();
    }

    /// GLUT's redraw: reshape if the size changed, display, then draw what was recorded.
    fn redraw(&mut self, event_loop: &ActiveEventLoop) {
        let (Some(gpu), Some(gl)) = (self.gpu.as_mut(), self.gl.as_mut()) else { return };
        if let Some(e) = gpu.lost() {
            return self.fail(event_loop, e);
        }
        let size = gpu.window.inner_size();
        if size.width == 0 || size.height == 0 {
            return; // minimised: nothing to draw into
        }
        if (size.width, size.height) != (gpu.config.width, gpu.config.height) {
            gpu.resize(size);
        }
        let frame = match gpu.surface.get_current_texture() {
            wgpu::CurrentSurfaceTexture::Success(f) | wgpu::CurrentSurfaceTexture::Suboptimal(f) => f,
            wgpu::CurrentSurfaceTexture::Timeout | wgpu::CurrentSurfaceTexture::Occluded => return,
            wgpu::CurrentSurfaceTexture::Outdated => {
                gpu.resize(size);
                gpu.window.request_redraw();
                return;
            }
            wgpu::CurrentSurfaceTexture::Lost => {
                if let Err(e) = gpu.recreate_surface() {
                    return self.fail(event_loop, e);
                }
                gpu.window.request_redraw();
                return;
            }
            other => {
                let why = gpu.lost().unwrap_or_else(|| format!("{other:?}"));
                return self.fail(event_loop, format!("the window surface failed: {why}"));
            }
        };
        let (width, height) = (size.width, size.height);
        let program_changed = std::mem::take(&mut self.program_changed) || self.size != Some((width, height));
        if program_changed || self.last_frame.is_none() {
            gl.glut.elapsed_ms = self.start.elapsed().as_millis() as i32;
            if self.size != Some((width, height)) {
                self.size = Some((width, height));
                self.app.run_reshape(gl, width as i32, height as i32);
            }
            self.app.run_display(gl);
            let recorded = gl.take_frame();
            if let Some(previous) = self.last_frame.replace(recorded) {
                gl.recycle_frame(previous);
            }
        }
        let Some(recorded) = self.last_frame.as_ref() else { return };
        let view = frame.texture.create_view(&Default::default());
        let mut encoder = gpu.renderer.device.create_command_encoder(&Default::default());
        gpu.renderer.encode(recorded, &mut encoder, &view, &gpu.depth, (width, height), gpu.config.format);
        gpu.renderer.queue.submit([encoder.finish()]);
        // An open GLUT menu over the picture: a second pass that loads what the first drew.
        if let Some(menu) = self.app.menu_overlay(gl) {
            let mut encoder = gpu.renderer.device.create_command_encoder(&Default::default());
            gpu.renderer.encode_over(&menu, &mut encoder, &view, &gpu.depth, (width, height), gpu.config.format);
            gpu.renderer.queue.submit([encoder.finish()]);
        }
        gpu.window.pre_present_notify();
        gpu.renderer.queue.present(frame);
        self.frames_drawn += 1;
        if self.app.frames().is_some_and(|n| self.frames_drawn >= n) {
            return event_loop.exit();
        }
        self.after_callback();
    }

    /// Milliseconds since the main loop started.
    fn now_ms(&self) -> f64 {
        self.start.elapsed().as_secs_f64() * 1e3
    }

    /// Carries out what GLUT calls in the last callback asked for: the idle and timer
    /// changes, a redisplay, the window's title, size and full-screen state.
    fn after_callback(&mut self) {
        let now = self.now_ms();
        let (Some(gpu), Some(gl)) = (self.gpu.as_ref(), self.gl.as_mut()) else { return };
        self.schedule.absorb(gl, now);
        if std::mem::take(&mut gl.glut.redisplay) {
            self.program_changed = true;
            gpu.window.request_redraw();
        }
        if let Some(title) = gl.take_window_title() {
            gpu.window.set_title(&title);
        }
        if let Some((width, height)) = gl.glut.reshape.take() {
            // The reshape callback runs when the window system grants the size.
            let _ = gpu.window.request_inner_size(PhysicalSize::new(width as u32, height as u32));
        }
        if std::mem::take(&mut gl.glut.full_screen) {
            gpu.window.set_fullscreen(Some(Fullscreen::Borderless(None)));
        }
    }

    /// Runs an input callback with `glutGetModifiers` answering, then redraws if it ran (the
    /// convenience this runner has always offered: input changes what is drawn) and carries
    /// out its requests.
    fn input(&mut self, run: impl FnOnce(&mut App, &mut Gl) -> bool) {
        self.input_event(|app, gl| if run(app, gl) { Redraw::Program } else { Redraw::Nothing });
    }

    /// [`WindowState::input`] for events that may go to a menu instead of the program.
    fn input_event(&mut self, run: impl FnOnce(&mut App, &mut Gl) -> Redraw) {
        let Some(gl) = self.gl.as_mut() else { return };
        gl.glut.modifiers = self.modifiers;
        gl.glut.elapsed_ms = self.start.elapsed().as_millis() as i32;
        let redraw = run(&mut self.app, gl);
        gl.glut.modifiers = 0;
        self.request(redraw);
        self.after_callback();
    }

    /// Asks for the redraw an event needs.
    fn request(&mut self, redraw: Redraw) {
        if redraw == Redraw::Program {
            self.program_changed = true;
        }
        if let (Redraw::Menu | Redraw::Program, Some(gpu)) = (redraw, &self.gpu) {
            gpu.window.request_redraw();
        }
    }

    /// A key pressed or released: Escape (pressed) closes the window; a key that types text
    /// goes to the keyboard callbacks, a `GLUT_KEY_*` key to the special ones.
    fn key(&mut self, event_loop: &ActiveEventLoop, event: &KeyEvent) {
        let pressed = event.state == ElementState::Pressed;
        if pressed && event.logical_key == Key::Named(NamedKey::Escape) {
            if self.app.close_menu() {
                return self.request(Redraw::Menu);
            }
            return event_loop.exit();
        }
        let (x, y) = self.cursor;
        if let Some(code) = special_key(&event.logical_key) {
            return self.input(|app, gl| app.run_special(gl, !pressed, code, x, y));
        }
        // GLUT's keyboard callback gets the character typed (Enter is '\r', Backspace '\b').
        // A release carries no text: the logical key (layout and modifiers applied) gives it.
        let text = if pressed { event.text.as_deref() } else { key_text(&event.logical_key) };
        let Some(key) = text.and_then(|t| t.chars().next()) else { return };
        if pressed {
            self.input(|app, gl| {
                app.run_keyboard(gl, key, x, y);
                true
            });
        } else {
            self.input(|app, gl| app.run_keyboard_up(gl, key, x, y));
        }
    }

    /// After the events of a loop turn: due timers, the idle callback, then sleep until the
    /// next timer (or not at all while an idle callback is set, as GLUT's loop spins).
    fn idle(&mut self, event_loop: &ActiveEventLoop) {
        let now = self.now_ms();
        if let Some(gl) = self.gl.as_mut() {
            gl.glut.elapsed_ms = now as i32;
            self.schedule.fire_due(gl, now);
            self.schedule.run_idle(gl, now);
        }
        self.after_callback();
        let flow = if self.schedule.has_idle() {
            ControlFlow::Poll
        } else if let Some(due) = self.schedule.next_due_ms() {
            ControlFlow::WaitUntil(self.start + Duration::from_secs_f64(due.max(0.0) / 1e3))
        } else {
            ControlFlow::Wait
        };
        event_loop.set_control_flow(flow);
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
                let mut gl = Gl::new(size.width.max(1) as i32, size.height.max(1) as i32);
                gl.set_tessellator(self.app.tessellator());
                self.app.run_init(&mut gl);
                self.schedule = self.app.take_schedule(0.0);
                self.start = Instant::now();
                self.gl = Some(gl);
                gpu.window.request_redraw();
                self.gpu = Some(gpu);
            }
            Err(e) => self.fail(event_loop, e),
        }
    }

    fn window_event(&mut self, event_loop: &ActiveEventLoop, _id: WindowId, event: WindowEvent) {
        match event {
            WindowEvent::CloseRequested | WindowEvent::Destroyed => event_loop.exit(),
            WindowEvent::Resized(size) => {
                if let Some(gpu) = self.gpu.as_mut() {
                    gpu.resize(size);
                    gpu.window.request_redraw();
                }
                self.program_changed = true;
            }
            WindowEvent::RedrawRequested => self.redraw(event_loop),
            WindowEvent::CursorMoved { position, .. } => {
                self.cursor = (position.x as i32, position.y as i32);
                let (x, y) = self.cursor;
                let held = self.buttons_down > 0;
                self.input_event(|app, gl| app.pointer_moved(gl, x, y, held));
            }
            WindowEvent::CursorEntered { .. } => self.input(|app, gl| app.run_entry(gl, GLUT_ENTERED)),
            WindowEvent::CursorLeft { .. } => self.input(|app, gl| app.run_entry(gl, GLUT_LEFT)),
            WindowEvent::ModifiersChanged(modifiers) => self.modifiers = glut_modifiers(&modifiers),
            WindowEvent::MouseInput { state, button, .. } => {
                let button = match button {
                    MouseButton::Left => GLUT_LEFT_BUTTON,
                    MouseButton::Middle => GLUT_MIDDLE_BUTTON,
                    MouseButton::Right => GLUT_RIGHT_BUTTON,
                    _ => return,
                };
                let down = state == ElementState::Pressed;
                self.buttons_down = if down { self.buttons_down + 1 } else { self.buttons_down.saturating_sub(1) };
                let (x, y) = self.cursor;
                let glut_state = if down { GLUT_DOWN } else { GLUT_UP };
                self.input_event(|app, gl| app.mouse_button(gl, button, glut_state, x, y));
            }
            WindowEvent::KeyboardInput { event, .. } => self.key(event_loop, &event),
            _ => {}
        }
    }

    fn about_to_wait(&mut self, event_loop: &ActiveEventLoop) {
        self.idle(event_loop);
    }

    fn exiting(&mut self, _event_loop: &ActiveEventLoop) {
        // Drop the surface before the window it was made from.
        self.gpu = None;
    }
}

/// The `GLUT_KEY_*` code of a key GLUT reports to `glutSpecialFunc`.
fn special_key(key: &Key) -> Option<i32> {
    let Key::Named(named) = key else { return None };
    let function_keys = [
        NamedKey::F1,
        NamedKey::F2,
        NamedKey::F3,
        NamedKey::F4,
        NamedKey::F5,
        NamedKey::F6,
        NamedKey::F7,
        NamedKey::F8,
        NamedKey::F9,
        NamedKey::F10,
        NamedKey::F11,
        NamedKey::F12,
    ];
    if let Some(k) = function_keys.iter().position(|f| f == named) {
        return Some(GLUT_KEY_F1 + k as i32);
    }
    Some(match named {
        NamedKey::ArrowLeft => GLUT_KEY_LEFT,
        NamedKey::ArrowUp => GLUT_KEY_UP,
        NamedKey::ArrowRight => GLUT_KEY_RIGHT,
        NamedKey::ArrowDown => GLUT_KEY_DOWN,
        NamedKey::PageUp => GLUT_KEY_PAGE_UP,
        NamedKey::PageDown => GLUT_KEY_PAGE_DOWN,
        NamedKey::Home => GLUT_KEY_HOME,
        NamedKey::End => GLUT_KEY_END,
        NamedKey::Insert => GLUT_KEY_INSERT,
        _ => return None,
    })
}

/// The character a released key typed, as GLUT's keyboard callbacks get it.
fn key_text(key: &Key) -> Option<&str> {
    match key {
        Key::Character(text) => Some(text.as_str()),
        Key::Named(NamedKey::Enter) => Some("\r"),
        Key::Named(NamedKey::Backspace) => Some("\u{8}"),
        Key::Named(NamedKey::Tab) => Some("\t"),
        Key::Named(NamedKey::Space) => Some(" "),
        Key::Named(NamedKey::Escape) => Some("\u{1b}"),
        Key::Named(NamedKey::Delete) => Some("\u{7f}"),
        _ => None,
    }
}

/// `glutGetModifiers`'s bits for the modifier keys held.
fn glut_modifiers(modifiers: &Modifiers) -> i32 {
    let state = modifiers.state();
    let mut bits = 0;
    if state.shift_key() {
        bits |= GLUT_ACTIVE_SHIFT;
    }
    if state.control_key() {
        bits |= GLUT_ACTIVE_CTRL;
    }
    if state.alt_key() {
        bits |= GLUT_ACTIVE_ALT;
    }
    bits
}
