//! GLUT's program-wide settings: `glutSetOption`, `glutSetKeyRepeat`, the context a program
//! asks for (`glutInitContextVersion`, `...Flags`, `...Profile`), `glutInitDisplayString`, and
//! `glutGet`/`glutDeviceGet`/`glutLayerGet`/`glutGameModeGet` with the answers freeglut 3.4
//! gives on X11 (found by a probe program under Xvfb: every name of `GL/freeglut_std.h` and
//! `GL/freeglut_ext.h` asked of each call, before and inside the main loop).
//!
//! The settings are one small value that the runner copies into every window's context after
//! a callback changes it, so each window's `Gl` answers with the program's settings.

use super::consts::*;
use crate::gl::types::GLenum;
use crate::gl::Gl;

/// freeglut's version as `glutGet(GLUT_VERSION)` gives it: 3.4.0.
pub const FREEGLUT_VERSION: i32 = 30400;

/// The settings every window shares.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct GlutOptions {
    /// `GLUT_ACTION_ON_WINDOW_CLOSE`: what closing a window does (`GLUT_ACTION_EXIT`, ...).
    pub action_on_close: i32,
    /// `GLUT_RENDERING_CONTEXT`: `GLUT_CREATE_NEW_CONTEXT` or `GLUT_USE_CURRENT_CONTEXT`.
    pub rendering_context: i32,
    /// `GLUT_DIRECT_RENDERING` (`-direct`/`-indirect` set it too).
    pub direct_rendering: i32,
    pub skip_stale_motion: i32,
    pub visualize_normals: i32,
    pub stroke_join_dots: i32,
    pub allow_negative_position: i32,
    /// `glutSetKeyRepeat`: `GLUT_KEY_REPEAT_OFF`, `_ON` or `_DEFAULT`.
    pub key_repeat: i32,
    /// `glutInitContextVersion`, `...Flags`, `...Profile`.
    pub context_version: (i32, i32),
    pub context_flags: i32,
    pub context_profile: i32,
    /// `glutInitWindowPosition` (-1, -1 until a program sets it).
    pub init_position: (i32, i32),
    /// `-iconic`: top-level windows start iconified.
    pub iconic: bool,
    /// `glutGameModeString`: width, height, bits per pixel, refresh rate.
    pub game_mode: super::limits::GameMode,
    /// `glutSetVertexAttribCoord3`, `...Normal`, `...TexCoord2`.
    pub vertex_attribs: [i32; 3],
    /// The joystick calls' settings.
    pub joysticks: super::joystick::Joysticks,
}

impl Default for GlutOptions {
    fn default() -> Self {
        Self {
            action_on_close: GLUT_ACTION_EXIT,
            rendering_context: GLUT_CREATE_NEW_CONTEXT,
            direct_rendering: GLUT_TRY_DIRECT_CONTEXT,
            skip_stale_motion: 0,
            visualize_normals: 0,
            stroke_join_dots: 0,
            allow_negative_position: 0,
            key_repeat: GLUT_KEY_REPEAT_ON,
            context_version: (1, 0),
            context_flags: 0,
            context_profile: 0,
            init_position: (-1, -1),
            iconic: false,
            game_mode: [-1; 4],
            vertex_attribs: [-1; 3],
            joysticks: Default::default(),
        }
    }
}

impl GlutOptions {
    /// `glutGet`'s answer for a setting; `None` for other names.
    pub(crate) fn get(&self, what: GLenum) -> Option<i32> {
        Some(match what {
            GLUT_ACTION_ON_WINDOW_CLOSE => self.action_on_close,
            GLUT_RENDERING_CONTEXT => self.rendering_context,
            GLUT_DIRECT_RENDERING => self.direct_rendering,
            GLUT_SKIP_STALE_MOTION_EVENTS => self.skip_stale_motion,
            GLUT_GEOMETRY_VISUALIZE_NORMALS => self.visualize_normals,
            GLUT_STROKE_FONT_DRAW_JOIN_DOTS => self.stroke_join_dots,
            GLUT_ALLOW_NEGATIVE_WINDOW_POSITION => self.allow_negative_position,
            GLUT_INIT_MAJOR_VERSION => self.context_version.0,
            GLUT_INIT_MINOR_VERSION => self.context_version.1,
            GLUT_INIT_FLAGS => self.context_flags,
            GLUT_INIT_PROFILE => self.context_profile,
            GLUT_INIT_WINDOW_X => self.init_position.0,
            GLUT_INIT_WINDOW_Y => self.init_position.1,
            GLUT_VERSION => FREEGLUT_VERSION,
            _ => return None,
        })
    }
}

/// `glutDeviceGet`'s answers without a joystick, spaceball, tablet or dials, as freeglut's
/// on an X server with a keyboard and a mouse.
fn device_get(options: &GlutOptions, ignore_key_repeat: bool, what: GLenum) -> i32 {
    match what {
        GLUT_HAS_KEYBOARD | GLUT_HAS_MOUSE => 1,
        GLUT_HAS_SPACEBALL | GLUT_HAS_DIAL_AND_BUTTON_BOX | GLUT_HAS_TABLET | GLUT_HAS_JOYSTICK => 0,
        // freeglut counts X's pointer buttons (wheel clicks among them).
        GLUT_NUM_MOUSE_BUTTONS => 10,
        GLUT_NUM_SPACEBALL_BUTTONS => 2,
        GLUT_NUM_BUTTON_BOX_BUTTONS | GLUT_NUM_DIALS | GLUT_NUM_TABLET_BUTTONS => 0,
        GLUT_DEVICE_IGNORE_KEY_REPEAT => i32::from(ignore_key_repeat),
        GLUT_DEVICE_KEY_REPEAT => options.key_repeat,
        // freeglut's joystick table answers for joystick 0 even where none is plugged in.
        GLUT_OWNS_JOYSTICK => 1,
        GLUT_JOYSTICK_BUTTONS => 32,
        GLUT_JOYSTICK_AXES => 2,
        GLUT_JOYSTICK_POLL_RATE => 0,
        _ => -1,
    }
}

