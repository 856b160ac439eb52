//! GLUT's program-wide settings and queries (`glutGet`, `glutDeviceGet`, `glutSetOption`,
//! `glutSetKeyRepeat`, the context asked for), the features X11 freeglut answers without
//! (overlays, game mode, video resizing, colour maps), freeglut's message handlers and
//! `glutGetProcAddress`. Before any window they act on the settings windows will take.

use super::init::{set_glut, with_glut};
use crate::context::with_gl;
use gleval::gl::types::*;
use std::ffi::{c_char, c_int, c_void, CStr, CString};
use std::rc::Rc;

entry! {
    /// `glutGet`.
    fn glutGet(what: GLenum) -> c_int {
        with_glut(|gl| gl.glut_get(what))
    }
}

entry! {
    /// `glutDeviceGet`.
    fn glutDeviceGet(what: GLenum) -> c_int {
        with_glut(|gl| gl.glut_device_get(what))
    }
}

entry! {
    /// `glutLayerGet`.
    fn glutLayerGet(what: GLenum) -> c_int {
        with_glut(|gl| gl.glut_layer_get(what))
    }
}

entry! {
    /// `glutGameModeGet`.
    fn glutGameModeGet(what: GLenum) -> c_int {
        with_glut(|gl| gl.glut_game_mode_get(what))
    }
}

entry! {
    /// `glutVideoResizeGet`.
    fn glutVideoResizeGet(what: GLenum) -> c_int {
        with_glut(|gl| gl.glut_video_resize_get(what))
    }
}

entry! {
    /// `glutSetOption` (freeglut).
    fn glutSetOption(what: GLenum, value: c_int) {
        set_glut(|gl| gl.glut_set_option(what, value))
    }
}

entry! {
    /// `glutSetKeyRepeat`.
    fn glutSetKeyRepeat(mode: c_int) {
        set_glut(|gl| gl.glut_set_key_repeat(mode))
    }
}

entry! {
    /// `glutInitContextVersion` (freeglut).
    fn glutInitContextVersion(major: c_int, minor: c_int) {
        set_glut(|gl| gl.glut_init_context_version(major, minor))
    }
}

entry! {
    /// `glutInitContextFlags` (freeglut).
    fn glutInitContextFlags(flags: c_int) {
        set_glut(|gl| gl.glut_init_context_flags(flags))
    }
}

entry! {
    /// `glutInitContextProfile` (freeglut).
    fn glutInitContextProfile(profile: c_int) {
        set_glut(|gl| gl.glut_init_context_profile(profile))
    }
}

entry! {
    /// `glutGameModeString`.
    unsafe fn glutGameModeString(string: *const c_char) {
        if !string.is_null() {
            let s = unsafe { CStr::from_ptr(string) }.to_string_lossy().into_owned();
            set_glut(|gl| gl.glut_game_mode_string(&s))
        }
    }
}

entry! {
    /// `glutEnterGameMode`: 0, the screen's mode cannot change (see `Gl::glut_enter_game_mode`).
    fn glutEnterGameMode() -> c_int {
        with_glut(|gl| gl.glut_enter_game_mode())
    }
}

forward! {
    glutLeaveGameMode() => glut_leave_game_mode;
    glutEstablishOverlay() => glut_establish_overlay;
    glutRemoveOverlay() => glut_remove_overlay;
    glutUseLayer(layer: GLenum) => glut_use_layer;
    glutPostOverlayRedisplay() => glut_post_overlay_redisplay;
    glutPostWindowOverlayRedisplay(window: c_int) => glut_post_window_overlay_redisplay;
    glutShowOverlay() => glut_show_overlay;
    glutHideOverlay() => glut_hide_overlay;
    glutSetupVideoResizing() => glut_setup_video_resizing;
    glutStopVideoResizing() => glut_stop_video_resizing;
    glutVideoResize(x: c_int, y: c_int, width: c_int, height: c_int) => glut_video_resize;
    glutVideoPan(x: c_int, y: c_int, width: c_int, height: c_int) => glut_video_pan;
    glutSetColor(index: c_int, red: GLfloat, green: GLfloat, blue: GLfloat) => glut_set_color;
    glutCopyColormap(window: c_int) => glut_copy_colormap;
    glutForceJoystickFunc() => glut_force_joystick_func;
    glutReportErrors() => glut_report_errors;
    glutSetVertexAttribCoord3(attrib: GLint) => glut_set_vertex_attrib_coord3;
    glutSetVertexAttribNormal(attrib: GLint) => glut_set_vertex_attrib_normal;
    glutSetVertexAttribTexCoord2(attrib: GLint) => glut_set_vertex_attrib_tex_coord2;
}

entry! {
    /// `glutGetColor`: -1 (an RGBA window has no colour map).
    fn glutGetColor(index: c_int, component: c_int) -> GLfloat {
        with_glut(|gl| gl.glut_get_color(index, component))
    }
}

entry! {
    /// `glutGetModeValues(mode, &size)` (freeglut): no values here (NULL, size 0).
    unsafe fn glutGetModeValues(mode: GLenum, size: *mut c_int) -> *mut c_int {
        let values = with_glut(|gl| gl.glut_get_mode_values(mode).len() as i32);
        if let Some(size) = unsafe { size.as_mut() } {
            *size = values;
        }
        std::ptr::null_mut()
    }
}

entry! {
    /// `glutExtensionSupported(name)`: 1 if `name` is a whole word of `GL_EXTENSIONS`.
    unsafe fn glutExtensionSupported(name: *const c_char) -> c_int {
        if name.is_null() {
            return 0;
        }
        let name = unsafe { CStr::from_ptr(name) }.to_string_lossy().into_owned();
        with_gl(|gl| gl.glut_extension_supported(&name))
    }
}

