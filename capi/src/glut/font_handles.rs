//! What a C font handle names. Two kinds of handle name a font:
//! - freeglut's numbers, which gleval's `GL/freeglut_std.h` gives the font macros
//!   (`GLUT_STROKE_ROMAN` is `(void *)0x0000`, ..., `GLUT_BITMAP_HELVETICA_18` is `(void *)0x0008`);
//! - the addresses of freeglut's font data symbols (`&glutStrokeRoman`, `&glutBitmap9By15`,
//!   ...), which programs compiled against the system's freeglut header pass. The library part
//!   that exports those symbols (binary compatibility) lists them in [`SYMBOL_FONTS`].
//!
//! Any other pointer names no font: the font calls draw nothing and measure 0.

use gleval::glut::consts::*;
use gleval::glut::fonts::{GlutBitmapFont, GlutStrokeFont, GLUT_STROKE_MONO_ROMAN, GLUT_STROKE_ROMAN};
use std::ffi::c_void;

/// freeglut's data symbols' addresses with the number of the font each names; filled by the
/// part of the library that exports them (`glutStrokeRoman` is font 0, ... as in
/// `GL/freeglut_std.h`'s Windows handles).
pub(crate) static SYMBOL_FONTS: std::sync::OnceLock<Vec<(usize, usize)>> = std::sync::OnceLock::new();

/// The freeglut font number a handle names.
fn number(handle: *const c_void) -> Option<usize> {
    let address = handle as usize;
    if address <= 8 {
        return Some(address);
    }
    SYMBOL_FONTS.get()?.iter().find(|(a, _)| *a == address).map(|(_, n)| *n)
}

/// The bitmap font a handle names.
pub(super) fn bitmap(handle: *const c_void) -> Option<GlutBitmapFont> {
    let n = number(handle)?;
    let fonts = [
        GLUT_BITMAP_9_BY_15,
        GLUT_BITMAP_8_BY_13,
        GLUT_BITMAP_TIMES_ROMAN_10,
        GLUT_BITMAP_TIMES_ROMAN_24,
        GLUT_BITMAP_HELVETICA_10,
        GLUT_BITMAP_HELVETICA_12,
        GLUT_BITMAP_HELVETICA_18,
    ];
    fonts.into_iter().find(|f| usize::from(f.id()) == n)
}

/// The stroke font a handle names.
pub(super) fn stroke(handle: *const c_void) -> Option<GlutStrokeFont> {
    match number(handle)? {
        0 => Some(GLUT_STROKE_ROMAN),
        1 => Some(GLUT_STROKE_MONO_ROMAN),
        _ => None,
    }
}
