//! A GLUT-like runner: `App::new(title, w, h).reshape(..).display(..).run()`.
//!
//! `run()` renders one frame headless to a PNG when the program was started with
//! `--png PATH`, and otherwise opens a window (feature `window`) that redraws on resize.
//! Callbacks take the [`Gl`] context, which keeps its state from frame to frame as a GL
//! context does; `gl.glut_get(GLUT_WINDOW_WIDTH)` answers inside them.

mod callbacks;
mod compose;
mod headless;
mod options;
pub(crate) mod program;
mod running;

pub use callbacks::{Int2Fn, Int3Fn, Int4Fn, Int5Fn, IntFn, JoystickFn, VoidFn};
pub use options::Options;
pub use running::{Pass, Running};

use crate::gl::{Frame, Gl, Tessellator};
use crate::glut::consts::{GLUT_DOWN, GLUT_UP};
use crate::glut::popup::{Popup, PopupEvent};
use crate::glut::state::TimerRequest;
use crate::glut::windows::WindowRequest;
use crate::glut::{IdleFn, Schedule};
use crate::render::Rasterizer;
use headless::window_reader;
pub(crate) use headless::Headless;
use program::Program;

type DisplayFn = Box<dyn FnMut(&mut Gl)>;
type ReshapeFn = Box<dyn FnMut(&mut Gl, i32, i32)>;
type KeyboardFn = Box<dyn FnMut(&mut Gl, char, i32, i32)>;
type SpecialFn = Box<dyn FnMut(&mut Gl, i32, i32, i32)>;
type MouseFn = Box<dyn FnMut(&mut Gl, i32, i32, i32, i32)>;
type MotionFn = Box<dyn FnMut(&mut Gl, i32, i32)>;
type EntryFn = Box<dyn FnMut(&mut Gl, i32)>;

/// What an input event asks of the window.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Redraw {
    /// Nothing changed.
    Nothing,
    /// Only the open menu changed: the program's last frame is shown again under it.
    Menu,
    /// A program callback ran: the display callback draws again (the convenience this
    /// runner has always offered: input changes what is drawn).
    Program,
}

impl Redraw {
    pub(crate) fn program_if(ran: bool) -> Self {
        if ran {
            Self::Program
        } else {
            Self::Nothing
        }
    }
}

/// A GLUT-style program: window size, title and callbacks.
pub struct App {
    title: String,
    width: i32,
    height: i32,
    init: Option<DisplayFn>,
    reshape: Option<ReshapeFn>,
    display: Option<DisplayFn>,
    keyboard: Option<KeyboardFn>,
    mouse: Option<MouseFn>,
    motion: Option<MotionFn>,
    passive_motion: Option<MotionFn>,
    keyboard_up: Option<KeyboardFn>,
    special: Option<SpecialFn>,
    special_up: Option<SpecialFn>,
    entry: Option<EntryFn>,
    idle: Option<IdleFn>,
    timers: Vec<TimerRequest>,
    display_mode: u32,
    /// `--frames N`: how many frames a run draws before it stops (headless: renders the last).
    frames: Option<usize>,
    tessellator: Tessellator,
    rasterizer: Rasterizer,
    /// The GLUT menu open in the window, if any.
    popup: Option<Popup>,
    /// Where the open menu was opened (for `glutMenuStatusFunc`).
    menu_at: (i32, i32),
    /// `glutInitWindowPosition` (a subwindow's place in its parent).
    position: Option<(i32, i32)>,
    /// The screen's size, as the window system says it (`GLUT_SCREEN_WIDTH`/`HEIGHT`); unset,
    /// GLUT answers the window's size.
    screen: Option<(i32, i32)>,
    /// The program's other windows, in creation order, each with its parent's number (0 for
    /// a top-level window); this window is number 1.
    extra: Vec<(i32, App)>,
    /// A context made before the main loop (the C ABI's `glutCreateWindow`), used instead of a
    /// fresh one.
    context: Option<Box<Gl>>,
    /// The callbacks beyond GLUT's first ones.
    more: callbacks::More,
    /// `-gldebug`: GL errors are reported after each display callback.
    gl_debug: bool,
}

