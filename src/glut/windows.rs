//! GLUT's windows as a program sees them from its callbacks: which window is current
//! (`glutSetWindow`, `glutGetWindow`), what each window is (size, position, parent, shown), and
//! what a callback asks of a window (`glutPostWindowRedisplay`, `glutPositionWindow`,
//! `glutShowWindow`, `glutDestroyWindow`, ...).
//!
//! Each window has its own context (GLUT 3 spec §4), so each has its own [`Gl`]; the runner
//! (`App`) keeps every context's copy of the window table up to date before a callback runs and
//! carries out the requests after it returns, as freeglut carries them out in its main loop.
//! Calls naming a window that does not exist are ignored with freeglut's complaint on stderr.

use super::consts::*;
use crate::gl::types::GLenum;
use crate::gl::Gl;

/// What a window is, as `glutGet` reports it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct WindowFacts {
    /// The window's number (from 1, in creation order, never reused).
    pub id: i32,
    /// The parent's number, 0 for a top-level window.
    pub parent: i32,
    /// Position: a subwindow's in its parent, a top-level window's on the screen.
    pub x: i32,
    pub y: i32,
    pub width: i32,
    pub height: i32,
    /// How many subwindows it has.
    pub children: i32,
    /// Shown (`glutShowWindow`) rather than hidden or iconified.
    pub shown: bool,
    /// `glutSetCursor`'s cursor.
    pub cursor: i32,
    /// `glutIgnoreKeyRepeat`.
    pub ignore_key_repeat: bool,
    /// `glutFullScreen` in force.
    pub full_screen: bool,
    /// `glutSetWindowData`: the program's pointer, kept as a number.
    pub data: usize,
}

/// What a callback asks of a window; the runner carries it out after the callback.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum WindowRequest {
    Redisplay,
    Position(i32, i32),
    Reshape(i32, i32),
    Show,
    Hide,
    Iconify,
    Push,
    Pop,
    FullScreen,
    LeaveFullScreen,
    FullScreenToggle,
    Title(String),
    IconTitle(String),
    WarpPointer(i32, i32),
    Cursor(i32),
    IgnoreKeyRepeat(bool),
    Data(usize),
    Destroy,
}

impl Gl {
    /// `glutGetWindow`: the current window's number (0 when there is none).
    #[must_use]
    pub fn glut_get_window(&self) -> i32 {
        self.glut.current()
    }

    /// `glutSetWindow(window)`: later window calls (and, in C, GL calls) go to `window`.
    /// freeglut complains and changes nothing if there is no such window.
    pub fn glut_set_window(&mut self, window: i32) {
        if self.glut.facts(window).is_some() {
            self.glut.program_mut().current = window;
        } else {
            self.glut_warning(&format!("glutSetWindow(): window ID {window} not found!"));
        }
    }

    /// What the current window is, if there is one.
    pub(crate) fn current_window_facts(&self) -> Option<WindowFacts> {
        self.glut.facts(self.glut.current())
    }

    fn request(&mut self, request: WindowRequest) {
        let current = self.glut.current();
        if current != 0 {
            self.glut.requests.push((current, request));
        }
    }

    /// Whether window calls act on this context's own window (or there are no windows: a
    /// context of its own, as in tests), rather than on another made current with
    /// `glutSetWindow`.
    pub(crate) fn acts_on_own_window(&self) -> bool {
        let current = self.glut.current();
        current == 0 || current == self.glut.window
    }

    /// A request for the current window: kept in this context's own fields when it is this
    /// context's window (the runner reads them), queued for the runner otherwise.
    pub(crate) fn window_request(&mut self, request: WindowRequest, own: impl FnOnce(&mut Self)) {
        if self.acts_on_own_window() {
            own(self);
        } else {
            self.request(request);
        }
    }

    /// `glutPostWindowRedisplay(window)`: `window`'s display callback runs again.
    pub fn glut_post_window_redisplay(&mut self, window: i32) {
        if self.glut.facts(window).is_some() {
            self.glut.requests.push((window, WindowRequest::Redisplay));
        } else {
            self.glut_warning(&format!("glutPostWindowRedisplay(): window ID {window} not found!"));
        }
    }

    /// `glutPositionWindow(x, y)`: moves the current window (a subwindow within its parent).
    pub fn glut_position_window(&mut self, x: i32, y: i32) {
        self.request(WindowRequest::Position(x, y));
    }

    /// `glutShowWindow`.
    pub fn glut_show_window(&mut self) {
        self.request(WindowRequest::Show);
    }

