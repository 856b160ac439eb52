//! The windowed mode of [`App`]: a winit 0.30 window with a wgpu surface for each top-level GLUT
//! window, redrawn like GLUT windows (reshape when the size changes, display when asked). Each
//! window's [`Gl`] context lives as long as the window, so GL state set in `init` or in earlier
//! frames persists. Subwindows are drawn by the CPU rasteriser and copied into their parent's
//! surface in place; input over a subwindow goes to its callbacks, in its own coordinates.

use crate::app::program::Program;
use crate::app::{App, Redraw};
use crate::gl::Gl;
use crate::glut::consts::*;
use crate::glut::windows::WindowRequest;
use crate::gpu::Attachments;
use crate::render::soft;
use std::collections::HashMap;
use std::error::Error;
use std::time::{Duration, Instant};
use winit::application::ApplicationHandler;
use winit::dpi::{PhysicalPosition, PhysicalSize};
use winit::event::{ElementState, KeyEvent, MouseButton, MouseScrollDelta, WindowEvent};
use winit::event_loop::{ActiveEventLoop, ControlFlow, EventLoop};
use winit::keyboard::{Key, NamedKey};
use winit::window::{Fullscreen, WindowId};

mod input;
mod surface;

use input::{cursor_icon, glut_modifiers, key_text, special_key};
use surface::Gpu;

/// A program whose windowed loop the program drives itself (`glutMainLoopEvent`): each pass
/// handles the events waiting, runs the callbacks they call for and draws what must be drawn,
/// then returns to the program.
#[cfg(any(target_os = "linux", target_os = "windows", target_os = "macos", target_os = "freebsd"))]
pub(crate) struct Pumped {
    event_loop: EventLoop<()>,
    state: WindowState,
}

#[cfg(any(target_os = "linux", target_os = "windows", target_os = "macos", target_os = "freebsd"))]
impl Pumped {
    /// The program's windows, not yet open (the first pass opens them).
    pub(crate) fn new(app: App) -> Result<Self, Box<dyn Error>> {
        let event_loop = connect()?;
        Ok(Self { event_loop, state: WindowState::new(app) })
    }

    /// One pass of the loop; `Some(exit)` once the loop is over (its windows closed), `exit`
    /// as [`run`]'s.
    pub(crate) fn pass(&mut self) -> Result<Option<bool>, Box<dyn Error>> {
        use winit::platform::pump_events::{EventLoopExtPumpEvents, PumpStatus};
        let status = self.event_loop.pump_app_events(Some(Duration::ZERO), &mut self.state);
        if let Some(e) = self.state.error.take() {
            return Err(e.into());
        }
        Ok(match status {
            PumpStatus::Continue => None,
            PumpStatus::Exit(_) => {
                let finish = self.state.program.finish();
                Some(self.state.exit || finish)
            }
        })
    }
}

/// The display's event loop, or why there is none.
fn connect() -> Result<EventLoop<()>, Box<dyn Error>> {
    const USE_PNG: &str = "run the program with --png PATH to render one frame to a PNG file instead";
    let has_display = ["DISPLAY", "WAYLAND_DISPLAY"].iter().any(|v| std::env::var_os(v).is_some_and(|s| !s.is_empty()));
    if !has_display {
        return Err(
            format!("no display to open a window on (neither DISPLAY nor WAYLAND_DISPLAY is set); {USE_PNG}").into()
        );
    }
    Ok(EventLoop::new().map_err(|e| format!("could not connect to the display ({e}); {USE_PNG}"))?)
}

/// Opens the program's windows and runs until the loop ends (the last window closed,
/// `glutLeaveMainLoop`, Escape); true if the program should exit rather than return from
/// `glutMainLoop` (freeglut's `GLUT_ACTION_ON_WINDOW_CLOSE`).
pub(crate) fn run(app: App) -> Result<bool, Box<dyn Error>> {
    let event_loop = connect()?;
    let mut state = WindowState::new(app);
    event_loop.run_app(&mut state)?;
    if let Some(e) = state.error {
        return Err(e.into());
    }
    let finish = state.program.finish();
    Ok(state.exit || finish)
}