impl App {
    /// `glutInitWindowSize(width, height)` + `glutCreateWindow(title)`.
    #[must_use]
    pub fn new(title: &str, width: i32, height: i32) -> Self {
        Self {
            title: title.to_owned(),
            width: width.max(1),
            height: height.max(1),
            init: None,
            reshape: None,
            display: None,
            keyboard: None,
            mouse: None,
            motion: None,
            passive_motion: None,
            keyboard_up: None,
            special: None,
            special_up: None,
            entry: None,
            idle: None,
            timers: Vec::new(),
            display_mode: 0,
            frames: None,
            tessellator: Tessellator::from_env(),
            rasterizer: Rasterizer::from_env(),
            popup: None,
            menu_at: (0, 0),
            position: None,
            screen: None,
            extra: Vec::new(),
            context: None,
            more: callbacks::More::default(),
            gl_debug: false,
        }
    }

    /// `glutInitWindowPosition(x, y)` for this window: where it opens on the screen (the
    /// window system may place it elsewhere).
    #[must_use]
    pub fn position(mut self, x: i32, y: i32) -> Self {
        self.position = Some((x, y));
        self
    }

    /// The screen's size in pixels, for `glutGet(GLUT_SCREEN_WIDTH)` and `GLUT_SCREEN_HEIGHT`
    /// (and their millimetres at 100 dots an inch): the C ABI gives the X screen's where there
    /// is a display, as freeglut answers. Without it a headless program is told its first
    /// window's size.
    #[must_use]
    pub fn screen_size(mut self, width: i32, height: i32) -> Self {
        self.screen = Some((width, height));
        self
    }

    /// Where this window asked to open, if it did.
    pub(crate) fn placed(&self) -> Option<(i32, i32)> {
        self.position
    }

    /// Another top-level window (`glutCreateWindow` again), with its own context and callbacks.
    /// Windows are numbered in the order they are added, from 2 (this one is 1); a window's
    /// own added windows follow it.
    #[must_use]
    pub fn window(mut self, other: App) -> Self {
        self.add_window(0, other);
        self
    }

    /// `glutCreateSubWindow(parent, x, y, width, height)`: `child` (of its own size, with its
    /// own context and callbacks) drawn inside window `parent` with its top left corner at
    /// (x, y) of the parent's, numbered as [`App::window`] numbers windows.
    #[must_use]
    pub fn sub_window(mut self, parent: i32, x: i32, y: i32, child: App) -> Self {
        self.add_window(parent, child.position(x, y));
        self
    }

    /// Adds a window (`parent` 0: top-level) and returns its number.
    pub fn add_window(&mut self, parent: i32, mut window: App) -> i32 {
        let id = self.extra.len() as i32 + 2;
        let grandchildren = std::mem::take(&mut window.extra);
        self.extra.push((parent, window));
        for (p, w) in grandchildren {
            self.extra.push((if p == 0 { 0 } else { p + id - 1 }, w));
        }
        id
    }

    /// Window `id` of this program (1: this one), to set its callbacks.
    pub fn window_mut(&mut self, id: i32) -> Option<&mut App> {
        if id == 1 {
            return Some(self);
        }
        let index = usize::try_from(id - 2).ok()?;
        self.extra.get_mut(index).map(|(_, w)| w)
    }

    /// Uses `gl` as this window's context when the program runs (a context the program set up
    /// before the main loop, as C programs do between `glutCreateWindow` and `glutMainLoop`).
    #[must_use]
    pub fn with_context(mut self, gl: Box<Gl>) -> Self {
        self.context = Some(gl);
        self
    }

    /// This window's context, made now if it was not yet (before the main loop).
    pub fn context_mut(&mut self) -> &mut Gl {
        if self.context.is_none() {
            self.context = Some(Box::new(self.new_gl()));
        }
        self.context.as_mut().expect("made above")
    }

