//! What a program asks of its window: redisplay, swap, modifiers, title, size, full screen.

use crate::context::with_gl;
use std::ffi::{c_char, c_int, CStr};

forward! {
    glutPostRedisplay() => glut_post_redisplay;
    glutSwapBuffers() => glut_swap_buffers;
    glutGetModifiers() -> c_int => glut_get_modifiers;
    glutReshapeWindow(width: c_int, height: c_int) => glut_reshape_window;
    glutFullScreen() => glut_full_screen;
}

entry! {
    /// `glutSetWindowTitle`.
    unsafe fn glutSetWindowTitle(title: *const c_char) {
        if !title.is_null() {
            let title = unsafe { CStr::from_ptr(title) }.to_string_lossy().into_owned();
            with_gl(|gl| gl.glut_set_window_title(&title))
        }
    }
}
