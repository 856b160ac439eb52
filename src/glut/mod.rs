//! GLUT's side of a program: its constants, and what a program asks of its window from inside
//! its callbacks (`glutPostRedisplay`, `glutTimerFunc`, `glutIdleFunc`, `glutGetModifiers`,
//! `glutSetWindowTitle`, `glutReshapeWindow`, `glutFullScreen`, `glutGet`).
//!
//! Those calls are methods of [`Gl`] (the porting rule: a callback gets the context, and C's
//! GLUT calls are made from callbacks). They only record the request; the runner (`App`, in a
//! window or headless) carries it out after the callback returns, as GLUT's main loop does.
//! Callbacks registered before the main loop (`glutDisplayFunc`, `glutSpecialFunc`, ...) are
//! `App`'s builder methods.

mod args;
pub mod consts;
pub mod display_mode;
pub mod fonts;
mod joystick;
mod limits;
mod menu;
pub(crate) mod messages;
#[cfg(all(feature = "gpu", feature = "png"))]
pub(crate) mod popup;
// The main loop's scheduling belongs to the runner, `App`.
mod cylinder;
pub(crate) mod options;
mod polyhedra;
#[cfg(all(feature = "gpu", feature = "png"))]
mod schedule;
mod shapes;
#[rustfmt::skip]
#[allow(clippy::excessive_precision, clippy::unreadable_literal, clippy::approx_constant)]
mod solids_data;
pub(crate) mod state;
mod teaset;
pub(crate) mod windows;

pub use args::{split_init_args, InitArgs, XOptions};
pub use menu::{MenuDestroyFn, MenuFn};
#[cfg(all(feature = "gpu", feature = "png"))]
pub(crate) use schedule::Schedule;
pub(crate) use state::GlutState;

use crate::gl::types::GLenum;
use crate::gl::Gl;
use consts::*;
pub use joystick::JoystickRange;
pub use limits::display_mode_from_string;
pub use messages::MessageFn;
pub use options::FREEGLUT_VERSION;
use windows::WindowRequest;

/// An idle callback (`glutIdleFunc`): runs when the window has nothing else to do.
pub type IdleFn = Box<dyn FnMut(&mut Gl)>;

/// A timer callback (`glutTimerFunc`): runs once, with the value it was registered with.
pub type TimerFn = Box<dyn FnMut(&mut Gl, i32)>;

impl Gl {
    /// `glutPostRedisplay`: the display callback runs again once the current callback returns
    /// (in a window at the display's rate; headless, it makes the next of `--frames N`).
    pub fn glut_post_redisplay(&mut self) {
        self.window_request(WindowRequest::Redisplay, |gl| gl.glut.redisplay = true);
    }

    /// `glutSwapBuffers`: in a double-buffered window the back buffer becomes the front one
    /// (recorded in the frame; see `Gl::record_swap_buffers`); a single-buffered window has
    /// nothing to swap.
    pub fn glut_swap_buffers(&mut self) {
        self.record_swap_buffers();
    }

    /// `glutGetModifiers`: `GLUT_ACTIVE_SHIFT`, `_CTRL` and `_ALT` bits held when the keyboard,
    /// special or mouse callback that is running was called (0 elsewhere, where GLUT warns).
    #[must_use]
    pub fn glut_get_modifiers(&self) -> i32 {
        self.glut.modifiers
    }

    /// `glutTimerFunc(msecs, func, value)`: `func(gl, value)` runs once, at least `msecs`
    /// milliseconds from now (headless: on the virtual clock of `--frames`, 60 frames a second).
    pub fn glut_timer_func(&mut self, msecs: u32, func: impl FnMut(&mut Gl, i32) + 'static, value: i32) {
        self.glut.timers.push((msecs, Box::new(func), value));
    }

    /// `glutIdleFunc`: `Some(f)` runs `f` whenever the window is idle, `None` (C's `NULL`)
    /// stops it.
    pub fn glut_idle_func(&mut self, func: Option<IdleFn>) {
        self.glut.idle = Some(func);
    }

    /// `glutSetWindowTitle`: the window shows `title` after the current callback (headless
    /// rendering ignores it).
    pub fn glut_set_window_title(&mut self, title: &str) {
        let own = title.to_owned();
        self.window_request(WindowRequest::Title(title.to_owned()), |gl| gl.glut.title = Some(own));
    }

    /// The title asked for since the last call, if any (the window applies it).
    pub fn take_window_title(&mut self) -> Option<String> {
        self.glut.title.take()
    }

    /// `glutReshapeWindow`: asks the window system for this size; the reshape callback runs
    /// when the window has it. Headless, the next frame is drawn at this size.
    pub fn glut_reshape_window(&mut self, width: i32, height: i32) {
        let size = (width.max(1), height.max(1));
        self.window_request(WindowRequest::Reshape(size.0, size.1), |gl| gl.glut.reshape = Some(size));
    }

    /// `glutFullScreen`: asks for the window to cover the screen (headless: nothing changes).
    pub fn glut_full_screen(&mut self) {
        self.window_request(WindowRequest::FullScreen, |gl| gl.glut.full_screen = true);
    }

