//! Feedback mode: `glFeedbackBuffer` and `glRenderMode`.
//!
//! `Gl` keeps the values; the C buffer is this thread's (GL's context is too) and receives
//! them when `glRenderMode` leaves feedback mode.

use crate::context::with_gl;
use gleval::gl::consts::GL_SELECT;
use gleval::gl::types::*;
use std::cell::Cell;

thread_local! {
    /// The buffer `glFeedbackBuffer` gave, and its size in values.
    static BUFFER: Cell<(*mut GLfloat, usize)> = const { Cell::new((std::ptr::null_mut(), 0)) };
}

/// The buffer `glFeedbackBuffer` last gave (`glGetPointerv(GL_FEEDBACK_BUFFER_POINTER)`).
pub(crate) fn feedback_pointer() -> *mut GLfloat {
    BUFFER.with(Cell::get).0
}

entry! {
    /// `glFeedbackBuffer`: `Gl::feedback_buffer`. C's NULL with a positive size is
    /// `GL_INVALID_VALUE` in GL, as a negative size is: it is passed on as one.
    unsafe fn glFeedbackBuffer(size: GLsizei, type_: GLenum, buffer: *mut GLfloat) {
        let size = if buffer.is_null() && size > 0 { -1 } else { size };
        with_gl(|gl| {
            let takes = gl.feedback_buffer_error(size, type_).is_none();
            gl.feedback_buffer(size, type_);
            if takes {
                BUFFER.with(|b| b.set((buffer, size as usize)));
            }
        })
    }
}

entry! {
    /// `glRenderMode`: `Gl::render_mode`; leaving feedback mode writes the values into the
    /// buffer given to `glFeedbackBuffer` (at most its size), leaving selection mode into
    /// `glSelectBuffer`'s.
    fn glRenderMode(mode: GLenum) -> GLint {
        with_gl(|gl| {
            let leaving_select = gl.render_mode_value() == GL_SELECT && !gl.inside_begin_end();
            let n = gl.render_mode(mode);
            if leaving_select {
                super::select::write_back(gl.select_values());
            } else if n != 0 {
                let (buffer, size) = BUFFER.with(Cell::get);
                let values = gl.feedback_values();
                let count = values.len().min(size);
                if !buffer.is_null() {
                    // SAFETY: glFeedbackBuffer's promise: `size` writable floats at `buffer`.
                    unsafe { std::ptr::copy_nonoverlapping(values.as_ptr(), buffer, count) };
                }
            }
            n
        })
    }
}
