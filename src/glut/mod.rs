//! GLUT's side of a program: its constants, and what a program asks of its window from inside
//! its callbacks (`glutPostRedisplay`, `glutTimerFunc`, `glutIdleFunc`, `glutGetModifiers`,
//! `glutSetWindowTitle`, `glutReshapeWindow`, `glutFullScreen`, `glutGet`).
//!
//! Those calls are methods of [`Gl`] (the porting rule: a callback gets the context, and C's
//! GLUT calls are made from callbacks). They only record the request; the runner (`App`, in a
//! window or headless) carries it out after the callback returns, as GLUT's main loop does.
//! Callbacks registered before the main loop (`glutDisplayFunc`, `glutSpecialFunc`, ...) are
//! `App`'s builder methods.

pub mod consts;
pub mod display_mode;
pub mod fonts;
mod menu;
#[cfg(all(feature = "gpu", feature = "png"))]
pub(crate) mod popup;
// The main loop's scheduling belongs to the runner, `App`.
#[cfg(all(feature = "gpu", feature = "png"))]
mod schedule;
mod shapes;
pub(crate) mod state;
mod teapot;

pub use menu::MenuFn;
#[cfg(all(feature = "gpu", feature = "png"))]
pub(crate) use schedule::Schedule;
pub(crate) use state::GlutState;

use crate::gl::types::GLenum;
use crate::gl::Gl;
use consts::*;

/// An idle callback (`glutIdleFunc`): runs when the window has nothing else to do.
pub type IdleFn = Box<dyn FnMut(&mut Gl)>;

/// A timer callback (`glutTimerFunc`): runs once, with the value it was registered with.
pub type TimerFn = Box<dyn FnMut(&mut Gl, i32)>;

impl Gl {
    /// `glutPostRedisplay`: the display callback runs again once the current callback returns
    /// (in a window at the display's rate; headless, it makes the next of `--frames N`).
    pub fn glut_post_redisplay(&mut self) {
        self.glut.redisplay = true;
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
        self.glut.title = Some(title.to_owned());
    }

    /// The title asked for since the last call, if any (the window applies it).
    pub fn take_window_title(&mut self) -> Option<String> {
        self.glut.title.take()
    }

    /// `glutReshapeWindow`: asks the window system for this size; the reshape callback runs
    /// when the window has it. Headless, the next frame is drawn at this size.
    pub fn glut_reshape_window(&mut self, width: i32, height: i32) {
        self.glut.reshape = Some((width.max(1), height.max(1)));
    }

    /// `glutFullScreen`: asks for the window to cover the screen (headless: nothing changes).
    pub fn glut_full_screen(&mut self) {
        self.glut.full_screen = true;
    }

    /// `glutGet`: the window's size and position, the initial size and display mode, the
    /// screen size (headless: the window's), `GLUT_ELAPSED_TIME` (ms since the program
    /// started; headless, the virtual clock of `--frames`), and the buffers GLUT's window has
    /// (RGBA, double buffered as asked, a 24-bit depth buffer). Other names give -1, as
    /// freeglut answers unknown queries.
    #[must_use]
    pub fn glut_get(&self, what: GLenum) -> i32 {
        let glut = &self.glut;
        match what {
            GLUT_WINDOW_X | GLUT_WINDOW_Y | GLUT_INIT_WINDOW_X | GLUT_INIT_WINDOW_Y => 0,
            GLUT_WINDOW_WIDTH | GLUT_SCREEN_WIDTH => self.width(),
            GLUT_WINDOW_HEIGHT | GLUT_SCREEN_HEIGHT => self.height(),
            GLUT_INIT_WINDOW_WIDTH => glut.init_size.0,
            GLUT_INIT_WINDOW_HEIGHT => glut.init_size.1,
            GLUT_INIT_DISPLAY_MODE => glut.display_mode as i32,
            GLUT_WINDOW_DOUBLEBUFFER => i32::from(glut.display_mode & GLUT_DOUBLE != 0),
            GLUT_WINDOW_RGBA => 1,
            GLUT_WINDOW_DEPTH_SIZE => 24,
            GLUT_ELAPSED_TIME => glut.elapsed_ms,
            GLUT_MENU_NUM_ITEMS => self.glut_menu_num_items(),
            _ => -1,
        }
    }
}
