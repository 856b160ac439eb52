//! What GLX says of itself: `glXQueryExtension`, `glXQueryVersion`, the extension, server and
//! client strings, and `glXGetProcAddress` (GLX 1.4, GLX_ARB_get_proc_address).

use super::{Bool, TRUE};
use crate::x11::{self, Display};
use std::ffi::{c_char, c_int, c_void, CStr};

/// The GLX extensions gleval implements: context creation with attributes (and the profile
/// attribute), GetProcAddress, the three swap-interval extensions, visual types.
pub const EXTENSIONS: &CStr = c"GLX_ARB_create_context GLX_ARB_create_context_profile GLX_ARB_get_proc_address GLX_EXT_swap_control GLX_EXT_visual_info GLX_MESA_swap_control GLX_SGI_swap_control";

const GLX_VENDOR: c_int = 1;
const GLX_VERSION: c_int = 2;
const GLX_EXTENSIONS: c_int = 3;

/// The string of `name`, as the server and the client both answer it.
fn string(name: c_int) -> *const c_char {
    match name {
        GLX_VENDOR => c"gleval".as_ptr(),
        GLX_VERSION => c"1.4".as_ptr(),
        GLX_EXTENSIONS => EXTENSIONS.as_ptr(),
        _ => std::ptr::null(),
    }
}

entry! {
    /// `glXQueryExtension`: GLX is there (gleval's own, on the client side); the first
    /// error and event codes are the server's GLX extension's where it has one, else 0.
    unsafe fn glXQueryExtension(display: *mut Display, error_base: *mut c_int, event_base: *mut c_int) -> Bool {
        let (error, event) = x11::glx_extension(display).map_or((0, 0), |(_, e)| (c_int::from(e), 0));
        // SAFETY: GLX's contract: NULL or ints to write.
        unsafe {
            if let Some(e) = error_base.as_mut() {
                *e = error;
            }
            if let Some(e) = event_base.as_mut() {
                *e = event;
            }
        }
        TRUE
    }
}

entry! {
    /// `glXQueryVersion`: 1.4.
    unsafe fn glXQueryVersion(_display: *mut Display, major: *mut c_int, minor: *mut c_int) -> Bool {
        // SAFETY: GLX's contract: NULL or ints to write.
        unsafe {
            if let Some(m) = major.as_mut() {
                *m = 1;
            }
            if let Some(m) = minor.as_mut() {
                *m = 4;
            }
        }
        TRUE
    }
}

entry! {
    /// `glXQueryExtensionsString`: [`EXTENSIONS`].
    fn glXQueryExtensionsString(_display: *mut Display, _screen: c_int) -> *const c_char {
        EXTENSIONS.as_ptr()
    }
}

entry! {
    /// `glXQueryServerString`: `GLX_VENDOR` "gleval", `GLX_VERSION` "1.4",
    /// `GLX_EXTENSIONS`; NULL for another name.
    fn glXQueryServerString(_display: *mut Display, _screen: c_int, name: c_int) -> *const c_char {
        string(name)
    }
}

entry! {
    /// `glXGetClientString`: as `glXQueryServerString` (gleval is both sides).
    fn glXGetClientString(_display: *mut Display, name: c_int) -> *const c_char {
        string(name)
    }
}

/// gleval's entry point for a NUL-terminated name, NULL if it implements none such.
///
/// # Safety
/// `name` is NULL or NUL-terminated.
pub unsafe fn proc_address(name: *const c_char) -> *mut c_void {
    if name.is_null() {
        return std::ptr::null_mut();
    }
    // SAFETY: the caller's promise.
    let name = unsafe { CStr::from_ptr(name) };
    crate::dl::own_entry_point(name.to_bytes()).unwrap_or(std::ptr::null_mut())
}

entry! {
    /// `glXGetProcAddress`: gleval's entry point of that name for every GL, GLU, GLUT, GLX
    /// and EGL function it implements, NULL for any other.
    unsafe fn glXGetProcAddress(name: *const u8) -> *mut c_void {
        // SAFETY: GLX's contract: a NUL-terminated name.
        unsafe { proc_address(name.cast()) }
    }
}

entry! {
    /// `glXGetProcAddressARB`: as `glXGetProcAddress`.
    unsafe fn glXGetProcAddressARB(name: *const u8) -> *mut c_void {
        // SAFETY: as above.
        unsafe { proc_address(name.cast()) }
    }
}
