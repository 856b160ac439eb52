//! Selection mode: `glSelectBuffer` and the name stack (`glRenderMode` is in `feedback.rs`).
//!
//! `Gl` keeps the values; the C buffer is this thread's (as GL's context is) and receives them
//! when `glRenderMode` leaves selection mode.

use crate::context::with_gl;
use gleval::gl::types::*;
use std::cell::Cell;

thread_local! {
    /// The buffer `glSelectBuffer` gave, and its size in values.
    static BUFFER: Cell<(*mut GLuint, usize)> = const { Cell::new((std::ptr::null_mut(), 0)) };
}

/// The buffer `glSelectBuffer` last gave (`glGetPointerv(GL_SELECTION_BUFFER_POINTER)`).
pub(crate) fn select_pointer() -> *mut GLuint {
    BUFFER.with(Cell::get).0
}

/// Copies the last selection pass's values into the caller's buffer (at most its size).
pub(crate) fn write_back(values: &[GLuint]) {
    let (buffer, size) = BUFFER.with(Cell::get);
    let count = values.len().min(size);
    if !buffer.is_null() {
        // SAFETY: glSelectBuffer's promise: `size` writable values at `buffer`.
        unsafe { std::ptr::copy_nonoverlapping(values.as_ptr(), buffer, count) };
    }
}

entry! {
    /// `glSelectBuffer`: `Gl::select_buffer`, keeping the buffer (NULL is accepted, as in
    /// Mesa; nothing is written to it).
    unsafe fn glSelectBuffer(size: GLsizei, buffer: *mut GLuint) {
        with_gl(|gl| {
            let takes = gl.select_buffer_error(size).is_none();
            gl.select_buffer(size);
            if takes {
                BUFFER.with(|b| b.set((buffer, gl.select_buffer_size())));
            }
        })
    }
}

forward! {
    glInitNames() => init_names;
    glLoadName(name: GLuint) => load_name;
    glPushName(name: GLuint) => push_name;
    glPopName() => pop_name;
    glPassThrough(token: GLfloat) => pass_through;
}