    /// This window and the windows added to it, in number order, with their parents.
    fn flatten(mut self) -> Vec<(i32, App)> {
        let extra = std::mem::take(&mut self.extra);
        std::iter::once((0, self)).chain(extra).collect()
    }

    /// Code the C program runs once after `glutCreateWindow` (the textbook's `Hint()`).
    #[must_use]
    pub fn init(mut self, f: impl FnMut(&mut Gl) + 'static) -> Self {
        self.init = Some(Box::new(f));
        self
    }

    /// `glutReshapeFunc`. Without one, GLUT's default sets `glViewport(0, 0, w, h)`.
    #[must_use]
    pub fn reshape(mut self, f: impl FnMut(&mut Gl, i32, i32) + 'static) -> Self {
        self.reshape = Some(Box::new(f));
        self
    }

    /// `glutDisplayFunc`.
    #[must_use]
    pub fn display(mut self, f: impl FnMut(&mut Gl) + 'static) -> Self {
        self.display = Some(Box::new(f));
        self
    }

    /// `glutKeyboardFunc`: called with the character typed and the mouse position in window
    /// pixels (origin top left) when a key is pressed in the window; the window then redraws.
    /// Escape closes the window, as the textbook programs do.
    #[must_use]
    pub fn keyboard(mut self, f: impl FnMut(&mut Gl, char, i32, i32) + 'static) -> Self {
        self.keyboard = Some(Box::new(f));
        self
    }

    /// `glutMouseFunc`: called with the button (`GLUT_LEFT_BUTTON`, `_MIDDLE_`, `_RIGHT_`), the
    /// state (`GLUT_DOWN`, `GLUT_UP`) and the mouse position in window pixels (origin top
    /// left) when a button is pressed or released; the window then redraws.
    #[must_use]
    pub fn mouse(mut self, f: impl FnMut(&mut Gl, i32, i32, i32, i32) + 'static) -> Self {
        self.mouse = Some(Box::new(f));
        self
    }

    /// `glutMotionFunc`: called with the mouse position while a button is held and the mouse
    /// moves; the window then redraws.
    #[must_use]
    pub fn motion(mut self, f: impl FnMut(&mut Gl, i32, i32) + 'static) -> Self {
        self.motion = Some(Box::new(f));
        self
    }

    /// `glutPassiveMotionFunc`: called with the mouse position when it moves with no button
    /// held.
    #[must_use]
    pub fn passive_motion(mut self, f: impl FnMut(&mut Gl, i32, i32) + 'static) -> Self {
        self.passive_motion = Some(Box::new(f));
        self
    }

    /// `glutKeyboardUpFunc`: called with the character and the mouse position when a key that
    /// types one is released.
    #[must_use]
    pub fn keyboard_up(mut self, f: impl FnMut(&mut Gl, char, i32, i32) + 'static) -> Self {
        self.keyboard_up = Some(Box::new(f));
        self
    }

    /// `glutSpecialFunc`: called with a `GLUT_KEY_*` code (arrows, F1..F12, page up/down, home,
    /// end, insert) and the mouse position when such a key is pressed; the window then redraws.
    #[must_use]
    pub fn special(mut self, f: impl FnMut(&mut Gl, i32, i32, i32) + 'static) -> Self {
        self.special = Some(Box::new(f));
        self
    }

    /// `glutSpecialUpFunc`: as [`App::special`], when the key is released.
    #[must_use]
    pub fn special_up(mut self, f: impl FnMut(&mut Gl, i32, i32, i32) + 'static) -> Self {
        self.special_up = Some(Box::new(f));
        self
    }

    /// `glutEntryFunc`: called with `GLUT_ENTERED` or `GLUT_LEFT` when the pointer enters or
    /// leaves the window.
    #[must_use]
    pub fn entry(mut self, f: impl FnMut(&mut Gl, i32) + 'static) -> Self {
        self.entry = Some(Box::new(f));
        self
    }

