//! What GLUT calls made inside callbacks leave for the runner, and what the runner tells them.

use super::menu::Menus;
use super::messages::Messages;
use super::options::GlutOptions;
use super::windows::{WindowFacts, WindowRequest};
use super::{IdleFn, TimerFn};
use std::cell::{Ref, RefCell, RefMut};
use std::rc::Rc;

/// A timer asked for with `glutTimerFunc`: delay in ms, callback, value.
pub(crate) type TimerRequest = (u32, TimerFn, i32);

/// What GLUT keeps once for the whole program (freeglut's `fgState` and `fgStructure`): its
/// settings and message handlers, its windows as the runner last saw them, the current window,
/// the clock and the screen. Every window's context holds the same one (a context made on its
/// own has its own), so a setting made in one window's callback is every window's at once.
#[derive(Default)]
pub(crate) struct ProgramState {
    /// The program-wide settings (`glutSetOption`, `glutSetKeyRepeat`, the context asked for).
    pub options: GlutOptions,
    /// The program's handlers of freeglut's messages.
    pub messages: Messages,
    /// Every window of the program, as the runner last saw them.
    pub windows: Vec<WindowFacts>,
    /// `glutGetWindow`: the window later window calls act on (0: none).
    pub current: i32,
    /// `GLUT_ELAPSED_TIME`, set by the runner.
    pub elapsed_ms: i32,
    /// The screen's size in pixels, set by the runner (0: headless, the window's).
    pub screen: (i32, i32),
    /// The menus made with `glutCreateMenu`, and the current one.
    pub menus: Menus,
    /// The size each tea-set piece (teapot, teacup, teaspoon) × (solid, wire) was first drawn
    /// at: freeglut computes its normals then and keeps them (`teaset.rs`).
    pub tea_set_first_scale: [[Option<f32>; 2]; 3],
}

impl ProgramState {
    /// The window with this number, if it exists.
    pub fn facts(&self, id: i32) -> Option<&WindowFacts> {
        self.windows.iter().find(|w| w.id == id)
    }

    pub fn facts_mut(&mut self, id: i32) -> Option<&mut WindowFacts> {
        self.windows.iter_mut().find(|w| w.id == id)
    }
}

/// The program's state, shared by its windows' contexts.
pub(crate) type SharedProgram = Rc<RefCell<ProgramState>>;

/// GLUT's state inside a [`crate::gl::Gl`]: requests made by callbacks (taken by the runner
/// after each callback), and the program's state, which every window's context shares.
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
    /// `glutIdleFunc`: `Some(new)` when a callback changed it.
    pub idle: Option<Option<IdleFn>>,
    /// `glutTimerFunc` calls not yet scheduled.
    pub timers: Vec<TimerRequest>,
    /// The menus attached to `GLUT_LEFT_BUTTON`, `_MIDDLE_`, `_RIGHT_` in this window (0:
    /// none); the menus themselves are the program's.
    pub attached_menus: [i32; 3],
    /// The window this context belongs to (0: none, a context of its own).
    pub window: i32,
    /// What callbacks asked of windows, with the window each request is for.
    pub requests: Vec<(i32, WindowRequest)>,
    /// `glutLeaveMainLoop` was called.
    pub leave_main_loop: bool,
    /// The program's state (see [`ProgramState`]).
    pub program: SharedProgram,
}

impl GlutState {
    /// The program's state, to read. Never held across a callback of the program's.
    pub fn program(&self) -> Ref<'_, ProgramState> {
        self.program.borrow()
    }

    /// The program's state, to change. Never held across a callback of the program's.
    pub fn program_mut(&self) -> RefMut<'_, ProgramState> {
        self.program.borrow_mut()
    }

    /// `glutGetWindow`.
    pub fn current(&self) -> i32 {
        self.program().current
    }

    /// The window with this number as the runner last saw it, if it exists.
    pub fn facts(&self, id: i32) -> Option<WindowFacts> {
        self.program().facts(id).copied()
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
            .field("idle_changed", &self.idle.is_some())
            .field("timers", &self.timers.len())
            .field("attached_menus", &self.attached_menus)
            .field("requests", &self.requests)
            .field("options", &self.program().options)
            .finish()
    }
}