/// A top-level window on the screen.
struct OnScreen {
    id: i32,
    gpu: Gpu,
    /// The size the reshape callback last saw.
    size: Option<(u32, u32)>,
}

struct WindowState {
    program: Program,
    /// The top-level windows on the screen, by winit's id.
    windows: HashMap<WindowId, OnScreen>,
    started: bool,
    /// The pointer in its window's pixels (origin top left, as GLUT reports it).
    cursor: (i32, i32),
    /// The top-level window the pointer is in.
    pointer_in: Option<WindowId>,
    /// Mouse buttons held (motion callbacks run only then, as GLUT's).
    buttons_down: u32,
    /// `GLUT_ACTIVE_*` bits of the modifier keys held.
    modifiers: i32,
    /// When the main loop started: `GLUT_ELAPSED_TIME` and the timers count from here.
    start: Instant,
    /// `--frames N`: the loop ends after N frames.
    frames: Option<usize>,
    frames_drawn: usize,
    /// A window closed with `GLUT_ACTION_EXIT`.
    exit: bool,
    /// The wheel's last motion and when it came.
    last_wheel: Option<(MouseScrollDelta, Instant)>,
    error: Option<String>,
}

impl WindowState {
    fn new(app: App) -> Self {
        let frames = app.frames();
        Self {
            program: Program::new(app),
            windows: HashMap::new(),
            started: false,
            cursor: (0, 0),
            pointer_in: None,
            buttons_down: 0,
            modifiers: 0,
            start: Instant::now(),
            frames,
            frames_drawn: 0,
            exit: false,
            last_wheel: None,
            error: None,
        }
    }

    fn fail(&mut self, event_loop: &ActiveEventLoop, error: String) {
        self.error = Some(error);
        event_loop.exit();
    }

    fn winit_id(&self, id: i32) -> Option<WindowId> {
        self.windows.iter().find(|(_, w)| w.id == id).map(|(k, _)| *k)
    }

    /// The top-level window that window `id` is drawn in.
    fn top_of(&self, mut id: i32) -> i32 {
        while let Some(k) = self.program.index(id) {
            let parent = self.program.slots[k].facts.parent;
            if parent == 0 {
                break;
            }
            id = parent;
        }
        id
    }

    /// Opens a winit window for every top-level GLUT window that has none.
    fn open_windows(&mut self, event_loop: &ActiveEventLoop) -> Result<(), String> {
        for k in self.program.top_level() {
            let id = self.program.slots[k].facts.id;
            if self.winit_id(id).is_some() {
                continue;
            }
            let slot = &self.program.slots[k];
            let gpu = Gpu::new(event_loop, slot.app.title(), &slot.facts, slot.app.placed())?;
            let size = gpu.window.inner_size();
            let slot = &mut self.program.slots[k];
            (slot.facts.width, slot.facts.height) = (size.width.max(1) as i32, size.height.max(1) as i32);
            if slot.iconic {
                gpu.window.set_minimized(true);
            }
            // The program's first reshape is at this size: no second one at the first redraw.
            let first = Some((size.width, size.height));
            self.windows.insert(gpu.window.id(), OnScreen { id, gpu, size: first });
        }
        Ok(())
    }

    /// GLUT's redraw of a top-level window: the reshape and display callbacks that are due
    /// (of every window), then this window's last frame with its subwindows over it.
    fn redraw(&mut self, event_loop: &ActiveEventLoop, winit: WindowId) {
        let Some(on) = self.windows.get_mut(&winit) else { return };
        if let Some(e) = on.gpu.lost() {
            return self.fail(event_loop, e);
        }
        let size = on.gpu.window.inner_size();
        if size.width == 0 || size.height == 0 {
            return; // minimised: nothing to draw into
        }
        let id = on.id;
        if on.size != Some((size.width, size.height)) {
            on.size = Some((size.width, size.height));
            if let Some(k) = self.program.index(id) {
                self.program.slots[k].reshape = Some((size.width as i32, size.height as i32));
                self.program.slots[k].redisplay = true;
            }
        }
        self.program.now_ms = self.now_ms();
        self.program.display_pending();
        self.after_callbacks(event_loop);
        if let Err(e) = self.present(winit, size) {
            return self.fail(event_loop, e);
        }
        self.frames_drawn += 1;
        if self.frames.is_some_and(|n| self.frames_drawn >= n) {
            event_loop.exit();
        }
    }