    /// `glutIdleFunc`: called whenever the window has nothing else to do; an animation calls
    /// `gl.glut_post_redisplay()` from it and runs at the display's rate. Headless, once per
    /// frame of `--frames N`. Callbacks change it with [`Gl::glut_idle_func`].
    #[must_use]
    pub fn idle(mut self, f: impl FnMut(&mut Gl) + 'static) -> Self {
        self.idle = Some(Box::new(f));
        self
    }

    /// `glutTimerFunc(msecs, f, value)` before the main loop: `f(gl, value)` runs once, `msecs`
    /// milliseconds after the loop starts (headless, on the virtual 60 Hz clock of
    /// `--frames`). Callbacks register more with [`Gl::glut_timer_func`].
    #[must_use]
    pub fn timer(mut self, msecs: u32, f: impl FnMut(&mut Gl, i32) + 'static, value: i32) -> Self {
        self.timers.push((msecs, Box::new(f), value));
        self
    }

    /// `glutInitDisplayMode` (`GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH`, ...): recorded for
    /// `glutGet`; the window always has a colour and a depth buffer, and shows each frame
    /// when the display callback returns.
    #[must_use]
    pub fn init_display_mode(mut self, mode: u32) -> Self {
        self.display_mode = mode;
        self
    }

    /// The key-release callback; false if there is none.
    pub fn run_keyboard_up(&mut self, gl: &mut Gl, key: char, x: i32, y: i32) -> bool {
        self.keyboard_up.as_mut().map(|f| f(gl, key, x, y)).is_some()
    }

    /// The special-key callback (`up` for a release); false if there is none.
    pub fn run_special(&mut self, gl: &mut Gl, up: bool, key: i32, x: i32, y: i32) -> bool {
        let callback = if up { &mut self.special_up } else { &mut self.special };
        callback.as_mut().map(|f| f(gl, key, x, y)).is_some()
    }

    /// The passive-motion callback; false if there is none.
    pub fn run_passive_motion(&mut self, gl: &mut Gl, x: i32, y: i32) -> bool {
        self.passive_motion.as_mut().map(|f| f(gl, x, y)).is_some()
    }

    /// The entry callback; false if there is none.
    pub fn run_entry(&mut self, gl: &mut Gl, state: i32) -> bool {
        self.entry.as_mut().map(|f| f(gl, state)).is_some()
    }

    /// The idle callback and timers registered so far, handed to the main loop.
    pub(crate) fn take_schedule(&mut self, now_ms: f64) -> Schedule {
        Schedule::new(self.idle.take(), std::mem::take(&mut self.timers), now_ms)
    }

    /// What the window does on a mouse button: the mouse callback; false if there is none.
    pub fn run_mouse(&mut self, gl: &mut Gl, button: i32, state: i32, x: i32, y: i32) -> bool {
        self.mouse.as_mut().map(|mouse| mouse(gl, button, state, x, y)).is_some()
    }

    /// What the window does with a mouse button, as GLUT's main loop does: while a menu is
    /// open the event goes to it (a choice runs the menu's callback); a press of a button with
    /// a menu attached (`glutAttachMenu`) opens that menu at the pointer; any other event goes
    /// to the mouse callback.
    pub(crate) fn mouse_button(&mut self, gl: &mut Gl, button: i32, state: i32, x: i32, y: i32) -> Redraw {
        if let Some(popup) = &mut self.popup {
            let event =
                if state == GLUT_DOWN { popup.press(x, y) } else { popup.release(&gl.glut.program().menus, x, y) };
            return self.after_menu_event(gl, event);
        }
        if state == GLUT_DOWN {
            if let Some(menu) = gl.glut_attached_menu(button) {
                self.run_menu_status(gl, crate::glut::consts::GLUT_MENU_IN_USE, x, y);
                self.popup = Popup::open(gl, menu, x, y, (gl.width(), gl.height()));
                self.menu_at = (x, y);
                return Redraw::Menu;
            }
        }
        // The release of the press that opened a menu belongs to the menu, not the program.
        if state == GLUT_UP && gl.glut_attached_menu(button).is_some() {
            return Redraw::Nothing;
        }
        Redraw::program_if(self.run_mouse(gl, button, state, x, y))
    }

