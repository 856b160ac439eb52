//! `GL/glew.h`: GLEW as textbook programs use it (`glewExperimental = GL_TRUE; glewInit();`,
//! then GL 1.1), answered by gleval: `glewInit` succeeds once a gleval context is current, and
//! the entry points are gleval's own (declared by `GL/gl.h`), so none is a null pointer.
//! Versions and extensions answer from `glGetString`, as GLEW reads them.

use crate::context::{has_current, with_gl};
use crate::strings::static_c_string;
use gleval::gl::consts::{GL_EXTENSIONS, GL_VERSION};
use gleval::gl::types::*;
use std::ffi::{c_char, CStr};
use std::sync::atomic::AtomicU8;

/// `glewExperimental`: programs set it before `glewInit`; it changes nothing here (gleval has
/// no core profile whose entry points GLEW would miss). Interior-mutable, so C may write it.
#[no_mangle]
pub static glewExperimental: AtomicU8 = AtomicU8::new(0);

/// The GLEW version `glewGetString` reports (the GLEW API this header follows).
const GLEW_VERSION: (&str, &str, &str, &str) = ("2.2.0", "2", "2", "0");

entry! {
    /// `glewInit`: `GLEW_OK` (0) with a context current, `GLEW_ERROR_NO_GL_VERSION` (1)
    /// without one, as GLEW answers when `glGetString(GL_VERSION)` is NULL.
    fn glewInit() -> GLenum {
        if has_current() { 0 } else { 1 }
    }
}

/// The current context's (major, minor) GL version.
fn gl_version() -> (u32, u32) {
    let text = with_gl(|gl| gl.get_string(GL_VERSION).map(|s| s.to_owned()).unwrap_or_default());
    let mut parts = text.split(|c: char| !c.is_ascii_digit()).filter_map(|p| p.parse().ok());
    (parts.next().unwrap_or(0), parts.next().unwrap_or(0))
}

/// Whether one name (`GL_VERSION_x_y` or an extension) is supported.
fn supported(name: &str) -> bool {
    if let Some(version) = name.strip_prefix("GL_VERSION_") {
        let mut parts = version.split('_').filter_map(|p| p.parse::<u32>().ok());
        let wanted = (parts.next().unwrap_or(u32::MAX), parts.next().unwrap_or(0));
        return has_current() && wanted <= gl_version();
    }
    let extensions = with_gl(|gl| gl.get_string(GL_EXTENSIONS).map(|s| s.to_owned()).unwrap_or_default());
    extensions.split_whitespace().any(|e| e == name)
}

/// A C string argument (NULL: empty).
///
/// # Safety
/// `s` is NULL or NUL-terminated.
unsafe fn text(s: *const c_char) -> String {
    if s.is_null() {
        return String::new();
    }
    unsafe { CStr::from_ptr(s) }.to_string_lossy().into_owned()
}

entry! {
    /// `glewIsSupported(names)`: every space-separated name supported.
    unsafe fn glewIsSupported(names: *const c_char) -> GLboolean {
        let names = unsafe { text(names) };
        GLboolean::from(!names.trim().is_empty() && names.split_whitespace().all(supported))
    }
}

entry! {
    /// `glewGetExtension(name)`: the extension is in `GL_EXTENSIONS`.
    unsafe fn glewGetExtension(name: *const c_char) -> GLboolean {
        let name = unsafe { text(name) };
        GLboolean::from(!name.starts_with("GL_VERSION_") && supported(&name))
    }
}

entry! {
    /// `glewGetErrorString(code)`: GLEW's messages.
    fn glewGetErrorString(code: GLenum) -> *const GLubyte {
        let message = match code {
            0 => "No error",
            1 => "Missing GL version",
            2 => "GL 1.1 and up are not supported",
            3 => "GLX 1.2 and up are not supported",
            _ => "Unknown error",
        };
        static_c_string(message).cast()
    }
}

entry! {
    /// `glewGetString(name)`: `GLEW_VERSION` (1) and its major, minor and micro parts (2..4).
    fn glewGetString(name: GLenum) -> *const GLubyte {
        let s = match name {
            1 => GLEW_VERSION.0,
            2 => GLEW_VERSION.1,
            3 => GLEW_VERSION.2,
            4 => GLEW_VERSION.3,
            _ => return std::ptr::null(),
        };
        static_c_string(s).cast()
    }
}
