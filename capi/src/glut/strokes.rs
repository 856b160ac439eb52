//! GLUT's stroke fonts. Their C handles are freeglut's numbers (`(void *)0` for
//! `GLUT_STROKE_ROMAN`, `(void *)1` for `GLUT_STROKE_MONO_ROMAN`) or its font symbols'
//! addresses (`font_handles.rs`); another pointer is no font, and the calls draw nothing and
//! measure 0.

use super::font_handles::stroke as font;
use super::fonts::c_bytes;
use crate::context::with_gl;
use std::ffi::{c_float, c_int, c_uchar, c_void};

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