    /// What the window does when the pointer moves: an open menu follows it; otherwise the
    /// motion callback if a button is held, the passive-motion callback if not.
    pub(crate) fn pointer_moved(&mut self, gl: &mut Gl, x: i32, y: i32, button_held: bool) -> Redraw {
        if let Some(popup) = &mut self.popup {
            return if popup.hover(gl, x, y) { Redraw::Menu } else { Redraw::Nothing };
        }
        Redraw::program_if(if button_held { self.run_motion(gl, x, y) } else { self.run_passive_motion(gl, x, y) })
    }

    /// Closes an open menu without a choice (Escape); false if none was open.
    pub(crate) fn close_menu(&mut self, gl: &mut Gl) -> bool {
        let open = self.popup.take().is_some();
        if open {
            let (x, y) = self.menu_at;
            self.run_menu_status(gl, crate::glut::consts::GLUT_MENU_NOT_IN_USE, x, y);
        }
        open
    }

    /// The open menu as a frame to draw over the program's last one (no clear, its own
    /// matrices), or `None` when no menu is open.
    pub(crate) fn menu_overlay(&self, gl: &Gl) -> Option<Frame> {
        self.popup.as_ref().map(|popup| popup.overlay(gl))
    }

    fn after_menu_event(&mut self, gl: &mut Gl, event: PopupEvent) -> Redraw {
        match event {
            PopupEvent::Open => Redraw::Menu,
            PopupEvent::Closed => {
                self.popup = None;
                let (x, y) = self.menu_at;
                self.run_menu_status(gl, crate::glut::consts::GLUT_MENU_NOT_IN_USE, x, y);
                Redraw::Menu
            }
            PopupEvent::Chosen { menu, value } => {
                self.popup = None;
                gl.run_menu_callback(menu, value);
                let (x, y) = self.menu_at;
                self.run_menu_status(gl, crate::glut::consts::GLUT_MENU_NOT_IN_USE, x, y);
                Redraw::Program
            }
        }
    }

    /// What the window does when the mouse moves with a button held: the motion callback;
    /// false if there is none.
    pub fn run_motion(&mut self, gl: &mut Gl, x: i32, y: i32) -> bool {
        self.motion.as_mut().map(|motion| motion(gl, x, y)).is_some()
    }

    /// The window size asked for.
    #[must_use]
    pub fn size(&self) -> (i32, i32) {
        (self.width, self.height)
    }

    pub(crate) fn run_init(&mut self, gl: &mut Gl) {
        if let Some(init) = &mut self.init {
            init(gl);
        }
    }

    /// What the window does on a key press: the keyboard callback (also for tests and other
    /// event loops).
    pub fn run_keyboard(&mut self, gl: &mut Gl, key: char, x: i32, y: i32) {
        if let Some(keyboard) = &mut self.keyboard {
            keyboard(gl, key, x, y);
        }
    }

    /// `--frames N`, if the program was started with it.
    #[must_use]
    pub fn frames(&self) -> Option<usize> {
        self.frames
    }

    /// The window title.
    #[must_use]
    pub fn title(&self) -> &str {
        &self.title
    }

    /// Where the program's contexts evaluate `glEvalMesh` grids. Initially from the environment
    /// (`GLEVAL_TESSELLATOR`, see [`Tessellator::from_env`]: `App` is where a program meets its
    /// environment, [`Gl::new`] never reads it); `--gpu` on the command line picks the GPU.
    #[must_use]
    pub fn with_tessellator(mut self, tessellator: Tessellator) -> Self {
        self.tessellator = tessellator;
        self
    }

