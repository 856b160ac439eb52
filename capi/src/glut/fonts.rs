//! GLUT's bitmap fonts and teapot.
//!
//! C GLUT's font handles are pointers: the small integers 2..=8 that `GL/glut.h` here gives
//! them, or on Linux the addresses of freeglut's font objects (`font_objects`). Another pointer
//! is no font: the calls then draw nothing and measure 0.

use super::font_objects::{self, Font};
use crate::context::with_gl;
use gleval::glut::fonts::GlutBitmapFont;
use std::ffi::{c_char, c_int, c_uchar, c_void, CStr};

forward! {
    glutSolidTeapot(size: f64) => glut_solid_teapot;
    glutWireTeapot(size: f64) => glut_wire_teapot;
}

/// The bitmap font a C handle names ([`font_objects::font`]).
pub(super) fn font(handle: *const c_void) -> Option<GlutBitmapFont> {
    match font_objects::font(handle)? {
        Font::Bitmap(f) => Some(f),
        Font::Stroke(_) => None,
    }
}

/// The bytes of a C string up to its NUL; empty for NULL.
///
/// # Safety
/// `s` is NULL or a NUL-terminated string.
pub(super) unsafe fn c_bytes<'a>(s: *const c_uchar) -> &'a [u8] {
    if s.is_null() {
        return &[];
    }
    unsafe { CStr::from_ptr(s.cast::<c_char>()) }.to_bytes()
}

entry! {
    /// `glutBitmapCharacter`.
    fn glutBitmapCharacter(handle: *const c_void, character: c_int) {
        if let Some(f) = font(handle) {
            with_gl(|gl| gl.glut_bitmap_character(f, character))
        }
    }
}

entry! {
    /// `glutBitmapString` (freeglut).
    unsafe fn glutBitmapString(handle: *const c_void, string: *const c_uchar) {
        if let Some(f) = font(handle) {
            let s = unsafe { c_bytes(string) };
            with_gl(|gl| gl.glut_bitmap_string(f, s))
        }
    }
}

entry! {
    /// `glutBitmapWidth`.
    fn glutBitmapWidth(handle: *const c_void, character: c_int) -> c_int {
        font(handle).map_or(0, |f| with_gl(|gl| gl.glut_bitmap_width(f, character)))
    }
}

entry! {
    /// `glutBitmapLength`.
    unsafe fn glutBitmapLength(handle: *const c_void, string: *const c_uchar) -> c_int {
        let s = unsafe { c_bytes(string) };
        font(handle).map_or(0, |f| with_gl(|gl| gl.glut_bitmap_length(f, s)))
    }
}

entry! {
    /// `glutBitmapHeight` (freeglut).
    fn glutBitmapHeight(handle: *const c_void) -> c_int {
        font(handle).map_or(0, |f| with_gl(|gl| gl.glut_bitmap_height(f)))
    }
}