    /// Draws window `winit`'s last frame, its subwindows and an open menu, and presents it.
    fn present(&mut self, winit: WindowId, size: PhysicalSize<u32>) -> Result<(), String> {
        let Some(on) = self.windows.get_mut(&winit) else { return Ok(()) };
        let Some(k) = self.program.index(on.id) else { return Ok(()) };
        let gpu = &mut on.gpu;
        if (size.width, size.height) != (gpu.config.width, gpu.config.height) {
            gpu.resize(size);
        }
        let frame = match gpu.surface.get_current_texture() {
            wgpu::CurrentSurfaceTexture::Success(f) | wgpu::CurrentSurfaceTexture::Suboptimal(f) => f,
            wgpu::CurrentSurfaceTexture::Timeout | wgpu::CurrentSurfaceTexture::Occluded => return Ok(()),
            wgpu::CurrentSurfaceTexture::Outdated => {
                gpu.resize(size);
                gpu.window.request_redraw();
                return Ok(());
            }
            wgpu::CurrentSurfaceTexture::Lost => {
                gpu.recreate_surface()?;
                gpu.window.request_redraw();
                return Ok(());
            }
            other => {
                let why = gpu.lost().unwrap_or_else(|| format!("{other:?}"));
                return Err(format!("the window surface failed: {why}"));
            }
        };
        let (width, height) = (size.width, size.height);
        let view = frame.texture.create_view(&Default::default());
        let slot = &mut self.program.slots[k];
        let mut encoder = gpu.renderer.device.create_command_encoder(&Default::default());
        gpu.renderer.encode(slot.gl.frame(), &mut encoder, &view, &gpu.depth, (width, height), gpu.config.format);
        gpu.renderer.queue.submit([encoder.finish()]);
        let id = slot.facts.id;
        compose(&mut self.program, gpu, &frame.texture, id, (0, 0));
        let slot = &mut self.program.slots[k];
        // An open GLUT menu over the picture: a second pass that loads what the first drew.
        if let Some(menu) = slot.app.menu_overlay(&slot.gl) {
            let mut encoder = gpu.renderer.device.create_command_encoder(&Default::default());
            let target = Attachments::window(&view, &gpu.depth, (width, height), gpu.config.format);
            gpu.renderer.encode_over(&menu, &mut encoder, &target);
            gpu.renderer.queue.submit([encoder.finish()]);
        }
        gpu.window.pre_present_notify();
        gpu.renderer.queue.present(frame);
        Ok(())
    }

    /// Milliseconds since the main loop started.
    fn now_ms(&self) -> f64 {
        self.start.elapsed().as_secs_f64() * 1e3
    }

    /// Carries out what the callbacks asked of the windows: redraws, titles, sizes, places,
    /// full screen, cursors, closing; the loop ends when they left it.
    fn after_callbacks(&mut self, event_loop: &ActiveEventLoop) {
        for (id, effect) in std::mem::take(&mut self.program.effects) {
            self.carry_out(id, &effect);
        }
        for slot in &self.program.slots {
            if slot.redisplay || slot.reshape.is_some() {
                let top = self.top_of(slot.facts.id);
                if let Some(on) = self.winit_id(top).and_then(|w| self.windows.get(&w)) {
                    on.gpu.window.request_redraw();
                }
            }
        }
        if self.program.leave {
            event_loop.exit();
        }
    }

