//! GLUT's stroke fonts. Their C handles are freeglut's, `(void *)0` for `GLUT_STROKE_ROMAN`
//! and `(void *)1` for `GLUT_STROKE_MONO_ROMAN` (gleval's `GL/glut.h`), or the addresses of
//! freeglut's `glutStrokeRoman`/`glutStrokeMonoRoman` (`font_objects`); another pointer is no
//! font, and the calls draw nothing and measure 0.

use super::font_objects::{self, Font};
use super::fonts::c_bytes;
use crate::context::with_gl;
use gleval::glut::fonts::GlutStrokeFont;
use std::ffi::{c_float, c_int, c_uchar, c_void};

/// The stroke font a C handle names ([`font_objects::font`]).
fn font(handle: *const c_void) -> Option<GlutStrokeFont> {
    match font_objects::font(handle)? {
        Font::Stroke(f) => Some(f),
        Font::Bitmap(_) => None,
    }
}

entry! {
    /// `glutStrokeCharacter`.
    fn glutStrokeCharacter(handle: *const c_void, character: c_int) {
        if let Some(f) = font(handle) {
            with_gl(|gl| gl.glut_stroke_character(f, character))
        }
    }
}

entry! {
    /// `glutStrokeString` (freeglut).
    unsafe fn glutStrokeString(handle: *const c_void, string: *const c_uchar) {
        if let Some(f) = font(handle) {
            let s = unsafe { c_bytes(string) };
            with_gl(|gl| gl.glut_stroke_string(f, s))
        }
    }
}

entry! {
    /// `glutStrokeWidth`.
    fn glutStrokeWidth(handle: *const c_void, character: c_int) -> c_int {
        font(handle).map_or(0, |f| with_gl(|gl| gl.glut_stroke_width(f, character)))
    }
}

entry! {
    /// `glutStrokeWidthf` (freeglut).
    fn glutStrokeWidthf(handle: *const c_void, character: c_int) -> c_float {
        font(handle).map_or(0.0, |f| with_gl(|gl| gl.glut_stroke_widthf(f, character)))
    }
}

entry! {
    /// `glutStrokeLength`.
    unsafe fn glutStrokeLength(handle: *const c_void, string: *const c_uchar) -> c_int {
        let s = unsafe { c_bytes(string) };
        font(handle).map_or(0, |f| with_gl(|gl| gl.glut_stroke_length(f, s)))
    }
}

entry! {
    /// `glutStrokeLengthf` (freeglut).
    unsafe fn glutStrokeLengthf(handle: *const c_void, string: *const c_uchar) -> c_float {
        let s = unsafe { c_bytes(string) };
        font(handle).map_or(0.0, |f| with_gl(|gl| gl.glut_stroke_lengthf(f, s)))
    }
}

entry! {
    /// `glutStrokeHeight` (freeglut).
    fn glutStrokeHeight(handle: *const c_void) -> c_float {
        font(handle).map_or(0.0, |f| with_gl(|gl| gl.glut_stroke_height(f)))
    }
}