    /// `glutHideWindow`.
    pub fn glut_hide_window(&mut self) {
        self.request(WindowRequest::Hide);
    }

    /// `glutIconifyWindow`: a top-level window is iconified (not shown; headless, not drawn).
    pub fn glut_iconify_window(&mut self) {
        self.request(WindowRequest::Iconify);
    }

    /// `glutPushWindow`: the current window goes below its siblings.
    pub fn glut_push_window(&mut self) {
        self.request(WindowRequest::Push);
    }

    /// `glutPopWindow`: the current window goes above its siblings.
    pub fn glut_pop_window(&mut self) {
        self.request(WindowRequest::Pop);
    }

    /// `glutDestroyWindow(window)`: the window and its subwindows close (their close callbacks
    /// run first, as freeglut's); destroying the current window leaves none current.
    pub fn glut_destroy_window(&mut self, window: i32) {
        if self.glut.facts(window).is_none() {
            return self.glut_warning(&format!("glutDestroyWindow(): window ID {window} not found!"));
        }
        self.glut.requests.push((window, WindowRequest::Destroy));
        if self.glut.current() == window {
            self.glut.program_mut().current = 0;
        }
    }

    /// `glutSetIconTitle`.
    pub fn glut_set_icon_title(&mut self, title: &str) {
        self.request(WindowRequest::IconTitle(title.to_owned()));
    }

    /// `glutLeaveFullScreen` (freeglut).
    pub fn glut_leave_full_screen(&mut self) {
        self.request(WindowRequest::LeaveFullScreen);
    }

    /// `glutFullScreenToggle` (freeglut).
    pub fn glut_full_screen_toggle(&mut self) {
        self.request(WindowRequest::FullScreenToggle);
    }

    /// `glutWarpPointer(x, y)`: moves the pointer to (x, y) in the current window.
    pub fn glut_warp_pointer(&mut self, x: i32, y: i32) {
        self.request(WindowRequest::WarpPointer(x, y));
    }

    /// `glutSetCursor(cursor)`: the current window's cursor (`GLUT_CURSOR_*`).
    pub fn glut_set_cursor(&mut self, cursor: i32) {
        self.request(WindowRequest::Cursor(cursor));
        let mut program = self.glut.program_mut();
        let current = program.current;
        if let Some(facts) = program.facts_mut(current) {
            facts.cursor = cursor;
        }
    }

    /// `glutIgnoreKeyRepeat(ignore)`: the current window's keyboard callbacks miss the
    /// events a held key repeats (freeglut: per window).
    pub fn glut_ignore_key_repeat(&mut self, ignore: i32) {
        self.request(WindowRequest::IgnoreKeyRepeat(ignore != 0));
        let mut program = self.glut.program_mut();
        let current = program.current;
        if let Some(facts) = program.facts_mut(current) {
            facts.ignore_key_repeat = ignore != 0;
        }
    }

    /// `glutSetWindowData(data)` (freeglut): a number the program keeps with the current window.
    pub fn glut_set_window_data(&mut self, data: usize) {
        self.request(WindowRequest::Data(data));
        let mut program = self.glut.program_mut();
        let current = program.current;
        if let Some(facts) = program.facts_mut(current) {
            facts.data = data;
        }
    }

    /// `glutGetWindowData` (freeglut): what `glutSetWindowData` kept (0 initially).
    #[must_use]
    pub fn glut_get_window_data(&self) -> usize {
        self.current_window_facts().map_or(0, |f| f.data)
    }

    /// `glutGet`'s answers about the current window; `None` for the other names.
    pub(crate) fn window_query(&self, what: GLenum) -> Option<i32> {
        let f = self.current_window_facts().unwrap_or(WindowFacts {
            width: self.width(),
            height: self.height(),
            cursor: GLUT_CURSOR_INHERIT,
            shown: true,
            ..WindowFacts::default()
        });
        Some(match what {
            GLUT_WINDOW_X => f.x,
            GLUT_WINDOW_Y => f.y,
            GLUT_WINDOW_WIDTH => f.width,
            GLUT_WINDOW_HEIGHT => f.height,
            GLUT_WINDOW_PARENT => f.parent,
            GLUT_WINDOW_NUM_CHILDREN => f.children,
            GLUT_WINDOW_CURSOR => f.cursor,
            GLUT_FULL_SCREEN => i32::from(f.full_screen),
            _ => return None,
        })
    }
}
