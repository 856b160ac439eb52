//! The rest of GLUT's per-window callbacks (`glutVisibilityFunc`, `glutWindowStatusFunc`,
//! `glutCloseFunc`, `glutMouseWheelFunc`, `glutPositionFunc`, ...) as `App` builder methods,
//! and the program-wide ones (`glutMenuStatusFunc`, `glutMenuStateFunc`).
//!
//! The device callbacks (joystick, spaceball, tablet, dials, button box, the multi-pointer
//! ones) are kept and never called, as freeglut never calls them where there is no such device
//! (`glutDeviceGet(GLUT_HAS_JOYSTICK)` and the others answer 0).

use super::App;
use crate::gl::Gl;

/// A callback of one `int`.
pub type IntFn = Box<dyn FnMut(&mut Gl, i32)>;
/// A callback of two `int`s.
pub type Int2Fn = Box<dyn FnMut(&mut Gl, i32, i32)>;
/// A callback of three `int`s.
pub type Int3Fn = Box<dyn FnMut(&mut Gl, i32, i32, i32)>;
/// A callback of four `int`s.
pub type Int4Fn = Box<dyn FnMut(&mut Gl, i32, i32, i32, i32)>;
/// A callback of five `int`s.
pub type Int5Fn = Box<dyn FnMut(&mut Gl, i32, i32, i32, i32, i32)>;
/// A callback of no arguments.
pub type VoidFn = Box<dyn FnMut(&mut Gl)>;
/// `glutJoystickFunc`'s callback: buttons, x, y, z.
pub type JoystickFn = Box<dyn FnMut(&mut Gl, u32, i32, i32, i32)>;

/// The callbacks beyond GLUT's first ones.
#[derive(Default)]
pub(crate) struct More {
    pub visibility: Option<IntFn>,
    pub window_status: Option<IntFn>,
    pub close: Option<VoidFn>,
    pub mouse_wheel: Option<Int4Fn>,
    pub position: Option<Int2Fn>,
    pub overlay_display: Option<VoidFn>,
    pub menu_status: Option<Int3Fn>,
    pub app_status: Option<IntFn>,
    pub init_context: Option<VoidFn>,
    // Devices freeglut finds none of on X11 without them: kept, never called.
    pub joystick: Option<(JoystickFn, i32)>,
    pub spaceball_motion: Option<Int3Fn>,
    pub spaceball_rotate: Option<Int3Fn>,
    pub spaceball_button: Option<Int2Fn>,
    pub button_box: Option<Int2Fn>,
    pub dials: Option<Int2Fn>,
    pub tablet_motion: Option<Int2Fn>,
    pub tablet_button: Option<Int4Fn>,
    pub multi_entry: Option<Int2Fn>,
    pub multi_button: Option<Int5Fn>,
    pub multi_motion: Option<Int3Fn>,
    pub multi_passive: Option<Int3Fn>,
}