/// freeglut's message handlers take `(fmt, va_list)`: the message is handed as a format with
/// no conversions (its `%` doubled) and an empty argument list, which `vfprintf` and its kin
/// never read. On x86-64 and AArch64 a `va_list` argument is passed as a pointer.
type MessageFn = extern "C" fn(*const c_char, *mut c_void);

fn handler(f: MessageFn) -> gleval::glut::MessageFn {
    Rc::new(move |message: &str| {
        let format = CString::new(message.replace('%', "%%").replace('\0', "")).unwrap_or_default();
        // Room for any platform's va_list; zero: there are no arguments to read.
        let mut arguments = [0u64; 4];
        if cfg!(any(target_arch = "x86_64", target_arch = "aarch64")) {
            f(format.as_ptr(), arguments.as_mut_ptr().cast());
        } else {
            eprintln!("freeglut: {message}");
        }
    })
}

entry! {
    /// `glutInitWarningFunc` (freeglut): `f(fmt, ap)` receives freeglut's warnings.
    fn glutInitWarningFunc(f: Option<MessageFn>) {
        set_glut(|gl| gl.glut_init_warning_func(f.map(handler)))
    }
}

entry! {
    /// `glutInitErrorFunc` (freeglut): `f(fmt, ap)` receives freeglut's errors.
    fn glutInitErrorFunc(f: Option<MessageFn>) {
        set_glut(|gl| gl.glut_init_error_func(f.map(handler)))
    }
}

/// The dynamic linker's answer about an address.
#[repr(C)]
struct DlInfo {
    file: *const c_char,
    base: *mut c_void,
    symbol: *const c_char,
    address: *mut c_void,
}

#[link(name = "dl")]
extern "C" {
    fn dladdr(address: *const c_void, info: *mut DlInfo) -> c_int;
    fn dlopen(file: *const c_char, flags: c_int) -> *mut c_void;
    fn dlsym(handle: *mut c_void, symbol: *const c_char) -> *mut c_void;
}

const RTLD_LAZY: c_int = 1;
const RTLD_NOLOAD: c_int = 4;

/// This library's own symbol `name` (not another library's of the same name).
fn own_symbol(name: &CStr) -> *mut c_void {
    let mut info = DlInfo {
        file: std::ptr::null(),
        base: std::ptr::null_mut(),
        symbol: std::ptr::null(),
        address: std::ptr::null_mut(),
    };
    let me = glutGetProcAddress as *const c_void;
    // SAFETY: dladdr fills `info` for an address of this library; dlopen with RTLD_NOLOAD
    // only finds the library already loaded (never loads one); dlsym reads a NUL-terminated
    // name.
    unsafe {
        if dladdr(me, &mut info) == 0 || info.file.is_null() {
            return std::ptr::null_mut();
        }
        let handle = dlopen(info.file, RTLD_LAZY | RTLD_NOLOAD);
        if handle.is_null() {
            return std::ptr::null_mut();
        }
        dlsym(handle, name.as_ptr())
    }
}

entry! {
    /// `glutGetProcAddress(name)` (freeglut): gleval's own entry point of that name (a GL, GLU
    /// or GLUT function it exports), NULL for another name.
    unsafe fn glutGetProcAddress(name: *const c_char) -> *mut c_void {
        if name.is_null() {
            return std::ptr::null_mut();
        }
        let name = unsafe { CStr::from_ptr(name) };
        if !name.to_bytes().starts_with(b"gl") {
            return std::ptr::null_mut();
        }
        own_symbol(name)
    }
}

forward! {
    glutJoystickGetNumAxes(ident: c_int) -> c_int => glut_joystick_get_num_axes;
    glutJoystickGetNumButtons(ident: c_int) -> c_int => glut_joystick_get_num_buttons;
    glutJoystickNotWorking(ident: c_int) -> c_int => glut_joystick_not_working;
    glutJoystickGetDeadBand(ident: c_int, axis: c_int) -> GLfloat => glut_joystick_get_dead_band;
    glutJoystickSetDeadBand(ident: c_int, axis: c_int, value: GLfloat) => glut_joystick_set_dead_band;
    glutJoystickGetSaturation(ident: c_int, axis: c_int) -> GLfloat => glut_joystick_get_saturation;
    glutJoystickSetSaturation(ident: c_int, axis: c_int, value: GLfloat) => glut_joystick_set_saturation;
}

/// A joystick range call: freeglut reads or writes one float an axis (2 axes).
macro_rules! joystick_ranges {
    ($($name:ident => $which:ident, $set:ident;)*) => {
        $(entry! {
            #[doc = concat!("`", stringify!($name), "(ident, axes)`: two floats (NULL: nothing).")]
            unsafe fn $name(ident: c_int, axes: *mut GLfloat) {
                if axes.is_null() {
                    return;
                }
                // SAFETY: freeglut's contract: `axes` holds a float for each of the 2 axes.
                let axes = unsafe { std::slice::from_raw_parts_mut(axes, 2) };
                let which = gleval::glut::JoystickRange::$which;
                joystick_ranges!(@call $set, ident, which, axes)
            }
        })*
    };
    (@call get, $ident:ident, $which:ident, $axes:ident) => { with_glut(|gl| gl.glut_joystick_get_range($ident, $which, $axes)) };
    (@call set, $ident:ident, $which:ident, $axes:ident) => { with_glut(|gl| gl.glut_joystick_set_range($ident, $which, $axes)) };
}

joystick_ranges! {
    glutJoystickGetMinRange => Min, get;
    glutJoystickGetMaxRange => Max, get;
    glutJoystickGetCenter => Center, get;
    glutJoystickSetMinRange => Min, set;
    glutJoystickSetMaxRange => Max, set;
    glutJoystickSetCenter => Center, set;
}