    fn carry_out(&mut self, id: i32, effect: &WindowRequest) {
        if *effect == WindowRequest::Destroy {
            if let Some(w) = self.winit_id(id) {
                self.windows.remove(&w);
            }
            return;
        }
        let top = self.top_of(id);
        let Some(on) = self.winit_id(top).and_then(|w| self.windows.get(&w)) else { return };
        let window = &on.gpu.window;
        let own = top == id;
        match effect {
            WindowRequest::Title(title) if own => window.set_title(title),
            WindowRequest::Reshape(w, h) if own => {
                let _ = window.request_inner_size(PhysicalSize::new(*w as u32, *h as u32));
            }
            WindowRequest::Position(x, y) if own => window.set_outer_position(PhysicalPosition::new(*x, *y)),
            WindowRequest::Show if own => {
                window.set_visible(true);
                window.set_minimized(false);
            }
            WindowRequest::Hide if own => window.set_visible(false),
            WindowRequest::Iconify if own => window.set_minimized(true),
            WindowRequest::FullScreen if own => window.set_fullscreen(Some(Fullscreen::Borderless(None))),
            WindowRequest::LeaveFullScreen if own => window.set_fullscreen(None),
            WindowRequest::FullScreenToggle if own => {
                let full = window.fullscreen().is_none();
                window.set_fullscreen(full.then_some(Fullscreen::Borderless(None)));
            }
            WindowRequest::Cursor(c) => window.set_cursor(cursor_icon(*c)),
            WindowRequest::WarpPointer(x, y) => {
                let (ox, oy) = self.offset_in_top(id);
                let _ = window.set_cursor_position(PhysicalPosition::new(x + ox, y + oy));
            }
            _ => window.request_redraw(),
        }
    }

    /// Where window `id`'s top left corner is in its top-level window.
    fn offset_in_top(&self, mut id: i32) -> (i32, i32) {
        let (mut x, mut y) = (0, 0);
        while let Some(k) = self.program.index(id) {
            let f = self.program.slots[k].facts;
            if f.parent == 0 {
                break;
            }
            (x, y) = (x + f.x, y + f.y);
            id = f.parent;
        }
        (x, y)
    }