    /// The screen's size in pixels that `glutGet(GLUT_SCREEN_WIDTH)` and `GLUT_SCREEN_HEIGHT`
    /// answer (`App::screen_size` sets it for every window of a program).
    pub fn glut_set_screen_size(&mut self, width: i32, height: i32) {
        self.glut.program_mut().screen = (width, height);
    }

    /// `glutGet`: every name freeglut 3.4 answers on X11. The current window's size, position,
    /// parent, children, cursor and full-screen state; its buffers (RGBA, double buffered as
    /// asked, a 24-bit depth buffer, stencil, alpha and accumulation as the display mode asks);
    /// the screen (headless: the window's size, at X's 100 dots an inch); the initial window
    /// and display mode; `GLUT_ELAPSED_TIME` (ms since the program started; headless, the
    /// virtual clock of `--frames`); the settings of `glutSetOption` and the context asked
    /// for; `GLUT_VERSION` (30400). Other names give -1, as freeglut answers them.
    #[must_use]
    pub fn glut_get(&self, what: GLenum) -> i32 {
        if let Some(answer) = self.window_query(what).or_else(|| self.glut.program().options.get(what)) {
            return answer;
        }
        let glut = &self.glut;
        let mode = glut.display_mode;
        let bits = |bit: u32, size: i32| if mode & bit != 0 { size } else { 0 };
        let program = glut.program();
        let screen = if program.screen.0 > 0 { program.screen } else { (self.width(), self.height()) };
        match what {
            GLUT_SCREEN_WIDTH => screen.0,
            GLUT_SCREEN_HEIGHT => screen.1,
            GLUT_SCREEN_WIDTH_MM => (f64::from(screen.0) * 0.254).round() as i32,
            GLUT_SCREEN_HEIGHT_MM => (f64::from(screen.1) * 0.254).round() as i32,
            GLUT_INIT_WINDOW_WIDTH => glut.init_size.0,
            GLUT_INIT_WINDOW_HEIGHT => glut.init_size.1,
            GLUT_INIT_DISPLAY_MODE => mode as i32,
            GLUT_INIT_STATE | GLUT_DISPLAY_MODE_POSSIBLE => 1,
            GLUT_WINDOW_DOUBLEBUFFER => bits(GLUT_DOUBLE, 1),
            GLUT_WINDOW_RGBA => i32::from(mode & GLUT_INDEX == 0),
            GLUT_WINDOW_DEPTH_SIZE => 24,
            GLUT_WINDOW_RED_SIZE | GLUT_WINDOW_GREEN_SIZE | GLUT_WINDOW_BLUE_SIZE => 8,
            GLUT_WINDOW_ALPHA_SIZE => bits(GLUT_ALPHA, 8),
            GLUT_WINDOW_BUFFER_SIZE => 24 + bits(GLUT_ALPHA, 8),
            GLUT_WINDOW_STENCIL_SIZE => bits(GLUT_STENCIL, 8),
            GLUT_WINDOW_ACCUM_RED_SIZE | GLUT_WINDOW_ACCUM_GREEN_SIZE | GLUT_WINDOW_ACCUM_BLUE_SIZE => {
                bits(GLUT_ACCUM, 16)
            }
            GLUT_WINDOW_ACCUM_ALPHA_SIZE => bits(GLUT_ACCUM | GLUT_ALPHA, 16) * i32::from(mode & GLUT_ALPHA != 0),
            GLUT_WINDOW_COLORMAP_SIZE
            | GLUT_WINDOW_NUM_SAMPLES
            | GLUT_WINDOW_STEREO
            | GLUT_WINDOW_SRGB
            | GLUT_WINDOW_FORMAT_ID
            | GLUT_WINDOW_BORDER_WIDTH
            | GLUT_WINDOW_HEADER_HEIGHT => 0,
            GLUT_ELAPSED_TIME => program.elapsed_ms,
            GLUT_MENU_NUM_ITEMS => self.glut_menu_num_items(),
            _ => -1,
        }
    }

    /// `glutLeaveMainLoop` (freeglut): the main loop ends after the current callback; with
    /// `GLUT_ACTION_ON_WINDOW_CLOSE` at `GLUT_ACTION_EXIT` (the default) the program then exits,
    /// otherwise `glutMainLoop` returns.
    pub fn glut_leave_main_loop(&mut self) {
        self.glut.leave_main_loop = true;
    }

    /// `glutExtensionSupported(name)`: whether `name` is one of the words of
    /// `glGetString(GL_EXTENSIONS)` (GLUT 3 spec §9.1: a whole word, not a prefix).
    #[must_use]
    pub fn glut_extension_supported(&mut self, name: &str) -> i32 {
        if name.is_empty() || name.contains(' ') {
            return 0;
        }
        let extensions = self.get_string(crate::gl::consts::GL_EXTENSIONS).unwrap_or_default();
        i32::from(extensions.split_whitespace().any(|e| e == name))
    }
}