/// Builder methods that store a callback.
macro_rules! builders {
    ($($(#[$doc:meta])* $name:ident($($arg:ty),*) => $field:ident;)*) => {
        impl App {
            $(
                $(#[$doc])*
                #[must_use]
                pub fn $name(mut self, f: impl FnMut(&mut Gl $(, $arg)*) + 'static) -> Self {
                    self.more.$field = Some(Box::new(f));
                    self
                }
            )*
        }
    };
}

impl App {
    /// `glutVisibilityFunc`: `GLUT_VISIBLE` when the window is shown, `GLUT_NOT_VISIBLE` when
    /// it is hidden or iconified. freeglut makes it of the window status, so it replaces a
    /// window status callback (and [`App::window_status`] replaces it).
    #[must_use]
    pub fn visibility(mut self, f: impl FnMut(&mut Gl, i32) + 'static) -> Self {
        self.more.visibility = Some(Box::new(f));
        self.more.window_status = None;
        self
    }

    /// `glutWindowStatusFunc`: `GLUT_FULLY_RETAINED` when the window is shown, `GLUT_HIDDEN`
    /// when it is hidden or iconified; it replaces a visibility callback.
    #[must_use]
    pub fn window_status(mut self, f: impl FnMut(&mut Gl, i32) + 'static) -> Self {
        self.more.window_status = Some(Box::new(f));
        self.more.visibility = None;
        self
    }
}

builders! {
    /// `glutCloseFunc` (and `glutWMCloseFunc`, its old name): runs before the window closes,
    /// whether the user closed it or the program called `glutDestroyWindow`.
    close() => close;
    /// `glutMouseWheelFunc`: wheel number, direction (+1 away from the user, -1 towards) and
    /// the pointer's position, once per notch. Without it the wheel's notches reach the mouse
    /// callback as buttons 3 (up) and 4 (down), as freeglut sends them.
    mouse_wheel(i32, i32, i32, i32) => mouse_wheel;
    /// `glutPositionFunc`: the window's new position after it moved.
    position_func(i32, i32) => position;
    /// `glutOverlayDisplayFunc`: X11 freeglut has no overlays, so it is never called.
    overlay_display() => overlay_display;
    /// `glutMenuStatusFunc` (`glutMenuStateFunc` without the position): `GLUT_MENU_IN_USE`
    /// when a menu opens, `GLUT_MENU_NOT_IN_USE` when it closes, with the pointer's position.
    menu_status(i32, i32, i32) => menu_status;
    /// `glutAppStatusFunc`: mobile platforms' pause and resume; never on a desktop.
    app_status(i32) => app_status;
    /// `glutInitContextFunc`: runs once the window's context exists, before its first reshape.
    init_context() => init_context;
    /// `glutSpaceballMotionFunc`: no spaceball, never called.
    spaceball_motion(i32, i32, i32) => spaceball_motion;
    /// `glutSpaceballRotateFunc`: no spaceball, never called.
    spaceball_rotate(i32, i32, i32) => spaceball_rotate;
    /// `glutSpaceballButtonFunc`: no spaceball, never called.
    spaceball_button(i32, i32) => spaceball_button;
    /// `glutButtonBoxFunc`: no button box, never called.
    button_box(i32, i32) => button_box;
    /// `glutDialsFunc`: no dials, never called.
    dials(i32, i32) => dials;
    /// `glutTabletMotionFunc`: no tablet, never called.
    tablet_motion(i32, i32) => tablet_motion;
    /// `glutTabletButtonFunc`: no tablet, never called.
    tablet_button(i32, i32, i32, i32) => tablet_button;
    /// `glutMultiEntryFunc`: no multi-pointer device, never called.
    multi_entry(i32, i32) => multi_entry;
    /// `glutMultiButtonFunc`: no multi-pointer device, never called.
    multi_button(i32, i32, i32, i32, i32) => multi_button;
    /// `glutMultiMotionFunc`: no multi-pointer device, never called.
    multi_motion(i32, i32, i32) => multi_motion;
    /// `glutMultiPassiveFunc`: no multi-pointer device, never called.
    multi_passive(i32, i32, i32) => multi_passive;
}

impl App {
    /// `glutJoystickFunc(f, poll_interval)`: no joystick (freeglut finds none without one), so
    /// `f` is never called.
    #[must_use]
    pub fn joystick(mut self, f: impl FnMut(&mut Gl, u32, i32, i32, i32) + 'static, poll_interval: i32) -> Self {
        self.more.joystick = Some((Box::new(f), poll_interval));
        self
    }

    /// Runs a callback of one `int` if it is set; false if not.
    pub(crate) fn run_int(gl: &mut Gl, f: &mut Option<IntFn>, value: i32) -> bool {
        f.as_mut().map(|f| f(gl, value)).is_some()
    }

    /// The window status and visibility callbacks for a window shown (`true`) or hidden.
    pub(crate) fn run_shown(&mut self, gl: &mut Gl, shown: bool) {
        use crate::glut::consts::*;
        let (status, visible) =
            if shown { (GLUT_FULLY_RETAINED, GLUT_VISIBLE) } else { (GLUT_HIDDEN, GLUT_NOT_VISIBLE) };
        Self::run_int(gl, &mut self.more.window_status, status);
        Self::run_int(gl, &mut self.more.visibility, visible);
    }

    /// The close callback; false if there is none.
    pub(crate) fn run_close(&mut self, gl: &mut Gl) -> bool {
        self.more.close.as_mut().map(|f| f(gl)).is_some()
    }

    /// The wheel as freeglut reports it: the wheel callback, or without one the mouse callback
    /// with buttons 3 (up) and 4 (down) pressed and released.
    pub(crate) fn run_wheel(&mut self, gl: &mut Gl, direction: i32, x: i32, y: i32) -> bool {
        use crate::glut::consts::{GLUT_DOWN, GLUT_UP};
        if let Some(wheel) = self.more.mouse_wheel.as_mut() {
            wheel(gl, 0, direction, x, y);
            return true;
        }
        let button = if direction > 0 { 3 } else { 4 };
        let down = self.run_mouse(gl, button, GLUT_DOWN, x, y);
        let up = self.run_mouse(gl, button, GLUT_UP, x, y);
        down || up
    }

    /// The position callback; false if there is none.
    pub(crate) fn run_position(&mut self, gl: &mut Gl, x: i32, y: i32) -> bool {
        self.more.position.as_mut().map(|f| f(gl, x, y)).is_some()
    }

    /// The menu status callback (program-wide: the first window's).
    pub(crate) fn run_menu_status(&mut self, gl: &mut Gl, status: i32, x: i32, y: i32) -> bool {
        self.more.menu_status.as_mut().map(|f| f(gl, status, x, y)).is_some()
    }

    /// The init-context callback.
    pub(crate) fn run_init_context(&mut self, gl: &mut Gl) {
        if let Some(f) = self.more.init_context.as_mut() {
            f(gl);
        }
    }

    /// Whether a callback of a device gleval never has is set (for tests: kept, never run).
    #[must_use]
    pub fn has_device_callbacks(&self) -> bool {
        let m = &self.more;
        m.joystick.is_some()
            || m.spaceball_motion.is_some()
            || m.spaceball_rotate.is_some()
            || m.spaceball_button.is_some()
            || m.button_box.is_some()
            || m.dials.is_some()
            || m.tablet_motion.is_some()
            || m.tablet_button.is_some()
            || m.multi_entry.is_some()
            || m.multi_button.is_some()
            || m.multi_motion.is_some()
            || m.multi_passive.is_some()
            || m.overlay_display.is_some()
            || m.app_status.is_some()
    }
}