    /// The tessellator this program's contexts use.
    #[must_use]
    pub fn tessellator(&self) -> Tessellator {
        self.tessellator
    }

    /// Which rasteriser draws headless frames (`--png`, `--time`, [`App::render_image`]).
    /// Initially from the environment (`GLEVAL_RASTERIZER`, see [`Rasterizer::from_env`]);
    /// `--wgpu` on the command line picks wgpu. The GPU tessellator always draws through
    /// wgpu, where its meshes are.
    #[must_use]
    pub fn with_rasterizer(mut self, rasterizer: Rasterizer) -> Self {
        self.rasterizer = rasterizer;
        self
    }

    /// The rasteriser headless frames are drawn with.
    #[must_use]
    pub fn rasterizer(&self) -> Rasterizer {
        match self.tessellator {
            Tessellator::Gpu => Rasterizer::Wgpu,
            Tessellator::Cpu => self.rasterizer,
        }
    }

    /// A fresh context of the window's size on this program's tessellator.
    pub(crate) fn new_gl(&self) -> Gl {
        let mut gl = Gl::new(self.width, self.height);
        gl.set_tessellator(self.tessellator);
        gl.glut.display_mode = self.display_mode;
        gl.set_buffer_config(crate::gl::BufferConfig::of_display_mode(self.display_mode));
        gl.glut.init_size = (self.width, self.height);
        gl.set_window_reader(window_reader(self.rasterizer()));
        gl
    }

    /// `glutMainLoop`: `--png PATH` renders one frame to PNG and returns; otherwise a window.
    /// `--gpu` selects the GPU tessellator. Errors are printed and the process exits with
    /// status 1, as a C program would fail.
    pub fn run(self) {
        self.run_with(Options::from_args(std::env::args().skip(1)));
    }

    /// [`App::run`] with options parsed elsewhere (C's `glutInit` takes them out of the
    /// program's `argv`, which then no longer holds them).
    pub fn run_with(self, options: Options) {
        self.run_loop(options);
    }

    /// [`App::run_with`], telling how the loop ended, as freeglut's `glutMainLoop` ends: true
    /// if the program should exit now (`GLUT_ACTION_ON_WINDOW_CLOSE` is `GLUT_ACTION_EXIT`),
    /// false if `glutMainLoop` returns to the program (`GLUT_ACTION_GLUTMAINLOOP_RETURNS`,
    /// `GLUT_ACTION_CONTINUE_EXECUTION`).
    pub fn run_loop(mut self, options: Options) -> bool {
        // A colour-index window cannot be had on Mesa: freeglut's fatal error (`glut::display_mode`).
        crate::glut::display_mode::exit_unless_possible(self.display_mode);
        crate::render::quiet_device_select();
        if options.gpu {
            self.tessellator = Tessellator::Gpu;
        }
        if options.wgpu {
            self.rasterizer = Rasterizer::Wgpu;
        }
        self.frames = options.frames;
        self.take_x_options(&options.glut);
        let result = match (options.time, options.png) {
            (Some(frames), _) => self.print_frame_time(frames).map(|()| true),
            (None, Some(path)) if options.profile => self.write_png_profiled(&path).map(|()| true),
            (None, Some(path)) => self.write_pngs(&path),
            (None, None) => self.run_window(),
        };
        match result {
            Ok(exit) => exit,
            Err(e) => {
                eprintln!("{e}");
                std::process::exit(1);
            }
        }
    }

    /// Runs init, reshape and display once on a fresh context and returns what was drawn.
    pub fn record_frame(&mut self) -> Gl {
        self.record_frames(1)
    }

