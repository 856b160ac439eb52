//! What GLUT calls made inside callbacks leave for the runner, and what the runner tells them.

use super::menu::Menus;
use super::messages::Messages;
use super::options::GlutOptions;
use super::windows::{WindowFacts, WindowRequest};
use super::{IdleFn, TimerFn};

/// A timer asked for with `glutTimerFunc`: delay in ms, callback, value.
pub(crate) type TimerRequest = (u32, TimerFn, i32);

/// GLUT's state inside a [`crate::gl::Gl`]: requests made by callbacks (taken by the runner
/// after each callback) and the facts the runner sets before calling them.
#[derive(Default)]
pub(crate) struct GlutState {
    /// `glutPostRedisplay` was called.
    pub redisplay: bool,
    /// `glutGetModifiers` while an input callback runs.
    pub modifiers: i32,
    /// `glutSetWindowTitle`.
    pub title: Option<String>,
    /// `glutReshapeWindow`.
    pub reshape: Option<(i32, i32)>,
    /// `glutFullScreen`.
    pub full_screen: bool,
    /// `glutInitDisplayMode` and `glutInitWindowSize`, for `glutGet`.
    pub display_mode: u32,
    pub init_size: (i32, i32),
    /// `GLUT_ELAPSED_TIME`, set by the runner.
    pub elapsed_ms: i32,
    /// `glutIdleFunc`: `Some(new)` when a callback changed it.
    pub idle: Option<Option<IdleFn>>,
    /// `glutTimerFunc` calls not yet scheduled.
    pub timers: Vec<TimerRequest>,
    /// The menus made with `glutCreateMenu` and the buttons they are attached to.
    pub menus: Menus,
    /// The window this context belongs to (0: none, a context of its own).
    pub window: i32,
    /// `glutGetWindow`: the window later window calls act on (0: none).
    pub current: i32,
    /// Every window of the program, as the runner last saw them.
    pub windows: Vec<WindowFacts>,
    /// What callbacks asked of windows, with the window each request is for.
    pub requests: Vec<(i32, WindowRequest)>,
    /// The program-wide settings (`glutSetOption`, `glutSetKeyRepeat`, the context asked for).
    pub options: GlutOptions,
    /// The screen's size in pixels, set by the runner (0: headless, the window's).
    pub screen: (i32, i32),
    /// `glutLeaveMainLoop` was called.
    pub leave_main_loop: bool,
    /// The program's handlers of freeglut's messages.
    pub messages: Messages,
}

impl GlutState {
    /// The window with this number, if it exists.
    pub fn facts(&self, id: i32) -> Option<&WindowFacts> {
        self.windows.iter().find(|w| w.id == id)
    }

    pub fn facts_mut(&mut self, id: i32) -> Option<&mut WindowFacts> {
        self.windows.iter_mut().find(|w| w.id == id)
    }
}

impl std::fmt::Debug for GlutState {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("GlutState")
            .field("redisplay", &self.redisplay)
            .field("modifiers", &self.modifiers)
            .field("title", &self.title)
            .field("reshape", &self.reshape)
            .field("full_screen", &self.full_screen)
            .field("display_mode", &self.display_mode)
            .field("elapsed_ms", &self.elapsed_ms)
            .field("idle_changed", &self.idle.is_some())
            .field("timers", &self.timers.len())
            .field("menus", &self.menus)
            .field("current", &self.current)
            .field("windows", &self.windows)
            .field("requests", &self.requests)
            .field("options", &self.options)
            .finish()
    }
}
