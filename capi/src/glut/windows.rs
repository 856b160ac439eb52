//! GLUT's windows in C: `glutCreateWindow`, `glutCreateSubWindow`, `glutSetWindow`, ... over
//! `App`'s windows.
//!
//! Before the main loop the program's windows are one `App` kept here (window 1 and the ones
//! added to it), each with its context made at once, so that GL calls between
//! `glutCreateWindow` and `glutMainLoop` set up that window's context. Each context stays at
//! the address it was made at for the window's life (the runner keeps them boxed), and C's
//! current context follows `glutSetWindow` by that address, in and out of the main loop.

use crate::context::{make_current, with_gl};
use gleval::app::App;
use gleval::gl::Gl;
use std::cell::RefCell;
use std::ffi::{c_char, c_int, c_void, CStr};

thread_local! {
    /// The program's windows before the main loop.
    static ROOT: RefCell<Option<App>> = const { RefCell::new(None) };
    /// Each window's context, by number.
    static CONTEXTS: RefCell<Vec<(i32, *mut Gl)>> = const { RefCell::new(Vec::new()) };
}

/// Takes the windows made so far (`glutMainLoop` runs them).
pub(super) fn take_root() -> Option<App> {
    ROOT.with(|r| r.borrow_mut().take())
}

/// How many windows were made (and not forgotten).
pub(super) fn window_count() -> usize {
    CONTEXTS.with(|c| c.borrow().len())
}

fn context_of(id: i32) -> Option<*mut Gl> {
    CONTEXTS.with(|c| c.borrow().iter().find(|(w, _)| *w == id).map(|(_, p)| *p))
}

/// Makes window `id`'s context current (it exists: its number is in every context's table).
fn switch_to(id: i32) {
    if let Some(p) = context_of(id) {
        // SAFETY: the pointer is the window's boxed context, alive while the window is (a
        // destroyed window leaves every context's table before its context is dropped, and
        // callers check the table first).
        let gl = unsafe { &mut *p };
        gl.glut_set_window(id);
        make_current(gl);
    }
}

/// A title as C gives it (NULL is empty).
///
/// # Safety
/// `s` is NULL or a NUL-terminated string.
unsafe fn text(s: *const c_char) -> String {
    if s.is_null() {
        return String::new();
    }
    unsafe { CStr::from_ptr(s) }.to_string_lossy().into_owned()
}

/// Adds a window to the program and makes its context current; its number.
fn create(parent: i32, app: App) -> c_int {
    ROOT.with(|r| {
        let mut root = r.borrow_mut();
        let id = match root.as_mut() {
            None => {
                *root = Some(app);
                1
            }
            Some(root) => root.add_window(parent, app),
        };
        let root = root.as_mut().expect("made above");
        let gl = root.window_mut(id).expect("just added").context_mut();
        let pointer: *mut Gl = gl;
        CONTEXTS.with(|c| c.borrow_mut().push((id, pointer)));
        root.sync_contexts(id);
        switch_to(id);
        id
    })
}

entry! {
    /// `glutCreateWindow(title)`: a top-level window with its own context, made current;
    /// its number (1, 2, ... in creation order).
    unsafe fn glutCreateWindow(title: *const c_char) -> c_int {
        let title = unsafe { text(title) };
        if ROOT.with(|r| r.borrow().is_none()) && window_count() > 0 {
            // Inside the main loop: GLUT's windows are made before it here.
            eprintln!("gleval: glutCreateWindow inside the main loop is not supported; the call is ignored");
            return 0;
        }
        create(0, super::init::new_window(&title, None))
    }
}

entry! {
    /// `glutCreateSubWindow(parent, x, y, width, height)`: a window drawn inside `parent` with
    /// its top left corner at (x, y), its own context made current; its number.
    fn glutCreateSubWindow(parent: c_int, x: c_int, y: c_int, width: c_int, height: c_int) -> c_int {
        if ROOT.with(|r| r.borrow().is_none()) || context_of(parent).is_none() {
            eprintln!("gleval: glutCreateSubWindow: no window {parent} before the main loop; the call is ignored");
            return 0;
        }
        create(parent, super::init::new_window("", Some((x, y, width, height))))
    }
}

entry! {
    /// `glutSetWindow(window)`: later window calls and GL calls go to `window`.
    fn glutSetWindow(window: c_int) {
        let known = with_gl(|gl| {
            gl.glut_set_window(window);
            i32::from(gl.glut_get_window() == window)
        });
        if known == 1 {
            switch_to(window);
        }
    }
}

entry! {
    /// `glutGetWindow`: the current window's number, 0 for none.
    fn glutGetWindow() -> c_int {
        with_gl(|gl| gl.glut_get_window())
    }
}

entry! {
    /// `glutDestroyWindow(window)`: the window (and its subwindows) close after the current
    /// callback, their close callbacks first. Its context is no longer reachable from C.
    fn glutDestroyWindow(window: c_int) {
        with_gl(|gl| gl.glut_destroy_window(window));
    }
}

forward! {
    glutPostWindowRedisplay(window: c_int) => glut_post_window_redisplay;
    glutPositionWindow(x: c_int, y: c_int) => glut_position_window;
    glutShowWindow() => glut_show_window;
    glutHideWindow() => glut_hide_window;
    glutIconifyWindow() => glut_iconify_window;
    glutPushWindow() => glut_push_window;
    glutPopWindow() => glut_pop_window;
    glutFullScreenToggle() => glut_full_screen_toggle;
    glutLeaveFullScreen() => glut_leave_full_screen;
    glutWarpPointer(x: c_int, y: c_int) => glut_warp_pointer;
    glutSetCursor(cursor: c_int) => glut_set_cursor;
    glutIgnoreKeyRepeat(ignore: c_int) => glut_ignore_key_repeat;
}

entry! {
    /// `glutSetIconTitle`.
    unsafe fn glutSetIconTitle(title: *const c_char) {
        let title = unsafe { text(title) };
        with_gl(|gl| gl.glut_set_icon_title(&title))
    }
}

entry! {
    /// `glutSetWindowData(data)` (freeglut): the program's pointer, kept with the window.
    fn glutSetWindowData(data: *mut c_void) {
        with_gl(|gl| gl.glut_set_window_data(data as usize))
    }
}

entry! {
    /// `glutGetWindowData` (freeglut).
    fn glutGetWindowData() -> *mut c_void {
        with_gl(|gl| gl.glut_get_window_data() as *mut c_void)
    }
}

/// Forgets every window's context (the loop is over: its windows are destroyed).
pub(super) fn forget_all() {
    CONTEXTS.with(|c| c.borrow_mut().clear());
}