    /// Runs the program headless for `frames` frames and returns the context of its first
    /// window holding what the last frame drew: every window's init, reshape and display, then,
    /// between frames, what GLUT's main loop does in one refresh of a 60 Hz display: the timers
    /// due by then (earliest first) and the idle callback once; the next frame is drawn when one
    /// of them posts a redisplay. The clock is virtual (`GLUT_ELAPSED_TIME` advances 1000/60 ms
    /// a step), so every run draws the same frames. A program that stops asking for redisplays
    /// ends early. The first window's callbacks stay with `self` (the others are used up).
    pub fn record_frames(&mut self, frames: usize) -> Gl {
        let mut program = Program::new(std::mem::replace(self, App::new("", 1, 1)));
        program.run_headless(frames);
        // The title a callback last asked for stays for the caller (a window would show it).
        let title = program.effects.iter().rev().find_map(|(id, e)| match e {
            WindowRequest::Title(t) if *id == 1 => Some(t.clone()),
            _ => None,
        });
        match program.index(1) {
            Some(k) => {
                let slot = program.slots.swap_remove(k);
                *self = slot.app;
                let mut gl = *slot.gl;
                if let Some(title) = title {
                    gl.glut_set_window_title(&title);
                }
                gl
            }
            None => self.new_gl(),
        }
    }

    pub(crate) fn draw_into(&mut self, gl: &mut Gl, width: i32, height: i32) {
        self.run_reshape(gl, width, height);
        self.run_display(gl);
    }

    /// The window now has this size: the reshape callback, or GLUT's default viewport.
    pub(crate) fn run_reshape(&mut self, gl: &mut Gl, width: i32, height: i32) {
        gl.set_window_size(width, height);
        match &mut self.reshape {
            Some(reshape) => reshape(gl, width, height),
            None => gl.viewport(0, 0, width, height),
        }
    }

    /// What the window does to redraw: the display callback into `gl`.
    pub fn run_display(&mut self, gl: &mut Gl) {
        if let Some(display) = &mut self.display {
            display(gl);
            if self.gl_debug {
                gl.glut_report_errors();
            }
        }
    }

    #[cfg(feature = "window")]
    fn run_window(self) -> Result<bool, Box<dyn std::error::Error>> {
        crate::window::run(self)
    }