    /// The window under the pointer in top-level window `top`: its deepest shown subwindow
    /// there (the topmost of siblings), with the pointer in that window's coordinates.
    fn hit(&self, top: i32, (x, y): (i32, i32)) -> (usize, i32, i32) {
        let mut k = self.program.index(top).unwrap_or(0);
        let (mut lx, mut ly) = (x, y);
        'descend: loop {
            let id = self.program.slots[k].facts.id;
            for child in self.program.children(id).into_iter().rev() {
                let f = self.program.slots[child].facts;
                if f.shown && lx >= f.x && ly >= f.y && lx < f.x + f.width && ly < f.y + f.height {
                    (k, lx, ly) = (child, lx - f.x, ly - f.y);
                    continue 'descend;
                }
            }
            return (k, lx, ly);
        }
    }

    /// Runs an input event's callbacks in the window under the pointer, with
    /// `glutGetModifiers` answering; redraws that window if the program ran.
    fn input_event(&mut self, event_loop: &ActiveEventLoop, run: impl FnOnce(&mut App, &mut Gl, i32, i32) -> Redraw) {
        let Some(top) = self.pointer_in.and_then(|w| self.windows.get(&w)).map(|on| on.id) else { return };
        let (k, x, y) = self.hit(top, self.cursor);
        self.program.now_ms = self.now_ms();
        let modifiers = self.modifiers;
        let redraw = self.program.callback(k, |app, gl| {
            gl.glut.modifiers = modifiers;
            let redraw = run(app, gl, x, y);
            gl.glut.modifiers = 0;
            redraw
        });
        match redraw {
            Redraw::Program => self.program.slots.get_mut(k).into_iter().for_each(|s| s.redisplay = true),
            Redraw::Menu => {
                if let Some(on) = self.windows.get(&self.pointer_in.expect("checked above")) {
                    on.gpu.window.request_redraw();
                }
            }
            Redraw::Nothing => {}
        }
        self.after_callbacks(event_loop);
    }

    /// A key pressed or released: Escape (pressed) closes an open menu or ends the program; a
    /// key that types text goes to the keyboard callbacks, a `GLUT_KEY_*` key to the special
    /// ones. A held key's repeats are dropped when `glutSetKeyRepeat(GLUT_KEY_REPEAT_OFF)` or
    /// the window's `glutIgnoreKeyRepeat` says so; otherwise each repeat is a release and a
    /// press, as X reports them to freeglut.
    fn key(&mut self, event_loop: &ActiveEventLoop, event: &KeyEvent) {
        let pressed = event.state == ElementState::Pressed;
        if pressed && event.logical_key == Key::Named(NamedKey::Escape) {
            let closed = self.pointer_in.and_then(|w| self.windows.get(&w)).and_then(|on| self.program.index(on.id));
            if let Some(k) = closed {
                if self.program.callback(k, |app, gl| app.close_menu(gl)) {
                    return self.after_callbacks(event_loop);
                }
            }
            return event_loop.exit();
        }
        if event.repeat {
            let Some(top) = self.pointer_in.and_then(|w| self.windows.get(&w)).map(|on| on.id) else { return };
            let (k, _, _) = self.hit(top, self.cursor);
            let ignore = self.program.slots[k].facts.ignore_key_repeat;
            if ignore || self.program.options().key_repeat == GLUT_KEY_REPEAT_OFF {
                return;
            }
            self.key_callbacks(event_loop, event, false);
        }
        self.key_callbacks(event_loop, event, pressed);
    }

    fn key_callbacks(&mut self, event_loop: &ActiveEventLoop, event: &KeyEvent, pressed: bool) {
        if let Some(code) = special_key(&event.logical_key) {
            return self.input_event(event_loop, |app, gl, x, y| {
                let ran = app.run_special(gl, !pressed, code, x, y);
                if ran {
                    Redraw::Program
                } else {
                    Redraw::Nothing
                }
            });
        }
        // GLUT's keyboard callback gets the character typed (Enter is '\r', Backspace '\b').
        // A release carries no text: the logical key (layout and modifiers applied) gives it.
        let text = if pressed {
            event.text.as_deref().or_else(|| key_text(&event.logical_key))
        } else {
            key_text(&event.logical_key)
        };
        let Some(key) = text.and_then(|t| t.chars().next()) else { return };
        self.input_event(event_loop, |app, gl, x, y| {
            if pressed {
                app.run_keyboard(gl, key, x, y);
                Redraw::Program
            } else if app.run_keyboard_up(gl, key, x, y) {
                Redraw::Program
            } else {
                Redraw::Nothing
            }
        });
    }

    /// After the events of a loop turn: due timers, the idle callback, then sleep until the
    /// next timer (or not at all while an idle callback is set, as GLUT's loop spins).
    fn idle(&mut self, event_loop: &ActiveEventLoop) {
        let now = self.now_ms();
        let swaps = self.program.buffer_swaps();
        self.program.step(now - self.program.now_ms);
        // A window whose idle callback or timer swapped its buffers without posting a
        // redisplay shows that frame (freeglut presents at the swap itself).
        for (id, count) in self.program.buffer_swaps() {
            if !swaps.contains(&(id, count)) {
                let top = self.top_of(id);
                if let Some(on) = self.winit_id(top).and_then(|w| self.windows.get(&w)) {
                    on.gpu.window.request_redraw();
                }
            }
        }
        self.after_callbacks(event_loop);
        let flow = if self.program.schedule.has_idle() {
            ControlFlow::Poll
        } else if let Some(due) = self.program.schedule.next_due_ms() {
            ControlFlow::WaitUntil(self.start + Duration::from_secs_f64(due.max(0.0) / 1e3))
        } else {
            ControlFlow::Wait
        };
        event_loop.set_control_flow(flow);
    }

    fn mouse_input(&mut self, event_loop: &ActiveEventLoop, state: ElementState, button: MouseButton) {
        let button = match button {
            MouseButton::Left => GLUT_LEFT_BUTTON,
            MouseButton::Middle => GLUT_MIDDLE_BUTTON,
            MouseButton::Right => GLUT_RIGHT_BUTTON,
            // X's buttons 8 and 9 (back, forward) are GLUT's 7 and 8, as freeglut reports them.
            MouseButton::Back => 7,
            MouseButton::Forward => 8,
            MouseButton::Other(n) => i32::from(n),
        };
        let down = state == ElementState::Pressed;
        self.buttons_down = if down { self.buttons_down + 1 } else { self.buttons_down.saturating_sub(1) };
        let glut_state = if down { GLUT_DOWN } else { GLUT_UP };
        self.input_event(event_loop, |app, gl, x, y| app.mouse_button(gl, button, glut_state, x, y));
    }

    fn wheel(&mut self, event_loop: &ActiveEventLoop, delta: MouseScrollDelta) {
        let notches = match delta {
            MouseScrollDelta::LineDelta(_, y) => y.round() as i32,
            MouseScrollDelta::PixelDelta(p) => (p.y / 20.0).round() as i32,
        };
        for _ in 0..notches.unsigned_abs() {
            let direction = notches.signum();
            self.input_event(event_loop, |app, gl, x, y| {
                if app.run_wheel(gl, direction, x, y) {
                    Redraw::Program
                } else {
                    Redraw::Nothing
                }
            });
        }
    }
}

