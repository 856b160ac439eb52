//! `glXUseXFont`: an X server font's glyphs as `glBitmap` display lists (GLX 1.4 §3.3.8), as
//! Mesa's `xfont.c` makes them: each glyph drawn by the server into a one-bit pixmap, read
//! back, and compiled as one `glBitmap` that advances the raster position by the glyph's
//! width. A character the font lacks gets an empty list. FLTK's GL text and Mesa's demos draw
//! their labels this way.

use crate::context::with_gl;
use crate::x11::{FontGlyphs, Xid};
use gleval::gl::consts::*;
use gleval::gl::Gl;
use std::ffi::c_int;

/// The pixel-store unpack modes `glBitmap` reads with, set to GL's defaults while the lists
/// are made and restored after, as Mesa does.
const UNPACK: [(u32, i32); 6] = [
    (GL_UNPACK_SWAP_BYTES, 0),
    (GL_UNPACK_LSB_FIRST, 0),
    (GL_UNPACK_ROW_LENGTH, 0),
    (GL_UNPACK_SKIP_ROWS, 0),
    (GL_UNPACK_SKIP_PIXELS, 0),
    (GL_UNPACK_ALIGNMENT, 1),
];

/// Makes lists `list_base ..` for the characters `first ..` (`count` of them).
fn make_lists(gl: &mut Gl, glyphs: &FontGlyphs, first: c_int, count: c_int, list_base: c_int) {
    let saved: Vec<(u32, i32)> = UNPACK
        .iter()
        .map(|&(name, _)| {
            let mut v = [0];
            gl.get_integerv(name, &mut v);
            (name, v[0])
        })
        .collect();
    for &(name, value) in &UNPACK {
        gl.pixel_storei(name, value);
    }
    for i in 0..count {
        let c = (first + i) as u32;
        gl.new_list((list_base + i) as u32, GL_COMPILE);
        if let Some(m) = glyphs.metrics(c) {
            let bits = glyphs.bitmap(c, &m);
            let (w, h) = (i32::from(m.rbearing - m.lbearing), i32::from(m.ascent + m.descent));
            // The glyph's baseline one row below the raster position's row, where Mesa's
            // lists put it (measured: capi/tests/glx/calls.c draws the same pixels).
            let yorig = f32::from(m.descent) - 1.0;
            gl.bitmap(w.max(0), h.max(0), -f32::from(m.lbearing), yorig, f32::from(m.width), 0.0, &bits);
        }
        gl.end_list();
    }
    for (name, value) in saved {
        gl.pixel_storei(name, value);
    }
}

entry! {
    /// `glXUseXFont(font, first, count, listBase)`: lists of the current context for the
    /// glyphs of the X font `font` of the current context's display. Without a current GLX
    /// context, nothing; a font that is not one is X's `BadFont`; `count` < 1 makes nothing.
    fn glXUseXFont(font: Xid, first: c_int, count: c_int, list_base: c_int) {
        let display = super::current_display();
        if display.is_null() || count < 1 {
            return;
        }
        let Some(glyphs) = FontGlyphs::open(display, font) else { return };
        with_gl(|gl| make_lists(gl, &glyphs, first, count, list_base));
    }
}