impl Gl {
    /// `glutSetOption(what, value)` (freeglut): the settings `glutGet` reads back. Other names
    /// are freeglut's "unknown option" warning.
    pub fn glut_set_option(&mut self, what: GLenum, value: i32) {
        match what {
            GLUT_INIT_WINDOW_WIDTH => self.glut.init_size.0 = value,
            GLUT_INIT_WINDOW_HEIGHT => self.glut.init_size.1 = value,
            GLUT_INIT_DISPLAY_MODE => self.glut.display_mode = value as u32,
            _ => {
                let mut program = self.glut.program_mut();
                let o = &mut program.options;
                match what {
                    GLUT_ACTION_ON_WINDOW_CLOSE => o.action_on_close = value,
                    GLUT_RENDERING_CONTEXT => o.rendering_context = value,
                    GLUT_DIRECT_RENDERING => o.direct_rendering = value,
                    GLUT_SKIP_STALE_MOTION_EVENTS => o.skip_stale_motion = value,
                    GLUT_GEOMETRY_VISUALIZE_NORMALS => o.visualize_normals = value,
                    GLUT_STROKE_FONT_DRAW_JOIN_DOTS => o.stroke_join_dots = value,
                    GLUT_ALLOW_NEGATIVE_WINDOW_POSITION => o.allow_negative_position = value,
                    GLUT_INIT_WINDOW_X => o.init_position.0 = value,
                    GLUT_INIT_WINDOW_Y => o.init_position.1 = value,
                    _ => {
                        drop(program);
                        self.glut_warning(&format!("glutSetOption(): missing enum handle {what}"));
                    }
                }
            }
        }
    }

    /// `glutSetKeyRepeat(mode)`: `GLUT_KEY_REPEAT_OFF` drops the events a held key repeats in
    /// every window; `_ON` and `_DEFAULT` keep them (freeglut: program-wide).
    pub fn glut_set_key_repeat(&mut self, mode: i32) {
        match mode {
            GLUT_KEY_REPEAT_OFF | GLUT_KEY_REPEAT_ON | GLUT_KEY_REPEAT_DEFAULT => {
                self.glut.program_mut().options.key_repeat = mode
            }
            _ => self.glut_warning(&format!("glutSetKeyRepeat(): invalid glutSetKeyRepeat mode: {mode}")),
        }
    }

    /// `glutInitContextVersion(major, minor)`: recorded for `glutGet`. gleval's context is
    /// GL 1.5, and runs a program asking for any version of the compatibility profile.
    pub fn glut_init_context_version(&mut self, major: i32, minor: i32) {
        self.glut.program_mut().options.context_version = (major, minor);
    }

    /// `glutInitContextFlags(flags)` (`GLUT_DEBUG`, `GLUT_FORWARD_COMPATIBLE`): recorded.
    pub fn glut_init_context_flags(&mut self, flags: i32) {
        self.glut.program_mut().options.context_flags = flags;
    }

    /// `glutInitContextProfile(profile)`: recorded for `glutGet`; a core profile is not one
    /// gleval has, and it says so once a process on stderr. Unlike `glutSetOption`, which
    /// does not know `GLUT_INIT_PROFILE` (freeglut warns), this warns of nothing.
    pub fn glut_init_context_profile(&mut self, profile: i32) {
        static SAID: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);
        if profile == GLUT_CORE_PROFILE && !SAID.swap(true, std::sync::atomic::Ordering::Relaxed) {
            eprintln!("gleval: a core profile was asked for; the context is GL 1.5 (compatibility)");
        }
        self.glut.program_mut().options.context_profile = profile;
    }

    /// GLUT's `-iconic`: top-level windows start iconified.
    pub fn glut_init_iconic(&mut self) {
        self.glut.program_mut().options.iconic = true;
    }

    /// Joins the program of `other`: its settings and message handlers become this context's,
    /// and stay shared (a window made before the main loop is one more window of the program
    /// whose settings were made before it).
    pub fn glut_inherit_settings(&mut self, other: &Gl) {
        self.glut.program = std::rc::Rc::clone(&other.glut.program);
    }

    /// `glutDeviceGet(what)`: the input devices, as freeglut on X11 answers them (no joystick,
    /// spaceball, tablet, dials or button box); -1 for other names.
    #[must_use]
    pub fn glut_device_get(&self, what: GLenum) -> i32 {
        let ignore = self.current_window_facts().is_some_and(|f| f.ignore_key_repeat);
        device_get(&self.glut.program().options, ignore, what)
    }

    /// `glutLayerGet(what)`: X11 freeglut has no overlays: none possible, the normal plane in
    /// use, nothing damaged; -1 for other names (as freeglut).
    #[must_use]
    pub fn glut_layer_get(&self, what: GLenum) -> i32 {
        match what {
            GLUT_OVERLAY_POSSIBLE | GLUT_HAS_OVERLAY | GLUT_TRANSPARENT_INDEX | GLUT_NORMAL_DAMAGED => 0,
            GLUT_LAYER_IN_USE => GLUT_NORMAL as i32,
            _ => -1,
        }
    }
}