/// Copies window `id`'s subwindows (drawn by the CPU rasteriser) into `target` at their places,
/// `origin` being `id`'s corner in the top-level window; their subwindows after them.
fn compose(program: &mut Program, gpu: &Gpu, target: &wgpu::Texture, id: i32, origin: (i32, i32)) {
    if !target.usage().contains(wgpu::TextureUsages::COPY_DST) {
        return;
    }
    for child in program.children(id) {
        let f = program.slots[child].facts;
        if !f.shown {
            continue;
        }
        let (x, y) = (origin.0 + f.x, origin.1 + f.y);
        let image = soft::render_frame(program.slots[child].gl.frame(), f.width.max(1) as u32, f.height.max(1) as u32);
        write_image(gpu, target, &image, x, y);
        compose(program, gpu, target, f.id, (x, y));
    }
}

/// Writes an RGBA image into the surface texture at (x, y), clipped to it.
fn write_image(gpu: &Gpu, target: &wgpu::Texture, image: &crate::render::Image, x: i32, y: i32) {
    let (tw, th) = (target.width() as i32, target.height() as i32);
    let (x0, y0) = (x.max(0), y.max(0));
    let (x1, y1) = ((x + image.width as i32).min(tw), (y + image.height as i32).min(th));
    if x0 >= x1 || y0 >= y1 {
        return;
    }
    let bgra = matches!(target.format(), wgpu::TextureFormat::Bgra8Unorm | wgpu::TextureFormat::Bgra8UnormSrgb);
    let mut bytes = Vec::with_capacity(((x1 - x0) * (y1 - y0) * 4) as usize);
    for row in y0..y1 {
        let start = (((row - y) * image.width as i32 + (x0 - x)) * 4) as usize;
        for px in image.pixels[start..start + ((x1 - x0) * 4) as usize].chunks_exact(4) {
            if bgra {
                bytes.extend_from_slice(&[px[2], px[1], px[0], px[3]]);
            } else {
                bytes.extend_from_slice(px);
            }
        }
    }
    gpu.renderer.queue.write_texture(
        wgpu::TexelCopyTextureInfo {
            texture: target,
            mip_level: 0,
            origin: wgpu::Origin3d { x: x0 as u32, y: y0 as u32, z: 0 },
            aspect: wgpu::TextureAspect::All,
        },
        &bytes,
        wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(((x1 - x0) * 4) as u32), rows_per_image: None },
        wgpu::Extent3d { width: (x1 - x0) as u32, height: (y1 - y0) as u32, depth_or_array_layers: 1 },
    );
    gpu.renderer.queue.submit([]);
}