    #[cfg(not(feature = "window"))]
    fn run_window(self) -> Result<bool, Box<dyn std::error::Error>> {
        Err("this build has no window support (feature `window`); run with --png PATH".into())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::glut::consts::*;
    use std::cell::RefCell;
    use std::rc::Rc;

    /// A program with a right-button menu of two entries and a mouse callback that logs.
    fn program(log: &Rc<RefCell<Vec<String>>>) -> (App, Gl) {
        let (menu_log, mouse_log) = (log.clone(), log.clone());
        let mut app = App::new("menus", 300, 200)
            .init(move |gl| {
                let log = menu_log.clone();
                gl.glut_create_menu(move |_, value| log.borrow_mut().push(format!("menu {value}")));
                gl.glut_add_menu_entry("Fill", 1);
                gl.glut_add_menu_entry("Outline", 2);
                gl.glut_attach_menu(GLUT_RIGHT_BUTTON);
            })
            .mouse(move |_, button, state, _, _| mouse_log.borrow_mut().push(format!("mouse {button} {state}")));
        let gl = app.record_frame();
        (app, gl)
    }

    #[test]
    fn the_attached_button_opens_the_menu_and_a_release_on_an_entry_chooses_it() {
        let log = Rc::new(RefCell::new(Vec::new()));
        let (mut app, mut gl) = program(&log);
        assert_eq!(app.mouse_button(&mut gl, GLUT_RIGHT_BUTTON, GLUT_DOWN, 40, 30), Redraw::Menu);
        assert!(app.menu_overlay(&gl).is_some());
        // Down to the second entry (the items start at the press point, 24 pixels each).
        assert_eq!(app.pointer_moved(&mut gl, 60, 30 + 2 + 24 + 12, true), Redraw::Menu);
        assert_eq!(app.mouse_button(&mut gl, GLUT_RIGHT_BUTTON, GLUT_UP, 60, 30 + 2 + 24 + 12), Redraw::Program);
        assert!(app.menu_overlay(&gl).is_none());
        // The other buttons still reach the program; the menu's button does not.
        app.mouse_button(&mut gl, GLUT_LEFT_BUTTON, GLUT_DOWN, 5, 5);
        assert_eq!(*log.borrow(), ["menu 2", "mouse 0 0"]);
    }

    #[test]
    fn escape_or_a_click_outside_closes_it_without_a_choice() {
        let log = Rc::new(RefCell::new(Vec::new()));
        let (mut app, mut gl) = program(&log);
        app.mouse_button(&mut gl, GLUT_RIGHT_BUTTON, GLUT_DOWN, 40, 30);
        assert_eq!(app.mouse_button(&mut gl, GLUT_RIGHT_BUTTON, GLUT_UP, 40, 30), Redraw::Menu);
        assert!(app.menu_overlay(&gl).is_some(), "a click leaves the menu open");
        assert_eq!(app.mouse_button(&mut gl, GLUT_LEFT_BUTTON, GLUT_DOWN, 250, 150), Redraw::Menu);
        assert!(app.menu_overlay(&gl).is_none());
        app.mouse_button(&mut gl, GLUT_RIGHT_BUTTON, GLUT_DOWN, 40, 30);
        assert!(app.close_menu(&mut gl));
        assert!(!app.close_menu(&mut gl));
        assert!(log.borrow().iter().all(|entry| !entry.starts_with("menu")));
    }

    #[test]
    fn a_rust_program_takes_gluts_x_options() {
        let args = ["-geometry", "64x48+5+6", "-indirect", "-gldebug", "--png", "x.png", "keep"].map(String::from);
        let options = Options::from_args(args);
        assert_eq!(options.png.as_deref(), Some("x.png"));
        let x = &options.glut;
        assert_eq!((x.size, x.position, x.direct, x.gl_debug), (Some((64, 48)), Some((5, 6)), Some(false), true));
        // A display callback that leaves a GL error: -gldebug reports it (and so clears it).
        let program = || App::new("x", 30, 20).display(|gl| gl.matrix_mode(0x1234));
        let mut app = program();
        app.take_x_options(x);
        assert_eq!((app.placed(), app.size()), (Some((5, 6)), (30, 20)));
        let mut gl = app.record_frame();
        assert_eq!(gl.glut_get(GLUT_DIRECT_RENDERING), GLUT_FORCE_INDIRECT_CONTEXT);
        assert_eq!(gl.get_error(), crate::gl::consts::GL_NO_ERROR);
        let mut gl = program().record_frame();
        assert_eq!(gl.glut_get(GLUT_DIRECT_RENDERING), GLUT_TRY_DIRECT_CONTEXT);
        assert_eq!(gl.get_error(), crate::gl::consts::GL_INVALID_ENUM);
    }

    #[test]
    fn the_program_state_exists_once_for_every_window() {
        // Window 2's init makes a program-wide setting; window 1's display, which runs later,
        // reads it from its own context, which holds the same state.
        let seen = Rc::new(RefCell::new(Vec::new()));
        let log = seen.clone();
        let second = App::new("two", 20, 20)
            .init(|gl| gl.glut_set_option(GLUT_ACTION_ON_WINDOW_CLOSE, GLUT_ACTION_CONTINUE_EXECUTION));
        let mut app = App::new("one", 20, 20)
            .display(move |gl| log.borrow_mut().push(gl.glut_get(GLUT_ACTION_ON_WINDOW_CLOSE)))
            .window(second);
        let mut program = program::Program::new(std::mem::replace(&mut app, App::new("", 1, 1)));
        let (a, b) = (&program.slots[0].gl.glut.program, &program.slots[1].gl.glut.program);
        assert!(Rc::ptr_eq(a, b));
        program.run_headless(1);
        assert_eq!(*seen.borrow(), [GLUT_ACTION_CONTINUE_EXECUTION]);
        assert_eq!(program.options().action_on_close, GLUT_ACTION_CONTINUE_EXECUTION);
    }
}