impl ApplicationHandler for WindowState {
    fn resumed(&mut self, event_loop: &ActiveEventLoop) {
        if self.started {
            return;
        }
        self.started = true;
        if let Err(e) = self.open_windows(event_loop) {
            return self.fail(event_loop, e);
        }
        self.start = Instant::now();
        self.program.start();
        self.after_callbacks(event_loop);
        for on in self.windows.values() {
            on.gpu.window.request_redraw();
        }
    }

    fn window_event(&mut self, event_loop: &ActiveEventLoop, winit: WindowId, event: WindowEvent) {
        match event {
            WindowEvent::CloseRequested => {
                let Some(id) = self.windows.get(&winit).map(|on| on.id) else { return };
                self.exit |= self.program.close_by_user(id);
                self.windows.remove(&winit);
                if self.exit {
                    event_loop.exit();
                }
                self.after_callbacks(event_loop);
            }
            WindowEvent::Destroyed => {}
            WindowEvent::Resized(size) => {
                if let Some(on) = self.windows.get_mut(&winit) {
                    on.gpu.resize(size);
                    on.gpu.window.request_redraw();
                }
            }
            WindowEvent::Moved(position) => {
                let Some(k) = self.windows.get(&winit).and_then(|on| self.program.index(on.id)) else { return };
                (self.program.slots[k].facts.x, self.program.slots[k].facts.y) = (position.x, position.y);
                self.program.refresh();
                self.program.callback(k, |app, gl| app.run_position(gl, position.x, position.y));
                self.after_callbacks(event_loop);
            }
            WindowEvent::RedrawRequested => self.redraw(event_loop, winit),
            WindowEvent::CursorMoved { position, .. } => {
                self.pointer_in = Some(winit);
                self.cursor = (position.x as i32, position.y as i32);
                let held = self.buttons_down > 0;
                self.input_event(event_loop, |app, gl, x, y| app.pointer_moved(gl, x, y, held));
            }
            WindowEvent::CursorEntered { .. } => {
                self.pointer_in = Some(winit);
                self.input_event(event_loop, |app, gl, _, _| Redraw::program_if(app.run_entry(gl, GLUT_ENTERED)));
            }
            WindowEvent::CursorLeft { .. } => {
                self.input_event(event_loop, |app, gl, _, _| Redraw::program_if(app.run_entry(gl, GLUT_LEFT)));
            }
            WindowEvent::ModifiersChanged(modifiers) => self.modifiers = glut_modifiers(&modifiers),
            WindowEvent::MouseInput { state, button, .. } => {
                self.pointer_in = Some(winit);
                self.mouse_input(event_loop, state, button);
            }
            WindowEvent::MouseWheel { delta, .. } => {
                self.pointer_in = Some(winit);
                // X reports a click of a wheel button made by XTEST (xdotool) twice, as the
                // button and as the scroll valuator's motion, at once; freeglut sees the button
                // once. The same motion again within 25 ms (faster than a hand turns a wheel) is
                // that echo.
                let now = Instant::now();
                let echo = self.last_wheel.is_some_and(|(d, t)| d == delta && now - t < Duration::from_millis(25));
                self.last_wheel = Some((delta, now));
                if !echo {
                    self.wheel(event_loop, delta);
                }
            }
            // winit makes up presses of the keys held when a window gains the focus; X tells
            // freeglut of no such key, so neither does this.
            WindowEvent::KeyboardInput { is_synthetic: true, .. } => {}
            WindowEvent::KeyboardInput { event, .. } => {
                self.pointer_in.get_or_insert(winit);
                self.key(event_loop, &event);
            }
            _ => {}
        }
    }

    fn about_to_wait(&mut self, event_loop: &ActiveEventLoop) {
        if self.started {
            self.idle(event_loop);
        }
    }

    fn exiting(&mut self, _event_loop: &ActiveEventLoop) {
        // Drop the surfaces before the windows they were made from.
        self.windows.clear();
    }
}
